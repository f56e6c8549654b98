"""The packed FMU passes fmpy's validation and runs from fmpy's command line."""

import csv
import math
import subprocess
import sys
from pathlib import Path

import pytest
from fmpy import read_model_description
from fmpy.validation import validate_fmu


def fmpy_command() -> list:
    exe = Path(sys.executable).parent / "fmpy"  # the console script of the interpreter's venv
    return [str(exe)] if exe.exists() else [sys.executable, "-m", "fmpy.command_line"]


def test_fmpy_validation_finds_no_problems(fmu_file):
    assert validate_fmu(str(fmu_file)) == []


def test_model_description_declares_what_the_design_promises(fmu_file):
    md = read_model_description(str(fmu_file))
    assert md.fmiVersion == "2.0"
    cs = md.coSimulation
    assert cs.modelIdentifier == "UnderwaterCable"
    assert cs.canHandleVariableCommunicationStepSize
    assert cs.canGetAndSetFMUstate and cs.canSerializeFMUstate
    assert not cs.canBeInstantiatedOnlyOncePerProcess
    names = {v.name for v in md.modelVariables}
    for name in ["tow.x", "tow.vx", "towTension", "towForce.z", "endPosition.z", "shape.x[1]",
                 "shape.z[21]", "tension[21]", "length", "diameter", "nElements", "initMode"]:
        assert name in names


def _run_cli(fmu_file, tmp_path, stop_time):
    out = tmp_path / "result.csv"
    cmd = fmpy_command() + ["simulate", str(fmu_file), "--output-file", str(out),
                            "--output-variables", "towTension", "endPosition.z"]
    if stop_time is not None:
        cmd += ["--stop-time", str(stop_time)]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, f"fmpy simulate failed:\n{proc.stdout}\n{proc.stderr}"
    with out.open() as f:
        rows = list(csv.DictReader(f))
    assert len(rows) > 1
    for row in rows:
        for key in ("towTension", "endPosition.z"):
            assert math.isfinite(float(row[key]))
    return rows


def test_fmpy_simulate_command_line_short_run(fmu_file, tmp_path):
    rows = _run_cli(fmu_file, tmp_path, stop_time=20)
    assert float(rows[-1]["time"]) == pytest.approx(20.0)


@pytest.mark.slow
def test_fmpy_simulate_command_line_default_experiment(fmu_file, tmp_path):
    md = read_model_description(str(fmu_file))
    rows = _run_cli(fmu_file, tmp_path, stop_time=None)
    assert float(rows[-1]["time"]) == pytest.approx(float(md.defaultExperiment.stopTime))
