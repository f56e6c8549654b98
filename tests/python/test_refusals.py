"""A refusal changes nothing: every setter of the FMI 2.0 and 3.0 FMUs that returns an error (a wrong count,
type, value reference, value, or a variable that may not be set now) leaves every variable as it was. Each
case sets a valid value first in the same call (which a setter that writes as it goes would keep) and then
the refused one; every variable is read before and after."""

import math

import numpy as np
import pytest
from fmpy import extract, read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import FMU2Slave
from fmpy.fmi3 import FMU3Slave

ERROR = 3


class Instance:
    """A cable instance of either FMU, its variables by name, and a snapshot of all of them."""

    def __init__(self, path, fmi3):
        self.md = read_model_description(str(path))
        self.dir = extract(str(path))
        self.fmi3 = fmi3
        self.vars = {v.name: v for v in self.md.modelVariables}
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        cls = FMU3Slave if fmi3 else FMU2Slave
        self.fmu = cls(guid=self.md.guid, unzipDirectory=self.dir,
                       modelIdentifier=self.md.coSimulation.modelIdentifier, instanceName="cable")
        self.fmu.instantiate()

    def enter_initialization(self):
        if self.fmi3:
            self.fmu.enterInitializationMode(startTime=0.0)
        else:
            self.fmu.setupExperiment(startTime=0.0)
            self.fmu.enterInitializationMode()

    def step_mode(self):
        self.enter_initialization()
        self.fmu.exitInitializationMode()
        self.fmu.doStep(0.0, 0.5)

    def count(self, v):
        """An array's number of values: its dimensions' sizes, given or its structural parameters' starts."""
        dims = getattr(v, "dimensions", None) or []
        starts = {u.valueReference: u.start for u in self.md.modelVariables}
        return int(np.prod([int(d.start if d.start is not None else starts[d.valueReference]) for d in dims])) \
            if dims else 1

    def snapshot(self, outputs=True):
        """Every variable's value (outputs too unless in initialization mode, where reading them computes)."""
        values = {}
        for v in self.md.modelVariables:
            if v.causality == "output" and not outputs:
                continue
            if v.name == "time":
                continue
            vr = [v.valueReference]
            if self.fmi3:
                get = {"Float64": self.fmu.getFloat64, "Int32": self.fmu.getInt32, "UInt64": self.fmu.getUInt64,
                       "Boolean": self.fmu.getBoolean, "String": self.fmu.getString}[v.type]
                values[v.name] = list(get(vr, nValues=self.count(v)))
            else:
                get = {"Real": self.fmu.getReal, "Integer": self.fmu.getInteger, "Boolean": self.fmu.getBoolean,
                       "String": self.fmu.getString}[v.type]
                values[v.name] = list(get(vr))
        return values

    def close(self):
        try:
            self.fmu.freeInstance()
        except Exception:
            pass


def same(before, after):
    """Names whose values differ (NaN equal to NaN)."""
    differ = []
    for name, a in before.items():
        b = after[name]
        if any(not (x == y or (isinstance(x, float) and math.isnan(x) and math.isnan(y))) for x, y in zip(a, b)):
            differ.append(name)
    return differ


# (case, mode, call): mode "init" (initialization mode: parameters and inputs settable) or "step" (after a
# step: inputs settable). Each call sets a valid value first, then something refused.
FMI2_CASES = [
    ("output after a valid input", "step", lambda c: c.fmu.setReal([c.vr["tow.x"], c.vr["towTension"]], [5.0, 1.0])),
    ("parameter after initialization", "step", lambda c: c.fmu.setReal([c.vr["tow.x"], c.vr["length"]], [5.0, 50.0])),
    ("NaN after a valid input", "step", lambda c: c.fmu.setReal([c.vr["tow.x"], c.vr["tow.vx"]], [5.0, math.nan])),
    ("unknown value reference", "step", lambda c: c.fmu.setReal([c.vr["tow.x"], 987654], [5.0, 1.0])),
    ("an Integer's value reference", "init",
     lambda c: c.fmu.setReal([c.vr["length"], c.vr["nElements"]], [55.0, 12.0])),
    ("NaN parameter", "init", lambda c: c.fmu.setReal([c.vr["length"], c.vr["diameter"]], [55.0, math.inf])),
    ("Integer: unknown value reference", "init",
     lambda c: c.fmu.setInteger([c.vr["nElements"], 987654], [12, 1])),
    ("Integer: parameter after initialization", "step", lambda c: c.fmu.setInteger([c.vr["nElements"]], [12])),
    ("Boolean: a Real's value reference", "init",
     lambda c: c.fmu.setBoolean([c.vr["enableBending"], c.vr["length"]], [False, True])),
    ("String: too long", "init",
     lambda c: c.fmu.setString([c.vr["lineFile"], c.vr["lineFile"]], ["deck.txt", "x" * 100000])),
    ("String: NULL", "init", lambda c: c.fmu.setString([c.vr["lineFile"], c.vr["lineFile"]], ["deck.txt", None])),
    ("input derivative of an unsupported order", "step",
     lambda c: c.fmu.setRealInputDerivatives([c.vr["tow.vx"], c.vr["tow.x"]], [1, 3], [2.0, 1.0])),
    ("input derivative of an output", "step",
     lambda c: c.fmu.setRealInputDerivatives([c.vr["tow.vx"], c.vr["towTension"]], [1, 1], [2.0, 1.0])),
    ("input derivative NaN", "step",
     lambda c: c.fmu.setRealInputDerivatives([c.vr["tow.vx"], c.vr["tow.vy"]], [1, 1], [2.0, math.nan])),
    ("input in the wrong state (terminated)", "terminated", lambda c: c.fmu.setReal([c.vr["tow.x"]], [5.0])),
]

FMI3_CASES = [
    ("Float64: too many values", "step", lambda c: c.fmu.setFloat64([c.vr["tow.x"], c.vr["tow.y"]], [5.0, 6.0, 7.0])),
    ("Float64: too few values", "step", lambda c: c.fmu.setFloat64([c.vr["tow.x"], c.vr["tow.y"]], [5.0])),
    ("Float64: output after a valid input", "step",
     lambda c: c.fmu.setFloat64([c.vr["tow.x"], c.vr["towTension"]], [5.0, 1.0])),
    ("Float64: NaN after a valid input", "step",
     lambda c: c.fmu.setFloat64([c.vr["tow.x"], c.vr["tow.vx"]], [5.0, math.nan])),
    ("Float64: the independent variable", "step", lambda c: c.fmu.setFloat64([c.vr["tow.x"], c.vr["time"]], [5.0, 1.0])),
    ("Float64: parameter in step mode", "step", lambda c: c.fmu.setFloat64([c.vr["tow.x"], c.vr["length"]], [5.0, 9.0])),
    ("Float64: unknown value reference", "init", lambda c: c.fmu.setFloat64([c.vr["length"], 987654], [55.0, 1.0])),
    ("Int32: too many values", "init", lambda c: c.fmu.setInt32([c.vr["nElements"]], [12, 13])),
    ("Boolean: too many values", "init", lambda c: c.fmu.setBoolean([c.vr["enableBending"]], [False, True])),
    ("String: too many values", "init", lambda c: c.fmu.setString([c.vr["lineFile"]], ["deck.txt", "other.txt"])),
    ("String: too long", "init",
     lambda c: c.fmu.setString([c.vr["lineFile"], c.vr["lineFile"]], ["deck.txt", "x" * 100000])),
    ("Binary: not a type of this FMU", "step", lambda c: c.fmu.setBinary([c.vr["tow.x"]], [b"\x01\x02"])),
    ("Float32: not a type of this FMU", "step", lambda c: c.fmu.fmi3SetFloat32(c.fmu.component, None, 0, None, 0)),
]


def run_case(path, fmi3, mode, call):
    c = Instance(path, fmi3)
    try:
        c.enter_initialization()
        if mode in ("step", "terminated"):
            c.fmu.exitInitializationMode()
            c.fmu.doStep(0.0, 0.5)
        if mode == "terminated":
            c.fmu.terminate()
        before = c.snapshot(outputs=mode != "init")
        with pytest.raises(FMICallException) as refused:
            call(c)
        assert refused.value.status == ERROR
        after = c.snapshot(outputs=mode != "init")
        return same(before, after)
    finally:
        c.close()


@pytest.mark.parametrize("case,mode,call", FMI2_CASES, ids=[c[0] for c in FMI2_CASES])
def test_fmi2_refused_setter_changes_nothing(fmu_file, case, mode, call):
    assert run_case(fmu_file, False, mode, call) == [], case


@pytest.mark.parametrize("case,mode,call", FMI3_CASES, ids=[c[0] for c in FMI3_CASES])
def test_fmi3_refused_setter_changes_nothing(fmi3_file, case, mode, call):
    assert run_case(fmi3_file, True, mode, call) == [], case


def test_fmi3_too_many_values_leave_the_instance_unable_to_step(fmi3_file):
    """fmi3SetFloat64 with too many values is an error like any other refusal: the instance is in the
    error state and does not step on (with or without the values)."""
    c = Instance(fmi3_file, True)
    try:
        c.step_mode()
        with pytest.raises(FMICallException):
            c.fmu.setFloat64([c.vr["tow.x"]], [5.0, 6.0])
        with pytest.raises(FMICallException):
            c.fmu.doStep(0.5, 0.5)
    finally:
        c.close()
