"""The report of `ucable check`: the rows of ucable.design_check as a printed table and as check.csv, and the
sentence that names the governing line. Printing and writing only; the numbers come from design_check."""

from __future__ import annotations

from .design_check import CheckRow, Verdict
from .tables import write_rows

CSV_COLUMNS = ["line", "location", "standard", "limit", "analysis", "mean T/MBL [-]", "max T/MBL [-]", "MBL [N]",
               "factors", "design tension [N]", "capacity [N]", "utilisation [-]", "result", "clause", "run"]


def _record(r: CheckRow) -> dict:
    return dict(zip(CSV_COLUMNS, [r.line, r.location, r.standard, r.limit, r.analysis, r.mean, r.max, r.MBL,
                                  r.factors, r.design, r.capacity, r.utilisation, "pass" if r.passed else "FAIL",
                                  r.clause, r.source]))


def write_check_csv(v: Verdict, path) -> None:
    """check.csv: one row per line, place and check (the columns of CSV_COLUMNS)."""
    write_rows(path, CSV_COLUMNS, [_record(r) for r in v.rows])


def format_check(v: Verdict) -> str:
    """The table ucable check prints, then the governing line and the verdict."""
    head = ["line", "where", "standard", "limit", "mean u", "max u", "MBL [kN]", "design [kN]", "capacity [kN]",
            "util.", "result"]
    body = [[str(r.line), r.location, r.standard, r.limit, f"{r.mean:.3f}", f"{r.max:.3f}", f"{r.MBL / 1e3:.0f}",
             f"{r.design / 1e3:.0f}", f"{r.capacity / 1e3:.0f}", f"{r.utilisation:.3f}",
             "pass" if r.passed else "FAIL"] for r in v.rows]
    widths = [max(len(h), *(len(b[i]) for b in body)) for i, h in enumerate(head)]
    lines = [f"case: {v.case} ({v.why}); u = tension / MBL; analysis {v.rows[0].analysis}",
             "  ".join(h.ljust(w) for h, w in zip(head, widths))]
    lines += ["  ".join(c.ljust(w) for c, w in zip(b, widths)) for b in body]
    lines.append(governing_sentence(v))
    return "\n".join(lines)


def governing_sentence(v: Verdict) -> str:
    g = v.governing
    margin = 1.0 - g.utilisation
    where = f"line {g.line} at its {g.location if g.location != 'along' else 'most loaded point'}"
    run = f" ({g.source})" if g.source else ""
    said = (f"governing: {where}{run}, {g.standard} {g.limit}: utilisation {g.utilisation:.3f} "
            f"({g.factors}; {g.clause})")
    if v.passed:
        return f"{said}: passes with a margin of {100 * margin:.1f} % of its capacity"
    return (f"{said}: FAILS by {100 * -margin:.1f} % of its capacity; {len(v.failed)} of {len(v.rows)} checks fail")
