"""Line strength checks as the mooring codes ask them (docs/design_checks.md): each line's tension against its
minimum breaking load (MBL) by API RP 2SK (factors of safety per condition and analysis method) and by
DNV-OS-E301 (partial safety factors on the mean and dynamic tension, ULS and ALS, consequence classes 1
and 2). Computation only: `check_lines` gives the rows, `governing` the line that governs;
`ucable.design_report` prints and writes them.

The tension of a line enters through its utilisation u = T / MBL, the FMU's outputs `line[k].fairleadUtilisation`,
`line[k].anchorUtilisation` (at its ends) and `line[k].maxUtilisation` (the largest along it), so a check is
linear in u: API's u_API = FOS max(u), DNV's u_DNV = (g_mean mean(u) + g_dyn (max(u) - mean(u))) / 0.95.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

CASES = ("intact", "damaged", "transient")
ANALYSES = ("dynamic", "quasi-static")
LOCATIONS = {"fairlead": "fairleadUtilisation", "anchor": "anchorUtilisation", "along": "maxUtilisation"}

API = "API RP 2SK, 3rd edition (2005), Section 6.4, Table 2"
# Factor of safety on the minimum breaking strength, by condition and analysis method (API RP 2SK 3rd ed.,
# Section 6.4, Table 2: tension limit 50, 60, 70, 80, 85, 95 % of MBS).
API_FOS = {("intact", "quasi-static"): 2.00, ("intact", "dynamic"): 1.67,
           ("damaged", "quasi-static"): 1.43, ("damaged", "dynamic"): 1.25,
           ("transient", "quasi-static"): 1.18, ("transient", "dynamic"): 1.05}

DNV = "DNV-OS-E301 (October 2010)"
DNV_STRENGTH = 0.95           # Ch.2 Sec.2 B 100: S_c = 0.95 S_mbs without test data of the line's strength
DNV_STRENGTH_CLAUSE = "Ch.2 Sec.2 B 100"
# Partial safety factors (gamma_mean, gamma_dyn) by limit state, consequence class and analysis of the
# dynamic tension (Ch.2 Sec.2 Table C1, ULS; Table C2, ALS).
DNV_FACTORS = {("ULS", 1, "dynamic"): (1.10, 1.50), ("ULS", 2, "dynamic"): (1.40, 2.10),
               ("ULS", 1, "quasi-static"): (1.70, 1.70), ("ULS", 2, "quasi-static"): (2.50, 2.50),
               ("ALS", 1, "dynamic"): (1.00, 1.10), ("ALS", 2, "dynamic"): (1.00, 1.25)}
DNV_CLAUSES = {"ULS": "Ch.2 Sec.2 Table C1", "ALS": "Ch.2 Sec.2 Table C2"}
# Table C1, note: consequence class 1, a characteristic mean tension above 2/3 of the dynamic one: one
# common factor 1.3 on the sum of both.
DNV_MEAN_DOMINATED = (2.0 / 3.0, 1.3)


class CheckError(ValueError):
    """A check that cannot be made (no MBL, no line, a case the standard has no factors for): one line."""


@dataclass
class LineTension:
    """One line's utilisation at one place over a run: its mean and its maximum (T / MBL)."""
    line: int
    location: str        # fairlead, anchor, along
    mean: float
    max: float
    MBL: float           # [N]
    source: str = ""     # the run (a sweep's combination)


@dataclass
class CheckRow:
    line: int
    location: str
    standard: str
    limit: str           # API: the condition; DNV: ULS / ALS
    analysis: str
    mean: float          # mean T / MBL
    max: float           # max T / MBL
    MBL: float
    factors: str         # what multiplies what
    design: float        # design tension [N]
    capacity: float      # [N]
    utilisation: float   # design / capacity: <= 1 passes
    clause: str
    source: str = ""

    @property
    def passed(self) -> bool:
        return self.utilisation <= 1.0


def line_numbers(columns) -> list[int]:
    """The lines whose utilisation a result holds (line[k].maxUtilisation columns)."""
    ks, k = [], 1
    while f"line[{k}].maxUtilisation" in columns or f"line[{k}].maxUtilisationMax" in columns:
        ks.append(k)
        k += 1
    return ks


def broken_lines(columns) -> dict[int, str]:
    """{line: "start" | "during"} of a run's line[k].broken outputs (absent: none broken): broken from its
    first row, or breaking during the run."""
    out = {}
    for k in range(1, 1 + len(columns)):
        b = columns.get(f"line[{k}].broken")
        if b is None:
            continue
        b = np.asarray(b, dtype=float)
        if b.size and b[0] > 0.5:
            out[k] = "start"
        elif np.any(b > 0.5):
            out[k] = "during"
    return out


def case_of(broken: dict[int, str], given: str | None) -> tuple[str, str]:
    """The run's case and why: the user's (`given`), else from its broken lines: one broken from the start
    is the damaged case, one breaking during the run the transient case, none the intact case."""
    if given is not None:
        if given not in CASES:
            raise CheckError(f"--case {given!r}: one of {', '.join(CASES)}")
        return given, "--case"
    if not broken:
        return "intact", "no line[k].broken output is set"
    if any(w == "during" for w in broken.values()):
        during = [k for k, w in broken.items() if w == "during"]
        return "transient", f"line{'s' if len(during) > 1 else ''} {', '.join(map(str, during))} broke during the run"
    return "damaged", f"line{'s' if len(broken) > 1 else ''} {', '.join(map(str, broken))} broken from the start"


def break_row(columns) -> int | None:
    """The first row at which a line is broken, of a run in which a line breaks (None: none does)."""
    rows = [int(np.argmax(np.asarray(columns[f"line[{k}].broken"], dtype=float) > 0.5))
            for k, when in broken_lines(columns).items() if when == "during"]
    return min(rows) if rows else None


def run_tensions(columns, source: str = "", rows: slice = slice(None)) -> list[LineTension]:
    """Each line's utilisation at its fairlead, its anchor and along it over a run (result.csv columns; `rows`
    of it), the lines broken in the run left out (they carry no tension to check)."""
    broken = broken_lines(columns)
    out = []
    for k in line_numbers(columns):
        if k in broken:
            continue
        mbl = np.asarray(columns.get(f"line[{k}].MBL", [0.0]), dtype=float)
        mbl = float(np.nanmax(mbl)) if mbl.size else 0.0
        for where, name in LOCATIONS.items():
            u = columns.get(f"line[{k}].{name}")
            if u is None:
                continue
            u = np.asarray(u, dtype=float)[rows]
            if u.size:
                out.append(LineTension(k, where, float(np.nanmean(u)), float(np.nanmax(u)), mbl, source))
    return out


def check_run(columns, given: str | None, analysis: str = "dynamic", consequence: tuple[int, ...] = (1, 2),
              standards: tuple[str, ...] = ("api", "dnv")) -> Verdict:
    """The verdict of one run: its case from `given` or its broken lines (case_of). A run in which a line
    breaks is checked as intact up to the break and as transient from it on (the rows say which part)."""
    case, why = case_of(broken_lines(columns), given)
    at = break_row(columns) if given is None else None
    if at is None:
        return verdict(check_lines(run_tensions(columns), case, analysis, consequence, standards), case, why)
    t = np.asarray(columns["time"], dtype=float)
    before = run_tensions(columns, f"before the break (t < {t[at]:g} s)", slice(0, at))
    after = run_tensions(columns, f"from the break (t >= {t[at]:g} s)", slice(at, None))
    rows = (check_lines(before, "intact", analysis, consequence, standards) if before else []) + \
        check_lines(after, case, analysis, consequence, standards)
    return verdict(rows, case, why + "; intact before the break")


def sweep_tensions(rows: list[dict]) -> list[LineTension]:
    """The same from a sweep's results (a row per run: line[k].<u>Mean, line[k].<u>Max, line[k].MBL)."""
    out = []
    for i, r in enumerate(rows):
        if r.get("status", "ok") != "ok":
            continue
        seed = r.get("waves.seed")
        source = f"waves.seed {seed:g}" if isinstance(seed, float) and np.isfinite(seed) else f"run {i + 1}"
        for k in line_numbers(r):
            if r.get(f"line[{k}].brokenAny", 0.0) > 0.5:
                continue
            for where, name in LOCATIONS.items():
                mean, high = r.get(f"line[{k}].{name}Mean"), r.get(f"line[{k}].{name}Max")
                if mean is None or high is None or not np.isfinite(high):
                    continue
                out.append(LineTension(k, where, float(mean), float(high), float(r.get(f"line[{k}].MBL", 0.0)),
                                       str(source)))
    return out


def api_row(t: LineTension, case: str, analysis: str) -> CheckRow:
    fos = API_FOS[(case, analysis)]
    return CheckRow(t.line, t.location, "API RP 2SK", case, analysis, t.mean, t.max, t.MBL,
                    f"FOS {fos:.2f} x Tmax", fos * t.max * t.MBL, t.MBL, fos * t.max,
                    f"{API}: {case}, {analysis}: FOS {fos:.2f}", t.source)


def dnv_row(t: LineTension, limit: str, consequence: int, analysis: str) -> CheckRow:
    key = (limit, consequence, analysis)
    if key not in DNV_FACTORS:
        raise CheckError(f"DNV-OS-E301 {limit} with a {analysis} analysis: the standard gives factors for a "
                         f"dynamic analysis only (--analysis dynamic)")
    g_mean, g_dyn = DNV_FACTORS[key]
    dyn = max(t.max - t.mean, 0.0)
    clause = f"{DNV} {DNV_CLAUSES[limit]}, S_c = {DNV_STRENGTH} MBL ({DNV_STRENGTH_CLAUSE})"
    ratio, common = DNV_MEAN_DOMINATED
    if limit == "ULS" and consequence == 1 and analysis == "dynamic" and t.mean > ratio * dyn:
        design, factors = common * (t.mean + dyn), f"{common:.2f} x (Tmean + Tdyn), Tmean > 2/3 Tdyn"
        clause += ", note to Table C1"
    else:
        design, factors = g_mean * t.mean + g_dyn * dyn, f"{g_mean:.2f} Tmean + {g_dyn:.2f} Tdyn"
    return CheckRow(t.line, t.location, "DNV-OS-E301", f"{limit} CC{consequence}", analysis, t.mean, t.max, t.MBL,
                    factors, design * t.MBL, DNV_STRENGTH * t.MBL, design / DNV_STRENGTH, clause, t.source)


def dnv_limit(case: str) -> str:
    """DNV-OS-E301's limit state of a case: intact ULS; after a line failure (damaged, transient) ALS."""
    return "ULS" if case == "intact" else "ALS"


def check_lines(tensions: list[LineTension], case: str, analysis: str = "dynamic",
                consequence: tuple[int, ...] = (1, 2), standards: tuple[str, ...] = ("api", "dnv")) -> list[CheckRow]:
    """The rows of every check of every line and place: API RP 2SK's for `case`, DNV-OS-E301's limit state of
    `case` for each consequence class. A line without an MBL is a CheckError naming it."""
    if analysis not in ANALYSES:
        raise CheckError(f"--analysis {analysis!r}: one of {', '.join(ANALYSES)}")
    if not tensions:
        raise CheckError("no line utilisation in the results (line[k].maxUtilisation): a result of this version's "
                         "ucable run, sweep or check is needed")
    rows = []
    for t in tensions:
        if not (t.MBL > 0.0) or not math.isfinite(t.MBL):
            raise CheckError(f"line {t.line}: MBL = {t.MBL:g} N: no breaking load to check against (give the deck's "
                             f"line type an MBL column, name it for its material, or set the parameter MBL)")
        if "api" in standards:
            rows.append(api_row(t, case, analysis))
        if "dnv" in standards:
            rows += [dnv_row(t, dnv_limit(case), c, analysis) for c in consequence]
    return rows


def governing(rows: list[CheckRow]) -> CheckRow:
    """The row of the largest utilisation."""
    return max(rows, key=lambda r: r.utilisation)


@dataclass
class Verdict:
    rows: list[CheckRow]
    case: str
    why: str
    governing: CheckRow
    failed: list[CheckRow] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        return not self.failed


def verdict(rows: list[CheckRow], case: str, why: str) -> Verdict:
    return Verdict(rows, case, why, governing(rows), [r for r in rows if not r.passed])


def run_statistics(columns) -> dict:
    """What a sweep keeps of a run for the checks and the extremes: per line its MBL, the mean and maximum
    of each utilisation, the maximum fairlead tension and whether it broke (line[k].brokenAny)."""
    out = {}
    broken = broken_lines(columns)
    lines = sorted(set(line_numbers(columns)) | {k for k in range(1, 1 + len(columns))
                                                 if f"line[{k}].fairleadTension" in columns})
    for k in lines:
        mbl = np.asarray(columns.get(f"line[{k}].MBL", [0.0]), dtype=float)
        out[f"line[{k}].MBL"] = float(np.nanmax(mbl)) if mbl.size else 0.0
        for name in LOCATIONS.values():
            u = columns.get(f"line[{k}].{name}")
            if u is not None:
                u = np.asarray(u, dtype=float)
                out[f"line[{k}].{name}Mean"] = float(np.nanmean(u))
                out[f"line[{k}].{name}Max"] = float(np.nanmax(u))
        tension = columns.get(f"line[{k}].fairleadTension")
        if tension is not None:
            out[f"line[{k}].fairleadTensionMax"] = float(np.nanmax(np.asarray(tension, dtype=float)))
        out[f"line[{k}].brokenAny"] = 1.0 if k in broken else 0.0
    return out


def statistics_units(name: str) -> str | None:
    """The unit of a run_statistics column (None: not one of them)."""
    if not name.startswith("line["):
        return None
    quantity = name.split(".", 1)[1]
    if quantity in ("MBL", "fairleadTensionMax"):
        return "N"
    if quantity == "brokenAny" or any(quantity.startswith(u) for u in LOCATIONS.values()):
        return "-"
    return None
