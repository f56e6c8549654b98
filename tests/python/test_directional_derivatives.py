"""fmi2GetDirectionalDerivative: the interface derivatives over the next communication step
(docs/cosimulation.md, "Interface derivatives") against central finite differences of fmi2DoStep with
the FMU state rolled back (fmi2GetFMUstate / fmi2SetFMUstate).

The finite differences are taken at a tight integrator tolerance (tensionTolerance 1e-8: the
integration noise in tension, about 1e-8 x 8 kN, over the 1 mm / 1 mm/s perturbations is below
1e-4 of the entries) and the perturbations keep the change in tension to tens of newtons, where the
cable responds linearly. What remains is the derivative's own error, the documented bound: 0.5 % of
the largest entry for steps up to 1 s (its time discretization, BDF2 with 64 and 128 substeps
extrapolated; the linearization about the state at the step start).
"""

import numpy as np
import pytest

from ucable.fmu import FMICallException
from ucable.units import KNOT

TOW = ["tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz"]
END = ["end.x", "end.y", "end.z", "end.vx", "end.vy", "end.vz"]
ACCELERATIONS = ["tow.ax", "tow.ay", "tow.az", "end.ax", "end.ay", "end.az"]
TOW_FORCE = ["towForce.x", "towForce.y", "towForce.z"]
END_FORCE = ["endForce.x", "endForce.y", "endForce.z"]
BOUND = 0.005  # of the largest entry: the documented accuracy


class Tow:
    """A steady tow along +x at 2 kn, the far end free, towing a body, or held by a partner moving
    with the tow point (bottomEnd 3), stepped by a master that passes the tow acceleration."""

    def __init__(self, make_cable, h, bottom_end, accelerations=True, extra=None):
        params = {"bottomEnd": bottom_end, "tensionTolerance": 1e-8, **(extra or {})}
        self.V, self.h, self.t, self.accelerations = 2.0 * KNOT, h, 0.0, accelerations
        self.end_offset = np.array([-200.0, 0.0, -150.0])
        if bottom_end == 2:
            params.update({"body.mass": 400.0, "body.CdA": 0.3})
        if bottom_end == 4:
            params.update({"body.mass": 400.0, "body.addedMass": 100.0, "body.volume": 0.1})
        self.cable = make_cable(parameters=params)
        self.cable.initialize(0.0, inputs=self.inputs())
        for _ in range(4):
            self.step()
            self.t += h

    def inputs(self, t=None):
        t = self.t if t is None else t
        x = {"tow.x": self.V * t, "tow.y": 0.0, "tow.z": 0.0, "tow.vx": self.V, "tow.vy": 0.0, "tow.vz": 0.0}
        e = self.end_offset + [self.V * t, 0.0, 0.0]
        x.update({"end.x": e[0], "end.y": e[1], "end.z": e[2], "end.vx": self.V, "end.vy": 0.0, "end.vz": 0.0})
        if self.accelerations:
            x.update(dict.fromkeys(ACCELERATIONS, 0.0))
        return x

    def step(self, change=None):
        inputs = self.inputs()
        for name, delta in (change or {}).items():
            inputs[name] += delta
        accelerations = [inputs.pop(name) for name in ACCELERATIONS if name in inputs]
        self.cable.set(inputs)
        if self.accelerations:  # the accelerations tow.a* / end.a* as input derivatives der(tow.v*), der(end.v*)
            self.cable.set_input_derivatives(["tow.vx", "tow.vy", "tow.vz", "end.vx", "end.vy", "end.vz"], 1,
                                             accelerations)
        self.cable.do_step(self.h, self.t)

    def derivatives(self, outputs, inputs):
        c = self.cable
        vo = [c.variables[n].valueReference for n in outputs]
        return np.column_stack([c.slave.getDirectionalDerivative(vo, [c.variables[n].valueReference], [1.0])
                                for n in inputs])

    def finite_differences(self, outputs, inputs, eps=1e-3):
        c = self.cable
        state = c.get_state()
        columns = []
        for name in inputs:
            values = []
            for sign in (1.0, -1.0):
                c.set_state(state, self.t)
                self.step({name: sign * eps})
                values.append(c.get_reals(outputs))
            columns.append((values[0] - values[1]) / (2.0 * eps))
        c.set_state(state, self.t)
        c.free_state(state)
        return np.column_stack(columns)


def relative_error(D, FD):
    return np.abs(D - FD).max() / np.abs(FD).max()


@pytest.mark.parametrize("h", [1.0, 0.5, 0.1, 0.02])
@pytest.mark.parametrize("bottom_end", [0, 2])
def test_tow_force_derivatives_equal_finite_differences_of_the_step(make_cable, h, bottom_end):
    tow = Tow(make_cable, h, bottom_end)
    D = tow.derivatives(TOW_FORCE, TOW)
    FD = tow.finite_differences(TOW_FORCE, TOW)
    assert relative_error(D, FD) < BOUND, (D, FD)


@pytest.mark.parametrize("h", [0.5, 0.1])
def test_derivatives_of_a_viscoelastic_line_carry_its_internal_strains(make_cable, h):
    """The viscoelastic model (relaxation time (c + c_d) / (EA_1 + EA_2) = 0.3 s, of the order of the steps):
    the internal strains' rows and their couplings to the tow point and the tow force are in the linearization."""
    extra = {"EA": 6.7e7, "EAdynamic": 2.0e8, "axialDamping": 1.0e8, "axialDampingDynamic": 2.0e6}
    tow = Tow(make_cable, h, 0, extra=extra)
    D = tow.derivatives(TOW_FORCE, TOW)
    FD = tow.finite_differences(TOW_FORCE, TOW)
    assert relative_error(D, FD) < BOUND, (D, FD)


def test_derivatives_without_input_derivatives_follow_the_estimated_acceleration(make_cable):
    """A master that passes no accelerations: the FMU differences the velocity inputs, so a velocity
    input moves the target acceleration too; the derivative says so."""
    tow = Tow(make_cable, 0.1, 0, accelerations=False)
    D = tow.derivatives(TOW_FORCE, TOW)
    FD = tow.finite_differences(TOW_FORCE, TOW)
    assert relative_error(D, FD) < BOUND, (D, FD)


@pytest.mark.parametrize("h", [1.0, 0.5, 0.05])
def test_end_force_derivatives_of_a_driven_far_end(make_cable, h):
    tow = Tow(make_cable, h, 3)
    inputs = TOW + END
    D = tow.derivatives(TOW_FORCE + END_FORCE, inputs)
    FD = tow.finite_differences(TOW_FORCE + END_FORCE, inputs)
    for rows in (slice(0, 3), slice(3, 6)):
        assert relative_error(D[rows], FD[rows]) < BOUND, (rows, D[rows], FD[rows])


@pytest.mark.parametrize("h", [1.0, 0.1])
def test_proxy_far_end_derivatives(make_cable, h):
    """bottomEnd 4: the tow force and the force on the body by the tow inputs within the documented
    bound (the proxy's inertia and its estimate's drag law are in the linearization, the force on the
    body follows from the proxy's state at the step's end); the body's reported state does not reach
    the cable within a step (tow force by end.*: exactly 0) and enters the force on the body through
    the tracking force alone, linearly: its columns are exact (to the finite differences' round-off)."""
    tow = Tow(make_cable, h, 4)
    D = tow.derivatives(TOW_FORCE + END_FORCE, TOW + END)
    FD = tow.finite_differences(TOW_FORCE + END_FORCE, TOW + END)
    assert relative_error(D[:3, :6], FD[:3, :6]) < BOUND, (D[:3, :6], FD[:3, :6])
    assert relative_error(D[3:, :6], FD[3:, :6]) < BOUND, (D[3:, :6], FD[3:, :6])
    assert np.all(FD[:3, 6:] == 0.0) and np.all(D[:3, 6:] == 0.0)
    assert relative_error(D[3:, 6:], FD[3:, 6:]) < 1e-6, (D[3:, 6:], FD[3:, 6:])


@pytest.mark.parametrize("h", [1.0, 0.5, 0.05])
def test_acceleration_columns_equal_finite_differences_of_the_step(make_cable, h):
    """The acceleration inputs (tow.a*, end.a*; here passed as der(tow.v*), der(end.v*)) move the end's
    target by h^2/2, h and 1 (position, velocity, acceleration) per unit."""
    tow = Tow(make_cable, h, 3)
    D = tow.derivatives(TOW_FORCE + END_FORCE, ACCELERATIONS)
    FD = tow.finite_differences(TOW_FORCE + END_FORCE, ACCELERATIONS, eps=1e-2)
    for rows in (slice(0, 3), slice(3, 6)):
        assert relative_error(D[rows], FD[rows]) < BOUND, (rows, D[rows], FD[rows])


def test_acceleration_inputs_are_the_input_derivatives(make_cable):
    """Setting tow.a* / end.a* with fmi2SetReal is passing der(tow.v*) / der(end.v*): the step is
    bit-identical; without either, the FMU estimates the acceleration from the velocity inputs."""
    runs = []
    for way in ("derivatives", "inputs", "neither"):
        tow = Tow(make_cable, 0.2, 3, accelerations=False)
        c, inputs = tow.cable, tow.inputs()
        inputs["tow.vx"] += 0.05
        c.set(inputs)
        a = [0.25, 0.0, -0.1, 0.2, 0.05, 0.0]
        if way == "derivatives":
            c.set_input_derivatives(["tow.vx", "tow.vy", "tow.vz", "end.vx", "end.vy", "end.vz"], 1, a)
        elif way == "inputs":
            c.set(dict(zip(ACCELERATIONS, a)))
        c.do_step(tow.h, tow.t)
        runs.append(c.get_reals(TOW_FORCE + END_FORCE))
        assert c.get_reals(ACCELERATIONS).tolist() == [0.0] * 6  # given for one step
    assert np.array_equal(runs[0], runs[1]) and not np.array_equal(runs[0], runs[2])


def test_seeds_combine_linearly_and_the_result_does_not_change_the_run(make_cable):
    tow = Tow(make_cable, 0.2, 0)
    c = tow.cable
    vo = [c.variables[n].valueReference for n in TOW_FORCE]
    vi = [c.variables[n].valueReference for n in TOW]
    seed = [0.3, -1.0, 2.0, 0.5, 0.1, -0.7]
    combined = np.array(c.slave.getDirectionalDerivative(vo, vi, seed))  # the direction integrated at once
    by_columns = tow.derivatives(TOW_FORCE, TOW) @ seed  # each column integrated alone (and kept)
    # linear to round-off: 1e-12 of the largest entry (192 banded solves of entries up to 1e5 N/m)
    assert np.max(np.abs(combined - by_columns)) <= 1e-12 * np.max(np.abs(by_columns))
    again = np.array(c.slave.getDirectionalDerivative(vo, vi, seed))  # now from the kept columns
    assert np.max(np.abs(again - by_columns)) <= 1e-12 * np.max(np.abs(by_columns))
    # Asking for derivatives leaves the simulation as it was: the next step is bit-identical.
    twin = Tow(make_cable, 0.2, 0)
    tow.step()
    twin.step()  # (both from the same time, without advancing: one step each)
    assert np.array_equal(c.get_reals(TOW_FORCE), twin.cable.get_reals(TOW_FORCE))


def stepped_cable(make_cable):
    cable = make_cable(parameters={})
    cable.initialize(0.0, inputs={"tow.vx": 1.0})
    cable.do_step(0.5, 0.0)
    return cable


def vrs(cable, names):
    return [cable.variables[n].valueReference for n in names]


def test_a_call_before_the_first_step_is_an_error(make_cable):
    cable = make_cable(parameters={})
    cable.initialize(0.0, inputs={"tow.vx": 1.0})
    with pytest.raises(FMICallException):  # there is no step yet whose length the next one takes
        cable.slave.getDirectionalDerivative(vrs(cable, ["towForce.x"]), vrs(cable, ["tow.x"]), [1.0])
    assert "available after the first fmi2DoStep" in cable.log_text()


@pytest.mark.parametrize("unknown, known, message", [
    ("towTension", "tow.x", "no derivative of towTension"),
    ("towForce.x", "current.x", "no derivative with respect to current.x"),
])
def test_unsupported_pairs_are_errors_naming_the_variable(make_cable, unknown, known, message):
    cable = stepped_cable(make_cable)
    with pytest.raises(FMICallException):
        cable.slave.getDirectionalDerivative(vrs(cable, [unknown]), vrs(cable, [known]), [1.0])
    assert message in cable.log_text()


def test_a_non_finite_seed_is_an_error_naming_the_input(make_cable):
    cable = stepped_cable(make_cable)
    with pytest.raises(FMICallException):
        cable.slave.getDirectionalDerivative(vrs(cable, ["towForce.x"]), vrs(cable, ["tow.x"]), [float("nan")])
    assert "seed of tow.x is not a finite number" in cable.log_text()
