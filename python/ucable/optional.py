"""Optional dependencies: a module the package needs for one feature only (libcosimpy for the libcosim
master), and the one-line message, with the command that installs it, when a module is missing."""

from __future__ import annotations

import importlib

INSTALL = {  # top-level module -> what installs it
    "libcosimpy": 'pip install "ucable[libcosim]" (or: pip install libcosimpy)',
    "dask": 'pip install "dask[distributed]"',
    "distributed": 'pip install "dask[distributed]"',
    "matplotlib": "pip install matplotlib",
    "scipy": "pip install scipy",
    "numpy": "pip install numpy",
    "fmpy": "pip install fmpy",
    "PIL": "pip install pillow",
}


class MissingDependencyError(ModuleNotFoundError):
    """A module a feature needs is not installed; the message names the feature and the install command."""


def missing_message(exc: ImportError, purpose: str | None = None) -> str:
    """'the Python module M is not installed (needed for PURPOSE): install it with: CMD'."""
    if isinstance(exc, MissingDependencyError):
        return str(exc)
    module = (exc.name or str(exc)).split(".")[0]
    needed = f" (needed for {purpose})" if purpose else ""
    how = INSTALL.get(module, f"pip install {module}")
    return f"the Python module {module!r} is not installed{needed}: install it with: {how}"


def require(module: str, purpose: str):
    """The module, imported; a MissingDependencyError naming `purpose` and the install command if it
    cannot be imported."""
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        raise MissingDependencyError(missing_message(exc, purpose), name=module) from None
