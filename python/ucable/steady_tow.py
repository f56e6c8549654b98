"""Independent steady solution of a cable towed at constant speed in still water.

This module does not use the FMU: it is the reference the FMU tests compare against.

Problem (2-D, in the vertical x-z plane of the tow): the tow point moves at speed V along +x at
the surface, the water is still, and the cable has reached a steady shape that translates with
the tow point. In the tow frame the water flows at -V x; the relative velocity of the water past
the cable is u = -V x (docs/model.md: u = U_current - dr/dt).

Geometry and signs (as in docs/model.md: Earth frame z up, s = 0 at the tow point):
  t = (-cos(phi), -sin(phi))   unit tangent pointing DOWN the cable (from the tow point to the end),
                               phi = angle of the cable below the horizontal, measured at each point
  n = (-sin(phi),  cos(phi))   unit normal, t rotated by +90 degrees

Loads per unit length (Morison drag with the MoorDyn/OrcaFlex convention):
  normal drag      Dn = 1/2 rho Cdn d    (V sin phi)^2   along +n  (backwards and up)
  tangential drag  Dt = 1/2 rho Cdt pi d (V cos phi)^2   along +t  (down the cable)
  submerged weight w  = (m - rho A) g, A = pi d^2 / 4   along -z

Equilibrium of the piece of cable below arc length s: d(T t)/ds = -f, i.e. with sigma = L - s
(unstretched distance from the lower end, integrated UPWARDS from the end):
  dT/dsigma   =  w sin(phi) + e Dt
  dphi/dsigma = -(e Dn - w cos(phi)) / T
  dx/dsigma   =  (1 + T/EA) cos(phi),    dz/dsigma = (1 + T/EA) sin(phi)
where e = 1 when drag acts per unit UNSTRETCHED length (the default, and what the FMU does:
src/terms/hydrodynamics.cpp integrates all loads over the unstretched arc length) and e = 1 + T/EA when
it acts per unit stretched length (the wetted length grows with the stretch; option
drag_per_stretched_length=True). Weight and buoyancy act per unit unstretched length (mass is
conserved; the cable volume is taken as conserved too). On the Hopland cable T/EA < 1e-4, so the
choice changes tensions by less than 0.01 %, far inside the 0.5 % the FMU tests ask for.

Integrating upwards is the stable direction: phi relaxes towards the critical angle phi_c where the
normal drag balances the normal component of the weight (Dn(phi_c) = w cos(phi_c)). At a free
lower end without load T = 0, and the only bounded solution is the straight line phi = phi_c with T
growing linearly (docs/model.md). With an end load F = (Fx, Fz) (force ON the cable at its
end, e.g. the drag and net weight of a towed body) the end condition is T t = F there.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp

from .units import GRAVITY, KNOT, WATER_DENSITY


@dataclass(frozen=True)
class CableProperties:
    """Cable and water properties (SI). Defaults: the Hopland 1993 tow cable (the FMU's defaults)."""

    length: float = 300.0
    diameter: float = 0.0332
    mass_per_length: float | None = None  # default rho_c A with rho_c = 3121 kg/m3
    EA: float | None = None  # default 77.5e9 A; math.inf for an inextensible cable
    Cdn: float = 1.649
    Cdt: float = 0.12
    water_density: float = WATER_DENSITY
    gravity: float = GRAVITY

    @property
    def area(self) -> float:
        return math.pi * self.diameter**2 / 4.0

    @property
    def mass(self) -> float:
        return self.mass_per_length if self.mass_per_length is not None else 3121.0 * self.area

    @property
    def axial_stiffness(self) -> float:
        return self.EA if self.EA is not None else 77.5e9 * self.area

    @property
    def submerged_weight(self) -> float:
        """w = (m - rho A) g [N/m], positive when the cable sinks."""
        return (self.mass - self.water_density * self.area) * self.gravity

    def normal_drag(self, speed: float, phi: float) -> float:
        """Normal drag per unit length on d [N/m] (magnitude, along +n)."""
        un = speed * math.sin(phi)
        return 0.5 * self.water_density * self.Cdn * self.diameter * un * abs(un)

    def tangential_drag(self, speed: float, phi: float) -> float:
        """Tangential drag per unit length on pi d [N/m] (along +t)."""
        ut = speed * math.cos(phi)
        return 0.5 * self.water_density * self.Cdt * math.pi * self.diameter * ut * abs(ut)


@dataclass
class SteadyTowSolution:
    """Steady towed-cable state. Positions are relative to the tow point (x back is negative, z up)."""

    speed: float
    top_tension: float  # [N] |force of the cable on the tow point|
    top_angle: float  # [rad] cable angle below the horizontal at the tow point
    top_force: tuple  # (Fx, Fz) [N] force of the cable on the tow point = T t(0)
    end_x: float  # [m] x of the lower end relative to the tow point
    end_z: float  # [m] z of the lower end relative to the tow point (negative = below)
    critical_angle: float  # [rad]
    s: np.ndarray = field(repr=False)  # unstretched arc length of the stations (0 = tow point)
    x: np.ndarray = field(repr=False)
    z: np.ndarray = field(repr=False)
    tension: np.ndarray = field(repr=False)
    angle: np.ndarray = field(repr=False)

    @property
    def end_depth(self) -> float:
        """Depth of the lower end below the tow point [m] (positive)."""
        return -self.end_z


def critical_angle(speed: float, cable: CableProperties = CableProperties()) -> float:
    """Angle below the horizontal where normal drag balances the normal weight component.

    Solves 1/2 rho Cdn d V^2 sin^2(phi) = w cos(phi), a quadratic in c = cos(phi).
    """
    w = cable.submerged_weight
    a = 0.5 * cable.water_density * cable.Cdn * cable.diameter * speed**2
    if a <= 0.0:
        return math.pi / 2.0
    c = (-w + math.sqrt(w * w + 4.0 * a * a)) / (2.0 * a)
    return math.acos(min(1.0, max(-1.0, c)))


def free_end_closed_form(speed: float, cable: CableProperties = CableProperties()) -> dict:
    """Closed form for a free lower end (exact for drag per unstretched length, the default).

    Straight line at phi_c; tension T(sigma) = (w sin phi_c + Dt(phi_c)) sigma; the stretched line
    has length L + k L^2 / (2 EA) with k the tension gradient.
    """
    phi = critical_angle(speed, cable)
    k = cable.submerged_weight * math.sin(phi) + cable.tangential_drag(speed, phi)
    L = cable.length
    stretched = L + k * L * L / (2.0 * cable.axial_stiffness)
    return {
        "critical_angle": phi,
        "top_tension": k * L,
        "tension_gradient": k,
        "end_x": -stretched * math.cos(phi),
        "end_z": -stretched * math.sin(phi),
    }


def body_end_load(speed: float, mass: float, volume: float, CdA: float,
                  water_density: float = WATER_DENSITY, gravity: float = GRAVITY) -> tuple:
    """End load (Fx, Fz) of a towed point body on the cable in a steady tow along +x.

    Quadratic drag 0.5 rho CdA V^2 opposes the motion (-x); net weight (m - rho V) g acts along -z.
    """
    drag = 0.5 * water_density * CdA * speed * abs(speed)
    return (-drag, -(mass - water_density * volume) * gravity)


def solve_steady_tow(speed: float, cable: CableProperties = CableProperties(),
                     end_load: tuple = (0.0, 0.0), n_stations: int = 21,
                     drag_per_stretched_length: bool = False,
                     rtol: float = 1e-11) -> SteadyTowSolution:
    """Steady shape and tension of a cable towed at `speed` [m/s] along +x in still water.

    end_load = (Fx, Fz) [N]: point force on the cable at its lower end (0 = free end).
    Returns the state at `n_stations` stations evenly spaced in unstretched arc length
    (index 0 at the tow point, like the FMU's shape.*[1]).
    """
    if speed < 0:
        raise ValueError("speed must be >= 0 (tow along +x)")
    L = cable.length
    EA = cable.axial_stiffness
    w = cable.submerged_weight
    phi_c = critical_angle(speed, cable)

    Fx, Fz = float(end_load[0]), float(end_load[1])
    T0 = math.hypot(Fx, Fz)
    if T0 > 0.0:
        phi0 = math.atan2(-Fz, -Fx)  # T t = F at the end, t = (-cos phi, -sin phi)
    else:
        phi0 = phi_c  # the only bounded solution at a load-free end

    def stretch(T):
        return 1.0 + T / EA if math.isfinite(EA) else 1.0

    def rhs(_sigma, y):
        T, phi = y[0], y[1]
        e = stretch(T)
        drag_factor = e if drag_per_stretched_length else 1.0
        dT = w * math.sin(phi) + drag_factor * cable.tangential_drag(speed, phi)
        normal = drag_factor * cable.normal_drag(speed, phi) - w * math.cos(phi)
        dphi = -normal / T if T > 0.0 else 0.0  # T = 0 only at a load-free end, where phi = phi_c
        return [dT, dphi, e * math.cos(phi), e * math.sin(phi)]

    scale = max(T0, abs(w) * L, 1.0)
    sol = solve_ivp(rhs, (0.0, L), [T0, phi0, 0.0, 0.0], method="DOP853", dense_output=True,
                    rtol=rtol, atol=[1e-12 * scale, 1e-13, 1e-12 * L, 1e-12 * L])
    if not sol.success:
        raise RuntimeError(f"steady tow ODE failed: {sol.message}")

    s = np.linspace(0.0, L, n_stations)
    Y = sol.sol(L - s)  # columns: stations from the tow point down
    x_top, z_top = Y[2, 0], Y[3, 0]
    T_top, phi_top = float(Y[0, 0]), float(Y[1, 0])
    return SteadyTowSolution(
        speed=speed,
        top_tension=T_top,
        top_angle=phi_top,
        top_force=(-T_top * math.cos(phi_top), -T_top * math.sin(phi_top)),
        end_x=float(-x_top),
        end_z=float(-z_top),
        critical_angle=phi_c,
        s=s,
        x=Y[2] - x_top,
        z=Y[3] - z_top,
        tension=Y[0].copy(),
        angle=Y[1].copy(),
    )


if __name__ == "__main__":
    for kn in (1.1, 2.4, 2.5):
        sol = solve_steady_tow(kn * KNOT)
        print(f"{kn:4.1f} kn: top tension {sol.top_tension:8.1f} N, angle "
              f"{math.degrees(sol.top_angle):5.2f} deg, end at x = {sol.end_x:7.2f} m, "
              f"z = {sol.end_z:7.2f} m")
