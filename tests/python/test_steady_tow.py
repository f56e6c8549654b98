"""A steady tow of the default (Hopland) cable with a free lower end matches the independent
steady solution (python/ucable/steady_tow.py, a scipy ODE in arc length).

Tolerance 0.5 %: with a free end the exact steady shape is a straight line with linearly growing
tension and strain (docs/model.md), which cubic Hermite elements represent exactly, so the
FMU differs from the ODE only by its solver tolerances (Newton for initMode 0, the integrator's
relTol afterwards) and by O(T/EA) < 1e-4 modelling choices (drag per stretched or unstretched
length). 0.5 % of the tension and 0.5 % of the cable length (1.5 m of end depth) leaves room for
those and would still catch any wrong load term (e.g. tangential drag on d instead of pi d is -29 %
at 2.5 kn).
"""

import math

import numpy as np
import pytest

from studies.cases.manoeuvre import constant_speed, run_tow
from ucable.steady_tow import CableProperties, solve_steady_tow
from ucable.units import KNOT

N_ELEMENTS = 20
REL_TENSION = 0.005
REL_LENGTH = 0.005


def check_against_reference(cable, ref, tow, where):
    """tow: where the tow point is now (the FMU extrapolates the last inputs over the step)."""
    L = CableProperties().length
    tow = np.asarray(tow, dtype=float)
    T = cable.get("towTension")
    Fx, Fy, Fz = (cable.get(f"towForce.{c}") for c in "xyz")
    end = np.array([cable.get(f"endPosition.{c}") for c in "xyz"]) - tow
    assert T == pytest.approx(ref.top_tension, rel=REL_TENSION), \
        f"{where}: towTension {T:.1f} N vs steady ODE {ref.top_tension:.1f} N"
    assert math.isclose(math.hypot(Fx, Fy, Fz), T, rel_tol=1e-9)
    # the cable pulls the tow point backwards and down (force of the cable ON the tow point)
    assert Fx < 0 and Fz < 0 and abs(Fy) <= 1e-6 * T
    assert -end[2] == pytest.approx(ref.end_depth, abs=REL_LENGTH * L), \
        f"{where}: end depth {-end[2]:.2f} m vs steady ODE {ref.end_depth:.2f} m"
    assert end[0] == pytest.approx(ref.end_x, abs=REL_LENGTH * L), \
        f"{where}: end x {end[0]:.2f} m vs steady ODE {ref.end_x:.2f} m"
    shape = cable.shape()
    top = np.array([shape["shape.x"][0], shape["shape.y"][0], shape["shape.z"][0]])
    assert np.allclose(top, tow, atol=1e-6 * L), f"{where}: station 1 at {top}, tow point at {tow}"
    assert np.allclose(shape["shape.x"] - tow[0], ref.x, atol=REL_LENGTH * L)
    assert np.allclose(shape["shape.z"] - tow[2], ref.z, atol=REL_LENGTH * L)


@pytest.mark.parametrize("knots", [1.1, 2.4])
def test_steady_tow_matches_ode_after_initialization_and_after_20_s(make_cable, knots):
    V = knots * KNOT
    ref = solve_steady_tow(V, CableProperties())
    cable = make_cable(parameters={"nElements": N_ELEMENTS, "initMode": 0})
    cable.initialize(inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": 0.0,
                             "tow.vx": V, "tow.vy": 0.0, "tow.vz": 0.0})
    check_against_reference(cable, ref, (0.0, 0.0, 0.0), f"{knots} kn after initialization")

    run = run_tow(cable, constant_speed(V), t_end=20.0, step=0.5, initialize=False,
                  record_shape=False)
    assert np.all(np.isfinite(run["towTension"]))
    check_against_reference(cable, ref, (V * 20.0, 0.0, 0.0), f"{knots} kn after 20 s")
    # a steady state stays steady: the tension history never leaves the 0.5 % band
    assert np.all(np.abs(run["towTension"] / ref.top_tension - 1) < REL_TENSION)
