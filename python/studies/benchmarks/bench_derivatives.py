"""Cost of the cable's interface derivatives (fmi2GetDirectionalDerivative) against its steps
(scripts/bench_derivatives).

The Hopland cable (20 elements, the defaults) with a driven far end (bottomEnd 3) in a steady tow at
2 kn, stepped by a master that passes the accelerations. From one saved state (fmi2SetFMUstate
invalidates what the FMU keeps, so every request below starts from nothing) it times, as the median
of --repeat runs: one communication step, and the requests of a master: one column, the three
endForce derivatives in one direction of the nine end inputs (what the reference Newton master asks per
direction), the nine end columns one by one, all 18 columns one by one. Wall time per request, and
the same in communication steps of the cable.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.paths import require_fmu
from ucable.units import KNOT

END = ["end.x", "end.y", "end.z", "end.vx", "end.vy", "end.vz", "end.ax", "end.ay", "end.az"]
TOW = ["tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz", "tow.ax", "tow.ay", "tow.az"]
END_FORCE = ["endForce.x", "endForce.y", "endForce.z"]


def parse_args(argv):
    p = argparse.ArgumentParser(prog="scripts/bench_derivatives", description=__doc__.split("\n")[0])
    p.add_argument("--step", type=float, default=0.5, help="communication step [s] (default 0.5)")
    p.add_argument("--repeat", type=int, default=30, help="timed repetitions, median kept (default 30)")
    p.add_argument("--fmu", type=Path, default=None)
    return p.parse_args(argv)


class SteadyTow:
    def __init__(self, fmu, h):
        self.V, self.h, self.t = 2.0 * KNOT, h, 0.0
        self.cable = CableFMU(fmu, parameters={"bottomEnd": 3}, instance_name="bench")
        self.cable.initialize(0.0, inputs=self.inputs())
        for _ in range(4):
            self.step()
            self.t += h
        self.state = self.cable.get_state()

    def inputs(self):
        return {"tow.x": self.V * self.t, "tow.vx": self.V, "end.x": -200.0 + self.V * self.t, "end.z": -150.0,
                "end.vx": self.V, "tow.ax": 0.0, "end.ax": 0.0}

    def step(self):
        self.cable.set(self.inputs())
        self.cable.do_step(self.h, self.t)

    def vrs(self, names):
        return [self.cable.variables[n].valueReference for n in names]


def timed(tow: SteadyTow, action, repeat: int) -> float:
    """Median wall time [s] of action() from the saved state."""
    times = []
    for _ in range(repeat):
        tow.cable.set_state(tow.state, tow.t)
        t0 = time.perf_counter()
        action()
        times.append(time.perf_counter() - t0)
    return float(np.median(times))


def compute(fmu, h: float = 0.5, repeat: int = 30) -> dict:
    tow = SteadyTow(fmu, h)
    slave, out = tow.cable.slave, tow.vrs(END_FORCE)

    def columns(names):
        return lambda: [slave.getDirectionalDerivative(out, tow.vrs([n]), [1.0]) for n in names]

    def direction():
        slave.getDirectionalDerivative(out, tow.vrs(END), [1.0, 0.5, -0.2, 0.3, 0.1, 0.0, 0.05, 0.0, 0.02])

    try:
        rows = {"one communication step": timed(tow, tow.step, repeat),
                "one column (end.x)": timed(tow, columns(["end.x"]), repeat),
                "one direction of the 9 end inputs": timed(tow, direction, repeat),
                "the 9 end columns, one by one": timed(tow, columns(END), repeat),
                "all 18 columns, one by one": timed(tow, columns(TOW + END), repeat)}
    finally:
        tow.cable.free_state(tow.state)
        tow.cable.free()
    return {"step": h, "repeat": repeat, "rows": rows}


def markdown(data: dict) -> str:
    step = data["rows"]["one communication step"]
    lines = [f"| request (h = {data['step']:g} s, median of {data['repeat']}) | wall time [ms] | cable steps |",
             "|---|---:|---:|"]
    for name, seconds in data["rows"].items():
        lines.append(f"| {name} | {seconds * 1e3:.3f} | {seconds / step:.1f} |")
    return "\n".join(lines)


def main(argv=None) -> int:
    args = parse_args(sys.argv[1:] if argv is None else argv)
    fmu = args.fmu or require_fmu()
    print(markdown(compute(fmu, args.step, args.repeat)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
