"""Small-amplitude dynamics (natural frequencies of a taut string and a beam-string) and time
convergence of the Hopland manoeuvre, through the FMU."""

import numpy as np
import pytest

from ucable.validation import VIB_EI, free_vibration, hopland_tension

# Issue 3: within 0.5 % of the analytic first three modes. Spatial error of 10 cubic elements on
# mode 3 is below 1e-4 (measured: N = 10 and N = 20 give the same frequencies to 2e-4), the
# integrator (relTol 1e-8) adds less, so 0.5 % is a generous bound.
FREQ_TOL = 0.005

FREQ_XFAIL = pytest.mark.xfail(
    strict=True,
    reason="FMU frequencies depend on the communication step with constant inputs: string "
           "+0.31 % (h = 0.01 s), +0.33 % (0.02 s), +0.72 % (0.05 s) for modes 1-3, the same with "
           "N = 10 or 20 and relTol 1e-8 or 1e-10; beam-string +0.30 % at 0.05 s (reported to the lead)")


@pytest.mark.parametrize("EI", [pytest.param(0.0, marks=FREQ_XFAIL, id="string"),
                                # passes at +0.30 %, but that is the same unexplained offset
                                pytest.param(VIB_EI, id="beam-string")])
def test_free_vibration_frequencies_match_analytic_first_three_modes(fmu_file, EI):
    r = free_vibration(fmu_file, EI, 10, step=0.05)
    assert np.all(np.abs(r["rel_error"]) <= FREQ_TOL), r["rel_error"]


@FREQ_XFAIL
@pytest.mark.slow
def test_frequencies_do_not_depend_on_the_communication_step(fmu_file):
    # Constant inputs after the pulse: the free vibration must not know the master's step. The
    # fitted frequency resolves 1e-5; allow 1e-3 (a fifth of the accuracy bound).
    a = free_vibration(fmu_file, 0.0, 10, step=0.05)["fitted"]
    b = free_vibration(fmu_file, 0.0, 10, step=0.02)["fitted"]
    assert np.all(np.abs(a / b - 1) <= 1e-3), a / b - 1


@pytest.mark.slow
def test_hopland_tension_converges_with_the_integrator_tolerance(fmu_file):
    # Reference relTol = absTol = 1e-10. The lead measured (C++) 2.7e-4 of the tension range at the
    # default 1e-8/1e-6 and 7e-5 at 1e-9/1e-7; BDF global error ~ tolerance, so one decade of
    # tolerance must buy at least a factor 2 and the default must stay within 1e-3 of the range.
    ref = hopland_tension(fmu_file, 1e-10, 1e-10)
    span = np.ptp(ref["tension"])
    err = {}
    for rel, abs_ in [(1e-8, 1e-6), (1e-9, 1e-7)]:
        run = hopland_tension(fmu_file, rel, abs_)
        err[rel] = np.max(np.abs(run["tension"] - ref["tension"])) / span
    assert err[1e-8] <= 1e-3
    assert err[1e-9] <= err[1e-8] / 2
