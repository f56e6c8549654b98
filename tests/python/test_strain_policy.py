"""One strain policy at the start (docs/model.md, "Strain at rest"): a line may rest as far stretched as its
material survives, a fibre rope 25 % (nylon, the most extensible, breaks at 20-25 %), a line as heavy for its
diameter as one with steel in it 10 % (chain and wire break below 3 %). Held ends farther apart than that are
refused before the statics, naming the line's length and the distance; a static state beyond it is refused
naming EA; beyond 5 % the start is a warning. MoorDyn's decks of a pretensioned rope, a soft spring and a
rope stretched 100 % (tests/data/decks, copied unchanged)."""

from __future__ import annotations

import math
import re

import pytest

from studies.comparisons import census_dynamics as cd
from studies.comparisons import public_decks as pd
from ucable.fmu import CableFMU

DECKS = pd.PUBLIC.parent
ROTATING = DECKS / "md_tests_Mooring_body_tests_rotatingBody.txt"
BODY_DRAG = DECKS / "refused" / "md_tests_Mooring_body_tests_bodyDrag.txt"
VISCO = DECKS / "refused" / "md_tests_Mooring_polyester_visco.txt"
CHAIN = DECKS / "chain.dat"


def _messages(c, status):
    return [text for s, _, text in c.messages if s == status]


def _refusal(fmu_file, path, inputs=None, **parameters) -> str:
    c = CableFMU(fmu_file, parameters={"lineFile": str(path), **parameters}, logging_on=True)
    try:
        with pytest.raises(Exception):
            c.initialize(inputs=inputs or {})
        return " ".join(_messages(c, "ERROR"))
    finally:
        c.free()


def test_a_rope_pretensioned_within_what_it_survives_starts_with_a_warning(fmu_file):
    """MoorDyn's rotatingBody: in no gravity a free body is held at the centre by six nylon lines of 0.9 m
    (EA 25152 N) to fixed points 1 m away, an 11.1 % pretension; a seventh line of 1 m reaches a coupled
    point 1 m beyond the body's side, unstretched. The body stays at the centre, each of the six carries
    EA (1 / 0.9 - 1) = 2794.67 N (one straight element of linear EA: exact to the statics' tolerance), and
    the start warns of the strain."""
    _, inputs = pd.setup(ROTATING)
    assert inputs == {"point[9].x": 2.0, "point[9].y": 0.0, "point[9].z": 5.0}
    c = CableFMU(fmu_file, parameters={"lineFile": str(ROTATING)}, logging_on=True)
    try:
        c.initialize(inputs=inputs)
        expected = 25152.0 * (1.0 / 0.9 - 1.0)
        for k in range(1, 7):
            assert c.get(f"line[{k}].fairleadTension") == pytest.approx(expected, rel=1e-9), k
            assert c.get(f"line[{k}].anchorTension") == pytest.approx(expected, rel=1e-9), k
        # the seventh, at its length between its ends, within the slack law's ramp (1e-5 EA; MoorDyn 0 N)
        assert abs(c.get("line[7].fairleadTension")) <= 1e-5 * 25152.0
        warnings = _messages(c, "WARNING")
        assert any(re.search(r"EA = 25152 N.*the line stretches 11\.1 % at rest .*more than steel wire or chain "
                             r"stretches before it breaks \(about 3 %\), within the 25 % a fibre rope survives", w)
                   for w in warnings), warnings
    finally:
        c.free()


def test_the_pretensioned_rope_deck_in_motion_agrees_with_moordyn(fmu_file):
    """rotatingBody with its coupled point surged by 1 % of the longest line (0.01 m) over 4 s periods: every
    line's tension at both ends against MoorDyn's run of the same deck, RMS over the mean and the peak, within
    the 0.1 % floor of the two codes' time integration (tests/python/test_census_dynamics.py; over 40 s at
    10 s periods the census in motion measured 4e-6 of the mean and 1e-5 at the peak)."""
    r = cd.run_deck(fmu_file, "rotatingBody", ROTATING, settings=cd.Settings(t_end=6.0, t_from=2.0, period=4.0))
    assert r["status"] == "ok" and r["moved"] == "point[9]" and r["system"], r
    assert len(r["rows"]) == 7
    for end in ("fairlead", "anchor"):
        assert r["worst"][f"{end}.rel_mean"] < 1e-3 and r["worst"][f"{end}.peak"] < 1e-3, (end, r["worst"])


def test_a_spring_within_a_ropes_stretch_at_the_decks_pose_starts_there(fmu_file):
    """MoorDyn's bodyDrag: a 10 kg body on a 4.5 m spring of EA 500 N (10 kg/m in 0.1 m: a rope's density) to an
    anchor 5 m below it; TmaxIC 0, so the body starts at rest where the deck puts it, the spring stretched 11 %
    on average, within what a rope survives (its equilibrium, the body hanging 5.77 m below the anchor, is
    MoorPy's, not the start). Its weight in water, w L = 86.07 N, hangs from the body: the closed form of an
    elastic vertical line, T = EA (5 / 4.5 - 1) +- w L / 2, 98.590 N at the body and 12.521 N at the anchor,
    which the line's cubic elements represent exactly (its tension is linear along it); the strain of the
    element at the body, 19.3 % (19.7 % at the body itself), is warned of. (At the deck's one segment the static
    solve does not settle, which the refusal says.)"""
    c = CableFMU(fmu_file, parameters={"lineFile": str(BODY_DRAG), "lineFileElements": 16}, logging_on=True)
    try:
        c.initialize()
        mean, half = 500.0 * (5.0 / 4.5 - 1.0), 0.5 * (10.0 - 1025.0 * 0.25 * math.pi * 0.1**2) * 9.81 * 4.5
        assert c.get("line[1].fairleadTension") == pytest.approx(mean + half, rel=1e-9)
        assert c.get("line[1].anchorTension") == pytest.approx(mean - half, rel=1e-9)
        warnings = _messages(c, "WARNING")
        assert any(re.search(r"EA = 500 N: the line stretches 19\.\d % at rest", w) for w in warnings), warnings
    finally:
        c.free()


def test_a_rope_between_points_twice_its_length_apart_is_refused_naming_its_length(fmu_file):
    """MoorDyn's viscoelastic test: a 1 m polyester rope between points 2 m apart, 100 % strain."""
    errors = _refusal(fmu_file, VISCO, inputs={"tow.x": 2.0})
    assert ("the line is too short for where its ends are: 1 m unstretched (the deck's UnstrLen), its far end "
            "(0, 0, 0) is 2 m from the tow point (2, 0, 0), a stretch of 100 %, more than the 25 % a fibre rope "
            "survives") in errors, errors
    assert "lengthen the line to at least 1.6 m or bring its ends within 1.25 m of each other" in errors, errors


def test_a_chain_short_of_its_anchor_by_a_ropes_stretch_is_refused_as_steel(fmu_file, tmp_path):
    """chain.dat's 900 m chain cut to 770 m: its anchor, 886 m away, is 15 % beyond it, within what a rope
    survives, not a chain (113 kg/m in 0.0766 m: steel's density): refused naming the length."""
    deck = tmp_path / "short.dat"
    deck.write_text(CHAIN.read_text().replace("1    chain     1        2        900",
                                              "1    chain     1        2        770"))
    errors = _refusal(fmu_file, deck, inputs={"tow.z": -70.0})
    assert "the line is too short for where its ends are: 770 m unstretched (the deck's UnstrLen)" in errors, errors
    assert re.search(r"a stretch of 15\.\d %, more than the 10 % a line with steel in it survives \(2\.452e\+04 "
                     r"kg/m3 for its diameter", errors), errors


def test_a_steel_cable_resting_beyond_what_steel_survives_is_refused(make_cable):
    """The default tow cable (3121 kg/m3 for its diameter: armoured) at EA 3.5e4 N stretches about 15 % at its
    top at rest: within a rope's 25 %, beyond the 10 % of a line with steel in it (at EA 1e5 N, 5.2 %, it is a
    warning: tests/python/test_first_contact_decks.py)."""
    c = make_cable(parameters={"EA": 3.5e4}, logging_on=True)
    with pytest.raises(Exception):
        c.initialize()
    errors = " ".join(_messages(c, "ERROR"))
    assert re.search(r"EA = 35000 N: the line stretches 1\d\.\d % at rest .*more than the 10 % a line with steel "
                     r"in it survives \(3121 kg/m3 for its diameter.*refusing the start: did you mean 35000 kN",
                     errors), errors
