"""Public MoorDyn and MoorPy decks loaded as a new user loads them: `lineFile` and nothing else, the tow
point (or the coupled bodies) held where the deck puts them, every other parameter at its default. The
static fairlead and anchor tensions are compared with MoorPy's equilibrium of the same file and, for a
single line between a Vessel and a Fixed point, with MoorDyn's own initial condition (moordyn.Init); the
three single-chain decks of MoorDyn's test suite (50, 200 and 600 m of water) are also heaved against
MoorDyn. A result more than 1 % from the reference without a warning or an error is SILENTLY WRONG.

"Before" is the same load with `enableSeabed` = false set alongside the deck: what the FMU did with a deck
before it took MoorDyn's seabed (it left the seabed off unless the importer switched it on).

    python -m studies.comparisons.first_contact_decks [--doc docs/first_contact.md] [--json FILE] [--no-moordyn]
                                          [--no-heave] [--decks NAME ...]

Computation here; markdown() formats (docs/first_contact.md, "Public decks as they are").
"""

from __future__ import annotations

import argparse
import json
import re
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import line_file_validation as lfv
from . import public_decks as pd

OWN = pd.PUBLIC.parent  # the repository's own decks (tests/data/decks/*.dat)
WRONG = 0.01  # more than this from the reference, without a warning or an error: silently wrong
SINGLE_CHAINS = ("md_tests_Mooring_WD0050_Chain.txt", "md_tests_Mooring_WD0200_Chain.txt",
                 "md_tests_Mooring_WD0600_Chain.txt")


def all_decks() -> list:
    """The public decks (tests/data/decks/public) and the repository's own (tests/data/decks/*.dat)."""
    return pd.decks() + sorted(OWN.glob("*.dat"))


def as_user(path: Path) -> dict:
    return {"lineFile": str(path)}


def as_before(path: Path) -> dict:
    return {"lineFile": str(path), "enableSeabed": False}


def moordyn_deck(path: Path, directory: Path) -> lfv.Deck:
    """The deck for MoorDyn, copied into directory without its fileIC option: MoorDyn's decks name a file
    of their initial state that is not published with them, and MoorDyn will not start without it (its
    own static solve gives the state; the FMU notes the option as not applicable)."""
    text = "\n".join(line for line in path.read_text().splitlines()
                     if not (len(line.split()) > 1 and line.split()[1].lower() in ("fileic", "icfile")))
    copy = directory / path.name
    copy.write_text(text + "\n")
    return lfv.read_deck(copy)


def _moordyn_reference(path: Path) -> dict | None:
    """MoorDyn's static fairlead and anchor tension of a deck with one Vessel and one Fixed point (None for
    other decks), with the CPU it took, or {"error": why}."""
    with tempfile.TemporaryDirectory() as tmp:
        try:
            deck = moordyn_deck(path, Path(tmp))
        except Exception:  # noqa: BLE001  (not a single line between a Vessel and a Fixed point)
            return None
        t0 = time.process_time()
        try:
            out = lfv.moordyn_statics(deck)
        except Exception as e:  # noqa: BLE001  (MoorDyn's own failure is a result here)
            return {"error": f"{type(e).__name__}: {e}"}
    out["cpu"] = time.process_time() - t0
    return out


def _verdict(r: dict) -> str:
    """ok, warned (off, with a warning or refused), SILENTLY WRONG, refused, or no reference."""
    if r["status"] != "ok":
        return "refused"
    worst = r["worst"] if r["worst"] is not None else r.get("worst_moordyn")
    if worst is None:
        return "no reference"
    if worst <= WRONG:
        return "ok"
    return "warned" if r["warnings"] else "SILENTLY WRONG"


def survey_deck(fmu, path: Path, moordyn: bool = True) -> dict:
    """One deck as the user loads it, and as before: MoorPy's and MoorDyn's references, the differences."""
    out = {"deck": path.name, "public": path.parent == pd.PUBLIC}
    for label, given in (("after", as_user(path)), ("before", as_before(path))):
        r = pd.compare(fmu, path, given=given)
        r["given"] = sorted(given)
        out[label] = r
    ref = _moordyn_reference(path) if moordyn else None
    out["moordyn"] = ref
    for label in ("after", "before"):
        r = out[label]
        # a line whose two end tensions match MoorPy's the other way round: the FMU names its ends the other way
        r["swapped"] = [k + 1 for k, (fr, f, ar, a) in enumerate(r.get("lines", []))
                        if max(abs(f / ar - 1), abs(a / fr - 1)) < 1e-3 < max(abs(f / fr - 1), abs(a / ar - 1))]
        r["worst_moordyn"] = None
        r["moordyn_vs_moorpy"] = None
        if ref and "error" not in ref and r.get("lines") and not r["system"]:
            fr, _, ar, _ = r["lines"][0]
            r["moordyn_vs_moorpy"] = max(abs(ref["fairlead"] / fr - 1.0), abs(ref["anchor"] / ar - 1.0))
        if ref and "error" not in ref and r["status"] == "ok" and not r["system"]:
            (f, a), = r["outputs"]
            r["worst_moordyn"] = max(abs(f / ref["fairlead"] - 1.0), abs(a / ref["anchor"] - 1.0))
        r["verdict"] = _verdict(r)
    return out


# ------------------------------------------------------------------------------------------- heave
@dataclass
class Heave(lfv.Surge):
    """The fairlead at its deck position + (0, 0, A (1 - cos w t)): at rest at t = 0."""
    period: float = 10.0
    axis: tuple = (0.0, 0.0, 1.0)


def heave(fmu, name: str, motion: Heave, t_end: float = 40.0, t_from: float = 10.0) -> dict:
    """The deck heaved in the FMU (as the user loads it, and as before) and in MoorDyn: the fairlead
    tension's RMS and largest difference from MoorDyn's over t >= t_from, relative to MoorDyn's range."""
    deck = lfv.read_deck(pd.PUBLIC / name)
    with tempfile.TemporaryDirectory() as tmp:
        md = lfv.moordyn_surge(moordyn_deck(deck.path, Path(tmp)), motion, t_end)
    out = {"deck": name, "amplitude": motion.amplitude, "period": motion.period,
           "moordyn": {"min": float(md.fairlead[md.t >= t_from].min()), "max": float(md.fairlead[md.t >= t_from].max()),
                       "cpu": md.cpu}}
    for label, given in (("after", as_user(deck.path)), ("before", as_before(deck.path))):
        ours = lfv.fmu_surge(fmu, deck, motion, t_end, parameters=given)
        sel = ours.t >= t_from - 1e-9
        diff = ours.fairlead[sel] - md.fairlead[sel]
        span = float(np.ptp(md.fairlead[sel]))
        out[label] = {"rms_range": float(np.sqrt(np.mean(diff ** 2))) / span,
                      "max_range": float(np.max(np.abs(diff))) / span,
                      "mean": float(np.mean(ours.fairlead[sel])), "cpu": ours.cpu}
    return out


def compute(fmu, names=None, moordyn: bool = True, heaves: bool = True, progress=None) -> dict:
    decks = [p for p in all_decks() if not names or p.name in names or p.stem in names]
    results = []
    for path in decks:
        if progress:
            progress(path.name)
        results.append(survey_deck(fmu, path, moordyn))
    heaved = []
    if heaves and moordyn:
        for name in SINGLE_CHAINS:
            if names and name not in names and Path(name).stem not in names:
                continue
            if progress:
                progress(f"heave {name}")
            heaved.append(heave(fmu, name, Heave()))
    return {"decks": results, "heave": heaved}


# ------------------------------------------------------------------------------------------- report
def _percent(x) -> str:
    return "" if x is None else f"{100 * x:.3g} %"


def _differences(r: dict) -> str:
    if r["status"] != "ok":
        return f"refused: {r['reason']}"
    parts = []
    if r["worst"] is not None:
        parts.append(f"MoorPy {_percent(r['worst'])}")
    elif r.get("moorpy"):
        parts.append("MoorPy fails")
    if r.get("worst_moordyn") is not None:
        off = r.get("moordyn_vs_moorpy")
        parts.append(f"MoorDyn {_percent(r['worst_moordyn'])}" +
                     (f" (MoorDyn's own start is {_percent(off)} from MoorPy's)" if off and off > 0.05 else ""))
    if r.get("swapped"):
        parts.append(f"line {', '.join(map(str, r['swapped']))}: both end tensions match MoorPy's within 0.1 % the "
                     "other way round (fairleadTension is the far end's)")
    return ", ".join(parts) or "no reference"


def markdown(data: dict) -> str:
    decks = data["decks"]
    wrong = [d for d in decks if d["after"]["verdict"] == "SILENTLY WRONG"]
    wrong_before = [d for d in decks if d["before"]["verdict"] == "SILENTLY WRONG"]
    out = [f"{len(decks)} decks loaded with `lineFile` alone (the tow point or the coupled bodies where the deck "
           f"puts them, every other parameter at its default). Silently wrong (more than {100 * WRONG:.0f} % "
           f"from the reference without a warning or an error): **{len(wrong)}** now, {len(wrong_before)} "
           "before (the same load with `enableSeabed` = false, as the FMU left a deck's seabed until it took "
           "MoorDyn's).", "",
           "Largest relative difference of a line's fairlead or anchor tension from MoorPy's equilibrium of the "
           "same file, and for a line between a Vessel and a Fixed point from MoorDyn's initial condition "
           "(`moordyn.Init`; MoorDyn's seabed lets a chain sink by its weight over `kBot` × `Diam` and its "
           "dynamic relaxation stops at `threshIC`, so it is a looser reference than MoorPy's). Warnings are "
           "the FMU's fmi2Warning messages at the start.", "",
           "| deck | user set | before | now | verdict | warnings now |", "|---|---|---|---|---|---|"]
    for d in decks:
        a, b = d["after"], d["before"]
        warned = "; ".join(re.sub(r"^lineFile \S+, ", "", w.split(": ", 1)[-1])[:160] for w in a["warnings"])
        warned = warned.replace("|", "\\|")
        name = d["deck"] if d["public"] else f"{d['deck']} (repository's)"
        out.append(f"| `{name}` | `lineFile` | {_differences(b)} | {_differences(a).replace('|', '/')} | "
                   f"{a['verdict']} | {warned} |")
    if data["heave"]:
        h0 = data["heave"][0]
        out += ["", f"Heave against MoorDyn: the fairlead moved by {h0['amplitude']:g} (1 − cos 2πt/"
                f"{h0['period']:g} s) m vertically from the deck's position, 0.1 s communication steps, the FMU's "
                "fairlead tension against MoorDyn's (its steps of 1e-4 s) from 10 s to 40 s, as a fraction of "
                "MoorDyn's range over that time.", "",
                "| deck | MoorDyn range [kN] | before: RMS / largest difference | now: RMS / largest difference |",
                "|---|---|---|---|"]
        for h in data["heave"]:
            md = h["moordyn"]
            out.append(f"| `{h['deck']}` | {md['min'] / 1e3:.1f} – {md['max'] / 1e3:.1f} | "
                       f"{_percent(h['before']['rms_range'])} / {_percent(h['before']['max_range'])} | "
                       f"{_percent(h['after']['rms_range'])} / {_percent(h['after']['max_range'])} |")
    return "\n".join(out)


def main(argv=None) -> int:  # pragma: no cover
    from ucable.paths import fmu_path

    from ..doc_section import add_report_options

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    add_report_options(ap, "first_contact_decks")
    ap.add_argument("--no-moordyn", action="store_true", help="MoorPy only (no MoorDyn statics, no heave)")
    ap.add_argument("--no-heave", action="store_true", help="no heave runs against MoorDyn")
    ap.add_argument("--decks", nargs="*", help="only these decks (file names or stems)")
    args = ap.parse_args(argv)
    data = compute(args.fmu or fmu_path(), args.decks, not args.no_moordyn, not args.no_heave,
                   progress=lambda d: print(d, file=sys.stderr, flush=True))
    text = markdown(data)
    if args.json:
        args.json.write_text(json.dumps(data, indent=1, default=str))
    if args.doc:
        from ..doc_section import write_section
        write_section(args.doc, text, "first_contact_decks")
    print(text)
    wrong = sum(d["after"]["verdict"] == "SILENTLY WRONG" for d in data["decks"])
    return 1 if wrong else 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
