"""The third-party towed body (tests/third_party_body: Towfish.fmu, built outside the project's CMake):
a valid FMI 2.0 co-simulation FMU that integrates its own translation, checked against closed forms.

Released from rest in still water the body sinks under its weight in water W = (m - rho V) g against
the drag 1/2 rho CdA_z v^2 with the inertia M = m + ma_z:

    v(t) = v_t tanh(t / tau),  depth(t) = v_t tau ln cosh(t / tau),  v_t = sqrt(2 W / (rho CdA_z)),
    tau = M v_t / W.

The FMU integrates by classical Runge-Kutta (4th order) in substeps of maxSubstep: its error against the
closed form must fall as the 4th power of the substep (the ratio of two substeps a factor 2 apart near
16) and keep falling so to the default substep (0.01 s: a few 1e-9 m and m/s).
"""

import math

import numpy as np
import pytest
from fmpy.validation import validate_fmu

from ucable.units import GRAVITY as G, WATER_DENSITY as RHO


def test_the_third_party_body_is_a_valid_fmu(towfish_fmu):
    assert validate_fmu(str(towfish_fmu)) == []


def sink(make_unit, fmu, substep, t_end=6.0, h=0.5, **parameters):
    body = make_unit(fmu, parameters={"maxSubstep": substep, **parameters}, instance_name="towfish")
    body.initialize(0.0)
    t, rows = 0.0, [(0.0, *body.get_reals(["position.z", "velocity.z"]))]
    while t < t_end - 1e-9:
        body.do_step(h, t)
        t += h
        rows.append((t, *body.get_reals(["position.z", "velocity.z"])))
    return np.array(rows)


def closed_form(t, m, ma, V, cda):
    W = (m - RHO * V) * G
    vt = math.sqrt(2.0 * W / (RHO * cda))
    tau = (m + ma) * vt / W
    return -vt * tau * np.log(np.cosh(t / tau)), -vt * np.tanh(t / tau), vt


@pytest.mark.parametrize("parameters, m, ma, V, cda", [
    ({}, 400.0, 100.0, 0.1, 0.3),  # the defaults
    # a towfish with anisotropic added mass and drag: only the z values act in a vertical fall
    ({"mass": 50.0, "addedMass": 5.0, "addedMass.x": 100.0, "addedMass.z": 20.0, "volume": 0.0125,
      "CdA": 0.05, "CdA.z": 0.1, "CdA.y": 3.0}, 50.0, 25.0, 0.0125, 0.15),
])
def test_sinking_in_still_water_follows_the_closed_form_at_fourth_order(make_unit, towfish_fmu, parameters,
                                                                        m, ma, V, cda):
    errors = []  # (depth, velocity) at substeps 0.1, 0.05 and 0.01 s
    for substep in (0.1, 0.05, 0.01):
        r = sink(make_unit, towfish_fmu, substep, **parameters)
        z, v, vt = closed_form(r[:, 0], m, ma, V, cda)
        errors.append((np.max(np.abs(r[:, 1] - z)), np.max(np.abs(r[:, 2] - v))))
        assert abs(r[-1, 2]) < vt  # approaches the terminal velocity from below
    for k in (0, 1):
        assert 13.0 < errors[0][k] / errors[1][k] < 19.0, errors  # 4th order: 16
    for k in (0, 1):  # and on down to 0.01 s (a factor 5^4 = 625 below 0.05 s; 2 for the asymptotics)
        assert errors[2][k] < 2.0 * errors[1][k] / 625.0, errors
    assert abs(r[-1, 2]) > 0.9 * vt  # the run reaches near the terminal velocity


def test_the_cable_force_and_the_current_act_as_declared(make_unit, towfish_fmu):
    """Held still by a current of 1 m/s along x: the body's steady state needs the cable to take its drag,
    weight in water and depressor lift: with that cable force it does not move (to round-off)."""
    CdA, CLA, m, V, u = 0.4, 0.2, 300.0, 0.05, 1.0
    drag = 0.5 * RHO * CdA * u * u
    lift = 0.5 * RHO * CLA * u * u
    W = (m - RHO * V) * G
    body = make_unit(towfish_fmu, parameters={"mass": m, "volume": V, "CdA": CdA, "CLA": CLA},
                     instance_name="held")
    body.initialize(0.0, inputs={"current.x": u, "cableForce.x": -drag, "cableForce.z": W + lift})
    for k in range(10):
        body.do_step(0.5, 0.5 * k)
    assert np.max(np.abs(body.get_reals(["position.x", "position.y", "position.z"]))) < 1e-9
    assert np.max(np.abs(body.get_reals(["velocity.x", "velocity.y", "velocity.z"]))) < 1e-9


def test_a_restored_state_repeats_the_step_bit_for_bit(make_unit, towfish_fmu):
    body = make_unit(towfish_fmu, parameters={"velocity0.x": 1.0}, instance_name="state")
    body.initialize(0.0, inputs={"cableForce.x": 100.0})
    body.do_step(0.5, 0.0)
    state = body.get_state()
    data = body.serialize_state(state)
    body.do_step(0.5, 0.5)
    first = body.get_reals(["position.x", "position.z", "velocity.x", "velocity.z"])
    copy = body.deserialize_state(data)
    body.set_state(copy, 0.5)
    body.free_state(copy)
    body.set({"cableForce.x": 100.0})
    body.do_step(0.5, 0.5)
    assert np.array_equal(body.get_reals(["position.x", "position.z", "velocity.x", "velocity.z"]), first)
    body.set_state(state, 0.5)
    body.set({"cableForce.x": 200.0})
    body.do_step(0.5, 0.5)
    assert body.get_reals(["velocity.x"])[0] > first[2]
    body.free_state(state)
