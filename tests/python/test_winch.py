"""Acceptance of the winch at the tow point (docs/winch.md): `winchMode` (1 rate, 2 constant
tension), inputs `winch.rate`/`winch.tension`, parameters `winch.minLength`/`winch.maxLength`/
`winch.maxRate`, output `unstretchedLength`.

References and tolerances (docs/winch.md): the state a run settles to after paying out (hauling in)
to a length is that of a cable started at that length with the same nominal element length,
the FMU's static initialization (`fmu_static_references`, itself within 1e-5 in tension and 3 mm
in depth of the steady ODE); 0.5 % in tow tension and 0.5 m in body depth.
"""

import math

import numpy as np
import pytest
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import fmi2Error

from ucable.units import KNOT
from studies.references.winch_reference import DeployBody, elements_for_length, fmu_static_references

SPEED = 2.0 * KNOT
NOMINAL = 15.0
STEP = 0.5


def winch_cable(make_cable, length, mode=1, min_length=50.0, max_length=600.0, max_rate=1.0,
                parameters_extra=None, **kwargs):
    """The scene body on the Hopland cable with a winch; the drum without an acceleration limit
    (winch.maxAcceleration 0: the rate applied over each step is the one set) unless
    parameters_extra says otherwise."""
    params = {**DeployBody().fmu_parameters(), "length": length,
              "nElements": elements_for_length(length, NOMINAL), "initMode": 0,
              "winchMode": mode, "winch.minLength": min_length, "winch.maxLength": max_length,
              "winch.maxRate": max_rate, "winch.maxAcceleration": 0.0, **(parameters_extra or {})}
    return make_cable(parameters=params, **kwargs)


def start(cable):
    cable.initialize(inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": 0.0,
                             "tow.vx": SPEED, "tow.vy": 0.0, "tow.vz": 0.0, "winch.rate": 0.0})


def fly(cable, t0, duration, rate):
    """Tows at SPEED for `duration` seconds from t0 with the winch at `rate`; returns the tow
    tension and unstretched length at every communication point."""
    n = int(round(duration / STEP))
    T, L = np.empty(n), np.empty(n)
    for k in range(n):
        t = t0 + k * STEP
        cable.set({"tow.x": SPEED * t, "tow.vx": SPEED, "winch.rate": rate})
        cable.do_step(STEP, t)
        T[k], L[k] = cable.get("towTension"), cable.get("unstretchedLength")
    return T, L


def check_settled(cable, fmu_file, length, where):
    ref = fmu_static_references(fmu_file, [length], SPEED, DeployBody(), NOMINAL)
    T = cable.get("towTension")
    depth = -cable.get("endPosition.z")
    assert cable.get("unstretchedLength") == pytest.approx(length, abs=1e-9)
    assert T == pytest.approx(ref.tow_tension[0], rel=0.005), \
        f"{where}: tow tension {T:.1f} N vs cable started at {length} m {ref.tow_tension[0]:.1f} N"
    assert depth == pytest.approx(ref.body_depth[0], abs=0.5), \
        f"{where}: body depth {depth:.2f} m vs cable started at {length} m {ref.body_depth[0]:.2f} m"


def test_payout_tension_is_smooth_sample_to_sample(make_cable):
    """A 0.5 m/s pay-out from 100 m for 60 s (30 m, two splits of 15 m elements): the tow tension
    changes by less than 0.5 % of its mean from one communication point to the next.

    The winch starts from rest at full speed: the line below the sheave must take up the pay-out
    speed at once, an axial transient within the first step after which the tension sits lower
    (the body is towed more slowly through the water while line is paid out). The smoothness asked
    is that of the pay-out running, across the splits: from the second sample on."""
    cable = winch_cable(make_cable, 100.0)
    start(cable)
    T, L = fly(cable, 0.0, 60.0, 0.5)
    assert np.allclose(L, 100.0 + 0.5 * STEP * np.arange(1, len(L) + 1), rtol=0, atol=1e-9)
    running = np.abs(np.diff(T[1:]))
    assert np.all(running < 0.005 * T.mean()), \
        f"largest sample-to-sample change {running.max():.1f} N, mean {T.mean():.1f} N"


def test_payout_100_to_300_then_haul_in_settle_like_cables_started_there(make_cable, fmu_file):
    """Pay-out 100 -> 300 m at 0.5 m/s towing at 2 kn, then settling; haul-in back to 100 m likewise.
    The body's depth relaxes slowly after the winch stops (its offset from the final depth falls about
    5-fold every 300 s), so each settling lasts 1200 s."""
    cable = winch_cable(make_cable, 100.0)
    start(cable)
    fly(cable, 0.0, 400.0, 0.5)  # 100 -> 300 m
    fly(cable, 400.0, 1200.0, 0.0)  # settle
    check_settled(cable, fmu_file, 300.0, "after pay-out to 300 m")
    fly(cable, 1600.0, 400.0, -0.5)  # 300 -> 100 m
    fly(cable, 2000.0, 1200.0, 0.0)
    check_settled(cable, fmu_file, 100.0, "after haul-in to 100 m")


def test_rate_saturates_at_the_length_limits_with_a_logged_event(make_cable):
    cable = winch_cable(make_cable, 100.0, max_length=110.0, logging_on=True)
    start(cable)
    _, L = fly(cable, 0.0, 30.0, 0.5)  # asks for 115 m
    assert L.max() == pytest.approx(110.0, abs=1e-9)
    assert L[-1] == pytest.approx(110.0, abs=1e-9)
    assert any("winch" in m for _, _, m in cable.messages), cable.log_text()
    _, L = fly(cable, 30.0, 5.0, 5.0)  # above maxRate and the limit: no further pay-out
    assert L[-1] == pytest.approx(110.0, abs=1e-9)
    _, L = fly(cable, 35.0, 4.0, -5.0)  # haul-in at maxRate (1 m/s)
    assert L[-1] == pytest.approx(106.0, abs=1e-9)


def test_nan_rate_is_an_error_naming_the_input(make_cable):
    cable = winch_cable(make_cable, 100.0, logging_on=True)
    start(cable)
    with pytest.raises(FMICallException) as err:
        cable.set({"winch.rate": math.nan})
        cable.do_step(STEP, 0.0)
    assert err.value.status == fmi2Error
    assert any("winch.rate" in m for s, _, m in cable.messages if s == "ERROR"), cable.log_text()


@pytest.mark.parametrize("limits", [(300.0, 300.0), (400.0, 300.0), (150.0, 600.0)],
                         ids=["min=max", "min>max", "length<min"])
def test_bad_limits_are_an_error_naming_the_parameter(make_cable, limits):
    cable = winch_cable(make_cable, 100.0, min_length=limits[0], max_length=limits[1],
                        logging_on=True)
    with pytest.raises(FMICallException) as err:
        start(cable)
    assert err.value.status == fmi2Error
    errors = [m for s, _, m in cable.messages if s == "ERROR"]
    assert any("winch.minLength" in m or "winch.maxLength" in m for m in errors), cable.log_text()


def test_state_saved_before_a_split_continues_bit_identically_after_restore(make_cable):
    """Saved at 100 m, the run pays out past a split (15 m elements split at 22.5 m) and a restored
    copy, in memory and serialized, repeats it bit for bit."""
    cable = winch_cable(make_cable, 100.0)
    start(cable)
    fly(cable, 0.0, 5.0, 0.5)
    state = cable.get_state()
    first, _ = fly(cable, 5.0, 40.0, 0.5)
    cable.set_state(state)
    again, _ = fly(cable, 5.0, 40.0, 0.5)
    assert np.array_equal(first, again)
    restored = cable.deserialize_state(cable.serialize_state(state))
    cable.set_state(restored)
    serialized, _ = fly(cable, 5.0, 40.0, 0.5)
    assert np.array_equal(first, serialized)


# A 2 t body (0.25 m^3, 500 kg added mass, 2 m^2 drag area) hanging on 200 m of the cable from a
# vessel heaving 1.5 m at 8 s: what the constant-tension winch (winchMode 2) is for.
HANGING = {"length": 200.0, "nElements": 14, "bottomEnd": 2, "body.mass": 2000.0, "body.volume": 0.25,
           "body.CdA": 2.0, "body.addedMass": 500.0, "winch.minLength": 50.0, "winch.maxLength": 400.0,
           "winch.maxRate": 2.0}
HEAVE, PERIOD, H = 1.5, 8.0, 0.1


def heave(cable, duration, set_tension=None):
    """The tow point heaves from t = 0; returns the tow tension and length at every step."""
    w = 2 * math.pi / PERIOD
    n = int(round(duration / H))
    T, L = np.empty(n), np.empty(n)
    for k in range(n):
        t = k * H  # the inputs at the step's start
        cable.set({"tow.z": HEAVE * math.sin(w * t), "tow.vz": HEAVE * w * math.cos(w * t)})
        if set_tension is not None:
            cable.set({"winch.tension": set_tension(cable)})
        cable.set_input_derivatives(["tow.vz"], 1, [-HEAVE * w * w * math.sin(w * t)])
        cable.do_step(H, k * H)
        T[k], L[k] = cable.get("towTension"), cable.get("unstretchedLength")
    return T, L


def test_constant_tension_winch_takes_the_heave_out_of_the_tension(make_cable):
    """Held at the static tension with a time constant of 5 ms, the winch pays out and hauls in with
    the heave: the tension varies less than half as much as with a fixed length, about the same
    mean, and the length follows the heave (docs/winch.md: std 2828 N fixed, 1020 N here)."""
    fixed = make_cable(parameters=HANGING)
    fixed.initialize()
    static = fixed.get("towTension")
    T_fixed, _ = heave(fixed, 40.0)
    held = make_cable(parameters={**HANGING, "winchMode": 2, "winch.timeConstant": 0.005})
    held.initialize(inputs={"winch.tension": static})
    T_held, L = heave(held, 40.0)
    last = slice(len(T_held) // 2, None)  # after the start-up (the heave starts from rest)
    assert T_held[last].std() < 0.5 * T_fixed[last].std(), (T_held[last].std(), T_fixed[last].std())
    assert T_held[last].mean() == pytest.approx(static, rel=0.01)
    assert L[last].max() - L[last].min() > 1.0  # it pays out and hauls in


def test_constant_tension_below_the_weight_lowers_the_body(make_cable):
    """Held 2 kN below the static tension (no heave), the winch pays out: the rate is the tension error
    over the line's axial stiffness and the time constant, rate = (T - T_set) L / (EA tau), so the
    body descends at the speed where its drag and the line's take up part of the 2 kN and the rest is
    the error that drives the winch."""
    tau = 0.05
    cable = make_cable(parameters={**HANGING, "winchMode": 2, "winch.timeConstant": tau})
    cable.initialize()
    static, EA = cable.get("towTension"), cable.get("EA")
    T, L = fly_still(cable, 60.0, static - 2000.0)
    assert np.all(np.diff(L) > 0.0)
    assert np.all(T > static - 2000.0)  # paying out all along, above the set tension
    rate = np.diff(L[-3:]) / STEP  # settled: the rate over the last steps
    expected = (T[-2:] - (static - 2000.0)) * L[-2:] / (EA * tau)
    assert rate == pytest.approx(expected, rel=0.02)


def fly_still(cable, duration, set_tension, t0=0.0):
    n = int(round(duration / STEP))
    T, L = np.empty(n), np.empty(n)
    for k in range(n):
        cable.set({"winch.tension": set_tension})
        cable.do_step(STEP, t0 + k * STEP)
        T[k], L[k] = cable.get("towTension"), cable.get("unstretchedLength")
    return T, L


def test_constant_tension_state_across_a_split_continues_bit_identically(make_cable):
    """The constant-tension winch's unknowns are part of the state: saved before the winch has paid out
    past a split, restored (in memory and serialized, in the same and in a fresh instance), the run
    repeats itself bit for bit."""
    cable = make_cable(parameters={**HANGING, "winchMode": 2, "winch.timeConstant": 0.002})
    cable.initialize()
    target = cable.get("towTension") - 3000.0
    fly_still(cable, 2.0, target)
    state = cable.get_state()
    first, L = fly_still(cable, 30.0, target, t0=2.0)
    assert L[-1] - L[0] > 8.0  # past a split of the 14.3 m top element (at 21.4 m)
    cable.set_state(state)
    again, _ = fly_still(cable, 30.0, target, t0=2.0)
    assert np.array_equal(first, again)
    cable.set_state(cable.deserialize_state(cable.serialize_state(state)))
    serialized, _ = fly_still(cable, 30.0, target, t0=2.0)
    assert np.array_equal(first, serialized)
    fresh = make_cable(parameters={**HANGING, "winchMode": 2, "winch.timeConstant": 0.002})
    fresh.initialize()
    fresh.set_state(fresh.deserialize_state(cable.serialize_state(state)))
    restored, _ = fly_still(fresh, 30.0, target, t0=2.0)
    assert np.array_equal(first, restored)


def test_a_fast_winch_on_a_fine_mesh_remeshes_many_elements_per_step(make_cable):
    """1 m elements and a winch at 10 m/s with 2 s communication steps: 20 elements paid out per step,
    then hauled in to the limit (a top element that the step would haul in below a quarter of an
    element is merged first, so it never runs out), then paid out again."""
    cable = make_cable(parameters={"length": 20.0, "nElements": 20, "bottomEnd": 2, "body.mass": 400.0,
                                   "body.volume": 0.1, "body.CdA": 0.3, "winchMode": 1, "winch.minLength": 5.0,
                                   "winch.maxLength": 200.0, "winch.maxRate": 20.0,
                                   "winch.maxAcceleration": 0.0}, logging_on=True)
    cable.initialize()
    t = 0.0
    for rate, h, n, length in ((10.0, 2.0, 5, 120.0), (-10.0, 2.0, 10, 5.0), (3.0, 0.5, 10, 20.0)):
        for _ in range(n):
            cable.set({"winch.rate": rate})
            cable.do_step(h, t)
            t += h
        assert cable.get("unstretchedLength") == pytest.approx(length, abs=1e-9)
        assert math.isfinite(cable.get("towTension")) and cable.get("towTension") > 0.0
    assert any("reaches winch.minLength" in m for _, _, m in cable.messages), cable.log_text()


@pytest.mark.parametrize("rate", [0.5, -0.5], ids=["split", "merge"])
def test_state_saved_where_the_next_step_remeshes_continues_exactly(make_cable, rate):
    """Saved at the communication point whose next step splits (pay-out at 0.5 m/s: the 14.3 m top
    element passes 21.4 m at 14.3 s) or merges (haul-in: it passes 7.1 m at 14.3 s), the run
    continues bit for bit in the same instance and in a fresh one: the remesh uses nothing but
    the saved state."""
    t_save = 14.5
    cable = winch_cable(make_cable, 100.0)
    start(cable)
    fly(cable, 0.0, t_save, rate)
    state = cable.serialize_state(cable.get_state())
    first, L = fly(cable, t_save, 5.0, rate)
    cable.set_state(cable.deserialize_state(state))
    again, _ = fly(cable, t_save, 5.0, rate)
    assert np.array_equal(first, again)
    fresh = winch_cable(make_cable, 100.0)  # a fresh instance with a history of its own: at rest
    fresh.initialize(inputs={"winch.rate": 0.0})
    fresh.set_state(fresh.deserialize_state(state))
    restored, _ = fly(fresh, t_save, 5.0, rate)
    assert np.array_equal(first, restored), (first[:3], restored[:3])


def test_constant_tension_winch_never_pays_out_a_compressed_line(make_cable):
    """The winch controls the tension along the line at the tow point (signed, the station tension
    `tension[1]`), not the size of the tow force: under an 8 m heave at 8 s the 2 t body cannot follow
    the sheave down and the top of the line is pushed; in none of those samples may the winch pay out
    (with the size of the force, a compressed line read as an overload and was paid out; docs/winch.md,
    "Constant tension")."""
    params = {**HANGING, "length": 100.0, "nElements": 7, "winch.minLength": 20.0, "winch.maxRate": 5.0}
    fixed = make_cable(parameters=params)
    fixed.initialize()
    static = fixed.get("towTension")
    cable = make_cable(parameters={**params, "winchMode": 2, "winch.timeConstant": 0.05})
    cable.initialize(inputs={"winch.tension": static})
    w = 2 * math.pi / PERIOD
    T, L = [], [cable.get("unstretchedLength")]
    for k in range(int(round(60.0 / H))):
        t = k * H
        cable.set({"tow.z": 8.0 * math.sin(w * t), "tow.vz": 8.0 * w * math.cos(w * t)})
        cable.set_input_derivatives(["tow.vz"], 1, [-8.0 * w * w * math.sin(w * t)])
        cable.do_step(H, t)
        T.append(cable.get("tension[1]"))
        L.append(cable.get("unstretchedLength"))
    T, paid = np.array(T), np.diff(L)
    compressed = T < 0.0
    assert compressed.sum() > 50, "the scene must compress the line's top"
    assert np.all(paid[compressed] <= 1e-9), f"paid out in {np.sum(paid[compressed] > 1e-9)} compressed samples"
    assert np.ptp(L) < 10.0  # it follows the heave, it does not run away


def limit_scene(make_cable, max_acceleration):
    """Pay-out at 1 m/s (winch.maxRate) from 100 m towards winch.maxLength 120 m, 0.5 s steps: the
    tow tension (max over each step) and the deployed length."""
    cable = winch_cable(make_cable, 100.0, max_length=120.0, logging_on=True,
                        parameters_extra={"winch.maxAcceleration": max_acceleration})
    start(cable)
    Tmax, L = [], []
    for k in range(80):
        t = k * STEP
        cable.set({"tow.x": SPEED * t, "tow.vx": SPEED, "winch.rate": 1.0})
        cable.do_step(STEP, t)
        Tmax.append(cable.get("towTensionMax"))
        L.append(cable.get("unstretchedLength"))
    return np.array(Tmax), np.array(L), cable


def test_winch_drum_with_an_acceleration_limit_brakes_to_stop_at_the_length_limit(make_cable):
    """winch.maxAcceleration A: the drum ramps to the requested 1 m/s and brakes at A so that it stops
    exactly at winch.maxLength; the rate never changes by more than A h over a step. Without the
    limit the drum stops from 1 m/s within one step and the line snaps the towed body to a halt."""
    A = 0.1
    Tmax, L, cable = limit_scene(make_cable, A)
    settled = Tmax[-1]
    rate = np.diff(np.concatenate([[100.0], L])) / STEP  # mean rate over each step
    assert L[-1] == pytest.approx(120.0, abs=1e-6)
    assert np.all(L <= 120.0 + 1e-6)
    assert np.max(np.abs(np.diff(rate))) <= A * STEP * (1 + 1e-9) + 1e-12
    assert any("brakes to stop at winch.maxLength" in m for _, _, m in cable.messages), cable.log_text()
    # braking at A, the line and the body (m L + mass + added mass = 824 kg) need (824 kg) A = 82 N
    # more than settled, 1.6 %, and their drag changes with their speed through the water by less than
    # the pay-out's own effect on the tension (docs/winch.md, "Measured"): well within 20 %; a drum
    # stopped within one step stops the line at once and snaps the tension to several times the
    # settled one (docs/winch.md, "The drum")
    assert Tmax.max() < 1.2 * settled, (Tmax.max(), settled)
    hard, L_hard, _ = limit_scene(make_cable, 0.0)
    assert L_hard[-1] == pytest.approx(120.0, abs=1e-9)
    assert hard.max() > 5.0 * settled


def test_constant_tension_winch_brakes_within_the_drum_envelope_at_the_length_limit(make_cable):
    """Held 5 kN below the hanging weight, the constant-tension winch lowers the 2 t body into
    winch.maxLength 205 m. With winch.maxAcceleration its command stays within the braking envelope
    c^2 = 2 A d: it slows down before the limit and stops there (past it only by what the drum's lag
    tau lets through, millimetres), and the tension stays nearer the static one than when the
    command drops to 0 at the limit."""
    fixed = make_cable(parameters=HANGING)
    fixed.initialize()
    static = fixed.get("towTension")
    runs = {}
    for A in (0.0, 0.2):
        cable = make_cable(parameters={**HANGING, "winchMode": 2, "winch.timeConstant": 0.05,
                                       "winch.maxLength": 205.0, "winch.maxAcceleration": A})
        cable.initialize(inputs={"winch.tension": static - 5000.0})
        runs[A] = fly_still(cable, 40.0, static - 5000.0)
    T, L = runs[0.2]
    assert L[-1] == pytest.approx(205.0, abs=0.01)
    assert L.max() <= 205.0 + 0.01
    # the largest tension sampled: braking along the envelope against stopping at the limit
    assert np.max(T) < np.max(runs[0.0][0])


def test_min_tension_sees_the_top_elements_material_motion(make_cable):
    """minTension (element means and node reactions) reads the top element with the velocities its
    forces see, the material's: hauling in at 0.5 m/s the line below the sheave is in tension all
    along, and the smallest tension is at the towed body (the tension grows towards the sheave).
    With the sheave's velocity the top element's damping read a strain rate of -c / l1, tens of kN."""
    cable = winch_cable(make_cable, 300.0)
    start(cable)
    for t in np.arange(0.0, 30.0, STEP):
        cable.set({"tow.x": SPEED * t, "tow.vx": SPEED, "winch.rate": -0.5})
        cable.do_step(STEP, t)
        end = cable.get("endTension")
        assert cable.get("minTension") == pytest.approx(end, rel=0.01), (t, cable.get("minTension"), end)
