"""FMU state get/set and serialization through fmpy: restoring a state and continuing reproduces
the original continuation bit for bit (FMI 2.0 section 2.1.8), also in a fresh, never initialized
instance."""

import numpy as np

from studies.manoeuvre import SCALAR_OUTPUTS, SHAPE_OUTPUTS, hopland_accelerate, tow_inputs

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
