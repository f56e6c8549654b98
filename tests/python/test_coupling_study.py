"""The stability analysis of the far-end coupling (studies.cosim.coupling_study, docs/cosimulation.md): the
model problem's amplification factors have the known limits, the implicit far end's model is stable at
every step and mass, and the explicit coupling's model predicts the measured limit of the FMUs.
"""

import numpy as np
import pytest

from studies.cosim import coupling_study as C
from ucable import system as S
from ucable.fmu import FMICallException


@pytest.mark.parametrize("ordering", S.ORDERINGS)
def test_added_mass_instability_at_any_step(ordering):
    """A body lighter than the cable end's inertia (mu = m_e / M > 1) amplifies at every step: under
    Gauss-Seidel rho -> mu for h -> 0 (a_{k+1} = -mu a_k); lighter ends are stable at small steps."""
    for Omega in (1e-3, 1e-2, 1e-1):
        assert C.stability_point(Omega, 1.5, ordering) > 1.0 + 1e-3
        assert C.stability_point(Omega, 0.5, ordering) <= 1.0 + 1e-4
    assert C.stability_point(1e-4, 1.5, "gauss-seidel") == pytest.approx(1.5, rel=1e-3)


def test_explicit_spring_coupling_is_stable_up_to_h_omega_one():
    """Without inertia and damping at the end, Gauss-Seidel exchange of a spring is stable up to
    h omega = 1.00 and not beyond (the classic explicit limit of a lagged spring)."""
    assert C.stability_point(0.99, 0.0, "gauss-seidel") <= 1.0 + 1e-12
    assert C.stability_point(1.02, 0.0, "gauss-seidel") > 1.0


def test_implicit_far_end_model_is_stable_at_every_step_and_mass():
    """The body's mass inside the implicit step, its drag linearized exactly: the one-step map is the
    exact solution of a damped system, rho < 1 (and the lagged drag of a partner without the
    linearization is stable too on the Hopland cable, which the lagged force drives together with the body)."""
    chain = C.Chain.hopland()
    for m in C.MASSES:
        b = S.Body(m).resolved()
        M, cp = b.mass + b.added_mass, C.drag_damping(b, 2.4 * S.KNOT)
        for h in C.STEPS:
            for ordering in S.ORDERINGS:
                assert C.stability_new(h, M, chain, cp, cp, ordering) < 1.0
                assert C.stability_new(h, M, chain, cp, 0.0, ordering) < 1.0


def test_chain_model_predicts_the_measured_limit_of_the_explicit_coupling(fmu_file):
    """400 kg body (500 kg with added mass), Gauss-Seidel: the model's critical step is 0.039 s. The
    three FMUs with the explicit far end, in the steady tow and the start of the turn (first 30 s): at 0.02 s
    they hold the internal body's equilibrium to within the integrator's tension tolerance (the
    default tensionTolerance, 1e-3 of the tension scale, here the initial tow tension), at 0.05 s
    round-off grows into tens of kN within 60 s, as the model says. How soon depends on the round-off
    that seeds it (any change of the cable's arithmetic moves it by seconds), so the unstable run is given
    twice the stable one's time."""
    h_crit = C.critical_step(500.0, C.Chain.hopland(), "gauss-seidel")
    assert 0.02 < h_crit < 0.05
    for h, stable, duration in ((0.02, True, 30.0), (0.05, False, 60.0)):
        internal = S.run("turn90", step=h, coupling="internal", body=S.Body(400.0), duration=duration)
        try:
            explicit = S.run("turn90", step=h, coupling="explicit", body=S.Body(400.0), duration=duration)
            error = np.max(np.abs(explicit["cable.towTension"] - internal["cable.towTension"]))
        except (S.Diverged, FMICallException):
            error = np.inf
        tolerance = 1e-3 * internal["cable.towTension"][0]
        assert (error < tolerance) if stable else (error > 1e3), (h, error, tolerance)


def test_the_converged_report_names_the_worse_manoeuvre_and_marks_the_bound():
    """--converged's report: each cell the worse manoeuvre's distance, bold beyond 0.2 m, the summary
    counting the runs within it (the vessel's held force apart from the linear one)."""
    cells = []
    for man, scale in (("accelerate", 0.1), ("turn90", 1.0)):
        for ordering in S.ORDERINGS:
            for coupling, force, d in (("internal", "held", 0.33), ("internal", "linear", 0.012),
                                       ("external", "linear", 0.013), ("proxy", "linear", 0.11)):
                cells.append(dict(manoeuvre=man, mass=4000.0, step=1.0, ordering=ordering, coupling=coupling,
                                  vessel_force=force, position_max=scale * d, tension_rms=scale * 1e-3, cpu=0.1))
    text = C.markdown_converged({"steps": [1.0], "masses": [4000.0], "manoeuvres": ["accelerate", "turn90"],
                                 "cells": cells})
    assert text.startswith(C.BEGIN_CONVERGED) and text.endswith(C.END_CONVERGED)
    row = "| 4000 kg | **0.33 m** | 0.012 m | 0.013 m | 0.11 m |"
    assert text.count(row) == 2  # both orderings, the turn's (worse) distances
    assert "12 of 12 runs within 0.2 m; the farthest 0.11 m (turn90, 4000 kg, 1 s, gauss-seidel, proxy)" in text
    assert "Force held: 2 of 4 within; the farthest 0.33 m (turn90" in text
