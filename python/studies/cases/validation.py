"""Validation scenes: the FMU (through fmpy) against exact solutions (studies.references.exact, ucable.steady_tow).

Each function runs one scene on a fresh CableFMU and returns plain numbers (errors are relative to
the cable length L unless the name says otherwise, CPU time is time.process_time() around
initialization and stepping). tests/python/test_validation_*.py assert bounds on them;
studies.reports.validation_report sweeps them and writes docs/validation.md.
"""

from __future__ import annotations

import math
import time

import numpy as np
from scipy.optimize import least_squares

from ..references.exact import (ElasticCatenary, beam_string_frequencies, circular_arc, elastica_cases,
                    string_frequencies)
from ucable.fmu import NUM_STATIONS, CableFMU
from .manoeuvre import hopland_accelerate, run_tow
from ucable.steady_tow import CableProperties, body_end_load, solve_steady_tow
from ucable.units import HOUR, NAUTICAL_MILE

# ---------------------------------------------------------------------------------------- elastica
ELASTICA_L, ELASTICA_D, ELASTICA_E = 10.0, 0.02, 2e11
ELASTICA_DEPTH = 50.0  # tow point depth: the whole rod stays submerged (buoyancy only below z = 0)


def elastica_parameters(n_elements: int, init_mode: int = 0) -> dict:
    """Paper section 3.2: clamped horizontal cantilever, neutrally buoyant (rho_c = rho_w = 1000)."""
    A = math.pi * ELASTICA_D**2 / 4
    return {"length": ELASTICA_L, "diameter": ELASTICA_D, "waterDensity": 1000.0,
            "massPerLength": 1000.0 * A, "EA": ELASTICA_E * A,
            "EI": ELASTICA_E * math.pi * ELASTICA_D**4 / 64, "axialDamping": 0.01 * ELASTICA_E * A,
            "nElements": n_elements, "topEnd": 1, "topTangent.x": 1.0, "topTangent.y": 0.0,
            "topTangent.z": 0.0, "initialDirection.x": 1.0, "initialDirection.y": 0.0,
            "initialDirection.z": 0.0, "initMode": init_mode}


def elastica_strain(P: float) -> float:
    """Largest axial strain P/EA: the inextensible reference ignores a tip shift of at most P L / EA."""
    return P / (ELASTICA_E * math.pi * ELASTICA_D**2 / 4)


def elastica_case(P: float) -> dict:
    return next(c for c in elastica_cases() if c["P"] == P)


def elastica_static(fmu, P: float, n_elements: int) -> dict:
    """Initial equilibrium (initMode 0) under the dead tip load P [N]; tip in the paper's axes
    (x along the clamp, y up = z + depth)."""
    ref = elastica_case(P)
    cable = CableFMU(fmu, parameters=elastica_parameters(n_elements))
    try:
        cpu = time.process_time()
        cable.initialize(inputs={"tow.z": -ELASTICA_DEPTH, "endLoad.z": -P})
        cpu = time.process_time() - cpu
        x, y = cable.get("endPosition.x"), cable.get("endPosition.z") + ELASTICA_DEPTH
    finally:
        cable.free()
    return {"P": P, "N": n_elements, "x": x, "y": y, "cpu": cpu,
            "error": math.hypot(x - ref["x_tip"], y - ref["y_tip"]) / ELASTICA_L}


def elastica_dynamic(fmu, P: float, n_elements: int, t_end: float, step: float = 0.05) -> dict:
    """Paper Figs. 7-8: the straight rod at rest (initMode 1) under the suddenly applied tip load,
    damped by the default Morison drag (Cdn 1.649, Cdt 0.12) and added mass. Returns the tip history."""
    cable = CableFMU(fmu, parameters=elastica_parameters(n_elements, init_mode=1))
    n = int(round(t_end / step))
    t = np.arange(n + 1) * step
    tip = np.zeros((n + 1, 2))
    try:
        cpu = time.process_time()
        cable.initialize(start_time=0.0, stop_time=t_end,
                         inputs={"tow.z": -ELASTICA_DEPTH, "endLoad.z": -P})
        names = ["endPosition.x", "endPosition.z"]
        tip[0] = cable.get_reals(names)
        for k in range(n):
            cable.do_step(step, t=t[k])
            tip[k + 1] = cable.get_reals(names)
        cpu = time.process_time() - cpu
    finally:
        cable.free()
    tip[:, 1] += ELASTICA_DEPTH
    return {"P": P, "N": n_elements, "t": t, "x": tip[:, 0], "y": tip[:, 1], "cpu": cpu}


def end_couple(fmu, turns: float, n_elements: int) -> dict:
    """The elastica's cantilever bent by a couple M = 2 pi turns EI / L about +y at its free end:
    exact shape a circular arc of radius EI/M. Error = largest distance of the 21 stations from
    their exact places on the arc, / L."""
    params = elastica_parameters(n_elements)
    M = 2.0 * math.pi * turns * params["EI"] / params["length"]
    cable = CableFMU(fmu, parameters=params)
    try:
        cpu = time.process_time()
        cable.initialize(inputs={"tow.z": -ELASTICA_DEPTH, "endCouple.y": M})
        cpu = time.process_time() - cpu
        shape = cable.shape()
        kappa = cable.get_reals([f"curvature[{k}]" for k in range(1, NUM_STATIONS + 1)])
    finally:
        cable.free()
    s = np.linspace(0.0, params["length"], NUM_STATIONS)
    x, z = circular_arc(s, params["EI"] / M)
    dist = np.hypot(shape["shape.x"] - x, shape["shape.z"] + ELASTICA_DEPTH - z)
    exact_kappa = M / params["EI"]
    return {"turns": turns, "N": n_elements, "error": float(dist.max()) / params["length"],
            "cpu": cpu, "tip_error": float(dist[-1]) / params["length"],
            "curvature_error": float(np.max(np.abs(kappa / exact_kappa - 1.0))),
            "kappa_h": exact_kappa * params["length"] / n_elements}


# ---------------------------------------------------------------------------------------- catenary
CATENARY_TOP = np.array([0.0, 0.0, -10.0])
CATENARY_ANCHOR = np.array([-250.0, 0.0, -170.0])


def catenary(fmu, n_elements: int, anchor=CATENARY_ANCHOR, top=CATENARY_TOP) -> dict:
    """The default (Hopland) cable, 300 m, anchored at `anchor`, top held at `top`, no bending, no
    seabed, hanging in still water (initMode 0): against Irvine's elastic catenary."""
    props = CableProperties()
    L = props.length
    span = np.asarray(top, float) - np.asarray(anchor, float)
    ref = ElasticCatenary(L, props.submerged_weight, props.axial_stiffness, span[0], span[2])
    chord = span / np.linalg.norm(span)
    params = {"nElements": n_elements, "bottomEnd": 1, "enableBending": 0,
              "anchor.x": anchor[0], "anchor.y": anchor[1], "anchor.z": anchor[2],
              "initialDirection.x": -chord[0], "initialDirection.y": 0.0,
              "initialDirection.z": -chord[2]}
    cable = CableFMU(fmu, parameters=params)
    try:
        cpu = time.process_time()
        cable.initialize(inputs={"tow.x": top[0], "tow.y": top[1], "tow.z": top[2]})
        cpu = time.process_time() - cpu
        shape = cable.shape()
        T_top, T_bottom = cable.get("towTension"), cable.get("endTension")
        H_top, H_bottom = -cable.get("towForce.x"), cable.get("endForce.x")
    finally:
        cable.free()
    p = L - np.linspace(0.0, L, NUM_STATIONS)  # Irvine's coordinate runs from the anchor
    x, z = ref.position(p)
    dist = np.hypot(shape["shape.x"] - (x + anchor[0]), shape["shape.z"] - (z + anchor[2]))
    return {"N": n_elements, "cpu": cpu, "ref": ref,
            "shape_error": float(dist.max()) / L,
            "top_tension": T_top, "bottom_tension": T_bottom, "H": H_top, "H_bottom": H_bottom,
            "top_tension_rel": T_top / ref.top_tension - 1.0,
            "bottom_tension_rel": T_bottom / ref.bottom_tension - 1.0,
            "H_rel": max(abs(H_top / ref.H - 1.0), abs(H_bottom / ref.H - 1.0)),
            "station_tension_rel": float(np.max(np.abs(shape["tension"] - ref.tension(p))))
            / ref.top_tension}


# ---------------------------------------------------------------------------------------- towing
def towed_body_parameters(mass: float = 500.0, volume: float = 0.1, CdA: float = 0.5) -> dict:
    """An illustrative depressor-like towed body: 500 kg, 0.1 m3, CdA 0.5 m2."""
    return {"body.mass": mass, "body.volume": volume, "body.CdA": CdA}


def steady_tow(fmu, knots: float, n_elements: int, body: dict | None = None) -> dict:
    """Steady tow of the default cable (free end, or an internal towed body, bottomEnd 2) at the
    initial equilibrium (initMode 0), against the steady ODE (ucable.steady_tow)."""
    props = CableProperties()
    V = knots * NAUTICAL_MILE / HOUR
    params = {"nElements": n_elements, "initMode": 0}
    end_load = (0.0, 0.0)
    if body:
        params.update({"bottomEnd": 2, **body})
        end_load = body_end_load(V, body["body.mass"], body["body.volume"], body["body.CdA"],
                                 props.water_density, props.gravity)
    ref = solve_steady_tow(V, props, end_load=end_load)
    cable = CableFMU(fmu, parameters=params)
    try:
        cpu = time.process_time()
        cable.initialize(inputs={"tow.vx": V})
        cpu = time.process_time() - cpu
        T = cable.get("towTension")
        Fx, Fz = cable.get("towForce.x"), cable.get("towForce.z")
        end_z = cable.get("endPosition.z")
    finally:
        cable.free()
    angle = math.atan2(-Fz, -Fx)
    return {"knots": knots, "N": n_elements, "body": bool(body), "cpu": cpu,
            "top_tension": T, "ref_top_tension": ref.top_tension,
            "top_angle_deg": math.degrees(angle), "ref_top_angle_deg": math.degrees(ref.top_angle),
            "end_depth": -end_z, "ref_end_depth": ref.end_depth,
            "tension_rel": T / ref.top_tension - 1.0,
            "angle_error_deg": math.degrees(angle - ref.top_angle),
            "depth_error": (-end_z - ref.end_depth) / props.length}


# ---------------------------------------------------------------------------------------- vibration
VIB_L, VIB_M, VIB_STRAIN, VIB_T = 10.0, 1.0, 1e-3, 400.0  # f1 about 1 Hz
VIB_EI = 405.0  # beam-string: (pi^2 EI)/(T L^2) = 0.1, the third mode 38 % above the string's
VIB_DEPTH = 20.0


def free_vibration(fmu, EI: float, n_elements: int, t_end: float = 20.0, step: float = 0.02,
                   station: int = 6) -> dict:
    """Pinned-pinned taut line (hinged tow point, anchor at L (1 + strain)), no gravity, drag or
    added mass. A lateral sin^2 pulse of the tow point (0.2 s, 1 mm) excites it; afterwards the
    tow point is fixed and shape.y[station] (s = L/4: no node of modes 1-3) vibrates freely.
    Frequencies: least-squares fit of three undamped sinusoids (guesses from the FFT peaks)."""
    d = math.sqrt(4.0 * VIB_M / (1025.0 * math.pi))  # neutrally buoyant as well
    params = {"length": VIB_L, "diameter": d, "massPerLength": VIB_M, "EA": VIB_T / VIB_STRAIN,
              "axialDamping": 0.0, "gravity": 0.0, "Cdn": 0.0, "Cdt": 0.0, "enableAddedMass": 0,
              "nElements": n_elements, "bottomEnd": 1, "anchor.x": VIB_L * (1 + VIB_STRAIN),
              "anchor.y": 0.0, "anchor.z": -VIB_DEPTH, "initialDirection.x": 1.0,
              "initialDirection.y": 0.0, "initialDirection.z": 0.0}
    if EI > 0:
        params["EI"] = EI
    else:
        params["enableBending"] = 0
    # 1 mm: the string is geometrically nonlinear, its tension (and so its frequencies) grows with
    # the square of the amplitude: a 1 cm pulse raised them by 0.3-0.7 %, 1 mm by 100 times less.
    tau, amp = 0.2, 0.001
    n = int(round(t_end / step))
    t = np.arange(1, n + 1) * step
    y = np.zeros(n)
    cable = CableFMU(fmu, parameters=params)
    try:
        cpu = time.process_time()
        cable.initialize(start_time=0.0, stop_time=t_end, inputs={"tow.z": -VIB_DEPTH})
        T0 = cable.get("towTension")
        name = f"shape.y[{station}]"
        for k in range(n):
            tk = k * step
            w = math.pi / tau
            on = tk < tau
            cable.set({"tow.y": amp * math.sin(w * tk) ** 2 if on else 0.0,
                       "tow.vy": amp * w * math.sin(2 * w * tk) if on else 0.0})
            cable.set_input_derivatives(["tow.vy"], 1, [2 * amp * w * w * math.cos(2 * w * tk) if on else 0.0])
            cable.do_step(step, t=tk)
            y[k] = cable.get(name)
        cpu = time.process_time() - cpu
    finally:
        cable.free()
    if EI > 0:
        exact = beam_string_frequencies(VIB_L, VIB_M, VIB_T, VIB_STRAIN, EI)
    else:
        exact = string_frequencies(VIB_L, VIB_M, VIB_T, VIB_STRAIN)
    free = t > tau + step
    fitted = fit_frequencies(t[free], y[free], guess_windows=exact)
    return {"EI": EI, "N": n_elements, "cpu": cpu, "exact": exact, "fitted": fitted,
            "rel_error": fitted / exact - 1.0, "tow_tension": T0, "t": t, "y": y}


def fit_frequencies(t: np.ndarray, y: np.ndarray, guess_windows) -> np.ndarray:
    """Frequencies [Hz] of a sum of undamped sinusoids. The FFT (Hann window, 16x zero padding)
    gives one peak per window centre +-10 % (the window only says which peak is which mode); a
    least-squares fit of sum_n a_n cos(2 pi f_n t) + b_n sin(2 pi f_n t) refines them."""
    dt = t[1] - t[0]
    nfft = 16 * len(t)
    spec = np.abs(np.fft.rfft((y - y.mean()) * np.hanning(len(t)), n=nfft))
    freq = np.fft.rfftfreq(nfft, d=dt)
    guesses = []
    for f in guess_windows:
        sel = np.flatnonzero(np.abs(freq - f) <= 0.1 * f)
        guesses.append(freq[sel[np.argmax(spec[sel])]])
    guesses = np.array(guesses)
    tc = t - t[0]

    def basis(f):
        cols = [np.ones_like(tc)]
        for fn in f:
            cols += [np.cos(2 * math.pi * fn * tc), np.sin(2 * math.pi * fn * tc)]
        return np.column_stack(cols)

    def residual(f):  # variable projection: amplitudes by linear least squares
        B = basis(f)
        coef, *_ = np.linalg.lstsq(B, y, rcond=None)
        return B @ coef - y

    fit = least_squares(residual, guesses, x_scale=guesses * 1e-3, xtol=1e-14, ftol=1e-14)
    return np.sort(fit.x)


# ---------------------------------------------------------------------------------------- time
def hopland_tension(fmu, rel_tol: float = 0.0, abs_tol: float = 0.0, n_elements: int = 20,
                    step: float = 0.5, progress=None, tension_tolerance: float | None = None) -> dict:
    """Top tension history of the Hopland acceleration manoeuvre (660 s, input derivatives on), at
    the integrator's tensionTolerance (default: the FMU's) with IDA's relTol/absTol as extra bounds
    (0: not used)."""
    profile, t_end = hopland_accelerate()
    params = {"nElements": n_elements, "relTol": rel_tol, "absTol": abs_tol}
    if tension_tolerance is not None:
        params["tensionTolerance"] = tension_tolerance
    cable = CableFMU(fmu, parameters=params)
    try:
        cpu = time.process_time()
        run = run_tow(cable, profile, t_end, step, record_shape=False, use_input_derivatives=True,
                      progress=progress)
        cpu = time.process_time() - cpu
        steps = cable.get("solver.nSteps")
    finally:
        cable.free()
    return {"relTol": rel_tol, "absTol": abs_tol, "tensionTolerance": tension_tolerance, "t": run.time,
            "tension": run["towTension"], "cpu": cpu, "nSteps": steps}


# ---------------------------------------------------------------------------------------- rates
def convergence_rate(n_elements, errors) -> float:
    """Least-squares slope p of log(error) = c - p log(N) (error ~ h^p)."""
    n = np.log(np.asarray(n_elements, float))
    e = np.log(np.asarray(errors, float))
    return float(-np.polyfit(n, e, 1)[0])
