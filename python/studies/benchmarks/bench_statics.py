"""Random anchored lines at rest: the FMU's static equilibrium against MoorPy (scripts/bench_statics).

Each line is drawn from a seed and its number alone (`--only ID` redraws exactly that line): single
lines and lines of 2-3 sections of chain, wire and polyester, some with a clump weight or a buoy,
anchored on a frictionless seabed 30-1500 m deep, tension-only, without bending, at seabedStiffness
3e5-1e8 N/m2. The reference is MoorPy's quasi-static system (an elastic catenary with seabed contact
per piece between points, every point resting on a rigid seabed within 1 mm). See
docs/statics_benchmark.md for the method and the measured numbers.

`--slope`: the same lines on a sloped plane seabed (seabedSlope 1-10 deg, a random heading; the anchor
on it at the drawn depth), against MoorPy's inclined catenary (its System with xSlope and ySlope).

draw_cases() draws, reference() and fmu_run() compute one line, run_benchmark() all of them,
summary() reduces the records to table rows, markdown() writes them.
"""

from __future__ import annotations

import argparse
import contextlib
import dataclasses
import math
import re
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..doc_section import write_section
from ..cases.mooring import chain_weight
from ..peers import moorpy
from ucable.paths import fmu_path
from ucable.units import GRAVITY as G, WATER_DENSITY as RHO

TAUT_SLACK = 0.05              # nearly taut: unstretched length / chord - 1 up to this
REFERENCE_BALANCE = 1e-5       # MoorPy's free points balanced to this fraction of the tension
OFF_BOUND = 0.01               # a run off by more than this without an error is the worst defect
ACCEPT_INIT_RATE = 0.995       # the acceptance of the static solver (docs/statics_benchmark.md)
ACCEPT_P95, ACCEPT_MAX = 0.002, 0.005
DEFAULT_GRADING = 2  # the FMU's default meshGrading: graded along the whole line
STIFFNESS_RANGE = (3e5, 1e8)  # seabedStiffness of the draw [N/m2], log-uniform
STIFFNESS_BANDS = [(3e5, 1e6), (1e6, 1e7), (1e7, 1e8 * (1 + 1e-12))]
REGIMES = ["touchdown", "suspended", "nearly taut"]

# Realistic line materials by nominal diameter d [m] (R4 studless chain, six-strand wire rope,
# polyester rope; the coefficients of common design tables): mass per length [kg/m], volumetric
# diameter (the displaced water) and axial stiffness EA [N].
MATERIALS = {
    "chain": {"d": (0.05, 0.16), "mass_d2": 20.0e3, "dvol_d": 1.80, "EA": lambda d: 85.6e9 * d ** 2 - 3.93e7 * d ** 3},
    "wire": {"d": (0.04, 0.12), "mass_d2": 5293.0, "dvol_d": 1.18, "EA": lambda d: 97.1e9 * d ** 2},
    # polyester: 1380 kg/m3 fibre; static EA of about 20 times the breaking load (~0.25e9 d^2 N)
    "polyester": {"d": (0.10, 0.25), "mass_d2": 679.0, "dvol_d": math.sqrt(4.0 / (1380.0 * math.pi) * 679.0),
                  "EA": lambda d: 5.0e9 * d ** 2},
}
FAMILIES = {"single": 0.35, "2 sections": 0.2, "3 sections": 0.2, "clump": 0.15, "buoy": 0.1}


# ----------------------------------------------------------------------------- the drawn lines
@dataclass
class Section:
    material: str
    nominal: float        # nominal diameter [m]
    length: float         # unstretched [m]
    diameter: float       # volumetric (displacement) diameter [m], the FMU's diameter
    massPerLength: float
    EA: float

    @property
    def weight(self) -> float:
        """Submerged weight per unstretched metre [N/m]."""
        return chain_weight({"massPerLength": self.massPerLength, "diameter": self.diameter}, RHO, G)


@dataclass
class Attachment:
    kind: str             # "clump" or "buoy"
    s: float              # unstretched arc length from the fairlead [m]
    mass: float
    volume: float


@dataclass
class Case:
    id: int
    family: str
    depth: float
    fairlead_z: float
    anchor_x: float       # the anchor at (anchor_x, 0, -depth), the fairlead at (0, 0, fairlead_z)
    stiffness: float
    sections: list        # from the fairlead down
    attachments: list = field(default_factory=list)
    slope: float = 0.0    # seabedSlope [deg]: the seabed descends along `heading`, `depth` deep under the anchor
    heading: float = 0.0  # seabedSlopeHeading [deg]

    @property
    def water_depth(self) -> float:
        """The seabed's depth under the fairlead (x = y = 0): the FMU's waterDepth."""
        return self.depth - math.tan(math.radians(self.slope)) * self.anchor_x * math.cos(math.radians(self.heading))

    @property
    def slopes(self) -> tuple:
        """MoorPy's xSlope, ySlope: the rise of the seabed per metre along x and y."""
        t = math.tan(math.radians(self.slope))
        return -t * math.cos(math.radians(self.heading)), -t * math.sin(math.radians(self.heading))

    @property
    def length(self) -> float:
        return sum(sec.length for sec in self.sections)

    @property
    def chord(self) -> float:
        return math.hypot(self.anchor_x, self.depth + self.fairlead_z)

    @property
    def slack(self) -> float:
        """Unstretched length over chord, minus one."""
        return self.length / self.chord - 1.0

    def describe(self) -> str:
        secs = " - ".join(f"{s.material} {s.length:.1f} m (d {1000 * s.nominal:.0f} mm)" for s in self.sections)
        att = "".join(f"; {a.kind} {a.mass / 1000:.2f} t, {a.volume:.3f} m3 at s = {a.s:.1f} m" for a in self.attachments)
        slope = f", seabedSlope {self.slope:.2f} deg heading {self.heading:.0f} deg" if self.slope else ""
        return (f"{secs}{att}; depth {self.depth:.1f} m, fairlead z {self.fairlead_z:.1f} m, anchor x "
                f"{self.anchor_x:.1f} m, seabedStiffness {self.stiffness:.3g}{slope}")


def make_section(material: str, nominal: float, length: float) -> Section:
    m = MATERIALS[material]
    return Section(material, nominal, length, m["dvol_d"] * nominal, m["mass_d2"] * nominal ** 2, m["EA"](nominal))


def _loguniform(rng, lo: float, hi: float) -> float:
    return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))


def _materials(rng, family: str) -> list:
    names = list(MATERIALS)
    if family in ("single", "clump", "buoy") and rng.uniform() < (1.0 if family == "single" else 0.5):
        return [names[rng.integers(3)]]
    count = 3 if family == "3 sections" or (family != "2 sections" and rng.uniform() < 0.5) else 2
    if count == 3:  # chain at both ends around a lighter middle, as a mooring is built, or any mix
        if rng.uniform() < 0.6:
            return ["chain", ["wire", "polyester"][rng.integers(2)], "chain"]
    out = [names[rng.integers(3)]]
    while len(out) < count:
        out.append([n for n in names if n != out[-1]][rng.integers(2)])
    return out


def touchdown_length(span: float, height: float) -> float:
    """Length of the inextensible catenary from an anchor on the seabed, where it is horizontal,
    to a point span across and height up: longer lines of a uniform weight touch down."""
    from scipy.optimize import brentq

    t = brentq(lambda t: (math.cosh(t) - 1.0) / t - height / span, 1e-9, 700.0, xtol=1e-14)
    return span / t * math.sinh(t)


def draw_length(rng, span: float, height: float, taut: bool) -> float:
    """An unstretched length: nearly taut (length / chord - 1 log-uniform in 1e-4 .. 0.05), or
    else fully suspended (for a uniform line; a third of the draws where there is room) or touching
    down, short of the way down and across (where a frictionless seabed leaves no tension)."""
    chord = math.hypot(span, height)
    if taut:
        return chord * (1.0 + _loguniform(rng, 1e-4, TAUT_SLACK))
    shortest, lifting = (1.0 + TAUT_SLACK) * chord, touchdown_length(span, height)
    if lifting > 1.001 * shortest and rng.uniform() < 1.0 / 3.0:
        return shortest + rng.uniform() * (lifting - shortest)
    start = max(shortest, lifting)
    return start + rng.uniform(0.0, 0.98) * (span + height - start)


SLOPE_RANGE = (1.0, 10.0)  # seabedSlope of --slope [deg], uniform
# seabedFriction of --slope: the static friction that holds a line resting across a slope in its plane, as
# MoorPy's planar profile does (the FMU's statics hold it there where seabedFriction > 0). 0.6: a wire
# rope's lateral coefficient on the seabed, the smallest of wire and chain; the draw's slopes (at most
# 10 deg, tan 0.18) need less. The statics are frictionless along the line, as MoorPy's.
SLOPE_FRICTION = 0.6
SLOPE_CLEARANCE = 0.2      # the seabed under the fairlead at least this fraction of the height below it


def draw_slope(seed: int, case_id: int, case: "Case") -> "Case":
    """The line on a sloped seabed, from a generator of its own (the line itself is the flat draw's):
    seabedSlope uniform in SLOPE_RANGE, a uniform heading, the anchor on the seabed at the drawn depth;
    the slope made gentler where the seabed would rise within SLOPE_CLEARANCE of the height below the
    fairlead."""
    rng = np.random.default_rng([seed, case_id, 2])
    slope, heading = rng.uniform(*SLOPE_RANGE), rng.uniform(0.0, 360.0)
    height = case.depth + case.fairlead_z
    rise = case.anchor_x * math.cos(math.radians(heading))  # the seabed's rise towards the fairlead per tan
    if rise > 0.0:
        slope = min(slope, math.degrees(math.atan((1.0 - SLOPE_CLEARANCE) * height / rise)))
    return dataclasses.replace(case, slope=float(slope), heading=float(heading))


def draw_case(seed: int, case_id: int, above_water: bool = False, slope: bool = False) -> Case:
    """Line `case_id` of the benchmark with `seed`: its own generator, so it never depends on how
    many lines are drawn. `above_water`: the fairlead 1-30 m above the surface (uniform); `slope`:
    on a sloped seabed (draw_slope)."""
    rng = np.random.default_rng([seed, case_id])
    family = list(FAMILIES)[rng.choice(len(FAMILIES), p=list(FAMILIES.values()))]
    depth = _loguniform(rng, 30.0, 1500.0)
    fairlead_z = -max(3.0, rng.uniform(0.02, 0.15) * depth)
    if above_water:
        fairlead_z = float(np.random.default_rng([seed, case_id, 1]).uniform(1.0, 30.0))
    height = depth + fairlead_z
    span = _loguniform(rng, 0.3, 5.0) * height
    length = draw_length(rng, span, height, taut=family not in ("clump", "buoy") and rng.uniform() < 1.0 / 3.0)
    materials = _materials(rng, family)
    fractions = rng.uniform(0.15, 0.7, len(materials))
    fractions /= fractions.sum()
    sections = [make_section(m, rng.uniform(*MATERIALS[m]["d"]), f * length)
                for m, f in zip(materials, fractions)]
    attachments = []
    if family in ("clump", "buoy"):
        line_weight = sum(s.weight * s.length for s in sections)
        joints = np.cumsum([s.length for s in sections])[:-1]
        s = (float(joints[rng.integers(len(joints))]) if len(joints) and rng.uniform() < 0.5
             else rng.uniform(0.3, 0.85) * length)
        if family == "clump":  # steel, 5-100 % of the line's weight
            mass = _loguniform(rng, 0.05, 1.0) * line_weight / (G * (1.0 - RHO / 7850.0))
            attachments.append(Attachment("clump", s, mass, mass / 7850.0))
        else:  # a buoy of 30 % of its displacement, lifting 5-40 % of the line's weight
            volume = _loguniform(rng, 0.05, 0.4) * line_weight / (0.7 * RHO * G)
            attachments.append(Attachment("buoy", s, 0.3 * RHO * volume, volume))
    case = Case(case_id, family, depth, fairlead_z, -span, _loguniform(rng, *STIFFNESS_RANGE), sections, attachments)
    return draw_slope(seed, case_id, case) if slope else case


def draw_cases(seed: int, n: int, above_water: bool = False, slope: bool = False) -> list:
    return [draw_case(seed, k, above_water, slope) for k in range(n)]


# ----------------------------------------------------------------------------- the reference
class ReferenceFailed(Exception):
    """MoorPy found no equilibrium (or one that is not a reference): the line is left out."""


def _pieces(case: Case) -> list:
    """The line cut at section joints and attachments: (section, length, the attachment at its
    upper end or None), from the fairlead down."""
    cuts = {round(c, 9) for c in np.cumsum([s.length for s in case.sections])[:-1]}
    cuts |= {round(a.s, 9) for a in case.attachments if a.s < case.length}
    cuts = sorted(cuts)
    bounds = [0.0, *cuts, case.length]
    starts = np.cumsum([0.0] + [s.length for s in case.sections])
    out = []
    for a, b in zip(bounds[:-1], bounds[1:]):
        k = int(np.searchsorted(starts, 0.5 * (a + b)) - 1)
        att = next((t for t in case.attachments if abs(t.s - a) < 1e-6 and a > 0.0), None)
        out.append((case.sections[k], b - a, att))
    return out


def _start(case: Case, s_from_anchor: float, guess: int) -> np.ndarray:
    """A free point's first position: on the chord (guess 0), or on the way along the seabed and
    up to the fairlead (guess 1), or between the two (guess 2)."""
    anchor = np.array([case.anchor_x, 0.0, -case.depth])
    fair = np.array([0.0, 0.0, case.fairlead_z])
    chord = anchor + (fair - anchor) * s_from_anchor / case.length
    span, height = -case.anchor_x, case.depth + case.fairlead_z
    f = s_from_anchor / (span + height)
    bent = (anchor + np.array([f * (span + height), 0.0, 1e-4]) if f * (span + height) <= span
            else np.array([0.0, 0.0, -case.depth + min(height, f * (span + height) - span)]))
    return [chord, bent, 0.5 * (chord + bent)][guess]


def _system(case: Case, guess: int):
    pieces = _pieces(case)[::-1]  # from the anchor up: MoorPy's end A is the lower end
    if case.slope:
        xs, ys = case.slopes
        ms = moorpy.system(depth=case.water_depth, rho=RHO, g=G, xSlope=xs, ySlope=ys)
    else:
        ms = moorpy.system(depth=case.depth, rho=RHO, g=G)
    ms.addPoint(1, np.array([case.anchor_x, 0.0, -case.depth]))
    s_from_anchor = 0.0
    for k, (sec, length, att) in enumerate(pieces):
        s_from_anchor += length
        if k == len(pieces) - 1:
            ms.addPoint(1, np.array([0.0, 0.0, case.fairlead_z]))
        else:  # the point above piece k
            ms.addPoint(0, _start(case, s_from_anchor, guess), m=att.mass if att else 0.0,
                        v=att.volume if att else 0.0)
        line_type = {"name": f"p{k}", "m": sec.massPerLength, "d_vol": sec.diameter, "w": sec.weight,
                     "EA": sec.EA}
        ms.addLine(length, line_type, nSegs=20, pointA=k + 1, pointB=k + 2)
    for p in ms.pointList:
        p.zTol = 1e-3  # points rest on a rigid seabed
    return ms


def _solve(case: Case, guess: int, tol: float):
    """MoorPy's equilibrium from one first guess; raises ReferenceFailed when it does not converge."""
    with moorpy.silenced():
        try:
            ms = _system(case, guess)
            ms.initialize()
            ok = ms.solveEquilibrium(tol=tol, maxIter=500)  # its lines to 0.01 tol
        except Exception as e:  # MoorPy's own failures (catenary, equilibrium)
            raise ReferenceFailed(f"{type(e).__name__}: {str(e).splitlines()[0][:100]}") from None
    if ok is False:
        raise ReferenceFailed("solveEquilibrium did not converge")
    scale = max(ms.lineList[-1].TB, ms.lineList[0].TA)
    residual = max((float(np.max(np.abs(p.getForces()))) for p in ms.pointList if p.type == 0), default=0.0)
    if residual > REFERENCE_BALANCE * scale:
        raise ReferenceFailed(f"free points out of balance by {residual:.3g} N")
    return ms


def reference_system(case: Case, tol: float = 1e-8):
    """MoorPy's solved system of the line, from the first of the first guesses of _start that
    converges; raises ReferenceFailed with the first failure when none does. On a slope, MoorPy's test
    of a line resting on it is corrected (peers.moorpy.sloped_seabed_classified) for every solve of
    its lines, the ones that draw them too."""
    if case.slope:
        with moorpy.sloped_seabed_classified():
            return _reference_system(case, tol)
    return _reference_system(case, tol)


def _reference_system(case: Case, tol: float):
    errors = []
    for guess in range(3):
        try:
            ms = _solve(case, guess, tol)
            break
        except ReferenceFailed as e:
            errors.append(str(e))
    else:
        raise ReferenceFailed(errors[0])
    if any(p.r[2] > -1.0 for p in ms.pointList):
        raise ReferenceFailed("a point reaches the sea surface")
    if case.slope:
        sloped_reference_applies(case, ms)
    return ms


def sloped_reference_applies(case: Case, ms) -> None:
    """Raises ReferenceFailed where MoorPy's answer on a sloped seabed is not the frictionless plane's:
    a free point resting on it (MoorPy's point contact pushes straight up, not along the normal), a
    line piece whose ends are both above the seabed passing below it (MoorPy leaves the seabed out of
    such a piece on a slope), or a line slack on the slope at its anchor (no tension there: on a
    frictionless slope such a line has no one shape)."""
    if any(p.type == 0 and p.r[2] < -ms.getDepthFromBathymetry(p.r[0], p.r[1])[0] + 1e-2 for p in ms.pointList):
        raise ReferenceFailed("a point rests on the sloped seabed (MoorPy's point contact is vertical)")
    for line in ms.lineList:
        xs, ys, zs, _ = line.getLineCoords(0.0)
        below = max(-ms.getDepthFromBathymetry(x, y)[0] - z for x, y, z in zip(xs, ys, zs))
        if below > 1e-3 * case.length:
            raise ReferenceFailed(f"MoorPy's line passes {below:.3g} m below the sloped seabed")
    if ms.lineList[0].TA < 1e-6 * ms.lineList[-1].TB:
        raise ReferenceFailed("slack on the slope at its anchor")


def air_reference(case: Case) -> dict:
    """A line whose fairlead is above the water: the shooting solution of studies.references.air_catenary (dry
    weight in air, submerged in water); MoorPy blends one weight over a line that leaves the water."""
    from ..references.air_catenary import NoSolution, solve

    sections = [(s.length, s.weight, s.massPerLength * G, s.EA) for s in case.sections[::-1]]
    points = [(case.length - a.s, (a.mass - RHO * a.volume) * G, a.mass * G) for a in case.attachments]
    try:
        ref = solve(sections, points, case.depth, -case.anchor_x, case.fairlead_z)
    except NoSolution as e:
        raise ReferenceFailed(str(e)) from None
    return {**ref, "resting_points": 0}


def reference(case: Case) -> dict:
    """MoorPy's equilibrium (the shooting reference where the fairlead is above the water):
    fairlead and anchor tension, the line's vertical force on the anchor, the grounded length and
    the free points resting on the seabed."""
    if case.fairlead_z > 0.0:
        return air_reference(case)
    ms = reference_system(case)
    bottom, top = ms.lineList[0], ms.lineList[-1]
    grounded = sum(float(line.LBot) for line in ms.lineList)
    resting = [p for p in ms.pointList if p.type == 0 and p.r[2] < -case.depth + 1e-2]
    return {"fairlead": float(top.TB), "anchor": float(bottom.TA), "anchor_vertical": float(bottom.fA[2]),
            "grounded": grounded, "resting_points": len(resting)}


def regime(case: Case, ref: dict) -> str:
    """touchdown: the reference has part of the line or a point on the seabed; otherwise nearly
    taut (length / chord - 1 <= 0.05) or fully suspended."""
    if ref["grounded"] > 0.0 or ref["resting_points"]:
        return "touchdown"
    return "nearly taut" if case.slack <= TAUT_SLACK else "suspended"


# ----------------------------------------------------------------------------- the FMU
def element_counts(case: Case, n_elements: int) -> list:
    """n_elements shared by the sections in proportion to their lengths (largest remainder, at least 1)."""
    lengths = np.array([s.length for s in case.sections])
    share = n_elements * lengths / lengths.sum()
    counts = np.maximum(1, np.floor(share)).astype(int)
    for k in np.argsort(counts - share):
        if counts.sum() >= n_elements:
            break
        counts[k] += 1
    return [int(c) for c in counts]


def fmu_parameters(case: Case, n_elements: int, grading: int = DEFAULT_GRADING) -> dict:
    p = {"meshGrading": grading, "bottomEnd": 1, "anchor.x": case.anchor_x, "anchor.y": 0.0, "anchor.z": -case.depth,
         "waterDepth": case.water_depth, "enableSeabed": True, "seabedStiffness": case.stiffness,
         "seabedSlope": case.slope, "seabedSlopeHeading": case.heading,
         "seabedFriction": SLOPE_FRICTION if case.slope else 0.0, "enableBending": False, "enableCompression": False,
         "waterDensity": RHO, "gravity": G}
    counts = element_counts(case, n_elements)
    if len(case.sections) == 1:
        s = case.sections[0]
        p.update(length=s.length, diameter=s.diameter, massPerLength=s.massPerLength, EA=s.EA, EI=0.0,
                 nElements=n_elements)
    else:
        p["nSections"] = len(case.sections)
        for k, (s, n) in enumerate(zip(case.sections, counts), start=1):
            p.update({f"section[{k}].length": s.length, f"section[{k}].diameter": s.diameter,
                      f"section[{k}].massPerLength": s.massPerLength, f"section[{k}].EA": s.EA,
                      f"section[{k}].EI": 0.0, f"section[{k}].nElements": n,
                      f"section[{k}].joint": 1})  # shackles: pinned, as MoorPy's points
    if case.attachments:
        p["nAttachments"] = len(case.attachments)
        for k, a in enumerate(case.attachments, start=1):
            p.update({f"attachment[{k}].s": a.s, f"attachment[{k}].mass": a.mass,
                      f"attachment[{k}].volume": a.volume})
    return p


FMU_OUTPUTS = ["towTension", "endTension", "tension[21]", "endForce.z"]


def fmu_run(fmu, case: Case, n_elements: int, grading: int = DEFAULT_GRADING) -> dict:
    """The FMU's static initialization (initMode 0): success, or the first error message."""
    from ucable.fmu import CableFMU

    t0 = time.perf_counter()
    c = CableFMU(fmu, parameters=fmu_parameters(case, n_elements, grading))
    try:
        c.initialize(inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": case.fairlead_z})
        values = dict(zip(FMU_OUTPUTS, (float(v) for v in c.get_reals(FMU_OUTPUTS))))
        out = {"ok": all(math.isfinite(v) for v in values.values()), "message": "", **values}
    except Exception as e:  # fmi2Error: fmpy raises, the FMU logged why
        errors = [m for s, _, m in c.messages if s in ("ERROR", "FATAL")]
        out = {"ok": False, "message": errors[0] if errors else f"{type(e).__name__}: {e}"}
    finally:
        c.free()
    out["seconds"] = time.perf_counter() - t0
    return out


# ----------------------------------------------------------------------------- the benchmark
def run_benchmark(fmu, cases: list, meshes: list, progress=None, grading: int = DEFAULT_GRADING) -> list:
    """One record per line and mesh: the line, its reference (or why it failed) and the FMU's run."""
    records = []
    for i, case in enumerate(cases):
        try:
            ref, ref_error = reference(case), ""
        except ReferenceFailed as e:
            ref, ref_error = None, str(e)
        for n in meshes:
            rec = {"id": case.id, "family": case.family, "elements": n, "stiffness": case.stiffness,
                   "slack": case.slack, "ref": ref, "ref_error": ref_error,
                   "regime": regime(case, ref) if ref else "reference failed"}
            if ref is not None:
                run = fmu_run(fmu, case, n, grading)
                rec["fmu"] = run
                if run["ok"]:
                    rec["err_fairlead"] = run["towTension"] / ref["fairlead"] - 1.0
                    rec["err_anchor"] = run["endTension"] / ref["anchor"] - 1.0
                    rec["err_axial"] = run["tension[21]"] / ref["anchor"] - 1.0
                    rec["err_vertical"] = (run["endForce.z"] - ref["anchor_vertical"]) / ref["anchor"]
                    rec["off"] = max(abs(rec["err_fairlead"]), abs(rec["err_anchor"])) > OFF_BOUND
            records.append(rec)
        if progress is not None:
            progress(i + 1, case.id)
    return records


def stiffness_pairs(fmu, cases: list, meshes: list, grading: int = DEFAULT_GRADING, progress=None) -> dict:
    """Each line at the softest and the stiffest seabed of the draw (3e5 and 1e8 N/m2), no reference:
    per mesh, how many start at both, at neither, only at the soft one and only at the stiff one, and
    the lines (id, mesh) that start on the soft seabed but not on the stiff one."""
    soft, stiff = STIFFNESS_RANGE
    counts = {n: {"both": 0, "neither": 0, "soft only": 0, "stiff only": 0} for n in meshes}
    lost = []
    for i, case in enumerate(cases):
        for n in meshes:
            ok = [fmu_run(fmu, dataclasses.replace(case, stiffness=k), n, grading)["ok"] for k in (soft, stiff)]
            key = {(True, True): "both", (False, False): "neither", (True, False): "soft only",
                   (False, True): "stiff only"}[tuple(ok)]
            counts[n][key] += 1
            if key == "soft only":
                lost.append((case.id, n))
        if progress is not None:
            progress(i + 1, case.id)
    return {"counts": counts, "lost": lost}


def band(stiffness: float) -> str:
    for lo, hi in STIFFNESS_BANDS:
        if lo <= stiffness < hi:
            return f"{lo:.0e}-{min(hi, 1e8):.0e}"
    return "other"


def _percentiles(values) -> tuple:
    if len(values) == 0:
        return (math.nan,) * 3
    a = np.abs(np.asarray(values))
    return float(np.median(a)), float(np.percentile(a, 95)), float(a.max())


def group_row(label: str, recs: list) -> dict:
    """Initialization rate and |relative error| percentiles of a group of records with a reference."""
    done = [r for r in recs if r["fmu"]["ok"]]
    row = {"group": label, "runs": len(recs), "initialized": len(done),
           "rate": len(done) / len(recs) if recs else math.nan,
           "off": sum(1 for r in done if r["off"])}
    for key in ("fairlead", "anchor", "axial", "vertical"):
        row[key] = _percentiles([r[f"err_{key}"] for r in done])
    return row


def failure_kind(message: str) -> str:
    """A failure message without the FMI function, with numbers as # and cut after the first."""
    text = re.sub(r"^fmi2\w+: ", "", message).replace("initialization failed: ", "")
    text = re.sub(r"[-+]?\d[\d.]*(e[-+]?\d+)?", "#", text)
    return text[:text.index("#") + 1] if "#" in text else text


def _size(r: dict) -> float:
    return max(abs(r["err_fairlead"]), abs(r["err_anchor"]))


def summary(records: list) -> dict:
    """The tables: rows by regime, by mesh, by regime and mesh, by stiffness band and mesh, by
    family; the failures' messages; the worst runs."""
    valid = [r for r in records if r["ref"] is not None]
    meshes = sorted({r["elements"] for r in valid})

    def rows(keyfun, order):
        return [group_row(k, [r for r in valid if keyfun(r) == k]) for k in order
                if any(keyfun(r) == k for r in valid)]

    bands = [band(lo) for lo, _ in STIFFNESS_BANDS]
    failures: dict = {}  # kind of message -> failed runs by mesh
    for r in valid:
        if not r["fmu"]["ok"]:
            by_mesh = failures.setdefault(failure_kind(r["fmu"]["message"]), dict.fromkeys(meshes, 0))
            by_mesh[r["elements"]] += 1
    worst_of_line: dict = {}
    for r in valid:
        if r["fmu"]["ok"] and (r["id"] not in worst_of_line or _size(r) > _size(worst_of_line[r["id"]])):
            worst_of_line[r["id"]] = r
    worst = sorted(worst_of_line.values(), key=lambda r: -_size(r))[:12]
    return {
        "lines": len({r["id"] for r in records}), "runs": len(records), "meshes": meshes,
        "reference_failed": sorted({(r["id"], r["ref_error"]) for r in records if r["ref"] is None}),
        "all": group_row("all", valid),
        "by_mesh": rows(lambda r: r["elements"], meshes),
        "by_regime": rows(lambda r: r["regime"], REGIMES),
        "by_regime_mesh": rows(lambda r: (r["regime"], r["elements"]), [(g, n) for g in REGIMES for n in meshes]),
        "by_band_mesh": rows(lambda r: (band(r["stiffness"]), r["elements"]), [(b, n) for b in bands for n in meshes]),
        "by_family": rows(lambda r: r["family"], list(FAMILIES)),
        "failures": sorted(failures.items(), key=lambda kv: -sum(kv[1].values())),
        "failed_runs": [r for r in valid if not r["fmu"]["ok"]],
        "worst": worst,
    }


# ----------------------------------------------------------------------------- Markdown
def _pct(x: float) -> str:
    if not math.isfinite(x):
        return "-"
    return f"{100 * x:.0f}" if abs(x) >= 1.0 else f"{100 * x:.2g}"


def _label(g) -> str:
    if isinstance(g, tuple):
        return " / ".join(str(x) for x in g)
    return str(g)


def table(rows: list, first: str) -> list:
    out = [f"| {first} | runs | initialized | fairlead % (median, 95th, max) | anchor `endTension` % | "
           f"anchor `tension[21]` % | `endForce.z` % of anchor tension | off > 1 %, no error |",
           "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        cells = [", ".join(_pct(v) for v in r[k]) for k in ("fairlead", "anchor", "axial", "vertical")]
        out.append(f"| {_label(r['group'])} | {r['runs']} | {r['initialized']} ({100 * r['rate']:.1f} %) | "
                   + " | ".join(cells) + f" | {r['off']} |")
    return out


def pairs_markdown(pairs: dict, stiffness: tuple) -> str:
    soft, stiff = stiffness
    out = [f"| elements | start at {soft:g} and {stiff:g} | at neither | at {soft:g} only | at {stiff:g} only |",
           "|---|---|---|---|---|"]
    for n, c in pairs["counts"].items():
        out.append(f"| {n} | {c['both']} | {c['neither']} | {c['soft only']} | {c['stiff only']} |")
    lost = ", ".join(f"line {i} at {n}" for i, n in pairs["lost"]) or "none"
    out.append(f"\nStarting at {soft:g} N/m2 but not at {stiff:g}: {lost}.")
    return "\n".join(out)


def markdown(data: dict, command: str, fmu_label: str, cases: dict) -> str:
    a = data["all"]
    at20 = next((r for r in data["by_mesh"] if r["group"] == 20), None)
    out = [f"Measured with `{command}` (FMU: {fmu_label}): {data['lines']} lines at "
           f"{', '.join(str(n) for n in data['meshes'])} elements, {data['runs']} runs; the reference failed on "
           f"{len(data['reference_failed'])} lines (excluded).", "",
           f"**All runs**: {a['initialized']} of {a['runs']} initialize ({100 * a['rate']:.1f} %); "
           f"{a['off']} runs are off by more than 1 % without an error."]
    if at20:
        out += ["", f"**Acceptance at 20 elements** (initialize >= {100 * ACCEPT_INIT_RATE:g} %, fairlead and anchor "
                f"tension 95th percentile <= {100 * ACCEPT_P95:g} %, max <= {100 * ACCEPT_MAX:g} %, no run off by more "
                f"than 1 % without an error): initialized {100 * at20['rate']:.1f} %; fairlead 95th "
                f"{_pct(at20['fairlead'][1])} %, max {_pct(at20['fairlead'][2])} %; anchor (`endTension`) 95th "
                f"{_pct(at20['anchor'][1])} %, max {_pct(at20['anchor'][2])} %; off without an error "
                f"{at20['off']} (all meshes: {a['off']})."]
    out += ["", "### By mesh", "", *table(data["by_mesh"], "elements"),
            "", "### By regime", "", *table(data["by_regime"], "regime"),
            "", "### By regime and mesh", "", *table(data["by_regime_mesh"], "regime / elements"),
            "", "### By seabed stiffness [N/m2] and mesh", "", *table(data["by_band_mesh"], "seabedStiffness / elements"),
            "", "### By family (all meshes)", "", *table(data["by_family"], "family"),
            "", "### Why initialization failed", "",
            f"| message (numbers as #, cut after the first) | failed runs at {' / '.join(map(str, data['meshes']))} "
            f"elements |", "|---|---|"]
    out += [f"| {m.replace('|', '/')} | {' / '.join(str(c[n]) for n in data['meshes'])} |"
            for m, c in data["failures"]] or ["| (none) | 0 |"]
    out += ["", "### The worst lines (largest fairlead or anchor error of a run without an error; reproduce "
            "with `--only ID`)", "",
            "| line | elements | regime | fairlead % | anchor `endTension` % | `tension[21]` % | line |",
            "|---|---|---|---|---|---|---|"]
    for r in data["worst"]:
        out.append(f"| {r['id']} | {r['elements']} | {r['regime']} | {100 * r['err_fairlead']:+.3g} | "
                   f"{100 * r['err_anchor']:+.3g} | {100 * r['err_axial']:+.3g} | {cases[r['id']].describe()} |")
    if data["reference_failed"]:
        out += ["", "The reference failed on: " + "; ".join(f"line {i} ({m})" for i, m in data["reference_failed"]) + "."]
    return "\n".join(out)


# ----------------------------------------------------------------------------- command line
def parse_args(argv):
    p = argparse.ArgumentParser(prog="scripts/bench_statics", description=__doc__.split("\n")[0])
    p.add_argument("--fmu", type=Path, default=fmu_path(),
                   help="the FMU (default: $UC_FMU, else build/UnderwaterCable.fmu)")
    p.add_argument("--n", type=int, default=200, help="number of random lines (default 200)")
    p.add_argument("--elements", type=int, nargs="+", default=[10, 20, 40],
                   help="element counts of the whole line (default 10 20 40)")
    p.add_argument("--seed", type=int, default=2026, help="seed of the draw (default 2026)")
    p.add_argument("--grading", type=int, choices=(0, 1, 2), default=DEFAULT_GRADING,
                   help="the FMU's meshGrading: 0 equal elements, 1 graded in each section, "
                        "2 graded along the line (default, as the FMU's)")
    p.add_argument("--stiffness-pairs", action="store_true",
                   help="instead of the comparison with MoorPy: start every line on the softest and the stiffest "
                        "seabed of the draw and count where the stiff one fails and the soft one does not")
    p.add_argument("--above-water", action="store_true",
                   help="the same lines with the fairlead 1-30 m above the surface; the reference is the shooting "
                        "solution of studies.references.air_catenary (dry weight in air)")
    p.add_argument("--slope", action="store_true",
                   help="the same lines on a sloped plane seabed (seabedSlope 1-10 deg, a random heading); the "
                        "reference is MoorPy's inclined catenary")
    p.add_argument("--only", type=int, nargs="+", default=None, metavar="ID",
                   help="run only these lines of the draw (reproduce a case; prints each run)")
    p.add_argument("--out", type=Path, default=None, help="write every run as CSV to this file")
    p.add_argument("--doc", type=Path, default=None,
                   help="write the tables into this Markdown file's generated section "
                        "(docs/statics_benchmark.md)")
    return p.parse_args(argv)


def write_csv(path: Path, records: list, cases: dict) -> None:
    cols = ["id", "family", "regime", "elements", "stiffness", "slack", "ok", "message", "ref_fairlead",
            "ref_anchor", "ref_anchor_vertical", "towTension", "endTension", "tension[21]", "endForce.z",
            "err_fairlead", "err_anchor", "err_axial", "err_vertical", "seconds", "ref_error", "line"]
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w") as f:
        f.write(",".join(cols) + "\n")
        for r in records:
            run, ref = r.get("fmu", {}), r["ref"] or {}
            row = {**r, **run, "ref_fairlead": ref.get("fairlead"), "ref_anchor": ref.get("anchor"),
                   "ref_anchor_vertical": ref.get("anchor_vertical"), "line": cases[r["id"]].describe()}
            f.write(",".join('"' + str(row.get(c, "")).replace('"', "'") + '"' if c in ("message", "ref_error", "line")
                             else str(row.get(c, "")) for c in cols) + "\n")


def print_only(records: list, cases: dict) -> None:
    for r in records:
        case = cases[r["id"]]
        if r is records[0] or records[records.index(r) - 1]["id"] != r["id"]:
            print(f"line {r['id']} ({case.family}, {r['regime']}, slack {case.slack:.3g}): {case.describe()}")
        if r["ref"] is None:
            print(f"  reference failed: {r['ref_error']}")
            continue
        ref, run = r["ref"], r["fmu"]
        head = (f"  {r['elements']:3d} elements: MoorPy fairlead {ref['fairlead']:.6g} N, anchor {ref['anchor']:.6g} N "
                f"(vertical {ref['anchor_vertical']:.4g}, grounded {ref['grounded']:.1f} m); ")
        if run["ok"]:
            print(head + f"FMU {run['towTension']:.6g} ({100 * r['err_fairlead']:+.3g} %), endTension "
                  f"{run['endTension']:.6g} ({100 * r['err_anchor']:+.3g} %), tension[21] {run['tension[21]']:.6g} "
                  f"({100 * r['err_axial']:+.3g} %), endForce.z {run['endForce.z']:.4g}")
        else:
            print(head + f"FMU failed: {run['message']}")


def _shown(path: Path) -> str:
    """The FMU's path as the reader can use it: relative to the working directory when inside it."""
    try:
        return str(path.resolve().relative_to(Path.cwd().resolve()))
    except ValueError:
        return path.name


def main(argv=None) -> int:
    from ucable.progress import ProgressBar

    args = parse_args(sys.argv[1:] if argv is None else argv)
    if not args.fmu.is_file():
        print(f"no FMU at {args.fmu}: build first (scripts/build) or pass --fmu", file=sys.stderr)
        return 2
    ids = args.only if args.only is not None else range(args.n)
    cases = {k: draw_case(args.seed, k, args.above_water, args.slope) for k in ids}
    bar = ProgressBar(len(cases), label="lines")
    t0 = time.perf_counter()
    if args.stiffness_pairs:
        pairs = stiffness_pairs(args.fmu, list(cases.values()), args.elements, args.grading,
                                progress=lambda i, cid: bar.update(i, f"line {cid}"))
        bar.close(f"{len(cases)} lines x {len(args.elements)} meshes x 2 seabeds")
        text = (f"Measured with `scripts/bench_statics --n {args.n} --elements {' '.join(map(str, args.elements))} "
                f"--seed {args.seed} --stiffness-pairs" + (f" --grading {args.grading}`" if args.grading != DEFAULT_GRADING else "`")
                + ":\n\n" + pairs_markdown(pairs, STIFFNESS_RANGE))
        print(text)
        if args.doc is not None:
            write_section(args.doc, text, "scripts/bench_statics --stiffness-pairs"
                          + (f" --grading {args.grading}" if args.grading != DEFAULT_GRADING else ""))
        return 0
    records = run_benchmark(args.fmu, list(cases.values()), args.elements,
                            progress=lambda i, cid: bar.update(i, f"line {cid}"), grading=args.grading)
    bar.close(f"{len(cases)} lines x {len(args.elements)} meshes")
    if args.out is not None:
        write_csv(args.out, records, cases)
    if args.only is not None:
        print_only(records, cases)
        return 0
    data = summary(records)
    command = "scripts/bench_statics " + " ".join(
        [f"--n {args.n}", "--elements " + " ".join(map(str, args.elements)), f"--seed {args.seed}"]
        + ([f"--grading {args.grading}"] if args.grading != DEFAULT_GRADING else [])
        + (["--above-water"] if args.above_water else []) + (["--slope"] if args.slope else []))
    text = markdown(data, command, _shown(args.fmu), cases)
    print(text)
    print(f"\n({time.perf_counter() - t0:.0f} s wall)")
    if args.doc is not None:
        # one generated section per grading: the default and the others side by side
        write_section(args.doc, text, "scripts/bench_statics" + (f" --grading {args.grading}" if args.grading != DEFAULT_GRADING else "")
                      + (" --above-water" if args.above_water else "") + (" --slope" if args.slope else ""))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
