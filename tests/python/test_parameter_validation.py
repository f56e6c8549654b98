"""Parameter validation in one place with one message format.

Every parameter of modelDescription.xml is driven through fmi2SetReal/SetInteger/SetBoolean with an
inadmissible value. Out-of-range finite values must give fmi2Error at fmi2ExitInitializationMode
(uc_params_check, src/model/params.cpp) with a log line "<variable> = <value> is outside <range>: <why>";
NaN and inf are rejected already by fmi2SetReal. A parameter without a case below fails
test_every_parameter_has_a_validation_case: add its range check and its case.
"""

import math
import re

import pytest
from fmpy import read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import fmi2Error

FORMAT = re.compile(r"(?P<name>[\w.|\[\]]+) = (?P<value>\S+) is outside (?P<range>.+?): (?P<why>.+)$")

# parameter -> (inadmissible value, extra settings that make the check apply, variable named in the message)
CASES = {
    "length": [(-1.0, {}, None), (0.0, {}, None)],
    "diameter": [(0.0, {}, None), (-0.03, {}, None)],
    "massPerLength": [(0.0, {}, None)],
    "EA": [(0.0, {}, None), (-1e7, {}, None)],
    "EI": [(-1.0, {}, None)],
    "axialDamping": [(-1.0, {}, None)],
    "Cdn": [(-0.1, {}, None)],
    "Cdt": [(-0.1, {}, None)],
    "Can": [(-0.1, {}, None)],
    "Cat": [(-0.1, {}, None)],
    "waterDensity": [(-1.0, {}, None)],
    "gravity": [(-9.81, {}, None)],
    "nElements": [(0, {}, None), (1001, {}, None)],
    "relTol": [(-1e-8, {}, None), (0.5, {}, None)],
    "absTol": [(-1e-6, {}, None), (2.0, {}, None)],
    "tensionTolerance": [(0.0, {}, None), (0.5, {}, None)],
    "positionTolerance": [(0.0, {}, None), (20.0, {}, None)],
    "bottomEnd": [(-1, {}, None), (99, {}, None)],
    "topEnd": [(-1, {}, None), (2, {}, None)],
    "initMode": [(-1, {}, None), (2, {}, None)],
    # a direction needs a non-zero vector: zero all three components (the message names |topTangent|)
    "topTangent.x": [(0.0, {"topEnd": 1, "topTangent.y": 0.0, "topTangent.z": 0.0}, "|topTangent|")],
    "topTangent.y": [(0.0, {"topEnd": 1, "topTangent.x": 0.0, "topTangent.z": 0.0}, "|topTangent|")],
    "topTangent.z": [(0.0, {"topEnd": 1, "topTangent.x": 0.0, "topTangent.y": 0.0}, "|topTangent|")],
    "initialDirection.x": [(0.0, {"initialDirection.y": 0.0, "initialDirection.z": 0.0}, "|initialDirection|")],
    "initialDirection.y": [(0.0, {"initialDirection.x": 0.0, "initialDirection.z": 0.0}, "|initialDirection|")],
    "initialDirection.z": [(0.0, {"initialDirection.x": 0.0, "initialDirection.y": 0.0}, "|initialDirection|")],
    "body.mass": [(-1.0, {"bottomEnd": 2}, None)],
    "body.volume": [(-1.0, {"bottomEnd": 2}, None)],
    "body.addedMass": [(-1.0, {"bottomEnd": 2}, None)],
    "body.CdA": [(-1.0, {"bottomEnd": 2}, None)],
    "waterDepth": [(0.0, {}, None), (-10.0, {}, None)],
    "seabedStiffness": [(-1.0, {}, None), (0.0, {"enableSeabed": True}, None)],
    "seabedDamping": [(-1.0, {}, None)],
    "seabedFriction": [(-0.1, {}, None)],
    "currentProfileRows": [(-1, {}, None), (11, {}, None)],
    "GJ": [(-1.0, {}, None), (0.0, {"enableTorsion": True, "torqueMode": 2}, None)],
    "torqueMode": [(-1, {}, None), (3, {}, None)],
}
# Profile depths must increase row by row: all 10 rows in use, 10 m apart, row k repeats row k - 1.
for _k in range(2, 11):
    _extra = {"currentProfileRows": 10}
    _extra.update({f"currentProfile.depth[{j}]": 10.0 * (j - 1) for j in range(1, 11) if j != _k})
    CASES[f"currentProfile.depth[{_k}]"] = [(10.0 * (_k - 2), _extra, None)]

# Anchor positions out of reach of the cable (DESIGN 4: "impossible anchor geometry" is an error):
# the default tow point is the origin, the cable 300 m long; 1 km away cannot be reached even at the
# breaking strain of any cable.
UNREACHABLE_ANCHOR = {
    "anchor.x": [(1000.0, {"bottomEnd": 1}, None)],
    "anchor.y": [(1000.0, {"bottomEnd": 1}, None)],
    "anchor.z": [(-1000.0, {"bottomEnd": 1}, None)],
}

# Parameters for which fmi2Set* cannot express an out-of-range value.
NO_OUT_OF_RANGE_VALUE = {
    "enableBending": "Boolean: fmi2SetBoolean maps any non-zero value to true",
    "enableAddedMass": "Boolean: fmi2SetBoolean maps any non-zero value to true",
    "enableSeabed": "Boolean: fmi2SetBoolean maps any non-zero value to true",
    "enableTorsion": "Boolean: fmi2SetBoolean maps any non-zero value to true",
    "enableCompression": "Boolean: fmi2SetBoolean maps any non-zero value to true",
    # the first row has no row above it; a depth above the surface (< 0) is not rejected
    "currentProfile.depth[1]": "any finite value is accepted (no lower bound, e.g. -50 m above the surface)",
    **{f"currentProfile.{c}[{k}]": "any finite current velocity is admissible"
       for c in "xy" for k in range(1, 11)},
    "lineFile": "String: any path is admissible; a file that cannot be read or a refused deck is an error "
                "at initialization (tests/python/test_line_file.py)",
    "waves.file": "String: any path is admissible; a file that cannot be read, a refused row or set without "
                  "waves.mode 3 is an error at initialization (tests/python/test_wave_components.py)",
    "currents.file": "String: any path is admissible; a file that cannot be read or refused data with "
                     "currents.mode 2 or 5 is an error at initialization (tests/python/test_current_data.py)",
    "seabed.file": "String: any path is admissible; a file that cannot be read, a refused grid or set with "
                   "seabedSlope or without enableSeabed is an error at initialization (tests/python/test_seabed_grid.py)",
}


def _parameters(fmu_file):
    md = read_model_description(str(fmu_file))
    return {v.name: v for v in md.modelVariables if v.causality == "parameter"}


def _flat(cases):
    return [(name, value, extra, named) for name, rows in cases.items() for value, extra, named in rows]


def _expect_rejected_at_initialization(make_cable, name, value, extra, named):
    cable = make_cable(instance_name="validation", logging_on=True)
    cable.slave.setupExperiment(startTime=0.0)
    cable.set({**extra, name: value})  # admissible for the setter: finite
    cable.slave.enterInitializationMode()
    with pytest.raises(FMICallException) as err:
        cable.slave.exitInitializationMode()
    assert err.value.status == fmi2Error
    errors = [m for s, _, m in cable.messages if s == "ERROR"]
    named = named or name
    matches = [FORMAT.search(m) for m in errors]
    matches = [m for m in matches if m and m.group("name") == named]
    assert matches, f"no error line '{named} = <value> is outside <range>: <why>' in:\n{cable.log_text()}"
    m = matches[0]
    if named == name:  # the message carries the value that was set
        assert float(m.group("value")) == pytest.approx(value, abs=0.0)
    assert m.group("range") and m.group("why")


@pytest.mark.parametrize("name,value,extra,named", _flat(CASES), ids=[f"{n}={v}" for n, v, _, _ in _flat(CASES)])
def test_out_of_range_parameter_is_rejected_with_the_one_message_format(make_cable, name, value, extra, named):
    _expect_rejected_at_initialization(make_cable, name, value, extra, named)


@pytest.mark.parametrize("name,value,extra,named", _flat(UNREACHABLE_ANCHOR),
                         ids=[f"{n}={v}" for n, v, _, _ in _flat(UNREACHABLE_ANCHOR)])
def test_unreachable_anchor_is_rejected(make_cable, name, value, extra, named):
    _expect_rejected_at_initialization(make_cable, name, value, extra, named)


def _ranged_parameters(fmu_file):
    """Numeric parameters with min and max in the model description (from the variable schema)."""
    return {n: v for n, v in _parameters(fmu_file).items()
            if v.type in ("Real", "Integer") and v.min is not None and v.max is not None}


def _beyond(value: float, direction: int, integer: bool):
    """A value clearly outside a bound: past it by its own magnitude plus one."""
    x = float(value) + direction * (abs(float(value)) + 1.0)
    return int(x) if integer else x


def test_every_parameter_has_min_and_max_in_the_model_description(fmu_file):
    numeric = {n for n, v in _parameters(fmu_file).items() if v.type in ("Real", "Integer")}
    assert not sorted(numeric - set(_ranged_parameters(fmu_file)))


def test_every_parameter_outside_its_model_description_range_is_rejected(make_cable, fmu_file):
    """The range in the XML is the one the FMU enforces: below min and above max are errors."""
    ranged = _ranged_parameters(fmu_file)
    assert len(ranged) > 40
    for name, v in sorted(ranged.items()):
        for bound, direction in ((v.min, -1), (v.max, +1)):
            value = _beyond(bound, direction, v.type == "Integer")
            _expect_rejected_at_initialization(make_cable, name, value, {}, None)


def test_every_parameter_has_a_validation_case(fmu_file):
    booleans = {n for n, v in _parameters(fmu_file).items() if v.type == "Boolean"}
    covered = (set(CASES) | set(UNREACHABLE_ANCHOR) | set(NO_OUT_OF_RANGE_VALUE) | booleans
               | set(_ranged_parameters(fmu_file)))
    missing = sorted(set(_parameters(fmu_file)) - covered)
    assert not missing, f"parameters without an out-of-range case (and maybe without a check): {missing}"


def _real_parameters(fmu_file):
    return sorted(n for n, v in _parameters(fmu_file).items() if v.type == "Real")


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf], ids=["nan", "inf", "-inf"])
def test_non_finite_real_parameters_are_rejected_by_the_setter_naming_the_variable(make_cable, fmu_file, bad):
    for name in _real_parameters(fmu_file):
        cable = make_cable(instance_name="nonfinite", logging_on=True)
        with pytest.raises(FMICallException) as err:
            cable.set({name: bad})
        assert err.value.status == fmi2Error
        errors = [m for s, _, m in cable.messages if s == "ERROR"]
        assert any(f"{name} = " in m for m in errors), f"{name}: {errors}"
        cable.free()


def test_non_finite_real_parameter_message_has_the_one_format(make_cable):
    cable = make_cable(instance_name="nonfinite", logging_on=True)
    with pytest.raises(FMICallException):
        cable.set({"diameter": math.nan})
    errors = [m for s, _, m in cable.messages if s == "ERROR"]
    assert any((m2 := FORMAT.search(m)) and m2.group("name") == "diameter" for m in errors), errors
