"""Result tables as engineers read them: every column named with its unit in brackets, angles in degrees.

The FMU reports SI units with angles in radians (the variable schema says which). The tables that
`ucable run`, `ucable sweep` and `ucable system` write name each column `NAME [UNIT]` (`time [s]`,
`towTension [N]`, `topDeclination [deg]`, `Cdn [-]` for a number without a unit); an angle the FMU
reports in rad (rad/s, rad/s2) is written in deg (deg/s, deg/s2), as a scene gives its angles. Text
columns (a sweep's `status` and `error`) carry no unit. `read_results` reads such a table back, keyed
by the full header and by the bare name.
"""

from __future__ import annotations

import csv
import io
import math
import re

import numpy as np

from .variables import VARIABLES

DIMENSIONLESS = "-"
TO_DEGREES = {"rad": "deg", "rad/s": "deg/s", "rad/s2": "deg/s2"}
# Columns that are not FMU variables: the scene's time and settings, the sweep's summary
OTHER_UNITS = {"time": "s", "duration": "s", "step": "s", "speed_kn": "kn", "heading": "deg", "heading_deg": "deg",
               "towTensionMax": "N", "towTensionMin": "N", "towTensionFinal": "N", "endDepthFinal": "m",
               "anchorTensionMax": "N", "lengthFinal": "m", "cpuSeconds": "s"}
TEXT_COLUMNS = ("status", "error", "case")
_LABEL = re.compile(r"^(?P<name>.*?) \[(?P<unit>[^\[\]]*)\]$")
_STIFFNESS = re.compile(r"stiffness\[(\d),(\d)\]$")


def stiffness_unit(i: int, j: int) -> str:
    """The unit of K[i,j] = -dF_i/dq_j, F = (force, moment), q = (translation [m], rotation [rad])."""
    return {(True, True): "N/m", (True, False): "N/rad", (False, True): "N", (False, False): "N.m/rad"}[
        (i <= 3, j <= 3)]


def schema_unit(name: str) -> str | None:
    """The unit of a column as the FMU (or the scene) has it; None when the name is unknown."""
    if name in OTHER_UNITS:
        return OTHER_UNITS[name]
    m = _STIFFNESS.search(name)
    if m:
        return stiffness_unit(int(m.group(1)), int(m.group(2)))
    v = VARIABLES.get(name)
    if v is None:
        return None
    if v.type == "Boolean":
        return DIMENSIONLESS
    return v.unit or DIMENSIONLESS


def written_unit(unit: str | None) -> tuple[str | None, float]:
    """The unit a table writes for a column in `unit`, and the factor from one to the other."""
    if unit in TO_DEGREES:
        return TO_DEGREES[unit], 180.0 / math.pi
    return unit, 1.0


def label(name: str, unit: str | None) -> str:
    return name if unit is None else f"{name} [{unit}]"


def labelled(columns: dict, units: dict | None = None, convert: bool = True) -> dict:
    """{NAME [UNIT]: values} of {NAME: values}: the unit from `units` (NAME -> unit), else the schema's;
    with `convert` an angle in rad is written in deg (its values converted). A name of no known unit
    is written as it is."""
    out = {}
    for name, values in columns.items():
        unit = (units or {}).get(name) or schema_unit(name)
        if name in TEXT_COLUMNS:
            unit = None
        factor = 1.0
        if convert:
            unit, factor = written_unit(unit)
        out[label(name, unit)] = values if factor == 1.0 else np.asarray(values, dtype=float) * factor
    return out


def bare_name(header: str) -> tuple[str, str | None]:
    """("towTension", "N") of "towTension [N]"; (header, None) without a unit."""
    m = _LABEL.match(header)
    return (m.group("name"), m.group("unit")) if m else (header, None)


class Results(dict):
    """A result table read back: numeric columns as float arrays, text columns as lists of str, under
    both the full header (`towTension [N]`) and the bare name (`towTension`); `units` maps each bare
    name to its unit (None for text)."""

    def __init__(self, headers: list[str], columns: list):
        super().__init__()
        self.headers = headers
        self.units = {}
        for h, c in zip(headers, columns):
            name, unit = bare_name(h)
            self[h] = c
            self.setdefault(name, c)
            self.units[name] = unit

    @property
    def rows(self) -> int:
        return len(self[self.headers[0]]) if self.headers else 0

    def records(self) -> list[dict]:
        """The rows as dicts keyed by the bare column names."""
        names = [bare_name(h)[0] for h in self.headers]
        return [dict(zip(names, values)) for values in zip(*(self[h] for h in self.headers))]


def _column(cells: list[str]):
    try:
        return np.array([float(c) if c != "" else math.nan for c in cells])
    except ValueError:
        return cells


def read_results(path) -> Results:
    """A table written by `ucable run` (result.csv, summary.csv), `ucable sweep` (results.csv) or
    `ucable system`: ucable.read_results("out/x/result.csv")["towTension"] is the array of the
    column `towTension [N]`."""
    with open(path, newline="") as f:
        headers = next(csv.reader(f), None)
        if headers is None:
            raise ValueError(f"{path}: empty, no header")
        body = f.read()
    if not body.strip():
        return Results(headers, [np.zeros(0) for _ in headers])
    try:  # all numbers (result.csv): numpy's parser
        data = np.loadtxt(io.StringIO(body), delimiter=",", ndmin=2).reshape(-1, len(headers))
        return Results(headers, list(data.T.copy()))
    except ValueError:  # text columns too (a sweep's status and error)
        rows = list(csv.reader(io.StringIO(body)))
        return Results(headers, [_column([r[i] if i < len(r) else "" for r in rows]) for i in range(len(headers))])


def fmu_units(path) -> dict:
    """{variable: unit} of an FMU's model description (the unit of its declared type where it has none)."""
    from fmpy import read_model_description

    out = {}
    for v in read_model_description(str(path)).modelVariables:
        unit = v.unit or (v.declaredType.unit if v.declaredType is not None else None)
        out[v.name] = unit or (DIMENSIONLESS if v.type in ("Real", "Integer", "Boolean") else None)
    return out


def system_units(system) -> dict:
    """{"unit.variable": unit} of a SystemStructure's FMUs, and the units of a system result's first
    columns (time, towTension, body.x/y/z)."""
    units = {"time": "s", "towTension": "N", "body.x": "m", "body.y": "m", "body.z": "m"}
    for name, sim in system.simulators.items():
        units.update({f"{name}.{v}": u for v, u in fmu_units(sim.source).items()})
    return units
