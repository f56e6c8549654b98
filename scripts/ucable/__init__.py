"""Python helpers for the UnderwaterCable FMU: locate it, drive it through fmpy, fly tow
manoeuvres, and an independent steady towed-cable solution to check it against.

Importable as `ucable` with scripts/ on sys.path (tests/python/conftest.py does that).
"""

from .paths import REPO_ROOT, fmu_path, require_fmu, MissingFMUError  # noqa: F401
from .steady_tow import KNOT  # noqa: F401
