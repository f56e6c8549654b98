"""ucable: run scenes of the UnderwaterCable FMU, sweep them on Dask, run the shipped systems.

    ucable run SCENE [--set NAME=VALUE ...] [--out DIR] [--animate]
    ucable sweep SCENE --vary NAME=V1,V2,... [--vary ...] [--set NAME=VALUE ...] [--workers N]
                 [--scheduler ADDRESS] [--out DIR]
    ucable scenes                  the shipped scenes
    ucable scenes show NAME        print a shipped scene (to copy and edit: ucable scenes show turn90 > my.toml)
    ucable scenes format           print the scene format's reference (every key, unit, default)
    ucable system NAME [--master fmpy|libcosim|newton] [--out DIR]    run a shipped system of FMUs
    ucable fmu                     the path of the FMU
    ucable --version

SCENE is a scene file (TOML; the format: ucable scenes format) or the name of a shipped scene. NAME is
any FMU parameter by its name, the scene's duration or step, or the tow's speed_kn [kn] or heading
[deg]. run writes DIR/result.csv (the outputs and, by default, every station's position, tension and
curvature), DIR/summary.csv (the results table it prints: max and min with their times) and
DIR/result.png, with --animate also DIR/result.gif; sweep writes DIR/results.csv (one row per
combination: the varied values, towTensionMax, towTensionMin, towTensionFinal, endDepthFinal,
cpuSeconds, status, error) and DIR/summary.png. Every column is named with its unit, angles in
degrees (`towTension [N]`, `topDeclination [deg]`); ucable.read_results reads them back.

Exit codes: 0 done; 1 a run failed (the FMU's message is printed), or some runs of a sweep failed;
2 a mistake in the scene or the command line (one line naming the file and the key). --debug
shows the traceback of any error.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .progress import ProgressBar

EXIT_FAILED = 1
EXIT_USAGE = 2


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


def cmd_run(a) -> int:
    from .scene import SceneError, load_scene, run_scene
    from .summary import format_table

    scene = load_scene(a.scene).with_overrides(parse_sets(a.set))
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
    from .scene import load_scene
    from .sweep import check_vary, combinations, parse_vary, plot_summary, run_sweep, write_results

    scene = load_scene(a.scene)
    vary = parse_vary(a.vary)
    fixed = parse_sets(a.set)
    check_vary(scene.with_overrides(fixed), vary)  # every value checked before anything runs
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
    plot_summary(rows, names, out / "summary.png", f"{scene.title}: sweep")
    failed = [r for r in rows if r["status"] != "ok"]
    print(f"wrote {out}/results.csv, summary.png")
    if failed:
        for r in failed:
            print(f"failed: {', '.join(f'{k}={r[k]}' for k in names)}: {r['error']}", file=sys.stderr)
        print(f"ucable: {len(failed)} of {n} runs failed", file=sys.stderr)
        return EXIT_FAILED
    return 0


def cmd_scenes(a) -> int:
    from .paths import find_scene, scene_format_doc, scenes_dir
    from .scene import load_scene

    if a.action == "format":
        sys.stdout.write(scene_format_doc().read_text())
        return 0
    if a.action == "show":
        if not a.name:
            raise SystemExit("ucable scenes show: give the NAME of a shipped scene (ucable scenes lists them)")
        load_scene(a.name)  # a shipped scene by name (a mistake: the names there are)
        sys.stdout.write(find_scene(a.name).read_text())
        return 0
    for path in sorted(scenes_dir().glob("*.toml")):
        print(f"{path.stem:28s} {load_scene(path).title}")
    return 0


def cmd_system(a) -> int:
    from . import system as S
    from .results import labelled, system_units, write_table
    from .summary import format_table, summary_columns, system_summary
    from .system_cli import plot

    if a.name is None:
        for name in S.system_names():
            print(f"{name:28s} {S.system_description(name)}")
        return 0
    if a.name not in S.system_names():
        from .scene_schema import SceneFileError, suggestion

        raise SceneFileError(f"no system {a.name!r}{suggestion(a.name, S.system_names()) or ''} "
                             f"(shipped: {', '.join(S.system_names())})")
    out = a.out or Path("out") / "system" / a.name
    out.mkdir(parents=True, exist_ok=True)
    bar = ProgressBar(S.named_duration(a.name, a.manoeuvre, a.duration), label=a.name)
    r = S.run_named(a.name, a.master, a.step, a.duration, a.manoeuvre, progress=bar)
    bar.close(f"{r.time[-1]:g} s simulated in {len(r.time) - 1} steps, {r.cpu:.2f} s CPU")
    write_table(out / "result.csv", labelled(r.columns(), system_units(S.load_named_system(a.name))))
    table = system_summary(r)
    write_table(out / "summary.csv", summary_columns(table))
    plot(out / "result.png", r, f"{a.name}: {a.master}, step {r.step:g} s")
    print(format_table(table))
    print(f"wrote {out}/: result.csv, summary.csv, result.png")
    if r.stats:
        from .newton import summary
        print(summary(r))
    return 0


def build_parser() -> argparse.ArgumentParser:
    from . import __version__

    ap = argparse.ArgumentParser(prog="ucable", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--version", action="version", version=f"ucable {__version__}")
    ap.add_argument("--debug", action="store_true", help="show the traceback of an error")
    sub = ap.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run", help="run one scene")
    r.add_argument("scene")
    r.add_argument("--set", action="append", metavar="NAME=VALUE", help="a parameter or setting (repeatable)")
    r.add_argument("--out", type=Path, default=None, help="output directory (default out/SCENE)")
    r.add_argument("--animate", action="store_true",
                   help="also write result.gif: the line's side and plan views over the run, coloured by tension")
    s = sub.add_parser("sweep", help="run the cartesian product of parameter values on Dask")
    s.add_argument("scene")
    s.add_argument("--vary", action="append", required=True, metavar="NAME=V1,V2,...",
                   help="a parameter, duration, step, or the tow's speed_kn [kn] or heading [deg] (repeatable)")
    s.add_argument("--set", action="append", metavar="NAME=VALUE", help="held for every combination")
    s.add_argument("--workers", type=int, default=2, help="local worker processes (default 2)")
    s.add_argument("--scheduler", default=None, help="address of a running Dask scheduler (default: a local cluster)")
    s.add_argument("--out", type=Path, default=None, help="output directory (default out/SCENE_sweep)")
    sc = sub.add_parser("scenes", help="list the shipped scenes; print one (scenes show NAME) or the format (scenes format)")
    sc.add_argument("action", nargs="?", choices=("list", "show", "format"), default="list")
    sc.add_argument("name", nargs="?")
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
    sub.add_parser("fmu", help="print the path of the FMU")
    return ap


def dispatch(a) -> int:
    if a.command == "run":
        return cmd_run(a)
    if a.command == "sweep":
        return cmd_sweep(a)
    if a.command == "scenes":
        return cmd_scenes(a)
    if a.command == "system":
        return cmd_system(a)
    from .paths import require_fmu

    print(require_fmu())
    return 0


def main(argv=None) -> int:
    a = build_parser().parse_args(argv)
    from .fmu import FMICallException
    from .paths import MissingFMUError
    from .scene import SceneError
    from .scene_schema import SceneFileError

    try:
        return dispatch(a)
    except SceneFileError as exc:
        if a.debug:
            raise
        print(f"ucable: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except (SceneError, MissingFMUError, FMICallException, FileNotFoundError, ValueError, RuntimeError) as exc:
        if a.debug:
            raise
        print(f"ucable: {exc}", file=sys.stderr)
        return EXIT_FAILED
    except KeyboardInterrupt:
        print("ucable: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    raise SystemExit(main())
