"""Rods of a MoorDyn deck through the FMU (docs/lines.md, "Rods"): a beam clamped to a Fixed rod is the
cantilever of the closed form."""

import math
from pathlib import Path

import numpy as np
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


def test_a_free_rod_hanging_on_two_ropes_rests_where_the_elastic_catenaries_put_it(fmu_file):
    """rod_hanging.dat (MoorDyn's RodHanging in water of 1000 kg/m3): a free rod of 20 m, 0.25 m, 77.7066 kg/m
    (a free body) hangs on two ropes of 450 m (0.09 m, 77.7066 kg/m, EA 384.243e6 N) from Fixed points 900 m
    apart. By symmetry each rope carries half the rod's weight in water at its lower end: the elastic
    catenary from (-450, 0) m with that vertical force at its end and 440 m of span gives the rod's depth
    and both end tensions (closed form below; the FMU's statics within 1e-6)."""
    g, rho = GRAVITY, 1000.0
    w = (77.7066 - rho * math.pi * 0.09 ** 2 / 4) * g
    L, EA = 450.0, 384.243e6
    Vb = (77.7066 * 20 - rho * math.pi * 0.25 ** 2 / 4 * 20) * g / 2
    Vt = Vb + w * L

    def span(H):
        return H / w * (math.asinh(Vt / H) - math.asinh(Vb / H)) + H * L / EA

    lo, hi = 1e3, 1e8
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if span(mid) < 440.0 else (lo, mid)
    H = lo
    depth = H / w * (math.sqrt(1 + (Vt / H) ** 2) - math.sqrt(1 + (Vb / H) ** 2)) + (Vb * L + w * L * L / 2) / EA
    c = CableFMU(fmu_file, parameters={"lineFile": str(DECKS / "rod_hanging.dat")}, logging_on=True)
    try:
        c.initialize()
        assert c.get("body[1].pose.z") == pytest.approx(-depth, rel=1e-6)
        assert c.get("body[1].pose.x") == pytest.approx(0.0, abs=1e-6)
        for k in (1, 2):
            ends = sorted((c.get(f"line[{k}].fairleadTension"), c.get(f"line[{k}].anchorTension")))
            assert ends[0] == pytest.approx(math.hypot(H, Vb), rel=1e-6)
            assert ends[1] == pytest.approx(math.hypot(H, Vt), rel=1e-6)
    finally:
        c.free()


def _swing(fmu_file, deck, output, rest, duration, h=0.1):
    """The deck released (TmaxIC 0) and stepped by h for `duration`: `output` less its value at rest at each
    step, and the period from its crossings of the rest value (twice their mean spacing)."""
    c = CableFMU(fmu_file, parameters={"lineFile": str(deck), "lineFileElements": 4})
    try:
        c.initialize()
        t, x = [], []
        for _ in range(int(duration / h)):
            c.do_step(h)
            t.append(c.time)
            x.append(c.get(output) - rest)
    finally:
        c.free()
    crossings = [t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i]) for i in range(len(x) - 1)
                 if (x[i] < 0) != (x[i + 1] < 0)]
    assert len(crossings) >= 2, crossings
    return x, 2 * float(np.mean(np.diff(crossings)))


PENDULUM = """--- MoorDyn Input File ---
a rod hanging on a line from a fixed point, released swinging in its slower mode
---------------------- LINE TYPES ----
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
string 0.02 1.0 5e6 0 0 0 0 0 0
---------------------- ROD TYPES ----
TypeName Diam Mass/m Cd Ca CdEnd CaEnd
(name) (m) (kg/m) (-) (-) (-) (-)
bar 0.1 50 0 0 0 0
---------------------- RODS ----
ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs
(#) (name) (#/key) (m) (m) (m) (m) (m) (m) (-) (-)
1 bar Free {ax:.12g} 0 -12 {bx:.12g} 0 -22 4 -
---------------------- POINTS ----
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed 0 0 -10 0 0 0 0
---------------------- LINES ----
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1 string 1 R1A 2.0 4 -
---------------------- OPTIONS ----
100 WtrDpth
1025 WtrDnsty
0 TmaxIC
------------------------- need this line ----
"""


@pytest.mark.slow
def test_a_rod_hanging_on_a_line_swings_with_the_double_pendulums_period(fmu_file, tmp_path):
    """A rod (10 m, 0.1 m, 50 kg/m, no drag, no added mass) on a 2 m string from a Fixed point is a double
    pendulum: string angle t1 and rod angle t2, M = m [[l^2, l L/2], [l L/2, L^2/4 + I/m]], K = (m - rho V) g
    [[l, 0], [0, L/2]] (buoyancy at the rod's centre), I = m (L^2/12 + d^2/16). Released at rest in its
    slower mode's shape (TmaxIC 0: from the deck's pose), the rod's centre swings with that mode's period,
    6.2968 s. Measured 6.3021 s at 0.1 s steps: the trapezoidal rule's phase error (omega h)^2 / 12 = 8e-4
    and the string's 2 kg; the amplitude stays (no drag)."""
    m, L, l, d, rho = 500.0, 10.0, 2.0, 0.1, 1025.0
    V = math.pi * d * d / 4 * L
    M = np.array([[m * l * l, m * l * L / 2], [m * l * L / 2, m * L * L / 4 + m * (L * L / 12 + d * d / 16)]])
    K = (m - rho * V) * GRAVITY * np.array([[l, 0.0], [0.0, L / 2]])
    ev, vec = np.linalg.eig(np.linalg.solve(M, K))
    slow = int(np.argmin(ev))
    period = 2 * math.pi / math.sqrt(ev[slow])
    t1, t2 = 0.02 * vec[:, slow] / np.max(np.abs(vec[:, slow]))
    deck = tmp_path / "pendulum.dat"
    deck.write_text(PENDULUM.format(ax=l * t1, bx=l * t1 + L * t2))
    x, measured = _swing(fmu_file, deck, "body[1].pose.x", 0.0, 1.3 * period)
    assert measured == pytest.approx(period, rel=2e-3)
    assert max(x) - min(x) == pytest.approx(2 * (l * t1 + L / 2 * t2), rel=1e-2)


CAN = """--- MoorDyn Input File ---
a floating can heaving
---------------------- LINE TYPES ----
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
pendant {dl} {ml} 1e7 0 0 0 0 0 0
---------------------- ROD TYPES ----
TypeName Diam Mass/m Cd Ca CdEnd CaEnd
(name) (m) (kg/m) (-) (-) (-) (-)
can {d} {mpl:.12g} 0 1.0 0 1.0
---------------------- RODS ----
ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs
(#) (name) (#/key) (m) (m) (m) (m) (m) (m) (-) (-)
1 can Free 0 0 {za:.12g} 0 0 {zb:.12g} 10 -
---------------------- POINTS ----
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Free 0 0 {zp:.12g} 0 0 0 0
---------------------- LINES ----
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1 pendant R1A 1 {Ll} 4 -
---------------------- OPTIONS ----
100 WtrDpth
{rho} WtrDnsty
0 TmaxIC
------------------------- need this line ----
"""


def test_a_floating_can_heaves_with_the_period_of_its_waterplane_and_added_mass(fmu_file, tmp_path):
    """A free rod floating upright through the waterline (10 m long, 10 m across, 90 % of it under water,
    no drag) with a 5 m pendant of 10 kg/m hanging from its bottom: its buoyancy follows its draft, so it
    heaves with T = 2 pi sqrt((m + a + m_pendant) / (rho g A_wp)), a the added mass of its one wet end,
    rho CaEnd pi d^3 / 12 (MoorDyn's); 7.0465 s. Released 0.2 m below its equilibrium at rest (TmaxIC 0):
    measured 7.0511 s at 0.1 s steps (+0.066 %: the trapezoidal rule's phase error (omega h)^2 / 12), swinging
    about the equilibrium draft by the 0.2 m it was given."""
    rho, d, L, ml, dl, Ll = 1025.0, 10.0, 10.0, 10.0, 0.05, 5.0
    A = math.pi * d * d / 4
    mpl = rho * A * 0.9
    m = mpl * L
    draft = (m * GRAVITY + (ml - rho * math.pi * dl * dl / 4) * GRAVITY * Ll) / (rho * GRAVITY * A)
    period = 2 * math.pi * math.sqrt((m + rho * math.pi * d ** 3 / 12 + ml * Ll) / (rho * GRAVITY * A))
    za = -draft - 0.2
    deck = tmp_path / "can.dat"
    deck.write_text(CAN.format(dl=dl, ml=ml, d=d, mpl=mpl, za=za, zb=za + L, zp=za - Ll, Ll=Ll, rho=rho))
    z, measured = _swing(fmu_file, deck, "body[1].pose.z", L / 2 - draft, 1.6 * period)
    assert measured == pytest.approx(period, rel=1.5e-3)
    assert max(z) == pytest.approx(0.2, rel=5e-3) and min(z) == pytest.approx(-0.2, rel=5e-3)
