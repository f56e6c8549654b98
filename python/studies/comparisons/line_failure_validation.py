"""Validations of a line failure (docs/line_failure.md, "Validation"), run by scripts/line_failure_report:

a. release wave: a taut, neutrally buoyant elastic line released at its fairlead. Its anchor force holds T0 until
   the release wave arrives at t = L0/c, c = sqrt(EA/m) (L0 the unstretched length, m the deck's mass per
   unstretched length: the axial added mass CaAx is 0 and a transverse added mass does not act on an axial wave),
   then falls to 0 (a tension-only line cannot carry the compression a bar would reflect). At 10, 20, 40 elements:
   the arrival time error and the anchor force before the arrival.
b. settled pose: the OC4 semisubmersible free in surge, sway and yaw (its mass and added mass, yaw inertia,
   damping) under a steady environmental load; line 1 breaks; the platform settles where MoorPy's equilibrium
   with line 1 removed puts it (the same load, the body's surge, sway and yaw free), and the remaining lines'
   tensions are MoorPy's.
c. momentum: in case a, the broken line's momentum (its mass times the velocity of its centre of mass, from the
   21 stations' positions) equals the impulse of the forces on it, ∫ (T_fairlead - T_anchor) dt: the impulse the
   body no longer receives (the lost tension) goes into the line until the anchor feels the release.
d. MoorDyn side by side: studies.comparisons.line_failure (BreakLine), run in a child process (MoorDyn is loaded
   before the FMU's modules there).

compute() returns the numbers, markdown() the section."""

from __future__ import annotations

import math
import tempfile
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.free_body import LOAD_NAMES, FreeBody
from ucable.units import WATER_DENSITY

from . import mooring_system as ms
from ..peers import moorpy

# ----------------------------------------------------------------------------------------------- a. release wave
DIAMETER = 0.1                                        # [m]
MASS = WATER_DENSITY * math.pi / 4 * DIAMETER ** 2   # [kg/m] neutrally buoyant: weight = buoyancy
EA = 1.0e6                                            # [N]
L0 = 200.0                                            # [m] unstretched
STRAIN = 0.01                                         # the initial stretch: T0 = EA * STRAIN
DEPTH, Z = 300.0, -100.0                              # water depth, the lines' depth [m]
FAIRLEAD_X = 10.0                                     # the fairleads on the body at x = +-10 m
T_RELEASE = 0.0500                                     # [s]
CENTROID_UNTIL = 1.35   # [L0/c] the deficit is taken up to this time after the release (the front has passed)
MOMENTUM_UNTIL = 0.9    # [L0/c] the momentum check while the anchor holds T0


def taut_deck() -> str:
    """Two taut horizontal lines along x from anchors to the body's fairleads at +-10 m, 100 m down; line 1
    (anchor 1 at -x) is released at its fairlead (point 3) by the deck's FAILURE row."""
    span = FAIRLEAD_X + L0 * (1.0 + STRAIN)
    return f"""--------------------- MoorDyn Input File ------------------------------------
Two taut neutrally buoyant elastic lines (line failure validation: release wave)
----------------------- LINE TYPES ------------------------------------------
Name     Diam      MassDen       EA    BA/-zeta    EI    Cd      Ca     CdAx   CaAx
(-)       (m)      (kg/m)        (N)    (N-s/-)    (-)   (-)     (-)    (-)    (-)
taut     {DIAMETER}    {MASS:.10g}    {EA:.6g}     0.0      0    1.2     1.0    0.0    0.0
---------------------- POINTS --------------------------------
ID     Attachment  X        Y         Z      M      V       CdA   CA
(-)    (-)        (m)      (m)       (m)    (kg)   (m^3)   (m^2)  (-)
1      Fixed    {-span:.10g}    0.0    {Z}     0       0       0     0
2      Fixed    {span:.10g}     0.0    {Z}     0       0       0     0
3      Vessel   {-FAIRLEAD_X}   0.0    {Z}     0       0       0     0
4      Vessel   {FAIRLEAD_X}    0.0    {Z}     0       0       0     0
---------------------- LINES --------------------------------------
ID      LineType   AttachA   AttachB  UnstrLen  NumSegs   Outputs
(-)       (-)        (-)       (-)       (m)      (-)       (-)
1         taut        1         3       {L0}     20        -
2         taut        2         4       {L0}     20        -
---------------------- FAILURE ---------------------------------------
ID    Point   Line(s)   FailTime   FailTen
()    ()      (,)       (s)        (N)
1     3       1         {T_RELEASE}    0
---------------------- SOLVER OPTIONS ---------------------------------------
{DEPTH}    WtrDpth   - water depth (m)
---------------------- OUTPUTS --------------------------------------------
END
------------------------- need this line --------------------------------------
"""


def wave_speed() -> float:
    return math.sqrt(EA / MASS)


STATIONS = 21
X_NAMES = [f"shape.x[{k}]" for k in range(1, STATIONS + 1)]


def release_run(fmu, elements: int, h: float, t_end: float, deck: Path) -> dict:
    """Line 1's anchor and fairlead tensions and its stations' x every h from 0 to t_end (the body held)."""
    names = ["line[1].anchorTension", "line[1].fairleadTension", "line[1].broken"] + X_NAMES
    with CableFMU(fmu, parameters={"lineFile": str(deck), "lineFileElements": elements,
                                   "enableCompression": False}) as c:
        c.initialize(inputs={"body[1].x": 0.0})
        rows = [c.get_reals(names)]
        n = int(round(t_end / h))
        for k in range(n):
            c.do_step(h, t=k * h)
            rows.append(c.get_reals(names))
    a = np.array(rows)
    return {"t": h * np.arange(len(rows)), "anchor": a[:, 0], "fairlead": a[:, 1], "broken": a[:, 2], "x": a[:, 3:]}


def crossing(t: np.ndarray, y: np.ndarray, level: float, after: float) -> float:
    """The first time after `after` at which y falls through level (linear between samples)."""
    for k in range(1, len(t)):
        if t[k] > after and y[k - 1] >= level > y[k]:
            return t[k - 1] + (y[k - 1] - level) / (y[k - 1] - y[k]) * (t[k] - t[k - 1])
    return math.nan


def momentum_check(run: dict, until: float) -> dict:
    """c: the line's momentum m L0 dx_cm/dt against the impulse ∫ (T_fairlead - T_anchor) dt, both from the
    release, compared through their time integrals (the centre of mass's displacement times m L0 against the
    double integral of the forces), at t_release + until."""
    t, x = run["t"], run["x"]
    # centre of mass: the stations are evenly spaced in unstretched length (trapezoid over them); stations run
    # from the fairlead (k = 1, at -10 m) to the anchor (k = 21, at -span)
    w = np.ones(STATIONS)
    w[0] = w[-1] = 0.5
    xcm = (x @ w) / w.sum()
    simpson = np.array([1.0] + [4.0 if k % 2 else 2.0 for k in range(1, STATIONS - 1)] + [1.0])
    xcm_s = (x @ simpson) / simpson.sum()  # the quadrature's error estimate: trapezoid against Simpson
    net = run["fairlead"] - run["anchor"]  # force on the line along +x: the fairlead pulls +x, the anchor -x
    k0 = int(round(T_RELEASE / (t[1] - t[0])))
    k1 = k0 + int(round(until / (t[1] - t[0])))
    h = t[1] - t[0]
    impulse = np.concatenate([[0.0], np.cumsum(0.5 * h * (net[k0 + 1:k1 + 1] + net[k0:k1]))])
    # the break is at the communication point t_release: the force is T0 - T0 = 0 before and -T_anchor after;
    # the sample at k0 is after the break (the step ended at it)
    moved = MASS * L0 * (xcm[k1] - xcm[k0])
    double = float(np.sum(0.5 * h * (impulse[1:] + impulse[:-1])))
    quadrature = MASS * L0 * abs((xcm_s[k1] - xcm_s[k0]) - (xcm[k1] - xcm[k0]))
    return {"displacement": float(xcm[k1] - xcm[k0]), "momentum_integral": moved, "quadrature": quadrature, "impulse_integral": double,
            "closed_form": -EA * STRAIN * until ** 2 / 2}


def release_wave(fmu, elements=(10, 20, 40)) -> dict:
    c = wave_speed()
    arrival = L0 / c
    T0 = EA * STRAIN
    h = T_RELEASE / 20.0  # the release at a communication point; L0/c is about 227 steps
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        deck = Path(tmp) / "taut.dat"
        deck.write_text(taut_deck())
        for n in elements:
            r = release_run(fmu, n, h, T_RELEASE + 1.4 * arrival, deck)
            t = r["t"]
            before = (t > T_RELEASE) & (t < T_RELEASE + 0.9 * arrival)
            t_half = crossing(t, r["anchor"], 0.5 * T0, T_RELEASE) - T_RELEASE
            # the front's centroid: with T falling from T0 to 0 at t_a, the deficit ∫ (T0 - T) dt up to a time t
            # after the front is T0 (t - t_a); a dispersed front keeps its centroid (its low frequencies travel at c)
            upto = (t >= T_RELEASE - 1e-12) & (t <= T_RELEASE + CENTROID_UNTIL * arrival + 1e-12)
            deficit = float(np.sum(0.5 * h * ((T0 - r["anchor"][upto])[1:] + (T0 - r["anchor"][upto])[:-1])))
            t_centroid = CENTROID_UNTIL * arrival - deficit / T0
            dev = np.abs(r["anchor"] / T0 - 1.0)
            first = t[(t > T_RELEASE) & (dev > 0.01)]
            mom = momentum_check(r, MOMENTUM_UNTIL * arrival)
            rows.append({"elements": n, "T_start": float(r["anchor"][0]), "arrival": t_half,
                         "error": t_half / arrival - 1.0, "centroid": t_centroid,
                         "centroid_error": t_centroid / arrival - 1.0,
                         "half_dev": float(np.max(dev[(t > T_RELEASE) & (t < T_RELEASE + 0.5 * arrival)])),
                         "precursor": float((first[0] - T_RELEASE) / arrival) if len(first) else math.nan,
                         "after": float(np.max(np.abs(r["anchor"][(t > T_RELEASE + 1.2 * arrival)
                                                                  & (t < T_RELEASE + CENTROID_UNTIL * arrival)]))),
                         "fairlead_after": float(np.max(np.abs(r["fairlead"][t > T_RELEASE + 1e-9]))),
                         "momentum": mom, "h": h})
    return {"T0": T0, "c": c, "arrival": arrival, "rows": rows}


# ----------------------------------------------------------------------------------------------- b. settled pose
PLATFORM_MASS = 1.3473e7 + 1.2e7        # [kg] OC4 semi (structure and ballast) plus its surge added mass
PLATFORM_INERTIA = 1.226e10 + 1.1e10   # [kg m2] yaw inertia plus added inertia (OC4 definition, HydroDyn's A66)
ENV_LOAD = 1.5e6                        # [N] steady environmental load, towards anchor 1 (60 degrees)
ENV_DIRECTION = math.radians(60.0)
SETTLE = 400.0                          # [s] the run after which the pose is compared


def env_load() -> tuple:
    return (ENV_LOAD * math.cos(ENV_DIRECTION), ENV_LOAD * math.sin(ENV_DIRECTION), 0.0)


def critical_damping(stiffness: float, inertia: float) -> float:
    return 2.0 * math.sqrt(stiffness * inertia)


def without_lines(text: str, removed: tuple) -> tuple:
    """A deck's text with the LINES rows of the IDs `removed` taken out and the rest numbered 1, 2, ... (MoorPy
    finds a line by its position); returns the text and {new ID: the deck's ID}."""
    lines = text.splitlines()
    start = next(i for i, l in enumerate(lines) if "LINES" in l and l.lstrip().startswith("-")) + 3
    out, ids, n = lines[:start], {}, 0
    k = start
    while k < len(lines) and not lines[k].lstrip().startswith("-"):
        cols = lines[k].split()
        if cols and int(cols[0]) not in removed:
            n += 1
            ids[n] = int(cols[0])
            out.append(" ".join([str(n)] + cols[1:]))
        k += 1
    return "\n".join(out + lines[k:]) + "\n", ids


def moorpy_equilibrium(deck: ms.SystemDeck, removed: tuple = (), load=None) -> dict:
    """MoorPy's equilibrium of the platform free in surge, sway and yaw (heave, roll, pitch held at 0) under the
    steady load, with the deck's lines `removed` (IDs) taken out: the pose and each remaining line's fairlead and
    anchor tension by its deck ID."""
    load = env_load() if load is None else load
    with tempfile.TemporaryDirectory() as tmp:
        text, ids = without_lines(deck.path.read_text(), removed)
        path = Path(tmp) / deck.path.name
        path.write_text(text)
        s = ms._moorpy_system(path, deck.depth)
        with moorpy.silenced():
            body = ms.attach_vessel_points(s, s.addBody(0, np.zeros(6), DOFs=[0, 1, 5],
                                                        f6Ext=np.array([load[0], load[1], 0.0, 0.0, 0.0, load[2]])))
            s.initialize()
            s.solveEquilibrium(tol=1e-6, maxIter=5000)
    tensions = {}
    for ln in s.lineList:
        a_is_fair = s.pointList[ln.attached[0] - 1].number in body.attachedP
        tensions[ids[ln.number]] = (float(ln.TA if a_is_fair else ln.TB), float(ln.TB if a_is_fair else ln.TA))
    return {"pose": np.array(body.r6, float), "tensions": tensions}


def free_platform_run(fmu, deck: ms.SystemDeck, t_break: float, t_end: float, h: float, start, elements: int,
                      damping, failure: bool = True, record: int = 1) -> dict:
    """The OC4 platform free in surge, sway and yaw from `start` (x, y, yaw [rad]); line 1 breaks at t_break.
    Returns the time, the pose, the lines' fairlead and anchor tensions, and the body's force."""
    extra = {"failure.line": 1, "failure.time": t_break} if failure else {}
    body = FreeBody(PLATFORM_MASS, PLATFORM_INERTIA, damping=tuple(damping), load=env_load(),
                    q=np.array(start, float))
    n = deck.lines
    names = [f"line[{k}].{q}" for k in range(1, n + 1) for q in ("fairleadTension", "anchorTension")] + \
        list(LOAD_NAMES)
    out = {"t": [], "q": [], "v": [], "tensions": [], "load": []}

    def inputs():
        return body.inputs(), body.acceleration()

    with CableFMU(fmu, parameters=ms.fmu_parameters(deck, lineFileElements=elements, **extra)) as c:
        u, _ = inputs()
        c.initialize(inputs=u)
        values = c.get_reals(names)
        body.lines = np.array(values[-3:])
        steps = int(round(t_end / h))
        for k in range(steps + 1):
            if k % record == 0 or k == steps:
                out["t"].append(k * h)
                out["q"].append(body.q.copy())
                out["v"].append(body.v.copy())
                out["tensions"].append(values[:-3])
                out["load"].append(values[-3:])
            if k == steps:
                break
            u, a = inputs()
            c.set(u)
            c.set_input_derivatives(["body[1].vx", "body[1].vy", "body[1].wz"], 1, [float(x) for x in a])
            c.do_step(h, t=k * h)
            values = c.get_reals(names)
            body.advance(h, np.array(values[-3:]))
    return {k: np.array(v) for k, v in out.items()}


def settled_pose(fmu, elements: int = 20, h: float = 0.5) -> dict:
    deck = ms.read_system_deck(ms.OC4)
    intact = moorpy_equilibrium(deck)
    damaged = moorpy_equilibrium(deck, removed=(1,))
    # the damping: critical for the damaged system's surge along the load (its stiffness from MoorPy's
    # equilibria: the load over the offset it makes would be a secant; a generous 4e4 N/m is used), yaw likewise
    c_x = critical_damping(4.0e4, PLATFORM_MASS)
    c_psi = critical_damping(4.0e7 * 1e2, PLATFORM_INERTIA)
    start = np.array([intact["pose"][0], intact["pose"][1], intact["pose"][5]])
    run = free_platform_run(fmu, deck, t_break=1.0, t_end=SETTLE, h=h, start=start, elements=elements,
                            damping=(c_x, c_x, c_psi), record=10)
    q_end = run["q"][-1]
    drift = np.linalg.norm(run["v"][-1][:2])
    fmu_t = run["tensions"][-1]
    rows = []
    for k in (2, 3):
        ref_f, ref_a = damaged["tensions"][k]
        rows.append({"line": k, "fmu_fairlead": fmu_t[2 * (k - 1)], "moorpy_fairlead": ref_f,
                     "fmu_anchor": fmu_t[2 * (k - 1) + 1], "moorpy_anchor": ref_a})
    return {"intact": intact, "damaged": damaged, "q_start": start, "q_end": q_end, "speed_end": drift,
            "tensions": rows, "run": run, "elements": elements, "h": h, "damping": (c_x, c_psi)}
