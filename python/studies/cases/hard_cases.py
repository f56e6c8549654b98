"""Hard cases: runs that make cable codes blow up, each with default solver settings.

A case is a tow-point trajectory (position, velocity and acceleration as functions of time; the
acceleration is passed as input derivative der(tow.v*), so the FMU sees the exact kinematics), FMU
parameters and a communication step. `run_case` flies it and returns a CaseResult: completed or the
FMU's error message, CPU time, integrator statistics, peak and minimum tension. `refine` repeats a case
with twice the elements and with tensionTolerance / 100 and reports the spread of the peak tension.

"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field, replace
from typing import Callable

import numpy as np

from ucable.fmu import NUM_STATIONS, CableFMU
from .manoeuvre import PiecewiseLinearSpeed
from ucable.units import GRAVITY as G, KNOT

DEFAULT_TENSION_TOLERANCE = 1e-3  # the FMU's default (schema/variables.toml)
STATS = ["solver.nSteps", "solver.nResidualEvals", "solver.nJacobianEvals", "solver.nNonlinearFailures",
         "solver.nErrorTestFailures"]
TENSIONS = ["towTension", "minTension"] + [f"tension[{k}]" for k in range(1, NUM_STATIONS + 1)]

# A trajectory maps t to (position, velocity, acceleration) of the tow point, each a length-3 array.
Trajectory = Callable[[float], tuple]


def along(profile: PiecewiseLinearSpeed, direction=(1.0, 0.0, 0.0), origin=(0.0, 0.0, 0.0)) -> Trajectory:
    """Motion along a fixed 3D direction with a piecewise-linear speed (distance integrated exactly)."""
    d = np.asarray(direction, float) / np.linalg.norm(direction)
    o = np.asarray(origin, float)

    def traj(t):
        return o + profile.distance(t) * d, profile.speed(t) * d, profile.acceleration(t) * d
    return traj


def with_heave(base: Trajectory, amplitude: float, period: float) -> Trajectory:
    """base + amplitude * (cos(2 pi t / period) - 1) on z: the heave starts at rest at its top (so an
    equilibrium start is the steady state of `base`) and first goes down."""
    w = 2.0 * math.pi / period

    def traj(t):
        p, v, a = (np.array(x, float) for x in base(t))
        p[2] += amplitude * (math.cos(w * t) - 1.0)
        v[2] -= amplitude * w * math.sin(w * t)
        a[2] -= amplitude * w * w * math.cos(w * t)
        return p, v, a
    return traj


def turn(speed: float, radius: float, t_start: float, angle_deg: float) -> Trajectory:
    """Straight along +x at `speed`, from t_start a left turn of `angle_deg` on a circle of `radius`
    at the same speed, then straight on the new heading."""
    angle = math.radians(angle_deg)
    omega = speed / radius
    t_end = t_start + angle / omega
    x0 = speed * t_start  # where the turn begins

    def traj(t):
        if t <= t_start:
            return np.array([speed * t, 0.0, 0.0]), np.array([speed, 0.0, 0.0]), np.zeros(3)
        th = omega * (min(t, t_end) - t_start)
        p = np.array([x0 + radius * math.sin(th), radius * (1.0 - math.cos(th)), 0.0])
        v = speed * np.array([math.cos(th), math.sin(th), 0.0])
        if t <= t_end:
            return p, v, speed * omega * np.array([-math.sin(th), math.cos(th), 0.0])
        return p + v * (t - t_end), v, np.zeros(3)
    return traj


@dataclass
class Case:
    name: str
    description: str
    parameters: dict
    trajectory: Trajectory
    t_end: float
    step: float
    inputs: dict = field(default_factory=dict)  # constant extra inputs (current, endLoad)
    refine: bool = True                           # run the mesh and tolerance refinement
    expect_failure: bool = False                  # a physically absurd case: a clean fmi2Error is the pass


@dataclass
class CaseResult:
    case: str
    n_elements: int
    tension_tolerance: float
    completed: bool
    message: str                 # the FMU's error message when not completed
    t_reached: float
    cpu: float                   # process CPU time of the run [s] (initialization included)
    stats: dict                  # solver.* at the end (cumulative)
    peak_tension: float          # max over communication points of towTension and tension[k]
    min_tension: float           # min over communication points of minTension
    finite: bool                 # every recorded output was finite
    time: np.ndarray = field(repr=False, default=None)
    tow_tension: np.ndarray = field(repr=False, default=None)
    max_tension: np.ndarray = field(repr=False, default=None)
    nsteps: np.ndarray = field(repr=False, default=None)
    state_restored: bool | None = None  # after a failure: the last good state was set back and re-read


def _set_kinematics(cable: CableFMU, traj: Trajectory, t: float, derivatives: bool) -> None:
    p, v, a = traj(t)
    cable.set({"tow.x": p[0], "tow.y": p[1], "tow.z": p[2], "tow.vx": v[0], "tow.vy": v[1], "tow.vz": v[2]})
    if derivatives:
        cable.set_input_derivatives(["tow.vx", "tow.vy", "tow.vz"], 1, a)


def _last_error(cable: CableFMU) -> str:
    errors = [m for s, _, m in cable.messages if s in ("ERROR", "FATAL", "DISCARD")]
    return errors[-1] if errors else "(no message logged)"


def run_case(fmu, case: Case, n_elements: int | None = None, tension_tolerance: float | None = None,
             t_end: float | None = None, progress=None, check_restore: bool = True) -> CaseResult:
    """Flies `case` (optionally with other nElements / tensionTolerance / end time) and collects the result.
    On an fmi2Error the FMU state saved before the failing step is restored and the outputs re-read:
    `state_restored` tells whether that worked."""
    params = dict(case.parameters)
    if n_elements is not None:
        params["nElements"] = n_elements
    if tension_tolerance is not None:
        params["tensionTolerance"] = tension_tolerance
    t_end = case.t_end if t_end is None else t_end
    n = int(math.ceil(t_end / case.step - 1e-9))
    times = np.array([min(k * case.step, t_end) for k in range(n + 1)])
    tow_t, max_t, nsteps = (np.full(n + 1, np.nan) for _ in range(3))
    min_tension, finite, message, restored = math.inf, True, "", None

    cable = CableFMU(fmu, parameters=params, instance_name=case.name)
    cpu0 = time.process_time()
    k_done = 0
    try:
        p, v, _ = case.trajectory(0.0)
        inputs = {"tow.x": p[0], "tow.y": p[1], "tow.z": p[2], "tow.vx": v[0], "tow.vy": v[1], "tow.vz": v[2]}
        inputs.update(case.inputs)
        derivatives = cable.can_interpolate_inputs

        def record(k):
            nonlocal min_tension, finite
            vals = cable.get_reals(TENSIONS + ["solver.nSteps"])
            finite = finite and bool(np.all(np.isfinite(vals)))
            tow_t[k], max_t[k], nsteps[k] = vals[0], max(vals[0], np.max(vals[2:-1])), vals[-1]
            min_tension = min(min_tension, vals[1])

        cable.initialize(0.0, t_end, inputs=inputs)
        record(0)
        state = cable.get_state() if check_restore else None
        for k in range(n):
            _set_kinematics(cable, case.trajectory, times[k], derivatives)
            if state is not None and k > 0:
                _refresh_state(cable, state)
            cable.do_step(times[k + 1] - times[k], t=times[k])
            record(k + 1)
            k_done = k + 1
            if progress is not None:
                progress.update(times[k + 1], f"{case.name} N={params.get('nElements', 20)} T={tow_t[k + 1]:9.0f} N")
        completed = True
    except Exception as e:  # fmpy raises FMICallException on fmi2Error
        completed = False
        message = _last_error(cable) if cable.messages else str(e)
        if check_restore and state is not None:
            restored = _try_restore(cable, state, times[k_done])
    cpu = time.process_time() - cpu0
    stats = {}
    try:
        stats = dict(zip(STATS, cable.get_reals(STATS)))
    except Exception:
        pass
    cable.free()
    return CaseResult(case=case.name, n_elements=params.get("nElements", 20), tension_tolerance=params.get("tensionTolerance", DEFAULT_TENSION_TOLERANCE),
                      completed=completed, message=message, t_reached=float(times[k_done]), cpu=cpu, stats=stats,
                      peak_tension=float(np.nanmax(max_t)) if k_done or completed else math.nan,
                      min_tension=float(min_tension), finite=finite, time=times[:k_done + 1],
                      tow_tension=tow_t[:k_done + 1], max_tension=max_t[:k_done + 1], nsteps=nsteps[:k_done + 1],
                      state_restored=restored)


def _refresh_state(cable: CableFMU, state):
    """fmi2GetFMUstate into the existing state (the FMU reuses it): the last good state before a step."""
    from fmpy.fmi2 import fmi2FMUstate  # noqa: F401
    from ctypes import byref
    cable.slave.fmi2GetFMUstate(cable.slave.component, byref(state))
    return state


def _try_restore(cable: CableFMU, state, t_good: float) -> bool:
    """fmi2SetFMUstate to the last good state after a failed step; then the outputs must be readable
    and the FMU's lastSuccessfulTime must be the time of that state."""
    try:
        cable.set_state(state)
        tension = cable.get("towTension")
        from ctypes import byref
        from fmpy.fmi2 import fmi2Real
        t = fmi2Real()
        cable.slave.fmi2GetRealStatus(cable.slave.component, 2, byref(t))  # fmi2LastSuccessfulTime
        return math.isfinite(tension) and abs(t.value - t_good) <= 1e-9 * max(1.0, t_good)
    except Exception:
        return False


@dataclass
class Refinement:
    base: CaseResult
    mesh: CaseResult | None
    tol: CaseResult | None

    @property
    def spread(self) -> float:
        """Largest relative difference of the peak tension of a refined run from the base run."""
        peaks = [r.peak_tension for r in (self.mesh, self.tol) if r is not None and r.completed]
        if not self.base.completed or not peaks:
            return math.nan
        return max(abs(p - self.base.peak_tension) for p in peaks) / self.base.peak_tension

    def converged(self, threshold: float) -> bool | None:
        if self.mesh is None and self.tol is None:
            return None
        s = self.spread
        return bool(math.isfinite(s) and s <= threshold)


def refine(fmu, case: Case, n_elements: int = 20, tension_tolerance: float = DEFAULT_TENSION_TOLERANCE, t_end: float | None = None,
           progress=None) -> Refinement:
    base = run_case(fmu, case, n_elements, tension_tolerance, t_end, progress)
    if not case.refine or not base.completed:
        return Refinement(base, None, None)
    mesh = run_case(fmu, case, 2 * n_elements, tension_tolerance, t_end, progress, check_restore=False)
    tol = run_case(fmu, case, n_elements, tension_tolerance / 100.0, t_end, progress, check_restore=False)
    return Refinement(base, mesh, tol)


# ---------------------------------------------------------------------------------------------------
# The cases. Lengths and loads are chosen so that the phenomenon certainly happens (numbers in the
# descriptions); everything not listed is the FMU default (the Hopland cable, tensionTolerance 1e-3).

def slack_snap(length: float = 100.0, amplitude: float = 5.0, period: float = 4.0, t_end: float = 40.0,
               step: float = 0.05) -> Case:
    """Vertical cable with a 2 t towed body (bottomEnd 2), the top heaving +-5 m at 4 s: the top comes down
    at up to 7.9 m/s and 12.3 m/s^2, faster than the body can sink (terminal speed
    sqrt(2 W / (rho CdA)) = 5.9 m/s with W = 17.6 kN submerged, CdA = 1 m^2), so the cable goes slack in
    every cycle and snaps when the top turns up again."""
    params = {"length": length, "bottomEnd": 2, "body.mass": 2000.0, "body.volume": 0.2,
              "body.addedMass": 200.0, "body.CdA": 1.0, "initMode": 0,
              "initialDirection.x": 0.0, "initialDirection.y": 0.0, "initialDirection.z": -1.0}
    traj = with_heave(along(PiecewiseLinearSpeed([0.0], [0.0])), amplitude, period)
    return Case("slack-snap", f"vertical {length:.0f} m, 2 t body, top heave +-{amplitude:g} m / {period:g} s",
                params, traj, t_end, step)


def free_fall_horizontal(length: float = 100.0, t_end: float = 60.0, step: float = 0.1) -> Case:
    """Free-hanging cable released at rest from a straight horizontal line (initMode 1): zero tension
    everywhere at t = 0, then it falls and swings down under the fixed top."""
    params = {"length": length, "initMode": 1, "initialDirection.x": 1.0, "initialDirection.y": 0.0,
              "initialDirection.z": 0.0}
    traj = along(PiecewiseLinearSpeed([0.0], [0.0]))
    return Case("near-zero: horizontal release", f"{length:.0f} m released horizontal at rest, top fixed",
                params, traj, t_end, step)


def vessel_stops_dead(speed_kn: float = 2.4, t_stop: float = 20.0, decel_time: float = 0.5,
                      t_end: float = 140.0, step: float = 0.1) -> Case:
    """Steady tow of the 300 m Hopland cable at 2.4 kn (equilibrium start), then the tow point stops
    within 0.5 s (2.5 m/s^2) and stays: the cable runs on, the top goes slack, the cable sinks."""
    v = speed_kn * KNOT
    profile = PiecewiseLinearSpeed([0.0, t_stop, t_stop + decel_time], [v, v, 0.0])
    return Case("near-zero: vessel stops dead", f"300 m at {speed_kn:g} kn, stop in {decel_time:g} s",
                {"initMode": 0}, along(profile), t_end, step)


def compression(length: float = 100.0, speed: float = 3.0, ramp: float = 2.0, t_end: float = 30.0,
                step: float = 0.1) -> Case:
    """Hanging free cable (equilibrium start, vertical), the top then pushed down at 3 m/s: the cable can
    only sink axially at about 1.7 m/s (submerged weight 17.8 N/m against tangential drag
    0.5 rho Cdt pi d v^2), so the upper part is compressed and must buckle; bending carries it."""
    profile = PiecewiseLinearSpeed([0.0, ramp], [0.0, speed])
    params = {"length": length, "initMode": 0, "initialDirection.x": 0.0, "initialDirection.y": 0.0,
              "initialDirection.z": -1.0}
    return Case("compression", f"{length:.0f} m hanging, top pushed down at {speed:g} m/s",
                params, along(profile, (0.0, 0.0, -1.0)), t_end, step)


def stiff_steel(length: float = 300.0, element_length: float = 5.0, t_end: float = 120.0, step: float = 1.0) -> Case:
    """Steel wire E = 2e11 Pa (d = 33.2 mm: EA = 1.73e8 N, 6.80 kg/m), 5 m elements, 1 s communication
    steps, towed through the Hopland acceleration (1.1 -> 2.4 kn in 60 s). Axial damping keeps the
    default time constant of 0.01 s (axialDamping = 0.01 s * EA)."""
    d = 0.0332
    area = math.pi * d * d / 4.0
    ea = 2e11 * area
    params = {"length": length, "nElements": int(round(length / element_length)), "EA": ea,
              "axialDamping": 0.01 * ea, "massPerLength": 7850.0 * area, "initMode": 0}
    profile = PiecewiseLinearSpeed([0.0, 60.0], [1.1 * KNOT, 2.4 * KNOT])
    return Case("very stiff steel", f"E = 2e11 Pa, {element_length:g} m elements, {step:g} s steps",
                params, along(profile), t_end, step)


def turn_180(speed_kn: float = 5.0, radius: float = 50.0, t_start: float = 30.0, t_end: float = 180.0,
             step: float = 0.5) -> Case:
    """Tow at 5 kn (equilibrium start), then a 180 deg turn on a 50 m radius (63 s, centripetal
    acceleration 0.13 m/s^2) and straight on."""
    v = speed_kn * KNOT
    return Case("violent: 180 deg turn at 5 kn", f"R = {radius:g} m, 300 m cable", {"initMode": 0},
                turn(v, radius, t_start, 180.0), t_end, step)


def tow_jerk(g_level: float = 10.0, duration: float = 0.1, speed_kn: float = 2.0, t_jerk: float = 10.0,
             t_end: float = 40.0, step: float = 0.02) -> Case:
    """Steady tow at 2 kn, then the tow point accelerates at g_level * g for `duration` and decelerates
    at the same rate back to 2 kn (1 m extra travel at 10 g, 0.1 s): an axial shock wave of about
    m c dv = 2.7 kg/m * 4980 m/s * 9.8 m/s = 132 kN runs down the cable."""
    v = speed_kn * KNOT
    dv = g_level * G * duration
    profile = PiecewiseLinearSpeed([0.0, t_jerk, t_jerk + duration, t_jerk + 2 * duration], [v, v, v + dv, v])
    name = f"violent: {g_level:g} g tow jerk"
    return Case(name, f"{g_level:g} g for {duration:g} s up and down at {speed_kn:g} kn", {"initMode": 0},
                along(profile), t_end, step)


def seabed_impact(length: float = 100.0, depth: float = 50.0, top_depth: float = 20.0, t_end: float = 60.0,
                  step: float = 0.1) -> Case:
    """A chain (117 kg/m, d = 0.137 m volume-equivalent, EA 7.5e8 N, no bending stiffness) released at
    rest from a horizontal straight line 30 m above the seabed, top fixed: it swings down and its
    far part strikes the seabed at about sqrt(2 g' 30 m) ~ 20 m/s, then lies on it (seabed stiffness
    1e6 N/m2, default damping)."""
    params = {"length": length, "diameter": 0.137, "massPerLength": 117.0, "EA": 7.5e8, "axialDamping": 7.5e6,
              "enableBending": 0, "Cdn": 2.4, "Cdt": 0.2, "initMode": 1, "initialDirection.x": 1.0,
              "initialDirection.y": 0.0, "initialDirection.z": 0.0, "enableSeabed": 1, "waterDepth": depth,
              "seabedStiffness": 1e6}
    traj = along(PiecewiseLinearSpeed([0.0], [0.0]), origin=(0.0, 0.0, -top_depth))
    return Case("seabed impact", f"{length:.0f} m chain released horizontal {depth - top_depth:g} m above the seabed",
                params, traj, t_end, step)


def long_run(hours: float = 24.0, speed_kn: float = 2.0, heave: float = 1.0, period: float = 10.0,
             step: float = 1.0) -> Case:
    """Steady tow of the Hopland cable at 2 kn with +-1 m / 10 s heave, 1 s steps, for `hours`."""
    v = speed_kn * KNOT
    traj = with_heave(along(PiecewiseLinearSpeed([0.0], [v])), heave, period)
    return Case("long run", f"{hours:g} h at {speed_kn:g} kn, heave +-{heave:g} m / {period:g} s",
                {"initMode": 0}, traj, hours * 3600.0, step, refine=False)


def all_cases() -> list:
    return [slack_snap(), free_fall_horizontal(), vessel_stops_dead(), compression(), stiff_steel(), turn_180(),
            tow_jerk(), seabed_impact()]


def hourly_drift(result: CaseResult, period: float = 10.0) -> dict:
    """Mean tow tension and solver steps per simulated hour (hours fully completed)."""
    t, tension, steps = result.time, result.tow_tension, result.nsteps
    hours = int(t[-1] // 3600)
    means, cost = [], []
    for h in range(hours):
        sel = (t > h * 3600 + 1e-9) & (t <= (h + 1) * 3600 + 1e-9)
        means.append(float(np.mean(tension[sel])))
        i0, i1 = np.searchsorted(t, h * 3600), np.searchsorted(t, (h + 1) * 3600)
        cost.append(float(steps[min(i1, len(steps) - 1)] - steps[i0]))
    return {"mean_tension": np.array(means), "steps_per_hour": np.array(cost)}


def variant(case: Case, **kwargs) -> Case:
    return replace(case, **kwargs)
