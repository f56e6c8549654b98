"""The results table of a run: the maximum and minimum of each quantity an engineer checks, with the time
of each, and its final value (summary.csv, and the table `ucable run` prints).

Per line: fairlead and anchor tension, grounded length; per body: the magnitude of the lines' force and
the horizontal offset from its start; for a tow: tension, layback, far-end (fish) depth, top angle; with
a winch the paid-out length. The tow tension's extremes are the FMU's within each communication step
(`towTensionMax`, `towTensionMin`), timed at the end of the step in which they occurred; the other
quantities are sampled at the communication points. Units as in result.csv (angles in degrees).
Computed here (`scene_summary`), formatted apart (`summary_columns`, `format_table`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .results import label, schema_unit, written_unit

HEADER = ["quantity", "unit", "max", "time of max [s]", "min", "time of min [s]", "final", "description"]


@dataclass
class Extreme:
    quantity: str
    unit: str
    max: float
    t_max: float
    min: float
    t_min: float
    final: float
    description: str


def extreme(quantity: str, description: str, t, values, unit: str | None = None, upper=None, lower=None,
            ) -> Extreme:
    """The extremes of `values` over times `t` (of `upper` / `lower` when given: within-step extremes), in
    the written unit of `unit` (default: the schema's unit of `quantity`)."""
    unit, factor = written_unit(unit if unit is not None else schema_unit(quantity))
    v = np.asarray(values, dtype=float) * factor
    hi = v if upper is None else np.asarray(upper, dtype=float) * factor
    lo = v if lower is None else np.asarray(lower, dtype=float) * factor
    i, j = int(np.nanargmax(hi)), int(np.nanargmin(lo))
    return Extreme(quantity, unit or "-", float(hi[i]), float(t[i]), float(lo[j]), float(t[j]), float(v[-1]),
                   description)


def line_numbers(columns: dict) -> list[int]:
    """The deck's lines recorded in `columns` (line[k].fairleadTension present)."""
    ks = []
    k = 1
    while f"line[{k}].fairleadTension" in columns:
        ks.append(k)
        k += 1
    return ks


def _tow_rows(t, c: dict, anchored: bool) -> list[Extreme]:
    fairlead = "fairlead tension (within-step extremes)" if anchored else "tow tension (within-step extremes)"
    rows = [extreme("towTension", fairlead, t, c["towTension"], upper=c.get("towTensionMax"),
                    lower=c.get("towTensionMin"))]
    if anchored:
        rows.append(extreme("endTension", "anchor tension", t, c["endTension"]))
        if "groundedLength" in c:
            rows.append(extreme("groundedLength", "length resting on the seabed", t, c["groundedLength"]))
        return rows
    if "layback" in c:
        rows.append(extreme("layback", "horizontal distance tow point - far end", t, c["layback"]))
    rows.append(extreme("endDepth", "far-end (fish) depth below the surface", t, -np.asarray(c["endPosition.z"]),
                        unit="m"))
    if "topDeclination" in c:
        rows.append(extreme("topDeclination", "top angle from the downward vertical", t, c["topDeclination"]))
    return rows


def _mooring_rows(t, c: dict) -> list[Extreme]:
    rows = []
    for k in line_numbers(c):
        rows.append(extreme(f"line[{k}].fairleadTension", f"line {k}: fairlead tension", t,
                            c[f"line[{k}].fairleadTension"]))
        rows.append(extreme(f"line[{k}].anchorTension", f"line {k}: anchor tension", t, c[f"line[{k}].anchorTension"]))
        if f"line[{k}].groundedLength" in c:
            rows.append(extreme(f"line[{k}].groundedLength", f"line {k}: length resting on the seabed", t,
                                c[f"line[{k}].groundedLength"]))
    return rows


def _body_rows(t, c: dict, k: int = 1) -> list[Extreme]:
    rows = []
    force = [f"body[{k}].force.{q}" for q in "xyz"]
    if all(n in c for n in force):
        F = np.linalg.norm(np.column_stack([c[n] for n in force]), axis=1)
        rows.append(extreme(f"body[{k}].force", f"body {k}: magnitude of the lines' force", t, F, unit="N"))
    pos = [f"body[{k}].{q}" for q in "xy"]
    if all(n in c for n in pos):
        x, y = (np.asarray(c[n], dtype=float) for n in pos)
        rows.append(extreme(f"body[{k}].offset", f"body {k}: horizontal offset from its start", t,
                            np.hypot(x - x[0], y - y[0]), unit="m"))
    return rows


def scene_summary(result) -> list[Extreme]:
    """The table of a scene's result (a SceneResult, or anything with .time, .columns and .scene)."""
    t, c = result.time, result.columns
    if result.scene.body:
        return _mooring_rows(t, c) + _strength_rows(t, c) + _body_rows(t, c)
    rows = _tow_rows(t, c, result.scene.kind == "anchored")
    if "unstretchedLength" in c:
        rows.append(extreme("unstretchedLength", "paid-out (unstretched) length", t, c["unstretchedLength"]))
    return rows + _strength_rows(t, c)


def _strength_rows(t, c: dict) -> list[Extreme]:
    """Each line's largest tension over its MBL along it, for the lines with an MBL (docs/design_checks.md)."""
    return [extreme(f"line[{k}].maxUtilisation", f"line {k}: largest tension / MBL along it", t,
                    c[f"line[{k}].maxUtilisation"]) for k in range(1, 1 + len(c)) if f"line[{k}].maxUtilisation" in c]


def system_summary(r) -> list[Extreme]:
    """The table of a system's result (ucable.system.SystemResult): a mooring system's lines (fairlead
    tension), the lines' force on the platform and its horizontal offset; a towed body's tow tension, the
    tension at the body, its depth and its layback behind the vessel's tow point."""
    t, v = r.time, r.values
    if "cable.line[1].fairleadTension" in v:
        rows = []
        k = 1
        while f"cable.line[{k}].fairleadTension" in v:
            rows.append(extreme(f"line[{k}].fairleadTension", f"line {k}: fairlead tension", t,
                                v[f"cable.line[{k}].fairleadTension"]))
            k += 1
        F = np.linalg.norm(np.column_stack([v[f"cable.body[1].force.{q}"] for q in "xyz"]), axis=1)
        rows.append(extreme("body[1].force", "platform: magnitude of the lines' force", t, F, unit="N"))
        if "vessel.platform.x" in v:
            x, y = v["vessel.platform.x"], v["vessel.platform.y"]
            rows.append(extreme("body[1].offset", "platform: horizontal offset from its start", t,
                                np.hypot(x - x[0], y - y[0]), unit="m"))
        return rows
    p = r.body_position
    rows = [extreme("towTension", "tow tension", t, v["cable.towTension"]),
            extreme("endTension", "tension at the body", t, v["cable.endTension"]),
            extreme("bodyDepth", "towed body's depth below the surface", t, -p[:, 2], unit="m")]
    if "vessel.tow.x" in v:
        rows.append(extreme("layback", "horizontal distance tow point - body", t,
                            np.hypot(p[:, 0] - v["vessel.tow.x"], p[:, 1] - v["vessel.tow.y"]), unit="m"))
    return rows


def summary_columns(rows: list[Extreme]) -> dict:
    """The table as columns for results.write_table (summary.csv)."""
    return {"quantity": [r.quantity for r in rows], "unit": [r.unit for r in rows],
            "max": [r.max for r in rows], "time of max [s]": [r.t_max for r in rows],
            "min": [r.min for r in rows], "time of min [s]": [r.t_min for r in rows],
            "final": [r.final for r in rows], "description": [r.description for r in rows]}


def _number(v: float) -> str:
    return f"{v:.6g}" if abs(v) < 1e6 or abs(v) >= 1e12 else f"{v:.0f}"


def format_table(rows: list[Extreme]) -> str:
    """The table as text, one quantity per line."""
    names = [label(r.quantity, r.unit) for r in rows]
    w = max([len(n) for n in names] + [8])
    lines = [f"{'':{w}s}  {'max':>11s} {'at [s]':>8s}  {'min':>11s} {'at [s]':>8s}  {'final':>11s}"]
    for n, r in zip(names, rows):
        lines.append(f"{n:{w}s}  {_number(r.max):>11s} {r.t_max:8.2f}  {_number(r.min):>11s} {r.t_min:8.2f}  "
                     f"{_number(r.final):>11s}")
    return "\n".join(lines)
