"""Decks larger than the FMU's first maxima (docs/systems_mooring.md, "Decks of any size"): a platform
held by 24 chains, a row of 8 platforms sharing anchors (24 lines, 8 coupled bodies), and a platform with
more lines than the FMU names (their load on the body is there, their tensions are not), against MoorPy
fed the same deck (the census's 0.5 %), with their states saved and restored bit for bit; the value
references of the first 16 lines, 4 bodies and 16 points as they were, the further elements after them.
"""

from __future__ import annotations

import numpy as np
import pytest

from studies.comparisons import large_decks as ld
from studies.comparisons import mooring_system as ms
from ucable.variables import MAX_BODIES, MAX_LINES, MAX_POINTS, VARIABLES

SURGE = (10.0, 0.0, 0.0, 0.0, 0.0, 0.0)


def test_the_first_elements_keep_their_value_references_and_the_further_ones_follow_the_others():
    """line[k], body[k] and point[k] up to 16, 4 and 16 have the value references they had before the
    maxima grew (the ones outside scripts use); the further elements are numbered from 10001 (inputs) and
    20001 (outputs), after every other variable."""
    vr = {n: v.value_reference for n, v in VARIABLES.items()}
    assert (MAX_LINES, MAX_BODIES, MAX_POINTS) == (64, 16, 64)
    assert vr["body[1].x"] == 1044 and vr["point[1].x"] == 1092 and vr["point[16].vz"] == 1187
    assert vr["body[4].q3"] == 1203 and vr["line[1].fairleadTension"] == 2170
    assert vr["line[16].groundedLength"] == 2233 and vr["body[4].stiffness[6,6]"] == 2401
    assert vr["point[16].position.z"] == 2500
    assert vr["body[5].x"] == 10001 and vr["line[17].fairleadTension"] == 20001
    kept = {"line": 16, "body": 4, "point": 16}
    for name, v in VARIABLES.items():
        family = name.split("[")[0]
        if family in kept and name.startswith(family + "["):
            k = int(name.split("[")[1].split("]")[0])
            beyond = k > kept[family]
            assert (v.value_reference >= 10001) == beyond, name


def _deck(tmp_path, text, name):
    return ms.read_system_deck(ld.write(text, tmp_path / name))


def test_a_platform_held_by_24_chains_loads_and_matches_moorpy(fmu_file, tmp_path):
    """24 lines (more than the 16 of before, refused then): every line's fairlead and anchor tension
    within 0.5 % of MoorPy's with the platform surged 10 m, the body's force within 0.5 % of the
    vertical load, its 6x6 stiffness within 1 % (the OC4 acceptance)."""
    deck = _deck(tmp_path, ld.radial_platform_deck(24, segments=10), "radial24.dat")
    assert deck.lines == 24
    ours, ref = ms.fmu_statics(fmu_file, deck, SURGE), ms.moorpy_statics(deck, SURGE)
    assert ours["fairlead"] == pytest.approx(ref["fairlead"], rel=5e-3)
    assert ours["anchor"] == pytest.approx(ref["anchor"], rel=5e-3)
    assert min(ref["fairlead"]) < 0.5 * max(ref["fairlead"])  # the surge loads the lines differently
    scale = abs(ref["load"][2])
    assert np.max(np.abs(ours["load"][:3] - ref["load"][:3])) < 5e-3 * scale
    assert ms.stiffness_difference(ours["stiffness"], ref["stiffness"]) < 1e-2


def _farm_inputs(platforms):
    return {f"body[{b}].{c}": x for b, p in enumerate(ld.farm_positions(platforms), start=1)
            for c, x in zip("xyz", p)}


def test_a_row_of_8_platforms_sharing_anchors_matches_moorpy(make_cable, tmp_path):
    """8 coupled bodies (more than the 4 of before) and 24 lines, 10 anchors shared by two lines: each
    line's tensions within 0.5 % of MoorPy's, each body's force within 0.5 % of its vertical load."""
    path = ld.write(ld.shared_anchor_farm(8), tmp_path / "farm8.dat")
    ref = ld.moorpy_lines(path)
    deck = ms.read_system_deck(path)
    c = make_cable(parameters=ms.fmu_parameters(deck))
    c.initialize(inputs=_farm_inputs(8))
    assert c.get_reals([f"line[{k}].fairleadTension" for k in range(1, 25)]) == pytest.approx(ref["fairlead"], rel=5e-3)
    assert c.get_reals([f"line[{k}].anchorTension" for k in range(1, 25)]) == pytest.approx(ref["anchor"], rel=5e-3)
    assert c.get("line[25].fairleadTension") == 0.0
    for b, load in enumerate(ref["loads"], start=1):
        force = c.get_reals([f"body[{b}].force.{a}" for a in "xyz"])
        assert np.max(np.abs(force - load[:3])) < 5e-3 * abs(load[2]), b
    assert c.get("body[9].force.z") == 0.0


def _farm_run(cable, steps, start=0, h=0.2):
    """Platforms 1 and 8 in surge from rest (the others still), the lines' fairlead tensions and the bodies'
    forces."""
    rows = []
    positions = ld.farm_positions(8)
    for k in range(start, start + steps):
        t = h * k
        x, v = 3.0 * (1.0 - np.cos(0.5 * t)), 1.5 * np.sin(0.5 * t)
        cable.set({"body[1].x": positions[0][0] + x, "body[1].vx": v,
                   "body[8].x": positions[7][0] - x, "body[8].vx": -v})
        cable.do_step(h)
        rows.append(cable.get_reals([f"line[{j}].fairleadTension" for j in range(1, 25)] +
                                    [f"body[{b}].force.{a}" for b in range(1, 9) for a in "xz"]))
    return np.array(rows)


def test_a_saved_state_of_the_farm_continues_bit_for_bit_also_in_a_new_instance(make_cable, tmp_path):
    deck = ms.read_system_deck(ld.write(ld.shared_anchor_farm(8, segments=6), tmp_path / "farm8.dat"))
    c = make_cable(parameters=ms.fmu_parameters(deck))
    c.initialize(inputs=_farm_inputs(8))
    _farm_run(c, 5)
    state = c.get_state()
    data = c.serialize_state(state)
    first = _farm_run(c, 5, start=5)
    assert np.ptp(first[:, 0]) > 1e3  # platform 1's surge pulls its lines
    c.set_state(state, time=1.0)
    assert _farm_run(c, 5, start=5).tobytes() == first.tobytes()
    fresh = make_cable(parameters=ms.fmu_parameters(deck))
    fresh.set_state(fresh.deserialize_state(data), time=1.0)
    assert _farm_run(fresh, 5, start=5).tobytes() == first.tobytes()


def test_lines_beyond_the_outputs_are_simulated_and_named_in_the_log(make_cable, tmp_path):
    """A platform held by MAX_LINES + 2 chains loads (a deck's lines are not limited); the log names the
    two lines without outputs line[k].*; they load the body all the same: its force with the platform
    surged matches MoorPy's within 0.5 % of the vertical load, and MoorPy's without them is more than
    1 % of it away."""
    n = MAX_LINES + 2
    deck = _deck(tmp_path, ld.radial_platform_deck(n, segments=10), "radial.dat")
    c = make_cable(parameters=ms.fmu_parameters(deck), logging_on=True)
    c.initialize(inputs={f"body[1].{name}": v for name, v in zip(ms.POSE_NAMES, SURGE)})
    notes = [m for _, _, m in c.messages if f"lines {MAX_LINES + 1} to {n}" in m]
    assert notes and "no outputs line[k].*" in notes[0], c.messages
    ref = ms.moorpy_statics(deck, SURGE)
    force = c.get_reals([f"body[1].force.{a}" for a in "xyz"])
    scale = abs(ref["load"][2])
    assert np.max(np.abs(force - ref["load"][:3])) < 5e-3 * scale
    assert c.get_reals([f"line[{k}].fairleadTension" for k in range(1, MAX_LINES + 1)]) == \
        pytest.approx(ref["fairlead"][:MAX_LINES], rel=5e-3)
    # without the last two lines the load would be another: MoorPy's of the deck without them
    short = ms.read_system_deck(ld.write(ld.radial_platform_deck(n, segments=10, keep=MAX_LINES),
                                         tmp_path / "short.dat"))
    assert np.max(np.abs(force - ms.moorpy_statics(short, SURGE)["load"][:3])) > 1e-2 * scale


def _fmi3_farm(fmi3_file, deck, sizes=None):
    """An FMI 3.0 instance of the farm's deck, its structural parameters set to `sizes` (name -> value) in
    configuration mode, initialized at the platforms' positions; returns (slave, value references, cleanup)."""
    import shutil

    from fmpy import extract, read_model_description
    from fmpy.fmi3 import FMU3Slave

    md = read_model_description(str(fmi3_file))
    directory = extract(str(fmi3_file))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    types = {v.name: v.type for v in md.modelVariables}
    fmu = FMU3Slave(guid=md.guid, unzipDirectory=directory, modelIdentifier="UnderwaterCable", instanceName="farm")
    fmu.instantiate()
    if sizes:
        fmu.enterConfigurationMode()
        fmu.setUInt64([vr[n] for n in sizes], list(sizes.values()))
        fmu.exitConfigurationMode()
    for name, value in ms.fmu_parameters(deck).items():
        if types[name] == "String":
            fmu.setString([vr[name]], [str(value)])
        elif types[name] == "Boolean":
            fmu.setBoolean([vr[name]], [bool(value)])
        else:
            fmu.setFloat64([vr[name]], [float(value)])
    bodies = (sizes or {}).get("nBodies", MAX_BODIES)
    positions = ld.farm_positions(8) + [(0.0, 0.0, 0.0)] * (bodies - 8)
    fmu.setFloat64([vr[f"body.{c}"] for c in "xyz"], [p[i] for i in range(3) for p in positions])
    fmu.enterInitializationMode(startTime=0.0)
    fmu.exitInitializationMode()

    def close(terminate=True):
        if terminate:
            fmu.terminate()
        fmu.freeInstance()
        shutil.rmtree(directory, ignore_errors=True)
    return fmu, vr, close


def test_fmi3_arrays_take_the_decks_sizes_through_structural_parameters(fmi3_file, make_cable, tmp_path):
    """FMI 3.0: nLines, nBodies and nPoints (UInt64 structural parameters, the maxima by default) size the
    line.*, body.* and point.* arrays; set in configuration mode to the farm's 24 lines and 8 bodies, the
    arrays hold 24 and 8 elements, the same bits as FMI 2.0's line[1..24] and body[1..8]; a size beyond the
    maximum, or set outside configuration mode, is refused (fmpy.validate: test_fmi3.py)."""
    from fmpy import read_model_description
    from fmpy.fmi1 import FMICallException
    md3 = {v.name: v for v in read_model_description(str(fmi3_file)).modelVariables}
    assert md3["nLines"].causality == "structuralParameter" and md3["nLines"].type == "UInt64"
    assert int(md3["nLines"].start) == MAX_LINES and md3["line.fairleadTension"].shape == (MAX_LINES,)
    assert md3["line.fairleadTension"].dimensions[0].valueReference == md3["nLines"].valueReference
    assert md3["body.stiffness"].dimensions[0].valueReference == md3["nBodies"].valueReference

    deck = ms.read_system_deck(ld.write(ld.shared_anchor_farm(8), tmp_path / "farm8.dat"))
    c = make_cable(parameters=ms.fmu_parameters(deck))
    c.initialize(inputs=_farm_inputs(8))
    fair2 = c.get_reals([f"line[{k}].fairleadTension" for k in range(1, 25)])
    force2 = c.get_reals([f"body[{k}].force.z" for k in range(1, 9)])
    stiffness2 = c.get_reals([f"body[{k}].stiffness[{i},{j}]" for k in range(1, 9) for i in range(1, 7)
                              for j in range(1, 7)])

    fmu, vr, close = _fmi3_farm(fmi3_file, deck, {"nLines": 24, "nBodies": 8, "nPoints": 1})
    try:
        assert list(fmu.getUInt64([vr["nLines"], vr["nBodies"]])) == [24, 8]
        assert np.array(fmu.getFloat64([vr["line.fairleadTension"]], nValues=24)).tobytes() == fair2.tobytes()
        assert np.array(fmu.getFloat64([vr["body.force.z"]], nValues=8)).tobytes() == force2.tobytes()
        assert np.array(fmu.getFloat64([vr["body.stiffness"]], nValues=8 * 36)).tobytes() == stiffness2.tobytes()
        with pytest.raises(FMICallException):
            fmu.getFloat64([vr["line.fairleadTension"]], nValues=MAX_LINES)  # the arrays hold 24 now
        with pytest.raises(FMICallException):
            fmu.setUInt64([vr["nLines"]], [30])  # outside configuration mode
    finally:
        close()
    fmu, vr, close = _fmi3_farm(fmi3_file, deck)  # the maxima by default
    try:
        lines = np.array(fmu.getFloat64([vr["line.fairleadTension"]], nValues=MAX_LINES))
        assert lines[:24].tobytes() == fair2.tobytes() and not np.any(lines[24:])
        fmu.reset()
        fmu.enterConfigurationMode()
        with pytest.raises(FMICallException):
            fmu.setUInt64([vr["nLines"]], [MAX_LINES + 1])
        assert list(fmu.getUInt64([vr["nLines"]])) == [MAX_LINES]
        fmu.exitConfigurationMode()
    finally:
        close(terminate=False)  # (reset: instantiated again)
