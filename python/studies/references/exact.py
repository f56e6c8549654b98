"""Exact (closed-form or quadrature-exact) solutions the validation compares the FMU against.

None of this uses the FMU. Sources:
  - cantilever elastica: tests/data/elastica.json (elliptic integrals, exact to 1e-12 L),
    loaded by `elastica_cases`;
  - pure end couple: a circular arc of radius EI/M (the bending moment is M everywhere);
  - elastic catenary between two fixed points: Irvine, "Cable Structures" (1981), eqs. 2.x, written
    here from the equilibrium of a segment with Hooke's law per unstretched length;
  - natural frequencies of a taut string and of a pinned-pinned beam-string (tensioned beam).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.optimize import fsolve

from ucable.paths import REPO_ROOT

# The project's reference numbers for the elastica (tests/data/elastica.json), kept in the repo so that a
# clone runs its tests wherever it is checked out.
ELASTICA_JSON = REPO_ROOT / "tests" / "data" / "elastica.json"


def elastica_cases(path: Path | None = None) -> list:
    """The four Table 1 cases (P = 20, 40, 60, 80 N) with exact tips and the paper's values."""
    with open(path or ELASTICA_JSON) as f:
        return json.load(f)["cases"]


def circular_arc(s: np.ndarray, radius: float) -> tuple:
    """Planar arc from the origin, tangent +x, bending towards -z: (x, z) at arc lengths s."""
    phi = np.asarray(s) / radius
    return radius * np.sin(phi), -radius * (1.0 - np.cos(phi))


@dataclass
class ElasticCatenary:
    """Elastic catenary of unstretched length L, submerged weight w [N/m of unstretched length] and
    axial stiffness EA hanging between a lower point A and an upper point B with B - A = (X, Z),
    X > 0, no seabed, no bending. Lagrangian coordinate p in [0, L] from A.

    With H the (constant) horizontal tension and V the vertical tension component at A (positive
    when the cable at A points upwards towards B), the tension is T(p) = sqrt(H^2 + (V + w p)^2)
    and (Hooke per unstretched length, T = EA (ds/dp - 1))
        x(p) = H p / EA + H / w [asinh((V + w p)/H) - asinh(V/H)]
        z(p) = (V p + w p^2 / 2) / EA + H / w [sqrt(1 + ((V + w p)/H)^2) - sqrt(1 + (V/H)^2)]
    H and V follow from x(L) = X, z(L) = Z.
    """

    L: float
    w: float
    EA: float
    X: float
    Z: float

    def __post_init__(self):
        chord = math.hypot(self.X, self.Z)
        # first guess: parabolic sag of a slack inextensible line, half the weight at each end
        slack = max(self.L - chord, 1e-3 * self.L)
        H0 = self.w * self.X**2 / (8.0 * math.sqrt(1.5 * slack * self.L))
        V0 = 0.5 * self.w * self.L * (1.0 - self.Z / self.L)
        sol, _, ier, msg = fsolve(lambda u: self._mismatch(math.exp(u[0]), u[1]),
                                  [math.log(H0), V0], full_output=True, xtol=1e-14)
        if ier != 1 and np.max(np.abs(self._mismatch(math.exp(sol[0]), sol[1]))) > 1e-9 * self.L:
            raise RuntimeError(f"elastic catenary: no solution ({msg})")
        self.H, self.V = math.exp(sol[0]), float(sol[1])

    def position(self, p, H=None, V=None):
        H = self.H if H is None else H
        V = self.V if V is None else V
        p = np.asarray(p, dtype=float)
        w, EA = self.w, self.EA
        x = H * p / EA + H / w * (np.arcsinh((V + w * p) / H) - np.arcsinh(V / H))
        z = (V * p + 0.5 * w * p**2) / EA + H / w * (np.hypot(1.0, (V + w * p) / H) - math.hypot(1.0, V / H))
        return x, z

    def _mismatch(self, H, V):
        x, z = self.position(self.L, H, V)
        return np.array([float(x) - self.X, float(z) - self.Z])

    def tension(self, p):
        return np.hypot(self.H, self.V + self.w * np.asarray(p, dtype=float))

    @property
    def bottom_tension(self) -> float:
        return float(self.tension(0.0))

    @property
    def top_tension(self) -> float:
        return float(self.tension(self.L))


def string_frequencies(length: float, mass_per_length: float, tension: float, strain: float,
                       modes=(1, 2, 3)) -> np.ndarray:
    """Taut string pinned at both ends, in Hz. The stretched length is L' = L (1 + strain) and the
    mass per stretched length m / (1 + strain): f_n = n / (2 L') sqrt(T (1 + strain) / m)."""
    Ls = length * (1.0 + strain)
    mu = mass_per_length / (1.0 + strain)
    return np.array([n / (2.0 * Ls) * math.sqrt(tension / mu) for n in modes])


def beam_string_frequencies(length: float, mass_per_length: float, tension: float, strain: float,
                            EI: float, modes=(1, 2, 3)) -> np.ndarray:
    """Pinned-pinned tensioned Euler beam (mode shapes sin(n pi s / L')), in Hz:
    f_n = n / (2 L') sqrt(T / mu) sqrt(1 + (n pi)^2 EI / (T L'^2)), L' and mu as for the string.
    EI is taken per stretched length; the difference is O(strain) in the correction term."""
    Ls = length * (1.0 + strain)
    f = string_frequencies(length, mass_per_length, tension, strain, modes)
    return np.array([fn * math.sqrt(1.0 + (n * math.pi) ** 2 * EI / (tension * Ls**2))
                     for fn, n in zip(f, modes)])


@dataclass
class TouchdownCatenary:
    """Elastic catenary from an anchor on a flat, frictionless, rigid seabed to a fairlead at
    horizontal distance X and height h above the seabed: unstretched length L, submerged weight w
    [N per unstretched metre], axial stiffness EA, no bending.

    A grounded part of unstretched length Lb carries the horizontal tension H (no friction) and is
    stretched to Lb (1 + H/EA); the suspended part Ls = L - Lb leaves the seabed with zero slope.
    With q the unstretched arc length from the touchdown point, V(q) = w q and
        x(q) = H q / EA + H / w asinh(w q / H),   z(q) = w q^2 / (2 EA) + H / w (sqrt(1 + (w q/H)^2) - 1).
    Unknowns (Ls, H): z(Ls) = h fixes H for a given Ls (z decreases monotonically in H), then the
    span Lb (1 + H/EA) + x(Ls) = X fixes Ls (outer root). When even the fully suspended line
    (Ls = L) is too short for the span, the line lifts off the anchor: then Irvine's catenary
    between the two points (`ElasticCatenary`) with a positive vertical anchor force is the answer
    (`lifted` is True and `grounded` 0).
    """

    L: float
    w: float
    EA: float
    X: float
    h: float

    def __post_init__(self):
        from scipy.optimize import brentq

        L, w, EA, X, h = self.L, self.w, self.EA, self.X, self.h
        if math.hypot(X, h) >= L * (1.0 + 1e3 * w * L / EA):
            raise ValueError("anchor out of reach")

        def height(q, H):
            a = w * q / H
            return w * q * q / (2.0 * EA) + H / w * (math.hypot(1.0, a) - 1.0)

        def H_for(q):
            # height(q, H) decreases from q (1 + w q/(2 EA)) at H -> 0 to w q^2/(2 EA) at H -> inf
            lo, hi = 1e-9 * w * L, 1e9 * w * L
            return math.exp(brentq(lambda u: height(q, math.exp(u)) - h, math.log(lo), math.log(hi),
                                   xtol=1e-15, rtol=1e-15, maxiter=500))

        def span_mismatch(q):
            H = H_for(q)
            return (L - q) * (1.0 + H / EA) + H * q / EA + H / w * math.asinh(w * q / H) - X

        q_min = h * (1.0 + 1e-12)  # the suspended part must at least reach the fairlead height
        if span_mismatch(L) < 0.0:  # even fully suspended with zero slope at the anchor: lifts off
            self.lifted = True
            self._free = ElasticCatenary(L, w, EA, X, h)
            self.H, self.suspended, self.grounded = self._free.H, L, 0.0
            self.fairlead_tension = self._free.top_tension
            self.anchor_vertical = self._free.V
            return
        self.lifted = False
        self.suspended = brentq(span_mismatch, q_min, L, xtol=1e-13 * L, rtol=1e-15, maxiter=500)
        self.H = H_for(self.suspended)
        self.grounded = L - self.suspended
        self.fairlead_tension = math.hypot(self.H, w * self.suspended)
        self.anchor_vertical = 0.0

    def position(self, p):
        """(x, z) of the material point at unstretched arc length p from the anchor, relative to
        the anchor (z measured up from the seabed)."""
        p = np.asarray(p, dtype=float)
        if self.lifted:
            return self._free.position(p)
        w, EA, H, Lb = self.w, self.EA, self.H, self.grounded
        q = np.clip(p - Lb, 0.0, None)
        xg = np.minimum(p, Lb) * (1.0 + H / EA)
        x = xg + H * q / EA + H / w * np.arcsinh(w * q / H)
        z = w * q**2 / (2.0 * EA) + H / w * (np.hypot(1.0, w * q / H) - 1.0)
        return x, z

    def tension(self, p):
        p = np.asarray(p, dtype=float)
        if self.lifted:
            return self._free.tension(p)
        return np.hypot(self.H, self.w * np.clip(p - self.grounded, 0.0, None))
