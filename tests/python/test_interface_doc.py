"""The FMU interface tables of docs/interface.md agree with modelDescription.xml (both are generated from the
variable schema: this checks the generator end to end): every variable is listed
with the right causality section, unit and default (its defaults are rounded to 6 significant
digits, hence rel = 1e-5). Needs no built FMU: it reads the checked-in modelDescription.xml."""

import re

import pytest
from fmpy import read_model_description

from ucable.paths import REPO_ROOT

SECTIONS = {"## Inputs": "input", "## Outputs": "output", "## Parameters": "parameter"}


def readme_rows():
    """{variable name: (section causality, unit cell, default cell)} from the tables of docs/interface.md."""
    rows, section = {}, None
    for line in (REPO_ROOT / "docs" / "interface.md").read_text().splitlines():
        for head, causality in SECTIONS.items():
            if line.startswith(head):
                section = causality
        if line.startswith("#") and not any(line.startswith(head) for head in SECTIONS):
            section = None
        if section is None or not line.startswith("| `"):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        tokens = re.findall(r"`([^`]+)`", cells[0])
        for j, token in enumerate(tokens):
            names = [token]
            m = re.fullmatch(r"(.+)\.([a-z](?:/[a-z])+)", token)  # a vector: name.x/y/z or name.x/y
            if m:
                names = [f"{m.group(1)}.{c}" for c in m.group(2).split("/")]
            for k, name in enumerate(names):
                default = cells[2] if section != "output" else None
                if default is not None and len(names) > 1:
                    default = re.findall(r"[-+0-9.e]+", default.split("(")[-1])[k]
                elif default is not None and len(tokens) > 1 and default.startswith("("):
                    default = re.findall(r"[-+0-9.e]+", default)[j]  # one per name: `a`, `b` | (1, 0)
                rows[name] = (section, cells[1], default)
    return rows


@pytest.fixture(scope="module")
def model_variables():
    md = read_model_description(str(REPO_ROOT / "modelDescription.xml"), validate=False)
    return md.modelVariables


def test_every_variable_is_documented_with_its_unit_and_default(model_variables):
    rows = readme_rows()
    for v in model_variables:
        name = re.sub(r"\[\d+,\d+\]", "[i,j]", v.name)  # matrices as name[i,j]
        name = re.sub(r"\[\d+\]", "[k]", name)  # arrays are documented as name[k]
        assert name in rows, f"{v.name} is missing from docs/interface.md"
        section, unit, default = rows[name]
        assert section == v.causality, f"{v.name}: docs/interface.md lists it under {section}s"
        if v.unit:
            readme_unit = unit.replace("²", "2").replace("³", "3")
            assert readme_unit == v.unit, f"{v.name}: docs/interface.md unit {unit!r}, modelDescription {v.unit!r}"
        if default is None or v.start is None:
            continue
        first = default.split()[0]
        if v.type == "Boolean":
            assert first == str(v.start).lower(), f"{v.name}: docs/interface.md default {first}"
        elif v.type == "String":
            assert first == f'"{v.start}"', f"{v.name}: docs/interface.md default {first}, modelDescription {v.start!r}"
        else:
            assert float(first) == pytest.approx(float(v.start), rel=1e-5), \
                f"{v.name}: docs/interface.md default {first}, modelDescription {v.start}"
