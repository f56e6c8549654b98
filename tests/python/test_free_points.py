"""Free points where three or more lines meet (docs/systems_mooring.md, "Free points where several lines
meet"): their static equilibrium against MoorPy fed the same deck (each free point's position within 1 cm,
every line's fairlead and anchor tension within 0.5 %), and their dynamics: a subsurface buoy released
from a displaced position, against MoorDyn fed the same deck, stable at communication steps of 0.5-1 s,
and an exact save/restore."""

from __future__ import annotations

import numpy as np
import pytest

from studies.comparisons import coupled_stiffness as cs
from studies.comparisons import free_points as fp
from studies.comparisons import mooring_system as ms
from ucable.fmu import CableFMU, FMICallException


def _check(fmu_file, path, current=0.0):
    ref, ours = fp.moorpy_statics(path, current), fp.fmu_statics(fmu_file, path, current)
    difference = fp.compare(ours, ref)
    assert difference["distance"] < 0.01, (ours["points"], ref["points"])
    assert difference["tension"] < 5e-3, (ours, ref)
    return ours, ref


def test_a_subsurface_buoy_on_three_legs_matches_moorpy(fmu_file):
    ours, _ = _check(fmu_file, fp.BUOY)
    # the legs are alike: the buoy stands over the middle of the anchors (which the deck rounds to 1 mm)
    assert abs(ours["points"][4][0]) < 1e-3 and abs(ours["points"][4][1]) < 1e-3


def test_the_buoy_in_a_current_matches_moorpy_where_the_current_acts_on_the_buoy(fmu_file, tmp_path):
    """MoorPy's current acts on the lines through a lumped load (module docstring), not on points: the
    comparison takes the lines' drag away, so that the buoy's drag alone moves it downstream."""
    path = fp.write_variant(fp.BUOY, tmp_path, fp.without_line_drag)
    ours, ref = _check(fmu_file, path, current=1.0)
    assert ours["points"][4][0] > 0.1  # 0.5 rho CdA U^2 = 1.5 kN against the legs' horizontal stiffness


def test_the_legs_drag_carries_the_buoy_further_downstream(fmu_file):
    """With the legs' own drag (which MoorPy lumps, not compared here) the buoy drifts further than with
    its own drag alone (0.12 m at 1 m/s, above)."""
    still, drift = fp.fmu_statics(fmu_file, fp.BUOY), fp.fmu_statics(fmu_file, fp.BUOY, current=1.0)
    # the upstream leg (line 1, its anchor at +x) slackens, the two downstream legs tighten
    assert drift["fairlead"][0] < still["fairlead"][0] < drift["fairlead"][1]
    assert drift["points"][4][0] > 0.2


JOINTS = fp.DECKS / "clump_and_buoy_legs.dat"  # two legs, each of two lines joined at a free point; a hanging weight


def test_free_points_one_or_two_lines_hold_report_their_positions(fmu_file):
    """A clump weight and a buoy where two lines meet are no free nodes (each leg is one line of two
    sections, the point a mass on the node between them), yet point[k].position is where that node stands,
    and a weight hanging at a line's free end where that end is: MoorPy's equilibrium of the three points
    within 1 cm, every line's tensions within 0.5 %."""
    ours, ref = _check(fmu_file, JOINTS)
    assert sorted(ref["points"]) == [2, 5, 7]
    assert ours["points"][2][2] < ours["points"][5][2]  # the clump sinks, the buoy lifts its leg


def test_a_two_line_joints_position_follows_the_line_and_restores(fmu_file):
    """The joints' positions are the lines' at each communication point (not held at their statics): the
    platform drawn 5 m along -x over 10 s slackens leg 2, whose buoy rises, and a restored state reads back
    the positions it was saved with, bit for bit."""
    deck = ms.read_system_deck(JOINTS)
    with CableFMU(fmu_file, parameters=ms.fmu_parameters(deck)) as c:
        c.initialize()
        position = lambda: np.array([[c.get(f"point[{k}].position.{a}") for a in "xyz"] for k in (2, 5)])
        start, h = position(), 0.5
        for k in range(20):
            c.set({"body[1].x": -0.25 * (k + 1), "body[1].vx": -0.5})
            c.do_step(h)
            if k == 9:
                state, saved = c.get_state(), position()
        moved = position()
        c.set_state(state)
        restored = position()
        c.free_state(state)
    assert moved[1][2] > start[1][2] + 0.5, (start, moved)  # leg 2 slackens: its buoy rises
    assert np.array_equal(restored, saved) and not np.array_equal(saved, moved)


def test_a_bridle_of_two_anchor_legs_and_a_pennant_to_the_platform_matches_moorpy(fmu_file, tmp_path):
    path = fp.write_variant(ms.OC4, tmp_path, fp.bridle)
    _check(fmu_file, path)


def test_the_buoy_as_a_free_body_matches_moorpy(fmu_file, tmp_path):
    """The buoy as a Free body (six unknowns), its centre of gravity below its reference point, the legs
    on its rim: its reference point and the points on it within 1 cm of MoorPy's, the tensions within
    0.5 %; in still water and in a 1 m/s current on the body alone, which tilts it."""
    ours, _ = _check(fmu_file, fp.BUOY_BODY)
    assert np.max(np.abs(ours["poses"][1][3:])) < 1e-6  # upright: the legs are alike
    drift, ref = _check(fmu_file, fp.write_variant(fp.BUOY_BODY, tmp_path, fp.without_line_drag), current=1.0)
    assert drift["poses"][1][0] > 0.05 and abs(drift["poses"][1][4]) > 1e-3  # pushed along x, pitched
    assert drift["poses"][1][4] == pytest.approx(ref["poses"][1][4], rel=0.02)


def test_a_free_bodys_drag_acts_in_its_axes(fmu_file, tmp_path):
    """Drag areas per body axis (CdA* 1|3|1: 3 m2 across its y axis) in a current of 1 m/s at 45 degrees:
    the drag, 1/2 rho |U| R diag(CdA) R^T U, pulls the body three times as hard along y as along x. Its
    reference point within 1 cm of MoorPy's given that force, the tensions within 0.5 %."""
    anisotropic = fp.write_variant(fp.BUOY_BODY, tmp_path, lambda s: fp.without_line_drag(s).replace(
        "15.0    3.0   1.0", "15.0    1|3|1   1.0"))
    current = (np.sqrt(0.5), np.sqrt(0.5))
    ours, _ = _check(fmu_file, anisotropic, current=current)
    still = fp.fmu_statics(fmu_file, fp.BUOY_BODY)["poses"][1]
    drift = ours["poses"][1][:2] - still[:2]
    assert drift[1] == pytest.approx(3.0 * drift[0], rel=0.05)  # the legs' stiffness is alike along x and y


# ----------------------------------------------------------------------------- the coupled stiffness
# The FMU's stiffness (the free nodes re-balanced on the lines' catenaries and condensed) and MoorPy's (its
# statics re-solved) rest on the same exact elastic catenaries: they differ by the finite differences'
# truncation, the FMU's (1 mm steps of each line with its other end held: (1 mm / the sag of the tautest
# line)^2, 5e-6 for the bridle's 70 m pennant, its sag 0.47 m) and MoorPy's (0.05 m steps of its whole
# statics: 1.3e-5 where its analytic stiffness is exact, the two bodies sharing a taut line), and the statics'
# tolerances (1e-8 m). MoorPy's `getCoupledStiffnessA` condenses a free body's rotations approximately: up to
# 5e-4 from its own finite differences, inside the acceptance's 1 %. In the current (the lines' drag taken
# away, MoorPy given the buoy's drag as a constant force) the buoy's balance moves: left out, the drag would
# leave the stiffness 5e-4 from MoorPy's.
STIFFNESS_TOLERANCE = 3e-5


@pytest.mark.parametrize("case", [
    "OC4 bridle, at rest", "OC4 bridle, surge 5 m, heave 2 m, pitch 3 deg",
    "platform with a leg through a buoy body, at rest",
    "platform with a leg through a buoy body, surge -6 m, sway 4 m, yaw 5 deg",
    "platform with a leg through a buoy body, a 1 m/s current on the buoy",
    "two bodies sharing a line (MoorPy's case9), body 1", "two bodies sharing a line (MoorPy's case9), body 2"])
def test_the_coupled_stiffness_with_the_free_nodes_rebalanced_matches_moorpy(fmu_file, tmp_path, case):
    """Each entry against the scale sqrt(K_ii K_jj) of its row and column: within the finite differences'
    truncation of MoorPy's re-solved statics, and within the acceptance's 1 % of its analytic stiffness."""
    r = cs.compare_case(fmu_file, *cs.cases(tmp_path)[case])
    assert r["vs_differences"] < STIFFNESS_TOLERANCE, r["K"]
    assert r["vs_analytic"] < 1e-2
    if "buoy body" not in case:  # no free body: MoorPy's analytic stiffness is exact too
        assert r["vs_analytic"] < STIFFNESS_TOLERANCE


def test_the_stiffness_read_is_that_of_the_present_state(make_cable, tmp_path):
    """body[1].stiffness is computed when it is read: read at every step or only at the last, after a restore
    of a saved state or in the run that saved it, it is the same, bit for bit, and it follows the motion."""
    path = cs.cases(tmp_path)["OC4 bridle, at rest"][0]
    names = cs.STIFFNESS_NAMES

    def run(cable, read_every):
        cable.initialize()
        first = cable.get_reals(names) if read_every else None
        for k in range(3):
            cable.set({"body[1].x": 0.5 * (k + 1), "body[1].vx": 5.0})
            cable.do_step(0.1, t=0.1 * k)
            if read_every:
                cable.get_reals(names)
        return first, cable.get_reals(names)

    parameters = ms.fmu_parameters(ms.read_system_deck(path))
    every, last = make_cable(parameters=parameters), make_cable(parameters=parameters)
    start, moved = run(every, True)
    assert np.array_equal(run(last, False)[1], moved)
    assert abs(moved[0] / start[0] - 1.0) > 1e-3  # the platform 1.5 m along x: the bridle's surge stiffness changed
    state = every.get_state()
    every.do_step(0.1, t=0.3)
    assert not np.array_equal(every.get_reals(names), moved)
    every.set_state(state, time=0.3)
    assert np.array_equal(every.get_reals(names), moved)


# ----------------------------------------------------------------------------- dynamics
DISPLACED = (3.0, 2.0, -70.0)  # the buoy's start: 4.6 m from its equilibrium (0, 0, -67.08)


def _released(tmp_path):
    return fp.displaced_deck(fp.BUOY, tmp_path, 4, DISPLACED)


def _released_body(tmp_path):
    return fp.displaced_body_deck(fp.BUOY_BODY, tmp_path, 1, (*DISPLACED, 5.0, -3.0, 0.0))


@pytest.mark.parametrize("step", [1.0, 0.5])
def test_the_released_buoy_oscillates_and_settles_at_its_equilibrium(fmu_file, tmp_path, step):
    """Released at rest 4.6 m from its equilibrium (the deck's TmaxIC 0), stepped at 0.5 and 1 s: the
    buoy swings through its equilibrium and its swings die away (the legs' drag and damping) around the
    position of the statics."""
    still = fp.fmu_statics(fmu_file, fp.BUOY)["points"][4]
    run = fp.fmu_release(fmu_file, _released(tmp_path), 4, 120.0, step)
    assert run["position"][0] == pytest.approx(DISPLACED, abs=1e-9)
    distance = np.linalg.norm(run["position"] - still, axis=1)
    swings = [distance[(run["t"] >= t0) & (run["t"] < t0 + 20.0)].max() for t0 in (20.0, 60.0, 100.0)]
    assert swings[0] > swings[1] > swings[2]
    assert swings[2] < 0.05 * distance[0]
    # it passes the equilibrium: the offset along x changes sign
    assert run["position"][:, 0].min() < -0.1


def test_the_released_buoy_matches_moordyn(fmu_file, tmp_path):
    """MoorDyn v2 fed the same deck (TmaxIC 0: the buoy starts where the deck puts it) at 80 segments per
    leg; the FMU at 20 elements with communication steps of 0.05 s. RMS difference of the legs' tensions
    at the buoy over 30 s (after the first second's snap), relative to the mean: the acceptance's 2 %."""
    path = _released(tmp_path)
    ref = fp.moordyn_release(fp.refined_deck(path, tmp_path, 80), 4, 30.0, 0.1)
    ours = fp.fmu_release(fmu_file, path, 4, 30.0, 0.05, lineFileElements=20)
    ours = {"t": ours["t"][::2], "tension": ours["tension"][::2]}
    assert fp.rms_difference(ours, ref, 1.0) < 0.02


@pytest.mark.slow
def test_the_released_buoy_matches_moordyn_with_both_converged(fmu_file, tmp_path):
    """The converged pair (docs/systems_mooring.md): the FMU at 40 elements per leg and 0.025 s steps,
    MoorDyn at 160 segments (dtM 0.125 ms): within 1 % (measured 0.74 %; MoorDyn's own change from 80 to
    160 segments is 0.61 %)."""
    path = _released(tmp_path)
    ref = fp.moordyn_release(fp.refined_deck(path, tmp_path, 160), 4, 30.0, 0.1)
    ours = fp.fmu_release(fmu_file, path, 4, 30.0, 0.025, lineFileElements=40)
    ours = {"t": ours["t"][::4], "tension": ours["tension"][::4]}
    assert fp.rms_difference(ours, ref, 1.0) < 0.01


@pytest.mark.parametrize("step", [1.0, 0.5, 0.1])
def test_the_released_free_body_swings_and_settles_at_its_equilibrium(fmu_file, tmp_path, step):
    """The buoy as a free body released at rest 4.6 m from its equilibrium, tilted by 5 and -3 degrees:
    stable at 0.1, 0.5 and 1 s steps, its swings die away around the statics' pose. (MoorDyn's swings of
    the body's point 4 over 0-20, 20-40, 40-60, 60-80 s: 5.17, 0.40, 0.25, 0.16 m; the FMU's at 0.1 s: 5.17,
    0.36, 0.23, 0.17 m; docs/systems_mooring.md.)"""
    still = fp.fmu_statics(fmu_file, fp.BUOY_BODY)["poses"][1]
    run = fp.fmu_release(fmu_file, _released_body(tmp_path), 4, 80.0, step, body=1)
    distance = np.linalg.norm(run["pose"][:, :3] - still[:3], axis=1)
    swings = [distance[(run["t"] >= t0) & (run["t"] < t0 + 20.0)].max() for t0 in (0.0, 30.0, 60.0)]
    assert swings[0] > swings[1] > swings[2]
    assert swings[2] < 0.05 * distance[0]
    assert np.max(np.abs(run["pose"][run["t"] >= 40.0, 3:5])) < 0.02  # upright again (from 0.087 rad)


def test_the_released_free_body_matches_moordyn(fmu_file, tmp_path):
    """The free body's release against MoorDyn v2 fed the same deck (docs/systems_mooring.md): the FMU at 20
    elements per leg and 0.05 s steps, MoorDyn at 40 segments. Both converged (40 elements, 0.025 s; 160
    segments) they differ by 1.54 % of the mean tension, MoorDyn's own change from 40 to 160 segments is
    0.89 %; this pair measured 1.60 %. Asserted within the acceptance's 2 %."""
    path = _released_body(tmp_path)
    ref = fp.moordyn_release(fp.refined_deck(path, tmp_path, 40), 4, 30.0, 0.1)
    ours = fp.fmu_release(fmu_file, path, 4, 30.0, 0.05, body=1, lineFileElements=20)
    ours = {"t": ours["t"][::2], "tension": ours["tension"][::2]}
    assert fp.rms_difference(ours, ref, 1.0) < 0.02


@pytest.mark.slow
def test_the_released_free_body_matches_moordyn_with_both_converged(fmu_file, tmp_path):
    """The converged pair: the FMU at 40 elements per leg and 0.025 s steps, MoorDyn at 160 segments
    (dtM 0.125 ms): measured 1.54 % (MoorDyn's own change from 80 to 160 segments: 0.87 %)."""
    path = _released_body(tmp_path)
    ref = fp.moordyn_release(fp.refined_deck(path, tmp_path, 160), 4, 30.0, 0.1)
    ours = fp.fmu_release(fmu_file, path, 4, 30.0, 0.025, body=1, lineFileElements=40)
    ours = {"t": ours["t"][::4], "tension": ours["tension"][::4]}
    assert fp.rms_difference(ours, ref, 1.0) < 0.02


def test_the_released_free_body_at_1_s_steps_follows_its_run_at_0_05_s(fmu_file, tmp_path):
    """Communication steps of 1 s in the release's snap: the steps whose estimated error in the body's
    position exceeds 1 cm are split into substeps (docs/systems_mooring.md, "Substeps"). Over 1-30 s the
    legs' tension differs from the run at 0.05 s steps by 1.37 % RMS of the mean (over 1-120 s: 0.76 %,
    2.25 % without the split), the reference point by at most 0.23 m (1.0 m without)."""
    path = _released_body(tmp_path)
    fine = fp.fmu_release(fmu_file, path, 4, 30.0, 0.05, body=1)
    coarse = fp.fmu_release(fmu_file, path, 4, 30.0, 1.0, body=1)
    fine = {"t": fine["t"][::20], "tension": fine["tension"][::20], "pose": fine["pose"][::20]}
    assert fp.rms_difference(coarse, fine, 1.0) < 0.02
    assert np.max(np.linalg.norm(coarse["pose"][:, :3] - fine["pose"][:, :3], axis=1)) < 0.5


def test_a_step_the_coupled_iteration_cannot_take_in_one_piece_is_split_into_substeps(make_cable, tmp_path):
    """The buoy body with its centre of gravity 3 m below its reference point and no rotational drag
    (CdA* 3|0): its coupled iteration does not converge over a step of 1 s from the release (measured
    before the substeps: fmi2DoStep failed at t = 0); the step is taken in substeps, logged once, and the
    release goes on."""
    path = _released_body(tmp_path)
    params = {**ms.fmu_parameters(ms.read_system_deck(path)), "lineFile": str(path)}
    path.write_text(path.read_text().replace("0|0|-1.0 ", "0|0|-3.0 ").replace("15.0    3.0   1.0", "15.0    3.0|0.0   1.0"))
    c = make_cable(parameters=params, logging_on=True)
    c.initialize()
    for k in range(10):
        c.do_step(1.0, t=float(k))
    tensions = c.get_reals([f"line[{k}].fairleadTension" for k in (1, 2, 3)])
    assert all(np.isfinite(tensions)) and min(tensions) > 0.0
    splits = [m for _, _, m in c.messages if "substeps" in m]
    assert len(splits) == 1 and "t = 0.000000 s" in splits[0], splits


@pytest.mark.parametrize("body", [False, True], ids=["free-point", "free-body"])
def test_a_saved_state_of_the_buoy_continues_bit_for_bit(make_cable, tmp_path, body):
    path = _released_body(tmp_path) if body else _released(tmp_path)
    params = {**ms.fmu_parameters(ms.read_system_deck(path)), "lineFile": str(path)}
    names = [f"line[{k}].fairleadTension" for k in (1, 2, 3)] + (
        [f"body[1].pose.{a}" for a in ("x", "y", "z", "roll", "pitch", "yaw")] if body else
        [f"point[4].position.{a}" for a in "xyz"])

    def run(cable, start, steps):
        out = []
        for k in range(start, start + steps):
            cable.do_step(0.2, t=0.2 * k)
            out.append(cable.get_reals(names))
        return np.array(out)

    c = make_cable(parameters=params)
    c.initialize()
    run(c, 0, 5)
    state = c.get_state()
    data = c.serialize_state(state)
    first = run(c, 5, 5)
    c.set_state(state, time=1.0)
    assert run(c, 5, 5).tobytes() == first.tobytes()
    fresh = make_cable(parameters=params)
    fresh.set_state(fresh.deserialize_state(data), time=1.0)
    assert run(fresh, 5, 5).tobytes() == first.tobytes()


def _buoy_state_at(make_cable, tmp_path, t_end, h=0.2):
    """The released buoy body's deck (a copy in tmp_path), its FMU parameters and its serialized state after
    steps of h to t_end."""
    path = _released_body(tmp_path)
    params = {**ms.fmu_parameters(ms.read_system_deck(path)), "lineFile": str(path)}
    c = make_cable(parameters=params)
    c.initialize()
    for k in range(int(round(t_end / h))):
        c.do_step(h, t=h * k)
    return path, params, c.serialize_state(c.get_state())


@pytest.mark.parametrize("edit", ["leg", "mass", "EA"])
def test_a_state_restored_after_its_deck_was_edited_is_refused_naming_the_file_and_the_value(
        make_cable, tmp_path, edit):
    """A mooring system's state carries every value its deck gave: restored (fmi2SetFMUstate after
    fmi2DeSerializeFMUstate, in a new instance) after the deck file was edited (a leg 10 m longer, the free
    body's mass doubled, EA halved) it is refused, naming the file and what differs, not stepped with the
    new deck's lines (which moved the body's moment by tens of MN m at the first step)."""
    path, params, data = _buoy_state_at(make_cable, tmp_path, 0.6)
    text = path.read_text()
    edits = {"leg": ("1         leg         1         4        128.5", "1         leg         1         4        138.5",
                     "length = 138.5 now, 128.5 in the state"),
             "mass": ("3000   0|0|-1.0", "6000   0|0|-1.0", "mass [kg] = 6000 now, 3000 in the state"),
             "EA": ("5.0E8", "2.5E8", "EA = 250000000 now, 500000000 in the state")}
    before, after, named = edits[edit]
    assert before in text
    path.write_text(text.replace(before, after, 1))
    fresh = make_cable(parameters=params)
    state = fresh.deserialize_state(data)
    with pytest.raises(FMICallException):
        fresh.set_state(state, time=0.6)
    refusals = [m for _, _, m in fresh.messages if "fmi2SetFMUstate" in m]
    assert refusals and f"lineFile {path}" in refusals[-1] and named in refusals[-1], fresh.log_text()
    assert "the deck is not the one the state was saved with" in refusals[-1]
    # the deck restored: the state continues
    path.write_text(text)
    again = make_cable(parameters=params)
    again.set_state(again.deserialize_state(data), time=0.6)
    again.do_step(0.2, t=0.6)


ROW = "3000   0|0|-1.0   5000     15.0    3.0   1.0"  # Mass CG* I* Volume CdA* Ca* of the buoy body


@pytest.mark.parametrize("fields, named", [
    ("3000   0|0|-1.0   -5000     15.0    3.0   1.0",
     "I = -5000: Free body 1's moment of inertia about its x axis is -5000 kg m2"),
    ("3000   0|0|-1.0   5000     15.0    -3.0   1.0", "CdA = -3.0: Free body 1's drag area in x is -3 m2"),
    ("3000   0|0|-1.0   5000     15.0    3.0   -1.0",
     "Ca = -1.0: Free body 1's added-mass coefficient in x is -1"),
    ("0   0|0|-1.0   5000     0    3.0   1.0",
     "Mass = 0 kg and Volume = 0 m3: Free body 1 has neither mass nor volume"),
], ids=["inertia", "drag", "added-mass", "no-mass-no-volume"])
def test_an_implausible_free_body_is_refused_at_the_start_naming_the_row_and_the_value(
        make_cable, tmp_path, fields, named):
    """A free body's negative inertia, drag area or added-mass coefficient, or neither mass nor volume:
    fmi2Error at the initialization naming the deck's row and the value (they were accepted, and the run
    failed later asking for a shorter communication step, or with negative drag ran on)."""
    text = fp.BUOY_BODY.read_text()
    assert ROW in text
    path = tmp_path / "buoy_body.dat"
    path.write_text(text.replace(ROW, fields, 1))
    c = make_cable(parameters={**ms.fmu_parameters(ms.read_system_deck(fp.BUOY_BODY)), "lineFile": str(path)})
    with pytest.raises(FMICallException):
        c.initialize()
    refusal = [m for _, _, m in c.messages if named in m]
    assert refusal and "line 12: " in refusal[0] and str(path) in refusal[0], c.log_text()


@pytest.mark.parametrize("running", ["system", "line"])
def test_a_refused_state_of_an_edited_deck_leaves_the_running_instance_as_it_was(make_cable, tmp_path, running):
    """A refused fmi2SetFMUstate changes nothing: a running instance (the buoy system of the edited deck, or a
    single line, whose core is not the state's) given the state of the deck before its edit refuses it and
    steps on bit for bit as an instance that never saw the call (the refusal dropped the instance's core and
    put the state's parameters in place of its own)."""
    path, params, data = _buoy_state_at(make_cable, tmp_path, 0.6)
    path.write_text(path.read_text().replace("3000   0|0|-1.0", "6000   0|0|-1.0", 1))
    own = params if running == "system" else {"nElements": 12}
    names = ([f"line[{k}].fairleadTension" for k in (1, 2, 3)] + [f"body[1].pose.{a}" for a in ("x", "z", "pitch")]
             if running == "system" else ["towForce.x", "towForce.z", "endPosition.z"])
    outputs = []
    for refused in (True, False):
        c = make_cable(parameters=own)
        c.initialize()
        c.do_step(0.2, t=0.0)
        if refused:
            state = c.deserialize_state(data)
            with pytest.raises(FMICallException):
                c.set_state(state)
            c.free_state(state)
            assert "the deck is not the one the state was saved with" in c.log_text()
        for k in range(1, 3):
            c.do_step(0.2, t=0.2 * k)
            outputs.append(c.get_reals(names))
    assert np.isfinite(outputs[0]).all()
    assert np.array(outputs[:2]).tobytes() == np.array(outputs[2:]).tobytes()


def test_a_buoy_on_a_chain_straight_above_its_anchor_rises_until_the_chain_is_taut(fmu_file):
    """A free body on a chain whose ends lie on one vertical, the chain 2 m longer than the deck's distance
    (its excess piled slack at the anchor: a start the line itself refuses): the free points' statics take
    the hanging line's tensions there (the catenary has none for a vertical line), so the buoy rises until
    the chain is taut. Closed form: the fairlead carries the buoy's net buoyancy, the anchor that less the
    chain's weight in water, the buoy stands 50 m plus the chain's stretch under the mean tension above
    the anchor; MoorPy's equilibrium of the same deck (which also has a chain from an anchor to its Vessel
    point, started where the deck places the point) agrees."""
    from studies.comparisons import public_decks as pd

    path = fp.DECKS / "buoy_vertical_chain.dat"
    result = pd.compare(fmu_file, path)
    assert result["status"] == "ok", result.get("reason")
    assert result["moorpy"] is None and result["worst"] < 1e-3, result["lines"]
    g, rho = 9.80665, 1025.0
    net = (rho * 15.0 - 3000.0) * g
    chain = (60.0 - rho * np.pi / 4 * 0.1**2) * g * 50.0
    (_, fairlead, _, anchor) = result["lines"][1]
    assert fairlead == pytest.approx(net, rel=1e-6)
    assert anchor == pytest.approx(net - chain, rel=1e-6)


_LAZY_WAVE = """lazy wave of the riser deck from its lower end, held where the FMU's body puts it
------------------------- LINE TYPES --------------------------------------------------
LineType  Diam    MassDenInAir    EA       BA/-zeta    EI    Can   Cat  Cdn   Cdt
(-)       (m)       (kg/m)        (N)      (Pa-s/-)  (n-m^2) (-)   (-)  (-)   (-)
cable     0.116      25         362e6      -1.0      38e3    1.0   0.0  1.1   0.008
bouyancy  0.361      59         362e6      -1.0      38e3    1.0  0.469 2.617 0.345
----------------------- POINTS ----------------------------------------------
Node      Type      X        Y         Z        M        V         CdA   CA
(-)       (-)      (m)      (m)       (m)      (kg)     (m^3)     (m^2)  (-)
1         Fixed    {x:.9f}     0      {z:.9f}      0        0          0     0
2         Free     375.0     0      -250.0      0        0          0     0
3         Free     290.0     0      -215.0      0        0          0     0
4         Vessel   0.0       0       -63.6       0        0          0     0
-------------------------- LINES -------------------------------------------------
Line     LineType NodeA     NodeB  UnstrLen   NumSegs     Flags/Outputs
(-)      (-)       (-)       (-)    (m)         (-)          (-)
1        cable       1       2    110.0       11           -
2        bouyancy    2       3     80.0        8           -
3        cable       3       4    340.0       34           -
-------------------------- SOLVER OPTIONS---------------------------------------------------
320        WtrDpth      - water depth
--------------------------- need this line -------------------------------------------------
"""


@pytest.mark.slow  # about 2 min on a loaded machine: the free body's Newton steps with the lines' solutions
def test_a_lazy_wave_riser_on_a_tethered_free_body_finds_its_equilibrium(fmu_file, tmp_path):
    """MoorDyn's riser deck: a free body 7 m above the seabed on a stiff tether (EA 362 MN, one element) to
    an anchor below it, held by a heavy cable to a second anchor and pulled by a lazy-wave riser (a buoyant
    section between two zero-length free rods) from a hang-off 63.6 m under water. At the deck's positions
    the tether sits exactly at its length (at the kink between slack and taut, 50 MN/m taut) and the free
    points' Newton steps find no smaller residual; damped steps with the Jacobian taken again find the
    equilibrium: the riser draws the body 1.6 m towards the hang-off, the cable to the anchor taut, the
    tether taut. The riser's tensions are those of MoorPy's statics of the lazy wave alone with its lower end
    held where the FMU's body puts it (MoorPy cannot read the whole deck)."""
    from studies.comparisons import public_decks as pd
    from studies.peers import moorpy
    from ucable.fmu import CableFMU

    path = fp.DECKS / "md_tests_Mooring_riser_riser_ic1.txt"
    given = pd.parameters(path, {}, 0.116)
    inputs = {f"point[{k}].{c}": v for k, xyz in pd.coupled_points(path).items() for c, v in zip("xyz", xyz)}
    c = CableFMU(fmu_file, parameters=given)
    try:
        c.initialize(inputs=inputs)
        tensions = [(c.get(f"line[{k}].fairleadTension"), c.get(f"line[{k}].anchorTension")) for k in range(1, 6)]
        x, z, pitch = (c.get(f"body[1].pose.{n}") for n in ("x", "z", "pitch"))
    finally:
        c.free()
    assert 449.0 < x < 452.0 and -314.0 < z < -312.0, (x, z)
    # the riser's lower end: rod 1's end B, 0.1 m behind the body's reference point along its x axis
    deck = tmp_path / "lazy_wave.txt"
    deck.write_text(_LAZY_WAVE.format(x=x - 0.1 * np.cos(pitch), z=z + 0.1 * np.sin(pitch)))
    with moorpy.silenced():
        s = moorpy.system(deck, rho=1025.0, g=9.80665)
        s.depth = 320.0
        s.initialize()
        assert s.solveEquilibrium(tol=1e-8, maxIter=5000) is not False
    ref = [(ln.TA, ln.TB) for ln in s.lineList]  # from the body's end up
    ours = [(tensions[2][1], tensions[2][0]), (tensions[3][1], tensions[3][0]), (tensions[4][1], tensions[4][0])]
    for (ra, rb), (oa, ob) in zip(ref, ours):
        assert oa == pytest.approx(ra, rel=5e-3) and ob == pytest.approx(rb, rel=5e-3), (ours, ref)
    assert tensions[0][0] > 0.0 and tensions[1][0] > 10e3  # the tether and the cable to the anchor taut
