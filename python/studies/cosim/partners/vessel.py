"""A small survey vessel in the horizontal plane (3 DOF: surge, sway, yaw) with a speed/heading
autopilot and the tow cable acting at a tow point aft.

Frames: Earth x, y horizontal, z up (as the FMU); heading psi from +x towards +y; body axes
x forward, y to port (right-handed with z up). Body velocities u (surge), v (sway), r (yaw rate).

Equations of motion (Fossen's manoeuvring model with diagonal added mass, no Munk moment):

    (m + Xa) du/dt - (m + Ya) v r = -Xu u - Xuu |u| u + thrust + Fx_tow
    (m + Ya) dv/dt + (m + Xa) u r = -Yv v - Yvv |v| v          + Fy_tow
    (Iz + Na) dr/dt               = -Nr r - Nrr |r| r + N_rudder + x_t Fy_tow - y_t Fx_tow

F_tow = the FMU output towForce.x/y (force of the cable on the tow point) in body axes; its vertical
component and the heave/pitch/roll it would cause are not modelled (a 50 t vessel does not feel a
5 kN vertical pull at the stern in the horizontal plane).

Default numbers: a ~20 m, 50 t survey vessel. Resistance 1.25 kN at 2.4 kn and 15 kN at 10 kn
(Xu = 400 N s/m, Xuu = 500 N s2/m2: ~80 kW effective power at 10 kn); surge added mass 5 % and sway
added mass 80 % of the mass (slender hull); yaw inertia m (L/4)^2 with 50 % added inertia; sway
drag of a 20 m x 2 m lateral area (Yvv = 0.5 rho A Cd with Cd = 1); yaw damping that allows about
3 deg/s at full rudder. Thrust limits 25 kN ahead / 12 kN astern (bollard pull of ~250 kW),
rudder yaw moment limit 200 kN m. Tow point on the centreline 10 m aft of the centre of gravity.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .rk4 import rk4_step


@dataclass
class VesselParameters:
    mass: float = 50.0e3  # [kg]
    added_mass_surge: float = 2.5e3  # [kg]
    added_mass_sway: float = 40.0e3  # [kg]
    inertia_yaw: float = 1.25e6  # [kg m2] = m (L/4)^2, L = 20 m
    added_inertia_yaw: float = 0.625e6  # [kg m2]
    Xu: float = 400.0  # [N s/m] linear surge resistance
    Xuu: float = 500.0  # [N s2/m2] quadratic surge resistance
    Yv: float = 1.0e4  # [N s/m]
    Yvv: float = 2.0e4  # [N s2/m2] 0.5 * 1025 * (20 m * 2 m) * Cd 1
    Nr: float = 2.0e6  # [N m s]
    Nrr: float = 2.0e7  # [N m s2]
    tow_x: float = -10.0  # [m] tow point in body axes (aft of the centre of gravity)
    tow_y: float = 0.0  # [m]
    max_thrust: float = 25.0e3  # [N] ahead
    max_astern: float = 12.0e3  # [N] astern (magnitude)
    max_rudder_moment: float = 2.0e5  # [N m]

    @property
    def m11(self):
        return self.mass + self.added_mass_surge

    @property
    def m22(self):
        return self.mass + self.added_mass_sway

    @property
    def m66(self):
        return self.inertia_yaw + self.added_inertia_yaw

    def surge_resistance(self, u):
        return self.Xu * u + self.Xuu * abs(u) * u


class Autopilot:
    """Speed (PI + feed-forward of ramp acceleration, resistance and measured tow force) and heading
    (PID + feed-forward of the reference turn rate) autopilot.

    speed_ref(t) -> (u_ref [m/s], du_ref/dt [m/s2]); heading_ref(t) -> (psi_ref [rad], r_ref [rad/s]).
    Gains from pole placement on the rigid vessel: speed loop a double pole at -0.2 rad/s, heading
    loop a double pole at -0.3 rad/s and one at -heading_integral_bandwidth (0.05 rad/s), whose
    integral action takes out the tow's steady yaw moment (0: the critically damped PD). Integrators
    with conditional anti-windup (frozen while the actuator saturates in the direction of the error).
    The same autopilot as the Vessel FMU's (tests/python/test_partner_fmus.py).
    """

    def __init__(self, p: VesselParameters, speed_ref, heading_ref, speed_bandwidth: float = 0.2,
                 heading_bandwidth: float = 0.3, heading_integral_bandwidth: float = 0.05):
        self.p = p
        self.speed_ref = speed_ref
        self.heading_ref = heading_ref
        w = speed_bandwidth
        self.kp_u = 2.0 * w * p.m11
        self.ki_u = w * w * p.m11
        w, wi = heading_bandwidth, heading_integral_bandwidth
        # poles -w, -w, -wi: (s + w)^2 (s + wi) = s^3 + (2 w + wi) s^2 + (w^2 + 2 w wi) s + w^2 wi
        self.kp_psi = (w * w + 2.0 * w * wi) * p.m66
        self.kd_psi = (2.0 * w + wi) * p.m66
        self.ki_psi = w * w * wi * p.m66

    def commands(self, t, u, psi, r, integral, fx_tow_body, heading_integral=0.0):
        """(thrust [N], rudder yaw moment [N m], d(integral)/dt, d(heading integral)/dt)."""
        p = self.p
        u_ref, a_ref = self.speed_ref(t)
        e = u_ref - u
        raw = (p.m11 * a_ref + p.surge_resistance(u_ref) - fx_tow_body
               + self.kp_u * e + self.ki_u * integral)
        thrust = min(p.max_thrust, max(-p.max_astern, raw))
        saturated = (thrust != raw) and (e * raw > 0.0)
        de = 0.0 if saturated else e

        psi_ref, r_ref = self.heading_ref(t)
        err = math.remainder(psi_ref - psi, 2.0 * math.pi)
        raw = (p.Nr * r_ref + p.Nrr * abs(r_ref) * r_ref
               + self.kp_psi * err + self.kd_psi * (r_ref - r) + self.ki_psi * heading_integral)
        moment = min(p.max_rudder_moment, max(-p.max_rudder_moment, raw))
        d_heading = 0.0 if (moment != raw and err * raw > 0.0) else err
        return thrust, moment, de, d_heading


class Vessel:
    """State x = [x, y, psi, u, v, r, speed-error integral, heading-error integral]."""

    N = 8

    def __init__(self, params: VesselParameters, autopilot: Autopilot, x0=0.0, y0=0.0, psi0=0.0,
                 u0=0.0, max_substep: float = 0.05):
        self.p = params
        self.ap = autopilot
        self.x = np.array([x0, y0, psi0, u0, 0.0, 0.0, 0.0, 0.0])
        self.t = 0.0
        self.max_substep = max_substep

    # ---------------------------------------------------------------- kinematics of the tow point
    def tow_point(self, x=None, tow_force=(0.0, 0.0), t=None):
        """Earth-frame tow point position (x, y), velocity and acceleration (the acceleration needs
        the tow force, as it comes from the equations of motion)."""
        x = self.x if x is None else x
        p = self.p
        X, Y, psi, u, v, r = x[:6]
        c, s = math.cos(psi), math.sin(psi)
        xt, yt = p.tow_x, p.tow_y
        pos = (X + c * xt - s * yt, Y + s * xt + c * yt)
        wx, wy = u - r * yt, v + r * xt
        vel = (c * wx - s * wy, s * wx + c * wy)
        d = self.derivatives(self.t if t is None else t, x, tow_force)
        du, dv, dr = d[3], d[4], d[5]
        ax_b = du - dr * yt - r * wy
        ay_b = dv + dr * xt + r * wx
        acc = (c * ax_b - s * ay_b, s * ax_b + c * ay_b)
        return pos, vel, acc

    # ---------------------------------------------------------------- dynamics
    def derivatives(self, t, x, tow_force):
        p = self.p
        _, _, psi, u, v, r, integral, heading_integral = x
        c, s = math.cos(psi), math.sin(psi)
        fx, fy = tow_force[0], tow_force[1]
        fxb, fyb = c * fx + s * fy, -s * fx + c * fy
        thrust, moment, de, dh = self.ap.commands(t, u, psi, r, integral, fxb, heading_integral)
        X = -p.surge_resistance(u) + thrust + fxb
        Yf = -p.Yv * v - p.Yvv * abs(v) * v + fyb
        Nm = -p.Nr * r - p.Nrr * abs(r) * r + moment + p.tow_x * fyb - p.tow_y * fxb
        du = (X + p.m22 * v * r) / p.m11
        dv = (Yf - p.m11 * u * r) / p.m22
        dr = Nm / p.m66
        return np.array([c * u - s * v, s * u + c * v, r, du, dv, dr, de, dh])

    def step(self, h, force_start, force_end):
        """Advance by h; the tow force (Earth x, y) varies linearly from force_start to force_end."""
        t0 = self.t
        f0 = np.asarray(force_start[:2], float)
        f1 = np.asarray(force_end[:2], float)

        def f(t, x):
            w = (t - t0) / h
            return self.derivatives(t, x, (1.0 - w) * f0 + w * f1)

        self.x = rk4_step(f, t0, self.x, h, self.max_substep)
        self.t = t0 + h

    def commands(self, tow_force):
        """(thrust [N], rudder yaw moment [N m]) of the autopilot now, given the tow force."""
        _, _, psi, u, _, r, integral, heading_integral = self.x
        c, s = math.cos(psi), math.sin(psi)
        thrust, moment, _, _ = self.ap.commands(self.t, u, psi, r, integral,
                                                c * tow_force[0] + s * tow_force[1], heading_integral)
        return thrust, moment

    @property
    def speed(self):
        return math.hypot(self.x[3], self.x[4])

    def get_state(self):
        return (self.t, self.x.copy())

    def set_state(self, state):
        self.t, x = state
        self.x = x.copy()
