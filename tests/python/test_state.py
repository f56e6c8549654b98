"""FMU state get/set and serialization through fmpy: restoring a state and continuing reproduces
the original continuation bit for bit (FMI 2.0 section 2.1.8), also in a fresh, never initialized
instance."""

import numpy as np
import pytest
from ucable.fmu import FMICallException

from studies.cases.manoeuvre import SCALAR_OUTPUTS, SHAPE_OUTPUTS, hopland_accelerate, tow_inputs

STEP = 0.5
T_SAVE = 20.0  # inside the acceleration ramp: the state is far from steady
T_CONT = 10.0
OUTPUTS = SCALAR_OUTPUTS + SHAPE_OUTPUTS


def advance(cable, profile, t0, duration):
    """Steps from t0 for `duration`, returns all outputs after every step (one array)."""
    rows = []
    n = int(round(duration / STEP))
    for k in range(n):
        t = t0 + k * STEP
        cable.set(tow_inputs(profile, t))
        cable.do_step(STEP, t=t)
        rows.append(cable.get_reals(OUTPUTS))
    return np.array(rows)


def test_restored_state_continues_bit_identically(make_cable):
    profile, _ = hopland_accelerate()
    cable = make_cable(parameters={"nElements": 20})
    cable.initialize(inputs=tow_inputs(profile, 0.0))
    advance(cable, profile, 0.0, T_SAVE)
    at_save = cable.get_reals(OUTPUTS)
    state = cable.get_state()
    first = advance(cable, profile, T_SAVE, T_CONT)

    cable.set_state(state)
    assert np.array_equal(cable.get_reals(OUTPUTS), at_save)
    second = advance(cable, profile, T_SAVE, T_CONT)
    assert np.array_equal(first, second), f"max difference {np.max(np.abs(first - second))}"

    data = cable.serialize_state(state)
    restored = cable.deserialize_state(data)
    assert cable.serialize_state(restored) == data
    cable.set_state(restored)
    third = advance(cable, profile, T_SAVE, T_CONT)
    assert np.array_equal(first, third), f"max difference {np.max(np.abs(first - third))}"
    cable.free_state(restored)
    cable.free_state(state)


def test_serialized_state_continues_in_a_fresh_uninitialized_instance(make_cable):
    """What fmusim --initial-fmu-state-file and fmpy simulate_fmu(fmu_state=...) do."""
    profile, _ = hopland_accelerate()
    cable = make_cable(instance_name="origin", parameters={"nElements": 20})
    cable.initialize(inputs=tow_inputs(profile, 0.0))
    advance(cable, profile, 0.0, T_SAVE)
    state = cable.get_state()
    data = cable.serialize_state(state)
    cable.free_state(state)
    first = advance(cable, profile, T_SAVE, T_CONT)

    fresh = make_cable(instance_name="fresh", parameters={"nElements": 20})
    restored = fresh.deserialize_state(data)
    fresh.set_state(restored)
    second = advance(fresh, profile, T_SAVE, T_CONT)
    fresh.free_state(restored)
    assert np.array_equal(first, second), f"max difference {np.max(np.abs(first - second))}"


@pytest.mark.parametrize("damage", ["truncated", "garbage", "flipped-header"])
def test_a_refused_serialized_state_leaves_a_fresh_instance_to_run_with_its_own_parameters(make_cable, damage):
    """fmi2DeSerializeFMUstate of a truncated, garbage or foreign buffer is refused and changes nothing: the
    fresh instance then initializes and runs with its own parameters bit for bit as one that never saw the
    call (the refusal put it into the error state, where it could neither initialize nor step)."""
    profile, _ = hopland_accelerate()
    origin = make_cable(instance_name="origin", parameters={"nElements": 20})
    origin.initialize(inputs=tow_inputs(profile, 0.0))
    advance(origin, profile, 0.0, 2.0)
    data = origin.serialize_state(state := origin.get_state())
    origin.free_state(state)
    damaged = {"truncated": data[: len(data) // 2],
               "garbage": bytes((37 * k + 11) % 256 for k in range(len(data))),
               "flipped-header": data[:8] + bytes([data[8] ^ 0x7F]) + data[9:]}[damage]
    runs = []
    for refused in (True, False):
        fresh = make_cable(instance_name="fresh", parameters={"nElements": 12, "length": 250.0})
        if refused:
            with pytest.raises(FMICallException):
                fresh.deserialize_state(damaged)
            assert "fmi2DeSerializeFMUstate" in fresh.log_text()
        fresh.initialize(inputs=tow_inputs(profile, 0.0))
        runs.append(advance(fresh, profile, 0.0, 2.0))
        assert fresh.get("length") == 250.0 and fresh.get("nElements") == 12
    assert np.isfinite(runs[0]).all()
    assert runs[0].tobytes() == runs[1].tobytes()
