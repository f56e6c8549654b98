"""Co-simulation masters: vessel + UnderwaterCable FMU (+ towed body), driven through fmpy.

Gauss-Seidel (default), per communication step [t_k, t_k + h]:
  1. the vessel's tow point at t_k (position, velocity and, from the vessel's equations of motion
     with the tow force F_k, acceleration) goes to the FMU: tow.* inputs, and the acceleration as
     input derivative der(tow.vx/vy) (fmi2SetRealInputDerivatives, order 1) so that the FMU moves
     the tow point along a smooth parabola inside the step;
     with an external towed body (bottomEnd 3) the body's position, velocity and acceleration go to
     end.* the same way;
  2. the FMU steps to t_k + h and reports F_{k+1} (towForce.*, endForce.*);
  3. the vessel (and the external body) step from t_k with the cable force interpolated linearly
     between F_k and F_{k+1} (RK4 substeps).
Iterative (predictor-corrector with FMU state rollback): after 1-3, the FMU is set back to its
state at t_k (fmi2SetFMUstate) and steps again with input derivatives equal to the partners'
mean acceleration over the step, (v_{k+1} - v_k) / h, so that its end velocities match the partners'
at t_{k+1}; the partners step again with the new forces; repeated until the forces change by less
than `tol` or `max_iter` corrections.

Internal towed body: the FMU's bottomEnd 2 with the same body (one monolithic implicit solve: the
reference for the external coupling).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from ucable.fmu import NUM_STATIONS, CableFMU
from ..cases.manoeuvre import SHAPE_OUTPUTS, PiecewiseLinearSpeed
from .partners import Autopilot, TowedBody, TowedBodyParameters, Vessel, VesselParameters

CABLE_OUTPUTS = ["towForce.x", "towForce.y", "towForce.z", "towTension",
                 "endForce.x", "endForce.y", "endForce.z", "endTension",
                 "endPosition.x", "endPosition.y", "endPosition.z",
                 "endVelocity.x", "endVelocity.y", "endVelocity.z", "minTension"]
_I = {n: i for i, n in enumerate(CABLE_OUTPUTS)}
TOW_IN = ["tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz"]
END_IN = ["end.x", "end.y", "end.z", "end.vx", "end.vy", "end.vz"]

COUPLINGS = ("none", "internal", "external")
MASTERS = ("gauss-seidel", "iterative")


# ------------------------------------------------------------------------------ references
class SpeedReference:
    """Autopilot speed order from a PiecewiseLinearSpeed: (u_ref, du_ref/dt)."""

    def __init__(self, profile: PiecewiseLinearSpeed):
        self.profile = profile

    def __call__(self, t):
        return self.profile.speed(t), self.profile.acceleration(t)


class HeadingReference:
    """Heading order psi0 until t0, then turning at `rate` [rad/s] (sign = direction) until the
    heading has changed by `angle` [rad] (math.inf: a circle)."""

    def __init__(self, psi0=0.0, t0=math.inf, rate=0.0, angle=0.0):
        self.psi0, self.t0, self.rate, self.angle = psi0, t0, rate, abs(angle)

    def turn_end(self):
        if self.rate == 0.0 or not math.isfinite(self.angle):
            return math.inf
        return self.t0 + self.angle / abs(self.rate)

    def __call__(self, t):
        if t <= self.t0 or self.rate == 0.0:
            return self.psi0, 0.0
        if t >= self.turn_end():
            return self.psi0 + math.copysign(self.angle, self.rate), 0.0
        return self.psi0 + self.rate * (t - self.t0), self.rate


# ------------------------------------------------------------------------------ scene
@dataclass
class CosimCase:
    speed: PiecewiseLinearSpeed
    heading: HeadingReference = field(default_factory=HeadingReference)
    t_end: float = 660.0
    step: float = 0.5
    n_elements: int = 20
    coupling: str = "none"  # none (free end), internal (bottomEnd 2), external (bottomEnd 3)
    body: TowedBodyParameters = field(default_factory=TowedBodyParameters)
    vessel: VesselParameters = field(default_factory=VesselParameters)
    master: str = "gauss-seidel"
    input_derivatives: bool = True
    max_iter: int = 2
    tol: float = 1e-3  # [N] force change that ends the corrector iterations
    cable_parameters: dict = field(default_factory=dict)


@dataclass
class CosimResult:
    time: np.ndarray
    vessel: np.ndarray  # (n, 8) state [x, y, psi, u, v, r, speed integral, heading integral]
    thrust: np.ndarray
    tow: np.ndarray  # (n, 3) tow point position
    cable: dict  # name -> (n,) for CABLE_OUTPUTS
    body: np.ndarray | None  # (n, 6) external body state
    shape: np.ndarray | None  # (n, 4, 21): x, y, z, tension (None if not recorded)
    cpu: float  # process time of the run [s]
    iterations: np.ndarray  # corrector iterations per step
    scene: CosimCase = None

    def __getitem__(self, name):
        return self.cable[name]

    @property
    def end_depth(self):
        """Depth of the far end below the tow point [m]."""
        return self.tow[:, 2] - self.cable["endPosition.z"]

    @property
    def speed(self):
        return np.hypot(self.vessel[:, 3], self.vessel[:, 4])


def _require_external(cable: CableFMU):
    missing = [n for n in END_IN if n not in cable.variables]
    if missing:
        raise RuntimeError(f"the FMU has no inputs {missing}: external towed body (bottomEnd 3) "
                           "needs an FMU with the end.* inputs")


def initial_body_position(fmu, scene: CosimCase, tow_inputs: dict) -> np.ndarray:
    """Steady position of the towed body at the start: the internal-body equilibrium of the FMU."""
    params = {"nElements": scene.n_elements, **scene.cable_parameters, **scene.body.fmu_parameters()}
    probe = CableFMU(fmu, parameters=params, instance_name="equilibrium-probe")
    try:
        probe.initialize(0.0, scene.t_end, inputs=tow_inputs)
        return probe.get_reals(["endPosition.x", "endPosition.y", "endPosition.z"])
    finally:
        probe.free()


class Master:
    """One co-simulation of a CosimCase; `advance()` does one communication step."""

    def __init__(self, scene: CosimCase, fmu=None, instance_name="cable"):
        if scene.coupling not in COUPLINGS:
            raise ValueError(f"coupling must be one of {COUPLINGS}")
        if scene.master not in MASTERS:
            raise ValueError(f"master must be one of {MASTERS}")
        self.scene = scene
        u0 = scene.speed.speed(0.0)
        psi0, _ = scene.heading(0.0)
        ap = Autopilot(scene.vessel, SpeedReference(scene.speed), scene.heading)
        self.vessel = Vessel(scene.vessel, ap, psi0=psi0, u0=u0)
        params = {"nElements": scene.n_elements, **scene.cable_parameters}
        if scene.coupling == "internal":
            params.update(scene.body.fmu_parameters())
        elif scene.coupling == "external":
            params.update({"bottomEnd": 3, "waterDensity": scene.body.water_density,
                           "gravity": scene.body.gravity})
        self.cable = CableFMU(fmu, parameters=params, instance_name=instance_name)
        self.derivs = scene.input_derivatives and self.cable.can_interpolate_inputs
        self.t = 0.0
        self.body = None

        tow = self._tow_inputs(np.zeros(3))
        inputs = dict(zip(TOW_IN, tow[0].tolist() + tow[1].tolist()))
        if scene.coupling == "external":
            _require_external(self.cable)
            p_end = initial_body_position(fmu, scene, inputs)
            v_end = tow[1]  # steady tow: the body moves with the tow point
            self.body = TowedBody(scene.body, p_end, v_end)
            inputs.update(dict(zip(END_IN, list(p_end) + list(v_end))))
        self.cable.initialize(0.0, scene.t_end, inputs=inputs)
        self.out = self.cable.get_reals(CABLE_OUTPUTS)

    # ------------------------------------------------------------------ coupling signals
    def _tow_inputs(self, tow_force):
        pos, vel, acc = self.vessel.tow_point(tow_force=tow_force, t=self.vessel.t)
        return (np.array([pos[0], pos[1], 0.0]), np.array([vel[0], vel[1], 0.0]),
                np.array([acc[0], acc[1], 0.0]))

    def tow_force(self, out=None):
        out = self.out if out is None else out
        return out[[_I["towForce.x"], _I["towForce.y"], _I["towForce.z"]]]

    def end_force(self, out=None):
        out = self.out if out is None else out
        return out[[_I["endForce.x"], _I["endForce.y"], _I["endForce.z"]]]

    def _set_inputs(self, tow, tow_acc, end=None, end_acc=None):
        values = dict(zip(TOW_IN, list(tow[0]) + list(tow[1])))
        if end is not None:
            values.update(dict(zip(END_IN, list(end[0]) + list(end[1]))))
        self.cable.set(values)
        if self.derivs:
            names, acc = ["tow.vx", "tow.vy", "tow.vz"], list(tow_acc)
            if end is not None:
                names += ["end.vx", "end.vy", "end.vz"]
                acc += list(end_acc)
            self.cable.set_input_derivatives(names, 1, acc)

    # ------------------------------------------------------------------ one step
    def advance(self, h: float) -> int:
        """One communication step; returns the number of corrector iterations done."""
        F0_tow, F0_end = self.tow_force(), self.end_force()
        tow = self._tow_inputs(F0_tow)
        end = end_acc = None
        if self.body is not None:
            end = (self.body.position.copy(), self.body.velocity.copy())
            end_acc = self.body.acceleration(self.body.x, F0_end)
        iterative = self.scene.master == "iterative"
        if iterative:
            cable_state = self.cable.get_state()
            vessel_state = self.vessel.get_state()
            body_state = self.body.get_state() if self.body is not None else None

        self._set_inputs(tow, tow[2], end, end_acc)
        self.cable.do_step(h, t=self.t)
        out = self.cable.get_reals(CABLE_OUTPUTS)
        self._step_partners(h, out, F0_tow, F0_end)

        iterations = 0
        self.last_change = np.nan  # force change of the last correction (iterative master)
        if iterative:
            try:
                for iterations in range(1, self.scene.max_iter + 1):
                    # mean accelerations of the partners over the step
                    v1_tow = self._tow_inputs(self.tow_force(out))[1]
                    acc_tow = (v1_tow - tow[1]) / h
                    acc_end = None
                    if self.body is not None:
                        acc_end = (self.body.velocity - end[1]) / h
                    self.cable.set_state(cable_state, time=self.t)
                    self.vessel.set_state(vessel_state)
                    if body_state is not None:
                        self.body.set_state(body_state)
                    self._set_inputs(tow, acc_tow, end, acc_end)
                    self.cable.do_step(h, t=self.t)
                    new = self.cable.get_reals(CABLE_OUTPUTS)
                    self._step_partners(h, new, F0_tow, F0_end)
                    change = max(np.max(np.abs(self.tow_force(new) - self.tow_force(out))),
                                 np.max(np.abs(self.end_force(new) - self.end_force(out))))
                    out = new
                    self.last_change = change
                    if change < self.scene.tol:
                        break
            finally:
                self.cable.free_state(cable_state)
        self.out = out
        self.t += h
        return iterations

    def _step_partners(self, h, out, F0_tow, F0_end):
        self.vessel.step(h, F0_tow, self.tow_force(out))
        if self.body is not None:
            self.body.step(h, F0_end, self.end_force(out))

    # ------------------------------------------------------------------ co-simulation state
    def snapshot(self) -> dict:
        """Everything needed to continue the co-simulation from now, the FMU part serialized
        (fmi2GetFMUstate + fmi2SerializeFMUstate): can be restored into another Master."""
        state = self.cable.get_state()
        try:
            data = self.cable.serialize_state(state)
        finally:
            self.cable.free_state(state)
        return {"t": self.t, "fmu": data, "out": self.out.copy(),
                "vessel": self.vessel.get_state(),
                "body": self.body.get_state() if self.body is not None else None}

    def restore(self, snap: dict) -> None:
        state = self.cable.deserialize_state(snap["fmu"])
        try:
            self.cable.set_state(state, time=snap["t"])
        finally:
            self.cable.free_state(state)
        self.t = snap["t"]
        self.out = snap["out"].copy()
        self.vessel.set_state(snap["vessel"])
        if self.body is not None:
            self.body.set_state(snap["body"])

    # ------------------------------------------------------------------ whole run
    def run(self, progress=None, record_shape: bool = True) -> CosimResult:
        sc = self.scene
        n = int(math.ceil(sc.t_end / sc.step - 1e-9))
        times = np.array([min(k * sc.step, sc.t_end) for k in range(n + 1)])
        vessel = np.zeros((n + 1, Vessel.N))
        thrust = np.zeros(n + 1)
        tow = np.zeros((n + 1, 3))
        cab = np.zeros((n + 1, len(CABLE_OUTPUTS)))
        body = np.zeros((n + 1, TowedBody.N)) if self.body is not None else None
        shape = np.zeros((n + 1, 4, NUM_STATIONS)) if record_shape else None
        iters = np.zeros(n + 1, dtype=int)

        def record(k):
            vessel[k] = self.vessel.x
            thrust[k] = self.vessel.commands(self.tow_force())[0]
            tow[k] = self._tow_inputs(self.tow_force())[0]
            cab[k] = self.out
            if body is not None:
                body[k] = self.body.x
            if record_shape:
                shape[k] = self.cable.get_reals(SHAPE_OUTPUTS).reshape(4, NUM_STATIONS)

        cpu0 = time.process_time()
        record(0)
        for k in range(n):
            iters[k + 1] = self.advance(times[k + 1] - times[k])
            record(k + 1)
            if progress is not None and (k % 20 == 0 or k == n - 1):
                progress.update(times[k + 1], f"t = {times[k + 1]:6.1f} s  "
                                f"T = {cab[k + 1, _I['towTension']]:8.1f} N")
        cpu = time.process_time() - cpu0
        return CosimResult(time=times, vessel=vessel, thrust=thrust, tow=tow,
                           cable={nm: cab[:, i] for i, nm in enumerate(CABLE_OUTPUTS)},
                           body=body, shape=shape, cpu=cpu, iterations=iters, scene=sc)

    def free(self):
        self.cable.free()


def run_scene(scene: CosimCase, fmu=None, progress=None, record_shape: bool = True) -> CosimResult:
    master = Master(scene, fmu)
    try:
        return master.run(progress, record_shape)
    except Exception:
        if master.cable.messages:
            print(master.cable.log_text())
        raise
    finally:
        master.free()
