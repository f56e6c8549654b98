"""CPU cost of the Hopland manoeuvre (660 s) with the UnderwaterCable FMU (run via scripts/bench_hopland).

CPU time is time.process_time() of this process around initialization + all communication steps
(the FMU runs in-process, so fmpy's per-step overhead is included: it is what a Python master pays).
Foundation acceptance: < 1 s CPU for 660 s with nElements = 20 (real-time factor > 660).
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

from ucable.fmu import CableFMU
from ..cases.manoeuvre import hopland_accelerate, run_tow
from ucable.paths import require_fmu

ACCEPT_CPU_S = 1.0


def parse_args(argv):
    p = argparse.ArgumentParser(prog="scripts/bench_hopland", description=__doc__.split("\n")[0])
    p.add_argument("--nElements", type=int, nargs="+", default=[20],
                   help="element counts (default 20)")
    p.add_argument("--tensionTolerance", type=float, nargs="+", default=[None],
                   help="integrator tension tolerances (default: the FMU's default)")
    p.add_argument("--steps", type=float, nargs="+", default=[0.5, 1.0],
                   help="communication steps [s] (default 0.5 1)")
    p.add_argument("--repeat", type=int, default=1, help="runs per case, best CPU kept (default 1)")
    p.add_argument("--input-derivatives", action=argparse.BooleanOptionalAction, default=True,
                   help="pass the tow acceleration via fmi2SetRealInputDerivatives (default on)")
    p.add_argument("--fmu", type=Path, default=None)
    return p.parse_args(argv)


def bench_case(fmu, n_elements, rel_tol, step, repeat, input_derivatives):
    profile, t_end = hopland_accelerate()
    best, final_tension, default_tol = math.inf, math.nan, None
    for _ in range(repeat):
        params = {"nElements": n_elements}
        if rel_tol is not None:
            params["tensionTolerance"] = rel_tol
        cable = CableFMU(fmu, parameters=params)
        try:
            default_tol = (float(cable.variables["tensionTolerance"].start)
                           if "tensionTolerance" in cable.variables else None)
            cpu0 = time.process_time()
            run = run_tow(cable, profile, t_end, step, record_shape=False,
                          use_input_derivatives=input_derivatives)
            cpu = time.process_time() - cpu0
        finally:
            cable.free()
        best = min(best, cpu)
        final_tension = run["towTension"][-1]
    return best, t_end, final_tension, rel_tol if rel_tol is not None else default_tol


def main(argv=None) -> int:
    args = parse_args(sys.argv[1:] if argv is None else argv)
    fmu = args.fmu if args.fmu is not None else require_fmu()
    print(f"Hopland manoeuvre 1.1 -> 2.4 kn (60 s ramp + 600 s), FMU {fmu}, input derivatives "
          f"{'on' if args.input_derivatives else 'off'}")
    print(f"{'nElements':>9} {'tensTol':>8} {'step [s]':>8} {'CPU [s]':>8} {'RT factor':>9} "
          f"{'T(660 s) [N]':>12}  accept (<{ACCEPT_CPU_S:g} s @ 20 el.)")
    for n in args.nElements:
        for tol in args.tensionTolerance:
            for step in args.steps:
                cpu, t_end, T_end, tol_used = bench_case(fmu, n, tol, step, args.repeat,
                                                         args.input_derivatives)
                ok = ""
                if n == 20:
                    ok = "yes" if cpu < ACCEPT_CPU_S else "NO"
                tol_s = f"{tol_used:.0e}" if tol_used is not None else "default"
                print(f"{n:9d} {tol_s:>8} {step:8g} {cpu:8.3f} {t_end / cpu:9.0f} {T_end:12.1f}  {ok}",
                      flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
