"""Static states a mooring user can trust (docs/model.md, "Initial equilibrium"): lines that rest on
the seabed, clumps resting or where the line lifts off, the force on a grounded anchor, a tow cable
whose end reaches the seabed, and the refusals where the answer would be wrong.

References: MoorPy's systems of lines and free points (rigid seabed, points resting within 1 mm),
the same equations solved independently. Our seabed is a penalty: a line rests a few millimetres
into it, at the penetration where the contact ramp k g(p) carries its weight (docs/model.md), so
MoorPy's seabed is put at that depth. What remains is the discretization and MoorPy's solver
tolerance (1e-6 of the forces): 1e-3 is the bound (the product's promise is 0.5 %)."""

import math

import numpy as np
import pytest

from ucable.fmu import CableFMU
from ucable.units import GRAVITY as G, WATER_DENSITY as RHO
from studies.reports.lines_figure import section_parameters
from studies.cases.mooring import chain_weight

CHAIN = {"diameter": 0.0766, "massPerLength": 113.0, "EA": 7.5e8}
WIRE = {"diameter": 0.08, "massPerLength": 32.0, "EA": 5.5e8}
TENSION_ONLY = {"bottomEnd": 1, "enableSeabed": True, "enableBending": False, "enableCompression": False}
BOUND = 1e-3


def resting_penetration(props, k):
    """Where a line of these properties rests on a seabed of stiffness k [N/m2]: k g(p) = w with the
    contact ramp g = p^2 / (2 delta) up to delta = 5 % of the diameter, p - delta / 2 beyond."""
    delta, ratio = 0.05 * props["diameter"], chain_weight(props) / k
    return ratio + delta / 2 if ratio >= delta / 2 else math.sqrt(2.0 * delta * ratio)


def moorpy_tensions(depth, points, lines, sink=0.0):
    """Fairlead and anchor tension of a MoorPy system: points (kind, position, mass, volume) from the
    anchor up, lines (point A, point B, length, type) from the anchor up; the seabed and every point
    on it `sink` metres deeper (where our line rests)."""
    mp = pytest.importorskip("moorpy")
    depth += sink
    points = [(kind, [r[0], r[1], r[2] - sink if r[2] <= -depth + sink else r[2]], m, v) for kind, r, m, v in points]
    ms = mp.System(depth=depth, rho=RHO, g=G)
    for name, props in (("chain", CHAIN), ("wire", WIRE)):
        d = props["diameter"]
        ms.lineTypes[name] = dict(name=name, d_vol=d, m=props["massPerLength"], EA=props["EA"],
                                  w=chain_weight(props), MBL=1e9, cost=0, notes="", input_d=d,
                                  input_type={}, Cd=1.2, Ca=1.0, CdAx=0.2, CaAx=0.0)
    for kind, r, m, v in points:
        ms.addPoint(kind, r, m=m, v=v)
    for a, b, length, kind in lines:
        ms.addLine(length, kind, pointA=a, pointB=b)
    for p in ms.pointList:
        p.zTol = 0.001
    ms.initialize()
    ms.solveEquilibrium(tol=1e-6, maxIter=2000)
    return np.linalg.norm(ms.lineList[-1].fB), np.linalg.norm(ms.lineList[0].fA)


def fmu_tensions(fmu_file, parameters, tow_z):
    with CableFMU(fmu_file, parameters=parameters) as c:
        c.initialize(inputs={"tow.z": tow_z})
        return c.get_reals(["towTension", "endTension", "endForce.z", "tension[21]"])


def sectioned(*sections):
    p = {"nSections": len(sections)}
    for k, (props, length, n) in enumerate(sections, start=1):
        p.update(section_parameters(k, length=length, nElements=n, joint=1, EI=0.0, **props))
    return p


@pytest.mark.parametrize("n_bottom", [10, 15, 20, 25, 30, 40])
def test_clump_resting_on_the_seabed_leaves_the_mooring_as_it_is(fmu_file, n_bottom):
    """Chain 50 m - wire 600 m - chain 350 m, a 15 t clump (1.91 m3) at the wire-chain joint resting
    on a 150 m seabed. Without its own contact the clump pressed the chain's elements into the seabed
    and the line folded (85-112 kN at 10-40 elements, silently)."""
    fairlead, anchor = moorpy_tensions(
        150.0, [(1, [-900, 0, -150], 0, 0), (0, [-500, 0, -150], 15000, 1.91), (0, [-50, 0, -40], 0, 0),
                (1, [0, 0, -15], 0, 0)],
        [(1, 2, 350.0, "chain"), (2, 3, 600.0, "wire"), (3, 4, 50.0, "chain")],
        sink=resting_penetration(CHAIN, 1e6))
    p = dict(TENSION_ONLY, waterDepth=150.0, seabedStiffness=1e6, **{"anchor.x": -900.0, "anchor.z": -150.0},
             nAttachments=1, **{"attachment[1].s": 650.0, "attachment[1].mass": 15000.0,
                                "attachment[1].volume": 1.91})
    p.update(sectioned((CHAIN, 50.0, 2), (WIRE, 600.0, 12), (CHAIN, 350.0, n_bottom)))
    top, end, end_z, last_station = fmu_tensions(fmu_file, p, -15.0)
    assert top == pytest.approx(fairlead, rel=BOUND)
    assert end == pytest.approx(anchor, rel=BOUND)
    # the grounded anchor is pulled along the seabed: no vertical force, the line's own tension
    assert abs(end_z) < 1e-3 * end
    assert last_station == pytest.approx(end, rel=1e-6)


@pytest.mark.parametrize("n", [25, 50])
def test_clump_where_the_line_lifts_off_turns_a_corner(fmu_file, n):
    """A wire with a 3 t clump (0.4 m3) at s = 240 m of 500 m, where it leaves the seabed: the clump's
    node is pinned (each side its own tangent), so the line turns the corner the point load makes.
    With one tangent there the fairlead was 0.94 / 0.50 % off at 25 / 50 elements."""
    fairlead, anchor = moorpy_tensions(
        150.0, [(1, [-450, 0, -150], 0, 0), (0, [-220, 0, -150], 3000, 0.4), (1, [0, 0, -10], 0, 0)],
        [(1, 2, 260.0, "wire"), (2, 3, 240.0, "wire")], sink=resting_penetration(WIRE, 1e6))
    p = dict(TENSION_ONLY, waterDepth=150.0, seabedStiffness=1e6, length=500.0, nElements=n, EI=0.0, **WIRE,
             **{"anchor.x": -450.0, "anchor.z": -150.0}, nAttachments=1,
             **{"attachment[1].s": 240.0, "attachment[1].mass": 3000.0, "attachment[1].volume": 0.4})
    top, end, _, _ = fmu_tensions(fmu_file, p, -10.0)
    assert top == pytest.approx(fairlead, rel=BOUND)
    assert end == pytest.approx(anchor, rel=BOUND)


def test_grounded_anchor_force_is_horizontal_and_does_not_drift_with_seabed_stiffness(fmu_file):
    """A chain resting on the seabed up to its anchor: on a frictionless seabed the anchor is pulled
    horizontally by H at every seabed stiffness. Before, the anchor held at z = -waterDepth pressed
    the last element into the seabed (or held it above, on a stiff one) and its contact loaded the
    anchor vertically by up to 0.9 of the tension."""
    length, depth, x = 600.0, 150.0, -555.0
    ends = []
    for k in (3e5, 1e6, 1e7, 1e8):
        _, anchor = moorpy_tensions(depth, [(1, [x, 0, -depth], 0, 0), (1, [0, 0, -20], 0, 0)],
                                    [(1, 2, length, "chain")], sink=resting_penetration(CHAIN, k))
        for n in (10, 20):
            p = dict(TENSION_ONLY, waterDepth=depth, seabedStiffness=k, length=length, nElements=n, EI=0.0,
                     **CHAIN, **{"anchor.x": x, "anchor.z": -depth})
            _, end, end_z, last_station = fmu_tensions(fmu_file, p, -20.0)
            assert abs(end_z) < 1e-3 * end, (k, n)
            assert end == pytest.approx(anchor, rel=BOUND), (k, n)
            ends.append(end)
    assert (max(ends) - min(ends)) / anchor < BOUND


def test_a_line_longer_than_the_way_down_and_across_is_refused_with_the_lengths(fmu_file):
    p = dict(TENSION_ONLY, waterDepth=100.0, length=200.0, nElements=10, EI=0.0, **CHAIN,
             **{"anchor.x": -100.0, "anchor.z": -100.0})
    with CableFMU(fmu_file, parameters=p) as c:
        with pytest.raises(Exception):
            c.initialize(inputs={"tow.z": -10.0})
        log = c.log_text()
    assert "longer than the way down to the seabed and across" in log
    assert "90 m + 100 m = 190 m" in log and "shorten it below 190 m" in log


def steady_tow(fmu_file, depth, init_mode, duration=0.0):
    v = 2 * 0.514444  # 2 kn
    with CableFMU(fmu_file, parameters={"enableSeabed": True, "waterDepth": depth, "initMode": init_mode}) as c:
        c.initialize(inputs={"tow.vx": v})
        t, h = 0.0, 0.5
        while t < duration - 1e-9:
            c.set({"tow.x": v * (t + h), "tow.vx": v})
            c.do_step(h, t=t)
            t += h
        return c.get_reals(["towTension", "endPosition.z"])


@pytest.mark.parametrize("depth", [199.0, 200.0])
def test_tow_cable_reaching_the_seabed_starts_with_its_end_on_it(fmu_file, depth):
    """The default 300 m cable at 2 kn would fly its end 200.4 m deep without a seabed. Over a 199 m
    and a 200 m seabed the static start puts its end on the seabed (before: hovering 12 m above it
    with a folded element, or no equilibrium), within 0.5 % of the same cable started from rest
    (initMode 1) and towed for 600 s to its steady state."""
    tension, end_z = steady_tow(fmu_file, depth, 0)
    steady, steady_z = steady_tow(fmu_file, depth, 1, duration=600.0)
    assert abs(end_z + depth) < 0.05
    assert abs(steady_z + depth) < 0.05
    assert tension == pytest.approx(steady, rel=5e-3)


def test_graded_state_continues_bit_identically_in_a_fresh_instance(graded_state_continuation):
    """The mesh graded at the touchdown is made at initialization; a state carries the end points it
    was graded for, and a fresh instance initialized elsewhere grades again from them."""
    p = dict(TENSION_ONLY, waterDepth=150.0, length=600.0, nElements=12, EI=0.0, **CHAIN,
             **{"anchor.x": -555.0, "anchor.z": -150.0})
    first, second = graded_state_continuation(p, -20.0, {"tow.x": 30.0}, ["towTension", "endTension", "shape.z[15]"])
    assert np.array_equal(first, second), f"max difference {np.max(np.abs(first - second))}"


@pytest.mark.parametrize("elements", [0, 10, 16, 24, 40, 60])
def test_clump_mooring_read_from_a_moordyn_deck_at_every_mesh(fmu_file, elements):
    """The resting-clump mooring above as a MoorDyn deck (pinned joints, the clump a Free point with
    mass and volume), at its own NumSegs (0) and with lineFileElements shared by length."""
    from pathlib import Path

    deck = Path(__file__).resolve().parents[1] / "data" / "decks" / "clump_on_seabed.dat"
    fairlead, anchor = moorpy_tensions(
        150.0, [(1, [-900, 0, -150], 0, 0), (0, [-500, 0, -150], 15000, 1.91), (0, [-50, 0, -40], 0, 0),
                (1, [0, 0, -15], 0, 0)],
        [(1, 2, 350.0, "chain"), (2, 3, 600.0, "wire"), (3, 4, 50.0, "chain")],
        sink=resting_penetration(CHAIN, 1e6))
    p = {"lineFile": str(deck), "lineFileElements": elements, "enableSeabed": True, "seabedStiffness": 1e6}
    top, end, end_z, _ = fmu_tensions(fmu_file, p, -15.0)
    assert top == pytest.approx(fairlead, rel=BOUND)
    assert end == pytest.approx(anchor, rel=BOUND)
    assert abs(end_z) < 1e-3 * end
