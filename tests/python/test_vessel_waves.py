"""The Vessel partner FMU's superimposed wave motion (docs/waves.md).

- Holding station (zero speed, fixed heading) it is the VesselRAO FMU's motion for the same sea and lever
  arm, to round-off, in regular and irregular seas.
- Underway at steady speed and heading, a regular wave moves every degree of freedom at the encounter
  frequency w + k U (head seas) or w - k U (following seas) with the RAO of the encounter period: the
  motions against the closed form, the response spectrum's peak at the encounter frequency.
- Velocity and acceleration of the tow point are the time derivatives of its position (central finite
  differences) underway, and in a turn when the RAO does not change with period and heading.
- waves.mode 0 leaves every output bit for bit as before (tests/python/test_golden.py).
"""

import math

import numpy as np
import pytest

from studies.cases.rao_box import DEFAULT_OUT as RAO_CSV
from studies.cases.rao_box import fmu_with_table, interpolate
from studies.cases.rao_box import read as read_rao
from ucable.system import partner_fmu
from ucable.units import GRAVITY as G

TOW = [f"tow.{q}" for q in ("x", "y", "z", "vx", "vy", "vz", "ax", "ay", "az")]
DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")
LEVER = {"towPoint.x": -30.0, "towPoint.y": 3.0, "towPoint.z": 4.0}


@pytest.fixture(scope="module")
def vessel_fmu(fmu_file):
    return partner_fmu("Vessel")


def deep_water_k(w):
    return w * w / G  # tanh(k h) = 1 to 1e-30 at the default 1000 m for periods below 20 s


@pytest.mark.parametrize("waves", [
    {"waves.mode": 1, "waves.height": 2.0, "waves.period": 8.25, "waves.direction": 0.4},
    {"waves.mode": 2, "waves.height": 3.0, "waves.period": 9.0, "waves.direction": 2.2, "waves.seed": 7,
     "waves.nComponents": 150, "waves.rampTime": 10.0, "waterDepth": 300.0},
])
def test_holding_station_it_moves_as_the_vessel_rao_fmu(vessel_fmu, make_unit, waves):
    """Vessel at rest (speed 0, no tow force: the autopilot holds it exactly) and VesselRAO at the same
    position, heading and lever arm: tow point, motions and elevation agree at every communication point.
    Tolerance: the two sum the same terms in another form and order (a |R| cos(theta - phi) against
    a (Re R cos theta + Im R sin theta)): round-off of the phases, |theta| 1e-16, times the largest
    motion rate (1e-12 absolute, with 1e-13 of the position's size)."""
    place = {"x0": 120.0, "y0": -35.0}
    v = make_unit(vessel_fmu, parameters={**waves, **LEVER, **place, "speed0": 0.0, "speed1": 0.0,
                                          "heading0": 2.5}, instance_name="vessel")
    r = make_unit(partner_fmu("VesselRAO"), parameters={**waves, **LEVER, **place, "heading": 2.5},
                  instance_name="rao")
    v.initialize(0.0, 60.0)
    r.initialize(0.0, 60.0)
    ours = TOW + [f"waveMotion.{m}" for m in DOFS] + ["waveElevation"]
    theirs = TOW + list(DOFS) + ["waveElevation"]
    heave = []
    for k in range(120):
        a, b = v.get_reals(ours), r.get_reals(theirs)
        assert np.allclose(a, b, rtol=1e-13, atol=1e-12), (k, a - b)
        heave.append(a[2])
        v.do_step(0.5, t=0.5 * k)
        r.do_step(0.5, t=0.5 * k)
    assert v.get_reals(["x", "y", "heading"]).tolist() == [120.0, -35.0, 2.5]  # it held station exactly
    assert np.std(heave) > 0.1  # the tow point moves


def run_underway(make_unit, fmu, parameters, step, steps, names):
    v = make_unit(fmu, parameters=parameters)
    v.initialize(0.0, step * steps)
    rows = [v.get_reals(names)]
    for k in range(steps):
        v.do_step(step, t=step * k)
        rows.append(v.get_reals(names))
    return np.array(rows)


@pytest.mark.parametrize("relative_heading, T", [(180.0, 8.0), (150.0, 8.0), (30.0, 8.0), (0.0, 3.0)])
def test_underway_the_motion_is_the_rao_of_the_encounter_period(vessel_fmu, make_unit, relative_heading, T):
    """Regular wave H 1 m, period T travelling along 0.3 rad; the vessel at 5 m/s (steady: no tow force, the
    autopilot's equilibrium) heading 0.3 - relative heading. At the reference point X(t) (the FMU's x, y)
    the wave's phase is theta = w t - k.X(t); every motion is Re[a conj(R) e^(i theta)] with R the
    table's RAO at the encounter period 2 pi / |we|, we = w - k.U, and the relative heading; R itself
    instead of its conjugate when we < 0 (the 3 s wave, slower than the vessel, overtaken in following
    seas). Tolerance: round-off of theta (|k.X| <= 200 rad: 1e-13) times the RAOs (about 1), 1e-12
    absolute."""
    H, direction, U = 1.0, 0.3, 5.0
    heading = direction - math.radians(relative_heading)
    params = {"waves.mode": 1, "waves.height": H, "waves.period": T, "waves.direction": direction,
              "heading0": heading, "speed0": U, "speed1": U}
    rows = run_underway(make_unit, vessel_fmu, params, 0.5, 80, ["x", "y", "heading", "speed"]
                        + [f"waveMotion.{m}" for m in DOFS])
    assert np.all(rows[:, 2] == heading) and np.allclose(rows[:, 3], U, rtol=1e-14)
    w = 2 * math.pi / T
    k = deep_water_k(w)
    kvec = k * np.array([math.cos(direction), math.sin(direction)])
    we = w - kvec @ (U * np.array([math.cos(heading), math.sin(heading)]))
    assert (we < 0.0) == (T == 3.0)
    R = interpolate(read_rao(RAO_CSV), 2 * math.pi / abs(we), relative_heading)
    assert np.max(np.abs(R - interpolate(read_rao(RAO_CSV), T, relative_heading))) > 0.05  # speed matters
    t = 0.5 * np.arange(rows.shape[0])
    theta = w * t - rows[:, :2] @ kvec
    expected = (H / 2 * (np.conj(R) if we > 0.0 else R)[None, :] * np.exp(1j * theta)[:, None]).real
    assert np.allclose(rows[:, 4:], expected, rtol=0, atol=1e-12)


@pytest.mark.parametrize("relative_heading, sign", [(180.0, 1.0), (0.0, -1.0)])
def test_underway_the_response_peaks_at_the_encounter_frequency(vessel_fmu, make_unit, relative_heading, sign):
    """Regular wave T 8 s (w 0.785 rad/s, k 0.0629 /m), vessel at 5 m/s in head or following seas: the
    encounter frequency is w + k U = 1.10 rad/s or w - k U = 0.47 rad/s. The tow point's heave over 512 s
    (0.5 s steps) has its spectral peak (Hann window) within one frequency bin (2 pi / 512 s = 0.0123
    rad/s) of it, 25 bins from the wave's own frequency."""
    T, U = 8.0, 5.0
    params = {"waves.mode": 1, "waves.height": 2.0, "waves.period": T, "waves.direction": 0.0,
              "heading0": -math.radians(relative_heading), "speed0": U, "speed1": U, **LEVER}
    z = run_underway(make_unit, vessel_fmu, params, 0.5, 1024, ["tow.z"])[1:, 0]
    spectrum = np.abs(np.fft.rfft((z - z.mean()) * np.hanning(z.size)))
    frequencies = 2 * math.pi * np.fft.rfftfreq(z.size, 0.5)
    w = 2 * math.pi / T
    we = w + sign * deep_water_k(w) * U
    resolution = frequencies[1]
    assert abs(frequencies[np.argmax(spectrum)] - we) <= resolution
    assert abs(we - w) > 20 * resolution


def check_derivatives(rows, h, omitted=0.0):
    """Velocity and acceleration (columns 3-5, 6-8) against central differences of position and velocity
    (columns 0-2): error at most h^2 / 6 max|third derivative|, that taken from the samples' third
    differences, doubled for the maximum between the samples; plus round-off eps |x| / h; plus, for the
    acceleration, a bound of what it leaves out (`omitted`)."""
    for value, derivative, allowance in ((slice(0, 3), slice(3, 6), 0.0), (slice(3, 6), slice(6, 9), omitted)):
        x = rows[:, value]
        central = (x[2:] - x[:-2]) / (2 * h)
        third = np.max(np.abs(x[3:] - 3 * x[2:-1] + 3 * x[1:-2] - x[:-3]), axis=0) / h ** 3
        bound = 2 * h * h / 6 * third + 1e-15 * np.max(np.abs(x), axis=0) / h + allowance
        error = np.max(np.abs(central - rows[1:-1, derivative]), axis=0)
        assert np.all(error <= bound), (error, bound)
        assert np.all(bound - allowance < 1e-3 * np.max(np.abs(rows[:, derivative]), axis=0) + 1e-12)  # it has teeth


def test_underway_velocity_and_acceleration_are_the_derivatives_of_position(vessel_fmu, make_unit):
    """JONSWAP Hs 3 m, Tp 8 s, head-quartering seas (135 deg), 3 m/s, growing over 40 s (the ramp's derivatives
    tested too); 0.02 s steps over 30 s."""
    params = {"waves.mode": 2, "waves.height": 3.0, "waves.period": 8.0, "waves.direction": 0.5,
              "waves.rampTime": 40.0, "heading0": 0.5 - math.radians(135.0), "speed0": 3.0, "speed1": 3.0,
              **LEVER}
    check_derivatives(run_underway(make_unit, vessel_fmu, params, 0.02, 1500, TOW), 0.02)


def test_in_a_turn_velocity_and_acceleration_are_the_derivatives_of_position(vessel_fmu, make_unit, tmp_path):
    """An RAO table of 2 periods x 2 headings (4 s and 30 s, 0 and 180 deg, every degree of freedom
    moving), a turn at 3 deg/s from t = 2 s through 45 deg in a regular wave H 2 m, T 7 s along 2 rad at
    3 m/s: the relative heading goes from 115 to 70 deg and the encounter period from 6.3 to 7.8 s, inside
    one cell of the table, whose interpolation is then smooth. The RAO changes with heading and encounter
    period; the velocity includes its rate, and so is the derivative of the position (the finite-difference
    bound). The acceleration leaves out the term of the encounter frequency's second derivative (the
    vessel's jerk): a |dR/dT| T |d2we/dt2| / |we| per degree of freedom, rotations times the lever arm,
    with we(t) = w - k.V(t) from the FMU's own velocity and its second derivative from central differences
    (the manoeuvre is smooth). Steps 0.02 s from 4 s to 14 s, away from the turn's start."""
    rows = ["4,0,0.1,10,0.05,20,0.2,5,0.5,40,0.8,-30,0.1,60", "4,180,0.2,-50,0.1,80,0.3,15,1,-20,0.4,70,0.3,-10",
            "30,0,0.9,90,0.3,-90,1,0,3,90,2,-90,0.5,30", "30,180,0.6,60,0.4,120,0.9,10,1,0,1,45,0.2,100"]
    fmu = fmu_with_table(vessel_fmu, tmp_path / "Vessel.fmu", "period,heading\n" + "\n".join(rows) + "\n")
    H, T, direction, h = 2.0, 7.0, 2.0, 0.02
    params = {"waves.mode": 1, "waves.height": H, "waves.period": T, "waves.direction": direction,
              "speed0": 3.0, "speed1": 3.0, "turnStart": 2.0, "turnRate": math.radians(3.0),
              "turnAngle": math.radians(45.0), **LEVER}
    out = run_underway(make_unit, fmu, params, h, 700, TOW + ["heading", "surge", "sway"])[200:]
    psi, u, v = out[:, 9], out[:, 10], out[:, 11]
    w = 2 * math.pi / T
    k = deep_water_k(w)
    we = w - k * (math.cos(direction) * (np.cos(psi) * u - np.sin(psi) * v)
                  + math.sin(direction) * (np.sin(psi) * u + np.cos(psi) * v))
    Te = 2 * math.pi / we
    relative = np.degrees(direction - psi)
    assert 4.0 < Te.min() and Te.max() < 30.0 and 0.0 < relative.min() and relative.max() < 180.0  # one cell
    table = np.array([[float(x) for x in r.split(",")] for r in rows])
    amplitude = table[:, 2::2] * np.where(np.arange(6) >= 3, math.pi / 180.0, 1.0)
    R = amplitude * np.exp(1j * np.radians(table[:, 3::2]))
    slope = np.max(np.abs(R[2:] - R[:2]), axis=0) / 26.0  # |dR/dT| bounds, per degree of freedom
    arm = np.linalg.norm([LEVER["towPoint.x"], LEVER["towPoint.y"], LEVER["towPoint.z"]])
    dd_we = np.abs(we[2:] - 2 * we[1:-1] + we[:-2]) / h ** 2
    omitted = H / 2 * np.max(Te[1:-1] * dd_we / we[1:-1]) * (slope[:3].sum() + arm * slope[3:].sum())
    assert omitted < 1e-2 * np.max(np.abs(out[:, 6:9]))  # small
    check_derivatives(out[:, :9], h, omitted)


def test_in_a_turn_with_a_constant_rao_the_derivatives_are_exact(vessel_fmu, make_unit, tmp_path):
    """An RAO table of one row (the same RAO at every period and heading, every degree of freedom moving):
    velocity and acceleration are then exact (the RAO does not change), and the turn (3 deg/s from t = 2 s) tests the kinematics
    of body axes turning under the motion and of an encounter frequency that changes with the course.
    Regular wave H 2 m, T 7 s; 0.02 s steps from 4 s to 14 s, inside the turn (its start changes the
    yaw acceleration abruptly)."""
    row = "10,90,0.3,20,0.2,-40,0.8,10,2,30,1.5,-60,0.5,80"
    fmu = fmu_with_table(vessel_fmu, tmp_path / "Vessel.fmu", f"period,heading\n{row}\n")
    params = {"waves.mode": 1, "waves.height": 2.0, "waves.period": 7.0, "waves.direction": 2.0,
              "speed0": 3.0, "speed1": 3.0, "turnStart": 2.0, "turnRate": math.radians(3.0),
              "turnAngle": math.radians(90.0), **LEVER}
    rows = run_underway(make_unit, fmu, params, 0.02, 700, TOW + ["yawRate"])
    assert np.min(rows[200:, 9]) > math.radians(1.0)  # turning throughout
    check_derivatives(rows[200:, :9], 0.02)


def test_bad_seas_and_tables_are_errors_naming_the_variable_or_file(vessel_fmu, make_unit, tmp_path):
    """The Vessel refuses what VesselRAO refuses, with the same messages (one sea, one table reader); in
    calm water it reads no table, so a broken one does not matter."""
    from ucable.fmu import FMICallException
    v = make_unit(vessel_fmu, parameters={"waves.mode": 1, "waves.height": 12.0, "waves.period": 5.0},
                  instance_name="steep")
    with pytest.raises(FMICallException):
        v.initialize(0.0, 10.0)
    assert any("waves.height = 12 is too steep" in m for _, _, m in v.messages), v.log_text()
    weightless = make_unit(vessel_fmu, parameters={"waves.mode": 1, "waves.height": 1.0, "gravity": 0.0},
                           instance_name="weightless")
    with pytest.raises(FMICallException):
        weightless.initialize(0.0, 10.0)
    assert any("gravity = 0" in m for _, _, m in weightless.messages), weightless.log_text()
    broken = fmu_with_table(vessel_fmu, tmp_path / "Vessel.fmu", "period,heading\n8,180,1\n")
    u = make_unit(broken, parameters={"waves.mode": 2, "waves.height": 1.0}, instance_name="table")
    with pytest.raises(FMICallException):
        u.initialize(0.0, 10.0)
    assert any("rao.csv" in m and "line 2: expected 14 comma-separated numbers" in m for _, _, m in u.messages)
    calm = make_unit(broken, instance_name="calm")
    calm.initialize(0.0, 10.0)
    calm.do_step(0.5, t=0.0)
    assert calm.get("waveElevation") == 0.0 and calm.get("tow.z") == 0.0
