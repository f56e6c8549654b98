"""Elastic catenary (Irvine, studies.references.exact.ElasticCatenary) and steady tows (ucable.steady_tow)
against the FMU's initial equilibrium. The seabed touchdown case is in test_mooring.py.
"""

import math

import pytest

from studies.cases.validation import catenary, convergence_rate, steady_tow, towed_body_parameters


def test_anchored_line_hangs_as_irvines_elastic_catenary(fmu_file):
    # Measured convergence ~h^4 (shape 4.1e-6 L at N = 10, 1.3e-7 L at N = 20, 5e-9 at N = 40;
    # end tensions 3-5e-6 at 10, 2-3e-7 at 20). Bounds at N = 20: h^4 from the 10-element value
    # (4e-6 / 16 = 2.6e-7) with a 4x margin: 1e-6.
    r = catenary(fmu_file, 20)
    assert r["shape_error"] <= 1e-6
    for key in ("top_tension_rel", "bottom_tension_rel", "H_rel", "station_tension_rel"):
        assert abs(r[key]) <= 1e-6, key


def test_catenary_converges_at_fourth_order(fmu_file):
    n = [5, 10, 20]
    rate = convergence_rate(n, [catenary(fmu_file, k)["shape_error"] for k in n])
    assert rate >= 3.5  # cubic Hermite positions: h^4 (measured 4.3)


@pytest.mark.parametrize("knots", [1.1, 2.4, 3.5])
def test_free_end_tow_is_exact(fmu_file, knots):
    # The exact steady shape is a straight line with linear tension, in the element space: the
    # only error is the statics' stopping test (residual at the round-off of the axial forces,
    # 64 EA eps (1 + |X| / l) ~ 2e-5 N, 4e-9 of the tension). Measured <= 2e-12.
    r = steady_tow(fmu_file, knots, 10)
    assert abs(r["tension_rel"]) <= 1e-8
    assert abs(r["angle_error_deg"]) <= 1e-6
    assert abs(r["depth_error"]) <= 1e-8


@pytest.mark.parametrize("knots", [1.1, 2.4, 3.5])
def test_towed_body_matches_steady_ode(fmu_file, knots):
    # Curved shape: discretization error h^4, then a floor of a few 1e-6 in tension set by
    # O(T/EA) = 1.4e-4 modelling choices the ODE and the FMU make differently at the end body.
    # Measured at N = 20: tension 0.2e-6 .. 5.6e-6, angle <= 1.8e-4 deg, depth <= 1.5e-6 L.
    r = steady_tow(fmu_file, knots, 20, towed_body_parameters())
    assert abs(r["tension_rel"]) <= 5e-5
    assert abs(r["angle_error_deg"]) <= 2e-3
    assert abs(r["depth_error"]) <= 1e-5
