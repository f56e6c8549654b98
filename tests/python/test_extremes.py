"""The Gumbel fit of realisation maxima (ucable.extremes, docs/design_checks.md) on synthetic samples of a
known Gumbel law, with a fixed RNG seed: the parameters' bias within what sampling theory allows, the
confidence interval of the MPM covering the true MPM as often as its level says, the duration scaling."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ucable.extremes import (fit_maxima, fit_mle, fit_moments, gumbel_sample, mpm, plot_gumbel,
                             reduced_variate)

MU, BETA = 1.0e6, 8.0e4  # a line's maxima [N]


@pytest.mark.parametrize("fit, var_mu, var_beta", [(fit_mle, 1.1087, 0.6079), (fit_moments, 1.1678, 1.1000)])
def test_parameters_are_unbiased_within_sampling_error(fit, var_mu, var_beta):
    """M fits of N maxima: the mean estimate within 3 standard errors of the truth plus the O(1/N) small-sample
    bias, beta / N. Asymptotic variances per beta^2 / N: maximum likelihood 1.1087 and 0.6079 (the inverse
    Fisher information); moments 1.1000 for beta (the sample SD's variance sigma^2 (kurtosis - 1) / 4N,
    kurtosis 5.4) and 1.1678 for mu (the mean's, beta's and their covariance through the skewness 1.1395)."""
    rng = np.random.default_rng(20251)
    M, N = 400, 200
    mu, beta = fit(gumbel_sample(MU, BETA, (M, N), rng))
    se_mu = BETA * math.sqrt(var_mu / N / M)
    se_beta = BETA * math.sqrt(var_beta / N / M)
    assert abs(np.mean(mu) - MU) < 3.0 * se_mu + BETA / N
    assert abs(np.mean(beta) - BETA) < 3.0 * se_beta + BETA / N
    # and the spread of the estimates is the asymptotic one (within 15 %: 400 fits estimate an SD to 4 %)
    assert np.std(beta) == pytest.approx(BETA * math.sqrt(var_beta / N), rel=0.15)
    assert np.std(mu) == pytest.approx(BETA * math.sqrt(var_mu / N), rel=0.15)


def test_mle_recovers_a_large_sample():
    rng = np.random.default_rng(7)
    x = gumbel_sample(MU, BETA, 200000, rng)
    mu, beta = fit_mle(x)
    # standard errors 1.05 sqrt(1.1087 / n) beta = 190 N, 140 N: 5 of them
    assert abs(float(mu) - MU) < 5 * BETA * math.sqrt(1.1087 / x.size)
    assert abs(float(beta) - BETA) < 5 * BETA * math.sqrt(0.6079 / x.size)


@pytest.mark.parametrize("method, trials", [("moments", 1000), ("mle", 300)])
def test_the_mpm_interval_covers_the_true_mpm_at_its_level(method, trials):
    """Trials of 15 maxima of 600 s realisations, the MPM over a 3 h storm with a 90 % interval: the share
    of intervals holding the true MPM is 0.90 within 3 binomial standard errors (0.028 for 1000 trials, 0.052
    for 300)."""
    rng = np.random.default_rng(42)
    level, T, D = 0.90, 600.0, 10800.0
    truth = mpm(MU, BETA, T, D)
    hits = 0
    for _ in range(trials):
        f = fit_maxima(gumbel_sample(MU, BETA, 15, rng), T, D, method=method, level=level, boots=400, rng=rng)
        hits += f.low <= truth <= f.high
    share = hits / trials
    assert abs(share - level) < 3.0 * math.sqrt(level * (1.0 - level) / trials), share


def test_the_mpm_scales_with_the_log_of_the_duration_ratio():
    """The maximum of D / T independent realisations of Gumbel(mu, beta) maxima is Gumbel(mu + beta ln(D/T),
    beta): checked on the maxima of 18 blocks, their mode (the MPM) estimated from 20000 such storms."""
    rng = np.random.default_rng(3)
    storms = gumbel_sample(MU, BETA, (20000, 18), rng).max(axis=1)
    mu, beta = fit_mle(storms)
    assert float(beta) == pytest.approx(BETA, rel=0.03)
    assert float(mu) == pytest.approx(mpm(MU, BETA, 600.0, 18 * 600.0), abs=3 * BETA * math.sqrt(1.1087 / 20000))
    f = fit_maxima(storms[:50], 600.0, 1200.0, boots=50)
    assert f.mpm == pytest.approx(f.mu + f.beta * math.log(2.0))


def test_fit_refuses_too_few_maxima_and_the_plot_is_drawn(tmp_path):
    with pytest.raises(ValueError, match="needs 3 maxima"):
        fit_maxima([1.0, 2.0], 100.0)
    y = reduced_variate(4)
    assert np.all(np.diff(y) > 0) and y[0] == pytest.approx(-math.log(-math.log(0.56 / 4.12)))
    f = fit_maxima(gumbel_sample(MU, BETA, 10, np.random.default_rng(1)), 600.0, 10800.0, boots=100)
    plot_gumbel({"line 1": f}, tmp_path / "g.png", "synthetic")
    assert (tmp_path / "g.png").stat().st_size > 0
