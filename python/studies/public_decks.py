"""Public MoorDyn and MoorPy decks (tests/data/decks/public, sources in its SOURCES.md) through `lineFile`:
each one the FMU accepts (one line, or a mooring system of lines on coupled bodies and points) is
compared with MoorPy's statics of the same file: every line's fairlead and anchor tension.

The FMU's coupled bodies start at the deck's X0 ... y0 (MoorDyn places them there before the coupling
moves them); MoorPy solves the deck as it reads it. What the deck does not set is set as MoorDyn has
it (docs/lines.md): the seabed from kBot and cBot times the diameter, tension-only lines.

compare() computes one deck, survey() all of them; used by tests/python/test_public_decks.py.
"""

from __future__ import annotations

import contextlib
import io
import warnings
from pathlib import Path

from ucable.fmu import CableFMU, FMICallException
from ucable.paths import REPO_ROOT
from .mooring_system import MOORDYN_GRAVITY

PUBLIC = REPO_ROOT / "tests" / "data" / "decks" / "public"
POSE = ("x", "y", "z", "roll", "pitch", "yaw")


def moorpy_system(path: Path):
    """MoorPy's equilibrium of the deck (its coupled bodies and points where the deck puts them)."""
    import moorpy as mp

    with contextlib.redirect_stdout(io.StringIO()), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        s = mp.System(file=str(path), rho=1025.0, g=MOORDYN_GRAVITY)
        if not s.depth:
            s.depth = max(-float(p.r[2]) for p in s.pointList)
        options = {k.lower(): v for k, v in s.MDoptions.items()}
        if "g" in options or "gravity" in options:
            s.g = float(options.get("g", options.get("gravity")))
        if "wtrdnsty" in options or "rho" in options:
            s.rho = float(options.get("wtrdnsty", options.get("rho")))
        s.initialize()
        s.solveEquilibrium(tol=1e-8, maxIter=5000)
    return s, options


def _coupled(s, end: int) -> bool:
    """Whether MoorPy's point `end` (1-based) is coupled: a Vessel/Coupled point or one on a coupled body."""
    p = s.pointList[end - 1]
    if p.type == -1:
        return True
    return any(end in b.attachedP and b.type == -1 for b in s.bodyList)


def parameters(path: Path, options: dict, diameter: float) -> dict:
    return {"lineFile": str(path), "enableSeabed": True,
            "seabedStiffness": float(options.get("kbot", 3.0e6)) * diameter,
            "seabedDamping": float(options.get("cbot", 3.0e5)) * diameter, "enableCompression": False}


def compare(fmu, path: Path) -> dict:
    """{"status": "refused", "reason"} or {"status": "ok", "system", "lines": [(MoorPy fairlead, FMU
    fairlead, MoorPy anchor, FMU anchor)], "worst"}."""
    s, options = moorpy_system(path)
    ref = []
    for ln in s.lineList:
        a, b = ln.attached
        fair_is_b = _coupled(s, b) or not _coupled(s, a)
        ref.append((float(ln.TB if fair_is_b else ln.TA), float(ln.TA if fair_is_b else ln.TB)))
    bottom = min(s.lineList, key=lambda ln: min(s.pointList[n - 1].r[2] for n in ln.attached))
    inputs = {}
    for k, body in enumerate(s.bodyList, start=1):
        if body.type == -1:
            inputs.update({f"body[{k}].{name}": float(v) for name, v in zip(POSE, body.r6)})
    single = not s.bodyList and sum(p.type == -1 for p in s.pointList) == 1 and \
        sum(p.type == 1 for p in s.pointList) == 1
    if single:  # one chain: the tow point is the deck's vessel point
        vessel = next(p for p in s.pointList if p.type == -1)
        inputs = {f"tow.{c}": float(v) for c, v in zip("xyz", vessel.r)}
    c = CableFMU(fmu, parameters=parameters(path, options, float(bottom.type["d_vol"])), logging_on=True)
    try:
        c.initialize(inputs=inputs)
        system = any("a mooring system" in text for _, _, text in c.messages)
        if system:
            ours = [(c.get(f"line[{k}].fairleadTension"), c.get(f"line[{k}].anchorTension"))
                    for k in range(1, len(ref) + 1)]
            pairs = [(r[0], o[0], r[1], o[1]) for r, o in zip(ref, ours)]
        else:  # a chain: its tow point and anchor against the chain's ends in MoorPy
            fair = next(r[0] for r, ln in zip(ref, s.lineList) if any(_coupled(s, n) for n in ln.attached))
            anchor = next(ln for ln in s.lineList if any(s.pointList[n - 1].type == 1 for n in ln.attached))
            anch = float(anchor.TA if s.pointList[anchor.attached[0] - 1].type == 1 else anchor.TB)
            pairs = [(fair, c.get("towTension"), anch, c.get("endTension"))]
    except FMICallException:
        errors = [text for status, _, text in c.messages if status == "ERROR"]
        return {"status": "refused", "reason": errors[0] if errors else "(no message)"}
    finally:
        c.free()
    worst = max(max(abs(f / fr - 1), abs(a / ar - 1)) for fr, f, ar, a in pairs)
    return {"status": "ok", "system": system, "lines": pairs, "worst": worst}


def decks() -> list:
    return sorted(p for p in PUBLIC.iterdir() if p.suffix in (".dat", ".txt"))


def survey(fmu) -> dict:
    return {p.name: compare(fmu, p) for p in decks()}


def markdown(results: dict) -> str:
    out = ["| deck | read as | lines | largest tension difference from MoorPy |", "|---|---|---|---|"]
    for name, r in results.items():
        if r["status"] == "ok":
            out.append(f"| `{name}` | {'system' if r['system'] else 'one line'} | {len(r['lines'])} | "
                       f"{100 * r['worst']:.3f} % |")
        else:
            out.append(f"| `{name}` | refused: {r['reason']} | | |")
    return "\n".join(out)


if __name__ == "__main__":  # pragma: no cover
    from ucable.paths import fmu_path

    print(markdown(survey(fmu_path())))
