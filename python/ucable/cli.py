"""ucable: run scenes of the UnderwaterCable FMU, sweep them on Dask, run the shipped systems.

    ucable run SCENE [--set NAME=VALUE ...] [--out DIR] [--animate] [--strict]
    ucable sweep SCENE --vary NAME=V1,V2,... [--vary ...] [--set NAME=VALUE ...] [--workers N]
                 [--scheduler ADDRESS] [--out DIR] [--strict]
    ucable sweep SCENE --seeds N [--seed0 S] [--storm SECONDS] [--fit mle|moments] [--level P] [...]
    ucable check SOURCE [--case intact|damaged|transient] [--analysis dynamic|quasi-static] [--class 1,2]
                 [--standard api,dnv] [--skip SECONDS] [--set NAME=VALUE ...] [--out DIR]
    ucable scenes                  the shipped scenes
    ucable scenes show NAME        print a shipped scene (to copy and edit: ucable scenes show turn90 > my.toml);
                                   on stderr, the files it needs beside it (its lineFile deck)
    ucable scenes copy NAME DIR    copy a shipped scene and the decks it names into DIR
    ucable scenes format           print the scene format's reference (every key, unit, default)
    ucable system NAME [--master fmpy|libcosim|newton] [--step H] [--out DIR] [--strict]    run a shipped system
    ucable fmu                     the path of the FMU (on stderr: the platforms it and its FMI 3.0 variant
                                   carry binaries for, and how to add win64)
    ucable --version

SCENE is a scene file (TOML; the format: ucable scenes format) or the name of a shipped scene. NAME is
any FMU parameter by its name, the scene's duration or step, or the tow's speed_kn [kn] or heading
[deg]. run writes DIR/result.csv (the outputs and, by default, every station's position, tension and
curvature), DIR/summary.csv (the results table it prints: max and min with their times) and
DIR/result.png, with --animate also DIR/result.gif; sweep writes DIR/results.csv (one row per
combination: the varied values, towTensionMax, towTensionMin, towTensionFinal, endDepthFinal,
cpuSeconds, status, error; per line its MBL and the mean and maximum of its utilisations) and
DIR/summary.png. sweep --seeds N runs N realisations of the scene's irregular sea (waves.seed S, S + 1,
...), fits each line's per-realisation maxima of the fairlead tension with a Gumbel distribution and
writes DIR/extremes.csv (the fit, the most probable maximum over --storm seconds, default 10800, and its
confidence interval) and DIR/gumbel.png (Gumbel probability paper). Every column is named with its unit, angles in
degrees (`towTension [N]`, `topDeclination [deg]`); ucable.read_results reads them back.

check: each line's tension against its minimum breaking load (MBL) by API RP 2SK and DNV-OS-E301
(docs/design_checks.md). SOURCE is a run's result.csv, a sweep's results.csv, a directory holding one of
them, or a scene (run first, with --set). The case is --case, else the run's line[k].broken outputs (a line
broken from the start: damaged; breaking during the run: transient; none: intact). It prints the table and
the governing line, and writes DIR/check.csv (default: beside the table read, or out/SCENE).

run, sweep and system warn when the communication step is longer than a tenth of the shortest period
or ramp in the scene (the tow's oscillations and speed or heading ramps, the waves' period, the
winch's ramps, the ramps of input tables; a system: beyond the steps its accuracy is documented
for); with --strict that warning is a refusal (exit code 2). run prints the winch's events: a length
limit (winch.minLength, winch.maxLength) or winch.maxRate reached, with the time and the value.

Exit codes: 0 done (check: every check passes); 3 check: a check fails; 1 a run failed (the FMU's message is printed), some runs of a sweep failed, or a
Python module a feature needs is missing (the command that installs it is printed); 2 a mistake in the
scene or the command line (one line naming the file and the key), including a scene the FMU refuses
at the start, or with --strict a step too long for the scene. Every error is one line; --debug shows its traceback.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .progress import ProgressBar

EXIT_FAILED = 1
EXIT_USAGE = 2
EXIT_CHECK_FAILED = 3


def parse_sets(items) -> dict:
    from .scene import parse_value
    from .scene_schema import SceneFileError

    out = {}
    for item in items or []:
        if "=" not in item:
            raise SceneFileError(f"--set {item!r}: expected NAME=VALUE")
        name, value = item.split("=", 1)
        out[name.strip()] = parse_value(value)
    return out


def check_steps(scenes, strict: bool) -> None:
    """Warns (stderr) when a scene's step is too long for it (step_check); with strict, refuses."""
    from .scene_schema import SceneFileError
    from .step_check import step_warnings

    said = []
    for scene in scenes:
        said += [w for w in step_warnings(scene) if w not in said]
    if said and strict:
        raise SceneFileError(f"{said[0]} (refused: --strict)")
    for w in said:
        print(f"ucable: warning: {w}", file=sys.stderr)


def cmd_run(a) -> int:
    from .scene import SceneError, load_scene, run_scene
    from .summary import format_table

    scene = load_scene(a.scene).with_overrides(parse_sets(a.set))
    check_steps([scene], a.strict)
    out = a.out or Path("out") / scene.name
    out.mkdir(parents=True, exist_ok=True)
    bar = ProgressBar(scene.duration, label=scene.name)
    try:
        result = run_scene(scene, progress=lambda t: bar.update(t, f"t = {t:7.1f} s"))
    except SceneError as exc:
        bar.close()
        if exc.partial is not None:  # keep what was computed, and say where it stopped
            written = write_run(exc.partial, out)
            n = len(exc.partial.time)
            print(f"ucable: the run stopped at t = {exc.stopped:g} s of {scene.duration:g} s; wrote the "
                  f"{n} row{'s' if n > 1 else ''} up to t = {exc.partial.time[-1]:g} s to {out}/: {', '.join(written)}",
                  file=sys.stderr)
        raise
    bar.close(f"{scene.duration:g} s simulated in {result.cpu:.2f} s CPU")
    written = write_run(result, out, animate=a.animate)
    for event in result.events:
        print(event)
    print(format_table(result.table()))
    print(f"wrote {out}/: {', '.join(written)}")
    return 0


def write_run(result, out: Path, animate: bool = False) -> list[str]:
    """result.csv, summary.csv, result.png (and result.gif) of a run (or of the part a failed run reached)."""
    result.write_csv(out / "result.csv")
    result.write_summary(out / "summary.csv")
    result.plot(out / "result.png")
    written = ["result.csv", "summary.csv", "result.png"]
    if animate:
        result.animate(out / "result.gif", progress=True)
        written.append("result.gif")
    return written


def cmd_sweep(a) -> int:
    from .optional import require
    from .scene import load_scene
    from .scene_schema import SceneFileError
    from .sweep import check_vary, combinations, parse_vary, plot_summary, run_sweep, write_results

    require("dask.distributed", "ucable sweep")
    scene = load_scene(a.scene)
    vary = parse_vary(a.vary or [])
    fixed = parse_sets(a.set)
    if a.seeds is not None:
        from .sweep import seed_values

        if not (a.storm > 0.0 and 0.0 < a.level < 1.0):
            raise SceneFileError(f"--storm {a.storm:g} s must be positive and --level {a.level:g} between 0 and 1")
        if vary:
            raise SceneFileError("--seeds runs realisations of one sea state: give the others with --set, not --vary")
        if int(scene.with_overrides(fixed).parameters.get("waves.mode", 0)) != 2:
            raise SceneFileError(f"--seeds: the scene {scene.name} has no irregular sea (waves.mode 2): its "
                                 f"realisations would all be the same")
        vary = {"waves.seed": seed_values(a.seeds, a.seed0)}
    elif not vary:
        raise SceneFileError("sweep: give what varies (--vary NAME=V1,V2,...) or the realisations (--seeds N) "
                             "(ucable sweep --help)")
    check_vary(scene.with_overrides(fixed), vary)  # every value checked before anything runs
    check_steps([scene.with_overrides({**fixed, **c}, source="--vary") for c in combinations(vary)], a.strict)
    n = len(combinations(vary))
    out = a.out or Path("out") / f"{scene.name}_sweep"
    out.mkdir(parents=True, exist_ok=True)
    bar = ProgressBar(n, label=f"sweep {scene.name}")
    where = a.scheduler or f"a local cluster of {a.workers} workers"
    print(f"{n} combinations on {where}", file=sys.stderr)
    rows, _ = run_sweep(scene, vary, fixed, workers=a.workers, scheduler=a.scheduler,
                           progress=lambda k: bar.update(k, f"{k}/{n}"))
    cpu = sum(r["cpuSeconds"] for r in rows)
    bar.close(f"{n} runs, {cpu:.1f} s CPU in the runs")
    names = list(vary)
    write_results(rows, names, out / "results.csv")
    failed = [r for r in rows if r["status"] != "ok"]
    written = "results.csv"
    if len(failed) == len(rows):
        print("ucable: warning: every run failed: no summary.png", file=sys.stderr)
    else:
        try:  # the table is written; a plot that cannot be drawn does not lose it
            plot_summary(rows, names, out / "summary.png", f"{scene.title}: sweep")
            written += ", summary.png"
        except Exception as exc:
            print(f"ucable: warning: summary.png not written: {type(exc).__name__}: {one_line(exc)}", file=sys.stderr)
    print(f"wrote {out}/{written}")
    if failed:
        for r in failed:
            print(f"failed: {', '.join(f'{k}={r[k]}' for k in names)}: {r['error']}", file=sys.stderr)
        print(f"ucable: {len(failed)} of {n} runs failed", file=sys.stderr)
    if a.seeds is not None and len(failed) < len(rows):
        sweep_extremes(a, scene.with_overrides(fixed), rows, out, fixed)
    return EXIT_FAILED if failed else 0


def sweep_extremes(a, scene, rows: list[dict], out: Path, fixed: dict) -> None:
    """The Gumbel fit of each line's per-realisation maxima: printed, extremes.csv and gumbel.png."""
    from .extremes import fit_maxima, format_fit, plot_gumbel
    from .scene_schema import SceneFileError
    from .sweep import realisation_maxima, stationary_duration, write_extremes

    duration = stationary_duration(scene)
    if not duration > 0.0:
        raise SceneFileError(f"--seeds: the scene's duration {scene.duration:g} s is not longer than its waves' "
                             f"ramp-in (waves.rampTime): no stationary sea to take maxima of")
    maxima = realisation_maxima(rows)
    fits = {name: fit_maxima(x, duration, a.storm, a.fit, a.level) for name, (x, _) in maxima.items()}
    mbls = {name: mbl for name, (_, mbl) in maxima.items()}
    print(f"maxima over {duration:g} s of stationary sea (duration less waves.rampTime) per realisation; MPM over "
          f"{a.storm:g} s = mu + beta ln({a.storm:g} / {duration:g})")
    for name, f in fits.items():
        print(format_fit(name, f, mbl=mbls[name]))
    write_extremes(fits, mbls, out / "extremes.csv")
    settings = f" ({', '.join(f'{k} = {v:g}' if isinstance(v, float) else f'{k} = {v}' for k, v in fixed.items())})"
    plot_gumbel(fits, out / "gumbel.png", f"{scene.title}{settings if fixed else ''}: maxima of {len(rows)} realisations")
    print(f"wrote {out}/extremes.csv, gumbel.png")


def check_source(a):
    """(the columns of a run or the rows of a sweep, "run" | "sweep", the default output directory) of
    `ucable check SOURCE`: a table written by run or sweep, a directory holding one, or a scene run here."""
    from .results import read_results
    from .scene import load_scene, run_scene
    from .scene_schema import SceneFileError

    source = Path(a.source)
    if source.is_dir():
        found = [source / n for n in ("result.csv", "results.csv") if (source / n).is_file()]
        if not found:
            raise SceneFileError(f"check {source}: no result.csv (ucable run) or results.csv (ucable sweep) in it")
        source = found[0]
    if source.suffix.lower() == ".csv":
        if not source.is_file():
            raise SceneFileError(f"check {source}: no such file")
        table = read_results(source)
        if "time" in table:
            return table, "run", source.parent
        if "status" in table:
            return table.records(), "sweep", source.parent
        raise SceneFileError(f"check {source}: neither a run's result.csv (a time column) nor a sweep's "
                             f"results.csv (a status column)")
    scene = load_scene(a.source).with_overrides(parse_sets(a.set))
    check_steps([scene], a.strict)
    bar = ProgressBar(scene.duration, label=scene.name)
    result = run_scene(scene, progress=lambda t: bar.update(t, f"t = {t:7.1f} s"))
    bar.close(f"{scene.duration:g} s simulated in {result.cpu:.2f} s CPU")
    out = a.out or Path("out") / scene.name
    out.mkdir(parents=True, exist_ok=True)
    print(f"wrote {out}/: {', '.join(write_run(result, out))}")
    return result.columns, "run", out


def check_cases(rows: list[dict], analysis: str, classes, standards):
    """The verdict of a sweep over the design cases: each run checked by its `case` column's case (intact,
    damaged, transient; a run's statistics are its case's part, ucable.sweep.run_case), the governing check
    over all of them."""
    from .design_check import CASES, CheckError, check_lines, sweep_tensions, verdict

    checked, seen = [], []
    for case in CASES:
        runs = [r for r in rows if r.get("case") == case]
        if runs:
            seen.append(case)
            checked += [replace_source(row, case) for row in check_lines(sweep_tensions(runs), case, analysis,
                                                                          classes, standards)]
    unknown = sorted({str(r.get("case")) for r in rows} - set(CASES))
    if unknown:
        raise CheckError(f"case column: {', '.join(unknown)} is not one of {', '.join(CASES)}")
    return verdict(checked, ", ".join(seen), "the sweep's case column (--vary case=...)")


def replace_source(row, case: str):
    """A check row whose run names its case."""
    from dataclasses import replace

    return replace(row, source=f"{case}: {row.source}" if row.source else case)


def cmd_check(a) -> int:
    import numpy as np

    from .design_check import CheckError, case_of, check_lines, check_run, sweep_tensions, verdict
    from .design_report import format_check, write_check_csv
    from .scene_schema import SceneFileError

    if a.set and Path(a.source).suffix.lower() == ".csv":
        raise SceneFileError("check: --set applies to a scene, not to a table already computed")
    try:
        classes = tuple(int(c) for c in a.consequence.split(","))
        standards = tuple(s.strip().lower() for s in a.standard.split(","))
        if not classes or any(c not in (1, 2) for c in classes):
            raise ValueError
        if not standards or any(s not in ("api", "dnv") for s in standards):
            raise SceneFileError(f"--standard {a.standard!r}: api, dnv or api,dnv")
    except ValueError:
        raise SceneFileError(f"--class {a.consequence!r}: DNV-OS-E301's consequence classes, 1, 2 or 1,2") from None
    data, kind, where = check_source(a)
    try:
        if kind == "run":
            if a.skip > 0.0:  # the start-up left out
                keep = np.asarray(data["time"], dtype=float) >= a.skip
                if not keep.any():
                    raise CheckError(f"--skip {a.skip:g} s leaves no row of the run (it ends at "
                                     f"{float(data['time'][-1]):g} s)")
                data = {name: np.asarray(values)[keep] for name, values in data.items()}
            v = check_run(data, a.case, a.analysis, classes, standards)
        elif a.case is None and any("case" in r for r in data):  # a sweep over the design cases (--vary case=...)
            v = check_cases(data, a.analysis, classes, standards)
        else:  # each run of a sweep by its own case (the user's, else its broken lines)
            if a.case is None and any(r.get(k, 0.0) > 0.5 for r in data for k in r if k.endswith(".brokenAny")):
                raise CheckError("a sweep whose runs break lines: give the case (--case damaged or transient)")
            case, why = case_of({}, a.case)
            v = verdict(check_lines(sweep_tensions(data), case, a.analysis, classes, standards), case, why)
    except CheckError as exc:
        raise SceneFileError(f"check {a.source}: {exc}") from None
    out = a.out or where
    out.mkdir(parents=True, exist_ok=True)
    write_check_csv(v, out / "check.csv")
    print(format_check(v))
    print(f"wrote {out}/check.csv")
    return 0 if v.passed else EXIT_CHECK_FAILED


def scene_files(scene, directory: Path) -> list[Path]:
    """The files a scene names (its lineFile deck) that lie beside it, and the decks' own companion
    files named in their options (a file name ending in .dat, .txt or .csv beside the deck)."""
    deck = scene.parameters.get("lineFile")
    if not deck or Path(deck).is_absolute() or not (directory / deck).is_file():
        return []
    deck = directory / deck
    files = [deck]
    for token in deck.read_text(errors="replace").split():
        if token.lower().endswith((".dat", ".txt", ".csv")) and (deck.parent / token).is_file():
            files.append(deck.parent / token)
    return list(dict.fromkeys(files))


def copy_scene(path: Path, files: list[Path], target: Path | None) -> int:
    """ucable scenes copy NAME DIR: the scene file and the files it needs into DIR (made if needed);
    files already there are not overwritten."""
    import shutil

    from .scene_schema import SceneFileError

    if target is None:
        raise SceneFileError(f"scenes copy {path.stem}: give the directory to copy it to (DIR)")
    target.mkdir(parents=True, exist_ok=True)
    copied = []
    for source in [path, *files]:
        destination = target / source.relative_to(path.parent)
        if destination.exists():
            raise SceneFileError(f"scenes copy {path.stem}: {destination} exists (not overwritten)")
    for source in [path, *files]:
        destination = target / source.relative_to(path.parent)
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(source, destination)
        copied.append(str(destination))
    print(f"copied {', '.join(copied)}; run it with: ucable run {target / path.name}")
    return 0


def cmd_scenes(a) -> int:
    from .paths import find_scene, scene_format_doc, scenes_dir
    from .scene import load_scene
    from .scene_schema import SceneFileError

    if a.action == "format":
        sys.stdout.write(scene_format_doc().read_text())
        return 0
    if a.action in ("show", "copy"):
        if not a.name:
            raise SceneFileError(f"scenes {a.action}: give the NAME of a shipped scene (ucable scenes lists them)")
        scene = load_scene(a.name)  # a shipped scene by name (a mistake: the names there are)
        path = find_scene(a.name)
        decks = scene_files(scene, path.parent)
        if a.action == "copy":
            return copy_scene(path, decks, a.dir)
        sys.stdout.write(path.read_text())
        if decks:
            print(f"ucable: the scene {path.stem} needs {', '.join(d.name for d in decks)} beside it: "
                  f"ucable scenes copy {path.stem} DIR copies them with it", file=sys.stderr)
        return 0
    for path in sorted(scenes_dir().glob("*.toml")):
        print(f"{path.stem:28s} {load_scene(path).title}")
    return 0


def cmd_system(a) -> int:
    from . import system as S
    from .results import labelled, system_units
    from .tables import write_columns
    from .summary import format_table, summary_columns, system_summary
    from .system_cli import plot

    if a.name is None:
        for name in S.system_names():
            print(f"{name:28s} {S.system_description(name)}")
        return 0
    from .scene_schema import SceneFileError, suggestion

    if a.name not in S.system_names():
        raise SceneFileError(f"no system {a.name!r}{suggestion(a.name, S.system_names()) or ''} "
                             f"(shipped: {', '.join(S.system_names())})")
    if a.master == "libcosim":
        from .optional import require

        require("libcosimpy", "--master libcosim")

    from .step_check import system_step_warnings

    warned = system_step_warnings(a.name, a.master, a.step)
    if warned and a.strict:
        raise SceneFileError(f"{warned[0]} (refused: --strict)")
    for w in warned:
        print(f"ucable: warning: {w}", file=sys.stderr)
    out = a.out or Path("out") / "system" / a.name
    out.mkdir(parents=True, exist_ok=True)
    bar = ProgressBar(S.named_duration(a.name, a.manoeuvre, a.duration), label=a.name)
    r = S.run_named(a.name, a.master, a.step, a.duration, a.manoeuvre, progress=bar)
    bar.close(f"{r.time[-1]:g} s simulated in {len(r.time) - 1} steps, {r.cpu:.2f} s CPU")
    write_columns(out / "result.csv", labelled(r.columns(), system_units(S.load_named_system(a.name))))
    table = system_summary(r)
    write_columns(out / "summary.csv", summary_columns(table))
    plot(out / "result.png", r, f"{a.name}: {a.master}, step {r.step:g} s")
    print(format_table(table))
    print(f"wrote {out}/: result.csv, summary.csv, result.png")
    if r.stats:
        from .newton import summary
        print(summary(r))
    return 0


class Parser(argparse.ArgumentParser):
    """A command-line mistake on one line (argparse prints the usage first), exit code 2."""

    def error(self, message):
        self.exit(EXIT_USAGE, f"{self.prog}: {' '.join(message.split())} ({self.prog} --help)\n")


def build_parser() -> argparse.ArgumentParser:
    from . import __version__

    ap = Parser(prog="ucable", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--version", action="version", version=f"ucable {__version__}")
    ap.add_argument("--debug", action="store_true", help="show the traceback of an error")
    sub = ap.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run", help="run one scene")
    r.add_argument("scene")
    r.add_argument("--set", action="append", metavar="NAME=VALUE", help="a parameter or setting (repeatable)")
    r.add_argument("--out", type=Path, default=None, help="output directory (default out/SCENE)")
    r.add_argument("--animate", action="store_true",
                   help="also write result.gif: the line's side and plan views over the run, coloured by tension")
    r.add_argument("--strict", action="store_true", help="refuse (exit code 2) what is otherwise a warning: a step "
                   "too long for the scene")
    s = sub.add_parser("sweep", help="run the cartesian product of parameter values on Dask")
    s.add_argument("scene")
    s.add_argument("--vary", action="append", metavar="NAME=V1,V2,...",
                   help="a parameter, duration, step, or the tow's speed_kn [kn] or heading [deg] (repeatable)")
    s.add_argument("--set", action="append", metavar="NAME=VALUE", help="held for every combination")
    s.add_argument("--seeds", type=int, default=None, metavar="N",
                   help="N realisations of the scene's irregular sea (waves.seed varied) and the Gumbel fit of "
                        "each line's maxima")
    s.add_argument("--seed0", type=int, default=1, help="--seeds: the first waves.seed (default 1)")
    s.add_argument("--storm", type=float, default=10800.0,
                   help="--seeds: the storm duration of the most probable maximum [s] (default 10800, 3 h)")
    s.add_argument("--fit", choices=("mle", "moments"), default="mle",
                   help="--seeds: maximum likelihood (default) or the method of moments")
    s.add_argument("--level", type=float, default=0.90, help="--seeds: the confidence level (default 0.90)")
    s.add_argument("--workers", type=int, default=2, help="local worker processes (default 2)")
    s.add_argument("--scheduler", default=None, help="address of a running Dask scheduler (default: a local cluster)")
    s.add_argument("--out", type=Path, default=None, help="output directory (default out/SCENE_sweep)")
    s.add_argument("--strict", action="store_true", help="refuse (exit code 2) what is otherwise a warning: a step "
                   "too long for a combination")
    k = sub.add_parser("check", help="each line's tension against its MBL by API RP 2SK and DNV-OS-E301")
    k.add_argument("source", help="a result.csv, a sweep's results.csv, a directory holding one, or a scene to run")
    k.add_argument("--case", choices=("intact", "damaged", "transient"), default=None,
                   help="the run's case (default: from its line[k].broken outputs, intact without them)")
    k.add_argument("--analysis", choices=("dynamic", "quasi-static"), default="dynamic",
                   help="how the tensions were computed: the factors of that analysis (default dynamic, the FMU's)")
    k.add_argument("--class", dest="consequence", default="1,2", metavar="1,2",
                   help="DNV-OS-E301's consequence classes to check (default 1,2)")
    k.add_argument("--standard", default="api,dnv", help="api, dnv or api,dnv (default both)")
    k.add_argument("--skip", type=float, default=0.0, metavar="SECONDS",
                   help="a run: leave out its rows before this time, the start-up (default 0)")
    k.add_argument("--set", action="append", metavar="NAME=VALUE", help="a scene's parameter (repeatable)")
    k.add_argument("--out", type=Path, default=None, help="where check.csv goes (default: beside the table)")
    k.add_argument("--strict", action="store_true", help="a scene: refuse a step too long for it")
    sc = sub.add_parser("scenes", help="list the shipped scenes; print one (scenes show NAME) or the format (scenes format)")
    sc.add_argument("action", nargs="?", choices=("list", "show", "copy", "format"), default="list")
    sc.add_argument("name", nargs="?")
    sc.add_argument("dir", nargs="?", type=Path, help="scenes copy: the directory to copy the scene and its decks to")
    y = sub.add_parser("system", help="run a shipped system of FMUs (vessel, cable, towed body); no NAME: list them")
    y.add_argument("name", nargs="?")
    y.add_argument("--master", choices=("fmpy", "libcosim", "newton"), default="fmpy",
                   help="co-simulation master (default fmpy); newton: the reference iterating master, for "
                        "towed_body_explicit (a body that integrates itself)")
    y.add_argument("--manoeuvre", default="accelerate",
                   help="the vessel's manoeuvre of a towed-body system: accelerate, decelerate, turn90, turn180, "
                        "stop, circle (default accelerate)")
    y.add_argument("--step", type=float, default=None, help="communication step [s] (default: the system file's)")
    y.add_argument("--duration", type=float, default=None, help="simulated time [s]")
    y.add_argument("--out", type=Path, default=None, help="output directory (default out/system/NAME)")
    y.add_argument("--strict", action="store_true", help="refuse (exit code 2) a step beyond the accuracy the "
                   "system documents (otherwise a warning)")
    sub.add_parser("fmu", help="print the path of the FMU")
    return ap


def dispatch(a) -> int:
    if a.command == "run":
        return cmd_run(a)
    if a.command == "sweep":
        return cmd_sweep(a)
    if a.command == "scenes":
        return cmd_scenes(a)
    if a.command == "check":
        return cmd_check(a)
    if a.command == "system":
        return cmd_system(a)
    from .paths import describe_fmus, require_fmu

    print(require_fmu())
    print(f"ucable: {describe_fmus()}", file=sys.stderr)
    return 0


def one_line(text) -> str:
    return " ".join(str(text).split())


def show_warning(message, category, filename, lineno, file=None, line=None) -> None:
    """Warnings on one line: 'ucable: warning: ...'."""
    print(f"ucable: warning: {one_line(message)}", file=sys.stderr)


def main(argv=None) -> int:
    a = build_parser().parse_args(argv)
    import warnings

    from .optional import missing_message
    from .scene_schema import SceneFileError

    previous = warnings.showwarning
    warnings.showwarning = show_warning
    try:
        return dispatch(a)
    except SceneFileError as exc:
        if a.debug:
            raise
        print(f"ucable: {one_line(exc)}", file=sys.stderr)
        return EXIT_USAGE
    except ImportError as exc:  # a module a feature needs (libcosimpy for --master libcosim, ...)
        if a.debug:
            raise
        print(f"ucable: {missing_message(exc)}", file=sys.stderr)
        return EXIT_FAILED
    except KeyboardInterrupt:
        print("ucable: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # the FMU's failure, a file that cannot be written, ...: one line
        if a.debug:
            raise
        known = type(exc).__name__ in ("SceneError", "MissingFMUError", "FMICallException", "Diverged")
        what = "" if known or isinstance(exc, (OSError, ValueError, RuntimeError)) else f"{type(exc).__name__}: "
        print(f"ucable: {what}{one_line(exc)} (--debug shows the traceback)" if what else f"ucable: {one_line(exc)}",
              file=sys.stderr)
        return EXIT_FAILED
    finally:
        warnings.showwarning = previous


if __name__ == "__main__":
    raise SystemExit(main())
