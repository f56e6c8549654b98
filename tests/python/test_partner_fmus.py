"""The partner FMUs (Vessel, VesselRAO, TowedBody): FMI conformance, the physics against independent solutions,
and the robustness every FMU of the project owes (bad parameters, NaN inputs, call sequences, states).

The Vessel FMU is a C port of the Python vessel model studies.cosim.partners.vessel: with the same constant
tow force both integrate the same equations with the same Runge-Kutta substeps, so they agree to
round-off (1e-9 m / 1e-12 rad after 400 steps: the two differ only in the order of floating-point
operations, whose error grows about linearly with the number of steps from 1e-16 relative).
"""

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from studies.cosim.masters import HeadingReference, SpeedReference
from ucable.fmu import FMICallException
from studies.cases.manoeuvre import PiecewiseLinearSpeed
from studies.cosim.partners import Autopilot, Vessel, VesselParameters
from ucable.units import KNOT
from ucable.system import partner_fmu
from ucable.units import GRAVITY as G, WATER_DENSITY as RHO


@pytest.fixture(scope="module")
def vessel_fmu(fmu_file):
    return partner_fmu("Vessel")


@pytest.fixture(scope="module")
def body_fmu(fmu_file):
    return partner_fmu("TowedBody")


@pytest.mark.parametrize("name", ["Vessel", "VesselRAO", "TowedBody"])
def test_fmpy_validate_and_fmutool_check_find_no_problem(fmu_file, name):
    out = subprocess.run([sys.executable, "-m", "fmpy", "validate", str(partner_fmu(name))],
                         capture_output=True, text=True)
    assert out.returncode == 0 and "No problems found" in out.stdout, out.stdout + out.stderr
    proc = subprocess.run([str(Path(sys.executable).parent / "fmutool"), "-input", str(partner_fmu(name)),
                           "-check"], capture_output=True, text=True, timeout=300)
    text = proc.stdout + proc.stderr
    assert proc.returncode == 0, text
    assert "This FMU seems to be compliant with FMI-2.0" in text, text
    assert "No semantic error against the FMI-2 standard" in text, text
    assert not [line for line in text.splitlines() if "ERROR" in line or "WARNING" in line], text


def fly_the_turn(vessel_fmu, make_unit, force, heading_integral_bandwidth=None):
    """The Vessel FMU and the Python vessel model through the turn and ramp below: both, after 200 s."""
    program = {"speed0": 1.1 * KNOT, "speed1": 2.4 * KNOT, "rampStart": 0.0, "rampDuration": 60.0,
               "turnStart": 30.0, "turnRate": math.radians(1.0), "turnAngle": math.radians(90.0)}
    gains = {}
    if heading_integral_bandwidth is not None:
        program["headingIntegralBandwidth"] = heading_integral_bandwidth
        gains["heading_integral_bandwidth"] = heading_integral_bandwidth
    v = make_unit(vessel_fmu, parameters=program)
    v.initialize(0.0, 200.0, inputs={f"towForce.{q}": f for q, f in zip("xyz", force)})
    p = VesselParameters()
    ap = Autopilot(p, SpeedReference(PiecewiseLinearSpeed([0.0, 60.0], [1.1 * KNOT, 2.4 * KNOT])),
                   HeadingReference(0.0, 30.0, math.radians(1.0), math.radians(90.0)), **gains)
    py = Vessel(p, ap, u0=1.1 * KNOT)
    for k in range(400):
        v.do_step(0.5, t=0.5 * k)
        py.step(0.5, force, force)
    return v, py


VESSEL_STATE = ["x", "y", "heading", "surge", "sway", "yawRate"]


def test_vessel_fmu_equals_the_python_vessel_model_in_a_turn_and_a_ramp(vessel_fmu, make_unit):
    """Speed ramp 1.1 -> 2.4 kn in 60 s and a 90 deg turn at 1 deg/s from 30 s, under a constant tow
    force with a lateral component (it yaws the vessel), 0.5 s steps for 200 s."""
    force = np.array([-5000.0, 1500.0, -3000.0])
    v, py = fly_the_turn(vessel_fmu, make_unit, force)
    fmu_state = v.get_reals(VESSEL_STATE)
    assert np.max(np.abs(fmu_state[:2] - py.x[:2])) < 1e-9
    assert np.max(np.abs(fmu_state[2:] - py.x[2:6])) < 1e-12
    # the turn was flown to its heading: the constant Earth-frame force yaws the vessel back by ~17 deg
    # once it is abeam (5 kN x 10 m against the PD's 0.17 MN m/rad, below), which the heading loop's
    # integral action (pole at -0.05 1/s) takes out: 80 s after the turn 17 deg x exp(-0.05 x 80) = 0.3 deg
    assert math.degrees(fmu_state[2]) == pytest.approx(90.0, abs=0.5)
    pos, vel, acc = py.tow_point(tow_force=force, t=200.0)
    tow = v.get_reals(["tow.x", "tow.y", "tow.vx", "tow.vy", "tow.ax", "tow.ay"])
    assert np.max(np.abs(tow - np.array([*pos, *vel, *acc]))) < 1e-9
    thrust, moment = py.commands(force)
    assert v.get("thrust") == pytest.approx(thrust, rel=1e-9)
    assert v.get("rudderMoment") == pytest.approx(moment, rel=1e-9, abs=1e-6)


def test_vessel_without_heading_integral_keeps_the_tow_offset(vessel_fmu, make_unit):
    """headingIntegralBandwidth 0 is the critically damped PD: the lateral force leaves the heading
    about 5 kN x 10 m / 0.17 MN m/rad = 17 deg short (the two models still agree)."""
    force = np.array([-5000.0, 1500.0, -3000.0])
    v, py = fly_the_turn(vessel_fmu, make_unit, force, heading_integral_bandwidth=0.0)
    fmu_state = v.get_reals(VESSEL_STATE)
    assert np.max(np.abs(fmu_state[2:] - py.x[2:6])) < 1e-12
    assert 60.0 < math.degrees(fmu_state[2]) < 80.0


TURN = {"speed0": 2.4 * KNOT, "speed1": 2.4 * KNOT, "turnStart": 30.0, "turnRate": math.radians(1.0),
        "turnAngle": math.radians(90.0)}
FINE = 1.0 / 128  # [s] the reference's step and every run's Runge-Kutta substep (binary: the times exact)


def turning_tow_force(t):
    """A tow force that grows and turns after the vessel (from 40 s at the turn's 1 deg/s): the side force of
    the turn, which yaws the vessel and makes it drift."""
    a = math.radians(1.0) * min(max(t - 40.0, 0.0), 90.0)
    T = 5000.0 + 20.0 * t
    return {"towForce.x": -T * math.cos(a), "towForce.y": -T * math.sin(a), "towForce.z": -3000.0}


def fly_under_the_turning_force(make_unit, vessel_fmu, h, timing, taken, t_end=150.0):
    """The tow point at t = h, 2 h, ... t_end with the force given as a master takes it: the force at the
    step's start (taken "start", a Jacobi master) or at its end ("end", Gauss-Seidel, the cable first)."""
    v = make_unit(vessel_fmu, parameters={**TURN, "towForceTiming": timing, "maxSubstep": FINE},
                  instance_name=f"v{timing}{taken}{h:g}")
    v.initialize(0.0, t_end, inputs=turning_tow_force(0.0))
    track = []
    for k in range(int(round(t_end / h))):
        v.set(turning_tow_force((k + (taken == "end")) * h))
        v.do_step(h, t=k * h)
        track.append(v.get_reals(["tow.x", "tow.y"]))
    return np.array(track)


def test_the_tow_force_over_a_step_is_second_order_as_its_timing_says(vessel_fmu, make_unit):
    """towForceTiming: the force over a communication step is linear in time, extrapolated from the last
    two inputs (1: they are the forces at the steps' starts) or interpolated from the input before (2: at
    the steps' ends), so the track's error falls with h^2, by 4 from 1 s to 0.5 s; held (0), whenever the
    master took it, the force is half a step early or late and the error falls with h, by 2. Reference: the
    force given every 1/128 s; every run integrates with the same 1/128 s substeps, so the differences are
    the force's over the step alone."""
    ref = fly_under_the_turning_force(make_unit, vessel_fmu, FINE, 1, "start")

    def error(h, timing, taken):
        stride = int(round(h / FINE))
        track = fly_under_the_turning_force(make_unit, vessel_fmu, h, timing, taken)
        return np.max(np.linalg.norm(track - ref[stride - 1::stride], axis=1))

    held = {taken: [error(h, 0, taken) for h in (1.0, 0.5)] for taken in ("start", "end")}
    for timing, taken in ((1, "start"), (2, "end")):
        e1, e05 = error(1.0, timing, taken), error(0.5, timing, taken)
        assert 3.5 < e1 / e05 < 4.5, (timing, e1, e05)  # second order
        assert e1 < 0.05 * held[taken][0], (timing, e1, held)
    for taken, (e1, e05) in held.items():
        assert 1.8 < e1 / e05 < 2.2, (taken, e1, e05)  # first order


def body_force(v, CdA=0.3, CLA=0.0, current=(0.0, 0.0)):
    u = np.array([current[0], current[1], 0.0]) - np.asarray(v, float)
    F = 0.5 * RHO * CdA * np.linalg.norm(u) * u
    F[2] -= 0.5 * RHO * CLA * (u[0] ** 2 + u[1] ** 2)
    return F


def test_towed_body_force_and_its_linearization(body_fmu, make_unit):
    """Force element: force.* is drag + depressor lift at the input velocity (closed form), and
    forceDamping.* = -d force / d v (central differences of the FMU's own force, step 1e-5 m/s:
    truncation ~(1e-5 / 1 m/s)^2 relative, cancellation ~1e-16 * 300 N / 1e-5 m/s = 3e-9 N s/m)."""
    params = {"CdA": 0.3, "CLA": 0.8, "current.x": 0.2, "current.y": -0.1}
    b = make_unit(body_fmu, parameters=params)
    v0 = np.array([1.3, 0.4, -0.2])
    b.initialize(0.0, 10.0, inputs={f"end.v{q}": x for q, x in zip("xyz", v0)})
    names = [f"force.{q}" for q in "xyz"]
    F = b.get_reals(names)
    assert np.allclose(F, body_force(v0, 0.3, 0.8, (0.2, -0.1)), rtol=1e-12, atol=1e-9)
    assert np.array_equal(b.get_reals([f"forceVelocity.{q}" for q in "xyz"]), v0)
    D = b.get_reals([f"forceDamping.{r}{c}" for r in "xyz" for c in "xyz"]).reshape(3, 3)
    numeric = np.zeros((3, 3))
    t, dv = 0.0, 1e-5
    for j, q in enumerate("xyz"):
        values = []
        for sign in (1, -1):
            v = v0.copy()
            v[j] += sign * dv
            b.set({f"end.v{c}": x for c, x in zip("xyz", v)})
            b.do_step(0.5, t=t)
            t += 0.5
            values.append(b.get_reals(names))
        numeric[:, j] = -(values[0] - values[1]) / (2 * dv)
    assert np.allclose(D, numeric, rtol=1e-6, atol=1e-6)
    assert D[2, 0] != 0.0 and D[0, 2] != D[2, 0]  # the lift makes it non-symmetric


def test_towed_body_sinks_at_its_terminal_velocity(body_fmu, make_unit):
    """Integrating its translation without a cable: (m - rho V) g = 1/2 rho CdA v^2. The time constant
    (m + ma) / (rho CdA v) = 0.37 s: after 30 s (80 time constants) the velocity is terminal to
    round-off; the fixed point of the Runge-Kutta map is the exact terminal velocity."""
    b = make_unit(body_fmu, parameters={"integrateTranslation": True, "position0.z": -10.0})
    b.initialize(0.0, 30.0)
    for k in range(60):
        b.do_step(0.5, t=0.5 * k)
    v_terminal = math.sqrt(2 * (400.0 - RHO * 0.1) * G / (RHO * 0.3))
    assert b.get("velocity.z") == pytest.approx(-v_terminal, rel=1e-9)
    assert b.get("acceleration.z") == pytest.approx(0.0, abs=1e-9)


def test_bad_parameters_and_inputs_are_errors_naming_the_variable(body_fmu, vessel_fmu, make_unit):
    b = make_unit(body_fmu, parameters={"mass": -1.0}, instance_name="b")
    with pytest.raises(FMICallException):
        b.initialize(0.0, 10.0)
    assert any("mass = -1 is outside [0, 1e+08]" in m for _, _, m in b.messages), b.log_text()
    v = make_unit(vessel_fmu, instance_name="v")
    v.initialize(0.0, 10.0)
    with pytest.raises(FMICallException):
        v.set({"towForce.x": float("nan")})
    assert any("towForce.x = nan" in m for _, _, m in v.messages), v.log_text()
    w = make_unit(vessel_fmu, instance_name="w")
    w.initialize(0.0, 10.0)
    with pytest.raises(FMICallException):
        w.set({"mass": 1.0})  # a fixed parameter after initialization
    assert any("mass is a fixed parameter" in m for _, _, m in w.messages), w.log_text()


def test_a_string_parameter_is_copied_into_the_instance_and_fixed_after_initialization(vessel_fmu, make_unit):
    """raoFile (String): the FMU keeps its own copy (the caller's buffer overwritten after fmi2SetString
    changes nothing), a string longer than the 4095 bytes it keeps, NULL, and a change after initialization
    are errors naming the variable; a wrong type's value reference is unknown."""
    import ctypes

    from fmpy.fmi2 import fmi2String, fmi2ValueReference
    v = make_unit(vessel_fmu, instance_name="v")
    vr = v.variables["raoFile"].valueReference
    buffer = ctypes.create_string_buffer(b"my_vessel.csv")
    one = (fmi2ValueReference * 1)(vr)
    v.slave.fmi2SetString(v.slave.component, one, 1, (fmi2String * 1)(ctypes.addressof(buffer)))
    ctypes.memset(buffer, ord("x"), len(buffer) - 1)
    v.initialize(0.0, 10.0)  # calm water: no RAO table is read
    assert v.get("raoFile") == "my_vessel.csv"
    with pytest.raises(FMICallException):
        v.set({"raoFile": "other.csv"})
    assert any("raoFile is a fixed parameter" in m for _, _, m in v.messages), v.log_text()
    with pytest.raises(FMICallException):
        v.slave.getReal([vr])
    assert any(f"unknown value reference {vr} for type Real" in m for _, _, m in v.messages), v.log_text()
    w = make_unit(vessel_fmu, parameters={"raoFile": "x" * 4095}, instance_name="w")  # the longest it keeps
    with pytest.raises(FMICallException):
        w.set({"raoFile": "x" * 4096})
    assert any("raoFile: the string is longer than the 4095 bytes this FMU keeps" in m for _, _, m in w.messages)
    n = make_unit(vessel_fmu, instance_name="n")
    with pytest.raises(FMICallException):
        n.slave.fmi2SetString(n.slave.component, one, 1, (fmi2String * 1)(None))
    assert any("raoFile: the value is a NULL pointer" in m for _, _, m in n.messages), n.log_text()


def test_do_step_before_initialization_is_an_illegal_call_sequence(body_fmu, make_unit):
    b = make_unit(body_fmu)
    with pytest.raises(FMICallException):
        b.slave.doStep(0.0, 0.5)
    assert any("illegal call sequence" in m for _, _, m in b.messages)


STATE_CASES = {
    "Vessel": ({"turnStart": 5.0, "turnRate": 0.02, "turnAngle": 1.0}, {"towForce.x": -4000.0, "towForce.y": 800.0}),
    "Vessel in waves": ({"turnStart": 5.0, "turnRate": 0.02, "turnAngle": 1.0, "waves.mode": 2, "waves.height": 3.0,
                         "waves.seed": 7, "waves.rampTime": 8.0, "waves.direction": 2.5},
                        {"towForce.x": -4000.0, "towForce.y": 800.0}),
    "VesselRAO": ({"waves.mode": 2, "waves.height": 3.0, "waves.seed": 7, "waves.rampTime": 8.0,
                   "waves.direction": 2.5, "towPoint.y": 4.0}, {}),
    "TowedBody": ({"integrateTranslation": True, "CLA": 0.5, "velocity0.x": 1.0},
                  {"cableForce.x": 300.0, "cableForce.z": 2500.0}),
}


@pytest.mark.parametrize("name", list(STATE_CASES))
def test_states_restore_and_serialize_bit_identically(fmu_file, make_unit, name):
    params, inputs = STATE_CASES[name]
    fmu = partner_fmu(name.split()[0])
    a = make_unit(fmu, parameters=params, instance_name="a")
    # the other instance starts with other parameters: the restored state brings (and rebuilds from) a's
    c = make_unit(fmu, parameters={**params, "waves.seed": 8} if "waves.mode" in params else params,
                  instance_name="c")
    for u in (a, c):
        u.initialize(0.0, 100.0, inputs=inputs)
    outputs = [n for n, v in a.variables.items() if v.causality == "output"]
    for k in range(10):
        a.do_step(0.5, t=0.5 * k)
    state = a.get_state()
    data = a.serialize_state(state)
    for j in range(10):
        a.do_step(0.5, t=5.0 + 0.5 * j)
    first = a.get_reals(outputs)
    a.set_state(state, time=5.0)
    for j in range(10):
        a.do_step(0.5, t=5.0 + 0.5 * j)
    assert np.array_equal(a.get_reals(outputs), first)
    c.set_state(c.deserialize_state(data), time=5.0)  # another instance, from the bytes
    for j in range(10):
        c.do_step(0.5, t=5.0 + 0.5 * j)
    assert np.array_equal(c.get_reals(outputs), first)
    a.free_state(state)


def test_reset_and_rerun_is_bit_identical(vessel_fmu, make_unit):
    program = {"turnStart": 2.0, "turnRate": 0.05, "turnAngle": 0.5}
    v = make_unit(vessel_fmu, parameters=program)
    outputs = [n for n, x in v.variables.items() if x.causality == "output"]

    def flight():
        v.initialize(0.0, 20.0, inputs={"towForce.x": -3000.0, "towForce.y": 500.0}, parameters=program)
        for k in range(20):
            v.do_step(0.5, t=0.5 * k)
        return v.get_reals(outputs)

    first = flight()
    v.slave.reset()
    assert np.array_equal(flight(), first)
