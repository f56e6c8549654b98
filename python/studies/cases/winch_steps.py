"""Winch ramps against the communication step (docs/winch.md, "Ramps and the communication step").

A scene's [winch] stages are a piecewise-linear table of winch.rate. The scene runner passes the
rate with its slope over each step (the input derivative of winch.rate), the drum follows the ramp
between communication points, and the tensions do not depend on the master's step. Measured here:

* the tow job: a 2 t towfish on 600 m of the default (Hopland) cable at 3 kn, hauled in 60 m and paid
  out again at 0.5 m/s (10 s ramps): towTensionMax and towTensionMin at 0.1, 0.5 and 1 s steps
  against a 0.05 s run, with the rate given with its derivative (the scene runner), held over each
  step as a master without derivatives sets it (drum at its default acceleration), and held with
  no acceleration limit (winch.maxAcceleration 0, the former default);
* the ramped pay-out: the deploy scene's body on 100 m at 2 kn paid out 0 -> 0.5 m/s in 10 s: the
  0.5 s steps' towTensionMax / towTensionMin against the tension sampled every 0.01 s, step by step
  (the fine run with the derivative: the drum's true course), with and without the derivative.

    python -m studies.cases.winch_steps [--quick] [--out DIR]
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.paths import require_fmu
from ucable.scene import load_scene, run_scene, signal_at
from ucable.units import HOUR, NAUTICAL_MILE

TOW_BODY = {"bottomEnd": 2, "body.mass": 2000.0, "body.volume": 0.25, "body.addedMass": 500.0,
            "body.CdA": 1.0}


def tow_job(step: float, duration: float = 300.0, extra: dict | None = None) -> dict:
    """The tow job: 600 m, 2 t towfish at 3 kn; the winch hauls in 60 m at 0.5 m/s and pays it out
    again (10 s ramps; each stage's integral 0.5 m/s x (120 s - 10 s) + the ramps' halves = 60 m)."""
    stages = [{"rate": -0.5, "duration": 130.0}, {"rate": 0.0, "duration": 20.0},
              {"rate": 0.5, "duration": 130.0}, {"rate": 0.0, "duration": max(duration - 280.0, 10.0)}]
    return {"title": "tow job with winch ramps", "duration": duration, "step": step, "record_shape": False,
            "parameters": {"length": 600.0, "nElements": 20, **TOW_BODY, "winch.minLength": 400.0,
                           "winch.maxLength": 700.0, "winch.maxRate": 1.0, **(extra or {})},
            "tow": {"speed_kn": 3.0}, "winch": {"ramp": 10.0, "stages": stages}}


def quick_tow_job(step: float, extra: dict | None = None) -> dict:
    """The tow job's first ramps only (haul-in starting and stopping), 40 s: the tests' variant."""
    d = tow_job(step, 40.0, extra)
    d["winch"]["stages"] = [{"rate": -0.5, "duration": 20.0}, {"rate": 0.0, "duration": 20.0}]
    return d


def payout(step: float, duration: float = 30.0, extra: dict | None = None) -> dict:
    """The deploy scene's body on 100 m at 2 kn, paid out 0 -> 0.5 m/s in 10 s, then running."""
    d = load_scene("deploy").data.copy()
    d = {**d, "duration": duration, "step": step, "record_shape": False,
         "parameters": {**d["parameters"], **(extra or {})},
         "winch": {"ramp": 10.0, "stages": [{"rate": 0.5, "duration": duration}]}}
    return d


def run_held(data: dict, fmu=None):
    """The scene run as a master without input derivatives: the rate held over each step (the value of
    the table at the step's start). Returns (times, towTension, towTensionMax, towTensionMin)."""
    s = load_scene(data)
    p = dict(s.parameters, winchMode=1)
    h, n = s.step, int(round(s.duration / s.step))
    V = float(s.tow["speed_kn"]) * NAUTICAL_MILE / HOUR
    out = np.zeros((n + 1, 3))
    with CableFMU(fmu or require_fmu(), parameters=p) as c:
        c.initialize(0.0, s.duration, inputs={"tow.vx": V, "winch.rate": 0.0})
        out[0] = [c.get("towTension")] * 3
        for k in range(n):
            t = k * h
            c.set({"tow.x": V * t, "tow.vx": V, "winch.rate": float(signal_at(s.winch["table"], t))})
            c.do_step(h, t)
            out[k + 1] = [c.get("towTension"), c.get("towTensionMax"), c.get("towTensionMin")]
    return np.arange(n + 1) * h, out[:, 0], out[:, 1], out[:, 2]


def extremes(data: dict, held: bool = False, fmu=None):
    """(towTensionMax, towTensionMin, cpu) over the run."""
    t0 = time.process_time()
    if held:
        _, _, tmax, tmin = run_held(data, fmu)
    else:
        r = run_scene(data, fmu=fmu)
        tmax, tmin = r["towTensionMax"], r["towTensionMin"]
    return float(np.max(tmax)), float(np.min(tmin)), time.process_time() - t0


def step_errors(coarse: float = 0.5, fine: float = 0.01, duration: float = 30.0, extra: dict | None = None, fmu=None,
                held: bool = False):
    """The ramped pay-out at the coarse step (held: the rate held over each step, no derivative): each
    step's towTensionMax/towTensionMin against the largest and smallest tension sampled every `fine`
    seconds in the same interval by the scene runner (the fine run's samples, both ends included).
    Returns (largest relative difference of the maxima, of the minima, the coarse run's overall max and
    min, the fine samples' overall max and min)."""
    if held:
        _, _, cmax, cmin = run_held(payout(coarse, duration, extra), fmu)
    else:
        rc = run_scene(payout(coarse, duration, extra), fmu=fmu)
        cmax, cmin = rc["towTensionMax"], rc["towTensionMin"]
    rf = run_scene(payout(fine, duration, extra), fmu=fmu)
    per = int(round(coarse / fine))
    T = rf["towTension"]
    dmax = dmin = 0.0
    for k in range(1, len(cmax)):
        window = T[(k - 1) * per:k * per + 1]
        dmax = max(dmax, abs(cmax[k] - window.max()) / window.max())
        dmin = max(dmin, abs(cmin[k] - window.min()) / window.min())
    return dmax, dmin, (float(cmax.max()), float(cmin.min())), (float(T.max()), float(T.min()))


def recover(step: float, extra: dict | None = None) -> dict:
    """The shipped recover scene at `step`, with parameter overrides."""
    d = load_scene("recover").data
    return {**d, "step": step, "parameters": {**d["parameters"], **(extra or {})}}


DRUMS = ((False, None), (True, None), (True, {"winch.maxAcceleration": 0.0}))  # (held, parameters)


def step_table(title: str, scene, steps, reference_step: float) -> None:
    """Prints the extremes of scene(step, extra) at each step, with the rate given with its derivative,
    held at the default drum and held without a drum limit, against the reference step's."""
    ref_max, ref_min, cpu = extremes(scene(reference_step))
    print(f"{title}: towTensionMax / towTensionMin [N] and their difference from the {reference_step:g} s run "
          f"with the derivative ({ref_max:.1f} / {ref_min:.1f} N, {cpu:.1f} s CPU)")
    print()
    print("| step [s] | rate with derivative | held, default drum (0.2 m/s²) | held, no drum limit (0) |")
    print("|---:|---:|---:|---:|")
    for h in steps:
        cells = []
        for held, extra in DRUMS:
            tmax, tmin, _ = extremes(scene(h, extra=extra), held=held)
            cells.append(f"{tmax:.0f} ({100 * (tmax / ref_max - 1):+.2f} %) / {tmin:.0f} "
                         f"({100 * (tmin / ref_min - 1):+.2f} %)")
        print(f"| {h:g} | " + " | ".join(cells) + " |")
        sys.stdout.flush()
    print()


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="the tests' 40 s variant of the tow job")
    ap.add_argument("--steps", type=float, nargs="+", default=[0.1, 0.5, 1.0])
    ap.add_argument("--reference-step", type=float, default=0.05)
    a = ap.parse_args(argv)
    step_table("Tow job, 40 s variant" if a.quick else "Tow job, 300 s", quick_tow_job if a.quick else tow_job,
               a.steps, a.reference_step)
    step_table("The shipped recover scene", recover, a.steps, a.reference_step)
    print("Ramped pay-out at 0.5 s against the tension sampled every 0.01 s (largest difference over the steps):")
    print()
    print("| drum | towTensionMax | towTensionMin | coarse max / min [N] | 0.01 s max / min [N] |")
    print("|---|---:|---:|---:|---:|")
    for label, extra, held in (("rate with derivative, default drum", None, False),
                               ("rate with derivative, no drum limit", {"winch.maxAcceleration": 0.0}, False),
                               ("held, default drum", None, True),
                               ("held, no drum limit", {"winch.maxAcceleration": 0.0}, True)):
        dmax, dmin, (cmax, cmin), (fmax, fmin) = step_errors(extra=extra, held=held)
        print(f"| {label} | {100 * dmax:.3f} % | {100 * dmin:.3f} % | {cmax:.0f} / {cmin:.0f} | "
              f"{fmax:.0f} / {fmin:.0f} |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
