"""Every tolerance a user can set works: relTol and absTol from 1e-3 to 1e-10 on a tow cable (the
Hopland manoeuvre) and an anchored line with bending stiffness (the stiff power cable), short runs
of the error-control scenes (docs/error_control.md). Each run completes, and its top tension
converges as the tolerance falls: the error against a tight run (tensionTolerance 1e-8 with the
same setting at 1e-10) never grows as the setting is tightened. relTol |y| counts |y| at least at
the unknown's scale (the line's length for a position, 1 for a tangent, these over the damping time
for their rates): with |y| alone a rate or tangent component passing through 0 asked for an error of
0, and relTol 1e-6 stopped the tow cable at t = 2e-7 s (IDA_TOO_MUCH_WORK)."""

import dataclasses

import numpy as np
import pytest

from studies.error_control import errors, run, scenes

SETTINGS = (1e-3, 1e-5, 1e-7, 1e-10)
DURATION = {"hopland": 5.0, "stiff": 2.0}


@pytest.fixture(scope="module")
def short_scenes():
    sc = scenes(short=True)
    return {name: dataclasses.replace(sc[name], t_end=t) for name, t in DURATION.items()}


@pytest.mark.parametrize("name", list(DURATION))
@pytest.mark.parametrize("key", ["relTol", "absTol"])
def test_the_run_completes_and_converges_as_the_tolerance_falls(fmu_file, short_scenes, name, key):
    scene = short_scenes[name]
    ref = run(fmu_file, scene, {"tensionTolerance": 1e-8, key: 1e-10})
    errs = []
    for tol in SETTINGS:
        r = run(fmu_file, scene, {key: tol})  # raises where the FMU fails
        assert np.all(np.isfinite(r.tension))
        errs.append(errors(r, ref)["max_newton"])
    # never worse for a tighter setting (to the last digits of the tension, 1e-9 of the scale)
    slack = 1e-9 * ref.tension_scale
    assert all(b <= a + slack for a, b in zip(errs, errs[1:])), errs
    # and within the default tension tolerance (1e-3 x solver.tensionScale) at every setting
    assert max(errs) <= 1e-3 * ref.tension_scale, errs
