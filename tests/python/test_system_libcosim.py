"""libcosim starts every shipped system file (systems/*/OspSystemStructure.xml) and runs it as the fmpy
master does.

libcosim reads every unit's outputs in initialization mode before it has set any input, and ends the
process when an FMU answers fmi2Error. The cable with a driven far end (bottomEnd 3) has both ends on the
origin then, where no initialization exists: it answers fmi2Warning with provisional outputs (all 0, the
far end at its inputs) and initializes when its inputs arrive (docs/cosimulation.md). Each run is a
process of its own, so that such an end is a failed test, not a lost test session.

Sane: the run is the fmpy master's with the calls of libcosim's fixed-step algorithm (Jacobi ordering,
no input derivatives; docs/cosimulation.md, "libcosim against fmpy"), and its tow tension is positive and
finite. Bit-identical where the communication points are exact in binary (0.5 s); at 0.2 s and 0.01 s the
two masters' times differ by round-off (libcosim counts nanoseconds), which moves the integrator's step
sequence: the tow tensions then agree within the cable's error control, tensionTolerance times its
tension scale (measured 0.11 N of 8.2 kN for the explicit system against the 8 N bound). The explicit system (the body integrating itself) runs at 0.01 s, where
that coupling is stable for its 400 kg body (unstable from 0.02 s under Jacobi, docs/cosimulation.md).
"""

import json
import subprocess
import sys

import numpy as np
import pytest

from ucable import system as S
from ucable.fmu import FMICallException

STEPS = {"towed_body_explicit": 0.01}
DURATION = 10.0

RUN = """
import json, sys
import numpy as np
from ucable import system as S
from ucable.fmu import FMICallException
name, step, duration, out = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
r = S.run_named(name, "libcosim", step, duration)
np.savez(out, time=r.time, **{k.replace(".", "__"): v for k, v in r.values.items()})
"""


def fmpy_like_libcosim(name, step, duration):
    if name in S.COUPLING_OF_SYSTEM:
        return S.run("accelerate", step, S.COUPLING_OF_SYSTEM[name], "fmpy", "jacobi", duration=duration,
                     input_derivatives=False)
    return S.run_fmpy(S.load_named_system(name), {}, step, duration, "jacobi", input_derivatives=False)


@pytest.mark.parametrize("name", S.system_names())
def test_libcosim_starts_every_shipped_system(fmu_file, name, tmp_path):
    step = STEPS.get(name, S.load_named_system(name).step)
    out = tmp_path / "libcosim.npz"
    proc = subprocess.run([sys.executable, "-c", RUN, name, repr(step), repr(DURATION), str(out)],
                          capture_output=True, text=True, cwd=S.REPO_ROOT,
                          env={"PYTHONPATH": str(S.REPO_ROOT / "python"), "PATH": "/usr/bin:/bin",
                               **({"UC_FMU": str(fmu_file)})})
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    lc = np.load(out)
    T = lc["cable__towTension"]
    assert len(T) == round(DURATION / step) + 1 and np.all(np.isfinite(T)) and np.all(T > 0.0)
    ref = fmpy_like_libcosim(name, step, DURATION)
    if (step * 1024).is_integer():
        for key, values in ref.values.items():
            assert np.array_equal(lc[key.replace(".", "__")], values), key
    else:
        bound = 1e-3 * np.max(np.abs(ref["cable.towTension"]))  # tensionTolerance (its default) x tension
        assert np.max(np.abs(T - ref["cable.towTension"])) <= bound


def test_the_explicit_system_file_starts_at_the_steady_far_end(fmu_file):
    """The start values of the shipped explicit system are the steady far end of its body (to the 1e-9 m
    of the file's digits)."""
    system = S.load_named_system("towed_body_explicit")
    body, cable = system.simulators["body"].initial, system.simulators["cable"].initial
    b = S.Body(body["mass"], body["addedMass"], body["volume"], body["CdA"])
    start = S.steady_far_end(system, {"vessel": system.simulators["vessel"].initial}, b)
    for q in "xyz":
        assert body[f"position0.{q}"] == pytest.approx(start[f"position0.{q}"], abs=1e-9)
        assert body[f"velocity0.{q}"] == pytest.approx(start[f"velocity0.{q}"], abs=1e-9)
        assert cable[f"end.{q}"] == body[f"position0.{q}"] and cable[f"end.v{q}"] == body[f"velocity0.{q}"]


def read_status(unit, names):
    """(status, values) of one fmi2GetReal call."""
    from ctypes import c_double

    from fmpy.fmi2 import fmi2ValueReference

    vr = (fmi2ValueReference * len(names))(*[unit.variables[n].valueReference for n in names])
    values = (c_double * len(names))()
    status = unit.slave.fmi2GetReal(unit.slave.component, vr, len(names), values)
    return status, np.array(values)


def test_outputs_read_before_the_inputs_are_set_are_provisional_not_an_error(make_cable):
    """The cable at bottomEnd 3 with both ends still on the origin (the start values): no initialization
    exists. Reading outputs is fmi2Warning with the provisional values (all 0, the far end at its inputs),
    the reason logged once, every warning with its message; once the inputs are set the outputs are the initialization's, and
    fmi2ExitInitializationMode succeeds. Left at the origin, fmi2ExitInitializationMode is an error."""
    from fmpy.fmi2 import fmi2OK, fmi2Warning

    names = ["towForce.x", "towForce.z", "endForce.z", "towTension", "endPosition.x", "endPosition.z",
             "endVelocity.x"]
    cable = make_cable(instance_name="provisional")
    cable.slave.setupExperiment(startTime=0.0)
    cable.set({"bottomEnd": 3, "end.vx": 0.5})
    cable.slave.enterInitializationMode()
    for _ in range(2):  # the failed initialization is not repeated; each warning comes with its message
        status, values = read_status(cable, names)
        assert status == fmi2Warning
        assert np.array_equal(values, [0, 0, 0, 0, 0, 0, 0.5])
    warnings = [m for s, _, m in cable.messages if s == "WARNING"]
    assert len(warnings) == 3, cable.log_text()
    assert "static equilibrium not found" in warnings[0] and "provisional" in warnings[1]
    assert "still provisional" in warnings[2]
    cable.set({"tow.x": -10.0, "tow.vx": 0.5, "end.x": -75.5, "end.z": -291.8})
    status, values = read_status(cable, names)
    assert status == fmi2OK and values[3] > 1000.0 and values[4:6].tolist() == [-75.5, -291.8]
    cable.slave.exitInitializationMode()

    stuck = make_cable(instance_name="stuck")
    stuck.slave.setupExperiment(startTime=0.0)
    stuck.set({"bottomEnd": 3})
    stuck.slave.enterInitializationMode()
    assert read_status(stuck, names)[0] == fmi2Warning
    with pytest.raises(FMICallException):
        stuck.slave.exitInitializationMode()
