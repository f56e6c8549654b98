"""Mooring surge scene: is the dynamic mean fairlead tension physics or numerics?

The scene of studies.cases.mooring (chain, seabed, fairlead x = A sin(2 pi t / T) from the static
equilibrium at x = 0) flown by our FMU and by MoorDyn v2 (PyPI `moordyn`) through the
work-precision helpers of studies.benchmarks.work_precision (Case, run_fmu, run_moordyn, moordyn_stable_dt),
so both codes see the same line, seabed, hydrodynamics and fairlead motion. The dynamic mean of
the fairlead tension |force of the line on the fairlead| over [average_from, t_end] is compared
with the quasi-static cycle mean (closed form, studies.cases.mooring.quasi_static_mean).

Variants for the physics decomposition: drag off (Cdn = Cdt = 0) and a slower surge (same
amplitude, longer period). Used by scripts/mooring_dynamic_mean.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..cases import mooring as m
from . import work_precision as wp

COMM_STEP = 0.1  # [s], as studies.cases.mooring.surge_run
# Our axial (Kelvin-Voigt) damping: the FMU default 0.01 s x 6.709e7 N (modelDescription.xml),
# set explicitly so MoorDyn can be given the same BA. MoorDyn's usual BA/-zeta = -0.8 instead
# damps each segment's axial mode at 80 % of critical: BA = 1.6 l sqrt(EA m) = 2.1e7 N s at
# 20 segments (31x ours), 1.3e6 N s at 320: its damping falls as the mesh is refined.
AXIAL_DAMPING = 0.01 * 6.709e7


class SineSurge:
    """Fairlead at (A sin(w t), 0, FAIRLEAD_Z): the surge of studies.cases.mooring with any period
    (position, velocity, acceleration; the Case.traj protocol of studies.benchmarks.work_precision)."""

    def __init__(self, amplitude=m.SURGE_AMPLITUDE, period=m.SURGE_PERIOD):
        self.A, self.w, self.period = amplitude, 2.0 * math.pi / period, period

    def state(self, t):
        s, c = math.sin(self.w * t), math.cos(self.w * t)
        e = np.array([1.0, 0.0, 0.0])
        return (np.array([self.A * s, 0.0, m.FAIRLEAD_Z]), self.A * self.w * c * e,
                -self.A * self.w ** 2 * s * e)

    def fairlead_x(self, n_phases: int) -> np.ndarray:
        return self.A * np.sin(2.0 * math.pi * np.arange(n_phases) / n_phases)


class Hold:
    """Fairlead held at (x, 0, FAIRLEAD_Z): for the codes' statics through the same runners."""

    def __init__(self, x):
        self.x = x

    def state(self, t):
        z = np.zeros(3)
        return np.array([self.x, 0.0, m.FAIRLEAD_Z]), z, z


def scene_case(period: float = m.SURGE_PERIOD, drag: bool = True, t_end: float = 300.0,
               traj=None, md_damping: str = "zeta") -> wp.Case:
    """The mooring surge scene as a studies.benchmarks.work_precision.Case. Our seabed is per unit length
    (seabedStiffness 1e6 N/m2 as studies.cases.mooring.CHAIN, seabedDamping left at the FMU default
    1000 N s/m2); MoorDyn's per unit contact area d x length, so kBot = k / d, cBot = c / d.
    md_damping: "zeta" (MoorDyn BA/-zeta = -0.8 as in studies.benchmarks.work_precision) or "matched"
    (MoorDyn BA = our AXIAL_DAMPING)."""
    ch = m.CHAIN
    cdn, cdt = (ch["Cdn"], ch["Cdt"]) if drag else (0.0, 0.0)
    line = dict(length=ch["length"], diameter=ch["diameter"], massPerLength=ch["massPerLength"],
                EA=ch["EA"], EI=0.0, Cdn=cdn, Cdt=cdt, Can=1.0, Cat=0.0)
    seabed_damping = 1000.0  # FMU default (modelDescription.xml)
    fmu_params = {k: v for k, v in ch.items() if k not in line}
    fmu_params.update(seabedDamping=seabed_damping, seabedFriction=0.0, axialDamping=AXIAL_DAMPING)
    if md_damping not in ("zeta", "matched"):
        raise ValueError(f"md_damping: 'zeta' or 'matched', not {md_damping!r}")
    return wp.Case(
        name=f"surge_T{period:g}{'' if drag else '_nodrag'}",
        title=f"mooring surge, period {period:g} s{'' if drag else ', no drag'}",
        traj=traj if traj is not None else SineSurge(period=period), t_end=t_end,
        comm_step=COMM_STEP, line=line, fmu_params=fmu_params,
        anchor=(m.ANCHOR_X, 0.0, -m.DEPTH), force_scale=3e6,
        seabed=dict(depth=m.DEPTH, kBot=ch["seabedStiffness"] / ch["diameter"],
                    cBot=seabed_damping / ch["diameter"]),
        md_ba=AXIAL_DAMPING if md_damping == "matched" else None)


@dataclass
class MeanResult:
    code: str
    resolution: int
    setting: str
    period: float
    drag: bool
    mean: float  # dynamic mean fairlead tension [N]
    t_min: float
    t_max: float
    cpu: float
    qs_mean: float  # quasi-static cycle mean of the same period (closed form) [N]
    min_axial: float = math.nan  # ours: smallest axial force over the cable and the run [N] (< 0: compression)

    @property
    def deviation(self) -> float:
        return self.mean / self.qs_mean - 1.0


def fairlead_tension(run: wp.Run) -> np.ndarray:
    return np.linalg.norm(run.force, axis=1)


def dynamic_mean(run: wp.Run, average_from: float):
    """Mean, min and max of the fairlead tension over the half-open window [average_from, t_end):
    a whole number of periods samples every phase once. (The closed window of
    studies.cases.mooring.surge_run counts the phase at t = 100 s and 300 s twice; that phase is near the
    snap peak, so it adds (T(phase 0) - mean) / 2001 ~ +0.04 points to the excess: MoorDyn, 40
    segments: +2.941 % closed, +2.899 % half-open, every 10 s cycle of 100-500 s within 0.002 of it.)"""
    sel = (run.t >= average_from - 1e-9) & (run.t < run.t[-1] - 1e-9)
    T = fairlead_tension(run)[sel]
    return float(T.mean()), float(T.min()), float(T.max())


def ours(fmu, n_elements: int, rel_tol: float = 1e-8, period: float = m.SURGE_PERIOD,
         drag: bool = True, t_end: float = 300.0, average_from: float = 100.0,
         qs_mean: float | None = None, compression: bool = True) -> MeanResult:
    """Our FMU on the scene (absTol = 100 relTol as in studies.benchmarks.work_precision.run_fmu; relTol 1e-8
    gives the FMU defaults 1e-8 / 1e-6 of studies.cases.mooring.surge_run). compression=False: the
    tension-only axial law (enableCompression = 0), MoorDyn's."""
    case = scene_case(period, drag, t_end)
    run = wp.run_fmu(fmu, case, n_elements, rel_tol, tolerance="relTol",
                     extra=None if compression else {"enableCompression": 0})
    mean, lo, hi = dynamic_mean(run, average_from)
    qs = m.quasi_static_mean(40) if qs_mean is None else qs_mean
    setting = f"relTol {rel_tol:.0e}" + ("" if compression else ", tension-only")
    return MeanResult("ours", n_elements, setting, period, drag, mean, lo, hi, run.cpu, qs,
                      run.stats["minTension"])


def moordyn_dt(n_seg: int, period: float = m.SURGE_PERIOD, drag: bool = True,
               md_damping: str = "zeta") -> float:
    """MoorDyn's largest stable RK2 step for this scene (bisection on 30 s trial runs)."""
    return wp.moordyn_stable_dt(scene_case(period, drag, md_damping=md_damping), n_seg, None)[0]


def moordyn(n_seg: int, dt: float, period: float = m.SURGE_PERIOD, drag: bool = True,
            t_end: float = 300.0, average_from: float = 100.0, qs_mean: float | None = None,
            md_damping: str = "zeta") -> MeanResult | None:
    """MoorDyn at dt; a run that blows up over the full 300 s is retried at 0.8 dt (down to
    0.3 of the given dt). None when no run survived."""
    case = scene_case(period, drag, t_end, md_damping=md_damping)
    dt0 = dt
    run = wp.run_moordyn(case, n_seg, dt, None)
    while run is None and dt > 0.3 * dt0:
        dt *= 0.8
        run = wp.run_moordyn(case, n_seg, dt, None)
    if run is None:
        return None
    mean, lo, hi = dynamic_mean(run, average_from)
    qs = m.quasi_static_mean(40) if qs_mean is None else qs_mean
    ba = "BA/-zeta -0.8" if md_damping == "zeta" else f"BA {AXIAL_DAMPING:.3g} N s (matched)"
    return MeanResult("MoorDyn", n_seg, f"dt {run.stats['dt']:.3g} s, {ba}", period, drag, mean, lo,
                      hi, run.cpu, qs)


def moordyn_static(n_seg: int, dt: float, x: float = 0.0, hold: float = 1.0) -> float:
    """MoorDyn's fairlead tension with the fairlead held at x: its own static initial condition
    (moordyn.Init), then `hold` s at rest (the force is read after the first step; a residual
    motion of the initial condition shows as a difference to the closed form)."""
    case = scene_case(t_end=hold, traj=Hold(x))
    run = wp.run_moordyn(case, n_seg, dt, None)
    if run is None:
        raise RuntimeError(f"MoorDyn static run failed (N = {n_seg}, dt = {dt:g})")
    return float(fairlead_tension(run)[-1])


# ----------------------------------------------------------------------------- study
def matched_dt(n_seg: int, fraction: float = 0.25) -> float:
    """MoorDyn's step with matched (light) damping: a fixed fraction of the axial wave transit time
    of a segment, l / sqrt(EA / m). The bisection of moordyn_stable_dt is not usable there: with
    BA = 6.7e5 N s the instability above ~0.5 l / c grows slowly and does not trip its blow-up
    check within the trial (measured at 20 segments: 0.5 l / c gives +8.7 % and 62 MN peaks,
    0.25 and 0.125 l / c agree to 0.02 percentage points)."""
    ch = m.CHAIN
    return fraction * ch["length"] / n_seg / math.sqrt(ch["EA"] / ch["massPerLength"])


# (period [s], drag) of the physics decomposition: drag off, slower surges
VARIANTS = [(10.0, False), (20.0, True), (50.0, True), (100.0, True), (100.0, False)]


@dataclass
class Study:
    qs_mean: float
    T0: float
    scene: list  # MeanResult of the reference scene (period 10 s, drag)
    statics: list  # (segments, dt, MoorDyn static fairlead tension at x = 0)
    variants: list  # MeanResult of VARIANTS
    average_from: float
    t_end: float


def run_study(fmu, elements=(20, 40, 80), tension_only=(20, 40, 80), tol_check=1e-10,
              segments=(20, 40, 80, 160),
              variant_elements=(20, 40), variant_segments=(40, 80), t_end=300.0,
              average_from=100.0, progress=None) -> Study:
    """All runs of scripts/mooring_dynamic_mean. progress(done, total, label) after each job."""
    qs = m.quasi_static_mean(40)
    jobs = [("ours", n, 1e-8, m.SURGE_PERIOD, True) for n in elements]
    jobs += [("ours tension-only", n, 1e-8, m.SURGE_PERIOD, True) for n in tension_only]
    if tol_check:
        jobs.append(("ours", min(elements), tol_check, m.SURGE_PERIOD, True))
    jobs += [("MoorDyn", n, "zeta", m.SURGE_PERIOD, True) for n in segments]
    jobs += [("MoorDyn", n, "matched", m.SURGE_PERIOD, True) for n in segments]
    jobs += [("static", n, None, None, None) for n in segments]
    for period, drag in VARIANTS:
        jobs += [("ours", n, 1e-8, period, drag) for n in variant_elements]
        jobs += [("MoorDyn", n, "zeta", period, drag) for n in variant_segments]
    scene, statics, variants, stable = [], [], [], {}
    kw = dict(t_end=t_end, average_from=average_from, qs_mean=qs)
    for j, (code, n, setting, period, drag) in enumerate(jobs):
        if progress is not None:
            progress(j, len(jobs), f"{code} N={n} {setting or ''} T={period} drag={drag}")
        if code.startswith("ours"):
            r = ours(fmu, n, setting, period, drag, compression=code == "ours", **kw)
        elif code == "MoorDyn" and setting == "matched":
            r = moordyn(n, matched_dt(n), period, drag, md_damping="matched", **kw)
        else:
            key = (n, period if code == "MoorDyn" else m.SURGE_PERIOD, drag if code == "MoorDyn" else True)
            if key not in stable:
                stable[key] = moordyn_dt(*key)
            if code == "static":
                statics.append((n, 0.9 * stable[key], moordyn_static(n, 0.9 * stable[key])))
                continue
            r = moordyn(n, 0.9 * stable[key], period, drag, **kw)
        if r is None:
            raise RuntimeError(f"MoorDyn blew up: N = {n}, {setting}, period {period}, drag {drag}")
        (scene if (period, drag) == (m.SURGE_PERIOD, True) else variants).append(r)
    if progress is not None:
        progress(len(jobs), len(jobs), "done")
    return Study(qs, m.closed_form().fairlead_tension, scene, statics, variants, average_from, t_end)


def save_study(s: Study, path) -> None:
    import json
    from dataclasses import asdict
    d = asdict(s)
    path.write_text(json.dumps(d, indent=1))


def load_study(path) -> Study:
    import json
    d = json.loads(path.read_text())
    d["scene"] = [MeanResult(**r) for r in d["scene"]]
    d["variants"] = [MeanResult(**r) for r in d["variants"]]
    d["statics"] = [tuple(x) for x in d["statics"]]
    return Study(**d)


# ----------------------------------------------------------------------------- report
def finest(results, code, period, drag):
    """The finest-mesh result of `code` for (period, drag) (MoorDyn: its usual damping), or None."""
    rs = [r for r in results if r.code == code and r.period == period and r.drag == drag
          and "matched" not in r.setting and "1e-10" not in r.setting and "tension-only" not in r.setting]
    return max(rs, key=lambda r: r.resolution) if rs else None


def _row(r: MeanResult) -> str:
    axial = "tension-only" if r.code == "MoorDyn" else f"{r.min_axial / 1e3:.0f}"
    return (f"| {r.code} | {r.resolution} | {r.setting} | {r.mean / 1e6:.5f} | {r.deviation:+.3%} | "
            f"{r.t_min / 1e6:.3f} .. {r.t_max / 1e6:.3f} | {axial} | {r.cpu:.2f} |")


HEAD = ["| code | elements / segments | step, tolerance, damping | dynamic mean [MN] | vs quasi-static "
        "| fairlead range [MN] | min axial force in the line [kN] | CPU [s] |",
        "|---|---|---|---|---|---|---|---|"]


def report(s: Study) -> str:
    lines = [
        "# Mooring surge: dynamic mean tension against the quasi-static mean", "",
        "Generated by `bash scripts/mooring_dynamic_mean` (module `studies.benchmarks.mooring_dynamics`; do not edit "
        "by hand). The scene of [mooring.md](mooring.md) section 3: chain 900 m, EA 7.5e8 N, 113 kg/m, "
        "d 0.0766 m, Cdn 2.4, Cdt 0.2 (on π d), Can 1, Cat 0, no bending, anchor at (-850, 0, -320) m, "
        "seabed at 320 m (ours: 1e6 N/m², 1000 N s/m² per unit length; MoorDyn: kBot, cBot = the same "
        "divided by d), fairlead x = 5 sin(2π t / T) m at z = -70 m from the static equilibrium at "
        f"x = 0, {s.t_end:g} s, mean of |fairlead force| every 0.1 s over [{s.average_from:g}, {s.t_end:g}) s "
        "(half-open: every phase once; the closed window of mooring.md counts the phase at 100 and 300 s, "
        "near the snap peak, twice, which adds ~0.04 points). "
        "Both codes are driven through the `studies.benchmarks.work_precision` runners (ours: inputs and der(tow.v) "
        "every 0.1 s; MoorDyn 2.7.2: RK2, the fairlead a coupled point moved every MoorDyn step, starting "
        "from its own static solution `moordyn.Init`).", "",
        f"Quasi-static cycle mean (closed form, 40 phases): **{s.qs_mean / 1e6:.5f} MN**; static tension "
        f"at x = 0: {s.T0 / 1e6:.5f} MN. Required bound: dynamic mean within 0.5 %.", "",
        "Axial damping: ours 0.01 s x 6.709e7 N = 6.7e5 N s (the FMU default, independent of the mesh). "
        "MoorDyn rows 'BA/-zeta -0.8' use its usual setting (80 % of critical damping of each segment's "
        "axial mode: BA = 1.6 l sqrt(EA m) = 2.1e7 N s at 20 segments, falling with l) at 0.9 x its "
        "stable step (bisection); rows 'BA 6.71e+05' use our damping, at 0.25 x the segment's axial "
        "transit time l / c (see `matched_dt`). Ours is an elastic rod that also carries compression; "
        "MoorDyn's segments are tension-only.", "",
        f"## 1. The reference scene: T = {m.SURGE_PERIOD:g} s, drag on", "", *HEAD,
        *[_row(r) for r in s.scene], "",
        "MoorDyn's own static fairlead tension at x = 0 (sanity check of its statics and of the matched "
        f"set-up against the closed form {s.T0 / 1e6:.5f} MN):", "",
        "| segments | dt [s] | static tension [MN] | vs closed form |", "|---|---|---|---|",
        *[f"| {n} | {dt:.3g} | {T / 1e6:.5f} | {T / s.T0 - 1:+.3%} |" for n, dt, T in s.statics], "",
        "## 2. Physics decomposition: drag off, slower surge (same 5 m amplitude)", "",
        "The quasi-static mean does not depend on the period (the same positions, the same phase "
        "weights).", "",
        "| period [s] | drag | " + HEAD[0][2:], "|---|---|" + HEAD[1][1:],
        *[f"| {r.period:g} | {'on' if r.drag else 'off'} " + _row(r) for r in s.variants], "",
        "## 3. Reading", "",
    ]
    lines += _reading(s)
    return "\n".join(lines) + "\n"


def _finest_two(rs):
    """(finest, next coarser) of results sorted by resolution, or (finest, None)."""
    rs = sorted(rs, key=lambda r: r.resolution)
    return rs[-1], (rs[-2] if len(rs) > 1 else None)


def _reading(s: Study) -> list:
    """Statements computed from the runs (each one states the numbers it rests on)."""
    out = []
    groups = {"ours": [r for r in s.scene if r.code == "ours" and r.setting == "relTol 1e-08"],
              "ours (tension-only)": [r for r in s.scene if "tension-only" in r.setting],
              "MoorDyn (BA/-zeta -0.8)": [r for r in s.scene if "zeta" in r.setting],
              "MoorDyn (BA matched)": [r for r in s.scene if "matched" in r.setting]}
    devs = [r.deviation for r in s.scene]
    out.append(f"- Reference scene: the runs of both codes lie {min(devs):+.2%} .. {max(devs):+.2%} from the "
               "quasi-static mean.")
    best = {}
    for name, rs in groups.items():
        if not rs:
            continue
        f, c = _finest_two(rs)
        best[name] = f
        seq = " / ".join(f"{r.deviation:+.3%}" for r in sorted(rs, key=lambda r: r.resolution))
        res = " / ".join(str(r.resolution) for r in sorted(rs, key=lambda r: r.resolution))
        last = f"; last refinement {c.resolution} -> {f.resolution}: {100 * (f.deviation - c.deviation):+.3f} points" if c else ""
        out.append(f"  - {name}, {res}: {seq}{last}.")
    tol = [(a, b) for a in groups["ours"] for b in s.scene
           if b.code == "ours" and b.resolution == a.resolution and b.setting.startswith("relTol")
           and b.setting != a.setting and "tension-only" not in b.setting]
    for a, b in tol:
        out.append(f"  - our relTol {b.setting.split()[-1]} instead of 1e-8 at {a.resolution} elements: "
                   f"{100 * (b.deviation - a.deviation):+.3f} points (the integrator is not what limits it).")
    if "ours" in best and len(best) > 1:
        o = best["ours"]
        for name, f in best.items():
            if name.startswith("MoorDyn"):
                out.append(f"  - finest runs, {name} {f.resolution} segments minus ours {o.resolution} "
                           f"elements: {100 * (f.deviation - o.deviation):+.3f} points.")
        rs = sorted(groups["ours"], key=lambda r: r.resolution)
        if min(r.min_axial for r in rs) < 0:
            out.append("  - our line goes into compression during the run (smallest axial force over the "
                       "cable " + " / ".join(f"{r.min_axial / 1e3:.0f}" for r in rs) + " kN at "
                       + " / ".join(str(r.resolution) for r in rs) + " elements; no bending stiffness), "
                       "MoorDyn's segments cannot (tension-only).")
        if "ours (tension-only)" in best:
            t = best["ours (tension-only)"]
            for name, f in best.items():
                if name.startswith("MoorDyn"):
                    out.append(f"  - with our tension-only law (enableCompression = 0, MoorDyn's): {name} "
                               f"{f.resolution} segments minus ours {t.resolution} elements: "
                               f"{100 * (f.deviation - t.deviation):+.3f} points.")
    verdict = "is" if min(devs) > 5e-3 else "is not"
    out.append(f"- Every run {verdict} above the 0.5 % bound for this scene.")
    slow = [f for T in sorted({r.period for r in s.variants if r.period >= 50.0})
            for f in (finest(s.variants, "ours", T, True), finest(s.variants, "MoorDyn", T, True)) if f]
    if slow:
        worst = max(abs(r.deviation) for r in slow)
        out.append(f"- Slow surge (T >= 50 s, drag on), finest run of each code: within {worst:.3%} of the "
                   f"quasi-static mean ({'inside' if worst < 5e-3 else 'outside'} the 0.5 % bound); "
                   "the coarser MoorDyn runs are further off (its lumped touchdown moves node by node).")
    out.append("- The finest run of each code, scene by scene, against the sum of the two codes' last "
               "refinement changes (their own discretization-error estimate):")
    every = s.variants + s.scene
    for T, drag in sorted({(r.period, r.drag) for r in every}):
        a, b = finest(every, "ours", T, drag), finest(every, "MoorDyn", T, drag)
        if not (a and b):
            continue
        steps = []
        for code in ("ours", "MoorDyn"):
            rs = [r for r in every if r.code == code and r.period == T and r.drag == drag
                  and "matched" not in r.setting and "1e-10" not in r.setting]
            f, c = _finest_two(rs)
            steps.append(abs(f.deviation - c.deviation) if c else math.nan)
        gap = abs(a.deviation - b.deviation)
        est = sum(steps)
        slack = min(a.t_min, b.t_min) < 0.1 * s.T0
        verdict = "" if math.isnan(est) else (", within" if gap <= est else ", beyond") + f" {100 * est:.3f}"
        out.append(f"  - T = {T:g} s, drag {'on' if drag else 'off'}: ours {a.resolution} el. "
                   f"{a.deviation:+.3%}, MoorDyn {b.resolution} seg. {b.deviation:+.3%}: gap "
                   f"{100 * gap:.3f} points{verdict}; smallest fairlead tension "
                   f"{min(a.t_min, b.t_min) / 1e3:.0f} kN{' (slack and snap)' if slack else ''}.")
    nodrag = [r for r in s.variants if not r.drag and r.period == m.SURGE_PERIOD]
    if nodrag:
        slack = min(r.t_min for r in nodrag) < 0.1 * s.T0
        out.append(
            f"- Drag off at T = {m.SURGE_PERIOD:g} s: {min(r.deviation for r in nodrag):+.2%} .. "
            f"{max(r.deviation for r in nodrag):+.2%}, smallest fairlead tension "
            f"{min(r.t_min for r in nodrag) / 1e6:.2f} MN ("
            + ("the top still goes slack)." if slack else
               f"no slack: above 10 % of T0), against {min(r.t_min for r in s.scene) / 1e3:.0f} kN and peaks "
               f"up to {max(r.t_max for r in s.scene) / 1e6:.2f} MN with drag (quasi-static maximum "
               f"{m.closed_form(m.SURGE_AMPLITUDE).fairlead_tension / 1e6:.2f} MN). So the excess of the reference "
               "scene comes with the drag: the normal drag on the chain (fairlead speed up to "
               f"{m.SURGE_AMPLITUDE * 2 * math.pi / m.SURGE_PERIOD:.2f} m/s) holds it back while the "
               "fairlead moves towards the anchor, the top goes slack and snaps taut on the way out; the "
               "tension cannot fall much below zero at the fairlead, while the snap peaks reach twice the "
               "quasi-static maximum."))
    return out


def plot(s: Study, path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2))
    groups = {}
    for r in s.scene:
        key = r.code + (("" if "tension-only" not in r.setting else " tension-only") if r.code == "ours"
                        else (" BA/-zeta -0.8" if "zeta" in r.setting else " BA matched"))
        if r.code == "ours" and "1e-10" in r.setting:
            continue
        groups.setdefault(key, []).append(r)
    for key, rs in groups.items():
        rs.sort(key=lambda r: r.resolution)
        a1.semilogx([r.resolution for r in rs], [100 * r.deviation for r in rs], "o-", label=key)
    a1.axhspan(-0.5, 0.5, color="g", alpha=0.15, label="required bound +-0.5 %")
    a1.set_xlabel("elements / segments"), a1.set_ylabel("dynamic mean - quasi-static [%]")
    a1.set_title(f"T = {m.SURGE_PERIOD:g} s, drag on"), a1.legend(fontsize=8), a1.grid(alpha=0.3)
    for code, drag, style in (("ours", True, "o-"), ("MoorDyn", True, "s--"), ("ours", False, "o:"),
                              ("MoorDyn", False, "s:")):
        every = s.variants + s.scene
        rs = [finest(every, code, T, drag) for T in sorted({r.period for r in every})]
        rs = [r for r in rs if r is not None]
        if not rs:
            continue
        a2.semilogx([r.period for r in rs], [100 * r.deviation for r in rs], style,
                    label=f"{code} (finest run per period), drag {'on' if drag else 'off'}")
    a2.axhspan(-0.5, 0.5, color="g", alpha=0.15)
    a2.set_xlabel("surge period [s]"), a2.set_ylabel("dynamic mean - quasi-static [%]")
    a2.set_title("5 m surge: period and drag"), a2.legend(fontsize=8), a2.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None) -> int:
    import argparse
    import sys
    from pathlib import Path

    from ucable.paths import REPO_ROOT, require_fmu
    from ucable.progress import ProgressBar

    p = argparse.ArgumentParser(prog="scripts/mooring_dynamic_mean", description=(
        "Mooring surge scene: dynamic mean fairlead tension of our FMU and MoorDyn against the "
        "quasi-static mean, with mesh/tolerance convergence and a drag / period decomposition."))
    p.add_argument("--elements", type=int, nargs="+", default=[20, 40, 80],
                   help="our element counts for the reference scene (default 20 40 80; 160 takes ~10 min)")
    p.add_argument("--tension-only", type=int, nargs="*", default=[20, 40, 80],
                   help="our element counts with enableCompression = 0 (MoorDyn's law; default 20 40 80)")
    p.add_argument("--segments", type=int, nargs="+", default=[20, 40, 80, 160],
                   help="MoorDyn segment counts for the reference scene (default 20 40 80 160)")
    p.add_argument("--tol-check", type=float, default=1e-10,
                   help="extra relTol at the smallest element count (0: skip; default 1e-10)")
    p.add_argument("--no-variants", action="store_true", help="skip the drag / period decomposition")
    p.add_argument("--doc", type=Path, default=None,
                   help="write the Markdown report here (e.g. docs/mooring_dynamic_mean.md; the PNG "
                        "goes next to it)")
    p.add_argument("--out", type=Path, default=REPO_ROOT / "out" / "mooring_dynamic_mean",
                   help="output directory (report and PNG; default out/mooring_dynamic_mean)")
    p.add_argument("--from-json", type=Path, default=None,
                   help="rewrite the report from a saved study (OUT/study.json) without running")
    p.add_argument("--fmu", type=Path, default=None)
    args = p.parse_args(argv)
    fmu = None if args.from_json else (args.fmu if args.fmu is not None else require_fmu())
    bar = ProgressBar(1, "mooring dynamic mean")

    def progress(done, total, label):
        bar.total = float(total)
        bar.update(done, label)

    args.out.mkdir(parents=True, exist_ok=True)
    if args.from_json is not None:
        s = load_study(args.from_json)
    else:
        s = run_study(fmu, elements=tuple(args.elements), tension_only=tuple(args.tension_only),
                      segments=tuple(args.segments),
                      tol_check=args.tol_check or None,
                      variant_elements=() if args.no_variants else (20, 40),
                      variant_segments=() if args.no_variants else (40, 80), progress=progress)
        bar.close()
        save_study(s, args.out / "study.json")
    text = report(s)
    png = args.out / "mooring_dynamic_mean.png"
    plot(s, png)
    text += f"\n![dynamic mean against resolution and period]({png.name})\n"
    (args.out / "mooring_dynamic_mean.md").write_text(text)
    if args.doc is not None:
        import shutil
        args.doc.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(png, args.doc.parent / png.name)
        args.doc.write_text(text)
        print(f"wrote {args.doc}", file=sys.stderr)
    print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
