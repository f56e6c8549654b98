"""Winch commands against the communication step (docs/winch.md, "Ramps and the communication step").

A ramped winch command reaches the drum as a ramp: the rate goes with its input derivative (the scene
runner passes the table's slope), and a rate held over a step reaches the drum through its finite
default acceleration. Acceptance: the tow job's towTensionMax within 1 % of a 0.05 s run at 0.1, 0.5
and 1 s steps; on a ramped pay-out at 0.5 s, each step's towTensionMax and towTensionMin within 0.5 %
of the tension sampled every 0.01 s. Limits the winch reaches are printed by `ucable run` with their
time and value.
"""

import numpy as np
import pytest

from ucable import cli
from ucable.scene import load_scene
from ucable.units import KNOT
from ucable.scene import run_scene
from studies.cases.winch_steps import extremes, payout, quick_tow_job, step_errors


@pytest.fixture(scope="module")
def tow_job_reference(fmu_file):
    return extremes(quick_tow_job(0.05), fmu=fmu_file)


@pytest.mark.parametrize("step", [0.1, 0.5, 1.0])
def test_tow_job_peak_tension_does_not_depend_on_the_step(fmu_file, tow_job_reference, step):
    """Hauling in 600 m with a 2 t towfish at 3 kn, the rate ramped 0 -> -0.5 m/s in 10 s and back: the
    largest tow tension at `step` within 1 % of the 0.05 s run's (with the rate held over each step and
    no drum acceleration limit it was 3-70 % above it, docs/winch.md)."""
    ref_max, ref_min, _ = tow_job_reference
    tmax, tmin, _ = extremes(quick_tow_job(step), fmu=fmu_file)
    assert tmax == pytest.approx(ref_max, rel=0.01), (step, tmax, ref_max)
    assert tmin == pytest.approx(ref_min, rel=0.01), (step, tmin, ref_min)


def test_the_recover_scene_start_does_not_depend_on_the_step(fmu_file):
    """The shipped recover scene's first 30 s (the haul-in ramped from rest to 0.5 m/s in 10 s): the
    extremes at 1 s steps within 1 % of the 0.05 s run's (the rate held over each step without a drum
    limit: +22 % / -64 % over the whole scene, docs/winch.md)."""
    recover = load_scene("recover").data
    ref = extremes({**recover, "duration": 30.0, "step": 0.05}, fmu=fmu_file)
    tmax, tmin, _ = extremes({**recover, "duration": 30.0, "step": 1.0}, fmu=fmu_file)
    assert tmax == pytest.approx(ref[0], rel=0.01) and tmin == pytest.approx(ref[1], rel=0.01), (tmax, tmin, ref)


def test_a_ramped_payout_onto_the_length_limit_follows_the_table_to_the_limit(fmu_file):
    """Paid out 0 -> 0.5 m/s in 4 s, 6 s at 0.5 m/s and back to rest in 4 s: 5 m, onto winch.maxLength
    105 m. The deployed length is the table's integral at every communication point, to the limit: the
    drum follows the ramp down onto it (it does not brake early along its envelope and stop short)."""
    d = payout(0.5, 24.0, {"winch.maxLength": 105.0})
    d["winch"] = {"ramp": 4.0, "stages": [{"rate": 0.5, "duration": 10.0}, {"rate": 0.0, "duration": 14.0}]}
    r = run_scene(d, fmu=fmu_file)
    table = r.scene.winch["table"]
    fine = np.linspace(0.0, 24.0, 24001)
    rate = np.interp(fine, table["times"], table["values"])
    paid = np.concatenate([[0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(fine))])
    np.testing.assert_allclose(r["unstretchedLength"], 100.0 + np.interp(r.time, fine, paid), rtol=0, atol=1e-6)
    assert r["unstretchedLength"][-1] == pytest.approx(105.0, abs=1e-9)


def test_ramped_payout_extremes_within_each_step_match_the_tension_sampled_at_10_ms(fmu_file):
    """The deploy body on 100 m at 2 kn, paid out 0 -> 0.5 m/s in 10 s: each 0.5 s step's towTensionMax
    and towTensionMin within 0.5 % of the largest and smallest tension a 0.01 s master samples in it
    (the drum's staircase made the smallest 1616 N against 4470 N sampled)."""
    dmax, dmin, coarse, fine = step_errors(0.5, 0.01, duration=15.0, fmu=fmu_file)
    assert dmax < 0.005, (dmax, coarse, fine)
    assert dmin < 0.005, (dmin, coarse, fine)


def winch_fmu(make_cable, **extra):
    params = {"length": 100.0, "nElements": 7, "bottomEnd": 2, "body.mass": 400.0, "body.volume": 0.1,
              "body.CdA": 0.3, "winchMode": 1, "winch.minLength": 50.0, "winch.maxLength": 300.0,
              "winch.maxRate": 1.0, **extra}
    c = make_cable(parameters=params)
    c.initialize(inputs={"tow.vx": 2.0 * KNOT, "winch.rate": 0.0})
    return c


def drive(c, h, n, rate, slope=None):
    """n steps of h at the command rate(t) (with its derivative `slope` when given); the lengths."""
    L = []
    for k in range(n):
        t = k * h
        c.set({"tow.x": 2.0 * KNOT * t, "tow.vx": 2.0 * KNOT, "winch.rate": rate(t)})
        if slope is not None:
            c.set_input_derivatives(["winch.rate"], 1, [slope])
        c.do_step(h, t)
        L.append(c.get("unstretchedLength"))
    return np.array(L)


def test_a_rate_with_its_derivative_is_followed_between_communication_points(make_cable):
    """winch.rate 0.05 t with the input derivative 0.05 m/s2: the deployed length is the ramp's
    integral, 100 + 0.025 t^2, at every communication point (the drum follows the command); held
    over each step, the drum runs behind it."""
    c = winch_fmu(make_cable)
    L = drive(c, 0.5, 20, lambda t: 0.05 * t, slope=0.05)
    t = 0.5 * np.arange(1, 21)
    np.testing.assert_allclose(L, 100.0 + 0.025 * t ** 2, rtol=0, atol=1e-9)
    held = drive(winch_fmu(make_cable), 0.5, 20, lambda t: 0.05 * t)
    assert np.max(np.abs(held - (100.0 + 0.025 * t ** 2))) > 0.01


def test_the_drum_has_a_finite_acceleration_by_default(make_cable):
    """winch.maxAcceleration defaults to 0.2 m/s2: a rate of 0.5 m/s set at once is reached after
    2.5 s, so the first second pays out 0.1 m (0.5 m at once without the limit)."""
    c = winch_fmu(make_cable)
    assert c.get("winch.maxAcceleration") == pytest.approx(0.2)
    L = drive(c, 0.5, 2, lambda t: 0.5)
    assert L[-1] - 100.0 == pytest.approx(0.5 * 0.2 * 1.0 ** 2, abs=1e-9)
    hard = drive(winch_fmu(make_cable, **{"winch.maxAcceleration": 0.0}), 0.5, 2, lambda t: 0.5)
    assert hard[-1] - 100.0 == pytest.approx(0.5, abs=1e-9)


def limit_scene(tmp_path, stages, extra=""):
    path = tmp_path / "limits.toml"
    path.write_text(f"""title = "winch limits"
duration = 30.0
step = 0.5
record_shape = false
[parameters]
length = 100.0
nElements = 7
bottomEnd = 2
"body.mass" = 400.0
"body.volume" = 0.1
"body.CdA" = 0.3
"winch.minLength" = 95.0
"winch.maxLength" = 104.0
"winch.maxRate" = 0.8
{extra}
[tow]
speed_kn = 2.0
[winch]
ramp = 2.0
stages = {stages}
""")
    return path


def test_run_prints_the_limits_the_winch_reaches(fmu_file, tmp_path, capsys):
    """A pay-out asked at 1 m/s (above winch.maxRate 0.8) into winch.maxLength 104 m: `ucable run`
    prints both, with the time and the value."""
    scene = limit_scene(tmp_path, '[ { rate = 1.0, duration = 30.0 } ]')
    assert cli.main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    out = capsys.readouterr().out
    lines = [line for line in out.splitlines() if line.startswith("winch: at t = ")]
    assert any("winch.maxRate = 0.8 m/s" in line for line in lines), out
    assert any("brakes to stop at winch.maxLength = 104 m" in line for line in lines), out
    assert any("the drum stops at winch.maxLength = 104 m" in line for line in lines), out
    scene = limit_scene(tmp_path, '[ { rate = -0.5, duration = 30.0 } ]')
    assert cli.main(["run", str(scene), "--out", str(tmp_path / "out2")]) == 0
    out = capsys.readouterr().out
    assert any(line.startswith("winch: at t = ") and "winch.minLength = 95 m" in line
               for line in out.splitlines()), out
