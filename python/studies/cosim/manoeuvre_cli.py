"""Co-simulation manoeuvres of a survey vessel towing the UnderwaterCable FMU (scripts/manoeuvre).

Writes out/manoeuvre/<name>/<name>.csv (one row per communication point) and two PNG figures:
<name>_time.png (tow tension, speed and heading, far-end depth, plan-view tracks) and
<name>_shapes.png (cable shapes at several times in the vertical plane and in plan view, like the
paper's Figs. 3-4).

The scene heave-lowering (studies.cases.heave_lowering) is a body hanging from the VesselRAO FMU in waves:
heave-lowering.csv and heave-lowering.png (tensions, snap events, motions).
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

from ..cases import heave_lowering, winch_scenes
from .masters import CABLE_OUTPUTS, COUPLINGS, MASTERS, run_scene
from ucable.fmu import NUM_STATIONS
from .partners import TowedBodyParameters
from ucable.paths import REPO_ROOT, require_fmu
from ucable.progress import ProgressBar
from .scenes import (DEFAULT_T_END, NAMES, PAPER_SETTLE, RAMP, SNAPSHOTS, SPEEDS_KN, make_scene,
                     settling_time, steady_depths)
from ucable.steady_tow import solve_steady_tow
from ucable.units import KNOT

EPS_LIST = (0.10, 0.05, 0.02, 0.01)
HEAVE_LOWERING = "heave-lowering"


def parse_args(argv):
    p = argparse.ArgumentParser(
        prog="scripts/manoeuvre",
        description="Fly a tow manoeuvre: a 50 t survey vessel (3 DOF, speed/heading autopilot) "
                    "towing the 300 m Hopland cable (UnderwaterCable FMU) through fmpy, "
                    "Gauss-Seidel coupling. Manoeuvres: " + ", ".join(NAMES) + ".",
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    p.add_argument("name", choices=NAMES + (HEAVE_LOWERING,) + winch_scenes.SCENES,
                   help="manoeuvre; deploy / recover: a towed body paid out 50 -> 600 m / hauled in 600 -> 50 m at "
                        "2 kn by the winch; ct-lowering: a 2 t body lowered by the constant-tension winch in heave; "
                        f"or {HEAVE_LOWERING}: a 2 t body on 500 m of umbilical hanging from an 80 m "
                        "vessel (VesselRAO FMU) in a JONSWAP sea")
    p.add_argument("--step", type=float, default=None,
                   help=f"communication step [s] (default 0.5; {HEAVE_LOWERING} 0.2)")
    p.add_argument("--nElements", type=int, default=20, help="cable elements")
    p.add_argument("--t-end", type=float, default=None,
                   help="simulated time [s] (default per manoeuvre: "
                        + ", ".join(f"{k} {v:g}" for k, v in DEFAULT_T_END.items())
                        + f", {HEAVE_LOWERING} {heave_lowering.DEFAULT_T_END:g})")
    p.add_argument("--body", choices=COUPLINGS, default="none",
                   help="towed body (400 kg, 0.1 m3, 0.3 m2 drag area): none = free cable end, "
                        "internal = FMU bottomEnd 2, external = Python body via end.* (bottomEnd 3)")
    p.add_argument("--master", choices=MASTERS, default="gauss-seidel")
    p.add_argument("--input-derivatives", action=argparse.BooleanOptionalAction, default=True,
                   help="pass tow (and body) accelerations via fmi2SetRealInputDerivatives")
    p.add_argument("--hs", type=float, default=3.0, help=f"{HEAVE_LOWERING}: significant wave height [m]")
    p.add_argument("--tp", type=float, default=9.0, help=f"{HEAVE_LOWERING}: peak period [s]")
    p.add_argument("--seed", type=int, default=1, help=f"{HEAVE_LOWERING}: waves.seed")
    p.add_argument("--components", type=int, default=200, help=f"{HEAVE_LOWERING}: waves.nComponents")
    p.add_argument("--rao-file", default="", metavar="PATH",
                   help=f"{HEAVE_LOWERING}: the vessel's RAO table (raoFile of the VesselRAO FMU, docs/waves.md: a "
                        "path or file:// URI; default the shipped generic 80 m vessel's)")
    p.add_argument("--out", type=Path, default=None, help="output directory (default out/manoeuvre/<name>)")
    p.add_argument("--fmu", type=Path, default=None, help="FMU (default build/UnderwaterCable.fmu or $UC_FMU)")
    return p.parse_args(argv)


def csv_columns():
    return (["time", "vessel.x", "vessel.y", "vessel.psi", "vessel.u", "vessel.v", "vessel.r",
             "vessel.speedIntegral", "thrust", "tow.x", "tow.y", "tow.z"] + CABLE_OUTPUTS
            + [f"body.{q}" for q in ("x", "y", "z", "vx", "vy", "vz")]
            + [f"{q}[{k}]" for q in ("shape.x", "shape.y", "shape.z", "tension")
               for k in range(1, NUM_STATIONS + 1)])


def write_csv(path: Path, r) -> None:
    n = len(r.time)
    body = r.body if r.body is not None else np.full((n, 6), np.nan)
    data = np.column_stack([r.time, r.vessel, r.thrust, r.tow]
                           + [r.cable[c] for c in CABLE_OUTPUTS]
                           + [body, r.shape.reshape(n, -1)])
    np.savetxt(path, data, delimiter=",", header=",".join(csv_columns()), comments="", fmt="%.10g")


def settle_report(name, r):
    if name not in SPEEDS_KN:
        return None
    d0, d1 = steady_depths(name)
    return {eps: settling_time(r.time, r.end_depth, d0, d1, eps) for eps in EPS_LIST}, (d0, d1)


def _equal_with_min_span(ax, span):
    """Equal axis scales; a straight track along x still gets a y range of `span`."""
    (x0, y0), (_, y1) = ax.dataLim.get_points()
    if y1 - y0 < span:
        mid = 0.5 * (y0 + y1)
        ax.update_datalim([(x0, mid - span / 2), (x0, mid + span / 2)])
        ax.autoscale_view()
    ax.set_aspect("equal", adjustable="datalim")


def plot(out: Path, name: str, r, args, settle) -> list:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    sc = r.scene
    title = (f"{name}: {sc.n_elements} elements, step {sc.step:g} s, body {sc.coupling}, "
             f"{sc.master}")
    files = []
    t = r.time
    fig, ax = plt.subplots(2, 2, figsize=(13, 8.5))
    a = ax[0, 0]
    a.plot(t, r["towTension"] / 1e3, label="tow tension (FMU)")
    if sc.coupling != "none":
        a.plot(t, r["endTension"] / 1e3, lw=0.8, label="far-end (towed body) tension")
    if name in SPEEDS_KN and sc.coupling == "none":
        for v, ls in zip(SPEEDS_KN[name], ("--", ":")):
            a.axhline(solve_steady_tow(v * KNOT).top_tension / 1e3, color="k", ls=ls, lw=0.8,
                      label=f"steady {v:g} kn (ODE)")
    a.set(xlabel="time [s]", ylabel="tension [kN]", title="tension")
    a.legend(fontsize=8)

    a = ax[0, 1]
    a.plot(t, r.speed / KNOT, label="vessel speed")
    a.plot(t, [sc.speed.speed(x) / KNOT for x in t], "k--", lw=0.8, label="speed order")
    a.set(xlabel="time [s]", ylabel="speed [kn]", title="speed and heading",
          ylim=(0.0, 1.15 * max(3.0, float(np.max(r.speed / KNOT)))))
    a2 = a.twinx()
    a2.plot(t, np.degrees(r.vessel[:, 2]), color="tab:red", lw=1, label="heading")
    a2.set_ylabel("heading [deg]", color="tab:red")
    lo, hi = a2.get_ylim()
    if hi - lo < 20.0:
        a2.set_ylim(-10.0, 10.0)
    a.legend(loc="center right", fontsize=8)

    a = ax[1, 0]
    a.plot(t, r.end_depth, label="far-end depth below tow point")
    if settle is not None:
        sett, (d0, d1) = settle
        for d, ls in zip((d0, d1), ("--", ":")):
            a.axhline(d, color="k", ls=ls, lw=0.8)
        band = 0.01 * abs(d1 - d0)
        a.axhspan(d1 - band, d1 + band, color="g", alpha=0.2, label="final steady ±1 % of change")
        ts = sett[0.01]
        if math.isfinite(ts):
            a.axvline(RAMP + ts, color="g", lw=1, label=f"settled (1 %): {ts:.0f} s after ramp")
        a.axvline(RAMP + PAPER_SETTLE[name], color="m", ls="--", lw=1,
                  label=f"paper: {PAPER_SETTLE[name]:.0f} s after ramp")
    a.invert_yaxis()
    a.set(xlabel="time [s]", ylabel="depth [m]", title="far-end depth")
    a.legend(fontsize=8)

    a = ax[1, 1]
    a.plot(r.vessel[:, 0], r.vessel[:, 1], label="vessel")
    a.plot(r["endPosition.x"], r["endPosition.y"], label="cable far end")
    a.set(xlabel="x [m]", ylabel="y [m]", title="plan view tracks")
    _equal_with_min_span(a, 200.0)
    a.legend(fontsize=8)
    for a in ax.ravel():
        a.grid(True, alpha=0.3)
    fig.suptitle(title)
    fig.tight_layout()
    files.append(out / f"{name}_time.png")
    fig.savefig(files[-1], dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(1, 2, figsize=(14, 6))
    cmap = plt.get_cmap("viridis")
    snaps = [s for s in SNAPSHOTS[name] if s <= t[-1] + 1e-9]
    for j, ts in enumerate(snaps):
        i = int(np.argmin(np.abs(t - ts)))
        col = cmap(j / max(1, len(snaps) - 1))
        sx, sy, sz = r.shape[i, 0], r.shape[i, 1], r.shape[i, 2]
        dist = -np.hypot(sx - sx[0], sy - sy[0])
        ax[0].plot(dist, sz, marker=".", ms=3, color=col, label=f"t = {t[i]:g} s")
        ax[1].plot(sx, sy, marker=".", ms=3, color=col, label=f"t = {t[i]:g} s")
        ax[1].plot(sx[0], sy[0], "k^", ms=5)
    ax[1].plot(r.vessel[:, 0], r.vessel[:, 1], "k:", lw=0.7, label="vessel track")
    ax[0].set(xlabel="horizontal distance behind the tow point [m]", ylabel="z [m]",
              title="cable shapes, vertical plane", aspect="equal")
    ax[1].set(xlabel="x [m]", ylabel="y [m]", title="cable shapes, plan view (tow point ▲)")
    _equal_with_min_span(ax[1], 200.0)
    for a in ax:
        a.grid(True, alpha=0.3)
        a.legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    files.append(out / f"{name}_shapes.png")
    fig.savefig(files[-1], dpi=110)
    plt.close(fig)
    return files


def main_heave_lowering(args, fmu, out: Path) -> int:
    scene = heave_lowering.HeaveLoweringCase(
        t_end=heave_lowering.DEFAULT_T_END if args.t_end is None else args.t_end,
        step=0.2 if args.step is None else args.step, n_elements=args.nElements, hs=args.hs, tp=args.tp,
        seed=args.seed, components=args.components, rao_file=args.rao_file)
    bar = ProgressBar(scene.t_end, label=args.name)
    r = heave_lowering.run(scene, fmu, progress=bar.update)
    bar.close(f"simulated {scene.t_end:g} s in {len(r.time) - 1} steps, {r.cpu:.2f} s CPU "
              f"(real-time factor {scene.t_end / r.cpu:.0f})")
    files = [out / f"{args.name}.csv", out / f"{args.name}.png"]
    heave_lowering.write_csv(files[0], r)
    heave_lowering.plot(files[1], r)
    s = r.summary()
    print(f"tow tension: min {s['towTension_min'] / 1e3:.1f} kN, max {s['towTension_max'] / 1e3:.1f} kN, "
          f"mean {s['towTension_mean'] / 1e3:.1f} kN, std {s['towTension_std'] / 1e3:.2f} kN (after the ramp); "
          f"least axial force {s['minTension_min'] / 1e3:.1f} kN, snap events {s['snap_events']}")
    print(f"heave std after the ramp: top {s['tow_heave_std']:.2f} m, body {s['body_heave_std']:.2f} m (about its "
          f"lowering); lowered {s['lowered']:.1f} m, the body {s['body_depth_final']:.1f} m deep")
    print("wrote:\n  " + "\n  ".join(str(f) for f in files))
    return 0


def main_winch(args, fmu, out: Path) -> int:
    bar = ProgressBar(winch_scenes.duration(args.name), label=args.name)
    r = winch_scenes.run(args.name, fmu, step=args.step, progress=bar.update)
    bar.close(f"simulated {r.time[-1]:g} s, {r.cpu:.2f} s CPU (real-time factor {r.time[-1] / r.cpu:.0f})")
    files = [out / f"{args.name}.csv", out / f"{args.name}.png"]
    winch_scenes.write_csv(files[0], r)
    winch_scenes.plot(files[1], r)
    for key, value in winch_scenes.summary(r).items():
        print(f"{key}: {value:.6g}")
    print("wrote:\n  " + "\n  ".join(str(f) for f in files))
    return 0


def main(argv=None) -> int:
    args = parse_args(sys.argv[1:] if argv is None else argv)
    if args.step is not None and args.step <= 0:
        sys.exit("--step must be > 0")
    fmu = args.fmu if args.fmu is not None else require_fmu()
    out = args.out if args.out is not None else REPO_ROOT / "out" / "manoeuvre" / args.name
    out.mkdir(parents=True, exist_ok=True)
    if args.name == HEAVE_LOWERING:
        return main_heave_lowering(args, fmu, out)
    if args.name in winch_scenes.SCENES:
        return main_winch(args, fmu, out)
    if args.step is None:
        args.step = 0.5
    scene = make_scene(args.name, t_end=args.t_end, step=args.step, n_elements=args.nElements,
                       coupling=args.body, master=args.master, body=TowedBodyParameters(),
                       input_derivatives=args.input_derivatives)
    bar = ProgressBar(scene.t_end, label=args.name)
    r = run_scene(scene, fmu, progress=bar)
    bar.close(f"simulated {scene.t_end:g} s in {len(r.time) - 1} steps, {r.cpu:.2f} s CPU "
              f"(real-time factor {scene.t_end / r.cpu:.0f})")
    for key, v in r.cable.items():
        if not np.all(np.isfinite(v)):
            print(f"warning: {key} has non-finite values", file=sys.stderr)

    csv_path = out / f"{args.name}.csv"
    write_csv(csv_path, r)
    settle = settle_report(args.name, r) if args.body == "none" else None
    files = [csv_path] + plot(out, args.name, r, args, settle)
    T = r["towTension"]
    print(f"tow tension: start {T[0]:.0f} N, min {T.min():.0f} N, max {T.max():.0f} N, "
          f"end {T[-1]:.0f} N; far-end depth {r.end_depth[0]:.1f} -> {r.end_depth[-1]:.1f} m")
    if settle is not None:
        sett, (d0, d1) = settle
        print(f"settling time after the ramp (end depth {d0:.1f} -> {d1:.1f} m steady): "
              + ", ".join(f"{100 * e:g} %: {s:.0f} s" for e, s in sett.items())
              + f"  (paper: {PAPER_SETTLE[args.name]:.0f} s)")
    print("wrote:\n  " + "\n  ".join(str(f) for f in files))
    return 0


if __name__ == "__main__":
    sys.exit(main())
