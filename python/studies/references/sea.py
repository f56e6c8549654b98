"""The FMU's wave components in Python: the generator documented in docs/waves.md, written again
from that description (not read out of the FMU), so that other codes can be fed the very sea the
FMU sees. tests/python/test_waves_moordyn.py checks that the FMU's `waveElevation` equals the
elevation of these components.

A component of amplitude a, frequency w, wavenumber k (w^2 = g k tanh(k h)), direction of travel
beta and phase p has the elevation a cos(k (x cos beta + y sin beta) - w t + p). Regular: one
component, a = H / 2, w = 2 pi / T, p = 0. JONSWAP: n components at the midpoints of equal bands
over [0.5, 3] w_p, amplitudes sqrt(2 S dw) with S scaled to 4 sqrt(m0) = Hs, phases 2 pi u with u
the doubles (top 53 bits) of SplitMix64 seeded with waves.seed.
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


@dataclass
class Sea:
    """Wave components (arrays of equal length) and the direction of travel."""
    amplitude: np.ndarray
    omega: np.ndarray
    k: np.ndarray
    phase: np.ndarray
    direction: float = 0.0

    def elevation(self, x: float, y: float, t) -> np.ndarray:
        """eta at (x, y) at the times t (the full sea, no ramp)."""
        d = x * math.cos(self.direction) + y * math.sin(self.direction)
        t = np.atleast_1d(np.asarray(t, float))
        theta = self.k[None, :] * d - self.omega[None, :] * t[:, None] + self.phase[None, :]
        return (self.amplitude[None, :] * np.cos(theta)).sum(axis=1)

    def kinematics(self, x: float, y: float, z: float, t: float, depth: float, wheeler: bool = True):
        """Water velocity and acceleration (3-vectors) and the elevation at a point below the surface;
        with Wheeler stretching the depth factors are those of h (z - eta) / (h + eta)."""
        eta = float(self.elevation(x, y, t)[0])
        zs = min(depth * (z - eta) / (depth + eta), 0.0) if wheeler else min(z, 0.0)
        cb, sb = math.cos(self.direction), math.sin(self.direction)
        theta = self.k * (x * cb + y * sb) - self.omega * t + self.phase
        ch = np.cosh(self.k * (zs + depth)) / np.sinh(self.k * depth)
        sh = np.sinh(self.k * (zs + depth)) / np.sinh(self.k * depth)
        aw, aw2 = self.amplitude * self.omega, self.amplitude * self.omega ** 2
        uh, w = np.sum(aw * ch * np.cos(theta)), np.sum(aw * sh * np.sin(theta))
        ah, az = np.sum(aw2 * ch * np.sin(theta)), np.sum(-aw2 * sh * np.cos(theta))
        return np.array([uh * cb, uh * sb, w]), np.array([ah * cb, ah * sb, az]), eta

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
    phase = np.array([2.0 * math.pi * random.uniform() for _ in range(n)])
    return Sea(np.sqrt(2.0 * scale * S * dw), omega, np.array([wave_number(w, h, g) for w in omega]), phase, beta)
