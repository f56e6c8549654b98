"""An independent reference for anchored lines whose upper part is in air: the elastic catenary of
a line of sections and point loads that weighs its dry weight above the water surface (z = 0) and its
submerged weight below, on a flat frictionless seabed, solved by shooting.

From the anchor at (0, -depth), u the unstretched arc length up the line, the tension (H, V(u)):
    dx/du = H / T + H / EA,  dz/du = V / T + V / EA,  dV/du = w(z, u),  T = sqrt(H^2 + V^2),
with w the section's dry weight per length where z > 0 and its submerged weight where z <= 0
(integrated numerically with an event at the surface: nothing of the FMU's closed-form pieces is
used). Where V at the anchor is negative the line rests on the seabed from the anchor until V
reaches 0 (frictionless: straight, stretched by H / EA). Point loads make V jump by their weight
(dry above the surface). H and V at the anchor are found by Newton's method on the fairlead's
position. MoorPy, which the other lines of the statics benchmark are compared with, gives a line
that leaves the water one uniform weight blended from its ends' heights, so it is no reference here.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import root


class NoSolution(Exception):
    """No profile of this kind: the line rests on the seabed twice, or the shooting did not converge."""


def _walk(H: float, v: float, sections: list, points: list, depth: float, rtol: float = 1e-11):
    """Integrates from the anchor; returns (x, z, V, grounded length, lowest height of the hanging
    part) at the fairlead. sections: (length, wet, dry, EA) from the anchor up; points: (u, wet, dry)
    with u from the anchor."""
    z0 = -depth
    x, z, V, u = 0.0, z0, v, 0.0
    grounded = 0.0
    lowest = math.inf
    bounds = []  # (u0, u1, wet, dry, EA): the sections cut at the point loads
    u0 = 0.0
    cuts = sorted(p[0] for p in points)
    for length, wet, dry, EA in sections:
        inner = [c for c in cuts if u0 < c < u0 + length]
        edges = [u0, *inner, u0 + length]
        for a, b in zip(edges[:-1], edges[1:]):
            bounds.append((a, b, wet, dry, EA))
        u0 += length
    resting = V < 0.0
    buoyResting = False
    for a, b, wet, dry, EA in bounds:
        for pu, pwet, pdry in points:
            if abs(pu - a) < 1e-9 and a > 0.0:
                P = pdry if z > 0.0 else pwet
                if resting and P < 0.0:
                    buoyResting = True  # no solution: a buoy cannot rest on the seabed
                V += P
                if resting and V >= 0.0:
                    resting = False  # the line lifts off at this clump
        l = b - a
        if resting:
            if wet > 0.0 and V + wet * l > 0.0:
                lg = -V / wet  # the touchdown inside this piece
                x += lg * (1.0 + H / EA)
                grounded += lg
                V = 0.0
                resting = False
                a = a + lg
                l = b - a
            else:
                x += l * (1.0 + H / EA)
                grounded += l
                V += wet * l
                continue

        def rhs(_u, y, inAir):
            T = math.hypot(H, y[2])
            return [H / T + H / EA, y[2] / T + y[2] / EA, dry if inAir else wet]

        def surface(_u, y, _inAir):
            return y[1]

        surface.terminal = True
        ua = a
        y = [x, z, V]
        while ua < b - 1e-12 * (b + 1.0):
            inAir = y[1] > 0.0 or (y[1] == 0.0 and rhs(0, y, False)[1] > 0.0)
            sol = solve_ivp(rhs, (ua, b), y, args=(inAir,), method="DOP853", rtol=rtol,
                            atol=1e-12 * max(depth, 1.0), events=surface, dense_output=False)
            lowest = min(lowest, float(np.min(sol.y[1])))
            y = list(sol.y[:, -1])
            ua = float(sol.t[-1])
            if sol.status == 1:  # at the surface: step just across it
                y[1] = 0.0
                rate = rhs(0, y, inAir)
                y[1] = 1e-13 * max(depth, 1.0) * (1.0 if rate[1] > 0.0 else -1.0)
        x, z, V = y
    if buoyResting:
        lowest = -math.inf
    return x, z, V, grounded, lowest


def solve(sections: list, points: list, depth: float, span: float, fairlead_z: float,
          guess: tuple | None = None) -> dict:
    """The line from an anchor on the seabed at depth `depth` to a fairlead `span` across at height
    `fairlead_z`. sections from the anchor up as (length, wet weight [N/m], dry weight [N/m], EA);
    points as (u from the anchor, wet weight [N], dry weight [N]). Returns the fairlead and anchor
    tensions, H, the anchor's vertical force, the grounded length."""
    L = sum(s[0] for s in sections)
    wmean = sum(s[0] * s[1] for s in sections) / L
    scale = max(abs(wmean) * L, 1.0)

    def residual(y):
        H, v = math.exp(y[0]), y[1] * scale
        x, z, _, _, _ = _walk(H, v, sections, points, depth, rtol=1e-9)
        return [(x - span) / L, (z - fairlead_z) / L]

    starts = [guess] if guess else []
    for f in (1.0, 0.3, 3.0, 0.1, 10.0, 0.03, 30.0):
        starts.append((f * scale, -0.3 * scale))
        starts.append((f * scale, 0.3 * scale))
    for H0, v0 in starts:
        sol = root(residual, [math.log(H0), v0 / scale], method="hybr", options={"xtol": 1e-13})
        if sol.success and max(abs(r) for r in sol.fun) < 1e-9:
            H, v = math.exp(sol.x[0]), sol.x[1] * scale
            x, z, V, grounded, lowest = _walk(H, v, sections, points, depth)
            if lowest == -math.inf:
                continue  # a buoy resting on the seabed: not the solution
            if lowest < -depth - 1e-3:
                raise NoSolution("the hanging line passes below the seabed (it rests twice)")
            anchorV = 0.0 if grounded > 0.0 else v
            return {"fairlead": math.hypot(H, V), "anchor": math.hypot(H, anchorV), "H": H,
                    "anchor_vertical": anchorV, "grounded": grounded}
    raise NoSolution("the shooting did not converge")
