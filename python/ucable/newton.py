"""The reference iterating master: a Newton iteration on the interface between the cable and a towed body
that integrates its own translation (the cable's far end follows it: bottomEnd 3), for bodies that a
non-iterating master cannot couple stably (docs/cosimulation.md, "The Newton master").

Per communication step [t, t + h] both FMUs are rolled back to t (fmi2GetFMUstate / fmi2SetFMUstate) as
often as needed. The unknown is the force F the body holds over the step (its cable-force input). One
evaluation of F: the body steps with F from its state (x, v) at t to (x1, v1); the cable's far end is
driven to exactly that state at t + h (inputs end.v = v, end.a = (v1 - v)/h, end.x = x1 - h (v + v1)/2:
a constant acceleration, docs/cosimulation.md, "Interface derivatives"), the cable steps, and the
residual is r(F) = endForce(t + h) - F. Newton's matrix is J = dendForce/dF - I with

    dendForce/dF = C B,  C: the cable's endForce against end.x/y/z and end.ax/ay/az
                         (fmi2GetDirectionalDerivative, asked once per direction: 3 requests),
                         B: the inputs' change per unit F, from the body's dx1/dF and dv1/dF
                         (finite differences: 3 extra body steps from the saved state).

The matrix is kept from step to step and computed again only when the iteration slows (a residual that
falls by less than `slow` per iteration) or before the cable can give derivatives (the first step, where
the cable's block is taken by finite differences as well). A step is converged when |r| <= tolerance x
max(|F|, the body's weight in air); it ends unconverged at max_iterations or when the residual stops
falling with a fresh matrix (the cable's variable-step integration answers input changes far below its
own tension tolerance with noise: the iteration cannot go below that). Both FMUs end the step in the state of the last evaluation: the body
held F, the cable's end is where the body is. The vessel is coupled as in the Gauss-Seidel fmpy master:
the cable steps with the vessel's tow point at t and its acceleration as input derivative, the vessel
steps after it with the cable's new tow force.
"""

from __future__ import annotations

import time as timer
from dataclasses import dataclass, field

import numpy as np

XYZ = "xyz"


@dataclass
class NewtonStats:
    steps: int = 0
    evaluations: int = 0  # cable and body steps of the iteration (without the Jacobians' extra ones)
    jacobians: int = 0  # Jacobians computed (3 cable directions + 3 body steps each)
    unconverged: int = 0  # steps that ended at max_iterations without reaching the tolerance
    max_evaluations: int = 0
    jacobian_cpu: float = 0.0  # [s] process time of the Jacobians
    residuals: list = field(default_factory=list)  # |r| / scale at the accepted evaluation of each step
    largest_force_residual: float = 0.0  # [N] the largest |r| accepted

    def as_dict(self) -> dict:
        s = max(self.steps, 1)
        return {"steps": self.steps, "evaluations per step": self.evaluations / s,
                "max evaluations": self.max_evaluations, "jacobians": self.jacobians,
                "unconverged": self.unconverged, "jacobian cpu": self.jacobian_cpu,
                "largest residual": max(self.residuals, default=0.0),
                "largest residual N": self.largest_force_residual}


class NewtonMaster:
    """The Newton master over a system vessel -> cable (bottomEnd 3) -> body: the units, connections and
    initialization of the Gauss-Seidel fmpy master (`base`, an ucable.system.FmpyMaster), the cable-body
    interface iterated."""

    def __init__(self, base, tolerance: float = 1e-4, max_iterations: int = 8, slow: float = 0.1,
                 body_weight: float = 1.0):
        self.base = base
        self.units = base.units
        self.tolerance, self.max_iterations, self.slow = tolerance, max_iterations, slow
        self.force_scale = max(body_weight, 1.0)
        cable, body = self.units["cable"], self.units["body"]
        self.cable, self.body = cable.fmu, body.fmu
        conns = base.system.connections
        to_cable = {c.input: c.output for c in conns if c.source == "body" and c.target == "cable"}
        from_cable = {c.output: c.input for c in conns if c.source == "cable" and c.target == "body"}
        try:
            self.body_position = [to_cable[f"end.{q}"] for q in XYZ]
            self.body_velocity = [to_cable[f"end.v{q}"] for q in XYZ]
            self.body_force = [from_cable[f"endForce.{q}"] for q in XYZ]
        except KeyError as e:
            raise ValueError(f"the newton master needs the body's position and velocity connected to the cable's "
                             f"end.* and the cable's endForce.* to the body (missing {e})") from None
        self.end_vrs = cable.vrs([f"end.{q}" for q in XYZ] + [f"end.a{q}" for q in XYZ])
        self.end_inputs = cable.vrs([f"end.{q}" for q in XYZ] + [f"end.v{q}" for q in XYZ] + [f"end.a{q}" for q in XYZ])
        self.end_force = cable.vrs([f"endForce.{q}" for q in XYZ])
        self.body_outputs = body.vrs(self.body_position + self.body_velocity)
        self.body_inputs = body.vrs(self.body_force)
        self.jacobian = None  # (3, 3) dr/dF, kept between steps
        self.cable_stepped = False  # the cable gives derivatives after its first step
        self.last_force = None
        self.stats = NewtonStats()
        self.t = 0.0

    def initialize(self):
        self.base.initialize()
        self.t = 0.0

    # ------------------------------------------------------------------ one evaluation
    def _evaluate(self, F, x0, v0, h, t, states):
        """The body steps with F, the cable's end follows it to its state at t + h: (endForce, x1, v1)."""
        cable_state, body_state = states
        self.body.set_state(body_state, t)
        self.body.slave.setReal(self.body_inputs, list(F))
        self.body.slave.doStep(t, h)
        y = np.array(self.body.slave.getReal(self.body_outputs))
        x1, v1 = y[:3], y[3:]
        self.cable.set_state(cable_state, t)
        self.base._transfer("cable")
        self.base._set_derivatives("cable")
        a = (v1 - v0) / h
        self.cable.slave.setReal(self.end_inputs, list(x1 - 0.5 * h * (v0 + v1)) + list(v0) + list(a))
        self.cable.slave.doStep(t, h)
        return np.array(self.cable.slave.getReal(self.end_force)), x1, v1

    def _body_block(self, F, h, t, body_state):
        """d(x1, v1)/dF (6 x 3) of the body's step, forward differences from the saved state."""
        def step(force):
            self.body.set_state(body_state, t)
            self.body.slave.setReal(self.body_inputs, list(force))
            self.body.slave.doStep(t, h)
            return np.array(self.body.slave.getReal(self.body_outputs))

        y0 = step(F)
        delta = 1e-6 * max(np.linalg.norm(F), self.force_scale)
        return np.column_stack([(step(F + delta * e) - y0) / delta for e in np.eye(3)])

    def _compute_jacobian(self, F, x0, v0, h, t, states):
        cpu0 = timer.process_time()
        cable_state, body_state = states
        B = self._body_block(F, h, t, body_state)
        dx1, dv1 = B[:3], B[3:]
        # the cable's inputs per unit F: end.x = x1 - h (v0 + v1)/2, end.a = (v1 - v0)/h (end.v fixed)
        dinputs = np.vstack([dx1 - 0.5 * h * dv1, dv1 / h])  # (6, 3): end.x/y/z, end.ax/ay/az
        if self.cable_stepped:
            self.cable.set_state(cable_state, t)
            dforce = np.column_stack([self.cable.slave.getDirectionalDerivative(self.end_force, self.end_vrs,
                                                                                list(dinputs[:, i]))
                                      for i in range(3)])
        else:  # no derivatives before the cable's first step: finite differences of the steps
            r0 = self._evaluate(F, x0, v0, h, t, states)[0]
            delta = 1e-4 * max(np.linalg.norm(F), self.force_scale)
            dforce = np.column_stack([(self._evaluate(F + delta * e, x0, v0, h, t, states)[0] - r0) / delta
                                      for e in np.eye(3)])
        self.jacobian = dforce - np.eye(3)
        self.stats.jacobians += 1
        self.stats.jacobian_cpu += timer.process_time() - cpu0

    # ------------------------------------------------------------------ one communication step
    def advance(self, h: float, t: float):
        base = self.base
        vessel = base.units.get("vessel")
        x0v0 = np.array(self.body.slave.getReal(self.body_outputs))
        x0, v0 = x0v0[:3], x0v0[3:]
        F_now = np.array(self.cable.slave.getReal(self.end_force))
        F = F_now if self.last_force is None else 2.0 * F_now - self.last_force  # linear extrapolation
        self.last_force = F_now
        states = (self.cable.get_state(), self.body.get_state())
        try:
            if self.jacobian is None:
                self._compute_jacobian(F, x0, v0, h, t, states)
            previous = None
            evaluations = 0
            fresh = self.stats.jacobians
            while True:
                Fc, _, _ = self._evaluate(F, x0, v0, h, t, states)
                evaluations += 1
                r = Fc - F
                scale = max(np.linalg.norm(Fc), self.force_scale)
                norm = np.linalg.norm(r) / scale
                if norm <= self.tolerance:
                    break
                if evaluations >= self.max_iterations:
                    self.stats.unconverged += 1
                    break
                if previous is not None and norm > self.slow * previous:
                    if self.stats.jacobians == fresh:
                        self._compute_jacobian(F, x0, v0, h, t, states)  # slow: a new matrix, here
                    elif norm >= previous:  # stagnates with a new matrix: the cable's integration noise
                        self.stats.unconverged += 1
                        break
                previous = norm
                F = F - np.linalg.solve(self.jacobian, r)
            # the cable and the body are in the state of the last evaluation
        finally:
            for unit, state in zip((self.cable, self.body), states):
                unit.free_state(state)
        self.cable_stepped = True
        self.stats.steps += 1
        self.stats.evaluations += evaluations
        self.stats.max_evaluations = max(self.stats.max_evaluations, evaluations)
        self.stats.residuals.append(norm)
        self.stats.largest_force_residual = max(self.stats.largest_force_residual, norm * scale)
        if vessel is not None:
            base._transfer("vessel")
            base._set_derivatives("vessel")
            vessel.fmu.slave.doStep(t, h)
        self.t = t + h

    def free(self):
        self.base.free()


def summary(result) -> str:
    """One line of a run's iteration counts (ucable.system.SystemResult of the newton master)."""
    s = result.stats
    return (f"newton: {s['evaluations per step']:.2f} evaluations per step (largest {s['max evaluations']}), "
            f"{s['jacobians']} Jacobians, {s['unconverged']} steps unconverged, "
            f"{1e3 * result.cpu / max(s['steps'], 1):.2f} ms CPU per step")
