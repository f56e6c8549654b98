"""Extreme statistics over realisations of one sea state (docs/design_checks.md, "Extremes over
realisations"): the per-realisation maxima of a line's tension fitted with a Gumbel distribution, the most
probable maximum (MPM) over the storm's duration and its confidence interval.

Gumbel: F(x) = exp(-exp(-(x - mu) / beta)). Fits: the method of moments (beta = s sqrt(6) / pi,
mu = mean - 0.5772 beta) and maximum likelihood (the scale's likelihood equation solved by bisection, the
location then in closed form). Duration: the maxima of realisations of length T are Gumbel(mu, beta); the
maximum over a storm of length D, taken as D / T independent stretches of that sea, is
Gumbel(mu + beta ln(D / T), beta), whose mode, the MPM, is mu + beta ln(D / T). Confidence interval:
a parametric bootstrap of the pivot (q* - q^) / beta* (q the MPM): for a location-scale family it has the
same distribution for every (mu, beta), so the interval's coverage is the nominal one up to the bootstrap's
Monte Carlo error. Computation only; `plot_gumbel` draws the probability paper.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

EULER = 0.5772156649015329
METHODS = ("mle", "moments")


def gumbel_sample(mu: float, beta: float, size, rng: np.random.Generator) -> np.ndarray:
    """Gumbel(mu, beta) variates by inversion."""
    return mu - beta * np.log(-np.log(rng.uniform(size=size)))


def fit_moments(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(mu, beta) by the method of moments along the last axis."""
    x = np.asarray(x, dtype=float)
    beta = np.std(x, axis=-1, ddof=1) * math.sqrt(6.0) / math.pi
    return np.mean(x, axis=-1) - EULER * beta, beta


def fit_mle(x: np.ndarray, iterations: int = 60) -> tuple[np.ndarray, np.ndarray]:
    """(mu, beta) by maximum likelihood along the last axis: beta solves
    beta = mean(x) - sum(x w) / sum(w), w = exp(-x / beta) (one root, bracketed about the moments' beta and
    halved `iterations` times: the relative error is below 2^-50 of the bracket); then
    mu = -beta ln(mean(exp(-x / beta))). Exponents shifted by min(x), so no overflow."""
    x = np.asarray(x, dtype=float)
    lo_x = np.min(x, axis=-1, keepdims=True)
    y = x - lo_x
    mean = np.mean(y, axis=-1)
    _, b0 = fit_moments(x)
    b0 = np.where(b0 > 0.0, b0, 1e-300)

    def g(beta):  # increasing in beta through the root
        w = np.exp(-y / beta[..., None])
        return beta - mean + np.sum(y * w, axis=-1) / np.sum(w, axis=-1)

    lo, hi = b0 * 0.02, b0 * 20.0
    for _ in range(20):  # widen where the root lies outside (a very short tail or a single outlier)
        bad_lo, bad_hi = g(lo) > 0.0, g(hi) < 0.0
        if not (bad_lo.any() or bad_hi.any()):
            break
        lo, hi = np.where(bad_lo, lo / 10.0, lo), np.where(bad_hi, hi * 10.0, hi)
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        up = g(mid) > 0.0
        lo, hi = np.where(up, lo, mid), np.where(up, mid, hi)
    beta = 0.5 * (lo + hi)
    mu = lo_x[..., 0] - beta * np.log(np.mean(np.exp(-y / beta[..., None]), axis=-1))
    return mu, beta


def fit(x: np.ndarray, method: str = "mle") -> tuple[np.ndarray, np.ndarray]:
    if method not in METHODS:
        raise ValueError(f"Gumbel fit {method!r}: one of {', '.join(METHODS)}")
    return fit_mle(x) if method == "mle" else fit_moments(x)


@dataclass
class GumbelFit:
    """A Gumbel fit of n maxima of realisations `duration` long, and the MPM over `storm`."""
    maxima: np.ndarray
    method: str
    mu: float
    beta: float
    duration: float   # of one realisation [s]
    storm: float      # [s]
    mpm: float        # mu + beta ln(storm / duration)
    low: float        # the confidence interval of the MPM
    high: float
    level: float
    boots: int

    @property
    def shift(self) -> float:
        return math.log(self.storm / self.duration)


def mpm(mu, beta, duration: float, storm: float):
    """The mode of the maximum over the storm: mu + beta ln(storm / duration)."""
    return mu + beta * math.log(storm / duration)


def fit_maxima(maxima, duration: float, storm: float | None = None, method: str = "mle", level: float = 0.90,
               boots: int = 1000, rng: np.random.Generator | None = None) -> GumbelFit:
    """The fit, the MPM over `storm` (default: one realisation) and its `level` confidence interval by the
    bootstrap of the pivot (q* - q^) / beta* over `boots` samples of the fitted law."""
    x = np.asarray(maxima, dtype=float)
    x = x[np.isfinite(x)]
    if x.size < 3:
        raise ValueError(f"a Gumbel fit needs 3 maxima or more (got {x.size}): more realisations (--seeds)")
    if not (0.0 < level < 1.0):
        raise ValueError(f"confidence level {level}: between 0 and 1")
    storm = duration if storm is None else storm
    if not (duration > 0.0 and storm > 0.0):
        raise ValueError(f"durations must be positive: realisation {duration} s, storm {storm} s")
    rng = rng if rng is not None else np.random.default_rng(0)
    mu, beta = (float(v) for v in fit(x, method))
    q = mpm(mu, beta, duration, storm)
    star = gumbel_sample(mu, beta, (boots, x.size), rng)
    mu_s, beta_s = fit(star, method)
    pivot = (mpm(mu_s, beta_s, duration, storm) - q) / beta_s
    lo_z, hi_z = np.quantile(pivot, [0.5 + level / 2.0, 0.5 - level / 2.0])
    return GumbelFit(np.sort(x), method, mu, beta, duration, storm, q, q - lo_z * beta, q - hi_z * beta, level, boots)


def reduced_variate(n: int) -> np.ndarray:
    """-ln(-ln F_i) at Gringorten's plotting positions F_i = (i - 0.44) / (n + 0.12), i = 1..n."""
    i = np.arange(1, n + 1)
    return -np.log(-np.log((i - 0.44) / (n + 0.12)))


def plot_gumbel(fits: dict, path, title: str, unit: str = "kN", scale: float = 1e3) -> None:
    """Gumbel probability paper: each line's sorted maxima against the reduced variate (Gringorten's
    positions), the fitted straight line x = mu + beta y, the MPM over the storm with its interval."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    ymax = 0.0
    for g, (name, f) in enumerate(fits.items()):
        color = f"C{g % 10}"
        y = reduced_variate(f.maxima.size)
        ax.plot(y, f.maxima / scale, "o", color=color, label=f"{name}: {f.maxima.size} maxima")
        ys = np.linspace(min(y[0], -1.5), max(y[-1], f.shift) + 0.5, 50)
        ax.plot(ys, (f.mu + f.beta * ys) / scale, "-", color=color,
                label=f"Gumbel ({f.method}): mu {f.mu / scale:.4g}, beta {f.beta / scale:.3g} {unit}")
        ax.errorbar([f.shift], [f.mpm / scale], yerr=[[(f.mpm - f.low) / scale], [(f.high - f.mpm) / scale]],
                    fmt="s", color=color, capsize=4,
                    label=f"MPM over {f.storm:g} s: {f.mpm / scale:.4g} {unit} ({100 * f.level:.0f} %: "
                          f"{f.low / scale:.4g} to {f.high / scale:.4g})")
        ymax = max(ymax, ys[-1])
    probabilities = [0.1, 0.5, 0.9, 0.99, 0.999]
    top = ax.secondary_xaxis("top", functions=(lambda y: y, lambda y: y))
    top.set_xticks([-math.log(-math.log(p)) for p in probabilities])
    top.set_xticklabels([f"{p:g}" for p in probabilities])
    top.set_xlabel("non-exceedance probability of a realisation's maximum")
    ax.set_xlabel("reduced variate -ln(-ln F)")
    ax.set_ylabel(f"maximum over a realisation [{unit}]")
    fig.suptitle(title, fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def format_fit(name: str, f: GumbelFit, unit: str = "kN", scale: float = 1e3, mbl: float = 0.0) -> str:
    said = (f"{name}: {f.maxima.size} maxima over {f.duration:g} s, Gumbel ({f.method}) mu {f.mu / scale:.4g} "
            f"{unit}, beta {f.beta / scale:.4g} {unit}; MPM over {f.storm:g} s {f.mpm / scale:.4g} {unit} "
            f"({100 * f.level:.0f} % interval {f.low / scale:.4g} to {f.high / scale:.4g} {unit})")
    if mbl > 0.0:
        said += f", {f.mpm / mbl:.3f} of MBL"
    return said
