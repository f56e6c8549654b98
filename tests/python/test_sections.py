"""Lines of several sections and attachments through the FMI (docs/lines.md): inadmissible sections
and attachments are errors naming the variable; a lazy-wave umbilical (the one of docs/lines.md)
takes its shape."""

from __future__ import annotations

import math

import numpy as np
import pytest
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import fmi2Error

from studies.reports.lines_figure import LAZY_WAVE, SECTIONS, VESSEL_Z


def _section(k: int, **values) -> dict:
    return {f"section[{k}].{name}": value for name, value in values.items()}


BAD = [
    ("nSections", {"nSections": 9}),
    ("section[2].length", {"nSections": 2, **_section(1, length=100.0)}),  # section 2 has no length
    ("section[1].length", {"nSections": 2, **_section(1, length=-5.0), **_section(2, length=100.0)}),
    ("section[3].diameter", {"nSections": 3, **_section(3, diameter=0.0)}),
    ("attachment[1].s", {"nAttachments": 1, "attachment[1].s": 301.0, "attachment[1].mass": 10.0}),
    ("attachment[2].s", {"nAttachments": 2, "attachment[1].s": 100.0, "attachment[2].s": 0.0}),
    ("attachment[1].mass", {"nAttachments": 1, "attachment[1].s": 100.0, "attachment[1].mass": math.nan}),
    ("nAttachments", {"nAttachments": 9}),
]


@pytest.mark.parametrize("name,values", BAD, ids=[n for n, _ in BAD])
def test_bad_sections_and_attachments_are_errors_naming_the_variable(make_cable, name, values):
    cable = make_cable(logging_on=True)
    with pytest.raises(FMICallException) as err:
        cable.slave.setupExperiment(startTime=0.0)
        cable.set(values)
        cable.slave.enterInitializationMode()
        cable.slave.exitInitializationMode()
    assert err.value.status == fmi2Error
    errors = [text for status, _, text in cable.messages if status == "ERROR"]
    assert any(name in text for text in errors), errors


def test_a_lazy_wave_umbilical_hogs_over_its_buoyancy_section(make_cable):
    cable = make_cable(parameters=LAZY_WAVE)
    cable.initialize(inputs={"tow.z": VESSEL_Z})
    shape = cable.shape()
    x, z = shape["shape.x"], shape["shape.z"]
    s = np.linspace(0.0, 700.0, 21)
    buoyant = (s > 320.0) & (s < 440.0)
    # the buoyancy section lifts the line into a hog: its highest point is above the sag bend before
    # it and above the line after it
    sag = z[s <= 320.0].min()
    hog = z[buoyant].max()
    assert hog > sag + 5.0, (sag, hog)
    assert hog > z[s >= 480.0].max() + 5.0
    assert cable.get("touchdownArcLength") < 700.0 and cable.get("seabedContactForce") > 0.0
    # the whole weight in water and the seabed's reaction balance the two ends' forces
    rho, g = 1025.0, 9.81
    wet = sum((p["massPerLength"] - rho * math.pi * p["diameter"] ** 2 / 4) * length * g
              for length, _, p in SECTIONS)
    vertical = cable.get("towForce.z") + cable.get("endForce.z") - cable.get("seabedContactForce")
    assert vertical == pytest.approx(-wet, rel=1e-6)
    assert np.all(np.diff(x) < 0.0)  # from the vessel toward the anchor, no loop
    spacing = 700.0 / 20
    assert np.all(np.hypot(np.diff(x), np.diff(z)) > 0.95 * spacing)  # no fold between stations
    assert cable.get("minTension") > 0.0


def test_one_section_is_the_line_of_the_scalar_parameters_bit_for_bit(make_cable):
    """nSections = 1 is the uniform line of length, diameter, ... nElements: whatever section[k] and
    attachment[k] hold (unused, nAttachments = 0), the results are those of the default FMU."""
    unused = {**_section(1, length=50.0, EA=1e5, nElements=3, joint=1), **_section(2, length=70.0),
              "attachment[1].s": 10.0, "attachment[1].mass": 1e3}
    names = ["towTension", "towForce.x", "towForce.z", "endPosition.x", "endPosition.z", "minTension"]
    runs = []
    for extra in ({}, unused):
        cable = make_cable(parameters=extra)
        cable.initialize(inputs={"tow.vx": 1.5})
        history = []
        for k in range(6):
            cable.set({"tow.x": 1.5 * k * 0.5, "tow.vx": 1.5 + 0.05 * k})
            cable.do_step(0.5, k * 0.5)
            history.append(cable.get_reals(names))
        runs.append(np.array(history))
    assert runs[0].tobytes() == runs[1].tobytes()
