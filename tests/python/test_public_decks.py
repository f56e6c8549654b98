"""The public MoorDyn and MoorPy decks that carry only lines, points and coupled bodies
(tests/data/decks/public, python/studies/public_decks.py): each one loads, as one line or as a mooring
system, and every line's fairlead and anchor tension matches MoorPy's statics of the same file within the
0.5 % asked of a deck (docs/systems_mooring.md, "Public decks")."""

import pytest

from studies import public_decks as pd


@pytest.mark.parametrize("path", pd.decks(), ids=lambda p: p.stem)
def test_a_public_deck_loads_and_matches_moorpy(fmu_file, path):
    result = pd.compare(fmu_file, path)
    assert result["status"] == "ok", result.get("reason")
    assert result["worst"] < 5e-3, result["lines"]
