"""A towed body as a 3-DOF point body: mass, isotropic added mass, weight in water, quadratic drag.

    (m + ma) dv/dt = F_cable + (rho V - m) g e_z + 1/2 rho CdA |u| u,   u = current - v

F_cable = the FMU output endForce.x/y/z with bottomEnd 3 (force of the cable on the body). The same
model, with the same parameters, is the FMU's internal towed body (bottomEnd 2, body.mass,
body.volume, body.addedMass, body.CdA), which makes internal and external coupling comparable.

Default numbers: a small towfish / depressor: 400 kg in air, 0.1 m3 displaced (2.9 kN weight in
water), added mass 100 kg (about the displaced mass of a streamlined body), drag area 0.3 m2
(Cd ~ 1 on a 0.3 m2 frontal area: 230 N at 2.4 kn).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .rk4 import rk4_step


@dataclass
class TowedBodyParameters:
    mass: float = 400.0  # [kg]
    volume: float = 0.1  # [m3]
    added_mass: float = 100.0  # [kg]
    CdA: float = 0.3  # [m2]
    water_density: float = 1025.0
    gravity: float = 9.81

    def fmu_parameters(self) -> dict:
        """The FMU's internal towed body (bottomEnd 2) with the same numbers."""
        return {"bottomEnd": 2, "body.mass": self.mass, "body.volume": self.volume,
                "body.addedMass": self.added_mass, "body.CdA": self.CdA,
                "waterDensity": self.water_density, "gravity": self.gravity}

    @property
    def weight_in_water(self):
        return (self.mass - self.water_density * self.volume) * self.gravity


class TowedBody:
    """State x = [x, y, z, vx, vy, vz] (Earth frame, z up)."""

    N = 6

    def __init__(self, params: TowedBodyParameters, position, velocity=(0.0, 0.0, 0.0),
                 current=(0.0, 0.0), max_substep: float = 0.01):
        self.p = params
        self.x = np.concatenate([np.asarray(position, float), np.asarray(velocity, float)])
        self.current = np.array([current[0], current[1], 0.0])
        self.t = 0.0
        self.max_substep = max_substep

    def acceleration(self, x, cable_force):
        p = self.p
        u = self.current - x[3:]
        f = np.asarray(cable_force, float) + 0.5 * p.water_density * p.CdA * np.linalg.norm(u) * u
        f[2] -= p.weight_in_water
        return f / (p.mass + p.added_mass)

    def derivatives(self, t, x, cable_force):
        return np.concatenate([x[3:], self.acceleration(x, cable_force)])

    def step(self, h, force_start, force_end):
        """Advance by h; the cable force varies linearly from force_start to force_end."""
        t0 = self.t
        f0 = np.asarray(force_start, float)
        f1 = np.asarray(force_end, float)

        def f(t, x):
            w = (t - t0) / h
            return self.derivatives(t, x, (1.0 - w) * f0 + w * f1)

        self.x = rk4_step(f, t0, self.x, h, self.max_substep)
        self.t = t0 + h

    @property
    def position(self):
        return self.x[:3]

    @property
    def velocity(self):
        return self.x[3:]

    def get_state(self):
        return (self.t, self.x.copy())

    def set_state(self, state):
        self.t, x = state
        self.x = x.copy()
