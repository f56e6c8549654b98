"""A deck's line whose NumSegs give too coarse a mesh for a right start (docs/lines.md, "Elements from
NumSegs"): the FMU starts it on the first finer mesh its search finds to pass the start's check, with a
warning naming the line, both element counts, the check's error at the deck's and lineFileElements; an
explicit lineFileElements is the user's choice, refused as before where its start is wrong."""

import re

import numpy as np
import pytest

from studies.comparisons import public_decks as pd

# The lazy-wave cable of MoorDyn's BodiesAndRods deck (200 m of cable from an anchor 200 m out in 70 m of water,
# 50 m buoyant, 50 m of cable), its top on a coupled point: the deck's 12 + 6 + 6 segments give it 6 + 3 + 3
# elements, on which its touchdown's anchor tension comes out 4.4 % below the elastic catenary's.
LAZY_WAVE = """MoorDyn v2 input file: a lazy-wave cable from a coupled point
------------------------- LINE TYPES --------------------------------------------------
LineType  Diam    MassDenInAir    EA       BA/-zeta    EI    Can   Cat  Cdn   Cdt
(-)       (m)       (kg/m)        (N)      (Pa-s/-)  (n-m^2) (-)   (-)  (-)   (-)
cable     0.175      40       751e6         -0.8      0.0    1.0   0.0  1.2   0.008
buoyancy  0.26       40       751e6         -0.8      0.0    1.0   0.0  1.2   0.008
----------------------- POINTS ----------------------------------------------
Node      Type      X        Y         Z        M        V         CdA   CA
(-)       (-)      (m)      (m)       (m)      (kg)     (m^3)     (m^2)  (-)
1         Fixed   -200       0      -70         0        0         0     0
2         Free     -60       0      -30         0        0         0     0
3         Free     -20       0      -30         0        0         0     0
4         Coupled   -7       0       -8         0        0         0     0
-------------------------- LINES -------------------------------------------------
Line     LineType NodeA     NodeB  UnstrLen  NumSegs     Flags/Outputs
(-)      (-)       (-)       (-)   (m)         (-)          (-)
1        cable      1         2    200          12           p
2      buoyancy     2         3     50           6           p
3        cable      3         4     50           6           p
-------------------------- SOLVER OPTIONS---------------------------------------------------
3.0e6    kb           - bottom stiffness
3.0e5    cb           - bottom damping
70       WtrDpth      - water depth
--------------------------- need this line -------------------------------------------------
"""


@pytest.fixture
def lazy_wave(tmp_path):
    path = tmp_path / "lazy_wave.dat"
    path.write_text(LAZY_WAVE)
    return path


def test_a_deck_line_too_coarse_for_its_start_starts_on_a_finer_mesh_with_a_warning(fmu_file, lazy_wave):
    """The deck's 6 + 3 + 3 elements put the anchor 4.4 % below the catenary (the check's limit 1 %): the FMU
    starts the line on the search's first finer mesh instead and says so; its end tensions are MoorPy's
    (whose catenary is exact here) within the check's 1 %."""
    pytest.importorskip("moorpy")
    result = pd.compare(fmu_file, lazy_wave)
    assert result["status"] == "ok", result.get("reason")
    assert result["worst"] < 0.01, result["lines"]
    warned = [w for w in result["warnings"] if "NumSegs give the line" in w]
    assert len(warned) == 1, result["warnings"]
    # (the FMU walks the cable from its top: its sections 3, 3 and 6)
    found = re.search(r"NumSegs give the line 3, 3, 6 elements, too coarse for its start \(the static equilibrium "
                      r"found differs from the line's elastic catenary.*\(([-+0-9.]+) % and ([-+0-9.]+) %\)\); "
                      r"started on (\d+), (\d+), (\d+) elements instead", warned[0])
    assert found, warned[0]
    assert abs(float(found.group(2))) > 1.0  # the error at the deck's elements, beyond the check's 1 %
    assert int(found.group(3)) == int(found.group(4)) == int(found.group(5)) == 12  # twice the deck's most, 6
    assert "set lineFileElements" in warned[0]


def test_an_explicit_line_file_elements_too_coarse_for_the_start_is_still_refused(fmu_file, lazy_wave, monkeypatch):
    """The same deck with lineFileElements = 12 set by the user (12 elements over the line, shared by length:
    8 + 2 + 2): the user's mesh is kept, and its wrong start refused as before, naming the count on which the
    line starts."""
    parameters = pd.parameters
    monkeypatch.setattr(pd, "parameters", lambda *a, **k: {**parameters(*a, **k), "lineFileElements": 12})
    result = pd.load(fmu_file, lazy_wave)
    assert result["status"] == "refused", result
    assert "differs from the line's elastic catenary" in result["reason"], result["reason"]
    assert re.search(r"with lineFileElements = \d+ the same line starts", result["reason"]), result["reason"]
    assert not any("NumSegs give the line" in w for w in result["warnings"]), result["warnings"]


def test_bodies_and_rods_starts_its_lazy_wave_cable_on_a_finer_mesh_balanced(fmu_file):
    """MoorDyn's BodiesAndRods deck (a free body of 1000 t with a can through the waterline and a second can
    pinned to it, three nylon legs, the lazy-wave cable above) was refused: its cable's anchor tension 10.9 %
    off the catenary on the deck's 6 + 3 + 3 elements. It starts with the warning, and its start is checked
    independently of the FMU (studies.comparisons.bodies_and_rods): MoorPy's lines with the body's points held
    where the FMU puts them give every line's end tensions within the start's 1 % check (measured 0.012 %), and
    the body's loads summed at its pose (its weight, the cans' weight and the water each displaces, cut by the
    surface, the lines' forces from MoorPy) balance to 1e-6 of its weight, force and moment (over 10 m), the
    pinned can's about its pin too (measured 3e-8)."""
    pytest.importorskip("moorpy")
    from studies.comparisons import bodies_and_rods as br

    r = br.compute(fmu_file, br.DECK)
    assert r["moorpy"] is None, r["moorpy"]
    warned = [w for w in r["fmu"]["warnings"] if "NumSegs give the line" in w]
    assert len(warned) == 1 and "mooring line 6: the deck's NumSegs give the line 3, 3, 6 elements" in warned[0], warned
    assert "-10.93 %" in warned[0], warned[0]  # the anchor's error at the deck's elements
    for k, line in r["lines"].items():
        assert max(abs(d) for d in line["difference"]) < 0.01, (k, line)
    assert max(r["points"].values()) < 0.05  # the cable's free points [m] (measured 8 mm)
    assert np.abs(r["force"]).max() < 1e-6 and np.abs(r["moment"]).max() < 1e-6, (r["force"], r["moment"])
    assert np.abs(r["pin_moment"]).max() < 1e-6, r["pin_moment"]


def test_a_state_on_the_finer_mesh_continues_in_an_instance_started_on_the_decks(graded_state_continuation, lazy_wave):
    """The cable started with its top at (0, 0, -8) m runs on the finer mesh (the warning above); a fresh
    instance started with its top 20 m farther out, where the deck's 6 + 3 + 3 elements pass the check, takes
    its serialized state (the line made again on the state's mesh) and continues exactly as the first."""
    parameters = {"lineFile": str(lazy_wave), "enableSeabed": True, "seabedStiffness": 3e6 * 0.175,
                  "seabedDamping": 3e5 * 0.175, "enableCompression": False}
    first, second = graded_state_continuation(parameters, -8.0, {"tow.x": 20.0}, ["towTension", "endTension"])
    np.testing.assert_array_equal(first, second)
