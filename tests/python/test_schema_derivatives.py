"""The variable schema's derivatives (schema/generate.py): which input is the time derivative of which
(derivativeOf) and the rows and columns of the directional derivatives. A schema whose derivativeOf names
no variable, a variable that is not an input, or makes a cycle is refused; the shipped schema gives the
chains fmu/value_access.c relies on."""

from __future__ import annotations

import importlib.util
import re
import sys
from pathlib import Path

import pytest

from ucable.variables import MAX_BODIES

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def generate():
    spec = importlib.util.spec_from_file_location("schema_generate", ROOT / "schema" / "generate.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up
    spec.loader.exec_module(module)
    return module


def edited_schema(tmp_path: Path, name: str, key: str, value: str) -> Path:
    """The shipped schema with `key = value` set in the [[variable]] entry called name."""
    text = (ROOT / "schema" / "variables.toml").read_text()
    start = text.index(f'name = "{name}"\n')
    end = text.find("\n[[variable]]", start)
    end = len(text) if end < 0 else end
    entry = text[start:end]
    line = f"{key} = {value}\n"
    entry, count = re.subn(rf"^{key} = .*\n", line, entry, flags=re.M)
    if count == 0:
        entry = entry.replace("description = ", line + "description = ", 1)
    path = tmp_path / "variables.toml"
    path.write_text(text[:start] + entry + text[end:])
    return path


def test_the_shipped_chains(generate):
    _, _, scalars = generate.load()
    of = {s.name: s.derivative_of for s in scalars if s.derivative_of}
    for c in "xyz":
        assert of[f"tow.v{c}"] == f"tow.{c}" and of[f"tow.a{c}"] == f"tow.v{c}"
        assert of[f"end.v{c}"] == f"end.{c}" and of[f"end.a{c}"] == f"end.v{c}"
        assert of[f"body[2].v{c}"] == f"body[2].{c}" and of[f"point[16].v{c}"] == f"point[16].{c}"
    field = {s.name: s.derivative_field for s in scalars if s.derivative_field}
    assert field["body[2].vy"] == "bodyAcceleration[7]" and field["body[2].wz"] == "bodyAcceleration[11]"
    assert field["point[3].vz"] == "pointAcceleration[8]" and field["current.y"] == "currentRate[1]"
    columns = sorted((s.jacobian[1], s.name) for s in scalars
                     if s.jacobian and s.jacobian[0] == "interface" and s.causality == "input")
    assert [n for _, n in columns] == ["tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz",
                                       "end.x", "end.y", "end.z", "end.vx", "end.vy", "end.vz",
                                       "tow.ax", "tow.ay", "tow.az", "end.ax", "end.ay", "end.az"]
    body = sorted((s.jacobian[1], s.name) for s in scalars
                  if s.jacobian and s.jacobian[0] == "body" and s.jacobian[2] == 1 and s.causality == "input")
    assert len(body) == 16 and body[0][1] == "body[1].x" and body[-1][1] == "body[1].q3"
    computed = [s.name for s in scalars if s.entry.get("computedWhenRead")]
    assert len(computed) == MAX_BODIES * 36 and computed[0] == "body[1].stiffness[1,1]"


@pytest.mark.parametrize("name, value, message", [
    ("tow.v{c}", '"tow.w{c}"', "derivativeOf 'tow.wx' is not a variable"),
    ("tow.v{c}", '"towForce.{c}"', "derivativeOf 'towForce.x' is not a Real input (it is a Real output)"),
    ("tow.v{c}", '"length"', "derivativeOf 'length' is not a Real input (it is a Real parameter)"),
    ("tow.{c}", '"tow.a{c}"', "derivativeOf makes a cycle: tow.x -> tow.ax -> tow.vx -> tow.x"),
    ("tow.a{c}", '"tow.{c}"', "tow.x already has the derivative 'tow.vx'"),
    ("torque", '"twist"', "derivativeOf 'twist': its unit N.m is not rad/s"),
])
def test_a_wrong_derivative_of_is_refused(generate, tmp_path, name, value, message):
    with pytest.raises(SystemExit) as refused:
        generate.load(edited_schema(tmp_path, name, "derivativeOf", value))
    assert message in str(refused.value)


def test_a_derivative_kept_twice_or_outside_the_inputs_is_refused(generate, tmp_path):
    with pytest.raises(SystemExit, match="but the input 'tow.ax' is its derivative"):
        generate.load(edited_schema(tmp_path, "tow.v{c}", "derivativeField", '"currentRate[{i}]"'))
    with pytest.raises(SystemExit, match="is not an \\[\\[internal\\]\\] double member of UCInputs"):
        generate.load(edited_schema(tmp_path, "current.{c}", "derivativeField", '"towAccelerationGiven"'))
    with pytest.raises(SystemExit, match="does not index"):
        generate.load(edited_schema(tmp_path, "current.{c}", "derivativeField", '"currentRate[{i} + 2]"'))
    with pytest.raises(SystemExit, match="derivativeOf is for inputs"):
        generate.load(edited_schema(tmp_path, "towForce.{c}", "derivativeOf", '"tow.{c}"'))
    with pytest.raises(SystemExit, match="computedWhenRead is for outputs"):
        generate.load(edited_schema(tmp_path, "tow.{c}", "computedWhenRead", "true"))


def test_a_gap_in_the_directional_derivatives_is_refused(generate, tmp_path):
    with pytest.raises(SystemExit, match=r"directionalDerivative 'interface': the inputs' indices"):
        generate.load(edited_schema(tmp_path, "end.a{c}", "directionalDerivative",
                                    '{ matrix = "interface", index = 16 }'))
