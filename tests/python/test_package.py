"""The Python package and its command: the API (ucable.fmu_path, run_scene), `ucable run` and a
two-worker `ucable sweep` on a local Dask cluster whose rows equal single runs, a failing
combination kept as a row; and (slow) `pip install .` into a fresh venv used from outside the clone."""

import os
import subprocess
import sys
import venv
from pathlib import Path

import numpy as np
import pytest

import ucable
from ucable.scene import load_scene, run_scene

ROOT = Path(__file__).resolve().parents[2]
SHORT = {"duration": 10.0}


def cli_env(fmu_file):
    env = dict(os.environ, UC_FMU=str(fmu_file))
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT / "python"), env.get("PYTHONPATH", "")])
    return env


def read_csv(path):
    return ucable.read_results(path).records()


def test_api_finds_the_fmu_and_the_scenes(fmu_file):
    assert Path(ucable.fmu_path()).is_file()
    names = {p.stem for p in ucable.scenes_dir().glob("*.toml")}
    assert {"hopland_accelerate", "hopland_decelerate", "turn90", "chain_mooring"} <= names
    for name in names:  # every packaged scene parses
        assert load_scene(name).duration > 0


def test_run_scene_returns_named_outputs(fmu_file):
    r = ucable.run_scene("hopland_accelerate", overrides=SHORT, fmu=fmu_file)
    assert r.time[-1] == pytest.approx(10.0)
    assert len(r["towTension"]) == len(r.time) == 21
    s = r.summary()
    assert s["towTensionMin"] <= s["towTensionFinal"] <= s["towTensionMax"]
    assert np.all(r["towTensionMax"] >= r["towTension"])
    # the tow point flies the scene: 1.1 kn for the first 10 s of the ramp (mean speed 1.21 kn)
    assert r["tow.x"][-1] == pytest.approx(10.0 * 0.5 * (1.1 + 1.1 + 1.3 * 10.0 / 60.0) * 1852 / 3600, rel=1e-6)


def test_overrides_reach_the_fmu_and_bad_ones_are_named(fmu_file):
    short = run_scene("hopland_accelerate", overrides={**SHORT, "length": 200.0}, fmu=fmu_file)
    long = run_scene("hopland_accelerate", overrides=SHORT, fmu=fmu_file)
    assert short["towTension"][0] < long["towTension"][0]  # less cable, less drag and weight
    with pytest.raises(Exception, match="length"):
        run_scene("hopland_accelerate", overrides={**SHORT, "length": -5.0}, fmu=fmu_file)


def test_cli_run_writes_csv_and_plot(fmu_file, tmp_path):
    out = tmp_path / "o"
    p = subprocess.run([sys.executable, "-m", "ucable.cli", "run", "hopland_accelerate", "--set", "duration=5",
                        "--out", str(out)], env=cli_env(fmu_file), capture_output=True, text=True, cwd=tmp_path,
                       timeout=300)
    assert p.returncode == 0, p.stderr
    rows = read_csv(out / "result.csv")
    assert len(rows) == 11 and {"time", "towTension", "towTensionMax", "endPosition.z", "tow.x"} <= set(rows[0])
    assert (out / "result.png").stat().st_size > 0


def test_two_worker_sweep_rows_equal_single_runs(fmu_file, tmp_path):
    out = tmp_path / "s"
    p = subprocess.run([sys.executable, "-m", "ucable.cli", "sweep", "hopland_accelerate", "--vary", "length=200,300,0",
                        "--vary", "Cdn=1.2,1.6", "--set", "duration=5", "--workers", "2", "--out", str(out)],
                       env=cli_env(fmu_file), capture_output=True, text=True, cwd=tmp_path, timeout=600)
    # length 0 is inside the schema's range [0, 1e5] but the FMU refuses it: those two rows fail, the
    # sweep goes on, writes every row, and exits 1 saying how many failed
    assert p.returncode == 1, p.stderr
    assert "2 of 6 runs failed" in p.stderr
    rows = read_csv(out / "results.csv")
    assert [(float(r["length"]), float(r["Cdn"])) for r in rows] == [
        (200.0, 1.2), (200.0, 1.6), (300.0, 1.2), (300.0, 1.6), (0.0, 1.2), (0.0, 1.6)]
    for r in rows:
        if float(r["length"]) == 0.0:
            assert r["status"] == "error" and "length" in r["error"], r
            continue
        assert r["status"] == "ok", r
        single = run_scene("hopland_accelerate", overrides={"duration": 5.0, "length": float(r["length"]),
                                                            "Cdn": float(r["Cdn"])}, fmu=fmu_file).summary()
        for key, value in single.items():
            assert float(r[key]) == pytest.approx(value, rel=1e-9), key  # the CSV keeps 10 digits
    assert (out / "summary.png").stat().st_size > 0


def test_sweep_with_a_value_out_of_range_runs_nothing(fmu_file, tmp_path):
    out = tmp_path / "s"
    p = subprocess.run([sys.executable, "-m", "ucable.cli", "sweep", "hopland_accelerate", "--vary", "Cdn=1.2,-1",
                        "--set", "duration=5", "--out", str(out)],
                       env=cli_env(fmu_file), capture_output=True, text=True, cwd=tmp_path, timeout=600)
    assert p.returncode == 2 and p.stderr.strip() == "ucable: --vary Cdn: -1 is outside [0, 100]", p.stderr
    assert not out.exists()


def test_sweep_in_which_every_run_failed_exits_nonzero(fmu_file, tmp_path):
    p = subprocess.run([sys.executable, "-m", "ucable.cli", "sweep", "hopland_accelerate", "--vary", "length=0",
                        "--set", "duration=2", "--workers", "1", "--out", str(tmp_path / "s")],
                       env=cli_env(fmu_file), capture_output=True, text=True, cwd=tmp_path, timeout=600)
    assert p.returncode == 1 and "1 of 1 runs failed" in p.stderr, p.stderr
    assert "Traceback" not in p.stderr


@pytest.mark.slow
def test_pip_install_runs_from_outside_the_clone(tmp_path):
    """What a new user does: a fresh venv, `pip install` of the clone (builds the FMUs with CMake),
    then the commands from a directory that is not the clone: the version, a shipped system, a
    shipped scene printed, edited and run (the shape in result.csv, result.png written)."""
    env_dir = tmp_path / "v"
    venv.create(env_dir, with_pip=True)
    pip = env_dir / "bin" / "pip"
    p = subprocess.run([str(pip), "install", "-v", str(ROOT)], capture_output=True, text=True, timeout=3000)
    assert p.returncode == 0, p.stdout + p.stderr
    assert "UnderwaterCable: the FMUs (FMI 2.0 and the FMI 3.0 variant) carry" in p.stdout + p.stderr  # CMake says
    py = env_dir / "bin" / "python"
    work = tmp_path / "elsewhere"
    work.mkdir()
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "UC_FMU")}
    q = subprocess.run([str(py), "-c", "import ucable; print(ucable.fmu_path())"], capture_output=True, text=True,
                       cwd=work, env=env)
    assert q.returncode == 0 and "site-packages" in q.stdout, q.stdout + q.stderr
    exe = str(env_dir / "bin" / "ucable")

    def ucable_cli(*args, timeout=600):
        return subprocess.run([exe, *args], capture_output=True, text=True, cwd=work, env=env, timeout=timeout)

    f = ucable_cli("fmu")  # the platforms, after pip hid the build's output; the FMI 3.0 variant installed too
    assert f.returncode == 0 and "site-packages" in f.stdout, f.stderr
    assert f.stderr.startswith("ucable: FMI 2.0: linux64") and "FMI 3.0 variant" in f.stderr, f.stderr
    v = ucable_cli("--version")
    assert v.returncode == 0 and v.stdout.strip() == f"ucable {ucable.__version__}", v.stdout + v.stderr
    y = ucable_cli("system", "towed_body", "--duration", "20", "--out", "sys")
    assert y.returncode == 0, y.stderr
    table = ucable.read_results(work / "sys" / "result.csv")
    assert table.headers[:2] == ["time [s]", "towTension [N]"]
    assert table.rows == 41 and table["towTension"][-1] > 0.0  # 20 s at the file's 0.5 s step
    show = ucable_cli("scenes", "show", "turn90")
    assert show.returncode == 0, show.stderr
    (work / "my.toml").write_text(show.stdout.replace("duration = 300.0", "duration = 10.0"))
    r = ucable_cli("run", "my.toml", "--out", "d")
    assert r.returncode == 0, r.stderr
    rows = read_csv(work / "d" / "result.csv")
    assert len(rows) == 21 and {"shape.x[1]", "shape.z[21]", "towTension"} <= set(rows[0])
    assert (work / "d" / "result.png").stat().st_size > 0
    bad = ucable_cli("run", "my.toml", "--set", "nElements=2.5")
    assert bad.returncode == 2 and "Traceback" not in bad.stderr
