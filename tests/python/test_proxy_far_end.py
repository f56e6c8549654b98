"""The proxy far end (bottomEnd 4, docs/cosimulation.md): a towed body that integrates its own
translation (the plain causal interface: cable force in, position and velocity out; the third party's
Towfish FMU and the TowedBody FMU with integrateTranslation) coupled behind the Vessel FMU by a master
that does not iterate.

Acceptance: with the body's (m + m_a) given exactly, within 1 % RMS tow tension and 0.2 m body position
of the internal body (bottomEnd 2, the same numbers, the same step and ordering), Hopland acceleration
and a 90 deg turn, 50 kg and 2 t, 0.1 and 0.5 s, Gauss-Seidel and Jacobi. The model problem's stability
(studies.cosim.proxy_study.stability_proxy) is checked against its limits.
"""

import math

import numpy as np
import pytest

from studies.cosim import proxy_study as P
from studies.cosim.coupling_study import POSITION_BOUND, TENSION_BOUND, Chain
from ucable import system as S


@pytest.mark.parametrize("body", ["towfish", "towedbody"])
@pytest.mark.parametrize("manoeuvre", P.MANOEUVRES)
@pytest.mark.parametrize("ordering", S.ORDERINGS)
@pytest.mark.parametrize("step", [0.1, 0.5])
@pytest.mark.parametrize("mass", [50.0, 2000.0])
def test_self_integrating_body_follows_the_internal_body(fmu_file, towfish_fmu, body, manoeuvre, ordering, step,
                                                         mass):
    """The third party's Towfish (built outside the project's CMake) and the project's TowedBody with
    integrateTranslation, each through the proxy far end."""
    cell, _ = P.run_pair(manoeuvre, step, ordering, mass, body_fmu=towfish_fmu if body == "towfish" else None)
    assert cell.status != "diverged" and cell.status != "fmi2Error", cell.note
    assert cell.tension_rms <= TENSION_BOUND
    assert cell.position_max <= POSITION_BOUND


def test_libcosim_runs_the_proxy_system_like_the_fmpy_jacobi_master(fmu_file):
    """libcosim's fixed-step algorithm calls what the fmpy Jacobi master without input derivatives
    calls: bit-identical results, the body's own state included."""
    pytest.importorskip("libcosimpy")
    lc = S.run("turn90", 0.5, "proxy", "libcosim", "jacobi", S.Body(400.0), duration=60.0)
    fj = S.run("turn90", 0.5, "proxy", "fmpy", "jacobi", S.Body(400.0), duration=60.0, input_derivatives=False)
    for key in lc.values:
        assert np.array_equal(lc[key], fj[key]), key


def test_the_proxy_system_file_starts_at_the_steady_far_end(fmu_file):
    """The start values of the shipped proxy system are the steady far end of its body (to the 1e-9 m
    of the file's digits), for the body and for the cable's end inputs."""
    system = S.load_named_system("towed_body_proxy")
    body, cable = system.simulators["body"].initial, system.simulators["cable"].initial
    b = S.Body(body["mass"], body["addedMass"], body["volume"], body["CdA"])
    start = S.steady_far_end(system, {"vessel": system.simulators["vessel"].initial}, b)
    pairs = [(f"end.{q}", f"position0.{q}") for q in "xyz"] + [(f"end.v{q}", f"velocity0.{q}") for q in "xyz"]
    for cable_input, body_start in pairs:
        assert (body[body_start], cable[cable_input]) == pytest.approx((start[body_start],) * 2, abs=1e-9)


def test_the_estimate_learns_the_bodys_drag_and_weight(fmu_file):
    """After the Hopland acceleration the proxy's estimate of the body's other forces equals the force
    the body reports (its drag and submerged weight at its velocity): the estimate is what the cable
    force alone does not explain. 0.1 % of that force: the body's velocity follows the proxy's to the
    cable integrator's tolerance and the estimate's last transient has decayed (660 s)."""
    r = S.run("accelerate", 0.5, "proxy", "fmpy", "gauss-seidel", S.Body(400.0))
    estimate = np.array([r[f"cable.bodyForceEstimate.{q}"][-1] for q in "xyz"])
    b = S.Body(400.0).resolved()
    weight = np.array([0.0, 0.0, -(b.mass - 1025.0 * b.volume) * 9.81])
    reported = np.array([r[f"body.force.{q}"][-1] for q in "xyz"]) + weight
    assert np.linalg.norm(estimate - reported) <= 1e-3 * np.linalg.norm(reported)


def test_restored_state_continues_bit_identically(fmu_file):
    """fmi2GetFMUstate / fmi2SetFMUstate with the proxy's estimate in the state: a run restored in the
    middle of the turn continues exactly as the original."""
    from ucable.fmu import CableFMU
    from ucable.paths import fmu_path

    params = {"bottomEnd": 4, "body.mass": 400.0, "body.addedMass": 100.0, "body.volume": 0.1}
    v = 2.4 * S.KNOT

    def inputs(k):  # a body that wanders about its steady place
        return {"tow.x": v * 0.5 * k, "tow.vx": v, "end.x": -200.0 + v * 0.5 * k + 0.01 * math.sin(k),
                "end.z": -150.0, "end.vx": v, "end.vy": 0.05 * math.sin(k)}

    a = CableFMU(fmu_path(), parameters=params, instance_name="a")
    b = CableFMU(fmu_path(), parameters=params, instance_name="b")
    try:
        for f in (a, b):
            f.initialize(0.0, inputs=inputs(0))
        for k in range(6):
            a.set(inputs(k))
            a.slave.doStep(0.5 * k, 0.5)
        state = a.slave.getFMUstate()
        for k in range(6, 9):
            b.set(inputs(k - 6))
            b.slave.doStep(0.5 * (k - 6), 0.5)
        b.slave.setFMUstate(state)
        names = [f"endForce.{q}" for q in "xyz"] + [f"bodyForceEstimate.{q}" for q in "xyz"] + ["towTension"]
        assert np.array_equal(a.get_reals(names), b.get_reals(names))
        for k in range(6, 12):
            for f in (a, b):
                f.set(inputs(k))
                f.slave.doStep(0.5 * k, 0.5)
        assert np.array_equal(a.get_reals(names), b.get_reals(names))
        a.slave.freeFMUstate(state)
    finally:
        a.free()
        b.free()


@pytest.mark.parametrize("ordering", S.ORDERINGS)
def test_model_problem_is_stable_with_inertia_errors_of_fifty_percent(ordering):
    """The gains of the defaults keep the model problem's amplification factor below 1 with the proxy's
    inertia 50 % off either way, without drag (the least damped case), from 0.01 to 1 s."""
    chain = Chain.hopland()
    for mass in (50.0, 2000.0):
        for err in (-0.5, 0.5):
            for h in (0.01, 0.1, 1.0):
                assert P.stability_proxy(h, 1.25 * mass, chain, 0.0, ordering, err, 0.0) < 1.0


def test_model_problem_needs_the_estimates_low_pass_under_jacobi():
    """The estimate's low-pass over five steps is what keeps Jacobi stable: over one step, a heavy body
    without drag amplifies (the body feels the proxy's force a step late and the estimate feeds that
    lag back into the proxy)."""
    chain = Chain.hopland()
    assert P.stability_proxy(0.5, 2500.0, chain, 0.0, "jacobi", 0.0, 0.0) < 1.0
    assert P.stability_proxy(0.5, 2500.0, chain, 0.0, "jacobi", 0.0, 0.0, tau=0.5) > 1.0


@pytest.mark.slow
def test_study_writes_its_tables(fmu_file, tmp_path):
    """The report generator end to end on a small grid: the tables of the section and the figure."""
    data = P.compute(steps=[0.5], masses=[400.0], manoeuvres=["turn90"], errors=[0.1], sensitivity_masses=[400.0])
    figure = tmp_path / "proxy.png"
    P.plot(data, figure)
    text = P.markdown(data, figure.name)
    assert figure.stat().st_size > 0
    assert "| 400 kg |" in text and "+10 %" in text
    assert "| **" not in text.split("**Inertia error**")[0]  # no cell outside the bounds
