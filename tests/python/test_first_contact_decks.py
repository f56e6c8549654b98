"""A deck runs as MoorDyn runs it, and nonsense is refused at the start (docs/lines.md, "Seabed";
docs/first_contact.md).

A MoorDyn deck loaded through `lineFile` alone has MoorDyn's seabed at WtrDpth (kBot x Diam, cBot x Diam,
FrictionCoefficient), a parameter the importer sets explicitly overrides the deck's and the log says so;
a static strain no line survives is an fmi2Error naming EA and the unit it was likely meant in; a line too
short for its ends is refused naming its length, not the anchor's coordinates.
"""

from __future__ import annotations

import pytest
from fmpy.fmi2 import fmi2Error

from studies.comparisons import first_contact_decks as fc
from studies.comparisons import public_decks as pd
from ucable.fmu import FMICallException

WD0200 = pd.PUBLIC / "md_tests_Mooring_WD0200_Chain.txt"
CHAIN = pd.PUBLIC.parent / "chain.dat"


def _messages(cable, status):
    return [text for s, _, text in cable.messages if s == status]


@pytest.mark.parametrize("name", ["md_tests_Mooring_WD0050_Chain.txt", "md_tests_Mooring_WD0200_Chain.txt",
                                  "chain.dat"])
def test_a_deck_loaded_with_line_file_alone_matches_moorpy(fmu_file, name):
    """The single chains of MoorDyn's tests rest on the seabed: loaded as they are, without the seabed
    they hung through it (fairlead 122 % and 40 % above MoorPy's for 50 and 200 m of water); with
    MoorDyn's seabed they are within the 0.5 % asked of a deck."""
    pytest.importorskip("moorpy")
    path = pd.PUBLIC / name if (pd.PUBLIC / name).exists() else pd.PUBLIC.parent / name
    r = fc.survey_deck(fmu_file, path, moordyn=False)
    after, before = r["after"], r["before"]
    assert after["status"] == "ok", after.get("reason")
    assert after["worst"] < 5e-3, after["lines"]
    assert after["verdict"] == "ok"
    if name != "chain.dat":  # its 900 m chain hangs 250 m: off the seabed, it is longer, not wrong by much
        assert before["worst"] > 0.1, before["lines"]


def test_the_log_says_where_the_seabed_comes_from(make_cable):
    c = make_cable(parameters={"lineFile": str(WD0200)}, logging_on=True)
    c.initialize(inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": 0.0})
    log = c.log_text()
    assert "seabedStiffness = 25200 N/m2 from kBot 100000 Pa/m (line 19) x Diam 0.252 m" in log, log
    assert "seabedDamping = 2520 N.s/m2 from cBot 10000 Pa s/m (line 20) x Diam 0.252 m" in log, log
    # MoorDyn's friction is not the FMU's: a warning, naming the options
    warnings = _messages(c, "WARNING")
    assert any("seabedFriction = FrictionCoefficient 0.5 (line 27)" in w and "FricDamp 200 N.s/m (MoorDyn's default"
               in w for w in warnings), warnings
    assert c.get("groundedLength") > 100.0


def test_a_parameter_the_importer_sets_overrides_the_deck_and_the_log_says_which_won(make_cable):
    """enableSeabed = false set through the FMI: the chain hangs through the seabed, as asked, and the log
    says the importer's value is used rather than the deck's seabed. Setting it to its default value
    counts: it is what the importer asked for."""
    off = make_cable(parameters={"lineFile": str(WD0200), "enableSeabed": False}, logging_on=True)
    on = make_cable(parameters={"lineFile": str(WD0200), "waterDepth": 210.0}, logging_on=True)
    for c in (off, on):
        c.initialize(inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": 0.0})
    assert "enableSeabed = false set through the FMI is used, not the deck's seabed" in off.log_text()
    assert off.get("minSeabedClearance") < -1.0  # through the seabed, as set
    assert "waterDepth = 210 set through the FMI is used, not WtrDpth 200 m (line 22)" in on.log_text()
    assert on.get("minSeabedClearance") > -0.1 and on.get("endPosition.z") == pytest.approx(-200.0, abs=0.5)


def _refusal(make_cable, parameters, inputs=None):
    c = make_cable(parameters=parameters, logging_on=True)
    with pytest.raises(FMICallException) as err:
        c.initialize(inputs=inputs or {})
    assert err.value.status == fmi2Error
    return "\n".join(_messages(c, "ERROR"))


def test_ea_given_in_mn_is_refused_at_the_start_naming_the_unit(make_cable):
    """EA = 500 meant as MN: the default tow cable stretched to many times its length ran until the
    integrator gave up (the far end 14 km deep); now refused at the start with the number and the unit."""
    errors = _refusal(make_cable, {"EA": 500.0})
    assert "EA = 500 N: the line's weight in water (5340.08 N) would stretch it 1.07e+03 %" in errors, errors
    assert "did you mean 500 MN (5e+08 N)?" in errors, errors


def test_a_static_strain_no_line_survives_is_refused_at_the_start(make_cable):
    """EA = 15 kN meant as kN: the default cable hangs stretched by a third at the top at rest (its weight in
    water, 5.3 kN, is under EA: not refused before the static solve); refused after it, with the strain
    and the unit."""
    errors = _refusal(make_cable, {"EA": 1.5e4})
    assert "EA = 15000 N: the line stretches 34.9 % at rest" in errors, errors
    assert "refusing the start: did you mean 15000 kN (1.5e+07 N)?" in errors, errors


def test_a_strain_beyond_steels_but_within_ropes_is_a_warning(make_cable):
    """The default cable at an EA that stretches it 5.2 % at the top at rest: it may be a rope, but no steel
    line."""
    c = make_cable(parameters={"EA": 1.0e5}, logging_on=True)
    c.initialize()
    warnings = _messages(c, "WARNING")
    assert any("EA = 100000 N: the line stretches" in w and "more than steel wire or chain" in w
               for w in warnings), c.log_text()


def test_a_line_too_short_for_its_anchor_is_refused_naming_its_length(make_cable, tmp_path):
    """chain.dat's 900 m chain cut to 500 m cannot reach its anchor 886 m away: the message names the
    line's length (the deck's UnstrLen), not the anchor's coordinates."""
    deck = tmp_path / "short.dat"
    deck.write_text(CHAIN.read_text().replace("1    chain     1        2        900", "1    chain     1        2        500"))
    errors = _refusal(make_cable, {"lineFile": str(deck)}, {"tow.z": -70.0})
    assert "the line is too short for where its ends are: 500 m unstretched (the deck's UnstrLen)" in errors, errors
    assert "anchor.x" not in errors, errors


def test_a_pennant_given_platform_end_first_names_its_ends_as_moorpy_does(fmu_file):
    """platform_buoy_leg.dat's pennant runs from the platform's fairlead (AttachA) to a point on the Free
    buoy body (AttachB): its fairleadTension is the platform's end, anchorTension the buoy's, each within
    the 0.5 % asked of a deck of MoorPy's tension at that end (the two ends differ by the chain's weight in
    water over the height between them, 22 % of the fairlead's tension: swapped, one was 28 % off)."""
    pytest.importorskip("moorpy")
    path = fc.OWN / "platform_buoy_leg.dat"
    r = pd.compare(fmu_file, path, given=fc.as_user(path))
    assert r["status"] == "ok", r.get("reason")
    for k, (fr, f, ar, a) in enumerate(r["lines"], start=1):
        assert f == pytest.approx(fr, rel=5e-3), f"line {k}: fairleadTension {f} N, MoorPy's {fr} N"
        assert a == pytest.approx(ar, rel=5e-3), f"line {k}: anchorTension {a} N, MoorPy's {ar} N"
    fr, f, ar, a = r["lines"][0]
    assert f > a  # the platform's end of the hanging pennant is its tauter end
