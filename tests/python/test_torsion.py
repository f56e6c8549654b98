"""Torsion through the FMU: Greenhill, constant torque / twist rate, end moments,
switched-off bit-identity, prescribed rotation, hockling. Scenes in studies.cases.torsion."""

import math

import numpy as np
import pytest

from ucable.fmu import NUM_STATIONS
from studies.cases.torsion import (DEPTH, TENSIONS, critical_torque, greenhill_parameters, run_hockling)


@pytest.mark.parametrize("tension", TENSIONS)
def test_greenhill_threshold_within_1_percent(fmu_file, tension):
    # 7 bisections on [0.8, 1.2] H_cr: bracket 0.31 % wide, midpoint within 0.16 % of the detected
    # threshold; the discretisation (20 elements, >= 6 per helix wavelength) and the finite 60 s
    # observation window shift the threshold by well under the required 1 %.
    ratio = critical_torque(fmu_file, tension, bisections=7)
    print(f"T = {tension} N: H_found / H_cr = {ratio:.4f}")
    assert abs(ratio - 1.0) < 0.01


def _run_straight(make_cable, mode, inputs, GJ=250.0, steps=4, couple=0.0):
    p = greenhill_parameters(100.0)
    p.update({"torqueMode": mode, "GJ": GJ})
    cable = make_cable(parameters=p)
    cable.initialize(0.0, inputs={"tow.z": DEPTH, "endCouple.y": couple, **inputs})
    for _ in range(steps):
        cable.do_step(0.5)
    return cable


def _twist(cable):
    return cable.get_reals([f"twist[{k}]" for k in range(1, NUM_STATIONS + 1)])


@pytest.mark.parametrize("couple", [0.0, 10.0])
def test_prescribed_torque_is_constant_and_equals_GJ_times_twist_rate(make_cable, couple):
    # straight (couple 0) and bent (a held end couple of 10 N.m, curvature ~0.1 /m) cable
    H, GJ, L = 50.0, 250.0, 10.0
    cable = _run_straight(make_cable, 1, {"torque": H}, GJ=GJ, couple=couple)
    assert cable.get("cableTorque") == H  # mode 1 passes the input through exactly
    s = np.linspace(0.0, L, NUM_STATIONS)  # stations equally spaced in unstretched arc length
    twist = _twist(cable)
    slope, offset = np.polyfit(s, twist, 1)
    # twist linear in s with slope H/GJ: round-off only
    assert np.max(np.abs(twist - (slope * s + offset))) < 1e-12
    assert slope == pytest.approx(H / GJ, rel=1e-12)
    assert twist[0] == 0.0


def test_straight_twisted_cable_end_moments_carry_H_along_the_axis(make_cable):
    H = 50.0
    cable = _run_straight(make_cable, 1, {"torque": H})
    tow = cable.get_reals([f"towMoment.{a}" for a in "xyz"])
    end = cable.get_reals([f"endMoment.{a}" for a in "xyz"])
    # straight along +x: no bending moment; the internal moment is M = EI r' x r'' - H t
    # (docs/torsion.md), so the cable acts on the tow point with -H t and on the far end with +H t;
    # the lateral components are round-off (|EI r' x r''| of a straight rod)
    assert tow[0] == pytest.approx(-H, rel=1e-12)
    assert end[0] == pytest.approx(H, rel=1e-12)
    assert np.max(np.abs(tow[1:])) < 1e-9 * H and np.max(np.abs(end[1:])) < 1e-9 * H


def test_prescribed_rotation_on_a_straight_cable(make_cable):
    # mode 2: a straight cable has no geometric twist, H = GJ Phi / L (parallel transport gives
    # exactly 0 for a straight line: no NaN from the 0/0 Frenet torsion)
    GJ, L, phi = 250.0, 10.0, 1.0
    cable = _run_straight(make_cable, 2, {"twist": phi}, GJ=GJ)
    H = cable.get("cableTorque")
    assert math.isfinite(H)
    assert H == pytest.approx(GJ * phi / L, rel=1e-12)
    assert _twist(cable)[-1] == pytest.approx(phi, rel=1e-12)


def _all_outputs(cable):
    names = [v.name for v in cable.model_description.modelVariables
             if v.causality == "output" and v.type == "Real"]
    ints = [v.name for v in cable.model_description.modelVariables
            if v.causality == "output" and v.type == "Integer"]
    return names, cable.get_reals(names), [cable.get(n) for n in ints]


def test_torsion_off_is_bit_identical_to_the_torque_free_model(make_cable):
    def run(extra, torque):
        p = greenhill_parameters(100.0)
        p.update(extra)
        cable = make_cable(parameters=p)
        cable.initialize(0.0, inputs={"tow.z": DEPTH, "endCouple.y": 1e-3, "torque": torque,
                                      "twist": torque / 10})
        cable.set({"tow.vy": 0.01})
        for k in range(10):
            cable.set({"tow.y": 0.01 * 0.5 * k})
            cable.do_step(0.5)
        return _all_outputs(cable)

    # the torque-free model: torsion off, no torque or twist input
    names, ref, ref_int = run({"enableTorsion": False, "torqueMode": 0}, 0.0)
    for extra in ({"enableTorsion": False, "torqueMode": 1},
                  {"enableTorsion": False, "torqueMode": 2},
                  {"enableTorsion": True, "torqueMode": 0}):
        _, out, out_int = run(extra, 50.0)
        diff = [n for n, a, b in zip(names, ref, out) if a != b]
        assert not diff, f"{extra}: outputs differ: {diff[:5]}"
        assert out_int == ref_int, f"{extra}: solver statistics differ (extra cost)"
    # and the torque does act when switched on (the bent rod moves out of plane)
    _, on, _ = run({"enableTorsion": True, "torqueMode": 1}, 50.0)
    assert any(a != b for a, b in zip(ref, on))


def test_hockling_completes_and_the_torque_falls(fmu_file):
    # short version of scripts/hockling: 20 elements, 1.5 m slack in 20 s, 20 s hold
    r = run_hockling(fmu_file, n_elements=20, ramp=20.0, hold=20.0)
    assert np.all(np.isfinite(r.torque)) and np.all(np.isfinite(r.max_lateral))
    assert r.t[-1] == pytest.approx(40.0)
    H0 = 2 * math.pi * 3 * 100.0 / 10.0  # GJ Phi / L of the straight cable
    assert r.torque[0] == pytest.approx(H0, rel=1e-12)
    # the loop's writhe takes up twist: H must fall by more than the 1e-3 relative solver noise;
    # a 1.5 m slack with a 1.28 m out-of-plane loop lowers it by several percent
    assert r.torque[-1] < 0.99 * H0
    assert r.max_lateral.max() > 0.5  # a loop formed (the imperfection alone is ~1e-5 m)
    assert r.tow_tension[-1] < r.tow_tension[0]


def _moment_imbalance(make_cable, H):
    """Moments on the whole cable about the origin after 60 s of a bent (end couple 20 N m), twisted
    rod: -towMoment - endMoment + r(0) x (-towForce) + r(L) x (-endForce); zero up to the accuracy of
    the bending moment recovered at the element ends."""
    p = greenhill_parameters(100.0)
    p["torqueMode"] = 1
    cable = make_cable(instance_name=f"balance{H:g}", parameters=p)
    cable.initialize(inputs={"tow.z": p["anchor.z"], "endCouple.y": 20.0, "torque": H})
    t = 0.0
    for _ in range(60):
        cable.do_step(1.0, t=t)
        t += 1.0
    g = lambda name: cable.get_reals([f"{name}.{a}" for a in "xyz"])
    s = cable.shape()
    r0 = np.array([s["shape.x"][0], s["shape.y"][0], s["shape.z"][0]])
    rL = np.array([s["shape.x"][-1], s["shape.y"][-1], s["shape.z"][-1]])
    return -g("towMoment") - g("endMoment") + np.cross(r0, -g("towForce")) + np.cross(rL, -g("endForce"))


def test_end_moments_balance_the_cable_with_the_torque_sign_of_the_equations(make_cable):
    # The torque part of the end moments must have the sign that the equations of motion imply
    # (M = EI r' x r'' - H t): a wrong sign leaves 2 H t unbalanced (60 N m here). What the torque
    # may add to the imbalance of the untwisted rod (0.87 N m: the bending moment recovered at the
    # element ends) is measured at 0.12 N m; asserted 0.5 N m.
    base = _moment_imbalance(make_cable, 0.0)
    for H in (30.0, -30.0):
        assert np.linalg.norm(_moment_imbalance(make_cable, H) - base) < 0.5, H
