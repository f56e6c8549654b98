"""Bit-for-bit regression against tests/data/golden: refactors that must not change the numbers
(the variable schema, the compiled line description, one section described by the scalar
parameters) reproduce every output of three short scenes exactly (scripts/ucable/golden.py)."""

import json

import pytest

from ucable.golden import GOLDEN_DIR, SCENES, run_scene


@pytest.mark.parametrize("scene", sorted(SCENES))
def test_outputs_equal_golden_bit_for_bit(fmu_file, scene):
    expected = json.loads((GOLDEN_DIR / f"{scene}.json").read_text())
    got = run_scene(scene, fmu_file)
    assert got["time"] == expected["time"]
    missing = sorted(set(expected["outputs"]) - set(got["outputs"]))
    assert not missing, f"outputs gone: {missing}"
    for name, values in expected["outputs"].items():
        if got["outputs"][name] != values:
            k = next(i for i, (a, b) in enumerate(zip(got["outputs"][name], values)) if a != b)
            pytest.fail(f"{scene}: {name} differs first at point {k}: "
                        f"{float.fromhex(got['outputs'][name][k])!r} != {float.fromhex(values[k])!r}")
