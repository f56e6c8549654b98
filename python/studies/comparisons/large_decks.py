"""Mooring decks larger than the FMU's first maxima (16 lines, 4 bodies, 16 points), written for the
checks of docs/systems_mooring.md ("Decks of any size"), and their statics in MoorPy.

* `radial_platform_deck(n)`: one platform (no BODIES section: the Vessel points ride body 1) held by n
  catenary chains of the OC4 semisubmersible's (scenes/oc4_semi.dat) at equal angles;
* `shared_anchor_farm(platforms)`: a row of coupled bodies (platforms), three chains each, neighbours
  sharing anchors (one anchor between platforms 2j-1 and 2j, two between 2j and 2j+1);
* `moorpy_lines(path, depth)`: MoorPy's statics of such a deck with its coupled bodies and points held
  where the deck puts them: each line's tension at its fairlead (the end on a body or a Vessel point)
  and at its anchor, and each coupled body's load of the lines.

Used by tests/python/test_deck_sizes.py.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ucable.units import STANDARD_GRAVITY, WATER_DENSITY
from ..peers import moorpy

DEPTH = 200.0
FAIRLEAD_RADIUS, FAIRLEAD_Z = 40.868, -14.0  # the OC4 platform's fairleads
ANCHOR_RADIUS = 837.6                        # its anchors, from the platform's centre
LENGTH = 835.35                              # its chains' unstretched length

HEAD = """--------------------- MoorDyn Input File ------------------------------------
{title}
----------------------- LINE TYPES ------------------------------------------
Name     Diam      MassDen       EA    BA/-zeta    EI    Cd      Ca     CdAx   CaAx
(-)       (m)      (kg/m)        (N)    (N-s/-)    (-)   (-)     (-)    (-)    (-)
main     0.0766    113.35     7.536E8     -1.0      0    2.0     0.8    0.4    0.25
"""
BODIES = """---------------------- BODIES ----
ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*
(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)
"""
POINTS = """---------------------- POINTS --------------------------------
ID     Attachment  X        Y         Z      M      V       CdA   CA
(-)    (-)        (m)      (m)       (m)    (kg)   (m^3)   (m^2)  (-)
"""
LINES = """---------------------- LINES --------------------------------------
ID      LineType   AttachA   AttachB  UnstrLen  NumSegs   Outputs
(-)       (-)        (-)       (-)       (m)      (-)       (-)
"""
TAIL = """---------------------- SOLVER OPTIONS ---------------------------------------
0.001    dtM       - time step to use in mooring integration (s)
3.0e6    kbot      - bottom stiffness (Pa/m)
3.0e5    cbot      - bottom damping (Pa-s/m)
{depth}    WtrDpth   - water depth (m)
------------------------ OUTPUTS --------------------------------------------
END
------------------------- need this line --------------------------------------
"""


def _point(pid: int, kind: str, x: float, y: float, z: float) -> str:
    return f"{pid}  {kind}  {x:.6f}  {y:.6f}  {z:.6f}  0  0  0  0\n"


def radial_platform_deck(lines: int, segments: int = 20, keep: int | None = None) -> str:
    """One platform held by `lines` chains at angles 360/lines apart (the first along +x); with `keep`, only
    the first `keep` of them (the same angles)."""
    anchors, fairleads, rows = [], [], []  # (the points in the order of their IDs, as MoorPy numbers them)
    n = lines if keep is None else keep
    for k in range(n):
        a = 2.0 * math.pi * k / lines
        c, s = math.cos(a), math.sin(a)
        anchors.append(_point(k + 1, "Fixed", ANCHOR_RADIUS * c, ANCHOR_RADIUS * s, -DEPTH))
        fairleads.append(_point(n + k + 1, "Vessel", FAIRLEAD_RADIUS * c, FAIRLEAD_RADIUS * s, FAIRLEAD_Z))
        rows.append(f"{k + 1}  main  {k + 1}  {n + k + 1}  {LENGTH}  {segments}  -\n")
    points = anchors + fairleads
    return (HEAD.format(title=f"One platform held by {lines} chains (written by studies.comparisons.large_decks)")
            + POINTS + "".join(points) + LINES + "".join(rows) + TAIL.format(depth=DEPTH))


def farm_positions(platforms: int) -> list:
    """The platforms' centres along x: 2 R between platforms 2j-1 and 2j, R between 2j and 2j+1."""
    x, out = 0.0, []
    for i in range(platforms):
        out.append((x, 0.0, 0.0))
        x += 2.0 * ANCHOR_RADIUS if i % 2 == 0 else ANCHOR_RADIUS
    return out


def shared_anchor_farm(platforms: int, segments: int = 10) -> str:
    """`platforms` coupled bodies in a row, three chains each (at 0, 120, 240 degrees on the odd-numbered
    platforms, 180, 300, 60 on the even-numbered), the anchors neighbours share written once."""
    anchors: dict = {}  # rounded position -> point ID
    bodies, points, rows = [], [], []
    next_id = 1
    for b, (x0, y0, _) in enumerate(farm_positions(platforms), start=1):
        bodies.append(f"{b}  Coupled  {x0:.6f}  {y0:.6f}  0  0  0  0  0  0  0  0  0  0\n")
        for j in range(3):
            a = math.radians(120.0 * j + (0.0 if b % 2 == 1 else 180.0))
            c, s = math.cos(a), math.sin(a)
            key = (round(x0 + ANCHOR_RADIUS * c, 3), round(y0 + ANCHOR_RADIUS * s, 3))
            if key not in anchors:
                anchors[key] = next_id
                points.append(_point(next_id, "Fixed", key[0], key[1], -DEPTH))
                next_id += 1
            fairlead = next_id
            points.append(_point(fairlead, f"Body{b}", FAIRLEAD_RADIUS * c, FAIRLEAD_RADIUS * s, FAIRLEAD_Z))
            next_id += 1
            rows.append(f"{len(rows) + 1}  main  {anchors[key]}  {fairlead}  {LENGTH}  {segments}  -\n")
    return (HEAD.format(title=f"A row of {platforms} platforms sharing anchors (written by "
                              "studies.comparisons.large_decks)")
            + BODIES + "".join(bodies) + POINTS + "".join(points) + LINES + "".join(rows)
            + TAIL.format(depth=DEPTH))


def write(text: str, path: Path) -> Path:
    path.write_text(text)
    return path


def moorpy_lines(path: Path, depth: float = DEPTH) -> dict:
    """MoorPy's statics of the deck at `path`, its coupled bodies and Vessel points held where the deck puts
    them: per line (the deck's order) the tension at its fairlead and at its anchor; per coupled body its
    lines' force and moment about its reference point."""
    s = moorpy.system(path, depth=depth, rho=WATER_DENSITY, g=STANDARD_GRAVITY)
    with moorpy.silenced():
        s.initialize()
        s.solveEquilibrium(tol=1e-8, maxIter=2000)
    fair, anchor = [], []
    for ln in s.lineList:
        a = s.pointList[ln.attached[0] - 1]
        a_fixed = a.type == 1 and a.number not in {n for body in s.bodyList for n in body.attachedP}
        fair.append(float(ln.TB if a_fixed else ln.TA))
        anchor.append(float(ln.TA if a_fixed else ln.TB))
    loads = [np.array(body.getForces(lines_only=True), float) for body in s.bodyList]
    return {"fairlead": fair, "anchor": anchor, "loads": loads}
