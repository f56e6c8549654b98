"""Mooring lines through the FMU: the chain on the seabed against the elastic catenary with touchdown
(studies.references.exact.TouchdownCatenary) and MoorPy, the surging fairlead, impossible geometry, the current
profile against an independent steady ODE, and the external far end (bottomEnd 3)."""

import math

import numpy as np
import pytest
from ucable.fmu import FMICallException

from studies.cases import mooring as m
from ucable.fmu import CableFMU


# ------------------------------------------------------------------ 1. catenary with touchdown
def test_closed_form_is_consistent():
    # The closed form's own checks: the fairlead lands where asked, the lifted-off branch takes
    # over continuously (a slack reference would make every comparison below meaningless).
    c = m.closed_form()
    x, z = c.position(m.CHAIN["length"])
    assert abs(x - (-m.ANCHOR_X)) < 1e-9 and abs(z - (m.FAIRLEAD_Z + m.DEPTH)) < 1e-9
    assert 0.0 < c.grounded < m.CHAIN["length"]


@pytest.mark.parametrize("n", [10, 20, 40])
def test_touchdown_catenary(fmu_file, n):
    # With a node at the touchdown (the mesh graded by the static profile) the hanging elements hold
    # a smooth catenary and the grounded ones lie straight, so the fairlead tension is as exact as a
    # suspended line's (bound 1e-4). The touchdown point is then set by the contact model: the chain
    # sinks w/k = 1 mm and the contact is smoothed over 4 mm, and the catenary rising z = sigma^2 / 2a
    # (a = H / w, about 300 m) past the half-diameter height that defines the touchdown moves by
    # a dz / sigma = 0.3 m = 3.5e-4 L for 5 mm of height; on 10 elements of 90 m the output's
    # sampling of the rising part adds to that (bound 1.5e-3 L).
    r = m.catenary_comparison(fmu_file, n)
    assert abs(r["tension_rel"]) < 1e-4
    assert abs(r["H_rel"]) < 1e-4
    assert abs(r["grounded_rel"]) < (1.5e-3 if n == 10 else 3.5e-4)
    # Shape: the 21 stations against the exact material points, within the contact's smoothing
    # band (4 mm) from 20 elements on; 10 elements of 90 m hold the catenary's curvature near the
    # touchdown to a few cm (bound 0.1 m, 1e-4 of the line)
    assert r["shape_error"] < (0.1 if n == 10 else 0.004)
    # the grounded chain rests on the seabed: penetration w/k ~ 1 mm (+ smoothing over 5 % of d)
    assert -0.01 < r["clearance"] < 0.0


# ------------------------------------------------------------------ 2. MoorPy
def test_moorpy_second_opinion(fmu_file):
    pytest.importorskip("moorpy")
    ref = m.moorpy_catenary()
    exact = m.closed_form()
    # two closed forms of the same problem: agree to their solver tolerances
    assert abs(ref["fairlead_tension"] / exact.fairlead_tension - 1) < 1e-6
    assert abs(ref["grounded"] - exact.grounded) < 1e-4 * m.CHAIN["length"]
    r = m.catenary_comparison(fmu_file, 40)
    # the same bounds as against the closed form: 0.1 % tension, 0.5 % L grounded
    assert abs(r["tension"] / ref["fairlead_tension"] - 1) < 1e-3
    # MoorPy's grounded length ends at the tangent point; the FMU's where the line rises half a
    # diameter above the seabed, which the catenary reaches a few metres further up
    rise = m.grounded_within(exact, 0.5 * m.CHAIN["diameter"]) - exact.grounded
    assert abs(r["grounded"] - (ref["grounded"] + rise)) < 5e-3 * m.CHAIN["length"]


# ------------------------------------------------------------------ 3. surging fairlead
def test_surge_follows_the_fairlead_short(fmu_file):
    # CI version: 30 s with 20 elements. With tow.vx and der(tow.vx) the FMU extrapolates the
    # inputs to the end of the step with position, velocity and acceleration (README: tow point
    # motion), so it misses the sine by the jerk term A w^3 h^3 / 6 = 2.07e-4 m at h = 0.1 s; the
    # next term is smaller by w h / 4 = 0.16, hence the factor 1.2.
    step, n = 0.1, 300
    w = 2 * math.pi / m.SURGE_PERIOD
    with CableFMU(fmu_file, parameters=m.chain_params(20)) as c:
        c.initialize(0.0, n * step, inputs=m.surge_inputs(0.0))
        worst, T = 0.0, []
        for k in range(n):
            t = k * step
            c.set(m.surge_inputs(t))
            c.set_input_derivatives(["tow.vx"], 1, [m.surge_acceleration(t)])
            c.do_step(step, t=t)
            worst = max(worst, abs(c.get("shape.x[1]") - m.SURGE_AMPLITUDE * math.sin(w * (t + step))))
            T.append(c.get("towTension"))
        end = c.get_reals(["endPosition.x", "endPosition.z"])
    assert worst < 1.2 * m.SURGE_AMPLITUDE * (w * step) ** 3 / 6
    # the anchor stays put, on the seabed at the height the chain rests at: k g(p) = w with the
    # contact ramp over delta = 5 % of d, at most w/k + delta / 2 = 1.1 + 1.9 mm into it
    assert abs(end[0] - m.ANCHOR_X) < 1e-9 and 0.0 <= -m.DEPTH - end[1] < 3e-3
    # the tension swings around the static value (quasi-static range 1.34..1.85 MN at -5..+5 m)
    T = np.array(T[100:])
    assert T.max() > m.closed_form(5.0).fairlead_tension * 0.98
    assert T.min() < m.closed_form(-5.0).fairlead_tension


@pytest.mark.slow
@pytest.mark.xfail(strict=True, reason=(
    "measured (20 elements, Cdn 2.4, Cdt 0.2, seabedStiffness 1e6, 0.1 s steps): dynamic mean fairlead tension over "
    "100-300 s 1.6161 MN, quasi-static cycle mean 1.5816 MN (closed form at 40 phases; FMU statics "
    "1.5816 MN), +2.2 % > the 0.5 % bound: the nearly taut chain nearly lifts off its anchor at "
    "+5 m (grounded 1.6 m), the fairlead tension falls to 8 kN (snap), and drag plus the convex tension-offset curve raise the dynamic mean. "
    "Physics, not numerics (docs/mooring_dynamic_mean.md): MoorDyn gives +2.7..+3.15 % at 20..320 segments, our "
    "tension-only law +2.99..+3.12 %; slow surges (T >= 50 s) are within 0.11 % in both codes; the criterion "
    "needs restating"))
def test_surge_mean_tension_is_quasi_static(fmu_file):
    r = m.surge_run(fmu_file, 300.0)
    dyn = r["tension"][r["t"] >= 100.0].mean()
    qs = m.quasi_static_mean(40)
    assert abs(dyn / qs - 1) < 5e-3  # the 0.5 % criterion


# ------------------------------------------------------------------ 4. impossible input
@pytest.mark.parametrize("params, inputs, names", [
    ({"anchor.x": -1000.0}, {}, ("anchor.x", "reach")),            # 1000 m > 1.1 x 900 m
    ({}, {"tow.z": -330.0}, ("tow.z", "seabed")),                   # fairlead 10 m under the seabed
    ({"waterDepth": -10.0}, {}, ("waterDepth",)),
])
def test_impossible_mooring_is_an_error(fmu_file, params, inputs, names):
    c = CableFMU(fmu_file, parameters=m.chain_params(20, **params))
    try:
        with pytest.raises(FMICallException):
            c.initialize(inputs={"tow.z": m.FAIRLEAD_Z, **inputs})
        errors = [text for status, _, text in c.messages if status == "ERROR"]
        assert errors, c.log_text()
        for name in names:
            assert any(name in text for text in errors), c.log_text()
    finally:
        c.free()


# ------------------------------------------------------------------ 5. current profile
def test_sheared_current_matches_steady_ode(fmu_file):
    # The cable hangs with a 2 kN end weight in 0.1 m/s uniform + a profile from (0.5, 0) m/s at
    # the surface to (0, 0.2) m/s at 250 m, constant below: a 3-D shape (~15 m x, ~10 m y offset).
    # The profile's kink at 250 m makes the curvature jump, so convergence is ~h^2: measured shape
    # errors 2.9 / 1.2 / 0.25 mm at 10 / 20 / 40 elements, top tension 2e-7 / 8e-8 / 2e-8.
    # Bounds at 20 elements: h^2 from the 10-element value (2.9 mm / 4) with a 4x margin: 3 mm
    # (1e-5 of the 300 m line); tension 1e-5.
    r = m.hanging_comparison(fmu_file, 20)
    assert r["shape_error"] < 3e-3
    assert abs(r["top_tension_rel"]) < 1e-5
    # the shear matters: without the profile the end would be 20 m elsewhere
    assert abs(r["end_offset_ref"][1]) > 5.0


def test_profile_rows_zero_is_the_uniform_case_bit_for_bit(fmu_file):
    # currentProfileRows = 0 must ignore the rows entirely (values set, not used): identical
    # bits over a short dynamic run with a time-varying uniform current.
    def run(extra):
        p = dict(m.HANG, **extra)
        out = []
        with CableFMU(fmu_file, parameters=p) as c:
            c.initialize(inputs={"endLoad.z": m.HANG_END_LOAD, "current.x": 0.1})
            for k in range(20):
                c.set({"current.x": 0.1 + 0.05 * math.sin(0.5 * k), "current.y": 0.02 * k})
                c.do_step(0.5)
                out.append(c.get_reals(["towTension", "shape.x[21]", "shape.y[21]", "shape.z[21]",
                                        "solver.nSteps"]))
        return np.array(out)

    rows = {k: v for k, v in m.SHEAR.items() if k != "currentProfileRows"}
    a = run({})
    b = run({**rows, "currentProfileRows": 0})
    assert np.array_equal(a, b)
    assert not np.array_equal(a, run(m.SHEAR))  # and the rows do act when switched on


# ------------------------------------------------------------------ 6. external far end
def resting_anchor_z(fmu_file) -> float:
    """Where the anchored chain's anchor sits: on the seabed at the height the chain rests at."""
    with CableFMU(fmu_file, parameters=m.chain_params(20)) as c:
        c.initialize(inputs={"tow.z": m.FAIRLEAD_Z})
        return c.get("endPosition.z")


def test_external_end_at_the_anchor_equals_the_anchored_line(fmu_file):
    # bottomEnd 3 with end.* held at the anchor solves the same equations as bottomEnd 1.
    # Statics: the same equilibrium to round-off (both start from the line's static profile on the
    # same graded mesh: 1e-9 relative on MN forces and 835 m positions). Dynamics (0.5 m
    # surge from rest, 10 s): IDA takes another step sequence, so they agree to the integration
    # tolerance, not round-off: each run's tension within tensionTolerance x solver.tensionScale of
    # the exact one (docs/error_control.md; 1e-3 x 1.1 MN at the defaults), so within twice that of
    # each other; positions within 1e-4 m (the position tolerance is 1 mm). The 5 m surge of the
    # scene snaps the chain (minTension < 0, see the report), where the two paths diverge by %.
    # the anchor force of a line without bending stiffness is reported along its tangent (the line
    # cannot pull otherwise; docs/model.md), the external body's as the element's reaction: they
    # share their size, endTension, to second order in the reaction's small transverse part
    names = ["towTension", "towForce.x", "towForce.z", "endTension", "minTension"]
    where = ["shape.x[11]", "shape.z[11]", "shape.x[5]", "shape.z[5]"]
    w, A = 2 * math.pi / m.SURGE_PERIOD, 0.5

    def surge_from_rest(t):
        return {"tow.x": -A * math.cos(w * t), "tow.vx": w * A * math.sin(w * t), "tow.z": m.FAIRLEAD_Z}

    def run(extra, inputs):
        out = []
        with CableFMU(fmu_file, parameters=m.chain_params(20, **extra)) as c:
            c.initialize(0.0, 10.0, inputs={**surge_from_rest(0.0), **inputs})
            statics = c.get_reals(names + where)
            scale = c.get("solver.tensionScale")
            for k in range(50):
                t = 0.2 * k
                c.set(surge_from_rest(t))
                c.set_input_derivatives(["tow.vx"], 1, [w * w * A * math.cos(w * t)])
                c.do_step(0.2, t=t)
                out.append(c.get_reals(names + where))
        return statics, np.array(out), scale

    s1, anchored, scale = run({}, {})
    s3, external, _ = run({"bottomEnd": 3}, {"end.x": m.ANCHOR_X, "end.y": 0.0, "end.z": resting_anchor_z(fmu_file)})
    np.testing.assert_allclose(np.delete(s3, 3), np.delete(s1, 3), rtol=1e-9, atol=1e-6)
    # the projection shortens the reaction by (transverse / tension)^2 / 2: 385 N of 1.3 MN, 5e-8
    assert s3[3] == pytest.approx(s1[3], rel=1e-7)
    k = len(names)
    assert np.max(np.abs(external[:, :k] - anchored[:, :k])) < 2 * 1e-3 * scale
    assert np.max(np.abs(external[:, k:] - anchored[:, k:])) < 1e-4
    assert s1[3] > 0.5e6


def test_external_end_at_rest_with_a_moving_fairlead_initializes_like_the_anchor(fmu_file):
    names = ["towTension", "towForce.x", "towForce.z", "endTension"]
    out = []
    anchor_z = resting_anchor_z(fmu_file)
    for extra, inputs in (({}, {}), ({"bottomEnd": 3}, {"end.x": m.ANCHOR_X, "end.z": anchor_z})):
        with CableFMU(fmu_file, parameters=m.chain_params(20, **extra)) as c:
            c.initialize(inputs={**m.surge_inputs(0.0), **inputs})
            out.append(c.get_reals(names))
    # the same equations and initial state: round-off (1e-9 relative on MN forces); the anchor's
    # force projected on the tangent to second order in its 3e-4 transverse part (5e-8)
    assert np.max(np.abs(out[1][:3] - out[0][:3])) < 1e-9 * np.max(np.abs(out[0]))
    assert out[1][3] == pytest.approx(out[0][3], rel=1e-7)
