"""A floating-wind mooring as a user brings it, loaded as it is: three semi-taut legs of chain and
polyester on a sloping seabed, one leg with a clump weight at its chain-polyester joint, one with a
buoy, in a JONSWAP sea with a sheared current; MoorPy's statics and MoorDyn's dynamics of the same
deck beside the FMU's, one table.

The deck (write_case) is a MoorDyn deck with its companions next to it, the way MoorDyn reads them:
`SeafloorFile` a grid of depths that is a plane rising along x (`SLOPE_DEG`), `WaveKin` 7 with
wave_frequencies.txt (the components of a JONSWAP spectrum, studies.references.sea), `Currents` 1 with
current_profile.txt (a sheared current across the x axis). The FMU gets the deck's name and nothing
else (`lineFile`: its seabed, waves and current come from the deck); the fairleads are the deck's
Vessel points, the FMU's body 1.

* statics in still water against MoorPy (its current is uniform only, so the comparison is of the deck
  written without waves and current), MoorPy told the slope (`xSlope`; its deck reader leaves
  `SeafloorFile` out): each line's fairlead and anchor tension;
* dynamics against MoorDyn v2 (PyPI `moordyn`): the platform in surge, heave and pitch
  (`MOTION`) in the waves and current, MoorDyn's free points
  started where MoorPy's still-water statics puts them and settled in the current by its own
  initial-condition generation: per line the fairlead tension's RMS difference (relative to MoorDyn's
  mean) and the difference of the peaks.

compute() returns the numbers, markdown() the section "A user's floating-wind deck" of
docs/systems_mooring.md. Used by scripts/user_trial and tests/python/test_user_trial.py.
"""

from __future__ import annotations

import argparse
import math
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU, FMICallException
from ucable.paths import fmu_path
from ucable.units import STANDARD_GRAVITY, WATER_DENSITY
from . import mooring_system as ms
from .waves_moordyn import wave_frequencies
from ..doc_section import write_section
from ..peers import moordyn, moorpy
from ..references.sea import sea_state

DEPTH = 150.0                  # [m] water depth at the origin (the platform)
SLOPE_DEG = 2.0                # [deg] the seabed rises along +x
FAIRLEAD_RADIUS, FAIRLEAD_Z = 40.0, -20.0
ANCHOR_RADIUS = 640.0
CHAIN_LENGTH = 250.0           # [m] from each anchor to its joint
POLYESTER_SLACK = 0.995        # polyester's unstretched length over the joint-fairlead distance
HEADINGS = (0.0, 120.0, 240.0)  # [deg] of the legs
CLUMP_MASS = 15000.0           # [kg] on leg 1's joint
BUOY_MASS, BUOY_VOLUME = 2000.0, 12.0  # [kg], [m3] on leg 2's joint
SEA = {"waves.mode": 2, "waves.height": 6.0, "waves.period": 11.0, "waves.gamma": 3.3, "waves.seed": 7,
       "waves.nComponents": 60, "waves.direction": math.radians(30.0), "waterDepth": DEPTH}
# z [m], uy [m/s]: 0.8 m/s at the surface, a power law of 1/7 down to 0.1 m/s at the seabed
CURRENT_ROWS = tuple((-z, 0.1 + 0.7 * (1.0 - z / 170.0) ** (1.0 / 7.0)) for z in (170.0, 150.0, 120.0, 90.0, 60.0,
                                                                                   30.0, 10.0, 0.0))
COMM_STEP = 0.1
DTM = 1e-3
# the platform from rest: a slow drift of 2 m over a minute, wave-frequency heave and pitch
MOTION = ms.PlatformMotion(surge=(2.0, 60.0), heave=(1.0, 11.0), pitch=(math.radians(2.0), 25.0))


def seabed_z(x: float, slope_deg: float = SLOPE_DEG) -> float:
    return -DEPTH + math.tan(math.radians(slope_deg)) * x


def _points(slope_deg: float = SLOPE_DEG) -> list:
    """(id, kind, x, y, z, mass, volume) of the deck's points: anchors 1-3, fairleads 4-6, joints 7-9."""
    rows = []
    for k, h in enumerate(HEADINGS):
        c, s = math.cos(math.radians(h)), math.sin(math.radians(h))
        x, y = ANCHOR_RADIUS * c, ANCHOR_RADIUS * s
        rows.append((k + 1, "Fixed", x, y, seabed_z(x, slope_deg), 0.0, 0.0))
    for k, h in enumerate(HEADINGS):
        c, s = math.cos(math.radians(h)), math.sin(math.radians(h))
        rows.append((k + 4, "Vessel", FAIRLEAD_RADIUS * c, FAIRLEAD_RADIUS * s, FAIRLEAD_Z, 0.0, 0.0))
    joints = ((CLUMP_MASS, 0.0), (BUOY_MASS, BUOY_VOLUME), (0.0, 0.0))
    for k, h in enumerate(HEADINGS):
        c, s = math.cos(math.radians(h)), math.sin(math.radians(h))
        r = ANCHOR_RADIUS - CHAIN_LENGTH
        rows.append((k + 7, "Free", r * c, r * s, seabed_z(r * c, slope_deg) + 1.0, *joints[k]))
    return rows


def _polyester_lengths(points: list) -> list:
    pos = {p[0]: np.array(p[2:5]) for p in points}
    return [POLYESTER_SLACK * float(np.linalg.norm(pos[k + 4] - pos[k + 7])) for k in range(3)]


def deck_text(waves: bool = True, current: bool = True, slope_deg: float = SLOPE_DEG, refine: int = 1) -> str:
    points = _points(slope_deg)
    poly = _polyester_lengths(points)
    point_rows = "\n".join(f"{i}  {kind}  {x:.17g}  {y:.17g}  {z:.17g}  {m:g}  {v:g}  0  0"
                           for i, kind, x, y, z, m, v in points)
    seafloor_row = "seafloor.txt  SeafloorFile  the seabed, a plane rising along x\n" if slope_deg else ""
    line_rows = "\n".join([f"{k + 1}  chain  {k + 1}  {k + 7}  {CHAIN_LENGTH:g}  {12 * refine}  -" for k in range(3)] +
                          [f"{k + 4}  polyester  {k + 7}  {k + 4}  {poly[k]:.4f}  {16 * refine}  -" for k in range(3)])
    dtm = DTM if refine == 1 else DTM / (1.25 * refine)
    return f"""--------------------- MoorDyn Input File ------------------------------------
A floating-wind semi-taut mooring: chain and polyester legs, a clump and a buoy, sloping seabed
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.216   288.0      1.23e9     -1.0        0          1.2    1.0    0.4     0.5
polyester  0.172   27.2       1.5e8      -1.0        0          2.0    1.0    0.4     0.0
---------------------- POINT PROPERTIES --------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
{point_rows}
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
{line_rows}
---------------------- OPTIONS -----------------------------------------
{dtm:g}        dtM         time step to use in mooring integration (s)
3.0e6         kBot        bottom stiffness (Pa/m)
3.0e5         cBot        bottom damping (Pa-s/m)
{WATER_DENSITY:g}        WtrDnsty    water density (kg/m^3)
{DEPTH:g}           WtrDpth     water depth (m)
{seafloor_row}400.0         TmaxIC      max time for ic gen (s)
4.0           CdScaleIC   factor by which to scale drag coefficients during dynamic relaxation (-)
1.0e-4        threshIC    threshold for IC convergence (-)
{7 if waves else 0}             WaveKin     wave components from wave_frequencies.txt
{1 if current else 0}             Currents    a steady current profile from current_profile.txt
------------------------- need this line --------------------------------------
"""


def seafloor_text(slope_deg: float, n: int = 15, half_width: float = 700.0) -> str:
    """MoorDyn's SeafloorFile: the numbers of x and y values, the x values, the y values, then x y z rows."""
    xs = np.linspace(-half_width, half_width, n)
    rows = [f"{n} {n}", " ".join(f"{x:.6f}" for x in xs), " ".join(f"{y:.6f}" for y in xs)]
    rows += [f"{x:.6f} {y:.6f} {seabed_z(x, slope_deg):.9f}" for x in xs for y in xs]
    return "\n".join(rows) + "\n"


def current_text() -> str:
    rows = "".join(f"{z:g} 0.0 {u:.6f} 0.0\n" for z, u in sorted(CURRENT_ROWS))
    return ("--------------------- MoorDyn steady currents File ----------------------------------\n"
            "a sheared current across the x axis\nz (m), ux (m/s), uy (m/s), uz (m/s)\n" + rows)


def write_case(directory: Path, waves: bool = True, current: bool = True, free_points: dict | None = None,
               slope_deg: float = SLOPE_DEG, name: str = "floating_wind.dat", refine: int = 1) -> Path:
    """The deck and its companions in `directory` (the seabed rising at slope_deg along x); free_points
    {id: (x, y, z)} replaces the deck's guesses; refine: NumSegs that many times the deck's, dtM divided by
    1.25 refine (the segments' axial wave crossing time shrinks with them)."""
    directory = Path(directory)
    text = deck_text(waves, current, slope_deg, refine)
    for i, r in (free_points or {}).items():
        old = next(line for line in text.splitlines() if line.startswith(f"{i}  Free"))
        text = text.replace(old, f"{i}  Free  {r[0]:.6f}  {r[1]:.6f}  {r[2]:.6f}  " + "  ".join(old.split()[5:]))
    path = directory / name
    path.write_text(text)
    (directory / "seafloor.txt").write_text(seafloor_text(slope_deg))
    (directory / "wave_frequencies.txt").write_text(wave_frequencies(sea_state(SEA)))
    (directory / "current_profile.txt").write_text(current_text())
    return path


# ----------------------------------------------------------------------------- statics
def moorpy_statics(path: Path, slope_deg: float) -> dict:
    """MoorPy's still-water equilibrium of the deck with the Vessel points on a body at the origin, told the
    slope (`xSlope`): per line (deck order) the tension at its end A and end B, the free points' positions."""
    s = moorpy.system(path, depth=DEPTH, rho=WATER_DENSITY, g=STANDARD_GRAVITY,
                      **({"xSlope": math.tan(math.radians(slope_deg)), "ySlope": 0.0} if slope_deg else {}))
    with moorpy.silenced():
        ms.attach_vessel_points(s, s.addBody(-1, np.zeros(6)))
        s.initialize()
        converged = s.solveEquilibrium(tol=1e-8, maxIter=2000)
    return {"A": [float(ln.TA) for ln in s.lineList], "B": [float(ln.TB) for ln in s.lineList],
            "points": {p.number: np.array(p.r, float) for p in s.pointList if p.type == 0},
            "converged": bool(converged is not False)}


def fmu_statics(fmu, path: Path) -> dict:
    """The FMU's start of the deck as it is (`lineFile` only): per line the anchor-side (end A) and
    fairlead-side (end B) tension and the log's warnings, or the refusal (`error`)."""
    c = CableFMU(fmu, parameters={"lineFile": str(path)}, logging_on=True)
    try:
        c.initialize()
        return {"A": [c.get(f"line[{k}].anchorTension") for k in range(1, 7)],
                "B": [c.get(f"line[{k}].fairleadTension") for k in range(1, 7)],
                "warnings": [text for _, status, text in c.messages if "Warning" in str(status)]}
    except FMICallException:
        return {"error": next((text for _, status, text in c.messages if "Error" in str(status)), "refused")}
    finally:
        c.free()


def moordyn_rest(path: Path, settle: float) -> dict:
    """MoorDyn's initial-condition generation, then `settle` seconds with the fairleads held: the forces on
    the fairleads (end B of lines 4-6) and the free points' positions."""
    deck = ms.read_system_deck(path)
    x = [float(v) for r in deck.fairleads for v in r]
    v = [0.0] * len(x)
    with moordyn.System(path, init=(x, v), also=_companions(path), chdir=True) as md:
        f = md.step(x, v, 0.0, 1e-12)
        t = 0.0
        while t < settle - 1e-9:
            f = md.step(x, v, t, 1.0)
            t += 1.0
        return {"B": list(np.linalg.norm(np.array(f).reshape(3, 3), axis=1)),
                "points": {k: np.array(md.point_position(md.point(k))) for k in (7, 8, 9)}}


def _companions(path: Path) -> list:
    return [path.parent / n for n in ("seafloor.txt", "wave_frequencies.txt", "current_profile.txt")]


# ----------------------------------------------------------------------------- dynamics
@dataclass
class Settings:
    t_end: float = 120.0
    t_from: float = 20.0   # statistics over t >= t_from (the first waves' start-up left out)
    settle: float = 100.0  # [s] MoorDyn's run to rest after its initial-condition generation
    moordyn_refine: int = 4  # MoorDyn at rest on NumSegs this many times the deck's (its mesh error: 4 % on leg 2)


def _fmu_history(fmu, path: Path, settings: Settings) -> ms.History:
    """The FMU given the deck's name only; the polyester lines 4-6 end at the fairleads."""
    return ms.fmu_motion(fmu, ms.read_system_deck(path), MOTION, settings.t_end, COMM_STEP,
                         accelerations=True, lines=[4, 5, 6], parameters={"lineFile": str(path)})


def _moordyn_history(path: Path, settings: Settings) -> ms.History:
    return ms.moordyn_motion(ms.read_system_deck(path), MOTION, settings.t_end, COMM_STEP,
                             per_step=False, also=_companions(path), chdir=True)


def _dynamics(fmu_h: ms.History, md_h: ms.History, t_from: float) -> dict:
    sel = fmu_h.t >= t_from - 1e-9
    diff = ms.rms_difference(fmu_h, md_h, t_from)
    peak_f, peak_m = fmu_h.fairlead[sel].max(axis=0), md_h.fairlead[sel].max(axis=0)
    return {"rms": diff["rms"], "rel_mean": diff["rel_mean"], "mean": diff["mean"],
            "peak_fmu": peak_f, "peak_moordyn": peak_m, "peak_diff": np.abs(peak_f / peak_m - 1.0),
            "cpu": {"fmu": fmu_h.cpu, "moordyn": md_h.cpu}, "info": {"fmu": fmu_h.info, "moordyn": md_h.info},
            "t": fmu_h.t, "fmu": fmu_h.fairlead, "moordyn": md_h.fairlead}


def compute(fmu, settings: Settings = Settings(), directory: Path | None = None) -> dict:
    """Every number of the section: still-water statics on a flat seabed (FMU, MoorPy, MoorDyn at rest) and on
    the deck's slope (FMU, MoorDyn at rest; MoorPy's answer told the slope beside them); dynamics in the waves
    and current against MoorDyn on each seabed where the FMU starts."""
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(directory or tmp)
        statics = {}
        for name, slope in (("flat", 0.0), ("slope", SLOPE_DEG)):
            still = write_case(work, waves=False, current=False, slope_deg=slope, name=f"floating_wind_{name}.dat")
            ref = moorpy_statics(still, slope)
            settled = write_case(work, waves=False, current=False, slope_deg=slope, free_points=ref["points"],
                                 name=f"floating_wind_{name}_moordyn.dat", refine=settings.moordyn_refine)
            statics[name] = {"fmu": fmu_statics(fmu, still), "moorpy": ref, "moordyn": moordyn_rest(settled,
                                                                                                    settings.settle)}
        dynamics = {}
        for name, slope in (("flat", 0.0), ("slope", SLOPE_DEG)):
            if "error" in statics[name]["fmu"]:
                continue  # the refusal is the FMU's answer; the table shows it
            full = write_case(work, slope_deg=slope, free_points=statics[name]["moorpy"]["points"],
                              name=f"floating_wind_{name}_sea.dat")
            dynamics[name] = _dynamics(_fmu_history(fmu, full, settings), _moordyn_history(full, settings),
                                       settings.t_from)
    return {"statics": statics, "dynamics": dynamics, "settings": settings}


# ----------------------------------------------------------------------------- Markdown
LEGS = ("1 (clump)", "2 (buoy)", "3")
SEABEDS = {"flat": "flat", "slope": f"{SLOPE_DEG:g} deg slope"}


def _pct(x: float) -> str:
    return f"{100.0 * x:+.2f} %"


def _kn(x: float) -> str:
    return f"{x / 1e3:.1f}"


def markdown(data: dict) -> str:
    st, dyn, se = data["statics"], data["dynamics"], data["settings"]
    out = ["Still water, the platform at rest: each leg's fairlead tension (the polyester's end B) and anchor "
           "tension (the chain's end A) [kN]. MoorDyn: its initial-condition generation from MoorPy's free "
           f"points, then {se.settle:g} s with the fairleads held, on {se.moordyn_refine} times the deck's NumSegs "
           "(it gives the fairleads' forces only).", "",
           "| seabed | leg | FMU fairlead | MoorPy | MoorDyn at rest | FMU - MoorPy | FMU - MoorDyn | FMU anchor | "
           "MoorPy | FMU - MoorPy |", "|---|---|---|---|---|---|---|---|---|---|"]
    refusals = []
    for name, label in SEABEDS.items():
        s = st[name]
        for j in range(3):
            mp_b, md_b, mp_a = s["moorpy"]["B"][j + 3], s["moordyn"]["B"][j], s["moorpy"]["A"][j]
            if "error" in s["fmu"]:
                ours = "refused | " + " | ".join([_kn(mp_b), _kn(md_b), "", "", "refused", _kn(mp_a), ""])
            else:
                b, a = s["fmu"]["B"][j + 3], s["fmu"]["A"][j]
                ours = " | ".join([_kn(b), _kn(mp_b), _kn(md_b), _pct(b / mp_b - 1.0), _pct(b / md_b - 1.0), _kn(a),
                                   _kn(mp_a), _pct(a / mp_a - 1.0)])
            out.append(f"| {label} | {LEGS[j]} | {ours} |")
        if "error" in s["fmu"]:
            refusals.append(f"On the {label} seabed the FMU refuses the deck: \"{s['fmu']['error']}\"")
        elif s["fmu"]["warnings"]:
            refusals.append(f"On the {label} seabed the FMU warns: " + "; ".join(s["fmu"]["warnings"]))
    out += ["", *refusals]
    if dyn:
        out += ["", f"In the waves (JONSWAP Hs {SEA['waves.height']:g} m, Tp {SEA['waves.period']:g} s, "
                f"{len(sea_state(SEA).omega)} components) and the sheared current, the platform in surge, heave and "
                f"pitch (from rest: a surge of {MOTION.surge[0]:g} m over {MOTION.surge[1]:g} s, heave {MOTION.heave[0]:g} m "
                f"over {MOTION.heave[1]:g} s, pitch {math.degrees(MOTION.pitch[0]):g} deg over {MOTION.pitch[1]:g} s, each "
                f"A (1 - cos)), over {se.t_from:g}-{se.t_end:g} s: each leg's fairlead tension [kN], the FMU against "
                "MoorDyn.", "",
                "| seabed | leg | MoorDyn mean | RMS difference / mean | peak FMU | peak MoorDyn | peak difference |",
                "|---|---|---|---|---|---|---|"]
        for name, d in dyn.items():
            for j in range(3):
                out.append(f"| {SEABEDS[name]} | {LEGS[j]} | {_kn(d['mean'][j])} | {100.0 * d['rel_mean'][j]:.2f} % | "
                           f"{_kn(d['peak_fmu'][j])} | {_kn(d['peak_moordyn'][j])} | "
                           f"{_pct(d['peak_fmu'][j] / d['peak_moordyn'][j] - 1.0)} |")
        out.append("")
        out += [f"CPU on the {SEABEDS[name]} seabed: FMU {d['cpu']['fmu']:.2f} s ({d['info']['fmu']}), MoorDyn "
                f"{d['cpu']['moordyn']:.1f} s ({d['info']['moordyn']})." for name, d in dyn.items()]
    return "\n".join(out)


def figure(data: dict, path: Path) -> None:  # pragma: no cover
    """The fairlead tensions in the waves, FMU against MoorDyn, a panel per leg and seabed."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    dyn = data["dynamics"]
    if not dyn:
        return
    fig, axes = plt.subplots(3, len(dyn), figsize=(6.5 * len(dyn), 7.5), sharex=True, squeeze=False)
    for col, (name, d) in enumerate(dyn.items()):
        for j in range(3):
            ax = axes[j][col]
            ax.plot(d["t"], d["moordyn"][:, j] / 1e3, color="0.6", lw=2.2, label="MoorDyn")
            ax.plot(d["t"], d["fmu"][:, j] / 1e3, color="C0", lw=1.0, label="FMU")
            ax.set_ylabel(f"leg {LEGS[j]} [kN]")
            ax.grid(alpha=0.3)
        axes[0][col].set_title(f"fairlead tension, {SEABEDS[name]} seabed")
        axes[-1][col].set_xlabel("time [s]")
    axes[0][0].legend(loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None) -> int:  # pragma: no cover
    ap = argparse.ArgumentParser(prog="scripts/user_trial", description=__doc__.split("\n\n")[0])
    ap.add_argument("--fmu", type=Path, default=None, help="the FMU (default: the build's)")
    ap.add_argument("--t-end", type=float, default=Settings.t_end, help="[s] of the dynamics (default %(default)s)")
    ap.add_argument("--doc", type=Path, help="write the section into this Markdown file (between its user_trial "
                    "markers) and the figure user_trial.png beside it")
    ap.add_argument("--keep", type=Path, help="write the decks and their companions into this directory")
    a = ap.parse_args(argv)
    if a.keep:
        a.keep.mkdir(parents=True, exist_ok=True)
    data = compute(a.fmu or fmu_path(), Settings(t_end=a.t_end), a.keep)
    text = markdown(data)
    print(text)
    if a.doc:
        write_section(a.doc, text, "user_trial")
        figure(data, a.doc.parent / "user_trial.png")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
