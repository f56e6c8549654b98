"""Where things are: the packed FMU, the scenes, and (in a clone) the repository root.

Installed with `pip install .`, the package holds the FMUs, the scenes and the system files itself;
run from a clone (the package on sys.path) they are the build's FMUs and the repository's scenes/ and
systems/. UC_FMU names another FMU.
"""

from __future__ import annotations

import os
from pathlib import Path

PACKAGE_DIR = Path(__file__).resolve().parent
REPO_ROOT = PACKAGE_DIR.parents[1]  # meaningful in a clone only (docs, out/ of the repository scripts)
PACKAGED_FMU = PACKAGE_DIR / "UnderwaterCable.fmu"
DEFAULT_FMU = PACKAGED_FMU if PACKAGED_FMU.is_file() else REPO_ROOT / "build" / "UnderwaterCable.fmu"


class MissingFMUError(FileNotFoundError):
    pass


def fmu_path() -> Path:
    """The FMU: the file named by the environment variable UC_FMU, else the one installed with the
    package, else build/UnderwaterCable.fmu of the clone the package is imported from."""
    env = os.environ.get("UC_FMU")
    return Path(env).expanduser().resolve() if env else DEFAULT_FMU


def require_fmu() -> Path:
    """The FMU path; raises MissingFMUError with the command that builds it if it is not there."""
    path = fmu_path()
    if not path.is_file():
        raise MissingFMUError(
            f"UnderwaterCable FMU not found at {path}: build first: scripts/build, or pip install the "
            f"repository (or point UC_FMU at an FMU)")
    return path


def fmi3_fmu_path() -> Path:
    """The FMI 3.0 variant beside the FMU: fmi3/UnderwaterCable.fmu in the package or the build."""
    return fmu_path().parent / "fmi3" / "UnderwaterCable.fmu"


def fmu_platforms(path: Path) -> list[str]:
    """The platforms an FMU carries binaries for (the folders under binaries/ of the zip)."""
    import zipfile

    with zipfile.ZipFile(path) as z:
        return sorted({n.split("/")[1] for n in z.namelist() if n.startswith("binaries/") and n.count("/") >= 2
                       and n.split("/")[1]})


WIN64_HINT = ("for win64 as well: bash scripts/setup --platforms linux64,win64, then pip install . again "
              "(or bash scripts/build --platforms linux64,win64 in a clone)")


def describe_fmus() -> str:
    """One line: the platforms of the FMU and of its FMI 3.0 variant, and how to get win64 when missing."""
    fmu = require_fmu()
    said = f"FMI 2.0: {', '.join(fmu_platforms(fmu)) or 'no binaries'}"
    fmi3 = fmi3_fmu_path()
    if fmi3.is_file():
        said += f"; FMI 3.0 variant {fmi3}: {', '.join(fmu_platforms(fmi3)) or 'no binaries'}"
    else:
        said += "; no FMI 3.0 variant beside it"
    if not any(p in ("win64", "x86_64-windows") for p in fmu_platforms(fmu)):
        said += f"; {WIN64_HINT}"
    return said


def scenes_dir() -> Path:
    """The scene files: installed with the package, or the clone's scenes/."""
    packaged = PACKAGE_DIR / "scenes"
    return packaged if packaged.is_dir() else REPO_ROOT / "scenes"


def systems_dir() -> Path:
    """The OSP system structure files (one folder per system): installed with the package, or the
    clone's systems/."""
    packaged = PACKAGE_DIR / "systems"
    return packaged if packaged.is_dir() else REPO_ROOT / "systems"


def scene_format_doc() -> Path:
    """The scene format's reference (docs/scenes.md): installed with the package, or the clone's."""
    packaged = PACKAGE_DIR / "scenes.md"
    return packaged if packaged.is_file() else REPO_ROOT / "docs" / "scenes.md"


def find_scene(name: str | Path) -> Path:
    """A scene file: the path as given if it exists, else a scene of that name (with or without
    .toml, with or without a scenes/ prefix) among the packaged ones."""
    path = Path(name).expanduser()
    if path.is_file():
        return path.resolve()
    candidate = scenes_dir() / Path(path.name).with_suffix(".toml").name
    if candidate.is_file():
        return candidate
    known = ", ".join(sorted(p.stem for p in scenes_dir().glob("*.toml")))
    raise FileNotFoundError(f"no scene {str(name)!r}: not a file, and not one of the packaged scenes ({known})")
