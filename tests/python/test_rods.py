"""Rods of a MoorDyn deck through the FMU (docs/lines.md, "Rods"): a beam clamped to a Fixed rod is the
cantilever of the closed form."""

from pathlib import Path

import pytest

from ucable.fmu import CableFMU
from ucable.units import STANDARD_GRAVITY as GRAVITY

DECKS = Path(__file__).resolve().parents[1] / "data" / "decks"


def test_a_beam_clamped_to_a_fixed_rod_bends_as_the_cantilever(fmu_file):
    """rod_cantilever.dat: 10 m of beam, 100 kg/m, EI 1e7 N m2, 10 m above the water, leaving a Fixed rod's
    end B along the rod (+x), its far end free: the tow point (the rod's end) carries the beam's weight
    and the tip deflects by w L^4 / (8 EI) = 0.12258 m (the small-deflection closed form; the large
    deflection's correction is of order (0.0123)^2)."""
    EI, L, w = 1e7, 10.0, 100.0 * GRAVITY
    c = CableFMU(fmu_file, parameters={"lineFile": str(DECKS / "rod_cantilever.dat")}, logging_on=True)
    try:
        c.initialize(inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": 10.0})
        assert -c.get("towForce.z") == pytest.approx(w * L, rel=1e-9)
        tip = 10.0 - c.shape()["shape.z"][-1]
        assert tip == pytest.approx(w * L ** 4 / (8 * EI), rel=1e-3)
        texts = [t for _, _, t in c.messages]
        assert any("rod 1 (Fixed, 1 m) read as Fixed point 2 (end B)" in t for t in texts), texts
        assert any("line 1 is clamped to rod 1 at the tow point: topEnd 1, topTangent (1, 0, 0)" in t for t in texts)
    finally:
        c.free()
