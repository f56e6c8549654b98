"""The coupled 6x6 stiffness of a mooring system's coupled body with its free nodes re-balanced
(docs/systems_mooring.md, "Mooring stiffness") against MoorPy fed the same deck.

MoorPy gives it two ways: `getCoupledStiffnessA` (its analytic line stiffnesses, the free points' and free
bodies' degrees of freedom condensed) and finite differences of its statics (the coupled body moved by
small steps each way, the free points and bodies re-solved by `solveEquilibrium` each time, as its
`getCoupledStiffness` does, here with tight tolerances and small steps). The rotations are small turns
about the earth axes from the body's pose, as the FMU's `body[k].stiffness` has them (MoorPy's angles
compose R = Rz Ry Rx: each turned pose is converted back to its angles).

Used by tests/python/test_free_points.py; `scripts/coupled_stiffness` measures the tables of the docs (and the
cost of the stiffness per step).
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ..doc_section import write_section
from ucable.units import WATER_DENSITY
from ..peers import moorpy
from .free_points import bridle, without_line_drag, write_variant
from .mooring_system import DECKS, OC4, POSE_NAMES, PlatformMotion, _moorpy_system, clumped_oc4, fmu_parameters, \
    read_system_deck, stiffness_difference
from .public_decks import PUBLIC

BUOY_LEG = DECKS / "platform_buoy_leg.dat"  # the OC4 platform, its first leg through a subsurface buoy body
FD_STEP = (0.05, 5e-4)  # MoorPy's finite differences: [m], [rad]


def _turned(pose, axis: int, angle: float) -> np.ndarray:
    """The pose turned by `angle` about earth axis `axis` (MoorPy's angles)."""
    c, s = np.cos(angle), np.sin(angle)
    k = np.eye(3)[axis]
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    R = (np.eye(3) + s * K + (1 - c) * K @ K) @ moorpy.rotation(*pose[3:])
    return np.concatenate([pose[:3], moorpy.angles(R)])


def _moorpy_coupled(path: Path, poses: dict, current: float = 0.0):
    """MoorPy's system of the deck, solved, with its coupled bodies at `poses` ({deck body ID: pose}, the
    others at the deck's), or (a deck without bodies) a coupled body 1 at poses[1] carrying the Vessel points,
    as the FMU's body 1 does. A current along x acts on the free points and bodies as the constant drag it
    is on them at rest (MoorPy has no current on points or bodies), at a body's reference point."""
    deck = read_system_deck(path)
    s = _moorpy_system(path, deck.depth)
    with moorpy.silenced():
        if not any(b.type == -1 for b in s.bodyList):
            body = s.addBody(-1, np.zeros(6))
            for p in s.pointList:
                if p.type == -1:
                    p.type = 1
                    body.attachPoint(p.number, np.array(p.r, float))
        for b in s.bodyList:
            if b.type == -1 and b.number in poses:
                b.setPosition(np.array(poses[b.number], float))
        drag = 0.5 * WATER_DENSITY * current * abs(current)
        for p in s.pointList:
            if p.type == 0:
                p.fExt = np.array([drag * p.CdA, 0.0, 0.0])
        for b in s.bodyList:
            if b.type == 0:
                b.f6Ext = np.array([drag * b.CdA[0], 0.0, 0.0, 0.0, 0.0, 0.0])
        s.initialize()
        s.solveEquilibrium(tol=1e-8, maxIter=2000)
    return s


def coupled_poses(path: Path) -> dict:
    """The deck's coupled bodies' poses {ID: pose} (a deck without bodies: body 1 at rest)."""
    s = _moorpy_system(path)
    return {b.number: np.array(b.r6, float) for b in s.bodyList if b.type == -1} or {1: np.zeros(6)}


def _solved_load(s, body, pose) -> np.ndarray:
    with moorpy.silenced():
        body.setPosition(np.array(pose, float))
        s.solveEquilibrium(tol=1e-8, maxIter=2000)
        return np.array(body.getForces(lines_only=True), float)


def moorpy_stiffness(path: Path, poses: dict, body: int = 1, current: float = 0.0) -> dict:
    """MoorPy's coupled stiffness of coupled body `body` (its deck ID; the coupled bodies at `poses`), the free
    points and bodies re-solved: analytic (its block of `getCoupledStiffnessA`) and by central differences of
    its statics, the other coupled bodies held."""
    s = _moorpy_coupled(path, poses, current)
    coupled = [b for b in s.bodyList if b.type == -1]
    k = [b.number for b in coupled].index(body)
    with moorpy.silenced():
        analytic = np.array(s.getCoupledStiffnessA(lines_only=False), float)[6 * k:6 * k + 6, 6 * k:6 * k + 6]
    pose = np.array(coupled[k].r6, float)
    K = np.zeros((6, 6))
    for j in range(6):
        d = FD_STEP[0] if j < 3 else FD_STEP[1]
        loads = []
        for sign in (1.0, -1.0):
            q = pose.copy()
            if j < 3:
                q[j] += sign * d
            else:
                q = _turned(pose, j - 3, sign * d)
            loads.append(_solved_load(s, coupled[k], q))
        K[:, j] = -(loads[0] - loads[1]) / (2.0 * d)
    return {"analytic": analytic, "differences": K}


def fmu_stiffness(fmu, path: Path, poses: dict, body: int = 1, current: float = 0.0, **extra) -> np.ndarray:
    """The FMU's body[body].stiffness after its static start (initMode 0), the coupled bodies at `poses`, in a
    uniform current along x."""
    deck = read_system_deck(path)
    inputs = {f"body[{k}].{name}": float(v) for k, pose in poses.items() for name, v in zip(POSE_NAMES, pose)}
    inputs["current.x"] = current
    with CableFMU(fmu, parameters=fmu_parameters(deck, **extra)) as c:
        c.initialize(inputs=inputs)
        return np.array([[c.get(f"body[{body}].stiffness[{i},{j}]") for j in range(1, 7)] for i in range(1, 7)])


def cases(directory: Path) -> dict:
    """The systems compared: {name: (deck path, the coupled bodies' poses, the body[, current along x])}; the
    bridle deck and the buoy's deck without the lines' drag are written into directory."""
    bridled = Path(directory) / "oc4_bridle.dat"
    bridled.write_text(bridle(OC4.read_text()))
    two = PUBLIC / "mp_tests_case9.dat"
    without_drag = write_variant(BUOY_LEG, directory, without_line_drag)  # the current on the buoy alone
    return {"OC4 bridle, at rest": (bridled, {1: np.zeros(6)}, 1),
            "OC4 bridle, surge 5 m, heave 2 m, pitch 3 deg":
                (bridled, {1: (5.0, 0.0, 2.0, 0.0, np.radians(3.0), 0.0)}, 1),
            "platform with a leg through a buoy body, at rest": (BUOY_LEG, {1: np.zeros(6)}, 1),
            "platform with a leg through a buoy body, surge -6 m, sway 4 m, yaw 5 deg":
                (BUOY_LEG, {1: (-6.0, 4.0, 0.0, 0.0, 0.0, np.radians(5.0))}, 1),
            "platform with a leg through a buoy body, a 1 m/s current on the buoy":
                (without_drag, {1: np.zeros(6)}, 1, 1.0),
            "two bodies sharing a line (MoorPy's case9), body 1": (two, coupled_poses(two), 1),
            "two bodies sharing a line (MoorPy's case9), body 2": (two, coupled_poses(two), 2)}


def compare_case(fmu, path: Path, poses: dict, body: int, current: float = 0.0) -> dict:
    """The FMU's stiffness against MoorPy's two: the largest |dK_ij| / sqrt(K_ii K_jj)."""
    ref = moorpy_stiffness(path, poses, body, current)
    ours = fmu_stiffness(fmu, path, poses, body, current)
    return {"K": ours, "diagonal": np.diag(ours),
            "vs_differences": stiffness_difference(ours, ref["differences"]),
            "vs_analytic": stiffness_difference(ours, ref["analytic"]),
            "moorpy_analytic_vs_differences": stiffness_difference(ref["analytic"], ref["differences"])}


def compare(fmu, directory: Path, progress=None) -> list:
    rows = []
    for name, case in cases(directory).items():
        if progress:
            progress(name)
        rows.append({"case": name, **compare_case(fmu, *case)})
    return rows


# ----------------------------------------------------------------------------- cost
STIFFNESS_NAMES = [f"body[1].stiffness[{i},{j}]" for i in range(1, 7) for j in range(1, 7)]
RATES = ("vx", "vy", "vz", "wx", "wy", "wz")


def step_cost(fmu, path: Path, read: bool, steps: int = 100, comm_step: float = 0.1) -> float:
    """CPU per communication step [s] of body 1 in the surge-heave-pitch motion, reading its 36 stiffness
    entries after each step (read) or as many other outputs (the fairlead tension of line 1)."""
    deck = read_system_deck(path)
    motion = PlatformMotion()
    names = STIFFNESS_NAMES if read else ["line[1].fairleadTension"] * len(STIFFNESS_NAMES)
    inputs = [f"body[1].{x}" for x in POSE_NAMES] + [f"body[1].{x}" for x in RATES]
    with CableFMU(fmu, parameters=fmu_parameters(deck)) as c:
        c.initialize()
        cpu = time.process_time()
        for k in range(steps):
            q, v, _ = motion.state(k * comm_step)
            c.set(dict(zip(inputs, [*q, *v])))
            c.do_step(comm_step, t=k * comm_step)
            c.get_reals(names)
        return (time.process_time() - cpu) / steps


def cost_cases(directory: Path) -> dict:
    clumped = Path(directory) / "oc4_clumped.dat"
    clumped.write_text(clumped_oc4(OC4.read_text()))
    return {"OC4, three chains": OC4, "OC4, clump weights between two deck lines": clumped,
            "OC4 bridle (a free point)": cases(directory)["OC4 bridle, at rest"][0],
            "platform with a leg through a buoy body (a free body)": BUOY_LEG}


def costs(fmu, directory: Path, steps: int = 100, repeats: int = 3, progress=None) -> list:
    """Per system: the CPU of a step with and without reading the stiffness (the least of `repeats` runs)."""
    rows = []
    for name, path in cost_cases(directory).items():
        if progress:
            progress(name)
        read = min(step_cost(fmu, path, True, steps) for _ in range(repeats))
        other = min(step_cost(fmu, path, False, steps) for _ in range(repeats))
        rows.append({"case": name, "read": read, "not_read": other})
    return rows


def markdown(rows: list, cost_rows: list, steps: int) -> str:
    out = ["Measured by `scripts/coupled_stiffness` (MoorPy 1.3.0): the largest |ΔK_ij| / √(K_ii K_jj) of the FMU's "
           "`body[k].stiffness` after its static start against MoorPy fed the same deck, its free points and bodies "
           "re-solved.", "",
           "| system, body pose | against MoorPy's differences of its statics | against its `getCoupledStiffnessA` "
           "| MoorPy's two apart |", "|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['case']} | {r['vs_differences']:.1e} | {r['vs_analytic']:.1e} | "
                   f"{r['moorpy_analytic_vs_differences']:.1e} |")
    out += ["", f"CPU per communication step (0.1 s; body 1 in the surge–heave–pitch motion below; the least of three "
            f"runs of {steps} steps), reading the 36 entries of `body[1].stiffness` after each step or as many other "
            "outputs:", "", "| system | stiffness read [ms] | not read [ms] | the stiffness's share |",
            "|---|---|---|---|"]
    for r in cost_rows:
        out.append(f"| {r['case']} | {1e3 * r['read']:.2f} | {1e3 * r['not_read']:.2f} | "
                   f"{(r['read'] - r['not_read']) / r['read']:.0%} |")
    return "\n".join(out)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="scripts/coupled_stiffness", description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    parser.add_argument("--fmu", type=Path, default=None, help="the FMU (default: the built one)")
    parser.add_argument("--steps", type=int, default=100, help="communication steps of each cost run")
    parser.add_argument("--doc", type=Path, default=None, help="write the tables into this Markdown file's section")
    args = parser.parse_args(argv)
    import tempfile

    from ucable import require_fmu

    fmu = args.fmu or require_fmu()
    say = lambda name: print(f"... {name}", flush=True)  # noqa: E731
    with tempfile.TemporaryDirectory() as tmp:
        rows = compare(fmu, Path(tmp), progress=say)
        cost_rows = costs(fmu, Path(tmp), args.steps, progress=say)
    text = markdown(rows, cost_rows, args.steps)
    print(text)
    if args.doc:
        write_section(args.doc, text, "coupled_stiffness")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
