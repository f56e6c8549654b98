"""The full Hopland acceleration manoeuvre (1.1 -> 2.4 kn in 60 s, then 600 s) at 0.5 s steps.

Settling: the paper (Zhang & Liu 2022, Hopland 1993 data) reports the cable settles about 360 s
after the ramp, so over the last 60 s (t = 600..660 s, 540 s after the ramp) the tension must be at
the steady 2.4 kn value. 1 %: the steady free-end state itself matches to 0.5 % (test_steady_tow);
the other 0.5 % covers the remaining slow decay of the transient, whose slowest mode (the cable
swinging up at constant length against drag) decays with a time constant of order a minute.
Not marked slow: it is the foundation acceptance run (< 1 s CPU with 20 elements), so CI runs it.
"""

import numpy as np
import pytest

from studies.cases.manoeuvre import SCALAR_OUTPUTS, hopland_accelerate, run_tow
from ucable.steady_tow import CableProperties, solve_steady_tow
from ucable.units import KNOT


def test_hopland_manoeuvre_runs_to_the_end_and_settles_at_the_2p4_knot_tension(make_cable):
    profile, t_end = hopland_accelerate()
    cable = make_cable(parameters={"nElements": 20})
    run = run_tow(cable, profile, t_end, step=0.5)

    assert run.time[-1] == pytest.approx(660.0)
    assert len(run.time) == 1321
    for name in SCALAR_OUTPUTS:
        assert np.all(np.isfinite(run[name])), f"{name} has non-finite values"
    assert np.all(np.isfinite(run.shape))

    steady = solve_steady_tow(2.4 * KNOT, CableProperties())
    last = run.time >= 600.0
    T = run["towTension"][last]
    worst = np.max(np.abs(T / steady.top_tension - 1))
    assert worst < 0.01, (f"towTension over 600..660 s: {T.min():.1f}..{T.max():.1f} N, "
                          f"steady 2.4 kn {steady.top_tension:.1f} N")
    depth = -(run["endPosition.z"][-1] - run.tow[-1, 2])
    assert depth == pytest.approx(steady.end_depth, abs=0.01 * CableProperties().length)
