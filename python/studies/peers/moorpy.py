"""MoorPy (PyPI `moorpy`), the quasi-static peer the studies compare the FMU's statics with: its
systems (read from a deck or built point by point), solved, with its console silenced; its closed
catenary; its angle convention.

`moorpy` is imported where it is used, never when this module is (see peers.moordyn: MoorDyn may not
load after it in the same process).
"""

from __future__ import annotations

import contextlib
import io
import warnings

import numpy as np


@contextlib.contextmanager
def silenced():
    """MoorPy prints as it reads and solves and warns about its own polynomial fits: both silenced
    inside the block."""
    with contextlib.redirect_stdout(io.StringIO()), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        yield


def system(path=None, **options):
    """MoorPy's System of the deck at `path` (or an empty one, built by the caller), with `options`
    (depth, rho, g) as MoorPy takes them."""
    import moorpy as mp

    with silenced():
        return mp.System(**options) if path is None else mp.System(file=str(path), **options)


def solve(s, tol: float, max_iter: int):
    """initialize and solveEquilibrium (MoorPy's answer: False when it did not converge)."""
    with silenced():
        s.initialize()
        return s.solveEquilibrium(tol=tol, maxIter=max_iter)


# Force scale of sloped_seabed_classified: MoorPy's test of a line resting on a sloped seabed then
# compares (the anchor's vertical force / 1e9 N) with tan(alpha), which holds for every anchor force of a
# mooring line (below 1e8 N at a slope of 1 deg and more), so its sloped profile (ProfileType 7) solves it.
_SLOPE_FORCE_SCALE = 1e-9


@contextlib.contextmanager
def sloped_seabed_classified():
    """MoorPy's catenary on a sloped seabed with its test of seabed contact corrected, inside the block.

    MoorPy (Catenary.eval_func_cat) takes a line whose end A is on a sloped seabed as hanging clear of it
    where VA > tan(alpha), the vertical anchor force in newtons against the slope's tangent, where a
    line rests on the slope while VA < HA tan(alpha) (its tangent would point into the slope). A line
    leaving its anchor at a smaller angle than the slope was then taken as hanging, and passed below
    the seabed. Inside the block a sloped line whose solution hangs (ProfileType 1) from an end on the
    seabed into the slope (VA < HA tan(alpha)) is solved again by MoorPy's own sloped profile, all its
    forces scaled by _SLOPE_FORCE_SCALE (its geometry and strains unchanged) and scaled back."""
    import moorpy.line as line

    original = line.catenary

    def classified(XF, ZF, L, EA, W, CB=0, alpha=0, HF0=0, VF0=0, **kw):
        out = original(XF, ZF, L, EA, W, CB=CB, alpha=alpha, HF0=HF0, VF0=VF0, **kw)
        info = out[4]
        if (alpha == 0 or CB < 0 or W <= 0 or info.get("ProfileType") != 1
                or info["VA"] >= info["HA"] * np.tan(np.radians(alpha))):
            return out
        s = _SLOPE_FORCE_SCALE
        fAH, fAV, fBH, fBV, info = original(XF, ZF, L, EA * s, W * s, CB=CB, alpha=alpha, HF0=HF0 * s,
                                            VF0=VF0 * s, **kw)
        for key in ("HF", "VF", "HA", "VA", "Te", "stiffnessA", "stiffnessB", "stiffnessBA"):
            if key in info:
                info[key] = np.asarray(info[key]) / s
        return fAH / s, fAV / s, fBH / s, fBV / s, info

    line.catenary = classified
    try:
        yield
    finally:
        line.catenary = original


def catenary(*args, **kwargs):
    """moorpy.Catenary.catenary: (fAH, fAV, fBH, fBV, info) of one elastic catenary with seabed."""
    from moorpy.Catenary import catenary as closed

    return closed(*args, **kwargs)


def rotation(roll, pitch, yaw):
    """MoorPy's orientation of a body: R = Rz(yaw) Ry(pitch) Rx(roll)."""
    cx, sx, cy, sy, cz, sz = np.cos(roll), np.sin(roll), np.cos(pitch), np.sin(pitch), np.cos(yaw), np.sin(yaw)
    Rx = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    Ry = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    Rz = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    return Rz @ Ry @ Rx


def angles(R: np.ndarray) -> np.ndarray:
    """(roll, pitch, yaw) of R = Rz Ry Rx (MoorPy's angles)."""
    return np.array([np.arctan2(R[2, 1], R[2, 2]), -np.arcsin(np.clip(R[2, 0], -1.0, 1.0)),
                     np.arctan2(R[1, 0], R[0, 0])])
