"""A tow position input that contradicts the velocity inputs is a real displacement of the tow point
(a tension spike): the FMU reports it once per run with a warning naming the distance, and stays
silent for a master whose positions are the integral of its velocities."""

from ucable.units import KNOT


def tow(make_cable, jump=0.0, steps=20, h=0.5):
    """Tows at 2 kn; from the middle of the run every other position input is off by `jump`."""
    c = make_cable(parameters={}, logging_on=True)
    V = 2.0 * KNOT
    c.initialize(0.0, inputs={"tow.vx": V})
    for k in range(steps):
        t = k * h
        c.set({"tow.x": V * t + (jump if k >= steps // 2 and k % 2 else 0.0), "tow.vx": V})
        c.do_step(h, t)
    return [m for s, cat, m in c.messages if "tow position input" in m]


def test_consistent_positions_give_no_warning(make_cable):
    assert tow(make_cable) == []


def test_a_position_jump_is_reported_once(make_cable):
    warnings = tow(make_cable, jump=1.0)
    assert len(warnings) == 1, warnings  # five mismatched steps, one report
    assert "is 1 m from where the tow point stands" in warnings[0]
    assert "tolerance 0.05 m" in warnings[0]


def test_a_jump_below_the_tolerance_is_not_reported(make_cable):
    assert tow(make_cable, jump=0.02) == []
