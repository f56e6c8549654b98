"""Body 1 of a mooring system free in surge, sway and yaw, integrated by the master from the lines' load on it
(the FMU's outputs body[1].force.x/y and body[1].moment.z) and a constant environmental load, as a scene's
[body.free] table gives it (docs/scenes.md). Heave, roll and pitch stay the scene's prescribed motion.

The equations: M x'' = F_lines + F_env - c v for x and y, I psi'' = M_lines + M_env - c_psi psi' for the yaw, with
M the platform's mass plus its added mass and I its yaw inertia plus added inertia. Each communication step h
the master gives the FMU the pose and velocity at the step's start and the acceleration (input derivative of the
velocity) from the load at that time; after the step it advances the state with the load at the step's end,
the trapezoidal rule on the lines' load (a second-order explicit coupling: the lines' load at both ends of
the step), the damping implicit:

    v1 = (v0 + h/2 (F0 + F1 + 2 F_env) / M - h/2 c v0 / M) / (1 + h/2 c / M),  x1 = x0 + h/2 (v0 + v1)

F1 is the load of a step the FMU took with the predicted motion x0 + h v0 + h^2/2 a0; the state the master
keeps is the corrected one. The predicted and corrected positions differ by O(h^3 F'/M), which for the
platform's periods (tens to hundreds of seconds) and steps of 1 s is millimetres."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

FREE_DOFS = (0, 1, 5)  # surge, sway, yaw in the order of the body's six degrees of freedom
LOAD_NAMES = ("body[1].force.x", "body[1].force.y", "body[1].moment.z")


@dataclass
class FreeBody:
    """The free platform: mass [kg] (with added mass, surge and sway), inertia [kg m2] (yaw, with added
    inertia), damping (c_x, c_y [N s/m], c_psi [N m s]), the constant environmental load (F_x, F_y [N], M_z
    [N m]); state q = (x, y, psi [rad]) and v, and the lines' load at the last communication point."""
    mass: float
    inertia: float
    damping: tuple = (0.0, 0.0, 0.0)
    load: tuple = (0.0, 0.0, 0.0)
    q: np.ndarray = field(default_factory=lambda: np.zeros(3))
    v: np.ndarray = field(default_factory=lambda: np.zeros(3))
    lines: np.ndarray = field(default_factory=lambda: np.zeros(3))

    @classmethod
    def from_table(cls, table: dict, start) -> "FreeBody":
        """From a checked [body.free] table and [body] start (x, y, z [m], roll, pitch, yaw [deg])."""
        return cls(mass=table["mass"], inertia=table["inertia"], damping=tuple(table.get("damping", (0.0,) * 3)),
                   load=tuple(table.get("load", (0.0,) * 3)),
                   q=np.array([start[0], start[1], math.radians(start[5])], float))

    def _inertia(self) -> np.ndarray:
        return np.array([self.mass, self.mass, self.inertia])

    def acceleration(self) -> np.ndarray:
        """x'', y'', psi'' at the last communication point."""
        return (self.lines + np.array(self.load) - np.array(self.damping) * self.v) / self._inertia()

    def inputs(self) -> dict:
        """The FMU's inputs of the free degrees of freedom at the last communication point."""
        return {"body[1].x": float(self.q[0]), "body[1].y": float(self.q[1]), "body[1].yaw": float(self.q[2]),
                "body[1].vx": float(self.v[0]), "body[1].vy": float(self.v[1]), "body[1].wz": float(self.v[2])}

    def pose(self, q) -> np.ndarray:
        """A six-DOF pose (SI, angles in rad) with surge, sway and yaw the free body's."""
        q = np.array(q, float)
        q[list(FREE_DOFS)] = self.q
        return q

    def rates(self, v) -> np.ndarray:
        """Six rates with the free ones the body's."""
        v = np.array(v, float)
        v[list(FREE_DOFS)] = self.v
        return v

    def accelerations(self, a) -> np.ndarray:
        """Six accelerations (the input derivatives of the body's rates) with the free ones the body's."""
        a = np.array(a, float)
        a[list(FREE_DOFS)] = self.acceleration()
        return a

    def advance(self, h: float, lines_after: np.ndarray) -> None:
        """The state at the end of a step of length h, from the lines' load at its start and end."""
        m, c = self._inertia(), np.array(self.damping)
        f = 0.5 * (self.lines + lines_after) + np.array(self.load)
        v1 = (self.v + h * (f - 0.5 * c * self.v) / m) / (1.0 + 0.5 * h * c / m)
        self.q = self.q + 0.5 * h * (self.v + v1)
        self.v = v1
        self.lines = np.array(lines_after, float)

