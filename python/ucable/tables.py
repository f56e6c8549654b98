"""The one CSV writer of the package (result.csv of a scene or a system, results.csv of a sweep).

Written by the csv module: a column name holding a comma (`body[1].stiffness[1,2]`) or a quote is
quoted, so csv, pandas and numpy (numpy.loadtxt, or numpy.genfromtxt with the names taken from the
csv module's header, as `ucable.read_results` does) read as many names as values in every row. Numbers are
written with ten significant digits.
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np


def _cell(value):
    if isinstance(value, (bool, np.bool_)):
        return str(bool(value)).lower()
    if isinstance(value, (float, np.floating)):
        return f"{float(value):.10g}"
    if isinstance(value, (np.integer,)):
        return int(value)
    return value


def _numeric(values) -> bool:
    return isinstance(values, np.ndarray) and values.dtype.kind in "fiu"


def write_columns(path: str | Path, columns: dict) -> None:
    """Columns of equal length (name -> sequence), one row per index; all-numeric tables are written
    with one format per row, as numpy.savetxt (fast for long runs)."""
    names = list(columns)
    data = [columns[n] if _numeric(columns[n]) else list(columns[n]) for n in names]
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(names)
        if all(_numeric(v) for v in data):
            line = ",".join(["%.10g"] * len(data)) + "\n"
            f.writelines(line % tuple(row) for row in np.column_stack(data))
            return
        for row in zip(*data):
            writer.writerow([_cell(v) for v in row])


def write_rows(path: str | Path, names: list[str], rows: list[dict]) -> None:
    """Rows given as dicts; a name a row lacks is an empty cell, keys not in `names` are left out."""
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=names, extrasaction="ignore")
        writer.writeheader()
        for r in rows:
            writer.writerow({n: _cell(r.get(n, "")) for n in names})
