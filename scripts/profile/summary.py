"""Summary of the callgrind runs of scripts/profile_callgrind (computes first, writes Markdown second).

    python summary.py DOC(0|1) DOC_PATH LABEL:SCENE:DIR ...

Each DIR holds driver.txt (the driver's "key value" statistics) and annotate.txt
(callgrind_annotate --inclusive=yes). Prints the Markdown; with DOC = 1 also writes DOC_PATH.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

# (row label, regular expression on callgrind_annotate's function column)
ROWS = [
    ("residual (uc::CableSimulation::residual)", r"uc::CableSimulation::residual\("),
    ("element residuals (uc::CableModel::element_residual)", r"uc::CableModel::element_residual\("),
    ("wave kinematics, sums over the components (uc::SeaState::kinematics)", r"uc::SeaState::kinematics\("),
    ("wave kinematics, Taylor polynomials (uc::SeaState::expanded_kinematics, their expansions included)",
     r"uc::SeaState::expanded_kinematics\("),
    ("wave kinematics, expansions (uc::SeaState::expand)", r"uc::SeaState::expand\("),
    ("cable Jacobian (uc::CableSimulation::jacobian)", r"uc::CableSimulation::jacobian\("),
    ("Newton matrix (Jacobian callback, assembly included)", r"uc::Integrator::jacobian_callback\("),
    ("band LU factorization (ls_setup)", r"uc::Integrator::ls_setup\("),
    ("linear solves (ls_solve)", r"uc::Integrator::ls_solve\("),
    ("IDA solve (IDASolve)", r"IDASolve\b"),
    ("uc_do_step", r"uc_do_step\b"),
]
SCENES = {
    "hopland": "Hopland cable (300 m, 20 elements), steady 1.1 kn then the ramp to 2.4 kn, 60 s, 0.5 s steps "
               "(scripts/profile/hopland_driver.c)",
    "heave": "heave case (1000 m umbilical, 10 t body, 2 m / 10 s heave, 0.5 m/s current, 20 elements), "
             "30 s, 0.1 s steps (scripts/profile/heave_driver.c)",
    "stiff": "stiff power cable with seabed (250 m, EA 7e8 N, EI 2e4 N m2, 100 m depth, surge 3 m at 8 s, "
             "20 elements), 30 s, 0.05 s steps (scripts/profile/stiff_driver.c)",
    "heave_waves": "heave case in a JONSWAP sea (Hs 3 m, Tp 10 s, 200 components, the water's motion acting on "
                   "the umbilical), 20 elements, 30 s, 0.1 s steps (scripts/profile/heave_waves_driver.c)",
    "chain": "chain mooring with seabed (835 m, EA 7.5e8 N, tension only, 200 m depth, surge 5 m at 12 s), "
             "tensionTolerance 0.1, 30 s, 0.05 s steps (scripts/profile/chain_driver.c)",
    "chain_still": "chain mooring with seabed, the fairlead held still, tensionTolerance 0.1, 30 s, 0.05 s steps "
                   "(scripts/profile/chain_driver.c with amplitude 0)",
    "stiff_loose": "stiff power cable with seabed at the benchmark's cheapest settings (tensionTolerance 0.1, "
                   "projectedErrorControl, positionTolerance 0.1 m, seabedContactSpacing 2 m, solver.maxOrder 2), "
                   "30 s, 0.05 s steps (scripts/profile/stiff_driver.c)",
}


BEGIN, END = "<!-- profile tables begin -->", "<!-- profile tables end -->"


def inclusive(annotate: str, pattern: str):
    for line in annotate.splitlines():
        m = re.match(r"\s*([\d,]+)\s+\(\s*[\d.]+%\)\s+(.*)", line)
        if m and re.search(pattern, m.group(2)):
            return int(m.group(1).replace(",", ""))
    return None


def measure(directory: Path) -> dict:
    stats = dict(line.split() for line in (directory / "driver.txt").read_text().splitlines() if line.strip())
    ann = (directory / "annotate.txt").read_text()
    total = re.search(r"([\d,]+)\s+\([\d.\s]+%\)\s+PROGRAM TOTALS", ann)
    out = {"stats": {k: float(v) for k, v in stats.items()},
           "rows": {label: inclusive(ann, pat) for label, pat in ROWS},
           "total": int(total.group(1).replace(",", "")) if total else None}
    s, r = out["stats"], out["rows"]
    n_el, steps = s["nElements"], s["nSteps"]
    res, jac = r[ROWS[0][0]], r["cable Jacobian (uc::CableSimulation::jacobian)"]
    out["per"] = {
        "instructions per IDA step (IDASolve / steps)": r["IDA solve (IDASolve)"] / steps,
        "instructions per element per residual evaluation": res / (s["nResidualEvals"] * n_el) if res else None,
        "instructions per element per cable Jacobian": jac / (s["nJacobianEvals"] * n_el) if jac else None,
        "residual evaluations per step": s["nResidualEvals"] / steps,
        "cable Jacobians per step": s["nJacobianEvals"] / steps,
    }
    if "nCommunicationSteps" in s:  # the drivers that step a ramped motion
        out["per"]["instructions per communication step (uc_do_step / communication steps)"] = (
            r["uc_do_step"] / s["nCommunicationSteps"])
    return out


def markdown(runs: dict) -> str:
    """runs: {scene: {label: measure(...)}}"""
    lines = ["## Profile: where the instructions of a time step go (callgrind)", "",
             "`bash scripts/profile_callgrind --compare before=DIR --doc` (valgrind callgrind: instruction "
             "counts, repeatable on this shared machine; wall time is not). Each checkout's core library "
             "(Release, -g) is linked with the C drivers of scripts/profile/, which drive it through "
             "src/api/cable_api.h with the exact tow acceleration. Columns: the checkouts compared (`now` is "
             "this one).", ""]
    for scene, by_label in runs.items():
        labels = list(by_label)
        lines += [f"### {SCENES.get(scene, scene)}", ""]
        head = "| | " + " | ".join(labels) + " |"
        lines += [head, "|---|" + "---|" * len(labels)]
        stat_keys = [("IDA steps", "nSteps"), ("residual evaluations", "nResidualEvals"),
                     ("cable Jacobian evaluations", "nJacobianEvals"),
                     ("nonlinear failures", "nNonlinearFailures"), ("error-test failures", "nErrorTestFailures")]
        for name, key in stat_keys:
            lines.append(f"| {name} | " + " | ".join(f"{by_label[l]['stats'][key]:.0f}" for l in labels) + " |")
        for name in next(iter(by_label.values()))["per"]:
            cells = []
            for l in labels:
                v = by_label[l]["per"][name]
                cells.append("-" if v is None else (f"{v:,.2f}" if v < 10 else f"{v:,.0f}"))
            lines.append(f"| **{name}** | " + " | ".join(cells) + " |")
        for name, _ in ROWS:
            cells = []
            for l in labels:
                v, tot = by_label[l]["rows"][name], by_label[l]["total"]
                cells.append("-" if v is None else f"{v:,} ({100 * v / tot:.1f} %)")
            lines.append(f"| {name} | " + " | ".join(cells) + " |")
        lines.append("| whole program (initialization included) | "
                     + " | ".join(f"{by_label[l]['total']:,}" for l in labels) + " |")
        lines.append("")
    return "\n".join(lines)


def main(argv) -> int:
    doc, doc_path = argv[0] == "1", Path(argv[1])
    runs: dict = {}
    for item in argv[2:]:
        label, scene, directory = item.split(":", 2)
        runs.setdefault(scene, {})[label] = measure(Path(directory))
    text = markdown(runs)
    print(text)
    if doc:
        # the tables go between the markers; the hand-written text around them stays
        old = doc_path.read_text() if doc_path.is_file() else ""
        if BEGIN in old and END in old:
            a, b = old.index(BEGIN) + len(BEGIN), old.index(END)
            doc_path.write_text(old[:a] + "\n" + text + "\n" + old[b:])
        else:
            doc_path.write_text(f"{BEGIN}\n{text}\n{END}\n")
        print(f"wrote {doc_path}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
