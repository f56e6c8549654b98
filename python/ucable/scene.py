"""Scenes: a run of the cable FMU described by a TOML file, and its result.

A scene file holds (docs/scenes.md lists every key with its type, unit and default)

    title = "..."
    duration = 660.0          # [s]
    step = 0.5                # communication step [s]
    outputs = ["waveElevation"]   # optional: more FMU variables to record
    record_shape = true       # the default: every station's position, columns shape.x[k] ...

    [parameters]              # any FMU parameter by its name (defaults for the others)
    length = 300.0

    [inputs]                  # optional: other FMU inputs, each a constant or a piecewise-linear table
    "current.x" = { times = [0.0, 60.0], values = [0.0, 0.5] }

    [tow]                     # the tow point (a vessel's stern, a fairlead, an A-frame)
    start = [0.0, 0.0, 0.0]   # [m]
    speed_kn = { times = [0.0, 60.0], values = [1.1, 2.4] }     # a constant or piecewise linear, held beyond
    heading_deg = 0.0                                           # from +x toward +y
    surge = { amplitude = 5.0, period = 10.0, direction = [1.0, 0.0, 0.0] }  # optional oscillation
    heave = { amplitude = 1.5, period = 10.0 }                  # optional vertical oscillation

    [body]                    # optional: body 1 of a mooring system (parameter lineFile, a deck of several
    start = [0, 0, 0, 0, 0, 0]   # lines; docs/systems_mooring.md): start pose x y z [m], roll pitch yaw [deg],
    surge = { amplitude = 5.0, period = 20.0 }   # and oscillations about it from rest (sway, heave in m,
    pitch = { amplitude = 3.0, period = 25.0 }   # roll, pitch, yaw in deg) as the tow's; with the parameter
                              # bodyOrientation = 1 the angles go to the FMU as their quaternion (R = Rx Ry Rz)
    [body.free]               # optional: body 1 free in surge, sway and yaw (ucable.free_body): mass and yaw
    mass = 2.5e7              # inertia with added mass [kg, kg m2], damping [N s/m, N s/m, N m s] and a steady
    inertia = 2.3e10          # load [N, N, N m]; the runner integrates them from the lines' load
    damping = [1e6, 1e6, 3e9]
    load = [7.5e5, 1.3e6, 0.0]

    [failure]                 # optional: a line of a mooring system breaks (docs/line_failure.md): the deck
    line = 1                  # line (ID), the deck point it detaches from (point = 0 or left out: its
    time = 120.0              # fairlead; or position = metres along it from its anchor, where it parts), at
                              # a time [s] and/or a tension [N]; sets failure.line/point/time/tension/position,
                              # and records line[k].broken and line[k].breakTime

    [winch]                   # optional: the winch's command in stages (sets winchMode 1 or 2)
    ramp = 10.0               # [s] from one stage's value to the next; a rate starts from rest
    stages = [ { rate = 0.5, duration = 600.0 }, { rate = 0.0, duration = 300.0 } ]

A relative `lineFile` is looked up next to the scene file first (the packaged scenes carry their decks).
With [body] the recorded columns add body 1's load (`body[1].force.*`, `body[1].moment.*`) and each line's
`line[k].fairleadTension` and `line[k].anchorTension`.

The tow point's velocity is the speed along the heading (plus the oscillations, which start from
rest: their amplitude grows over `ramp` seconds, one period unless given, with a half cosine), its
position the velocity integrated over a grid 20 times finer than the step, and its acceleration is
passed to the FMU as the input derivative, as a master that knows the vessel's motion does. The
other inputs take their value at the start of each communication step; the winch's rate goes with
its derivative, the slope of its table over the step, so that a ramp reaches the drum as a ramp
(exact on a piecewise-linear table whose corners are communication points).
"""

from __future__ import annotations

import copy
import math
import re
import time
import tomllib
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .fmu import NUM_STATIONS, CableFMU, FMICallException
from .free_body import LOAD_NAMES as FREE_LOADS
from .free_body import FreeBody
from .fmu import load as load_fmu
from .orientation import ANGLES_XYZ, QUATERNION, quaternion_from_angles
from .variables import MAX_LINES, VARIABLES
from .paths import find_scene, require_fmu
from .scene_schema import Checker, SceneFileError, validate
from .units import KNOT

RECORDED = ["towTension", "towTensionMax", "towTensionMin", "towForce.x", "towForce.y", "towForce.z",
            "endPosition.x", "endPosition.y", "endPosition.z", "minTension", "layback", "topDeclination"]
ANCHORED_RECORDED = ["endTension", "groundedLength", "anchorUplift"]
WINCH_RECORDED = ["unstretchedLength"]
SHAPE = [f"shape.{c}[{k}]" for c in "xyz" for k in range(1, NUM_STATIONS + 1)]
STATIONS = [f"{q}[{k}]" for q in ("tension", "curvature") for k in range(1, NUM_STATIONS + 1)]  # with the shape
BODY_RATES = [f"body[1].{n}" for n in ("vx", "vy", "vz", "wx", "wy", "wz")]
BODY_RECORDED = [f"body[1].{q}.{c}" for q in ("force", "moment") for c in "xyz"]
STRENGTH = ("MBL", "fairleadUtilisation", "anchorUtilisation", "maxUtilisation")  # docs/design_checks.md
BROKEN = tuple(q for q in ("broken", "breakTime") if f"line[1].{q}" in VARIABLES)  # line failure, where the FMU has it
LINES_RECORDED = [f"line[{k}].{q}" for k in range(1, MAX_LINES + 1)
                  for q in ("fairleadTension", "anchorTension", "groundedLength") + STRENGTH + BROKEN]
LINE_STRENGTH_RECORDED = [f"line[1].{q}" for q in STRENGTH]  # a single line's (kept when it has an MBL)
FAILURE_RECORDED = [f"line[{k}].{q}" for k in range(1, MAX_LINES + 1) for q in ("broken", "breakTime")]
BODY_POSE = [f"body[1].{n}" for n in ("x", "y", "z", "roll", "pitch", "yaw")]  # the scene's motion of body 1
SCENE_SETTINGS = ("duration", "step")
TOW_SETTINGS = {"speed_kn": "speed_kn", "heading": "heading_deg", "heading_deg": "heading_deg"}  # NAME -> [tow] key
BOTTOM_ANCHORED = 1


class SceneError(RuntimeError):
    """A scene the FMU failed on while running; the message holds what the FMU logged. `partial` is the
    result up to the last communication point reached (None when the FMU failed at its start), `stopped`
    the time of the step that failed."""

    def __init__(self, message: str, partial: "SceneResult | None" = None, stopped: float | None = None):
        super().__init__(message)
        self.partial = partial
        self.stopped = stopped


CASES = ("intact", "damaged", "transient")  # a scene with a line failure by time, as `--vary case=...` runs it


def failure_case(data: dict, case, where: str, check: Checker) -> dict:
    """The scene data of one design case of a scene whose [failure] breaks a line at a time: intact (no
    failure), damaged (the line breaks within the first communication step, so the run is the damaged system
    from the start) or transient (the scene as written)."""
    if case not in CASES:
        check.fail(where, f"expected one of {', '.join(CASES)}, got {case!r}")
    failure = data.get("failure") or {}
    if not failure.get("time"):
        check.fail(where, "a case needs a [failure] table that breaks its line at a time (time > 0)")
    if case == "intact":
        data.pop("failure", None)
    elif case == "damaged":
        data["failure"] = {**failure, "time": min(float(data["step"]), float(failure["time"]))}
        data["failure"].pop("tension", None)
    return data


def case_statistics_from(scene: "Scene", case) -> float:
    """The time from which a case's statistics are taken (`ucable sweep --vary case=...`): the scene's break
    time for the damaged and transient cases (the lead-in before it is the intact system's), 0 for the intact."""
    if case in ("damaged", "transient"):
        return float(scene.parameters.get("failure.time", 0.0))
    return 0.0


@dataclass
class Scene:
    """A checked scene: `data` as written (a TOML file's tables), the checked values in the fields."""
    name: str
    title: str
    duration: float
    step: float
    parameters: dict = field(default_factory=dict)
    inputs: dict = field(default_factory=dict)
    tow: dict = field(default_factory=dict)
    outputs: list = field(default_factory=list)
    record_shape: bool = True
    winch: dict = field(default_factory=dict)  # {"input", "mode", "table"} from [winch] stages, or {}
    body: dict = field(default_factory=dict)   # checked [body], or {}
    data: dict = field(default_factory=dict, repr=False)
    source: str = "scene"
    directory: Path | None = None  # of the scene file (a relative lineFile is looked up there first)

    @classmethod
    def from_data(cls, data: dict, source: str, directory: Path | None = None) -> "Scene":
        c = validate(data, source)
        return cls(name=c["name"], title=c["title"], duration=c["duration"], step=c["step"],
                   parameters=c["parameters"], inputs=c["inputs"], tow=c["tow"], outputs=c["outputs"],
                   record_shape=c["record_shape"], winch=c["winch"], body=c["body"], data=data, source=source,
                   directory=directory)

    def with_overrides(self, overrides: dict, source: str = "--set") -> "Scene":
        """A copy with `overrides` applied: scene settings (duration, step, record_shape), the tow's
        constant speed_kn or heading [deg] (replacing the [tow] table's), or FMU parameters; each is
        checked (a SceneFileError names `source` and the key)."""
        check = Checker(None)
        data = copy.deepcopy(self.data)
        for key, value in overrides.items():
            where = f"{source} {key}"
            if key in SCENE_SETTINGS:
                data[key] = check.number(value, where, positive=True)
            elif key in TOW_SETTINGS:
                speed = key == "speed_kn"
                data.setdefault("tow", {})[TOW_SETTINGS[key]] = check.number(value, where, nonnegative=speed)
            elif key == "case":
                data = failure_case(data, value, where, check)
            elif key == "record_shape":
                if not isinstance(value, bool):
                    check.fail(where, "expected true or false")
                data[key] = value
            else:
                data.setdefault("parameters", {})[key] = check.parameter(key, value, where)
        return Scene.from_data(data, self.source, self.directory)

    @property
    def kind(self) -> str:
        """'winch' (the length changes), 'anchored' (bottomEnd 1) or 'tow' (everything else)."""
        if self.winch or self.parameters.get("winchMode", 0) != 0:
            return "winch"
        if self.parameters.get("bottomEnd", 0) == BOTTOM_ANCHORED:
            return "anchored"
        return "tow"


def read_toml(path: Path) -> dict:
    """A TOML file's tables; a syntax error is a SceneFileError naming the file and the line."""
    try:
        return tomllib.loads(path.read_text())
    except tomllib.TOMLDecodeError as exc:
        raise SceneFileError(f"{path}: not valid TOML: {exc}") from None
    except UnicodeDecodeError as exc:
        raise SceneFileError(f"{path}: not a text file: {exc}") from None


def load_scene(source: str | Path | dict) -> Scene:
    """A scene from a file path, a packaged scene's name, or an already parsed dict."""
    if isinstance(source, dict):
        return Scene.from_data(source, source.get("name", "scene"))
    try:
        path = find_scene(source)
    except FileNotFoundError as exc:
        raise SceneFileError(str(exc)) from None
    data = dict(read_toml(path))
    data.setdefault("name", path.stem)
    return Scene.from_data(data, str(source), path.parent)


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


def signal_at(signal, t):
    """A checked signal (a constant or { times, values }) at time(s) t: piecewise linear, held beyond."""
    if isinstance(signal, dict):
        return np.interp(t, signal["times"], signal["values"])
    return np.full_like(np.asarray(t, dtype=float), float(signal)) if np.ndim(t) else float(signal)


def signal_slope(signal, t0: float, t1: float) -> float:
    """The mean slope of a checked signal over [t0, t1]: its derivative there when the table is linear
    over the interval, and in any case the slope that brings it to its value at t1."""
    if not isinstance(signal, dict):
        return 0.0
    return float((np.interp(t1, signal["times"], signal["values"]) -
                  np.interp(t0, signal["times"], signal["values"])) / (t1 - t0))


def winch_events(cable: CableFMU) -> list:
    """The winch's events the FMU logged (a length limit reached, the drum braking to it, the rate cut by
    winch.maxRate), one line each with the time and the value: 'winch: at t = ...'."""
    out = []
    for _, _, message in cable.messages:
        k = message.find("winch: at t = ")
        for part in message[k:].split("; winch: ") if k >= 0 else []:
            line = part if part.startswith("winch: ") else "winch: " + part
            if line not in out:
                out.append(line)
    return out


def soft_start(t: np.ndarray, ramp: float):
    """The envelope e(t) = (1 - cos(pi t / ramp)) / 2 up to `ramp`, 1 after, and its two derivatives:
    an oscillation multiplied by it starts from rest (zero position, velocity and acceleration)."""
    if ramp <= 0.0:
        one = np.ones_like(t)
        return one, 0.0 * one, 0.0 * one
    w = math.pi / ramp
    inside = t < ramp
    e = np.where(inside, 0.5 * (1.0 - np.cos(w * t)), 1.0)
    de = np.where(inside, 0.5 * w * np.sin(w * t), 0.0)
    dde = np.where(inside, 0.5 * w * w * np.cos(w * t), 0.0)
    return e, de, dde


class BodyMotion:
    """Body 1's pose, rates and their derivatives from a scene's checked [body] table: each degree of
    freedom its start plus A e(t) sin(w t) (e the soft start); the angular velocity is the angles'
    rates and the angular acceleration their second derivatives (exact for a rotation about one axis,
    to first order in the angles otherwise). The accelerations go to the FMU as input derivatives."""

    def __init__(self, body: dict):
        self.body = body

    def at(self, t: float):
        q = np.array(self.body["start"], dtype=float)
        q[3:] = np.radians(q[3:])
        v, a = np.zeros(6), np.zeros(6)
        for i, dof in enumerate(("surge", "sway", "heave", "roll", "pitch", "yaw")):
            m = self.body.get(dof)
            if not m:
                continue
            A = m["amplitude"] if i < 3 else math.radians(m["amplitude"])
            w = 2.0 * math.pi / m["period"]
            e, de, dde = (float(x[0]) for x in soft_start(np.array([t]), m["ramp"]))
            s, c = math.sin(w * t), math.cos(w * t)
            q[i] += A * e * s
            v[i] += A * (de * s + e * w * c)
            a[i] += A * (dde * s + 2.0 * de * w * c - e * w * w * s)
        return q, v, a

    def inputs(self, t: float, orientation: int = ANGLES_XYZ, free: FreeBody | None = None) -> dict:
        """Body 1's inputs at t; with orientation (bodyOrientation) QUATERNION the angles are passed as the
        quaternion of R = Rx Ry Rz of them, the orientation the FMU's angles give by default. With `free` its
        surge, sway and yaw are the free body's."""
        q, v, _ = self.at(t)
        if free:
            q, v = free.pose(q), free.rates(v)
        names = ("x", "y", "z", "roll", "pitch", "yaw", "vx", "vy", "vz", "wx", "wy", "wz")
        d = {f"body[1].{n}": float(x) for n, x in zip(names, [*q, *v])}
        if orientation == QUATERNION:
            for n in ("roll", "pitch", "yaw"):
                del d[f"body[1].{n}"]
            d.update({f"body[1].q{i}": x for i, x in enumerate(quaternion_from_angles(*q[3:]))})
        return d


class TowMotion:
    """The tow point's position, velocity and acceleration from a scene's checked [tow] table."""

    def __init__(self, tow: dict, duration: float, step: float):
        fine = step / 20.0
        self.t = np.arange(0.0, duration + 0.5 * fine, fine)
        if self.t[-1] < duration:
            self.t = np.append(self.t, duration)
        t = self.t
        V = signal_at(tow.get("speed_kn", 0.0), t) * KNOT
        psi = np.radians(signal_at(tow.get("heading_deg", 0.0), t))
        v = np.stack([V * np.cos(psi), V * np.sin(psi), np.zeros_like(V)], axis=1)
        x = np.zeros_like(v)
        x[1:] = np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t)[:, None], axis=0)
        x += np.asarray(tow.get("start", [0.0, 0.0, 0.0]), dtype=float)
        a = np.gradient(v, t, axis=0)
        for key in ("surge", "heave"):
            m = tow.get(key)
            if not m:
                continue
            A, w = m["amplitude"], 2.0 * math.pi / m["period"]
            d = np.asarray(m.get("direction", [0.0, 0.0, 1.0]), dtype=float)
            d = d / np.linalg.norm(d)
            e, de, dde = soft_start(t, m.get("ramp", m["period"]))
            s, c = np.sin(w * t), np.cos(w * t)
            x += (A * e * s)[:, None] * d
            v += (A * (de * s + e * w * c))[:, None] * d
            a += (A * (dde * s + 2.0 * de * w * c - e * w * w * s))[:, None] * d
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
    seabed: float | None = None  # the seabed's depth when the FMU has one (enableSeabed; a deck's WtrDpth)
    events: list = field(default_factory=list)  # the winch's events (winch_events)

    def __getitem__(self, name: str) -> np.ndarray:
        return self.columns[name]

    def summary(self) -> dict:
        """The numbers a sweep tabulates: tension extremes over the run (from every internal
        integrator step), final tension and far-end depth; anchored, the anchor tension's maximum."""
        s = {"towTensionMax": float(np.max(self["towTensionMax"])),
             "towTensionMin": float(np.min(self["towTensionMin"])),
             "towTensionFinal": float(self["towTension"][-1]),
             "endDepthFinal": float(-self["endPosition.z"][-1])}
        if "endTension" in self.columns:
            s["anchorTensionMax"] = float(np.max(self["endTension"]))
        if "unstretchedLength" in self.columns:
            s["lengthFinal"] = float(self["unstretchedLength"][-1])
        return s

    def write_csv(self, path: Path) -> None:
        """result.csv: time and every column, named with its unit (angles in degrees: ucable.results)."""
        from .results import labelled
        from .tables import write_columns

        write_columns(path, labelled({"time": self.time, **self.columns}))

    def table(self) -> list:
        """The results table (ucable.summary): extremes with their times, per line, body and tow."""
        from .summary import scene_summary

        return scene_summary(self)

    def write_summary(self, path: Path) -> None:
        """summary.csv: the results table."""
        from .summary import summary_columns
        from .tables import write_columns

        write_columns(path, summary_columns(self.table()))

    def shapes(self) -> np.ndarray | None:
        """The recorded stations, shape [time, station, xyz], or None without record_shape."""
        if SHAPE[0] not in self.columns:
            return None
        n = NUM_STATIONS
        return np.stack([np.stack([self[f"shape.{c}[{k}]"] for k in range(1, n + 1)], axis=1) for c in "xyz"],
                        axis=2)

    def plot(self, path: Path) -> None:
        from .scene_plots import plot_result

        plot_result(self, path)

    def animate(self, path: Path, frames: int = 120, progress: bool = False) -> None:
        from .scene_plots import animate_result

        animate_result(self, path, frames, progress)


def _fmu_message(cable: CableFMU) -> str:
    """What the FMU logged as an error, without the FMI function names it prefixes."""
    said = []
    for status, _, message in cable.messages:
        if status not in ("ERROR", "FATAL"):
            continue
        text = message.split(": ", 1)[1] if message.startswith("fmi2") and ": " in message else message
        if text not in said:
            said.append(text)
    return "; ".join(said)


class SceneWarning(UserWarning):
    """Something in a scene that runs but may not be what was meant (the CLI prints it on one line)."""


_VESSEL_POINT = re.compile(r"(?:not the file's vessel point|hold them at its X Y Z =) \(([^,()]+), ([^,()]+), ([^,()]+)\)")


def deck_path(deck: str, directory: Path | None, where: str = "[parameters] lineFile",
              resources: Path | None = None) -> str:
    """The file a scene's lineFile names: an absolute path, else next to the scene file, else in the
    current directory, else (the name kept, the FMU finds it) in the FMU's resources; a SceneFileError
    saying where it looked when it is in none of them."""
    path = Path(deck).expanduser()
    if path.is_absolute():
        if path.is_file():
            return str(path)
        raise SceneFileError(f"{where} = {deck!r}: no such file")
    for base in ([directory] if directory is not None else []) + [Path.cwd()]:
        if (base / path).is_file():
            return str((base / path).resolve())
    if resources is not None and (resources / path).is_file():
        return deck
    near = f"next to the scene ({directory}) or " if directory is not None and directory != Path.cwd() else ""
    raise SceneFileError(f"{where} = {deck!r}: no such file {near}in the current directory ({Path.cwd()}); "
                         f"a shipped scene's decks come with it: ucable scenes copy NAME DIR")


def deck_vessel_point(fmu, parameters: dict) -> list | None:
    """The tow point of a one-line deck (its Vessel or Coupled point, or the Fixed point the line starts
    from), as the FMU reads it: a probe instance with the tow point at the origin logs the point when it
    lies elsewhere. None for a mooring system or a deck whose point is the origin."""
    probe = CableFMU(fmu, parameters=parameters, logging_on=True)
    try:
        try:
            probe.initialize(0.0)
        except FMICallException:
            pass  # the start from the origin may fail; the point is logged before
        for _, _, message in probe.messages:
            m = _VESSEL_POINT.search(message)
            if m:
                return [float(x) for x in m.groups()]
        return None
    finally:
        probe.free()


def tow_start(s: "Scene", fmu, parameters: dict) -> dict:
    """The [tow] table to run with: a one-line deck's tow point where the scene gives no [tow] start
    (the start the deck says); a SceneWarning when the scene's start differs from the deck's point."""
    tow = dict(s.tow)
    if not parameters.get("lineFile") or s.body:
        return tow
    point = deck_vessel_point(fmu, parameters)
    if point is None:
        return tow
    given = "start" in s.data.get("tow", {})
    if not given:
        tow["start"] = point
    elif any(abs(a - b) > 1e-9 * max(1.0, abs(b)) for a, b in zip(tow["start"], point)):
        def show(v):
            return "(" + ", ".join(f"{x:g}" for x in v) + ")"

        warnings.warn(SceneWarning(
            f"{s.source}: [tow] start = {show(tow['start'])} m is not the deck's tow point {show(point)} m "
            f"(lineFile {parameters['lineFile']!r}): the line starts from [tow] start; leave [tow] start out "
            f"to start at the deck's point"), stacklevel=3)
    return tow


def run_scene(scene: Scene | str | Path | dict, overrides: dict | None = None, fmu: str | Path | None = None,
              progress=None) -> SceneResult:
    """Runs a scene (a Scene, a file, a packaged scene's name or a parsed dict) with parameter or
    setting overrides; progress(t) is called after every step. A mistake in the scene or an
    override is a SceneFileError (before anything runs, or when the FMU refuses a parameter); a
    failure of the FMU during the run is a SceneError."""
    s = scene if isinstance(scene, Scene) else load_scene(scene)
    if overrides:
        s = s.with_overrides(overrides)
    n = int(math.ceil(s.duration / s.step - 1e-9))
    times = np.array([min(k * s.step, s.duration) for k in range(n + 1)])
    extra = {"anchored": ANCHORED_RECORDED, "winch": WINCH_RECORDED}.get(s.kind, [])
    body = BodyMotion(s.body) if s.body else None
    free = FreeBody.from_table(s.body["free"], s.body["start"]) if s.body.get("free") else None
    if body:
        extra = extra + BODY_RECORDED + LINES_RECORDED
    else:
        extra = extra + LINE_STRENGTH_RECORDED
    if s.parameters.get("failure.line"):
        extra = extra + FAILURE_RECORDED
    recorded = list(dict.fromkeys(RECORDED + extra + s.outputs + (SHAPE + STATIONS if s.record_shape else [])))
    data = np.zeros((n + 1, len(recorded)))
    tow = np.zeros((n + 1, 3))
    pose = np.zeros((n + 1, 6))
    parameters = dict(s.parameters)
    fmu = fmu or require_fmu()
    if parameters.get("lineFile"):
        parameters["lineFile"] = deck_path(parameters["lineFile"], s.directory, f"{s.source}: [parameters] lineFile",
                                           Path(load_fmu(fmu)[0]) / "resources")
    signals = dict(s.inputs)
    if s.winch:
        parameters.setdefault("winchMode", s.winch["mode"])
        signals[s.winch["input"]] = s.winch["table"]
    motion = TowMotion(tow_start(s, fmu, parameters), s.duration, s.step)
    cable = CableFMU(fmu, parameters=parameters)
    cable.slave.setDebugLogging(True, ["logEvents"])  # the winch's limits (winch_events)
    rate_signal = signals.get("winch.rate") if isinstance(signals.get("winch.rate"), dict) else None
    t = 0.0
    done = -1  # the last communication point reached
    cpu0 = time.process_time()
    try:
        def inputs(t):
            x, v, _ = motion.at(t)
            d = {"tow.x": x[0], "tow.y": x[1], "tow.z": x[2], "tow.vx": v[0], "tow.vy": v[1], "tow.vz": v[2]}
            d.update({name: float(signal_at(sig, t)) for name, sig in signals.items()})
            if body:
                d.update(body.inputs(t, int(parameters.get("bodyOrientation", ANGLES_XYZ)), free))
            return d

        def body_pose(t):
            q = body.at(t)[0]
            return free.pose(q) if free else q

        cpu0 = time.process_time()
        try:
            cable.initialize(0.0, s.duration, inputs=inputs(0.0))
        except FMICallException as exc:  # a refusal at the start is the scene's mistake, not a failure of the run
            said = _fmu_message(cable) or str(exc)
            if "invalid parameter" in said:
                raise SceneFileError(f"{s.source}: {said}") from exc
            raise SceneFileError(f"{s.source}: the FMU could not start: {said}") from exc
        seabed = seabed_depth(cable, parameters)
        read_row = recorded_reader(cable, recorded)
        data[0] = read_row()
        tow[0] = motion.at(0.0)[0]
        if free:
            free.lines = np.array(cable.get_reals(list(FREE_LOADS)))
        pose[0] = body_pose(0.0) if body else 0.0
        done = 0
        for k in range(n):
            t = times[k]
            cable.set(inputs(t))
            cable.set_input_derivatives(["tow.vx", "tow.vy", "tow.vz"], 1, list(motion.at(t)[2]))
            if rate_signal is not None:
                cable.set_input_derivatives(["winch.rate"], 1, [signal_slope(rate_signal, t, times[k + 1])])
            if body:
                a = body.at(t)[2]
                cable.set_input_derivatives(BODY_RATES, 1, [float(x) for x in (free.accelerations(a) if free else a)])
            cable.do_step(times[k + 1] - t, t)
            data[k + 1] = read_row()
            if free:
                free.advance(times[k + 1] - t, np.array(cable.get_reals(list(FREE_LOADS))))
            tow[k + 1] = motion.at(times[k + 1])[0]
            pose[k + 1] = body_pose(times[k + 1]) if body else 0.0
            done = k + 1
            if progress is not None:
                progress(times[k + 1])
        cpu = time.process_time() - cpu0
    except FMICallException as exc:  # say what the FMU said (the variable it refused, the failure)
        rows = slice(0, done + 1)  # the communication points reached: a failed run keeps them
        partial = None if done < 0 else SceneResult(
            s, times[rows], _columns(recorded, data[rows], tow[rows], pose[rows] if body else None, s.outputs),
            time.process_time() - cpu0, seabed)
        raise SceneError(f"{s.source}: the FMU failed at t = {t:g} s: {_fmu_message(cable) or exc}",
                         partial, float(t)) from exc
    finally:
        events = winch_events(cable)
        cable.free()
    return SceneResult(s, times, _columns(recorded, data, tow, pose if body else None, s.outputs), cpu, seabed, events)


def recorded_reader(cable: CableFMU, recorded: list):
    """A function that reads the recorded variables at a communication point: the Reals in one fmi2GetReal,
    a Boolean or Integer (a line's `broken` flag) as 0/1 or its value."""
    others = [i for i, name in enumerate(recorded) if name in VARIABLES and VARIABLES[name].type != "Real"]
    if not others:
        return lambda: cable.get_reals(recorded)
    reals = [i for i in range(len(recorded)) if i not in set(others)]
    real_names = [recorded[i] for i in reals]

    def read() -> np.ndarray:
        row = np.zeros(len(recorded))
        row[reals] = cable.get_reals(real_names)
        for i in others:
            row[i] = float(cable.get(recorded[i]))
        return row

    return read


def deck_water_depth(path) -> float | None:
    """A MoorDyn deck's water depth as MoorDyn takes it: its OPTIONS row `VALUE WtrDpth`, else the depth
    of its deepest point (the POINTS, CONNECTIONS or NODES table's Z); None when neither is found."""
    try:
        text = Path(path).read_text(errors="replace")
    except OSError:
        return None
    section, deepest = "", None
    for row in text.splitlines():
        tokens = row.split()
        if row.lstrip().startswith("---"):
            section = row.upper()
            continue
        if len(tokens) >= 2 and tokens[1].lower() == "wtrdpth":
            try:
                return float(tokens[0])
            except ValueError:
                return None
        if any(k in section for k in ("POINT", "CONNECTION", "NODE")) and len(tokens) >= 5 and tokens[0].isdigit():
            try:
                z = float(tokens[4])
            except ValueError:
                continue
            deepest = -z if deepest is None else max(deepest, -z)
    return deepest


def seabed_depth(cable: CableFMU, parameters: dict) -> float | None:
    """The depth of the seabed the run has, for the plots: a deck's WtrDpth (MoorDyn always has its seabed
    there) unless the scene sets waterDepth, else the FMU's waterDepth when enableSeabed is on; None
    without a seabed."""
    deck = deck_water_depth(parameters["lineFile"]) if parameters.get("lineFile") else None
    if deck is not None and "waterDepth" not in parameters:
        return deck
    return float(cable.get("waterDepth")) if cable.get("enableSeabed") else None


def _columns(recorded: list, data: np.ndarray, tow: np.ndarray, pose: np.ndarray | None,
             requested: list) -> dict:
    """The result's columns: the recorded outputs (of the line[k].* a mooring scene adds, the deck's lines
    only, those whose fairlead tension is not zero throughout; every `requested` one), the tow point,
    body 1's pose when the scene moves it."""
    lines = {name.split(".")[0] for i, name in enumerate(recorded)
             if name.endswith(".fairleadTension") and name in LINES_RECORDED and np.any(data[:, i] != 0.0)}
    if "line[1].MBL" in recorded and "line[1].fairleadTension" not in recorded:  # a single line
        lines.add("line[1]")
    # the breaking strength's columns of lines with an MBL only
    weak = {name.split(".")[0] for i, name in enumerate(recorded) if name.endswith(".MBL") and not np.any(data[:, i] > 0.0)}
    columns = {name: data[:, i] for i, name in enumerate(recorded)
               if name in requested or ((name not in LINES_RECORDED and name not in LINE_STRENGTH_RECORDED)
                                        or (name.split(".")[0] in lines
                                            and not (name.split(".", 1)[1] in STRENGTH and name.split(".")[0] in weak)))}
    columns.update({"tow.x": tow[:, 0], "tow.y": tow[:, 1], "tow.z": tow[:, 2]})
    if pose is not None:
        columns.update({name: pose[:, i] for i, name in enumerate(BODY_POSE)})
    return columns
