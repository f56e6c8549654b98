"""Anchored lines whose fairlead is above the water: the part in air weighs its dry weight, the part
in water its submerged weight, in the elements (a coarse top element crossing the surface too: its
buoyancy integrated exactly between the crossings), in the static profile that starts them and in
the check of the start. The reference is the shooting
solution of studies.references.air_catenary (MoorPy blends one weight over a line that leaves the water),
itself checked against MoorPy on submerged lines first. The lines are those of scripts/bench_statics
with the fairlead 1-30 m above the surface (docs/statics_benchmark.md): single polyester and chain
lines, two sections and a clump, at 10 and 20 elements."""

import dataclasses

import pytest

from studies.benchmarks import bench_statics as B

SEED = 2026
# Refused at every mesh, off by -9 %, -6 %, refused at 10, off by -3.8 % before the profile weighed the
# part in air dry; then refused (the long top element crossing the surface weighed its part in air wet)
ABOVE = [0, 17, 21, 25, 29]
MESHES = [10, 20]


@pytest.mark.parametrize("line", [0, 7, 8])
def test_the_shooting_reference_is_moorpy_on_submerged_lines(line):
    pytest.importorskip("moorpy")
    case = B.draw_case(SEED, line)  # fairlead below the surface: MoorPy is exact
    ours, moorpy = B.air_reference(case), B.reference(case)
    # MoorPy rests a point on the seabed within its zTol of 1 mm: 1e-4 of the tension covers it
    assert ours["fairlead"] == pytest.approx(moorpy["fairlead"], rel=1e-4)
    assert ours["anchor"] == pytest.approx(moorpy["anchor"], rel=2e-4)


def test_the_reference_weighs_the_part_in_air_dry():
    """The same line with its fairlead 20 m up: all wet, the fairlead tension would be lower by the
    buoyancy of the part in air; the reference's vertical tension at the fairlead is the submerged
    weight of the hanging part below the surface plus the dry weight above it."""
    case = dataclasses.replace(B.draw_case(SEED, 25, True), fairlead_z=20.0)
    sec = case.sections[0]
    dry = sec.massPerLength * B.G
    ref = B.air_reference(case)
    wet_case = B.air_reference(dataclasses.replace(
        case, sections=[dataclasses.replace(sec, massPerLength=sec.weight / B.G, diameter=1e-9)]))
    assert ref["fairlead"] > wet_case["fairlead"] * (1.0 + 0.5 * 20.0 * (dry - sec.weight) / wet_case["fairlead"])


@pytest.fixture(scope="module")
def runs(fmu_file):
    out = {}
    for line in ABOVE:
        case = B.draw_case(SEED, line, above_water=True)
        ref = B.air_reference(case)
        for n in MESHES:
            out[(line, n)] = (case, ref, B.fmu_run(fmu_file, case, n))
    return out


@pytest.mark.parametrize("line", ABOVE)
@pytest.mark.parametrize("n", MESHES)
def test_a_line_above_the_water_starts_at_its_dry_and_wet_catenary(runs, line, n):
    """An element crossing the surface integrates its buoyancy exactly between the crossings of the
    waterline (docs/model.md, "Lines in air and water"): a long graded top element weighs its part in
    air dry, so the line starts, and matches the reference as a submerged line does (the statics
    benchmark's acceptance at 20 elements, max 0.5 %)."""
    case, ref, run = runs[(line, n)]
    assert case.fairlead_z > 1.0
    assert run["ok"], run["message"]
    assert run["towTension"] == pytest.approx(ref["fairlead"], rel=5e-3)
    assert run["endTension"] == pytest.approx(ref["anchor"], rel=5e-3)


def test_a_beam_deck_in_air_without_bending_starts_at_its_dry_catenary(fmu_file):
    """MoorDyn's BeamSimplySupported deck (10 m of 100 kg/m, EA 1.5e9 N, between two Fixed points
    10 m apart, 10 m above the water) run without bending: a taut elastic catenary of the dry weight,
    10 = 2 (H / w) asinh(w L / 2H) + H L / EA. Its check compared with the submerged weight and
    refused the start (181.9 kN against 114.1 kN)."""
    import math

    from scipy.optimize import brentq

    from studies.comparisons import public_decks as pd
    from ucable.fmu import CableFMU

    L, EA, w = 10.0, 1.5e9, 100.0 * 9.80665
    H = brentq(lambda H: 2.0 * H / w * math.asinh(w * L / (2.0 * H)) + H * L / EA - 10.0, 1e3, 1e8, xtol=1e-6)
    expected = math.hypot(H, 0.5 * w * L)
    c = CableFMU(fmu_file, parameters={"lineFile": str(pd.PUBLIC / "md_tests_Mooring_BeamSimplySupported.txt"),
                                       "enableCompression": False, "enableSeabed": True, "enableBending": False})
    try:
        c.initialize(inputs={"tow.x": 10.0, "tow.y": 0.0, "tow.z": 10.0})
        assert c.get("towTension") == pytest.approx(expected, rel=2e-3)
        assert c.get("endTension") == pytest.approx(expected, rel=2e-3)
    finally:
        c.free()
