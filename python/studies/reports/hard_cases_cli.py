"""Hard-case table (run via scripts/hard_cases): every case with default solver settings.

For each case: result, CPU time, integrator statistics, peak tension and whether the peak tension
converges under refinement (2x elements, tensionTolerance / 100; "yes" if the largest relative change of the
peak is below --threshold). A physically absurd tow jerk must end in a clean fmi2Error whose log names
the SUNDIALS flag and time, with the last good state restorable by fmi2SetFMUstate. The long run
(24 h of steady tow with heave at 1 s steps) reports the drift of the hourly mean tension and the
solver steps per simulated hour. Seabed impact is pending the seabed.
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

from ..cases import hard_cases as hc
from ucable.paths import REPO_ROOT, require_fmu
from ucable.progress import ProgressBar

PENDING = []  # cases not written yet: (name, status)


def parse_args(argv):
    p = argparse.ArgumentParser(prog="scripts/hard_cases", description=__doc__.split("\n")[0])
    p.add_argument("--cases", nargs="*", default=None,
                   help="substrings of case names to run (default: all)")
    p.add_argument("--hours", type=float, default=24.0,
                   help="simulated hours of the long run (default 24; 0 skips it)")
    p.add_argument("--no-refine", action="store_true", help="skip the refinement runs")
    p.add_argument("--threshold", type=float, default=0.05,
                   help="relative peak-tension spread accepted as converged (default 0.05)")
    p.add_argument("--absurd-g", type=float, default=1e5,
                   help="g level of the absurd tow jerk that must fail cleanly (default 1e5, 0.01 s)")
    p.add_argument("--doc", type=Path, default=None,
                   help="also write the table as Markdown to this file (e.g. docs/robustness.md)")
    p.add_argument("--out", type=Path, default=REPO_ROOT / "out" / "hard_cases", help="output directory")
    p.add_argument("--fmu", type=Path, default=None)
    return p.parse_args(argv)


def fmt_stats(s: dict) -> str:
    if not s:
        return "-"
    g = lambda k: int(s.get(k, 0))  # noqa: E731
    return (f"{g('solver.nSteps')} st, {g('solver.nResidualEvals')} res, {g('solver.nJacobianEvals')} jac, "
            f"{g('solver.nNonlinearFailures')} ncf, {g('solver.nErrorTestFailures')} etf")


def row_for(ref: hc.Refinement, case: hc.Case, threshold: float) -> dict:
    b = ref.base
    if b.completed:
        result = f"completed {b.t_reached:g} s" + ("" if b.finite else ", NON-FINITE outputs")
    else:
        result = f"fmi2Error at t = {b.t_reached:g} s: {b.message}"
        if b.state_restored is not None:
            result += f"; last good state restored: {'yes' if b.state_restored else 'NO'}"
    conv = ref.converged(threshold)
    refined = []
    if ref.mesh is not None:
        refined.append(f"2N: {ref.mesh.peak_tension / 1e3:.2f} kN" + ("" if ref.mesh.completed else " (failed)"))
    if ref.tol is not None:
        refined.append(f"tensionTolerance/100: {ref.tol.peak_tension / 1e3:.2f} kN" + ("" if ref.tol.completed else " (failed)"))
    return {
        "case": case.name,
        "setup": case.description,
        "result": result,
        "cpu": f"{b.cpu:.2f}",
        "stats": fmt_stats(b.stats),
        "peak": f"{b.peak_tension / 1e3:.2f}" if math.isfinite(b.peak_tension) else "-",
        "min": f"{b.min_tension / 1e3:.2f}" if math.isfinite(b.min_tension) else "-",
        "converged": "-" if conv is None else (f"{'yes' if conv else 'NO'} (spread {100 * ref.spread:.2g} %; "
                                                + ", ".join(refined) + ")"),
    }


COLUMNS = [("case", "case"), ("setup", "setup"), ("result", "result"), ("cpu", "CPU [s]"),
           ("stats", "integrator statistics"), ("peak", "peak tension [kN]"), ("min", "min tension [kN]"),
           ("converged", "converged under refinement")]


def print_table(rows) -> None:
    for r in rows:
        print(f"\n== {r['case']} ({r['setup']})")
        for key, title in COLUMNS[2:]:
            print(f"   {title:28s} {r[key]}")


def markdown(rows, long_summary: str | None, threshold: float, fmu: Path) -> str:
    lines = ["| " + " | ".join(t for _, t in COLUMNS) + " |", "|" + "---|" * len(COLUMNS)]
    for r in rows:
        lines.append("| " + " | ".join(str(r[k]).replace("|", "/") for k, _ in COLUMNS) + " |")
    for name, status in PENDING:
        lines.append(f"| {name} | - | {status} | - | - | - | - | - |")
    text = "\n".join(lines)
    if long_summary:
        text += "\n\n" + long_summary
    return text


def long_run(fmu, hours: float, out: Path) -> str:
    case = hc.long_run(hours=hours)
    bar = ProgressBar(case.t_end, "long run")
    r = hc.run_case(fmu, case, progress=bar, check_restore=False)
    bar.close("long run done")
    if not r.completed:
        return f"Long run ({case.description}): fmi2Error at t = {r.t_reached:g} s: {r.message}"
    d = hc.hourly_drift(r)
    m, c = d["mean_tension"], d["steps_per_hour"]
    out.mkdir(parents=True, exist_ok=True)
    with (out / "long_run_hourly.csv").open("w") as f:
        f.write("hour,mean_tow_tension_N,solver_steps\n")
        for i, (a, b) in enumerate(zip(m, c)):
            f.write(f"{i + 1},{a:.6f},{b:.0f}\n")
    drift = (m.max() - m.min()) / m.mean() if len(m) else math.nan
    growth = c[-1] / c[0] if len(c) > 1 and c[0] > 0 else math.nan
    return (f"Long run ({case.description}, 1 s steps): completed {r.t_reached / 3600:g} h in {r.cpu:.1f} s CPU "
            f"({fmt_stats(r.stats)}). Hourly mean tow tension {m.min():.2f} .. {m.max():.2f} N "
            f"(spread {100 * drift:.4f} % of the mean); solver steps per simulated hour {c.min():.0f} .. "
            f"{c.max():.0f} (last/first hour {growth:.3f}). Peak tension {r.peak_tension / 1e3:.2f} kN, "
            f"min {r.min_tension / 1e3:.2f} kN. Per-hour values: out/hard_cases/long_run_hourly.csv.")


def main(argv=None) -> int:
    args = parse_args(sys.argv[1:] if argv is None else argv)
    fmu = args.fmu or require_fmu()
    cases = hc.all_cases()
    absurd = hc.tow_jerk(g_level=args.absurd_g, duration=0.01, t_end=12.0)
    absurd = hc.variant(absurd, name=f"absurd: {args.absurd_g:g} g tow jerk", refine=False, expect_failure=True)
    cases.append(absurd)
    if args.cases:
        cases = [c for c in cases if any(s in c.name for s in args.cases)]
    rows = []
    failures = 0
    for case in cases:
        runs = 1 if (args.no_refine or not case.refine) else 3
        bar = ProgressBar(case.t_end * runs, case.name)
        offset = [0.0]

        class Shifted:  # one bar over the base and the refined runs
            def update(self, value, extra=""):
                if value >= case.t_end - 1e-9:
                    offset[0] += case.t_end
                    bar.update(offset[0], extra)
                else:
                    bar.update(offset[0] + value, extra)

        c = hc.variant(case, refine=case.refine and not args.no_refine)
        ref = hc.refine(fmu, c, progress=Shifted())
        bar.close(f"{case.name}: {'completed' if ref.base.completed else 'fmi2Error'}")
        row = row_for(ref, case, args.threshold)
        rows.append(row)
        ok = (not ref.base.completed and ref.base.state_restored) if case.expect_failure else \
            (ref.base.completed and ref.base.finite)
        failures += 0 if ok else 1
    long_summary = long_run(fmu, args.hours, args.out) if args.hours > 0 else None
    print_table(rows)
    if long_summary:
        print("\n" + long_summary)
    args.out.mkdir(parents=True, exist_ok=True)
    table = markdown(rows, long_summary, args.threshold, fmu)
    (args.out / "hard_cases.md").write_text(table + "\n")
    if args.doc:
        write_doc(args.doc, table, args.threshold)
        print(f"\nwrote {args.doc}")
    return 0 if failures == 0 else 1


def write_doc(path: Path, table: str, threshold: float) -> None:
    """Replaces the generated block between the markers of docs/robustness.md (or creates the file)."""
    begin, end = "<!-- hard_cases table begin -->", "<!-- hard_cases table end -->"
    block = f"{begin}\n{table}\n{end}"
    if path.exists():
        text = path.read_text()
        if begin in text and end in text:
            text = text[:text.index(begin)] + block + text[text.index(end) + len(end):]
            path.write_text(text)
            return
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(f"# Robustness: hard cases\n\nGenerated by `scripts/hard_cases --doc {path}` "
                    f"(convergence threshold {100 * threshold:g} %).\n\n{block}\n")


if __name__ == "__main__":
    sys.exit(main())
