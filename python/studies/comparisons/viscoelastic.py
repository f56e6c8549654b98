"""The viscoelastic axial model (EAdynamic, EAdynamicSlope, axialDampingDynamic; docs/model.md) against
MoorDyn v2 and MoorPy fed the same deck: MoorDyn's own test deck tests/Mooring/polyester/visco.txt (its
rope, EA_s|EA_Dc|EA_D_Lm = 1.424e8|1.586e8|0.4 N and BA_s|BA_d = 4e9|11e6 N s, one segment, no gravity),
with the unstretched length set for a strain of 1 % (the deck's own 100 % is beyond the 25 % a rope survives,
refused at the ends' positions), the fairlead moved sinusoidally along the line.

compute() returns the numbers, markdown() the section of docs/model.md between its BEGIN/END marks
(`python -m studies.comparisons.viscoelastic /path/to/MoorDyn --write`).
"""

from __future__ import annotations

import argparse
import math
import re
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.paths import REPO_ROOT
from ..peers import moordyn, moorpy


@dataclass
class Settings:
    length: float = 1.98          # unstretched [m]: 1.0101 % strain between the deck's points (0 and 2 m)
    amplitude: float = 0.005      # fairlead motion along x [m]: a strain amplitude of 0.25 %
    periods: tuple = (2.0, 10.0, 50.0)  # [s]: below, near and above the relaxation time (2.6 s)
    cycles: int = 4
    settle: float = 30.0          # [s]: the compared (last) cycle starts after it (ten relaxation times: the
    #                               two codes' different starts have died out)
    comm_step: float = 0.01


def deck_text(source: Path, length: float) -> str:
    """visco.txt with its line's UnstrLen set to `length`."""
    text = source.read_text(errors="replace")
    return re.sub(r"(\n1\s+rope\s+1\s+2\s+)1\.0(\s)", lambda m: f"{m.group(1)}{length}{m.group(2)}", text, count=1)


def motion(t: float, a: float, period: float):
    """x(t) = 2 + a (1 - cos(w t)) (from rest at the deck's point), its velocity and acceleration."""
    w = 2.0 * math.pi / period
    return 2.0 + a * (1.0 - math.cos(w * t)), a * w * math.sin(w * t), a * w * w * math.cos(w * t)


def cycles(s: Settings, period: float) -> int:
    return max(s.cycles, math.ceil(s.settle / period) + 1)


def run_fmu(deck: Path, s: Settings, period: float) -> np.ndarray:
    n = int(round(cycles(s, period) * period / s.comm_step))
    out = np.zeros(n + 1)
    with CableFMU(str(REPO_ROOT / "build" / "UnderwaterCable.fmu"),
                  parameters={"lineFile": str(deck), "enableCompression": False}) as c:
        x, v, a = motion(0.0, s.amplitude, period)
        c.initialize(inputs={"tow.x": x, "tow.y": 0.0, "tow.z": 0.0})
        out[0] = c.get("towTension")
        for k in range(n):
            t = k * s.comm_step
            x, v, a = motion(t, s.amplitude, period)
            c.set({"tow.x": x, "tow.vx": v})
            c.set_input_derivatives(["tow.vx"], 1, [a])
            c.do_step(s.comm_step, t=t)
            out[k + 1] = c.get("towTension")
    return out


def run_moordyn(deck: Path, s: Settings, period: float, dt: float = 0.001) -> np.ndarray:
    n = int(round(cycles(s, period) * period / s.comm_step))
    out = np.zeros(n + 1)
    sub = int(round(s.comm_step / dt))
    x0, v0, _ = motion(0.0, s.amplitude, period)
    start = ([x0, 0.0, 0.0], [v0, 0.0, 0.0])

    def coupled(t):
        x, v, _ = motion(t, s.amplitude, period)
        return [x, 0.0, 0.0], [v, 0.0, 0.0]

    def record(k, f):
        out[k] = float(np.linalg.norm(f))

    with moordyn.System(deck, init=start) as md:
        moordyn.drive(md, start, n, s.comm_step, sub, coupled, record)
    return out


def moorpy_tension(deck: Path):
    """MoorPy's static tension (static EA), or why MoorPy does not solve the deck."""
    try:
        sys_ = moorpy.system(deck)
        sys_.initialize()
        sys_.solveEquilibrium()
        line = sys_.lineList[0]
        return float(max(line.TA, line.TB))
    except ZeroDivisionError as e:  # its catenary divides by the weight: g = 0 in the deck
        return f"not solved ({type(e).__name__}: {e}; the deck has g = 0)"


def compute(moordyn_checkout: Path, s: Settings | None = None) -> dict:
    s = s or Settings()
    source = Path(moordyn_checkout) / "tests" / "Mooring" / "polyester" / "visco.txt"
    result = {"settings": s.__dict__, "cases": []}
    with tempfile.TemporaryDirectory() as tmp:
        deck = Path(tmp) / "visco_taut.txt"
        deck.write_text(deck_text(source, s.length))
        strain = 2.0 / s.length - 1.0
        result["static"] = {"closed_form": 1.424e8 * strain, "moorpy": moorpy_tension(deck)}
        for period in s.periods:
            f = run_fmu(deck, s, period)
            m = run_moordyn(deck, s, period)
            last = slice(int(round((cycles(s, period) - 1) * period / s.comm_step)), None)  # the last cycle
            d = f[last] - m[last]
            result["cases"].append({
                "period": period, "fmu_start": float(f[0]), "moordyn_start": float(m[0]),
                "rms": float(np.sqrt(np.mean(d ** 2))), "max": float(np.max(np.abs(d))),
                "range_moordyn": float(np.ptp(m[last])), "range_fmu": float(np.ptp(f[last])),
                "peak_fmu": float(np.max(f[last])), "peak_moordyn": float(np.max(m[last])),
                "mean_moordyn": float(np.mean(m[last]))})
    return result


def markdown(r: dict) -> str:
    s = r["settings"]
    lines = [
        "Generated by `python -m studies.comparisons.viscoelastic` (python/studies/comparisons/viscoelastic.py).",
        f"MoorDyn's deck `tests/Mooring/polyester/visco.txt` with UnstrLen {s['length']} m (1.01 % strain), "
        f"the fairlead at x = 2 + {s['amplitude']} (1 − cos(2π t / P)) m, at least {s['cycles']} cycles and until "
        f"{s['settle']:g} s; differences over the last cycle. MoorDyn steps at 1 ms. The two codes start apart: the "
        "FMU at the static equilibrium of the internal strain (EA_s ε), MoorDyn's initial-condition solve from "
        "the segment's whole stretch in its static spring; the difference dies out with the relaxation time "
        "(c + c_d) / (EA₁ + EA₂) = 2.7 s.",
        "",
        f"Static tension: closed form EA_s ε {r['static']['closed_form']:.6g} N, MoorPy (static EA): "
        + (f"{r['static']['moorpy']:.6g} N." if isinstance(r['static']['moorpy'], float) else r['static']['moorpy'] + "."),
        "",
        "| period P [s] | tension at t = 0, FMU / MoorDyn [N] | range of the last cycle, FMU / MoorDyn [N] | "
        "peak, FMU / MoorDyn [N] | RMS difference [N] (of the range) | largest difference [N] |",
        "|---|---|---|---|---|---|",
    ]
    for c in r["cases"]:
        lines.append(
            f"| {c['period']:g} | {c['fmu_start']:.6g} / {c['moordyn_start']:.6g} | {c['range_fmu']:.4g} / "
            f"{c['range_moordyn']:.4g} | {c['peak_fmu']:.6g} / {c['peak_moordyn']:.6g} | {c['rms']:.3g} "
            f"({100 * c['rms'] / c['range_moordyn']:.2f} %) | {c['max']:.3g} |")
    return "\n".join(lines) + "\n"


BEGIN, END = "<!-- BEGIN viscoelastic_moordyn -->", "<!-- END viscoelastic_moordyn -->"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("moordyn", type=Path, help="a MoorDyn v2 checkout (its tests/Mooring)")
    ap.add_argument("--write", action="store_true", help="write the section into docs/model.md")
    a = ap.parse_args(argv)
    text = markdown(compute(a.moordyn))
    print(text)
    if a.write:
        doc = REPO_ROOT / "docs" / "model.md"
        body = doc.read_text()
        i, j = body.index(BEGIN) + len(BEGIN), body.index(END)
        doc.write_text(body[:i] + "\n" + text + body[j:])
    return 0


if __name__ == "__main__":
    sys.exit(main())
