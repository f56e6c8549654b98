"""A seabed given as a grid (seabed.file, a deck's SeafloorFile; docs/model.md "A seabed given as a grid")
against the peers: the chain of tests/data/decks/chain.dat (900 m, anchored 850 m away, fairlead 70 m deep)

- on a valley whose floor is a plane along the line and whose flanks rise across it, MoorPy's statics with
  its bathymetry file (MoorPy lays a line on the chord between the seabed under its two ends: exact on
  that floor), and
- across a ridge (the seabed curved along the line: the chain rises 40 m over the crest and hangs from
  there), MoorDyn run on the same deck with the grid as its SeafloorFile after its dynamic relaxation.

    cd python && ../.venv/bin/python -m studies.comparisons.seabed_grid
"""

from __future__ import annotations

import json
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[3]
DECK = ROOT / "tests" / "data" / "decks" / "chain.dat"
ANCHOR_X, FAIRLEAD_Z = -850.0, -70.0
XS = np.arange(-1000.0, 201.0, 25.0)
YS = np.arange(-120.0, 121.0, 20.0)


def flank(y: float) -> float:
    """The valley's flanks: a floor 60 m wide, rising 4 m 60 m beyond it."""
    return 4.0 * min(1.0, (max(0.0, abs(y) - 30.0) / 60.0) ** 2)


def valley(x: float, y: float) -> float:
    """A floor descending 0.04 towards +x, flanks across it."""
    return -300.0 - 0.04 * x + flank(y)


def ridge(x: float, y: float) -> float:
    """Curved along the line: the floor of `valley` pulled down towards the anchor, a crest at x = -400 m."""
    return valley(x, y) - 2.0e-4 * (x + 300.0) ** 2 * (x < -300.0)


def seafloor_text(height) -> str:
    """MoorDyn's SeafloorFile."""
    rows = [f"{len(XS)} {len(YS)}", " ".join(f"{x:.17g}" for x in XS), " ".join(f"{y:.17g}" for y in YS)]
    rows += [f"{x:.17g} {y:.17g} {height(x, y):.17g}" for x in XS for y in YS]
    return "\n".join(rows) + "\n"


def bathymetry_text(height) -> str:
    """MoorPy's bathymetry file (depths positive down)."""
    rows = ["--- bathymetry ---", f"nGridX {len(XS)}", f"nGridY {len(YS)}", " ".join(f"{x:.17g}" for x in XS)]
    rows += [f"{y:.17g} " + " ".join(f"{-height(x, y):.17g}" for x in XS) for y in YS]
    return "\n".join(rows) + "\n"


def deck_text(height, seafloor: str | None = None, segments: int = 40) -> str:
    """chain.dat with its anchor on the grid (and WtrDpth the grid's mean depth, MoorDyn's) and a SeafloorFile."""
    text = DECK.read_text()
    text = text.replace("1    Fixed       -850     0     -320", f"1    Fixed       -850     0     {height(ANCHOR_X, 0.0):.6f}")
    text = text.replace("900       40", f"900       {segments}")
    if seafloor:
        text = text.replace("9.81     g ", f"{seafloor}    SeafloorFile    the seabed's grid\n9.81     g ")
    return text


def fmu_statics(fmu_path: str, height, directory: Path) -> dict:
    """The FMU's start on the deck with the grid as its SeafloorFile (MoorDyn's format, beside the deck)."""
    from ucable.fmu import CableFMU

    (directory / "grid.txt").write_text(seafloor_text(height))
    deck = directory / "chain_grid.dat"
    deck.write_text(deck_text(height, "grid.txt"))
    c = CableFMU(fmu_path, parameters={"lineFile": str(deck)}, logging_on=True)
    try:
        c.initialize(inputs={"tow.z": FAIRLEAD_Z})
        out = dict(zip(["fairlead", "anchor", "grounded"], c.get_reals(["towTension", "endTension", "groundedLength"])))
        c.do_step(5.0, 0.0)  # the tow held: the start is at rest
        out["fairlead after 5 s"], out["anchor after 5 s"] = c.get_reals(["towTension", "endTension"])
        return {k: float(v) for k, v in out.items()}
    finally:
        c.free()


def moorpy_statics(height, directory: Path) -> dict:
    """MoorPy's equilibrium of the deck (the fairlead fixed where the deck puts it) on its bathymetry file."""
    from studies.peers import moorpy

    (directory / "bathymetry.txt").write_text(bathymetry_text(height))
    deck = directory / "chain_mp.dat"
    deck.write_text(deck_text(height))
    s = moorpy.system(deck, bathymetry=str(directory / "bathymetry.txt"))
    moorpy.solve(s, tol=1e-6, max_iter=500)
    line = s.lineList[0]
    return {"fairlead": float(np.linalg.norm(line.fB)), "anchor": float(np.linalg.norm(line.fA)),
            "grounded": float(line.LBot)}


MOORDYN_SCRIPT = r"""
import json, sys, moordyn, numpy as np
deck, fairlead = sys.argv[1], [float(v) for v in sys.argv[2:5]]
s = moordyn.Create(deck)
moordyn.Init(s, fairlead, [0.0, 0.0, 0.0])  # its dynamic relaxation
line = moordyn.GetLine(s, 1)
n = moordyn.GetLineN(line)
t, h = 0.0, 1.0
for k in range(int(sys.argv[5])):  # then held
    moordyn.Step(s, fairlead, [0.0, 0.0, 0.0], t, h)
    t += h
ten = lambda i: float(np.linalg.norm(moordyn.GetLineNodeTen(line, i)))
# its tensions are its segments': extrapolated to the end nodes from the last two (peers.moordyn)
print(json.dumps({"fairlead": 2.0 * ten(n) - ten(n - 1), "anchor": 2.0 * ten(0) - ten(1),
                  "grounded": float(sum(np.linalg.norm(moordyn.GetLineNodeSeabedForce(line, i)) > 0.0
                                        for i in range(n + 1))) * 900.0 / n}))
moordyn.Close(s)
"""


def moordyn_relaxed(height, directory: Path, held: int = 200) -> dict:
    """MoorDyn on the same deck with the grid as its SeafloorFile, after its dynamic relaxation and `held` s held
    (in a process of its own: peers.moordyn). grounded: the nodes with a seabed force times the segment length."""
    import subprocess

    (directory / "grid.txt").write_text(seafloor_text(height))
    deck = directory / "chain_md.dat"
    deck.write_text(deck_text(height, "grid.txt"))
    script = directory / "run_moordyn.py"
    script.write_text(MOORDYN_SCRIPT)
    done = subprocess.run([sys.executable, str(script), str(deck), "0", "0", str(FAIRLEAD_Z), str(held)],
                          cwd=directory, capture_output=True, text=True, check=True)
    return json.loads(done.stdout[done.stdout.rindex('{"fairlead"'):].splitlines()[0])


def main(fmu_path: str | None = None) -> dict:
    fmu_path = fmu_path or str(ROOT / "build" / "UnderwaterCable.fmu")
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        results["valley: FMU"] = fmu_statics(fmu_path, valley, d)
        results["valley: MoorPy"] = moorpy_statics(valley, d)
        results["ridge: FMU"] = fmu_statics(fmu_path, ridge, d)
        results["ridge: MoorDyn"] = moordyn_relaxed(ridge, d)
    return results


if __name__ == "__main__":
    print(json.dumps(main(*sys.argv[1:]), indent=1))
