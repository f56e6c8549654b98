"""The scene format: a mistake is one line naming the file and the key (with "did you mean"), exit
code 2, no traceback (--debug shows it); time-varying inputs { times, values }, winch stages, motions
that start from rest; the shape recorded by default; `ucable scenes show`, `ucable --version`."""

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import ucable
from ucable.cli import main
from ucable.scene import TowMotion, load_scene, run_scene
from ucable.scene_schema import SceneFileError, validate
from ucable.units import KNOT
from ucable.variables import NUM_STATIONS

ROOT = Path(__file__).resolve().parents[2]
HEAD = 'title = "t"\nduration = 4.0\nstep = 0.5\n'

# (scene text after HEAD, the key the one-line message must name, a word it must say)
MISTAKES = [
    ("[tow]\nspeed = 2.0\n", "[tow] speed", "did you mean 'speed_kn'?"),
    ("[tow]\nspeed_kn = { times = [0.0, 10.0], values = [1.0] }\n", "[tow] speed_kn", "values 1"),
    ("[tow]\nspeed_kn = \"fast\"\n", "[tow] speed_kn", "expected a number"),
    ("[tow]\nsurge = { amplitude = 1.0 }\n", "[tow] surge.period", "missing"),
    ("[tow]\nheading_deg = { times = [10.0, 0.0], values = [0.0, 90.0] }\n", "[tow] heading_deg.times", "decrease"),
    ("[parameters]\nnElements = 2.5\n", "[parameters] nElements", "expected an integer"),
    ("[parameters]\nlenght = 200.0\n", "[parameters] lenght", "did you mean 'length'?"),
    ("[parameters]\nCdn = -1.0\n", "[parameters] Cdn", "outside [0, 100]"),
    ("[parameters]\nenableSeabed = 2\n", "[parameters] enableSeabed", "true or false"),
    ("[parameters]\n\"current.x\" = 0.5\n", "[parameters] current.x", "give it in [inputs]"),
    ("[inputs]\n\"curent.x\" = 0.5\n", "[inputs] curent.x", "did you mean 'current.x'?"),
    ("[inputs]\n\"tow.x\" = 0.5\n", "[inputs] tow.x", "[tow]"),
    ("[inputs]\n\"current.x\" = { times = [0.0], value = [0.5] }\n", "[inputs] current.x.value",
     "did you mean 'values'?"),
    ("dration = 3.0\n", "dration", "did you mean 'duration'?"),
    ("outputs = [\"towTensoin\"]\n", "outputs[1]", "did you mean 'towTension'?"),
    ("[winch]\nstages = [ { rate = 0.5 } ]\n", "[winch] stages[1].duration", "missing"),
    ("[winch]\nstages = [ { rate = 0.5, duration = 20.0 }, { tension = 1e4, duration = 20.0 } ]\n",
     "[winch] stages[2]", "winch mode"),
]


def write(tmp_path, text, name="s.toml"):
    path = tmp_path / name
    path.write_text(HEAD + text)
    return path


@pytest.mark.parametrize("text, key, says", MISTAKES, ids=[m[1] for m in MISTAKES])
def test_a_scene_mistake_is_one_line_naming_file_and_key_exit_2(tmp_path, capsys, text, key, says):
    path = write(tmp_path, text)
    assert main(["run", str(path), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith(f"ucable: {path}: {key}: "), err
    assert says in err and "\n" not in err, err
    assert not (tmp_path / "o").exists()  # nothing ran


def test_toml_syntax_error_names_the_file_and_line(tmp_path, capsys):
    path = write(tmp_path, "[tow\nspeed_kn = 1.0\n")
    assert main(["run", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith(f"ucable: {path}: not valid TOML") and "line 4" in err and "\n" not in err


@pytest.mark.parametrize("args, says", [
    (["--set", "nElements=2.5"], "ucable: --set nElements: expected an integer, got 2.5"),
    (["--set", "lenght=2"], "ucable: --set lenght: unknown parameter; did you mean 'length'?"),
    (["--set", "duration=-1"], "ucable: --set duration: must be positive, got -1"),
    (["--set", "length"], "ucable: --set 'length': expected NAME=VALUE"),
])
def test_command_line_mistakes_exit_2(capsys, args, says):
    assert main(["run", "hopland_accelerate", *args]) == 2
    assert capsys.readouterr().err.strip() == says


def test_unknown_scene_names_the_shipped_ones(capsys):
    assert main(["run", "turn9O"]) == 2
    err = capsys.readouterr().err
    assert "no scene 'turn9O'" in err and "turn90" in err


def test_the_process_prints_no_traceback_and_debug_shows_it(tmp_path, fmu_file):
    path = write(tmp_path, "[parameters]\nnElements = 2.5\n")
    env = {"PYTHONPATH": str(ROOT / "python"), "UC_FMU": str(fmu_file)}
    p = subprocess.run([sys.executable, "-m", "ucable.cli", "run", str(path)], capture_output=True, text=True, env=env)
    assert p.returncode == 2 and p.stderr.count("\n") == 1 and "Traceback" not in p.stderr, p.stderr
    q = subprocess.run([sys.executable, "-m", "ucable.cli", "--debug", "run", str(path)], capture_output=True,
                       text=True, env=env)
    assert q.returncode != 0 and "Traceback" in q.stderr and "SceneFileError" in q.stderr


def test_a_parameter_the_fmu_refuses_is_a_scene_mistake(tmp_path, capsys, fmu_file):
    # length 0 is inside the schema's range [0, 1e5]; the FMU's own check refuses it: one line, exit 2
    path = write(tmp_path, "[parameters]\nlength = 0.0\n")
    assert main(["run", str(path), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith(f"ucable: {path}: invalid parameter: length = 0") and "\n" not in err, err
    assert err.count("fmi2") == 0  # the FMI function names are not repeated at the user


def test_a_start_the_fmu_refuses_is_one_line_exit_2(tmp_path, capsys, fmu_file):
    """Not a key's mistake but a state the FMU cannot start from (the tow point below the seabed): a
    mistake in the scene all the same, its message, one line, exit code 2."""
    path = write(tmp_path, "[parameters]\nenableSeabed = true\nwaterDepth = 100.0\n[tow]\nstart = [0.0, 0.0, -150.0]\n")
    assert main(["run", str(path), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith(f"ucable: {path}: the FMU could not start: ") and "below the seabed" in err, err
    assert "\n" not in err


def test_every_shipped_scene_is_valid():
    for path in ucable.scenes_dir().glob("*.toml"):
        load_scene(path)


def test_integers_written_as_whole_floats_are_accepted():
    s = validate({"duration": 1.0, "step": 0.5, "parameters": {"nElements": 12.0}}, "x")
    assert s["parameters"]["nElements"] == 12 and isinstance(s["parameters"]["nElements"], int)
    with pytest.raises(SceneFileError, match="nElements: expected an integer, got 12.5"):
        validate({"duration": 1.0, "step": 0.5, "parameters": {"nElements": 12.5}}, "x")


def test_winch_stages_become_a_piecewise_linear_rate_from_rest():
    s = validate({"duration": 100.0, "step": 0.5, "winch": {"ramp": 5.0, "stages": [
        {"rate": 0.5, "duration": 40.0}, {"rate": 0.0, "duration": 20.0}, {"rate": -0.2, "duration": 30.0, "ramp": 0.0}]}},
        "x")
    w = s["winch"]
    assert w["input"] == "winch.rate" and w["mode"] == 1
    assert w["table"] == {"times": [0.0, 5.0, 40.0, 45.0, 60.0, 60.0, 90.0],
                          "values": [0.0, 0.5, 0.5, 0.0, 0.0, -0.2, -0.2]}


def test_motions_start_from_rest_and_reach_their_amplitude():
    tow = validate({"duration": 60.0, "step": 0.1, "tow": {"surge": {"amplitude": 5.0, "period": 10.0}}}, "x")["tow"]
    m = TowMotion(tow, 60.0, 0.1)
    x, v, a = m.at(0.0)
    assert np.allclose([x[0], v[0], a[0]], 0.0, atol=1e-12)
    # past the ramp (one period) it is the oscillation itself: x = A sin(w t), v = A w cos(w t)
    w = 2 * math.pi / 10.0
    x, v, a = m.at(32.5)
    assert x[0] == pytest.approx(5.0 * math.sin(w * 32.5), abs=1e-9)
    assert v[0] == pytest.approx(5.0 * w * math.cos(w * 32.5), abs=1e-9)
    assert a[0] == pytest.approx(-5.0 * w * w * math.sin(w * 32.5), abs=1e-9)
    # the ramp's velocity is the derivative of its position (centred differences on the fine grid)
    dt = m.t[1] - m.t[0]
    vx = np.gradient(m.x[:, 0], dt)
    assert np.max(np.abs(vx[1:-1] - m.v[1:-1, 0])) < (w ** 3) * 5.0 * dt * dt  # O(dt^2) of the difference
    # heave is the same along z
    tow = validate({"duration": 20.0, "step": 0.1, "tow": {"heave": {"amplitude": 1.5, "period": 8.0}}}, "x")["tow"]
    x, v, _ = TowMotion(tow, 20.0, 0.1).at(0.0)
    assert np.allclose([x[2], v[2]], 0.0)


def test_constant_speed_and_heading_are_accepted():
    tow = validate({"duration": 10.0, "step": 0.5, "tow": {"speed_kn": 2.0, "heading_deg": 90.0}}, "x")["tow"]
    x, v, _ = TowMotion(tow, 10.0, 0.5).at(10.0)
    assert v[1] == pytest.approx(2.0 * KNOT) and abs(v[0]) < 1e-12 and x[1] == pytest.approx(20.0 * KNOT)


def read_rows(path):
    return ucable.read_results(path).records()


def test_time_varying_current_and_winch_reach_the_fmu(tmp_path, fmu_file):
    """A current ramped from 0 to 0.4 m/s pushes the hanging far end downstream against the same
    scene in still water; a winch paying out 0.5 m/s after a 4 s ramp lengthens the cable by the
    table's integral (the FMU holds each step's starting rate: within step x jump / 2)."""
    base = {"name": "w", "duration": 20.0, "step": 0.5,
            "parameters": {"bottomEnd": 2, "body.mass": 400.0, "body.volume": 0.1, "length": 100.0,
                           "nElements": 8, "initialDirection.x": 0.0, "initialDirection.z": -1.0}}
    still = run_scene(base, fmu=fmu_file)
    current = run_scene({**base, "inputs": {"current.x": {"times": [0.0, 10.0], "values": [0.0, 0.4]}}}, fmu=fmu_file)
    assert still["endPosition.x"][-1] == pytest.approx(0.0, abs=1e-3)
    assert current["endPosition.x"][-1] > 1.0  # downstream, well beyond the still run's 1e-3 m
    assert current["endPosition.x"][2] < 0.1 * current["endPosition.x"][-1]  # the current grows in time
    winch = {**base, "parameters": {**base["parameters"], "winch.timeConstant": 0.001, "winch.maxRate": 2.0},
             "winch": {"ramp": 4.0, "stages": [{"rate": 0.5, "duration": 20.0}]}}
    L = run_scene(winch, fmu=fmu_file)["unstretchedLength"]
    expected = 0.5 * (20.0 - 4.0) + 0.5 * 4.0 / 2.0  # the table's integral
    # held over each 0.5 s step of the 4 s ramp, the rate is (0.5 / 4) * 0.5 / 2 below its mean
    hold = (0.5 / 4.0) * (0.5 / 2.0) * 4.0
    assert L[0] == pytest.approx(100.0)
    assert L[-1] - L[0] == pytest.approx(expected, abs=hold + 1e-3)


def test_result_csv_holds_the_shape_by_default(tmp_path, fmu_file, capsys):
    out = tmp_path / "o"
    assert main(["run", "chain_mooring", "--set", "duration=1", "--out", str(out)]) == 0
    rows = read_rows(out / "result.csv")
    names = set(rows[0])
    for c in "xyz":
        assert {f"shape.{c}[{k}]" for k in range(1, NUM_STATIONS + 1)} <= names
    # station 1 is the tow point (the fairlead), the last the anchor of chain_mooring
    r = rows[-1]
    assert float(r["shape.z[1]"]) == pytest.approx(float(r["tow.z"]), abs=1e-6)
    assert float(r[f"shape.x[{NUM_STATIONS}]"]) == pytest.approx(-850.0, abs=1e-6)
    assert {"endTension", "groundedLength"} <= names  # the anchored scene's quantities
    assert (out / "result.png").stat().st_size > 0
    out2 = tmp_path / "p"
    assert main(["run", "chain_mooring", "--set", "duration=1", "--set", "record_shape=false", "--out", str(out2)]) == 0
    assert "shape.x[1]" not in read_rows(out2 / "result.csv")[0]


def test_animate_writes_a_gif(tmp_path, fmu_file):
    out = tmp_path / "o"
    assert main(["run", "turn90", "--set", "duration=2", "--out", str(out), "--animate"]) == 0
    assert (out / "result.gif").read_bytes()[:6] in (b"GIF89a", b"GIF87a")


def test_scenes_show_prints_a_scene_that_runs_as_a_file(tmp_path, capsys, fmu_file):
    assert main(["scenes", "show", "turn90"]) == 0
    text = capsys.readouterr().out
    assert text == (ucable.scenes_dir() / "turn90.toml").read_text()
    path = tmp_path / "my.toml"
    path.write_text(text.replace("duration = 300.0", "duration = 1.0"))
    assert main(["run", str(path), "--out", str(tmp_path / "d")]) == 0
    assert main(["scenes", "show", "turn9"]) == 2


def test_version(capsys):
    with pytest.raises(SystemExit) as e:
        main(["--version"])
    assert e.value.code == 0 and capsys.readouterr().out.strip() == f"ucable {ucable.__version__}"
    import tomllib

    with open(ROOT / "pyproject.toml", "rb") as f:
        assert tomllib.load(f)["project"]["version"] == ucable.__version__


@pytest.mark.parametrize("name, length, depth", [("deploy", 300.0, 244.14), ("recover", 100.0, 91.996),
                                                 ("ct_lowering", 250.0, 250.0)])
def test_shipped_winch_scenes_reach_their_target(fmu_file, name, length, depth):
    """deploy/recover: the towed body's steady depth at 2 kn on 300 m (docs/winch.md: 244.14 m) and on
    100 m (the recover scene's own start); 200 s after the winch stops the deploy is still settling
    (docs/winch.md: 0.7 m off after 600 s), hence 3 %. ct_lowering hangs the body below the top."""
    r = run_scene(name, fmu=fmu_file)
    L = r["unstretchedLength"]
    assert L[-1] == pytest.approx(length, abs=1.0)
    assert -r["endPosition.z"][-1] == pytest.approx(depth, rel=0.03)
    assert r.scene.kind == "winch"


def test_scenes_format_prints_the_reference(capsys):
    assert main(["scenes", "format"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("# Scene format") and "`speed_kn`" in out


@pytest.mark.parametrize("name", ["towed_body", "heave_lowering"])
def test_system_runs_a_shipped_system(tmp_path, fmu_file, name):
    out = tmp_path / "sys"
    assert main(["system", name, "--duration", "2", "--out", str(out)]) == 0
    table = ucable.read_results(out / "result.csv")
    assert table.headers[:5] == ["time [s]", "towTension [N]", "body.x [m]", "body.y [m]", "body.z [m]"]
    rows = table.records()
    assert float(rows[-1]["time"]) == pytest.approx(2.0) and float(rows[-1]["towTension"]) > 0.0
    assert (out / "result.png").stat().st_size > 0


def test_system_unknown_name_exit_2(capsys):
    assert main(["system", "towed_bdy"]) == 2
    assert "did you mean 'towed_body'?" in capsys.readouterr().err
