"""Validations of a line failure (docs/line_failure.md, "Validation"): the release wave of a taut line against its
closed form, the momentum the released line takes up against the impulse of the forces on it, and the settled
pose after a break against MoorPy's equilibrium without the line."""
from __future__ import annotations

import math
import tempfile
from pathlib import Path

import numpy as np
import pytest

from studies.comparisons import line_failure_validation as v
from studies.comparisons import mooring_system as ms


@pytest.fixture(scope="module")
def released(fmu_file):
    """Line 1 of the taut deck released at its fairlead, 20 elements (the stations at the nodes)."""
    with tempfile.TemporaryDirectory() as tmp:
        deck = Path(tmp) / "taut.dat"
        deck.write_text(v.taut_deck())
        arrival = v.L0 / v.wave_speed()
        return v.release_run(fmu_file, 20, v.T_RELEASE / 20.0, v.T_RELEASE + v.CENTROID_UNTIL * arrival, deck)


def test_the_anchor_holds_its_tension_until_the_release_wave_arrives_at_L_over_c(released):
    t, T = released["t"], released["anchor"]
    T0, arrival, n = v.EA * v.STRAIN, v.L0 / v.wave_speed(), 20
    assert T[0] == pytest.approx(T0, rel=1e-6)  # a straight weightless line: T = EA strain
    assert np.all(released["broken"][t >= v.T_RELEASE - 1e-12] == 1.0)
    # before the element's fastest (dispersive) waves can reach it, the anchor holds T0
    early = (t > v.T_RELEASE) & (t < v.T_RELEASE + 0.5 * arrival)
    assert np.max(np.abs(T[early] / T0 - 1.0)) < 0.01
    # the front's centroid: the deficit of the anchor force from the release to a time after the front
    h = t[1] - t[0]
    upto = t >= v.T_RELEASE - 1e-12
    deficit = np.sum(0.5 * h * ((T0 - T[upto])[1:] + (T0 - T[upto])[:-1]))
    centroid = v.CENTROID_UNTIL * arrival - deficit / T0
    # the resolution: the released element unloads as a whole and the anchor's element feels the front as it
    # enters: each one element's transit time L0/(n c)
    assert abs(centroid - arrival) <= 2.0 * arrival / n, (centroid, arrival)
    # after the front a tension-only line is slack at the anchor (a bar would reflect -T0); the front's ringing
    late = t > v.T_RELEASE + 1.2 * arrival
    assert np.max(np.abs(T[late])) < 0.05 * T0


def test_the_released_line_takes_up_the_impulse_of_the_forces_on_it(released):
    arrival = v.L0 / v.wave_speed()
    m = v.momentum_check(released, v.MOMENTUM_UNTIL * arrival)
    # the tolerance: the centre of mass's quadrature over the 21 stations (trapezoid against Simpson)
    assert abs(m["momentum_integral"] - m["impulse_integral"]) <= m["quadrature"], m
    # and both are the closed form's -T0 tau^2/2 to the front's dispersion (the anchor force falls before L0/c)
    assert m["impulse_integral"] == pytest.approx(m["closed_form"], rel=0.02)


def test_the_platform_settles_where_moorpy_puts_it_without_the_broken_line(fmu_file):
    deck = ms.read_system_deck(ms.OC4)
    intact = v.moorpy_equilibrium(deck)
    damaged = v.moorpy_equilibrium(deck, removed=(1,))
    c_x = v.critical_damping(4.0e4, v.PLATFORM_MASS)
    start = [intact["pose"][0], intact["pose"][1], intact["pose"][5]]
    run = v.free_platform_run(fmu_file, deck, t_break=1.0, t_end=SETTLE, h=0.5, start=start, elements=10,
                              damping=(c_x, c_x, 6e9), record=20)
    q = run["q"][-1]
    offset = math.hypot(*damaged["pose"][:2])
    assert math.hypot(q[0] - damaged["pose"][0], q[1] - damaged["pose"][1]) < 0.005 * offset, (q, damaged["pose"])
    assert abs(q[2]) < 1e-4  # symmetric about the load's direction: no yaw
    T = run["tensions"][-1]
    for k in (2, 3):
        fair, anchor = damaged["tensions"][k]
        assert T[2 * (k - 1)] == pytest.approx(fair, rel=0.005), k
        assert T[2 * (k - 1) + 1] == pytest.approx(anchor, rel=0.005), k
    assert T[0] < 1e-3 * intact["tensions"][1][0]  # the broken line's bare end


SETTLE = 300.0  # [s] the damaged system's surge period is 144 s; about critical damping settles it within 2 periods
