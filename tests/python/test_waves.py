"""Waves through the FMU: waveElevation is the closed-form elevation at the tow point, a hanging
cable's tension answers at the wave period, bad wave parameters are refused naming the variable
(waves.mode 0 is today's model bit for bit: tests/python/test_golden.py)."""

import math

import numpy as np
import pytest

from ucable.fmu import FMICallException
from ucable.units import STANDARD_GRAVITY as G


def hanging(make_cable, waves, t_end=120.0, step=0.25, x=0.0):
    c = make_cable(parameters={"gravity": G, **waves})
    c.initialize(0.0, inputs={"tow.x": x})
    rows = [c.get_reals(["waveElevation", "towTension"])]
    for k in range(int(round(t_end / step))):
        c.set({"tow.x": x})
        c.do_step(step, k * step)
        rows.append(c.get_reals(["waveElevation", "towTension"]))
    return np.arange(len(rows)) * step, np.array(rows)


def test_wave_elevation_at_the_tow_point_is_the_closed_form(make_cable):
    H, T, x = 2.0, 8.0, 17.0
    t, rows = hanging(make_cable, {"waves.mode": 1, "waves.height": H, "waves.period": T}, t_end=20.0, x=x)
    w = 2 * math.pi / T
    k = w * w / G  # deep water (1000 m)
    assert np.allclose(rows[:, 0], 0.5 * H * np.cos(k * x - w * t), atol=1e-9)


def test_a_hanging_cable_answers_at_the_wave_period(make_cable):
    T = 8.0
    t, calm = hanging(make_cable, {})
    _, wavy = hanging(make_cable, {"waves.mode": 1, "waves.height": 2.0, "waves.period": T, "waves.rampTime": 16.0})
    assert np.ptp(calm[:, 1]) < 1e-3 * calm[0, 1]  # calm water: the hanging cable stays at rest
    late = t >= 40.0
    tension = wavy[late, 1] - wavy[late, 1].mean()
    assert np.ptp(tension) > 0.01 * calm[0, 1]  # the waves pull on the cable near the surface
    spectrum = np.abs(np.fft.rfft(tension))
    freq = np.fft.rfftfreq(len(tension), t[1] - t[0])
    assert freq[np.argmax(spectrum)] == pytest.approx(1.0 / T, abs=1.0 / (t[late][-1] - t[late][0]))


@pytest.mark.parametrize("params, named", [
    ({"waves.mode": 1, "waves.height": 12.0, "waves.period": 6.0}, "waves.height"),  # breaking: H / lambda 0.21
    ({"waves.mode": 1, "waves.height": 2.0, "waves.period": 0.0}, "waves.period"),
    ({"waves.mode": 1, "waves.height": float("nan")}, "waves.height"),
    ({"waves.mode": 3}, "waves.mode"),
])
def test_bad_wave_parameters_are_refused_naming_the_variable(make_cable, params, named):
    c = make_cable(parameters={})
    with pytest.raises(FMICallException):
        c.initialize(0.0, parameters=params)
    assert named in c.log_text()


def current_ramp(make_cable, step, derivatives, t_end=40.0, rate=0.05):
    """The current grows at `rate` m/s^2 along x (0 to 1 m/s in 20 s, then held) around a hanging cable."""
    c = make_cable(parameters={})
    c.initialize(0.0, inputs={})
    out = [c.get("towTension")]
    for k in range(int(round(t_end / step))):
        t = k * step
        c.set({"current.x": rate * min(t, 20.0)})
        if derivatives:
            c.set_input_derivatives(["current.x"], 1, [rate if t < 20.0 else 0.0])
        c.do_step(step, t)
        out.append(c.get("towTension"))
    return np.array(out)


def test_a_current_changing_within_the_step_follows_its_input_derivative(make_cable):
    """At 1 s steps a master that passes der(current.x) gives the tension of a fine-stepped run (the
    current's ramp is then exact within each step); one that does not holds the current over each
    step, a step behind."""
    fine = current_ramp(make_cable, 0.02, True)[::50]
    with_rate = current_ramp(make_cable, 1.0, True)
    held = current_ramp(make_cable, 1.0, False)
    err_rate, err_held = np.abs(with_rate - fine).max(), np.abs(held - fine).max()
    assert err_rate < 0.05 * err_held, (err_rate, err_held)
    assert err_held > 1.0  # the held current is worth newtons on this cable


def test_a_taut_vertical_cable_carries_the_morison_integral_of_the_closed_form(make_cable):
    """A 50 m cable pinned 2 m below the surface and at an anchor straight below, 50 kN pretension, in
    a regular wave (H 2 m, T 8 s, deep water). Taut, it hardly moves, so the water's load per length is
    Morison's with the closed-form kinematics: q = 1/2 rho Cdn d |u| u + rho A (1 + Can) du/dt
    (horizontal u at the cable), and a pinned string passes int q (L - s) / L ds to its top. The
    reference neglects the cable's own lateral motion: its first mode (0.85 Hz against the wave's
    0.125 Hz) amplifies the response by 1 / (1 - (f / f1)^2) - 1 = 2.2 %, the bound on the amplitude."""
    rho, g, L, d, H, T, Cdn, Can, ztop = 1025.0, 9.80665, 50.0, 0.05, 2.0, 8.0, 1.2, 1.0, -2.0
    params = {"length": L, "diameter": d, "massPerLength": 5.0, "EA": 5e7, "EI": 0.0, "enableBending": False,
              "Cdn": Cdn, "Cdt": 0.0, "Can": Can, "Cat": 0.0, "bottomEnd": 1, "anchor.z": ztop - L * 1.001,
              "nElements": 20, "gravity": g, "waterDensity": rho, "waves.mode": 1, "waves.height": H,
              "waves.period": T, "waves.rampTime": 16.0, "initialDirection.x": 0.0, "initialDirection.z": -1.0}
    c = make_cable(parameters=params)
    c.initialize(0.0, inputs={"tow.z": ztop})
    dt, t_end = 0.05, 64.0
    t = np.arange(1, int(round(t_end / dt)) + 1) * dt
    fx = []
    for k in range(len(t)):
        c.set({"tow.z": ztop})
        c.do_step(dt, k * dt)
        fx.append(c.get("towForce.x"))
    fx = np.array(fx)
    w = 2 * math.pi / T
    k = w * w / g
    s = np.linspace(0.0, L, 2001)
    z = ztop - s

    def top_force(time):
        u = 0.5 * H * w * np.exp(k * z) * math.cos(-w * time)
        acc = 0.5 * H * w * w * np.exp(k * z) * math.sin(-w * time)
        q = 0.5 * rho * Cdn * d * np.abs(u) * u + rho * math.pi * d * d / 4 * (1 + Can) * acc
        return np.trapezoid(q * (L - s) / L, s)

    late = t > 32.0  # after the ramp and its transient
    reference = np.array([top_force(x) for x in t[late]])
    f1 = math.sqrt(c.get("towTension") / (5.0 + rho * math.pi * d * d / 4 * Can)) / (2 * L)
    bound = 1.0 / (1.0 - (1.0 / T / f1) ** 2) - 1.0
    assert 0.01 < bound < 0.03
    assert np.ptp(fx[late]) / np.ptp(reference) - 1.0 == pytest.approx(0.0, abs=bound)


SHEAR = {"currentProfileRows": 2, "currentProfile.depth[1]": 0.0, "currentProfile.x[1]": 0.3,
         "currentProfile.y[1]": 0.0, "currentProfile.depth[2]": 100.0, "currentProfile.x[2]": 0.0,
         "currentProfile.y[2]": 0.2}


def ramp_in_steps(make_cable, n, tolerance, derivatives=True, rate=(0.05, 0.02), t_end=10.0):
    """The uniform current ramped from 0 at `rate` over t_end in n communication steps, on top of a
    sheared depth profile, around the default hanging cable: the state at t_end."""
    c = make_cable(parameters={**SHEAR, "tensionTolerance": tolerance})
    c.initialize(0.0, inputs={})
    h = t_end / n
    for k in range(n):
        t = k * h
        c.set({"current.x": rate[0] * t, "current.y": rate[1] * t})
        if derivatives:
            c.set_input_derivatives(["current.x", "current.y"], 1, list(rate))
        c.do_step(h, t)
    return c.get("towTension"), c.get_reals(["towForce.x", "towForce.y", "towForce.z",
                                              "endPosition.x", "endPosition.y", "endPosition.z"])


def test_a_current_ramp_in_one_step_is_the_ramp_in_many(make_cable):
    """A current ramped by its input derivatives over one 10 s communication step (with a depth
    profile added to it throughout) ends where the same ramp in a hundred 0.1 s steps ends: the
    integrator then takes different steps through the same equations, so the two differ by its
    local error, bounded by tensionTolerance x the tension (5.3 N here) and shrinking with it
    (measured: 0.015 N at 1e-3, 2e-4 N at 1e-5). Holding the current over each step instead
    (no derivatives) is a newton off."""
    for tolerance in (1e-3, 1e-5):
        T_big, big = ramp_in_steps(make_cable, 1, tolerance)
        T_small, small = ramp_in_steps(make_cable, 100, tolerance)
        assert abs(T_big - T_small) < tolerance * T_small
        assert np.abs(big[:3] - small[:3]).max() < tolerance * T_small
        assert np.abs(big[3:] - small[3:]).max() < 1e-3  # positionTolerance
        if tolerance == 1e-3:
            err_coarse = abs(T_big - T_small)
    assert abs(T_big - T_small) < 0.1 * err_coarse  # the difference is the integrator's error
    T_held, held = ramp_in_steps(make_cable, 100, 1e-5, derivatives=False)
    assert abs(T_held - T_small) > 0.5


def scale_in_steps(make_cable, n, tolerance, derivatives=True, rate=0.15, t_end=10.0):
    """The depth profile's factor currentScale ramped from 1 at `rate` over t_end in n steps (the
    uniform current 0): a current strengthening in proportion at every depth; the state at t_end."""
    c = make_cable(parameters={**SHEAR, "tensionTolerance": tolerance})
    c.initialize(0.0, inputs={})
    h = t_end / n
    for k in range(n):
        t = k * h
        c.set({"currentScale": 1.0 + rate * t})
        if derivatives:
            c.set_input_derivatives(["currentScale"], 1, [rate])
        c.do_step(h, t)
    return c.get("towTension"), c.get_reals(["towForce.x", "towForce.y", "towForce.z"])


def test_the_profile_scales_with_currentScale(make_cable):
    """currentScale multiplies the depth profile: the profile doubled is currentScale 2 bit for bit
    (a factor 2 is exact in floating point), and the default 1 is the profile as given."""
    doubled = {k: 2.0 * v if k.startswith(("currentProfile.x", "currentProfile.y")) else v for k, v in SHEAR.items()}
    runs = []
    for params, scale in ((doubled, 1.0), (SHEAR, 2.0)):
        c = make_cable(parameters=params)
        c.initialize(0.0, inputs={"currentScale": scale})
        c.set({"currentScale": scale})
        c.do_step(0.5, 0.0)
        runs.append(c.get_reals(["towTension", "towForce.x", "towForce.y", "endPosition.x", "endPosition.y"]))
    assert runs[0].tobytes() == runs[1].tobytes()
    assert abs(runs[0][2]) > 1.0  # the profile's y current really acts
    c = make_cable(parameters=SHEAR)
    c.initialize(0.0, inputs={})
    assert c.get("currentScale") == 1.0  # its start value: the profile as given


def test_a_profile_scaled_over_one_step_is_the_ramp_in_many(make_cable):
    """currentScale ramped by its input derivative over one 10 s step ends where the same ramp in a
    hundred 0.1 s steps ends, to the integrator's local error (bounded by tensionTolerance x the
    tension and shrinking with it); held constant over each step instead it is measurably off."""
    for tolerance in (1e-3, 1e-5):
        T_big, big = scale_in_steps(make_cable, 1, tolerance)
        T_small, small = scale_in_steps(make_cable, 100, tolerance)
        assert abs(T_big - T_small) < tolerance * T_small
        assert np.abs(big - small).max() < tolerance * T_small
        if tolerance == 1e-3:
            err_coarse = abs(T_big - T_small)
    assert abs(T_big - T_small) < 0.5 * err_coarse  # the difference is the integrator's: it shrinks with it
    T_held, _ = scale_in_steps(make_cable, 100, 1e-5, derivatives=False)
    assert abs(T_held - T_small) > 20 * abs(T_big - T_small)
