"""scripts/bench_sweep: the wall-clock speed-up of `ucable sweep` with more local Dask workers.

Runs the same sweep (a scene x the product of --vary values) on LocalClusters of 1 and N workers and
prints the table: combinations, wall seconds, CPU seconds inside the runs, speed-up. Note that a
speed-up is bounded by the cores that are free while it runs.
"""

from __future__ import annotations

import argparse
import os

from ucable.scene import load_scene
from ucable.sweep import combinations, parse_vary, run_sweep


def measure(scene_name: str, vary: list[str], fixed: dict, workers: list[int]) -> list[dict]:
    scene = load_scene(scene_name)
    grid = parse_vary(vary)
    rows = []
    for n in workers:
        results, wall = run_sweep(scene, grid, fixed, workers=n)
        rows.append({"workers": n, "runs": len(combinations(grid)), "wall": wall,
                     "cpu": sum(r["cpuSeconds"] for r in results),
                     "failed": sum(r["status"] != "ok" for r in results)})
    return rows


def table(rows: list[dict]) -> str:
    base = rows[0]["wall"]
    lines = ["| workers | runs | wall [s] | CPU in the runs [s] | speed-up |", "|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['workers']} | {r['runs']} | {r['wall']:.1f} | {r['cpu']:.1f} | {base / r['wall']:.2f} |")
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="scripts/bench_sweep", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scene", default="chain_mooring")
    ap.add_argument("--vary", action="append", default=None, metavar="NAME=V1,V2,...")
    ap.add_argument("--duration", type=float, default=30.0)
    ap.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    a = ap.parse_args(argv)
    vary = a.vary or ["Cdn=2.0,2.4", "EA=5e8,7.5e8"]
    rows = measure(a.scene, vary, {"duration": a.duration}, a.workers)
    print(f"{a.scene}, {a.duration:g} s, vary {' '.join(vary)}; {os.cpu_count()} cores on this machine")
    print(table(rows))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
