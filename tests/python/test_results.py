"""Results engineers read: units in every column name of what `ucable run`, `ucable sweep` and `ucable system`
write (angles in degrees), the results table (summary.csv) against the result's rows, plots that suit the
kind of scene, a failed run that keeps its rows, the tow's speed and heading swept, the systems listed with
their descriptions, the animation."""

import math

import numpy as np
import pytest

from ucable import read_results
from ucable.cli import main
from ucable.fmu import FMICallException
from ucable.results import bare_name, labelled
from ucable.tables import write_columns as write_table
from ucable.scene import CableFMU, run_scene
from ucable.units import KNOT
from ucable.system import system_names

UNIT = " ["  # every numeric column: NAME [UNIT]


def test_labels_carry_the_schema_unit_and_angles_turn_to_degrees(tmp_path):
    cols = labelled({"time": [0.0, 1.0], "towTension": [1.0, 2.0], "topDeclination": [0.0, math.pi / 2],
                     "Cdn": [1.0, 1.0], "body[1].stiffness[1,5]": [0.0, 0.0], "status": ["ok", "ok"]})
    assert list(cols) == ["time [s]", "towTension [N]", "topDeclination [deg]", "Cdn [-]",
                          "body[1].stiffness[1,5] [N/rad]", "status"]
    assert cols["topDeclination [deg]"][1] == pytest.approx(90.0)
    write_table(tmp_path / "t.csv", cols)
    back = read_results(tmp_path / "t.csv")
    assert back["body[1].stiffness[1,5]"].tolist() == [0.0, 0.0]  # the comma in the name is quoted
    assert back["topDeclination"] is back["topDeclination [deg]"] and back.units["topDeclination"] == "deg"
    assert back["status"] == ["ok", "ok"] and back.units["status"] is None


def test_run_writes_every_column_with_its_unit_and_angles_in_degrees(tmp_path, fmu_file, capsys):
    out = tmp_path / "o"
    assert main(["run", "hopland_accelerate", "--set", "duration=2", "--out", str(out)]) == 0
    header = (out / "result.csv").read_text().splitlines()[0]
    names = header.split(",")
    assert names[:2] == ["time [s]", "towTension [N]"]
    assert all(UNIT in n and n.endswith("]") for n in names), [n for n in names if UNIT not in n]
    for name in ("topDeclination [deg]", "shape.z[21] [m]", "tension[21] [N]", "curvature[1] [1/m]",
                 "layback [m]", "tow.x [m]"):
        assert name in names
    r = read_results(out / "result.csv")
    ref = run_scene("hopland_accelerate", overrides={"duration": 2.0}, fmu=fmu_file)
    assert np.allclose(r["topDeclination"], np.degrees(ref["topDeclination"]), rtol=1e-9)
    assert np.allclose(r["towTension [N]"], ref["towTension"], rtol=1e-9)
    assert 10.0 < r["topDeclination"][-1] < 90.0  # a towed cable leaves the stern well off the vertical


def summary_row(summary, quantity):
    i = list(summary["quantity"]).index(quantity)
    return {h: summary[h][i] for h in summary.headers}


def check_extreme(summary, quantity, t, values, upper=None, lower=None):
    """The row of `quantity` against the result's rows: its extremes (the CSVs keep 10 digits), each timed
    at a row that reaches it, and the final value."""
    row = summary_row(summary, quantity)
    hi = values if upper is None else upper
    lo = values if lower is None else lower
    assert row["max"] == pytest.approx(np.max(hi), rel=1e-9, abs=1e-9), quantity
    assert row["time of max [s]"] in t[np.isclose(hi, np.max(hi), rtol=1e-9, atol=1e-9)], quantity
    assert row["min"] == pytest.approx(np.min(lo), rel=1e-9, abs=1e-9), quantity
    assert row["time of min [s]"] in t[np.isclose(lo, np.min(lo), rtol=1e-9, atol=1e-9)], quantity
    assert row["final"] == pytest.approx(values[-1], rel=1e-9, abs=1e-9), quantity


def test_summary_of_a_tow_holds_tension_layback_fish_depth_and_top_angle(tmp_path, fmu_file, capsys):
    out = tmp_path / "o"
    assert main(["run", "hopland_accelerate", "--set", "duration=5", "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    r, s = read_results(out / "result.csv"), read_results(out / "summary.csv")
    assert list(s["quantity"]) == ["towTension", "layback", "endDepth", "topDeclination"]
    assert list(s["unit"]) == ["N", "m", "m", "deg"]
    t = r["time"]
    check_extreme(s, "towTension", t, r["towTension"], r["towTensionMax"], r["towTensionMin"])
    check_extreme(s, "layback", t, r["layback"])
    check_extreme(s, "endDepth", t, -r["endPosition.z"])
    check_extreme(s, "topDeclination", t, r["topDeclination"])  # in degrees, as the CSV
    assert "towTension [N]" in printed and "topDeclination [deg]" in printed  # the table is printed


def test_summary_of_an_anchored_line_holds_fairlead_anchor_and_grounded_length(tmp_path, fmu_file, capsys):
    out = tmp_path / "o"
    assert main(["run", "chain_mooring", "--set", "duration=2", "--out", str(out)]) == 0
    r, s = read_results(out / "result.csv"), read_results(out / "summary.csv")
    assert list(s["quantity"]) == ["towTension", "endTension", "groundedLength"]
    t = r["time"]
    check_extreme(s, "towTension", t, r["towTension"], r["towTensionMax"], r["towTensionMin"])
    check_extreme(s, "endTension", t, r["endTension"])
    check_extreme(s, "groundedLength", t, r["groundedLength"])
    assert summary_row(s, "groundedLength")["min"] > 50.0  # the chain rests on the seabed


def test_summary_of_a_mooring_system_holds_each_line_and_the_body(tmp_path, fmu_file, capsys):
    out = tmp_path / "o"
    assert main(["run", "oc4_platform", "--set", "duration=3", "--out", str(out)]) == 0
    r, s = read_results(out / "result.csv"), read_results(out / "summary.csv")
    t = r["time"]
    expected = []
    for k in (1, 2, 3):
        for q in ("fairleadTension", "anchorTension", "groundedLength"):
            expected.append(f"line[{k}].{q}")
            check_extreme(s, f"line[{k}].{q}", t, r[f"line[{k}].{q}"])
    assert list(s["quantity"]) == expected + ["body[1].force", "body[1].offset"]
    F = np.linalg.norm(np.column_stack([r[f"body[1].force.{q}"] for q in "xyz"]), axis=1)
    check_extreme(s, "body[1].force", t, F)
    x, y = r["body[1].x"], r["body[1].y"]
    check_extreme(s, "body[1].offset", t, np.hypot(x - x[0], y - y[0]))
    assert summary_row(s, "body[1].offset")["max"] > 0.1  # the platform surges
    assert "body[1].pitch [deg]" in r.headers  # the scene's pose, its angles in degrees


@pytest.mark.parametrize("scene, kind, first_panel_lines, seabed", [
    ("hopland_accelerate", "tow", 1, None), ("chain_mooring", "anchored", 2, 320.0),
    ("oc4_platform", "mooring", 6, 200.0)])
def test_the_plot_suits_the_kind_of_scene(fmu_file, scene, kind, first_panel_lines, seabed):
    """Per-line tensions for a mooring (fairlead and anchor of each of its 3 lines), the fairlead and anchor
    of an anchored line, the tow tension of a tow; the plan view holds the vessel's (tow point's, body's)
    track; a range graph where the stations are recorded; the seabed where the run has one (the OC4 deck
    has no WtrDpth: MoorDyn's seabed is at its deepest point, the anchors 200 m down)."""
    from ucable.scene_plots import plot_kind, result_figure

    r = run_scene(scene, overrides={"duration": 2.0}, fmu=fmu_file)
    assert plot_kind(r) == kind
    assert r.seabed == seabed
    fig = result_figure(r)
    ax = fig.axes
    assert len(ax[0].lines) == first_panel_lines
    track = ax[3].lines[0]
    x, _ = track.get_data()
    assert len(x) == len(r.time) and "track" in track.get_label()
    assert ax[5].get_title() == ("range graph" if r.shapes() is not None else
                                 "tension range per line (no stations recorded: record_shape = false)")
    if r.seabed is not None and r.shapes() is not None:  # the seabed in the side profile
        assert any(line.get_label().startswith("seabed") for line in ax[4].lines)
    import matplotlib.pyplot as plt
    plt.close(fig)


class FailingCable(CableFMU):
    """The cable FMU failing in the step that starts at FAIL_AT, as an integrator that gives up."""
    FAIL_AT = 1.0

    def do_step(self, h, t=None):
        if t is not None and t >= self.FAIL_AT - 1e-9:
            raise FMICallException("fmi2DoStep", 3)
        super().do_step(h, t)


def test_a_failed_run_keeps_its_rows_and_says_where_it_stopped(tmp_path, fmu_file, monkeypatch, capsys):
    full = run_scene("hopland_accelerate", overrides={"duration": 3.0}, fmu=fmu_file)
    monkeypatch.setattr("ucable.scene.CableFMU", FailingCable)
    out = tmp_path / "o"
    assert main(["run", "hopland_accelerate", "--set", "duration=3", "--out", str(out)]) == 1
    err = capsys.readouterr().err
    assert "the run stopped at t = 1 s of 3 s" in err and "rows up to t = 1 s" in err, err
    assert "the FMU failed at t = 1 s" in err
    r = read_results(out / "result.csv")
    assert r["time"].tolist() == pytest.approx([0.0, 0.5, 1.0])  # every communication point reached
    assert np.allclose(r["towTension"], full["towTension"][:3], rtol=1e-9)
    assert (out / "summary.csv").is_file() and (out / "result.png").is_file()


def test_speed_and_heading_set_the_tow(fmu_file, capsys):
    r = run_scene("hopland_accelerate", overrides={"duration": 4.0, "speed_kn": 2.0, "heading": 90.0}, fmu=fmu_file)
    assert r["tow.y"][-1] == pytest.approx(4.0 * 2.0 * KNOT, rel=1e-9) and abs(r["tow.x"][-1]) < 1e-9
    assert main(["run", "hopland_accelerate", "--set", "speed_kn=-1"]) == 2
    assert capsys.readouterr().err.strip() == "ucable: --set speed_kn: must not be negative, got -1"


def test_sweep_varies_speed_and_heading_with_units_in_the_columns(fmu_file, tmp_path, capsys):
    out = tmp_path / "s"
    assert main(["sweep", "hopland_accelerate", "--vary", "speed_kn=1.5,2.5", "--vary", "heading=0,45", "--set",
                 "duration=3", "--workers", "2", "--out", str(out)]) == 0
    header = (out / "results.csv").read_text().splitlines()[0].split(",")
    assert header == ["speed_kn [kn]", "heading [deg]", "towTensionMax [N]", "towTensionMin [N]",
                      "towTensionFinal [N]", "endDepthFinal [m]", "cpuSeconds [s]", "status", "error"]
    r = read_results(out / "results.csv")
    assert list(zip(r["speed_kn"], r["heading"])) == [(1.5, 0.0), (1.5, 45.0), (2.5, 0.0), (2.5, 45.0)]
    final = r["towTensionFinal"]
    assert final[2] > final[0] and final[3] > final[1]  # faster, more drag
    assert final[1] == pytest.approx(final[0], rel=1e-6)  # the heading turns the still-water tow only
    for i in (0, 3):
        single = run_scene("hopland_accelerate", overrides={"duration": 3.0, "speed_kn": r["speed_kn"][i],
                                                            "heading": r["heading"][i]}, fmu=fmu_file).summary()
        for key in ("towTensionMax", "towTensionMin", "towTensionFinal", "endDepthFinal"):
            assert r[key][i] == pytest.approx(single[key], rel=1e-9), key


def test_system_lists_the_systems_with_their_descriptions(capsys):
    assert main(["system"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert [line.split()[0] for line in lines] == system_names()
    described = dict(line.split(None, 1) for line in lines)
    assert described["moored_platform"] == "A moored floating platform in waves"
    assert described["towed_body_internal"].startswith("Vessel -> cable with the towed body inside the cable FMU")


def test_system_writes_units_in_the_column_names_and_its_results_table(tmp_path, fmu_file, capsys):
    out = tmp_path / "sys"
    assert main(["system", "towed_body", "--duration", "2", "--out", str(out)]) == 0
    r = read_results(out / "result.csv")
    assert r.headers[:5] == ["time [s]", "towTension [N]", "body.x [m]", "body.y [m]", "body.z [m]"]
    assert "vessel.heading [deg]" in r.headers and "cable.endForce.z [N]" in r.headers
    assert all(bare_name(h)[1] is not None for h in r.headers), r.headers
    s, t = read_results(out / "summary.csv"), r["time"]
    assert list(s["quantity"]) == ["towTension", "endTension", "bodyDepth", "layback"]
    check_extreme(s, "towTension", t, r["towTension"])
    check_extreme(s, "bodyDepth", t, -r["body.z"])
    check_extreme(s, "layback", t, np.hypot(r["body.x"] - r["vessel.tow.x"], r["body.y"] - r["vessel.tow.y"]))
    assert "bodyDepth [m]" in capsys.readouterr().out


def test_a_mooring_system_gets_its_lines_and_the_platform_in_the_table(tmp_path, fmu_file, capsys):
    out = tmp_path / "sys"
    assert main(["system", "moored_platform", "--duration", "4", "--out", str(out)]) == 0
    r, s = read_results(out / "result.csv"), read_results(out / "summary.csv")
    assert list(s["quantity"]) == [f"line[{k}].fairleadTension" for k in (1, 2, 3)] + ["body[1].force",
                                                                                          "body[1].offset"]
    for k in (1, 2, 3):
        check_extreme(s, f"line[{k}].fairleadTension", r["time"], r[f"cable.line[{k}].fairleadTension"])
    assert "vessel.platform.pitch [deg]" in r.headers


def test_animation_has_every_frame_and_shows_progress(tmp_path, fmu_file, capsys):
    from PIL import Image

    out = tmp_path / "o"
    assert main(["run", "chain_mooring", "--set", "duration=3", "--out", str(out), "--animate"]) == 0
    with Image.open(out / "result.gif") as gif:
        assert gif.n_frames == 31  # every communication point of 3 s at 0.1 s
    assert "animation" in capsys.readouterr().err


def test_requested_line_outputs_are_kept(fmu_file):
    """A scene's `outputs` are recorded as asked: of the default tow (a free far end, no seabed) line 1's
    grounded length is 0 throughout and its anchor tension nearly so, and both are columns (only the
    line[k] columns a mooring scene adds for every possible line are left out for lines its deck does not
    have)."""
    asked = ["line[1].anchorTension", "line[1].groundedLength"]
    r = run_scene({"name": "t", "duration": 1.0, "step": 0.5, "outputs": asked}, fmu=fmu_file)
    assert r["line[1].groundedLength"].tolist() == [0.0, 0.0, 0.0]
    assert np.max(np.abs(r["line[1].anchorTension"])) < 1e-3  # N, of a free end
