"""Free points where three or more lines meet (docs/systems_mooring.md, "Free points where several lines
meet"): the statics of a subsurface buoy on three legs 120 degrees apart (tests/data/decks/subsurface_buoy.dat)
and of a bridle against MoorPy fed the same deck.

MoorPy solves the free points' equilibrium with its quasi-static catenaries; its current acts on the lines
(their drag lumped into a uniform load that tilts each catenary's plane) but not on points, so a point's
drag in a current is given to MoorPy as the constant external force it is on a point at rest.

Used by tests/python/test_free_points.py.
"""

from __future__ import annotations

import re
import time
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.units import WATER_DENSITY
from ..peers import moordyn, moorpy
from .mooring_system import DECKS, _moorpy_system, fmu_parameters, read_system_deck

BUOY = DECKS / "subsurface_buoy.dat"
BUOY_BODY = DECKS / "subsurface_buoy_body.dat"  # the buoy as a Free body, the legs on its rim


def without_line_drag(text: str) -> str:
    """The deck with every line type's drag coefficients (Cd, CdAx) set to 0: in a current only the
    points' drag acts."""
    lines = text.splitlines()
    start = next(i for i, s in enumerate(lines) if "LINE TYPES" in s.upper())
    end = next(i for i in range(start + 1, len(lines)) if lines[i].lstrip().startswith("---"))
    for i in range(start + 3, end):
        f = lines[i].split()
        if len(f) >= 10:
            f[6] = "0.0"  # Cd
            f[8] = "0.0"  # CdAx
            lines[i] = "  ".join(f)
    return "\n".join(lines) + "\n"


def free_point_ids(path: Path) -> list:
    """IDs of the deck's Free points that hold a line (whatever number of lines meet there: all have
    point[k].position.*)."""
    s = _moorpy_system(path)
    return [p.number for p in s.pointList if p.type == 0 and len(p.attached) >= 1]


def free_bodies(path: Path) -> dict:
    """The deck's Free bodies: {ID: [the positions of the points on it in its frame]}."""
    s = _moorpy_system(path)
    return {b.number: [np.array(r, float) for r in b.rPointRel] for b in s.bodyList if b.type == 0}


def _fmu_rotation(roll, pitch, yaw):  # R = Rx Ry Rz (MoorDyn's, the FMU's)
    from .mooring_system import body_rotation
    return body_rotation(roll, pitch, yaw)


def _body_points(pose, rotation, local) -> list:
    R = rotation(*pose[3:])
    return [np.asarray(pose[:3]) + R @ r for r in local]


def _current(current) -> np.ndarray:
    """A uniform current: a speed along x, or its (x, y) components."""
    c = np.atleast_1d(np.asarray(current, float))
    return np.array([c[0], c[1] if len(c) > 1 else 0.0, 0.0])


def moorpy_statics(path: Path, current=0.0) -> dict:
    """MoorPy's equilibrium of the deck's free points and bodies, the deck's Vessel points where the deck
    puts them, in a uniform current (along x, or (x, y)): each free point's position, each free body's pose and the
    positions of the points on it, each line's tension at AttachB (the fairlead side in the decks here)
    and AttachA. A body's drag in the current is given to MoorPy as a force at its reference point (its drag
    areas in its axes at the deck's orientation), and its buoyancy is placed at its centre of gravity, as
    MoorDyn v2 applies a body's weight and buoyancy."""
    deck = read_system_deck(path)
    s = _moorpy_system(path, deck.depth)
    U = _current(current)
    with moorpy.silenced():
        if U.any():
            s.currentMod = 1
            s.current = U
        for p in s.pointList:  # the point's drag at rest in the current (MoorPy has none on points)
            if p.type == 0:
                p.fExt = 0.5 * WATER_DENSITY * p.CdA * np.linalg.norm(U) * U
        for b in s.bodyList:
            if b.type == 0:
                b.rM = np.array(b.rCG, float)  # MoorDyn's buoyancy acts at the centre of gravity (MoorPy's at rM)
                R = _fmu_rotation(*np.asarray(b.r6[3:], float))
                drag = 0.5 * WATER_DENSITY * np.linalg.norm(U) * R @ (np.asarray(b.CdA, float)[:3] * (R.T @ U))
                b.f6Ext = np.concatenate([drag, np.zeros(3)])
        s.initialize()
        for _ in range(3):  # MoorPy's line drag is that of the previous solution: iterate it to its fixed point
            s.solveEquilibrium(tol=1e-8, maxIter=2000)
    points = {p.number: np.array(p.r, float) for p in s.pointList}
    bodies = free_bodies(path)
    poses = {b.number: np.array(b.r6, float) for b in s.bodyList if b.number in bodies}
    points = {k: points[k] for k in free_point_ids(path)}
    for k, local in bodies.items():
        for j, x in enumerate(_body_points(poses[k], moorpy.rotation, local)):
            points[f"body{k}.{j}"] = x
    return {"points": points, "poses": poses,
            "fairlead": [float(ln.TB) for ln in s.lineList], "anchor": [float(ln.TA) for ln in s.lineList]}


def fmu_statics(fmu, path: Path, current=0.0, **extra) -> dict:
    """The FMU's static start (initMode 0) of the deck in a uniform current (along x, or (x, y))."""
    deck = read_system_deck(path)
    U = _current(current)
    with CableFMU(fmu, parameters={**fmu_parameters(deck), "lineFile": str(path), **extra}) as c:
        c.initialize(inputs={"current.x": U[0], "current.y": U[1]})
        points = {k: np.array([c.get(f"point[{k}].position.{a}") for a in "xyz"]) for k in free_point_ids(path)}
        poses = {k: np.array([c.get(f"body[{k}].pose.{a}") for a in ("x", "y", "z", "roll", "pitch", "yaw")])
                 for k in free_bodies(path)}
        for k, local in free_bodies(path).items():
            for j, x in enumerate(_body_points(poses[k], _fmu_rotation, local)):
                points[f"body{k}.{j}"] = x
        return {"points": points, "poses": poses,
                "fairlead": [c.get(f"line[{k}].fairleadTension") for k in range(1, deck.lines + 1)],
                "anchor": [c.get(f"line[{k}].anchorTension") for k in range(1, deck.lines + 1)]}


def compare(ours: dict, ref: dict) -> dict:
    """Largest distance between the free points' (and the free bodies' points') positions [m] and largest
    relative tension difference."""
    distance = max(float(np.linalg.norm(ours["points"][k] - ref["points"][k])) for k in ref["points"])
    tension = max(abs(a - b) / b for key in ("fairlead", "anchor") for a, b in zip(ours[key], ref[key]))
    return {"distance": distance, "tension": float(tension)}


def write_variant(path: Path, directory: Path, edit) -> Path:
    """The deck with `edit` applied to its text, written into directory."""
    out = Path(directory) / path.name
    out.write_text(edit(Path(path).read_text()))
    return out


def bridle(text: str) -> str:
    """The OC4 deck with its fairlead point 4 made a Free point where lines 1 and 2 (to two anchors) and a
    pennant of 70 m to the platform's point 5 meet."""
    text = text.replace("4      Vessel    20.434   35.393   -14.0", "4      Free      20.434   35.393   -60.0", 1)
    text = text.replace("2         main        2         5", "2         main        2         4", 1)
    return re.sub(r"(3         main        3         6       835.35     20        -)",
                  r"\1\n4         main        4         5       70.0       4         -", text, count=1)


# ----------------------------------------------------------------------------- dynamics: a release
def displaced_deck(path: Path, directory: Path, point: int, position) -> Path:
    """The deck with free point `point` placed at `position` and TmaxIC 0: MoorDyn starts it there at rest
    without generating initial conditions, and so does the FMU (each line in its static shape with its
    ends there)."""
    text = Path(path).read_text()
    row = re.search(rf"^{point}(\s+)Free\s+\S+\s+\S+\s+\S+(.*)$", text, flags=re.M)
    x, y, z = position
    text = text[:row.start()] + f"{point}{row.group(1)}Free {x:.6f} {y:.6f} {z:.6f}{row.group(2)}" + text[row.end():]
    text = re.sub(r"^\S+(\s+TmaxIC)", r"0.0\1", text, flags=re.M | re.I)
    out = Path(directory) / f"{Path(path).stem}_released{Path(path).suffix}"
    out.write_text(text)
    return out


def refined_deck(path: Path, directory: Path, segments: int) -> Path:
    """The deck with every line in `segments` segments and MoorDyn's time step dtM scaled from 1 ms at 20
    segments (its explicit integration's stability limit shrinks with the segments' length)."""
    text = Path(path).read_text()
    lines = text.splitlines()
    start = next(i for i, s in enumerate(lines) if re.match(r"^-+\s*LINES\b", s.strip(), flags=re.I))
    for i in range(start + 3, len(lines)):
        f = lines[i].split()
        if len(f) < 7 or lines[i].lstrip().startswith("---"):
            break
        f[5] = str(segments)
        lines[i] = "  ".join(f)
    text = "\n".join(lines) + "\n"
    text = re.sub(r"^\S+(\s+dtM)", f"{0.02 / segments:.6g}\\1", text, flags=re.M)
    out = Path(directory) / f"{Path(path).stem}_{segments}{Path(path).suffix}"
    out.write_text(text)
    return out


def displaced_body_deck(path: Path, directory: Path, body: int, pose) -> Path:
    """The deck with free body `body` placed at `pose` (x, y, z [m], roll, pitch, yaw [deg]) and TmaxIC 0."""
    text = Path(path).read_text()
    row = re.search(rf"^{body}(\s+)Free(\s+\S+){{6}}(.*)$", text, flags=re.M)
    text = text[:row.start()] + f"{body}{row.group(1)}Free " + " ".join(f"{v:.6f}" for v in pose) + \
        f"{row.group(3)}" + text[row.end():]
    text = re.sub(r"^\S+(\s+TmaxIC)", r"0.0\1", text, flags=re.M | re.I)
    out = Path(directory) / f"{Path(path).stem}_released{Path(path).suffix}"
    out.write_text(text)
    return out


def fmu_release(fmu, path: Path, point: int, t_end: float, comm_step: float = 0.1, progress=None,
                body: int = 0, **extra) -> dict:
    """The FMU from the deck's start: every line's tension at AttachB (the buoy) and the point's
    position (or with body, that free body's pose) at each communication point."""
    deck = read_system_deck(path)
    times = np.arange(0.0, t_end + 0.5 * comm_step, comm_step)
    names = [f"line[{k}].fairleadTension" for k in range(1, deck.lines + 1)] + \
        ([f"body[{body}].pose.{a}" for a in ("x", "y", "z", "roll", "pitch", "yaw")] if body else
         [f"point[{point}].position.{a}" for a in "xyz"])
    out = np.zeros((len(times), len(names)))
    with CableFMU(fmu, parameters={**fmu_parameters(deck), "lineFile": str(path), **extra}) as c:
        c.initialize()
        out[0] = c.get_reals(names)
        cpu0 = time.process_time()
        for k in range(len(times) - 1):
            c.do_step(comm_step, t=times[k])
            out[k + 1] = c.get_reals(names)
            if progress:
                progress(times[k + 1])
        cpu = time.process_time() - cpu0
    return {"t": times, "tension": out[:, :deck.lines], ("pose" if body else "position"): out[:, deck.lines:],
            "cpu": cpu}


def moordyn_release(path: Path, point: int, t_end: float, comm_step: float = 0.1) -> dict:
    """MoorDyn v2 fed the same deck (no coupled objects: one call per communication step, MoorDyn
    substepping at dtM), in a process of its own (peers.moordyn.release: loaded after MoorPy or the
    FMU's modules, MoorDyn 2.7's Create crashes at random on these decks): each line's tension at its
    end B and the point's position (tensions from t = comm_step: MoorDyn computes them in its first step)."""
    return moordyn.release(path, point, read_system_deck(path).lines, t_end, comm_step)


def rms_difference(a: dict, b: dict, t_from: float = 0.0) -> float:
    """Largest over the lines of the RMS tension difference over t >= t_from, relative to b's mean."""
    sel = a["t"] >= t_from - 1e-9
    diff = a["tension"][sel] - b["tension"][sel]
    return float(np.max(np.sqrt(np.mean(diff ** 2, axis=0)) / np.mean(b["tension"][sel], axis=0)))
