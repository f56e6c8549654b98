"""ucable: run scenes of the UnderwaterCable FMU, or sweep them on Dask.

    ucable run SCENE [--set NAME=VALUE ...] [--out DIR]
    ucable sweep SCENE --vary NAME=V1,V2,... [--vary ...] [--set NAME=VALUE ...] [--workers N]
                 [--scheduler ADDRESS] [--out DIR]
    ucable scenes          the packaged scenes
    ucable fmu             the path of the FMU

SCENE is a scene file (TOML, docs/package.md) or the name of a packaged scene. NAME is any FMU
parameter by its name, or the scene's duration or step. run writes DIR/result.csv and
DIR/result.png; sweep writes DIR/results.csv (one row per combination: the varied values,
towTensionMax, towTensionMin, towTensionFinal, endDepthFinal, cpuSeconds, status, error) and
DIR/summary.png.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .progress import ProgressBar


def parse_sets(items) -> dict:
    from .scene import parse_value

    out = {}
    for item in items or []:
        if "=" not in item:
            raise SystemExit(f"ucable: --set {item!r}: expected NAME=VALUE")
        name, value = item.split("=", 1)
        out[name.strip()] = parse_value(value)
    return out


def cmd_run(a) -> int:
    from .scene import load_scene, run_scene

    scene = load_scene(a.scene).with_overrides(parse_sets(a.set))
    out = a.out or Path("out") / scene.name
    out.mkdir(parents=True, exist_ok=True)
    bar = ProgressBar(scene.duration, label=scene.name)
    result = run_scene(scene, progress=lambda t: bar.update(t, f"t = {t:7.1f} s"))
    bar.close(f"{scene.duration:g} s simulated in {result.cpu:.2f} s CPU")
    result.write_csv(out / "result.csv")
    result.plot(out / "result.png")
    s = result.summary()
    print(f"tow tension max {s['towTensionMax']:.1f} N, min {s['towTensionMin']:.1f} N, final "
          f"{s['towTensionFinal']:.1f} N; far end {s['endDepthFinal']:.2f} m deep; wrote {out}/result.csv, result.png")
    return 0


def cmd_sweep(a) -> int:
    from .scene import load_scene
    from .sweep import combinations, parse_vary, plot_summary, run_sweep, write_results

    scene = load_scene(a.scene)
    try:
        vary = parse_vary(a.vary)
    except ValueError as e:
        raise SystemExit(f"ucable: {e}")
    n = len(combinations(vary))
    out = a.out or Path("out") / f"{scene.name}_sweep"
    out.mkdir(parents=True, exist_ok=True)
    bar = ProgressBar(n, label=f"sweep {scene.name}")
    where = a.scheduler or f"a local cluster of {a.workers} workers"
    print(f"{n} combinations on {where}", file=sys.stderr)
    rows, wall = run_sweep(scene, vary, parse_sets(a.set), workers=a.workers, scheduler=a.scheduler,
                           progress=lambda k: bar.update(k, f"{k}/{n}"))
    cpu = sum(r["cpuSeconds"] for r in rows)
    bar.close(f"{n} runs in {wall:.1f} s wall, {cpu:.1f} s CPU in the runs")
    names = list(vary)
    write_results(rows, names, out / "results.csv")
    plot_summary(rows, names, out / "summary.png", f"{scene.title}: sweep")
    failed = [r for r in rows if r["status"] != "ok"]
    print(f"wrote {out}/results.csv, summary.png; {len(failed)} of {n} failed")
    return 0


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="ucable", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run", help="run one scene")
    r.add_argument("scene")
    r.add_argument("--set", action="append", metavar="NAME=VALUE", help="a parameter or setting (repeatable)")
    r.add_argument("--out", type=Path, default=None, help="output directory (default out/SCENE)")
    s = sub.add_parser("sweep", help="run the cartesian product of parameter values on Dask")
    s.add_argument("scene")
    s.add_argument("--vary", action="append", required=True, metavar="NAME=V1,V2,...")
    s.add_argument("--set", action="append", metavar="NAME=VALUE", help="held for every combination")
    s.add_argument("--workers", type=int, default=2, help="local worker processes (default 2)")
    s.add_argument("--scheduler", default=None, help="address of a running Dask scheduler (default: a local cluster)")
    s.add_argument("--out", type=Path, default=None, help="output directory (default out/SCENE_sweep)")
    sub.add_parser("scenes", help="list the packaged scenes")
    sub.add_parser("fmu", help="print the path of the FMU")
    a = ap.parse_args(argv)
    if a.command == "run":
        return cmd_run(a)
    if a.command == "sweep":
        return cmd_sweep(a)
    if a.command == "scenes":
        from .paths import scenes_dir
        from .scene import load_scene

        for path in sorted(scenes_dir().glob("*.toml")):
            print(f"{path.stem:28s} {load_scene(path).title}")
        return 0
    from .paths import require_fmu

    print(require_fmu())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
