"""Integrator steps per simulated second against the communication step, on the heave case.

    scripts/comm_steps [--fmu LABEL=PATH ...] [--steps 0.01 0.02 ...] [--t-end 200] [--doc PATH]

For each FMU (default: the build's) and each communication step, the heave case of studies.cases.heave is
flown by a master passing position, velocity and acceleration (der(tow.vz)) at every communication
point, with the FMU's default solver settings. The table gives IDA steps and residual evaluations per
simulated second, the CPU time, and the top-tension error against a reference run (the first FMU,
0.005 s steps, relTol 1e-10), from t = 10 s (after the ramp) on. Computes first (`study`), then
writes Markdown (`markdown`).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from . import heave
from ucable.paths import REPO_ROOT, require_fmu
from ucable.progress import ProgressBar

DEFAULT_STEPS = (0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0)
REFERENCE = dict(step=0.005, extra={"relTol": 1e-10, "absTol": 1e-8})


def study(fmus: dict, steps=DEFAULT_STEPS, t_end: float = 200.0, n_elements: int = 20) -> dict:
    """{label: [(step, HeaveRun, errors)]} and the reference run."""
    first = next(iter(fmus.values()))
    total = t_end * (1 + len(fmus) * len(steps))
    bar = ProgressBar(total, label="comm steps")
    done = [0.0]

    def progress(base):
        return lambda t: bar.update(base + t)

    ref = heave.run(first, REFERENCE["step"], t_end, n_elements, extra=REFERENCE["extra"],
                    instance_name="reference", progress=progress(0.0))
    done[0] = t_end
    rows = {}
    for label, path in fmus.items():
        rows[label] = []
        for h in steps:
            r = heave.run(path, h, t_end, n_elements, instance_name=f"{label}_{h:g}", progress=progress(done[0]))
            done[0] += t_end
            rows[label].append((h, r, heave.tension_errors(r, ref)))
    bar.close("done")
    return {"rows": rows, "reference": ref, "t_end": t_end, "n_elements": n_elements}


def markdown(result: dict, notes: dict | None = None) -> str:
    rows, ref = result["rows"], result["reference"]
    labels = list(rows)
    head = ["communication step [s]"]
    for what in ("IDA steps per simulated s", "residual evals per simulated s", "CPU [s]",
                 "top tension error (RMS, rel.)"):
        head += [f"{what}: {lab}" for lab in labels]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    steps = [h for h, _, _ in rows[labels[0]]]
    t_end = result["t_end"]
    for i, h in enumerate(steps):
        cells = [f"{h:g}"]
        cells += [f"{rows[lab][i][1].steps_per_second():.1f}" for lab in labels]
        cells += [f"{rows[lab][i][1].stats['solver.nResidualEvals'] / t_end:.0f}" for lab in labels]
        cells += [f"{rows[lab][i][1].cpu:.2f}" for lab in labels]
        cells += [f"{rows[lab][i][2]['rms']:.1e}" for lab in labels]
        lines.append("| " + " | ".join(cells) + " |")
    text = "\n".join(lines)
    legend = "".join(f"\n- **{lab}**: {notes[lab]}" for lab in labels if notes and lab in notes)
    return (f"{text}\n\nReference: {ref.stats['solver.nSteps']:.0f} IDA steps "
            f"({ref.steps_per_second():.0f} per simulated s) at {REFERENCE['step']:g} s communication steps, "
            f"relTol {REFERENCE['extra']['relTol']:g}, absTol {REFERENCE['extra']['absTol']:g}; "
            f"{result['n_elements']} elements, {t_end:g} s simulated, errors from t = {heave.PERIOD:g} s."
            + legend + "\n")


def parse_args(argv):
    p = argparse.ArgumentParser(prog="scripts/comm_steps", description=__doc__.split("\n")[0])
    p.add_argument("--fmu", action="append", default=None, metavar="LABEL=PATH",
                   help="an FMU to measure (repeat to compare; default: now=build/UnderwaterCable.fmu)")
    p.add_argument("--note", action="append", default=[], metavar="LABEL=TEXT",
                   help="what an FMU label stands for (printed under the table)")
    p.add_argument("--steps", type=float, nargs="+", default=list(DEFAULT_STEPS))
    p.add_argument("--t-end", type=float, default=200.0)
    p.add_argument("--elements", type=int, default=20)
    p.add_argument("--doc", type=Path, default=None,
                   help="replace the table between the markers in this Markdown file")
    return p.parse_args(argv)


BEGIN, END = "<!-- comm_steps table begin -->", "<!-- comm_steps table end -->"


def main(argv=None) -> int:
    args = parse_args(sys.argv[1:] if argv is None else argv)
    fmus = {}
    for item in args.fmu or [f"now={require_fmu()}"]:
        label, _, path = item.partition("=")
        fmus[label] = Path(path)
    notes = dict(n.partition("=")[::2] for n in args.note)
    result = study(fmus, args.steps, args.t_end, args.elements)
    text = markdown(result, notes)
    print(text)
    if args.doc is not None:
        doc = args.doc if args.doc.is_absolute() else REPO_ROOT / args.doc
        old = doc.read_text()
        a, b = old.index(BEGIN) + len(BEGIN), old.index(END)
        doc.write_text(old[:a] + "\n" + text + old[b:])
        print(f"wrote {doc}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
