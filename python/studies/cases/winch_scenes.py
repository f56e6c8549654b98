"""Winch scenes (scripts/manoeuvre deploy | recover | ct-lowering), docs/winch.md.

* deploy: a towed body (400 kg, the manoeuvre scenes' body) on the Hopland cable at 2 kn, paid out
  from 50 m to 600 m at 0.5 m/s (the winch accelerating and stopping at 0.05 m/s2), then 900 s at 600 m; the body's depth and the tow tension against the deployed length,
  next to the steady tow at each length (the independent steady-tow ODE).
* recover: the same body hauled in from 600 m to 50 m.
* ct-lowering: a 2 t body lowered from 50 m by the constant-tension winch (winchMode 2) under a
  vessel heaving 1.5 m at 8 s; the master sets the tension 1.5 kN below the hanging weight of the
  deployed length, so the winch pays out while it takes the heave out of the tension.

run() computes (no files), write_csv() and plot() write.
"""

from __future__ import annotations

import csv
import math
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.units import KNOT
from ..references.winch_reference import DeployBody, elements_for_length, ode_references

SCENES = ("deploy", "recover", "ct-lowering")
NOMINAL = 15.0  # [m] element length
ACCELERATION = 0.05  # [m/s2] of the winch in the deploy and recover scenes
SETTLE = 900.0  # [s] at the final length


@dataclass
class Result:
    name: str
    time: np.ndarray
    length: np.ndarray
    tension: np.ndarray
    depth: np.ndarray  # far end below the tow point [m]
    cpu: float
    reference: dict = field(default_factory=dict)  # steady references against length (deploy, recover)
    extra: dict = field(default_factory=dict)


def _tow(name: str, fmu, step: float, rate: float, progress=None) -> Result:
    start, end = (50.0, 600.0) if name == "deploy" else (600.0, 50.0)
    speed = 2.0 * KNOT
    body = DeployBody()
    params = {**body.fmu_parameters(), "length": start, "nElements": elements_for_length(start, NOMINAL),
              "winchMode": 1, "winch.minLength": 50.0, "winch.maxLength": 600.0, "winch.maxRate": 2.0}
    duration = abs(end - start) / rate + SETTLE  # then SETTLE seconds at the final length
    n = int(round(duration / step))
    out = {k: np.empty(n + 1) for k in ("t", "L", "T", "z")}
    with CableFMU(fmu, parameters=params) as c:
        c.initialize(inputs={"tow.vx": speed})
        cpu = time.process_time()
        for k in range(n + 1):
            t = k * step
            out["t"][k], out["L"][k] = t, c.get("unstretchedLength")
            out["T"][k], out["z"][k] = c.get("towTension"), -c.get("endPosition.z")
            if k == n:
                break
            # the winch accelerates and stops at ACCELERATION (a drum does not change speed at once)
            remaining = abs(end - out["L"][k])
            command = min(rate, ACCELERATION * (t + step), math.sqrt(2.0 * ACCELERATION * remaining))
            # inputs are the values at the step's start (the FMU extrapolates them over the step)
            c.set({"tow.x": speed * t, "tow.vx": speed, "winch.rate": math.copysign(command, end - start)})
            c.do_step(step, t)
            if progress:
                progress(t + step)
        cpu = time.process_time() - cpu
    grid = np.linspace(50.0, 600.0, 23)
    ref = ode_references(grid, speed, body)
    return Result(name, out["t"], out["L"], out["T"], out["z"], cpu,
                  reference={"length": grid, "tension": ref.tow_tension, "depth": ref.body_depth})


def _ct_lowering(fmu, step: float, progress=None, duration: float = 240.0) -> Result:
    hanging = {"length": 50.0, "nElements": 4, "bottomEnd": 2, "body.mass": 2000.0, "body.volume": 0.25,
               "body.CdA": 2.0, "body.addedMass": 500.0, "winchMode": 2, "winch.timeConstant": 0.001,
               "winch.minLength": 20.0, "winch.maxLength": 1000.0, "winch.maxRate": 2.0}
    amplitude, period, offset = 1.5, 8.0, 1500.0
    w = 2 * math.pi / period
    n = int(round(duration / step))
    out = {k: np.empty(n + 1) for k in ("t", "L", "T", "z", "set", "heave")}
    with CableFMU(fmu, parameters=hanging) as c:
        c.initialize()
        p = {k: c.get(k) for k in ("massPerLength", "diameter", "waterDensity", "gravity")}
        line_weight = (p["massPerLength"] - p["waterDensity"] * math.pi * p["diameter"] ** 2 / 4) * p["gravity"]
        body_weight = (2000.0 - p["waterDensity"] * 0.25) * p["gravity"]
        cpu = time.process_time()
        for k in range(n + 1):
            t = k * step
            L = c.get("unstretchedLength")
            target = body_weight + line_weight * L - offset
            out["t"][k], out["L"][k], out["set"][k] = t, L, target
            out["T"][k], out["z"][k] = c.get("towTension"), -c.get("endPosition.z")
            out["heave"][k] = c.get("tow.z")
            if k == n:
                break
            # inputs are the values at the step's start (the FMU extrapolates them over the step)
            c.set({"tow.z": amplitude * math.sin(w * t), "tow.vz": amplitude * w * math.cos(w * t),
                   "winch.tension": target})
            c.set_input_derivatives(["tow.vz"], 1, [-amplitude * w * w * math.sin(w * t)])
            c.do_step(step, t)
            if progress:
                progress(t + step)
        cpu = time.process_time() - cpu
    return Result("ct-lowering", out["t"], out["L"], out["T"], out["z"], cpu,
                  extra={"set": out["set"], "heave": out["heave"]})


def run(name: str, fmu, step: float | None = None, rate: float = 0.5, progress=None) -> Result:
    if name == "ct-lowering":
        return _ct_lowering(fmu, 0.1 if step is None else step, progress)
    return _tow(name, fmu, 0.5 if step is None else step, rate, progress)


def duration(name: str, rate: float = 0.5) -> float:
    return 240.0 if name == "ct-lowering" else 550.0 / rate + SETTLE


def summary(r: Result) -> dict:
    """Numbers a reader checks: for deploy/recover the settled state against the steady tow at the final
    length; for ct-lowering the tension's distance from the set value and the length paid out."""
    if r.name == "ct-lowering":
        err = r.tension - r.extra["set"]
        half = slice(len(err) // 4, None)
        return {"paid_out": r.length[-1] - r.length[0], "tension_error_rms": float(np.sqrt(np.mean(err[half] ** 2))),
                "tension_error_max": float(np.abs(err[half]).max()), "heave_amplitude": float(np.abs(r.extra["heave"]).max())}
    ref_T = float(np.interp(r.length[-1], r.reference["length"], r.reference["tension"]))
    ref_z = float(np.interp(r.length[-1], r.reference["length"], r.reference["depth"]))
    return {"final_length": float(r.length[-1]), "tension": float(r.tension[-1]), "steady_tension": ref_T,
            "depth": float(r.depth[-1]), "steady_depth": ref_z,
            "largest_step_change": float(np.abs(np.diff(r.tension[2:])).max())}


def write_csv(path: Path, r: Result) -> None:
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        cols = ["time [s]", "unstretchedLength [m]", "towTension [N]", "body depth [m]"] + \
               (["winch.tension [N]", "tow.z [m]"] if r.extra else [])
        w.writerow(cols)
        for k in range(len(r.time)):
            row = [r.time[k], r.length[k], r.tension[k], r.depth[k]]
            if r.extra:
                row += [r.extra["set"][k], r.extra["heave"][k]]
            w.writerow([f"{v:.10g}" for v in row])


def plot(path: Path, r: Result) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    if r.name == "ct-lowering":
        fig, ax = plt.subplots(3, 1, figsize=(10, 8), sharex=True)
        ax[0].plot(r.time, r.tension / 1e3, lw=0.8, label="tow tension")
        ax[0].plot(r.time, r.extra["set"] / 1e3, "k--", lw=1, label="winch.tension (set)")
        ax[0].set_ylabel("tension [kN]")
        ax[0].legend()
        ax[1].plot(r.time, r.length, label="deployed length")
        ax[1].set_ylabel("length [m]")
        ax[2].plot(r.time, r.extra["heave"], label="tow point heave")
        ax[2].plot(r.time, -r.depth + r.extra["heave"] + r.depth[0], label="body, relative to its start")
        ax[2].set_ylabel("z [m]")
        ax[2].set_xlabel("time [s]")
        ax[2].legend()
        ax[0].set_title("Constant-tension lowering of a 2 t body under a vessel heaving 1.5 m at 8 s")
    else:
        fig, ax = plt.subplots(1, 2, figsize=(12, 4.5))
        ax[0].plot(r.length, r.tension / 1e3, lw=1, label="FMU, winch running")
        ax[0].plot(r.reference["length"], r.reference["tension"] / 1e3, "k.", label="steady tow at that length")
        ax[0].set_xlabel("deployed length [m]")
        ax[0].set_ylabel("tow tension [kN]")
        ax[1].plot(r.length, r.depth, lw=1, label="FMU, winch running")
        ax[1].plot(r.reference["length"], r.reference["depth"], "k.", label="steady tow at that length")
        ax[1].set_xlabel("deployed length [m]")
        ax[1].set_ylabel("body depth below the tow point [m]")
        for a in ax:
            a.legend()
        fig.suptitle(f"{r.name}: towed body at 2 kn, winch at 0.5 m/s (accelerating at {ACCELERATION} m/s2), "
                     f"then {SETTLE:.0f} s at the final length")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
