"""scripts/lines_figure: a lazy-wave umbilical, a line of three sections, in its static equilibrium.

An umbilical in 300 m of water: 320 m hanging from the vessel, 120 m with buoyancy modules (an
equivalent diameter whose displacement exceeds the weight), 260 m down to an anchor on the seabed;
rigid joints, the umbilical's bending stiffness throughout. compute() returns the shape and the end
forces, plot() draws it by section (docs/lines_lazy_wave.png). Used by tests/python/test_sections.py.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.paths import REPO_ROOT, require_fmu

UMBILICAL = dict(diameter=0.15, massPerLength=35.0, EA=5e8, EI=2e4, GJ=2e4, axialDamping=5e6,
                 Cdn=1.2, Cdt=0.01, Can=1.0, Cat=0.0)
BUOYANCY = {**UMBILICAL, "diameter": 0.35, "massPerLength": 70.0}
# (length [m], elements, properties) from the vessel
SECTIONS = [(320.0, 16, UMBILICAL), (120.0, 12, BUOYANCY), (260.0, 13, UMBILICAL)]
VESSEL_Z = -10.0


def section_parameters(k: int, **values) -> dict:
    return {f"section[{k}].{name}": value for name, value in values.items()}


LAZY_WAVE = {
    "nSections": len(SECTIONS), "bottomEnd": 1, "anchor.x": -520.0, "anchor.y": 0.0, "anchor.z": -300.0,
    "waterDepth": 300.0, "enableSeabed": True, "seabedStiffness": 1e5, "seabedDamping": 1e4,
    # tension-only, as a static analysis of such a line assumes: with compression allowed the static
    # solver can settle on a buckled equilibrium where the line reaches the seabed
    "enableCompression": False,
    "initialDirection.x": -1.0, "initialDirection.z": -1.0,
}
for _k, (_length, _n, _props) in enumerate(SECTIONS, start=1):
    LAZY_WAVE.update(section_parameters(_k, length=_length, nElements=_n, **_props))

OUTPUTS = ["minTension", "towTension", "towForce.z", "endForce.z", "seabedContactForce", "touchdownArcLength", "topDeclination"]


def compute(fmu) -> dict:
    with CableFMU(fmu, parameters=LAZY_WAVE) as c:
        c.initialize(inputs={"tow.z": VESSEL_Z})
        out = dict(zip(OUTPUTS, c.get_reals(OUTPUTS)))
        out.update(c.shape())
    total = sum(length for length, _, _ in SECTIONS)
    out["s"] = np.linspace(0.0, total, len(out["shape.x"]))
    out["boundaries"] = np.cumsum([0.0] + [length for length, _, _ in SECTIONS])
    return out


def plot(data: dict, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    x, z, s = data["shape.x"], data["shape.z"], data["s"]
    fig, ax = plt.subplots(figsize=(10, 5))
    names = ["hanging section", "buoyancy section", "bottom section"]
    edges = data["boundaries"]
    colors = ["tab:blue", "tab:orange", "tab:green"]
    ax.plot(x, z, "o", color="0.3", ms=3, label="output stations")
    for i in range(len(s) - 1):  # each interval between stations in the colour of the section at its middle
        k = int(np.searchsorted(edges, 0.5 * (s[i] + s[i + 1]))) - 1
        ax.plot(x[i:i + 2], z[i:i + 2], "-", color=colors[k], lw=3 if k == 1 else 1.8)
    for k in range(len(edges) - 1):
        ax.plot([], [], "-", color=colors[k], lw=3 if k == 1 else 1.8, label=f"{names[k]} ({edges[k + 1] - edges[k]:.0f} m)")
    ax.axhline(-300.0, color="saddlebrown", lw=1)
    ax.axhline(0.0, color="steelblue", lw=0.8)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z [m]")
    ax.set_aspect("equal")
    ax.set_title(f"Lazy-wave umbilical at rest: top tension {data['towTension'] / 1e3:.1f} kN, "
                 f"touchdown at s = {data['touchdownArcLength']:.0f} m (21 output stations)")
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="scripts/lines_figure", description=__doc__.split("\n\n")[0])
    ap.add_argument("--png", type=Path, default=REPO_ROOT / "docs" / "lines_lazy_wave.png", help="figure (default %(default)s)")
    args = ap.parse_args(argv)
    data = compute(require_fmu())
    plot(data, args.png)
    print(f"wrote {args.png}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
