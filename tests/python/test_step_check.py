"""A communication step too long for the scene is warned of, and refused with --strict (exit code 2):
`ucable run`, `ucable sweep` (docs/scenes.md, "A step short enough for the scene") and `ucable system`
beyond the steps a system's accuracy is documented for (docs/systems.md)."""

import pytest

from ucable import cli
from ucable.scene import load_scene
from ucable.step_check import scene_periods, step_warnings, system_step_warnings

SURGING = """title = "a tow point surging with a 12 s period"
duration = 20.0
step = {step}
record_shape = false
[parameters]
length = 100.0
nElements = 5
[tow]
speed_kn = 2.0
surge = {{ amplitude = 2.0, period = 12.0, direction = [1.0, 0.0, 0.0] }}
"""


def surging(tmp_path, step):
    path = tmp_path / f"surge_{step}.toml"
    path.write_text(SURGING.format(step=step))
    return path


def test_the_periods_and_ramps_of_a_scene_are_found():
    s = load_scene("deploy")
    periods = scene_periods(s)
    assert (10.0, "[winch] stages (winch.rate): the ramp from 0 s to 10 s") in periods
    assert min(t for t, _ in periods) == 10.0
    waves = load_scene("lowering_in_waves")
    assert any(what == "[parameters] waves.period" and t == 10.0 for t, what in scene_periods(waves))
    assert any(what == "[tow] heave.period" for _, what in scene_periods(waves))
    # a jump (two entries at one time) and a table segment that holds its value are no ramps
    jump = load_scene({"duration": 100.0, "step": 1.0, "tow": {"speed_kn": 2.0},
                       "inputs": {"current.x": {"times": [0.0, 50.0, 50.0, 100.0], "values": [0.0, 0.0, 0.5, 0.5]}}})
    assert scene_periods(jump) == []


def test_shipped_scenes_are_not_warned():
    for name in ("deploy", "recover", "turn90", "lowering_in_waves", "ct_lowering", "hopland_accelerate"):
        assert step_warnings(load_scene(name)) == [], name


def test_a_step_longer_than_a_tenth_of_a_period_is_warned():
    s = load_scene("deploy").with_overrides({"step": 10.0})
    (w,) = step_warnings(s)
    assert "step = 10 s" in w and "[winch] stages" in w and "use step <= 1 s" in w
    assert step_warnings(load_scene("deploy").with_overrides({"step": 1.0})) == []


def test_run_warns_of_a_surge_step_too_long_and_strict_refuses_it(fmu_file, tmp_path, capsys):
    scene = surging(tmp_path, 10.0)
    assert cli.main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    err = capsys.readouterr().err
    assert "warning" in err and "[tow] surge.period (12 s)" in err and "use step <= 1.2 s" in err, err
    assert cli.main(["run", str(scene), "--strict", "--out", str(tmp_path / "out2")]) == cli.EXIT_USAGE
    err = capsys.readouterr().err
    assert "refused: --strict" in err, err
    assert not (tmp_path / "out2" / "result.csv").exists()
    assert cli.main(["run", str(surging(tmp_path, 1.0)), "--strict", "--set", "duration=2",
                     "--out", str(tmp_path / "out3")]) == 0
    assert "warning" not in capsys.readouterr().err


def test_run_of_the_winch_ramps_at_a_10_s_step_is_refused_with_strict(tmp_path, capsys):
    assert cli.main(["run", "deploy", "--set", "step=10", "--strict", "--out", str(tmp_path)]) == cli.EXIT_USAGE
    assert "[winch] stages" in capsys.readouterr().err


def test_sweep_warns_of_a_combination_with_a_step_too_long(tmp_path, capsys):
    code = cli.main(["sweep", "deploy", "--vary", "step=0.5,10", "--strict", "--out", str(tmp_path)])
    assert code == cli.EXIT_USAGE
    assert "step = 10 s" in capsys.readouterr().err


def test_systems_say_when_the_step_is_beyond_their_documented_accuracy(capsys):
    assert system_step_warnings("heave_lowering", "fmpy", None) == []
    (w,) = system_step_warnings("heave_lowering", "fmpy", 1.0)
    assert "waves.period = 9 s" in w and "0.9" in w
    assert system_step_warnings("towed_body", "fmpy", 1.0) == []
    assert system_step_warnings("towed_body", "fmpy", 2.0) != []
    assert system_step_warnings("towed_body_explicit", "newton", 0.5) == []
    assert system_step_warnings("towed_body_explicit", "fmpy", 0.5) != []
    assert cli.main(["system", "moored_platform", "--step", "1", "--strict"]) == cli.EXIT_USAGE
    assert "moored_platform" in capsys.readouterr().err
