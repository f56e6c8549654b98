"""Steady references for a winch run: the towed state a cable of each deployed length settles to.

A deploy or recover scene pays cable out or hauls it in slowly; at every paid-out length the
quasi-steady state is that of a cable of that length towed steadily. Two references, both computed
here as data (no plotting, no files):

- `ode_references`: the independent steady-tow ODE (python/ucable/steady_tow.py), no FMU;
- `fmu_static_references`: the FMU's own static initialization (initMode 0, a steady tow at the
  initial tow velocity) of a cable started at that length with the same nominal element length.

The winch acceptance compares a run that paid out (or hauled in) to length L, then settled, with the
second ("a cable started at L"); the first checks the second independently.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ucable.steady_tow import CableProperties, body_end_load, solve_steady_tow
from ucable.units import KNOT


@dataclass(frozen=True)
class DeployBody:
    """The towed body of the deploy and recover scenes (the manoeuvre scenes' body)."""

    mass: float = 400.0  # [kg]
    volume: float = 0.1  # [m3]
    added_mass: float = 100.0  # [kg]
    CdA: float = 0.3  # [m2]

    def fmu_parameters(self) -> dict:
        return {"bottomEnd": 2, "body.mass": self.mass, "body.volume": self.volume,
                "body.addedMass": self.added_mass, "body.CdA": self.CdA}


@dataclass
class LengthReferences:
    """Steady tow state against the deployed (unstretched) length."""

    lengths: np.ndarray  # [m] unstretched length
    tow_tension: np.ndarray  # [N]
    body_depth: np.ndarray  # [m] depth of the far end below the tow point
    layback: np.ndarray  # [m] horizontal distance tow point -> far end


def ode_references(lengths, speed: float = 2.0 * KNOT, body: DeployBody = DeployBody(),
                   cable: CableProperties = CableProperties()) -> LengthReferences:
    """Independent steady solution (scipy ODE in arc length) at each length."""
    load = body_end_load(speed, body.mass, body.volume, body.CdA, cable.water_density,
                         cable.gravity)
    lengths = np.asarray(lengths, dtype=float)
    T, depth, layback = (np.empty_like(lengths) for _ in range(3))
    for i, L in enumerate(lengths):
        c = replace(cable, length=float(L))
        sol = solve_steady_tow(speed, c, end_load=load)
        T[i], depth[i], layback[i] = sol.top_tension, sol.end_depth, -sol.end_x
    return LengthReferences(lengths, T, depth, layback)


def elements_for_length(length: float, nominal_element_length: float) -> int:
    """Element count of a cable started at `length` with about the nominal element length."""
    return max(1, int(round(length / nominal_element_length)))


def fmu_static_references(fmu_file, lengths, speed: float = 2.0 * KNOT,
                          body: DeployBody = DeployBody(), nominal_element_length: float = 15.0,
                          parameters: dict | None = None, progress=None) -> LengthReferences:
    """The FMU's static initialization (initMode 0) of a cable started at each length.

    parameters: further FMU parameters (cable properties); progress: optional callable(i, n).
    """
    from ucable.fmu import CableFMU

    lengths = np.asarray(lengths, dtype=float)
    T, depth, layback = (np.empty_like(lengths) for _ in range(3))
    for i, L in enumerate(lengths):
        p = {**body.fmu_parameters(), **(parameters or {}), "length": float(L),
             "nElements": elements_for_length(L, nominal_element_length), "initMode": 0}
        cable = CableFMU(fmu_file, parameters=p)
        try:
            cable.initialize(inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": 0.0,
                                     "tow.vx": speed, "tow.vy": 0.0, "tow.vz": 0.0})
            T[i] = cable.get("towTension")
            depth[i] = -cable.get("endPosition.z")
            layback[i] = math.hypot(cable.get("endPosition.x"), cable.get("endPosition.y"))
        finally:
            cable.free()
        if progress is not None:
            progress(i + 1, len(lengths))
    return LengthReferences(lengths, T, depth, layback)
