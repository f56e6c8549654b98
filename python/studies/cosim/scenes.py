"""The named co-simulation manoeuvres (vessel + cable, optionally a towed body) and their analysis.

accelerate   Hopland (1993) acceleration: 1.1 kn steady, speed order ramped to 2.4 kn in 60 s
decelerate   Hopland deceleration: 2.5 kn steady, ramped to 1.0 kn in 60 s
turn90       90 deg turn to port at 2.4 kn, heading order turning at 1 deg/s from t = 30 s
turn180      180 deg turn (U-turn) to port at 2.4 kn, 1 deg/s from t = 30 s
stop         emergency stop from 2.4 kn: speed order to zero in 5 s from t = 30 s (full astern)
circle       steady circle to port at 2.4 kn, heading order turning at 0.5 deg/s from t = 30 s
             (radius u / r = 141 m)

Settling time (accelerate, decelerate): the paper (Zhang & Liu 2022, section 3.1) says the cable
re-settles about 360 s (acceleration) and 460 s (deceleration) after the ramp ends at t = 60 s. Here:

    t_settle(eps) = (last time t with |d(t) - d_final| > eps |d_final - d_initial|) - 60 s

with d the far-end depth below the tow point, d_initial/d_final the steady depths at the initial
and final speeds from the independent steady-tow ODE (ucable.steady_tow; the FMU's own steady
state agrees with it to 0.05 m, 0.05 % of the depth change). eps = 1 % is the headline number.
"""

from __future__ import annotations

import math

import numpy as np

from .masters import CosimCase, HeadingReference
from ..cases.manoeuvre import PiecewiseLinearSpeed
from ucable.steady_tow import CableProperties, solve_steady_tow
from ucable.units import KNOT

RAMP = 60.0
TOW_SPEED_KN = 2.4
PAPER_SETTLE = {"accelerate": 360.0, "decelerate": 460.0}
SPEEDS_KN = {"accelerate": (1.1, 2.4), "decelerate": (2.5, 1.0)}
DEFAULT_T_END = {"accelerate": 1200.0, "decelerate": 1200.0, "turn90": 600.0, "turn180": 700.0,
                 "stop": 600.0, "circle": 1500.0}
T_MANOEUVRE = 30.0  # start of turns and of the stop
NAMES = tuple(DEFAULT_T_END)

# times of the cable shapes drawn in the plots
SNAPSHOTS = {"accelerate": [0, 60, 120, 240, 420, 660, 1200],
             "decelerate": [0, 60, 120, 240, 420, 660, 1200],
             "turn90": [0, 60, 90, 120, 180, 300, 600],
             "turn180": [0, 60, 120, 180, 240, 360, 700],
             "stop": [0, 31, 35, 60, 120, 240, 600],
             "circle": [0, 120, 240, 480, 720, 1000, 1500]}


def make_scene(name: str, t_end: float | None = None, **kwargs) -> CosimCase:
    if name not in NAMES:
        raise ValueError(f"unknown manoeuvre {name!r}; choose from {', '.join(NAMES)}")
    t_end = DEFAULT_T_END[name] if t_end is None else t_end
    v = TOW_SPEED_KN * KNOT
    heading = HeadingReference()
    if name in SPEEDS_KN:
        v0, v1 = SPEEDS_KN[name]
        speed = PiecewiseLinearSpeed([0.0, RAMP], [v0 * KNOT, v1 * KNOT])
    elif name == "stop":
        speed = PiecewiseLinearSpeed([0.0, T_MANOEUVRE, T_MANOEUVRE + 5.0], [v, v, 0.0])
    else:
        speed = PiecewiseLinearSpeed([0.0], [v])
        if name == "turn90":
            heading = HeadingReference(0.0, T_MANOEUVRE, math.radians(1.0), math.radians(90.0))
        elif name == "turn180":
            heading = HeadingReference(0.0, T_MANOEUVRE, math.radians(1.0), math.radians(180.0))
        elif name == "circle":
            heading = HeadingReference(0.0, T_MANOEUVRE, math.radians(0.5), math.inf)
    return CosimCase(speed=speed, heading=heading, t_end=t_end, **kwargs)


def steady_depths(name: str, cable: CableProperties = CableProperties()):
    """(initial, final) steady end depth below the tow point [m] for accelerate/decelerate."""
    v0, v1 = SPEEDS_KN[name]
    return (solve_steady_tow(v0 * KNOT, cable).end_depth, solve_steady_tow(v1 * KNOT, cable).end_depth)


def settling_time(time, depth, d_initial, d_final, eps=0.01, t_ref=RAMP) -> float:
    """Last time |depth - d_final| > eps |d_final - d_initial|, minus t_ref; NaN if the run ends
    outside the band (not settled within the run)."""
    band = eps * abs(d_final - d_initial)
    outside = np.abs(np.asarray(depth) - d_final) > band
    if outside[-1]:
        return math.nan
    idx = np.nonzero(outside)[0]
    if len(idx) == 0:
        return 0.0
    return float(time[idx[-1] + 1] - t_ref)
