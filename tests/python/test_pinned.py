"""Pinned bodies and pinned rods of a MoorDyn deck through the FMU (docs/lines.md, "Rods";
docs/systems_mooring.md, "Pinned bodies"): a CoupledPinned body and a rod pinned to a coupled body or to the
ground turn about their pin as the physical pendulum of the closed form, in air and in water (added inertia
and buoyancy), under a pin that accelerates (MoorDyn's own test of its pinned body), and upright as a
buoyant column pinned at the seabed; body[k].force is the pin's load on what holds it; a saved state
continues bit for bit."""

import math

import numpy as np
import pytest

from ucable.fmu import CableFMU
from ucable.units import STANDARD_GRAVITY as GRAVITY
from studies.comparisons.pinned_bodies import deck as moordyn_deck, pinned_body_deck, pinned_rod_deck

def _physical_pendulum(m, L, d, s1, s2, rho, Ca):
    """The period of a rod of mass m, length L, diameter d from s1 to s2 along its axis from the pin (s1 < s2),
    small swings about the vertical: I_pin = m (L^2/12 + d^2/16) + m s_c^2 + Ca rho A (s2^3 - s1^3) / 3 (the
    water it moves sideways), restoring |m - rho V| g |s_c|."""
    A, sc = math.pi * d * d / 4, 0.5 * (s1 + s2)
    inertia = m * (L * L / 12 + d * d / 16) + m * sc * sc + Ca * rho * A * (s2 ** 3 - s1 ** 3) / 3
    return 2 * math.pi * math.sqrt(inertia / (abs(m - rho * A * L) * GRAVITY * abs(sc)))


def _run(fmu_file, deck, inputs, outputs, duration, h, drive=None):
    """The deck initialized with the body inputs and stepped by h for `duration`: the time and each output."""
    c = CableFMU(fmu_file, parameters={"lineFile": str(deck)}, logging_on=True)
    try:
        c.initialize(inputs=inputs)
        t, out = [0.0], [c.get_reals(outputs)]
        for k in range(int(round(duration / h))):
            if drive:
                c.set(drive(k * h))
            c.do_step(h)
            t.append(c.time)
            out.append(c.get_reals(outputs))
    finally:
        c.free()
    return np.array(t), np.array(out)


def _period(t, x):
    crossings = [t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i]) for i in range(len(x) - 1)
                 if (x[i] < 0) != (x[i + 1] < 0)]
    assert len(crossings) >= 3, crossings
    return 2 * float(np.mean(np.diff(crossings)))


@pytest.mark.parametrize("rho, Ca", [(0.0, 0.0), (1025.0, 1.0)], ids=["air", "water"])
def test_a_rod_on_a_pinned_body_swings_as_the_physical_pendulum(fmu_file, tmp_path, rho, Ca):
    """A rod 10 m long, 2 m across, of 5000 kg/m, hanging from 5 to 15 m below the pin of a CoupledPinned
    body (MoorDyn's pinnedBody deck), released 3 deg from the vertical: in vacuum T = 6.6115 s; in water
    (its buoyancy at its centre, its transverse added mass Ca rho A over its length turning about the pin)
    14.202 s. Measured at 0.05 s steps within the trapezoidal rule's phase error (omega h)^2 / 12 < 2e-4
    and the finite amplitude's (theta^2 / 16 = 1.7e-4); the pin carries the rod's weight in water at rest."""
    d, mpl, L = 2.0, 5000.0, 10.0
    m = mpl * L
    period = _physical_pendulum(m, L, d, -15.0, -5.0, rho, Ca)
    deck = tmp_path / "pinned.dat"
    deck.write_text(pinned_body_deck(d, mpl, Ca, -5.0, 3.0, -5.0, -15.0, rho))
    t, out = _run(fmu_file, deck, {"body[1].z": -5.0}, ["body[1].pose.roll", "body[1].force.z"], 1.6 * period, 0.05)
    assert out[0, 0] == pytest.approx(math.radians(3.0), rel=1e-10)
    assert _period(t, out[:, 0]) == pytest.approx(period, rel=1e-3)
    assert out[:, 0].max() == pytest.approx(math.radians(3.0), rel=2e-3)
    assert out[:, 0].min() == pytest.approx(-math.radians(3.0), rel=2e-3)
    # at the extreme of the swing (at rest) the pin carries the weight in water W less the tangential
    # acceleration's share, W (1 - (m + m_a) s_c^2 sin^2(theta) / I) with I about the pin and m_a = Ca rho A L
    # the transverse added mass (the water it accelerates pushes on the pin too)
    i = int(np.argmin(out[:, 0]))
    sc, A = 10.0, math.pi * d * d / 4
    inertia = m * (L * L / 12 + d * d / 16 + sc * sc) + Ca * rho * A * (15.0 ** 3 - 5.0 ** 3) / 3
    weight = (m - rho * A * L) * GRAVITY
    moved = m + Ca * rho * A * L
    assert -out[i, 1] == pytest.approx(weight * (1 - moved * sc * sc * math.sin(out[i, 0]) ** 2 / inertia), rel=2e-4)


@pytest.mark.parametrize("rho, Ca", [(0.0, 0.0), (1025.0, 1.0)], ids=["vacuum", "water"])
def test_a_pinned_body_under_an_accelerating_pin_swings_about_the_angle_of_the_acceleration(fmu_file, tmp_path,
                                                                                            rho, Ca):
    """MoorDyn's test of its pinned body: the pinnedBody deck (in vacuum) with its pin accelerated at 0.5 m/s2
    along y from rest swings between 0 and twice the tilt atan(-a/g) = -0.05094 rad (the pendulum on an
    accelerating cart); the pin's load along y is -m a on average. In water the rod's transverse added mass
    m_a = Ca rho A L is accelerated with the pin and its buoyancy lightens it: tan(tilt) = -(m + m_a) a /
    ((m - rho V) g), -0.2313 rad. The swing's period about the tilt is the physical pendulum's under the
    apparent weight sqrt(W^2 + ((m + m_a) a)^2), times 1 + tilt^2 / 16 for its amplitude: 6.6116 s in vacuum,
    14.058 s in water. Over one swing the pin's mean load along y is -m a - m_a (a <cos^2 phi> + s_c <phi''
    cos phi>): the added mass sees the transverse part of the rod's acceleration only (-38.6 kN in water, where
    -(m + m_a) a would be -41.1 kN)."""
    d, mpl, L, a = 2.0, 5000.0, 10.0, 0.5
    A = math.pi * d * d / 4
    deck = tmp_path / "pinned.dat"
    deck.write_text(pinned_body_deck(d, mpl, Ca, -5.0, 0.0, -5.0, -15.0, rho))
    period = _physical_pendulum(mpl * L, L, d, -15.0, -5.0, rho, Ca)
    h = 0.05
    t, out = _run(fmu_file, deck, {"body[1].z": -5.0}, ["body[1].pose.roll", "body[1].force.y"], 2.2 * period, h,
                  drive=lambda t: {"body[1].y": 0.5 * a * t * t, "body[1].vy": a * t})
    m, ma, sc = mpl * L, Ca * rho * A * L, 10.0
    W, F = (m - rho * A * L) * GRAVITY, (m + ma) * a
    tilt = math.atan(-F / W)
    phi = out[:, 0]
    assert phi.min() == pytest.approx(2 * tilt, rel=1e-3)
    assert phi.max() == pytest.approx(0.0, abs=2e-3 * abs(tilt))
    period *= (1 + (F / W) ** 2) ** -0.25 * (1 + tilt * tilt / 16)
    assert _period(t, phi - tilt) == pytest.approx(period, rel=1e-3)
    # over one whole swing (between two crossings of the tilt in the same direction)
    ups = [i for i in range(len(phi) - 1) if phi[i] - tilt < 0 <= phi[i + 1] - tilt]
    swing = slice(ups[0], ups[1])
    rate = np.gradient(phi, h)
    # <phi'' cos phi> = <phi'^2 sin phi> over a whole period (by parts)
    expected = -m * a - ma * (a * np.mean(np.cos(phi[swing]) ** 2) + sc * np.mean(rate[swing] ** 2 * np.sin(phi[swing])))
    assert np.mean(out[swing, 1]) == pytest.approx(expected, rel=1e-3)


def test_a_buoyant_column_pinned_at_the_seabed_rocks_as_the_inverted_pendulum_its_buoyancy_rights(fmu_file, tmp_path):
    """A spar-like column (20 m, 2 m across, half the density of the water, Ca 1) pinned at its foot 60 m down
    (a CoupledPinned body at the seabed, its rod from the pin up along its z axis): its buoyancy at its centre
    rights it, T = 2 pi sqrt(I_pin / ((rho V - m) g L / 2)) with I_pin = m (L^2/3 + d^2/16) + Ca rho A L^3 / 3:
    12.694 s. Released 3 deg off upright; the pin holds it down with its net buoyancy at rest."""
    d, L, rho = 2.0, 20.0, 1025.0
    A = math.pi * d * d / 4
    mpl = 0.5 * rho * A
    period = _physical_pendulum(mpl * L, L, d, 0.0, L, rho, 1.0)
    deck = tmp_path / "column.dat"
    deck.write_text(pinned_body_deck(d, mpl, 1.0, -60.0, 3.0, 0.0, L, rho))
    t, out = _run(fmu_file, deck, {"body[1].z": -60.0}, ["body[1].pose.roll", "body[1].force.z"], 1.6 * period, 0.1)
    assert _period(t, out[:, 0]) == pytest.approx(period, rel=1e-3)
    assert out[:, 0].min() == pytest.approx(-math.radians(3.0), rel=2e-3)
    assert out[0, 1] == pytest.approx((rho * A * L - mpl * L) * GRAVITY, rel=1e-10)


def test_a_rod_pinned_to_a_coupled_body_swings_and_loads_the_body_at_its_pin(fmu_file, tmp_path):
    """A rod (8 m, 0.5 m, 400 kg/m, Ca 1) pinned at its end A to coupled body 1 (Body1Pinned, 2 m out along
    the body's x axis) hangs and swings as the physical pendulum (8.0614 s in water); body 1's load is the
    pin's: along x it swings about 0 with the rod, at rest its vertical part is the rod's weight in water and
    its moment about the body's reference point that force's at the 2 m arm."""
    d, mpl, L, rho, theta = 0.5, 400.0, 8.0, 1025.0, math.radians(2.0)
    A = math.pi * d * d / 4
    period = _physical_pendulum(mpl * L, L, d, -L, 0.0, rho, 1.0)
    deck = tmp_path / "pinned_rod.dat"
    deck.write_text(pinned_rod_deck("Body1Pinned", 2 + L * math.sin(theta), -L * math.cos(theta)))
    inputs = {"body[1].z": -10.0}
    t, out = _run(fmu_file, deck, inputs, ["body[1].force.x", "body[1].force.z", "body[1].moment.y"],
                  1.6 * period, 0.05)
    assert _period(t, out[:, 0]) == pytest.approx(period, rel=1e-3)
    weight = (mpl - rho * A) * L * GRAVITY
    assert out[0, 1] == pytest.approx(-weight, rel=1e-10)
    assert out[0, 2] == pytest.approx(2.0 * weight, rel=1e-10)  # (2, 0, 0) x (0, 0, -W): +2 W about y


def test_a_rod_pinned_to_the_ground_rests_where_its_line_balances_its_weight_about_the_pin(fmu_file, tmp_path):
    """A rod (8 m, 400 kg/m, 0.5 m) pinned to the ground at its end A ('Pinned'), held by a neutrally buoyant
    vertical line (weightless in water) from its end B to a Fixed point 30 m above: level, the moments about the
    pin balance with the line carrying half the rod's weight in water, T = W / 2. The line's unstretched length
    is 30 m / (1 + T / EA), so the statics (Newton on the pinned body's rotation) must find the rod level and
    T = W / 2 at both of the line's ends."""
    rho, d, EA = 1025.0, 0.1, 1e7
    W = (400.0 - rho * math.pi * 0.5 ** 2 / 4) * 8 * GRAVITY
    T = W / 2
    deck = tmp_path / "ground.dat"
    deck.write_text(moordyn_deck("a rod pinned to the ground, held level by a vertical line", "bar 0.5 400 0 1.0 0 0",
                                "1 bar Pinned 0 0 -50 8 0 -50 10 -", line_type=f"rope {d} {rho * math.pi * d * d / 4:.12g} "
                                f"{EA} 0 0 0 0 0 0", points="1 Fixed 8 0 -20 0 0 0 0",
                                lines=f"1 rope R1B 1 {30.0 / (1 + T / EA):.15g} 4 -",
                                options="100 WtrDpth\n1025 WtrDnsty"))
    c = CableFMU(fmu_file, parameters={"lineFile": str(deck)}, logging_on=True)
    try:
        c.initialize()
        texts = [m for _, _, m in c.messages]
        assert any("read as pinned body 1 (its end A held fixed, free to turn about it)" in m for m in texts), texts
        assert c.get("line[1].fairleadTension") == pytest.approx(T, rel=1e-6)
        assert c.get("line[1].anchorTension") == pytest.approx(T, rel=1e-6)
        assert c.get("body[1].pose.yaw") == pytest.approx(0.0, abs=1e-7)
        assert c.get("body[1].pose.pitch") == pytest.approx(0.0, abs=1e-7)
    finally:
        c.free()


def test_a_saved_state_of_a_swinging_pinned_rod_continues_bit_for_bit(fmu_file, tmp_path):
    """fmi2GetFMUstate mid-swing of the rod pinned to coupled body 1, the body moving: restored in the same
    instance and (serialized) in a new one, the continuation's pin load and pose are the same bits."""
    deck = tmp_path / "pinned_rod.dat"
    deck.write_text(pinned_rod_deck("Body1Pinned", 2 + 8 * math.sin(0.05), -8 * math.cos(0.05)))
    names = ["body[1].force.x", "body[1].force.z", "body[1].moment.y"] + [
        f"body[2].pose.{a}" for a in ("x", "y", "z", "roll", "pitch", "yaw")]

    def drive(t):
        return {"body[1].x": 0.3 * math.sin(0.5 * t), "body[1].vx": 0.15 * math.cos(0.5 * t), "body[1].z": -10.0}

    def run(cable, start, steps, h=0.2):
        out = []
        for k in range(start, start + steps):
            cable.set(drive(h * k))
            cable.do_step(h, t=h * k)
            out.append(cable.get_reals(names))
        return np.array(out)

    c = CableFMU(fmu_file, parameters={"lineFile": str(deck)})
    fresh = CableFMU(fmu_file, parameters={"lineFile": str(deck)})
    try:
        c.initialize(inputs=drive(0.0))
        run(c, 0, 5)
        state = c.get_state()
        data = c.serialize_state(state)
        first = run(c, 5, 5)
        c.set_state(state, time=1.0)
        assert run(c, 5, 5).tobytes() == first.tobytes()
        fresh.set_state(fresh.deserialize_state(data), time=1.0)
        assert run(fresh, 5, 5).tobytes() == first.tobytes()
        assert np.ptp(first[:, 0]) > 100.0  # it swings: the pin's load changes
    finally:
        c.free()
        fresh.free()
