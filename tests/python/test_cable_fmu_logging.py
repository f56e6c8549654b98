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


def run_child(venv_python, body: str):
    """Runs `body` in a child process with the package importable (a crash there is its exit code,
    139 for a segmentation fault, not the test run's)."""
    script = f"import gc, sys\nsys.path.insert(0, {str(PYTHON)!r})\n" + textwrap.dedent(body)
    return subprocess.run([venv_python, "-c", script], capture_output=True, text=True, timeout=300)


def test_other_fmpy_logger_proxy_users_leave_cable_fmu_logging(fmu_file, venv_python):
    """fmpy.simulate_fmu(..., logger=f) registers its own logger with fmpy's process-wide proxy
    (before, between and after CableFMUs): each instance still receives its own messages, and the
    process ends normally."""
    done = run_child(venv_python, f"""
        from fmpy import simulate_fmu
        from ucable.fmu import CableFMU, FMICallException
        fmu = {str(fmu_file)!r}
        seen = []
        def simulate():
            simulate_fmu(fmu, stop_time=1.0, output_interval=0.5, logger=lambda *a: seen.append(a[2]))
        def provoke(unit):
            try:
                unit.set({{"tow.x": float("nan")}})
            except FMICallException:
                pass
            return sum(1 for s, _, m in unit.messages if s == "ERROR" and "tow.x" in m)
        simulate()
        gc.collect()
        first = CableFMU(fmu, instance_name="first")
        first.initialize()
        simulate()
        gc.collect()
        counts = [provoke(first)]
        second = CableFMU(fmu, instance_name="second")
        second.initialize()
        third = CableFMU(fmu, instance_name="third")
        third.initialize()
        simulate()
        gc.collect()
        counts.append(provoke(second))
        first.free()
        second.free()
        simulate()
        gc.collect()
        counts.append(provoke(third))
        third.free()
        print(counts)
    """)
    assert done.returncode == 0, f"exit {done.returncode}: {done.stderr[-2000:]}"
    assert done.stdout.strip().splitlines()[-1] == "[1, 1, 1]"


def test_instances_dropped_without_free_are_freed(fmu_file, venv_python):
    """CableFMUs dropped without free() (initialized, as a script that forgets free() leaves them) are
    collected and their FMU instances freed: 150 of them grow the resident memory by far less than
    one instance's size per instance (about 400 KiB when they leaked)."""
    done = run_child(venv_python, f"""
        import weakref
        from ucable.fmu import CableFMU
        def rss_kib():
            for line in open("/proc/self/status"):
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
        def one():
            unit = CableFMU({str(fmu_file)!r})
            unit.initialize()
            unit.do_step(0.5, 0.0)
            return weakref.ref(unit)
        for _ in range(30):  # warm up: the library, the allocator's arenas
            one()
        gc.collect()
        before = rss_kib()
        refs = [one() for _ in range(150)]
        gc.collect()
        after = rss_kib()
        print(sum(r() is not None for r in refs), (after - before) / 150)
    """)
    assert done.returncode == 0, done.stderr[-2000:]
    alive, per_instance_kib = done.stdout.split()
    assert alive == "0"
    assert float(per_instance_kib) < 40.0, f"{per_instance_kib} KiB per instance dropped without free()"


def test_instances_alive_at_exit_are_freed_cleanly(fmu_file, venv_python):
    done = run_child(venv_python, f"""
        from ucable.fmu import CableFMU
        kept = [CableFMU({str(fmu_file)!r}, logging_on=True) for _ in range(3)]
        for unit in kept:
            unit.initialize()
            unit.do_step(0.5, 0.0)
        print("exiting")
    """)
    assert done.returncode == 0 and done.stdout.strip() == "exiting", done.stderr[-2000:]
