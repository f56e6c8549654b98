"""Torsion scenes through the FMU: Greenhill's buckling torque and hockling.

Greenhill: a weightless hinged-hinged rod along x (L = 10 m, EI = 100 N.m2, EA = 1e6 N, m = 1 kg/m,
Cdn = 1, 20 elements), tow point fixed at (0, 0, -50), far end anchored at (L (1 + T/EA), 0, -50) so
that the tension is T. A tiny lateral endCouple.y (1e-6 EI/L) during the initial equilibrium is the
imperfection; then a constant torque H (torqueMode 1) acts for 60 s at 0.5 s steps. The rod is
unstable when its largest lateral deflection grows 100-fold (or the integration fails, a buckled
rod thrashing). Exact threshold: H_cr = 2 EI sqrt(pi^2/L^2 + T/EI).

Hockling: a cable twisted by a prescribed end rotation (torqueMode 2) whose tow point is moved
toward the anchor, releasing the tension; the writhe of the forming loop takes up twist and the
torque falls.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ucable.fmu import NUM_STATIONS, CableFMU

GREENHILL_L = 10.0
GREENHILL_EI = 100.0
GREENHILL_EA = 1e6
DEPTH = -50.0
TENSIONS = (0.0, 100.0, 400.0)


def greenhill_exact(tension: float, EI: float = GREENHILL_EI, L: float = GREENHILL_L) -> float:
    return 2 * EI * math.sqrt(math.pi**2 / L**2 + tension / EI)


def greenhill_parameters(tension: float, n_elements: int = 20) -> dict:
    L, EA = GREENHILL_L, GREENHILL_EA
    return {"length": L, "diameter": 0.02, "massPerLength": 1.0, "EA": EA, "EI": GREENHILL_EI,
            "gravity": 0.0, "Cdn": 1.0, "Cdt": 0.0, "nElements": n_elements, "bottomEnd": 1,
            "anchor.x": L * (1 + tension / EA), "anchor.y": 0.0, "anchor.z": DEPTH,
            "initialDirection.x": 1.0, "initialDirection.y": 0.0, "initialDirection.z": 0.0,
            "enableTorsion": True, "torqueMode": 1, "axialDamping": 0.01 * EA}


def _lateral(cable: CableFMU) -> float:
    s = cable.shape()
    return float(np.max(np.hypot(s["shape.y"], s["shape.z"] - DEPTH)))


def deflection_growth(fmu_file, tension: float, H: float, t_end: float = 60.0, step: float = 0.5,
                      limit: float = 1e3) -> float:
    """Largest lateral deflection over t_end under torque H divided by the initial imperfection
    (inf when the integration fails: the buckled rod thrashes)."""
    cable = CableFMU(fmu_file, parameters=greenhill_parameters(tension), instance_name="greenhill")
    try:
        cable.initialize(0.0, inputs={"tow.z": DEPTH, "endCouple.y": 1e-6 * GREENHILL_EI / GREENHILL_L})
        initial = _lateral(cable)
        cable.set({"endCouple.y": 0.0, "torque": H})
        worst = initial
        for _ in range(int(round(t_end / step))):
            try:
                cable.do_step(step)
            except Exception:
                return math.inf
            worst = max(worst, _lateral(cable))
            if worst > limit * initial:
                break
        return worst / initial
    finally:
        cable.free()


def critical_torque(fmu_file, tension: float, bisections: int = 5, growth: float = 100.0) -> float:
    """Bisection on H over [0.8, 1.2] H_cr; returns the midpoint of the final bracket / H_cr.
    5 bisections leave a bracket of 0.4/32 = 1.25 % of H_cr: the midpoint is within 0.63 %."""
    exact = greenhill_exact(tension)
    lo, hi = 0.8, 1.2
    for _ in range(bisections):
        mid = 0.5 * (lo + hi)
        if deflection_growth(fmu_file, tension, mid * exact) > growth:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


# ---------------------------------------------------------------------------------- hockling
@dataclass
class HocklingResult:
    t: np.ndarray
    torque: np.ndarray
    tow_tension: np.ndarray
    max_lateral: np.ndarray
    shapes: dict = field(default_factory=dict)  # time -> (x, y, z) arrays at the 21 stations
    cpu: float = 0.0


def hockling_parameters(n_elements: int = 40, GJ: float = 100.0) -> dict:
    return {"length": 10.0, "diameter": 0.02, "massPerLength": 1.0, "EA": 1e6, "EI": 100.0,
            "GJ": GJ, "gravity": 0.0, "Cdn": 1.2, "Cdt": 0.1, "nElements": n_elements,
            "bottomEnd": 1, "anchor.x": 10.004, "anchor.y": 0.0, "anchor.z": DEPTH,
            "initialDirection.x": 1.0, "initialDirection.y": 0.0, "initialDirection.z": 0.0,
            "enableTorsion": True, "torqueMode": 2, "axialDamping": 0.01 * 1e6}


def run_hockling(fmu_file, slack: float = 1.5, ramp: float = 60.0, hold: float = 60.0,
                 step: float = 0.1, turns: float = 3.0, n_elements: int = 40,
                 snapshot_times=(), progress=None) -> HocklingResult:
    """The tow point moves toward the anchor by `slack` over `ramp` seconds, then holds."""
    import time as _time
    cable = CableFMU(fmu_file, parameters=hockling_parameters(n_elements), instance_name="hockling")
    names = [f"shape.{c}[{k}]" for c in "xyz" for k in range(1, NUM_STATIONS + 1)]
    try:
        cpu0 = _time.process_time()
        cable.initialize(0.0, inputs={"tow.z": DEPTH, "twist": 2 * math.pi * turns, "endCouple.y": 1e-4})
        cable.set({"endCouple.y": 0.0})
        ts, Hs, Ts, lat = [], [], [], []
        shapes = {}
        snaps = sorted(snapshot_times)
        n = int(round((ramp + hold) / step))

        def record(t):
            v = cable.get_reals(names + ["cableTorque", "towTension"])
            x, y, z = (v[i * NUM_STATIONS:(i + 1) * NUM_STATIONS] for i in range(3))
            ts.append(t)
            Hs.append(v[-2])
            Ts.append(v[-1])
            lat.append(float(np.max(np.hypot(y, z - DEPTH))))
            while snaps and snaps[0] <= t + 1e-9:
                shapes[snaps.pop(0)] = (x.copy(), y.copy(), z.copy())

        record(0.0)
        for i in range(n):
            t = i * step
            t1 = (i + 1) * step
            # input at the start of the step; the FMU interpolates with the velocity input
            x = slack * min(t, ramp) / ramp
            vx = slack / ramp if t < ramp - 1e-9 else 0.0
            cable.set({"tow.x": x, "tow.vx": vx})
            cable.do_step(step, t=t)
            record(t1)
            if progress is not None:
                progress(t1)
        cpu = _time.process_time() - cpu0
        return HocklingResult(np.array(ts), np.array(Hs), np.array(Ts), np.array(lat), shapes, cpu)
    finally:
        cable.free()
