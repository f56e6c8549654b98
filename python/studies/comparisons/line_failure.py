"""Line failure against MoorDyn (docs/line_failure.md, "Comparison with MoorDyn"): the OC4 semisubmersible's
three chains (scenes/oc4_semi.dat), the platform held at rest, line 1 detached from its fairlead (point 4) at
2 s. MoorDyn-C has no failure trigger: its BreakLine is called at 2 s (the line's end goes on a new free point).
The broken line's anchor tension over the 28 s after the break, every 0.1 s, is compared.

    .venv/bin/python -m studies.comparisons.line_failure     (from python/)

MoorDyn runs first, in this process, before the FMU's modules are loaded (peers/moordyn.py: MoorDyn 2.7's Create
can crash when loaded after them)."""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[3]
DECK = REPO / "scenes" / "oc4_semi.dat"
FAIRLEADS = [20.434, 35.393, -14.0, -40.868, 0.0, -14.0, 20.434, -35.393, -14.0]
T_BREAK, H, T_END = 2.0, 0.1, 30.0


def moordyn_run(segments: int = 20, dtM: float = 5e-4) -> np.ndarray:
    """(t, line 1's anchor tension) every H with BreakLine at T_BREAK."""
    import moordyn

    with tempfile.TemporaryDirectory() as tmp:
        text = DECK.read_text().replace("0.001    dtM", f"{dtM}    dtM")
        text = text.replace("835.35     20", f"835.35     {segments}")
        path = Path(tmp) / DECK.name
        path.write_text(text)
        system = moordyn.Create(str(path))
        x, v = np.array(FAIRLEADS), np.zeros(9)
        moordyn.Init(system, x, v)
        line, point = moordyn.GetLine(system, 1), moordyn.GetPoint(system, 4)
        out, n = [], int(round(T_END / H))
        for k in range(n):
            t = k * H
            if k == int(round(T_BREAK / H)):
                moordyn.BreakLine(system, point, line)
            moordyn.Step(system, x, v, t, H)
            out.append((t + H, np.linalg.norm(moordyn.GetLineNodeTen(line, 0))))
        moordyn.Close(system)
        shutil.rmtree(tmp, ignore_errors=True)
    return np.array(out)


def fmu_run(elements: int = 10, h: float = H) -> np.ndarray:
    from ucable.fmu import CableFMU
    from ucable.paths import require_fmu

    from .mooring_system import fmu_parameters, read_system_deck

    p = fmu_parameters(read_system_deck(DECK), lineFileElements=elements,
                       **{"failure.line": 1, "failure.time": T_BREAK})
    c = CableFMU(require_fmu(), parameters=p)
    c.initialize()
    out = []
    for k in range(int(round(T_END / h))):
        c.do_step(h, t=k * h)
        out.append((k * h + h, c.get("line[1].anchorTension")))
    c.free()
    return np.array(out)


def compute() -> dict:
    """The RMS differences of the broken line's anchor tension over T_BREAK..T_END, relative to its tension
    before the break (MoorDyn 20 segments's), and the tensions at T_END."""
    md = moordyn_run()
    md40 = moordyn_run(segments=40, dtM=2.5e-4)
    ours = fmu_run()
    ours20 = fmu_run(elements=20)
    after = md[:, 0] > T_BREAK + 1e-9
    ref = md[0, 1]  # the anchor tension before the break

    def rms(a, b):
        d = a[after, 1] - b[after, 1]
        return float(np.sqrt(np.mean(d * d)) / ref)

    return {"before": float(ref), "t_break": T_BREAK, "t_end": T_END,
            "rows": [("MoorDyn 40 segments (dtM 2.5e-4 s) against MoorDyn 20 (dtM 5e-4 s)", rms(md40, md)),
                     ("FMU 10 elements, 0.1 s steps, against MoorDyn 20 segments", rms(ours, md)),
                     ("FMU 20 elements against MoorDyn 20 segments", rms(ours20, md)),
                     ("FMU 20 elements against MoorDyn 40 segments", rms(ours20, md40))],
            "end": {"MoorDyn 20": float(md[-1, 1]), "MoorDyn 40": float(md40[-1, 1]), "FMU 10": float(ours[-1, 1]),
                    "FMU 20": float(ours20[-1, 1])}}


def main(argv=None) -> None:
    import argparse
    import json

    p = argparse.ArgumentParser(prog="studies.comparisons.line_failure", description=__doc__.split("\n")[0])
    p.add_argument("--json", type=Path, help="write the numbers as JSON")
    args = p.parse_args(argv)
    data = compute()
    for name, value in data["rows"]:
        print(f"{name}: anchor tension RMS difference over {T_BREAK}-{T_END} s: {value:.2%} of {data['before']:.4g} N")
    print("at", T_END, "s:", ", ".join(f"{k} {v:.4g} N" for k, v in data["end"].items()))
    if args.json:
        args.json.write_text(json.dumps(data))


if __name__ == "__main__":
    main()
