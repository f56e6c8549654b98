"""Engineering outputs (docs/outputs.md): touchdown and grounded length on every seabed stiffness, the
cable's angles at the tow point and the anchor, layback, the seabed's reaction, the tow tension's
extremes between communication points and the online fatigue count.

References are independent: the elastic catenary with touchdown (studies.references.exact), the rainflow count
of the `rainflow` package, and the FMU's own tension sampled at fine communication steps.
"""

import math

import numpy as np
import pytest

from studies.cases import mooring as M

ELEMENTS = 20
ELEMENT_LENGTH = M.CHAIN["length"] / ELEMENTS


def statics(make_cable, fairlead_x=0.0, **extra):
    c = make_cable(parameters=M.chain_params(ELEMENTS, **extra))
    c.initialize(inputs={"tow.x": fairlead_x, "tow.z": M.FAIRLEAD_Z})
    names = ["touchdownArcLength", "groundedLength", "seabedContactForce", "layback", "topDeclination",
             "topAzimuth", "anchorUplift", "towForce.x", "towForce.z", "towTension", "towTensionMax",
             "towTensionMin"]
    return dict(zip(names, c.get_reals(names)))


@pytest.mark.parametrize("stiffness", [3e5, 1e6, 1e7, 1e8])
def test_touchdown_and_grounded_length_agree_with_the_catenary_at_every_seabed_stiffness(make_cable, stiffness):
    """The chain lies on the seabed over its last ~80 m; the touchdown point and the grounded length
    agree with the elastic catenary within one element length (the resolution of the mesh), however
    stiff the seabed (the former touchdown test against zero clearance reported no contact at 1e7)."""
    exact = M.closed_form()
    o = statics(make_cable, seabedStiffness=stiffness)
    # against the catenary's tangent point, and against its point half a diameter up (the definition)
    assert abs(o["touchdownArcLength"] - (M.CHAIN["length"] - exact.grounded)) < ELEMENT_LENGTH
    assert abs(o["groundedLength"] - exact.grounded) < ELEMENT_LENGTH
    assert abs(o["groundedLength"] - M.grounded_within(exact, 0.5 * M.CHAIN["diameter"])) < ELEMENT_LENGTH / 4
    assert o["touchdownArcLength"] + o["groundedLength"] == pytest.approx(M.CHAIN["length"], abs=1e-9)
    assert o["anchorUplift"] == 0.0  # lying on the seabed at the anchor


def test_angles_and_layback_of_the_catenary(make_cable):
    exact = M.closed_form()
    o = statics(make_cable)
    assert o["layback"] == pytest.approx(-M.ANCHOR_X, abs=1e-9)  # both ends are placed
    # At the fairlead the cable leaves towards the anchor (-x) at atan(H / V) from the vertical, V the
    # weight of the suspended length; the tension is accurate to 1e-4 (the catenary validation).
    V = M.chain_weight() * exact.suspended
    assert o["topDeclination"] == pytest.approx(math.atan2(exact.H, V), abs=2e-4)
    assert o["topAzimuth"] == pytest.approx(math.pi, abs=1e-9)
    # Statics: the tension has no extremes of its own yet.
    assert o["towTensionMax"] == o["towTension"] == o["towTensionMin"]


def test_anchor_uplift_of_a_taut_line_is_the_catenary_angle(make_cable):
    fairlead_x = 14.0  # the chain lifts off the seabed: the catenary pulls up at the anchor
    exact = M.closed_form(fairlead_x)
    assert exact.lifted
    o = statics(make_cable, fairlead_x)
    # Only the anchor's immediate neighbourhood lies within half a diameter of the seabed.
    assert o["groundedLength"] < ELEMENT_LENGTH / 8
    assert o["anchorUplift"] == pytest.approx(math.atan2(exact.anchor_vertical, exact.H), abs=2e-3)
    assert o["anchorUplift"] > 0.0


def test_seabed_contact_force_carries_the_grounded_chain_on_a_soft_seabed(make_cable):
    """Statics on a frictionless seabed: the seabed carries the wet weight of the grounded part. On a
    soft seabed (the chain sinks 3.5 mm) the contact force follows it within the weight of one element."""
    exact = M.closed_form()
    o = statics(make_cable, seabedStiffness=3e5)
    w = M.chain_weight()
    assert abs(o["seabedContactForce"] - w * exact.grounded) < w * ELEMENT_LENGTH


def start_moving(make_cable, step, t_end=20.0, speed=0.5):
    """The chain's fairlead set moving at 0.5 m/s along +x from rest: the jump in velocity rings the
    line. Position and velocity are exactly what a master at any step size passes (linear in time),
    so runs at different communication steps differ only by the time integration."""
    c = make_cable(parameters=M.chain_params(ELEMENTS))
    inputs = lambda t: {"tow.x": speed * t, "tow.vx": speed, "tow.z": M.FAIRLEAD_Z}
    c.initialize(inputs=inputs(0.0))
    rows = []
    for k in range(int(round(t_end / step))):
        t = k * step
        c.set(inputs(t))
        c.set_input_derivatives(["tow.vx"], 1, [0.0])
        c.do_step(step, t)
        rows.append(c.get_reals(["towTension", "towTensionMax", "towTensionMin"]))
    return c, np.array(rows)


def test_tension_extremes_bound_what_a_fine_master_sees_and_find_what_it_misses(make_cable):
    """At 1 s communication steps, towTensionMax/Min over each step bound the tension that a master
    sampling every 0.05 s sees in that step, within the integrator's tension tolerance (1e-3 of the
    tension scale; the two runs agree to about a tenth of it at common times), and the internal steps
    find troughs of the ringing that even the 20 fine samples per step miss."""
    coarse_cable, coarse = start_moving(make_cable, 1.0)
    _, fine = start_moving(make_cable, 0.05)
    tolerance = 1e-3 * coarse_cable.get("solver.tensionScale")
    per = fine[:, 0].reshape(-1, 20)  # the fine samples inside each coarse step
    assert np.abs(coarse[:, 0] - per[:, -1]).max() < tolerance
    assert np.all(coarse[:, 1] >= per.max(axis=1) - tolerance)
    assert np.all(coarse[:, 2] <= per.min(axis=1) + tolerance)
    assert np.all(coarse[:, 1] >= coarse[:, 0]) and np.all(coarse[:, 2] <= coarse[:, 0])
    assert (coarse[:, 2] - per.min(axis=1)).min() < -10 * tolerance


def surge(make_cable, step, extra=None, t_end=20.0):
    c = make_cable(parameters=M.chain_params(ELEMENTS, **(extra or {})))
    c.initialize(inputs=M.surge_inputs(0.0))
    rows = []
    for k in range(int(round(t_end / step))):
        t = k * step
        c.set(M.surge_inputs(t))
        c.set_input_derivatives(["tow.vx"], 1, [M.surge_acceleration(t)])
        c.do_step(step, t)
        rows.append(c.get_reals(["towTension", "towTensionMax", "towTensionMin", "fatigueDamage"]))
    return c, np.array(rows)


FATIGUE = {"fatigue.area": 0.01, "fatigue.m": 3.0, "fatigue.logK": 12.0}


HEAVE_FATIGUE = {"fatigue.area": 1e-4, "fatigue.m": 3.0, "fatigue.logK": 12.0}


def test_fatigue_damage_equals_an_offline_rainflow_count_of_the_tension_history(make_cable):
    """The Hopland cable hanging from a tow point heaving 1.5 m at 8 s, sampled every 0.01 s: the
    online count (the tension after every internal step: about 6200 steps for the 6000 samples, the
    extra ones on monotone stretches) against the rainflow package's ASTM E1049 count of the samples
    with the same S-N curve. Both count the same turning points, so the two Miner's sums agree to
    round-off; a missed turning point would shift a range by the tension change over a step (tens of
    newtons of a 5.5 kN range, a percent of the damage)."""
    rainflow = pytest.importorskip("rainflow")
    c = make_cable(parameters=dict(HEAVE_FATIGUE))
    w = 2.0 * math.pi / 8.0
    inputs = lambda t: {"tow.z": 1.5 * math.sin(w * t), "tow.vz": 1.5 * w * math.cos(w * t)}
    c.initialize(inputs=inputs(0.0))
    history = [c.get("towTension")]
    step = 0.01
    for k in range(6000):
        t = k * step
        c.set(inputs(t))
        c.set_input_derivatives(["tow.vz"], 1, [-1.5 * w * w * math.sin(w * t)])
        c.do_step(step, t)
        history.append(c.get("towTension"))
    m, K, area = HEAVE_FATIGUE["fatigue.m"], 10.0 ** HEAVE_FATIGUE["fatigue.logK"], HEAVE_FATIGUE["fatigue.area"]
    offline = sum(n * (r / area / 1e6) ** m / K for r, n in rainflow.count_cycles(history))
    assert offline > 0.0
    assert c.get("fatigueDamage") == pytest.approx(offline, rel=1e-9)


def test_fatigue_damage_is_exact_across_save_and_restore(make_cable):
    a = make_cable(parameters=M.chain_params(ELEMENTS, **FATIGUE))
    a.initialize(inputs=M.surge_inputs(0.0))
    t = 0.0
    for k in range(40):
        a.set(M.surge_inputs(t))
        a.do_step(0.25, t)
        t = (k + 1) * 0.25
    state = a.serialize_state(a.get_state())
    b = make_cable(parameters=M.chain_params(ELEMENTS, **FATIGUE))
    b.initialize(inputs=M.surge_inputs(0.0))
    b.set_state(b.deserialize_state(state), t)
    for cable in (a, b):
        for k in range(40):
            tk = t + k * 0.25
            cable.set(M.surge_inputs(tk))
            cable.do_step(0.25, tk)
    names = ["fatigueDamage", "towTensionMax", "towTensionMin"]
    assert a.get_reals(names)[0] > 0.0
    assert np.array_equal(a.get_reals(names), b.get_reals(names))


def test_fatigue_is_off_by_default(make_cable):
    _, rows = surge(make_cable, 0.5, t_end=5.0)
    assert np.all(rows[:, 3] == 0.0)


def test_tension_extremes_equal_those_of_a_very_fine_master(make_cable):
    """The other direction: towTensionMax/Min at 1 s steps are not just bounds but the extremes. A
    master sampling every 0.01 s (with each step's start) finds the same extremes within the
    integrator's tension tolerance plus what sampling can miss of a smooth peak: |T''| dt^2 / 8,
    with dt^2 T'' the largest second difference of its own samples."""
    coarse_cable, coarse = start_moving(make_cable, 1.0)
    fine_cable = make_cable(parameters=M.chain_params(ELEMENTS))
    fine_cable.initialize(inputs={"tow.x": 0.0, "tow.vx": 0.5, "tow.z": M.FAIRLEAD_Z})
    start = fine_cable.get("towTension")
    _, fine = start_moving(make_cable, 0.01)
    samples = np.concatenate([[start], fine[:, 0]])
    windows = np.array([samples[100 * k:100 * k + 101] for k in range(len(coarse))])  # with the start
    tolerance = 1e-3 * coarse_cable.get("solver.tensionScale")
    sampling = np.abs(np.diff(samples, 2)).max() / 8.0
    assert np.all(coarse[:, 1] >= windows.max(axis=1) - tolerance)
    assert np.all(coarse[:, 1] <= windows.max(axis=1) + tolerance + sampling)
    assert np.all(coarse[:, 2] <= windows.min(axis=1) + tolerance)
    assert np.all(coarse[:, 2] >= windows.min(axis=1) - tolerance - sampling)
