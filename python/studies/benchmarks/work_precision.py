"""Work-precision benchmark: UnderwaterCable FMU against MoorDyn v2, run via
scripts/bench_work_precision.

For every case, both codes fly the same prescribed fairlead/tow-point trajectory:
  * our FMU over a grid of nElements x tensionTolerance (the integrator's tolerance in tension,
    docs/error_control.md), inputs set at every
    communication point with the exact acceleration passed as der(tow.v*) (fmi2SetRealInputDerivatives);
  * MoorDyn (PyPI `moordyn`, its default RK2 scheme) from an input file, the tow point a coupled
    Point moved by this script with moordyn.Step at every MoorDyn time step, over a grid of segment
    counts and time steps; its stable limit is found by bisection on dt (a run blows up when it
    returns NaN/inf, an error, or a force above 100x the expected scale).
Each run's error is measured against a converged reference (our finest run); the table gives CPU
(time.process_time of the stepping loop, including the Python/fmpy overhead each code pays when
driven from Python), real-time factor and errors; the CPU ratio MoorDyn/ours at matched error comes
from log-log interpolation of each code's Pareto front (error vs CPU).
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from ..cases import heave
from ucable.fmu import CableFMU
from ..cases.manoeuvre import hopland_accelerate
from ucable.paths import REPO_ROOT, require_fmu
from ucable.progress import ProgressBar
from ..peers import moordyn
from ucable.units import KNOT

OUT_DIR = REPO_ROOT / "out" / "bench_work_precision"
DOC = REPO_ROOT / "docs" / "performance.md"
MD_BA_ZETA = 0.8  # MoorDyn BA/-zeta = -0.8: damping ratio of the segment axial mode (its docs' example)
BLOWUP_FACTOR = 100.0  # a force above 100x the case's force scale (or NaN) is a blown-up run


# ----------------------------------------------------------------------------- trajectories
class HoplandTow:
    """Tow point along +x at the surface: 1.1 kn, linear ramp to 2.4 kn in 60 s, 600 s more."""

    def __init__(self):
        self.profile, self.t_end = hopland_accelerate()

    def state(self, t):
        p = self.profile
        return (np.array([p.distance(t), 0.0, 0.0]), np.array([p.speed(t), 0.0, 0.0]),
                np.array([p.acceleration(t), 0.0, 0.0]))


class HeldStill:
    """The tow point (fairlead) held where `traj` starts: the runs on it cost what the communication
    points cost alone (one integrator step each, the inputs set and the outputs read)."""

    def __init__(self, traj):
        self.x0 = np.asarray(traj.state(0.0)[0], float)

    def state(self, t):
        return self.x0.copy(), np.zeros(3), np.zeros(3)


class RampedSurge:
    """Fairlead surge x0 + A r(t) sin(2 pi t / T) along x, r = 3 tau^2 - 2 tau^3 (tau = t / t_ramp)
    ramps the amplitude in smoothly (position, velocity and acceleration start at rest)."""

    def __init__(self, x0, amplitude, period, t_ramp, t_end):
        self.x0, self.A, self.w, self.tr, self.t_end = (np.asarray(x0, float), amplitude,
                                                        2 * math.pi / period, t_ramp, t_end)

    def state(self, t):
        tau = min(max(t / self.tr, 0.0), 1.0)
        r = 3 * tau**2 - 2 * tau**3
        dr = (6 * tau - 6 * tau**2) / self.tr if t < self.tr else 0.0
        ddr = (6 - 12 * tau) / self.tr**2 if t < self.tr else 0.0
        s, c, w = math.sin(self.w * t), math.cos(self.w * t), self.w
        x = self.A * r * s
        v = self.A * (dr * s + r * w * c)
        a = self.A * (ddr * s + 2 * dr * w * c - r * w * w * s)
        e = np.array([1.0, 0.0, 0.0])
        return self.x0 + x * e, v * e, a * e


# ----------------------------------------------------------------------------- cases
@dataclass
class Case:
    name: str
    title: str
    traj: object
    t_end: float
    comm_step: float  # FMU communication step [s]; also the output sampling of both codes
    line: dict  # length, diameter, massPerLength, EA, EI, Cdn, Cdt, Can, Cat
    fmu_params: dict  # extra FMU parameters (ends)
    anchor: tuple | None  # None: free lower end
    force_scale: float  # [N] for the blow-up check
    frame_speed: float = 0.0  # MoorDyn runs in a frame moving at this speed along x (Galilean)
    metrics: tuple = ("tension", "end_rms")  # (tension metric, second metric): ratios and plot
    columns: tuple = ("tension", "end_rms", "end_max")  # error columns of the table
    description: str = ""
    fmu_grid: dict = field(default_factory=dict)
    md_grid: dict = field(default_factory=dict)
    reference: dict = field(default_factory=lambda: dict(full=(80, 1e-7), quick=(40, 1e-5)))  # (N, tensionTolerance)
    seabed: dict | None = None  # MoorDyn-style flat seabed: depth [m], kBot [Pa/m], cBot [Pa s/m]
    md_ba: float | None = None  # MoorDyn BA [N s] (axial damping, as our axialDamping); None: -MD_BA_ZETA
    inputs: dict = field(default_factory=dict)  # constant FMU inputs (current)
    current: float = 0.0  # uniform current along x [m/s], the same in MoorDyn
    body: dict | None = None  # MoorDyn point at the free far end: mass, volume, CdA, CA
    reference_step: float | None = None  # communication step of our reference run (None: comm_step)
    calm_twin: dict | None = None  # FMU parameters that make the sea calm: a cost table calm vs this case
    still_twin: bool = False  # a cost table of the cheap runs against the same runs with the fairlead held still
    doc_after: str | None = None  # a partial run puts this case's section after that case's in the doc


HOPLAND_LINE = dict(length=300.0, diameter=0.0332, massPerLength=2.7018, EA=6.709e7, EI=1000.0,
                    Cdn=1.649, Cdt=0.12, Can=1.0, Cat=0.0)
STIFF_LINE = dict(length=250.0, diameter=0.2, massPerLength=60.0, EA=7e8, EI=2e4,
                  Cdn=1.2, Cdt=0.008, Can=1.0, Cat=0.0)
STIFF_FAIRLEAD = (0.0, 0.0, -10.0)
STIFF_ANCHOR = (-210.0, 0.0, -100.0)
# Chain: 117 kg/m with a volume-equivalent diameter of 0.137 m gives a wet weight of
# 117 g - rho g pi d^2/4 = 1147.8 - 148.2 = 999.6 N/m; no bending stiffness (a chain).
CHAIN_LINE = dict(length=835.0, diameter=0.137, massPerLength=117.0, EA=7.5e8, EI=0.0,
                  Cdn=2.4, Cdt=0.2, Can=1.0, Cat=0.0)
CHAIN_FAIRLEAD = (0.0, 0.0, -20.0)
CHAIN_ANCHOR = (-800.0, 0.0, -200.0)
# MoorDyn's seabed (its defaults, written out in the input file): vertical force on a node
# (kBot penetration - cBot vz) d l_node, i.e. per unit contact area d x length. Ours is per unit
# cable length per metre of penetration, so seabedStiffness = kBot d and seabedDamping = cBot d.
MD_KBOT, MD_CBOT = 3.0e6, 3.0e5
# Axial (Kelvin-Voigt) damping of the chain, the same in both codes (our axialDamping, MoorDyn's BA):
# the time constant the FMU's documentation gives users (axialDamping = 0.01 s x EA) times the line's
# EA. The snap of the chain is an axial wave, so the damping is part of the answer: the reference's
# fairlead tension moves by 2.3 % RMS between this and the FMU's default (0.01 s x the default EA,
# 0.9 ms x the chain's EA).
AXIAL_DAMPING_TIME = 0.01


def seabed_params(line, depth):
    return {"enableSeabed": 1, "waterDepth": depth, "seabedStiffness": MD_KBOT * line["diameter"],
            "seabedDamping": MD_CBOT * line["diameter"], "seabedFriction": 0.0}


def make_cases():
    hop = HoplandTow()
    hopland = Case(
        name="hopland", title="Hopland tow manoeuvre (300 m, free end, 1.1 -> 2.4 kn in 60 s, 660 s)",
        traj=hop, t_end=hop.t_end, comm_step=0.5, line=HOPLAND_LINE, fmu_params={"bottomEnd": 0},
        anchor=None, force_scale=1e4, frame_speed=1.1 * KNOT,
        description=(
            "Default FMU cable, free lower end, tow point at the surface along +x. Errors: max |T - "
            "T_ref| over the run relative to the range of T_ref (T = tow-point force magnitude); "
            "RMS and max over the run of the 3-D far-end position difference."),
        fmu_grid=dict(full=[(n, tol) for n in (5, 10, 20, 40) for tol in (1e-1, 1e-2, 1e-3, 1e-4)],
                      quick=[(10, 1e-3)]),
        md_grid=dict(full=[(n, f) for n in (10, 20, 40, 80) for f in (0.9,)] + [(20, 0.45)],
                     quick=[(10, 0.9)]),
        reference=dict(full=(80, 1e-7), quick=(40, 1e-5)),
    )
    mooring = Case(
        name="mooring",
        title="Chain mooring with seabed (835 m, 1000 N/m wet, EA 7.5e8 N, 200 m depth, surge 5 m at 12 s, 120 s)",
        traj=RampedSurge(CHAIN_FAIRLEAD, 5.0, 12.0, 12.0, 120.0), t_end=120.0, comm_step=0.05,
        line=CHAIN_LINE,
        fmu_params={"bottomEnd": 1, "anchor.x": CHAIN_ANCHOR[0], "anchor.y": CHAIN_ANCHOR[1],
                    "anchor.z": CHAIN_ANCHOR[2], "enableBending": 0, "enableCompression": 0,
                    "axialDamping": AXIAL_DAMPING_TIME * CHAIN_LINE["EA"], **seabed_params(CHAIN_LINE, 200.0)},
        md_ba=AXIAL_DAMPING_TIME * CHAIN_LINE["EA"],
        anchor=CHAIN_ANCHOR, force_scale=3e6, metrics=("tension_rmsrel", "mid_rms"),
        columns=("tension_rmsrel", "tension", "mid_rms", "mid_max"),
        seabed=dict(depth=200.0, kBot=MD_KBOT, cBot=MD_CBOT),
        description=(
            "Chain: 835 m, 117 kg/m, volume-equivalent diameter 0.137 m (wet weight 999.6 N/m), "
            "EA 7.5e8 N, no bending stiffness (ours: enableBending = 0; MoorDyn: EI = 0), tension only "
            "(ours: enableCompression = 0, the chain goes slack as MoorDyn's does; the switch table "
            "shows the two-sided law), Cdn 2.4, "
            "Cdt 0.2 (on pi d), Can 1, Cat 0. Axial damping matched: MoorDyn BA = our axialDamping = 0.01 s x EA. Anchor on the seabed at (-800, 0, -200) m, fairlead at "
            "(0, 0, -20) m; 200 m depth. Fairlead surge 5 m amplitude at 12 s along x, amplitude "
            "ramped in smoothly over the first 12 s. Seabed in both codes, matched: MoorDyn kBot = "
            f"{MD_KBOT:.1e} Pa/m and cBot = {MD_CBOT:.1e} Pa s/m (its defaults, per unit contact area d x "
            "node length); ours per unit length: seabedStiffness = kBot d = "
            f"{MD_KBOT * 0.137:.4g} N/m2, seabedDamping = cBot d = {MD_CBOT * 0.137:.4g} N s/m2, no "
            "friction in either (ours smooths the contact onset over 5 % of d = 7 mm; MoorDyn's is a "
            "kink at zero penetration). Errors: fairlead tension |towForce| RMS difference relative to "
            "the RMS of the reference tension (the usual '% RMS'), its max relative to the range; "
            "RMS and max of the mid-line position difference (our station 11 of 21 = 417.5 m from "
            "the fairlead; MoorDyn node N/2). Ours also at tensionTolerance 0.1 with positionTolerance 0.01 "
            "and 0.1 m: there the default 1 mm, not the tension tolerance, sets the steps (at 5 elements "
            "tensionTolerance 0.1 and 0.01 take the same steps); with the contact sampled every 2 m "
            "(seabedContactSpacing, docs/model.md); and with equal elements (meshGrading 0). By default the "
            "nodes are graded by the static profile (finer where the chain hangs, 45 m elements where it "
            "rests at 40 elements against 21 m equal ones), which makes the start exact but leaves the "
            "stretch the surge lifts off the seabed to coarser elements."),
        # and the loosest setting with the position tolerance (1 mm by default, the tolerance that sets
        # the steps at tensionTolerance 0.1) at 1 cm and 10 cm
        fmu_grid=dict(full=[(5, 1e-1), (5, 1e-2)] + [(n, tol) for n in (10, 20, 40) for tol in (1e-1, 1e-2, 1e-3, 1e-4)]
                      + [(n, 1e-1, {"positionTolerance": pt}) for n in (5, 10, 20, 40) for pt in (0.01, 0.1)]
                      + [(n, 1e-1, {"positionTolerance": 0.1, "seabedContactSpacing": 2.0}) for n in (5, 10, 20)]
                      + [(n, tol, {"meshGrading": 0}) for n in (10, 20, 40) for tol in (1e-1, 1e-3)]
                      + [(n, 1e-1, {"meshGrading": 0, "positionTolerance": 0.1}) for n in (5, 10, 20, 40)],
                      quick=[(10, 1e-3)]),
        md_grid=dict(full=[(n, 0.9) for n in (10, 20, 40, 80, 160)], quick=[(10, 0.9)]),
        reference=dict(full=(80, 1e-6), quick=(20, 1e-4)), still_twin=True,
    )
    stiff = Case(
        name="stiff", title="Stiff power cable with seabed (250 m, EA 7e8 N, EI 2e4 N m2, 100 m depth, surge 3 m at 8 s, 120 s)",
        traj=RampedSurge(STIFF_FAIRLEAD, 3.0, 8.0, 8.0, 120.0), t_end=120.0, comm_step=0.05,
        line=STIFF_LINE, fmu_params={"bottomEnd": 1, "anchor.x": STIFF_ANCHOR[0],
                                     "anchor.y": STIFF_ANCHOR[1], "anchor.z": STIFF_ANCHOR[2],
                                     **seabed_params(STIFF_LINE, 100.0)},
        anchor=STIFF_ANCHOR, force_scale=1e6, metrics=("tension", "curv_top"),
        columns=("tension", "tension_rmsrel", "curv_top", "mid_rms"),
        seabed=dict(depth=100.0, kBot=MD_KBOT, cBot=MD_CBOT),
        description=(
            "Power cable: 250 m, 60 kg/m, d 0.2 m (wet weight 273 N/m), EA 7e8 N, EI 2e4 N m2 (in both "
            "codes), Cdn 1.2, Cdt 0.008 (on pi d), Can 1. Anchor on the seabed at (-210, 0, -100) m, "
            "fairlead at (0, 0, -10) m, hinged in both codes: about 100 m of cable rest on the seabed "
            "(static catenary estimate), which both codes model with the same matched contact as the "
            f"mooring case (kBot {MD_KBOT:.0e} Pa/m, cBot {MD_CBOT:.0e} Pa s/m; ours x d = 0.2 m). "
            "Fairlead surge 3 m at 8 s along x, amplitude ramped in smoothly over the first period. "
            "Errors: fairlead tension max |T - T_ref| relative to the range of T_ref and RMS relative "
            "to RMS(T_ref); top curvature: our FMU outputs only maxCurvature over the whole cable, so "
            "both codes' top curvature is the Menger curvature (circle) through the positions at arc "
            "lengths 0, L/20 and L/10 from the fairlead (our shape stations 1-3; MoorDyn nodes N, "
            "N - N/20, N - N/10, so only N multiple of 20): a chord approximation averaging the "
            "curvature over the top 25 m (it misses the hinge's bending boundary layer, sqrt(EI/T) < "
            "1 m); error = RMS difference relative to RMS of the reference; mid-length position RMS. Ours also "
            "at tensionTolerance 0.1 with projectedErrorControl = true (the tangents' error test along and "
            "across the cable, docs/error_control.md; off by default), and with positionTolerance 0.1 m "
            "as well, from 3 to 40 elements, with the contact sampled every 2 m (seabedContactSpacing; "
            "off by default: the five axial points of each element; docs/model.md), and with that and "
            "the integrator's BDF formulas kept at the A-stable orders 1-2 (solver.maxOrder = 2; default 5; "
            "docs/error_control.md), and with all that on equal elements (meshGrading 0: by default the "
            "nodes are graded by the static profile, which leaves the top of the cable coarser)."),
        # and the loosest setting with the error test of the tangents along and across the cable,
        # also with the position tolerance at 10 cm (and on coarser meshes: the cheap end)
        fmu_grid=dict(full=[(n, tol) for n in (10, 20, 40) for tol in (1e-1, 1e-2, 1e-3, 1e-4)]
                      + [(n, 1e-1, {"projectedErrorControl": True}) for n in (10, 20, 40)]
                      + [(n, 1e-1, {"projectedErrorControl": True, "positionTolerance": 0.1})
                         for n in (3, 5, 6, 10, 15, 20, 40)]
                      + [(n, 1e-1, {"projectedErrorControl": True, "positionTolerance": 0.1, "seabedContactSpacing": 2.0})
                         for n in (6, 10, 15, 20)]
                      + [(n, 1e-1, {"projectedErrorControl": True, "positionTolerance": 0.1, "seabedContactSpacing": 2.0,
                                    "solver.maxOrder": 2}) for n in (6, 10, 15, 20, 40)]
                      + [(n, 1e-1, {"meshGrading": 0, "projectedErrorControl": True, "positionTolerance": 0.1,
                                    "seabedContactSpacing": 2.0, "solver.maxOrder": 2}) for n in (6, 10, 15, 20, 40)],
                      quick=[(10, 1e-3)]),
        md_grid=dict(full=[(n, 0.9) for n in (20, 40, 80)], quick=[(20, 0.9)]),
        reference=dict(full=(80, 1e-6), quick=(20, 1e-5)), still_twin=True,
    )
    heave_case = Case(
        name="heave",
        title="Heave: umbilical with a heavy body (1000 m, EA 5e8 N, 10 t body, 2 m / 10 s heave, 0.5 m/s current, 200 s)",
        traj=heave.RampedHeave(), t_end=200.0, comm_step=0.1, line=dict(heave.LINE),
        fmu_params={k: v for k, v in heave.parameters(20).items() if k not in heave.LINE and k != "nElements"},
        # force scale: a run whose top force exceeds 100 x 1e4 N = 1 MN (5 x the largest tension
        # of the heave) has blown up (an unstable MoorDyn step stays bounded, near 1.5 MN)
        anchor=None, force_scale=1e4, metrics=("tension_rmsrel", "end_rms"),
        columns=("tension_rmsrel", "tension", "end_rms"),
        inputs={"current.x": heave.CURRENT}, current=heave.CURRENT,
        body=dict(mass=heave.BODY["body.mass"], volume=heave.BODY["body.volume"], CdA=heave.BODY["body.CdA"],
                  CA=heave.BODY["body.addedMass"] / (1025.0 * heave.BODY["body.volume"])),
        md_ba=0.01 * heave.LINE["EA"], reference_step=0.01,
        description=(
            "A long umbilical with a heavy body hanging from a heaving vessel (python/studies/cases/heave.py): "
            "1000 m, d 0.1 m, 20 kg/m, EA 5e8 N, EI 1e4 N m2 (in both codes), Cdn 1.2, Cdt 0.008 (on "
            "pi d), Can 1; a 10 t body of 2 m3 with 2 t added mass and CdA 3 m2 at the lower end (ours "
            "bottomEnd 2; MoorDyn a Free point with the same mass, volume, CdA and CA = 2 t / (rho V)); "
            "0.5 m/s current along x in both; the top heaves 2 m at 10 s, ramped in over the first "
            "period, from the static equilibrium in the current (MoorDyn starts from our equilibrium "
            "shape, as in the Hopland case). Axial damping matched: MoorDyn BA = our axialDamping = "
            "0.01 s x EA. Driven as masters drive us: our FMU at 0.1 s communication steps with the "
            "acceleration as input derivative; MoorDyn with the exact top position and velocity at "
            "every one of its time steps. Errors: top tension |force| RMS difference relative to the "
            "RMS of the reference tension (the usual '% RMS') and its max relative to the range; "
            "RMS of the body position difference. Reference: ours at 40 elements, tensionTolerance "
            "1e-7 and 0.01 s communication steps (the extrapolated tow motion within 1e-8 m of the "
            "exact one)."),
        fmu_grid=dict(full=[(1, 1e-2), (2, 1e-2)] + [(n, tol) for n in (3, 5, 10, 20) for tol in (1e-2, 1e-3, 1e-4)],
                      quick=[(5, 1e-3)]),
        md_grid=dict(full=[(n, 0.9) for n in (5, 10, 20, 40, 80)], quick=[(10, 0.9)]),
        reference=dict(full=(40, 1e-7), quick=(10, 1e-5)),
    )
    heave_waves = replace(
        heave_case, name="heave_waves",
        title=("Heave in waves: the heave case in a JONSWAP sea (Hs 3 m, Tp 10 s, 200 components) acting on the "
               "umbilical, 200 s"),
        fmu_params={**heave_case.fmu_params, **HEAVE_WAVES},
        md_grid=dict(full=[], quick=[]), calm_twin={"waves.mode": 0}, doc_after="heave",
        description=(
            "The heave case above (the same umbilical, body, current and 2 m / 10 s heave of the top, the same "
            "grid and reference) with the water moving in an irregular sea: JONSWAP Hs 3 m, Tp 10 s, gamma 3.3, "
            "200 components, seed 1, travelling along +x, no ramp; the Morison loads use the velocity relative "
            "to current plus waves and the fluid inertia of the waves' acceleration (docs/waves.md). Ours only: "
            "MoorDyn is not fed the same wave components here. Errors against our reference in the same sea "
            "(40 elements, tensionTolerance 1e-7, 0.01 s steps). The second table puts each run's cost next to "
            "the same run in calm water (waves.mode = 0): the difference is the price of the wave kinematics."))
    return {"hopland": hopland, "mooring": mooring, "stiff": stiff, "heave": heave_case, "heave_waves": heave_waves}


HEAVE_WAVES = {"waves.mode": 2, "waves.height": 3.0, "waves.period": 10.0, "waves.gamma": 3.3, "waves.seed": 1,
               "waves.nComponents": 200}


# ----------------------------------------------------------------------------- runs
@dataclass
class Run:
    code: str
    resolution: int
    setting: str  # tolerance or time step
    cpu: float
    t: np.ndarray
    force: np.ndarray  # (n, 3) force of the cable on the tow point
    end: np.ndarray  # (n, 3) far-end position
    mid: np.ndarray  # (n, 3) mid-length position
    top: np.ndarray  # (n, 3, 3) positions at arc lengths 0, L/20, L/10 from the top (NaN: unknown)
    stats: dict = field(default_factory=dict)
    errors: dict = field(default_factory=dict)
    label: str = ""
    tolerance: float | None = None  # ours: the tensionTolerance (or relTol) of the run
    extra: dict = field(default_factory=dict)  # ours: the further FMU parameters of the run


def sample_times(case):
    n = int(round(case.t_end / case.comm_step))
    return np.arange(n + 1) * case.comm_step


FMU_OUT = ["towForce.x", "towForce.y", "towForce.z", "endPosition.x", "endPosition.y",
           "endPosition.z", "shape.x[11]", "shape.y[11]", "shape.z[11]",
           "shape.x[1]", "shape.y[1]", "shape.z[1]", "shape.x[2]", "shape.y[2]", "shape.z[2]",
           "shape.x[3]", "shape.y[3]", "shape.z[3]", "minTension"]
FMU_STATS = ["solver.nSteps", "solver.nResidualEvals", "solver.nJacobianEvals",
             "solver.nNonlinearFailures", "solver.nErrorTestFailures"]


def static_top_tension(fmu, case, n_elements, **extra) -> float:
    """Top tension [N] of `case`'s line at rest where its trajectory starts (the FMU's static solver
    alone), with n_elements and further FMU parameters."""
    params = {**case.line, **case.fmu_params, "nElements": n_elements, **extra}
    x, v, _ = case.traj.state(0.0)
    with CableFMU(fmu, parameters=params) as c:
        c.initialize(inputs=dict(zip(["tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz"], [*x, *v])))
        return c.get("towTension")


def run_fmu(fmu, case, n_elements, tol, extra=None, label="", step=None, tolerance="tensionTolerance"):
    """Our FMU on `case` with `n_elements` and the integrator tolerance `tol` (tensionTolerance; with
    tolerance="relTol" IDA's relTol with absTol = 100 relTol, as extra bounds on the default). The
    master passes position, velocity and acceleration at every communication point (case.comm_step,
    or `step` if given: a divisor of it, e.g. for a reference run); outputs at case.comm_step."""
    params = dict(case.line)
    params.update(case.fmu_params)
    params["nElements"] = n_elements
    if tolerance == "relTol":
        params.update(relTol=tol, absTol=100.0 * tol)
    else:
        params[tolerance] = tol
    params.update(extra or {})
    times = sample_times(case)
    sub = 1 if step is None else int(round(case.comm_step / step))
    h = case.comm_step / sub
    out = np.zeros((len(times), len(FMU_OUT)))
    cable = CableFMU(fmu, parameters=params, instance_name=f"{case.name}_{n_elements}")
    try:
        # The inputs of every communication step computed ahead, and the FMI calls made directly
        # with ctypes arrays built once: the loop costs what an FMI master's loop costs (about 3.5 us
        # per communication step in Python, against 16 us through the name-based wrappers), as the
        # MoorDyn loop below steps a trajectory computed ahead.
        from fmpy.fmi2 import fmi2Integer, fmi2Real, fmi2True, fmi2ValueReference
        slave = cable.slave
        vr = lambda names: (fmi2ValueReference * len(names))(*[cable.variables[n].valueReference for n in names])
        in_names = ["tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz"]
        vr_in, vr_der, vr_out = vr(in_names), vr(in_names[3:]), vr(FMU_OUT)
        order = (fmi2Integer * 3)(1, 1, 1)
        n_out = len(FMU_OUT)
        out_buf = (fmi2Real * n_out)()
        steps = []
        for k in range(len(times) - 1):
            for j in range(sub):
                t = times[k] + j * h
                x, v, a = case.traj.state(t)
                steps.append((t, times[k + 1] - t if j == sub - 1 else h, (fmi2Real * 6)(*x, *v),
                              (fmi2Real * 3)(*a), j == sub - 1))
        x, v, _ = case.traj.state(0.0)
        inp = dict(zip(in_names, [*x, *v]))
        inp.update(case.inputs)
        cable.initialize(0.0, case.t_end, inputs=inp)
        out[0] = cable.get_reals(FMU_OUT)
        sh = cable.shape()
        shape0 = np.array([sh["shape.x"], sh["shape.y"], sh["shape.z"]])
        component = slave.component
        set_real, set_der, do_step, get_real = (slave.fmi2SetReal, slave.fmi2SetRealInputDerivatives,
                                                slave.fmi2DoStep, slave.fmi2GetReal)
        k = 0
        cpu0 = time.process_time()
        for t, dt, values, acc, last in steps:
            set_real(component, vr_in, 6, values)
            set_der(component, vr_der, 3, order, acc)
            do_step(component, t, dt, fmi2True)
            if last:
                k += 1
                get_real(component, vr_out, n_out, out_buf)
                out[k] = out_buf
        cpu = time.process_time() - cpu0
        stats = dict(zip(FMU_STATS, cable.get_reals(FMU_STATS)))
        stats["shape0"] = shape0
        stats["minTension"] = float(out[:, 18].min())  # over the cable and the run
    finally:
        cable.free()
    tags = ",".join(f"{k}={v:g}" for k, v in (extra or {}).items())
    short = "tol" if tolerance == "tensionTolerance" else tolerance
    if step is not None:
        tags = ",".join(t for t in (tags, f"step={h:g}") if t)
    setting = f"{tolerance} {tol:.0e}" + "".join(f", {k} = {v:g}" for k, v in (extra or {}).items())
    return Run("ours", n_elements, setting, cpu, times, out[:, 0:3], out[:, 3:6],
               out[:, 6:9], out[:, 9:18].reshape(-1, 3, 3), stats,
               label=label or (f"ours N={n_elements} {short}={tol:.0e}" + (f" {tags}" if tags else "")),
               tolerance=tol, extra=dict(extra or {}))


# ----------------------------------------------------------------------------- MoorDyn
def moordyn_input(case, n_seg, dt, workdir: Path, end_guess) -> Path:
    ln = case.line
    ba = -MD_BA_ZETA if case.md_ba is None else case.md_ba
    if case.anchor is None:
        e = end_guess[:, -1]
        b = case.body or dict(mass=0.0, volume=0.0, CdA=0.0, CA=0.0)
        p1 = (f"1     Free      {e[0]:.10g} {e[1]:.10g} {e[2]:.10g}  {b['mass']:.10g}  {b['volume']:.10g}  "
              f"{b['CdA']:.10g}  {b['CA']:.10g}")
    else:
        a = case.anchor
        p1 = f"1     Fixed     {a[0]:.10g} {a[1]:.10g} {a[2]:.10g}  0  0  0  0"
    x0, _, _ = case.traj.state(0.0)
    # no seabed: 5000 m of water (the cable never reaches it)
    sb = case.seabed or dict(depth=5000.0, kBot=MD_KBOT, cBot=MD_CBOT)
    depth, kbot, cbot = sb["depth"], sb["kBot"], sb["cBot"]
    text = f"""--------------------- MoorDyn Input File ------------------------------------
UnderwaterCable work-precision benchmark, case {case.name}
---------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA     BA/-zeta    EI    Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)    (N-s/-)     (N-m^2) (-)  (-)    (-)     (-)
cable  {ln['diameter']:.10g} {ln['massPerLength']:.10g} {ln['EA']:.10g} {ba:g} {ln['EI']:.10g} {ln['Cdn']:.10g} {ln['Can']:.10g} {ln['Cdt']:.10g} {ln['Cat']:.10g}
---------------------- POINTS --------------------------------
ID   Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)        (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
{p1}
2     Coupled   {x0[0]:.10g} {x0[1]:.10g} {x0[2]:.10g}  0  0  0  0
---------------------- LINES --------------------------------------
ID    LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)      (m)       (-)      (-)
1     cable      1        2        {ln['length']:.10g}  {n_seg}  -
---------------------- OPTIONS -----------------------------------------
{dt:.10g}   dtM
9.81     g
1025     rho
{depth:.10g}     WtrDpth
{kbot:.10g}     kBot
{cbot:.10g}     cBot
{1 if case.frame_speed or case.current else 0}        Currents
0        writeLog
1        disableOutput
1        disableOutTime
------------------------- need this line -------------------------------------
"""
    path = workdir / "lines.txt"
    path.write_text(text)
    if case.frame_speed or case.current:
        with open(workdir / "current_profile.txt", "w") as f:
            f.write("--------------------- MoorDyn steady currents File -----------------\n"
                    "uniform current along x (minus V0 in the frame of a steady tow)\n"
                    "z (m), ux (m/s), uy (m/s), uz (m/s)\n")
            for z in (-5000.0, -1000.0, 0.0, 10.0):
                f.write(f"{z} {case.current - case.frame_speed:.15g} 0.0 0.0\n")
    return path


def run_moordyn(case, n_seg, dt, steady_shape, t_stop=None, label=""):
    """One MoorDyn run with time step dt (adjusted so that comm_step / dt is an integer).
    Returns a Run, or None when it blew up. In a case with frame_speed (the Hopland tow) MoorDyn
    runs in the frame moving at that speed with a uniform current -frame_speed: the steady tow at
    t = 0 is then a state at rest, which MoorDyn can start from (its initial-condition solver does
    not apply currents, and in the Earth frame a tow from rest needs > 2000 s to settle).
    steady_shape (3, 21): the steady-tow shape at the 21 stations (from the reference run), set
    as MoorDyn's initial node positions (see peers.moordyn.System.set_line_nodes); None for anchored cases, which
    start from MoorDyn's own static initial condition (moordyn.Init)."""
    sub = int(math.ceil(case.comm_step / dt - 1e-9))
    dt = case.comm_step / sub
    t_stop = case.t_end if t_stop is None else t_stop
    times = sample_times(case)
    times = times[times <= t_stop + 1e-9]
    V0 = case.frame_speed
    ok = True
    try:  # chdir: MoorDyn reads current_profile.txt from the working directory
        with moordyn.System(write=lambda tmp: moordyn_input(case, n_seg, dt, tmp, steady_shape), chdir=True) as md:
            x0, v0, _ = case.traj.state(0.0)
            xf = [x0[0], x0[1], x0[2]]
            vf = [v0[0] - V0, v0[1], v0[2]]
            if case.anchor is None:  # a free far end: start from our steady (or equilibrium) shape
                md.init(xf, vf, no_ic=True)
                md.set_line_nodes(md.line(1), n_seg, steady_shape)
            else:
                md.init(xf, vf)
            line = md.line(1)
            end_point = md.point(1)
            force = np.zeros((len(times), 3))
            end = np.zeros((len(times), 3))
            mid = np.zeros((len(times), 3))
            top = np.full((len(times), 3, 3), np.nan)
            top_nodes = ([n_seg, n_seg - n_seg // 20, n_seg - n_seg // 10] if n_seg % 20 == 0
                         else None)  # arc lengths 0, L/20, L/10 from the top (node 0: anchor)
            tt = 0.0
            # pre-computed coupled-point trajectory in MoorDyn's frame, one entry per MoorDyn step
            nsteps = (len(times) - 1) * sub
            traj_x, traj_v = [], []
            for i in range(nsteps):
                t = i * dt
                x, v, _ = case.traj.state(t)
                traj_x.append([x[0] - V0 * t, x[1], x[2]])
                traj_v.append([v[0] - V0, v[1], v[2]])
            limit = BLOWUP_FACTOR * case.force_scale

            def record(k, f):
                t = times[k]
                force[k] = f
                e = md.point_position(end_point) if case.anchor is None else md.node_position(line, 0)
                m = md.node_position(line, n_seg // 2)
                end[k] = (e[0] + V0 * t, e[1], e[2])
                mid[k] = (m[0] + V0 * t, m[1], m[2])
                if top_nodes is not None:
                    for j, node in enumerate(top_nodes):
                        q = md.node_position(line, node)
                        top[k, j] = (q[0] + V0 * t, q[1], q[2])

            step = md.step_raw
            cpu0 = time.process_time()
            i = 0
            for k in range(len(times) - 1):
                for _ in range(sub):
                    f = step(traj_x[i], traj_v[i], tt, dt)
                    tt += dt
                    i += 1
                if not (np.all(np.isfinite(f)) and max(abs(c) for c in f) < limit):
                    ok = False
                    break
                record(k + 1, f)
            cpu = time.process_time() - cpu0
            # row 0 (t = 0) stays empty: moordyn.Step returns forces at the end of each call and
            # the error metrics compare t > 0 only
    except Exception:  # MoorDyn reports NaN states as errors
        ok = False
        cpu = math.nan
    if not ok:
        return None
    return Run("MoorDyn", n_seg, f"dt {dt:.3g} s", cpu, times, force, end, mid, top,
               {"dt": dt, "steps": (len(times) - 1) * sub},
               label=label or f"MoorDyn N={n_seg} dt={dt:.2e}")


def moordyn_stable_dt(case, n_seg, steady_shape, t_trial=None, rel=0.03):
    """Largest stable dt (bisection between a stable and an unstable dt, to `rel`), judged on a
    trial run of t_trial s (default 30 s: RK2's limit is set by the axial waves, which grow within
    a few hundred steps when unstable; a run that still blows up later is retried at 0.8 dt)."""
    ln = case.line
    c = math.sqrt(ln["EA"] / ln["massPerLength"])
    seg = ln["length"] / n_seg
    lo, hi = 0.1 * seg / c, 4.0 * seg / c
    t_trial = min(case.t_end, 30.0) if t_trial is None else t_trial
    while run_moordyn(case, n_seg, lo, steady_shape, t_stop=t_trial) is None:
        hi, lo = lo, lo / 3
        if lo < 1e-3 * seg / c:
            raise RuntimeError(f"MoorDyn unstable even at dt = {lo:g} s (N = {n_seg})")
    while hi / lo > 1 + rel:
        mid = math.sqrt(lo * hi)
        if run_moordyn(case, n_seg, mid, steady_shape, t_stop=t_trial) is None:
            hi = mid
        else:
            lo = mid
    return lo, lo * c / seg


# ----------------------------------------------------------------------------- errors
def top_curvature(top):
    """Menger curvature 4 area / (|a| |b| |c|) of the triangle through the three top positions
    (arc lengths 0, L/20, L/10): the curvature of the circle through them, per sample."""
    p0, p1, p2 = top[:, 0], top[:, 1], top[:, 2]
    a, b, c = p1 - p0, p2 - p1, p2 - p0
    cross = np.linalg.norm(np.cross(a, b), axis=1)
    return 2.0 * cross / (np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1) * np.linalg.norm(c, axis=1))


def errors(run, ref):
    """Error metrics of `run` against `ref` on the common samples (t > 0)."""
    sl = slice(1, None)
    T = np.linalg.norm(run.force, axis=1)[sl]
    Tr = np.linalg.norm(ref.force, axis=1)[sl]
    rng = Tr.max() - Tr.min()
    de = np.linalg.norm(run.end - ref.end, axis=1)[sl]
    dm = np.linalg.norm(run.mid - ref.mid, axis=1)[sl]
    k, kr = top_curvature(run.top)[sl], top_curvature(ref.top)[sl]
    out = {"tension": float(np.max(np.abs(T - Tr)) / rng),
            "tension_rms": float(np.sqrt(np.mean((T - Tr) ** 2)) / rng),
            "tension_rmsrel": float(np.sqrt(np.mean((T - Tr) ** 2) / np.mean(Tr**2))),
            "end_rms": float(np.sqrt(np.mean(de**2))), "end_max": float(de.max()),
            "mid_rms": float(np.sqrt(np.mean(dm**2))), "mid_max": float(dm.max())}
    if np.all(np.isfinite(k)) and np.mean(kr**2) > 0:  # MoorDyn has nodes at the top stations only when 20 divides N
        out["curv_top"] = float(np.sqrt(np.mean((k - kr) ** 2) / np.mean(kr**2)))
    return out


def pareto(points):
    """(cpu, err) pairs -> Pareto front sorted by cpu (each point better in error than all cheaper)."""
    front, best = [], math.inf
    for cpu, err in sorted(points):
        if err < best and err > 0:
            front.append((cpu, err))
            best = err
    return front


def cpu_at_error(front, err, bound=False):
    """CPU of a Pareto front at error `err` by log-log interpolation; None outside its range.
    With bound=True, outside the range: (cpu, kind) with the front's end as a bound on the CPU
    at that error: kind "<=" (err above the cheapest run's error: a cheaper run would do) or ">="
    (err below the most accurate run's error: it would cost more than that run)."""
    if not front:
        return None
    errs = [e for _, e in front]
    if err > errs[0] or err < errs[-1]:
        if not bound:
            return None
        return (front[0][0], "<=") if err > errs[0] else (front[-1][0], ">=")
    for (c0, e0), (c1, e1) in zip(front, front[1:]):
        if e1 <= err <= e0:
            if e0 == e1:
                return c0
            w = (math.log(err) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(c0) + w * (math.log(c1) - math.log(c0)))
    return front[0][0]


def matched_ratios(runs, metric):
    runs = [r for r in runs if metric in r.errors]
    ours = pareto([(r.cpu, r.errors[metric]) for r in runs if r.code == "ours"])
    md = pareto([(r.cpu, r.errors[metric]) for r in runs if r.code == "MoorDyn"])
    rows = []
    for r in runs:
        if r.code != "MoorDyn":
            continue
        e = r.errors[metric]
        c_ours = cpu_at_error(ours, e, bound=True)
        kind = "="
        if isinstance(c_ours, tuple):
            c_ours, kind = c_ours
            kind = ">=" if kind == "<=" else "<="  # bound on our CPU -> opposite bound on the ratio
        c_md = cpu_at_error(md, e)
        rows.append((r.label, e, c_md if c_md is not None else r.cpu, c_ours, kind))
    return rows


# ----------------------------------------------------------------------------- main
def parse_args(argv):
    p = argparse.ArgumentParser(prog="scripts/bench_work_precision", description=__doc__.split("\n")[0])
    p.add_argument("--quick", action="store_true",
                   help="CI size: one small grid point per code and a cheaper reference")
    p.add_argument("--cases", nargs="+", default=None, help="cases to run (default: all)")
    p.add_argument("--out", type=Path, default=OUT_DIR, help="output directory (CSV-like log, PNG)")
    p.add_argument("--doc", type=Path, default=None,
                   help="write the markdown report here (full mode default: docs/performance.md)")
    p.add_argument("--switches", action=argparse.BooleanOptionalAction, default=None,
                   help="also tabulate the cost of each model switch (default: on in full mode)")
    p.add_argument("--fmu", type=Path, default=None)
    p.add_argument("--appendices", action="store_true",
                   help="only rewrite the report's appendices from docs/performance_limits.md and "
                        "docs/performance_profile.md (runs nothing)")
    args = p.parse_args(argv)
    if args.switches is None:
        args.switches = not args.quick
    return args


REPEAT_BELOW = 0.5  # [s]: runs of either code cheaper than this are timed REPEATS times, the fastest counts
REPEATS = 3


def fastest(run_once):
    """run_once() (a Run, or None when it failed), timed by the fastest of REPEATS runs when it is cheap:
    the cheap runs take 0.02-0.5 s, where this shared machine's noise is 10-30 %."""
    run = run_once()
    if run is not None and run.cpu < REPEAT_BELOW:
        for _ in range(REPEATS - 1):
            again = run_once()
            if again is not None:
                run.cpu = min(run.cpu, again.cpu)
    return run


def run_case(fmu, case, quick, progress_label=""):
    mode = "quick" if quick else "full"
    ref_n, ref_tol = case.reference[mode]
    # a grid point of ours is (N, tensionTolerance) or (N, tensionTolerance, further parameters)
    jobs = ([("ours", g[0], g[1:]) for g in case.fmu_grid[mode]]
            + [("MoorDyn", n, f) for n, f in case.md_grid[mode]])
    bar = ProgressBar(len(jobs) + 1, label=f"{progress_label}{case.name}")
    bar.update(0, "reference")
    ref = run_fmu(fmu, case, ref_n, ref_tol, step=case.reference_step,
                  label=f"ours N={ref_n} tol={ref_tol:.0e}"
                        + (f" step={case.reference_step:g}" if case.reference_step else "") + " (reference)")
    shape0 = ref.stats.pop("shape0") if case.anchor is None else None  # steady state at t = 0
    end_guess = shape0
    runs, limits = [], {}
    for j, (code, n, setting) in enumerate(jobs):
        bar.update(j + 1, f"{code} N={n}")
        if code == "ours":
            runs.append(fastest(lambda: run_fmu(fmu, case, n, setting[0], extra=setting[1] if len(setting) > 1 else None)))
        else:
            if n not in limits:
                limits[n] = moordyn_stable_dt(case, n, end_guess)
            dt = setting * limits[n][0]
            run = fastest(lambda: run_moordyn(case, n, dt, end_guess))
            while run is None and dt > 0.2 * limits[n][0]:  # unstable over the full run: back off
                dt *= 0.8
                run = fastest(lambda: run_moordyn(case, n, dt, end_guess))
            if run is not None:
                run.stats["dt_limit"] = limits[n][0]
                run.stats["cfl_limit"] = limits[n][1]
                runs.append(run)
    bar.update(len(jobs) + 1, "done")
    bar.close(f"{case.name}: {len(runs)} runs")
    for r in runs + [ref]:
        r.errors = errors(r, ref)
    return ref, runs, limits


METRIC_LABELS = {
    "tension": "tension error (max, rel. to range)",
    "tension_rmsrel": "tension error (RMS, rel. to RMS)",
    "curv_top": "top curvature error (RMS, rel. to RMS)",
    "end_rms": "end position RMS [m]", "end_max": "end position max [m]",
    "mid_rms": "mid position RMS [m]", "mid_max": "mid position max [m]",
}


def stat_cells(st):
    """Integrator statistics of a run: ours from the solver.* outputs, MoorDyn its step count."""
    steps = int(st.get("solver.nSteps", st.get("steps", 0)))
    rest = [st.get(k) for k in FMU_STATS[1:]]
    return [str(steps)] + ["" if v is None else str(int(v)) for v in rest]


def fmt_table(case, ref, runs):
    cols = case.columns
    head = ("| code | resolution | step / tolerance | CPU [s] | CPU s per simulated s | real-time factor | "
            + " | ".join(METRIC_LABELS[c] for c in cols)
            + " | steps | residual evals | Jacobian evals | nonlinear failures | error-test failures |")
    lines = [head, "|" + "---|" * (11 + len(cols))]
    for r in runs + [ref]:
        resolution = f"{r.resolution} {'elements' if r.code == 'ours' else 'segments'}"
        errs = " | ".join(f"{r.errors[c]:.2e}" if c in r.errors else "-" for c in cols)
        lines.append(
            f"| {r.code}{' (reference)' if r is ref else ''} | {resolution} | {r.setting} | {r.cpu:.3f} | "
            f"{r.cpu / case.t_end:.2e} | {case.t_end / r.cpu:.0f} | {errs} | "
            + " | ".join(stat_cells(r.stats)) + " |")
    return "\n".join(lines)


def fmt_ratios(case, runs):
    out = []
    for metric in case.metrics:
        name = METRIC_LABELS[metric].split(" [")[0]
        rows = matched_ratios(runs, metric)
        out.append(f"\nAt matched {name} (each MoorDyn run; our CPU interpolated log-log on our "
                   f"Pareto front of error vs CPU; outside our measured error range the front's end "
                   f"gives a bound):\n")
        out.append("| MoorDyn run | error | MoorDyn CPU at that error (its Pareto front) [s] | our CPU at that error [s] "
                   "| ratio MoorDyn/ours |")
        out.append("|---|---|---|---|---|")
        for label, e, c_md, c_ours, kind in rows:
            note = {"=": "", ">=": " (our cheapest run is more accurate: a bound)",
                    "<=": " (beyond our most accurate run: a bound)"}[kind]
            ratio = f"{'' if kind == '=' else kind + ' '}{c_md / c_ours:.2f}{note}" if c_ours else "-"
            c_o = f"{'' if kind == '=' else ('<= ' if kind == '>=' else '>= ')}{c_ours:.3f}" if c_ours else "-"
            out.append(f"| {label} | {e:.2e} | {c_md:.3f} | {c_o} | {ratio} |")
    return "\n".join(out)


def plot(case, ref, runs, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, metric in zip(axes, case.metrics):
        for code, marker in (("ours", "o"), ("MoorDyn", "s")):
            rs = [r for r in runs if r.code == code and r.errors.get(metric, 0) > 0]
            if not rs:
                continue
            ax.loglog([r.cpu for r in rs], [r.errors[metric] for r in rs], marker, label=code)
            for r in rs:
                ax.annotate(f"{r.resolution}", (r.cpu, r.errors[metric]), fontsize=7,
                            textcoords="offset points", xytext=(3, 3))
            front = pareto([(r.cpu, r.errors[metric]) for r in rs])
            ax.loglog([c for c, _ in front], [e for _, e in front], "-", alpha=0.5)
        ax.set_xlabel("CPU time [s]")
        ax.set_ylabel(METRIC_LABELS[metric])
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.suptitle(case.title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


DEFAULT_TOLERANCE = 1e-3  # the FMU's default tensionTolerance
SWITCHES = [("default (20 elements, tensionTolerance 1e-3)", 20, {}),
             ("enableBending = 0", 20, {"enableBending": 0}),
             ("enableAddedMass = 0", 20, {"enableAddedMass": 0}),
             ("axialDamping = 1e-3 s x EA", 20, "damping"),
             ("nElements = 10", 10, {}), ("nElements = 40", 40, {})]


# Real-time targets, per case: (metric, error bound or None, real-time factor required there).
TARGETS = {
    "hopland": [("end_rms", 0.018, 900.0), ("end_rms", 0.3, 14000.0)],
    "mooring": [("tension_rmsrel", 0.01, 360.0)],
    "stiff": [(None, None, 500.0)],
}


@dataclass
class RatioTarget:
    """CPU ratio MoorDyn / ours required at matched error: at every MoorDyn run whose error is at
    most max_error (None: every run), or at the error `at` (both codes interpolated on their
    Pareto fronts)."""
    metric: str
    ratio: float
    max_error: float | None = None
    at: float | None = None

    def text(self) -> str:
        what = METRIC_LABELS[self.metric].split(" [")[0]
        if self.at is not None:
            return f">= {self.ratio:g}x at {what} {self.at:g}"
        return f">= {self.ratio:g}x at every matched {what}" + (
            f" from {self.max_error:g} down" if self.max_error is not None else "")


RATIO_TARGETS = {
    "hopland": [RatioTarget("tension", 10.0), RatioTarget("end_rms", 10.0)],
    "stiff": [RatioTarget("tension", 10.0), RatioTarget("curv_top", 10.0)],
    "mooring": [RatioTarget("tension_rmsrel", 1.0), RatioTarget("tension_rmsrel", 3.0, at=0.02)],
    "heave": [RatioTarget("tension_rmsrel", 1.0, max_error=0.01), RatioTarget("tension_rmsrel", 5.0, at=0.001)],
}


def ratio_verdict(runs, target: RatioTarget):
    """(cells text, verdict "met" / "NOT met" / "undecided", measured text)."""
    if target.at is not None:
        def at(code):
            front = pareto([(r.cpu, r.errors[target.metric]) for r in runs
                            if r.code == code and target.metric in r.errors])
            c = cpu_at_error(front, target.at, bound=True)
            return (None, None) if c is None else (c if isinstance(c, tuple) else (c, "="))
        (c_m, k_m), (c_o, k_o) = at("MoorDyn"), at("ours")
        if c_m is None or c_o is None:
            return "", "undecided", "no runs"
        ratio = c_m / c_o
        # a bound on a CPU: "<=" (the cheapest run is more accurate) or ">=" (beyond the most accurate run)
        lower = k_m in ("=", ">=") and k_o in ("=", "<=")
        upper = k_m in ("=", "<=") and k_o in ("=", ">=")
        kind = "=" if lower and upper else ">=" if lower else "<=" if upper else "?"
        note = {"=": "", ">=": " (a lower bound)", "<=": " (an upper bound)", "?": " (both bounds the same way: unknown)"}[kind]
        measured = (f"{'' if kind == '=' else kind + ' '}{ratio:.2f}{note}: MoorDyn {'' if k_m == '=' else k_m + ' '}"
                    f"{c_m:.3g} s, ours {'' if k_o == '=' else k_o + ' '}{c_o:.3g} s at {target.at:g}")
        verdict = ("met" if ratio >= target.ratio else "NOT met") if kind == "=" else (
            "met" if kind == ">=" and ratio >= target.ratio else
            "NOT met" if kind == "<=" and ratio < target.ratio else "undecided")
        return measured, verdict, measured
    rows = [row for row in matched_ratios(runs, target.metric)
            if target.max_error is None or row[1] <= target.max_error]
    if not rows:
        return "", "undecided", "no MoorDyn run in that error range"
    cells = ", ".join(f"{lab.split(' dt=')[0].replace('MoorDyn ', '')}: "
                      f"{'' if kind == '=' else kind + ' '}{c_md / c_o:.2f}"
                      for lab, _, c_md, c_o, kind in rows)
    fail = [1 for _, _, c_md, c_o, kind in rows if kind != ">=" and c_md / c_o < target.ratio]
    open_ = [1 for _, _, c_md, c_o, kind in rows if kind == ">=" and c_md / c_o < target.ratio]
    verdict = "NOT met" if fail else "undecided" if open_ else "met"
    return cells, verdict, cells


def targets_text(case, runs):
    """The targets against this run's measurements (never relaxed: the gap is stated)."""
    ours = [r for r in runs if r.code == "ours"]
    lines = []
    for metric, bound, rt in TARGETS.get(case.name, []):
        ok = [r for r in ours if bound is None or r.errors.get(metric, math.inf) <= bound]
        what = "any accuracy" if bound is None else f"{METRIC_LABELS[metric].split(' [')[0]} <= {bound:g}"
        if not ok:
            lines.append(f"- target >= {rt:g}x real time at {what}: no run of ours reached that error.")
            continue
        best = min(ok, key=lambda r: r.cpu)
        got = case.t_end / best.cpu
        verdict = "met" if got >= rt else f"NOT met: gap {rt / got:.1f}x"
        lines.append(f"- target >= {rt:g}x real time at {what}: best {got:.0f}x ({best.label}); {verdict}.")
    for target in RATIO_TARGETS.get(case.name, []):
        cells, verdict, _ = ratio_verdict(runs, target)
        lines.append(f"- CPU ratio MoorDyn/ours, target {target.text()}: {cells or '-'}; {verdict}"
                     + (" (a lower bound below the target decides nothing)" if verdict == "undecided" else "") + ".")
    md = [r for r in runs if r.code == "MoorDyn"]
    if md:
        fin = max(md, key=lambda r: (r.resolution, -r.stats.get("dt", 0)))
        errs = ", ".join(f"{METRIC_LABELS[c].split(' [')[0]} {fin.errors[c]:.2e}"
                         + (" m" if "position" in METRIC_LABELS[c] else "")
                         for c in case.columns if c in fin.errors)
        lines.append(f"- Reference check: MoorDyn's finest run ({fin.label}) against our reference: {errs}.")
    fin = max(ours, key=lambda r: (r.resolution, -float(r.setting.split()[-1]))) if ours else None
    # compression above 1 % of the peak fairlead tension changes the snap dynamics
    if fin is not None and fin.stats.get("minTension", 0.0) < -0.01 * np.linalg.norm(fin.force, axis=1).max():
        no_ei = case.fmu_params.get("enableBending", 1) == 0
        if case.fmu_params.get("enableCompression", 1) == 0:
            lines.append(
                f"- Compression: our minimum axial force over the cable during the run is "
                f"{fin.stats['minTension'] / 1e3:.0f} kN ({fin.label}). Tension-only acts on each element's "
                "mean tension, the force it transmits, as on MoorDyn's segments; the strain's higher modes "
                "inside an element stay two-sided (they only shape it), so inside a slack element the axial "
                "force at a station can dip below zero while the element transmits none.")
        else:
            lines.append(
                f"- Compression: our minimum axial force over the cable during the run is "
                f"{fin.stats['minTension'] / 1e3:.0f} kN ({fin.label}): our cable is an elastic rod "
                "that also carries compression"
                + (" (here without bending stiffness, so the compressed part has no length scale of "
                   "its own and resolves with the mesh)" if no_ei else "")
                + ", while MoorDyn's lines are tension-only (a slack segment carries no force). The "
                "two codes therefore converge to different snap dynamics, which bounds their "
                "agreement above.")
    for r in ours:
        st = r.stats
        if r.resolution == 20 and r.setting == f"tensionTolerance {DEFAULT_TOLERANCE:.0e}" and "solver.nSteps" in st:
            n = st["solver.nSteps"]
            lines.append(
                f"- Integrator, ours N=20 at the default tolerance: {int(n)} steps in {case.t_end:g} s (mean step "
                f"{1e3 * case.t_end / n:.2f} ms), {st['solver.nResidualEvals'] / n:.2f} residual and "
                f"{st['solver.nJacobianEvals'] / n:.2f} Jacobian evaluations per step, "
                f"{int(st['solver.nErrorTestFailures'])} error-test and "
                f"{int(st['solver.nNonlinearFailures'])} nonlinear failures; "
                f"{1e6 * r.cpu / n:.0f} us CPU per step.")
    return "\n".join(lines)


def calm_table(fmu, case, runs):
    """Each of our runs next to the same run in calm water: (rows, Markdown)."""
    rows = []
    for r in [x for x in runs if x.code == "ours"]:
        tol = r.tolerance
        calm = run_fmu(fmu, case, r.resolution, tol, extra={**r.extra, **case.calm_twin})
        rows.append((r.resolution, tol, calm.cpu, r.cpu, int(calm.stats["solver.nSteps"]),
                     int(r.stats["solver.nSteps"]), calm.stats["solver.nResidualEvals"],
                     r.stats["solver.nResidualEvals"]))
    lines = ["| resolution | tensionTolerance | CPU calm [s] | CPU in waves [s] | waves / calm | steps calm | "
             "steps in waves | CPU per residual evaluation calm [us] | in waves [us] |", "|---|---|---|---|---|---|---|---|---|"]
    for n, tol, c_calm, c_waves, s_calm, s_waves, r_calm, r_waves in rows:
        lines.append(f"| {n} elements | {tol:.0e} | {c_calm:.3f} | {c_waves:.3f} | {c_waves / c_calm:.1f} | {s_calm} | "
                     f"{s_waves} | {1e6 * c_calm / r_calm:.1f} | {1e6 * c_waves / r_waves:.1f} |")
    return rows, "\n".join(lines)


STILL_TOLERANCE = 1e-1  # the still twin is run for our runs at this tensionTolerance (the cheap end)


def still_rows(fmu, case, runs):
    """Our runs at STILL_TOLERANCE next to the same runs with the fairlead held still:
    (resolution, setting, CPU moving, CPU still, steps moving, steps still, communication points)."""
    still_case = replace(case, traj=HeldStill(case.traj))
    rows = []
    for r in [x for x in runs if x.code == "ours" and x.tolerance == STILL_TOLERANCE]:
        still = fastest(lambda: run_fmu(fmu, still_case, r.resolution, r.tolerance, extra=r.extra))
        rows.append((r.resolution, r.setting, r.cpu, still.cpu, int(r.stats["solver.nSteps"]),
                     int(still.stats["solver.nSteps"]), len(r.t) - 1))
    return rows


def still_table(rows) -> str:
    lines = ["| resolution | setting | CPU [s] | CPU held still [s] | held still / moving | steps | steps held still | "
             "CPU per communication point held still [us] |", "|---|---|---|---|---|---|---|---|"]
    for n, setting, c_move, c_still, s_move, s_still, points in rows:
        lines.append(f"| {n} elements | {setting} | {c_move:.3f} | {c_still:.3f} | {c_still / c_move:.2f} | {s_move} | "
                     f"{s_still} | {1e6 * c_still / points:.1f} |")
    return "\n".join(lines)


def switch_table(fmu, case, ref):
    """What each model switch costs and how much it changes the answer."""
    cols = case.metrics
    lines = ["| model (ours) | CPU [s] | real-time factor | " + " | ".join(METRIC_LABELS[c] for c in cols)
             + " | steps | residual evals | Jacobian evals | nonlinear failures | error-test failures |",
             "|" + "---|" * (8 + len(cols))]
    switches = list(SWITCHES)
    if case.seabed is not None:
        switches.insert(3, ("enableSeabed = 0", 20, {"enableSeabed": 0}))
    if case.fmu_params.get("enableCompression", 1) == 0:
        switches.insert(1, ("enableCompression = 1 (two-sided)", 20, {"enableCompression": 1}))
    for label, n, extra in switches:
        if extra == "damping":
            extra = {"axialDamping": 1e-3 * case.line["EA"]}
        if case.fmu_params.get("enableBending", 1) == 0 and extra == {"enableBending": 0}:
            continue  # already off in this case (a chain)
        try:
            r = run_fmu(fmu, case, n, DEFAULT_TOLERANCE, extra=extra)
        except Exception as exc:  # a switch the FMU rejects is reported, not hidden
            lines.append(f"| {label} | failed: {exc} |" + " |" * (7 + len(cols)))
            continue
        r.stats.pop("shape0", None)
        e = errors(r, ref)
        errs = " | ".join(f"{e[c]:.2e}" if c in e else "-" for c in cols)
        lines.append(f"| {label} | {r.cpu:.3f} | {case.t_end / r.cpu:.0f} | {errs} | "
                     + " | ".join(stat_cells(r.stats)) + " |")
    return "\n".join(lines)


def main(argv=None) -> int:
    args = parse_args(sys.argv[1:] if argv is None else argv)
    if args.appendices:
        doc = args.doc or DOC
        doc.write_text(with_appendices(doc.read_text(), doc.parent))
        print(f"updated the appendices of {doc}")
        return 0
    fmu = args.fmu if args.fmu is not None else require_fmu()
    cases = make_cases()
    names = args.cases or list(cases)
    args.out.mkdir(parents=True, exist_ok=True)
    doc = args.doc if args.doc is not None else (None if args.quick else DOC)
    sections = []
    for name in names:
        case = cases[name]
        ref, runs, limits = run_case(fmu, case, args.quick)
        table = fmt_table(case, ref, runs)
        ratios = fmt_ratios(case, runs)
        png = args.out / f"{case.name}_work_precision.png"
        plot(case, ref, runs, png)
        lim = "; ".join(f"N = {n}: dt_max = {d:.3g} s = {c:.2f} x segment / axial wave speed"
                        for n, (d, c) in sorted(limits.items()))
        has_md = any(r.code == "MoorDyn" for r in runs)
        text = (f"## {case.title}\n\n{case.description}\n\n"
                + (f"MoorDyn stable limit (bisection, RK2): {lim}.\n\n" if limits else "")
                + f"{table}\n" + (f"{ratios}\n" if has_md else "")
                + f"\nTargets against this run:\n\n"
                f"{targets_text(case, runs)}\n\n![work-precision {case.name}]({png.name})\n")
        if case.calm_twin is not None:
            text += ("\n### The same runs in calm water (the price of the wave kinematics)\n\n"
                     + calm_table(fmu, case, runs)[1] + "\n")
        if case.still_twin and not args.quick:
            text += ("\n### The price of the communication points (the cheap runs with the fairlead held still)\n\n"
                     f"Our runs at tensionTolerance {STILL_TOLERANCE:g} again with the fairlead held where it starts: "
                     "the same communication steps, inputs set and outputs read at each, one integrator step "
                     "each. What they cost is a floor under any run of this case driven at these steps.\n\n"
                     + still_table(still_rows(fmu, case, runs)) + "\n")
        if args.switches and case.calm_twin is None:
            text += ("\n### What each switch costs (ours; errors against the reference above)\n\n"
                     + switch_table(fmu, case, ref) + "\n")
        print(text, flush=True)
        sections.append((case, ref, runs, text, png))
    if doc is not None:
        if args.cases and set(names) != set(cases) and doc.is_file():
            splice_doc(doc, sections)  # a partial run updates its own sections only
        else:
            write_doc(doc, sections, args)
    return 0


def splice_sections(text: str, sections) -> str:
    """text with each case's section ("## <title>" up to the next "## " heading) replaced by the new one,
    or, when it has none yet, inserted after the section of case.doc_after (else before the first
    section that is not a case's, else at the end)."""
    def bounds(lines, title):
        head = f"## {title}"
        for i, line in enumerate(lines):
            if line.strip() == head:
                j = i + 1
                while j < len(lines) and not lines[j].startswith("## "):
                    j += 1
                return i, j
        return None

    cases = make_cases()
    lines = text.split("\n")
    for case, ref, runs, section, png in sections:
        new = section.rstrip("\n").split("\n") + [""]
        where = bounds(lines, case.title)
        if where is not None:
            lines[where[0]:where[1]] = new
            continue
        after = bounds(lines, cases[case.doc_after].title) if case.doc_after in cases else None
        at = after[1] if after is not None else appendix_start(lines)
        lines[at:at] = new
    return "\n".join(lines)


def splice_glance(text: str, sections) -> str:
    """text with the rows of the "Targets at a glance" table that belong to the cases of `sections`
    replaced by this run's (the other cases' rows stay as they are)."""
    names = {s[0].name for s in sections}
    case_of = lambda line: line.split(" | ")[0][2:] if line.startswith("| ") else None
    lines = text.split("\n")
    head = next((i for i, line in enumerate(lines) if line.strip() == "## Targets at a glance"), None)
    if head is None:
        return text
    end = next((i for i in range(head + 1, len(lines)) if lines[i].startswith("## ")), len(lines))
    table = [i for i in range(head + 1, end) if lines[i].startswith("|")]
    if not table:
        return text
    old = [i for i in table if case_of(lines[i]) in names]
    at = old[0] if old else table[-1] + 1
    new_rows = [row for row in glance_table(sections).split("\n") if case_of(row) in names]
    for i in reversed(old):
        del lines[i]
    lines[at:at] = new_rows
    return "\n".join(lines)


APPENDICES = ("performance_limits.md", "performance_profile.md")  # hand-written / callgrind, next to the report


def appendix_text(folder: Path) -> str:
    """The report's appendices as they are now in `folder`."""
    return "\n".join(f.read_text() for f in (folder / name for name in APPENDICES) if f.is_file())


def appendix_start(lines) -> int:
    """Index of the report's first appendix line: the first "## " section that is neither a case's nor
    the targets at a glance (len(lines) when there is none)."""
    heads = {f"## {case.title}" for case in make_cases().values()} | {"## Targets at a glance"}
    return next((i for i, line in enumerate(lines) if line.startswith("## ") and line.strip() not in heads), len(lines))


def with_appendices(text: str, folder: Path) -> str:
    """text with its appendices replaced by those in `folder` now."""
    lines = text.split("\n")
    return "\n".join(lines[:appendix_start(lines)]) + "\n" + appendix_text(folder)


def splice_doc(doc: Path, sections) -> None:
    import shutil
    for case, ref, runs, text, png in sections:
        if png.resolve() != (doc.parent / png.name).resolve():
            shutil.copy(png, doc.parent / png.name)
    text = splice_glance(splice_sections(doc.read_text(), sections), sections)
    doc.write_text(with_appendices(text, doc.parent))
    print(f"updated {doc} (the sections of {', '.join(s[0].name for s in sections)})")


def glance_table(sections) -> str:
    """The CPU-ratio targets of every case against this run, one row each."""
    lines = ["## Targets at a glance", "",
             "CPU ratio MoorDyn / ours at matched error, from the tables below (each code's Pareto front "
             "of error against CPU, interpolated log-log; outside a code's measured range the front's end "
             "gives a bound, and a lower bound below the target decides nothing).", "",
             "| case | target | measured | verdict |", "|---|---|---|---|"]
    for case, ref, runs, text, png in sections:
        for target in RATIO_TARGETS.get(case.name, []):
            _, verdict, measured = ratio_verdict(runs, target)
            lines.append(f"| {case.name} | {target.text()} | {measured} | {verdict} |")
    return "\n".join(lines) + "\n"


def write_doc(doc, sections, args):
    import shutil
    doc.parent.mkdir(parents=True, exist_ok=True)
    parts = [DOC_HEADER, glance_table(sections)]
    for case, ref, runs, text, png in sections:
        if png.resolve() != (doc.parent / png.name).resolve():
            shutil.copy(png, doc.parent / png.name)
        parts.append(text)
    parts.append(appendix_text(doc.parent))
    doc.write_text("\n".join(parts))
    print(f"wrote {doc}")


DOC_HEADER = """# Performance: work-precision against MoorDyn

Generated by `bash scripts/bench_work_precision` (do not edit by hand; the section on the unmet
targets comes from `docs/performance_limits.md`, the profile section from
`docs/performance_profile.md`, written by `bash scripts/profile_callgrind`).
CPU is `time.process_time()` of the stepping loop of each code driven from Python on the same
machine in one run (our FMU through fmpy, MoorDyn through its `moordyn` Python module calling
`moordyn.Step` every MoorDyn time step); runs of either code under 0.5 s are timed three times and
the fastest counts; absolute times vary on this shared machine, ratios much less. Errors are measured against our finest run (the reference row). Ours run on grids of
nElements x tensionTolerance (the integrator's tolerance in tension, relative to the tension scale:
docs/error_control.md; the default is 1e-3; some runs also with a looser positionTolerance,
projectedErrorControl, seabedContactSpacing or solver.maxOrder, as their rows say); MoorDyn on grids of segments at 0.9 x its stable step.

How the two models are matched: same line properties; Morison drag normal on d and tangential on
pi d in both codes (MoorDyn's CdAx is defined on pi d); normal added mass Can on the displaced
volume, no tangential added mass; gravity 9.81, water 1025 kg/m3; bending stiffness EI given to
MoorDyn as well (its v2 lines have bending). Internal axial damping: in the Hopland tow each code
runs as its users run it, ours with its default axialDamping (0.01 s x the cable's EA), MoorDyn with
BA/-zeta = -0.8 (80 % of critical damping of the segment axial mode, resolution dependent); there
the damping's effect on the slow outputs compared is below the errors shown (see the switch table:
axialDamping). The same holds for the stiff power cable's top curvature (ours at its default
axialDamping, 6.7e5 N s = 1 ms x its EA; with 0.01 s x EA our curvature errors at 10 / 20 / 40
elements moved from 4.8 / 0.36 / 0.06 % to 4.75 / 0.36 / 0.058 %). In the chain and the heave case
the axial dynamics are part of the answer (the chain's snap is an axial wave: its reference fairlead
tension moves by 2.3 % RMS between 0.01 s x EA and the FMU's default, which is 0.01 s x the default
EA, 0.9 ms x the chain's), so both codes get the same material damping, BA = axialDamping = 0.01 s x
EA, as the FMU's documentation tells users to set it. MoorDyn applies drag per stretched length,
ours per unstretched length (strain < 1e-4 here). MoorDyn lumps mass and loads at nodes, so its
tow-point force includes the half-segment node's weight, drag and inertia: this is part of its
discretization error and converges to the rod-end force as N grows.
"""


if __name__ == "__main__":
    sys.exit(main())
