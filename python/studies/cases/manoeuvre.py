"""Tow manoeuvres: a speed profile drives the tow point of a CableFMU.

The tow position is the exact integral of the speed profile, and the tow velocity input is the
profile itself, so position and velocity inputs are always consistent (docs/model.md: the
driven end must never jump). At each communication point t_k = k h the master sets the sampled
tow state (x(t_k), v(t_k)) and, if asked and supported, the acceleration as an input derivative.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass, field

import numpy as np

from ucable.fmu import NUM_STATIONS, CableFMU
from ucable.units import KNOT

TOW_INPUTS = ["tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz"]
SCALAR_OUTPUTS = ["towTension", "towForce.x", "towForce.y", "towForce.z",
                  "endTension", "endPosition.x", "endPosition.y", "endPosition.z",
                  "minTension"]
SHAPE_OUTPUTS = ([f"shape.x[{k}]" for k in range(1, NUM_STATIONS + 1)]
                 + [f"shape.y[{k}]" for k in range(1, NUM_STATIONS + 1)]
                 + [f"shape.z[{k}]" for k in range(1, NUM_STATIONS + 1)]
                 + [f"tension[{k}]" for k in range(1, NUM_STATIONS + 1)])


class PiecewiseLinearSpeed:
    """Speed [m/s] linear between breakpoints, constant outside; distance integrated exactly."""

    def __init__(self, times, speeds):
        if len(times) != len(speeds) or len(times) < 1:
            raise ValueError("times and speeds must have the same, non-zero length")
        if any(b <= a for a, b in zip(times, times[1:])):
            raise ValueError("times must increase")
        self.times = [float(t) for t in times]
        self.speeds = [float(v) for v in speeds]
        # distance travelled from t = 0 at every breakpoint
        self._dist = [0.0]
        for i in range(1, len(self.times)):
            dt = self.times[i] - self.times[i - 1]
            self._dist.append(self._dist[-1] + 0.5 * (self.speeds[i] + self.speeds[i - 1]) * dt)
        self._offset = self._distance_from_first(0.0)

    def _segment(self, t):
        return bisect.bisect_right(self.times, t) - 1  # -1 before the first breakpoint

    def speed(self, t: float) -> float:
        i = self._segment(t)
        if i < 0:
            return self.speeds[0]
        if i >= len(self.times) - 1:
            return self.speeds[-1]
        f = (t - self.times[i]) / (self.times[i + 1] - self.times[i])
        return self.speeds[i] + f * (self.speeds[i + 1] - self.speeds[i])

    def acceleration(self, t: float) -> float:
        i = self._segment(t)
        if i < 0 or i >= len(self.times) - 1:
            return 0.0
        return (self.speeds[i + 1] - self.speeds[i]) / (self.times[i + 1] - self.times[i])

    def _distance_from_first(self, t: float) -> float:
        i = self._segment(t)
        if i < 0:
            return self.speeds[0] * (t - self.times[0])
        v = self.speed(t)
        return self._dist[i] + 0.5 * (self.speeds[i] + v) * (t - self.times[i])

    def distance(self, t: float) -> float:
        """Distance travelled since t = 0 (negative before 0)."""
        return self._distance_from_first(t) - self._offset


def hopland_accelerate(v0_kn: float = 1.1, v1_kn: float = 2.4, ramp: float = 60.0,
                       hold: float = 600.0):
    """The Hopland (1993) acceleration manoeuvre: steady v0, linear ramp to v1 in `ramp` s, then
    `hold` s more. Returns (profile, end time)."""
    return PiecewiseLinearSpeed([0.0, ramp], [v0_kn * KNOT, v1_kn * KNOT]), ramp + hold


def constant_speed(v: float) -> PiecewiseLinearSpeed:
    return PiecewiseLinearSpeed([0.0], [v])


@dataclass
class TowRun:
    """Sampled results of a tow manoeuvre (one row per communication point, t = 0 included)."""

    time: np.ndarray
    tow: np.ndarray  # (n, 3) tow position input
    tow_velocity: np.ndarray  # (n, 3)
    outputs: dict  # name -> (n,) array for SCALAR_OUTPUTS
    shape: np.ndarray | None = field(default=None, repr=False)  # (n, 4, 21): x, y, z, tension

    def __getitem__(self, name: str) -> np.ndarray:
        return self.outputs[name]


def tow_inputs(profile, t: float, heading=(1.0, 0.0, 0.0), z: float = 0.0) -> dict:
    """FMU inputs of a tow point moving along the horizontal `heading` at depth z."""
    hx, hy, _ = heading
    norm = math.hypot(hx, hy)
    hx, hy = hx / norm, hy / norm
    d, v = profile.distance(t), profile.speed(t)
    return {"tow.x": d * hx, "tow.y": d * hy, "tow.z": z,
            "tow.vx": v * hx, "tow.vy": v * hy, "tow.vz": 0.0}


def run_tow(cable: CableFMU, profile, t_end: float, step: float, heading=(1.0, 0.0, 0.0),
            z: float = 0.0, record_shape: bool = True, initialize: bool = True,
            use_input_derivatives: bool = False, progress=None) -> TowRun:
    """Fly the tow point of `cable` along `profile` from t = 0 to t_end with communication step
    `step` (the last step is shortened to end exactly at t_end). Initializes the FMU (with the
    inputs at t = 0) unless initialize is False. progress: optional ProgressBar."""
    n = int(math.ceil(t_end / step - 1e-9))
    times = np.array([min(k * step, t_end) for k in range(n + 1)])
    if initialize:
        cable.initialize(start_time=0.0, stop_time=t_end, inputs=tow_inputs(profile, 0.0, heading, z))
    derivs = use_input_derivatives and cable.can_interpolate_inputs
    hx, hy, _ = heading
    norm = math.hypot(hx, hy)

    tow = np.zeros((n + 1, 3))
    tow_v = np.zeros((n + 1, 3))
    scalars = np.zeros((n + 1, len(SCALAR_OUTPUTS)))
    shape = np.zeros((n + 1, 4, NUM_STATIONS)) if record_shape else None

    def record(k):
        inp = tow_inputs(profile, times[k], heading, z)
        tow[k] = [inp["tow.x"], inp["tow.y"], inp["tow.z"]]
        tow_v[k] = [inp["tow.vx"], inp["tow.vy"], inp["tow.vz"]]
        scalars[k] = cable.get_reals(SCALAR_OUTPUTS)
        if record_shape:
            shape[k] = cable.get_reals(SHAPE_OUTPUTS).reshape(4, NUM_STATIONS)

    record(0)
    for k in range(n):
        t = times[k]
        cable.set(tow_inputs(profile, t, heading, z))
        if derivs:
            a = profile.acceleration(t)
            cable.set_input_derivatives(["tow.vx", "tow.vy"], 1, [a * hx / norm, a * hy / norm])
        cable.do_step(times[k + 1] - t, t=t)
        record(k + 1)
        if progress is not None:
            progress.update(times[k + 1], f"t = {times[k + 1]:6.1f} s  T = {scalars[k + 1, 0]:8.1f} N")

    return TowRun(time=times, tow=tow, tow_velocity=tow_v,
                  outputs={name: scalars[:, i] for i, name in enumerate(SCALAR_OUTPUTS)},
                  shape=shape)
