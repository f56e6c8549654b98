"""scripts/outputs_figure: what the engineering outputs measure, drawn on two FMU statics.

Left: the mooring chain (anchored, partly on the seabed) in its vertical plane, with layback,
topDeclination, touchdownArcLength and groundedLength. Right: the same chain pulled taut (lifted off
the seabed) with anchorUplift, and the tow point's plan view with topAzimuth. compute() returns the
numbers, plot() draws them (docs/outputs.png).
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

from ..cases import mooring as M
from ucable.fmu import CableFMU
from ucable.paths import require_fmu

OUTPUTS = ["layback", "topDeclination", "topAzimuth", "anchorUplift", "touchdownArcLength", "groundedLength",
           "seabedContactForce", "towTension"]


def compute(fmu, fairlead_x: float) -> dict:
    with CableFMU(fmu, parameters=M.chain_params(20)) as c:
        c.initialize(inputs={"tow.x": fairlead_x, "tow.z": M.FAIRLEAD_Z})
        out = dict(zip(OUTPUTS, c.get_reals(OUTPUTS)))
        out.update(c.shape())
    return out


def plot(resting: dict, taut: dict, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(13, 5))
    for ax, r, title in ((axes[0], resting, "resting on the seabed"), (axes[1], taut, "lifted off (taut)")):
        x, z = r["shape.x"], r["shape.z"]
        ax.plot(x, z, "o-", color="tab:blue", ms=3, label="cable (21 stations)")
        ax.axhline(-M.DEPTH, color="saddlebrown", lw=2, label="seabed")
        ax.plot([x[0], x[-1]], [z[0] + 15, z[0] + 15], color="k", lw=1)
        ax.annotate("", xy=(x[-1], z[0] + 15), xytext=(x[0], z[0] + 15), arrowprops=dict(arrowstyle="<->"))
        ax.text(0.5 * (x[0] + x[-1]), z[0] + 22, f"layback {r['layback']:.0f} m", ha="center")
        # the tow point's declination from the downward vertical
        d = r["topDeclination"]
        ax.plot([x[0], x[0]], [z[0], z[0] - 80], "k--", lw=0.8)
        ax.plot([x[0], x[0] - 80 * math.sin(d)], [z[0], z[0] - 80 * math.cos(d)], "k-", lw=0.8)
        ax.text(x[0] - 40, z[0] - 95, f"topDeclination\n{math.degrees(d):.1f}° from the vertical", ha="center", fontsize=8)
        if r["anchorUplift"] == 0.0:
            s = np.linspace(0.0, M.CHAIN["length"], len(x))
            td = np.interp(r["touchdownArcLength"], s, x)
            ax.plot([td, x[-1]], [-M.DEPTH, -M.DEPTH], color="tab:red", lw=4,
                    label=f"groundedLength {r['groundedLength']:.1f} m")
            ax.plot(td, -M.DEPTH, "v", color="tab:red", ms=9,
                    label=f"touchdown at touchdownArcLength {r['touchdownArcLength']:.1f} m")
        else:
            u = r["anchorUplift"]
            ax.plot([x[-1], x[-1] + 150], [-M.DEPTH, -M.DEPTH], "k--", lw=0.8)
            ax.plot([x[-1], x[-1] + 150 * math.cos(u)], [-M.DEPTH, -M.DEPTH + 150 * math.sin(u)], "k-", lw=0.8)
            ax.text(x[-1] + 160, -M.DEPTH + 3, f"anchorUplift {math.degrees(u):.1f}° above the horizontal", fontsize=8)
        ax.set_title(f"Chain mooring, fairlead at x = {x[0]:.0f} m: {title}")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("z [m]")
        ax.legend(loc="center left", fontsize=8)
        ax.grid(alpha=0.3)
    # plan view of the tow point's azimuth
    inset = axes[1].inset_axes([0.6, 0.12, 0.37, 0.3])
    a = taut["topAzimuth"]
    inset.annotate("", xy=(math.cos(a), math.sin(a)), xytext=(0, 0), arrowprops=dict(arrowstyle="->", color="tab:blue"))
    inset.annotate("", xy=(1, 0), xytext=(0, 0), arrowprops=dict(arrowstyle="->", color="k"))
    inset.text(1.0, 0.08, "+x", fontsize=7)
    inset.text(-1.0, 0.25, f"topAzimuth {math.degrees(a):.0f}°\n(plan view, from +x to +y)", fontsize=7)
    inset.set_xlim(-1.2, 1.2)
    inset.set_ylim(-0.6, 0.6)
    inset.set_xticks([])
    inset.set_yticks([])
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="scripts/outputs_figure", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--png", type=Path, default=Path("docs/outputs.png"))
    a = ap.parse_args(argv)
    fmu = require_fmu()
    plot(compute(fmu, 0.0), compute(fmu, 14.0), a.png)
    print(f"wrote {a.png}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
