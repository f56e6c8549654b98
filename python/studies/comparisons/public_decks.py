"""Public MoorDyn and MoorPy decks through `lineFile`, compared with MoorPy's statics of the same file.

Two uses:

- the decks kept in tests/data/decks/public (sources in its SOURCES.md): survey() loads each one and
  compares every line's fairlead and anchor tension with MoorPy's (tests/python/test_public_decks.py);
- the census of every MoorDyn v2 input file of the MoorDyn (`tests/Mooring`, `example`) and MoorPy
  (`examples`, `tests`) repositories, from checkouts of them: census() loads each one (a file with a
  LINE TYPES and a LINES section) and records what the FMU does with it, loaded and compared with MoorPy
  or refused with its message; census_markdown() is the table of docs/systems_mooring.md, "Public decks".

The FMU's coupled bodies start at the deck's X0 ... y0 (MoorDyn places them there before the coupling
moves them), a deck's one tow point where the deck puts it (its Vessel point, or without one the Fixed
point the FMU takes as the tow point: the higher of two, on a tie the one at AttachB); MoorPy solves the
deck as it reads it. What the deck does not set is set as MoorDyn has it (docs/lines.md): the seabed
from kBot and cBot times the diameter, tension-only lines.

    python -m studies.comparisons.public_decks [--doc docs/systems_mooring.md]      # the kept decks: their table
    python -m studies.comparisons.public_decks --census MOORDYN MOORPY [--json FILE] [--doc docs/systems_mooring.md]
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

from ucable.fmu import CableFMU, FMICallException
from ucable.paths import REPO_ROOT
from ucable.units import STANDARD_GRAVITY, WATER_DENSITY
from ..peers import moorpy

PUBLIC = REPO_ROOT / "tests" / "data" / "decks" / "public"
POSE = ("x", "y", "z", "roll", "pitch", "yaw")
CENSUS_FOLDERS = {"moordyn": ("tests/Mooring", "example"), "moorpy": ("examples", "tests")}


def moorpy_system(path: Path):
    """MoorPy's equilibrium of the deck (its coupled bodies and points where the deck puts them):
    (system, options, None), or (system or None, options, why MoorPy fails)."""
    options, s = {}, None
    with moorpy.silenced():
        try:
            s = moorpy.system(path, rho=WATER_DENSITY, g=STANDARD_GRAVITY)
            if not s.depth:
                s.depth = max(-float(p.r[2]) for p in s.pointList)
            options = {k.lower(): v for k, v in s.MDoptions.items()}
            if "g" in options or "gravity" in options:
                s.g = float(options.get("g", options.get("gravity")))
            if "wtrdnsty" in options or "rho" in options:
                s.rho = float(options.get("wtrdnsty", options.get("rho")))
            s.initialize()
            ok = s.solveEquilibrium(tol=1e-8, maxIter=5000)
        except Exception as e:  # noqa: BLE001  (MoorPy's own failure is a result here)
            return s, options, f"{type(e).__name__}: {e}".strip()
    if ok is False:
        return s, options, "solveEquilibrium did not converge"
    return s, options, unbalanced(s)


def unbalanced(s):
    """Why MoorPy's equilibrium is not one (tensions not finite, a free point's forces not balanced to
    1e-3 of the largest tension), or None."""
    import numpy as np

    tensions = [float(t) for ln in s.lineList for t in (ln.TA, ln.TB)]
    if not all(np.isfinite(tensions)):
        return "its line tensions are not finite"
    scale = max(max(abs(t) for t in tensions), 1.0)
    for p in s.pointList:
        if p.type == 0 and not any(p.number in b.attachedP for b in s.bodyList):
            residual = float(np.linalg.norm(p.getForces()))
            if residual > 1e-3 * max(scale, abs(p.m * s.g)):
                return f"its point {p.number} is left with {residual:.4g} N unbalanced"
    return None


def _coupled(s, end: int) -> bool:
    """Whether MoorPy's point `end` (1-based) is coupled: a Vessel/Coupled point or one on a coupled body."""
    p = s.pointList[end - 1]
    if p.type == -1:
        return True
    return any(end in b.attachedP and b.type == -1 for b in s.bodyList)


def tow_point(s):
    """The point (MoorPy's) the FMU takes as a one-line deck's tow point: the Vessel point, else the Fixed
    point (the higher of two; on a tie the one at AttachB of its line), else None."""
    vessels = [p for p in s.pointList if p.type == -1]
    if vessels:
        return vessels[0]
    fixed = [p for p in s.pointList if p.type == 1]
    if not fixed:
        return None

    def at_b(p):
        ln = next((ln for ln in s.lineList if p.number in ln.attached), None)
        return ln is not None and ln.attached[1] == p.number

    return max(fixed, key=lambda p: (float(p.r[2]), at_b(p)))


def coupled_points(path: Path) -> dict:
    """The deck's Coupled (Vessel) points as it places them, read from its POINTS table (MoorDyn v2's
    `POINTS`, v1's `CONNECTION` or `NODE` tables): {ID: (x, y, z)}. Read from the file itself, not through
    MoorPy, which fails on some decks the FMU reads (a body's `CdA` of two values)."""
    points, in_points = {}, False
    for line in path.read_text(errors="replace").splitlines():
        words = line.split()
        if line.lstrip().startswith("---"):
            upper = line.upper()
            in_points = any(k in upper for k in ("POINT", "CONNECTION", "NODE"))
            continue
        if not in_points or len(words) < 5:
            continue
        try:
            number, xyz = int(words[0]), tuple(float(v) for v in words[2:5])
        except ValueError:
            continue  # a header row
        if words[1].lower() in ("vessel", "coupled", "cpld"):
            points[number] = xyz
    return points


def parameters(path: Path, options: dict, diameter: float) -> dict:
    return {"lineFile": str(path), "enableSeabed": True,
            "seabedStiffness": float(options.get("kbot", 3.0e6)) * diameter,
            "seabedDamping": float(options.get("cbot", 3.0e5)) * diameter, "enableCompression": False}


def _line_pairs(s) -> list:
    """Per MoorPy line, its (fairlead, anchor) tension as the FMU orients a line of a system: the fairlead
    at its end on a coupled object (AttachB where both or neither are); None where neither end is on one
    (the orientation is then the FMU's walk, matched below)."""
    out = []
    for ln in s.lineList:
        a, b = ln.attached
        if _coupled(s, a) or _coupled(s, b):
            fair_is_b = _coupled(s, b)
            out.append((float(ln.TB if fair_is_b else ln.TA), float(ln.TA if fair_is_b else ln.TB), True))
        else:
            out.append((float(ln.TB), float(ln.TA), False))
    return out


def _single_pair(s, tow) -> tuple:
    """MoorPy's tension at a one-line deck's tow point and at the far end of its chain."""
    ln = next(ln for ln in s.lineList if tow.number in ln.attached)
    fair = float(ln.TA if ln.attached[0] == tow.number else ln.TB)
    counts = {p.number: sum(p.number in x.attached for x in s.lineList) for p in s.pointList}
    far = next(n for n, c in counts.items() if c == 1 and n != tow.number)
    last = next(x for x in s.lineList if far in x.attached)
    return fair, float(last.TA if last.attached[0] == far else last.TB)


def _relative(ours: float, ref: float) -> float:
    return abs(ours - ref) / max(abs(ref), 1e-12)


def setup(path: Path, s=None, options=None) -> tuple:
    """The FMU's parameters (parameters(): the deck completed as MoorDyn has it) and initial inputs of the
    deck, from MoorPy's reading where it has one: its coupled bodies at their X0 ... y0, a one-line deck's tow
    point (tow_point), a system's Coupled points where the deck puts them."""
    options = options or {}
    inputs, diameter = {}, 0.1
    if s is not None and s.lineList:
        bottom = min(s.lineList, key=lambda ln: min(s.pointList[n - 1].r[2] for n in ln.attached))
        diameter = float(bottom.type["d_vol"])
        for k, body in enumerate(s.bodyList, start=1):
            if body.type == -1:
                inputs.update({f"body[{k}].{name}": float(v) for name, v in zip(POSE, body.r6)})
        tow = tow_point(s) if not s.bodyList else None
        if tow is not None:
            inputs.update({f"tow.{c}": float(v) for c, v in zip("xyz", tow.r)})
    # a system's Coupled points where the deck puts them (the inputs' default is the origin)
    for k, xyz in coupled_points(path).items():
        inputs.update({f"point[{k}].{c}": v for c, v in zip("xyz", xyz)})
    return parameters(path, options, diameter), inputs


def load(fmu, path: Path, s=None, options=None, given=None) -> dict:
    """The FMU's initialization of the deck, inputs from MoorPy's reading where it has one (setup):
    {"status": "refused", "reason", "warnings"} or {"status": "ok", "system", "outputs", "warnings"}.
    given: the FMU's parameters (default: setup's, the deck completed as MoorDyn has it)."""
    completed, inputs = setup(path, s, options)
    c = CableFMU(fmu, parameters=given if given is not None else completed, logging_on=True)
    warned = lambda: [text for status, _, text in c.messages if status == "WARNING"]  # noqa: E731
    try:
        c.initialize(inputs=inputs)
        system = any("a mooring system" in text for _, _, text in c.messages)
        n = len(s.lineList) if s is not None else 0
        if system:
            outputs = [(c.get(f"line[{k}].fairleadTension"), c.get(f"line[{k}].anchorTension"))
                       for k in range(1, n + 1)]
        else:
            outputs = [(c.get("towTension"), c.get("endTension"))]
        return {"status": "ok", "system": system, "outputs": outputs, "warnings": warned()}
    except FMICallException:
        errors = [text for status, _, text in c.messages if status == "ERROR"]
        reason = errors[0] if errors else "(no message)"
        return {"status": "refused", "reason": reason.split(f"lineFile {path}, ")[-1], "warnings": warned()}
    finally:
        c.free()


def compare(fmu, path: Path, given=None) -> dict:
    """{"status": "refused", "reason", "moorpy"} or {"status": "ok", "system", "lines": [(MoorPy fairlead,
    FMU fairlead, MoorPy anchor, FMU anchor)], "worst", "moorpy"}: "moorpy" is None, or why MoorPy fails
    (then no comparison: "worst" None). given: the FMU's parameters (load)."""
    s, options, why = moorpy_system(path)
    result = load(fmu, path, s if s is not None and s.lineList else None, options, given)
    result["moorpy"] = why
    if result["status"] != "ok" or why is not None:
        result.setdefault("lines", [])
        result["worst"] = None
        return result
    if result["system"]:
        pairs = []
        for (fr, ar, oriented), (f, a) in zip(_line_pairs(s), result["outputs"]):
            if not oriented and max(_relative(a, fr), _relative(f, ar)) < max(_relative(f, fr), _relative(a, ar)):
                fr, ar = ar, fr  # a line between fixed points or nodes: the FMU walks it from its own end
            pairs.append((fr, f, ar, a))
    else:
        fr, ar = _single_pair(s, tow_point(s))
        (f, a), = result["outputs"]
        pairs = [(fr, f, ar, a)]
    result["lines"] = pairs
    result["worst"] = max(max(_relative(f, fr), _relative(a, ar)) for fr, f, ar, a in pairs)
    return result


def decks() -> list:
    return sorted(p for p in PUBLIC.iterdir() if p.suffix in (".dat", ".txt"))


def survey(fmu) -> dict:
    return {p.name: compare(fmu, p) for p in decks()}


def _difference(r: dict) -> str:
    return f"{100 * r['worst']:.3f} %" if r["worst"] is not None else f"MoorPy fails: {r['moorpy']}"


def markdown(results: dict) -> str:
    out = ["| deck | read as | lines | largest tension difference from MoorPy |", "|---|---|---|---|"]
    for name, r in results.items():
        if r["status"] == "ok":
            out.append(f"| `{name}` | {'system' if r['system'] else 'one line'} | {len(r['outputs'])} | "
                       f"{_difference(r)} |")
        else:
            out.append(f"| `{name}` | refused: {r['reason']} | | |")
    return "\n".join(out)


# ------------------------------------------------------------------------------------------- census
def is_deck(path: Path) -> bool:
    """A MoorDyn v2 input file: a header line naming LINE TYPES (or LINE DICTIONARY) and one naming LINES."""
    try:
        text = path.read_text(errors="replace").upper()
    except OSError:
        return False
    headers = [line for line in text.splitlines() if "---" in line]
    return (any("LINE TYPES" in h or "LINE DICTIONARY" in h for h in headers)
            and any(re.search(r"\bLINES\b|LINE LIST|LINE PROPERTIES", h) for h in headers))


def census_decks(moordyn: Path, moorpy: Path) -> list:
    """(label, path) of every deck in the two checkouts' folders, label "md:<path>" or "mp:<path>"."""
    found = []
    for prefix, root in (("md", moordyn), ("mp", moorpy)):
        for folder in CENSUS_FOLDERS["moordyn" if prefix == "md" else "moorpy"]:
            for p in sorted((root / folder).rglob("*")):
                if p.is_file() and p.suffix.lower() in (".txt", ".dat") and is_deck(p):
                    found.append((f"{prefix}:{p.relative_to(root).as_posix()}", p))
    return found


def census(fmu, moordyn: Path, moorpy: Path, progress=None) -> list:
    results = []
    for label, path in census_decks(moordyn, moorpy):
        if progress:
            progress(label)
        r = compare(fmu, path)
        results.append({"deck": label, **r})
    return results


# The reasons of the census table: (pattern on the FMU's message or MoorPy's failure, the reason shown).
REASONS = [
    (r"pushes the line into its anchor", "a current pushing a line into its anchor at the start"),
    (r"through or above the waterline", "a rod through the waterline on a body"),
    (r"rod \d+ is coupled and pinned|pinned to Free", "a pinned rod"),
    (r"the Syrope model", "Syrope lines"),
    (r"SeafloorFile|bathymetry", "a bathymetry file"),
    (r"viscoelastic", "viscoelastic EA"),
    (r"Cl = ", "vortex-induced vibration (`Cl`)"),
    (r"WaveKin = (\d+)", "`WaveKin` {0}"),
    (r"Currents = (\d+)", "`Currents` {0}"),
    (r"the line is too short for where its ends are",
     "a line stretched beyond what it survives at the deck's positions"),
    (r"the line stretches \S+ % at rest", "a line stretched beyond what it survives at its equilibrium"),
    (r"rests on the waterline's buoyancy ramp", "a float standing through the water surface"),
    (r"within the waves' reach of the surface", "a line in the wave zone (wetted below z = 0, not below the waves)"),
    (r"no static equilibrium", "no static equilibrium (a line longer than the way down and across)"),
    (r"static equilibrium not found", "static equilibrium not found"),
    (r"pinned", "a pinned body"),
    (r"static equilibrium of the free points", "static equilibrium of the free points not found"),
    (r"exceeds the breaking limit", "a wave component steeper than the breaking limit 1/7"),
]


def reason_of(result: dict) -> str:
    if result["status"] == "ok":
        return "loaded"
    for pattern, label in REASONS:
        m = re.search(pattern, result["reason"])
        if m:
            return label.format(*m.groups())
    return result["reason"]


def census_markdown(results: list) -> str:
    loaded = [r for r in results if r["status"] == "ok"]
    out = [f"{len(results)} decks: {len(loaded)} load "
           f"({sum(not r['system'] for r in loaded)} as one line, {sum(r['system'] for r in loaded)} as "
           f"mooring systems), {len(results) - len(loaded)} refused.", "",
           "| deck | FMU | largest tension difference from MoorPy |", "|---|---|---|"]
    for r in sorted(loaded, key=lambda r: r["deck"]):
        n = len(r["lines"])
        lines = f"{n} line{'s' if n > 1 else ''}" if r["system"] and n else ""
        out.append(f"| `{r['deck']}` | {'system' if r['system'] else 'one line'}{', ' + lines if lines else ''} | "
                   f"{_difference(r)} |")
    out += ["", "| reason refused | decks | the FMU's message (first deck) |", "|---|---|---|"]
    groups: dict = {}
    for r in results:
        if r["status"] != "ok":
            groups.setdefault(reason_of(r), []).append(r)
    for reason, rs in sorted(groups.items(), key=lambda kv: (-len(kv[1]), kv[0])):
        names = ", ".join(f"`{r['deck']}`" + (" (MoorPy fails too)" if r["moorpy"] else "") for r in rs)
        message = rs[0]["reason"].replace("|", "\\|")
        out.append(f"| {reason} | {len(rs)}: {names} | {message} |")
    return "\n".join(out)


def main(argv=None) -> int:  # pragma: no cover
    from ucable.paths import fmu_path

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--census", nargs=2, metavar=("MOORDYN", "MOORPY"), type=Path,
                    help="checkouts of FloatingArrayDesign/MoorDyn and NREL/MoorPy: the census of their decks")
    ap.add_argument("--json", type=Path, help="also write the results as JSON")
    ap.add_argument("--fmu", type=Path, default=None, help="the FMU (default: the build's)")
    ap.add_argument("--doc", type=Path, help="also write the table into this Markdown file, between "
                    "<!-- BEGIN public_decks[_census] --> and <!-- END ... -->")
    args = ap.parse_args(argv)
    fmu = args.fmu or fmu_path()
    if args.census:
        results = census(fmu, *args.census, progress=lambda d: print(d, file=sys.stderr, flush=True))
        text, name = census_markdown(results), "public_decks_census"
    else:
        results = survey(fmu)
        text, name = markdown(results), "public_decks"
    from ..doc_section import publish
    publish(text, name, args.doc, args.json, results)
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
