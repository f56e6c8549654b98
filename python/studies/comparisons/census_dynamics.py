"""The census's decks in motion: every public deck the FMU loads (studies.comparisons.public_decks, the
census) run under one prescribed motion in the FMU and in MoorDyn v2 (PyPI `moordyn`) fed the same file,
their fairlead and anchor tensions side by side.

The motion (Settings): every coupled object of the deck surges along x by A (1 - cos 2 pi t / T) from rest
(no jump in position or velocity at t = 0), T = 10 s, A = 1 % of the deck's longest line (its unstretched
length), at most 2 m (a platform's wave-frequency surge); the first period is left out of the statistics.
What moves:

- a system's coupled bodies (the FMU's `body[k].*`, MoorDyn's coupled body), its Coupled points (with a
  BODIES section the FMU's `point[k].*`; without one they are on the FMU's body 1, which moves);
- a one-line deck's tow point (the FMU's `tow.*`, where the census puts it: its Vessel point, else its
  higher Fixed point): in MoorDyn that point of the deck is made Coupled where it is Fixed;
- a deck with none (a system with no coupled object, a one-line deck whose tow point MoorPy cannot name):
  nothing, both run from their start unforced.

The FMU starts from its static equilibrium (the census's start) and gets the position, velocity and
acceleration (an input derivative) of what moves at each communication step; MoorDyn starts from its own
initial conditions (moordyn.Init: its dynamic relaxation up to the deck's TmaxIC) and gets the position and
velocity at the start of each of `calls` calls per communication step (it moves its coupled points linearly
within a call), at the deck's mesh and dtM, in a process of its own (peers.moordyn.driven), so that its
crash or blow-up is a result of the table. Each deck line's tension at its two ends is compared: a system's
line k, its fairlead (FMU `line[k].fairleadTension`) with MoorDyn's end of deck line k that the FMU takes
for its fairlead, its anchor with the other end (fmu_line_ends: the FMU's own rule, read from the deck's point
types and line ends);
a one-line deck's tow point and the far end of its chain of deck lines.

compute() returns the numbers, markdown() the table of docs/systems_mooring.md, "The census in motion"
(between its census_dynamics markers). Used by scripts/census_dynamics and
tests/python/test_census_dynamics.py.
"""

from __future__ import annotations

import argparse
import json
import math
import re
import sys
import tempfile
import time
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU, FMICallException
from . import line_file_validation as lfv
from . import public_decks as pd
from ..doc_section import add_report_options, publish, write_json
from ..peers import moordyn

NAME = "census_dynamics"


@dataclass
class Settings:
    period: float = 10.0        # [s] of the surge
    fraction: float = 0.01      # amplitude: this fraction of the deck's longest line ...
    cap: float = 2.0            # [m] ... at most this
    t_end: float = 40.0         # [s] simulated
    t_from: float = 10.0        # [s] statistics over t >= t_from (the first period left out)
    comm_step: float = 0.1      # [s] the FMU's communication step and the sampling of both
    calls: int = 10             # moordyn.Step calls per communication step
    moordyn_refine: int = 1     # MoorDyn on this many times the deck's NumSegs (dtM divided as much)
    timeout: float = 900.0      # [s] of CPU for MoorDyn's process on one deck


# ----------------------------------------------------------------------------- the deck
def _sections(path: Path):
    """(section header in upper case, the rows under it) of a deck, in order."""
    header, rows = None, []
    for line in Path(path).read_text(errors="replace").splitlines():
        if line.lstrip().startswith("---"):
            if header is not None:
                yield header, rows
            header, rows = line.upper(), []
        elif header is not None:
            rows.append(line)
    if header is not None:
        yield header, rows


def _is_lines(header: str) -> bool:
    return bool(re.search(r"\bLINES\b|LINE LIST|LINE PROPERTIES", header))


def line_lengths(path: Path) -> list:
    """The unstretched length of each deck line (the LINES table's UnstrLen column, found by its header)."""
    for header, rows in _sections(path):
        if not _is_lines(header):
            continue
        column, out = None, []
        for row in rows:
            words = row.split()
            if column is None:
                column = next((i for i, w in enumerate(words) if re.match(r"unstr|length", w, re.I)), None)
                continue
            try:
                out.append(float(words[column]))
            except (IndexError, ValueError):
                continue  # the units row
        return out
    return []


def has_bodies(path: Path) -> bool:
    """Whether the deck has a BODIES section with a row (its Coupled points are then the FMU's point[k])."""
    return any(re.search(r"\bBOD(Y|IES)\b", h) and any(r.split() and r.split()[0].isdigit() for r in rows)
               for h, rows in _sections(path))


def coupled_tow_text(path: Path, point: int) -> str:
    """The deck's text with its point `point` (a Fixed point, the FMU's tow point) made Coupled, so that
    MoorDyn takes its motion."""
    out, in_points = [], False
    for line in Path(path).read_text(errors="replace").splitlines():
        if line.lstrip().startswith("---"):
            in_points = any(k in line.upper() for k in ("POINT", "CONNECTION", "NODE"))
        words = line.split()
        if in_points and len(words) > 1 and words[0] == str(point):
            line = re.sub(r"^(\s*\S+\s+)\S+", r"\1Coupled", line, count=1)
        out.append(line)
    return "\n".join(out) + "\n"


def _table(path: Path, is_table) -> list:
    """The rows of the deck's first section is_table(header) picks, as (header words, data rows' words): the
    header row is the first row, the units row and blank rows are dropped (a data row starts with a number)."""
    for header, rows in _sections(path):
        if not is_table(header):
            continue
        rows = [r.split() for r in rows if r.split()]
        if not rows:
            return [], []
        return rows[0], [w for w in rows[1:] if re.fullmatch(r"\d+", w[0])]
    return [], []


def _attach(word: str, rods: dict) -> str:
    """A deck line's end (AttachA/B, v1's NodeAnch/NodeFair) as a key: the point "12", a rod's end "R1A" ("R1" for
    a rod of no segments: one point, as the FMU reads it)."""
    m = re.fullmatch(r"(?i)(?:rod|r)(\d+)([ab])", word)
    if not m:
        return word.upper()
    segments = rods.get(m.group(1), ("", "1"))[1]
    return f"R{m.group(1)}" + ("" if segments == "0" else m.group(2).upper())


def line_end_roles(path: Path) -> list:
    """Per deck line (in deck order): its two ends' (point key, role), end A first; role "coupled" (a Coupled or
    Vessel point, a point on a Coupled body, a coupled body or rod itself), "node" (a Free point where three or
    more lines meet, a point on a Free or Pinned body), "fixed" (a Fixed or Anchor point, a point on a Fixed
    body), else "free"."""
    head, rows = _table(path, lambda h: bool(re.search(r"\bBOD(Y|IES)\b", h)))
    bodies = {w[0]: w[1].lower() for w in rows if len(w) > 1}
    head, rows = _table(path, lambda h: bool(re.search(r"\bRODS?\b", h)) and "TYPE" not in h and not _is_lines(h))
    rods = {w[0]: (w[2].lower(), w[9] if len(w) > 9 else "1") for w in rows if len(w) > 2}  # ID: (attachment, NumSegs)
    head, rows = _table(path, lambda h: any(k in h for k in ("POINT", "CONNECTION", "NODE")) and not _is_lines(h))
    kinds = {w[0]: w[1].lower() for w in rows if len(w) > 1}
    head, rows = _table(path, _is_lines)
    lower = [h.lower() for h in head]
    a = next((i for i, h in enumerate(lower) if re.match(r"(attach|node|end|con)\w*a(nch)?\w*$", h) and "fair" not in h), None)
    b = next((i for i, h in enumerate(lower) if re.match(r"(attach|node|end|con)\w*(b|fair\w*)$", h)), None)
    if a is None or b is None:
        raise ValueError(f"{path.name}: its LINES table names no AttachA/AttachB (NodeA/NodeB, NodeAnch/NodeFair) "
                         f"columns: {' '.join(head)}")
    ends = [(_attach(w[a], rods), _attach(w[b], rods)) for w in rows if len(w) > max(a, b)]
    count = {}
    for pair in ends:
        for key in pair:
            count[key] = count.get(key, 0) + 1

    def role(key: str) -> str:
        rod = re.fullmatch(r"R(\d+)([AB]?)", key)
        kind = kinds.get(key, "")
        if rod:  # a rod of no segments is a point of its kind; one with segments a free body where it is Free
            attachment, segments = rods.get(rod.group(1), ("", "1"))
            kind = "free" if attachment == "free" and segments == "0" else "pinned" if attachment == "free" else attachment
            kind = "body" + kind[4:] if kind.startswith("body") else kind
        m = re.fullmatch(r"(?:body|b)(\d+)", kind)
        body = bodies.get(m.group(1), "") if m else "pinned" if kind == "pinned" else None
        if kind in ("coupled", "vessel", "cpld", "fairlead", "vess") or body in ("coupled", "vessel", "cpld"):
            return "coupled"
        if body in ("free", "pinned", "cpldpin", "coupledpinned") or (kind in ("free", "connect", "con")
                                                                        and count.get(key, 0) >= 3):
            return "node"
        if kind in ("fixed", "anchor", "fix") or body == "fixed":
            return "fixed"
        return "free"

    return [((ka, role(ka)), (kb, role(kb))) for ka, kb in ends]


def fmu_line_ends(path: Path) -> list:
    """Per deck line (the FMU's `line[k]` is deck line k): ((k, end) of the FMU's `line[k].fairleadTension`, (k,
    end) of its `anchorTension`), lines from 1, ends MoorDyn's (0 = A, 1 = B). The FMU's rule
    (src/deck/mooring_deck.cpp): a deck line's fairlead is its end on a coupled object (end B where both are),
    else the end where the FMU's walk enters it; the walk starts on a coupled object, else (second pass) on a
    free node (a Free point joining three or more lines, a Free body), else (third pass) at a Fixed point, deck
    lines in deck order, end B before end A, and runs on through Free points that join two deck lines. Read
    from the deck's point types and line ends (line_end_roles), never from the tensions."""
    roles = line_end_roles(path)
    at = {}
    for k, ends in enumerate(roles):
        for e, (key, _) in enumerate(ends):
            at.setdefault(key, []).append((k, e))
    entered = [1] * len(roles)  # a line the FMU does not reach (it refuses such a deck): end B
    used = [False] * len(roles)
    for wanted in ("coupled", "node", "fixed"):
        for first in range(len(roles)):
            if used[first]:
                continue
            start = next((e for e in (1, 0) if roles[first][e][1] == wanted), None)
            if start is None:
                continue
            k, e = first, start
            while True:
                used[k], entered[k] = True, e
                key, role = roles[k][1 - e]
                onward = [p for p in at[key] if p != (k, 1 - e)]
                if role != "free" or len(onward) != 1 or used[onward[0][0]]:
                    break
                k, e = onward[0]
    out = []
    for k, ends in enumerate(roles):
        fair = next((e for e in (1, 0) if ends[e][1] == "coupled"), entered[k])
        out.append(((k + 1, fair), (k + 1, 1 - fair)))
    return out


def amplitude(path: Path, settings: Settings) -> float:
    lengths = line_lengths(path)
    return min(settings.fraction * max(lengths), settings.cap) if lengths else settings.cap


# ----------------------------------------------------------------------------- the two runs
def fmu_run(fmu, parameters: dict, inputs: dict, n_lines: int, moving, surge: lfv.Surge, settings: Settings) -> dict:
    """The FMU from its static start (its inputs `inputs`), the objects moving(system) (input prefixes:
    body[k], point[k], tow) surging: t, tension (2, times, lines: at the anchor end, at the fairlead end),
    system, moved, cpu_init, cpu, error (refused: the start's; else the step's, the tensions NaN from there)."""
    n = int(round(settings.t_end / settings.comm_step))
    times = np.arange(n + 1) * settings.comm_step
    c = CableFMU(fmu, parameters=parameters, logging_on=True)
    out = {"t": times, "error": "", "refused": False, "cpu_init": 0.0, "cpu": 0.0, "system": False, "moved": [],
           "tension": None}
    try:
        cpu0 = time.process_time()
        try:
            c.initialize(inputs=inputs)
        except FMICallException:
            out["refused"] = True
            raise
        out["cpu_init"] = time.process_time() - cpu0
        out["system"] = system = any("a mooring system" in text for _, _, text in c.messages)
        out["moved"] = moved = moving(system)
        names = ([f"line[{k}].anchorTension" for k in range(1, n_lines + 1)] +
                 [f"line[{k}].fairleadTension" for k in range(1, n_lines + 1)]) if system else ["endTension", "towTension"]
        m = n_lines if system else 1
        out["tension"] = tension = np.full((2, n + 1, m), np.nan)
        tension[:, 0] = c.get_reals(names).reshape(2, m)
        base = {p: inputs.get(f"{p}.x", 0.0) for p in moved}
        cpu0 = time.process_time()
        for k in range(n):
            dx, v, a = surge.state(times[k])
            c.set({**{f"{p}.x": x + dx[0] for p, x in base.items()}, **{f"{p}.vx": v[0] for p in moved}})
            if moved:
                c.set_input_derivatives([f"{p}.vx" for p in moved], 1, [a[0]] * len(moved))
            c.do_step(settings.comm_step, t=times[k])
            tension[:, k + 1] = c.get_reals(names).reshape(2, m)
        out["cpu"] = time.process_time() - cpu0
    except FMICallException:
        errors = [text for status, _, text in c.messages if status == "ERROR"]
        out["error"] = errors[0] if errors else "(no message)"
    finally:
        c.free()
    return out


def _attached(text: str) -> list:
    """Per point (from 1), its (line, end) pairs from peers.moordyn.driven's `attached`."""
    return [[tuple(int(v) for v in pair.split(".")) for pair in row.split()] for row in text.split(";")]


def chain_ends(attached: list, tow: int) -> tuple:
    """((line, end) at the tow point, (line, end) at the far end of its chain of deck lines through points
    that join two lines), lines and ends as MoorDyn's (1-based lines, end 0 = A)."""
    line, end = attached[tow - 1][0]
    for _ in range(len(attached)):
        far = next(i for i, pairs in enumerate(attached) if (line, 1 - end) in pairs)
        others = [p for p in attached[far] if p != (line, 1 - end)]
        if len(others) != 1:
            return attached[tow - 1][0], (line, 1 - end)
        line, end = others[0]
    raise ValueError("the chain of lines from the tow point closes on itself")


def pairs(fmu: dict, md: dict, tow: int | None, fairleads: list | None = None) -> list:
    """Per FMU line: (label, FMU anchor series, FMU fairlead series, MoorDyn's at the same ends); fairleads: per
    line of a system, MoorDyn's (deck line, end) at its fairlead and at its anchor (fmu_line_ends; where not
    given, line k's end B and end A)."""
    T = md["tension"]
    if not fmu["system"]:
        (l1, e1), (l2, e2) = chain_ends(_attached(md["attached"]), tow) if tow else ((1, 1), (1, 0))
        return [("tow point", fmu["tension"][0][:, 0], fmu["tension"][1][:, 0], T[e2][:, l2 - 1], T[e1][:, l1 - 1])]
    out = []
    for k in range(min(fmu["tension"].shape[2], len(fairleads) if fairleads is not None else T.shape[2])):
        (lf, ef), (la, ea) = fairleads[k] if fairleads is not None else ((k + 1, 1), (k + 1, 0))
        fa, ff = fmu["tension"][0][:, k], fmu["tension"][1][:, k]
        out.append((f"line {k + 1}", fa, ff, T[ea][:, la - 1], T[ef][:, lf - 1]))
    return out


def statistics(t, label, fa, ff, ma, mf, t_from: float) -> dict:
    """Per end (anchor, fairlead): the peak difference (relative to MoorDyn's peak), the RMS difference
    relative to MoorDyn's mean and range (line_file_validation.rms_difference), and the start (t = 0)."""
    d = lfv.rms_difference(lfv.History("FMU", t, ff, fa, 0.0), lfv.History("MoorDyn", t, mf, ma, 0.0), t_from)
    sel = t >= t_from - 1e-9
    for end, ours, ref in (("fairlead", ff, mf), ("anchor", fa, ma)):
        d[end]["peak"] = float(np.max(ours[sel]) / np.max(ref[sel]) - 1.0) if np.max(ref[sel]) > 0 else math.nan
        d[end]["start"] = float(ours[0] / ref[0] - 1.0) if ref[0] > 0 else float("nan")
    d["label"] = label
    return d


def moordyn_run(path: Path, base: Path | None, tow, moved: list, surge: lfv.Surge, settings: Settings) -> dict:
    """MoorDyn on the deck (peers.moordyn.driven), its coupled objects surging if `moved` (the FMU's moving
    objects) is not empty; tow: MoorPy's point of a one-line deck's tow point, made Coupled where the deck
    has it Fixed; at settings.moordyn_refine times the deck's NumSegs."""
    text = coupled_tow_text(path, tow.number) if tow is not None and tow.type == 1 else None
    if settings.moordyn_refine > 1:
        with tempfile.TemporaryDirectory() as tmp:
            source = Path(tmp) / path.name
            source.write_text(text if text is not None else path.read_text(errors="replace"))
            text = lfv.refined_deck_file(source, settings.moordyn_refine, Path(tmp)).read_text()
        # a fileIC holds the deck's own mesh: the refined one makes its initial conditions itself
        text = re.sub(r"^\s*\S+\s+fileIC\b.*$", "", text, flags=re.M | re.I)
    n = int(round(settings.t_end / settings.comm_step))
    starts = (np.arange(n * settings.calls) / settings.calls) * settings.comm_step
    shift = np.array([[surge.state(t)[i][0] for t in starts] for i in (0, 1)]) if moved else None
    return moordyn.driven(path, settings.comm_step, n, base=base, text=text, calls=settings.calls, shift=shift,
                          timeout=settings.timeout)


def run_deck(fmu, label: str, path: Path, base: Path | None = None, settings: Settings = Settings(),
             series: bool = False) -> dict:
    """One deck: both runs and their comparison, or why there is none (status: "refused" by the FMU, "moordyn"
    fails, "fmu" fails in motion, "ok"); series: also the compared histories (t, then per line its label and
    the FMU's anchor and fairlead tension, MoorDyn's at the same ends)."""
    s, options, _ = pd.moorpy_system(path)
    s = s if s is not None and s.lineList else None
    parameters, inputs = pd.setup(path, s, options)
    lengths = line_lengths(path)
    result = {"deck": label, "amplitude": amplitude(path, settings), "lines": len(lengths)}
    # what moves: decided on the deck; whether it is a system the FMU says at its start
    tow = pd.tow_point(s) if s is not None and not s.bodyList else None
    moved_system = ([k[:-2] for k in inputs if re.fullmatch(r"(body|point)\[\d+\]\.x", k)] if has_bodies(path)
                    else ["body[1]"] if pd.coupled_points(path) else [])
    moved_system = [p for p in moved_system if not p.startswith("point") or has_bodies(path)]
    surge = lfv.Surge(amplitude=result["amplitude"], period=settings.period)
    ours = fmu_run(fmu, parameters, inputs, len(lengths), lambda system: moved_system if system else
                   (["tow"] if "tow.x" in inputs else []), surge, settings)
    if ours["refused"]:
        return {**result, "status": "refused", "reason": ours["error"]}
    system, moved = ours["system"], ours["moved"]
    result.update(system=system, moved=", ".join(moved) if moved else "nothing", t_end=settings.t_end)
    md = moordyn_run(path, base, None if system or not moved else tow, moved, surge, settings)
    result.update(cpu_fmu=ours["cpu_init"] + ours["cpu"], cpu_fmu_run=ours["cpu"], fmu_error=ours["error"],
                  cpu_moordyn=md.get("cpu_init", 0.0) + md.get("cpu", 0.0), cpu_moordyn_init=md.get("cpu_init", 0.0),
                  moordyn_error=md["error"], moordyn_layout=md.get("layout", ""), tmax_ic=_option(path, "TmaxIC"),
                  dtm=_option(path, "dtM"))
    if "tension" not in md or ours["tension"] is None:
        return {**result, "status": "moordyn" if "tension" not in md else "fmu"}
    t = ours["t"]
    usable = np.isfinite(md["tension"]).all(axis=(0, 2)) & np.isfinite(ours["tension"]).all(axis=(0, 2))
    upto = int(np.argmin(usable)) if not usable.all() else len(t)
    if upto * settings.comm_step <= settings.t_from:
        return {**result, "status": "moordyn" if md["error"] else "fmu"}
    fairleads = fmu_line_ends(path) if system else None
    compared = pairs(ours, md, tow.number if (not system and tow is not None) else None, fairleads)
    rows = [statistics(t[:upto], lab, *(x[:upto] for x in histories), settings.t_from) for lab, *histories in compared]
    if series:
        result["series"] = (t, compared)
    result.update(status="ok", rows=rows, until=float(t[upto - 1]), 
                  ends=" ".join(f"{lf}{'AB'[ef]}-{la}{'AB'[ea]}" for (lf, ef), (la, ea) in fairleads or []),
                  worst={f"{end}.{key}": max((abs(r[end][key]) for r in rows if np.isfinite(r[end][key])), default=float("nan"))
                         for end in ("fairlead", "anchor") for key in ("peak", "rel_mean", "rel_range", "start")})
    return result


def _option(path: Path, name: str):
    for header, rows in _sections(path):
        if "OPTION" in header:
            for row in rows:
                words = row.split()
                if len(words) > 1 and words[1].lower() == name.lower():
                    return words[0]
    return None


# ----------------------------------------------------------------------------- the census
def census_cases(moordyn_root: Path, moorpy_root: Path) -> list:
    """(label, path, base) of the census's decks (public_decks.census_decks), base the census folder MoorDyn's
    copy holds (its SeafloorFile paths are relative to that folder's parent)."""
    out = []
    for label, path in pd.census_decks(moordyn_root, moorpy_root):
        root = moordyn_root if label.startswith("md:") else moorpy_root
        folders = pd.CENSUS_FOLDERS["moordyn" if label.startswith("md:") else "moorpy"]
        folder = next(f for f in folders if label[3:].startswith(f + "/"))
        out.append((label, path, root / folder))
    return out


def compute(fmu, cases, settings: Settings = Settings(), progress=None) -> dict:
    decks = []
    for label, path, base in cases:
        decks.append(run_deck(fmu, label, Path(path), base, settings))
        if progress:
            progress(decks[-1])
    from importlib.metadata import version
    return {"settings": asdict(settings), "decks": decks, "moordyn_version": version("moordyn")}


# ----------------------------------------------------------------------------- Markdown
def _pct(x, sign: bool = False) -> str:
    return "" if x is None or not np.isfinite(x) else f"{100.0 * x:{'+' if sign else ''}.2f} %"


def _note(d: dict) -> str:
    notes = []
    if d.get("moved") == "nothing":
        notes.append("no coupled object: unforced")
    if d.get("moordyn_error"):
        notes.append(f"MoorDyn: {d['moordyn_error']}")
    if d.get("fmu_error"):
        notes.append(f"FMU: {d['fmu_error']}")
    if d["status"] == "ok" and d["until"] < d.get("t_end", d["until"]):
        notes.append(f"compared up to {d['until']:g} s")
    try:
        float(d.get("dtm") or 0.0)
    except ValueError:
        notes.append(f"its dtM is `{d['dtm']}`, not a number")
    starts = _starts(d)
    tmax = f"TmaxIC {d['tmax_ic']} s" if d.get("tmax_ic") else "MoorDyn's default TmaxIC"
    if any(s > UNLOADED for s in starts):
        notes.append(f"MoorDyn starts with a line unloaded ({tmax})")
    elif any(abs(s) > 0.02 for s in starts):
        notes.append(f"MoorDyn's start ({tmax}) off the FMU's statics")
    if d["status"] == "ok" and not any(np.isfinite(v) for v in d["worst"].values() if v is not None):
        notes.append("the motion does not reach the lines (MoorDyn's tensions constant)")
    return "; ".join(notes).replace("|", "\\|")


UNLOADED = 99.0  # a start above MoorDyn's by this (MoorDyn's tension under 1 % of the FMU's): it starts unloaded


def _starts(d: dict) -> list:
    """The start differences (FMU / MoorDyn - 1 at t = 0) of every compared line end."""
    return [r[end]["start"] for r in d.get("rows", []) for end in ("fairlead", "anchor")
            if r[end]["start"] is not None and np.isfinite(r[end]["start"])]


def markdown(data: dict) -> str:
    se = data["settings"]
    decks = data["decks"]
    loaded = [d for d in decks if d["status"] != "refused"]
    ok = [d for d in loaded if d["status"] == "ok"]
    out = [f"{len(loaded)} decks the FMU loads (of {len(decks)}); compared with MoorDyn {data['moordyn_version']}: "
           f"{len(ok)}; MoorDyn fails on {sum(d['status'] == 'moordyn' for d in loaded)}, the FMU in motion on "
           f"{sum(d['status'] == 'fmu' for d in loaded)}. Surge A (1 − cos 2πt/T), T {se['period']:g} s, A = "
           f"{100 * se['fraction']:g} % of the deck's longest line, at most {se['cap']:g} m; {se['t_end']:g} s, "
           f"statistics from {se['t_from']:g} s; the worst line of each deck. Peak: the FMU's largest tension over "
           "MoorDyn's − 1; RMS: of the difference, over MoorDyn's mean and over its range (max − min); start: at "
           "t = 0, the FMU's static start over MoorDyn's after its initial conditions − 1. CPU [s]: the FMU's start "
           "and run; MoorDyn's initial conditions + run.", "",
           "| deck | moves | A [m] | fairlead: peak | RMS / mean | RMS / range | anchor: peak | RMS / mean | "
           "RMS / range | start | CPU FMU | CPU MoorDyn | note |", "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for d in sorted(loaded, key=lambda d: d["deck"]):
        w = d.get("worst", {})
        cells = [_pct(w.get(k)) for k in ("fairlead.peak", "fairlead.rel_mean", "fairlead.rel_range", "anchor.peak",
                                           "anchor.rel_mean", "anchor.rel_range")]
        starts = [s for s in _starts(d) if s <= UNLOADED]
        start = max(starts, key=abs) if starts else None
        cpu_md = (f"{d['cpu_moordyn_init']:.2f} + {d['cpu_moordyn'] - d['cpu_moordyn_init']:.2f}"
                  if d.get("moordyn_error", "") == "" or d["status"] == "ok" else "")
        out.append(f"| `{d['deck']}` | {d.get('moved', '')} | {d['amplitude']:.3g} | " + " | ".join(cells) +
                   f" | {_pct(start, sign=True)} | {d.get('cpu_fmu', 0.0):.2f} | {cpu_md} | {_note(d)} |")
    return "\n".join(out)


def _summary(d: dict) -> str:
    w = d.get("worst", {})
    return (f"{d['deck']}: {d['status']}" + (f", fairlead RMS/mean {_pct(w.get('fairlead.rel_mean'))}, peak "
            f"{_pct(w.get('fairlead.peak'))}" if w else "") + (f" ({_note(d)})" if d["status"] != "refused" and _note(d) else ""))


def main(argv=None) -> int:  # pragma: no cover
    from ucable.paths import fmu_path

    ap = argparse.ArgumentParser(prog="scripts/census_dynamics", description=__doc__.split("\n\n")[0])
    ap.add_argument("--census", nargs=2, metavar=("MOORDYN", "MOORPY"), type=Path,
                    help="checkouts of MoorDyn and MoorPy (the census's decks)")
    ap.add_argument("--decks", nargs="*", default=None, help="only these decks (labels, e.g. md:tests/Mooring/lines.txt)")
    ap.add_argument("--t-end", type=float, default=Settings.t_end)
    ap.add_argument("--from-json", type=Path, help="write the table from a saved study (its --json) without running")
    add_report_options(ap, NAME)
    a = ap.parse_args(argv)
    if a.from_json:
        publish(markdown(json.loads(a.from_json.read_text())), NAME, a.doc)
        return 0
    if not a.census:
        ap.error("--census MOORDYN MOORPY is needed (or --from-json)")
    cases = census_cases(*a.census)
    if a.decks:
        cases = [c for c in cases if c[0] in a.decks]
    done = []

    def progress(d):
        print(_summary(d), file=sys.stderr, flush=True)
        done.append(d)
        if a.json:  # the decks so far, should a later one stop the study
            write_json(a.json, {"decks": done})

    data = compute(a.fmu or fmu_path(), cases, Settings(t_end=a.t_end), progress=progress)
    publish(markdown(data), NAME, a.doc, a.json, data)
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
