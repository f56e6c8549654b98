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
