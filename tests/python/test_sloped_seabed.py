"""A line resting on a sloped seabed (seabedSlope, docs/model.md "Seabed"): contact along the slope's normal,
friction along its surface.

A straight line of length L lying on a plane seabed of angle alpha, along its line of steepest descent, and
sliding along it at the speed V carries in its resting part, at the distance s from its free end,

    T(s) = w s (sin alpha + mu_V cos alpha)   dragged up the slope (the tow above the line, moving up),
    T(s) = w s (sin alpha - mu_V cos alpha)   lowered down it (the tow above the line, moving down),

with w the submerged weight per length and mu_V = mu V / sqrt(V^2 + v_eps^2) the regularized Coulomb
coefficient at that speed (v_eps = 0.01 m/s): the weight's part along the slope, w sin alpha, and the
friction of its normal part, mu_V w cos alpha, both per metre. Drag is left out (Cdt = 0; the line moves
along itself, so the normal drag is zero), so the closed form is exact for the discrete line: its loads are
linear along it, which the elements integrate exactly, and the tow point's tension is the exact reaction.
"""

import math
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ucable.units import GRAVITY

ALPHA, HEADING = 10.0, 0.0  # the seabed descends along +x
DEPTH, LENGTH, SPEED, MU = 100.0, 200.0, 0.3, 0.5
FRICTION_VELOCITY = 0.01  # the regularization of terms/seabed.h


def parameters(**extra) -> dict:
    return {"length": LENGTH, "nElements": 20, "waterDepth": DEPTH, "enableSeabed": True,
            "seabedSlope": ALPHA, "seabedSlopeHeading": HEADING, "seabedFriction": MU,
            "seabedStiffness": 1e6, "Cdt": 0.0, "bottomEnd": 0, **extra}


def weight(cable: CableFMU) -> float:
    d, rho = cable.get("diameter"), cable.get("waterDensity")
    return (cable.get("massPerLength") - rho * math.pi * d * d / 4.0) * GRAVITY


def closed_form(w: float, s: float, sign: float, alpha: float = ALPHA) -> float:
    a = math.radians(alpha)
    mu = MU * SPEED / math.hypot(SPEED, FRICTION_VELOCITY)
    return w * s * (math.sin(a) + sign * mu * math.cos(a))


def test_a_line_dragged_up_a_slope_carries_its_weight_along_it_and_its_friction(fmu_file):
    # the steady tow (initMode 0): the tow point on the seabed at the origin, moving straight up the slope
    a = math.radians(ALPHA)
    cable = CableFMU(fmu_file, parameters=parameters(initMode=0))
    try:
        cable.initialize(inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": -DEPTH,
                                 "tow.vx": -SPEED * math.cos(a), "tow.vy": 0.0, "tow.vz": SPEED * math.sin(a)})
        w = weight(cable)
        expected = closed_form(w, LENGTH, +1.0)
        assert abs(cable.get("towTension") / expected - 1.0) < 1e-6, (cable.get("towTension"), expected)
        # the line lies on the slope, down it from the tow point: z = -DEPTH - tan(alpha) x
        shape = cable.shape()
        assert shape["shape.x"][-1] > 0.99 * LENGTH * math.cos(a)
        on_slope = shape["shape.z"] + DEPTH + math.tan(a) * shape["shape.x"]
        assert np.max(np.abs(on_slope)) < 0.01, on_slope
        # and its tension falls linearly to the free end at every station, within the load of the tip (the
        # contact of the piece beyond the last element's outer contact point, 0.047 of its length, acts on
        # the end node; the last elements spread it, and it fades geometrically up the line)
        s = np.linspace(0.0, LENGTH, 21)
        expected_profile = np.array([closed_form(w, LENGTH - x, +1.0) for x in s])
        tip = closed_form(w, 0.0469101 * LENGTH / 20, +1.0)
        assert np.max(np.abs(shape["tension"] - expected_profile)) < tip, shape["tension"] - expected_profile
        assert np.max(np.abs(shape["tension"][:10] - expected_profile[:10])) < 1e-6 * expected
    finally:
        cable.free()


def test_a_line_lowered_down_a_slope_is_held_by_its_friction(fmu_file):
    # At 30 degrees tan(alpha) = 0.58 > mu: the line would slide by itself, and the tow holds back what
    # friction does not. Started at rest along the slope (initMode 1), the tow moving down it at V; after
    # the start's transient the line slides with the tow.
    alpha = 30.0
    a = math.radians(alpha)
    down = (math.cos(a), 0.0, -math.sin(a))
    cable = CableFMU(fmu_file, parameters=parameters(initMode=1, seabedSlope=alpha, **{
        "initialDirection.x": down[0], "initialDirection.y": 0.0, "initialDirection.z": down[2]}))
    try:
        cable.initialize(inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": -DEPTH,
                                 "tow.vx": SPEED * down[0], "tow.vy": 0.0, "tow.vz": SPEED * down[2]})
        w = weight(cable)
        h, t = 0.5, 0.0
        while t < 20.0 - 1e-9:
            t += h
            cable.set({"tow.x": SPEED * down[0] * t, "tow.z": -DEPTH + SPEED * down[2] * t})
            cable.do_step(h)
        expected = closed_form(w, LENGTH, -1.0, alpha)
        assert expected > 0.0
        assert abs(cable.get("towTension") / expected - 1.0) < 1e-6, (cable.get("towTension"), expected)
    finally:
        cable.free()


DECKS = Path(__file__).resolve().parents[1] / "data" / "decks"


def test_a_decks_seafloor_file_that_is_a_plane_is_the_sloped_seabed(fmu_file):
    """MoorDyn's SeafloorFile named from the directory above the deck's (as MoorDyn, which reads it from its
    working directory, names it) and holding the plane z = -362.5 - 0.05 x: the deck's line starts as the
    same deck without it on the sloped seabed set by parameters (waterDepth 362.5 m, seabedSlope atan 0.05,
    heading 0). Before, the deck was refused ("a bathymetry file is not supported")."""
    outputs = ["towTension", "endTension", "groundedLength", "minSeabedClearance", "endPosition.z"]
    by_file = CableFMU(fmu_file, parameters={"lineFile": str(DECKS / "seafloor" / "chain_on_slope.dat")})
    by_parameters = CableFMU(fmu_file, parameters={
        "lineFile": str(DECKS / "chain.dat"), "waterDepth": 362.5,
        "seabedSlope": math.degrees(math.atan(0.05)), "seabedSlopeHeading": 0.0})
    try:
        values = []
        for cable in (by_file, by_parameters):
            cable.initialize(inputs={"tow.z": -70.0})
            values.append(cable.get_reals(outputs))
        assert values[0][2] > 5.0  # part of the chain rests on the slope (14 m: it falls away from the anchor)
        np.testing.assert_allclose(values[0], values[1], rtol=1e-9, atol=1e-9)
    finally:
        by_file.free()
        by_parameters.free()
