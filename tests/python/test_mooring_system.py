"""Mooring systems through `lineFile` (docs/systems_mooring.md): the OC4 DeepCwind semisubmersible's three
chains (scenes/oc4_semi.dat) on the FMU's body 1 against MoorPy fed the same deck, the
interface of the lines' load on the body, exact state save/restore of the whole system, and what a
system deck refuses.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from fmpy.fmi2 import fmi2Error

from studies.comparisons import mooring_system as ms
from ucable.fmu import FMICallException
from ucable.orientation import ANGLES_XYZ, ANGLES_ZYX, QUATERNION, quaternion_from_angles

DECK = ms.read_system_deck(ms.OC4)
# Poses of body 1 where MoorPy's orientation (Rz Ry Rx) and the FMU's (Rx Ry Rz) are the same rotation.
POSES = [(0.0,) * 6, (10.0, 0.0, 0.0, 0.0, 0.0, 0.0), (5.0, 0.0, 2.0, 0.0, math.radians(3.0), 0.0),
         (-4.0, 3.0, -1.0, 0.0, 0.0, math.radians(10.0))]


@pytest.mark.parametrize("pose", POSES, ids=["rest", "surge10", "surge-heave-pitch", "yaw10"])
def test_oc4_line_tensions_and_stiffness_match_moorpy(fmu_file, pose):
    """The acceptance's 0.5 % on every line's fairlead and anchor tension, 1 % on the coupled 6x6
    stiffness (each entry against the scale sqrt(K_ii K_jj) of its row and column), and the body's
    force to 0.5 % of the vertical load."""
    _assert_matches_moorpy(ms.fmu_statics(fmu_file, DECK, pose), ms.moorpy_statics(DECK, pose))


def _assert_matches_moorpy(ours: dict, ref: dict):
    """The acceptance's bounds on the statics of body 1 against MoorPy's."""
    assert ours["fairlead"] == pytest.approx(ref["fairlead"], rel=5e-3)
    assert ours["anchor"] == pytest.approx(ref["anchor"], rel=5e-3)
    assert ms.stiffness_difference(ours["stiffness"], ref["stiffness"]) < 1e-2
    scale = abs(ref["load"][2])
    assert np.max(np.abs(ours["load"][:3] - ref["load"][:3])) < 5e-3 * scale
    assert np.max(np.abs(ours["load"][3:] - ref["load"][3:])) < 5e-3 * scale * 40.0  # arms of 40 m


# A pose turned about all three axes, where the two angle conventions are different rotations.
COMBINED_POSE = (4.0, -3.0, 1.0, math.radians(4.0), math.radians(-6.0), math.radians(15.0))


@pytest.mark.parametrize("orientation", [ANGLES_ZYX, QUATERNION], ids=["openfast-angles", "quaternion"])
def test_a_pose_turned_about_three_axes_matches_moorpy(fmu_file, orientation):
    """MoorPy composes its angles R = Rz Ry Rx: the FMU given the same angles with bodyOrientation 2, or
    their quaternion with bodyOrientation 1, matches its statics as at the single-axis poses (0.5 % on
    the tensions, 1 % on the stiffness; measured 0.001 % and 8e-10); the same angles read as MoorDyn's
    R = Rx Ry Rz (bodyOrientation 0) are another rotation, 1 % off in the tensions, 2.4 % in the stiffness."""
    ref = ms.moorpy_statics(DECK, COMBINED_POSE)
    x, angles = COMBINED_POSE[:3], COMBINED_POSE[3:]
    if orientation == QUATERNION:
        q = quaternion_from_angles(*angles, convention=ANGLES_ZYX)
        inputs = {**{f"body[1].{n}": v for n, v in zip("xyz", x)}, **{f"body[1].q{i}": v for i, v in enumerate(q)}}
        ours = ms.fmu_statics(fmu_file, DECK, inputs=inputs, bodyOrientation=QUATERNION)
    else:
        ours = ms.fmu_statics(fmu_file, DECK, COMBINED_POSE, bodyOrientation=ANGLES_ZYX)
    _assert_matches_moorpy(ours, ref)
    moordyn = ms.fmu_statics(fmu_file, DECK, COMBINED_POSE)
    assert ms.stiffness_difference(moordyn["stiffness"], ref["stiffness"]) > 1e-2
    assert moordyn["fairlead"] != pytest.approx(ref["fairlead"], rel=5e-3)


def _turning(t):
    """Body 1 moving in all six degrees of freedom, turning about all three axes at once: pose, rates."""
    w = np.array([0.3, 0.2, 0.5, 0.4, 0.25, 0.1])
    amplitude = np.array([3.0, 2.0, 1.0, 0.05, 0.06, 0.15])
    return amplitude * np.sin(w * t), amplitude * w * np.cos(w * t)


def _turning_run(make_cable, orientation, tolerance, scale=1.0, steps=50, h=0.2, logging_on=False):
    """Line tensions and body 1's load over `steps` steps of _turning, its orientation given as the angles
    of R = Rx Ry Rz (bodyOrientation 0) or their quaternion times scale (1)."""
    c = make_cable(parameters=ms.fmu_parameters(DECK, bodyOrientation=orientation, tensionTolerance=tolerance,
                                                positionTolerance=tolerance), logging_on=logging_on)

    def inputs(t):
        q, v = _turning(t)
        d = {f"body[1].{n}": x for n, x in zip(ms.POSE_NAMES[:3] + ("vx", "vy", "vz", "wx", "wy", "wz"),
                                                [*q[:3], *v])}
        if orientation == QUATERNION:
            d.update({f"body[1].q{i}": scale * x for i, x in enumerate(quaternion_from_angles(*q[3:]))})
        else:
            d.update({f"body[1].{n}": x for n, x in zip(ms.POSE_NAMES[3:], q[3:])})
        return d

    names = [f"line[{k}].fairleadTension" for k in (1, 2, 3)] + BODY_LOAD
    c.initialize(inputs=inputs(0.0))
    rows = [c.get_reals(names)]
    for k in range(steps):
        c.set(inputs(k * h))
        c.do_step(h, k * h)
        rows.append(c.get_reals(names))
    return np.array(rows), c


def test_a_pose_as_angles_and_as_its_quaternion_gives_the_same_loads(make_cable):
    """Body 1 turning about all three axes for 10 s, its orientation given as MoorDyn's angles
    (bodyOrientation 0) and as their quaternion (1): the two rotation matrices differ by round-off (1e-16),
    so the static start and the first step agree to round-off; from there the lines' integrators choose
    their steps on outputs that differ by round-off, and the runs differ by what their error control
    leaves: measured 1.1e-4, 2.8e-6 and 5.2e-8 of each output's largest value at tolerances 1e-3, 1e-5
    and 1e-7. Bound at 1e-7: 10 times the tolerance."""
    tolerance = 1e-7
    angles, _ = _turning_run(make_cable, ANGLES_XYZ, tolerance)
    quaternion, _ = _turning_run(make_cable, QUATERNION, tolerance)
    scale = np.abs(angles).max(axis=0)
    assert np.all(scale > 1e4)
    assert np.max(np.abs(quaternion[:2] - angles[:2]) / scale) < 1e-12
    assert np.max(np.abs(quaternion - angles) / scale) < 10.0 * tolerance


def test_a_quaternion_off_unit_norm_is_normalized_or_refused(make_cable):
    """bodyOrientation 1: a quaternion 0.5 % too long is normalized (the static start the same to round-off,
    reported once); one 2 % too long is refused with its norm, as is one of zeros."""
    unit, _ = _turning_run(make_cable, QUATERNION, 1e-3, steps=3)
    longer, c = _turning_run(make_cable, QUATERNION, 1e-3, scale=1.005, steps=3, logging_on=True)
    assert np.max(np.abs(longer[0] - unit[0]) / np.abs(unit[0]).max()) < 1e-12
    reports = [m for _, _, m in c.messages if "normalized" in m]
    assert len(reports) == 1 and "body[1].q0/q1/q2/q3 has norm 1.005" in reports[0], reports
    for scale in (1.02, 0.0):
        with pytest.raises(FMICallException) as err:
            _turning_run(make_cable, QUATERNION, 1e-3, scale=scale, steps=1, logging_on=True)
        assert err.value.status == fmi2Error


def test_a_refused_quaternion_names_the_body_and_its_norm(make_cable):
    c = make_cable(parameters=ms.fmu_parameters(DECK, bodyOrientation=QUATERNION), logging_on=True)
    with pytest.raises(FMICallException):
        c.initialize(inputs={"body[1].q0": 0.0, "body[1].q1": 0.0, "body[1].q2": 0.0, "body[1].q3": 0.9})
    log = "\n".join(m for s, _, m in c.messages if s == "ERROR")
    assert "body[1].q0/q1/q2/q3 = (0, 0, 0, 0.9) has norm 0.9: not a unit quaternion" in log, log


def test_a_third_of_a_turn_in_yaw_permutes_the_three_lines(make_cable):
    """The deck is symmetric under a turn of 120 degrees about the vertical: the platform offset along x
    carries the tensions of the platform offset along the turned direction, the lines relabelled."""
    a, b = make_cable(parameters=ms.fmu_parameters(DECK)), make_cable(parameters=ms.fmu_parameters(DECK))
    phi = 2.0 * math.pi / 3.0
    a.initialize(inputs={"body[1].x": 8.0})
    b.initialize(inputs={"body[1].x": 8.0 * math.cos(phi), "body[1].y": 8.0 * math.sin(phi)})
    ta = [a.get(f"line[{k}].fairleadTension") for k in (1, 2, 3)]
    tb = [b.get(f"line[{k}].fairleadTension") for k in (1, 2, 3)]
    # line k + 1 (cyclically) stands to the turned offset as line k to the offset along x
    # the deck's anchors are rounded to 1 mm (725.383 for 837.6 sin 60 deg = 725.38293): 7e-5 m of a line
    # whose fairlead stiffness is 7e4 N/m, 5 N of 1e6
    assert tb == pytest.approx([ta[2], ta[0], ta[1]], rel=2e-5)
    assert min(ta) < 0.9 * max(ta)  # the offset loads the lines differently


def _run(cable, steps, start=0):
    history = []
    for k in range(start, start + steps):
        t = 0.2 * k
        q, v, _ = ms.PlatformMotion().state(t)
        cable.set({**{f"body[1].{n}": x for n, x in zip(ms.POSE_NAMES, q)},
                   **{f"body[1].{n}": x for n, x in zip(("vx", "vy", "vz", "wx", "wy", "wz"), v)}})
        cable.do_step(0.2)
        history.append(cable.get_reals([f"line[{j}].fairleadTension" for j in (1, 2, 3)] +
                                       [f"body[1].force.{a}" for a in "xyz"] + ["body[1].moment.y"]))
    return np.array(history)


def test_a_saved_state_continues_bit_for_bit_also_in_a_new_instance(make_cable):
    c = make_cable(parameters=ms.fmu_parameters(DECK))
    c.initialize()
    _run(c, 10)
    state = c.get_state()
    data = c.serialize_state(state)
    first = _run(c, 10, start=10)
    c.set_state(state, time=2.0)
    again = _run(c, 10, start=10)
    assert first.tobytes() == again.tobytes()
    fresh = make_cable(parameters=ms.fmu_parameters(DECK))
    fresh.set_state(fresh.deserialize_state(data), time=2.0)
    assert _run(fresh, 10, start=10).tobytes() == first.tobytes()


def test_a_system_does_not_warn_about_the_unused_tow_inputs(make_cable):
    """The lines of a system take their fairleads from the body inputs; tow.* (left at 0) is not a
    tow point that jumps."""
    c = make_cable(parameters=ms.fmu_parameters(DECK))
    c.initialize()
    _run(c, 3)
    assert not [m for s, _, m in c.messages if s in ("WARNING", "ERROR")]


def test_a_single_line_is_line_1_of_a_system(make_cable):
    c = make_cable(parameters={"lineFile": str(ms.DECKS / "chain.dat"), "enableSeabed": True})
    c.initialize(inputs={"tow.z": -70.0})
    assert c.get("line[1].fairleadTension") == c.get("towTension")
    assert c.get("line[1].anchorTension") == c.get("endTension")
    assert c.get("line[2].fairleadTension") == 0.0


def _refused(make_cable, tmp_path, text: str) -> str:
    path = tmp_path / "system.dat"
    path.write_text(text)
    c = make_cable(parameters={"lineFile": str(path)}, logging_on=True)
    with pytest.raises(FMICallException) as err:
        c.initialize()
    assert err.value.status == fmi2Error
    return "\n".join(text for status, _, text in c.messages if status == "ERROR")


def test_a_line_between_two_anchors_out_of_its_reach_is_refused_with_the_reason(make_cable, tmp_path):
    """A line of a system may run between two Fixed points (walked from one of them); chain 2 put between
    the anchors 1 and 2, 1450.8 m apart, cannot reach: refused naming the line and the distance."""
    text = ms.OC4.read_text()
    edit = ("2         main        2         5", "2         main        2         1")
    assert edit[0] in text
    log = _refused(make_cable, tmp_path, text.replace(edit[0], edit[1], 1))
    assert "mooring line 2: the line is too short for where its ends are" in log, log
    assert "is 1450.77 m from the tow point" in log and "anchor.x" not in log, log


def test_a_line_no_coupled_object_holds_runs_from_its_anchor(make_cable, tmp_path):
    """Chain 2 with its Vessel point made Free hangs from nothing: walked from its anchor to its free end,
    it lies on the seabed, all of it."""
    text = ms.OC4.read_text()
    edit = ("5      Vessel   -40.868", "5      Free     -40.868")
    assert edit[0] in text
    path = tmp_path / "system.dat"
    path.write_text(text.replace(edit[0], edit[1], 1))
    c = make_cable(parameters=ms.fmu_parameters(ms.read_system_deck(ms.OC4)) | {"lineFile": str(path)},
                   logging_on=True)
    c.initialize()
    assert c.get("line[2].groundedLength") == pytest.approx(835.35, rel=1e-9)
    assert c.get("line[1].fairleadTension") == pytest.approx(c.get("line[3].fairleadTension"), rel=1e-9)


def test_a_free_body_that_holds_no_line_is_refused_with_the_reason(make_cable, tmp_path):
    text = ms.OC4.read_text().replace(
        "---------------------- LINES", "---------------------- BODIES ----\nID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* "
        "I* Volume CdA* Ca*\n(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)\n"
        "1 Free 0 0 0 0 0 0 1e6 0 1e7 1000 0 0\n---------------------- LINES", 1)
    log = _refused(make_cable, tmp_path, text)
    assert "line 22: Free body 1 holds no line" in log, log


def test_a_coupled_body_of_the_deck_carries_its_points(make_cable, tmp_path):
    """The same three chains with their fairleads on a coupled body of a BODIES section (points Body1, at
    positions relative to it) are the same system as the deck's Vessel points on body 1."""
    text = ms.oc4_with_a_coupled_body().replace("Vessel", "Body1")
    path = tmp_path / "body.dat"
    path.write_text(text)
    pose = {"body[1].x": 6.0, "body[1].pitch": 0.03}
    a = make_cable(parameters={**ms.fmu_parameters(DECK), "lineFile": str(path)})
    b = make_cable(parameters=ms.fmu_parameters(DECK))
    a.initialize(inputs=pose)
    b.initialize(inputs=pose)
    names = [f"line[{k}].fairleadTension" for k in (1, 2, 3)] + [f"body[1].moment.{x}" for x in "xyz"]
    assert a.get_reals(names).tobytes() == b.get_reals(names).tobytes()


def _dynamics_difference(fmu_file, tmp_path, elements: int, factor: int) -> np.ndarray:
    from studies.comparisons.line_file_validation import refined_deck_file

    motion, t_end = ms.PlatformMotion(), 50.0
    ours = ms.fmu_motion(fmu_file, DECK, motion, t_end, lineFileElements=elements)
    deck = ms.read_system_deck(refined_deck_file(ms.OC4, factor, tmp_path)) if factor > 1 else DECK
    theirs = ms.moordyn_motion(deck, motion, t_end)
    return ms.rms_difference(ours, theirs)["rel_mean"]


def test_the_platform_in_surge_heave_and_pitch_matches_moordyn(fmu_file, tmp_path):
    """Surge 5 m / 20 s, heave 2 m / 10 s, pitch 3 deg / 25 s from rest for 50 s: RMS fairlead-tension
    difference within the acceptance's 1 % of the mean on every line, 20 elements per line against
    MoorDyn at twice the deck's NumSegs (40 segments, dtM 0.5 ms; measured 0.47 % from the converged
    FMU, docs/systems_mooring.md)."""
    rel = _dynamics_difference(fmu_file, tmp_path, 20, 2)
    assert np.all(rel < 1e-2), rel


@pytest.mark.slow
def test_both_codes_converged_agree_on_the_platform_motion(fmu_file, tmp_path):
    """The same with both codes refined: 40 elements against 80 segments at dtM 0.25 ms, where MoorDyn's
    refinements from 20 to 40 to 80 segments approach the converged FMU (0.85, 0.47, 0.18 %): within
    0.5 %, MoorDyn's own change from 40 to 80 segments (0.3 %) and a margin, half the acceptance's 1 %."""
    rel = _dynamics_difference(fmu_file, tmp_path, 40, 4)
    assert np.all(rel < 5e-3), rel


BODY_LOAD = [f"body[1].force.{a}" for a in "xyz"] + [f"body[1].moment.{a}" for a in "xyz"]
BODY_INPUTS = [f"body[1].{n}" for n in ms.POSE_NAMES + ("vx", "vy", "vz", "wx", "wy", "wz")]


def body_inputs(orientation: int) -> list:
    """Body 1's inputs as bodyOrientation reads them: x, y, z, its orientation (roll, pitch, yaw or q0..q3),
    vx, vy, vz, wx, wy, wz."""
    if orientation != QUATERNION:
        return BODY_INPUTS
    return BODY_INPUTS[:3] + [f"body[1].q{i}" for i in range(4)] + BODY_INPUTS[6:]


class Drift:
    """Body 1 at an offset, pitched pose, at rest (rates 0) or drifting slowly in all six degrees of freedom;
    with an orientation (bodyOrientation) other than 0 at a pose turned about all three axes, its angles
    passed as that orientation's inputs (1: the quaternion of R = Rx Ry Rz of them)."""

    def __init__(self, moving: bool, accelerating: bool = False, orientation: int = 0):
        turned = [0.02, 0.03, 0.05] if orientation else [0.0, 0.03, 0.0]
        self.q0 = np.array([4.0, 0.0, -1.0, *turned])
        self.v0 = np.array([0.05, 0.02, 0.01, 0.002, 0.003, 0.001]) if moving else np.zeros(6)
        self.a = np.array([0.01, -0.005, 0.002, 0.0005, -0.0004, 0.0002]) if accelerating else np.zeros(6)
        self.accelerating = accelerating
        self.orientation = orientation
        self.names = body_inputs(orientation)

    def inputs(self, t):
        v = self.v0 + self.a * t
        q = self.q0 + self.v0 * t + 0.5 * self.a * t * t
        turn = quaternion_from_angles(*q[3:]) if self.orientation == QUATERNION else q[3:]
        return dict(zip(self.names, [*q[:3], *turn, *v]))

    def step(self, cable, h, t, change=None):
        """Sets the inputs at t (one changed by the given amount) and, when accelerating, their input
        derivatives der(body[1].v*), der(body[1].w*), then steps."""
        x = self.inputs(t)
        for name, delta in (change or {}).items():
            x[name] += delta
        cable.set(x)
        if self.accelerating:
            cable.set_input_derivatives(BODY_INPUTS[6:], 1, list(self.a))
        cable.do_step(h, t)


@pytest.mark.parametrize("h,moving,accelerating,orientation", [
    (0.5, False, False, ANGLES_XYZ), (0.1, False, False, ANGLES_XYZ), (0.1, True, False, ANGLES_XYZ),
    (0.1, True, True, ANGLES_XYZ), (0.1, True, True, QUATERNION), (0.1, True, True, ANGLES_ZYX)])
def test_body_load_derivatives_equal_finite_differences_of_the_step(make_cable, h, moving, accelerating, orientation):
    """fmi2GetDirectionalDerivative of body[1].force/moment with respect to body[1].* over the next step,
    against central differences of fmi2DoStep with the state rolled back. The perturbations (1 mm,
    1e-5 rad, 1 mm/s, 1e-5 rad/s) keep the lines linear; at tensionTolerance 1e-8 the integration noise
    is below 1e-4 of the entries. Bound: the lines' own derivatives' 0.5 % of the largest entry
    (test_directional_derivatives.py), per block of like units. At rest the lines' derivatives are
    exact to 0.05 % (measured), so the test isolates the chain through the body's motion and arms; the
    slow drift adds the angular-velocity terms (measured 0.19 %). A platform moving fast within the
    step is linearized about the step's start (docs/systems_mooring.md: 0.66 % at 0.1 s, 4.5 % at 0.5 s in
    the surge-heave-pitch motion). With the body's accelerations passed as input derivatives the fairleads'
    accelerations move with the angles and the angular velocity too. With the orientation as a quaternion
    (bodyOrientation 1, perturbed by 1e-5 each, the normalization's radial direction included) or as the
    angles of R = Rz Ry Rx (2) the derivatives are with respect to those inputs, at a pose turned about all
    three axes; the orientation inputs not read have none."""
    c = make_cable(parameters={**ms.fmu_parameters(DECK), "tensionTolerance": 1e-8, "bodyOrientation": orientation})
    body = Drift(moving, accelerating, orientation)
    c.initialize(inputs=body.inputs(0.0))
    t = 0.0
    for _ in range(4):
        body.step(c, h, t)
        t += h
    vo = [c.variables[n].valueReference for n in BODY_LOAD]
    D = np.column_stack([c.slave.getDirectionalDerivative(vo, [c.variables[n].valueReference], [1.0])
                         for n in body.names])
    unread = [n for n in body_inputs(QUATERNION) + BODY_INPUTS if n not in body.names]
    assert all(c.slave.getDirectionalDerivative(vo, [c.variables[n].valueReference], [1.0]) == [0.0] * 6
               for n in unread)
    state = c.get_state()
    columns = []
    for name in body.names:
        eps = 1e-3 if name.split(".")[1] in ("x", "y", "z", "vx", "vy", "vz") else 1e-5
        values = []
        for sign in (1.0, -1.0):
            c.set_state(state, t)
            body.step(c, h, t, {name: sign * eps})
            values.append(c.get_reals(BODY_LOAD))
        columns.append((values[0] - values[1]) / (2.0 * eps))
    c.set_state(state, t)
    FD = np.column_stack(columns)
    turns = len(body.names) - 9  # the orientation inputs: 3 angles or 4 quaternion components
    for rows in (slice(0, 3), slice(3, 6)):
        for cols in (slice(0, 3), slice(3, 3 + turns), slice(3 + turns, 6 + turns), slice(6 + turns, 9 + turns)):
            scale = np.abs(FD[rows, cols]).max()
            assert np.abs(D[rows, cols] - FD[rows, cols]).max() < 5e-3 * scale, (rows, cols, D[rows, cols],
                                                                                  FD[rows, cols])


def test_the_moored_platform_scene_runs_and_records_the_lines(fmu_file):
    """scenes/oc4_platform.toml (`ucable run oc4_platform`): its deck found next to it, body 1 moving as
    [body] says; the recorded line 1 is the single-line towTension, the static start MoorPy's."""
    from ucable.scene import run_scene

    r = run_scene("oc4_platform", overrides={"duration": 5.0}, fmu=fmu_file)
    assert r["line[1].fairleadTension"].tobytes() == r["towTension"].tobytes()
    assert "line[4].fairleadTension" not in r.columns  # three lines in the deck
    assert r["line[2].fairleadTension"][0] == pytest.approx(ms.moorpy_statics(DECK)["fairlead"][1], rel=5e-3)
    assert r["body[1].force.z"][0] < -1.8e6 and abs(r["body[1].force.x"][-1]) > 1e3  # the surge has begun


def test_the_moored_platform_scene_passes_a_quaternion_with_body_orientation_1(fmu_file):
    """`--set bodyOrientation=1`: the scene's angles go to the FMU as their quaternion, the same platform
    motion: every recorded column within 10 times the integrators' tolerance (1e-7) of the angles' run
    (the pitch of 3 degrees left out would change the moments by far more)."""
    from ucable.scene import run_scene

    tight = {"duration": 5.0, "tensionTolerance": 1e-7, "positionTolerance": 1e-7}
    angles = run_scene("oc4_platform", overrides=tight, fmu=fmu_file)
    quaternion = run_scene("oc4_platform", overrides={**tight, "bodyOrientation": 1}, fmu=fmu_file)
    for name in ["body[1].moment.y", "body[1].force.x"] + [f"line[{k}].fairleadTension" for k in (1, 2, 3)]:
        scale = np.abs(angles[name]).max()
        assert scale > 1e3 and np.abs(quaternion[name] - angles[name]).max() < 1e-6 * scale, name


def test_the_vessel_rao_fmu_drives_the_platform_under_fmpy_and_libcosim(fmu_file):
    """systems/moored_platform: the VesselRAO FMU's platform.* outputs drive body 1 in a JONSWAP sea (Hs 3 m,
    Tp 9 s, head seas) for 30 s. Stable at 0.1 and 1 s communication steps under both masters; the sea loads
    the lines (line 1's tension swings by more than 5 %). fmpy passes the platform's accelerations as input
    derivatives, libcosim's fixed-step algorithm passes none: at 0.1 s they agree within 0.2 % of the
    tension (measured 0.05 %: the accelerations estimated from two velocity samples 0.1 s apart)."""
    from ucable.system import run_named

    runs = {(m, h): run_named("moored_platform", master=m, step=h, duration=30.0)
            for m in ("fmpy", "libcosim") for h in (0.1, 1.0)}
    for r in runs.values():
        T = r["cable.line[1].fairleadTension"]
        assert np.all(np.isfinite(T)) and T.min() > 0.5 * T[0] and T.max() < 2.0 * T[0]
        assert np.ptp(T) > 0.05 * T[0]
    a, b = runs[("fmpy", 0.1)], runs[("libcosim", 0.1)]
    for name in ("cable.line[1].fairleadTension", "cable.line[2].fairleadTension"):
        assert np.max(np.abs(a[name] - b[name])) < 2e-3 * np.mean(a[name]), name


def test_body_accelerations_as_input_derivatives_keep_long_steps_accurate(fmu_file):
    """der(body[1].v*) and der(body[1].w*): the platform's surge-heave-pitch at 0.5 s communication steps
    against 0.05 s steps (both with the derivatives): fairlead tensions within 1.5 % (measured 0.85 %);
    without them the acceleration is the difference of the velocity samples, a step late, and the
    tensions are off by 10 % (docs/systems_mooring.md)."""
    motion, t_end = ms.PlatformMotion(), 30.0
    ref = ms.fmu_motion(fmu_file, DECK, motion, t_end, 0.05, accelerations=True)
    errors = {}
    for given in (True, False):
        run = ms.fmu_motion(fmu_file, DECK, motion, t_end, 0.5, accelerations=given)
        errors[given] = np.max(np.abs(run.fairlead - ref.fairlead[::10]) / np.mean(ref.fairlead, axis=0))
    assert errors[True] < 1.5e-2, errors
    assert errors[True] < 0.2 * errors[False], errors


@pytest.mark.parametrize("pose", [POSES[0], POSES[2]], ids=["rest", "surge-heave-pitch"])
def test_chains_with_clump_weights_between_lines_match_moorpy(fmu_file, tmp_path, pose):
    """Each OC4 chain in two deck lines joined by a Free point with a 20 t clump weight: every system line is
    a chain of two sections with the clump an attachment at their pinned joint; line[k] of the deck's six
    lines is each section's tension at its ends. Against MoorPy (which solves the free points): tensions
    within 0.5 %, stiffness within 1 % (measured 0.012 %, 2e-9)."""
    path = tmp_path / "oc4_clump.dat"
    path.write_text(ms.clumped_oc4(ms.OC4.read_text()))
    deck = ms.read_system_deck(path)
    ref, ours = ms.moorpy_statics(deck, pose), ms.fmu_statics(fmu_file, deck, pose)
    assert len(ours["fairlead"]) == 6
    assert ours["fairlead"] == pytest.approx(ref["fairlead"], rel=5e-3)
    assert ours["anchor"] == pytest.approx(ref["anchor"], rel=5e-3)
    assert ms.stiffness_difference(ours["stiffness"], ref["stiffness"]) < 1e-2


@pytest.mark.slow
def test_chains_with_clump_weights_in_motion_match_moordyn(fmu_file, tmp_path):
    """The clumped OC4 system (20 t clumps between two deck lines per leg) in the surge-heave-pitch motion
    for 50 s: the fairlead tensions (deck lines 4-6) of the FMU (20 elements per section) and MoorDyn at
    twice the deck's NumSegs, its clumps settled from MoorPy's equilibrium, differ by less than the
    acceptance's 1 % of the mean (measured 0.26 %; 0.59 % against MoorDyn at the deck's NumSegs)."""
    from studies.comparisons.line_file_validation import refined_deck_file

    path = tmp_path / "oc4_clump.dat"
    path.write_text(ms.clumped_oc4(ms.OC4.read_text()))
    deck = ms.read_system_deck(path)
    motion = ms.PlatformMotion()
    ours = ms.fmu_motion(fmu_file, deck, motion, 50.0, accelerations=True, lines=[4, 5, 6], lineFileElements=20)
    settled = ms.read_system_deck(refined_deck_file(ms.settled_deck(path, tmp_path), 2, tmp_path))
    theirs = ms.moordyn_motion(settled, motion, 50.0)
    assert np.all(ms.rms_difference(ours, theirs)["rel_mean"] < 1e-2)


def test_vessel_points_of_a_deck_with_bodies_follow_the_point_inputs(make_cable, tmp_path):
    """With a BODIES section the deck's Vessel points are coupled points driven by point[k].* (k their ID):
    placed and moved where body 1 would carry them, the lines are the same bit for bit, and the points'
    forces add up to the body's force."""
    text = ms.oc4_with_a_coupled_body()
    path = tmp_path / "points.dat"
    path.write_text(text)
    offset, velocity = np.array([3.0, -1.0, 0.5]), np.array([0.2, 0.1, -0.05])
    points = make_cable(parameters={**ms.fmu_parameters(DECK), "lineFile": str(path)})
    body = make_cable(parameters=ms.fmu_parameters(DECK))

    def point_inputs(t):
        x = {}
        for k, r in zip((4, 5, 6), DECK.fairleads):
            p = offset + velocity * t + r
            x.update({f"point[{k}].{c}": float(v) for c, v in zip("xyz", p)})
            x.update({f"point[{k}].v{c}": float(v) for c, v in zip("xyz", velocity)})
        return x

    def body_inputs(t):
        p = offset + velocity * t
        return {**{f"body[1].{c}": float(v) for c, v in zip("xyz", p)},
                **{f"body[1].v{c}": float(v) for c, v in zip("xyz", velocity)}}

    points.initialize(inputs=point_inputs(0.0))
    body.initialize(inputs=body_inputs(0.0))
    lines = [f"line[{k}].{q}" for k in (1, 2, 3) for q in ("fairleadTension", "anchorTension")]
    for k in range(4):
        if k:
            points.set(point_inputs(0.5 * (k - 1)))
            points.do_step(0.5)
            body.set(body_inputs(0.5 * (k - 1)))
            body.do_step(0.5)
        assert points.get_reals(lines).tobytes() == body.get_reals(lines).tobytes()
        total = sum(np.array([points.get(f"point[{j}].force.{c}") for c in "xyz"]) for j in (4, 5, 6))
        expected = np.array([body.get(f"body[1].force.{c}") for c in "xyz"])
        assert np.allclose(total, expected, rtol=0.0, atol=1e-9 * np.linalg.norm(expected))
        assert points.get("body[1].force.z") == 0.0  # no line on the body
