"""Inadmissible parameters give fmi2Error with a logged message naming the variable
(schema/variables.toml holds each range and its reason), and another live instance of the same FMU is not disturbed."""

import math

import pytest
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import fmi2Error

from studies.cases.manoeuvre import constant_speed, run_tow
from ucable.units import KNOT

BAD = [
    ("length", -300.0),
    ("diameter", math.nan),
    ("diameter", 0.0),
    ("nElements", 0),
]


def set_and_initialize(cable, name, value):
    cable.slave.setupExperiment(startTime=0.0)
    cable.set({name: value})  # may already fail here (fmi2SetReal/Integer) ...
    cable.set({"tow.vx": 1.1 * KNOT})
    cable.slave.enterInitializationMode()
    cable.slave.exitInitializationMode()  # ... or here, when the parameters are checked


@pytest.mark.parametrize("name,value", BAD, ids=[f"{n}={v}" for n, v in BAD])
def test_bad_parameter_is_an_error_that_names_the_variable(make_cable, name, value):
    good = make_cable(instance_name="good")
    good.initialize(inputs={"tow.vx": 1.1 * KNOT})

    bad = make_cable(instance_name="bad", logging_on=True)
    with pytest.raises(FMICallException) as err:
        set_and_initialize(bad, name, value)
    assert err.value.status == fmi2Error, f"{err.value.function} returned {err.value.status}"
    errors = [m for status, _, m in bad.messages if status == "ERROR"]
    assert errors, f"no error message was logged; log:\n{bad.log_text()}"
    assert any(name in m for m in errors), f"no error message names {name!r}: {errors}"

    # the other instance carries on
    run = run_tow(good, constant_speed(1.1 * KNOT), t_end=5.0, step=0.5, initialize=False,
                  record_shape=False)
    assert math.isfinite(run["towTension"][-1]) and run["towTension"][-1] > 0
