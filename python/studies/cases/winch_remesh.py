"""Winch remeshing measured: what a split or merge of the top element does to the tow tension, and
whether a coarse master's extremes and fatigue count agree with the same run sampled at 0.01 s.

    bash scripts/winch_remesh [--element-lengths 5 15 30] [--out DIR]

Computation first (`remesh_moves`, `master_agreement`, each returning data), Markdown second
(`markdown`). The scenes are those of docs/winch.md: the 400 kg body towed at 2 kn on the
Hopland cable, paid out from 100 m or hauled in from 300 m at 0.5 m/s, the drum ramping at
0.05 m/s2; a 2 t body lowered by the constant-tension winch under a 1.5 m, 8 s heave.
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.progress import ProgressBar
from ucable.units import KNOT
from ..references.winch_reference import DeployBody, elements_for_length

SPEED = 2.0 * KNOT
RATE = 0.5  # [m/s] winch speed of the pay-out and haul-in scenes
DRUM_ACCELERATION = 0.05  # [m/s2]
FINE = 0.01  # [s] the fine master's step
FATIGUE = {"fatigue.area": 8.66e-4}  # the Hopland cable's steel area: a Miner's sum to compare
HEAVE, PERIOD = 1.5, 8.0  # [m], [s] of the constant-tension scene


@dataclass
class RemeshCase:
    """A winch scene: FMU parameters, initial inputs and the inputs at each communication point."""

    name: str
    parameters: dict
    initial: dict
    inputs: callable  # t -> (inputs dict, {name: input derivative})
    duration: float
    coarse: float  # [s] the coarse master's step
    start_length: float = 0.0
    nominal: float = 0.0  # [m] nominal element length (remeshes happen every `nominal` of winch travel)


def towed_scene(kind: str, element_length: float, duration: float = 100.0) -> RemeshCase:
    """Pay-out ('payout', 100 m and up) or haul-in ('haulin', 300 m and down) at 0.5 m/s towing the
    400 kg body at 2 kn."""
    length = 100.0 if kind == "payout" else 300.0
    rate = RATE if kind == "payout" else -RATE
    n = elements_for_length(length, element_length)
    params = {**DeployBody().fmu_parameters(), "length": length, "nElements": n, "initMode": 0,
              "winchMode": 1, "winch.minLength": 20.0, "winch.maxLength": 600.0, "winch.maxRate": 1.0,
              "winch.maxAcceleration": DRUM_ACCELERATION, **FATIGUE}

    def inputs(t):
        return {"tow.x": SPEED * t, "tow.vx": SPEED, "winch.rate": rate}, {}

    return RemeshCase(kind, params, {"tow.vx": SPEED, "winch.rate": 0.0}, inputs, duration, 0.5, length, length / n)


def tension_scene(duration: float = 60.0) -> RemeshCase:
    """The constant-tension winch lowering a 2 t body on 200 m (14 elements) under a 1.5 m, 8 s heave,
    1.5 kN below the static tension, time constant 5 ms (splits every 20 s or so)."""
    params = {"length": 200.0, "nElements": 14, "bottomEnd": 2, "body.mass": 2000.0, "body.volume": 0.25,
              "body.CdA": 2.0, "body.addedMass": 500.0, "winchMode": 2, "winch.timeConstant": 0.005,
              "winch.minLength": 50.0, "winch.maxLength": 400.0, "winch.maxRate": 2.0,
              "winch.maxAcceleration": 0.5, **FATIGUE}
    w = 2.0 * math.pi / PERIOD
    static = hanging_tension(params)

    def inputs(t):
        values = {"tow.z": HEAVE * math.sin(w * t), "tow.vz": HEAVE * w * math.cos(w * t),
                  "winch.tension": static - 1500.0}
        return values, {"tow.vz": -HEAVE * w * w * math.sin(w * t)}

    # the run starts in the motion of its inputs: the heave's velocity, the winch at the set tension
    initial = {"tow.vz": HEAVE * w, "winch.tension": static - 1500.0}
    return RemeshCase("tension", params, initial, inputs, duration, 0.1, 200.0, 200.0 / 14)


def hanging_tension(params: dict) -> float:
    """The static tow tension of the line hanging at fixed length."""
    fixed = {k: v for k, v in params.items() if not k.startswith("winch")}
    cable = CableFMU(parameters=fixed)
    try:
        cable.initialize()
        return cable.get("towTension")
    finally:
        cable.free()


@dataclass
class Run:
    """Outputs at every communication point of one run."""

    t: np.ndarray
    tension: np.ndarray
    tmax: np.ndarray
    tmin: np.ndarray
    length: np.ndarray
    damage: float
    steps: list = field(default_factory=list)


def run(scene: RemeshCase, steps, progress=None) -> Run:
    """The scene through the communication steps `steps` (a sequence of step sizes)."""
    cable = CableFMU(parameters=scene.parameters)
    rows = []
    try:
        cable.initialize(inputs=scene.initial)
        t = 0.0
        for k, h in enumerate(steps):
            values, derivatives = scene.inputs(t)
            cable.set(values)
            if derivatives:
                cable.set_input_derivatives(list(derivatives), 1, list(derivatives.values()))
            cable.do_step(h, t)
            t += h
            rows.append((t, *cable.get_reals(["towTension", "towTensionMax", "towTensionMin",
                                              "unstretchedLength"])))
            if progress and k % 100 == 0:
                progress(t)
        damage = cable.get("fatigueDamage")
    finally:
        cable.free()
    a = np.array(rows)
    return Run(a[:, 0], a[:, 1], a[:, 2], a[:, 3], a[:, 4], damage, list(steps))


def uniform(duration: float, h: float) -> list:
    return [h] * int(round(duration / h))


# --------------------------------------------------------------------------- master agreement
def master_agreement(scene: RemeshCase, progress=None) -> dict:
    """The scene run at its coarse step and at 0.01 s: for each coarse step, its towTensionMax/Min
    against the largest/smallest the 0.01 s master saw in the same interval (its own towTensionMax/
    Min), relative to the mean tension; and the two fatigue sums."""
    coarse = run(scene, uniform(scene.duration, scene.coarse))
    fine = run(scene, uniform(scene.duration, FINE), progress)
    per = int(round(scene.coarse / FINE))
    fmax = fine.tmax[: per * len(coarse.t)].reshape(-1, per).max(axis=1)
    fmin = fine.tmin[: per * len(coarse.t)].reshape(-1, per).min(axis=1)
    mean = fine.tension.mean()
    return {"scene": scene.name, "mean": mean, "coarse_step": scene.coarse,
            "max_diff": float(np.max(np.abs(coarse.tmax - fmax)) / mean),
            "min_diff": float(np.max(np.abs(coarse.tmin - fmin)) / mean),
            "damage_coarse": coarse.damage, "damage_fine": fine.damage,
            "damage_diff": abs(coarse.damage - fine.damage) / fine.damage,
            "travel": float(np.ptp(fine.length)), "remeshes": remesh_count(scene, fine)}


def remesh_count(scene: RemeshCase, r: Run) -> int:
    """Splits and merges the run went through: one per nominal element length of net travel
    beyond half an element (the top element splits at 1.5 and merges at 0.5 nominal lengths)."""
    travel = np.abs(r.length - scene.start_length)
    return int(np.floor(travel.max() / scene.nominal + 0.5))


# --------------------------------------------------------------------------- split / merge moves
def remesh_times(scene: RemeshCase, r: Run) -> list:
    """The communication points at which the run split or merged the top element: where the winch's
    net travel first passed (k - 1/2) nominal lengths."""
    travel = np.abs(r.length - scene.start_length)
    times = []
    for k in range(1, remesh_count(scene, r) + 1):
        crossed = np.nonzero(travel > (k - 0.5) * scene.nominal)[0]
        if len(crossed):
            times.append(float(r.t[crossed[0]]))
    return times


def deviation(r: Run, t0: float, half: float = 1.0) -> float:
    """Largest distance of the tension, and of each step's extremes, from a quadratic fitted to the
    tension at the communication points in [t0 - half, t0 + half]: how far the tension strays from
    its smooth course there [N]."""
    inside = (r.t >= t0 - half) & (r.t <= t0 + half)
    t, T = r.t[inside], r.tension[inside]
    fit = np.polynomial.Polynomial.fit(t, T, 2)
    prev = np.concatenate([[t[0] - FINE], t[:-1]])
    hi = np.maximum(fit(prev), fit(t))
    lo = np.minimum(fit(prev), fit(t))
    return float(max(np.max(np.abs(T - fit(t))), np.max(r.tmax[inside] - hi), np.max(lo - r.tmin[inside])))


def remesh_moves(kind: str, element_length: float, remeshes: int = 2, progress=None) -> dict:
    """How far a split (pay-out) or merge (haul-in) moves the tow tension, sampled at 0.01 s for
    2 s around each of the first `remeshes` remeshes (0.5 s steps in between), relative to the mean
    tension; and the same measure midway between remeshes, where nothing happens but the pay-out."""
    scene = towed_scene(kind, element_length)
    # the drum ramps to 0.5 m/s in 10 s (2.5 m of travel), then runs at 0.5 m/s; the remeshes
    # measured are those from 5 s after the ramp on (the ramp's end is a change of the motion)
    ramp = RATE / DRUM_ACCELERATION
    first = int(np.floor((0.5 * RATE * ramp + 5.0 * RATE) / scene.nominal + 0.5)) + 1
    travel_to = [(k - 0.5) * scene.nominal for k in range(first, first + remeshes)]
    when = [ramp + (d - 0.5 * RATE * ramp) / RATE for d in travel_to]
    quiet = [w + 0.5 * scene.nominal / RATE for w in when]
    marks = sorted(when + quiet)
    steps, t = [], 0.0
    for m in marks:
        while t + 0.5 <= m - 1.5:
            steps.append(0.5)
            t += 0.5
        for _ in range(int(round((m + 1.5 - t) / FINE))):
            steps.append(FINE)
            t += FINE
    r = run(scene, steps, progress)
    found = [t for t in remesh_times(scene, r) if t > ramp + 5.0][:remeshes]
    mean = float(np.mean(r.tension))
    return {"kind": kind, "element_length": scene.nominal, "mean": mean,
            "remesh": [deviation(r, t0) / mean for t0 in found],
            "quiet": [deviation(r, t0) / mean for t0 in quiet[: len(found)]], "times": found}


# --------------------------------------------------------------------------- report
def markdown(moves: list, agreement: list) -> str:
    lines = ["| scene | nominal element [m] | mean tension [N] | remesh: largest move | "
             "midway (no remesh) |", "|---|---:|---:|---:|---:|"]
    for m in moves:
        lines.append(f"| {'pay-out (splits)' if m['kind'] == 'payout' else 'haul-in (merges)'} | "
                     f"{m['element_length']:.2f} | {m['mean']:.0f} | "
                     f"{100 * max(m['remesh']):.4f} % | {100 * max(m['quiet']):.4f} % |")
    lines += ["", "| scene | coarse step [s] | remeshes | towTensionMax diff | towTensionMin diff | "
              "fatigueDamage coarse | 0.01 s | diff |", "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for a in agreement:
        lines.append(f"| {a['scene']} | {a['coarse_step']} | {a['remeshes']} | {100 * a['max_diff']:.3f} % | "
                     f"{100 * a['min_diff']:.3f} % | {a['damage_coarse']:.4e} | {a['damage_fine']:.4e} | "
                     f"{100 * a['damage_diff']:.3f} % |")
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="scripts/winch_remesh", description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--element-lengths", type=float, nargs="+", default=[5.0, 15.0, 30.0],
                        help="nominal element lengths of the split/merge measurement [m]")
    parser.add_argument("--out", type=Path, help="also write DIR/remesh_moves.csv and DIR/master_agreement.csv")
    args = parser.parse_args(argv)
    moves, agreement = [], []
    cases = [(k, l) for l in args.element_lengths for k in ("payout", "haulin")]
    bar = ProgressBar(len(cases) + 3, "winch remesh")
    for i, (kind, length) in enumerate(cases):
        moves.append(remesh_moves(kind, length))
        bar.update(i + 1)
    for i, scene in enumerate([towed_scene("payout", 15.0), towed_scene("haulin", 15.0), tension_scene()]):
        agreement.append(master_agreement(scene))
        bar.update(len(cases) + i + 1)
    bar.close()
    print(markdown(moves, agreement))
    if args.out:
        args.out.mkdir(parents=True, exist_ok=True)
        with open(args.out / "remesh_moves.csv", "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["kind", "element_length", "mean", "remesh_move", "quiet_move"])
            for m in moves:
                w.writerow([m["kind"], m["element_length"], m["mean"], max(m["remesh"]), max(m["quiet"])])
        with open(args.out / "master_agreement.csv", "w", newline="") as f:
            keys = list(agreement[0])
            w = csv.DictWriter(f, fieldnames=keys)
            w.writeheader()
            w.writerows(agreement)
    return 0


if __name__ == "__main__":
    sys.exit(main())
