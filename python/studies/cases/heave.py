"""The heave case: a long umbilical with a heavy body hanging from a heaving vessel, in a current.

1000 m umbilical (d 0.1 m, 20 kg/m, EA 5e8 N, EI 1e4 N m2, Cdn 1.2, Cdt 0.008, Can 1), a 10 t
body (2 m3, 2 t added mass, CdA 3 m2) on its lower end (bottomEnd 2), a 0.5 m/s current along x.
The vessel heaves the top 2 m in amplitude at 10 s, the amplitude ramped in smoothly over the first
period; the run starts from the static equilibrium in the current. The top tension (about 200 kN,
+-11 % with the heave) is what a designer reads.

The master drives the FMU the way co-simulation masters do: position and velocity inputs at every
communication point, and (by default) the acceleration as input derivative der(tow.vz).
`run` flies it and returns the top tension at every communication point with the integrator
statistics and the CPU time of the stepping loop.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from ucable.fmu import CableFMU

LINE = dict(length=1000.0, diameter=0.1, massPerLength=20.0, EA=5e8, EI=1e4, Cdn=1.2, Cdt=0.008,
            Can=1.0, Cat=0.0)
BODY = {"body.mass": 10000.0, "body.volume": 2.0, "body.addedMass": 2000.0, "body.CdA": 3.0}
CURRENT = 0.5  # [m/s] along x
AMPLITUDE, PERIOD = 2.0, 10.0  # heave of the top [m], [s]

STATS = ["solver.nSteps", "solver.nResidualEvals", "solver.nJacobianEvals", "solver.nNonlinearFailures",
         "solver.nErrorTestFailures"]


def parameters(n_elements: int = 20, **extra) -> dict:
    """FMU parameters of the case (everything else at the FMU's defaults)."""
    p = dict(LINE)
    p.update(BODY)
    p.update({"nElements": n_elements, "axialDamping": 0.01 * LINE["EA"], "bottomEnd": 2, "initMode": 0,
              "initialDirection.x": 0.0, "initialDirection.y": 0.0, "initialDirection.z": -1.0})
    p.update(extra)
    return p


class RampedHeave:
    """Top heave z = A r(t) sin(2 pi t / T), r = 3 tau^2 - 2 tau^3 (tau = t / T, 1 after one period):
    position, velocity and acceleration start at rest and stay continuous."""

    def __init__(self, amplitude: float = AMPLITUDE, period: float = PERIOD, t_ramp: float | None = None):
        self.A, self.w = amplitude, 2.0 * math.pi / period
        self.tr = period if t_ramp is None else t_ramp

    def state(self, t: float):
        tau = min(max(t / self.tr, 0.0), 1.0)
        r = 3 * tau**2 - 2 * tau**3
        dr = (6 * tau - 6 * tau**2) / self.tr if t < self.tr else 0.0
        ddr = (6 - 12 * tau) / self.tr**2 if t < self.tr else 0.0
        s, c, w = math.sin(self.w * t), math.cos(self.w * t), self.w
        z = self.A * r * s
        v = self.A * (dr * s + r * w * c)
        a = self.A * (ddr * s + 2 * dr * w * c - r * w * w * s)
        return np.array([0.0, 0.0, z]), np.array([0.0, 0.0, v]), np.array([0.0, 0.0, a])


@dataclass
class HeaveRun:
    step: float
    t: np.ndarray
    tension: np.ndarray  # towTension at the communication points
    cpu: float  # process time of the stepping loop [s]
    stats: dict = field(default_factory=dict)

    def steps_per_second(self) -> float:
        return self.stats["solver.nSteps"] / self.t[-1]


def run(fmu, step: float, t_end: float = 200.0, n_elements: int = 20, derivatives: bool = True,
        extra: dict | None = None, instance_name: str = "heave", progress=None) -> HeaveRun:
    """One run with communication step `step`; outputs at the communication points."""
    traj = RampedHeave()
    n = int(round(t_end / step))
    times = np.arange(n + 1) * step
    tension = np.zeros(n + 1)
    cable = CableFMU(fmu, parameters=parameters(n_elements, **(extra or {})), instance_name=instance_name)
    try:
        cable.initialize(0.0, t_end, inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": 0.0, "current.x": CURRENT})
        tension[0] = cable.get("towTension")
        cpu0 = time.process_time()
        for k in range(n):
            p, v, a = traj.state(times[k])
            cable.set({"tow.x": p[0], "tow.y": p[1], "tow.z": p[2], "tow.vx": v[0], "tow.vy": v[1],
                       "tow.vz": v[2]})
            if derivatives:
                cable.set_input_derivatives(["tow.vx", "tow.vy", "tow.vz"], 1, a)
            cable.do_step(times[k + 1] - times[k], t=times[k])
            tension[k + 1] = cable.get("towTension")
            if progress is not None:
                progress(times[k + 1])
        cpu = time.process_time() - cpu0
        stats = dict(zip(STATS, cable.get_reals(STATS)))
    finally:
        cable.free()
    return HeaveRun(step, times, tension, cpu, stats)


def tension_errors(run_: HeaveRun, ref: HeaveRun, t_from: float = PERIOD) -> dict:
    """Top-tension errors of `run_` against `ref` at the common communication points after the
    ramp (t >= t_from): RMS relative to the RMS tension, max relative to the range of the
    reference."""
    common, i, j = np.intersect1d(np.round(run_.t, 9), np.round(ref.t, 9), return_indices=True)
    keep = common >= t_from - 1e-9
    T, Tr = run_.tension[i][keep], ref.tension[j][keep]
    return {"rms": float(np.sqrt(np.mean((T - Tr) ** 2) / np.mean(Tr**2))),
            "max_range": float(np.max(np.abs(T - Tr)) / (Tr.max() - Tr.min()))}
