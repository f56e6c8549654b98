"""Free points where three or more lines meet (docs/systems_mooring.md, "Free points where several lines
meet"): their static equilibrium against MoorPy fed the same deck (each free point's position within 1 cm,
every line's fairlead and anchor tension within 0.5 %), and their dynamics: a subsurface buoy released
from a displaced position, against MoorDyn fed the same deck, stable at communication steps of 0.5-1 s,
and an exact save/restore."""

from __future__ import annotations

import numpy as np
import pytest

from studies import coupled_stiffness as cs
from studies import free_points as fp
from studies import mooring_system as ms
from ucable.fmu import FMICallException


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


@pytest.mark.parametrize("step", [0.5, 0.1])
def test_the_released_free_body_swings_and_settles_at_its_equilibrium(fmu_file, tmp_path, step):
    """The buoy as a free body released at rest 4.6 m from its equilibrium, tilted by 5 and -3 degrees:
    stable at 0.1 and 0.5 s steps, its swings die away around the statics' pose (docs/systems_mooring.md:
    at 1 s steps the coupled iteration does not converge in this release)."""
    still = fp.fmu_statics(fmu_file, fp.BUOY_BODY)["poses"][1]
    path = fp.displaced_body_deck(fp.BUOY_BODY, tmp_path, 1, (*DISPLACED, 5.0, -3.0, 0.0))
    run = fp.fmu_release(fmu_file, path, 4, 60.0, step, body=1)
    distance = np.linalg.norm(run["pose"][:, :3] - still[:3], axis=1)
    swings = [distance[(run["t"] >= t0) & (run["t"] < t0 + 20.0)].max() for t0 in (0.0, 20.0, 40.0)]
    assert swings[0] > swings[1] > swings[2]
    assert swings[2] < 0.05 * distance[0]
    assert np.max(np.abs(run["pose"][run["t"] >= 40.0, 3:5])) < 0.02  # upright again (from 0.087 rad)


@pytest.mark.parametrize("body", [False, True], ids=["free-point", "free-body"])
def test_a_saved_state_of_the_buoy_continues_bit_for_bit(make_cable, tmp_path, body):
    path = (fp.displaced_body_deck(fp.BUOY_BODY, tmp_path, 1, (*DISPLACED, 5.0, -3.0, 0.0)) if body
            else _released(tmp_path))
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
