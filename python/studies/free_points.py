"""Free points where three or more lines meet (docs/systems_mooring.md, "Free points where several lines
meet"): the statics of a subsurface buoy on three legs 120 degrees apart (tests/data/decks/subsurface_buoy.dat)
and of a bridle against MoorPy fed the same deck.

MoorPy solves the free points' equilibrium with its quasi-static catenaries; its current acts on the lines
(their drag lumped into a uniform load that tilts each catenary's plane) but not on points, so a point's
drag in a current is given to MoorPy as the constant external force it is on a point at rest.

Used by tests/python/test_free_points.py.
"""

from __future__ import annotations

import contextlib
import io
import re
import warnings
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from .mooring_system import DECKS, _moorpy_system, fmu_parameters, read_system_deck

BUOY = DECKS / "subsurface_buoy.dat"
WATER_DENSITY = 1025.0


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
    """IDs of the deck's Free points where three or more lines meet."""
    s = _moorpy_system(path)
    counts = {p.number: len(p.attached) for p in s.pointList}
    return [p.number for p in s.pointList if p.type == 0 and counts[p.number] >= 3]


def moorpy_statics(path: Path, current: float = 0.0) -> dict:
    """MoorPy's equilibrium of the deck's free points, the deck's Vessel points where the deck puts them,
    in a uniform current along x: each free point's position, each line's tension at AttachB (the fairlead
    side in the decks here) and AttachA."""
    deck = read_system_deck(path)
    s = _moorpy_system(path, deck.depth)
    with contextlib.redirect_stdout(io.StringIO()), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        if current:
            s.currentMod = 1
            s.current = np.array([current, 0.0, 0.0])
        for p in s.pointList:  # the point's drag at rest in the current (MoorPy has none on points)
            if p.type == 0:
                p.fExt = np.array([0.5 * WATER_DENSITY * p.CdA * current * abs(current), 0.0, 0.0])
        s.initialize()
        for _ in range(3):  # MoorPy's line drag is that of the previous solution: iterate it to its fixed point
            s.solveEquilibrium(tol=1e-8, maxIter=2000)
    points = {p.number: np.array(p.r, float) for p in s.pointList}
    return {"points": {k: points[k] for k in free_point_ids(path)},
            "fairlead": [float(ln.TB) for ln in s.lineList], "anchor": [float(ln.TA) for ln in s.lineList]}


def fmu_statics(fmu, path: Path, current: float = 0.0, **extra) -> dict:
    """The FMU's static start (initMode 0) of the deck in a uniform current along x."""
    deck = read_system_deck(path)
    with CableFMU(fmu, parameters={**fmu_parameters(deck), "lineFile": str(path), **extra}) as c:
        c.initialize(inputs={"current.x": current})
        points = {k: np.array([c.get(f"point[{k}].position.{a}") for a in "xyz"]) for k in free_point_ids(path)}
        return {"points": points,
                "fairlead": [c.get(f"line[{k}].fairleadTension") for k in range(1, deck.lines + 1)],
                "anchor": [c.get(f"line[{k}].anchorTension") for k in range(1, deck.lines + 1)]}


def compare(ours: dict, ref: dict) -> dict:
    """Largest distance between the free points' positions [m] and largest relative tension difference."""
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
