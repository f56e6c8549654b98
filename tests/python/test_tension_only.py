"""enableCompression = false: the tension-only axial law of chains and ropes, through the FMU.

A hanging chain whose top is driven downward faster than the chain can fall cannot be pushed: once
the unloading wave has passed, it falls freely (no drag, no added mass here), so its free end
accelerates at the buoyancy-reduced gravity g (1 - rho A / m), while the two-sided law pushes it
down with the top. Where the cable stays taut the two laws agree.

The law acts on each element's mean tension; the softened higher strain modes (1 % of EA, the
anti-locking projection) stay two-sided, so an element that is shortened non-uniformly (the top
element here, which the tow point runs into) still resists a little: measured, the end falls at
g_eff within 0.4 % when the top is driven at 1.2 g_eff, but 17 % slower when it is driven at 2 g_eff
(docs/model.md).
"""

import math

import numpy as np
import pytest

from ucable.units import GRAVITY as G, WATER_DENSITY as RHO

CHAIN = {"length": 100.0, "diameter": 0.0332, "massPerLength": 2.7018, "EA": 6.709e7,
         "enableBending": False, "enableAddedMass": False, "Cdn": 0.0, "Cdt": 0.0,
         "nElements": 10, "bottomEnd": 0, "initMode": 0}
TOP_Z = -10.0  # below the free-surface ramp


def push(p=CHAIN) -> float:
    """Downward acceleration of the top: 20 % faster than the chain can fall."""
    return 1.2 * free_fall_acceleration(p)


def top_share(p=CHAIN) -> float:
    l = p["length"] / p["nElements"]
    return (push(p) + free_fall_acceleration(p)) * p["massPerLength"] * l / 2.0


def free_fall_acceleration(p=CHAIN) -> float:
    return G * (1.0 - RHO * math.pi * p["diameter"] ** 2 / 4.0 / p["massPerLength"])


def drive_down(make_cable, compression: bool, t_end=0.6, h=0.01):
    """Top at rest at TOP_Z until t = 0, then z = TOP_Z - push() t^2 / 2 (inputs with their derivative).
    Returns time, far-end z and tow tension."""
    c = make_cable(parameters=dict(CHAIN, enableCompression=compression))
    c.initialize(0.0, t_end, inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": TOP_Z})
    n = int(round(t_end / h))
    t = np.arange(n + 1) * h
    z = np.empty(n + 1)
    T = np.empty(n + 1)
    z[0], T[0] = c.get("endPosition.z"), c.get("towTension")
    for k in range(n):
        tk = t[k]
        c.set({"tow.z": TOP_Z - 0.5 * push() * tk * tk, "tow.vz": -push() * tk})
        c.set_input_derivatives(["tow.vz"], 1, [-push()])
        c.do_step(h, t=tk)
        z[k + 1], T[k + 1] = c.get("endPosition.z"), c.get("towTension")
    return t, z, T


def end_acceleration(t, z, t0, t1):
    """Second derivative of a quadratic fitted to z(t) on [t0, t1]."""
    m = (t >= t0) & (t <= t1)
    return 2.0 * np.polyfit(t[m], z[m], 2)[0]


def test_a_chain_driven_down_faster_than_it_can_fall_falls_freely(make_cable):
    t, z, T = drive_down(make_cable, compression=False)
    # The unloading wave needs L / c = 100 m / 4983 m/s = 0.02 s to reach the free end and
    # return; from 0.2 s on the chain is slack everywhere and falls freely. The fit over 0.2-0.6 s
    # is exact for free fall; axial ringing left from the unloading is damped in ~0.01 s
    # (Kelvin-Voigt). Bound: the slack chain passes on less than 1/20 of the extra acceleration
    # that the two-sided law transmits (test below); the quadratic fit itself is exact.
    a = end_acceleration(t, z, 0.2, 0.6)
    assert abs(a + free_fall_acceleration()) < 0.05 * (push() - free_fall_acceleration())
    # Slack: no tension reaches the tow point; it carries only the inertia and weight of the mass
    # its shape functions attach to it, at most half an element: (push + g_eff) m l / 2 = 196 N,
    # against 1780 N of weight before and 356 N of push with the two-sided law.
    assert np.max(np.abs(T[t >= 0.2])) < top_share()
    assert T[0] == pytest.approx(free_fall_acceleration() * CHAIN["massPerLength"] * CHAIN["length"], rel=1e-4)


def test_the_two_sided_law_pushes_the_chain_down_with_the_top(make_cable):
    t, z, T = drive_down(make_cable, compression=True)
    # A 100 m column: the axial wave keeps the far end with the top (strain ~ m a L / EA = 1e-6),
    # so the end accelerates with the top, not at g_eff, and the top pushes with (push - g_eff) m L.
    a = end_acceleration(t, z, 0.2, 0.6)
    assert a == pytest.approx(-push(), rel=5e-3)
    assert np.all(T[t >= 0.2] > 0.5 * (push() - free_fall_acceleration()) * CHAIN["massPerLength"] * CHAIN["length"])


def test_where_the_chain_stays_taut_the_two_laws_agree(fmu_file):
    """Static catenary of the mooring chain with touchdown (everywhere in tension, 1.3 MN and more):
    the tension-only law equals the two-sided one above 1e-5 EA = 7.5 kN, so the equilibria agree
    to the static solver's convergence."""
    from studies.cases import mooring

    a = mooring.fmu_statics(fmu_file, 20, enableCompression=True)
    b = mooring.fmu_statics(fmu_file, 20, enableCompression=False)
    assert np.min(b["tension"]) > 1e-5 * mooring.CHAIN["EA"]
    assert b["towTension"] == pytest.approx(a["towTension"], rel=1e-9)
    assert np.max(np.abs(b["shape.z"] - a["shape.z"])) < 1e-6


@pytest.mark.parametrize("compression", [True, False])
def test_a_two_sided_line_that_goes_slack_says_which_law_to_use(fmu_file, compression):
    """The slack-snap hard case (a 2 t body below 100 m of cable, the top heaving faster than the
    body sinks): with the two-sided law the cable pushes with its full EA where it would buckle at a
    few hundred newtons (-58 kN in docs/robustness.md), and the run says so once, naming the law to
    use; tension-only, it says nothing."""
    from studies.cases import hard_cases as hc
    from ucable.fmu import CableFMU

    case = hc.slack_snap(t_end=4.0)
    params = dict(case.parameters, nElements=10, enableCompression=compression)
    with CableFMU(fmu_file, parameters=params, logging_on=True) as c:
        p, v, _ = case.trajectory(0.0)
        c.initialize(0.0, case.t_end, inputs={"tow.z": p[2], "tow.vz": v[2]})
        t = 0.0
        while t < case.t_end - 1e-9:
            p, v, _ = case.trajectory(t + case.step)
            c.set({"tow.x": p[0], "tow.z": p[2], "tow.vz": v[2]})
            c.do_step(case.step, t=t)
            t += case.step
        log = c.log_text()
    warnings = log.count("axial compression (minTension)")
    assert warnings == (1 if compression else 0), log[-2000:]
    if compression:
        assert "enableCompression = false" in log
