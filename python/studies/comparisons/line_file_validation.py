"""Lines read from MoorDyn v2 decks (`lineFile`) against independent codes fed the same file:

* statics against MoorPy (quasi-static elastic catenaries per line with seabed contact, solved for
  the free points): fairlead and anchor tension at a few fairlead offsets, and MoorDyn's own static
  solution (`moordyn.Init`) for scale;
* dynamics against MoorDyn v2 (PyPI `moordyn`): the fairlead surging x = A (1 - cos 2 pi t / T) from
  the static equilibrium (at rest at t = 0 in both codes), fairlead and anchor tension histories and
  their RMS difference.

The FMU reads the deck through `lineFile`; what a deck does not set is set alongside it as MoorDyn
would have it (docs/lines.md): the seabed from the deck's kBot and cBot times the diameter of the
line type on the seabed, MoorDyn's tension-only axial law (enableCompression false).

Used by scripts/line_file_report (-> docs/lines_validation.md) and tests/python/test_line_file.py.
"""

from __future__ import annotations

import math
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.paths import REPO_ROOT
from ucable.units import GRAVITY, WATER_DENSITY
from ..peers import moordyn, moorpy

DECKS = REPO_ROOT / "tests" / "data" / "decks"


# ----------------------------------------------------------------------------- the deck
@dataclass
class Deck:
    """What the comparison needs to know of a deck (read by MoorPy's own reader)."""
    path: Path
    fairlead: np.ndarray          # the Vessel/Coupled point
    anchor: np.ndarray            # the Fixed point
    depth: float
    options: dict = field(default_factory=dict)  # OPTIONS as name (lower case) -> text
    bottom_diameter: float = 0.0  # Diam of the line attached to the anchor (the one on the seabed)
    lines: list = field(default_factory=list)    # (type name, length, NumSegs), as listed

    def option(self, name: str, default: float) -> float:
        return float(self.options.get(name.lower(), default))


def read_deck(path: Path) -> Deck:
    s = moorpy.system(path)
    fair = [p for p in s.pointList if p.type == -1]
    anch = [p for p in s.pointList if p.type == 1]
    if len(fair) != 1 or len(anch) != 1:
        raise ValueError(f"{path}: one Vessel/Coupled and one Fixed point expected")
    bottom = [ln for ln in s.lineList if anch[0].number in ln.attached]
    return Deck(path=Path(path), fairlead=np.array(fair[0].r, float), anchor=np.array(anch[0].r, float),
                depth=float(s.depth), options={k.lower(): v for k, v in s.MDoptions.items()},
                bottom_diameter=float(bottom[0].type["d_vol"]),
                lines=[(ln.type["name"], float(ln.L), int(ln.nNodes - 1)) for ln in s.lineList])


def default_elements(deck: Deck) -> int:
    """Our elements for the deck by the rule of docs/lines.md: ceil(NumSegs / 2) per line."""
    return sum(max(1, (n + 1) // 2) for _, _, n in deck.lines)


def fmu_parameters(deck: Deck, **extra) -> dict:
    """lineFile plus what the deck does not set, as MoorDyn has it (docs/lines.md)."""
    d = deck.bottom_diameter
    p = {"lineFile": str(deck.path), "enableSeabed": True,
         "seabedStiffness": deck.option("kBot", 3.0e6) * d, "seabedDamping": deck.option("cBot", 3.0e5) * d,
         "enableCompression": False}
    p.update(extra)
    return p


def refined_deck(deck: Deck, factor: int, directory: Path) -> Deck:
    """The deck with every line in factor x NumSegs segments and dtM / factor (refined_deck_file)."""
    return read_deck(refined_deck_file(deck.path, factor, directory))


def refined_deck_file(source: Path, factor: int, directory: Path) -> Path:
    """The deck with every line in factor x NumSegs segments and dtM / factor, the damping kept in N s
    (BA = -zeta is converted with the original segment length, one line type per line), written to
    directory: the same physics on a finer MoorDyn mesh."""
    source = Path(source)
    text = source.read_text().splitlines()
    section, skip, types, type_rows, line_rows = None, 0, {}, [], []
    for i, row in enumerate(text):
        if "---" in row:
            u = row.upper()
            section = ("types" if "LINE TYPES" in u or "LINE DICTIONARY" in u else
                       "lines" if any(k in u for k in ("LINES", "LINE LIST", "LINE PROPERTIES")) else
                       "options" if "OPTIONS" in u else None)
            skip = 2 if section in ("types", "lines") else 0
            continue
        if skip:
            skip -= 1
            continue
        tokens = row.split()
        if not tokens or tokens[0].startswith("#"):
            continue
        if section == "types":
            types[tokens[0]] = tokens
            type_rows.append(i)
        elif section == "lines":
            line_rows.append(i)
        elif section == "options" and len(tokens) > 1 and tokens[1].lower() == "dtm":
            text[i] = f"{float(tokens[0]) / factor:.6g} dtM"
    new_types = []
    for i in line_rows:
        t = text[i].split()
        base = types[t[1]]
        length, n = float(t[4]), int(t[5])
        ba = float(base[4])
        if ba < 0:
            ba = -ba * (length / n) * math.sqrt(float(base[3]) * float(base[2]))
        name = f"{base[0]}_{t[0]}"
        new_types.append(" ".join([name, *base[1:4], f"{ba:.17g}", *base[5:]]))
        text[i] = " ".join([t[0], name, t[2], t[3], t[4], str(n * factor), *t[6:]])
    text[type_rows[0]:type_rows[-1] + 1] = new_types
    path = Path(directory) / f"{source.stem}_x{factor}{source.suffix}"
    path.write_text("\n".join(text) + "\n")
    return path


# ----------------------------------------------------------------------------- statics
def moorpy_statics(deck: Deck, dx: float = 0.0) -> dict:
    """MoorPy's equilibrium with the fairlead moved by dx along x: tensions at both ends."""
    with moorpy.silenced():
        s = moorpy.system(deck.path, depth=deck.depth, rho=deck.option("rho", WATER_DENSITY),
                          g=deck.option("g", GRAVITY))
        for p in s.pointList:
            if p.type == -1:
                p.setPosition(np.array(p.r, float) + np.array([dx, 0.0, 0.0]))
        s.initialize()
        s.solveEquilibrium(tol=1e-7, maxIter=2000)
    fair = next(p for p in s.pointList if p.type == -1)
    anch = next(p for p in s.pointList if p.type == 1)
    top = next(ln for ln in s.lineList if fair.number in ln.attached)
    bottom = next(ln for ln in s.lineList if anch.number in ln.attached)
    T_fair = top.TB if top.attached[1] == fair.number else top.TA
    T_anch = bottom.TA if bottom.attached[0] == anch.number else bottom.TB
    grounded = sum(getattr(ln, "LBot", 0.0) for ln in s.lineList)
    return {"fairlead": float(T_fair), "anchor": float(T_anch), "grounded": float(grounded)}


def fmu_statics(fmu, deck: Deck, dx: float = 0.0, **extra) -> dict:
    """The FMU's initMode-0 equilibrium with the fairlead at the deck's point moved by dx along x."""
    x = deck.fairlead + np.array([dx, 0.0, 0.0])
    with CableFMU(fmu, parameters=fmu_parameters(deck, **extra)) as c:
        c.initialize(inputs={"tow.x": x[0], "tow.y": x[1], "tow.z": x[2]})
        length = sum(ln[1] for ln in deck.lines)
        return {"fairlead": c.get("towTension"), "anchor": c.get("endTension"),
                "grounded": length - c.get("touchdownArcLength")}


def _moordyn_end_tensions(md: moordyn.System, deck: Deck, force) -> tuple:
    """(fairlead, anchor) tension: |force on the coupled point|, |end-segment tension| at the anchor."""
    return float(np.linalg.norm(force)), md.tension_at(deck.anchor)


def moordyn_statics(deck: Deck) -> dict:
    """MoorDyn's static initial condition (moordyn.Init) at the deck's fairlead position."""
    with moordyn.System(deck.path, init=(list(deck.fairlead), [0.0, 0.0, 0.0])) as md:
        f = md.step(list(deck.fairlead), [0.0, 0.0, 0.0], 0.0, deck.option("dtM", 1e-4))
        fair, anchor = _moordyn_end_tensions(md, deck, f)
    return {"fairlead": fair, "anchor": anchor}


# ----------------------------------------------------------------------------- dynamics
@dataclass
class Surge:
    """Fairlead at deck.fairlead + A (1 - cos w t) along `axis` (x: surge): at rest at t = 0."""
    amplitude: float = 2.0
    period: float = 15.0
    axis: tuple = (1.0, 0.0, 0.0)

    def state(self, t):
        w = 2.0 * math.pi / self.period
        e = np.array(self.axis)
        return (self.amplitude * (1.0 - math.cos(w * t)) * e, self.amplitude * w * math.sin(w * t) * e,
                self.amplitude * w * w * math.cos(w * t) * e)


@dataclass
class History:
    code: str
    t: np.ndarray
    fairlead: np.ndarray
    anchor: np.ndarray
    cpu: float
    info: str = ""


def fmu_surge(fmu, deck: Deck, surge: Surge, t_end: float, comm_step: float = 0.1, progress=None,
              parameters=None, **extra) -> History:
    """The FMU through the surge (any motion with state(t), e.g. a heave): position, velocity and
    acceleration (an input derivative) at the start of each communication step (the FMU follows a cubic
    in time from them). parameters: the FMU's parameters (default fmu_parameters(deck, **extra))."""
    times = np.arange(0.0, t_end + 0.5 * comm_step, comm_step)
    fair, anch = np.zeros(len(times)), np.zeros(len(times))
    c = CableFMU(fmu, parameters=parameters if parameters is not None else fmu_parameters(deck, **extra))
    try:
        x0 = deck.fairlead
        c.initialize(inputs={"tow.x": x0[0], "tow.y": x0[1], "tow.z": x0[2]})
        fair[0], anch[0] = c.get("towTension"), c.get("endTension")
        cpu0 = time.process_time()
        names = ["tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz"]
        for k in range(len(times) - 1):
            t = times[k]
            dx, v, a = surge.state(t)  # the state at the start of the step, which the FMU extrapolates
            c.set(dict(zip(names, [*(x0 + dx), *v])))
            c.set_input_derivatives(["tow.vx", "tow.vy", "tow.vz"], 1, a)
            c.do_step(comm_step, t=t)
            fair[k + 1], anch[k + 1] = c.get("towTension"), c.get("endTension")
            if progress:
                progress(times[k + 1])
        cpu = time.process_time() - cpu0
        steps = c.get("solver.nSteps")
    finally:
        c.free()
    return History("FMU", times, fair, anch, cpu, f"{steps:.0f} integrator steps")


def moordyn_surge(deck: Deck, surge: Surge, t_end: float, comm_step: float = 0.1, progress=None) -> History:
    """MoorDyn fed the same deck: moordyn.Init at rest, then moordyn.Step every dtM of the deck with the
    exact fairlead position and velocity at the start of the step (MoorDyn moves the coupled point
    linearly from them within a call)."""
    dt = deck.option("dtM", 1e-4)
    sub = int(math.ceil(comm_step / dt - 1e-9))
    dt = comm_step / sub
    times = np.arange(0.0, t_end + 0.5 * comm_step, comm_step)
    fair, anch = np.zeros(len(times)), np.zeros(len(times))
    x0 = deck.fairlead
    start = (list(x0), [0.0, 0.0, 0.0])

    def coupled(t):
        dx, v, _ = surge.state(t)  # MoorDyn moves the point from x by xd (t' - t) over the step
        return list(x0 + dx), list(v)

    def record(k, f):
        fair[k], anch[k] = _moordyn_end_tensions(md, deck, f)

    with moordyn.System(deck.path, init=start) as md:
        cpu = moordyn.drive(md, start, len(times) - 1, comm_step, sub, coupled, record, progress)
    return History("MoorDyn", times, fair, anch, cpu, f"dt {dt:.2g} s, {sub * (len(times) - 1)} steps")


def rms_difference(a: History, b: History, t_from: float) -> dict:
    """RMS of the tension differences over t >= t_from, absolute and relative to b's mean and range."""
    sel = a.t >= t_from - 1e-9
    out = {}
    for end in ("fairlead", "anchor"):
        x, y = getattr(a, end)[sel], getattr(b, end)[sel]
        rms = float(np.sqrt(np.mean((x - y) ** 2)))
        mean, spread = float(np.mean(y)), float(np.ptp(y))  # either 0: a line the motion leaves alone, unloaded
        out[end] = {"rms": rms, "rel_mean": rms / mean if mean else math.nan, "rel_range": rms / spread if spread else math.nan,
                    "max": float(np.max(np.abs(x - y))), "mean_a": float(np.mean(x)), "mean_b": float(np.mean(y)),
                    "min_b": float(np.min(y)), "max_b": float(np.max(y))}
    return out


# ----------------------------------------------------------------------------- the report
DEFAULT_DECKS = (DECKS / "chain.dat", DECKS / "chain_wire_chain.dat", DECKS / "clump_weight.dat")


@dataclass
class Settings:
    deck: Path = DECKS / "chain.dat"
    offsets: tuple = (-2.0, 0.0, 2.0)
    surge: Surge = field(default_factory=Surge)
    t_end: float = 120.0
    t_from: float = 30.0
    comm_step: float = 0.1


def compute(fmu, settings: Settings, progress_factory=None) -> dict:
    """Every number of the report (no formatting)."""
    deck = read_deck(settings.deck)
    statics = []
    for dx in settings.offsets:
        ref = moorpy_statics(deck, dx)
        ours = fmu_statics(fmu, deck, dx)
        finer = fmu_statics(fmu, deck, dx, lineFileElements=2 * default_elements(deck))
        statics.append({"dx": dx, "moorpy": ref, "fmu": ours, "fmu_fine": finer})
    md_static = moordyn_statics(deck)
    md_ref = moorpy_statics(deck, 0.0)

    def bar(label):
        return progress_factory(settings.t_end, label) if progress_factory else None

    histories = {}
    with tempfile.TemporaryDirectory() as tmp:
        fine = refined_deck(deck, 2, Path(tmp))
        for key, d in (("deck", deck), ("fine", fine)):
            b = bar(f"FMU surge ({key})")
            histories[("FMU", key)] = fmu_surge(fmu, d, settings.surge, settings.t_end, settings.comm_step,
                                                progress=b.update if b else None)
            if b:
                b.close()
            b = bar(f"MoorDyn surge ({key})")
            histories[("MoorDyn", key)] = moordyn_surge(d, settings.surge, settings.t_end, settings.comm_step,
                                                        progress=b.update if b else None)
            if b:
                b.close()
    h = histories
    comparisons = [
        ("FMU vs MoorDyn, the deck", h[("FMU", "deck")], h[("MoorDyn", "deck")]),
        ("FMU vs MoorDyn, both meshes 2x finer", h[("FMU", "fine")], h[("MoorDyn", "fine")]),
        ("MoorDyn 2x finer vs MoorDyn", h[("MoorDyn", "fine")], h[("MoorDyn", "deck")]),
        ("FMU 2x finer vs FMU", h[("FMU", "fine")], h[("FMU", "deck")]),
    ]
    return {"deck": deck, "settings": settings, "statics": statics, "moordyn_static": md_static,
            "moordyn_static_ref": md_ref, "histories": histories,
            "rms": [(label, rms_difference(a, b, settings.t_from)) for label, a, b in comparisons]}


# ----------------------------------------------------------------------------- Markdown
def _pct(x: float) -> str:
    return f"{100.0 * x:+.3f} %"


def markdown(report: list) -> str:
    """docs/lines_validation.md from the results of compute(), one per deck."""
    out = ["# Lines from MoorDyn decks: validation", "",
           "Generated by `scripts/line_file_report`. Each deck is read by the FMU through `lineFile` "
           "(elements by the rule of [lines.md](lines.md)), by MoorPy and by MoorDyn. Set alongside it in "
           "the FMU, as MoorDyn has them: `enableSeabed`, `seabedStiffness` = kBot × Diam and "
           "`seabedDamping` = cBot × Diam of the line on the anchor (the one on the seabed), "
           "`enableCompression` = false (MoorDyn's tension-only segments).", ""]
    for data in report:
        out += deck_section(data)
    return "\n".join(out)


def deck_section(data: dict) -> list:
    deck, st = data["deck"], data["settings"]
    rel = deck.path.relative_to(REPO_ROOT) if deck.path.is_relative_to(REPO_ROOT) else deck.path
    lines_text = ", ".join(f"{name} {length:g} m ({n} segments)" for name, length, n in deck.lines)
    out = [f"## `{rel}`", "",
           f"{lines_text}, from the vessel point at ({deck.fairlead[0]:g}, {deck.fairlead[1]:g}, "
           f"{deck.fairlead[2]:g}) m to the anchor at ({deck.anchor[0]:g}, {deck.anchor[1]:g}, "
           f"{deck.anchor[2]:g}) m, water depth {deck.depth:g} m; {default_elements(deck)} elements in the FMU.", "",
           "### Statics against MoorPy", "",
           "MoorPy 1.3.0 (`moorpy.System(file=...)`, `solveEquilibrium`): an elastic catenary per line on a "
           "rigid frictionless seabed, the free points solved for; the FMU's static equilibrium "
           "(`initMode` 0). Fairlead moved by dx along x.", "",
           "| dx [m] | MoorPy fairlead [N] | FMU fairlead [N] | diff. | MoorPy anchor [N] | FMU anchor [N] | diff. "
           "| FMU, 2x elements: fairlead, anchor | MoorPy grounded [m] | FMU grounded [m] |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    worst = 0.0
    for r in data["statics"]:
        mp, us, fine = r["moorpy"], r["fmu"], r["fmu_fine"]
        df, da = us["fairlead"] / mp["fairlead"] - 1, us["anchor"] / mp["anchor"] - 1
        worst = max(worst, abs(df), abs(da))
        out.append(f"| {r['dx']:+g} | {mp['fairlead']:.0f} | {us['fairlead']:.0f} | {_pct(df)} | {mp['anchor']:.0f} "
                   f"| {us['anchor']:.0f} | {_pct(da)} | {_pct(fine['fairlead'] / mp['fairlead'] - 1)}, "
                   f"{_pct(fine['anchor'] / mp['anchor'] - 1)} | {mp['grounded']:.1f} | {us['grounded']:.1f} |")
    ms, mr = data["moordyn_static"], data["moordyn_static_ref"]
    out += ["", f"Largest difference from MoorPy: **{100 * worst:.3f} %** (bound 0.5 %). For scale, MoorDyn's own "
            f"static solution of the same deck at dx = 0 (`moordyn.Init`) differs from MoorPy by "
            f"{_pct(ms['fairlead'] / mr['fairlead'] - 1)} at the fairlead and "
            f"{_pct(ms['anchor'] / mr['anchor'] - 1)} at the anchor.", ""]
    h = data["histories"]
    a, b = h[("FMU", "deck")], h[("MoorDyn", "deck")]
    sv = st.surge
    out += ["### Dynamics against MoorDyn", "",
            f"MoorDyn v2 (PyPI `moordyn`) fed the same file: its static initial condition, then "
            f"`moordyn.Step` every {b.info.split(',')[0].removeprefix('dt ')} with the exact fairlead position "
            f"and velocity. The fairlead surges x = {sv.amplitude:g} (1 - cos 2π t / {sv.period:g} s) m from rest "
            f"for {st.t_end:g} s; the FMU gets position, velocity and acceleration (input derivatives) every "
            f"{st.comm_step:g} s. Tensions: MoorDyn's force on the coupled point and the tension of the "
            "anchor's end segment; the FMU's `towTension` and `endTension`.", "",
            "| end | MoorDyn mean [N] | FMU mean [N] | MoorDyn range [N] |", "|---|---|---|---|"]
    main_rms = data["rms"][0][1]
    for end in ("fairlead", "anchor"):
        r = main_rms[end]
        out.append(f"| {end} | {r['mean_b']:.0f} | {r['mean_a']:.0f} | {r['min_b']:.0f} .. {r['max_b']:.0f} |")
    out += ["", f"RMS of the tension differences over t ≥ {st.t_from:g} s. The 2x finer meshes are the deck with "
            "twice the segments in every line (BA kept in N s, MoorDyn's dtM halved), which the FMU meshes with "
            "twice the elements: how far each code still is from its converged answer.", "",
            "| comparison | fairlead RMS [N] | / mean | / range | anchor RMS [N] | / mean | / range |",
            "|---|---|---|---|---|---|---|"]
    for label, r in data["rms"]:
        f, an = r["fairlead"], r["anchor"]
        out.append(f"| {label} | {f['rms']:.0f} | {100 * f['rel_mean']:.2f} % | {100 * f['rel_range']:.2f} % | "
                   f"{an['rms']:.0f} | {100 * an['rel_mean']:.2f} % | {100 * an['rel_range']:.2f} % |")
    cpu = ", ".join(f"{code} {'' if key == 'deck' else '2x '}{r.cpu:.2f} s ({r.info})" for (code, key), r in h.items())
    out += ["", f"CPU time for {st.t_end:g} s: {cpu}.", "",
            f"![tension histories]({plot_name(deck)})", ""]
    return out


def plot_name(deck: Deck) -> str:
    return f"lines_validation_{deck.path.stem}.png"


def plot(data: dict, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    a, b = data["histories"][("FMU", "deck")], data["histories"][("MoorDyn", "deck")]
    fig, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    for ax, end in zip(axes, ("fairlead", "anchor")):
        ax.plot(b.t, getattr(b, end) / 1e6, "k-", lw=1.5, label="MoorDyn")
        ax.plot(a.t, getattr(a, end) / 1e6, "r--", lw=1.2, label="FMU (lineFile)")
        ax.set_ylabel(f"{end} tension [MN]")
        ax.grid(alpha=0.3)
    axes[0].legend()
    axes[1].set_xlabel("t [s]")
    axes[0].set_title(f"{data['deck'].path.name}: fairlead surge, same deck in both codes")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main(argv=None) -> int:
    import argparse

    from ucable.paths import require_fmu
    from ucable.progress import ProgressBar

    ap = argparse.ArgumentParser(prog="scripts/line_file_report", description=__doc__.split("\n\n")[0])
    ap.add_argument("--deck", type=Path, action="append", dest="decks",
                    help="a MoorDyn v2 deck (repeat for several; default: " +
                         ", ".join(str(d.relative_to(REPO_ROOT)) for d in DEFAULT_DECKS) + ")")
    ap.add_argument("--t-end", type=float, default=Settings.t_end, help="surge duration [s] (default %(default)s)")
    ap.add_argument("--from", dest="t_from", type=float, default=Settings.t_from,
                    help="start of the RMS window [s] (default %(default)s)")
    ap.add_argument("--amplitude", type=float, default=Surge.amplitude, help="surge amplitude A [m]")
    ap.add_argument("--period", type=float, default=Surge.period, help="surge period T [s]")
    ap.add_argument("--out", type=Path, default=REPO_ROOT / "docs", help="output directory (default docs/)")
    args = ap.parse_args(argv)
    fmu = require_fmu()
    report = []
    for deck in args.decks or DEFAULT_DECKS:
        settings = Settings(deck=deck.resolve(), surge=Surge(args.amplitude, args.period), t_end=args.t_end,
                            t_from=args.t_from)
        report.append(compute(fmu, settings, progress_factory=lambda total, label: ProgressBar(total, label)))
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "lines_validation.md").write_text(markdown(report))
    for data in report:
        plot(data, args.out / plot_name(data["deck"]))
    print(f"wrote {args.out / 'lines_validation.md'} and its figures")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
