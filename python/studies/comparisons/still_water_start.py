"""A line with no static equilibrium in the water's flow at its start, started from its equilibrium in still water
(docs/model.md, "Initial equilibrium": a start in still water), against MoorDyn, which starts every deck so.

MoorDyn's `Currents` 5 decks wavekin_2_curr5 and wavekin_3_curr5 (a 410 m chain, 1 MN, in a 4-D current that
drags it into its anchor at t = 0): each run by the FMU and by MoorDyn 2.7 (the `moordyn` module) for `t_end`
seconds, the vessel point held, on the same current. The deck's 4-D file is made the same for both codes:
MoorDyn's reader skips the file's first node row (it reads from the seventh line), so MoorDyn gets a copy with
that row repeated; and the file's data end at 15 s, after which MoorDyn starts the record over and the FMU
holds the last sample, so both get a copy with a third time `hold` whose rows repeat the last sample's (the
current held from 15 s on in both). Sampled every `step` s: the fairlead tension (the FMU's `towTension`,
MoorDyn's end B extrapolated from its last two segments) and the anchor tension (`endTension`, MoorDyn's end A
from its first two), their RMS and largest differences against MoorDyn's range over the run, and each code's
CPU time (its start and its run).

    python -m studies.comparisons.still_water_start MOORDYN_CHECKOUT [--t-end 60] [--json out.json]
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

DECKS = ("wavekin_2/wavekin_2_curr5.txt", "wavekin_2/wavekin_3_curr5.txt")
VESSEL = (0.0, 0.0, 0.0)


def held_grid(text: str, hold: float, repeat_first: bool) -> str:
    """The 4-D current file with a third time `hold` whose rows repeat the last time's (the current held after
    the data), and with repeat_first its first node row written twice (MoorDyn then reads every node)."""
    lines = text.splitlines()
    dims = lines[0].split()
    times = lines[4].split()
    last = times[-1]
    dims[3] = str(int(dims[3]) + 1)
    held = f"{hold:.1f}"
    rows = []
    for row in lines[5:]:
        if not row.strip():
            continue
        rows.append(row)
        fields = row.split()
        if fields[3] == last:
            rows.append(" ".join(fields[:3] + [held] + fields[4:]))
    if repeat_first:
        rows.insert(0, rows[0])
    head = [" ".join(dims)] + lines[1:4] + [lines[4].rstrip() + " " + held]
    return "\n".join(head + rows) + "\n"


def copy_deck(moordyn_checkout: Path, deck: str, directory: Path, hold: float, for_moordyn: bool,
              frictionless: bool = False) -> Path:
    """The deck and its files in `directory`, the 4-D file held (held_grid); frictionless: FrictionCoefficient 0."""
    source = Path(moordyn_checkout) / "tests" / "Mooring" / deck
    for f in source.parent.iterdir():
        if f.is_file():
            shutil.copy(f, directory / f.name)
    grid = directory / "current_profile_4d.txt"
    grid.write_text(held_grid(grid.read_text(), hold, repeat_first=for_moordyn))
    path = directory / source.name
    if frictionless:
        text, n = re.subn(r"^([0-9.eE+-]+)(\s+FrictionCoefficient\b)", r"0.0\g<2>", path.read_text(), flags=re.M)
        assert n == 1, f"no FrictionCoefficient in {deck}"
        path.write_text(text)
    return path


def fmu_run(fmu: Path, path: Path, t_end: float, step: float) -> dict:
    from ucable.fmu import CableFMU

    c = CableFMU(fmu, parameters={"lineFile": str(path)}, logging_on=True)
    try:
        cpu = time.process_time()
        c.initialize(inputs={f"tow.{k}": v for k, v in zip("xyz", VESSEL)})
        start_cpu = time.process_time() - cpu
        fair, anchor, times = [c.get("towTension")], [c.get("endTension")], [0.0]
        t = 0.0
        cpu = time.process_time()
        while t < t_end - 1e-9:
            c.do_step(step, t)
            t += step
            times.append(t)
            fair.append(c.get("towTension"))
            anchor.append(c.get("endTension"))
        run_cpu = time.process_time() - cpu
        warnings = [m for s, _, m in c.messages if s == "WARNING"]
    finally:
        c.free()
    return {"t": np.array(times), "fairlead": np.array(fair), "anchor": np.array(anchor), "cpu": (start_cpu, run_cpu),
            "warnings": warnings}


def moordyn_run(path: Path, t_end: float, step: float) -> dict:
    from ..peers import moordyn

    also = [f for f in path.parent.iterdir() if f.is_file() and f != path]
    x, v = list(VESSEL), [0.0, 0.0, 0.0]
    cpu = time.process_time()
    with moordyn.System(path, also=also, init=(x, v), chdir=True) as md:
        start_cpu = time.process_time() - cpu
        line = md.line(1)

        def anchor() -> float:  # end A, its first two segments' tensions extrapolated to the node
            return float(2.0 * np.linalg.norm(md.node_tension(line, 0)) - np.linalg.norm(md.node_tension(line, 1)))

        fair, anch, times = [md.end_b_tension(line)], [anchor()], [0.0]
        t = 0.0
        cpu = time.process_time()
        while t < t_end - 1e-9:
            md.step(x, v, t, step)
            t += step
            times.append(t)
            fair.append(md.end_b_tension(line))
            anch.append(anchor())
        run_cpu = time.process_time() - cpu
    return {"t": np.array(times), "fairlead": np.array(fair), "anchor": np.array(anch), "cpu": (start_cpu, run_cpu)}


def moordyn_process(path: Path, t_end: float, step: float) -> dict:
    """moordyn_run in a process of its own (MoorDyn 2.7 loaded after the FMU's modules crashes at random)."""
    out = path.parent / "moordyn_result.json"
    env = dict(os.environ, PYTHONPATH=str(Path(__file__).resolve().parents[2]))
    subprocess.run([sys.executable, "-m", "studies.comparisons.still_water_start", "--moordyn-deck", str(path),
                    "--t-end", str(t_end), "--step", str(step), "--json", str(out)], check=True, env=env)
    r = json.loads(out.read_text())
    return {k: (np.array(v) if isinstance(v, list) and k != "cpu" else v) for k, v in r.items()}


def compare(ours: np.ndarray, theirs: np.ndarray, t: np.ndarray, t_from: float) -> dict:
    window = t >= t_from - 1e-9
    d = ours[window] - theirs[window]
    span = float(np.ptp(theirs[window]))
    return {"from": t_from, "rms": float(np.sqrt(np.mean(d ** 2))), "peak": float(np.max(np.abs(d))),
            "range": span, "moordyn_min": float(np.min(theirs[window])), "moordyn_max": float(np.max(theirs[window])),
            "fmu_min": float(np.min(ours[window])), "fmu_max": float(np.max(ours[window])),
            "fmu_mean": float(np.mean(ours[window])), "moordyn_mean": float(np.mean(theirs[window]))}


def run(fmu: Path, moordyn_checkout: Path, t_end: float = 60.0, step: float = 0.1, hold: float = 1000.0,
        frictionless: bool = False) -> list:
    results = []
    for deck in DECKS:
        with tempfile.TemporaryDirectory() as a, tempfile.TemporaryDirectory() as b:
            ours = fmu_run(fmu, copy_deck(moordyn_checkout, deck, Path(a), hold, False, frictionless), t_end, step)
            theirs = moordyn_process(copy_deck(moordyn_checkout, deck, Path(b), hold, True, frictionless), t_end, step)
        entry = {"deck": deck, "frictionless": frictionless, "t_end": t_end, "step": step, "fmu_cpu": ours["cpu"], "moordyn_cpu": theirs["cpu"],
                 "warnings": ours["warnings"],
                 "start": {"fmu": [float(ours["fairlead"][0]), float(ours["anchor"][0])],
                           "moordyn": [float(theirs["fairlead"][0]), float(theirs["anchor"][0])]},
                 "series": {"t": ours["t"].tolist(), "fmu_fairlead": ours["fairlead"].tolist(),
                            "fmu_anchor": ours["anchor"].tolist(), "moordyn_fairlead": theirs["fairlead"].tolist(),
                            "moordyn_anchor": theirs["anchor"].tolist()}}
        for end in ("fairlead", "anchor"):
            entry[end] = {f"from_{w:g}": compare(ours[end], theirs[end], ours["t"], w) for w in (0.0, 10.0)}
        results.append(entry)
    return results


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("moordyn", type=Path, nargs="?", help="MoorDyn checkout (its tests/Mooring decks)")
    parser.add_argument("--moordyn-deck", type=Path, help="only MoorDyn's run of this deck, into --json")
    parser.add_argument("--fmu", type=Path, default=None)
    parser.add_argument("--t-end", type=float, default=60.0)
    parser.add_argument("--step", type=float, default=0.1)
    parser.add_argument("--json", type=Path, default=None)
    parser.add_argument("--frictionless", action="store_true", help="both codes with FrictionCoefficient 0")
    args = parser.parse_args(argv)
    if args.moordyn_deck:
        r = moordyn_run(args.moordyn_deck, args.t_end, args.step)
        args.json.write_text(json.dumps({k: (v.tolist() if isinstance(v, np.ndarray) else v) for k, v in r.items()}))
        return 0
    from ucable.paths import require_fmu

    results = run(args.fmu or require_fmu(), args.moordyn, args.t_end, args.step, frictionless=args.frictionless)
    for r in results:
        print(f"{r['deck']}: start FMU {r['start']['fmu']}, MoorDyn {r['start']['moordyn']}; "
              f"CPU FMU {r['fmu_cpu'][0]:.2f} + {r['fmu_cpu'][1]:.2f} s, MoorDyn {r['moordyn_cpu'][0]:.2f} + "
              f"{r['moordyn_cpu'][1]:.2f} s")
        for end in ("fairlead", "anchor"):
            for key, c in r[end].items():
                print(f"  {end} {key}: RMS {c['rms']:.4g} N, peak {c['peak']:.4g} N, MoorDyn range {c['range']:.4g} N "
                      f"[{c['moordyn_min']:.4g}, {c['moordyn_max']:.4g}], FMU [{c['fmu_min']:.4g}, {c['fmu_max']:.4g}],"
                      f" means {c['fmu_mean']:.6g} / {c['moordyn_mean']:.6g}")
        for w in r["warnings"]:
            print("  warning:", w[:300])
    if args.json:
        args.json.write_text(json.dumps(results))
    return 0


if __name__ == "__main__":
    sys.exit(main())
