"""Breaking strength and design checks (docs/design_checks.md): the MBL of a deck's line type (MoorPy's
formulas at a few nominal diameters, hand values), the FMU's utilisation outputs (tension / MBL) on a
one-line scene and on the shipped OC4 system deck, `ucable check` (table, check.csv, exit codes, the case
from line[k].broken) and `ucable sweep --seeds` (Gumbel fit of the realisations' maxima)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from ucable import read_results
from ucable.design_check import API_FOS, DNV_FACTORS, DNV_STRENGTH
from ucable.fmu import CableFMU
from ucable.scene import run_scene
from ucable.tables import write_columns

ROOT = Path(__file__).resolve().parents[2]

# A single line from a Fixed anchor to the Coupled fairlead, its type's name and Mass/m filled in.
DECK = """--------------------- MoorDyn Input File ------------------------------------
one line of a named material
---------------------- LINE TYPES ----------------------------------------
TypeName   Diam     Mass/m   EA       BA/-zeta   EI   Cd    Ca    CdAx   CaAx
(name)     (m)      (kg/m)   (N)      (N-s/-)    (-)  (-)   (-)   (-)    (-)
{name}     {diam}   {mass}   1.0e9    -0.8       0    1.2   1.0   0.1    0.0
---------------------- POINTS ---------------------------------------------
ID   Attachment  X        Y     Z       Mass   Volume  CdA    CA
(#)  (-)         (m)      (m)   (m)     (kg)   (m^3)   (m^2)  (-)
1    Fixed       -850     0     -320    0      0       0      0
2    Coupled     0        0     -70     0      0       0      0
---------------------- LINES ----------------------------------------------
ID   LineType  AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)    (#)      (#)      (m)       (-)      (-)
1    {name}    1        2        900       20       -
---------------------- OPTIONS --------------------------------------------
320      WtrDpth
------------------------- need this line -------------------------------------
"""

# (type name, nominal diameter d [m], Mass/m = mass_d2 d^2 [kg/m], MBL [N] by hand from MoorProps_default.yaml:
# chain 9.11e2 d + 1.21e9 d^2 - 2.19e9 d^3, wire 1022e6 d^2, polyester 308e6 d^2, nylon 207e6 d^2 + 230e6 d^3)
MOORPY = [("chain", 0.05, 50.0, 2751295.55), ("chain", 0.10, 200.0, 9910091.1), ("chain", 0.15, 450.0, 19833886.65),
          ("studlink", 0.10, 219.0, 9910091.1), ("wire", 0.05, 13.2325, 2555000.0), ("wire", 0.10, 52.93, 10220000.0),
          ("polyester", 0.10, 6.79, 3080000.0), ("polyester", 0.20, 27.16, 12320000.0),
          ("nylon", 0.10, 5.85, 2300000.0), ("nylon", 0.20, 23.40, 10120000.0)]
MOORPY_MATERIAL = {"chain": "chain", "studlink": "chain_studlink", "wire": "wire", "polyester": "polyester",
                   "nylon": "nylon"}


def cli(*args, cwd, fmu_file=None, timeout=600):
    env = dict(os.environ)
    if fmu_file is not None:
        env["UC_FMU"] = str(fmu_file)
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT / "python"), env.get("PYTHONPATH", "")])
    return subprocess.run([sys.executable, "-m", "ucable.cli", *args], env=env, capture_output=True, text=True,
                           cwd=cwd, timeout=timeout)


@pytest.mark.parametrize("name, d, mass, mbl", MOORPY)
def test_a_deck_type_named_for_its_material_gets_moorpys_mbl(fmu_file, tmp_path, name, d, mass, mbl):
    deck = tmp_path / "line.dat"
    deck.write_text(DECK.format(name=name, diam=f"{1.8 * d:.5f}", mass=f"{mass:.6g}"))
    cable = CableFMU(fmu_file, parameters={"lineFile": str(deck)}, logging_on=True)
    try:
        cable.initialize(inputs={"tow.z": -70.0})
        assert cable.get("line[1].MBL") == pytest.approx(mbl, rel=1e-9)
        said = " ".join(m[2] for m in cable.messages)
        assert f"line type '{name}': no MBL column: MoorPy's" in said, said
        assert f"= {d:.4g} m" in said, said  # the nominal diameter it took
        # the fairlead's utilisation is its tension over that MBL
        assert cable.get("line[1].fairleadUtilisation") == pytest.approx(cable.get("towTension") / mbl, rel=1e-12)
    finally:
        cable.free()
    moorpy = pytest.importorskip("moorpy.helpers")
    import moorpy as mp

    source = Path(mp.__file__).parent / "library" / "MoorProps_default.yaml"
    assert moorpy.getLineProps(d * 1000.0, MOORPY_MATERIAL[name], source=str(source))["MBL"] == pytest.approx(
        mbl, rel=1e-9)


def test_one_line_scene_utilisations_are_tensions_over_the_mbl(fmu_file):
    mbl = 6.0e6
    r = run_scene("chain_mooring", overrides={"duration": 2.0, "step": 0.5, "MBL": mbl}, fmu=fmu_file)
    c = r.columns
    assert np.all(c["line[1].MBL"] == mbl)
    assert np.allclose(c["line[1].fairleadUtilisation"], c["towTension"] / mbl, rtol=1e-12, atol=0.0)
    assert np.allclose(c["line[1].anchorUtilisation"], c["endTension"] / mbl, rtol=1e-12, atol=0.0)
    # along the line: at least either end's, and a hanging chain's largest tension is at its fairlead
    u = c["line[1].maxUtilisation"]
    assert np.all(u >= c["line[1].fairleadUtilisation"]) and np.all(u >= c["line[1].anchorUtilisation"])
    assert np.allclose(u, c["line[1].fairleadUtilisation"], rtol=0.02)
    # without an MBL the columns are left out of the result
    plain = run_scene("chain_mooring", overrides={"duration": 0.5, "step": 0.5}, fmu=fmu_file)
    assert "line[1].maxUtilisation" not in plain.columns


def test_shipped_system_deck_utilisations_are_tensions_over_the_mbl(fmu_file):
    """oc4_semi.dat's type 'main' names no material: the parameter MBL is each line's."""
    mbl = 7.0e6
    r = run_scene("oc4_platform", overrides={"duration": 1.0, "step": 0.5, "MBL": mbl}, fmu=fmu_file)
    c = r.columns
    for k in (1, 2, 3):
        assert np.all(c[f"line[{k}].MBL"] == mbl)
        assert np.allclose(c[f"line[{k}].fairleadUtilisation"], c[f"line[{k}].fairleadTension"] / mbl, rtol=1e-12)
        assert np.allclose(c[f"line[{k}].anchorUtilisation"], c[f"line[{k}].anchorTension"] / mbl, rtol=1e-12)
        assert np.all(c[f"line[{k}].maxUtilisation"] >= c[f"line[{k}].fairleadUtilisation"])
        assert 0.05 < c[f"line[{k}].fairleadUtilisation"][0] < 0.5  # ~1.1 MN of pretension over 7 MN
    assert "line[4].MBL" not in c


def test_shipped_system_deck_with_its_type_named_chain_takes_the_chain_formula(fmu_file, tmp_path):
    text = (ROOT / "scenes" / "oc4_semi.dat").read_text()
    deck = tmp_path / "oc4_chain.dat"
    deck.write_text(text.replace("\nmain ", "\nchain").replace(" main ", " chain "))
    cable = CableFMU(fmu_file, parameters={"lineFile": str(deck)})
    try:
        cable.initialize()
        # d = sqrt(113.35 / 20.0e3) = 0.0752828 m: 9.11e2 d + 1.21e9 d^2 - 2.19e9 d^3 = 5923346.6 N
        for k in (1, 2, 3):
            assert cable.get(f"line[{k}].MBL") == pytest.approx(5923346.6, abs=1.0)
            assert cable.get(f"line[{k}].fairleadUtilisation") == pytest.approx(
                cable.get(f"line[{k}].fairleadTension") / 5923346.64, rel=1e-9)
    finally:
        cable.free()


def synthetic_result(path, u_fair, u_anchor=None, mbl=5e6, broken=None, lines=1):
    """A result.csv as ucable run writes it: time and line[k].* utilisation columns."""
    n = len(u_fair)
    cols = {"time": np.arange(n) * 0.5}
    for k in range(1, lines + 1):
        cols[f"line[{k}].MBL [N]"] = np.full(n, mbl)
        cols[f"line[{k}].fairleadUtilisation [-]"] = np.asarray(u_fair, dtype=float)
        cols[f"line[{k}].anchorUtilisation [-]"] = np.asarray(u_anchor if u_anchor is not None else u_fair) * 0.8
        cols[f"line[{k}].maxUtilisation [-]"] = np.asarray(u_fair, dtype=float)
        if broken is not None:
            cols[f"line[{k}].broken [-]"] = np.asarray(broken[k - 1], dtype=float)
    write_columns(path, cols)


def test_check_of_a_passing_run_prints_the_table_writes_check_csv_and_exits_0(tmp_path):
    u = np.array([0.2, 0.3, 0.5, 0.3, 0.2])  # mean 0.3, max 0.5
    synthetic_result(tmp_path / "result.csv", u)
    p = cli("check", "result.csv", cwd=tmp_path)
    assert p.returncode == 0, p.stdout + p.stderr
    assert "case: intact (no line[k].broken output is set)" in p.stdout
    rows = read_results(tmp_path / "check.csv").records()
    assert len(rows) == 3 * 3  # fairlead, anchor, along x API, DNV CC1, DNV CC2
    by = {(r["location"], r["standard"], r["limit"]): r for r in rows}
    # API RP 2SK intact, dynamic: FOS 1.67 on the maximum
    assert by[("fairlead", "API RP 2SK", "intact")]["utilisation"] == pytest.approx(1.67 * 0.5)
    # DNV-OS-E301 ULS CC2: (1.40 Tmean + 2.10 Tdyn) / (0.95 MBL), Tdyn = max - mean
    assert by[("fairlead", "DNV-OS-E301", "ULS CC2")]["utilisation"] == pytest.approx((1.4 * 0.3 + 2.1 * 0.2) / 0.95)
    # CC1 with the mean above 2/3 of the dynamic tension: 1.3 (Tmean + Tdyn)
    assert by[("fairlead", "DNV-OS-E301", "ULS CC1")]["utilisation"] == pytest.approx(1.3 * 0.5 / 0.95)
    assert by[("fairlead", "DNV-OS-E301", "ULS CC1")]["design tension"] == pytest.approx(1.3 * 0.5 * 5e6)
    assert all(r["result"] == "pass" for r in rows)
    governing = "governing: line 1 at its fairlead, DNV-OS-E301 ULS CC2: utilisation 0.884"
    assert governing in p.stdout and "passes with a margin of 11.6 %" in p.stdout, p.stdout


def test_check_of_a_failing_run_names_the_line_and_exits_3(tmp_path):
    u = np.array([0.3, 0.4, 0.65, 0.4])  # API intact dynamic: 1.67 x 0.65 = 1.0855
    synthetic_result(tmp_path / "result.csv", u, lines=2)
    p = cli("check", str(tmp_path), "--standard", "api", "--out", "o", cwd=tmp_path)
    assert p.returncode == 3, p.stdout + p.stderr
    assert "FAILS by 8.5 % of its capacity" in p.stdout and "governing: line 1 at its fairlead" in p.stdout
    rows = read_results(tmp_path / "o" / "check.csv").records()
    assert {r["line"] for r in rows} == {1.0, 2.0} and {r["standard"] for r in rows} == {"API RP 2SK"}
    assert [r["result"] for r in rows if r["location"] == "fairlead"] == ["FAIL", "FAIL"]
    # without its first two rows (t < 1 s) the maximum is the same, the mean higher: DNV ULS CC2 fails (1.050)
    s = cli("check", "result.csv", "--skip", "1", "--standard", "dnv", "--class", "2", cwd=tmp_path)
    assert s.returncode == 3 and f"utilisation {(1.4 * 0.525 + 2.1 * 0.125) / 0.95:.3f}" in s.stdout, s.stdout + s.stderr
    # the same run as damaged (--case): FOS 1.25 passes
    q = cli("check", "result.csv", "--case", "damaged", "--standard", "api", cwd=tmp_path)
    assert q.returncode == 0 and f"utilisation {1.25 * 0.65:.3f}" in q.stdout, q.stdout + q.stderr


def test_the_case_comes_from_the_broken_outputs(tmp_path):
    u = np.array([0.3, 0.4, 0.5, 0.4])
    # line 2 breaks at t = 1 s (row 2): line 1 intact before, transient from then on (API FOS 1.05, DNV ALS);
    # line 2 left out
    synthetic_result(tmp_path / "result.csv", u, lines=2, broken=[[0, 0, 0, 0], [0, 0, 1, 1]])
    p = cli("check", "result.csv", cwd=tmp_path)
    assert p.returncode == 0, p.stdout + p.stderr
    assert "case: transient (line 2 broke during the run; intact before the break)" in p.stdout
    rows = read_results(tmp_path / "check.csv").records()
    assert {r["line"] for r in rows} == {1.0}
    fair = {(r["standard"], r["limit"]): r for r in rows if r["location"] == "fairlead"}
    assert fair[("API RP 2SK", "intact")]["utilisation"] == pytest.approx(API_FOS[("intact", "dynamic")] * 0.4)
    assert fair[("API RP 2SK", "intact")]["run"] == "before the break (t < 1 s)"
    assert fair[("API RP 2SK", "transient")]["utilisation"] == pytest.approx(API_FOS[("transient", "dynamic")] * 0.5)
    g_mean, g_dyn = DNV_FACTORS[("ALS", 2, "dynamic")]  # from the break: mean 0.45, max 0.5
    assert fair[("DNV-OS-E301", "ALS CC2")]["utilisation"] == pytest.approx((g_mean * 0.45 + g_dyn * 0.05) / DNV_STRENGTH)
    g_mean, g_dyn = DNV_FACTORS[("ULS", 2, "dynamic")]  # before: mean 0.35, max 0.4
    assert fair[("DNV-OS-E301", "ULS CC2")]["utilisation"] == pytest.approx((g_mean * 0.35 + g_dyn * 0.05) / DNV_STRENGTH)
    # broken from the start: damaged
    synthetic_result(tmp_path / "result.csv", u, lines=2, broken=[[0, 0, 0, 0], [1, 1, 1, 1]])
    p = cli("check", "result.csv", cwd=tmp_path)
    assert "case: damaged (line 2 broken from the start)" in p.stdout, p.stdout + p.stderr


def test_check_refuses_a_line_without_mbl_and_bad_options_with_exit_2(tmp_path):
    synthetic_result(tmp_path / "result.csv", [0.2, 0.3], mbl=0.0)
    p = cli("check", "result.csv", cwd=tmp_path)
    assert p.returncode == 2 and "line 1: MBL = 0 N: no breaking load to check against" in p.stderr, p.stderr
    synthetic_result(tmp_path / "result.csv", [0.2, 0.3])
    p = cli("check", "result.csv", "--class", "3", cwd=tmp_path)
    assert p.returncode == 2 and "--class '3'" in p.stderr, p.stderr
    p = cli("check", "result.csv", "--analysis", "quasi-static", "--case", "damaged", "--standard", "dnv",
            cwd=tmp_path)
    assert p.returncode == 2 and "dynamic analysis only" in p.stderr, p.stderr


def test_check_runs_a_scene_and_checks_its_line(fmu_file, tmp_path):
    p = cli("check", "chain_mooring", "--set", "duration=2", "--set", "step=0.5", "--set", "MBL=6e6", "--out", "c",
            fmu_file=fmu_file, cwd=tmp_path)
    assert p.returncode == 0, p.stdout + p.stderr
    result = read_results(tmp_path / "c" / "result.csv")
    rows = read_results(tmp_path / "c" / "check.csv").records()
    u = result["line[1].maxUtilisation"]
    along = [r for r in rows if r["location"] == "along" and r["standard"] == "API RP 2SK"][0]
    assert along["max T/MBL"] == pytest.approx(u.max(), rel=1e-9)
    assert along["utilisation"] == pytest.approx(1.67 * u.max(), rel=1e-9)


def test_sweep_over_seeds_fits_the_maxima_and_its_results_are_checked(fmu_file, tmp_path):
    p = cli("sweep", "lowering_in_waves", "--seeds", "3", "--set", "duration=4", "--set", "step=0.5",
            "--set", "waves.rampTime=1", "--set", "MBL=2e5", "--set", "length=100", "--storm", "300",
            "--out", "s", fmu_file=fmu_file, cwd=tmp_path)
    assert p.returncode == 0, p.stdout + p.stderr
    rows = read_results(tmp_path / "s" / "results.csv").records()
    assert [r["waves.seed"] for r in rows] == [1.0, 2.0, 3.0]
    maxima = np.array([r["towTensionMax"] for r in rows])
    assert len(set(maxima)) == 3  # three different seas
    assert all(r["line[1].MBL"] == 2e5 for r in rows)
    ext = read_results(tmp_path / "s" / "extremes.csv").records()
    assert len(ext) == 1 and ext[0]["line"] == "line 1" and ext[0]["realisations"] == 3
    from ucable.extremes import fit_mle

    # refitted from results.csv's maxima, which keep 10 digits (1e-5 N of some 17 kN): within 1e-3 N
    mu, beta = fit_mle(maxima)
    assert ext[0]["mu"] == pytest.approx(float(mu), abs=1e-3) and ext[0]["beta"] == pytest.approx(float(beta), abs=1e-3)
    assert ext[0]["MPM"] == pytest.approx(float(mu + beta * np.log(300.0 / 3.0)), abs=1e-2)  # 4 s less 1 s of ramp
    assert ext[0]["low"] < ext[0]["MPM"] < ext[0]["high"]
    assert (tmp_path / "s" / "gumbel.png").stat().st_size > 0
    assert "MPM over 300 s" in p.stdout
    q = cli("check", "s/results.csv", "--standard", "api", fmu_file=fmu_file, cwd=tmp_path)
    assert q.returncode == 0, q.stdout + q.stderr  # some 17 kN over 200 kN
    worst = max(r["line[1].maxUtilisationMax"] for r in rows)
    assert f"utilisation {1.67 * worst:.3f}" in q.stdout, q.stdout


def test_seeds_refuse_a_calm_scene_and_too_few_realisations(fmu_file, tmp_path):
    p = cli("sweep", "chain_mooring", "--seeds", "3", fmu_file=fmu_file, cwd=tmp_path)
    assert p.returncode == 2 and "no irregular sea (waves.mode 2)" in p.stderr, p.stderr
    p = cli("sweep", "lowering_in_waves", "--seeds", "2", fmu_file=fmu_file, cwd=tmp_path)
    assert p.returncode == 2 and "needs 3 realisations or more" in p.stderr, p.stderr


def test_a_sweep_keeps_each_lines_maxima_with_or_without_an_mbl():
    """run_statistics of a system run (line 1 with an MBL, line 2 without) and the maxima a seeds sweep fits."""
    from ucable.design_check import run_statistics
    from ucable.sweep import realisation_maxima

    t1, t2 = np.array([1e5, 3e5, 2e5]), np.array([4e5, 5e5, 4.5e5])
    columns = {"time": np.arange(3.0), "line[1].fairleadTension": t1, "line[1].MBL": np.full(3, 1e6),
               "line[1].fairleadUtilisation": t1 / 1e6, "line[1].anchorUtilisation": t1 / 2e6,
               "line[1].maxUtilisation": t1 / 1e6, "line[2].fairleadTension": t2}
    s = run_statistics(columns)
    assert s["line[1].maxUtilisationMax"] == 0.3 and s["line[1].maxUtilisationMean"] == pytest.approx(0.2)
    assert s["line[1].fairleadTensionMax"] == 3e5 and s["line[2].fairleadTensionMax"] == 5e5
    assert s["line[2].MBL"] == 0.0 and "line[2].maxUtilisationMax" not in s
    rows = [{**s, "status": "ok", "towTensionMax": 3e5}, {**s, "status": "error"}]
    maxima = realisation_maxima(rows)
    assert list(maxima) == ["line 1", "line 2"]
    assert maxima["line 2"][0].tolist() == [5e5] and maxima["line 1"][1] == 1e6


def test_a_run_records_a_boolean_output_such_as_a_lines_broken_flag(fmu_file):
    """Line failure's line[k].broken may be a Boolean: a run reads it with the Reals, as 0 or 1."""
    from ucable.scene import recorded_reader

    cable = CableFMU(fmu_file, parameters={"enableSeabed": True})
    try:
        cable.initialize(inputs={"tow.z": -10.0})
        row = recorded_reader(cable, ["towTension", "enableSeabed", "endPosition.z"])()
        assert row.tolist() == [cable.get("towTension"), 1.0, cable.get("endPosition.z")]
    finally:
        cable.free()
