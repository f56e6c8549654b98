"""The heave-lowering scene: a 2 t body on 500 m of umbilical lowered at 0.25 m/s from a vessel in an
irregular sea, the VesselRAO FMU driving the cable FMU's top through fmpy (scripts/manoeuvre
heave-lowering).

Vessel: the generic 80 m vessel of the VesselRAO FMU (its shipped RAO table; rao_file: another's),
holding station at the origin, heading +x, in head seas (the waves travel along -x); the umbilical leaves
over the stern, 36 m aft of midships on the centreline at the waterline. Sea: JONSWAP Hs 3 m, Tp 9 s,
gamma 3.3, 200 components, ramped in over 20 s; the same waves.* parameters go to both FMUs, so the water
around the cable is the sea that moves the vessel. Umbilical and body: those of the scene file
lowering_in_waves (500 m, d 0.03 m, 2 kg/m, EA 3e7 N, EI 500 N m2, Cdn 1.2, Cdt 0.01; a 2 t body of
0.5 m3 with 1 t added mass and a drag area of 3 m2 on the lower end, bottomEnd 2), in 1000 m of water,
starting from rest straight below the top. The winch (winchMode 1) pays out at lower_rate from the
start, 75 m in 300 s, below its limit winch.maxLength = max_length (lower_rate 0: the body only
hangs). (That scene file prescribes a sinusoidal heave of the top instead.)

Master: at every communication point the vessel's tow-point position and velocity go to the cable's tow.*
inputs and its acceleration to der(tow.v*) (fmi2SetRealInputDerivatives); the vessel's motion is a closed
form of time, so the order of the two FMUs does not matter. A snap event is a communication step after
which minTension (the least axial force along the cable) is below zero, coming from a step where it was not.
"""

from __future__ import annotations

import math
import time as timer
from dataclasses import dataclass, field

import numpy as np

import tomllib

from . import heave
from ucable.fmu import CableFMU
from ucable.paths import find_scene
from ucable.system import partner_fmu

DEFAULT_T_END = 300.0


@dataclass
class HeaveLoweringCase:
    t_end: float = DEFAULT_T_END
    step: float = 0.2
    n_elements: int = 20
    hs: float = 3.0
    tp: float = 9.0
    gamma: float = 3.3
    seed: int = 1
    components: int = 200
    ramp: float = 20.0
    mode: int = 2  # 1: a regular wave of height hs and period tp
    direction: float = math.pi  # waves travelling along -x: head seas for the vessel heading +x
    tow_point: tuple = (-36.0, 0.0, 0.0)
    water_depth: float = 1000.0
    line_scene: str = "lowering_in_waves"  # the scene file whose umbilical and body hang here
    rao_file: str = ""  # the vessel's RAO table (VesselRAO's raoFile, docs/waves.md); "": the shipped one
    lower_rate: float = 0.25  # [m/s] winch pay-out from the start (the input winch.rate, held)
    max_length: float = 600.0  # [m] the winch's limit (winch.maxLength)
    extra: dict = field(default_factory=dict)  # further cable parameters

    def waves(self) -> dict:
        return {"waves.mode": self.mode, "waves.height": self.hs, "waves.period": self.tp,
                "waves.gamma": self.gamma, "waves.direction": self.direction, "waves.seed": self.seed,
                "waves.nComponents": self.components, "waves.rampTime": self.ramp,
                "waterDepth": self.water_depth}

    def vessel_parameters(self) -> dict:
        return {**self.waves(), "x0": 0.0, "y0": 0.0, "heading": 0.0, "towPoint.x": self.tow_point[0],
                "towPoint.y": self.tow_point[1], "towPoint.z": self.tow_point[2],
                **({"raoFile": self.rao_file} if self.rao_file else {})}

    def line(self) -> dict:
        """The umbilical and body parameters of the scene file (its sea left out: ours is set here)."""
        with open(find_scene(self.line_scene), "rb") as f:
            params = tomllib.load(f)["parameters"]
        return {k: v for k, v in params.items() if not k.startswith("waves.")}

    def winch(self) -> dict:
        """The winch's mode, limits and its rate (an input given its start value, as the system file)."""
        return {"winchMode": 1, "winch.maxLength": self.max_length, "winch.maxRate": 1.0,
                "winch.rate": self.lower_rate}

    def cable_parameters(self) -> dict:
        return {**self.line(), "nElements": self.n_elements, "waterDepth": self.water_depth, **self.waves(),
                **self.winch(), **self.extra}


VESSEL_OUT = ["tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz", "tow.ax", "tow.ay", "tow.az",
              "heave", "pitch", "waveElevation"]
CABLE_OUT = ["towTension", "minTension", "endTension", "endPosition.x", "endPosition.y", "endPosition.z",
             "endVelocity.z", "waveElevation", "unstretchedLength"]
COLUMNS = (["time"] + [f"vessel.{n}" for n in VESSEL_OUT] + [f"cable.{n}" for n in CABLE_OUT])


@dataclass
class Result:
    scene: HeaveLoweringCase
    time: np.ndarray
    values: dict  # column -> (n,) array
    cpu: float
    stats: dict

    def __getitem__(self, name):
        return self.values[name]

    def snap_events(self) -> list:
        """(start, end) times of the intervals with minTension < 0 (communication points)."""
        neg = self["cable.minTension"] < 0.0
        events, start = [], None
        for t, n in zip(self.time, neg):
            if n and start is None:
                start = t
            if not n and start is not None:
                events.append((start, t))
                start = None
        if start is not None:
            events.append((start, self.time[-1]))
        return events

    def body_heave(self) -> np.ndarray:
        """The body's vertical motion about its lowering: z + (paid-out length) - z(0)."""
        L = self["cable.unstretchedLength"]
        return self["cable.endPosition.z"] + (L - L[0]) - self["cable.endPosition.z"][0]

    def summary(self) -> dict:
        T = self["cable.towTension"]
        settled = self.time >= min(self.scene.ramp, self.time[-1])  # after the ramp (all of a short run)
        body_z = self.body_heave()[settled]
        tow_z = self["vessel.tow.z"][settled]
        L = self["cable.unstretchedLength"]
        return {"towTension_min": float(T.min()), "towTension_max": float(T.max()),
                "towTension_mean": float(T[settled].mean()), "towTension_std": float(T[settled].std()),
                "minTension_min": float(self["cable.minTension"].min()), "snap_events": len(self.snap_events()),
                "tow_heave_std": float(tow_z.std()), "body_heave_std": float(body_z.std()),
                "lowered": float(L[-1] - L[0]), "body_depth_final": float(-self["cable.endPosition.z"][-1]),
                "cpu": self.cpu}


def run(scene: HeaveLoweringCase, cable_fmu, progress=None) -> Result:
    n = int(round(scene.t_end / scene.step))
    times = np.arange(n + 1) * scene.step
    out = np.zeros((n + 1, len(COLUMNS)))
    vessel = CableFMU(partner_fmu("VesselRAO"), parameters=scene.vessel_parameters(), instance_name="vessel")
    cable = CableFMU(cable_fmu, parameters=scene.cable_parameters(), instance_name="cable")
    try:
        vessel.initialize(0.0, scene.t_end)
        v = vessel.get_reals(VESSEL_OUT)
        cable.initialize(0.0, scene.t_end, inputs=dict(zip(["tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz"],
                                                           v[:6])))
        tow_in = [cable.variables[q].valueReference for q in ("tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz")]
        cpu0 = timer.process_time()
        for k in range(n + 1):
            c = cable.get_reals(CABLE_OUT)
            out[k] = [times[k], *v, *c]
            if k == n:
                break
            cable.slave.setReal(tow_in, list(v[:6]))
            cable.set_input_derivatives(["tow.vx", "tow.vy", "tow.vz"], 1, v[6:9])
            cable.do_step(scene.step, t=times[k])
            vessel.do_step(scene.step, t=times[k])
            v = vessel.get_reals(VESSEL_OUT)
            if progress is not None:
                progress(times[k + 1])
        cpu = timer.process_time() - cpu0
        stats = dict(zip(heave.STATS, cable.get_reals(heave.STATS)))
    finally:
        cable.free()
        vessel.free()
    return Result(scene, times, {c: out[:, i] for i, c in enumerate(COLUMNS)}, cpu, stats)


def write_csv(path, r: Result) -> None:
    data = np.column_stack([r.values[c] for c in COLUMNS])
    np.savetxt(path, data, delimiter=",", header=",".join(COLUMNS), comments="", fmt="%.10g")


def plot(path, r: Result) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    sc, t = r.scene, r.time
    fig, ax = plt.subplots(3, 1, figsize=(12, 10), sharex=True)
    a = ax[0]
    a.plot(t, r["cable.towTension"] / 1e3, lw=0.9, label="top (tow) tension")
    a.plot(t, r["cable.endTension"] / 1e3, lw=0.9, label="tension at the body")
    a.set(ylabel="tension [kN]", title="tension")
    a.legend(fontsize=8, loc="upper right")
    a = ax[1]
    a.plot(t, r["cable.minTension"] / 1e3, lw=0.9, color="tab:purple", label="least axial force along the cable")
    a.axhline(0.0, color="k", lw=0.8)
    for i, (t0, t1) in enumerate(r.snap_events()):
        a.axvspan(t0, t1, color="r", alpha=0.3, label="snap (minTension < 0)" if i == 0 else None)
    a.set(ylabel="minTension [kN]", title=f"slack and snap events: {len(r.snap_events())}")
    a.legend(fontsize=8, loc="upper right")
    a = ax[2]
    a.plot(t, r["vessel.waveElevation"], lw=0.8, color="0.6", label="wave elevation at the vessel")
    a.plot(t, r["vessel.tow.z"], lw=0.9, label="top (stern) heave")
    z0, lowered = r["cable.endPosition.z"][0], r["cable.unstretchedLength"][-1] - r["cable.unstretchedLength"][0]
    a.plot(t, r.body_heave(), lw=0.9, label=f"body heave about its lowering ({-z0:.1f} m deep, lowered {lowered:.1f} m)")
    a.plot(t, r["cable.endPosition.x"] - r["cable.endPosition.x"][0], lw=0.9, ls="--",
           label="body surge (x)")
    a.set(xlabel="time [s]", ylabel="[m]", title="motion")
    a.legend(fontsize=8, loc="upper right")
    for a in ax:
        a.grid(True, alpha=0.3)
    mode = "JONSWAP Hs" if sc.mode == 2 else "regular H"
    line = sc.line()
    fig.suptitle(f"heave-lowering: {line['body.mass'] / 1e3:g} t body on {line['length']:g} m umbilical, {mode} {sc.hs:g} m, "
                 f"T{'p' if sc.mode == 2 else ''} {sc.tp:g} s, head seas, {sc.n_elements} elements, "
                 f"step {sc.step:g} s")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
