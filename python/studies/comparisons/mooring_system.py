"""Mooring systems read from MoorDyn decks (`lineFile` with several lines and bodies,
docs/systems_mooring.md) against independent codes fed the same file.

* statics against MoorPy: the deck's Vessel points attached to a MoorPy body at the platform's
  reference point (what the FMU's body 1 is), each line's fairlead and anchor tension, the body's
  force and moment and its 6x6 coupled stiffness (`getCoupledStiffnessA`, lines only);
* dynamics against MoorDyn v2 (PyPI `moordyn`): the platform moving in surge, heave and pitch from
  rest; MoorDyn is fed the fairleads' motion (its Vessel points), the FMU the body's.

Used by tests/python/test_mooring_system.py and scripts/bench_mooring_system.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.paths import REPO_ROOT
from ucable.units import STANDARD_GRAVITY, WATER_DENSITY
from ..peers import moordyn, moorpy

DECKS = REPO_ROOT / "tests" / "data" / "decks"
OC4 = REPO_ROOT / "scenes" / "oc4_semi.dat"  # the deck of the scene oc4_platform
POSE_NAMES = ("x", "y", "z", "roll", "pitch", "yaw")


# ----------------------------------------------------------------------------- the deck in MoorPy
@dataclass
class SystemDeck:
    """What the comparisons need to know of a deck with Vessel points (read by MoorPy's reader)."""
    path: Path
    depth: float
    fairleads: list  # per Vessel point (in the order of the lines on them): its position on the platform
    diameters: list  # per line
    options: dict
    lines: int = 0   # lines of the deck

    def option(self, name: str, default: float) -> float:
        return float(self.options.get(name.lower(), default))


def _moorpy_system(path: Path, depth: float = 0.0):
    return moorpy.system(path, depth=depth, rho=WATER_DENSITY, g=STANDARD_GRAVITY)


def oc4_with_a_coupled_body() -> str:
    """The OC4 deck's text with a BODIES section holding one Coupled body at the origin: its Vessel points
    4, 5, 6 are then coupled points (point[k].*, absolute positions) instead of moving with body 1."""
    return OC4.read_text().replace(
        "---------------------- LINES", "---------------------- BODIES ----\nID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* "
        "I* Volume CdA* Ca*\n(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)\n"
        "1 Coupled 0 0 0 0 0 0 0 0 0 0 0 0\n---------------------- LINES", 1)


def read_system_deck(path: Path) -> SystemDeck:
    s = _moorpy_system(path)
    depth = float(s.depth) or max(-float(p.r[2]) for p in s.pointList)  # MoorDyn: the deepest point
    fairleads = []
    for ln in s.lineList:
        ends = [s.pointList[n - 1] for n in ln.attached]
        fairleads += [np.array(p.r, float) for p in ends if p.type == -1]
    return SystemDeck(path=Path(path), depth=depth, fairleads=fairleads,
                      diameters=[float(ln.type["d_vol"]) for ln in s.lineList],
                      options={k.lower(): v for k, v in s.MDoptions.items()}, lines=len(s.lineList))


def clumped_oc4(text: str, mass: float = 20000.0, volume: float = 1.0) -> str:
    """The OC4 deck with each chain in two (400 m from the anchor, the rest to the fairlead) joined by a
    Free point carrying a clump weight."""
    text = text.replace("""6      Vessel    20.434  -35.393   -14.0     0       0       0     0""",
    """6      Vessel    20.434  -35.393   -14.0     0       0       0     0
7      Free     200.0    346.0    -190.0  {m}  {v}  0     0
8      Free    -400.0      0.0    -190.0  {m}  {v}  0     0
9      Free     200.0   -346.0    -190.0  {m}  {v}  0     0""".format(m=mass, v=volume))
    text = text.replace("""1         main        1         4       835.35     20        -
2         main        2         5       835.35     20        -
3         main        3         6       835.35     20        -""",
    """1         main        1         7       400.0      10        -
2         main        2         8       400.0      10        -
3         main        3         9       400.0      10        -
4         main        7         4       435.35     10        -
5         main        8         5       435.35     10        -
6         main        9         6       435.35     10        -""")
    return text


def fmu_parameters(deck: SystemDeck, **extra) -> dict:
    """lineFile plus what the deck does not set, as MoorDyn has it (docs/lines.md): the seabed from kBot
    and cBot times the lines' diameter, tension-only lines."""
    d = deck.diameters[0]
    p = {"lineFile": str(deck.path), "enableSeabed": True, "seabedStiffness": deck.option("kBot", 3.0e6) * d,
         "seabedDamping": deck.option("cBot", 3.0e5) * d, "enableCompression": False}
    p.update(extra)
    return p


def attach_vessel_points(s, body):
    """The deck's Vessel points (MoorPy's coupled points) made points of `body` at their coordinates (what the
    FMU's body 1 carries); returns the body."""
    for p in s.pointList:
        if p.type == -1:
            p.type = 1
            body.attachPoint(p.number, np.array(p.r, float))
    return body


def moorpy_statics(deck: SystemDeck, pose=(0.0,) * 6) -> dict:
    """MoorPy with the Vessel points on a coupled body at `pose` (MoorPy's angles: R = Rz Ry Rx):
    line tensions, the body's force and moment (lines only) and its analytic coupled stiffness."""
    s = _moorpy_system(deck.path, deck.depth)
    with moorpy.silenced():
        body = attach_vessel_points(s, s.addBody(-1, np.array(pose, float)))
        s.initialize()
        s.solveEquilibrium(tol=1e-8, maxIter=2000)
        K = s.getCoupledStiffnessA(lines_only=True)
    fair, anch = [], []
    for ln in s.lineList:
        a_is_fair = s.pointList[ln.attached[0] - 1].number in body.attachedP
        fair.append(float(ln.TA if a_is_fair else ln.TB))
        anch.append(float(ln.TB if a_is_fair else ln.TA))
    return {"fairlead": fair, "anchor": anch, "load": np.array(body.getForces(lines_only=True), float),
            "stiffness": np.array(K, float)}


def fmu_statics(fmu, deck: SystemDeck, pose=(0.0,) * 6, inputs=None, **extra) -> dict:
    """The FMU's static equilibrium (initMode 0) with body 1 at `pose` (or the given body inputs)."""
    n = deck.lines
    with CableFMU(fmu, parameters=fmu_parameters(deck, **extra)) as c:
        c.initialize(inputs=inputs or {f"body[1].{name}": v for name, v in zip(POSE_NAMES, pose)})
        load = [c.get(f"body[1].force.{a}") for a in "xyz"] + [c.get(f"body[1].moment.{a}") for a in "xyz"]
        K = [[c.get(f"body[1].stiffness[{i},{j}]") for j in range(1, 7)] for i in range(1, 7)]
        return {"fairlead": [c.get(f"line[{k}].fairleadTension") for k in range(1, n + 1)],
                "anchor": [c.get(f"line[{k}].anchorTension") for k in range(1, n + 1)],
                "load": np.array(load), "stiffness": np.array(K)}


def stiffness_difference(K: np.ndarray, ref: np.ndarray) -> float:
    """Largest |K_ij - ref_ij| / sqrt(|ref_ii ref_jj|): each entry against the scale of its row's and
    column's diagonal (entries that vanish by symmetry have no scale of their own)."""
    d = np.sqrt(np.abs(np.diag(ref)))
    return float(np.max(np.abs(K - ref) / np.outer(d, d)))


# ----------------------------------------------------------------------------- dynamics
@dataclass
class PlatformMotion:
    """Surge, heave and pitch of the platform's reference point, each q = A (1 - cos(2 pi t / T)) (an
    oscillation of amplitude A about A, at rest at t = 0, as the single line's surge of
    line_file_validation)."""
    surge: tuple = (5.0, 20.0)   # amplitude [m], period [s]
    heave: tuple = (2.0, 10.0)
    pitch: tuple = (math.radians(3.0), 25.0)

    def state(self, t: float):
        """Pose (x, y, z, roll, pitch, yaw), its rate and acceleration at t."""
        q, v, a = np.zeros(6), np.zeros(6), np.zeros(6)
        for dof, (amp, period) in ((0, self.surge), (2, self.heave), (4, self.pitch)):
            w = 2.0 * math.pi / period
            q[dof] = amp * (1.0 - math.cos(w * t))
            v[dof] = amp * w * math.sin(w * t)
            a[dof] = amp * w * w * math.cos(w * t)
        return q, v, a


def body_rotation(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """R = Rx(roll) Ry(pitch) Rz(yaw), the FMU's (and MoorDyn v2's) orientation of a body."""
    cx, sx, cy, sy, cz, sz = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch), math.cos(yaw),
                              math.sin(yaw))
    Rx = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    Ry = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    Rz = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    return Rx @ Ry @ Rz


def fairlead_motion(deck: SystemDeck, q: np.ndarray, v: np.ndarray):
    """Positions and velocities of the deck's fairleads on the platform at pose q moving at v (the
    angular velocity the pose's angle rates: pitch only here, where they are the same)."""
    R = body_rotation(*q[3:])
    pos, vel = [], []
    for r in deck.fairleads:
        arm = R @ r
        pos.append(q[:3] + arm)
        vel.append(v[:3] + np.cross(v[3:], arm))
    return pos, vel


@dataclass
class History:
    code: str
    t: np.ndarray
    fairlead: np.ndarray  # [time, line]
    cpu: float
    info: str = ""


def fmu_motion(fmu, deck: SystemDeck, motion: PlatformMotion, t_end: float, comm_step: float = 0.1,
               progress=None, accelerations: bool = False, lines: list | None = None, parameters: dict | None = None,
               **extra) -> History:
    """The FMU with body 1 following the motion: pose and rates at the start of each communication step,
    with accelerations their input derivatives der(body[1].v*), der(body[1].w*) (the angles' second
    derivatives: pitch only here, where they are the angular acceleration); lines: the deck lines whose
    fairlead tension it records (default: 1 .. the number of Vessel points); parameters: the FMU's
    parameters as they are (default: fmu_parameters of the deck with extra)."""
    times = np.arange(0.0, t_end + 0.5 * comm_step, comm_step)
    lines = lines or list(range(1, len(deck.fairleads) + 1))
    out = np.zeros((len(times), len(lines)))
    names = [f"line[{k}].fairleadTension" for k in lines]
    inputs = [f"body[1].{x}" for x in POSE_NAMES] + [f"body[1].{x}" for x in
                                                     ("vx", "vy", "vz", "wx", "wy", "wz")]
    with CableFMU(fmu, parameters=parameters or fmu_parameters(deck, **extra)) as c:
        c.initialize()
        out[0] = c.get_reals(names)
        cpu0 = time.process_time()
        for k in range(len(times) - 1):
            q, v, a = motion.state(times[k])
            c.set(dict(zip(inputs, [*q, *v])))
            if accelerations:
                c.set_input_derivatives(inputs[6:], 1, list(a))
            c.do_step(comm_step, t=times[k])
            out[k + 1] = c.get_reals(names)
            if progress:
                progress(times[k + 1])
        cpu = time.process_time() - cpu0
        steps = c.get("solver.nSteps")
    return History("FMU", times, out, cpu, f"{steps:.0f} integrator steps (line 1)")


def moordyn_motion(deck: SystemDeck, motion: PlatformMotion, t_end: float, comm_step: float = 0.1,
                   per_step: bool = True, progress=None, also=(), chdir: bool = False) -> History:
    """MoorDyn fed the same deck, its Vessel points following the platform. per_step: moordyn.Step at
    every dtM of the deck with the exact fairlead position and velocity at its start (the project's way
    of driving MoorDyn, docs/performance.md: each call pays Python's overhead); otherwise one call per
    communication step, MoorDyn substepping at dtM and moving the points linearly from the step's start
    (its coupling to a master). Fairlead tensions are the magnitudes of the forces on the points. also: the
    files MoorDyn reads beside the deck; chdir: MoorDyn runs in their directory (it reads a SeafloorFile
    from the working directory)."""
    dt = deck.option("dtM", 1e-3)
    sub = int(math.ceil(comm_step / dt - 1e-9))
    dt = comm_step / sub
    calls = sub if per_step else 1
    times = np.arange(0.0, t_end + 0.5 * comm_step, comm_step)
    n = len(deck.fairleads)
    out = np.zeros((len(times), n))

    def flat(q, v):
        pos, vel = fairlead_motion(deck, q, v)
        return [float(x) for p in pos for x in p], [float(x) for u in vel for x in u]

    def coupled(t):
        q, v, _ = motion.state(t)
        return flat(q, v)

    def record(k, f):
        out[k] = np.linalg.norm(np.array(f).reshape(n, 3), axis=1)

    start = flat(np.zeros(6), np.zeros(6))
    with moordyn.System(deck.path, init=start, also=also, chdir=chdir) as md:
        cpu = moordyn.drive(md, start, len(times) - 1, comm_step, calls, coupled, record, progress)
    how = f"{calls} call{'s' if calls > 1 else ''} per {comm_step:g} s"
    return History("MoorDyn", times, out, cpu, f"dtM {dt:.2g} s, {how}")


def settled_deck(path: Path, directory: Path) -> Path:
    """The deck for MoorDyn with its Free points where MoorPy's statics puts them and a longer, tighter
    initial settling (TmaxIC 400 s, threshIC 1e-4): MoorDyn's own settling from the deck's guesses leaves
    clump weights far from their equilibrium (the OC4 clumps: 0.21 MN at the fairleads for 1.48 MN)."""
    import re

    s = _moorpy_system(path, read_system_deck(path).depth)
    with moorpy.silenced():
        s.initialize()
        s.solveEquilibrium(tol=1e-8, maxIter=2000)
    text = Path(path).read_text()
    for q in s.pointList:
        if q.type != 0:
            continue
        row = re.search(rf"^{q.number}\s+Free\s+\S+\s+\S+\s+\S+(.*)$", text, flags=re.M)
        text = text[:row.start()] + f"{q.number} Free {q.r[0]:.6f} {q.r[1]:.6f} {q.r[2]:.6f}{row.group(1)}" + \
            text[row.end():]
    text = re.sub(r"^\S+(\s+TmaxIC)", r"400.0\1", text, flags=re.M)
    text = re.sub(r"^\S+(\s+threshIC)", r"0.0001\1", text, flags=re.M)
    out = Path(directory) / f"{Path(path).stem}_settled{Path(path).suffix}"
    out.write_text(text)
    return out


def rms_difference(a: History, b: History, t_from: float = 0.0) -> dict:
    """RMS of the fairlead-tension differences over t >= t_from, per line, relative to b's mean."""
    sel = a.t >= t_from - 1e-9
    diff = a.fairlead[sel] - b.fairlead[sel]
    rms = np.sqrt(np.mean(diff ** 2, axis=0))
    mean = np.mean(b.fairlead[sel], axis=0)
    return {"rms": rms, "mean": mean, "rel_mean": rms / mean, "worst": float(np.max(rms / mean))}
