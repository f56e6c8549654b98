"""Given wave components (`waves.mode` 3) against MoorDyn: its public deck wavekin_7.txt (`WaveKin` 7, two
components of wave_frequencies.txt travelling along x and at 1.57 rad) read by the FMU, and MoorDyn run on
the same files.

The deck: a light chain (13.3 mm, 1.1 kg/m, EA 7.51e6 N) of 410 m from an anchor at (-400, 0, -50) m on a
seabed 50 m deep to a vessel point at the mean surface (0, 0, 0), 82 segments, MoorDyn's seabed (kBot 1e5,
cBot 1e4, friction 0.5). The vessel point is held in both codes; both start from their static equilibrium
in still water (the deck's TmaxIC 0: MoorDyn's lines start on their catenary) and see the full waves from
t = 0 with Wheeler stretching. The fairlead tension of each, sampled every `step` seconds: its mean and
its range after `settle` seconds, and the RMS of the difference of the two histories.

    python -m studies.comparisons.wave_components MOORDYN_CHECKOUT [--t-end 120] [--segments N]
"""

from __future__ import annotations

import argparse
import shutil
import sys
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ..peers import moordyn

VESSEL = (0.0, 0.0, 0.0)


def deck_directory(moordyn_checkout: Path) -> Path:
    return Path(moordyn_checkout) / "tests" / "Mooring" / "wavekin_7"


def copy_case(source: Path, directory: Path, segments: int | None = None) -> Path:
    """wavekin_7.txt and its wave_frequencies.txt in `directory` (segments: another NumSegs)."""
    text = (source / "wavekin_7.txt").read_text()
    if segments is not None:
        old = "410       82"
        assert old in text
        text = text.replace(old, f"410       {segments}", 1)
    path = directory / "wavekin_7.txt"
    path.write_text(text)
    shutil.copy(source / "wave_frequencies.txt", directory / "wave_frequencies.txt")
    return path


def fmu_tension(fmu, path: Path, t_end: float, step: float, **parameters) -> dict:
    c = CableFMU(fmu, parameters={"lineFile": str(path), **parameters}, logging_on=True)
    try:
        c.initialize(inputs={f"tow.{k}": v for k, v in zip("xyz", VESSEL)})
        times, tension, elevation = [0.0], [c.get("towTension")], [c.get("waveElevation")]
        t = 0.0
        while t < t_end - 1e-9:
            c.do_step(step, t)
            t += step
            times.append(t)
            tension.append(c.get("towTension"))
            elevation.append(c.get("waveElevation"))
        return {"t": np.array(times), "tension": np.array(tension), "elevation": np.array(elevation),
                "messages": [m for _, _, m in c.messages]}
    finally:
        c.free()


def moordyn_tension(path: Path, t_end: float, step: float) -> dict:
    x, v = list(VESSEL), [0.0, 0.0, 0.0]
    with moordyn.System(path, also=[path.parent / "wave_frequencies.txt"], init=(x, v)) as md:
        times, tension, elevation = [0.0], [], []
        elevation.append(md.wave_kinematics(*VESSEL)[2])
        point = md.point(2)
        tension.append(float(np.linalg.norm(md.api.GetPointForce(point))))
        t = 0.0
        while t < t_end - 1e-9:
            f = md.step(x, v, t, step)
            t += step
            times.append(t)
            tension.append(float(np.linalg.norm(f)))
            elevation.append(md.wave_kinematics(*VESSEL)[2])
    return {"t": np.array(times), "tension": np.array(tension), "elevation": np.array(elevation)}


def statistics(t: np.ndarray, tension: np.ndarray, settle: float) -> dict:
    w = t >= settle - 1e-9
    return {"mean": float(np.mean(tension[w])), "range": float(np.ptp(tension[w])), "rms": float(np.std(tension[w]))}


def compare(fmu, source: Path, directory: Path, t_end: float = 120.0, step: float = 0.5,
            settle: float = 40.0, segments: int | None = None, **parameters) -> dict:
    """The FMU and MoorDyn on the deck of `source` (wavekin_7.txt and wave_frequencies.txt) copied into
    `directory`."""
    path = copy_case(Path(source), Path(directory), segments)
    ours = fmu_tension(fmu, path, t_end, step, **parameters)
    theirs = moordyn_tension(path, t_end, step)
    w = ours["t"] >= settle - 1e-9
    difference = ours["tension"][w] - theirs["tension"][w]
    return {"fmu": statistics(ours["t"], ours["tension"], settle),
            "moordyn": statistics(theirs["t"], theirs["tension"], settle),
            "history": float(np.sqrt(np.mean((difference - difference.mean()) ** 2)) / np.std(theirs["tension"][w])),
            "elevation": float(np.max(np.abs(ours["elevation"] - theirs["elevation"]))),
            "messages": ours["messages"], "series": (ours, theirs)}


def main(argv=None) -> int:
    from ucable.paths import require_fmu

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("moordyn_path", type=Path, help="a MoorDyn checkout (its tests/Mooring/wavekin_7)")
    ap.add_argument("--t-end", type=float, default=120.0)
    ap.add_argument("--segments", type=int, default=None)
    args = ap.parse_args(argv)
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        r = compare(require_fmu(), deck_directory(args.moordyn_path), Path(tmp), t_end=args.t_end, segments=args.segments)
    for code in ("fmu", "moordyn"):
        s = r[code]
        print(f"{code:8s} mean {s['mean']:10.2f} N  range {s['range']:9.2f} N  rms {s['rms']:8.3f} N")
    print(f"history difference {r['history']:.3f} of MoorDyn's RMS; elevation at the fairlead within {r['elevation']:.2e} m")
    return 0


if __name__ == "__main__":
    sys.exit(main())
