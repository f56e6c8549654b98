"""scripts/hockling: a twisted cable (torqueMode 2, 3 turns) whose tension is released forms a loop.

Writes out/hockling/hockling.csv (t, H, tow tension, max lateral deflection), shapes.csv (the
21 stations at the snapshot times) and hockling.png (shape in 3 views, H(t), tension(t)).
"""

from __future__ import annotations

import argparse
import csv
from pathlib import Path

import numpy as np

from ucable.paths import require_fmu
from ucable.progress import ProgressBar
from ..cases.torsion import DEPTH, run_hockling


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="scripts/hockling", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--slack", type=float, default=1.5, help="tow-point travel toward the anchor [m]")
    ap.add_argument("--ramp", type=float, default=60.0, help="duration of the travel [s]")
    ap.add_argument("--hold", type=float, default=60.0, help="hold after the travel [s]")
    ap.add_argument("--turns", type=float, default=3.0, help="prescribed end rotation [turns]")
    ap.add_argument("--elements", type=int, default=40)
    ap.add_argument("--step", type=float, default=0.1, help="communication step [s]")
    ap.add_argument("--out", type=Path, default=Path("out/hockling"))
    ap.add_argument("--png", type=Path, default=None, help="also copy the plot here (e.g. docs/)")
    a = ap.parse_args(argv)
    t_end = a.ramp + a.hold
    snaps = [0.0, 0.25 * a.ramp, 0.5 * a.ramp, 0.75 * a.ramp, a.ramp, t_end]
    bar = ProgressBar(t_end, "hockling")
    r = run_hockling(require_fmu(), slack=a.slack, ramp=a.ramp, hold=a.hold, step=a.step,
                     turns=a.turns, n_elements=a.elements, snapshot_times=snaps,
                     progress=lambda t: bar.update(t, f"t = {t:.1f} s"))
    bar.close(f"done: {r.cpu:.2f} s CPU")
    a.out.mkdir(parents=True, exist_ok=True)
    with open(a.out / "hockling.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["t_s", "cableTorque_Nm", "towTension_N", "maxLateral_m"])
        for row in zip(r.t, r.torque, r.tow_tension, r.max_lateral):
            w.writerow([f"{v:.9g}" for v in row])
    with open(a.out / "shapes.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["t_s", "station", "x_m", "y_m", "z_m"])
        for t, (x, y, z) in sorted(r.shapes.items()):
            for k in range(len(x)):
                w.writerow([f"{t:g}", k + 1, f"{x[k]:.9g}", f"{y[k]:.9g}", f"{z[k]:.9g}"])
    print(f"H: {r.torque[0]:.2f} -> {r.torque[-1]:.2f} N.m (min {r.torque.min():.2f}), "
          f"tow tension {r.tow_tension[0]:.1f} -> {r.tow_tension[-1]:.2f} N, "
          f"max lateral deflection {r.max_lateral.max():.3f} m, CPU {r.cpu:.2f} s")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 3, figsize=(14, 8))
    views = [("x", "y", 0, 1), ("x", "z", 0, 2), ("y", "z", 1, 2)]
    for (h, v, i, j), axis in zip(views, ax[0]):
        for t, xyz in sorted(r.shapes.items()):
            pts = [xyz[0], xyz[1], xyz[2] - DEPTH]
            axis.plot(pts[i], pts[j], ".-", label=f"t = {t:g} s")
        axis.set_xlabel(f"{h} [m]")
        axis.set_ylabel(f"{v} [m]" + (" (from -50 m)" if v == "z" else ""))
        axis.set_aspect("equal", adjustable="datalim")
        axis.grid(True)
    ax[0][0].legend(fontsize=7)
    ax[1][0].plot(r.t, r.torque)
    ax[1][0].set_ylabel("cableTorque H [N.m]")
    ax[1][1].plot(r.t, r.tow_tension)
    ax[1][1].set_ylabel("towTension [N]")
    ax[1][2].plot(r.t, r.max_lateral)
    ax[1][2].set_ylabel("max lateral deflection [m]")
    for axis in ax[1]:
        axis.set_xlabel("t [s]")
        axis.grid(True)
    fig.suptitle(f"Hockling: {a.turns:g} turns, tow point moved {a.slack:g} m toward the anchor "
                 f"in {a.ramp:g} s, held {a.hold:g} s ({a.elements} elements)")
    fig.tight_layout()
    fig.savefig(a.out / "hockling.png", dpi=90)
    if a.png:
        fig.savefig(a.png, dpi=90)
    print(f"wrote {a.out}/hockling.csv, shapes.csv, hockling.png" + (f", {a.png}" if a.png else ""))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
