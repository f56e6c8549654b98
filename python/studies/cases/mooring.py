"""Mooring-line validation through the FMU: the chain of the mooring scene on a seabed
against the elastic catenary with touchdown (studies.references.exact.TouchdownCatenary) and MoorPy, the
surging fairlead against the quasi-static mean, a hanging cable in a sheared current against an
independent steady ODE, and the external far end (bottomEnd 3) against the anchored one.

Used by tests/python/test_mooring.py and scripts/mooring_report.
"""

from __future__ import annotations

import math
import time

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from ..peers import moorpy
from ..references.exact import TouchdownCatenary
from ucable.fmu import NUM_STATIONS, CableFMU

# The mooring chain: 900 m, EA 7.5e8 N, 113 kg/m, d 0.0766 m in 320 m of water, fairlead 70 m
# deep, anchor 850 m away. Drag coefficients as in tests/core/test_mooring.cpp (chain-like).
DEPTH = 320.0
FAIRLEAD_Z = -70.0
ANCHOR_X = -850.0
CHAIN = {
    "length": 900.0, "diameter": 0.0766, "massPerLength": 113.0, "EA": 7.5e8, "EI": 0.0,
    "enableBending": False, "Cdn": 2.4, "Cdt": 0.2, "bottomEnd": 1,
    "anchor.x": ANCHOR_X, "anchor.y": 0.0, "anchor.z": -DEPTH,
    "enableSeabed": True, "waterDepth": DEPTH,
    # w/k = 1062 N/m / 1e6 N/m2: the grounded chain sinks 1 mm into the seabed
    "seabedStiffness": 1e6,
}
SURGE_AMPLITUDE = 5.0
SURGE_PERIOD = 10.0


def chain_params(n_elements: int, **extra) -> dict:
    p = dict(CHAIN, nElements=n_elements)
    p.update(extra)
    return p


def chain_weight(p: dict = CHAIN, rho: float = 1025.0, g: float = 9.81) -> float:
    """Submerged weight per unstretched metre [N/m]."""
    return (p["massPerLength"] - rho * math.pi * p["diameter"] ** 2 / 4.0) * g


def closed_form(fairlead_x: float = 0.0) -> TouchdownCatenary:
    """The chain's elastic catenary with touchdown, fairlead at (fairlead_x, FAIRLEAD_Z)."""
    return TouchdownCatenary(CHAIN["length"], chain_weight(), CHAIN["EA"], fairlead_x - ANCHOR_X,
                             FAIRLEAD_Z + DEPTH)


def moorpy_catenary(fairlead_x: float = 0.0) -> dict:
    """MoorPy's quasi-static catenary (moorpy.Catenary.catenary, frictionless seabed, CB = 0)."""
    fAH, fAV, fBH, fBV, info = moorpy.catenary(fairlead_x - ANCHOR_X, FAIRLEAD_Z + DEPTH, CHAIN["length"],
                                        CHAIN["EA"], chain_weight(), CB=0.0, Tol=1e-10, MaxIter=200)
    return {"fairlead_tension": math.hypot(fBH, fBV), "H": abs(fBH), "grounded": info["LBot"]}


def fmu_statics(fmu, n_elements: int, fairlead_x: float = 0.0, **extra) -> dict:
    """The FMU's initMode-0 static equilibrium of the chain with the fairlead at (x, 0, -70)."""
    with CableFMU(fmu, parameters=chain_params(n_elements, **extra)) as c:
        c.initialize(inputs={"tow.x": fairlead_x, "tow.z": FAIRLEAD_Z})
        out = {k: c.get(k) for k in ("towTension", "towForce.x", "towForce.z", "touchdownArcLength",
                                      "minSeabedClearance")}
        out.update(c.shape())
    return out


def grounded_within(exact: TouchdownCatenary, height: float) -> float:
    """Unstretched length from the anchor to where the exact line rises `height` above the seabed:
    the grounded length as the FMU reports it (the line within half a diameter of the seabed)."""
    if exact.lifted:
        return 0.0
    return brentq(lambda p: float(exact.position(p)[1]) - height, exact.grounded, CHAIN["length"], xtol=1e-12)


def catenary_comparison(fmu, n_elements: int) -> dict:
    """FMU statics against the closed form: relative tension errors, grounded-length error / L and
    the largest distance of the 21 stations from the exact material points [m]."""
    exact = closed_form()
    r = fmu_statics(fmu, n_elements)
    L = CHAIN["length"]
    grounded = L - r["touchdownArcLength"]
    s = np.linspace(0.0, L, NUM_STATIONS)  # unstretched arc length from the fairlead
    xe, ze = exact.position(L - s)
    dist = np.hypot(r["shape.x"] - (ANCHOR_X + xe), r["shape.z"] - (-DEPTH + ze))
    return {
        "n": n_elements, "tension": r["towTension"], "tension_exact": exact.fairlead_tension,
        "tension_rel": r["towTension"] / exact.fairlead_tension - 1.0,
        "H": abs(r["towForce.x"]), "H_exact": exact.H, "H_rel": abs(r["towForce.x"]) / exact.H - 1.0,
        "grounded": grounded, "grounded_exact": grounded_within(exact, 0.5 * CHAIN["diameter"]),
        "grounded_rel": (grounded - grounded_within(exact, 0.5 * CHAIN["diameter"])) / L,
        "shape_error": float(np.max(dist)), "clearance": r["minSeabedClearance"],
        "shape": r, "exact": exact,
    }


# ---------------------------------------------------------------------------------- surge scene
def surge_inputs(t: float) -> dict:
    w = 2.0 * math.pi / SURGE_PERIOD
    return {"tow.x": SURGE_AMPLITUDE * math.sin(w * t), "tow.vx": SURGE_AMPLITUDE * w * math.cos(w * t),
            "tow.z": FAIRLEAD_Z}


def surge_acceleration(t: float) -> float:
    w = 2.0 * math.pi / SURGE_PERIOD
    return -SURGE_AMPLITUDE * w * w * math.sin(w * t)


def surge_run(fmu, t_end: float, n_elements: int = 20, step: float = 0.1, progress=None) -> dict:
    """Fairlead surging x = 5 sin(2 pi t / 10), with tow.vx and der(tow.vx) (input derivatives)
    so the FMU follows the motion exactly. Starts from the static equilibrium at x = 0 (the
    nodes at rest, the fairlead already moving). Returns time, towTension, CPU seconds, steps."""
    n = int(round(t_end / step))
    t = np.arange(n + 1) * step
    T = np.empty(n + 1)
    with CableFMU(fmu, parameters=chain_params(n_elements)) as c:
        c.initialize(0.0, t_end, inputs=surge_inputs(0.0))
        T[0] = c.get("towTension")
        cpu = time.process_time()
        for k in range(n):
            c.set(surge_inputs(t[k]))
            c.set_input_derivatives(["tow.vx"], 1, [surge_acceleration(t[k])])
            c.do_step(step, t=t[k])
            T[k + 1] = c.get("towTension")
            if progress is not None:
                progress(t[k + 1])
        cpu = time.process_time() - cpu
        steps = c.get("solver.nSteps")
    return {"t": t, "tension": T, "cpu": cpu, "steps": steps, "realtime_factor": t_end / cpu}


def surge_phases(n_positions: int = 40) -> np.ndarray:
    """Fairlead x at n equally spaced phases of one surge cycle."""
    return SURGE_AMPLITUDE * np.sin(2.0 * math.pi * np.arange(n_positions) / n_positions)


def quasi_static_mean(n_positions: int = 40, fmu=None, n_elements: int = 20) -> float:
    """Cycle average of the static fairlead tension at the instantaneous fairlead position (the
    trapezoidal rule on equally spaced phases is spectrally accurate for a periodic function):
    the closed form, or the FMU's own statics when `fmu` is given."""
    xs = surge_phases(n_positions)
    if fmu is None:
        return float(np.mean([closed_form(x).fairlead_tension for x in xs]))
    return float(np.mean([fmu_statics(fmu, n_elements, x)["towTension"] for x in xs]))


# ---------------------------------------------------------------------------------- current profile
HANG = {  # the default (Hopland) cable hanging from the surface with a 2 kN end weight, no bending
    "EI": 0.0, "enableBending": False, "bottomEnd": 0, "nElements": 20,
}
HANG_END_LOAD = -2000.0  # endLoad.z [N]
SHEAR = {"currentProfileRows": 2, "currentProfile.depth[1]": 0.0, "currentProfile.x[1]": 0.5,
         "currentProfile.y[1]": 0.0, "currentProfile.depth[2]": 250.0, "currentProfile.x[2]": 0.0,
         "currentProfile.y[2]": 0.2}
UNIFORM = {"current.x": 0.1, "current.y": 0.0}


def profile_current(depth: np.ndarray | float, rows: dict = SHEAR, uniform: dict = UNIFORM):
    """(ux, uy) at depth (positive down): rows interpolated linearly, constant beyond the ends,
    plus the uniform current."""
    n = rows["currentProfileRows"]
    d = [rows[f"currentProfile.depth[{k}]"] for k in range(1, n + 1)]
    ux = np.interp(depth, d, [rows[f"currentProfile.x[{k}]"] for k in range(1, n + 1)]) + uniform["current.x"]
    uy = np.interp(depth, d, [rows[f"currentProfile.y[{k}]"] for k in range(1, n + 1)]) + uniform["current.y"]
    return ux, uy


def hanging_cable_ode(rows: dict = SHEAR, uniform: dict = UNIFORM, end_load: float = HANG_END_LOAD,
                      n_stations: int = NUM_STATIONS) -> dict:
    """Steady equilibrium of the default cable hanging from (0, 0, 0) in the depth-dependent current,
    integrated upwards from the loaded end in 3-D vector form (independent of the FMU).

    P = T tau (tau: unit tangent pointing UP the cable, sigma: unstretched length from the end):
        dP/dsigma = -(f_drag + (0, 0, -w)),   dr/dsigma = (1 + T/EA) tau,   P(0) = -endLoad,
    with Morison drag per unstretched length of the current u(z) past the still cable:
        normal 1/2 rho Cdn d |u_n| u_n,  tangential 1/2 rho Cdt pi d |u_t| u_t.
    The end depth is shot (brentq) so that the top lands at z = 0; x, y are then shifted to 0."""
    from ucable.steady_tow import CableProperties

    cp = CableProperties()
    rho, d, EA, w, L = cp.water_density, cp.diameter, cp.axial_stiffness, cp.submerged_weight, cp.length

    def rhs(_s, y):
        P, r = y[:3], y[3:]
        T = np.linalg.norm(P)
        tau = P / T
        ux, uy = profile_current(-r[2], rows, uniform)
        u = np.array([ux, uy, 0.0])
        ut = np.dot(u, tau) * tau
        un = u - ut
        f = (0.5 * rho * cp.Cdn * d * np.linalg.norm(un) * un
             + 0.5 * rho * cp.Cdt * math.pi * d * np.linalg.norm(ut) * ut)
        f[2] -= w
        return np.concatenate([-f, (1.0 + T / EA) * tau])

    def shoot(z_end, dense=False):
        y0 = [0.0, 0.0, -end_load, 0.0, 0.0, z_end]
        return solve_ivp(rhs, (0.0, L), y0, method="DOP853", rtol=1e-12, atol=1e-10, dense_output=dense)

    z_end = brentq(lambda z: shoot(z).y[5, -1], -1.01 * L, -0.5 * L, xtol=1e-12)
    sol = shoot(z_end, dense=True)
    s = np.linspace(0.0, L, n_stations)  # from the top, like shape.*[1..]
    Y = sol.sol(L - s)
    top = sol.y[:, -1]
    return {"x": Y[3] - top[3], "y": Y[4] - top[4], "z": Y[5], "tension": np.linalg.norm(Y[:3], axis=0),
            "top_force": top[:3]}


def hanging_cable_fmu(fmu, n_elements: int = 20, rows: dict = SHEAR, uniform: dict = UNIFORM) -> dict:
    p = dict(HANG, nElements=n_elements)
    p.update(rows)
    with CableFMU(fmu, parameters=p) as c:
        c.initialize(inputs={**uniform, "endLoad.z": HANG_END_LOAD})
        out = c.shape()
        out["towForce"] = c.get_reals(["towForce.x", "towForce.y", "towForce.z"])
    return out


def hanging_comparison(fmu, n_elements: int = 20) -> dict:
    ref = hanging_cable_ode()
    r = hanging_cable_fmu(fmu, n_elements)
    dist = np.sqrt((r["shape.x"] - ref["x"]) ** 2 + (r["shape.y"] - ref["y"]) ** 2 + (r["shape.z"] - ref["z"]) ** 2)
    T_ref = np.linalg.norm(ref["top_force"])
    return {"n": n_elements, "shape_error": float(np.max(dist)),
            "top_tension": float(np.linalg.norm(r["towForce"])), "top_tension_ref": float(T_ref),
            "top_tension_rel": float(np.linalg.norm(r["towForce"]) / T_ref - 1.0),
            "end_offset": (float(r["shape.x"][-1]), float(r["shape.y"][-1]), float(r["shape.z"][-1])),
            "end_offset_ref": (float(ref["x"][-1]), float(ref["y"][-1]), float(ref["z"][-1]))}
