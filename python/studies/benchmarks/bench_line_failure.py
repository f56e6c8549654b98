"""The cost of a line failure: scenes/oc4_storm_break (the OC4 semisubmersible free in surge, sway and yaw in a
JONSWAP storm, line 1 breaking at its fairlead at 600 s), run by scripts/bench_line_failure.

* speed: simulated time over CPU (time.process_time of the run, the runner's Python included), for the intact
  and the transient case (target: 100 times real time or more on one core);
* the cost of the break: the integrator steps (`solver.nSteps`, line 1's integrator: the broken line's) and the
  CPU of the communication steps over a window from the break, less the same window of the intact run; against
  the cost of one integrator restart, measured as the first second of a calm run at rest (the integrators start
  at order 1 with a small step) less a later second of it (target: the break costs no more than one restart).

compute() returns the numbers, markdown() the table."""

from __future__ import annotations

import sys
import time

import numpy as np

from ucable.scene import load_scene, run_scene

from ..doc_section import bench_main

SCENE = "oc4_storm_break"
WINDOW = 10.0  # [s] the window after the break whose cost is compared
RESTART_WINDOW = 1.0  # [s] the window at the start of a calm run that holds the integrator's start


def timed_run(fmu, case: str, duration: float | None = None, break_time: float | None = None,
              calm: bool = False) -> dict:
    """The scene in one case (shortened to `duration` with the break at `break_time`): per communication point its
    time, the CPU since the start and line 1's integrator steps."""
    scene = load_scene(SCENE)
    data = {**scene.data, "outputs": list(scene.data.get("outputs", [])) + ["solver.nSteps"]}
    if duration:
        data["duration"] = duration
    if calm:
        data["parameters"] = {**data["parameters"], "waves.mode": 0}
    break_time = break_time or float(data["failure"]["time"])
    data["failure"] = {**data["failure"], "time": break_time}
    scene = type(scene).from_data(data, scene.source, scene.directory).with_overrides({"case": case})
    cpu, times = [], []
    t0 = time.process_time()

    def progress(t):
        times.append(t)
        cpu.append(time.process_time() - t0)

    result = run_scene(scene, fmu=fmu, progress=progress)
    return {"t": np.array([0.0] + times), "cpu": np.array([0.0] + cpu), "steps": np.array(result["solver.nSteps"]),
            "total": result.cpu, "duration": scene.duration,
            "break": break_time}


def window(run: dict, start: float, length: float) -> tuple:
    """(CPU [s], line 1's integrator steps) of the communication steps from start to start + length."""
    i0 = int(np.searchsorted(run["t"], start - 1e-9))
    i1 = int(np.searchsorted(run["t"], start + length - 1e-9))
    return run["cpu"][i1] - run["cpu"][i0], int(run["steps"][i1] - run["steps"][i0])


def compute(fmu, quick: bool = False) -> dict:
    short = {"duration": 120.0, "break_time": 60.0} if quick else {}
    intact = timed_run(fmu, "intact", **short)
    transient = timed_run(fmu, "transient", **short)
    tb = transient["break"]
    # one restart: the integrator's first steps from order 1 and a small step, in calm water at rest (the first
    # second of a run less a later one)
    calm = timed_run(fmu, "intact", duration=4.0 * RESTART_WINDOW, calm=True)
    restart = tuple(a - b for a, b in zip(window(calm, 0.0, RESTART_WINDOW), window(calm, 2.0 * RESTART_WINDOW,
                                                                                       RESTART_WINDOW)))
    brk = tuple(a - b for a, b in zip(window(transient, tb, WINDOW), window(intact, tb, WINDOW)))
    rest = transient["duration"] - tb - WINDOW
    return {"intact": intact, "transient": transient, "restart": restart, "break": brk, "window": WINDOW, "after": window(transient, tb + WINDOW, rest), "after_intact": window(intact, tb + WINDOW, rest)}


def markdown(d: dict) -> str:
    i, t = d["intact"], d["transient"]
    w = d["window"]
    rc, rs = d["restart"]
    bc, bs = d["break"]
    out = [f"`{SCENE}`: {t['duration']:g} s simulated, line 1 breaking at {t['break']:g} s; CPU is time.process_time "
           "of the run on one core (the scene runner's Python included).", "",
           "| run | CPU [s] | × real time | line 1's integrator steps |", "|---|---|---|---|",
           f"| intact | {i['total']:.2f} | {i['duration'] / i['total']:.0f} | {int(i['steps'][-1])} |",
           f"| transient (the break at {t['break']:g} s) | {t['total']:.2f} | {t['duration'] / t['total']:.0f} | "
           f"{int(t['steps'][-1])} |", "",
           f"| cost | CPU [s] | line 1's integrator steps |", "|---|---|---|",
           f"| one integrator restart: the first {RESTART_WINDOW:g} s of a calm run at rest less {RESTART_WINDOW:g} s "
           f"from {2 * RESTART_WINDOW:g} s | "
           f"{rc:.3f} | {rs} |",
           f"| the break: {w:g} s from it less the same {w:g} s intact | {bc:.3f} | {bs} |",
           f"| the broken line after that: {t['duration'] - t['break'] - w:g} s less the same intact | "
           f"{d['after'][0] - d['after_intact'][0]:.3f} | {d['after'][1] - d['after_intact'][1]} |"]
    return "\n".join(out)


def main(argv=None) -> int:
    return bench_main(argv, "bench_line_failure", __doc__.split("\n")[0], "CI size: 120 s, the break at 60 s", compute, markdown)

if __name__ == "__main__":
    sys.exit(main())
