"""Water pushed by the importer (water.source 1, docs/waves.md "Water pushed by the importer") through the
FMI 3.0 FMU's arrays: the FMU gives the load points' positions (waterPoint.*), the importer the water's
velocity and local acceleration there (waterVelocity.*, waterAcceleration.*). Pushing the FMU's own Airy wave
reproduces its built-in wave to first order in the communication step; a uniform pushed current is the
built-in current bit for bit; the arrays are in the model description as FMI 3.0 arrays sized by the
structural parameter nWaterPoints; a saved state continues bit for bit with the same water pushed; FMI 2.0
and too short arrays are refused naming what is wrong."""

import math
import shutil

import numpy as np
import pytest
from fmpy import extract, read_model_description
from fmpy.fmi3 import FMU3Slave
from fmpy.validation import validate_fmu

from ucable.fmu import FMICallException
from ucable.units import STANDARD_GRAVITY as G

TOW = {"tow.x": 0.0, "tow.y": 0.0, "tow.z": -1.0}
N_ELEMENTS = 20
POINTS = 3 * N_ELEMENTS  # load points: 3 per element
WAVE = {"H": 2.0, "T": 8.0, "ramp": 16.0}  # deep water (waterDepth 1000 m): k h = 63


class Cable3:
    """One FMI 3.0 instance of the cable, addressed by name; the water arrays as numpy arrays."""

    def __init__(self, path, parameters, sizes=None):
        self.md = read_model_description(str(path))
        self.dir = extract(str(path))
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        self.types = {v.name: v.type for v in self.md.modelVariables}
        self.messages = []
        self.fmu = FMU3Slave(guid=self.md.guid, unzipDirectory=self.dir, modelIdentifier="UnderwaterCable",
                             instanceName="pushed")
        self.fmu.instantiate(loggingOn=True,
                             logMessage=lambda env, status, category, text: self.messages.append(text.decode()))
        self.n = (sizes or {}).get("nWaterPoints", int(self.md.modelVariables[
            [v.name for v in self.md.modelVariables].index("nWaterPoints")].start))
        if sizes:
            self.fmu.enterConfigurationMode()
            self.fmu.setUInt64([self.vr[k] for k in sizes], list(sizes.values()))
            self.fmu.exitConfigurationMode()
        for name, value in parameters.items():
            kind = self.types[name]
            if kind == "Int32":
                self.fmu.setInt32([self.vr[name]], [int(value)])
            elif kind == "Boolean":
                self.fmu.setBoolean([self.vr[name]], [bool(value)])
            elif kind == "String":
                self.fmu.setString([self.vr[name]], [str(value)])
            else:
                self.fmu.setFloat64([self.vr[name]], [float(value)])

    def set(self, values):
        self.fmu.setFloat64([self.vr[n] for n in values], [float(v) for v in values.values()])

    def get(self, name):
        return self.fmu.getFloat64([self.vr[name]])[0]

    def positions(self):
        """waterPoint.x/y/z: (nWaterPoints, 3)."""
        values = self.fmu.getFloat64([self.vr[f"waterPoint.{c}"] for c in "xyz"], nValues=3 * self.n)
        return np.array(values).reshape(3, self.n).T

    def push(self, u, a):
        """Velocity and acceleration, (points, 3) each (zeros beyond)."""
        full = np.zeros((2, self.n, 3))
        full[0, :len(u)], full[1, :len(a)] = u, a
        vrs = [self.vr[f"waterVelocity.{c}"] for c in "xyz"] + [self.vr[f"waterAcceleration.{c}"] for c in "xyz"]
        self.fmu.setFloat64(vrs, list(full.transpose(0, 2, 1).ravel()))

    def initialize(self, inputs):
        self.set(inputs)
        self.fmu.enterInitializationMode(startTime=0.0)
        self.fmu.exitInitializationMode()

    def close(self):
        self.fmu.freeInstance()
        shutil.rmtree(self.dir, ignore_errors=True)


def airy(r, t, H=WAVE["H"], T=WAVE["T"], ramp=WAVE["ramp"]):
    """The FMU's regular wave along +x in deep water (docs/waves.md): velocity and local acceleration at the
    points r (n, 3) at time t; above the mean surface those of z = 0; grown over rampTime by half a cosine."""
    w = 2 * math.pi / T
    k = w * w / G
    f = 0.5 * (1 - math.cos(math.pi * t / ramp)) if t < ramp else 1.0
    e = np.exp(k * np.minimum(r[:, 2], 0.0))
    theta = k * r[:, 0] - w * t
    a = 0.5 * H
    u = np.zeros_like(r)
    acc = np.zeros_like(r)
    u[:, 0], u[:, 2] = f * a * w * e * np.cos(theta), f * a * w * e * np.sin(theta)
    acc[:, 0], acc[:, 2] = f * a * w * w * e * np.sin(theta), -f * a * w * w * e * np.cos(theta)
    return u, acc


OUT = ["towTension", "towForce.x", "towForce.y"]


def run(path, parameters, step, t_end, water=None, inputs=TOW):
    """towTension, towForce.x/y (columns) at every communication point; water(r, t) -> (u, a) pushed at the positions the FMU gives
    at each step's start (water.source 1), or None (the FMU's own water)."""
    c = Cable3(path, {"nElements": N_ELEMENTS, **parameters, **({"water.source": 1} if water else {})})
    if water:
        c.push(*water(np.zeros((POINTS, 3)), 0.0))
    c.initialize(inputs)
    out = [[c.get(n) for n in OUT]]
    for k in range(int(round(t_end / step))):
        t = k * step
        if water:
            c.push(*water(c.positions()[:POINTS], t))
        c.set(inputs)
        c.fmu.doStep(t, step)
        out.append([c.get(n) for n in OUT])
    c.close()
    return np.array(out)


def test_the_water_arrays_are_fmi3_arrays_sized_by_nWaterPoints(fmi3_file):
    assert validate_fmu(str(fmi3_file)) == []
    variables = {v.name: v for v in read_model_description(str(fmi3_file)).modelVariables}
    size = variables["nWaterPoints"]
    assert size.causality == "structuralParameter" and size.type == "UInt64" and int(size.start) == 3072
    for name, causality, unit in [("waterPoint", "output", "m"), ("waterVelocity", "input", "m/s"),
                                  ("waterAcceleration", "input", "m/s2")]:
        for c in "xyz":
            v = variables[f"{name}.{c}"]
            assert (v.type, v.causality, v.unit) == ("Float64", causality, unit)
            assert [d.valueReference for d in v.dimensions] == [size.valueReference]
    assert variables["water.source"].type == "Int32" and variables["waterPointCount"].causality == "output"


def test_the_fmu_gives_its_load_points_and_their_count(fmi3_file):
    c = Cable3(fmi3_file, {"nElements": N_ELEMENTS, "water.source": 1}, sizes={"nWaterPoints": 100})
    c.initialize(TOW)
    assert c.get("waterPointCount") == POINTS
    r = c.positions()
    assert r.shape == (100, 3) and not r[POINTS:].any()  # zeros beyond the load points
    # the hanging line: the load points go down from the tow point, three Gauss points per 15 m element
    z = r[:POINTS, 2]
    assert np.all(np.diff(z) < 0) and -1.0 - 15.0 < z[0] < -1.0 and z[-1] > -1.0 - 300.0 * 1.01
    gauss = 0.5 - math.sqrt(0.15)  # the 3-point rule's first point on [0, 1]
    assert z[0] == pytest.approx(-1.0 - gauss * 15.0, rel=1e-3)
    c.close()
    own = Cable3(fmi3_file, {"nElements": N_ELEMENTS})
    own.initialize(TOW)
    assert own.get("waterPointCount") == 0 and not own.positions().any()
    own.close()


def test_a_uniform_pushed_current_is_the_built_in_current(fmi3_file):
    """The line let go straight (initMode 1) in a 0.6 m/s current along x and 0.2 m/s along y: the water
    pushed at every load point gives the built-in current's tension bit for bit (the same velocity, zero
    acceleration, zero gradients)."""
    params = {"initMode": 1, "initialDirection.x": 0.0, "initialDirection.z": -1.0}
    current = np.array([0.6, 0.2, 0.0])
    own = run(fmi3_file, params, 0.5, 20.0, inputs={**TOW, "current.x": 0.6, "current.y": 0.2})
    pushed = run(fmi3_file, params, 0.5, 20.0, water=lambda r, t: (np.tile(current, (len(r), 1)), np.zeros_like(r)))
    calm = run(fmi3_file, params, 0.5, 20.0)
    assert np.max(np.abs(own[:, 1] - calm[:, 1])) > 0.1 * np.max(calm[:, 0])  # the current drags the line
    assert np.array_equal(own, pushed), np.max(np.abs(own - pushed))


def test_pushing_the_fmus_own_wave_reproduces_it_to_first_order_in_the_step(fmi3_file):
    """The regular wave (H 2 m, T 8 s, grown over 16 s) computed by the importer at the load points and pushed
    at each step's start: the tension follows the built-in wave's within what a swing half a step late
    would miss by at 0.2 s steps, and the difference halves with the step (the acceleration is held over the
    step, the velocity carried on by it, both taken where the load point stood at the step's start)."""
    params = {"waves.mode": 1, "waves.height": WAVE["H"], "waves.period": WAVE["T"],
              "waves.rampTime": WAVE["ramp"]}
    t_end = 32.0
    calm = run(fmi3_file, {}, 0.2, t_end)
    errors = {}
    for step in (0.2, 0.1):
        own = run(fmi3_file, params, step, t_end)
        pushed = run(fmi3_file, {}, step, t_end, water=airy)
        swing = np.ptp(own[len(own) // 2:, 0])
        assert swing > 0.01 * calm[0, 0]  # the wave pulls on the line
        errors[step] = np.max(np.abs(own[:, 0] - pushed[:, 0])) / swing
    # a swing half a step late is off by at most (omega h / 2) of its amplitude, (omega h / 4) of its range
    assert errors[0.2] < 2 * math.pi / WAVE["T"] * 0.2 / 4, errors
    assert 0.35 < errors[0.1] / errors[0.2] < 0.65, errors  # first order in the step


def test_a_saved_state_continues_bit_for_bit_with_the_same_water_pushed(fmi3_file):
    """The pushed water is an input, not state: the importer pushes it again after restoring (here the same
    wave at the positions the FMU gives), and the run continues with the same bits, also in a fresh instance."""
    step, params = 0.25, {"nElements": N_ELEMENTS, "water.source": 1}

    def advance(c, t0, steps):
        rows = []
        for k in range(steps):
            t = t0 + k * step
            c.push(*airy(c.positions()[:POINTS], t))
            c.set(TOW)
            c.fmu.doStep(t, step)
            rows.append([c.get("towTension")] + list(c.positions()[:POINTS].ravel()))
        return np.array(rows)

    c = Cable3(fmi3_file, params)
    c.initialize(TOW)
    advance(c, 0.0, 40)
    state = c.fmu.getFMUState()
    data = c.fmu.serializeFMUState(state)
    first = advance(c, 10.0, 20)
    c.fmu.setFMUState(state)
    c.push(np.full((POINTS, 3), 9.0), np.full((POINTS, 3), 9.0))  # whatever was pushed last is not state
    second = advance(c, 10.0, 20)
    c.fmu.freeFMUState(state)
    c.close()
    fresh = Cable3(fmi3_file, params)  # never initialized
    restored = fresh.fmu.deserializeFMUState(data)
    fresh.fmu.setFMUState(restored)
    fresh.fmu.freeFMUState(restored)
    third = advance(fresh, 10.0, 20)
    fresh.close()
    assert np.array_equal(first, second) and np.array_equal(first, third)


def test_too_short_arrays_and_bad_water_are_refused_naming_them(fmi3_file):
    c = Cable3(fmi3_file, {"nElements": N_ELEMENTS, "water.source": 1}, sizes={"nWaterPoints": 50})
    with pytest.raises(Exception):
        c.initialize(TOW)
    text = "\n".join(c.messages)
    assert "60 load points" in text and "nWaterPoints = 50" in text, text
    c.close()
    c = Cable3(fmi3_file, {"nElements": N_ELEMENTS, "water.source": 1})
    c.initialize(TOW)
    u = np.zeros((POINTS, 3))
    u[6, 2] = float("nan")
    c.push(u, np.zeros((POINTS, 3)))
    with pytest.raises(Exception):
        c.fmu.doStep(0.0, 0.5)
    assert any("waterVelocity.z[7] = nan m/s" in m for m in c.messages), c.messages
    c.close()
    c = Cable3(fmi3_file, {"water.source": 1, "winchMode": 1})  # a winch changes the elements, so the points
    with pytest.raises(Exception):
        c.initialize(TOW)
    assert any("water.source = 1 is outside {0} with winchMode != 0" in m for m in c.messages), c.messages
    c.close()
    for vr_name, count, said in [("waterPoint.x", 3072, "cannot be set"), ("waterVelocity.x", 3071, "3072 elements")]:
        c = Cable3(fmi3_file, {"water.source": 1})
        with pytest.raises(Exception):
            c.fmu.setFloat64([c.vr[vr_name]], [0.0] * count)
        assert any(said in m for m in c.messages), c.messages
        c.close()


def test_fmi2_refuses_pushed_water_naming_the_parameter(make_cable):
    c = make_cable(parameters={})
    with pytest.raises(FMICallException):
        c.initialize(0.0, parameters={"water.source": 1})
    assert "water.source = 1" in c.log_text() and "FMI 3.0" in c.log_text()



def test_a_mooring_systems_lines_take_the_pushed_water_one_after_the_other(fmi3_file):
    """The OC4 platform's three chains (scenes/oc4_semi.dat) with the platform at rest: 3 load points per
    element of every line, the lines one after the other; a uniform current of 0.5 m/s along x pushed at all
    of them gives the built-in current's fairlead tensions through the statics and 10 s of steps."""
    from studies.comparisons import mooring_system as ms

    params = ms.fmu_parameters(ms.read_system_deck(ms.OC4))
    current = np.array([0.5, 0.0, 0.0])
    runs = []
    for pushed in (False, True):
        c = Cable3(fmi3_file, {**params, **({"water.source": 1} if pushed else {})})
        flow = {} if pushed else {"current.x": current[0]}
        if pushed:
            c.push(np.tile(current, (c.n, 1)), np.zeros((c.n, 3)))
        c.initialize(flow)
        if pushed:
            count = int(c.get("waterPointCount"))
            r = c.positions()[:count]
            per_line = count // 3
            assert count == 3 * per_line and per_line % 3 == 0 and not c.positions()[count:].any()
            ends = [r[k * per_line] for k in range(3)] + [r[(k + 1) * per_line - 1] for k in range(3)]
            # each line's points run from one end to the other: near its fairlead (14 m deep) or its anchor (200 m)
            assert sorted(round(e[2] / 100) for e in ends) == [-2, -2, -2, 0, 0, 0], ends
        rows = []
        for k in range(20):
            if pushed:
                c.push(np.tile(current, (c.n, 1)), np.zeros((c.n, 3)))
            else:
                c.set(flow)
            c.fmu.doStep(0.5 * k, 0.5)
            rows.append(c.fmu.getFloat64([c.vr["line.fairleadTension"]], nValues=64)[:3])
        runs.append(np.array(rows))
        c.close()
    assert np.ptp(runs[0][-1]) > 100.0  # the current loads line 2 (along x) unlike lines 1 and 3 (symmetric)
    assert np.array_equal(runs[0], runs[1]), np.max(np.abs(runs[0] - runs[1]))


def test_water_set_in_initialization_mode_makes_the_statics_anew(fmi3_file):
    """In initialization mode the importer reads waterPoint.* (the statics with the water set so far: none),
    sets the water there and leaves: the statics are made again with it. A uniform 0.6 m/s current so set
    gives the built-in current's statics (initMode 0) to the bit."""
    current = {"current.x": 0.6}
    own = Cable3(fmi3_file, {"nElements": N_ELEMENTS})
    own.initialize({**TOW, **current})
    expected = [own.get(n) for n in OUT]
    own.close()
    c = Cable3(fmi3_file, {"nElements": N_ELEMENTS, "water.source": 1})
    c.set(TOW)
    c.fmu.enterInitializationMode(startTime=0.0)
    still = c.positions()[:POINTS]  # the statics in still water: the line hangs straight down
    assert np.ptp(still[:, 0]) < 1e-6 and c.get("towForce.x") == pytest.approx(0.0, abs=1e-6)
    c.push(np.tile([0.6, 0.0, 0.0], (POINTS, 1)), np.zeros((POINTS, 3)))
    c.fmu.exitInitializationMode()
    assert [c.get(n) for n in OUT] == expected
    assert np.ptp(c.positions()[:POINTS, 0]) > 10.0  # the current has swept the line aside
    c.close()
