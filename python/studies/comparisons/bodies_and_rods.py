"""MoorDyn's public BodiesAndRods deck as the census loads it (studies.comparisons.public_decks), its static start
checked where it can be: MoorDyn v2.7 does not settle this deck (docs/systems_mooring.md), so

- the lines: MoorPy fed the same lines with the body's points held where the FMU's statics put them (the deck's
  Body1 points made Fixed there, the BODIES and RODS left out): every line's end tensions and the cable's two
  free points against the FMU's;
- the body: its loads at the FMU's pose summed from physics, independently of the FMU: its weight, can 1's weight
  and buoyancy (the displaced volume of a cylinder of diameter 10 m cut by the surface: rho g A l at the
  centroid shifted by I tan(theta) / (A l) across the axis and I tan^2(theta) / (2 A l) along it), the pinned
  can's weight and buoyancy on its pin, and MoorPy's line forces at the body's points: force and moment about
  the reference point, relative to the body's weight; and the pinned can's moment about its pin.

    python -m studies.comparisons.bodies_and_rods [--deck PATH] [--fmu build/UnderwaterCable.fmu]

(the deck: tests/data/decks/md_tests_Mooring_BodiesAndRods.dat, MoorDyn's tests/Mooring/BodiesAndRods.dat unchanged;
tests/python/test_deck_mesh.py)
"""

from __future__ import annotations

import argparse
import math
import re
import tempfile
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.paths import REPO_ROOT
from ucable.units import STANDARD_GRAVITY as G, WATER_DENSITY as RHO
from . import public_decks as pd
from ..peers import moorpy

DECK = REPO_ROOT / "tests" / "data" / "decks" / "md_tests_Mooring_BodiesAndRods.dat"
# the deck's body and rods (BODIES, ROD TYPES, RODS)
BODY_MASS, CAN_D, CAN_MPL = 1.0e6, 10.0, 1.0e3
CAN1 = (np.array([0.0, 0.0, 2.0]), np.array([0.0, 0.0, 15.0]))
PIN, CAN2_B = np.array([2.0, 0.0, 2.0]), np.array([5.0, 0.0, 15.0])
BODY_POINTS = {1: (0.0, 0.0, -10.0), 3: (0.0, 0.0, -10.0), 5: (0.0, 0.0, -10.0), 10: (0.0, 0.0, 0.0)}


def rotation(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """R = Rx Ry Rz (the FMU's body[k].pose angles)."""
    cr, sr, cp, sp, cy, sy = math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch), math.cos(yaw), math.sin(yaw)
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return rx @ ry @ rz


def can_loads(a: np.ndarray, b: np.ndarray, d: float, mass_per_length: float):
    """A can from a (under water) to b: its weight and buoyancy, each (force, point). The buoyancy is the
    water a cylinder cut by the plane z = 0 displaces (the cut across its side, not an end cap): rho g A l,
    l the axis's length under water, at the centroid of that volume."""
    length = float(np.linalg.norm(b - a))
    u = (b - a) / length
    weight = (np.array([0.0, 0.0, -mass_per_length * length * G]), 0.5 * (a + b))
    area, inertia = math.pi * d * d / 4, math.pi * d ** 4 / 64
    if b[2] <= 0.0:
        return weight, (np.array([0.0, 0.0, RHO * G * area * length]), 0.5 * (a + b))
    wet = -a[2] / u[2]
    cos_t = u[2]
    tan_t = math.sqrt(max(0.0, 1.0 - cos_t * cos_t)) / cos_t
    centre = a + 0.5 * wet * u
    # across the axis toward its low side (the side the axis leans to: longer under water), and along it
    lean = np.array([u[0], u[1], 0.0])
    across = np.zeros(3)
    if np.linalg.norm(lean) > 0.0:
        low = lean - np.dot(lean, u) * u  # perpendicular to u in the plane of u and the vertical, pointing down
        low /= np.linalg.norm(low)
        across = low * inertia * tan_t / (area * wet)
    centroid = centre + across + u * inertia * tan_t * tan_t / (2 * area * wet)
    return weight, (np.array([0.0, 0.0, RHO * G * area * wet]), centroid)


def fmu_start(fmu: Path, path: Path) -> dict:
    """The FMU's start as the census makes it (public_decks.setup from MoorPy's reading of the deck, not its
    statics, which fail on this deck)."""
    s = moorpy.system(path, rho=RHO, g=G)
    parameters, inputs = pd.setup(path, s, {k.lower(): v for k, v in s.MDoptions.items()})
    c = CableFMU(fmu, parameters=parameters, logging_on=True)
    try:
        c.initialize(inputs=inputs)
        out = {"pose": [c.get(f"body[1].pose.{n}") for n in pd.POSE],
               "pin_pose": [c.get(f"body[2].pose.{n}") for n in pd.POSE],
               "lines": {k: (c.get(f"line[{k}].fairleadTension"), c.get(f"line[{k}].anchorTension")) for k in range(1, 7)},
               "points": {k: np.array([c.get(f"point[{k}].position.{a}") for a in "xyz"]) for k in (8, 9)},
               "warnings": [m for st, _, m in c.messages if st == "WARNING"]}
    finally:
        c.free()
    return out


def moorpy_lines(path: Path, at: dict):
    """MoorPy's statics of the deck's lines with the body's points Fixed where `at` puts them."""
    text = path.read_text()
    text = re.sub(r"-+ *BODIES.*?(?=-+ *POINTS)", "", text, flags=re.S)
    text = re.sub(r"-+ *ROD TYPES.*?(?=-+ *BODIES|-+ *RODS)", "", text, flags=re.S)
    text = re.sub(r"-+ *RODS .*?(?=-+ *POINTS)", "", text, flags=re.S)

    def fixed(match):
        k = int(match.group(1))
        x, y, z = at[k]
        return f"{k}  Fixed  {x:.9f}  {y:.9f}  {z:.9f}"

    text = re.sub(r"^(\d+)\s+Body1\s+\S+\s+\S+\s+\S+", fixed, text, flags=re.M)
    with tempfile.TemporaryDirectory() as folder:
        deck = Path(folder) / "lines.dat"
        deck.write_text(text)
        s, _, why = pd.moorpy_system(deck)
    return s, why


def compute(fmu: Path, path: Path) -> dict:
    """The FMU's start of the deck at `path` (BodiesAndRods) and its checks (the module's docstring)."""
    ours = fmu_start(fmu, path)
    x = np.array(ours["pose"][:3])
    R = rotation(*ours["pose"][3:])
    at = {k: x + R @ np.array(r) for k, r in BODY_POINTS.items()}
    s, why = moorpy_lines(path, at)
    if s is None or why is not None:
        return {"fmu": ours, "moorpy": why}
    lines = {}
    for k, ln in enumerate(s.lineList, start=1):
        f, a = ours["lines"][k]
        ta, tb = float(ln.TA), float(ln.TB)
        if abs(f - ta) + abs(a - tb) < abs(f - tb) + abs(a - ta):
            ta, tb = tb, ta  # the FMU's fairlead is MoorPy's end B, unless this way round fits
        lines[k] = {"fmu": (f, a), "moorpy": (tb, ta), "difference": (f / tb - 1, a / ta - 1)}
    points = {k: float(np.linalg.norm(ours["points"][k] - s.pointList[k - 1].r)) for k in (8, 9)}
    # the body's loads at the FMU's pose
    loads = [(np.array([0.0, 0.0, -BODY_MASS * G]), x)]
    loads += list(can_loads(x + R @ CAN1[0], x + R @ CAN1[1], CAN_D, CAN_MPL))
    pin = x + R @ PIN
    pin_pose = ours["pin_pose"]
    axis = rotation(*pin_pose[3:])[:, 0]
    can2 = can_loads(pin, pin + np.linalg.norm(CAN2_B - PIN) * axis, CAN_D, CAN_MPL)
    pin_moment = sum(np.cross(p - pin, f) for f, p in can2)
    loads.append((sum(f for f, _ in can2), pin))  # the pinned can's load on the body, at its pin
    for k in BODY_POINTS:
        loads.append((np.array(s.pointList[k - 1].getForces()[:3], dtype=float), at[k]))
    force = sum(f for f, _ in loads)
    moment = sum(np.cross(p - x, f) for f, p in loads)
    weight = BODY_MASS * G
    return {"fmu": ours, "moorpy": None, "lines": lines, "points": points,
            "force": force / weight, "moment": moment / (weight * CAN_D),
            "pin_moment": pin_moment / (CAN_MPL * np.linalg.norm(CAN2_B - PIN) * G * CAN_D)}


def report(r: dict) -> str:
    o = r["fmu"]
    out = [f"FMU start: body x {o['pose'][0]:.4f} m, z {o['pose'][2]:.4f} m, pitch {o['pose'][4]:.5f} rad; "
           f"pinned can pitch {o['pin_pose'][4]:.5f} rad"]
    out += [f"warning: {w}" for w in o["warnings"]]
    if r["moorpy"] is not None:
        return "\n".join(out + [f"MoorPy fails: {r['moorpy']}"])
    for k, line in r["lines"].items():
        (f, a), (mf, ma), (df, da) = line["fmu"], line["moorpy"], line["difference"]
        out.append(f"line {k}: FMU {f:.2f} / {a:.2f} N, MoorPy {mf:.2f} / {ma:.2f} N ({100 * df:+.3f} %, {100 * da:+.3f} %)")
    out += [f"point {k}: {d * 1000:.1f} mm from MoorPy's" for k, d in r["points"].items()]
    out.append("body: unbalanced force / weight " + np.array2string(r["force"], precision=3) +
               ", moment / (weight x 10 m) " + np.array2string(r["moment"], precision=3) +
               "; pinned can's moment about its pin / (its weight x 10 m) " + np.array2string(r["pin_moment"], precision=3))
    return "\n".join(out)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--deck", type=Path, default=DECK, help="MoorDyn's BodiesAndRods deck")
    parser.add_argument("--fmu", type=Path, default=REPO_ROOT / "build" / "UnderwaterCable.fmu")
    args = parser.parse_args(argv)
    print(report(compute(args.fmu, args.deck)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
