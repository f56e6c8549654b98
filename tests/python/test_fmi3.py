"""The FMI 3.0 variant (build/fmi3/UnderwaterCable.fmu, docs/fmi3.md) through fmpy's FMI 3.0 importer:
valid, both platforms in it, the stations and a mooring system's lines, bodies and points as arrays, and
the same cable as the FMI 2.0 FMU: the Hopland manoeuvre and the OC4 platform's moorings give the same
bits, a serialized state continues bit for bit in a fresh instance, the interface derivatives (the single
line's and the platform's) equal the FMI 2.0 ones, and the FMU's messages arrive as plain text."""

import shutil
import zipfile

import numpy as np
import pytest
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave
from fmpy.fmi3 import FMU3Slave
from fmpy.validation import validate_fmu

from studies.comparisons import mooring_system as ms
from studies.cases.manoeuvre import NUM_STATIONS, hopland_accelerate, tow_inputs
from ucable.variables import MAX_BODIES, MAX_LINES, MAX_POINTS

STEP = 0.5
T_END = 90.0   # through the 60 s ramp and 30 s beyond
T_SAVE = 30.0  # inside the ramp
SCALARS = ["towTension", "towForce.x", "towForce.z", "endPosition.x", "endPosition.z", "minTension"]
ARRAYS = ["shape.x", "shape.z", "tension"]


class Cable:
    """One instance of either FMU, addressed by the FMI 2.0 names (arrays as name[k] in FMI 2.0)."""

    def __init__(self, path, fmi3, messages=None, early=False):
        self.md = read_model_description(str(path))
        self.dir = extract(str(path))
        self.fmi3 = fmi3
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        cls = FMU3Slave if fmi3 else FMU2Slave
        self.fmu = cls(guid=self.md.guid, unzipDirectory=self.dir,
                       modelIdentifier=self.md.coSimulation.modelIdentifier, instanceName="cable")
        if fmi3:
            log = None if messages is None else (lambda env, status, category, text: messages.append(text.decode()))
            self.fmu.instantiate(loggingOn=messages is not None, logMessage=log, earlyReturnAllowed=early)
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

    def set_parameters(self, values):
        """Parameters of any type, by name (the same names in both FMUs)."""
        types = {v.name: v.type for v in self.md.modelVariables}
        for name, value in values.items():
            if types[name] == "String":
                self.fmu.setString([self.vr[name]], [str(value)])
            elif types[name] == "Boolean":
                self.fmu.setBoolean([self.vr[name]], [bool(value)])
            elif types[name] in ("Integer", "Int32"):
                (self.fmu.setInt32 if self.fmi3 else self.fmu.setInteger)([self.vr[name]], [int(value)])
            else:
                self.set({name: value})

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


@pytest.mark.parametrize("n_values", [NUM_STATIONS - 1, NUM_STATIONS + 1])
def test_fmi3_an_array_read_into_the_wrong_count_is_refused_with_both_counts(fmi3_file, n_values):
    """One array of NUM_STATIONS elements read into too few or too many values: fmi3Error, and the
    message gives the values passed and the elements asked for."""
    messages = []
    cable = Cable(fmi3_file, True, messages)
    cable.initialize(tow_inputs(hopland_accelerate()[0], 0.0))
    with pytest.raises(Exception):
        cable.fmu.getFloat64([cable.vr["tension"]], nValues=n_values)
    text = "\n".join(messages)
    assert f"{n_values} values for 1 value references of {NUM_STATIONS} elements in all" in text, text
    cable.close()


# A mooring system: FMI 2.0 family name (k the index, c the component) -> the FMI 3.0 arrays of it,
# each with its number of elements (k outer).
SYSTEM_OUTPUTS = [("line[{k}].fairleadTension", "", MAX_LINES), ("line[{k}].anchorTension", "", MAX_LINES),
                  ("line[{k}].minTension", "", MAX_LINES), ("line[{k}].groundedLength", "", MAX_LINES),
                  ("body[{k}].force.{c}", "xyz", MAX_BODIES), ("body[{k}].moment.{c}", "xyz", MAX_BODIES),
                  ("point[{k}].force.{c}", "xyz", MAX_POINTS)]
BODY_RATES = ("vx", "vy", "vz", "wx", "wy", "wz")


class System(Cable):
    """The OC4 platform's moorings (scenes/oc4_semi.dat) in either FMU: body 1's pose and rates as inputs,
    the lines', bodies' and points' outputs read as FMI 2.0 scalars or FMI 3.0 arrays, in the FMI 2.0 order
    (k outer, component inner)."""

    def set_body(self, pose_and_rates):
        names = ms.POSE_NAMES + BODY_RATES
        if self.fmi3:  # body.x = [body 1, body 2, ..., body MAX_BODIES]
            self.set_arrays({f"body.{n}": [x] + [0.0] * (MAX_BODIES - 1) for n, x in zip(names, pose_and_rates)})
        else:
            self.set({f"body[1].{n}": x for n, x in zip(names, pose_and_rates)})

    def set_arrays(self, arrays):
        names = list(arrays)
        self.fmu.setFloat64([self.vr[n] for n in names], [x for n in names for x in arrays[n]])

    def outputs(self):
        values = []
        for family, components, count in SYSTEM_OUTPUTS:
            comps = components or [""]
            if self.fmi3:
                name = family.replace("[{k}]", "")
                arrays = [self.fmu.getFloat64([self.vr[name.replace("{c}", c)]], nValues=count) for c in comps]
                values += [arrays[j][k] for k in range(count) for j in range(len(comps))]
            else:
                values += self.fmu.getReal([self.vr[family.replace("{k}", str(k)).replace("{c}", c)]
                                            for k in range(1, count + 1) for c in comps])
        if self.fmi3:
            values += self.fmu.getFloat64([self.vr["body.stiffness"]], nValues=MAX_BODIES * 36)
        else:
            values += self.fmu.getReal([self.vr[f"body[{k}].stiffness[{i},{j}]"] for k in range(1, MAX_BODIES + 1)
                                        for i in range(1, 7) for j in range(1, 7)])
        return np.array(values)


def test_the_system_arrays_of_the_fmi3_fmu(fmi3_file):
    """A mooring system's names in FMI 3.0: its FMI 2.0 names without [k], one array per component, the
    stiffness one array [body, i, j], each on the value reference of its first FMI 2.0 element."""
    md2 = {v.name: v for v in read_model_description(str(fmi3_file.parent.parent / "UnderwaterCable.fmu")).modelVariables}
    md3 = {v.name: v for v in read_model_description(str(fmi3_file)).modelVariables}
    dims = {n: list(v.shape) for n, v in md3.items() if v.dimensions}  # the structural parameters at their start
    expected = {"line.fairleadTension": [MAX_LINES], "body.force.x": [MAX_BODIES], "body.moment.z": [MAX_BODIES],
                "body.stiffness": [MAX_BODIES, 6, 6], "body.x": [MAX_BODIES], "body.roll": [MAX_BODIES],
                "body.wz": [MAX_BODIES], "point.x": [MAX_POINTS], "point.vz": [MAX_POINTS],
                "point.force.y": [MAX_POINTS], "point.position.x": [MAX_POINTS], "body.pose.yaw": [MAX_BODIES],
                "shape.x": [NUM_STATIONS]}
    assert {n: dims.get(n) for n in expected} == expected
    for name in expected:
        first = name.replace("body.", "body[1].").replace("point.", "point[1].").replace("line.", "line[1].")
        first = first + "[1,1]" if name == "body.stiffness" else first
        first = first + "[1]" if name == "shape.x" else first
        assert md3[name].valueReference == md2[first].valueReference, name
    assert md3["body.x"].start == " ".join(["0"] * MAX_BODIES) and md3["body.x"].causality == "input"
    assert "body[1].x" not in md3 and "line[1].fairleadTension" not in md3


def test_the_oc4_moorings_through_fmi3_arrays_are_bit_identical_to_fmi2(fmi3_file, fmu_file):
    """The OC4 platform's three chains with body 1 in surge, heave and pitch for 10 s at 0.2 s steps: every
    line, body and point output (the stiffness included) the same bits through the FMI 3.0 arrays as through
    the FMI 2.0 scalars; then the directional derivatives of the body's load with respect to its inputs
    (FMI 3.0: the arrays body.force.*, body.moment.* against body.x ... body.wz, seeded on element 1) equal
    the FMI 2.0 ones of body 1, and the other bodies' elements (not in the deck) are 0."""
    deck = ms.read_system_deck(ms.OC4)
    motion, h = ms.PlatformMotion(), 0.2
    runs, derivatives = [], []
    for path, fmi3 in ((fmu_file, False), (fmi3_file, True)):
        system = System(path, fmi3)
        system.set_parameters(ms.fmu_parameters(deck))
        q, v, _ = motion.state(0.0)
        system.set_body([*q, *v])
        system.initialize({})
        rows = [system.outputs()]
        for k in range(50):
            q, v, _ = motion.state(k * h)
            system.set_body([*q, *v])
            system.fmu.doStep(k * h, h)
            rows.append(system.outputs())
        runs.append(np.array(rows))
        loads = [f"body{{k}}.{a}.{c}" for a in ("force", "moment") for c in "xyz"]
        inputs = ms.POSE_NAMES + BODY_RATES
        if fmi3:
            unknowns = [system.vr[n.format(k="")] for n in loads]
            columns = [system.fmu.getDirectionalDerivative(unknowns, [system.vr[f"body.{n}"]], [1.0] + [0.0] * (MAX_BODIES - 1),
                                                           nSensitivity=6 * MAX_BODIES) for n in inputs]
            columns = np.array(columns).reshape(len(inputs), 6, MAX_BODIES)
            assert np.all(columns[:, :, 1:] == 0.0)
            derivatives.append(columns[:, :, 0])
        else:
            unknowns = [system.vr[n.format(k="[1]")] for n in loads]
            derivatives.append(np.array([system.fmu.getDirectionalDerivative(unknowns, [system.vr[f"body[1].{n}"]], [1.0])
                                         for n in inputs]))
        system.close()
    fmi2, fmi3 = runs
    assert fmi2.shape == (51, 4 * MAX_LINES + 6 * MAX_BODIES + 3 * MAX_POINTS + 36 * MAX_BODIES)
    tensions = fmi2[:, :3]
    assert tensions.min() > 5e5 and np.ptp(tensions[:, 0]) > 1e5  # three loaded chains, line 1 pulled by the surge
    assert np.all(fmi2[:, [4 * MAX_LINES, 4 * MAX_LINES + 2]] != 0.0)  # body 1's force x, z (y: 0 by symmetry)
    assert np.array_equal(fmi2, fmi3), f"max difference {np.max(np.abs(fmi2 - fmi3))}"
    assert np.any(derivatives[0] != 0.0)
    assert np.array_equal(derivatives[0], derivatives[1])


def test_an_fmi3_state_of_the_oc4_moorings_is_refused_after_the_deck_was_edited(fmi3_file, tmp_path):
    """fmi3SetFMUState of a deserialized state in a new instance after the deck file was edited (line 1
    10 m longer): fmi3Error naming the file and the value, not a run on the edited deck's lines."""
    path = tmp_path / "oc4_semi.dat"
    text = ms.OC4.read_text()
    path.write_text(text)
    parameters = {**ms.fmu_parameters(ms.read_system_deck(ms.OC4)), "lineFile": str(path)}
    motion, h = ms.PlatformMotion(), 0.2
    system = System(fmi3_file, True)
    system.set_parameters(parameters)
    q, v, _ = motion.state(0.0)
    system.set_body([*q, *v])
    system.initialize({})
    for k in range(3):
        q, v, _ = motion.state(k * h)
        system.set_body([*q, *v])
        system.fmu.doStep(k * h, h)
    state = system.fmu.getFMUState()
    data = system.fmu.serializeFMUState(state)
    system.fmu.freeFMUState(state)
    system.close()
    before = "1         main        1         4       835.35"
    assert before in text
    path.write_text(text.replace(before, "1         main        1         4       845.35", 1))
    messages = []
    fresh = System(fmi3_file, True, messages=messages)
    fresh.set_parameters(parameters)
    restored = fresh.fmu.deserializeFMUState(data)
    with pytest.raises(Exception):
        fresh.fmu.setFMUState(restored)
    refusal = [m for m in messages if "fmi2SetFMUstate" in m or "SetFMUState" in m]
    assert refusal and f"lineFile {path}" in refusal[-1], messages
    assert "length = 845.35000000000002 now, 835.35000000000002 in the state" in refusal[-1], refusal


def test_a_refused_fmi3_serialized_state_leaves_a_fresh_instance_to_run(fmi3_file):
    """fmi3DeserializeFMUState of a truncated buffer: fmi3Error, and the fresh instance then initializes and
    runs bit for bit as one that never saw the call (the refusal put it into the error state)."""
    profile, _ = hopland_accelerate()
    origin = Cable(fmi3_file, True)
    origin.initialize(tow_inputs(profile, 0.0))
    origin.advance(profile, 0.0, 2.0)
    state = origin.fmu.getFMUState()
    data = origin.fmu.serializeFMUState(state)
    origin.fmu.freeFMUState(state)
    origin.close()
    runs = []
    for refused in (True, False):
        fresh = Cable(fmi3_file, True)
        if refused:
            with pytest.raises(Exception):
                fresh.fmu.deserializeFMUState(data[:-3])
        fresh.initialize(tow_inputs(profile, 0.0))
        runs.append(fresh.advance(profile, 0.0, 2.0))
        fresh.close()
    assert runs[0].tobytes() == runs[1].tobytes()


def _line_one(cable, name):
    """line[1].<name> of a system through its FMI 3.0 array (element 1 of 16)."""
    return cable.fmu.getFloat64([cable.vr[f"line.{name}"]], nValues=MAX_LINES)[0]


def _failing_oc4(fmi3_file, early, **failure):
    cable = Cable(fmi3_file, True, early=early)
    cable.set_parameters(ms.fmu_parameters(ms.read_system_deck(ms.OC4), lineFileElements=10,
                                           **{"failure.line": 1, **failure}))
    cable.initialize({})
    return cable


def _pull(cable, t):
    """The platform pulled away from anchor 1 at 0.5 m/s (along (-0.5, -0.866)): line 1's tension rises."""
    v = 0.5
    values = [-0.5 * v * t, -0.866 * v * t, -0.5 * v, -0.866 * v]  # body 1's; the arrays hold MAX_BODIES
    cable.fmu.setFloat64([cable.vr[f"body.{n}"] for n in ("x", "y", "vx", "vy")],
                         [x for value in values for x in [value] + [0.0] * (MAX_BODIES - 1)])


# With earlyReturnAllowed, fmi3DoStep returns at a line failure's break: earlyReturn true, lastSuccessfulTime the
# break's time (failure.time exactly; by tension, where the step located it), the outputs those at the break (the
# line broken, its breakTime); the next step goes on from there. After it, the run agrees with the run without early
# return at the later communication points within the integrators' tolerance in tension (tensionTolerance 1e-3 times
# the lines' tension scale: 1106 N on these chains): the two take the same pieces up to the break, and after it the
# same lines from the same state over the rest of the step, the one inside a step, the other in a step of its own.
@pytest.mark.parametrize("failure", [{"failure.time": 2.3}, {"failure.tension": 1.2e6}], ids=["time", "tension"])
def test_an_fmi3_step_returns_early_at_a_line_failure_where_the_importer_allows_it(fmi3_file, failure):
    plain, early = _failing_oc4(fmi3_file, False, **failure), _failing_oc4(fmi3_file, True, **failure)
    h, tolerance = 0.5, 1e-3 * 1.106e6
    try:
        t, returned, worst = 0.0, [], 0.0
        pulled = "failure.tension" in failure
        compared = 0
        for k in range(1, 25):
            if pulled:
                _pull(plain, (k - 1) * h)
            assert plain.fmu.doStep((k - 1) * h, h)[2] is False  # no early return without earlyReturnAllowed
            while t < k * h - 1e-12:
                if pulled:
                    _pull(early, t)
                _, _, back, last = early.fmu.doStep(t, k * h - t)
                if back:
                    returned.append(last)
                    assert last < k * h and _line_one(early, "broken") == 1.0
                    assert _line_one(early, "breakTime") == last  # the state at the break
                else:  # the communication point, as the FMU's own time reaches it (to round-off)
                    assert abs(last - k * h) <= 1e-12 * k * h
                t = last
            if returned:
                compared += 1
                for name in ("fairleadTension", "anchorTension"):
                    a, b = _line_one(plain, name), _line_one(early, name)
                    assert abs(a - b) <= tolerance, (k * h, name, a, b)
                    worst = max(worst, abs(a - b))
                bf = [early.fmu.getFloat64([early.vr[f"body.force.{c}"]], nValues=MAX_BODIES)[0] for c in "xy"]
                pf = [plain.fmu.getFloat64([plain.vr[f"body.force.{c}"]], nValues=MAX_BODIES)[0] for c in "xy"]
                assert np.allclose(bf, pf, rtol=0, atol=2 * tolerance), (k * h, bf, pf)
        print(f"early return at {returned} s; line 1's tensions after it differ by {worst:.3g} N at most")
        assert len(returned) == 1, returned
        assert returned[0] == _line_one(plain, "breakTime")  # the break the run without early return had
        if not pulled:
            assert returned[0] == 2.3
        assert compared > 10
    finally:
        plain.close()
        early.close()


# One line whose far end lets go (docs/line_failure.md, "One line"): the same early return at its break.
def test_an_fmi3_step_of_one_line_returns_early_where_its_far_end_lets_go(fmi3_file):
    cable = Cable(fmi3_file, True, early=True)
    try:
        cable.set_parameters({"bottomEnd": 1, "anchor.x": 200.0, "anchor.z": -200.0, "failure.line": 1,
                              "failure.time": 2.3})
        cable.initialize({})
        t = 0.0
        for _ in range(4):
            assert cable.fmu.doStep(t, 0.5)[2] is False
            t += 0.5
        _, _, back, last = cable.fmu.doStep(t, 0.5)
        assert back is True and last == 2.3
        assert _line_one(cable, "broken") == 1.0 and _line_one(cable, "breakTime") == 2.3
        _, _, back, last = cable.fmu.doStep(last, 3.0 - last)
        assert back is False and abs(last - 3.0) <= 1e-12
    finally:
        cable.close()
