"""The steady references of the winch scenes: the FMU's static initialization of a cable started at
each deployed length (what a paid-out and settled run must match) agrees with the independent
steady-tow ODE (python/ucable/steady_tow.py).

Tolerances: those the winch acceptance uses, 0.5 % in tow tension and 0.5 m in body depth. With a
towed body the steady shape is curved, so the FMU's cubic elements no longer represent it exactly;
the discretization error of 15 m cubic Hermite elements (fourth order in position) on a shape
whose angle changes by less than 40 degrees over the line is far below that, as the measured
differences in docs/winch.md show. A wrong body load (drag or net weight) or a wrong element count
for the length moves the tension by percents.
"""

import numpy as np
import pytest

from studies.references.winch_reference import (DeployBody, elements_for_length, fmu_static_references,
                                    ode_references)

LENGTHS = [50.0, 100.0, 300.0, 600.0]


def test_element_count_keeps_the_nominal_element_length():
    assert elements_for_length(300.0, 15.0) == 20
    assert elements_for_length(50.0, 15.0) == 3
    assert elements_for_length(5.0, 15.0) == 1


def test_ode_references_grow_with_length():
    ref = ode_references(LENGTHS)
    assert np.all(np.diff(ref.tow_tension) > 0)
    assert np.all(np.diff(ref.body_depth) > 0)
    assert np.all(np.diff(ref.layback) > 0)
    # the body hangs below the tow point and the line is shorter than its length in both directions
    assert np.all(ref.body_depth < ref.lengths) and np.all(ref.layback < ref.lengths)


def test_fmu_static_initialization_matches_steady_ode_at_each_length(fmu_file):
    ode = ode_references(LENGTHS)
    fmu = fmu_static_references(fmu_file, LENGTHS)
    for i, L in enumerate(LENGTHS):
        assert fmu.tow_tension[i] == pytest.approx(ode.tow_tension[i], rel=0.005), \
            f"{L} m: tow tension {fmu.tow_tension[i]:.1f} N vs ODE {ode.tow_tension[i]:.1f} N"
        assert fmu.body_depth[i] == pytest.approx(ode.body_depth[i], abs=0.5), \
            f"{L} m: body depth {fmu.body_depth[i]:.2f} m vs ODE {ode.body_depth[i]:.2f} m"
        assert fmu.layback[i] == pytest.approx(ode.layback[i], abs=0.5), \
            f"{L} m: layback {fmu.layback[i]:.2f} m vs ODE {ode.layback[i]:.2f} m"


def test_body_parameters_reach_the_fmu(fmu_file):
    """A heavier body (twice the net weight) must change the FMU reference: the body is really on."""
    light = fmu_static_references(fmu_file, [100.0])
    heavy = fmu_static_references(fmu_file, [100.0], body=DeployBody(mass=605.0))
    assert heavy.tow_tension[0] > light.tow_tension[0] * 1.1


def test_winch_references_command_writes_csv_and_plot(fmu_file, tmp_path, monkeypatch):
    from studies.reports import winch_reference_cli

    monkeypatch.setenv("UC_FMU", str(fmu_file))
    winch_reference_cli.main(["--lengths", "100", "300", "200", "--out", str(tmp_path)])
    data = np.genfromtxt(tmp_path / "references.csv", delimiter=",", names=True)
    assert list(data["length"]) == [100.0, 300.0]
    assert np.allclose(data["towTensionFMU"], data["towTensionODE"], rtol=0.005)
    assert (tmp_path / "references.png").stat().st_size > 0
