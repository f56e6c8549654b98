"""The scene format, checked before anything runs: every key, its type and its range.

A mistake is a SceneFileError whose message is one line naming the file and the key, with a "did
you mean" when the key is close to a known one, e.g.

    my.toml: [tow] speed: unknown key; did you mean 'speed_kn'?
    my.toml: [parameters] nElements: expected an integer, got 2.5

`validate(data, source)` returns the scene as plain data with every value in its checked form
(tables { times, values } as lists of floats, integers as int). The keys, their meaning, units and
defaults are listed in docs/scenes.md.
"""

from __future__ import annotations

import difflib
import math

from .variables import VARIABLES

TOP_KEYS = ("title", "duration", "step", "outputs", "record_shape", "parameters", "inputs", "tow", "winch", "body",
            "failure", "name")
# [failure]: a line failure of a mooring system (docs/line_failure.md), mapped onto the failure.* parameters
FAILURE_KEYS = ("line", "point", "time", "tension", "position")
TOW_KEYS = ("start", "speed_kn", "heading_deg", "surge", "heave")
SURGE_KEYS = ("amplitude", "period", "direction", "ramp")
HEAVE_KEYS = ("amplitude", "period", "ramp")
TABLE_KEYS = ("times", "values")
WINCH_KEYS = ("ramp", "stages")
STAGE_KEYS = ("duration", "rate", "tension", "ramp")
DEFAULT_WINCH_RAMP = 10.0  # [s] from one stage's value to the next
# set by the scene itself, not by [inputs]
TOW_INPUTS = ("tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz")
WINCH_INPUTS = {"rate": "winch.rate", "tension": "winch.tension"}
WINCH_MODES = {"rate": 1, "tension": 2}
# [body]: body 1 of a mooring system (docs/systems_mooring.md); degrees of freedom in the order of its inputs
BODY_DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")
BODY_KEYS = ("start",) + BODY_DOFS + ("free",)
# [body.free]: body 1 free in surge, sway and yaw, integrated by the runner (ucable.free_body)
FREE_KEYS = ("mass", "inertia", "damping", "load")
FREE_BODY_DOFS = ("surge", "sway", "yaw")
OSCILLATION_KEYS = ("amplitude", "period", "ramp")
BODY_INPUT_NAMES = tuple(f"body[1].{n}" for n in ("x", "y", "z", "roll", "pitch", "yaw", "vx", "vy", "vz",
                                                   "wx", "wy", "wz", "q0", "q1", "q2", "q3"))


class SceneFileError(ValueError):
    """A mistake in a scene (file, --set or --vary): the message names where and which key."""


def _kind(value) -> str:
    if isinstance(value, bool):
        return "a boolean"
    if isinstance(value, int):
        return "an integer"
    if isinstance(value, float):
        return "a number"
    if isinstance(value, str):
        return "a string"
    if isinstance(value, dict):
        return "a table"
    if isinstance(value, list):
        return "a list"
    return type(value).__name__


def _show(value) -> str:
    if isinstance(value, str):
        return repr(value)
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return f"{value:g}" if isinstance(value, float) else str(value)
    return _kind(value)


def suggestion(name: str, known) -> str:
    """'; did you mean 'x'?' for the closest known name, or ''."""
    close = difflib.get_close_matches(name, list(known), n=1, cutoff=0.6)
    if not close:
        lower = {k.lower(): k for k in known}
        if name.lower() in lower:
            close = [lower[name.lower()]]
    return f"; did you mean {close[0]!r}?" if close else ""


class Checker:
    def __init__(self, source: str | None):
        self.source = source  # the file (None: the command line, named in `where`)

    def fail(self, where: str, message: str):
        raise SceneFileError(f"{self.source + ': ' if self.source else ''}{where}: {message}")

    def keys(self, table: dict, allowed, where: str, required=()) -> None:
        def at(key):  # "[tow] speed", "[tow] surge.period", "duration"
            table = where.startswith("[") and where.endswith("]") and " " not in where
            return key if not where else f"{where} {key}" if table else f"{where}.{key}"

        for key in table:
            if key not in allowed:
                hint = suggestion(key, allowed) or f" (known: {', '.join(allowed)})"
                self.fail(at(key), "unknown key" + hint)
        for key in required:
            if key not in table:
                self.fail(at(key), "missing (required)")

    def table(self, value, where: str) -> dict:
        if not isinstance(value, dict):
            self.fail(where, f"expected a table, got {_show(value)}")
        return value

    def number(self, value, where: str, positive=False, nonnegative=False) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.fail(where, f"expected a number, got {_show(value)}")
        x = float(value)
        if not math.isfinite(x):
            self.fail(where, f"expected a finite number, got {_show(value)}")
        if positive and x <= 0.0:
            self.fail(where, f"must be positive, got {_show(value)}")
        if nonnegative and x < 0.0:
            self.fail(where, f"must not be negative, got {_show(value)}")
        return x

    def vector(self, value, where: str) -> list:
        if not (isinstance(value, list) and len(value) == 3):
            self.fail(where, f"expected three numbers [x, y, z], got {_show(value)}")
        return [self.number(v, f"{where}[{i + 1}]") for i, v in enumerate(value)]

    def signal(self, value, where: str):
        """A constant (a number) or a piecewise-linear table { times = [...], values = [...] }."""
        if isinstance(value, dict):
            self.keys(value, TABLE_KEYS, where, required=TABLE_KEYS)
            times, values = value["times"], value["values"]
            for key, seq in (("times", times), ("values", values)):
                if not isinstance(seq, list) or not seq:
                    self.fail(f"{where}.{key}", f"expected a non-empty list of numbers, got {_show(seq)}")
            if len(times) != len(values):
                self.fail(where, f"times has {len(times)} entries, values {len(values)}: give one value per time")
            t = [self.number(v, f"{where}.times[{i + 1}]") for i, v in enumerate(times)]
            v = [self.number(x, f"{where}.values[{i + 1}]") for i, x in enumerate(values)]
            for i in range(1, len(t)):
                if t[i] < t[i - 1]:
                    self.fail(f"{where}.times", f"must not decrease ({t[i - 1]:g} then {t[i]:g})")
            return {"times": t, "values": v}
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.fail(where, f"expected a number or {{ times = [...], values = [...] }}, got {_show(value)}")
        return self.number(value, where)

    def parameter(self, name: str, value, where: str):
        """An FMU parameter's value, checked against its type and its range in the variable schema."""
        var = VARIABLES.get(name)
        if var is None or var.causality != "parameter":
            params = [n for n, v in VARIABLES.items() if v.causality == "parameter"]
            hint = " (an input: give it in [inputs])" if var is not None and var.causality == "input" else ""
            self.fail(where, "unknown parameter" + (hint or suggestion(name, params)))
        if var.type == "Boolean":
            if isinstance(value, bool):
                return value
            if isinstance(value, int) and value in (0, 1):
                return bool(value)
            self.fail(where, f"expected true or false, got {_show(value)}")
        if var.type == "String":
            if not isinstance(value, str):
                self.fail(where, f"expected a string, got {_show(value)}")
            return value
        if var.type == "Integer":
            if isinstance(value, bool) or not isinstance(value, (int, float)):
                self.fail(where, f"expected an integer, got {_show(value)}")
            if isinstance(value, float) and not value.is_integer():
                self.fail(where, f"expected an integer, got {_show(value)}")
            x = int(value)
        else:
            x = self.number(value, where)
        if var.min is not None and x < var.min or var.max is not None and x > var.max:
            unit = f" {var.unit}" if var.unit else ""
            self.fail(where, f"{_show(x)} is outside [{var.min:g}, {var.max:g}]{unit}")
        return x


def validate(data: dict, source: str) -> dict:
    """The checked scene (see the module's docstring); raises SceneFileError on the first mistake."""
    c = Checker(source)
    c.table(data, "scene")
    c.keys(data, TOP_KEYS, "", required=("duration", "step"))
    out = {"name": data.get("name", "scene"), "title": data.get("title", data.get("name", "scene"))}
    for key in ("name", "title"):
        if not isinstance(out[key], str):
            c.fail(key, f"expected a string, got {_show(out[key])}")
    out["duration"] = c.number(data["duration"], "duration", positive=True)
    out["step"] = c.number(data["step"], "step", positive=True)
    if out["step"] > out["duration"]:
        c.fail("step", f"{out['step']:g} s is longer than the duration {out['duration']:g} s")
    outputs = data.get("outputs", [])
    if not isinstance(outputs, list):
        c.fail("outputs", f"expected a list of variable names, got {_show(outputs)}")
    for i, name in enumerate(outputs):
        if not isinstance(name, str):
            c.fail(f"outputs[{i + 1}]", f"expected a variable name, got {_show(name)}")
        if name not in VARIABLES:
            c.fail(f"outputs[{i + 1}]", f"no variable {name!r}" + suggestion(name, VARIABLES))
    out["outputs"] = list(outputs)
    record = data.get("record_shape", True)
    if not isinstance(record, bool):
        c.fail("record_shape", f"expected true or false, got {_show(record)}")
    out["record_shape"] = record

    parameters = c.table(data.get("parameters", {}), "[parameters]")
    check_dotted_keys(c, parameters, "[parameters]")
    out["parameters"] = {k: c.parameter(k, v, f"[parameters] {k}") for k, v in parameters.items()}

    winch = c.table(data.get("winch", {}), "[winch]")
    out["winch"] = check_winch(c, winch, out["parameters"]) if winch else {}

    inputs = c.table(data.get("inputs", {}), "[inputs]")
    check_dotted_keys(c, inputs, "[inputs]")
    known_inputs = [n for n, v in VARIABLES.items() if v.causality == "input"]
    out["inputs"] = {}
    for name, value in inputs.items():
        where = f"[inputs] {name}"
        var = VARIABLES.get(name)
        if var is None or var.causality != "input":
            hint = " (a parameter: give it in [parameters])" if var is not None and var.causality == "parameter" else ""
            c.fail(where, "not an input of the FMU" + (hint or suggestion(name, known_inputs)))
        if name in TOW_INPUTS:
            c.fail(where, "the tow point moves as [tow] says (start, speed_kn, heading_deg, surge, heave)")
        if out["winch"] and name in WINCH_INPUTS.values():
            c.fail(where, "given by [winch] stages as well: use one of them")
        out["inputs"][name] = c.signal(value, where)

    failure = c.table(data.get("failure", {}), "[failure]")
    if failure:
        out["parameters"].update(check_failure(c, failure, out["parameters"]))

    tow = c.table(data.get("tow", {}), "[tow]")
    out["tow"] = check_tow(c, tow)
    body = c.table(data.get("body", {}), "[body]")
    out["body"] = check_body(c, body) if body else {}
    if out["body"]:
        for name in out["inputs"]:
            if name in BODY_INPUT_NAMES:
                c.fail(f"[inputs] {name}", "body 1 moves as [body] says (start, surge, sway, heave, roll, pitch, yaw)")
    return out


def _dotted(table: dict, prefix: str = ""):
    """(dotted name, value) of the leaves of nested tables; a { times, values } table is a leaf."""
    for key, value in table.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict) and not set(value) <= set(TABLE_KEYS):
            yield from _dotted(value, name + ".")
        else:
            yield name, value


def check_dotted_keys(c: Checker, table: dict, where: str) -> None:
    """An unquoted dotted key (body.mass = 400) is a nested table in TOML: a SceneFileError telling to
    quote the name ("body.mass" = 400) when the dotted name is a variable of the FMU."""
    for key, value in table.items():
        if key in VARIABLES or not isinstance(value, dict) or set(value) <= set(TABLE_KEYS):
            continue
        for name, leaf in _dotted(value, key + "."):
            if name in VARIABLES:
                c.fail(f"{where} {name}", f"an unquoted dotted key makes a TOML table: quote the name, "
                                          f"\"{name}\" = {_show(leaf)}")


def check_failure(c: Checker, failure: dict, parameters: dict) -> dict:
    """[failure]: the deck line (its ID) whose end detaches, the deck point it detaches from (0 or left out: its
    fairlead) or the position along it where it parts [m from its anchor], the time [s] and/or the tension [N] at
    which it does; the failure.* parameters they set."""
    c.keys(failure, FAILURE_KEYS, "[failure]", required=("line",))
    for name in ("failure.line", "failure.point", "failure.time", "failure.tension", "failure.position"):
        if name in parameters:
            c.fail(f"[parameters] {name}", "given by [failure] as well: use one of them")
    line, point = failure["line"], failure.get("point", 0)
    for key, value in (("line", line), ("point", point)):
        if isinstance(value, bool) or not isinstance(value, int) or value < (1 if key == "line" else 0):
            what = "a deck line ID (1, 2, ...)" if key == "line" else "a deck point ID (0: the line's fairlead)"
            c.fail(f"[failure] {key}", f"expected {what}, got {_show(value)}")
    time = c.number(failure.get("time", 0.0), "[failure] time", nonnegative=True)
    tension = c.number(failure.get("tension", 0.0), "[failure] tension", nonnegative=True)
    if time == 0.0 and tension == 0.0:
        c.fail("[failure]", "give a time [s], a tension [N] or both (the first reached breaks the line)")
    values = {"line": line, "point": point, "time": time, "tension": tension}
    if "position" in failure:  # along the line, not at a point
        values["position"] = c.number(failure["position"], "[failure] position", nonnegative=True)
        if point != 0:
            c.fail("[failure] position", "a break along the line is at its position, not at a point: give one of them")
    return {f"failure.{key}": c.parameter(f"failure.{key}", value, f"[failure] {key}") for key, value in values.items()}


def check_body(c: Checker, body: dict) -> dict:
    """[body]: body 1's start pose (x, y, z [m], roll, pitch, yaw [deg]) and oscillations from rest."""
    c.keys(body, BODY_KEYS, "[body]")
    start = body.get("start", [0.0] * 6)
    if not (isinstance(start, list) and len(start) == 6):
        c.fail("[body] start", "expected six numbers [x, y, z, roll, pitch, yaw] (m, deg)")
    out = {"start": [c.number(v, f"[body] start[{i + 1}]") for i, v in enumerate(start)]}
    for dof in BODY_DOFS:
        if dof not in body:
            continue
        out[dof], _ = check_oscillation(c, body[dof], OSCILLATION_KEYS, f"[body] {dof}")
    if "free" in body:
        out["free"] = check_free_body(c, c.table(body["free"], "[body.free]"), out)
    return out


def check_free_body(c: Checker, free: dict, body: dict) -> dict:
    """[body.free]: body 1 free in surge, sway and yaw: its mass with added mass [kg], its yaw inertia with added
    inertia [kg m2], damping [c_x, c_y, c_yaw] (N s/m, N s/m, N m s) and a steady load [F_x, F_y, M_z] (N, N, N m)."""
    c.keys(free, FREE_KEYS, "[body.free]", required=("mass", "inertia"))
    for dof in FREE_BODY_DOFS:
        if dof in body:
            c.fail(f"[body] {dof}", "a free degree of freedom of [body.free] cannot be given a motion as well")
    out = {"mass": c.number(free["mass"], "[body.free] mass", positive=True),
           "inertia": c.number(free["inertia"], "[body.free] inertia", positive=True)}
    for key in ("damping", "load"):
        value = free.get(key, [0.0, 0.0, 0.0])
        if not (isinstance(value, list) and len(value) == 3):
            c.fail(f"[body.free] {key}", f"expected three numbers (surge, sway, yaw), got {_show(value)}")
        out[key] = [c.number(x, f"[body.free] {key}[{i + 1}]", nonnegative=key == "damping")
                    for i, x in enumerate(value)]
    return out


def check_oscillation(c: Checker, value, allowed, where: str):
    """An oscillation { amplitude, period [, ramp] ...}: the checked amplitude, period and ramp (default
    one period), and the table as given."""
    m = c.table(value, where)
    c.keys(m, allowed, where, required=("amplitude", "period"))
    checked = {"amplitude": c.number(m["amplitude"], f"{where}.amplitude"),
               "period": c.number(m["period"], f"{where}.period", positive=True)}
    checked["ramp"] = c.number(m.get("ramp", checked["period"]), f"{where}.ramp", nonnegative=True)
    return checked, m


def check_tow(c: Checker, tow: dict) -> dict:
    c.keys(tow, TOW_KEYS, "[tow]")
    out = {"start": c.vector(tow.get("start", [0.0, 0.0, 0.0]), "[tow] start"),
           "speed_kn": c.signal(tow.get("speed_kn", 0.0), "[tow] speed_kn"),
           "heading_deg": c.signal(tow.get("heading_deg", 0.0), "[tow] heading_deg")}
    for motion, allowed in (("surge", SURGE_KEYS), ("heave", HEAVE_KEYS)):
        if motion not in tow:
            continue
        where = f"[tow] {motion}"
        checked, m = check_oscillation(c, tow[motion], allowed, where)
        if motion == "surge":
            d = c.vector(m.get("direction", [1.0, 0.0, 0.0]), f"{where}.direction")
            if math.hypot(*d) == 0.0:
                c.fail(f"{where}.direction", "must not be zero")
            checked["direction"] = d
        else:
            checked["direction"] = [0.0, 0.0, 1.0]
        out[motion] = checked
    return out


def check_winch(c: Checker, winch: dict, parameters: dict) -> dict:
    """[winch] stages -> the winch input as a piecewise-linear table, and the winch mode."""
    c.keys(winch, WINCH_KEYS, "[winch]", required=("stages",))
    ramp = c.number(winch.get("ramp", DEFAULT_WINCH_RAMP), "[winch] ramp", nonnegative=True)
    stages = winch["stages"]
    if not isinstance(stages, list) or not stages:
        c.fail("[winch] stages", "expected a list of stages like { rate = 0.5, duration = 60.0 }")
    kind = None
    checked = []
    for i, stage in enumerate(stages):
        where = f"[winch] stages[{i + 1}]"
        s = c.table(stage, where)
        c.keys(s, STAGE_KEYS, where, required=("duration",))
        given = [k for k in WINCH_INPUTS if k in s]
        if len(given) != 1:
            c.fail(where, "give exactly one of rate [m/s, + pays out] or tension [N]")
        if kind is not None and given[0] != kind:
            c.fail(where, f"{given[0]} after {kind} stages: the winch mode is fixed for a run")
        kind = given[0]
        duration = c.number(s["duration"], f"{where}.duration", positive=True)
        stage_ramp = c.number(s.get("ramp", ramp), f"{where}.ramp", nonnegative=True)
        if stage_ramp > duration:
            c.fail(f"{where}.ramp", f"{stage_ramp:g} s is longer than the stage ({duration:g} s)")
        checked.append((duration, stage_ramp, c.number(s[kind], f"{where}.{kind}")))
    mode = WINCH_MODES[kind]
    if parameters.get("winchMode", mode) != mode:
        c.fail("[parameters] winchMode", f"{parameters['winchMode']} but the [winch] stages give the {kind} "
                                         f"(winchMode {mode})")
    # a rate starts from rest; a tension starts at the first stage's value
    t, value = 0.0, 0.0 if kind == "rate" else checked[0][2]
    times, values = [0.0], [value]
    for duration, stage_ramp, target in checked:
        times.append(t + stage_ramp)  # a ramp of 0 is a step (two entries at one time)
        values.append(target)
        t += duration
        times.append(t)
        values.append(target)
    return {"input": WINCH_INPUTS[kind], "mode": mode, "table": {"times": times, "values": values}}
