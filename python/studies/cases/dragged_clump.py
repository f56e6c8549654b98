"""A clump weight dragged over the seabed: does the fairlead tension converge under refinement?

400 m of chain (113 kg/m, d 0.0766 m, EA 7.5e8 N, no bending, tension-only) from a tow point 5 m
deep, free at its far end, with a 20 t clump (2.5 m3) at s = 300 m, over a 100 m seabed
(seabedStiffness 1e6 N/m2, seabedFriction 1.0), towed along x. The run starts from the steady tow at
`start_speed` and steps to `speed` over 5 s, which disturbs the sliding clump and the chain that
pulls it: the clump's mass on the chain's axial stiffness rings at about 1.4 Hz, and what the case
asks of the model is that the ringing and the steady tension are the same on every mesh.

    python -m studies.cases.dragged_clump 20 40 60        # the table of docs/model.md
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from ucable.fmu import CableFMU
from ucable.paths import fmu_path

LINE = {"length": 400.0, "diameter": 0.0766, "massPerLength": 113.0, "EA": 7.5e8, "EI": 0.0,
        "enableBending": False, "enableCompression": False, "bottomEnd": 0,
        "enableSeabed": True, "waterDepth": 100.0, "seabedStiffness": 1e6, "seabedFriction": 1.0,
        "nAttachments": 1, "attachment[1].s": 300.0, "attachment[1].mass": 20000.0,
        "attachment[1].volume": 2.5}
TOW_DEPTH = 5.0  # [m]
WINDOWS = [(5.0, 30.0), (30.0, 60.0), (60.0, 90.0), (90.0, 120.0)]  # [s]


def run(n_elements: int, fmu=None, start_speed: float = 0.45, speed: float = 0.5, duration: float = 120.0,
        step: float = 0.1) -> np.ndarray:
    """Rows (t, towTension, towTensionMax, towTensionMin) at every communication point."""
    c = CableFMU(fmu or fmu_path(), parameters=dict(LINE, nElements=n_elements))
    try:
        c.initialize(inputs={"tow.x": 0.0, "tow.z": -TOW_DEPTH, "tow.vx": start_speed})
        t, x, rows = 0.0, 0.0, []
        while t < duration - 1e-9:
            v = start_speed + (speed - start_speed) * min(1.0, (t + step) / 5.0)
            x += step * v
            c.set({"tow.x": x, "tow.vx": v})
            c.do_step(step, t)
            t += step
            rows.append((t, *c.get_reals(["towTension", "towTensionMax", "towTensionMin"])))
    finally:
        c.free()
    return np.array(rows)


def windows(rows: np.ndarray) -> list:
    """Per window of WINDOWS: (start, end, mean, lowest, highest) of the tow tension [N]."""
    out = []
    for lo, hi in WINDOWS:
        s = rows[(rows[:, 0] > lo) & (rows[:, 0] <= hi + 1e-9)]
        out.append((lo, hi, float(s[:, 1].mean()), float(s[:, 3].min()), float(s[:, 2].max())))
    return out


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m studies.cases.dragged_clump", description=__doc__.split("\n")[0])
    p.add_argument("elements", type=int, nargs="*", default=[20, 40, 60], help="meshes (default 20 40 60)")
    p.add_argument("--fmu", default=None, help="the FMU (default: the package's)")
    args = p.parse_args(argv)
    print("| elements | window [s] | mean [kN] | range [kN] | CPU [s] |")
    print("|---|---|---|---|---|")
    for n in args.elements:
        t0 = time.process_time()
        rows = run(n, args.fmu)
        cpu = time.process_time() - t0
        for lo, hi, mean, low, high in windows(rows):
            print(f"| {n} | {lo:g}-{hi:g} | {mean / 1e3:.1f} | {low / 1e3:.1f}-{high / 1e3:.1f} | {cpu:.1f} |", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
