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
