"""Hopland (1993) acceleration manoeuvre with the UnderwaterCable FMU (run via scripts/demo).

Steady tow at 1.1 kn along +x at the surface, linear ramp to 2.4 kn in 60 s, then 600 s more.
Writes a CSV and PNG plots (tow tension, end depth, cable shapes like the paper's Fig. 3).
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
from pathlib import Path

import numpy as np

from ucable.fmu import NUM_STATIONS, CableFMU
from ..cases.manoeuvre import SCALAR_OUTPUTS, hopland_accelerate, run_tow
from ucable.paths import REPO_ROOT, require_fmu
from ucable.progress import ProgressBar
from ucable.steady_tow import CableProperties, solve_steady_tow
from ucable.units import KNOT

SNAPSHOT_TIMES = [0, 30, 60, 120, 240, 420, 660]


def parse_args(argv):
    p = argparse.ArgumentParser(
        prog="scripts/demo",
        description="Fly the Hopland acceleration manoeuvre (1.1 kn -> 2.4 kn in 60 s, then 600 s) "
                    "with the UnderwaterCable FMU and plot tension, end depth and cable shapes.")
    p.add_argument("--step", type=float, default=0.5, help="communication step [s] (default 0.5)")
    p.add_argument("--out", type=Path, default=REPO_ROOT / "out" / "demo",
                   help="output directory (default out/demo)")
    p.add_argument("--nElements", type=int, default=20, help="number of cable elements (default 20)")
    p.add_argument("--v0", type=float, default=1.1, help="initial tow speed [kn] (default 1.1)")
    p.add_argument("--v1", type=float, default=2.4, help="final tow speed [kn] (default 2.4)")
    p.add_argument("--ramp", type=float, default=60.0, help="ramp duration [s] (default 60)")
    p.add_argument("--hold", type=float, default=600.0, help="time after the ramp [s] (default 600)")
    p.add_argument("--input-derivatives", action=argparse.BooleanOptionalAction, default=True,
                   help="also pass the tow acceleration via fmi2SetRealInputDerivatives (default on; "
                        "with --no-input-derivatives only position and velocity are sampled)")
    p.add_argument("--fmu", type=Path, default=None,
                   help="FMU file (default build/UnderwaterCable.fmu or $UC_FMU)")
    return p.parse_args(argv)


def write_csv(path: Path, run) -> None:
    header = (["time", "tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz"] + SCALAR_OUTPUTS
              + [f"{q}[{k}]" for q in ("shape.x", "shape.y", "shape.z", "tension")
                 for k in range(1, NUM_STATIONS + 1)])
    with path.open("w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        for i, t in enumerate(run.time):
            row = [t, *run.tow[i], *run.tow_velocity[i]]
            row += [run.outputs[name][i] for name in SCALAR_OUTPUTS]
            row += list(run.shape[i].ravel())
            w.writerow([f"{v:.10g}" for v in row])


def plot(out: Path, run, args, steady) -> list:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    files = []
    title = f"Hopland tow {args.v0:g} -> {args.v1:g} kn, {args.nElements} elements, step {args.step:g} s"

    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.plot(run.time, run["towTension"], label="FMU towTension")
    for s, ls in zip(steady, ("--", ":")):
        ax.axhline(s.top_tension, color="k", ls=ls, lw=0.8,
                   label=f"steady {s.speed / KNOT:g} kn (ODE): {s.top_tension:.0f} N")
    ax.set(xlabel="time [s]", ylabel="tow tension [N]", title=title)
    ax.grid(True, alpha=0.3)
    ax.legend()
    files.append(out / "tow_tension.png")
    fig.savefig(files[-1], dpi=120, bbox_inches="tight")
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.plot(run.time, -(run["endPosition.z"] - run.tow[:, 2]), label="FMU end depth")
    for s, ls in zip(steady, ("--", ":")):
        ax.axhline(s.end_depth, color="k", ls=ls, lw=0.8,
                   label=f"steady {s.speed / KNOT:g} kn (ODE): {s.end_depth:.1f} m")
    ax.set(xlabel="time [s]", ylabel="end depth below the tow point [m]", title=title)
    ax.invert_yaxis()
    ax.grid(True, alpha=0.3)
    ax.legend()
    files.append(out / "end_depth.png")
    fig.savefig(files[-1], dpi=120, bbox_inches="tight")
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(8, 6))
    for t in SNAPSHOT_TIMES:
        if t > run.time[-1] + 1e-9:
            continue
        i = int(np.argmin(np.abs(run.time - t)))
        x = run.shape[i, 0] - run.tow[i, 0]
        z = run.shape[i, 2] - run.tow[i, 2]
        ax.plot(x, z, marker=".", label=f"t = {run.time[i]:g} s")
    for s, ls in zip(steady, ("--", ":")):
        ax.plot(s.x, s.z, color="k", ls=ls, lw=0.8, label=f"steady {s.speed / KNOT:g} kn (ODE)")
    ax.set(xlabel="x relative to the tow point [m]", ylabel="z [m]", title=title, aspect="equal")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    files.append(out / "cable_shapes.png")
    fig.savefig(files[-1], dpi=120, bbox_inches="tight")
    plt.close(fig)
    return files


def main(argv=None) -> int:
    args = parse_args(sys.argv[1:] if argv is None else argv)
    if args.step <= 0:
        sys.exit("--step must be > 0")
    fmu = args.fmu if args.fmu is not None else require_fmu()
    args.out.mkdir(parents=True, exist_ok=True)

    profile, t_end = hopland_accelerate(args.v0, args.v1, args.ramp, args.hold)
    cable = CableFMU(fmu, parameters={"nElements": args.nElements})
    bar = ProgressBar(t_end, label="hopland")
    try:
        run = run_tow(cable, profile, t_end, args.step, progress=bar,
                      use_input_derivatives=args.input_derivatives)
    except Exception:
        if cable.messages:
            print(cable.log_text(), file=sys.stderr)
        raise
    finally:
        cable.free()
    bar.close(f"simulated {t_end:g} s in {len(run.time) - 1} communication steps")

    if not all(np.all(np.isfinite(v)) for v in run.outputs.values()):
        print("warning: non-finite outputs", file=sys.stderr)

    csv_path = args.out / "hopland_accelerate.csv"
    write_csv(csv_path, run)
    steady = [solve_steady_tow(v * KNOT, CableProperties()) for v in (args.v0, args.v1)]
    files = [csv_path] + plot(args.out, run, args, steady)

    T = run["towTension"]
    print(f"tow tension: start {T[0]:.1f} N, max {T.max():.1f} N, end {T[-1]:.1f} N "
          f"(steady ODE: {steady[0].top_tension:.1f} N at {args.v0:g} kn, "
          f"{steady[1].top_tension:.1f} N at {args.v1:g} kn)")
    print("wrote:")
    for f in files:
        print(f"  {f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
