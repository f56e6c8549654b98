"""Sweeps: the cartesian product of parameter values over a scene, run on dask.distributed.

Each combination is one task with its own FMU instance; a combination that fails (a parameter the
FMU refuses, an integrator failure) is a row with its error, never a lost sweep. Without a scheduler
address a LocalCluster of `workers` single-threaded processes runs it on this machine; with one, the
same tasks go to that cluster (its workers need the `ucable` package installed).
"""

from __future__ import annotations

import csv
import itertools
import time
import traceback

import numpy as np

from .scene import Scene, load_scene, parse_value, run_scene

SUMMARY = ["towTensionMax", "towTensionMin", "towTensionFinal", "endDepthFinal"]


def parse_vary(items: list[str]) -> dict:
    """["length=200,300", "Cdn=1.2,1.6"] -> {"length": [200, 300], "Cdn": [1.2, 1.6]}."""
    out = {}
    for item in items:
        if "=" not in item:
            raise ValueError(f"--vary {item!r}: expected NAME=V1,V2,...")
        name, values = item.split("=", 1)
        vals = [parse_value(v) for v in values.split(",") if v.strip() != ""]
        if not vals:
            raise ValueError(f"--vary {item!r}: no values")
        out[name.strip()] = vals
    return out


def combinations(vary: dict) -> list[dict]:
    names = list(vary)
    return [dict(zip(names, values)) for values in itertools.product(*(vary[n] for n in names))]


def run_case(scene_data: dict, overrides: dict) -> dict:
    """One combination (runs on a worker): the summary row, or the error."""
    row = dict(overrides)
    t0 = time.process_time()
    try:
        result = run_scene(load_scene(scene_data), overrides)
        row.update(result.summary())
        row["cpuSeconds"] = result.cpu
        row["status"] = "ok"
        row["error"] = ""
    except Exception as exc:  # a failing combination is a row, not a lost sweep
        row.update({k: float("nan") for k in SUMMARY})
        row["cpuSeconds"] = time.process_time() - t0
        row["status"] = "error"
        last = traceback.format_exception_only(type(exc), exc)[-1].strip()
        row["error"] = last.replace("\n", " ")
    return row


def scene_data(scene: Scene) -> dict:
    return {"name": scene.name, "title": scene.title, "duration": scene.duration, "step": scene.step,
            "parameters": scene.parameters, "inputs": scene.inputs, "tow": scene.tow, "outputs": scene.outputs}


def run_sweep(scene: Scene, vary: dict, fixed: dict | None = None, workers: int = 2, scheduler: str | None = None,
              progress=None) -> tuple[list[dict], float]:
    """Rows in the order of the cartesian product, and the wall-clock seconds of the sweep."""
    from dask.distributed import Client, LocalCluster, as_completed

    base = scene_data(scene.with_overrides(fixed or {}))
    cases = combinations(vary)
    wall0 = time.perf_counter()
    cluster = None
    if scheduler is None:
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)
    client = Client(scheduler if scheduler is not None else cluster)
    try:
        futures = {client.submit(run_case, base, case, pure=False): i for i, case in enumerate(cases)}
        rows = [None] * len(cases)
        for done, future in enumerate(as_completed(futures), start=1):
            rows[futures[future]] = future.result()
            if progress is not None:
                progress(done)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    return rows, time.perf_counter() - wall0


def write_results(rows: list[dict], names: list[str], path) -> None:
    columns = names + SUMMARY + ["cpuSeconds", "status", "error"]
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        writer.writeheader()
        for r in rows:
            writer.writerow({c: f"{v:.10g}" if isinstance(v := r.get(c, ""), float) else v for c in columns})


def plot_summary(rows: list[dict], names: list[str], path, title: str) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    labels = [", ".join(f"{n}={r[n]}" for n in names) for r in rows]
    x = np.arange(len(rows))
    fig, ax = plt.subplots(1, 2, figsize=(max(8, 1.2 * len(rows) + 4), 4.5))
    tmax = np.array([r["towTensionMax"] for r in rows], dtype=float) / 1e3
    tmin = np.array([r["towTensionMin"] for r in rows], dtype=float) / 1e3
    tfin = np.array([r["towTensionFinal"] for r in rows], dtype=float) / 1e3
    ax[0].vlines(x, tmin, tmax, color="tab:blue", lw=6, alpha=0.4, label="min-max over the run")
    ax[0].plot(x, tfin, "o", color="tab:blue", label="final")
    ax[0].set_ylabel("tow tension [kN]")
    ax[0].legend(fontsize=8)
    ax[1].plot(x, [r["endDepthFinal"] for r in rows], "s", color="tab:green")
    ax[1].set_ylabel("final far-end depth [m]")
    for a in ax:
        a.set_xticks(x)
        a.set_xticklabels(labels, rotation=30, ha="right", fontsize=8)
        a.grid(alpha=0.3)
        for i, r in enumerate(rows):
            if r["status"] != "ok":
                a.annotate("failed", (i, 0), xycoords=("data", "axes fraction"), color="tab:red", ha="center")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
