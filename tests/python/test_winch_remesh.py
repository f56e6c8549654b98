"""Winch remeshing leaves no trace in the tension (docs/winch.md, "Split and merge" and "Measured"):
a split or merge of the top element moves the tow tension by less than 0.1 % of its mean at any
element length, and the extremes (towTensionMax/Min) and the fatigue count of a coarse master agree
within 0.5 % with the same run sampled by a 0.01 s master. The scenes and measures are those of
python/studies/cases/winch_remesh.py."""

import pytest

from studies.cases import winch_remesh

MOVE = 1e-3  # of the mean tension: a remesh is no physical event
AGREEMENT = 5e-3  # of the mean tension (extremes) and of the Miner's sum


@pytest.mark.parametrize("element_length", [5.0, 15.0, 30.0])
@pytest.mark.parametrize("kind", ["payout", "haulin"])
def test_a_split_or_merge_moves_the_tension_less_than_a_thousandth(fmu_file, kind, element_length):
    """Sampled at 0.01 s for 2 s around each of two splits (pay-out) or merges (haul-in), the tension
    and each step's extremes stay within 0.1 % of the mean from a quadratic through the samples."""
    moves = winch_remesh.remesh_moves(kind, element_length)
    assert len(moves["remesh"]) == 2, moves["times"]
    assert max(moves["remesh"]) < MOVE, moves


@pytest.mark.parametrize("scene", [lambda: winch_remesh.towed_scene("payout", 15.0),
                                   lambda: winch_remesh.towed_scene("haulin", 15.0),
                                   winch_remesh.tension_scene], ids=["payout", "haulin", "tension"])
def test_extremes_and_fatigue_agree_with_a_fine_master(fmu_file, scene):
    """Each coarse step's towTensionMax/Min against the largest/smallest the 0.01 s master saw in
    the same interval, and the two runs' fatigueDamage, through at least two splits or merges."""
    agreement = winch_remesh.master_agreement(scene())
    assert agreement["remeshes"] >= 2, agreement
    assert agreement["max_diff"] < AGREEMENT, agreement
    assert agreement["min_diff"] < AGREEMENT, agreement
    assert agreement["damage_diff"] < AGREEMENT, agreement
