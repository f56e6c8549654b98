"""The Syrope model of a polyester rope (syrope.*; docs/model.md, "Syrope fibre-rope model") against MoorDyn v2
fed the same decks: MoorDyn's tests/Mooring/syrope/{linear_wc,quadratic_wc,exp_wc}/line.txt (one segment of
1 m, no gravity, the original working curve owc.dat, Tmax0 1.3886e6 N, Tmean0 4.339e5 N), the Coupled point
moved along the line: a slow stretch, hold, unload and reload (MoorDyn's own test's profile of strain, shorter:
segments of `segment` s, a few of the slow strain's relaxation times BA_s / (EA_Dc + EA_D_Lm T), about 300 s),
with a harmonic wave-frequency strain on top.

compute() returns the numbers, markdown() the section of docs/model.md between its BEGIN/END marks
(`python -m studies.comparisons.syrope /path/to/MoorDyn --write`).
"""

from __future__ import annotations

import argparse
import math
import shutil
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.paths import REPO_ROOT
from ..doc_section import write_section
from ..peers import moordyn

CASES = ("linear_wc", "quadratic_wc", "exp_wc")


@dataclass
class Settings:
    segment: float = 1200.0    # [s] each leg of the slow profile (four relaxation times)
    wave: float = 2e-4         # amplitude of the harmonic strain
    wave_period: float = 12.0  # [s]
    comm_step: float = 0.2     # [s] (MoorDyn's test's; it steps at the deck's dtM 0.05 s)


def strain(t: float, eps0: float, s: Settings) -> tuple:
    """MoorDyn's test's slow strain (eps0; ramp to 3 eps0; hold; down to 2 eps0; hold; up to 3.5 eps0) plus the
    harmonic one, started smoothly: the strain and its rate."""
    T = s.segment
    knots = [(0, eps0), (T, eps0), (2 * T, 3 * eps0), (3 * T, 3 * eps0), (4 * T, 2 * eps0), (5 * T, 2 * eps0),
             (6 * T, 3.5 * eps0)]
    slow, rate = knots[-1][1], 0.0
    for (t0, e0), (t1, e1) in zip(knots, knots[1:]):
        if t0 <= t < t1:
            slow, rate = e0 + (e1 - e0) * (t - t0) / (t1 - t0), (e1 - e0) / (t1 - t0)
            break
    w = 2.0 * math.pi / s.wave_period
    ramp = min(1.0, t / (2.0 * s.wave_period))  # the harmonic grows over two periods from rest
    dramp = 1.0 / (2.0 * s.wave_period) if t < 2.0 * s.wave_period else 0.0
    return (slow + ramp * s.wave * math.sin(w * t),
            rate + ramp * s.wave * w * math.cos(w * t) + dramp * s.wave * math.sin(w * t))


def initial_strain(deck: Path) -> float:
    """The Coupled point's x in the deck (the line runs from x = 0, 1 m long): its strain."""
    for line in deck.read_text().splitlines():
        parts = line.split()
        if len(parts) > 2 and parts[0] == "2" and parts[1].lower() == "coupled":
            return float(parts[2]) - 1.0
    raise ValueError(f"{deck}: no Coupled point 2")


def run_fmu(deck: Path, s: Settings, duration: float) -> np.ndarray:
    eps0 = initial_strain(deck)
    n = int(round(duration / s.comm_step))
    out = np.zeros(n + 1)
    with CableFMU(str(REPO_ROOT / "build" / "UnderwaterCable.fmu"), parameters={"lineFile": str(deck)}) as c:
        c.initialize(inputs={"tow.x": 1.0 + eps0, "tow.y": 0.0, "tow.z": -5.0})
        out[0] = c.get("towTension")
        for k in range(n):
            t = k * s.comm_step
            e, de = strain(t, eps0, s)
            c.set({"tow.x": 1.0 + e, "tow.vx": de})
            c.do_step(s.comm_step, t=t)
            out[k + 1] = c.get("towTension")
    return out


def run_moordyn(folder: Path, case: str, s: Settings, duration: float) -> np.ndarray:
    eps0 = initial_strain(folder / case / "line.txt")
    n = int(round(duration / s.comm_step))
    out = np.zeros(n + 1)

    def write(tmp: Path) -> Path:
        shutil.copy(folder / "owc.dat", tmp / "owc.dat")
        shutil.copytree(folder / case, tmp / case)
        return tmp / case / "line.txt"

    def coupled(t):
        e, de = strain(t, eps0, s)
        return [1.0 + e, 0.0, -5.0], [de, 0.0, 0.0]

    def record(k, f):
        out[k] = float(np.linalg.norm(f))

    start = coupled(0.0)
    with moordyn.System(write=write, init=start) as md:
        moordyn.drive(md, start, n, s.comm_step, 1, coupled, record)
    return out


def compute(folder: Path, s: Settings | None = None, cases=CASES) -> dict:
    """folder: MoorDyn's tests/Mooring/syrope (or the copy in tests/data/decks/public/syrope)."""
    s = s or Settings()
    folder = Path(folder)
    duration = 6.0 * s.segment
    result = {"settings": s.__dict__, "cases": []}
    for case in cases:
        f = run_fmu(folder / case / "line.txt", s, duration)
        m = run_moordyn(folder, case, s, duration)
        d = f - m
        late = slice(int(round(s.segment / s.comm_step)), None)  # from the first ramp on
        result["cases"].append({
            "case": case, "fmu_start": float(f[0]), "moordyn_start": float(m[0]),
            "range": float(np.ptp(m)), "rms": float(np.sqrt(np.mean(d ** 2))), "max": float(np.max(np.abs(d))),
            "rms_late": float(np.sqrt(np.mean(d[late] ** 2))),
            "peak_fmu": float(np.max(f)), "peak_moordyn": float(np.max(m)),
            "end_fmu": float(f[-1]), "end_moordyn": float(m[-1])})
    return result


def markdown(r: dict) -> str:
    s = r["settings"]
    lines = [
        "Generated by `python -m studies.comparisons.syrope` (python/studies/comparisons/syrope.py).",
        f"MoorDyn's decks `tests/Mooring/syrope/*/line.txt`, the Coupled point at x = 1 + ε(t) m: ε from the deck's "
        f"ε₀ for {s['segment']:g} s, up to 3 ε₀, held, down to 2 ε₀, held, up to 3.5 ε₀ (legs of {s['segment']:g} s), "
        f"plus {s['wave']:g} sin(2π t / {s['wave_period']:g} s); both codes driven at {s['comm_step']:g} s "
        "(MoorDyn steps at the deck's dtM, 0.05 s).",
        "",
        "| deck | tension at t = 0, FMU / MoorDyn [N] | range [N] | peak, FMU / MoorDyn [N] | at the end, FMU / MoorDyn [N] "
        "| RMS difference [N] (of the range) | from the first ramp on | largest difference [N] |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for c in r["cases"]:
        lines.append(
            f"| `{c['case']}` | {c['fmu_start']:.6g} / {c['moordyn_start']:.6g} | {c['range']:.4g} | "
            f"{c['peak_fmu']:.6g} / {c['peak_moordyn']:.6g} | {c['end_fmu']:.6g} / {c['end_moordyn']:.6g} | "
            f"{c['rms']:.3g} ({100 * c['rms'] / c['range']:.2f} %) | {c['rms_late']:.3g} "
            f"({100 * c['rms_late'] / c['range']:.2f} %) | {c['max']:.3g} |")
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("moordyn", type=Path, help="a MoorDyn v2 checkout (its tests/Mooring/syrope)")
    ap.add_argument("--write", action="store_true", help="write the section into docs/model.md")
    ap.add_argument("--segment", type=float, default=Settings.segment)
    a = ap.parse_args(argv)
    text = markdown(compute(a.moordyn / "tests" / "Mooring" / "syrope", Settings(segment=a.segment)))
    print(text)
    if a.write:
        write_section(REPO_ROOT / "docs" / "model.md", text, "syrope_moordyn")
    return 0


if __name__ == "__main__":
    sys.exit(main())
