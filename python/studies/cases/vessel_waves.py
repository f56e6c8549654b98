"""The Vessel FMU's superimposed wave motion, measured (scripts/vessel_waves -> docs/waves.md, the section
between the markers of scripts/vessel_waves):

- encounter: a regular wave T 8 s, H 2 m, the vessel holding station or at 5 m/s in head and following
  seas: the encounter frequency w - k.V, the spectral peak of the tow point's heave over 512 s, and the
  heave and pitch amplitudes at the reference point;
- derivatives in turns: how far the tow point's velocity and acceleration are from the central
  differences of its position and velocity (0.01 s steps) in turns at 2.4 kn, with the shipped RAOs;
- cost: microseconds per communication step without waves, in a regular wave and in JONSWAP seas.
"""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.units import GRAVITY as G, KNOT

TOW = [f"tow.{q}" for q in ("x", "y", "z", "vx", "vy", "vz", "ax", "ay", "az")]
LEVER = {"towPoint.x": -30.0, "towPoint.y": 3.0, "towPoint.z": 4.0}
ENCOUNTERS = ((0.0, 180.0), (5.0, 180.0), (5.0, 0.0))  # speed [m/s], relative heading [deg]
TURNS = ((1.0, 7.0), (1.0, 10.0), (3.0, 7.0), (3.0, 10.0))  # turn rate [deg/s], wave period [s]
COSTS = ((0, 1), (1, 1), (2, 200), (2, 1000))  # waves.mode, waves.nComponents


def run(fmu, parameters: dict, step: float, steps: int, names: list, progress=None) -> np.ndarray:
    """The outputs `names` at every communication point (rows), from t = 0."""
    with CableFMU(fmu, parameters=parameters, instance_name="vessel") as v:
        v.initialize(0.0, step * steps)
        rows = [v.get_reals(names)]
        for k in range(steps):
            v.do_step(step, t=step * k)
            rows.append(v.get_reals(names))
            if progress and k % 100 == 99:
                progress(k + 1)
    return np.array(rows)


def encounter(fmu, speed: float, relative: float, progress=None) -> dict:
    T, step, steps = 8.0, 0.5, 1024
    params = {"waves.mode": 1, "waves.height": 2.0, "waves.period": T, "waves.direction": 0.0,
              "heading0": -math.radians(relative), "speed0": speed, "speed1": speed, **LEVER}
    rows = run(fmu, params, step, steps, ["tow.z", "waveMotion.heave", "waveMotion.pitch"], progress)[1:]
    z = rows[:, 0] - rows[:, 0].mean()
    spectrum = np.abs(np.fft.rfft(z * np.hanning(z.size)))
    frequencies = 2 * math.pi * np.fft.rfftfreq(z.size, step)
    w = 2 * math.pi / T
    we = w - w * w / G * speed * math.cos(math.radians(relative))  # deep water: k = w^2 / g
    return {"speed": speed, "relative": relative, "omega": w, "encounter": we,
            "peak": float(frequencies[np.argmax(spectrum)]), "bin": float(frequencies[1]),
            "heave": float(np.ptp(rows[:, 1]) / 2), "pitch": math.degrees(np.ptp(rows[:, 2]) / 2)}


def turn_derivatives(fmu, rate: float, period: float, progress=None) -> dict:
    """Errors of velocity and acceleration against central differences, relative to the largest
    wave-frequency velocity and acceleration (the run's minus the same run without waves), from 5 s on."""
    h, steps, skip = 0.01, 6000, 500
    params = {"waves.mode": 1, "waves.height": 2.0, "waves.period": period, "waves.direction": 2.0,
              "speed0": 2.4 * KNOT, "speed1": 2.4 * KNOT, "turnStart": 2.0, "turnRate": math.radians(rate),
              "turnAngle": math.radians(180.0), **LEVER}
    rows = run(fmu, params, h, steps, TOW, progress)[skip:]
    calm = run(fmu, {**params, "waves.mode": 0}, h, steps, TOW)[skip:]
    out = {"rate": rate, "period": period}
    for name, value, derivative in (("velocity", slice(0, 3), slice(3, 6)), ("acceleration", slice(3, 6), slice(6, 9))):
        x = rows[:, value]
        error = np.linalg.norm((x[2:] - x[:-2]) / (2 * h) - rows[1:-1, derivative], axis=1)
        scale = np.max(np.linalg.norm(rows[:, derivative] - calm[:, derivative], axis=1))
        out[name] = {q: float(np.percentile(error, p) / scale) for q, p in (("median", 50), ("p995", 99.5), ("max", 100))}
    return out


def cost(fmu, mode: int, n: int) -> float:
    """Microseconds per 0.1 s communication step (two Runge-Kutta substeps), best of three runs of 2000."""
    params = {"waves.mode": mode, "waves.height": 3.0 if mode else 0.0, "waves.nComponents": n,
              "speed0": 2.0, "speed1": 2.0}
    with CableFMU(fmu, parameters=params, instance_name="vessel") as v:
        v.initialize(0.0, 1e4)
        best = math.inf
        for rep in range(3):
            t0 = time.perf_counter()
            for k in range(2000):
                v.do_step(0.1, t=0.1 * (k + 2000 * rep))
            best = min(best, (time.perf_counter() - t0) / 2000)
    return 1e6 * best


def compute(fmu, progress_factory=None) -> dict:
    def with_bar(total, label, measure):
        bar = progress_factory(total, label) if progress_factory else None
        result = measure(bar.update if bar else None)
        if bar:
            bar.close()
        return result

    return {"encounters": [with_bar(1024, f"encounter {U:g} m/s {mu:g} deg", lambda p, U=U, mu=mu: encounter(fmu, U, mu, p))
                           for U, mu in ENCOUNTERS],
            "turns": [with_bar(6000, f"turn {r:g} deg/s T {T:g} s", lambda p, r=r, T=T: turn_derivatives(fmu, r, T, p))
                      for r, T in TURNS],
            "costs": [{"mode": m, "n": n, "us": cost(fmu, m, n)} for m, n in COSTS]}


def markdown(data: dict) -> str:
    seas = {180.0: "head seas", 0.0: "following seas"}
    out = ["Regular wave H 2 m, T 8 s (ω 0.785 rad/s), tow point (−30, 3, 4) m, shipped RAOs: the encounter "
           "frequency ω − k·V, the spectral peak of the tow point's heave over 512 s (Hann window), and the "
           "amplitudes at the reference point.", "",
           "| vessel | encounter frequency [rad/s] | heave peak [rad/s] (bin) | encounter period [s] "
           "| heave [m] | pitch [deg] |", "|---|---|---|---|---|---|"]
    for e in data["encounters"]:
        who = "holding station" if e["speed"] == 0.0 else f"{e['speed']:g} m/s, {seas[e['relative']]}"
        out.append(f"| {who} | {e['encounter']:.3f} | {e['peak']:.3f} ({e['bin']:.4f}) | "
                   f"{2 * math.pi / e['encounter']:.2f} | {e['heave']:.3f} | {e['pitch']:.2f} |")
    out += ["", "Velocity and acceleration of the tow point against the central differences of its position and "
            "velocity, in turns at 2.4 kn (regular wave H 2 m along 2 rad, shipped RAOs, tow point (−30, 3, 4) m, "
            "0.01 s steps from 5 s to 60 s), relative to the largest wave-frequency velocity or acceleration:", "",
            "| turn, wave period | velocity: median, 99.5 %, max | acceleration: median, 99.5 % |", "|---|---|---|"]
    for t in data["turns"]:
        v, a = t["velocity"], t["acceleration"]
        out.append(f"| {t['rate']:g} deg/s, T {t['period']:g} s | {v['median']:.1e}, {v['p995']:.1e}, "
                   f"{100 * v['max']:.1f} % | {a['median']:.1e}, {a['p995']:.1e} |")
    costs = {(c["mode"], c["n"]): c["us"] for c in data["costs"]}
    out += ["", "Cost per communication step of 0.1 s (two Runge-Kutta substeps), best of three runs of 2000 "
            f"steps: {costs[(0, 1)]:.1f} µs without waves, {costs[(1, 1)]:.1f} µs in a regular wave, "
            f"{costs[(2, 200)]:.0f} µs in a JONSWAP sea of 200 components and {costs[(2, 1000)]:.0f} µs with 1000.",
            ""]
    return "\n".join(out)


def main(argv=None) -> int:
    import argparse
    import json

    from ..doc_section import write_section
    from ucable.paths import REPO_ROOT
    from ucable.progress import ProgressBar
    from ucable.system import partner_fmu

    p = argparse.ArgumentParser(prog="scripts/vessel_waves", description=__doc__.split("\n\n")[0])
    p.add_argument("--doc", type=Path, default=REPO_ROOT / "docs" / "waves.md",
                   help="the Markdown file whose section between the markers is rewritten (default docs/waves.md)")
    p.add_argument("--json", type=Path, default=REPO_ROOT / "out" / "vessel_waves" / "study.json",
                   help="the numbers, as JSON")
    p.add_argument("--fmu", type=Path, default=None, help="the Vessel FMU (default: next to the cable's)")
    a = p.parse_args(argv)
    data = compute(a.fmu or partner_fmu("Vessel"), lambda total, label: ProgressBar(total, label))
    a.json.parent.mkdir(parents=True, exist_ok=True)
    a.json.write_text(json.dumps(data, indent=1))
    write_section(a.doc, markdown(data), "scripts/vessel_waves")
    print(f"wrote {a.doc} and {a.json}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
