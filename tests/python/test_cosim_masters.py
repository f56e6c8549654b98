"""The co-simulation masters: exact FMU state rollback and serialization through them, and the
coupling error of Gauss-Seidel vs the iterative (predictor-corrector) master.

Bit-identical means np.array_equal on every output: the FMU state holds everything that determines
the continuation (integrator history included), so any difference is a defect, not round-off.
"""

import numpy as np
import pytest

from studies.cosim.masters import CABLE_OUTPUTS, Master
from studies.cases.manoeuvre import SHAPE_OUTPUTS
from studies.cosim.scenes import make_scene

OUTPUTS = CABLE_OUTPUTS + SHAPE_OUTPUTS


def continue_for(master, n, h):
    rows = []
    for _ in range(n):
        master.advance(h)
        rows.append(np.concatenate([master.cable.get_reals(OUTPUTS), master.vessel.x]))
    return np.array(rows)


@pytest.mark.parametrize("kind", ["gauss-seidel", "iterative"])
def test_snapshot_restore_and_serialization_continue_bit_identically(fmu_file, kind):
    """Save the co-simulation inside the ramp and the turn, continue, restore (same instance and a
    fresh instance from the serialized bytes) and continue again: identical to the last bit."""
    h = 0.5
    scene = make_scene("turn90", t_end=200.0, step=h, master=kind)
    a = Master(scene, fmu_file, instance_name="a")
    b = Master(scene, fmu_file, instance_name="b")
    try:
        continue_for(a, 100, h)  # into the turn (starts at 30 s)
        snap = a.snapshot()
        first = continue_for(a, 40, h)
        a.restore(snap)
        second = continue_for(a, 40, h)
        assert np.array_equal(first, second), f"max difference {np.max(np.abs(first - second))}"
        b.restore(snap)  # b was initialized at t = 0: the serialized state replaces everything
        third = continue_for(b, 40, h)
        assert np.array_equal(first, third), f"max difference {np.max(np.abs(first - third))}"
    finally:
        a.free()
        b.free()


def test_repeated_step_with_the_same_inputs_is_bit_identical(fmu_file):
    """The iterative master's premise: rollback + the same inputs = the same step."""
    scene = make_scene("accelerate", t_end=100.0, step=0.5)
    m = Master(scene, fmu_file)
    try:
        continue_for(m, 40, 0.5)  # t = 20 s: accelerating
        state = m.cable.get_state()
        m.cable.do_step(0.5, t=m.t)
        one = m.cable.get_reals(OUTPUTS)
        for _ in range(3):
            m.cable.set_state(state, time=m.t)
            m.cable.do_step(0.5, t=m.t)
            assert np.array_equal(one, m.cable.get_reals(OUTPUTS))
        m.cable.free_state(state)
    finally:
        m.free()


# A corrector converges only as far as the FMU's response to its inputs is smooth: where a corrected
# input changes IDA's sequence of internal steps, the outputs move by about the integration error
# (measured at the start of the turn, t = 30 s: 21 mN at the default tensionTolerance 1e-3, where
# the tension error is about 0.2 N). To converge to 1 mN the cable integrates to tensionTolerance 1e-5
# (0.08 N on the 8 kN tension scale).
CABLE = {"tensionTolerance": 1e-5}


def tension_error(fmu_file, kind, h, ref):
    scene = make_scene("circle", t_end=120.0, step=h, master=kind, max_iter=3, tol=1e-3)
    scene.cable_parameters = dict(CABLE)
    m = Master(scene, fmu_file)
    try:
        n = int(round(scene.t_end / h))
        T = [m.out[CABLE_OUTPUTS.index("towTension")]]
        its, worst = 0, 0.0
        for _ in range(n):
            its += m.advance(h)
            if kind == "iterative":
                worst = max(worst, m.last_change)
            T.append(m.out[CABLE_OUTPUTS.index("towTension")])
        T = np.array(T)
        if ref is None:
            return T, its, worst
        stride = int(round(h / 0.05))
        return np.max(np.abs(T - ref[::stride])), its, worst
    finally:
        m.free()


def test_iterative_master_converges_and_is_more_accurate_than_gauss_seidel(fmu_file):
    """Entry into the circle (turning at 0.5 deg/s from 30 s), 120 s: reference = Gauss-Seidel at 0.05 s. At 1 s, the corrector passes the
    vessel's mean acceleration over the step to the FMU instead of the one at the step start, which
    removes the first-order coupling error; it must converge (<= 3 corrections to 1 mN) and beat
    Gauss-Seidel at the same step (measured: 2.1 N vs 0.17 N).
    Not used here, and why: in a straight acceleration both masters are within 0.3 N of the
    reference (nothing to gain); in turn90 the rudder moment saturates and un-saturates around
    t = 100 s, the fixed-point map of that step is discontinuous and the corrector alternates
    between two force values 0.2 N apart (a property of the saturating partner, not of the FMU)."""
    ref, _, _ = tension_error(fmu_file, "gauss-seidel", 0.05, None)
    err_gs, _, _ = tension_error(fmu_file, "gauss-seidel", 1.0, ref)
    err_it, its, worst = tension_error(fmu_file, "iterative", 1.0, ref)
    print(f"max |T - T_ref| at 1 s: Gauss-Seidel {err_gs:.3f} N, iterative {err_it:.3f} N, "
          f"{its} corrections in 120 steps, last correction changed the forces by <= {worst:.2e} N")
    assert worst < 1e-3, "the corrector did not converge to 1 mN within 3 corrections"
    assert err_it < err_gs
