"""pytest set-up: makes python/ importable (the `ucable` package and the `studies`) and provides the FMU path.

Tests that need the FMU use the `fmu_file` fixture. When the FMU has not been built they FAIL in
CI (CI=true) and are skipped elsewhere, both with the message "build first: scripts/build".
"""

import os
import sys
from pathlib import Path

import pytest

REPO_ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO_ROOT / "python"))

from ucable.paths import MissingFMUError, require_fmu  # noqa: E402


def _in_ci() -> bool:
    return os.environ.get("CI", "").lower() in ("1", "true", "yes")


@pytest.fixture(scope="session")
def fmu_file() -> Path:
    try:
        return require_fmu()
    except MissingFMUError as e:
        if _in_ci():
            pytest.fail(str(e), pytrace=False)
        pytest.skip(str(e))


@pytest.fixture(scope="session")
def fmi3_file(fmu_file) -> Path:
    """The FMI 3.0 variant built beside the FMU (scripts/build)."""
    path = fmu_file.parent / "fmi3" / "UnderwaterCable.fmu"
    if not path.is_file():
        pytest.fail(f"no FMI 3.0 FMU at {path}: build first: scripts/build", pytrace=False)
    return path


@pytest.fixture(scope="session")
def venv_python() -> str:
    """The interpreter running the tests (the .venv one when run through scripts/test)."""
    return sys.executable


@pytest.fixture
def make_unit():
    """Factory of FMU instances (the cable or a partner FMU, by path), all freed at the end of the
    test; the logs of those that logged are printed (pytest shows them when the test fails)."""
    from ucable.fmu import CableFMU

    made = []

    def factory(path, **kwargs):
        unit = CableFMU(path, **kwargs)
        made.append(unit)
        return unit

    yield factory
    for unit in made:
        if unit.messages:
            print(f"--- FMU log of {unit.slave.instanceName}:\n{unit.log_text()}")
        unit.free()


@pytest.fixture
def make_cable(fmu_file, make_unit):
    """Factory of cable FMU instances (make_unit on the cable's FMU)."""
    return lambda **kwargs: make_unit(fmu_file, **kwargs)


@pytest.fixture
def graded_state_continuation(fmu_file):
    """continuation(parameters, tow_z, elsewhere, outputs) -> (first, second): an anchored line started
    with its tow point at (0, 0, tow_z) steps 2 s of surge, its state is serialized, and it steps 3 s
    more (first); a fresh instance initialized with the tow point moved by `elsewhere` (another mesh)
    takes the state and steps the same 3 s (second). A state that carries its mesh gives equal arrays."""
    import math

    import numpy as np
    from ucable.fmu import CableFMU

    def advance(c, t0, steps, tow_z, outputs):
        out = []
        for k in range(steps):
            t = t0 + 0.5 * k
            c.set({"tow.x": math.sin(0.3 * (t + 0.5)), "tow.vx": 0.3 * math.cos(0.3 * (t + 0.5)), "tow.z": tow_z})
            c.do_step(0.5, t=t)
            out.append(c.get_reals(outputs))
        return np.array(out)

    def continuation(parameters, tow_z, elsewhere, outputs):
        with CableFMU(fmu_file, parameters=parameters) as c, CableFMU(fmu_file, parameters=parameters) as fresh:
            c.initialize(inputs={"tow.z": tow_z})
            advance(c, 0.0, 4, tow_z, outputs)
            data = c.serialize_state(state := c.get_state())
            c.free_state(state)
            first = advance(c, 2.0, 6, tow_z, outputs)
            fresh.initialize(inputs={**elsewhere, "tow.z": tow_z})
            restored = fresh.deserialize_state(data)
            fresh.set_state(restored)
            second = advance(fresh, 2.0, 6, tow_z, outputs)
            fresh.free_state(restored)
        return first, second

    return continuation


@pytest.fixture(scope="session")
def towfish_fmu(tmp_path_factory) -> Path:
    """Towfish.fmu: a towed body FMU of "another vendor" (tests/third_party_body), built for this session
    by its own script, outside the project's CMake (the C compiler and zip, nothing else)."""
    import subprocess

    out = tmp_path_factory.mktemp("third_party_body")
    proc = subprocess.run(["bash", str(REPO_ROOT / "tests" / "third_party_body" / "build.sh"), str(out)],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return out / "Towfish.fmu"
