"""ucable: the UnderwaterCable FMU from Python.

    import ucable
    ucable.fmu_path()                      # the FMU (installed with the package, or a clone's build/)
    cable = ucable.CableFMU(parameters={"length": 300.0})   # one instance, variables by name
    result = ucable.run_scene("hopland_accelerate", overrides={"Cdn": 1.4})   # a scene file, run
    result["towTension"]                   # named outputs as numpy arrays
    table = ucable.read_results("out/x/result.csv")   # a written table: table["towTension"] is "towTension [N]"

Scenes (TOML files: parameters, tow-point manoeuvre, step, duration) and the command line
(`ucable run`, `ucable sweep` on Dask) are in ucable.scene and ucable.cli; docs/package.md.
The repository's own scripts and tests use the same package (scripts/ on sys.path in a clone).
"""

__version__ = "0.1.0"

from .paths import REPO_ROOT, MissingFMUError, find_scene, fmi3_fmu_path, fmu_path, require_fmu, scenes_dir  # noqa: F401
from .units import KNOT  # noqa: F401


def __getattr__(name):  # the heavier modules load on first use
    if name == "CableFMU":
        from .fmu import CableFMU
        return CableFMU
    if name == "read_results":
        from .results import read_results
        return read_results
    if name in ("Scene", "load_scene", "run_scene", "SceneResult"):
        from . import scene
        return getattr(scene, name)
    raise AttributeError(f"module 'ucable' has no attribute {name!r}")
