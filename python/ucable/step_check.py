"""Is a scene's communication step short enough for what the scene moves?

Between communication points the FMU extrapolates its inputs (the tow point's motion, the winch's
command, the other inputs) from what the master gave at the step's start. A step that is long against
a period of the motion, the waves or a ramp of a table samples it with a few points: the FMU then
follows a staircase or a polygon of the motion, and the tensions it reports belong to that one
(measured: the chain_mooring scene's fairlead surging 5 m at a 12 s period, 67.1 MN peak tension at a
10 s step against 3.06 MN at 0.2 s; docs/scenes.md). The rule of thumb: a step of at most a tenth of the shortest
period or ramp in the scene.
"""

from __future__ import annotations

import math

from .variables import VARIABLES

STEP_FRACTION = 0.1  # the longest step, as a fraction of the shortest period or ramp


def _table_segments(signal, what: str) -> list:
    """The ramps of a piecewise-linear { times, values } table: (duration, what) of every segment whose
    value changes over a positive time (a jump, two entries at one time, is no ramp: it is held)."""
    if not isinstance(signal, dict):
        return []
    times, values = signal["times"], signal["values"]
    out = []
    for k in range(len(times) - 1):
        dt = float(times[k + 1]) - float(times[k])
        if dt > 0.0 and values[k + 1] != values[k]:
            out.append((dt, f"{what}: the ramp from {float(times[k]):g} s to {float(times[k + 1]):g} s"))
    return out


def scene_periods(scene) -> list:
    """Every period and ramp duration of a checked scene that a communication step must resolve, as
    (seconds, what) pairs: the tow point's and body 1's oscillations (period and soft start), the
    waves' period, the ramps of the tow's speed and heading tables, of the [winch] stages and of the
    [inputs] tables."""
    out = []
    tow = scene.tow or {}
    for key in ("surge", "heave"):
        m = tow.get(key)
        if m:
            out.append((float(m["period"]), f"[tow] {key}.period"))
            ramp = m.get("ramp", m["period"])
            if ramp and ramp > 0.0 and ramp != m["period"]:
                out.append((float(ramp), f"[tow] {key}.ramp"))
    for key in ("speed_kn", "heading_deg"):
        out += _table_segments(tow.get(key), f"[tow] {key}")
    for dof, m in (scene.body or {}).items():
        if isinstance(m, dict) and "period" in m:
            out.append((float(m["period"]), f"[body] {dof}.period"))
            if m.get("ramp", 0.0) > 0.0 and m["ramp"] != m["period"]:
                out.append((float(m["ramp"]), f"[body] {dof}.ramp"))
    p = {name: v.start for name, v in VARIABLES.items() if name.startswith("waves.")}
    p.update(scene.parameters)  # the FMU's defaults where the scene is silent
    if p["waves.mode"] and float(p["waves.height"]) > 0.0:
        out.append((float(p["waves.period"]), "[parameters] waves.period"))
    if scene.winch:
        out += _table_segments(scene.winch["table"], f"[winch] stages ({scene.winch['input']})")
    for name, signal in scene.inputs.items():
        out += _table_segments(signal, f"[inputs] {name}")
    return [(t, what) for t, what in out if t > 0.0 and math.isfinite(t)]


def step_warnings(scene) -> list:
    """The warning (one line, naming the shortest period or ramp its step does not resolve and how many
    others) when the scene's communication step is longer than STEP_FRACTION of a period or ramp of
    the scene; empty when the step is short enough."""
    h = float(scene.step)
    short = sorted((t, what) for t, what in scene_periods(scene) if h > STEP_FRACTION * t * (1.0 + 1e-12))
    if not short:
        return []
    t, what = short[0]
    more = f" (and {len(short) - 1} more period(s) or ramp(s) under {10.0 * h:g} s)" if len(short) > 1 else ""
    return [f"{scene.source}: step = {h:g} s is longer than a tenth of {what} ({t:g} s){more}: the FMU follows a "
            f"coarse sampling of it and its tensions can be far off; use step <= {STEP_FRACTION * t:g} s"]


# The communication steps up to which each shipped system's accuracy is documented (docs/systems.md,
# docs/cosimulation.md): the towed-body systems were measured within their bounds at steps 0.01-1 s;
# the explicit one only with the iterating master (without it, its coupling is unstable above a
# critical step, EXPLICIT_STEP); the systems in a sea resolve the waves as the scenes do (a tenth of the peak
# period the system file gives waves.period).
TOWED_BODY_STEP = 1.0  # [s]
# [s] the critical step of the explicit coupling of a 400 kg body without the iterating master, by
# ordering (docs/cosimulation.md, the model problem): fmpy's Gauss-Seidel, libcosim's Jacobi
EXPLICIT_STEP = {"fmpy": 0.0392, "libcosim": 0.015}


def _system_wave_periods(path) -> list:
    """The waves.period start values of a system file's units, [s]."""
    import re

    text = path.read_text()
    return [float(v) for v in re.findall(r'variable="waves\.period"\s*>\s*<Real\s+value="([^"]+)"', text)]


def system_step_warnings(name: str, master: str, step: float) -> list:
    """The warning (one line) when a shipped system runs at a step beyond the accuracy it documents; empty
    within it."""
    from .system import COUPLING_OF_SYSTEM, load_named_system

    system = load_named_system(name)
    h = float(system.step if step is None else step)
    if name in COUPLING_OF_SYSTEM:
        if COUPLING_OF_SYSTEM[name] == "explicit" and master != "newton":
            limit = EXPLICIT_STEP.get(master, min(EXPLICIT_STEP.values()))
            why = (f"the explicit coupling of {name}'s 400 kg body without --master newton is unstable above "
                   f"{limit:g} s with {master} (docs/cosimulation.md)")
        else:
            limit, why = TOWED_BODY_STEP, (f"{name}'s accuracy is documented for steps up to "
                                           f"{TOWED_BODY_STEP:g} s (docs/cosimulation.md)")
    else:
        periods = _system_wave_periods(system.path)
        if not periods:
            return []
        T = min(periods)
        limit, why = STEP_FRACTION * T, (f"a tenth of the sea's peak period waves.period = {T:g} s in {name}: the "
                                         f"vessel's motion and the waves are sampled too coarsely")
    if h <= limit * (1.0 + 1e-12):
        return []
    return [f"system {name}: step = {h:g} s is beyond {limit:g} s, {why}; the tensions can be far off: use "
            f"--step {limit:g} or less"]
