"""`ucable.CableFMU` with several instances alive: each instance's messages reach that instance,
and freeing one leaves the others' logging intact (fmpy's logger proxy keeps one logger per
process, so the wrapper registers one process-wide logger and routes by componentEnvironment)."""

import subprocess
import textwrap
from pathlib import Path

import pytest

from ucable.fmu import CableFMU, FMICallException

PYTHON = Path(__file__).resolve().parents[2] / "python"


def provoke_error(unit):
    """A NaN input: the FMU refuses it with an ERROR message naming the variable."""
    with pytest.raises(FMICallException):
        unit.set({"tow.x": float("nan")})


def errors(unit):
    return [m for s, _, m in unit.messages if s == "ERROR"]


def test_each_instance_receives_its_own_messages(fmu_file):
    first = CableFMU(fmu_file, instance_name="first", logging_on=True)
    second = CableFMU(fmu_file, instance_name="second", logging_on=True)
    try:
        first.initialize()
        second.initialize()
        provoke_error(first)
        assert any("tow.x" in m for m in errors(first)), first.log_text()
        assert errors(second) == [], second.log_text()
        provoke_error(second)
        assert len(errors(second)) == 1 and len(errors(first)) == 1
    finally:
        first.free()
        second.free()


def test_freeing_one_instance_leaves_the_other_logging(fmu_file, venv_python):
    """In a child process (a dangling logger crashes the process, exit 139): the second instance is
    freed and collected, then the first one logs."""
    script = textwrap.dedent(f"""
        import gc, sys
        sys.path.insert(0, {str(PYTHON)!r})
        from ucable.fmu import CableFMU, FMICallException
        first = CableFMU({str(fmu_file)!r}, instance_name="first", logging_on=True)
        second = CableFMU({str(fmu_file)!r}, instance_name="second", logging_on=True)
        first.initialize()
        second.free()
        del second
        gc.collect()
        try:
            first.set({{"tow.x": float("nan")}})
        except FMICallException:
            pass
        print(sum(1 for s, _, m in first.messages if s == "ERROR" and "tow.x" in m))
        first.free()
    """)
    done = subprocess.run([venv_python, "-c", script], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "1"
