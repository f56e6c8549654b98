"""The FMI 3.0 variant (build/fmi3/UnderwaterCable.fmu, docs/fmi3.md) through fmpy's FMI 3.0 importer:
valid, both platforms in it, the stations as arrays, and the same cable as the FMI 2.0 FMU: the Hopland
manoeuvre gives the same bits, a serialized state continues bit for bit in a fresh instance, the interface
derivatives equal the FMI 2.0 ones, and the FMU's messages arrive as plain text."""

import shutil
import zipfile

import numpy as np
import pytest
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave
from fmpy.fmi3 import FMU3Slave
from fmpy.validation import validate_fmu

from studies.manoeuvre import NUM_STATIONS, hopland_accelerate, tow_inputs

STEP = 0.5
T_END = 90.0   # through the 60 s ramp and 30 s beyond
T_SAVE = 30.0  # inside the ramp
SCALARS = ["towTension", "towForce.x", "towForce.z", "endPosition.x", "endPosition.z", "minTension"]
ARRAYS = ["shape.x", "shape.z", "tension"]


@pytest.fixture(scope="module")
def fmi3_file(fmu_file):
    path = fmu_file.parent / "fmi3" / "UnderwaterCable.fmu"
    if not path.is_file():
        pytest.fail(f"no FMI 3.0 FMU at {path}: build first: scripts/build", pytrace=False)
    return path


class Cable:
    """One instance of either FMU, addressed by the FMI 2.0 names (arrays as name[k] in FMI 2.0)."""

    def __init__(self, path, fmi3, messages=None):
        self.md = read_model_description(str(path))
        self.dir = extract(str(path))
        self.fmi3 = fmi3
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        cls = FMU3Slave if fmi3 else FMU2Slave
        self.fmu = cls(guid=self.md.guid, unzipDirectory=self.dir,
                       modelIdentifier=self.md.coSimulation.modelIdentifier, instanceName="cable")
        if fmi3:
            log = None if messages is None else (lambda env, status, category, text: messages.append(text.decode()))
            self.fmu.instantiate(loggingOn=messages is not None, logMessage=log)
        else:
            self.fmu.instantiate()

    def initialize(self, inputs):
        self.set(inputs)
        if self.fmi3:
            self.fmu.enterInitializationMode(startTime=0.0)
        else:
            self.fmu.setupExperiment(startTime=0.0)
            self.fmu.enterInitializationMode()
        self.fmu.exitInitializationMode()

    def set(self, values):
        names = list(values)
        vrs = [self.vr[n] for n in names]
        (self.fmu.setFloat64 if self.fmi3 else self.fmu.setReal)(vrs, [values[n] for n in names])

    def outputs(self):
        """The scalars, then the arrays' elements, as one array."""
        if self.fmi3:
            scalars = self.fmu.getFloat64([self.vr[n] for n in SCALARS])
            arrays = self.fmu.getFloat64([self.vr[n] for n in ARRAYS], nValues=len(ARRAYS) * NUM_STATIONS)
        else:
            scalars = self.fmu.getReal([self.vr[n] for n in SCALARS])
            arrays = self.fmu.getReal([self.vr[f"{a}[{k}]"] for a in ARRAYS for k in range(1, NUM_STATIONS + 1)])
        return np.array(list(scalars) + list(arrays))

    def advance(self, profile, t0, t1):
        rows = []
        for k in range(int(round((t1 - t0) / STEP))):
            t = t0 + k * STEP
            self.set(tow_inputs(profile, t))
            self.fmu.doStep(t, STEP)
            rows.append(self.outputs())
        return np.array(rows)

    def close(self):
        self.fmu.terminate()
        self.fmu.freeInstance()
        shutil.rmtree(self.dir, ignore_errors=True)


def test_the_fmi3_fmu_is_valid_and_carries_both_platforms(fmi3_file, fmu_file):
    assert validate_fmu(str(fmi3_file)) == []
    md = read_model_description(str(fmi3_file))
    assert md.fmiVersion == "3.0" and md.coSimulation.modelIdentifier == "UnderwaterCable"
    names = {v.name: v for v in md.modelVariables}
    assert int(names["shape.x"].dimensions[0].start) == NUM_STATIONS
    assert names["tension"].type == "Float64" and names["nElements"].type == "Int32"
    assert names["time"].causality == "independent"
    platforms = {n.split("/")[1] for n in zipfile.ZipFile(fmi3_file).namelist() if n.count("/") >= 2
                 and n.startswith("binaries/")}
    fmi2_platforms = {n.split("/")[1] for n in zipfile.ZipFile(fmu_file).namelist() if n.count("/") >= 2
                      and n.startswith("binaries/")}
    # the FMI 3.0 names of the FMI 2.0 FMU's platforms (FMI 3.0 section 2.5.1.1)
    assert platforms == {{"linux64": "x86_64-linux", "win64": "x86_64-windows"}[p] for p in fmi2_platforms}


def test_hopland_through_fmi3_is_bit_identical_to_fmi2(fmi3_file, fmu_file):
    profile, _ = hopland_accelerate()
    runs = []
    for path, fmi3 in ((fmu_file, False), (fmi3_file, True)):
        cable = Cable(path, fmi3)
        cable.initialize(tow_inputs(profile, 0.0))
        runs.append(np.vstack([cable.outputs(), cable.advance(profile, 0.0, T_END)]))
        cable.close()
    assert runs[0].shape == (int(T_END / STEP) + 1, len(SCALARS) + len(ARRAYS) * NUM_STATIONS)
    assert np.array_equal(runs[0], runs[1]), f"max difference {np.max(np.abs(runs[0] - runs[1]))}"


def test_a_serialized_fmi3_state_continues_bit_for_bit_in_a_fresh_instance(fmi3_file):
    profile, _ = hopland_accelerate()
    cable = Cable(fmi3_file, True)
    cable.initialize(tow_inputs(profile, 0.0))
    cable.advance(profile, 0.0, T_SAVE)
    state = cable.fmu.getFMUState()
    data = cable.fmu.serializeFMUState(state)
    cable.fmu.freeFMUState(state)
    first = cable.advance(profile, T_SAVE, T_END)
    cable.close()

    fresh = Cable(fmi3_file, True)  # never initialized
    restored = fresh.fmu.deserializeFMUState(data)
    fresh.fmu.setFMUState(restored)
    fresh.fmu.freeFMUState(restored)
    assert fresh.fmu.getFloat64([0]) == [T_SAVE]  # the independent variable time
    second = fresh.advance(profile, T_SAVE, T_END)
    fresh.close()
    assert np.array_equal(first, second)


def test_directional_derivatives_equal_the_fmi2_ones(fmi3_file, fmu_file):
    profile, _ = hopland_accelerate()
    unknowns = ["towForce.x", "towForce.z", "endForce.x"]
    knowns = ["tow.x", "tow.vx", "tow.z"]
    columns = []
    for path, fmi3 in ((fmu_file, False), (fmi3_file, True)):
        cable = Cable(path, fmi3)
        cable.initialize(tow_inputs(profile, 0.0))
        cable.advance(profile, 0.0, 10.0)
        u, k = [cable.vr[n] for n in unknowns], [cable.vr[n] for n in knowns]
        columns.append(np.array([cable.fmu.getDirectionalDerivative(u, k, list(seed))
                                 for seed in np.eye(len(knowns))]))
        cable.close()
    assert np.any(columns[0] != 0.0)
    assert np.array_equal(columns[0], columns[1])


def test_fmi3_messages_arrive_as_plain_text(fmi3_file):
    messages = []
    cable = Cable(fmi3_file, True, messages)
    with pytest.raises(Exception):
        cable.fmu.setFloat64([cable.vr["length"]], [-3.0])
        cable.initialize(tow_inputs(hopland_accelerate()[0], 0.0))
    text = "\n".join(messages)
    assert "length" in text and "%%" not in text, text
    cable.fmu.freeInstance()
    shutil.rmtree(cable.dir, ignore_errors=True)
