"""Sweeps: the cartesian product of parameter values over a scene, run on dask.distributed.

Each combination is one task with its own FMU instance; a combination that fails (a parameter the
FMU refuses, an integrator failure) is a row with its error, never a lost sweep. Without a scheduler
address a LocalCluster of `workers` single-threaded processes runs it on this machine; with one, the
same tasks go to that cluster (its workers need the `ucable` package installed).
"""

from __future__ import annotations

import itertools
import time
import traceback
from pathlib import Path

import numpy as np

from .design_check import run_statistics, statistics_units
from .scene import Scene, SceneError, case_statistics_from, load_scene, parse_value, run_scene
from .scene_schema import SceneFileError
from .tables import write_rows

SUMMARY = ["towTensionMax", "towTensionMin", "towTensionFinal", "endDepthFinal"]
EXTRA_SUMMARY = ["anchorTensionMax", "lengthFinal"]  # anchored lines, winch scenes


def parse_vary(items: list[str]) -> dict:
    """["length=200,300", "Cdn=1.2,1.6"] -> {"length": [200, 300], "Cdn": [1.2, 1.6]}."""
    out = {}
    for item in items:
        if "=" not in item:
            raise SceneFileError(f"--vary {item!r}: expected NAME=V1,V2,...")
        name, values = item.split("=", 1)
        vals = [parse_value(v) for v in values.split(",") if v.strip() != ""]
        if not vals:
            raise SceneFileError(f"--vary {item!r}: no values")
        out[name.strip()] = vals
    return out


def check_vary(scene: Scene, vary: dict) -> None:
    """Every varied value checked as an override of the scene (a SceneFileError names it)."""
    for name, values in vary.items():
        for value in values:
            scene.with_overrides({name: value}, source="--vary")


def combinations(vary: dict) -> list[dict]:
    names = list(vary)
    return [dict(zip(names, values)) for values in itertools.product(*(vary[n] for n in names))]


def run_case(scene_data: dict, overrides: dict, directory: str | None = None) -> dict:
    """One combination (runs on a worker): the summary row, or the error. `directory` is the scene
    file's (a relative lineFile is looked up there first, as `ucable run` does)."""
    row = dict(overrides)
    t0 = time.process_time()
    try:
        scene = load_scene(scene_data)
        scene.directory = Path(directory) if directory else None
        result = run_scene(scene, overrides)
        row.update(result.summary())
        columns = result.columns
        start = case_statistics_from(scene, overrides.get("case"))
        if start > 0.0:  # a design case's part of the run (scene.failure_case)
            keep = np.asarray(result.time, dtype=float) >= start - 1e-9
            columns = {name: np.asarray(values)[keep] for name, values in columns.items()}
        row.update(run_statistics(columns))
        row["cpuSeconds"] = result.cpu
        row["status"] = "ok"
        row["error"] = ""
    except Exception as exc:  # a failing combination is a row, not a lost sweep
        row.update({k: float("nan") for k in SUMMARY})
        row["cpuSeconds"] = time.process_time() - t0
        row["status"] = "error"
        known = isinstance(exc, (SceneFileError, SceneError))  # their message says it all
        last = str(exc) if known else traceback.format_exception_only(type(exc), exc)[-1].strip()
        row["error"] = last.replace("\n", " ")
    return row


def scene_data(scene: Scene) -> dict:
    """The scene as data (what a worker gets)."""
    return {**scene.data, "name": scene.name, "title": scene.title}


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
        directory = str(scene.directory) if scene.directory is not None else None
        futures = {client.submit(run_case, base, case, directory, pure=False): i for i, case in enumerate(cases)}
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
    """results.csv: one row per combination, each column named with its unit (a varied name's from the
    variable schema, its values as given: `length [m]`, `speed_kn [kn]`, `heading [deg]`)."""
    from .results import TEXT_COLUMNS, label, schema_unit

    extra = [k for k in EXTRA_SUMMARY if any(k in r for r in rows)]
    lines = list(dict.fromkeys(c for r in rows for c in r if statistics_units(c) is not None and c not in names))
    columns = names + SUMMARY + extra + lines + ["cpuSeconds", "status", "error"]
    headers = {c: label(c, None if c in TEXT_COLUMNS else (statistics_units(c) or schema_unit(c))) for c in columns}
    write_rows(path, list(headers.values()), [{headers[c]: r.get(c, "") for c in columns} for r in rows])


def _numeric(values) -> bool:
    return all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values)


def plot_summary(rows: list[dict], names: list[str], path, title: str) -> None:
    """The summary against what varies: with one numeric name (or the first of several, the others
    as one line each) on the x axis; otherwise one position per combination. Tension extremes and
    the final tension; the final far-end depth, or the anchor tension's maximum of anchored lines."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    first = names[0]
    axis_values = [r[first] for r in rows]
    numeric = _numeric(axis_values)
    others = names[1:]
    groups: dict = {}
    for i, r in enumerate(rows):
        groups.setdefault(tuple(r[n] for n in others), []).append(i)
    anchored = any("anchorTensionMax" in r and r["status"] == "ok" for r in rows)
    key2, label2, scale2 = (("anchorTensionMax", "anchor tension max [kN]", 1e3) if anchored else
                            ("endDepthFinal", "final far-end depth [m]", 1.0))
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.5))
    for g, (group, idx) in enumerate(groups.items()):
        x = np.array([axis_values[i] for i in idx], dtype=float) if numeric else np.array(idx, dtype=float)
        if numeric:
            order = np.argsort(x)
            idx, x = [idx[i] for i in order], x[order]
        label = ", ".join(f"{n}={v}" for n, v in zip(others, group)) or None
        color = f"C{g % 10}"

        def col(key, scale=1.0):
            return np.array([rows[i].get(key, np.nan) for i in idx], dtype=float) / scale

        ax[0].fill_between(x, col("towTensionMin", 1e3), col("towTensionMax", 1e3), color=color, alpha=0.2)
        ax[0].plot(x, col("towTensionFinal", 1e3), "o-", color=color, label=label)
        ax[1].plot(x, col(key2, scale2), "s-", color=color, label=label)
        for i, xi in zip(idx, x):
            if rows[i]["status"] != "ok":
                for a in ax:
                    a.annotate("failed", (xi, 0.05), xycoords=("data", "axes fraction"), color="tab:red",
                               ha="center", rotation=90)
    ax[0].set_ylabel("tow tension [kN]: final (markers), min-max over the run (band)")
    ax[1].set_ylabel(label2)
    for a in ax:
        if numeric:
            a.set_xlabel(first)
        else:
            a.set_xticks(range(len(rows)))
            a.set_xticklabels([", ".join(f"{n}={r[n]}" for n in names) for r in rows], rotation=30, ha="right",
                              fontsize=8)
        a.grid(alpha=0.3)
        if others:
            a.legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def seed_values(seeds: int, first: int) -> list[int]:
    """The waves.seed of each realisation: first, first + 1, ..."""
    if seeds < 3:
        raise SceneFileError(f"--seeds {seeds}: a Gumbel fit needs 3 realisations or more")
    if first < 0 or first + seeds - 1 > 999999999:
        raise SceneFileError(f"--seed0 {first}: waves.seed is in [0, 999999999]")
    return list(range(first, first + seeds))


def realisation_maxima(rows: list[dict]) -> dict:
    """{line name: (the maxima of its fairlead tension over each realisation [N], its MBL [N])} of a sweep
    over seeds (runs that failed left out): line[k].fairleadTensionMax, or for a single line (no line[k].*
    tensions recorded) the tow point's towTensionMax, its fairlead."""
    ok = [r for r in rows if r.get("status") == "ok"]
    out = {}
    k = 1
    while any(f"line[{k}].fairleadTensionMax" in r for r in ok):
        if not any(r.get(f"line[{k}].brokenAny", 0.0) > 0.5 for r in ok):
            out[f"line {k}"] = (np.array([r[f"line[{k}].fairleadTensionMax"] for r in ok], dtype=float),
                                max(r.get(f"line[{k}].MBL", 0.0) for r in ok))
        k += 1
    if not out and ok:
        out["line 1"] = (np.array([r["towTensionMax"] for r in ok], dtype=float),
                         max(r.get("line[1].MBL", 0.0) for r in ok))
    return out


def stationary_duration(scene: Scene) -> float:
    """The part of a realisation the maxima stand for: the scene's duration less the waves' ramp-in."""
    ramp = float(scene.parameters.get("waves.rampTime", 0.0))
    return scene.duration - ramp


def write_extremes(fits: dict, mbls: dict, path) -> None:
    """extremes.csv: one row per line: the fit, the MPM over the storm and its interval (N)."""
    rows = [{"line": name, "realisations": f.maxima.size, "method": f.method, "mu [N]": f.mu, "beta [N]": f.beta,
             "realisation [s]": f.duration, "storm [s]": f.storm, "MPM [N]": f.mpm, "low [N]": f.low,
             "high [N]": f.high, "level [-]": f.level, "MBL [N]": mbls.get(name, 0.0),
             "MPM / MBL [-]": f.mpm / mbls[name] if mbls.get(name, 0.0) > 0.0 else ""}
            for name, f in fits.items()]
    write_rows(path, list(rows[0]) if rows else ["line"], rows)
