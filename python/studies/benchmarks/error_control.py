"""Tension error against the integrator's tension tolerance, on the benchmark scenes.

    scripts/error_control [--short] [--tolerances 1e-1 1e-2 ...] [--doc docs/error_control.md]

Each scene (the Hopland tow manoeuvre, the heave case, the stiff power cable and the chain mooring
of scripts/bench_work_precision, with their communication steps and exact input derivatives) is
flown at every tensionTolerance of the list and once at tensionTolerance 1e-8, the reference: same
mesh (20 elements), same communication step, so the difference is the time integration's error
alone. The errors are those of the top tension |towForce| at the communication points: max
|T - T_ref| relative to the range of T_ref, RMS relative to the RMS of T_ref, and the max in
newtons against the tolerance in newtons (tensionTolerance x solver.tensionScale). `--short` runs
the first 20-80 s of each scene (what tests/python/test_error_control.py checks). Computes first
(`curves`), then writes Markdown (`markdown`).

`--position`: instead, the position tolerance at loose tension tolerances on the chain mooring (the
full 120 s): pairs of tensionTolerance and positionTolerance against the same reference
(`position_rows`, `position_markdown`; its own markers in the doc).
"""

from __future__ import annotations

import argparse
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..cases import heave
from ucable.fmu import CableFMU
from ucable.paths import REPO_ROOT, require_fmu
from ucable.progress import ProgressBar

TOLERANCES = (1e-1, 1e-2, 1e-3, 1e-4, 1e-5)
DEFAULT_POSITION_TOLERANCE = 1e-3  # [m], the FMU's default positionTolerance
# (tensionTolerance, positionTolerance [m]) of the position study
POSITION_PAIRS = ((1e-1, 1e-3), (1e-1, 1e-2), (1e-1, 1e-1), (1e-2, 1e-3), (1e-2, 1e-1), (1e-3, 1e-3), (1e-3, 1e-1))
REFERENCE_TOLERANCE = 1e-8
DEFAULT_TOLERANCE = 1e-3  # the FMU's default tensionTolerance (schema/variables.toml)
STATS = ["solver.nSteps", "solver.nResidualEvals", "solver.nJacobianEvals"]


@dataclass
class ErrorControlCase:
    name: str
    title: str
    parameters: dict
    trajectory: object  # .state(t) -> (position, velocity, acceleration) of the tow point
    step: float
    t_end: float
    inputs: dict = field(default_factory=dict)  # constant inputs (current)


@dataclass
class ErrorControlRun:
    t: np.ndarray
    tension: np.ndarray  # |towForce| at the communication points
    tension_scale: float
    cpu: float
    stats: dict


def scenes(short: bool = False) -> dict:
    """The benchmark scenes (full length, or the first 20-80 s with short=True)."""
    from . import work_precision as wp
    cases = wp.make_cases()
    out = {}
    for name, t_short in (("hopland", 80.0), ("stiff", 20.0), ("mooring", 20.0)):
        c = cases[name]
        p = dict(c.line)
        p.update(c.fmu_params)
        p["nElements"] = 20
        out[name] = ErrorControlCase(name, c.title, p, c.traj, c.comm_step, t_short if short else c.t_end)
    out["heave"] = ErrorControlCase("heave", "Heave: 1000 m umbilical, 10 t body, 2 m / 10 s, 0.5 m/s current",
                         heave.parameters(20), heave.RampedHeave(), 0.1, 30.0 if short else 200.0,
                         {"current.x": heave.CURRENT})
    return {k: out[k] for k in ("hopland", "heave", "stiff", "mooring")}


def run(fmu, scene: ErrorControlCase, extra: dict | None = None) -> ErrorControlRun:
    """One run of `scene` with the FMU's defaults plus `extra` parameters."""
    params = dict(scene.parameters)
    params.update(extra or {})
    n = int(round(scene.t_end / scene.step))
    times = np.arange(n + 1) * scene.step
    tension = np.zeros(n + 1)
    names = ["towForce.x", "towForce.y", "towForce.z"]
    cable = CableFMU(fmu, parameters=params, instance_name=scene.name)
    try:
        def inputs(t):
            p, v, a = scene.trajectory.state(t)
            return {"tow.x": p[0], "tow.y": p[1], "tow.z": p[2], "tow.vx": v[0], "tow.vy": v[1],
                    "tow.vz": v[2]}, a

        inp, _ = inputs(0.0)
        inp.update(scene.inputs)
        cable.initialize(0.0, scene.t_end, inputs=inp)
        tension[0] = np.linalg.norm(cable.get_reals(names))
        cpu0 = time.process_time()
        for k in range(n):
            inp, a = inputs(times[k])
            cable.set(inp)
            cable.set_input_derivatives(["tow.vx", "tow.vy", "tow.vz"], 1, a)
            cable.do_step(times[k + 1] - times[k], t=times[k])
            tension[k + 1] = np.linalg.norm(cable.get_reals(names))
        cpu = time.process_time() - cpu0
        stats = dict(zip(STATS, cable.get_reals(STATS)))
        scale = cable.get("solver.tensionScale")
    finally:
        cable.free()
    return ErrorControlRun(times, tension, scale, cpu, stats)


def errors(r: ErrorControlRun, ref: ErrorControlRun) -> dict:
    """Top-tension errors of r against ref (t > 0)."""
    d = np.abs(r.tension[1:] - ref.tension[1:])
    T = ref.tension[1:]
    return {"max_range": float(d.max() / np.ptp(T)), "rms_rel": float(np.sqrt(np.mean(d**2) / np.mean(T**2))),
            "max_newton": float(d.max())}


def curves(fmu, short: bool = False, tolerances=TOLERANCES, names=None, extra: dict | None = None,
           references: dict | None = None) -> dict:
    """{scene: {"reference": ErrorControlRun, "rows": [(tensionTolerance, ErrorControlRun, errors)]}}. `extra`: further
    parameters of the rows (not of the reference, which is the FMU's defaults at 1e-8); `references`:
    the reference runs of an earlier call ({scene: ErrorControlRun}), not flown again."""
    sc = scenes(short)
    names = names or list(sc)
    bar = ProgressBar(len(names) * (len(tolerances) + 1), label="error control")
    out, k = {}, 0
    for name in names:
        ref = (references or {}).get(name) or run(fmu, sc[name], {"tensionTolerance": REFERENCE_TOLERANCE})
        k += 1
        bar.update(k, name)
        rows = []
        for tol in tolerances:
            r = run(fmu, sc[name], {**(extra or {}), "tensionTolerance": tol})
            rows.append((tol, r, errors(r, ref)))
            k += 1
            bar.update(k, f"{name} {tol:g}")
        out[name] = {"scene": sc[name], "reference": ref, "rows": rows}
    bar.close("done")
    return out


def monotone(values) -> bool:
    return all(b <= a for a, b in zip(values, values[1:]))


def markdown(result: dict) -> str:
    lines = []
    for name, c in result.items():
        sc, ref = c["scene"], c["reference"]
        lines += [f"### {sc.title} ({sc.t_end:g} s, {sc.step:g} s steps)", "",
                  f"Tension scale {ref.tension_scale / 1e3:.1f} kN; reference (tensionTolerance "
                  f"{REFERENCE_TOLERANCE:g}): {ref.stats['solver.nSteps']:.0f} IDA steps, CPU {ref.cpu:.2f} s.", "",
                  "| tensionTolerance | tolerance [N] | max error [N] | max error / range | RMS error / RMS | "
                  "IDA steps | residual evals | CPU [s] |",
                  "|---|---|---|---|---|---|---|---|"]
        for tol, r, e in c["rows"]:
            mark = " (default)" if tol == DEFAULT_TOLERANCE else ""
            lines.append(f"| {tol:g}{mark} | {tol * r.tension_scale:.3g} | {e['max_newton']:.3g} | "
                         f"{e['max_range']:.1e} | {e['rms_rel']:.1e} | {r.stats['solver.nSteps']:.0f} | "
                         f"{r.stats['solver.nResidualEvals']:.0f} | {r.cpu:.2f} |")
        errs = [e["max_newton"] for _, _, e in c["rows"]]
        within = all(e["max_newton"] <= tol * r.tension_scale for tol, r, e in c["rows"])
        lines += ["", f"Max error monotone in the tolerance: {'yes' if monotone(errs) else 'NO'}; "
                  f"below the tolerance in newtons at every setting: {'yes' if within else 'NO'}.", ""]
    return "\n".join(lines)


def position_rows(fmu, name="mooring", short=False, pairs=POSITION_PAIRS):
    """The scene at each (tensionTolerance, positionTolerance) of `pairs` against its reference
    (tensionTolerance 1e-8, the default position tolerance): (scene, reference, [(tol, pos, run, errors)])."""
    scene = scenes(short)[name]
    bar = ProgressBar(len(pairs) + 1, label="position tolerance")
    ref = run(fmu, scene, {"tensionTolerance": REFERENCE_TOLERANCE})
    rows = []
    for k, (tol, pos) in enumerate(pairs):
        bar.update(k + 1, f"{tol:g} / {pos:g} m")
        r = run(fmu, scene, {"tensionTolerance": tol, "positionTolerance": pos})
        rows.append((tol, pos, r, errors(r, ref)))
    bar.close("done")
    return scene, ref, rows


def position_markdown(scene, ref, rows) -> str:
    def mark(value, default):
        return f"{value:g}" + (" (default)" if value == default else "")
    lines = [f"{scene.title} ({scene.t_end:g} s, {scene.step:g} s steps, {scene.parameters['nElements']} elements); "
             f"tension scale {ref.tension_scale / 1e3:.1f} kN; errors against tensionTolerance "
             f"{REFERENCE_TOLERANCE:g} on the same mesh.", "",
             "| tensionTolerance | positionTolerance [m] | tolerance [N] | max error [N] | max error / range | "
             "RMS error / RMS | IDA steps | CPU [s] |", "|---|---|---|---|---|---|---|---|"]
    for tol, pos, r, e in rows:
        lines.append(f"| {mark(tol, DEFAULT_TOLERANCE)} | {mark(pos, DEFAULT_POSITION_TOLERANCE)} | "
                     f"{tol * r.tension_scale:.3g} | {e['max_newton']:.3g} | {e['max_range']:.1e} | "
                     f"{e['rms_rel']:.1e} | {r.stats['solver.nSteps']:.0f} | {r.cpu:.2f} |")
    within = all(e["max_newton"] <= tol * r.tension_scale for tol, _, r, e in rows)
    lines += ["", f"Below the tension tolerance in newtons at every setting: {'yes' if within else 'NO'}."]
    return "\n".join(lines)


BEGIN, END = "<!-- error_control table begin -->", "<!-- error_control table end -->"
POSITION_BEGIN, POSITION_END = "<!-- position table begin -->", "<!-- position table end -->"


def splice(doc: Path, begin: str, end: str, text: str) -> None:
    """Replaces what lies between the markers `begin` and `end` in `doc` with `text`."""
    old = doc.read_text()
    a, b = old.index(begin) + len(begin), old.index(end)
    doc.write_text(old[:a] + "\n" + text + "\n" + old[b:])


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="scripts/error_control", description=__doc__.split("\n")[0])
    p.add_argument("--short", action="store_true", help="the short scenes of the tests (seconds, not minutes)")
    p.add_argument("--tolerances", type=float, nargs="+", default=list(TOLERANCES))
    p.add_argument("--scenes", nargs="+", default=None, help="hopland heave stiff mooring (default: all)")
    p.add_argument("--fmu", type=Path, default=None)
    p.add_argument("--position", action="store_true",
                   help="the position tolerance at loose tension tolerances (chain mooring) instead")
    p.add_argument("--doc", type=Path, default=None, help="replace the table between the markers in this file")
    args = p.parse_args(sys.argv[1:] if argv is None else argv)
    fmu = args.fmu or require_fmu()
    if args.position:
        text, markers = position_markdown(*position_rows(fmu, short=args.short)), (POSITION_BEGIN, POSITION_END)
    else:
        text, markers = markdown(curves(fmu, args.short, args.tolerances, args.scenes)), (BEGIN, END)
    print(text)
    if args.doc is not None:
        doc = args.doc if args.doc.is_absolute() else REPO_ROOT / args.doc
        splice(doc, *markers, text)
        print(f"wrote {doc}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
