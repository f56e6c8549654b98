"""A taut riser and a hanging umbilical in waves: our FMU against MoorDyn v2 fed the same wave
components.

Taut: a vertical line pinned at a fixed point 5 m below the mean surface and at an anchor on the
seabed straight below (100 m of water), pretensioned. Hanging: the same line hanging from the same
point with a 2 t body at its end. Both codes start from their static equilibrium in calm water and
see the full waves from t = 0. MoorDyn (PyPI `moordyn`) gets the FMU's own components (studies.references.sea,
the documented generator, equal to the FMU's `waveElevation`) through its `WaveKin` 7 mode: a
`wave_frequencies.txt` of complex amplitudes that it sums at every node at every evaluation of its
equations, with Wheeler stretching (the FMU runs with `waves.stretching` = 1 to match). Both codes
have the same line, drag, added mass and Froude-Krylov forces (normal and tangential), axial damping
in N s and no bending stiffness; held ends are coupled points in MoorDyn, so the tensions compared
there are the reactions.

compute() returns every number (tension statistics per code and run, differences); markdown()
writes the section "Against MoorDyn" of docs/waves.md from them (between its BEGIN and END
markers). Used by scripts/waves_moordyn and tests/python/test_waves_moordyn.py.
"""

from __future__ import annotations

import math
import time
from dataclasses import asdict, dataclass, replace
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ..peers import moordyn
from ..references.sea import Sea, sea_state


@dataclass(frozen=True)
class Riser:
    depth: float = 100.0          # water depth; the anchor is on the seabed at (0, 0, -depth)
    top_z: float = -5.0           # the upper pinned point (0, 0, top_z)
    length: float = 94.2          # unstretched [m]: ~0.8 % strain over the 95 m span
    diameter: float = 0.1
    mass: float = 15.0            # [kg/m]
    EA: float = 1.0e7
    BA: float = 1.0e4             # axial (Kelvin-Voigt) damping [N s], MoorDyn's BA
    Cdn: float = 1.2
    Cdt: float = 0.01
    Can: float = 1.0
    Cat: float = 0.0
    g: float = 9.81
    rho: float = 1025.0
    # a body at the lower end instead of the anchor (hanging): mass [kg], volume [m3], drag area
    # [m2], added-mass coefficient (added mass rho V Ca); body_mass 0: anchored
    body_mass: float = 0.0
    body_volume: float = 0.0
    body_cda: float = 0.0
    body_ca: float = 0.0

    @property
    def hanging(self) -> bool:
        return self.body_mass > 0.0


# An umbilical hanging from the same point with a 2 t body (0.5 m3, drag area 0.88 m2) at its end
HANGING = Riser(length=90.0, body_mass=2000.0, body_volume=0.5, body_cda=0.88, body_ca=1.0)


@dataclass(frozen=True)
class Waves:
    """The FMU's waves.* parameters of a case."""
    name: str
    mode: int
    height: float
    period: float
    n_components: int = 50
    seed: int = 1
    t_end: float = 100.0
    t_from: float = 40.0          # statistics over [t_from, t_end]
    spreading: float = 0.0        # waves.spreading (cos-2s exponent; 0: long-crested)
    n_directions: int = 15        # waves.nDirections of a spread sea

    def parameters(self, riser: Riser) -> dict:
        p = {"waves.mode": self.mode, "waves.height": self.height, "waves.period": self.period,
             "waves.nComponents": self.n_components, "waves.seed": self.seed, "waves.stretching": 1,
             "waterDepth": riser.depth, "gravity": riser.g}
        if self.spreading > 0.0:
            p.update({"waves.spreading": self.spreading, "waves.nDirections": self.n_directions})
        return p


REGULAR = Waves("regular", 1, 4.0, 10.0, t_end=100.0, t_from=40.0)
# 50 components over [0.5, 3] wp: the record repeats after 2 pi / dw = 200 s, the window below.
IRREGULAR = Waves("irregular", 2, 4.0, 10.0, n_components=50, t_end=240.0, t_from=40.0)
# A short-crested sea: cos-2s, s = 2, in 5 directions of 20 components (100 in all; the record repeats
# after 2 pi / dw = 80 s); not in CASES (the generated section), checked by tests/python/test_waves_moordyn.py.
SPREAD = Waves("spread", 2, 4.0, 10.0, n_components=20, t_end=120.0, t_from=40.0, spreading=2.0, n_directions=5)


@dataclass(frozen=True)
class Case:
    name: str
    riser: Riser
    waves: Waves


# The hanging umbilical's body bounces on the elastic line at ~1 Hz after the waves' sudden start,
# barely damped (time constant ~27 s measured): its statistics start at 150 s.
CASES = (Case("taut, regular", Riser(), REGULAR), Case("taut, irregular", Riser(), IRREGULAR),
         Case("hanging, regular", HANGING, replace(REGULAR, t_end=250.0, t_from=150.0)),
         Case("hanging, irregular", HANGING, replace(IRREGULAR, t_end=350.0, t_from=150.0)))

COMM_STEP = 0.1   # [s] sampling of both codes
MD_CFL = 0.5      # MoorDyn's dtM as a fraction of the axial wave's crossing time of a segment


# ----------------------------------------------------------------------------- our FMU
# The FMU's tensionTolerance of the comparison: the default 1e-3 is a local error of 88 N on this
# riser's 88 kN, more than the waves' tension RMS (~66 N); at 1e-5 the results no longer change with
# the tolerance (docs/waves.md).
TOLERANCE = 1e-5


def fmu_parameters(riser: Riser, waves: Waves, n_elements: int, tolerance: float = TOLERANCE) -> dict:
    p = {"tensionTolerance": tolerance, "length": riser.length, "diameter": riser.diameter,
         "massPerLength": riser.mass, "EA": riser.EA, "EI": 0.0, "enableBending": False, "axialDamping": riser.BA,
         "Cdn": riser.Cdn, "Cdt": riser.Cdt, "Can": riser.Can, "Cat": riser.Cat, "enableAddedMass": True,
         "waterDensity": riser.rho, "enableCompression": False, "enableSeabed": False,
         "initialDirection.x": 0.0, "initialDirection.z": -1.0, "nElements": n_elements, **waves.parameters(riser)}
    if riser.hanging:
        # MoorDyn's point feels no acceleration of the water: neither does our body here
        p.update({"bottomEnd": 2, "body.mass": riser.body_mass, "body.volume": riser.body_volume,
                  "body.addedMass": riser.rho * riser.body_volume * riser.body_ca, "body.CdA": riser.body_cda,
                  "enableBodyFluidInertia": False})
    else:
        p.update({"bottomEnd": 1, "anchor.x": 0.0, "anchor.y": 0.0, "anchor.z": -riser.depth})
    return p


@dataclass
class History:
    code: str
    mesh: int            # our elements or MoorDyn's segments
    accuracy: float      # our tensionTolerance or MoorDyn's dtM / (axial crossing time of a segment)
    t: np.ndarray
    top: np.ndarray      # tension at the upper point [N]
    bottom: np.ndarray   # at the anchor [N]
    cpu: float
    info: str = ""


def run_fmu(fmu, riser: Riser, waves: Waves, n_elements: int, tolerance: float = TOLERANCE,
            t_end: float | None = None, progress=None) -> History:
    t_end = waves.t_end if t_end is None else t_end
    n = int(round(t_end / COMM_STEP))
    top, bottom = np.zeros(n + 1), np.zeros(n + 1)
    tow = {"tow.x": 0.0, "tow.y": 0.0, "tow.z": riser.top_z}
    with CableFMU(fmu, parameters=fmu_parameters(riser, waves, n_elements, tolerance)) as c:
        c.initialize(0.0, inputs=tow)
        top[0], bottom[0] = c.get("towTension"), c.get("endTension")
        cpu0 = time.process_time()
        for k in range(n):
            c.set(tow)
            c.do_step(COMM_STEP, k * COMM_STEP)
            top[k + 1], bottom[k + 1] = c.get("towTension"), c.get("endTension")
            if progress:
                progress((k + 1) * COMM_STEP)
        cpu = time.process_time() - cpu0
        steps = c.get("solver.nSteps")
    return History("FMU", n_elements, tolerance, np.arange(n + 1) * COMM_STEP, top, bottom, cpu,
                   f"{steps:.0f} steps")


# ----------------------------------------------------------------------------- MoorDyn
def wave_frequencies(sea: Sea) -> str:
    """MoorDyn's wave_frequencies.txt of the components: omega, Re and Im of the complex amplitude A,
    direction; MoorDyn's elevation is |A| sin(w t - k x + arg A), ours a cos(k x - w t + p), so
    A = a exp(i (pi/2 - p)). The first row must be omega = 0."""
    directions = sea.directions()
    rows = [f"0 0 0 {directions[0] if len(directions) else 0.0:.17g}"]
    for a, w, p, b in zip(sea.amplitude, sea.omega, sea.phase, directions):
        psi = 0.5 * math.pi - p
        rows.append(f"{w:.17g} {a * math.cos(psi):.17g} {a * math.sin(psi):.17g} {b:.17g}")
    return "\n".join(rows) + "\n"


def moordyn_dt(riser: Riser, n_seg: int, cfl: float = MD_CFL) -> float:
    """dtM: cfl times the axial wave's crossing time of a segment, a whole fraction of COMM_STEP."""
    crossing = riser.length / n_seg / math.sqrt(riser.EA / riser.mass)
    sub = math.ceil(COMM_STEP / (cfl * crossing) - 1e-9)
    return COMM_STEP / sub


def moordyn_deck(riser: Riser, n_seg: int, dt: float) -> str:
    top, d = riser.top_z, riser.depth
    if riser.hanging:  # MoorDyn's first guess of the free end: straight below
        bottom = (f"1     Free       0 0 {top - riser.length:.17g}  {riser.body_mass:.17g}  {riser.body_volume:.17g}  "
                  f"{riser.body_cda:.17g}  {riser.body_ca:.17g}")
    else:
        bottom = f"1     Coupled    0 0 {-d:.17g}  0  0  0  0"
    return f"""--------------------- MoorDyn Input File ------------------------------------
UnderwaterCable: a taut vertical riser in waves (studies.comparisons.waves_moordyn)
---------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA     BA/-zeta    EI    Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)    (N-s/-)     (N-m^2) (-)  (-)    (-)     (-)
riser {riser.diameter:.17g} {riser.mass:.17g} {riser.EA:.17g} {riser.BA:.17g} 0 {riser.Cdn:.17g} {riser.Can:.17g} {riser.Cdt:.17g} {riser.Cat:.17g}
---------------------- POINTS --------------------------------
ID   Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)        (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
{bottom}
2     Coupled    0 0 {top:.17g}  0  0  0  0
---------------------- LINES --------------------------------------
ID    LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)      (m)       (-)      (-)
1     riser      1        2        {riser.length:.17g}  {n_seg}  -
---------------------- OPTIONS -----------------------------------------
{dt:.17g}   dtM
{riser.g:.17g}     g
{riser.rho:.17g}     rho
{d:.17g}     WtrDpth
7        WaveKin
0        Currents
1e-6     threshIC
200      TmaxIC
0        writeLog
1        disableOutput
1        disableOutTime
------------------------- need this line -------------------------------------
"""


class MoorDynRiser:
    """A MoorDyn system of the riser in the sea, in a temporary directory (MoorDyn reads
    wave_frequencies.txt next to its input file and writes there)."""

    def __init__(self, riser: Riser, waves: Waves, n_seg: int, cfl: float = MD_CFL):
        self.riser, self.n_seg = riser, n_seg
        self.dt = moordyn_dt(riser, n_seg, cfl)
        self.sea = sea_state(waves.parameters(riser))
        self.x = ([] if riser.hanging else [0.0, 0.0, -riser.depth]) + [0.0, 0.0, riser.top_z]

    def _write(self, tmp: Path) -> Path:
        (tmp / "riser.txt").write_text(moordyn_deck(self.riser, self.n_seg, self.dt))
        (tmp / "wave_frequencies.txt").write_text(wave_frequencies(self.sea))
        return tmp / "riser.txt"

    def __enter__(self):
        self.md = moordyn.System(write=self._write, chdir=True, init=self.start, quiet="setup").__enter__()
        self.line = self.md.line(1)
        return self

    def __exit__(self, *exc):
        return self.md.__exit__(*exc)

    @property
    def start(self) -> tuple:
        return self.x, [0.0] * len(self.x)

    def kinematics(self, x: float, y: float, z: float):
        """MoorDyn's water velocity, acceleration and elevation at a point at its present time."""
        return self.md.wave_kinematics(x, y, z)

    def tensions(self, f) -> tuple:
        """(top, bottom) tension from the forces of a step: |forces on the held points|, at a hanging
        body the tension of the line's last segment."""
        if self.riser.hanging:
            return float(np.linalg.norm(f)), float(np.linalg.norm(self.md.node_tension(self.line, 0)))
        return float(np.linalg.norm(f[3:6])), float(np.linalg.norm(f[0:3]))

    def step(self, t: float, h: float) -> tuple:
        """Advance from t by h (whole dtM steps); the (top, bottom) tension."""
        return self.tensions(self.md.step(*self.start, t, h))


def run_moordyn(riser: Riser, waves: Waves, n_seg: int, cfl: float = MD_CFL, t_end: float | None = None,
                progress=None) -> History:
    t_end = waves.t_end if t_end is None else t_end
    n = int(round(t_end / COMM_STEP))
    top, bottom = np.zeros(n + 1), np.zeros(n + 1)
    with MoorDynRiser(riser, waves, n_seg, cfl) as md:

        def record(k, f):
            top[k], bottom[k] = md.tensions(f)

        cpu = moordyn.drive(md.md, md.start, n, COMM_STEP, 1, lambda t: md.start, record, progress,
                            whole_steps=True)
        dt = md.dt
    return History("MoorDyn", n_seg, cfl, np.arange(n + 1) * COMM_STEP, top, bottom, cpu, f"dtM {dt:.3g} s")


# ----------------------------------------------------------------------------- statistics
def statistics(h: History, t_from: float) -> dict:
    """Per end: mean, RMS of the fluctuation (std), amplitude (half the range) over t >= t_from."""
    sel = h.t >= t_from - 1e-9
    out = {}
    for end in ("top", "bottom"):
        x = getattr(h, end)[sel]
        out[end] = {"mean": float(x.mean()), "rms": float(x.std()), "amplitude": 0.5 * float(np.ptp(x))}
    return out


def difference(a: History, b: History, t_from: float) -> dict:
    """a against b per end: relative differences of RMS and amplitude, and the RMS of the
    difference of the fluctuations (means removed) relative to b's RMS."""
    sa, sb = statistics(a, t_from), statistics(b, t_from)
    sel = a.t >= t_from - 1e-9
    out = {}
    for end in ("top", "bottom"):
        x, y = getattr(a, end)[sel], getattr(b, end)[sel]
        out[end] = {"rms": sa[end]["rms"] / sb[end]["rms"] - 1.0,
                    "amplitude": sa[end]["amplitude"] / sb[end]["amplitude"] - 1.0,
                    "mean": sa[end]["mean"] - sb[end]["mean"],
                    "history": float(np.sqrt(np.mean(((x - x.mean()) - (y - y.mean())) ** 2))) / sb[end]["rms"]}
    return out


# ----------------------------------------------------------------------------- the study
def default_runs(elements=(5, 10, 20), segments=(20, 40, 80)) -> tuple:
    """(FMU runs as (elements, tensionTolerance), MoorDyn runs as (segments, dtM / crossing time)):
    each mesh at the comparison's accuracy, plus our finest mesh at the default tolerance 1e-3 and
    at 1e-6, and MoorDyn's middle mesh at half the time step."""
    fmu = [(elements[-1], 1e-3)] + [(n, TOLERANCE) for n in elements] + [(elements[-1], 1e-6)]
    md = [(n, MD_CFL) for n in segments]
    md.insert(len(md) - 1, (segments[len(segments) // 2] if len(segments) > 1 else segments[0], 0.5 * MD_CFL))
    return tuple(fmu), tuple(md)


@dataclass
class Settings:
    fmu_runs: tuple = default_runs()[0]
    moordyn_runs: tuple = default_runs()[1]
    cases: tuple = CASES


def reference(runs: list) -> "History":
    """A code's reference run: its finest mesh, and there its finest accuracy."""
    return max(runs, key=lambda h: (h.mesh, -h.accuracy))


def moordyn_error_estimate(case: dict) -> dict | None:
    """Richardson's estimate of the remaining mesh error of MoorDyn's reference (second order: the
    change from the next coarser mesh at the same time step / 3), per end and statistic, relative
    to the reference; None without such a pair of runs."""
    md = [r for r in case["rows"] if r["code"] == "MoorDyn"]
    ref = next(r for r in md if r["reference"])
    coarser = [r for r in md if r["accuracy"] == ref["accuracy"] and r["mesh"] < ref["mesh"]]
    if not coarser:
        return None
    prev = max(coarser, key=lambda r: r["mesh"])

    def largest_change(a, b):  # over both ends and both statistics, relative to b
        return max(abs(a["stats"][e][k] / b["stats"][e][k] - 1.0) for e in ("top", "bottom") for k in ("rms", "amplitude"))

    # halving the time step: runs on one mesh at two accuracies
    pairs = [(a, b) for a in md for b in md if a["mesh"] == b["mesh"] and a["accuracy"] < b["accuracy"]]
    ours = [r for r in case["rows"] if r["code"] == "FMU" and not r["reference"] and r["accuracy"] <= TOLERANCE]
    fmu_ref = next(r for r in case["rows"] if r["code"] == "FMU" and r["reference"])
    converged = [r for r in ours if r["mesh"] >= 10]
    return {"segments": [prev["mesh"], ref["mesh"]],
            **{end: {k: (ref["stats"][end][k] - prev["stats"][end][k]) / 3.0 / ref["stats"][end][k]
                     for k in ("rms", "amplitude")} for end in ("top", "bottom")},
            "time_step": {"segments": pairs[0][0]["mesh"], "change": largest_change(*pairs[0])} if pairs else None,
            "fmu_spread": max((largest_change(r, fmu_ref) for r in converged), default=None)}


def compute(fmu, settings: Settings, progress_factory=None) -> dict:
    """Every number of the report: per case, each run of each code, its statistics, its differences
    to the same code's reference run (finest mesh, finest accuracy) and to the other code's."""
    cases = []
    for case in settings.cases:
        riser, waves = case.riser, case.waves
        runs = {"FMU": [], "MoorDyn": []}
        plan = ([("FMU", m, a, lambda m, a, p: run_fmu(fmu, riser, waves, m, a, progress=p))
                 for m, a in settings.fmu_runs] +
                [("MoorDyn", m, a, lambda m, a, p: run_moordyn(riser, waves, m, a, progress=p))
                 for m, a in settings.moordyn_runs])
        for code, mesh, accuracy, run in plan:
            bar = progress_factory(waves.t_end, f"{case.name}: {code} {mesh} ({accuracy:g})") if progress_factory else None
            runs[code].append(run(mesh, accuracy, bar.update if bar else None))
            if bar:
                bar.close()
        ref = {code: reference(runs[code]) for code in runs}
        other = {"FMU": "MoorDyn", "MoorDyn": "FMU"}
        rows = []
        for code in ("FMU", "MoorDyn"):
            for h in runs[code]:
                rows.append({"code": code, "mesh": h.mesh, "accuracy": h.accuracy, "cpu": h.cpu, "info": h.info,
                             "reference": h is ref[code], "stats": statistics(h, waves.t_from),
                             "vs_own": difference(h, ref[code], waves.t_from),
                             "vs_other": difference(h, ref[other[code]], waves.t_from)})
        sea = sea_state(waves.parameters(riser))
        cases.append({"name": case.name, "riser": {**asdict(riser), "hanging": riser.hanging},
                      "waves": asdict(waves), "hs": sea.hs(), "rows": rows,
                      "references": {code: {"mesh": ref[code].mesh, "accuracy": ref[code].accuracy} for code in ref},
                      "finest": difference(ref["FMU"], ref["MoorDyn"], waves.t_from)})
        cases[-1]["moordyn_error"] = moordyn_error_estimate(cases[-1])
    from importlib.metadata import version
    return {"cases": cases, "comm_step": COMM_STEP, "md_cfl": MD_CFL,
            "tolerance": TOLERANCE, "moordyn_version": version("moordyn")}


# ----------------------------------------------------------------------------- Markdown
def _pct(x: float) -> str:
    return f"{100.0 * x:+.2f} %"


def _accuracy(row: dict) -> str:
    if row["code"] == "FMU":
        return f"tol {row['accuracy']:.0e}"
    return f"dtM {row['accuracy']:g} crossing"


def markdown(data: dict) -> str:
    taut = next(c for c in data["cases"] if not c["riser"]["hanging"])
    r = taut["riser"]
    top = next(row for row in taut["rows"] if row["code"] == "FMU" and row["reference"])["stats"]["top"]["mean"]
    hanging = next((c["riser"] for c in data["cases"] if c["riser"]["hanging"]), None)
    out = ["## Against MoorDyn", "",
           "This section is generated by `scripts/waves_moordyn` (the numbers are computed by "
           "`studies.comparisons.waves_moordyn.compute`, the text is written from them).", "",
           f"**Taut**: a vertical riser, {r['length']:g} m unstretched, pinned at (0, 0, {r['top_z']:g}) m and at "
           f"an anchor on the seabed straight below in {r['depth']:g} m of water: diameter {r['diameter']:g} m, "
           f"{r['mass']:g} kg/m, EA {r['EA']:.3g} N, axial damping {r['BA']:.3g} N s, no bending stiffness, "
           f"Cdn {r['Cdn']:g}, Cdt {r['Cdt']:g}, Can {r['Can']:g}, Cat {r['Cat']:g}, ρ {r['rho']:g} kg/m³, "
           f"g {r['g']:g} m/s². Both ends are held points in both codes: the tensions are the reactions there "
           "(|`towForce`|, |`endForce`|; MoorDyn: the forces on its two coupled points)."]
    if hanging:
        h = hanging
        out += ["", f"**Hanging**: the same line, {h['length']:g} m, hanging from the same point with a body at its "
                f"end: {h['body_mass']:g} kg, {h['body_volume']:g} m³, drag area {h['body_cda']:g} m², added mass "
                f"ρ V × {h['body_ca']:g} (FMU: `bottomEnd` 2 and `body.*`; MoorDyn: a free point with that mass, "
                "volume, CdA and CA). Neither code puts the waves' acceleration on the body here (no Froude–Krylov "
                "force on it: MoorDyn's point has none, and the FMU runs with `enableBodyFluidInertia` false). Bottom tension: ours at the body; MoorDyn's in the line's last segment, half a "
                "segment above the body, so its mean is higher by about half a segment's wet weight and converges "
                "at first order. The body bounces on the elastic line at about 1 Hz after the waves' sudden start, "
                "barely damped (a time constant of about 27 s): the statistics of this line start at 150 s."]
    out += ["", "Both codes start from their static equilibrium in calm water and see the full waves from t = 0 "
            "(no ramp), travelling along +x.", "",
            f"MoorDyn {data.get('moordyn_version', 'v2')} (PyPI `moordyn`, lumped masses, its default RK2 time "
            "integration) is fed the FMU's own "
            "wave components: `WaveKin` 7 with a `wave_frequencies.txt` of complex amplitudes "
            "A = a e^{i(π/2 − p)} (MoorDyn's elevation is |A| sin(ω t − k x + arg A), ours "
            "a cos(k x − ω t + p)), which it sums at every node at every evaluation of its equations, with "
            "Wheeler stretching; the FMU runs with `waves.stretching` = 1. The components are those of "
            "`studies.references.sea`, the generator of the convention above written again in Python; "
            "`tests/python/test_waves_moordyn.py` checks that they give the FMU's `waveElevation` to round-off "
            "and MoorDyn's own velocity, acceleration and elevation at points of the water column (to 1e-11 "
            "relative for the regular wave, 1e-8 for the irregular sea: MoorDyn solves the dispersion "
            f"relation to seven digits). Both codes are sampled every {data['comm_step']:g} s.", "",
            "Accuracy: the FMU's `tensionTolerance` (tol) and MoorDyn's time step dtM as a fraction of the "
            "axial wave's crossing time of a segment. The FMU's default tolerance 1e-3 is a local error of "
            f"{1e-3 * top:.0f} N in the taut riser's {top / 1e3:.0f} kN, more than the waves' tension RMS: the "
            f"comparison runs at {data['tolerance']:.0e}, and the rows at 1e-3 and 1e-6 show what the tolerance "
            "does. RMS: the standard deviation of the tension over the window; amplitude: half its range; "
            "history: the RMS of the difference of the two fluctuations (means removed) over the reference's "
            "RMS. Each run is compared with its own code's reference (finest mesh, then finest accuracy: "
            "marked ref.), which shows how converged it is, and with the other code's reference.", ""]
    for case in data["cases"]:
        w = case["waves"]
        kind = (f"regular wave, H {w['height']:g} m, T {w['period']:g} s" if w["mode"] == 1 else
                f"JONSWAP sea, Hs {w['height']:g} m (of the components: {case['hs']:.3f} m), Tp {w['period']:g} s, "
                f"γ 3.3, {w['n_components']} components, seed {w['seed']}")
        out += [f"### {case['name'].capitalize()}: {kind}", "",
                f"Statistics over t = {w['t_from']:g}–{w['t_end']:g} s.", "",
                "| code | mesh | accuracy | top: mean [N] | RMS [N] | amplitude [N] | bottom: mean [N] | RMS [N] "
                "| amplitude [N] | vs own ref.: top RMS, amplitude, history | bottom RMS, amplitude, history "
                "| vs other's ref.: top RMS, amplitude, history | bottom RMS, amplitude, history | CPU [s] |",
                "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]

        def trio(d):
            return f"{_pct(d['rms'])}, {_pct(d['amplitude'])}, {100 * d['history']:.2f} %"

        for row in case["rows"]:
            s, own, oth = row["stats"], row["vs_own"], row["vs_other"]
            unit = "elements" if row["code"] == "FMU" else "segments"
            ref = " (ref.)" if row["reference"] else ""
            own_text = ("ref.", "ref.") if row["reference"] else (trio(own["top"]), trio(own["bottom"]))
            out.append(
                f"| {row['code']}{ref} | {row['mesh']} {unit} | {_accuracy(row)} | {s['top']['mean']:.0f} "
                f"| {s['top']['rms']:.2f} | {s['top']['amplitude']:.2f} | {s['bottom']['mean']:.0f} "
                f"| {s['bottom']['rms']:.2f} | {s['bottom']['amplitude']:.2f} | {own_text[0]} | {own_text[1]} "
                f"| {trio(oth['top'])} | {trio(oth['bottom'])} | {row['cpu']:.1f} |")
        f = case["finest"]
        out += ["", f"References, FMU against MoorDyn: top RMS {_pct(f['top']['rms'])}, amplitude "
                f"{_pct(f['top']['amplitude'])}, history {100 * f['top']['history']:.2f} %, mean "
                f"{f['top']['mean']:+.1f} N; bottom RMS {_pct(f['bottom']['rms'])}, amplitude "
                f"{_pct(f['bottom']['amplitude'])}, history {100 * f['bottom']['history']:.2f} %, mean "
                f"{f['bottom']['mean']:+.1f} N."]
        e = case.get("moordyn_error")
        if e:
            out += [f"MoorDyn's own remaining mesh error at {e['segments'][1]} segments, estimated from its change "
                    f"since {e['segments'][0]} (second order: the change / 3): top RMS {_pct(e['top']['rms'])}, "
                    f"amplitude {_pct(e['top']['amplitude'])}; bottom RMS {_pct(e['bottom']['rms'])}, amplitude "
                    f"{_pct(e['bottom']['amplitude'])}."]
            if e.get("time_step"):
                out[-1] += (f" Halving MoorDyn's time step at {e['time_step']['segments']} segments changes its "
                            f"statistics by at most {100 * e['time_step']['change']:.3f} %.")
            if e.get("fmu_spread") is not None:
                out[-1] += (f" Our runs from 10 elements at tolerances {data['tolerance']:.0e} and below differ from "
                            f"our reference by at most {100 * e['fmu_spread']:.3f} %.")
        out += [""]
    return "\n".join(out)


def write_section(doc: Path, section: str) -> None:
    """Replace the section of this script in doc (appended if absent)."""
    from ..doc_section import write_section as write
    write(doc, section, "scripts/waves_moordyn")


def main(argv=None) -> int:
    import argparse
    import json

    from ucable.paths import REPO_ROOT, require_fmu
    from ucable.progress import ProgressBar

    p = argparse.ArgumentParser(prog="scripts/waves_moordyn", description=(
        "A taut riser and a hanging umbilical in regular and irregular waves: our FMU against MoorDyn v2 fed the same wave "
        "components, tension RMS and amplitude at both ends with mesh refinement of each code."))
    p.add_argument("--elements", type=int, nargs="+", default=[5, 10, 20],
                   help="our meshes (elements), at tensionTolerance %g; the last also at 1e-3 and 1e-6" % TOLERANCE)
    p.add_argument("--segments", type=int, nargs="+", default=[20, 40, 80],
                   help="MoorDyn's meshes (segments), at dtM = %g crossing times; the middle one also at half" % MD_CFL)
    p.add_argument("--cases", nargs="+", choices=[c.name.replace(", ", "-") for c in CASES],
                   default=[c.name.replace(", ", "-") for c in CASES], help="the cases (default: all four)")
    p.add_argument("--doc", type=Path, default=REPO_ROOT / "docs" / "waves.md",
                   help="the Markdown file whose section between the markers is rewritten (default docs/waves.md)")
    p.add_argument("--json", type=Path, default=REPO_ROOT / "out" / "waves_moordyn" / "study.json",
                   help="the numbers, as JSON")
    p.add_argument("--fmu", type=Path, default=None)
    p.add_argument("--from-json", type=Path, default=None,
                   help="rewrite the section from a saved study (the --json of an earlier run) without running")
    a = p.parse_args(argv)
    if a.from_json:
        data = json.loads(a.from_json.read_text())
        for case in data["cases"]:
            case["moordyn_error"] = moordyn_error_estimate(case)
        write_section(a.doc, markdown(data))
        print(f"wrote {a.doc}")
        return 0
    cases = tuple(c for c in CASES if c.name.replace(", ", "-") in a.cases)
    fmu_runs, moordyn_runs = default_runs(tuple(a.elements), tuple(a.segments))
    settings = Settings(fmu_runs=fmu_runs, moordyn_runs=moordyn_runs, cases=cases)
    data = compute(a.fmu or require_fmu(), settings, progress_factory=lambda total, label: ProgressBar(total, label))
    a.json.parent.mkdir(parents=True, exist_ok=True)
    a.json.write_text(json.dumps(data, indent=1))
    write_section(a.doc, markdown(data))
    print(f"wrote {a.doc} and {a.json}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
