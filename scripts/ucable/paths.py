"""Where things are: the repository root and the packed FMU."""

from __future__ import annotations

import os
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parents[2]
DEFAULT_FMU = REPO_ROOT / "build" / "UnderwaterCable.fmu"


class MissingFMUError(FileNotFoundError):
    pass


def fmu_path() -> Path:
    """build/UnderwaterCable.fmu, or the file named by the environment variable UC_FMU."""
    env = os.environ.get("UC_FMU")
    return Path(env).expanduser().resolve() if env else DEFAULT_FMU


def require_fmu() -> Path:
    """The FMU path; raises MissingFMUError with the command that builds it if it is not there."""
    path = fmu_path()
    if not path.is_file():
        raise MissingFMUError(
            f"UnderwaterCable FMU not found at {path}: build first: scripts/build "
            f"(or point UC_FMU at an FMU)")
    return path
