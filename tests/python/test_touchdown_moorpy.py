"""Touchdown outputs against MoorPy on a short chain with more than half of it on the seabed.

A 600 m chain (the mooring chain's section: 113 kg/m, 0.0766 m, EA 7.5e8 N) from a fairlead 20 m
deep to an anchor 555 m away on a seabed 150 m down: MoorPy's elastic catenary (frictionless seabed)
lays its last 337 m on the seabed, so 12 of the 21 output stations rest there. The FMU's
static equilibrium must place the touchdown and the grounded length within one element length of
MoorPy's at every seabed stiffness from soft to rigid-like (a touchdown test against zero clearance
once reported no contact at all on such a line at 1e7 N/m2)."""

import math

import numpy as np
import pytest

from studies.cases import mooring as M

LENGTH, DEPTH, FAIRLEAD_Z, ANCHOR_X = 600.0, 150.0, -20.0, -555.0
ELEMENTS = 20
ELEMENT_LENGTH = LENGTH / ELEMENTS
CHAIN = dict(M.CHAIN, length=LENGTH, waterDepth=DEPTH, nElements=ELEMENTS,
             **{"anchor.x": ANCHOR_X, "anchor.z": -DEPTH})


def moorpy_reference() -> dict:
    catenary = pytest.importorskip("moorpy.Catenary").catenary
    w = M.chain_weight(CHAIN)
    fAH, fAV, fBH, fBV, info = catenary(-ANCHOR_X, FAIRLEAD_Z + DEPTH, LENGTH, CHAIN["EA"], w, CB=0.0,
                                        Tol=1e-10, MaxIter=200)
    return {"grounded": info["LBot"], "H": abs(fBH), "V": abs(fBV)}


def fmu_statics(make_cable, stiffness: float) -> dict:
    c = make_cable(parameters=dict(CHAIN, seabedStiffness=stiffness))
    c.initialize(inputs={"tow.x": 0.0, "tow.z": FAIRLEAD_Z})
    names = ["touchdownArcLength", "groundedLength", "minSeabedClearance", "layback", "topDeclination",
             "anchorUplift", "towTension"]
    out = dict(zip(names, c.get_reals(names)))
    out["clearance"] = c.shape()["shape.z"] + DEPTH  # height of the 21 stations above the seabed
    return out


@pytest.mark.parametrize("stiffness", [3e5, 1e6, 1e7, 1e8])
def test_touchdown_agrees_with_moorpy_at_every_seabed_stiffness(make_cable, stiffness):
    ref = moorpy_reference()
    o = fmu_statics(make_cable, stiffness)
    s = np.linspace(0.0, LENGTH, len(o["clearance"]))  # the stations' unstretched arc length
    resting = o["clearance"] < 0.5 * CHAIN["diameter"]  # the definition of resting on the seabed
    assert resting.sum() >= 11  # the situation described above: most stations grounded
    # the touchdown output and the shape agree: stations before it are up, stations beyond rest
    assert np.all(~resting[s < o["touchdownArcLength"]]) and np.all(resting[s > o["touchdownArcLength"]])
    assert abs(o["touchdownArcLength"] - (LENGTH - ref["grounded"])) < ELEMENT_LENGTH
    assert abs(o["groundedLength"] - ref["grounded"]) < ELEMENT_LENGTH
    # the smallest clearance is sampled more finely than the stations
    assert o["minSeabedClearance"] <= o["clearance"].min()
    assert o["anchorUplift"] == 0.0
    assert o["layback"] == pytest.approx(-ANCHOR_X, abs=1e-9)
    # fairlead angle from the downward vertical: atan(H / V) of the catenary's fairlead force; the
    # static tension matches a catenary to 1e-4 (the mooring validation), so 1e-3 rad is ample
    assert o["topDeclination"] == pytest.approx(math.atan2(ref["H"], ref["V"]), abs=1e-3)
