"""Classical fourth-order Runge-Kutta over one step, split into substeps."""

from __future__ import annotations

import math

import numpy as np


def rk4_step(f, t: float, x: np.ndarray, h: float, max_substep: float) -> np.ndarray:
    """Advance dx/dt = f(t, x) from t to t + h with n = ceil(h / max_substep) RK4 substeps."""
    n = max(1, int(math.ceil(h / max_substep - 1e-12)))
    dt = h / n
    for i in range(n):
        ti = t + i * dt
        k1 = f(ti, x)
        k2 = f(ti + 0.5 * dt, x + 0.5 * dt * k1)
        k3 = f(ti + 0.5 * dt, x + 0.5 * dt * k2)
        k4 = f(ti + dt, x + dt * k3)
        x = x + (dt / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
    return x
