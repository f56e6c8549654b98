"""Currents given as data (`Currents` 2 and 5, docs/waves.md "A current given as data") against MoorDyn: the six
public MoorDyn decks that read current_profile_dynamic.txt or current_profile_4d.txt, each run by the FMU and by
MoorDyn (the `moordyn` module) on the same files, the deck's coupled point held where the deck puts it.

For each deck: the top tension of its first line (the FMU's `towTension`, or `line[1].fairleadTension` for a
system; MoorDyn's force on its coupled point, or the tension of the line's end A at its fixed point, extrapolated
from its first two segments), sampled every `step` seconds over the window where both codes use the file's data
(MoorDyn starts the record over after its last sample, the FMU holds it): the RMS of the difference of the two
histories and the largest difference, against MoorDyn's RMS about its mean; and the FMU's static equilibrium at
t = 0 against MoorPy's where MoorPy solves the deck (MoorPy takes no current: it is the same problem only where
the current is zero at t = 0). MoorDyn v2.7 skips the first node row of a current_profile_4d.txt (it reads the
nodes from the file's seventh line; the node on the sixth keeps a zero current): the 4D decks are also run by
MoorDyn on a copy of the file with that row repeated, so that it reads every node ("MoorDyn, all rows").

    python -m studies.comparisons.current_data MOORDYN_CHECKOUT [--json out.json] [--doc docs/waves.md]
    python -m studies.comparisons.current_data --from-json out.json --doc docs/waves.md
"""

from __future__ import annotations

import argparse
import json
import re
import shutil
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ..peers import moordyn


@dataclass(frozen=True)
class Case:
    deck: str          # below tests/Mooring of the MoorDyn checkout
    top: tuple         # the first line's top point (the coupled point, or its fixed end A)
    coupled: bool      # the top is the deck's Vessel point (moordyn.Step's forces), else a fixed end A
    t_end: float       # [s] the window where both codes take the file's data
    grid4d: bool       # current_profile_4d.txt (else current_profile_dynamic.txt)


CASES = (
    Case("wavekin_2/wavekin_2_curr2.txt", (0.0, 0.0, 0.0), True, 40.0, False),
    Case("wavekin_2/wavekin_3_curr2.txt", (0.0, 0.0, 0.0), True, 40.0, False),
    Case("wavekin_3/test_dynamic_currents.txt", (18.0, 5.0, -10.0), False, 55.0, False),
    Case("wavekin_2/wavekin_2_curr5.txt", (0.0, 0.0, 0.0), True, 14.5, True),
    Case("wavekin_2/wavekin_3_curr5.txt", (0.0, 0.0, 0.0), True, 14.5, True),
    Case("wavekin_4/hanging_lines.txt", (-50.0, 0.0, -16.6), False, 14.5, True),
)


def copy_case(moordyn_checkout: Path, case: Case, directory: Path, every_row: bool = False,
              current: bool = True) -> Path:
    """The deck and the files beside it in `directory`; every_row: the 4D file with its first node row
    repeated (MoorDyn then reads them all); current False: the deck's Currents set to 0."""
    source = Path(moordyn_checkout) / "tests" / "Mooring" / case.deck
    for f in source.parent.iterdir():
        if f.is_file():
            shutil.copy(f, directory / f.name)
    if not current:
        deck = directory / source.name
        text, n = re.subn(r"^(\s*)[25](\s+Currents\b)", r"\g<1>0\g<2>", deck.read_text(), count=1, flags=re.M)
        assert n == 1, f"no Currents option in {case.deck}"
        deck.write_text(text)
    if every_row:
        grid = directory / "current_profile_4d.txt"
        lines = grid.read_text().splitlines(keepends=True)
        grid.write_text("".join(lines[:5] + [lines[5]] + lines[5:]))
    return directory / source.name


class RefusedDeck(Exception):
    """The FMU's initialization refused the deck: its error message."""


def fmu_run(fmu, path: Path, case: Case, step: float) -> dict:
    from fmpy.fmi1 import FMICallException

    c = CableFMU(fmu, parameters={"lineFile": str(path)}, logging_on=True)
    try:
        try:
            c.initialize(inputs={f"tow.{k}": v for k, v in zip("xyz", case.top)})
        except FMICallException:
            errors = [m for s, _, m in c.messages if s == "ERROR"]
            raise RefusedDeck(errors[0].split("initialization failed: ")[-1] if errors else "(no message)")
        system = any("a mooring system" in text for _, _, text in c.messages)
        name = "line[1].fairleadTension" if system else "towTension"
        times, tension = [0.0], [c.get(name)]
        t = 0.0
        while t < case.t_end - 1e-9:
            c.do_step(step, t)
            t += step
            times.append(t)
            tension.append(c.get(name))
        return {"t": np.array(times), "tension": np.array(tension), "system": system,
                "messages": [(s, m) for s, _, m in c.messages]}
    finally:
        c.free()


def moordyn_run(path: Path, case: Case, step: float) -> dict:
    x, v = (list(case.top), [0.0, 0.0, 0.0]) if case.coupled else ([], [])
    also = [f for f in path.parent.iterdir() if f.is_file() and f != path]
    with moordyn.System(path, also=also, init=(x, v), chdir=True) as md:
        line = md.line(1)

        def top() -> float:
            if case.coupled:
                return float(np.linalg.norm(md.api.GetPointForce(md.point(2))))
            # end A: its first two segments' tensions extrapolated to the node
            return float(2.0 * np.linalg.norm(md.node_tension(line, 0)) - np.linalg.norm(md.node_tension(line, 1)))

        times, tension = [0.0], [top()]
        t = 0.0
        while t < case.t_end - 1e-9:
            md.step(x, v, t, step)
            t += step
            times.append(t)
            tension.append(top())
    return {"t": np.array(times), "tension": np.array(tension)}


def difference(ours: dict, theirs: dict) -> dict:
    d = ours["tension"] - theirs["tension"]
    scale = float(np.std(theirs["tension"]))
    return {"rms": float(np.sqrt(np.mean(d ** 2))), "peak": float(np.max(np.abs(d))), "moordyn_rms": scale,
            "moordyn_mean": float(np.mean(theirs["tension"])), "fmu_mean": float(np.mean(ours["tension"])),
            "fmu_peak": float(np.max(ours["tension"])), "moordyn_peak": float(np.max(theirs["tension"]))}


def statics(fmu, path: Path) -> dict:
    """The FMU's statics against MoorPy's (studies.comparisons.public_decks.compare)."""
    from .public_decks import compare as against_moorpy

    r = against_moorpy(fmu, path)
    return {"status": r["status"], "moorpy": r.get("moorpy"), "worst": r.get("worst"), "lines": r.get("lines", []),
            "reason": r.get("reason")}


def compute(fmu, moordyn_checkout: Path, step: float = 0.5, progress=None) -> list:
    results = []
    for case in CASES:
        if progress:
            progress(case.deck)
        entry = {"deck": case.deck, "t_end": case.t_end, "grid4d": case.grid4d}
        with tempfile.TemporaryDirectory() as tmp:
            path = copy_case(moordyn_checkout, case, Path(tmp))
            try:
                ours = fmu_run(fmu, path, case, step)
            except RefusedDeck as e:  # a deck the FMU refuses: its reason
                entry["refused"] = str(e)
                results.append(entry)
                continue
            entry["warnings"] = [m for s, m in ours["messages"] if s == "WARNING"]
            entry["statics"] = statics(fmu, path)
            theirs = moordyn_run(path, case, step)
            entry["moordyn"] = difference(ours, theirs)
            entry["series"] = {"t": ours["t"].tolist(), "fmu": ours["tension"].tolist(),
                               "moordyn": theirs["tension"].tolist()}
        with tempfile.TemporaryDirectory() as tmp:  # the same deck without its current: the current's share
            path = copy_case(moordyn_checkout, case, Path(tmp), current=False)
            still_ours, still_theirs = fmu_run(fmu, path, case, step), moordyn_run(path, case, step)
            effect_ours = ours["tension"] - still_ours["tension"]
            effect_theirs = theirs["tension"] - still_theirs["tension"]
            d = effect_ours - effect_theirs
            entry["effect"] = {"fmu_rms": float(np.sqrt(np.mean(effect_ours ** 2))),
                               "moordyn_rms": float(np.sqrt(np.mean(effect_theirs ** 2))),
                               "rms": float(np.sqrt(np.mean(d ** 2))), "peak": float(np.max(np.abs(d)))}
            entry["series"]["fmu_still"] = still_ours["tension"].tolist()
            entry["series"]["moordyn_still"] = still_theirs["tension"].tolist()
        if case.grid4d:
            with tempfile.TemporaryDirectory() as tmp:
                path = copy_case(moordyn_checkout, case, Path(tmp), every_row=True)
                every = moordyn_run(path, case, step)
                entry["moordyn_all_rows"] = difference(ours, every)
                entry["series"]["moordyn_all_rows"] = every["tension"].tolist()
        results.append(entry)
    return results


def markdown(results: list) -> str:
    rows = ["| deck | window | FMU mean, peak | MoorDyn mean, peak, RMS | difference RMS, peak | "
            "MoorDyn reading every 4D row: difference RMS, peak | the current's share (with less without it): "
            "FMU RMS, MoorDyn RMS, difference RMS, peak | statics vs MoorPy |",
            "|---|---|---|---|---|---|---|---|"]
    for r in results:
        if "refused" in r:
            rows.append(f"| `{r['deck']}` | refused: {r['refused']} | | | | | | |")
            continue
        e = r["effect"]
        effect_text = f"{e['fmu_rms']:.1f} N, {e['moordyn_rms']:.1f} N, {e['rms']:.1f} N, {e['peak']:.1f} N"
        m = r["moordyn"]
        every = r.get("moordyn_all_rows")
        every_text = f"{every['rms']:.1f} N, {every['peak']:.1f} N" if every else "(not a 4D file)"
        s = r["statics"]
        if s["status"] != "ok":
            static_text = f"refused: {s['reason']}"
        elif s["worst"] is None:
            static_text = f"MoorPy fails: {s['moorpy']}"
        else:
            static_text = f"{100 * s['worst']:.3f} %"
        rows.append(f"| `{r['deck']}` | 0 to {r['t_end']:g} s | {m['fmu_mean']:.1f} N, {m['fmu_peak']:.1f} N | "
                    f"{m['moordyn_mean']:.1f} N, {m['moordyn_peak']:.1f} N, {m['moordyn_rms']:.1f} N | "
                    f"{m['rms']:.1f} N, {m['peak']:.1f} N | {every_text} | {effect_text} | {static_text} |")
    return "\n".join(rows) + "\n"


def frictionless_share(fmu, moordyn_checkout: Path, deck: str, step: float = 0.5) -> dict:
    """The current's share (with less without the current) of one deck in both codes with its seabed friction
    off (FrictionCoefficient 0): how much of the share's difference is the two codes' friction models."""
    case = next(c for c in CASES if c.deck == deck)
    runs = {}
    for current in (True, False):
        with tempfile.TemporaryDirectory() as tmp:
            path = copy_case(moordyn_checkout, case, Path(tmp), current=current)
            text, n = re.subn(r"^([0-9.eE+-]+)(\s+FrictionCoefficient\b)", r"0.0\g<2>", path.read_text(), flags=re.M)
            assert n == 1, f"no FrictionCoefficient in {deck}"
            path.write_text(text)
            runs[current] = (fmu_run(fmu, path, case, step)["tension"], moordyn_run(path, case, step)["tension"])
    ours, theirs = runs[True][0] - runs[False][0], runs[True][1] - runs[False][1]
    d = ours - theirs
    return {"deck": deck, "fmu_rms": float(np.sqrt(np.mean(ours ** 2))), "moordyn_rms": float(np.sqrt(np.mean(theirs ** 2))),
            "rms": float(np.sqrt(np.mean(d ** 2))), "peak": float(np.max(np.abs(d)))}


SECTION = "scripts/current_data_moordyn"


def section(results: list) -> str:
    """The generated section of docs/waves.md: the table and what it rests on."""
    return ("### Against MoorDyn: currents given as data\n\n"
            "This section is generated by `scripts/current_data_moordyn` (`studies.comparisons.current_data`: "
            "the numbers are computed first, the text written from them). The six public MoorDyn decks with "
            "`Currents` 2 or 5, each run by the FMU (its defaults, the deck's elements) and by MoorDyn 2.7 "
            "(`moordyn` module, the deck's dtM) on the same files, the deck's vessel or fixed top point held; "
            "the top tension of line 1 sampled every 0.5 s from t = 0 to the end of the window, which ends "
            "before the data do (after them MoorDyn starts the record over, the FMU holds it). Difference: the "
            "RMS and the largest absolute difference of the two histories. Statics: the FMU's initial tension "
            "at both ends against MoorPy's (its largest relative difference; MoorPy takes no current).\n\n"
            + markdown(results))


def main(argv=None) -> int:
    from ucable.paths import require_fmu

    from ..doc_section import write_section

    ap = argparse.ArgumentParser(prog="scripts/current_data_moordyn", description=__doc__.splitlines()[0])
    ap.add_argument("moordyn_path", type=Path, nargs="?", help="a MoorDyn checkout (its tests/Mooring)")
    ap.add_argument("--step", type=float, default=0.5, help="sampling and communication step [s]")
    ap.add_argument("--json", type=Path, help="write the results (with the histories) there")
    ap.add_argument("--from-json", type=Path, help="the results of an earlier run (nothing is run)")
    ap.add_argument("--doc", type=Path, help=f"write the section into this Markdown file (its {SECTION} markers)")
    ap.add_argument("--frictionless", metavar="DECK", help="only the current's share of DECK (e.g. "
                    "wavekin_2/wavekin_3_curr2.txt) in both codes with the seabed friction off")
    args = ap.parse_args(argv)
    if args.frictionless:
        print(json.dumps(frictionless_share(require_fmu(), args.moordyn_path, args.frictionless, args.step)))
        return 0
    if args.from_json:
        results = json.loads(args.from_json.read_text())
    else:
        if args.moordyn_path is None:
            ap.error("a MoorDyn checkout, or --from-json")
        results = compute(require_fmu(), args.moordyn_path, args.step, progress=lambda d: print(d, file=sys.stderr))
        if args.json:
            args.json.write_text(json.dumps(results, indent=1))
    text = section(results)
    print(text)
    if args.doc:
        write_section(args.doc, text, SECTION)
    return 0


if __name__ == "__main__":
    sys.exit(main())
