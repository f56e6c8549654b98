"""Bit-for-bit regression against tests/data/golden: refactors that must not change the numbers
(the variable schema, the compiled line description, one section described by the scalar
parameters) reproduce every output of three short scenes exactly (python/studies/cases/golden.py); the
Vessel partner FMU without waves (waves.mode 0, whatever the other wave parameters) reproduces every
output of a manoeuvre recorded before it had any (its heading loop's integral pole at 0: the PD it had then)."""

import json

import pytest

from studies.cases.golden import GOLDEN_DIR, SCENES, VESSEL_SCENES, run_scene, run_vessel_scene


@pytest.mark.parametrize("scene", sorted(SCENES))
def test_outputs_equal_golden_bit_for_bit(fmu_file, scene):
    compare(scene, run_scene(scene, fmu_file))


@pytest.mark.parametrize("scene", sorted(VESSEL_SCENES))
@pytest.mark.parametrize("waves", [{}, {"waves.mode": 0, "waves.height": 3.0, "waves.period": 7.0,
                                        "waves.direction": 1.0, "waves.rampTime": 5.0}])
def test_vessel_without_waves_equals_golden_bit_for_bit(fmu_file, scene, waves):
    compare(scene, run_vessel_scene(scene, parameters=waves))


def compare(scene, got):
    expected = json.loads((GOLDEN_DIR / f"{scene}.json").read_text())
    assert got["time"] == expected["time"]
    missing = sorted(set(expected["outputs"]) - set(got["outputs"]))
    assert not missing, f"outputs gone: {missing}"
    for name, values in expected["outputs"].items():
        if got["outputs"][name] != values:
            k = next(i for i, (a, b) in enumerate(zip(got["outputs"][name], values)) if a != b)
            pytest.fail(f"{scene}: {name} differs first at point {k}: "
                        f"{float.fromhex(got['outputs'][name][k])!r} != {float.fromhex(values[k])!r}")
