"""Proxy far end study (scripts/proxy_study): a towed body that integrates its own translation (a plain
causal interface: cable force in, position and velocity out) coupled through the proxy far end
(bottomEnd 4): the third party's Towfish FMU (tests/third_party_body, built outside the project's CMake)
and the project's TowedBody FMU with integrateTranslation, computed two ways:

1. theory: the amplification factor (spectral radius of the one-step map) of the model problem of
   scripts/coupling_study (the cable's axial chain) with the proxy at its end, the external body with
   the tracking force and the estimate, against h omega, for body masses and inertia errors, both
   orderings (stability_proxy);
2. measurement: the three-FMU system over the Hopland acceleration and a 90 deg turn, body masses
   50-2000 kg, steps 0.1 / 0.5 / 1 s, Gauss-Seidel and Jacobi (fmpy), against the internal body
   (bottomEnd 2, the same numbers, the same step and ordering): the acceptance table, and the same with
   the proxy's inertia (m + m_a) off by -50 ... +50 % (the sensitivity table).

compute() returns the data; markdown() and plot() write the report: the generated section of
docs/cosimulation.md (markers `proxy_study`) and docs/proxy_amplification.png.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import tempfile
import time
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np
from scipy.linalg import expm

from ucable import system as S
from ucable.fmu import FMICallException
from ucable.paths import REPO_ROOT, require_fmu
from ucable.progress import ProgressBar
from ucable.units import KNOT

from .coupling_study import POSITION_BOUND, TENSION_BOUND, Chain, _compare, _spectral_radius, end_mass_system
from ..doc_section import write_section

MASSES = [50.0, 200.0, 400.0, 1000.0, 2000.0]
STEPS = [0.1, 0.5, 1.0]
MANOEUVRES = ["accelerate", "turn90"]
INERTIA_ERRORS = [-0.5, -0.25, -0.1, 0.1, 0.25, 0.5]
SENSITIVITY_MASSES = [50.0, 2000.0]
# the FMU's defaults (schema): tracking gains as fractions of M / h^2 and M / h, the estimate's
# low-pass max(FILTER_TIME, FILTER_STEPS h)
ALPHA, BETA, FILTER_TIME, FILTER_STEPS = 0.05, 0.3, 1.0, 5.0
SECTION = "proxy_study"
BODIES = {"towfish": "the third party's Towfish FMU (tests/third_party_body)",
          "towedbody": "the project's TowedBody FMU, integrateTranslation = true"}


# ------------------------------------------------------------------------------------ theory
def _body_map(M: float, cb: float, h: float) -> np.ndarray:
    """Exact step of a body M x'' = F - cb x' with F held: maps (x, v, F) to (x, v, F)."""
    return expm(np.array([[0.0, 1.0, 0.0], [0.0, -cb / M, 1.0 / M], [0.0, 0.0, 0.0]]) * h)


def _phi(a: float) -> float:
    """a / (e^a - 1), 1 at a = 0."""
    return 1.0 if abs(a) < 1e-12 else a / math.expm1(a)


def stability_proxy(h: float, M: float, chain: Chain, cb: float, ordering: str, inertia_error: float = 0.0,
                    learned: float = 1.0, alpha: float = ALPHA, beta: float = BETA, tau: float | None = None) -> float:
    """Spectral radius of the proxy far end's one-step map, as the FMUs do it. The cable's axial chain
    (coupling_study.Chain, the tow point held) ends in the proxy: the end node carries the proxy's
    inertia Mp = M (1 + inertia_error) and the estimate Fe - cp v (its constant part held over the step,
    its drag law cp = learned * cb at the proxy's velocity), integrated exactly with the chain. After
    the step the cable returns the force that takes a body with the estimated forces from the proxy's
    old velocity v0 to its new v1, F = -(Fe - cp v1) - (Mp / h) phi(cp h / Mp) (v0 - v1), plus the
    tracking force T = Mp [alpha (e + h e' + d) / h^2 + beta e' / h] (e, e': the proxy's position and
    velocity less the body's at the step's start, d the proxy's departure from the trapezoidal path),
    and moves the estimate's constant part, Fe -= h / (tau + h) T. The body (mass M, its own linear
    drag cb) integrates exactly with F held: the new F under Gauss-Seidel, the one of the last step
    under Jacobi."""
    if tau is None:
        tau = max(FILTER_TIME, FILTER_STEPS * h)
    f = chain.n - 1
    Mp = M * (1.0 + inertia_error)
    cp = learned * cb
    me = chain.m / 2 + Mp
    A = end_mass_system(chain, me, cp)  # chain, proxy (x, v), the estimate's constant part held
    A[2 * f + 1, 2 * f + 2] = 1.0 / me
    E = expm(A * h)
    B = _body_map(M, cb, h)
    jac = ordering == "jacobi"
    gamma = h / (tau + h)
    follow = Mp / h * _phi(cp * h / Mp)

    def step(s):
        xp, vp, Fe = s[2 * f], s[2 * f + 1], s[2 * f + 2]
        xb, vb, F_last = s[2 * f + 3], s[2 * f + 4], s[2 * f + 5]
        y = E @ s[:2 * f + 3]
        xp1, vp1 = y[2 * f], y[2 * f + 1]
        e, ev = xp - xb, vp - vb
        T = Mp * (alpha * (e + h * ev + (xp1 - xp - 0.5 * h * (vp + vp1))) / h ** 2 + beta * ev / h)
        F = -(Fe - cp * vp1) - follow * (vp - vp1) + T
        body = B @ np.array([xb, vb, F_last if jac else F])
        return np.concatenate([y[:2 * f + 2], [Fe - gamma * T, body[0], body[1], F]])

    return _spectral_radius(step, 2 * f + 6)


def drag_damping(mass: float, speed: float = 1.1 * KNOT) -> float:
    """Along-flow derivative of the body's quadratic drag at the slowest tow speed, rho CdA |u| [N s/m]."""
    return 1025.0 * S.Body(mass).resolved().cda * speed


def theory() -> dict:
    """Spectral radii against h omega (omega^2 = k / M, k the last element's axial stiffness) for the
    body masses and inertia errors, both orderings, without the body's drag (the least damped case);
    and the largest radius over a grid of steps 0.01-1 s, bodies of 20-2000 kg (added mass a quarter),
    inertia errors -50 ... +50 %: without drag, and with the drag at the slowest tow speed, the
    estimate's drag law learned (cp = cb), not yet (0) or twice the body's."""
    chain = Chain.hopland()
    hs = np.geomspace(0.01, 2.0, 40)
    out = {"chain": asdict(chain), "steps": hs.tolist(), "curves": {}}
    for ordering in S.ORDERINGS:
        for mass in (50.0, 2000.0):
            M = mass * 1.25
            for err in (-0.5, 0.0, 0.5):
                key = f"{ordering}|{mass:g}|{err:g}"
                out["curves"][key] = {"Omega": (hs * math.sqrt(chain.k / M)).tolist(),
                                      "rho": [stability_proxy(h, M, chain, 0.0, ordering, err, 0.0) for h in hs]}
    worst = {}
    for ordering in S.ORDERINGS:
        for err in (-0.5, -0.25, 0.0, 0.25, 0.5):
            rho, where = 0.0, None
            for mass in (20.0, 50.0, 400.0, 2000.0):
                for cb, learned in ((0.0, 0.0), (drag_damping(mass), 0.0), (drag_damping(mass), 1.0),
                                    (drag_damping(mass), 2.0)):
                    for h in (0.01, 0.05, 0.1, 0.2, 0.5, 1.0):
                        r = stability_proxy(h, mass * 1.25, chain, cb, ordering, err, learned)
                        if r > rho:
                            rho, where = r, {"mass": mass, "drag": cb, "learned": learned, "step": h}
            worst[f"{ordering}|{err:g}"] = {"rho": rho, **where}
    out["worst"] = worst
    return out


# ------------------------------------------------------------------------------------ measurement
@dataclass
class Cell:
    body: str  # BODIES
    manoeuvre: str
    ordering: str
    step: float
    mass: float
    inertia_error: float  # relative error of the proxy's (m + m_a)
    status: str  # ok, bounds, diverged, fmi2Error
    tension_rms: float  # RMS tow-tension difference to the internal body / RMS tension
    position_max: float  # [m] largest distance between the external body and the internal one
    cpu: float
    note: str = ""


def proxy_parameters(mass: float, inertia_error: float) -> dict:
    """The cable's parameters that put the proxy's inertia off by inertia_error: the added-mass matrix
    adds inertia_error (m + m_a) I (the weight and buoyancy stay the body's)."""
    if inertia_error == 0.0:
        return {}
    b = S.Body(mass).resolved()
    d = inertia_error * (b.mass + b.added_mass)
    return {f"body.addedMassMatrix.{q}{q}": d for q in "xyz"}


def run_pair(manoeuvre: str, step: float, ordering: str, mass: float, inertia_error: float = 0.0,
             internal=None, duration: float | None = None, body_fmu: Path | None = None):
    """(cell, internal result): the proxy run against the internal body at the same step and ordering
    (fmpy; Gauss-Seidel passes the tow acceleration, Jacobi passes nothing, as libcosim); the body FMU
    body_fmu (the TowedBody's names) or the TowedBody itself."""
    derivatives = ordering == "gauss-seidel"
    body = S.Body(mass)
    name = "towedbody" if body_fmu is None else "towfish"
    if internal is None:
        internal = S.run(manoeuvre, step, "internal", "fmpy", ordering, body, duration=duration,
                         input_derivatives=derivatives)
    cpu0 = time.process_time()
    try:
        r = S.run(manoeuvre, step, "proxy", "fmpy", ordering, body, duration=duration,
                  input_derivatives=derivatives, cable_parameters=proxy_parameters(mass, inertia_error),
                  body_fmu=body_fmu)
    except (S.Diverged, FMICallException) as e:
        status = "diverged" if isinstance(e, S.Diverged) else "fmi2Error"
        return Cell(name, manoeuvre, ordering, step, mass, inertia_error, status, math.nan, math.nan,
                    time.process_time() - cpu0, str(e)[:120]), internal
    rms, _, dp = _compare(r, internal)
    ok = rms <= TENSION_BOUND and dp <= POSITION_BOUND
    return Cell(name, manoeuvre, ordering, step, mass, inertia_error, "ok" if ok else "bounds", rms, dp,
                r.cpu), internal


def measure(steps=STEPS, masses=MASSES, manoeuvres=MANOEUVRES, errors=INERTIA_ERRORS,
            sensitivity_masses=SENSITIVITY_MASSES, bodies=("towfish",), towfish=None, progress=None) -> list:
    """The cells; the sensitivity runs with the first of the bodies."""
    cells = []
    done = 0
    for man in manoeuvres:
        for mass in masses:
            for ordering in S.ORDERINGS:
                for h in steps:
                    internal = None
                    for b in bodies:
                        fmu = towfish if b == "towfish" else None
                        cell, internal = run_pair(man, h, ordering, mass, internal=internal, body_fmu=fmu)
                        cells.append(cell)
                        done += 1
                        if progress is not None:
                            progress.update(done, f"{b} {man} {mass:g} kg {ordering} {h:g} s: {cell.status}")
                    if mass not in sensitivity_masses:
                        continue
                    fmu = towfish if bodies[0] == "towfish" else None
                    for err in errors:
                        cells.append(run_pair(man, h, ordering, mass, err, internal, body_fmu=fmu)[0])
                        done += 1
                        if progress is not None:
                            progress.update(done, f"{man} {mass:g} kg {ordering} {h:g} s {err:+.0%}: "
                                                  f"{cells[-1].status}")
    return cells


def count_runs(steps, masses, manoeuvres, errors, sensitivity_masses, bodies=("towfish",)) -> int:
    per = len(steps) * len(S.ORDERINGS)
    return len(manoeuvres) * per * (len(masses) * len(bodies) +
                                    len([m for m in masses if m in sensitivity_masses]) * len(errors))


def compute(steps=STEPS, masses=MASSES, manoeuvres=MANOEUVRES, errors=INERTIA_ERRORS,
            sensitivity_masses=SENSITIVITY_MASSES, bodies=("towfish",), progress=None) -> dict:
    from .third_party_study import build_towfish

    with tempfile.TemporaryDirectory(prefix="towfish-") as tmp:
        towfish = build_towfish(Path(tmp)) if "towfish" in bodies else None
        cells = measure(steps, masses, manoeuvres, errors, sensitivity_masses, tuple(bodies), towfish, progress)
    return {"steps": list(steps), "masses": list(masses), "manoeuvres": list(manoeuvres), "errors": list(errors),
            "sensitivity_masses": list(sensitivity_masses), "bodies": list(bodies),
            "cells": [asdict(c) for c in cells], "theory": theory()}


# ------------------------------------------------------------------------------------ report
def _worst(cells, ordering, h, m, err, body):
    group = [c for c in cells if c["ordering"] == ordering and c["step"] == h and c["mass"] == m
             and c["inertia_error"] == err and c["body"] == body]
    rank = {"fmi2Error": 3, "diverged": 2, "bounds": 1, "ok": 0}
    return max(group, key=lambda c: (rank[c["status"]], c["position_max"] if c["position_max"] == c["position_max"]
                                     else 0.0))


def _cell_text(c) -> str:
    if c["status"] in ("diverged", "fmi2Error"):
        return f"**{c['status']}**"
    text = f"{100 * c['tension_rms']:.2g} % / {c['position_max']:.2g} m"
    return f"**{text}**" if c["status"] != "ok" else text


def markdown(data: dict, figure: str) -> str:
    cells, steps, masses, bodies = data["cells"], data["steps"], data["masses"], data["bodies"]
    lines = [f"Measured by `scripts/proxy_study` (fmpy, the three-FMU system with a body FMU integrating its own "
             f"translation, {', '.join(data['manoeuvres'])}). Each cell: RMS tow-tension difference to the internal "
             f"body (`bottomEnd` 2, the same numbers, the same step and ordering) in % of the RMS tension / largest "
             f"distance between the two bodies; the worse of the manoeuvres. **Bold**: outside the bounds "
             f"({100 * TENSION_BOUND:g} %, {POSITION_BOUND:g} m) or failed.", ""]
    header = "| body mass | " + " | ".join(f"{o} {h:g} s" for o in S.ORDERINGS for h in steps) + " |"
    rule = "|---|" + "---:|" * (len(steps) * len(S.ORDERINGS))
    for body in bodies:
        name = BODIES[body][0].upper() + BODIES[body][1:]
        lines += [f"**{name}, (m + m_a) given exactly**", "", header, rule]
        for m in masses:
            lines.append(f"| {m:g} kg | " + " | ".join(_cell_text(_worst(cells, o, h, m, 0.0, body))
                                                      for o in S.ORDERINGS for h in steps) + " |")
        exact = [c for c in cells if c["inertia_error"] == 0.0 and c["body"] == body]
        ok = [c for c in exact if c["status"] == "ok"]
        finite = [c for c in exact if c["tension_rms"] == c["tension_rms"]]
        lines += ["", f"{len(ok)} of {len(exact)} runs within the bounds."]
        if finite:
            wt = max(finite, key=lambda c: c["tension_rms"])
            wp = max(finite, key=lambda c: c["position_max"])
            lines[-1] += (f" Largest RMS tension difference {100 * wt['tension_rms']:.2g} % ({wt['manoeuvre']}, "
                          f"{wt['mass']:g} kg, {wt['step']:g} s, {wt['ordering']}), largest position difference "
                          f"{wp['position_max']:.3g} m ({wp['manoeuvre']}, {wp['mass']:g} kg, {wp['step']:g} s, "
                          f"{wp['ordering']}).")
        lines.append("")
    lines += [f"**Inertia error** ({BODIES[bodies[0]]}): the proxy's (m + m_a) off by the error (the added-mass "
              "matrix adds it; the body FMU unchanged), the same cells:", "",
              "| body mass | inertia error | " + " | ".join(f"{o} {h:g} s" for o in S.ORDERINGS for h in steps) + " |",
              "|---|---:|" + "---:|" * (len(steps) * len(S.ORDERINGS))]
    for m in data["sensitivity_masses"]:
        if m not in masses:
            continue
        for err in sorted(data["errors"] + [0.0]):
            lines.append(f"| {m:g} kg | {100 * err:+.0f} % | " + " | ".join(
                _cell_text(_worst(cells, o, h, m, err, bodies[0])) for o in S.ORDERINGS for h in steps) + " |")
    th = data["theory"]
    lines += ["", "Model problem (the cable's axial chain, the proxy at its end, the gains of the defaults): the "
              "largest amplification factor over steps 0.01–1 s, bodies of 20–2000 kg, without drag and with the "
              "drag at 1.1 kn (its derivative c_b), the estimate's drag law c_p = 0, c_b or 2 c_b:",
              "", "| ordering | inertia error | largest ρ | at |", "|---|---:|---:|---|"]
    for key, w in th["worst"].items():
        ordering, err = key.split("|")
        lines.append(f"| {ordering} | {100 * float(err):+.0f} % | {w['rho']:.4f} | {w['mass']:g} kg, "
                     f"{w['step']:g} s, c_b = {w['drag']:.0f} N s/m, c_p = {w['learned']:g} c_b |")
    lines += ["", f"![proxy amplification factors]({figure})"]
    return "\n".join(lines)


def plot(data: dict, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    styles = {-0.5: ":", 0.0: "-", 0.5: "--"}
    colours = {"50": "C0", "2000": "C3"}
    for ax, ordering in zip(axes, S.ORDERINGS):
        for key, curve in data["theory"]["curves"].items():
            o, mass, err = key.split("|")
            if o != ordering:
                continue
            ax.semilogx(curve["Omega"], curve["rho"], styles[float(err)], color=colours[mass],
                        label=f"{mass} kg, inertia {100 * float(err):+.0f} %")
        ax.axhline(1.0, color="k", lw=0.8)
        ax.set(xlabel="h ω  (ω² = EA / (l_e M))", title=f"proxy far end, {ordering}, no drag")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("amplification factor ρ")
    axes[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def parse_args(argv):
    p = argparse.ArgumentParser(prog="scripts/proxy_study", description=__doc__.split("\n")[0],
                                formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    p.add_argument("--steps", type=float, nargs="+", default=STEPS, help="communication steps [s]")
    p.add_argument("--masses", type=float, nargs="+", default=MASSES, help="body masses [kg]")
    p.add_argument("--manoeuvres", nargs="+", default=MANOEUVRES, choices=list(S.MANOEUVRES))
    p.add_argument("--errors", type=float, nargs="*", default=INERTIA_ERRORS,
                   help="relative errors of the proxy's inertia for the sensitivity table")
    p.add_argument("--sensitivity-masses", type=float, nargs="*", default=SENSITIVITY_MASSES,
                   help="body masses of the sensitivity table")
    p.add_argument("--bodies", nargs="+", default=list(BODIES), choices=list(BODIES),
                   help="the body FMUs (the sensitivity table uses the first)")
    p.add_argument("--out", type=Path, default=REPO_ROOT / "out" / "proxy_study", help="directory for study.json")
    p.add_argument("--doc", type=Path, default=None,
                   help="write the report into this Markdown file's generated section and the figure next to it "
                        "(docs/cosimulation.md)")
    p.add_argument("--from-json", type=Path, default=None, help="report from a saved study.json, no runs")
    return p.parse_args(argv)


def main(argv=None) -> int:
    args = parse_args(sys.argv[1:] if argv is None else argv)
    args.out.mkdir(parents=True, exist_ok=True)
    if args.from_json is not None:
        data = json.loads(args.from_json.read_text())
    else:
        require_fmu()
        steps, masses = sorted(args.steps), sorted(args.masses)
        bar = ProgressBar(count_runs(steps, masses, args.manoeuvres, args.errors, args.sensitivity_masses,
                                     args.bodies), label="proxy study")
        data = compute(steps, masses, args.manoeuvres, args.errors, args.sensitivity_masses, args.bodies,
                       progress=bar)
        bar.close("done")
        (args.out / "study.json").write_text(json.dumps(data))
    where = args.doc.parent if args.doc is not None else args.out
    figure = "proxy_amplification.png"
    plot(data, where / figure)
    section = markdown(data, figure)
    if args.doc is not None:
        write_section(args.doc, section, SECTION)
        print(f"updated {args.doc}")
    else:
        (args.out / "report.md").write_text(section + "\n")
    print(section)
    return 0


if __name__ == "__main__":
    sys.exit(main())
