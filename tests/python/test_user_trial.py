"""A floating-wind deck as a user brings it (studies.comparisons.user_trial, docs/systems_mooring.md, "A
user's floating-wind deck"): chain and polyester legs, a clump weight and a buoy at their joints, a sloping
seabed from a SeafloorFile, waves from wave_frequencies.txt and a sheared current from current_profile.txt,
given to the FMU by its name alone (`lineFile`)."""

from __future__ import annotations

import pytest

from studies.comparisons import user_trial as ut


@pytest.fixture(scope="module")
def flat(fmu_file, tmp_path_factory):
    path = ut.write_case(tmp_path_factory.mktemp("flat"), waves=False, current=False, slope_deg=0.0)
    return ut.fmu_statics(fmu_file, path), ut.moorpy_statics(path, 0.0)


def test_the_deck_starts_as_it_is_without_a_warning(flat):
    ours, _ = flat
    assert "error" not in ours, ours.get("error")
    assert ours["warnings"] == []


@pytest.mark.parametrize("leg", [2, 3])
def test_the_legs_clear_of_the_seabed_at_their_joint_match_moorpy(flat, leg):
    """The buoy's leg and the plain one: each line's tension at both ends within the census's 0.5 % of
    MoorPy's elastic catenaries (the chain from the anchor, the polyester to the fairlead)."""
    ours, ref = flat
    for k in (leg - 1, leg + 2):  # the chain (deck line leg) and the polyester (deck line leg + 3)
        assert ours["A"][k] == pytest.approx(ref["A"][k], rel=5e-3)
        assert ours["B"][k] == pytest.approx(ref["B"][k], rel=5e-3)


@pytest.mark.slow
def test_every_leg_matches_moordyn_refined_and_run_to_rest(flat, tmp_path):
    """MoorDyn on four times the deck's segments, started from MoorPy's free points and run 100 s with the
    fairleads held: every fairlead tension within the census's 0.5 % (measured 0.03-0.13 %), the clump's leg
    too, where MoorPy's catenary with its clump 1.8 m above the seabed is 3.8 % below both (the leg is taut:
    its tension moves 0.4 MN per metre of the joint)."""
    ours, ref = flat
    settled = ut.write_case(tmp_path, waves=False, current=False, slope_deg=0.0, free_points=ref["points"],
                            refine=4)
    theirs = ut.moordyn_rest(settled, 100.0)
    assert ours["B"][3:] == pytest.approx(theirs["B"], rel=5e-3)


def test_on_its_slope_the_deck_starts_and_its_log_names_the_seabed_it_uses(fmu_file, tmp_path):
    """The anchors down the slope lie below WtrDpth: with a SeafloorFile that is where its seabed is, and the
    log says the plane it uses, not that the water depth moved to the deepest anchor."""
    from ucable.fmu import CableFMU

    path = ut.write_case(tmp_path, waves=False, current=False)
    with CableFMU(fmu_file, parameters={"lineFile": str(path)}, logging_on=True) as c:
        c.initialize()
        log = [text for _, _, text in c.messages]
    assert any("SeafloorFile: its grid is a plane, the seabed 150" in m for m in log), log
    assert not any("lies below WtrDpth" in m for m in log), [m for m in log if "WtrDpth" in m]
