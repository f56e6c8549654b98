"""What a new user of `ucable` hits first: result.csv readable by csv, numpy and pandas with matrix
columns (body[1].stiffness[i,j]); requested line outputs kept; a sweep that finds the deck next to its
scene; `ucable scenes copy` (a scene with its deck); a missing optional module named with its install
command; every scene mistake (also those the FMU refuses at the start) exit 2 on one line; unquoted
dotted TOML keys explained; a one-line deck's tow point where the deck puts it; `ucable fmu` naming
the platforms."""

import csv
import math
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from ucable.cli import main
from ucable.fmu import CableFMU
from ucable.results import labelled
from ucable.scene import SceneResult, load_scene, run_scene
from ucable.scene_schema import SceneFileError

ROOT = Path(__file__).resolve().parents[2]
DECKS = ROOT / "tests" / "data" / "decks"
HEAD = 'title = "t"\nduration = 1.0\nstep = 0.5\nrecord_shape = false\n'
MATRIX = [f"body[1].stiffness[{i},{j}]" for i in (1, 2) for j in (1, 2)]


def cli(*args, fmu_file=None, cwd=None, prelude=""):
    """`ucable ARGS` in a child process (prelude: Python run before, e.g. to hide a module)."""
    env_path = str(ROOT / "python")
    code = f"import sys\nsys.path.insert(0, {env_path!r})\n{prelude}\nfrom ucable.cli import main\nsys.exit(main(sys.argv[1:]))"
    env = {"PATH": "/usr/bin:/bin", "HOME": str(Path.home())}
    if fmu_file is not None:
        env["UC_FMU"] = str(fmu_file)
    return subprocess.run([sys.executable, "-c", code, *map(str, args)], capture_output=True, text=True,
                          cwd=cwd, env=env, timeout=600)


def read_columns(path):
    from ucable import read_results

    return read_results(path)


def scene_warning():
    from ucable.scene import SceneWarning

    return SceneWarning


def one_line_error(p, code):
    assert p.returncode == code, p.stderr
    assert "Traceback" not in p.stderr and p.stderr.count("\n") == 1, p.stderr
    return p.stderr.strip()


# ---------------------------------------------------------------------------------------- CSV
def check_readers(path, names, rows):
    with open(path, newline="") as f:
        table = list(csv.reader(f))
    assert table[0] == names
    assert all(len(r) == len(names) for r in table[1:]) and len(table) == rows + 1
    data = np.genfromtxt(path, delimiter=",", skip_header=1, names=table[0], ndmin=1)
    assert len(data.dtype.names) == len(names) and data.shape == (rows,)
    assert np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2).shape == (rows, len(names))
    try:
        import pandas
    except ImportError:
        return
    assert list(pandas.read_csv(path).columns) == names


def test_result_csv_with_matrix_columns_is_read_by_csv_numpy_and_pandas(tmp_path):
    t = np.array([0.0, 0.5, 1.0])
    columns = {"towTension": 1e3 * (1 + t), **{n: -1e4 * (k + 1) + t for k, n in enumerate(MATRIX)}, "tow.x": t}
    SceneResult(None, t, columns, 0.0).write_csv(tmp_path / "result.csv")
    headers = list(labelled({"time": t, **columns}))  # each name with its unit
    assert headers[0] == "time [s]" and headers[2] == "body[1].stiffness[1,1] [N/m]"
    check_readers(tmp_path / "result.csv", headers, 3)
    back = read_columns(tmp_path / "result.csv")
    assert back.headers == headers
    for name, values in columns.items():
        np.testing.assert_array_equal(back[name], values)


def test_system_result_csv_uses_the_same_writer(tmp_path):
    from ucable.system_cli import write_csv

    write_csv(tmp_path / "r.csv", {"time": np.arange(2.0), "a[1,2]": np.ones(2), 'b "q"': np.zeros(2)})
    check_readers(tmp_path / "r.csv", ["time", "a[1,2]", 'b "q"'], 2)


def test_recorded_stiffness_of_a_mooring_system(fmu_file, tmp_path):
    """The OC4 platform with its 6x6 stiffness recorded: one value per name in every row."""
    (tmp_path / "oc4_semi.dat").write_bytes((ROOT / "scenes" / "oc4_semi.dat").read_bytes())
    text = (ROOT / "scenes" / "oc4_platform.toml").read_text().replace("duration = 100.0", "duration = 0.2")
    text = text.replace("record_shape = false", "record_shape = false\noutputs = [" +
                        ", ".join(f'"{n}"' for n in MATRIX) + "]")
    (tmp_path / "s.toml").write_text(text)
    assert main(["run", str(tmp_path / "s.toml"), "--out", str(tmp_path / "o")]) == 0
    with open(tmp_path / "o" / "result.csv", newline="") as f:
        rows = list(csv.reader(f))
    assert {len(r) for r in rows} == {len(rows[0])}
    back = read_columns(tmp_path / "o" / "result.csv")
    assert set(MATRIX) <= set(back) and np.all(back["body[1].stiffness[1,1]"] > 0.0)


def test_requested_line_outputs_are_kept_when_zero(fmu_file):
    scene = load_scene({**load_scene("hopland_accelerate").data, "duration": 1.0, "record_shape": False,
                        "outputs": ["line[2].fairleadTension", "line[2].anchorTension"]})
    r = run_scene(scene, fmu=fmu_file)
    assert np.all(r["line[2].fairleadTension"] == 0.0) and "line[2].anchorTension" in r.columns


# -------------------------------------------------------------------------------------- sweep
def write_deck_scene(directory, start=None):
    shutil.copyfile(DECKS / "chain_wire_chain.dat", directory / "deck.dat")
    tow = f"[tow]\nstart = {start}\n" if start is not None else ""
    (directory / "s.toml").write_text(HEAD + '[parameters]\nlineFile = "deck.dat"\n' + tow)
    return directory / "s.toml"


def test_sweep_case_finds_the_deck_next_to_the_scene(fmu_file, tmp_path, monkeypatch):
    from ucable.sweep import run_case, scene_data

    monkeypatch.setenv("UC_FMU", str(fmu_file))
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    scenes = tmp_path / "scenes"
    scenes.mkdir()
    scene = load_scene(write_deck_scene(scenes))
    row = run_case(scene_data(scene), {"Cdn": 1.2}, str(scene.directory))
    assert row["status"] == "ok", row["error"]
    single = run_scene(scene, overrides={"Cdn": 1.2}, fmu=fmu_file).summary()
    assert row["towTensionFinal"] == single["towTensionFinal"]


def test_cli_sweep_of_a_deck_scene_from_another_directory(fmu_file, tmp_path):
    scenes = tmp_path / "scenes"
    scenes.mkdir()
    path = write_deck_scene(scenes)
    p = cli("sweep", path, "--vary", "Cdn=1.2", "--workers", "1", "--out", tmp_path / "s", fmu_file=fmu_file,
            cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    with open(tmp_path / "s" / "results.csv") as f:
        rows = list(csv.DictReader(f))
    assert [r["status"] for r in rows] == ["ok"], rows
    assert (tmp_path / "s" / "summary.png").stat().st_size > 0


def test_summary_plot_of_a_sweep_where_every_run_failed(tmp_path):
    from ucable.sweep import SUMMARY, plot_summary

    for vary in ({"length": [200, 300]}, {"lineFile": ["a.dat", "b.dat"]}, {"Cdn": [1.2]}):
        name, values = next(iter(vary.items()))
        rows = [{name: v, **{k: math.nan for k in SUMMARY}, "cpuSeconds": 0.1, "status": "error", "error": "x"}
                for v in values]
        plot_summary(rows, [name], tmp_path / f"{name}.png", "all failed")
        assert (tmp_path / f"{name}.png").stat().st_size > 0


def fake_sweep(status):
    from ucable.sweep import SUMMARY

    def run_sweep(scene, vary, fixed, workers, scheduler, progress):
        rows = [{"Cdn": v, **{k: 1e4 for k in SUMMARY}, "cpuSeconds": 0.1, "status": status, "error": ""}
                for v in vary["Cdn"]]
        return rows, 0.1
    return run_sweep


def test_a_summary_plot_that_fails_keeps_the_table_and_says_so(tmp_path, monkeypatch, capsys):
    import ucable.sweep

    def crash(*args):
        raise OverflowError("In draw_path: Exceeded cell block limit")
    monkeypatch.setattr(ucable.sweep, "run_sweep", fake_sweep("ok"))
    monkeypatch.setattr(ucable.sweep, "plot_summary", crash)
    assert main(["sweep", "hopland_accelerate", "--vary", "Cdn=1.2,1.4", "--out", str(tmp_path / "s")]) == 0
    err = capsys.readouterr().err
    assert "ucable: warning: summary.png not written: OverflowError: In draw_path" in err
    assert (tmp_path / "s" / "results.csv").is_file() and not (tmp_path / "s" / "summary.png").exists()


def test_a_sweep_where_every_run_failed_draws_no_summary(tmp_path, monkeypatch, capsys):
    import ucable.sweep

    monkeypatch.setattr(ucable.sweep, "run_sweep", fake_sweep("error"))
    assert main(["sweep", "hopland_accelerate", "--vary", "Cdn=1.2,1.4", "--out", str(tmp_path / "s")]) == 1
    assert "every run failed: no summary.png" in capsys.readouterr().err
    assert (tmp_path / "s" / "results.csv").is_file() and not (tmp_path / "s" / "summary.png").exists()


# ------------------------------------------------------------------------------- scenes copy/show
def test_scenes_copy_brings_the_deck_and_the_copy_runs(fmu_file, tmp_path, capsys):
    assert main(["scenes", "copy", "oc4_platform", str(tmp_path / "mine")]) == 0
    assert sorted(p.name for p in (tmp_path / "mine").iterdir()) == ["oc4_platform.toml", "oc4_semi.dat"]
    assert "ucable run" in capsys.readouterr().out
    assert main(["run", str(tmp_path / "mine" / "oc4_platform.toml"), "--set", "duration=0.2",
                 "--out", str(tmp_path / "o")]) == 0
    assert main(["scenes", "copy", "oc4_platform", str(tmp_path / "mine")]) == 2  # nothing overwritten
    assert "exists" in capsys.readouterr().err


def test_scenes_show_names_the_files_a_scene_needs(capsys):
    assert main(["scenes", "show", "oc4_platform"]) == 0
    out, err = capsys.readouterr()
    assert out.startswith("# A moored floating platform") and "oc4_semi.dat" not in err.split("needs")[0]
    assert "needs oc4_semi.dat" in err and "scenes copy oc4_platform" in err and err.count("\n") == 1
    assert main(["scenes", "show", "turn90"]) == 0
    assert capsys.readouterr().err == ""


def test_a_deck_that_is_not_there_is_a_scene_mistake_without_temporary_paths(fmu_file, tmp_path):
    """`scenes show oc4_platform > my.toml` without the deck: exit 2, one line, the way out; no path of
    the FMU's temporary extraction (which the FMU's own message names)."""
    p = subprocess.run([sys.executable, "-c", "import sys; sys.path.insert(0, sys.argv[1]); from ucable.cli import main;"
                        "sys.exit(main(['scenes', 'show', 'oc4_platform']))", str(ROOT / "python")],
                       capture_output=True, text=True)
    (tmp_path / "my.toml").write_text(p.stdout.replace("duration = 100.0", "duration = 0.2"))
    err = one_line_error(cli("run", "my.toml", "--out", "o", fmu_file=fmu_file, cwd=tmp_path), 2)
    assert err.startswith("ucable: my.toml: [parameters] lineFile = 'oc4_semi.dat': no such file"), err
    assert "ucable scenes copy" in err and "resources" not in err and "/tmp/tmp" not in err


def test_fmu_messages_name_the_fmu_not_its_temporary_extraction(fmu_file):
    from ucable.fmu import FMICallException

    unit = CableFMU(fmu_file, parameters={"lineFile": "no_such_deck.dat"})
    try:
        with pytest.raises(FMICallException):
            unit.initialize(0.0)
        said = unit.log_text()
        assert f"<{fmu_file.name}>/resources/no_such_deck.dat" in said and str(unit.unzipdir) not in said, said
    finally:
        unit.free()


# ------------------------------------------------------------------------- optional modules
@pytest.mark.parametrize("module, args, says", [
    ("libcosimpy", ["system", "towed_body", "--master", "libcosim", "--duration", "1"], 'pip install "ucable[libcosim]"'),
    ("dask", ["sweep", "hopland_accelerate", "--vary", "Cdn=1.2", "--set", "duration=1"], 'pip install "dask[distributed]"'),
])
def test_a_missing_optional_module_is_one_line_with_its_install_command(fmu_file, tmp_path, module, args, says):
    p = cli(*args, "--out", tmp_path / "o", fmu_file=fmu_file, cwd=tmp_path,
            prelude=f"sys.modules[{module!r}] = None  # as if not installed")
    err = one_line_error(p, 1)
    assert f"the Python module {module!r} is not installed" in err and says in err, err


@pytest.mark.parametrize("args", [["rnu", "turn90"], ["system", "towed_body", "--master", "fmpi"], ["sweep", "turn90"]])
def test_a_command_line_mistake_is_one_line_exit_2(args):
    err = one_line_error(cli(*args), 2)
    assert err.startswith("ucable") and "--help" in err, err


def test_an_unexpected_error_is_one_line(tmp_path, fmu_file):
    (tmp_path / "o").write_text("a file where the output directory should be")
    err = one_line_error(cli("run", "hopland_accelerate", "--out", tmp_path / "o", fmu_file=fmu_file), 1)
    assert "File exists" in err or "Not a directory" in err, err


# ---------------------------------------------------------------------------- scene mistakes
def test_a_start_the_fmu_refuses_exits_2(tmp_path, fmu_file):
    (tmp_path / "s.toml").write_text(HEAD + "[parameters]\nenableSeabed = true\nwaterDepth = 100.0\n"
                                            "[tow]\nstart = [0.0, 0.0, -150.0]\n")
    err = one_line_error(cli("run", tmp_path / "s.toml", "--out", tmp_path / "o", fmu_file=fmu_file), 2)
    assert "the FMU could not start" in err and "below the seabed" in err and "fmi2" not in err, err


@pytest.mark.parametrize("table, text, name", [
    ("parameters", "body.mass = 400.0", "body.mass"),
    ("parameters", "section.1.length = 10.0", None),
    ("inputs", "current.x = { times = [0.0, 1.0], values = [0.0, 0.5] }", "current.x"),
])
def test_unquoted_dotted_keys_get_the_quoting_hint(table, text, name):
    with pytest.raises(SceneFileError) as e:
        load_scene({**load_scene("hopland_accelerate").data, table: __import__("tomllib").loads(text)})
    if name is not None:
        assert f'[{table}] {name}: an unquoted dotted key makes a TOML table: quote the name, "{name}" = ' in str(e.value)
    else:
        assert "unknown parameter" in str(e.value)


# --------------------------------------------------------------------------- deck tow point
def deck_start_tension(fmu_file, point):
    unit = CableFMU(fmu_file, parameters={"lineFile": str(DECKS / "chain_wire_chain.dat")})
    try:
        unit.initialize(0.0, inputs={"tow.x": point[0], "tow.y": point[1], "tow.z": point[2]})
        return unit.get("towTension")
    finally:
        unit.free()


def test_a_one_line_deck_starts_at_its_vessel_point(fmu_file, tmp_path):
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error", scene_warning())
        r = run_scene(load_scene(write_deck_scene(tmp_path)), fmu=fmu_file)
    assert r["tow.z"][0] == -20.0 and r["tow.x"][0] == 0.0
    assert r["towTension"][0] == pytest.approx(deck_start_tension(fmu_file, (0.0, 0.0, -20.0)), rel=1e-9)
    assert abs(r["towTension"][0] - deck_start_tension(fmu_file, (0.0, 0.0, 0.0))) > 1e3


def test_a_tow_start_other_than_the_decks_is_said(fmu_file, tmp_path):
    with pytest.warns(scene_warning(), match=r"\[tow\] start = \(0, 0, -10\) m is not the deck's tow point \(0, 0, -20\)"):
        r = run_scene(load_scene(write_deck_scene(tmp_path, "[0.0, 0.0, -10.0]")), fmu=fmu_file)
    assert r["tow.z"][0] == -10.0


def test_cli_prints_the_tow_start_warning_on_one_line(fmu_file, tmp_path):
    p = cli("run", write_deck_scene(tmp_path, "[0.0, 0.0, -10.0]"), "--out", tmp_path / "o", fmu_file=fmu_file)
    assert p.returncode == 0, p.stderr
    said = [line for line in p.stderr.splitlines() if "warning" in line]
    assert len(said) == 1 and said[0].startswith("ucable: warning: ") and "deck's tow point" in said[0], p.stderr


# ------------------------------------------------------------------------------ platforms
def test_ucable_fmu_names_the_platforms_and_how_to_add_win64(fmu_file, capsys):
    from ucable.paths import fmu_platforms

    assert main(["fmu"]) == 0
    out, err = capsys.readouterr()
    assert out.strip() == str(fmu_file)
    platforms = fmu_platforms(fmu_file)
    assert err.startswith(f"ucable: FMI 2.0: {', '.join(platforms)}") and err.count("\n") == 1
    assert ("scripts/setup --platforms linux64,win64" in err) == ("win64" not in platforms)


def test_the_wheel_installs_the_fmi3_variant_and_says_the_platforms():
    """pip's build (CMake under scikit-build-core) installs the FMI 3.0 variant beside the FMU and says
    which platforms it built; the message after the build points to `ucable fmu`."""
    cmake = (ROOT / "CMakeLists.txt").read_text()
    skbuild = cmake[cmake.index("if(SKBUILD)"):]
    skbuild = skbuild[:skbuild.index("endif()\n\nif(")]
    assert "${CMAKE_BINARY_DIR}/fmi3/UnderwaterCable.fmu DESTINATION ucable/fmi3" in skbuild
    assert "carry binaries for" in skbuild and "scripts/setup --platforms linux64,win64" in skbuild
    import tomllib

    message = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["scikit-build"]["messages"]["after-success"]
    assert "ucable fmu" in message and "{" not in message


def test_a_deck_in_the_fmus_resources_is_found_by_its_name(fmu_file, tmp_path, monkeypatch):
    """A relative lineFile in none of the scene's directory and the current one, but in the FMU's
    resources (an FMU that carries decks), goes to the FMU by its name, which finds it there."""
    from ucable.fmu import load

    resources = Path(load(fmu_file)[0]) / "resources"
    resources.mkdir(exist_ok=True)
    shutil.copyfile(DECKS / "chain.dat", resources / "resource_chain.dat")
    monkeypatch.chdir(tmp_path)
    try:
        r = run_scene(load_scene({**load_scene(write_deck_scene(tmp_path)).data, "parameters":
                                  {"lineFile": "resource_chain.dat"}}), fmu=fmu_file)
        assert r["tow.z"][0] == -70.0  # chain.dat's Vessel point
    finally:
        (resources / "resource_chain.dat").unlink()
