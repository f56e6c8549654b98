"""scripts/winch_references: steady tow tension, body depth and layback against deployed length.

Computes the two references of the winch scenes (the steady-tow ODE and the FMU's static
initialization of a cable started at each length, see studies.references.winch_reference), then writes
OUT/references.csv, OUT/references.png and prints a Markdown table of the differences.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from ucable.paths import require_fmu
from ucable.progress import ProgressBar
from ucable.units import KNOT
from ..references.winch_reference import DeployBody, fmu_static_references, ode_references


def compute(lengths, knots: float, element_length: float, body: DeployBody, fmu=None) -> dict:
    """The references as arrays (no files): {'ode': LengthReferences, 'fmu': LengthReferences}."""
    speed = knots * KNOT
    bar = ProgressBar(len(lengths), "static solves")
    fmu_refs = fmu_static_references(fmu or require_fmu(), lengths, speed, body, element_length,
                                     progress=lambda i, n: bar.update(i))
    bar.close()
    return {"ode": ode_references(lengths, speed, body), "fmu": fmu_refs}


def markdown(refs: dict) -> str:
    o, f = refs["ode"], refs["fmu"]
    rows = ["| length [m] | tension ODE [N] | FMU - ODE | depth ODE [m] | FMU - ODE [m] | "
            "layback ODE [m] | FMU - ODE [m] |", "|---:|---:|---:|---:|---:|---:|---:|"]
    for i, L in enumerate(o.lengths):
        rows.append(f"| {L:g} | {o.tow_tension[i]:.1f} | "
                    f"{100 * (f.tow_tension[i] / o.tow_tension[i] - 1):+.4f} % | "
                    f"{o.body_depth[i]:.2f} | {f.body_depth[i] - o.body_depth[i]:+.3f} | "
                    f"{o.layback[i]:.2f} | {f.layback[i] - o.layback[i]:+.3f} |")
    return "\n".join(rows)


def write(refs: dict, out: Path) -> None:
    out.mkdir(parents=True, exist_ok=True)
    o, f = refs["ode"], refs["fmu"]
    table = np.column_stack([o.lengths, o.tow_tension, f.tow_tension, o.body_depth, f.body_depth,
                             o.layback, f.layback])
    np.savetxt(out / "references.csv", table, delimiter=",", comments="",
               header="length,towTensionODE,towTensionFMU,bodyDepthODE,bodyDepthFMU,"
                      "laybackODE,laybackFMU")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].plot(o.lengths, o.tow_tension / 1e3, "-", label="steady ODE")
    ax[0].plot(f.lengths, f.tow_tension / 1e3, "o", ms=4, label="FMU static")
    ax[0].set_xlabel("deployed length [m]")
    ax[0].set_ylabel("tow tension [kN]")
    ax[1].plot(o.lengths, o.body_depth, "-", label="body depth, steady ODE")
    ax[1].plot(f.lengths, f.body_depth, "o", ms=4, label="body depth, FMU static")
    ax[1].plot(o.lengths, o.layback, "--", label="layback, steady ODE")
    ax[1].plot(f.lengths, f.layback, "s", ms=4, label="layback, FMU static")
    ax[1].set_xlabel("deployed length [m]")
    ax[1].set_ylabel("[m]")
    for a in ax:
        a.grid(alpha=0.3)
        a.legend()
    fig.tight_layout()
    fig.savefig(out / "references.png", dpi=120)
    plt.close(fig)


def main(argv=None) -> None:
    p = argparse.ArgumentParser(prog="scripts/winch_references", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--lengths", type=float, nargs=3, default=[50.0, 600.0, 25.0],
                   metavar=("FROM", "TO", "STEP"), help="deployed lengths [m] (default 50 600 25)")
    p.add_argument("--knots", type=float, default=2.0, help="tow speed [kn] (default 2)")
    p.add_argument("--element-length", type=float, default=15.0,
                   help="nominal element length of the FMU cables [m] (default 15)")
    p.add_argument("--out", type=Path, default=Path("out/winch_references"),
                   help="output directory (default out/winch_references)")
    a = p.parse_args(argv)
    start, stop, step = a.lengths
    lengths = np.arange(start, stop + 0.5 * step, step)
    refs = compute(lengths, a.knots, a.element_length, DeployBody())
    write(refs, a.out)
    print(markdown(refs))
    print(f"wrote {a.out}/references.csv and references.png")


if __name__ == "__main__":
    main()
