"""The FMU's wave components in Python: the generator documented in docs/waves.md, written again
from that description (not read out of the FMU), so that other codes can be fed the very sea the
FMU sees. tests/python/test_waves_moordyn.py checks that the FMU's `waveElevation` equals the
elevation of these components.

A component of amplitude a, frequency w, wavenumber k (w^2 = g k tanh(k h)), direction of travel
beta and phase p has the elevation a cos(k (x cos beta + y sin beta) - w t + p). Regular: one
component, a = H / 2, w = 2 pi / T, p = 0. JONSWAP: n components at the midpoints of equal bands
over [0.5, 3] w_p, amplitudes sqrt(2 S dw) with S scaled to 4 sqrt(m0) = Hs, phases 2 pi u with u
the doubles (top 53 bits) of SplitMix64 seeded with waves.seed. A spread sea (waves.spreading s > 0,
waves.nDirections n > 1): the JONSWAP components in each of n directions beta + theta_j, theta_j = -pi +
(j + 1/2) 2 pi / n, amplitudes times sqrt(w_j / sum w), w_j = G(s) cos^{2s}(theta_j / 2) 2 pi / n, and
direction j's phases the uniforms j n_c + i of the same sequence.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

_MASK = (1 << 64) - 1


class SplitMix64:
    """Steele, Lea and Flood's 64-bit generator; uniform() is a double from the top 53 bits."""

    def __init__(self, seed: int):
        self.state = seed & _MASK

    def next(self) -> int:
        self.state = (self.state + 0x9E3779B97F4A7C15) & _MASK
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & _MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & _MASK
        return z ^ (z >> 31)

    def uniform(self) -> float:
        return (self.next() >> 11) * 2.0 ** -53


def wave_number(omega: float, depth: float, g: float) -> float:
    """k of omega^2 = g k tanh(k h) by Newton's method to round-off."""
    k = omega * omega / g
    if k * depth < 10.0:
        k = max(k, omega / math.sqrt(g * depth))
    for _ in range(100):
        th = math.tanh(k * depth)
        step = (g * k * th - omega * omega) / (g * (th + k * depth * (1.0 - th * th)))
        k -= step
        if abs(step) <= 1e-15 * k:
            break
    return k


def _jonswap_shape(w: float, wp: float, gamma: float) -> float:
    sigma = 0.07 if w <= wp else 0.09
    r = math.exp(-(w - wp) ** 2 / (2.0 * sigma * sigma * wp * wp))
    return w ** -5.0 * math.exp(-1.25 * (wp / w) ** 4) * gamma ** r


def spreading_directions(s: float, n: int) -> tuple:
    """The cos-2s spreading's n directions about the mean (offsets theta_j) and their weights
    D(theta_j) 2 pi / n, D(theta) = G(s) cos^{2s}(theta / 2), G(s) = Gamma(s + 1) / (2 sqrt(pi) Gamma(s + 1/2))."""
    G = math.exp(math.lgamma(s + 1.0) - math.lgamma(s + 0.5)) / (2.0 * math.sqrt(math.pi))
    theta = np.array([-math.pi + (j + 0.5) * 2.0 * math.pi / n for j in range(n)])
    return theta, G * np.cos(0.5 * theta) ** (2.0 * s) * 2.0 * math.pi / n


@dataclass
class Sea:
    """Wave components (arrays of equal length) and the direction of travel (one for all, or one per
    component: a spread sea)."""
    amplitude: np.ndarray
    omega: np.ndarray
    k: np.ndarray
    phase: np.ndarray
    direction: float | np.ndarray = 0.0

    def directions(self) -> np.ndarray:
        """The direction of travel of each component."""
        return np.broadcast_to(np.asarray(self.direction, float), self.amplitude.shape)

    def elevation(self, x: float, y: float, t) -> np.ndarray:
        """eta at (x, y) at the times t (the full sea, no ramp)."""
        d = x * np.cos(self.directions()) + y * np.sin(self.directions())
        t = np.atleast_1d(np.asarray(t, float))
        theta = (self.k * d)[None, :] - self.omega[None, :] * t[:, None] + self.phase[None, :]
        return (self.amplitude[None, :] * np.cos(theta)).sum(axis=1)

    def kinematics(self, x: float, y: float, z: float, t: float, depth: float, wheeler: bool = True):
        """Water velocity and acceleration (3-vectors) and the elevation at a point below the surface;
        with Wheeler stretching the depth factors are those of h (z - eta) / (h + eta)."""
        eta = float(self.elevation(x, y, t)[0])
        zs = min(depth * (z - eta) / (depth + eta), 0.0) if wheeler else min(z, 0.0)
        cb, sb = np.cos(self.directions()), np.sin(self.directions())
        theta = self.k * (x * cb + y * sb) - self.omega * t + self.phase
        ch = np.cosh(self.k * (zs + depth)) / np.sinh(self.k * depth)
        sh = np.sinh(self.k * (zs + depth)) / np.sinh(self.k * depth)
        aw, aw2 = self.amplitude * self.omega, self.amplitude * self.omega ** 2
        uh, w = aw * ch * np.cos(theta), np.sum(aw * sh * np.sin(theta))
        ah, az = aw2 * ch * np.sin(theta), np.sum(-aw2 * sh * np.cos(theta))
        return (np.array([np.sum(uh * cb), np.sum(uh * sb), w]), np.array([np.sum(ah * cb), np.sum(ah * sb), az]),
                eta)

    def hs(self) -> float:
        """4 sqrt(m0) of the components."""
        return 4.0 * math.sqrt(0.5 * float(np.sum(self.amplitude ** 2)))


def sea_state(parameters: dict) -> Sea:
    """The components of the FMU's waves.* parameters (FMU defaults where not given)."""
    p = {"waves.mode": 0, "waves.height": 0.0, "waves.period": 10.0, "waves.gamma": 3.3,
         "waves.direction": 0.0, "waves.seed": 1, "waves.nComponents": 200, "waterDepth": 1000.0,
         "gravity": 9.81, **parameters}
    mode, H, T = int(p["waves.mode"]), float(p["waves.height"]), float(p["waves.period"])
    h, g, beta = float(p["waterDepth"]), float(p["gravity"]), float(p["waves.direction"])
    if mode == 0 or H == 0.0:
        return Sea(*(np.zeros(0) for _ in range(4)), direction=beta)
    wp = 2.0 * math.pi / T
    if mode == 1:
        return Sea(np.array([0.5 * H]), np.array([wp]), np.array([wave_number(wp, h, g)]), np.zeros(1), beta)
    n = int(p["waves.nComponents"])
    w0, w1 = 0.5 * wp, 3.0 * wp
    dw = (w1 - w0) / n
    omega = np.array([w0 + (i + 0.5) * dw for i in range(n)])
    S = np.array([_jonswap_shape(w, wp, float(p["waves.gamma"])) for w in omega])
    scale = H * H / 16.0 / float(np.sum(S * dw))
    random = SplitMix64(int(p["waves.seed"]))
    amplitude, k = np.sqrt(2.0 * scale * S * dw), np.array([wave_number(w, h, g) for w in omega])
    spreading, n_directions = float(p.get("waves.spreading", 0.0)), int(p.get("waves.nDirections", 15))
    if spreading > 0.0 and n_directions > 1:
        theta, weight = spreading_directions(spreading, n_directions)
        phase = np.array([2.0 * math.pi * random.uniform() for _ in range(n * n_directions)])
        return Sea(np.concatenate([amplitude * math.sqrt(wj / weight.sum()) for wj in weight]), np.tile(omega, n_directions),
                   np.tile(k, n_directions), phase, np.repeat(beta + theta, n))
    phase = np.array([2.0 * math.pi * random.uniform() for _ in range(n)])
    return Sea(amplitude, omega, k, phase, beta)
