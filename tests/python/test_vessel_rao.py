"""The VesselRAO partner FMU: the tow-point motion is the RAO response to the cable's own sea.

- In a regular wave at a tabulated period and heading, the motion of every degree of freedom is the RAO
  of the shipped table times the wave amplitude, and the tow point at a lever arm moves by translation +
  rotation x lever arm, with velocity and acceleration the exact time derivatives (closed form, round-off).
- Between the table's periods and headings, the RAO is the complex bilinear interpolation of the table.
- The vessel's waveElevation at its reference point equals the cable FMU's waveElevation at the same point
  in regular and JONSWAP seas for several seeds (one sea, generated identically in C and C++).
- Breaking waves and NaN parameters are refused naming the variable; a malformed RAO table is an error
  naming the file and the line; a one-row table holds for every period and heading.
- The shipped generic RAOs tend, in long waves, to a vessel that follows the surface (signs and phases
  of every degree of freedom against the surface's elevation, slopes and particle displacement).
"""

import math

import numpy as np
import pytest

from ucable.fmu import FMICallException
from studies.cases.rao_box import DEFAULT_OUT as RAO_CSV
from studies.cases.rao_box import fmu_with_table, interpolate
from studies.cases.rao_box import read as read_rao
from ucable.system import partner_fmu


@pytest.fixture(scope="module")
def rao_fmu(fmu_file):
    return partner_fmu("VesselRAO")


@pytest.fixture(scope="module")
def table():
    return read_rao(RAO_CSV)


def expected_tow(R, a, w, kX, t, lever, heading, x0, y0):
    """Tow point position, velocity, acceleration in a regular wave: motions Re[R a e^{-i(w t - kX)}]."""
    z = R * a * np.exp(-1j * (w * t - kX))
    s, v, acc = z.real, (-1j * w * z).real, (-w * w * z).real
    ch, sh = math.cos(heading), math.sin(heading)
    out = []
    for k, q in enumerate((s, v, acc)):
        body = q[:3] + np.cross(q[3:], lever) + (lever if k == 0 else 0.0)
        out.append(np.array([ch * body[0] - sh * body[1], sh * body[0] + ch * body[1], body[2]]))
    out[0][:2] += (x0, y0)
    return out, s


TOW = [f"tow.{q}" for q in ("x", "y", "z", "vx", "vy", "vz", "ax", "ay", "az")]
MOTIONS = ["surge", "sway", "heave", "roll", "pitch", "yaw"]


@pytest.mark.parametrize("period, relative_heading", [(8.0, 180.0), (10.0, 135.0), (8.25, 100.0)])
def test_regular_wave_motion_is_the_rao_times_the_amplitude(rao_fmu, make_unit, table, period, relative_heading):
    """Wave H 2 m travelling along 0.4 rad, vessel at (120, -35) m heading 0.4 - relative heading, tow
    point 30 m aft, 3 m to port and 4 m up. Tolerance: round-off of sums of a few terms of size
    |R| a w^2 ~ 1 (1e-12 absolute)."""
    H, direction, x0, y0 = 2.0, 0.4, 120.0, -35.0
    heading = direction - math.radians(relative_heading)
    lever = np.array([-30.0, 3.0, 4.0])
    params = {"waves.mode": 1, "waves.height": H, "waves.period": period, "waves.direction": direction,
              "x0": x0, "y0": y0, "heading": heading, "towPoint.x": lever[0], "towPoint.y": lever[1],
              "towPoint.z": lever[2]}
    v = make_unit(rao_fmu, parameters=params)
    v.initialize(0.0, 60.0)
    R = interpolate(table, period, relative_heading)
    if period == 8.0:  # a tabulated point: the table's own row
        row = table[(table[:, 0] == 8.0) & (table[:, 1] == relative_heading)][0]
        assert np.allclose(np.abs(R[:3]), row[2:8:2], rtol=1e-12)
    w = 2 * math.pi / period
    k = w * w / 9.81 / math.tanh(w * w / 9.81 * 1000.0)  # deep water to 1e-30 at 1000 m
    kX = k * (x0 * math.cos(direction) + y0 * math.sin(direction))
    t, heights = 0.0, []
    for step in range(25):
        (pos, vel, acc), motions = expected_tow(R, H / 2, w, kX, t, lever, heading, x0, y0)
        got = v.get_reals(TOW)
        heights.append(got[2])
        assert np.allclose(got, np.concatenate([pos, vel, acc]), rtol=0, atol=1e-11), (t, got)
        assert np.allclose(v.get_reals(MOTIONS), motions, rtol=0, atol=1e-12)
        assert v.get("waveElevation") == pytest.approx(H / 2 * math.cos(kX - w * t), abs=1e-12)
        v.do_step(0.4, t=t)
        t += 0.4
    assert np.ptp(heights) > 0.4  # the wave moves the tow point: the test compares something


@pytest.mark.parametrize("mode, seed", [(1, 1), (2, 1), (2, 0), (2, 31337)])
def test_the_vessel_and_the_cable_see_the_same_sea(rao_fmu, fmu_file, make_unit, mode, seed):
    """The cable's tow point held at the vessel's reference point (x0, y0): the two waveElevation
    outputs agree to round-off at every communication point (the sea ramped in over 10 s)."""
    waves = {"waves.mode": mode, "waves.height": 3.0, "waves.period": 9.0, "waves.seed": seed,
             "waves.direction": 2.2, "waves.nComponents": 150, "waves.rampTime": 10.0, "waterDepth": 300.0}
    x0, y0 = -60.0, 25.0
    v = make_unit(rao_fmu, parameters={**waves, "x0": x0, "y0": y0})
    c = make_unit(fmu_file, parameters={**waves, "length": 50.0, "nElements": 2})
    v.initialize(0.0, 40.0)
    c.initialize(0.0, 40.0, inputs={"tow.x": x0, "tow.y": y0, "tow.z": 0.0})
    etas = []
    for k in range(40):
        v.do_step(0.5, t=0.5 * k)
        c.do_step(0.5, t=0.5 * k)
        etas.append((v.get("waveElevation"), c.get("waveElevation")))
    etas = np.array(etas)
    assert np.max(np.abs(etas[:, 0] - etas[:, 1])) < 1e-12 * 3.0
    assert np.std(etas[:, 0]) > 0.3  # a sea, not calm water


def test_bad_wave_parameters_are_errors_naming_the_variable(rao_fmu, make_unit):
    v = make_unit(rao_fmu, parameters={"waves.mode": 1, "waves.height": 12.0, "waves.period": 5.0}, instance_name="steep")
    with pytest.raises(FMICallException):
        v.initialize(0.0, 10.0)
    assert any("waves.height = 12 is too steep" in m for _, _, m in v.messages), v.log_text()
    u = make_unit(rao_fmu, instance_name="nan")
    with pytest.raises(FMICallException):
        u.set({"waves.period": float("nan")})
    assert any("waves.period = nan" in m for _, _, m in u.messages), u.log_text()
    w = make_unit(rao_fmu, parameters={"waves.mode": 3}, instance_name="mode")
    with pytest.raises(FMICallException):
        w.initialize(0.0, 10.0)
    assert any("waves.mode = 3 is outside [0, 2]" in m for _, _, m in w.messages), w.log_text()


ROW = ",".join(["1.0", "0.0"] * 6)


@pytest.mark.parametrize("text, named", [
    ("period,heading\n8,180," + ROW + "\n8,180,1\n", "line 3: expected 14 comma-separated numbers"),
    ("period,heading\n8,0," + ROW + "\n8,180," + ROW + "\n9,0," + ROW + "\n9,0," + ROW + "\n",
     "period 9 s and heading 0 deg appear twice"),
    ("period,heading\n8,0," + ROW + "\n9,180," + ROW + "\n", "2 rows are not one per period and heading"),
    ("period,heading\n-8,0," + ROW + "\n", "line 2: a period must be positive"),
    ("period,heading\n8,0," + ROW.replace("1.0", "nan", 1) + "\n", "line 2: a period must be positive, amplitudes"),
    ("# nothing but a comment\n", "has no rows"),
])
def test_a_malformed_rao_table_is_an_error_naming_the_file_and_line(rao_fmu, make_unit, tmp_path, text, named):
    v = make_unit(fmu_with_table(rao_fmu, tmp_path / "VesselRAO.fmu", text), parameters={"waves.mode": 1, "waves.height": 1.0})
    with pytest.raises(FMICallException):
        v.initialize(0.0, 10.0)
    assert any("rao.csv" in m and named in m for _, _, m in v.messages), v.log_text()


def test_a_one_row_table_holds_its_rao_for_every_period_and_heading(rao_fmu, make_unit, tmp_path):
    """One row: held beyond its period and for every heading; heave 0.5 m/m lagging 30 deg."""
    row = ",".join(["0", "0", "0", "0", "0.5", "30", "0", "0", "0", "0", "0", "0"])
    f = fmu_with_table(rao_fmu, tmp_path / "VesselRAO.fmu", f"period,heading\n10,90,{row}\n")
    v = make_unit(f, parameters={"waves.mode": 1, "waves.height": 2.0, "waves.period": 7.0, "towPoint.x": 0.0,
                            "heading": 1.0})
    v.initialize(0.0, 10.0)
    w = 2 * math.pi / 7.0
    for k in range(5):
        v.do_step(0.3, t=0.3 * k)
        assert v.get("heave") == pytest.approx(0.5 * math.cos(w * 0.3 * (k + 1) - math.radians(30.0)), abs=1e-13)


def test_reset_and_rerun_is_bit_identical(rao_fmu, make_unit):
    params = {"waves.mode": 2, "waves.height": 3.0, "waves.seed": 11, "waves.rampTime": 5.0, "towPoint.y": 2.0}
    v = make_unit(rao_fmu, parameters=params)
    outputs = [n for n, x in v.variables.items() if x.causality == "output"]

    def run():
        v.initialize(0.0, 20.0, parameters=params)
        for k in range(20):
            v.do_step(0.5, t=0.5 * k)
        return v.get_reals(outputs)

    first = run()
    v.slave.reset()
    assert np.array_equal(run(), first)
    assert np.std(first) > 0.0


@pytest.mark.parametrize("period", [80.0, 200.0])
@pytest.mark.parametrize("heading", [180.0, 135.0, 90.0, 30.0])
def test_the_shipped_raos_follow_the_surface_in_long_waves(period, heading):
    """The generic barge's RAOs (python/studies/cases/rao_box.py) tend to a vessel that follows the surface as
    the wave grows long: for eta = a e^{i k (x cos mu + y sin mu)}, heave a, roll d(eta)/dy = i k sin(mu) a
    (positive lifts the port side), pitch -d(eta)/dx = -i k cos(mu) a (positive lowers the bow), surge and
    sway the water's horizontal displacement i a (cos mu, sin mu), and yaw the rotation that best fits
    that displacement over the waterplane, -k sin(mu) cos(mu) (L^2 - B^2) / (L^2 + B^2) a. The
    oscillators' damping lags them by 2 zeta omega / omega_n (zeta <= 0.4), the rest is of order
    (omega / omega_n)^2, k T and (k L)^2: with omega_n the lowest natural frequency (roll, 9.8 s),
    0.8 r + 3 r^2, r = 9.8 s / period, bounds the difference (relative to k a for the rotations)."""
    from studies.cases.rao_box import B, L, box_raos
    w = 2 * math.pi / period
    k = w * w / 9.81
    mu = math.radians(heading)
    yaw = -k * math.sin(mu) * math.cos(mu) * (L * L - B * B) / (L * L + B * B)
    limit = np.array([1j * math.cos(mu), 1j * math.sin(mu), 1.0, 1j * k * math.sin(mu), -1j * k * math.cos(mu), yaw])
    scale = np.array([1.0, 1.0, 1.0, k, k, k])
    r = 9.8 / period
    assert np.all(np.abs(box_raos(period, heading) - limit) <= (0.8 * r + 3 * r * r) * scale)


# ---- raoFile: the engineer's own RAO table -------------------------------------------------------------

SEA = {"waves.mode": 2, "waves.height": 3.0, "waves.period": 9.0, "waves.seed": 5, "waves.direction": 2.4,
       "waves.rampTime": 4.0}
VESSEL_SEA = {**SEA, "speed0": 1.0, "speed1": 1.5, "turnStart": 2.0, "turnRate": 0.02, "turnAngle": 0.3}


def outputs_of_run(unit, steps=20, h=0.5):
    """Every output at every communication point of a run from t = 0: a dict name -> values."""
    names = [n for n, x in unit.variables.items() if x.causality == "output"]
    unit.initialize(0.0, steps * h)
    rows = [unit.get_reals(names)]
    for k in range(steps):
        unit.do_step(h, t=k * h)
        rows.append(unit.get_reals(names))
    return dict(zip(names, np.array(rows).T))


def table_with(path, scale_heave=1.0):
    """The shipped table written to path, its heave amplitudes times scale_heave (Python's shortest
    round-trip repr: strtod reads back exactly the scaled double)."""
    lines = RAO_CSV.read_text().splitlines()
    out = []
    for line in lines:
        fields = line.split(",")
        if len(fields) == 14 and not line.startswith("#") and fields[0] != "period":
            fields[6] = repr(float(fields[6]) * scale_heave)
        out.append(",".join(fields))
    path.write_text("\n".join(out) + "\n")
    return path


@pytest.mark.parametrize("name, params", [("VesselRAO", {**SEA, "towPoint.y": 4.0}), ("Vessel", VESSEL_SEA)])
def test_a_copy_of_the_shipped_table_as_raofile_moves_the_vessel_bit_identically(make_unit, tmp_path, monkeypatch,
                                                                                name, params):
    """The shipped table copied to a temporary file and named by raoFile as an absolute path, a file://
    URI and a path relative to the working directory; and "rao.csv" (relative: found in the resources
    first): every output at every point is the default's to the bit."""
    fmu = partner_fmu(name)
    copy = table_with(tmp_path / "my vessel.csv")  # a space: percent-encoded in the URI
    monkeypatch.chdir(tmp_path)
    default = outputs_of_run(make_unit(fmu, parameters=params, instance_name="default"))
    for value in (str(copy), copy.as_uri(), "my vessel.csv", "rao.csv"):
        unit = make_unit(fmu, parameters={**params, "raoFile": value}, instance_name="own")
        got = outputs_of_run(unit)
        assert all(np.array_equal(got[n], default[n]) for n in default), value
        assert unit.get("raoFile") == value
    assert np.ptp(default["tow.z"]) > 0.1  # the waves move the tow point: the comparison compares something


def test_doubled_heave_amplitudes_double_the_heave_of_a_tow_point_under_the_reference_point(rao_fmu, make_unit,
                                                                                           tmp_path):
    """Tow point at the RAO reference point (zero lever arm): its z is the heave alone, so a table with
    every heave amplitude doubled (phases unchanged) gives exactly twice the default's tow.z, tow.vz and
    tow.az (a factor 2 is exact in every operation of the interpolation and the sum), and the other
    degrees of freedom unchanged."""
    params = {**SEA, "towPoint.x": 0.0, "towPoint.y": 0.0, "towPoint.z": 0.0}
    names = ["tow.z", "tow.vz", "tow.az", "heave", "surge", "sway", "roll", "pitch", "yaw"]

    def run(extra):
        v = make_unit(rao_fmu, parameters={**params, **extra})
        v.initialize(0.0, 10.0)
        rows = []
        for k in range(20):
            v.do_step(0.5, t=0.5 * k)
            rows.append(v.get_reals(names))
        return np.array(rows)

    default = run({})
    doubled = run({"raoFile": str(table_with(tmp_path / "doubled.csv", 2.0))})
    assert np.ptp(default[:, 0]) > 0.1
    assert np.array_equal(doubled[:, :4], 2.0 * default[:, :4])
    assert np.array_equal(doubled[:, 4:], default[:, 4:])


@pytest.mark.parametrize("name, params", [("VesselRAO", SEA), ("Vessel", VESSEL_SEA)])
def test_a_missing_or_malformed_raofile_is_an_error_naming_raofile_and_the_path(make_unit, tmp_path, name, params):
    fmu = partner_fmu(name)
    missing = tmp_path / "no_such_table.csv"
    v = make_unit(fmu, parameters={**params, "raoFile": str(missing)}, instance_name="missing")
    with pytest.raises(FMICallException) as e:
        v.initialize(0.0, 10.0)
    assert e.value.status == 3  # fmi2Error
    assert any(f"raoFile = '{missing}' cannot be read: tried {missing} (no such file)" in m
               for _, _, m in v.messages), v.log_text()
    bad = tmp_path / "bad.csv"
    bad.write_text("period,heading\n8,180," + ROW + "\n8,180,1\n")
    u = make_unit(fmu, parameters={**params, "raoFile": bad.as_uri()}, instance_name="malformed")
    with pytest.raises(FMICallException) as e:
        u.initialize(0.0, 10.0)
    assert e.value.status == 3
    assert any(f"raoFile = '{bad.as_uri()}': RAO table {bad}, line 3: expected 14 comma-separated numbers" in m
               for _, _, m in u.messages), u.log_text()


def test_a_restored_state_brings_its_raofile_and_table(rao_fmu, make_unit, tmp_path):
    """A state of an instance with its own table, serialized and restored into an instance of the shipped
    table, continues with the saved instance's table, bit for bit."""
    own = str(table_with(tmp_path / "doubled.csv", 2.0))
    a = make_unit(rao_fmu, parameters={**SEA, "raoFile": own}, instance_name="a")
    c = make_unit(rao_fmu, parameters=SEA, instance_name="c")
    for u in (a, c):
        u.initialize(0.0, 20.0)
    for k in range(10):
        a.do_step(0.5, t=0.5 * k)
    data = a.serialize_state(a.get_state())
    tail = []
    for k in range(10):
        a.do_step(0.5, t=5.0 + 0.5 * k)
        tail.append(a.get_reals(TOW))
    c.set_state(c.deserialize_state(data), time=5.0)
    assert c.get("raoFile") == own
    for k in range(10):
        c.do_step(0.5, t=5.0 + 0.5 * k)
        assert np.array_equal(c.get_reals(TOW), tail[k])
