"""Free points where three or more lines meet (docs/systems_mooring.md, "Free points where several lines
meet"): their static equilibrium against MoorPy fed the same deck. The acceptance: each free point's
position within 1 cm, every line's fairlead and anchor tension within 0.5 %."""

from __future__ import annotations

import pytest

from studies import free_points as fp
from studies import mooring_system as ms
from ucable.fmu import FMICallException


def _check(fmu_file, path, current=0.0):
    ref, ours = fp.moorpy_statics(path, current), fp.fmu_statics(fmu_file, path, current)
    difference = fp.compare(ours, ref)
    assert difference["distance"] < 0.01, (ours["points"], ref["points"])
    assert difference["tension"] < 5e-3, (ours, ref)
    return ours, ref


def test_a_subsurface_buoy_on_three_legs_matches_moorpy(fmu_file):
    ours, _ = _check(fmu_file, fp.BUOY)
    # the legs are alike: the buoy stands over the middle of the anchors (which the deck rounds to 1 mm)
    assert abs(ours["points"][4][0]) < 1e-3 and abs(ours["points"][4][1]) < 1e-3


def test_the_buoy_in_a_current_matches_moorpy_where_the_current_acts_on_the_buoy(fmu_file, tmp_path):
    """MoorPy's current acts on the lines through a lumped load (module docstring), not on points: the
    comparison takes the lines' drag away, so that the buoy's drag alone moves it downstream."""
    path = fp.write_variant(fp.BUOY, tmp_path, fp.without_line_drag)
    ours, ref = _check(fmu_file, path, current=1.0)
    assert ours["points"][4][0] > 0.1  # 0.5 rho CdA U^2 = 1.5 kN against the legs' horizontal stiffness


def test_the_legs_drag_carries_the_buoy_further_downstream(fmu_file):
    """With the legs' own drag (which MoorPy lumps, not compared here) the buoy drifts further than with
    its own drag alone (0.12 m at 1 m/s, above)."""
    still, drift = fp.fmu_statics(fmu_file, fp.BUOY), fp.fmu_statics(fmu_file, fp.BUOY, current=1.0)
    # the upstream leg (line 1, its anchor at +x) slackens, the two downstream legs tighten
    assert drift["fairlead"][0] < still["fairlead"][0] < drift["fairlead"][1]
    assert drift["points"][4][0] > 0.2


def test_a_bridle_of_two_anchor_legs_and_a_pennant_to_the_platform_matches_moorpy(fmu_file, tmp_path):
    path = fp.write_variant(ms.OC4, tmp_path, fp.bridle)
    _check(fmu_file, path)


def test_a_system_with_free_points_has_no_dynamics_yet(make_cable):
    c = make_cable(parameters=ms.fmu_parameters(ms.read_system_deck(fp.BUOY)), logging_on=True)
    c.initialize()
    with pytest.raises(FMICallException):
        c.do_step(0.1)
    assert any("no dynamics yet" in text for _, _, text in c.messages), c.messages
