"""The public MoorDyn and MoorPy decks the FMU loads (tests/data/decks/public, python/studies/comparisons/public_decks.py):
each one loads, as one line or as a mooring system, and every line's fairlead and anchor tension matches
MoorPy's statics of the same file within the 0.5 % asked of a deck (docs/systems_mooring.md, "Public
decks"). Where MoorPy's own equilibrium fails (named below, checked to fail), the FMU is checked against
the closed form of the deck's statics."""

import math
import re

import numpy as np
import pytest

from studies.comparisons import public_decks as pd
from ucable.fmu import CableFMU
from ucable.units import STANDARD_GRAVITY as GRAVITY

# MoorPy 1.3.0 finds no equilibrium of these: a neutrally buoyant line hanging from a fixed point (it
# leaves the weight of the end mass unbalanced), a beam between two fixed points above the water
# (tensions NaN), a W-shaped chain between two fixed points on a buoy (point 2 left with 13.5 kN
# unbalanced, its iteration wandering).
MOORPY_FAILS = {"md_tests_Mooring_lifting", "md_tests_Mooring_BeamSimplySupported", "mp_tests_case6"}


@pytest.mark.parametrize("path", pd.decks(), ids=lambda p: p.stem)
def test_a_public_deck_loads_and_matches_moorpy(fmu_file, path):
    result = pd.compare(fmu_file, path)
    assert result["status"] == "ok", result.get("reason")
    assert (result["moorpy"] is not None) == (path.stem in MOORPY_FAILS), result["moorpy"]
    if result["moorpy"] is None:
        assert result["worst"] < 5e-3, result["lines"]


def _statics(fmu_file, name, tow):
    c = CableFMU(fmu_file, parameters={"lineFile": str(pd.PUBLIC / name), "enableCompression": False,
                                       "enableSeabed": True}, logging_on=True)
    c.initialize(inputs={f"tow.{k}": v for k, v in zip("xyz", tow)})
    return c


def test_a_neutral_line_hanging_from_a_fixed_point_carries_its_end_mass(fmu_file):
    """lifting: a line of 7.85398 kg/m and 0.1 m in water of 1000 kg/m3 (net -1.6e-6 kg/m: neutral)
    hangs from the Fixed point at the origin, the tow point, with 1000 kg at its free end: the tension
    is the end mass's weight, 9806.65 N, along the whole line."""
    c = _statics(fmu_file, "md_tests_Mooring_lifting.txt", (0.0, 0.0, 0.0))
    try:
        weight = 1000.0 * GRAVITY
        assert c.get("towTension") == pytest.approx(weight, rel=1e-6)
        assert c.get("endTension") == pytest.approx(weight, rel=1e-6)
        assert any("the Fixed point 1 is the tow point" in t for _, _, t in c.messages)
    finally:
        c.free()


def test_a_beam_between_two_fixed_points_sags_as_the_tie_beam(fmu_file):
    """BeamSimplySupported: 10 m of 100 kg/m, EI 1e7 N m2, EA 1.5e9 N, pinned between two Fixed points
    10 m apart, 10 m above the water (no buoyancy): the end reactions carry half the weight each, and
    the mid-span deflection is the tie-beam's, w/T (L^2/8 + (1/cosh(kL/2) - 1)/k^2), k^2 = T/EI, its
    axial force T from the stretch T L/EA = 1/2 the integral of the slope squared (T = 6009 N: mid
    deflection 12.69 mm). The deflection is insensitive to T (12.67 mm at T = 7345 N), T is not (it
    rests on a stretch of 4e-6); the FMU's T is 7345 N and is not compared."""
    EI, EA, L, w = 1e7, 1.5e9, 10.0, 100.0 * GRAVITY

    def mid_deflection(T):
        k = math.sqrt(T / EI)
        return w / T * (L * L / 8 + (1 / math.cosh(k * L / 2) - 1) / k ** 2)

    def stretch_mismatch(T):
        k = math.sqrt(T / EI)
        x = np.linspace(0.0, L, 20001)
        slope = w / T * ((L - 2 * x) / 2 + np.sinh(k * (x - L / 2)) / math.cosh(k * L / 2) / k)
        return T * L / EA - 0.5 * np.trapezoid(slope ** 2, x)

    lo, hi = 100.0, 1e6
    for _ in range(100):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if stretch_mismatch(mid) < 0 else (lo, mid)
    c = _statics(fmu_file, "md_tests_Mooring_BeamSimplySupported.txt", (10.0, 0.0, 10.0))
    try:
        assert -c.get("towForce.z") == pytest.approx(w * L / 2, rel=1e-6)
        assert -c.get("endForce.z") == pytest.approx(w * L / 2, rel=1e-6)
        sag = 10.0 - c.shape()["shape.z"][10]  # station 11 of 21: mid-span
        assert sag == pytest.approx(mid_deflection(lo), rel=5e-3)
    finally:
        c.free()


def test_a_chain_between_two_fixed_points_on_a_buoy_balances_its_loads(fmu_file):
    """case6: 1320 m of 500 kg/m, 0.2 m chain from a Fixed point at the surface through a 200 m3 buoy
    to another, part of it on the frictionless seabed: the forces on its two ends balance horizontally
    (to 1e-6 of its weight), and vertically they leave the seabed a reaction between 0 and the weight
    of the chain (MoorPy's equilibrium of this deck leaves the buoy 13.5 kN out of balance)."""
    c = _statics(fmu_file, "mp_tests_case6.dat", (0.0, 400.0, 0.0))
    try:
        per_metre = (500.0 - 1025.0 * math.pi * 0.1 ** 2) * GRAVITY
        weight, buoyancy = per_metre * 1320.0, 1025.0 * GRAVITY * 200.0
        ends = np.array([c.get(f"towForce.{k}") + c.get(f"endForce.{k}") for k in "xyz"])
        assert np.max(np.abs(ends[:2])) < 1e-6 * weight, ends
        seabed = ends[2] - (buoyancy - weight)
        assert c.get("groundedLength") > 0.0 and 0.0 < seabed < weight, (seabed, c.get("groundedLength"))
    finally:
        c.free()


def _refusal(fmu_file, path, **parameters):
    refused = CableFMU(fmu_file, parameters={"lineFile": str(path), **parameters}, logging_on=True)
    try:
        with pytest.raises(Exception):
            refused.initialize()
        return " ".join(m[2] for m in refused.messages if m[0] == "ERROR")
    finally:
        refused.free()


def test_a_float_standing_through_the_water_surface_is_refused_naming_the_waterline(fmu_file):
    """MoorDyn's tripod: a short, very stiff float (0.63 m of 0.82 m diameter, EI 9.3e7 N m2) on a tether
    (EA 25.8 MN) from the node where three bridles meet, its top out of the water. The static solve of the
    float's line stalled at the round-off of the float's bending forces (2.7e-5 N, about 1e-16 of the
    bending terms EI B X that cancel there) and refused it as not found; converged at that floor, the float
    stands straight up, carried by the waterline's buoyancy ramp over one diameter above z = 0 (1746 N of
    its 1834 N, where MoorDyn, taking the geometric submerged length, leans it at 40 degrees with 708 N on
    the tether): the start is refused, naming the ramp's share, within seconds."""
    errors = _refusal(fmu_file, pd.PUBLIC.parent / "refused" / "md_tests_Mooring_tripod.txt")
    found = re.search(r"rests on the waterline's buoyancy ramp: .*diameter 0\.82 m.* is (\S+) N, (\S+) %", errors)
    assert found, errors
    assert 1500.0 < float(found.group(1)) < 2000.0 and float(found.group(2)) > 10.0, errors


def test_the_search_for_an_element_count_that_starts_a_line_is_cut_short_by_its_budget(fmu_file):
    """MoorDyn's bodyDrag: a body on a 4.5 m spring whose static solve does not settle on the deck's one segment,
    nor on the finer meshes tried. The trials share a budget of the static solver's work (the refusal took 25 s
    on another deck before the search had one); the refusal says the search was cut short and which element
    counts it tried, twice the deck's first."""
    errors = _refusal(fmu_file, pd.PUBLIC.parent / "refused" / "md_tests_Mooring_body_tests_bodyDrag.txt")
    assert "mooring line 1: static equilibrium not found" in errors, errors
    found = re.search(r"the search for an element count that starts the line was cut short: its budget of "
                      r"30000 element iterations of the static solver was spent \(tried ([0-9, ]+)\)", errors)
    assert found, errors
    assert found.group(1).split(", ")[0] == "2", errors  # twice the deck's 1 element a line first


def test_lines_in_the_wave_zone_are_refused_naming_the_waterline_convention(fmu_file):
    """MoorDyn's wave_surface: five 13 mm chains between fixed points from 10 m below to 10 m above the water in
    a regular wave of 5 m amplitude (0.4 rad/s in 30 m). The FMU wets a line below z = 0, MoorDyn below the
    moving surface: run, the two highest chains came out 27 % and 19 % below MoorDyn's mean tension. The start
    refuses the first line that runs along the zone within 5 m of the surface (more than twice its 10 m height
    in it), line 4 (ends 3 m above the water), naming the length, the load the convention may misplace and what
    to do."""
    errors = _refusal(fmu_file, pd.PUBLIC.parent / "refused" / "md_tests_Mooring_wave_surface" / "wave_surface.txt")
    found = re.search(r"mooring line 4: ([0-9.]+) m of the line lie within the waves' reach of the surface "
                      r"\(\|z\| < 5 m; the water there up to ([0-9.]+) m/s\): the FMU wets a line below the mean "
                      r"water level z = 0, not below the wave's surface, which would misplace up to ([0-9.]+) N of "
                      r"buoyancy and wave drag there", errors)
    assert found, errors
    # the surface water's speed a w coth(k h): 5 m x 0.4 rad/s x coth(0.762), k h from 0.4^2 = g k tanh(30 k)
    assert float(found.group(2)) == pytest.approx(3.114, abs=1e-3), errors
    assert float(found.group(1)) > 20.0, errors  # along the zone: more than twice its height
    assert "refusing the start of a line that runs along the surface (set the waves off (waves.mode 0" in errors, errors


def test_a_chain_with_a_nominal_bending_stiffness_is_checked_against_its_catenary(fmu_file, monkeypatch):
    """MoorDyn's MHK_RM1 deck gives its chains EI = 0.8 N m2: a bending length of millimetres on lines
    of 130 m, so the catenary holds their end tensions, and the static state is checked against it as
    a line without bending stiffness is. On equal elements (meshGrading 0) the anchor of line 1 came
    out 6.3 % off MoorPy (up to 15 % on another line) without an error; now the deck's 15 elements a line
    fail that check, and the line starts on the first finer mesh that passes it, with a warning (the
    deck's NumSegs chose the elements); set explicitly (lineFileElements 15), the same mesh is refused,
    naming the lineFileElements on which the line starts. Graded (the default), it is within 0.5 % of
    MoorPy."""
    pytest.importorskip("moorpy")
    path = pd.PUBLIC / "md_example_MHK_RM1_Floating_MHK_RM1_Floating_MoorDyn.dat"
    graded = pd.compare(fmu_file, path)
    assert graded["status"] == "ok" and graded["worst"] < 5e-3, graded.get("reason")
    parameters = pd.parameters
    monkeypatch.setattr(pd, "parameters", lambda *a, **k: {**parameters(*a, **k), "meshGrading": 0})
    equal = pd.compare(fmu_file, path)
    assert equal["status"] == "ok" and equal["worst"] < 1e-2, equal.get("reason")  # the start's check: 1 %
    refined = [w for w in equal["warnings"] if "NumSegs give the line 15 elements, too coarse for its start" in w]
    assert refined and all("differs from the line's elastic catenary" in w for w in refined), equal["warnings"]
    monkeypatch.setattr(pd, "parameters", lambda *a, **k: {**parameters(*a, **k), "meshGrading": 0,
                                                             "lineFileElements": 15})
    explicit = pd.compare(fmu_file, path)
    assert explicit["status"] == "refused", explicit.get("worst")
    assert "differs from the line's elastic catenary" in explicit["reason"], explicit["reason"]
    assert re.search(r"with lineFileElements = \d+ the same line starts", explicit["reason"]), explicit["reason"]
