"""Rods fixed to a free body through the waterline (docs/lines.md, "Rods"): the body's buoyancy, its centre
and its added mass follow the rods' part under water, so a spar floats at the draft its weight sets and heaves
with the period of its waterplane and the added mass of its wet end."""

import math

import numpy as np
import pytest

from ucable.fmu import CableFMU
from ucable.units import STANDARD_GRAVITY as GRAVITY

SPAR = """--- MoorDyn Input File ---
a spar: a free body ballasted at its reference point, a can of 18 m on it through the waterline
---------------------- LINE TYPES ----
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
pendant {dl} {ml} 1e7 0 0 0 0 0 0
---------------------- ROD TYPES ----
TypeName Diam Mass/m Cd Ca CdEnd CaEnd
(name) (m) (kg/m) (-) (-) (-) (-)
can {d} {mpl} 0 1.0 0 1.0
---------------------- BODIES ----
ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca
(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)
1 Free 0 0 {z0:.12g} 0 0 0 {mb} 0 1e8 0 0 0
---------------------- RODS ----
ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs
(#) (name) (#/key) (m) (m) (m) (m) (m) (m) (-) (-)
1 can Body1 0 0 0 0 0 {L} 6 -
---------------------- POINTS ----
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Body1 0 0 0 0 0 0 0
2 Free 0 0 {zp:.12g} 0 0 0 0
---------------------- LINES ----
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1 pendant 1 2 {Ll} 4 -
---------------------- OPTIONS ----
100 WtrDpth
{rho} WtrDnsty
{tmax} TmaxIC
------------------------- need this line ----
"""

RHO, D, L, MPL, MB, DL, ML, LL = 1025.0, 6.0, 18.0, 1000.0, 2.0e5, 0.05, 10.0, 5.0
AREA = math.pi * D * D / 4
MASS = MB + MPL * L  # the body and its can
PENDANT = ML * LL  # the pendant's mass, its weight in water less its buoyancy below
DRAFT = (MASS + (ML - RHO * math.pi * DL * DL / 4) * LL) / (RHO * AREA)


def _deck(tmp_path, z0, tmax):
    deck = tmp_path / "spar.dat"
    deck.write_text(SPAR.format(dl=DL, ml=ML, d=D, mpl=MPL, mb=MB, L=L, z0=z0, zp=z0 - LL, Ll=LL, rho=RHO, tmax=tmax))
    return deck


def test_a_spar_on_a_free_body_floats_at_the_draft_its_weight_sets(fmu_file, tmp_path):
    """Statics from the deck's pose 7 m down: the can's draft d solves (M + m_can + the pendant's weight in
    water) = rho A d: 7.52350 m (the body's reference point at the can's foot, z = -d), upright."""
    c = CableFMU(fmu_file, parameters={"lineFile": str(_deck(tmp_path, -7.0, 100)), "lineFileElements": 4})
    try:
        c.initialize()
        assert c.get("body[1].pose.z") == pytest.approx(-DRAFT, abs=1e-5)
        assert c.get("body[1].pose.x") == pytest.approx(0.0, abs=1e-9)
        assert c.get("body[1].pose.pitch") == pytest.approx(0.0, abs=1e-9)
    finally:
        c.free()


def test_a_spar_on_a_free_body_heaves_with_its_waterplane_and_the_added_mass_of_its_wet_end(fmu_file, tmp_path):
    """Released 0.2 m below its draft at rest (TmaxIC 0): T = 2 pi sqrt((M + m_can + m_pendant + a33) /
    (rho g A)), a33 = CaEnd rho pi d^3 / 12 of its one wet end (the can's transverse Ca moves no water in
    heave), 6.1919 s; swinging 0.2 m about the draft (no drag)."""
    a33 = RHO * math.pi * D ** 3 / 12
    period = 2 * math.pi * math.sqrt((MASS + PENDANT + a33) / (RHO * GRAVITY * AREA))
    h = 0.1
    c = CableFMU(fmu_file, parameters={"lineFile": str(_deck(tmp_path, -DRAFT - 0.2, 0)), "lineFileElements": 4})
    try:
        c.initialize()
        t, z = [], []
        for _ in range(int(1.6 * period / h)):
            c.do_step(h)
            t.append(c.time)
            z.append(c.get("body[1].pose.z") + DRAFT)
    finally:
        c.free()
    crossings = [t[i] - z[i] * (t[i + 1] - t[i]) / (z[i + 1] - z[i]) for i in range(len(z) - 1)
                 if (z[i] < 0) != (z[i + 1] < 0)]
    assert len(crossings) >= 2, crossings
    measured = 2 * float(np.mean(np.diff(crossings)))
    # the trapezoidal rule's phase error (omega h)^2 / 12 = 8.6e-4 at h = 0.1 s
    assert measured == pytest.approx(period, rel=1.5e-3)
    assert max(z) == pytest.approx(0.2, rel=5e-3) and min(z) == pytest.approx(-0.2, rel=5e-3)
