"""The Hopland acceleration (tow point prescribed, 1.1 -> 2.4 kn in 60 s) under a second master:
DNV's libcosim (Open Simulation Platform) through libcosimpy.

libcosim loads the FMU itself (its own FMI importer, not fmpy), runs it with a fixed step, and the
tow-point inputs are set before every step through an override manipulator. libcosim does not call
fmi2SetRealInputDerivatives, so the FMU estimates the tow acceleration from the velocity samples;
the matching fmpy run is studies.cases.manoeuvre.run_tow(use_input_derivatives=False).
"""

from __future__ import annotations

import math

import numpy as np

from ..cases.manoeuvre import TOW_INPUTS, hopland_accelerate, tow_inputs

OUTPUTS = ["towTension", "endPosition.z"]


def run_hopland_libcosim(fmu, step: float = 0.5, t_end: float | None = None, n_elements: int = 20):
    """(time, {output: values}) of the Hopland acceleration run by libcosim (row 0, the state
    after initialization, is NaN: the observer sees values only after the first step)."""
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimManipulator import CosimManipulator
    from libcosimpy.CosimObserver import CosimObserver
    from libcosimpy.CosimSlave import CosimLocalSlave

    log_output_level(CosimLogLevel.WARNING)
    profile, t_default = hopland_accelerate()
    t_end = t_default if t_end is None else t_end
    step_ns = int(round(step * 1e9))
    if abs(step_ns - step * 1e9) > 1e-3:
        raise ValueError("libcosim steps are integer nanoseconds")
    n = int(round(t_end / step))

    ex = CosimExecution.from_step_size(step_ns)
    idx = ex.add_local_slave(CosimLocalSlave(fmu_path=str(fmu), instance_name="cable"))
    vr = {v.name.decode(): v.reference for v in ex.slave_variables(idx)}
    ex.integer_initial_value(idx, vr["nElements"], n_elements)
    for name, value in tow_inputs(profile, 0.0).items():
        ex.real_initial_value(idx, vr[name], value)
    manip = CosimManipulator.create_override()
    ex.add_manipulator(manip)
    obs = CosimObserver.create_last_value()
    ex.add_observer(obs)
    refs_in = [vr[nm] for nm in TOW_INPUTS]
    refs_out = [vr[nm] for nm in OUTPUTS]

    time = np.arange(n + 1) * step
    values = np.full((n + 1, len(OUTPUTS)), math.nan)
    for k in range(n):
        inp = tow_inputs(profile, time[k])
        manip.slave_real_values(idx, refs_in, [inp[nm] for nm in TOW_INPUTS])
        if not ex.step():
            raise RuntimeError(f"libcosim step failed at t = {time[k]:g} s")
        values[k + 1] = obs.last_real_values(idx, refs_out)
    return time, {nm: values[:, i] for i, nm in enumerate(OUTPUTS)}
