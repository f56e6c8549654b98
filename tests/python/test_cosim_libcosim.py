"""A second FMI importer and master: DNV's libcosim (libcosimpy) runs the Hopland acceleration.

libcosim has its own FMU loader (FMI Library) and calls the same FMI functions in the same order
as studies.cases.manoeuvre.run_tow with plain sampling (set inputs, doStep), so the results must be
bit-identical: the FMU is deterministic and keeps no state outside its instance.
"""

import numpy as np
import pytest

from ucable.fmu import CableFMU
from studies.cases.manoeuvre import hopland_accelerate, run_tow

from studies.cosim import libcosim_scene  # libcosimpy is in requirements.txt: missing = failure


def test_libcosim_and_fmpy_masters_agree_bit_for_bit(fmu_file):
    t_end = 200.0
    time, lc = libcosim_scene.run_hopland_libcosim(fmu_file, step=0.5, t_end=t_end)
    profile, _ = hopland_accelerate()
    cable = CableFMU(fmu_file, parameters={"nElements": 20})
    try:
        run = run_tow(cable, profile, t_end, 0.5, record_shape=False, use_input_derivatives=False)
    finally:
        cable.free()
    assert np.array_equal(time, run.time)
    for name in ("towTension", "endPosition.z"):
        a, b = lc[name][1:], run[name][1:]
        assert np.all(np.isfinite(a))
        assert np.array_equal(a, b), f"{name}: max difference {np.max(np.abs(a - b))}"
