"""The line of a MoorDyn v2 input file (parameter lineFile, docs/lines.md) through the FMU with fmpy.

A deck in the FMU's resources directory is found by a relative path and gives the same results, bit for
bit, as the same line described by parameters; parameters set alongside the deck still apply; a deck
outside the supported subset is an fmi2Error naming the file and its line.
"""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import pytest
from fmpy.fmi2 import fmi2Error

from studies.cases import mooring as m
from ucable.fmu import FMICallException, load

DECKS = Path(__file__).resolve().parents[1] / "data" / "decks"
CHAIN_DECK = DECKS / "chain.dat"

# The chain of chain.dat described by parameters, as docs/lines.md maps it: BA/-zeta = -0.8 on 40
# segments of 22.5 m, NumSegs 40 -> 20 elements.
CHAIN_BY_PARAMETERS = {
    "length": 900.0, "diameter": 0.0766, "massPerLength": 113.0, "EA": 7.5e8, "EI": 0.0,
    "axialDamping": 0.8 * (900.0 / 40) * math.sqrt(7.5e8 * 113.0),
    "Cdn": 2.4, "Cdt": 0.2, "Can": 1.0, "Cat": 0.0, "nElements": 20, "bottomEnd": 1,
    "anchor.x": m.ANCHOR_X, "anchor.y": 0.0, "anchor.z": -m.DEPTH,
    "waterDepth": m.DEPTH, "gravity": 9.81, "waterDensity": 1025.0,
    # the deck's seabed, MoorDyn's: on at WtrDpth, its default kBot and cBot (3e6 Pa/m, 3e5 Pa s/m: the
    # deck is silent) x Diam
    "enableSeabed": True, "seabedStiffness": 3.0e6 * 0.0766, "seabedDamping": 3.0e5 * 0.0766,
    "enableCompression": False,  # MoorDyn's tension-only lines, as the deck sets
}
# What the deck does not describe, set alongside it.
SCENE = {"enableSeabed": True, "seabedStiffness": 1e6, "enableBending": False}
OUTPUTS = ["towTension", "towForce.x", "towForce.z", "endTension", "touchdownArcLength",
           "minSeabedClearance"] + [f"tension[{k}]" for k in range(1, 22)] + \
          [f"shape.{c}[{k}]" for c in "xz" for k in range(1, 22)]


@pytest.fixture
def deck_in_resources(fmu_file):
    """chain.dat copied into the extracted FMU's resources/ directory (where fmpy points
    fmuResourceLocation), removed afterwards."""
    unzipdir, _ = load(fmu_file)
    resources = Path(unzipdir) / "resources"
    resources.mkdir(exist_ok=True)
    target = resources / "test_chain.dat"
    shutil.copy(CHAIN_DECK, target)
    yield target.name
    target.unlink()


def _surge_run(cable, steps: int = 6, h: float = 0.5, speed: float = 0.3):
    """Static equilibrium at the fairlead (0, 0, -70), then a surge at `speed`: outputs per step."""
    cable.initialize(inputs={"tow.z": m.FAIRLEAD_Z, "tow.vx": speed})
    history = [cable.get_reals(OUTPUTS)]
    for k in range(steps):
        cable.set({"tow.x": speed * (k + 1) * h})
        cable.do_step(h)
        history.append(cable.get_reals(OUTPUTS))
    return history


def test_a_deck_in_the_resources_is_the_same_line_as_its_parameters_bit_for_bit(make_cable, deck_in_resources):
    deck = make_cable(parameters={"lineFile": deck_in_resources, **SCENE})
    params = make_cable(parameters={**CHAIN_BY_PARAMETERS, **SCENE})
    a, b = _surge_run(deck), _surge_run(params)
    assert a[0][0] > 1.5e6  # the fairlead tension of the catenary with touchdown (docs/mooring.md)
    for k, (x, y) in enumerate(zip(a, b)):
        assert x.tobytes() == y.tobytes(), f"step {k}: {x - y}"
    assert deck.get("lineFile") == deck_in_resources


def test_a_relative_path_is_found_in_the_resources_directory(make_cable, deck_in_resources):
    # one instance only: fmpy's logger proxy hands every message to the instance made last
    cable = make_cable(parameters={"lineFile": deck_in_resources, **SCENE}, logging_on=True)
    cable.initialize(inputs={"tow.z": m.FAIRLEAD_Z})
    read = [text for _, _, text in cable.messages if "read (" in text]
    assert read and f"resources/{deck_in_resources} read" in read[0], cable.log_text()


def test_the_deck_statics_match_the_closed_form_catenary(make_cable):
    """The deck read through the FMU is the mooring chain: its static fairlead tension is the elastic
    catenary's with touchdown within the discretization error of 20 elements (docs/mooring.md: 5e-6),
    over the seabed where the chain rests (a few millimetres into it: the anchor's height)."""
    cable = make_cable(parameters={"lineFile": str(CHAIN_DECK), **SCENE})
    cable.initialize(inputs={"tow.z": m.FAIRLEAD_Z})
    rests = cable.get("endPosition.z")
    exact = m.TouchdownCatenary(m.CHAIN["length"], m.chain_weight(), m.CHAIN["EA"], -m.ANCHOR_X,
                                m.FAIRLEAD_Z - rests).fairlead_tension
    assert cable.get("towTension") == pytest.approx(exact, rel=2e-5)


def test_parameters_set_alongside_the_deck_still_apply(make_cable):
    soft = make_cable(parameters={"lineFile": str(CHAIN_DECK), **SCENE, "seabedStiffness": 1e5})
    same = make_cable(parameters={**CHAIN_BY_PARAMETERS, **SCENE, "seabedStiffness": 1e5})
    stiff = make_cable(parameters={"lineFile": str(CHAIN_DECK), **SCENE})
    for c in (soft, same, stiff):
        c.initialize(inputs={"tow.z": m.FAIRLEAD_Z})
    assert soft.get_reals(OUTPUTS).tobytes() == same.get_reals(OUTPUTS).tobytes()
    # resting where k g(p) = w: w/k + delta/2 = 12.5 mm at 1e5 against sqrt(2 delta w/k) = 2.9 mm
    assert soft.get("minSeabedClearance") < 3.0 * stiff.get("minSeabedClearance")


def _refused(make_cable, path: str) -> str:
    cable = make_cable(parameters={"lineFile": path}, logging_on=True)
    with pytest.raises(FMICallException) as err:
        cable.initialize(inputs={"tow.z": m.FAIRLEAD_Z})
    assert err.value.status == fmi2Error
    return "\n".join(text for status, _, text in cable.messages if status == "ERROR")


def test_an_unreadable_deck_is_an_error_naming_the_paths_tried(make_cable):
    log = _refused(make_cable, "no_such_deck.dat")
    assert "lineFile = 'no_such_deck.dat' cannot be read: tried " in log
    assert "resources/no_such_deck.dat (no such file)" in log
    assert str(Path.cwd() / "no_such_deck.dat") + " (no such file)" in log


@pytest.mark.parametrize("edit,line,what", [
    (("chain      0.0766", "chain      0.07z6"), 7, "Diam '0.07z6' is not a number"),
    (("1    chain     1        2", "1    chain     R1A      2"), 16, "AttachA 'R1A': a rod's end, but the deck has no RODS rows"),
    (("1    Fixed  ", "1    Vessel "), 12, "a second Vessel point (the first is point 1)"),
    (("7.5e8    -0.8", "ea.txt   -0.8"), 7, "EA 'ea.txt': the tension-strain file is not next to the deck, or cannot be read"),
    (("7.5e8    -0.8", "9e8|7.5e8 -0.8"), 7, "EA '9e8|7.5e8': the viscoelastic model needs EA_s > 0 [N], a dynamic stiffness above it"),
], ids=["non-numeric", "rod", "two-vessels", "missing-EA-file", "viscoelastic-EA-below-static"])
def test_a_refused_deck_is_an_error_naming_its_line(make_cable, tmp_path, edit, line, what):
    text = CHAIN_DECK.read_text()
    assert edit[0] in text
    path = tmp_path / "bad.dat"
    path.write_text(text.replace(edit[0], edit[1], 1))
    log = _refused(make_cable, str(path))
    assert f"lineFile {path}, line {line}: {what}" in log, log


@pytest.mark.parametrize("name", ["chain.dat", "chain_wire_chain.dat", "clump_weight.dat"])
@pytest.mark.parametrize("dx", [-2.0, 0.0, 2.0])
def test_the_deck_statics_match_moorpy_fed_the_same_file(fmu_file, name, dx):
    """MoorPy (quasi-static elastic catenaries with seabed contact, its free points solved for) reads
    the same deck: fairlead and anchor tension within the 0.5 % asked of a line described by a deck
    (docs/lines_validation.md): one line; three lines joined at pinned points; two lines joined at a
    clump weight."""
    from studies.comparisons import line_file_validation as v

    deck = v.read_deck(DECKS / name)
    ref, ours = v.moorpy_statics(deck, dx), v.fmu_statics(fmu_file, deck, dx)
    assert ours["fairlead"] == pytest.approx(ref["fairlead"], rel=5e-3)
    assert ours["anchor"] == pytest.approx(ref["anchor"], rel=5e-3)


def test_a_free_far_end_with_mass_is_the_towed_body_bit_for_bit(make_cable, tmp_path):
    """A Free point at the far end (no Fixed point) with mass, volume, drag area and added-mass
    coefficient is the towed body: bottomEnd 2 with body.addedMass = CA rho V."""
    text = CHAIN_DECK.read_text()
    fixed = "1    Fixed       -850     0     -320    0      0       0      0"
    assert fixed in text
    path = tmp_path / "towed.dat"
    path.write_text(text.replace(fixed, "1    Free        -850     0     -320    2000   0.5     1.5    0.8"))
    body = {"bottomEnd": 2, "body.mass": 2000.0, "body.volume": 0.5, "body.CdA": 1.5,
            "body.addedMass": 0.8 * 1025.0 * 0.5}
    params = {k: v for k, v in CHAIN_BY_PARAMETERS.items() if not k.startswith("anchor.")}
    deck = make_cable(parameters={"lineFile": str(path), "enableBending": False})
    same = make_cable(parameters={**params, **body, "enableBending": False})
    for c in (deck, same):
        c.initialize(inputs={"tow.z": m.FAIRLEAD_Z, "tow.vx": 1.0})
        c.do_step(0.5)
    assert deck.get("endTension") > 0.0
    assert deck.get_reals(OUTPUTS).tobytes() == same.get_reals(OUTPUTS).tobytes()


# clump_weight.dat described by parameters: the 400 m line from the fairlead is section 1, the pinned
# point with the clump weight is an attachment at its end, the 500 m line to the anchor section 2.
def _chain_section(k: int, length: float, segments: int) -> dict:
    damping = 0.8 * (length / segments) * math.sqrt(7.5e8 * 113.0)
    values = {"length": length, "diameter": 0.0766, "massPerLength": 113.0, "EA": 7.5e8, "EI": 0.0,
              "GJ": 1000.0, "axialDamping": damping, "Cdn": 2.4, "Cdt": 0.2, "Can": 1.0, "Cat": 0.0,
              "nElements": (segments + 1) // 2, "joint": 1}
    return {f"section[{k}].{name}": value for name, value in values.items()}


CLUMP_BY_PARAMETERS = {
    **{k: v for k, v in CHAIN_BY_PARAMETERS.items() if k in ("bottomEnd", "anchor.x", "anchor.y", "anchor.z",
                                                               "waterDepth", "gravity", "waterDensity",
                                                               "seabedDamping", "enableCompression")},
    "nSections": 2, **_chain_section(1, 400.0, 18), **_chain_section(2, 500.0, 22),
    "nAttachments": 1, "attachment[1].s": 400.0, "attachment[1].mass": 20000.0, "attachment[1].volume": 2.5,
    "attachment[1].CdA": 3.0, "attachment[1].addedMass": 1.0 * 1025.0 * 2.5,
}


def test_a_viscoelastic_deck_is_the_same_line_as_its_parameters_bit_for_bit(make_cable, tmp_path):
    """MoorDyn's EA_s|EA_d and BA_s|BA_d read into EA, EAdynamic, axialDamping, axialDampingDynamic: the deck and
    the parameters run the same line; its dynamic tension differs from the constant EA's."""
    path = tmp_path / "visco_chain.dat"
    path.write_text(CHAIN_DECK.read_text().replace("7.5e8    -0.8", "7.5e8|9e8 -0.8|2e6", 1))
    deck = make_cable(parameters={"lineFile": str(path), **SCENE})
    params = make_cable(parameters={**CHAIN_BY_PARAMETERS, "EAdynamic": 9e8, "axialDampingDynamic": 2e6, **SCENE})
    constant = make_cable(parameters={**CHAIN_BY_PARAMETERS, **SCENE})
    a, b, c = _surge_run(deck), _surge_run(params), _surge_run(constant)
    for k, (x, y) in enumerate(zip(a, b)):
        assert x.tobytes() == y.tobytes(), f"step {k}: {x - y}"
    assert deck.get("EAdynamic") == 0.0  # the deck's values are used, not written back
    assert abs(a[-1][0] - c[-1][0]) > 1e-4 * c[-1][0]  # in motion: the model
    # at rest: the static EA (the static solver's tolerance)
    rest = []
    for p in ({**CHAIN_BY_PARAMETERS, "EAdynamic": 9e8, "axialDampingDynamic": 2e6, **SCENE}, {**CHAIN_BY_PARAMETERS, **SCENE}):
        cable = make_cable(parameters=p)
        cable.initialize(inputs={"tow.z": m.FAIRLEAD_Z})
        rest.append(cable.get("towTension"))
    assert abs(rest[0] - rest[1]) < 1e-8 * rest[1], rest


def test_a_deck_of_two_lines_and_a_clump_weight_is_the_same_line_as_its_sections_bit_for_bit(make_cable):
    deck = make_cable(parameters={"lineFile": str(DECKS / "clump_weight.dat"), **SCENE})
    params = make_cable(parameters={**CLUMP_BY_PARAMETERS, **SCENE})
    a, b = _surge_run(deck), _surge_run(params)
    for k, (x, y) in enumerate(zip(a, b)):
        assert x.tobytes() == y.tobytes(), f"step {k}: {x - y}"


@pytest.mark.parametrize("name", ["chain.dat", pytest.param("chain_wire_chain.dat", marks=pytest.mark.slow),
                                  "clump_weight.dat"])
def test_the_surge_differs_from_moordyn_by_discretization_only(fmu_file, tmp_path, name):
    """The fairlead surge of the deck in both codes (docs/lines_validation.md): refining both meshes 2x
    (BA kept in N s) brings the two codes' tension histories closer, at the fairlead and the anchor."""
    from studies.comparisons import line_file_validation as v

    deck = v.read_deck(DECKS / name)
    fine = v.refined_deck(deck, 2, tmp_path)
    surge, t_end, t_from = v.Surge(2.0, 15.0), 45.0, 15.0
    base = v.rms_difference(v.fmu_surge(fmu_file, deck, surge, t_end), v.moordyn_surge(deck, surge, t_end), t_from)
    refined = v.rms_difference(v.fmu_surge(fmu_file, fine, surge, t_end), v.moordyn_surge(fine, surge, t_end),
                               t_from)
    for end in ("fairlead", "anchor"):
        assert refined[end]["rms"] < base[end]["rms"], (end, base[end], refined[end])
