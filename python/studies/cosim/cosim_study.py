"""Coupling study (scripts/cosim_study): communication step and towed-body coupling, as a
Markdown table for docs/cosimulation.md.

Scene: the vessel turns 90 deg to port at 2.4 kn (scripts/manoeuvre turn90), first 200 s, with
  - a free cable end,
  - the towed body inside the FMU (bottomEnd 2: one implicit solve, no coupling error),
  - the same body as a Python partner (bottomEnd 3, end.* inputs, endForce.* outputs),
each at communication steps 0.01 .. 1 s, Gauss-Seidel with input derivatives. Errors are against the
0.01 s run of the internal body (body cases) or of the free end: max |towTension - ref| and
max |endPosition - ref| over the common communication points.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

from .masters import Master, run_scene
from ucable.paths import REPO_ROOT, require_fmu
from ucable.progress import ProgressBar
from .scenes import make_scene

STEPS = [0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0]
T_END = 200.0


def parse_args(argv):
    p = argparse.ArgumentParser(prog="scripts/cosim_study", description=__doc__.split("\n")[0],
                                formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    p.add_argument("--steps", type=float, nargs="+", default=STEPS, help="communication steps [s]")
    p.add_argument("--t-end", type=float, default=T_END, help="simulated time [s]")
    p.add_argument("--master", default="gauss-seidel", choices=["gauss-seidel", "iterative"])
    p.add_argument("--out", type=Path, default=REPO_ROOT / "out" / "cosim_study" / "table.md",
                   help="Markdown table (use docs/cosimulation_table.md to update the docs)")
    p.add_argument("--fmu", type=Path, default=None)
    return p.parse_args(argv)


def has_external(fmu) -> bool:
    m = Master(make_scene("turn90", t_end=1.0), fmu)
    try:
        return "end.vx" in m.cable.variables
    finally:
        m.free()


def one(fmu, coupling, h, t_end, master):
    scene = make_scene("turn90", t_end=t_end, step=h, coupling=coupling, master=master)
    try:
        r = run_scene(scene, fmu, record_shape=False)
    except Exception as e:  # an unstable coupling may end in an FMU error: that is a result
        return None, f"{type(e).__name__}: {str(e)[:60]}"
    T = r["towTension"]
    if not np.all(np.isfinite(T)) or np.max(np.abs(T)) > 1e6:
        return r, "diverged"
    return r, ""


def main(argv=None) -> int:
    args = parse_args(sys.argv[1:] if argv is None else argv)
    fmu = args.fmu if args.fmu is not None else require_fmu()
    couplings = ["none", "internal"] + (["external"] if has_external(fmu) else [])
    steps = sorted(args.steps)
    bar = ProgressBar(len(couplings) * len(steps), label="cosim_study")
    results = {}
    done = 0
    for c in couplings:
        for h in steps:
            cpu0 = time.process_time()
            r, note = one(fmu, c, h, args.t_end, args.master)
            results[(c, h)] = (r, note, time.process_time() - cpu0)
            done += 1
            bar.update(done, f"{c} {h:g} s {note}")
    bar.close("done")

    def ref_for(c):
        return results[("none" if c == "none" else "internal", steps[0])][0]

    lines = [f"Turn 90 deg at 2.4 kn, {args.t_end:g} s, 20 elements, {args.master}; reference: "
             f"the {steps[0]:g} s run of the free end (free rows) or of the internal body (body rows).",
             "",
             "| far end | step [s] | steps | max \\|ΔT_tow\\| [N] | max \\|Δ end position\\| [m] | "
             "T_tow(200 s) [N] | end depth (200 s) [m] | CPU [s] | note |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    for c in couplings:
        ref = ref_for(c)
        for h in steps:
            r, note, cpu = results[(c, h)]
            if r is None or note:
                lines.append(f"| {c} | {h:g} | {int(round(args.t_end / h))} | - | - | - | - | "
                             f"{cpu:.2f} | {note or 'failed'} |")
                continue
            stride = int(round(h / steps[0]))
            n = len(r.time)
            if ref is not None and (n - 1) * stride <= len(ref.time) - 1:
                dT = np.max(np.abs(r["towTension"] - ref["towTension"][::stride][:n]))
                dp = max(np.max(np.abs(r[f"endPosition.{q}"] - ref[f"endPosition.{q}"][::stride][:n]))
                         for q in "xyz")
                err = f"{dT:.3g} | {dp:.3g}"
            else:
                err = "- | -"
            lines.append(f"| {c} | {h:g} | {n - 1} | {err} | {r['towTension'][-1]:.1f} | "
                         f"{r.end_depth[-1]:.2f} | {cpu:.2f} | {note} |")
    if "external" not in couplings:
        lines += ["", "The FMU has no end.* inputs (bottomEnd 3): external rows not run."]
    text = "\n".join(lines) + "\n"
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(text)
    print(text)
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
