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

from studies.benchmarks.error_control import errors, run, scenes

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


def test_a_deck_with_bending_stiffness_runs_at_a_tight_reltol(fmu_file):
    """MoorDyn's flexible jumper deck (Lowe and Langley 2006: 170 m, EI 120.8 kN m2), its top surging
    1 m with a 10 s period for 2 s: relTol 1e-5 stopped at t = 1 ms; now relTol 1e-5 and 1e-10
    complete, and the tighter one is closer to a run at tensionTolerance 1e-7."""
    import math

    from studies.comparisons import public_decks as pd
    from ucable.fmu import CableFMU

    def top_tension(extra):
        c = CableFMU(fmu_file, parameters={"lineFile": str(pd.PUBLIC / "md_tests_Mooring_lowe_and_langley_2006_line.txt"),
                                           **extra})
        try:
            c.initialize(inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": -5.0})
            t, h, a, w = 0.0, 0.05, 1.0, 2.0 * math.pi / 10.0
            for _ in range(40):
                t1 = t + h
                c.set({"tow.x": a * math.sin(w * t1), "tow.vx": a * w * math.cos(w * t1),
                       "tow.ax": -a * w * w * math.sin(w * t1)})
                c.do_step(h, t)
                t = t1
            return c.get("towTension")
        finally:
            c.free()

    ref = top_tension({"tensionTolerance": 1e-7})
    loose, tight = top_tension({"relTol": 1e-5}), top_tension({"relTol": 1e-10})
    assert abs(tight - ref) < abs(loose - ref)
