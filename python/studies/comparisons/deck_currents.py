"""MoorDyn's steady current profile (`Currents` 1 with current_profile.txt next to the deck) read by the FMU
as its current profile (docs/lines.md, "Options and environment"), against MoorDyn fed the same files.

The mooring chain of tests/data/decks/chain.dat (900 m, 113 kg/m, fairlead 70 m deep, anchor 850 m away on
a seabed 320 m deep) in a sheared current across its plane (along y, from 0.8 m/s at the surface to 0.2 m/s
at 200 m and below; the file has a redundant row, on the straight line between its neighbours). The FMU's
static equilibrium in that current against MoorDyn run to rest: the fairlead's force, its mean over the last
`average` seconds of a run of `t_end` seconds with the fairlead held (MoorDyn's own initial-condition
generation applies the current too, but stops at its threshold; the run settles the drag-damped chain).

    python -m studies.comparisons.deck_currents      # the table of the comparison
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.paths import REPO_ROOT
from ..peers import moordyn

CHAIN = REPO_ROOT / "tests" / "data" / "decks" / "chain.dat"
FAIRLEAD = (0.0, 0.0, -70.0)
# z, uy: MoorDyn's rows, z increasing; -100 lies on the line between -200 and 0
PROFILE = ((-320.0, 0.2), (-200.0, 0.2), (-100.0, 0.5), (0.0, 0.8))


def write_case(directory: Path, segments: int = 40, current: bool = True) -> Path:
    """The chain deck with `Currents` 1 (or 0) and its current_profile.txt in `directory`."""
    text = CHAIN.read_text().replace(" 40       -", f" {segments}       -", 1)
    assert "320      WtrDpth" in text
    text = text.replace("320      WtrDpth", f"320      WtrDpth\n{1 if current else 0}        Currents", 1)
    path = directory / "chain_current.dat"
    path.write_text(text)
    rows = "".join(f"{z:g} 0.0 {u:g} 0.0\n" for z, u in PROFILE)
    (directory / "current_profile.txt").write_text(
        "--------------------- MoorDyn steady currents File ----------------------------------\n"
        "sheared current across the chain's plane\nz (m), ux (m/s), uy (m/s), uz (m/s)\n" + rows)
    return path


def fmu_parameters(path: Path, **extra) -> dict:
    return {"lineFile": str(path), "enableSeabed": True, "seabedStiffness": 3.0e6 * 0.0766,
            "seabedDamping": 3.0e5 * 0.0766, "enableCompression": False, **extra}


def fmu_statics(fmu, path: Path, **extra) -> dict:
    c = CableFMU(fmu, parameters=fmu_parameters(path, **extra), logging_on=True)
    try:
        c.initialize(inputs={f"tow.{k}": v for k, v in zip("xyz", FAIRLEAD)})
        return {"force": np.array([c.get(f"towForce.{k}") for k in "xyz"]),
                "profile": [(c.get(f"currentProfile.depth[{k}]"), c.get(f"currentProfile.y[{k}]"))
                            for k in range(1, c.get("currentProfileRows") + 1)],
                "messages": [t for _, _, t in c.messages]}
    finally:
        c.free()


def moordyn_rest(path: Path, t_end: float = 200.0, average: float = 20.0, step: float = 1.0) -> np.ndarray:
    """MoorDyn's force on the held fairlead, the mean over the run's last `average` seconds."""
    x, v = list(FAIRLEAD), [0.0, 0.0, 0.0]
    with moordyn.System(path, also=[path.parent / "current_profile.txt"], init=(x, v)) as md:
        forces, t = [], 0.0
        while t < t_end - 1e-9:
            f = md.step(x, v, t, step)
            t += step
            if t > t_end - average - 1e-9:
                forces.append(np.array(f, float))
    return np.mean(forces, axis=0)


def compare(fmu, directory: Path, segments: int = 40, t_end: float = 200.0) -> dict:
    """The FMU's static fairlead force in the deck's current, MoorDyn's at rest, the FMU's in still water."""
    path = write_case(directory, segments)
    still_dir = directory / "still"
    still_dir.mkdir(exist_ok=True)
    still = fmu_statics(fmu, write_case(still_dir, segments, current=False))
    ours = fmu_statics(fmu, path)
    theirs = moordyn_rest(path, t_end=t_end)
    diff = np.linalg.norm(ours["force"] - theirs) / np.linalg.norm(theirs)
    return {"fmu": ours["force"], "moordyn": theirs, "still": still["force"], "difference": diff,
            "profile": ours["profile"], "messages": ours["messages"]}


def main(argv=None) -> int:  # pragma: no cover
    from ucable.paths import fmu_path

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--segments", type=int, default=40, help="MoorDyn's segments (the FMU: half as many elements)")
    ap.add_argument("--t-end", type=float, default=200.0, help="MoorDyn's run to rest [s]")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        r = compare(fmu_path(), Path(tmp), args.segments, args.t_end)
    print(f"FMU's profile rows (depth, uy): {r['profile']}")
    for name in ("fmu", "moordyn", "still"):
        f = r[name]
        print(f"{name:8s} fairlead force {f[0]:12.1f} {f[1]:12.1f} {f[2]:12.1f}  |F| {np.linalg.norm(f):12.1f} N")
    print(f"difference FMU - MoorDyn: {100 * r['difference']:.3f} % of |F|")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
