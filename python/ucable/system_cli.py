"""scripts/system: fly a manoeuvre with the three-FMU system vessel -> cable -> towed body.

Writes DIR/result.csv (one row per communication point; first columns time, towTension, body.x,
body.y, body.z: the towed body = the cable's far end, Earth frame, z up) and DIR/result.png.
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

from .fmu import FMICallException
from .paths import REPO_ROOT
from .progress import ProgressBar
from .system import COUPLINGS, MANOEUVRES, MASTERS, ORDERINGS, Body, Diverged, run


def parse_args(argv):
    p = argparse.ArgumentParser(
        prog="scripts/system", description=__doc__.split("\n")[0].split(": ", 1)[1],
        formatter_class=argparse.ArgumentDefaultsHelpFormatter,
        epilog="Couplings: internal = the body inside the cable FMU (bottomEnd 2); external = the TowedBody "
               "FMU supplies the body's hydrodynamic force with its velocity linearization and the cable "
               "FMU integrates the body (systems/towed_body/OspSystemStructure.xml); explicit = the "
               "TowedBody FMU integrates its own translation (the old coupling, unstable above a few "
               "hundredths of a second); proxy = the TowedBody FMU integrates its own translation and the cable "
               "FMU integrates a proxy with its inertia and returns the force that makes it follow "
               "(bottomEnd 4, systems/towed_body_proxy/OspSystemStructure.xml). Body values not given are scaled from the default body (400 kg, "
               "0.1 m3, 100 kg added mass, 0.3 m2 drag area) to --body-mass: same density, added mass a "
               "quarter of the mass, drag area with mass^(2/3).")
    p.add_argument("manoeuvre", choices=list(MANOEUVRES),
                   help="accelerate/decelerate: Hopland speed ramps; turn90/turn180: turns at 2.4 kn; stop; circle")
    p.add_argument("--step", type=float, default=0.5, help="communication step [s]")
    p.add_argument("--coupling", choices=COUPLINGS, default="external", help="how the towed body is coupled")
    p.add_argument("--master", choices=MASTERS, default="fmpy",
                   help="co-simulation master; newton: the reference iterating master (ucable.newton) for a body "
                        "that integrates itself (--coupling explicit)")
    p.add_argument("--body-fmu", type=Path, default=None, metavar="PATH",
                   help="with --coupling explicit: another body FMU that integrates itself, in place of the "
                        "TowedBody (its names: mass, addedMass, volume, CdA, CLA, position0.*, velocity0.*; input "
                        "cableForce.*; outputs position.*, velocity.*)")
    p.add_argument("--ordering", choices=ORDERINGS, default=None,
                   help="fmpy: gauss-seidel (cable first, then body and vessel) or jacobi; libcosim: jacobi "
                        "(default: gauss-seidel for fmpy, jacobi for libcosim)")
    p.add_argument("--body-mass", type=float, default=400.0, help="body mass in air [kg]")
    p.add_argument("--body-added-mass", type=float, default=None, help="body added mass [kg]")
    p.add_argument("--body-volume", type=float, default=None, help="body displaced volume [m3]")
    p.add_argument("--body-cda", type=float, default=None, help="body drag area [m2]")
    p.add_argument("--body-cla", type=float, default=0.0,
                   help="depressor lift area [m2] (lift 1/2 rho CLA |u_h|^2 downwards; external or explicit)")
    p.add_argument("--duration", type=float, default=None,
                   help="simulated time [s] (default per manoeuvre: "
                        + ", ".join(f"{k} {v[1]:g}" for k, v in MANOEUVRES.items()) + ")")
    p.add_argument("--input-derivatives", action=argparse.BooleanOptionalAction, default=True,
                   help="fmpy: pass the vessel's tow acceleration to the cable (fmi2SetRealInputDerivatives)")
    p.add_argument("--waves", type=int, choices=(0, 1, 2), default=0,
                   help="the sea of vessel and cable: 0 calm, 1 a regular wave (--hs is its height H, --tp its "
                        "period T), 2 JONSWAP; the vessel's RAO motion is superimposed on its manoeuvre")
    p.add_argument("--hs", type=float, default=2.0, help="wave height H or significant height Hs [m]")
    p.add_argument("--tp", type=float, default=8.0, help="wave period T or peak period Tp [s]")
    p.add_argument("--wave-direction", type=float, default=180.0,
                   help="direction the waves travel [deg from +x toward +y] (180: head seas at the start)")
    p.add_argument("--seed", type=int, default=1, help="seed of the irregular sea's phases")
    p.add_argument("--wave-ramp", type=float, default=20.0, help="time over which the sea grows from calm [s]")
    p.add_argument("--rao-file", default=None, metavar="PATH",
                   help="the vessel's RAO table (its parameter raoFile, docs/waves.md: a path or file:// URI, a "
                        "relative path looked up in the FMU's resources, then here; default the shipped generic "
                        "80 m vessel's); with --waves 1 or 2")
    p.add_argument("--out", type=Path, default=None, help="output directory (default out/system/<manoeuvre>)")
    return p.parse_args(argv)


def waves_of(args) -> dict | None:
    """The waves.* parameters of the command line (None in calm water: nothing is set)."""
    if args.waves == 0:
        return None
    return {"waves.mode": args.waves, "waves.height": args.hs, "waves.period": args.tp,
            "waves.direction": math.radians(args.wave_direction), "waves.seed": args.seed,
            "waves.rampTime": args.wave_ramp}


def write_csv(path: Path, columns: dict) -> None:
    from .tables import write_columns

    write_columns(path, columns)


def plot(path: Path, r, title: str) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    if "cable.line[1].fairleadTension" in r.values:  # a mooring system: its lines and the platform
        return plot_mooring(path, r, title)
    t, p = r.time, r.body_position
    fig, ax = plt.subplots(2, 2, figsize=(13, 8.5))
    a = ax[0, 0]
    a.plot(t, r["cable.towTension"] / 1e3, label="tow tension")
    a.plot(t, r["cable.endTension"] / 1e3, lw=0.8, label="tension at the body")
    a.set(xlabel="time [s]", ylabel="tension [kN]", title="cable tension")
    a.legend(fontsize=8)
    a = ax[0, 1]
    if "vessel.speed" in r.values:  # a manoeuvring vessel
        a.plot(t, r["vessel.speed"] / 0.5144444444444445, label="vessel speed [kn]")
        a.set(xlabel="time [s]", ylabel="speed [kn]", title="vessel speed and heading")
        a2 = a.twinx()
        a2.plot(t, np.degrees(r["vessel.heading"]), color="tab:red", lw=1)
        a2.set_ylabel("heading [deg]", color="tab:red")
    else:  # a vessel holding station in waves
        a.plot(t, r["vessel.tow.z"], label="tow point heave")
        a.set(xlabel="time [s]", ylabel="z [m]", title="tow point heave")
    a = ax[1, 0]
    a.plot(t, -p[:, 2], label="body depth")
    a.invert_yaxis()
    a.set(xlabel="time [s]", ylabel="depth [m]", title="towed body depth")
    a = ax[1, 1]
    ship = "vessel.x" if "vessel.x" in r.values else "vessel.tow.x"
    a.plot(r[ship], r[ship.replace(".x", ".y")], label="vessel")
    a.plot(p[:, 0], p[:, 1], label="towed body")
    a.set(xlabel="x [m]", ylabel="y [m]", title="plan view")
    a.set_aspect("equal", adjustable="datalim")
    a.legend(fontsize=8)
    save(fig, ax, path, title)


def save(fig, ax, path: Path, title: str) -> None:
    import matplotlib.pyplot as plt

    for a in ax.ravel():
        a.grid(True, alpha=0.3)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_mooring(path: Path, r, title: str) -> None:
    """A mooring system's result: each line's fairlead tension, the lines' force on the platform, the
    platform's motion (the vessel FMU's platform.*), its track in plan."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t, v = r.time, r.values
    fig, ax = plt.subplots(2, 2, figsize=(13, 8.5))
    a = ax[0, 0]
    k = 1
    while f"cable.line[{k}].fairleadTension" in v:
        a.plot(t, v[f"cable.line[{k}].fairleadTension"] / 1e3, label=f"line {k}")
        k += 1
    a.set(xlabel="time [s]", ylabel="fairlead tension [kN]", title="line tensions")
    a.legend(fontsize=8)
    a = ax[0, 1]
    for q in "xyz":
        a.plot(t, v[f"cable.body[1].force.{q}"] / 1e3, label=f"F{q}")
    a.set(xlabel="time [s]", ylabel="force [kN]", title="the lines' force on the platform")
    a.legend(fontsize=8)
    a = ax[1, 0]
    has_pose = "vessel.platform.x" in v
    if has_pose:
        for q in "xyz":
            a.plot(t, v[f"vessel.platform.{q}"], label=f"{q} [m]")
        a2 = a.twinx()
        for q, c in zip(("roll", "pitch", "yaw"), ("tab:red", "tab:purple", "tab:brown")):
            a2.plot(t, np.degrees(v[f"vessel.platform.{q}"]), ls=":", color=c, label=f"{q} [deg]")
        a2.set_ylabel("angles [deg] (dotted)")
        a2.legend(fontsize=8, loc="upper right")
    a.set(xlabel="time [s]", ylabel="position [m]", title="platform motion")
    a.legend(fontsize=8, loc="upper left")
    a = ax[1, 1]
    if has_pose:
        a.plot(v["vessel.platform.x"], v["vessel.platform.y"], color="k", label="platform track")
        a.plot(v["vessel.platform.x"][-1], v["vessel.platform.y"][-1], "k^")
    a.set(xlabel="x [m]", ylabel="y [m]", title="plan view")
    a.set_aspect("equal", adjustable="datalim")
    a.legend(fontsize=8)
    save(fig, ax, path, title)


def main(argv=None) -> int:
    args = parse_args(sys.argv[1:] if argv is None else argv)
    if not args.step > 0:
        sys.exit("--step must be > 0")
    ordering = args.ordering or ("jacobi" if args.master == "libcosim" else "gauss-seidel")
    if args.master == "libcosim" and ordering != "jacobi":
        sys.exit("libcosim's fixed-step algorithm is Jacobi: --ordering jacobi")
    if args.rao_file is not None and not args.waves:
        sys.exit("--rao-file needs --waves 1 or 2 (in calm water the vessel reads no RAO table)")
    body = Body(args.body_mass, args.body_added_mass, args.body_volume, args.body_cda, args.body_cla)
    duration = MANOEUVRES[args.manoeuvre][1] if args.duration is None else args.duration
    out = args.out if args.out is not None else REPO_ROOT / "out" / "system" / args.manoeuvre
    out.mkdir(parents=True, exist_ok=True)
    bar = ProgressBar(duration, label=args.manoeuvre)
    try:
        r = run(args.manoeuvre, args.step, args.coupling, args.master, ordering, body, duration,
                input_derivatives=args.input_derivatives, waves=waves_of(args),
                vessel_parameters=None if args.rao_file is None else {"raoFile": args.rao_file}, progress=bar,
                body_fmu=args.body_fmu)
    except (ValueError, FileNotFoundError) as e:
        sys.exit(f"scripts/system: {e}")
    except FMICallException as e:
        sys.exit(f"scripts/system: {e} (the FMU log above says why)")
    except Diverged as e:
        sys.exit(f"scripts/system: the co-simulation diverged: {e}")
    bar.close(f"simulated {duration:g} s in {len(r.time) - 1} steps, {r.cpu:.2f} s CPU")
    write_csv(out / "result.csv", r.columns())
    b = body.resolved()
    title = (f"{args.manoeuvre}: step {args.step:g} s, coupling {args.coupling}, {args.master} {ordering}; body "
             f"{b.mass:g} kg, {b.added_mass:g} kg added, {b.volume:g} m3, CdA {b.cda:.3g} m2")
    if args.waves:
        title += (f"; {('regular wave H', 'JONSWAP Hs')[args.waves - 1]} {args.hs:g} m, T {args.tp:g} s, "
                  f"travelling {args.wave_direction:g} deg")
    plot(out / "result.png", r, title)
    T, p = r["cable.towTension"], r.body_position
    print(f"tow tension: start {T[0]:.0f} N, min {np.nanmin(T):.0f} N, max {np.nanmax(T):.0f} N, end {T[-1]:.0f} N; "
          f"body depth {-p[0, 2]:.1f} -> {-p[-1, 2]:.1f} m")
    if r.stats:
        from .newton import summary
        print(summary(r))
    print(f"wrote:\n  {out / 'result.csv'}\n  {out / 'result.png'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
