"""Scenes: a run of the cable FMU described by a TOML file, and its result.

A scene file holds

    title = "..."
    duration = 660.0          # [s]
    step = 0.5                # communication step [s]
    outputs = ["shape.z[21]"] # optional: more FMU outputs to record

    [parameters]              # any FMU parameter by its name (defaults for the others)
    length = 300.0

    [inputs]                  # optional: other FMU inputs held constant (e.g. current.x)

    [tow]                     # the tow point (the vessel's stern)
    start = [0.0, 0.0, 0.0]   # [m]
    speed_kn = { times = [0.0, 60.0], values = [1.1, 2.4] }     # piecewise linear, held beyond
    heading_deg = { times = [0.0], values = [0.0] }             # from +x toward +y, piecewise linear
    surge = { amplitude = 5.0, period = 10.0, direction = [1.0, 0.0, 0.0] }  # optional oscillation

The tow point's velocity is the speed along the heading (plus the surge), its position the velocity
integrated over a grid 20 times finer than the step, and its acceleration is passed to the FMU as
the input derivative, as a master that knows the vessel's motion does.
"""

from __future__ import annotations

import math
import time
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .fmu import CableFMU, FMICallException
from .paths import find_scene, require_fmu
from .steady_tow import KNOT

RECORDED = ["towTension", "towTensionMax", "towTensionMin", "towForce.x", "towForce.y", "towForce.z",
            "endPosition.x", "endPosition.y", "endPosition.z", "minTension"]
SCENE_SETTINGS = ("duration", "step")


class SceneError(RuntimeError):
    """A scene the FMU refused or failed on; the message holds what the FMU logged."""


@dataclass
class Scene:
    name: str
    title: str
    duration: float
    step: float
    parameters: dict = field(default_factory=dict)
    inputs: dict = field(default_factory=dict)
    tow: dict = field(default_factory=dict)
    outputs: list = field(default_factory=list)

    def with_overrides(self, overrides: dict) -> "Scene":
        """A copy with `overrides` applied: scene settings (duration, step) or FMU parameters."""
        s = Scene(self.name, self.title, self.duration, self.step, dict(self.parameters), dict(self.inputs),
                  dict(self.tow), list(self.outputs))
        for key, value in overrides.items():
            if key in SCENE_SETTINGS:
                setattr(s, key, float(value))
            else:
                s.parameters[key] = value
        return s


def load_scene(source: str | Path | dict) -> Scene:
    """A scene from a file path, a packaged scene's name, or an already parsed dict."""
    if isinstance(source, dict):
        data, name = source, source.get("name", "scene")
    else:
        path = find_scene(source)
        data, name = tomllib.loads(path.read_text()), path.stem
    unknown = set(data) - {"name", "title", "duration", "step", "outputs", "parameters", "inputs", "tow"}
    if unknown:
        raise ValueError(f"scene {name}: unknown keys {sorted(unknown)}")
    for key in ("duration", "step"):
        if not (isinstance(data.get(key), (int, float)) and data[key] > 0):
            raise ValueError(f"scene {name}: '{key}' must be a positive number of seconds")
    return Scene(name=name, title=data.get("title", name), duration=float(data["duration"]),
                 step=float(data["step"]), parameters=dict(data.get("parameters", {})),
                 inputs=dict(data.get("inputs", {})), tow=dict(data.get("tow", {})),
                 outputs=list(data.get("outputs", [])))


def parse_value(text: str):
    """A --set value: true/false, an integer, a float, or the text itself."""
    low = text.strip().lower()
    if low in ("true", "false"):
        return low == "true"
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


class TowMotion:
    """The tow point's position, velocity and acceleration from a scene's [tow] table."""

    def __init__(self, tow: dict, duration: float, step: float):
        fine = step / 20.0
        self.t = np.arange(0.0, duration + 0.5 * fine, fine)
        if self.t[-1] < duration:
            self.t = np.append(self.t, duration)
        speed = tow.get("speed_kn", {"times": [0.0], "values": [0.0]})
        heading = tow.get("heading_deg", {"times": [0.0], "values": [0.0]})
        V = np.interp(self.t, speed["times"], speed["values"]) * KNOT
        psi = np.radians(np.interp(self.t, heading["times"], heading["values"]))
        v = np.stack([V * np.cos(psi), V * np.sin(psi), np.zeros_like(V)], axis=1)
        x = np.zeros_like(v)
        x[1:] = np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(self.t)[:, None], axis=0)
        x += np.asarray(tow.get("start", [0.0, 0.0, 0.0]), dtype=float)
        a = np.gradient(v, self.t, axis=0)
        surge = tow.get("surge")
        if surge:
            A, T = float(surge["amplitude"]), float(surge["period"])
            d = np.asarray(surge.get("direction", [1.0, 0.0, 0.0]), dtype=float)
            d = d / np.linalg.norm(d)
            w = 2.0 * math.pi / T
            x += A * np.sin(w * self.t)[:, None] * d
            v += A * w * np.cos(w * self.t)[:, None] * d
            a += -A * w * w * np.sin(w * self.t)[:, None] * d
        self.x, self.v, self.a = x, v, a

    def at(self, t: float):
        """At the grid point nearest t (communication points lie on the grid)."""
        k = int(np.searchsorted(self.t, t))
        if k == len(self.t) or (k > 0 and t - self.t[k - 1] < self.t[k] - t):
            k -= 1
        return self.x[k], self.v[k], self.a[k]


@dataclass
class SceneResult:
    scene: Scene
    time: np.ndarray
    columns: dict  # name -> array over time
    cpu: float

    def __getitem__(self, name: str) -> np.ndarray:
        return self.columns[name]

    def summary(self) -> dict:
        """The numbers a sweep tabulates: tension extremes over the run (from every internal
        integrator step), final tension and far-end depth."""
        return {"towTensionMax": float(np.max(self["towTensionMax"])),
                "towTensionMin": float(np.min(self["towTensionMin"])),
                "towTensionFinal": float(self["towTension"][-1]),
                "endDepthFinal": float(-self["endPosition.z"][-1])}

    def write_csv(self, path: Path) -> None:
        names = ["time"] + list(self.columns)
        data = np.column_stack([self.time] + [self.columns[n] for n in self.columns])
        np.savetxt(path, data, delimiter=",", header=",".join(names), comments="", fmt="%.10g")

    def plot(self, path: Path) -> None:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
        t = self.time
        ax[0].fill_between(t, self["towTensionMin"] / 1e3, self["towTensionMax"] / 1e3, color="tab:blue",
                           alpha=0.25, label="min-max within each step")
        ax[0].plot(t, self["towTension"] / 1e3, color="tab:blue", label="at communication points")
        ax[0].set_xlabel("t [s]")
        ax[0].set_ylabel("tow tension [kN]")
        ax[0].legend(fontsize=8)
        ax[1].plot(t, -self["endPosition.z"], color="tab:green")
        ax[1].set_xlabel("t [s]")
        ax[1].set_ylabel("far-end depth [m]")
        ax[1].invert_yaxis()
        ax[2].plot(self["tow.x"], self["tow.y"], label="tow point")
        ax[2].plot(self["endPosition.x"], self["endPosition.y"], label="far end")
        ax[2].set_xlabel("x [m]")
        ax[2].set_ylabel("y [m]")
        ax[2].axis("equal")
        ax[2].legend(fontsize=8)
        for a in ax:
            a.grid(alpha=0.3)
        fig.suptitle(self.scene.title)
        fig.tight_layout()
        fig.savefig(path, dpi=100)
        plt.close(fig)


def run_scene(scene: Scene | str | Path | dict, overrides: dict | None = None, fmu: str | Path | None = None,
              progress=None) -> SceneResult:
    """Runs a scene (a Scene, a file, a packaged scene's name or a parsed dict) with parameter or
    setting overrides; progress(t) is called after every step."""
    s = scene if isinstance(scene, Scene) else load_scene(scene)
    s = s.with_overrides(overrides or {})
    motion = TowMotion(s.tow, s.duration, s.step)
    n = int(math.ceil(s.duration / s.step - 1e-9))
    times = np.array([min(k * s.step, s.duration) for k in range(n + 1)])
    recorded = RECORDED + [o for o in s.outputs if o not in RECORDED]
    data = np.zeros((n + 1, len(recorded)))
    tow = np.zeros((n + 1, 3))
    cable = CableFMU(fmu or require_fmu(), parameters=s.parameters)
    try:
        def inputs(t):
            x, v, _ = motion.at(t)
            d = {"tow.x": x[0], "tow.y": x[1], "tow.z": x[2], "tow.vx": v[0], "tow.vy": v[1], "tow.vz": v[2]}
            d.update(s.inputs)
            return d

        cpu0 = time.process_time()
        cable.initialize(0.0, s.duration, inputs=inputs(0.0))
        data[0] = cable.get_reals(recorded)
        tow[0] = motion.at(0.0)[0]
        for k in range(n):
            t = times[k]
            cable.set(inputs(t))
            cable.set_input_derivatives(["tow.vx", "tow.vy", "tow.vz"], 1, list(motion.at(t)[2]))
            cable.do_step(times[k + 1] - t, t)
            data[k + 1] = cable.get_reals(recorded)
            tow[k + 1] = motion.at(times[k + 1])[0]
            if progress is not None:
                progress(times[k + 1])
        cpu = time.process_time() - cpu0
    except FMICallException as exc:  # say what the FMU said (the variable it refused, the failure)
        said = "; ".join(m for status, _, m in cable.messages if status in ("ERROR", "FATAL", "WARNING"))
        raise SceneError(f"scene {s.name}: {exc}" + (f": {said}" if said else "")) from exc
    finally:
        cable.free()
    columns = {name: data[:, i] for i, name in enumerate(recorded)}
    columns.update({"tow.x": tow[:, 0], "tow.y": tow[:, 1], "tow.z": tow[:, 2]})
    return SceneResult(s, times, columns, cpu)
