"""Given wave components, waves.mode 3 (docs/waves.md, "Given components"): from a file set by the importer
(waves.file) and from a MoorDyn deck's WaveKin 7 (its public deck wavekin_7.txt, two components of two
directions), against the closed form and against MoorDyn fed the same files."""

import math

import numpy as np
import pytest

from studies.comparisons import wave_components as wc
from ucable.fmu import CableFMU
from ucable.paths import REPO_ROOT

WAVEKIN_7 = REPO_ROOT / "tests" / "data" / "decks" / "public" / "wavekin_7"
G = 9.81


def wave_number(w: float, depth: float) -> float:
    k = w * w / G
    for _ in range(100):
        k -= (G * k * math.tanh(k * depth) - w * w) / (G * math.tanh(k * depth) + G * k * depth / math.cosh(k * depth) ** 2)
    return k


def test_a_waves_file_is_the_sum_of_its_components(fmu_file, tmp_path):
    """waves.mode 3 with waves.file (rows omega, amplitude, phase, [direction]; a row without a direction
    travels along waves.direction): waveElevation at the tow point is the closed-form sum of the
    components, a cos(k (x cos b + y sin b) - omega t + p), to 1e-12 of their amplitudes."""
    components = [(0.5, 0.8, 0.3, None), (0.9, 0.3, -1.0, 1.2), (0.62, 0.5, 2.0, None)]
    (tmp_path / "waves.txt").write_text("# omega amplitude phase direction\n" + "".join(
        f"{w!r} {a!r} {p!r}" + ("" if b is None else f" {b!r}") + "\n" for w, a, p, b in components))
    direction, depth, x, y = 0.4, 80.0, 12.0, -7.0
    c = CableFMU(fmu_file, parameters={"waves.mode": 3, "waves.file": str(tmp_path / "waves.txt"),
                                       "waves.direction": direction, "waterDepth": depth, "gravity": G,
                                       "length": 50.0, "nElements": 5}, logging_on=True)
    try:
        c.initialize(inputs={"tow.x": x, "tow.y": y, "tow.z": -5.0})
        assert any("waves.file" in m and "read: 3 wave components" in m for _, _, m in c.messages)
        for t in np.arange(0.5, 5.01, 0.5):
            c.do_step(0.5, t - 0.5)
            eta = sum(a * math.cos(wave_number(w, depth) * (x * math.cos(direction if b is None else b)
                                                             + y * math.sin(direction if b is None else b)) - w * t + p)
                      for w, a, p, b in components)
            assert c.get("waveElevation") == pytest.approx(eta, abs=1e-12 * 1.6)
    finally:
        c.free()


def test_a_waves_file_that_cannot_be_read_or_makes_no_sea_is_refused_naming_it(fmu_file, tmp_path):
    (tmp_path / "bad.txt").write_text("0.5 1.0\n")
    (tmp_path / "good.txt").write_text("0.5 1.0 0.0\n")
    for mode, name, what in ((3, "missing.txt", "waves.file = '"),
                             (3, "bad.txt", "line 1: a row is omega [rad/s] amplitude [m]"),
                             (1, "good.txt", "is set with waves.mode = 1: its components are the sea of waves.mode 3 only")):
        c = CableFMU(fmu_file, parameters={"waves.mode": mode, "waves.file": str(tmp_path / name)}, logging_on=True)
        try:
            with pytest.raises(Exception):
                c.initialize()
            assert any(what in m for _, _, m in c.messages), c.messages
        finally:
            c.free()


@pytest.mark.slow
def test_wavekin_7_deck_loads_its_two_directions_and_its_tension_follows_moordyns(fmu_file, tmp_path):
    """MoorDyn's public deck wavekin_7.txt: two components (0.35 rad/s, 1 m along x; 0.4 rad/s, 1 m at
    1.57 rad) on a light chain from an anchor 400 m away to a vessel point held at the surface. The FMU
    reads them as waves.mode 3 (two directions of travel); MoorDyn runs on the same files. The water is the
    same: the elevation at the fairlead within 1e-6 m (MoorDyn's seven-digit dispersion relation; measured
    1.1e-10 m). Over 40 to 80 s the fairlead tension's range agrees within 10 % (measured 461.4 N against
    443.9 N, 4.0 %; the history of the fluctuation 6.7 % of MoorDyn's RMS apart). The means are not
    compared: in still water the two codes' statics agree to 0.05 % (2866.1 N, 2867.5 N), in the waves
    the FMU's mean rises by 5.7 %, MoorDyn's does not (docs/waves.md, "Given components": a difference at
    the fairlead, which pierces the surface, left open)."""
    r = wc.compare(fmu_file, WAVEKIN_7, tmp_path, t_end=80.0, step=0.5, settle=40.0)
    assert any("WaveKin 7: the 2 components of wave_frequencies.txt are the given components of waves.mode 3"
               in m for m in r["messages"]), r["messages"]
    assert r["elevation"] < 1e-6
    assert r["fmu"]["range"] == pytest.approx(r["moordyn"]["range"], rel=0.10)
    assert r["history"] < 0.15


def test_wavekin_2_spectrum_is_moordyns_water_at_its_grid_samples(fmu_file, tmp_path):
    """WaveKin 2: MoorDyn interpolates wave_frequencies.txt (uneven rows: 0, 0.25, 0.5, 0.75, 1 rad/s and
    one at 0.625) to steps of the smallest spacing, 0.125 rad/s, transforms it onto the grid of
    water_grid.txt (samples every 2 pi / 0.125 / 16 = pi s) and interpolates linearly between samples.
    The FMU reads the interpolated spectrum as its components and sums them: its waveElevation at the
    fairlead, linearly interpolated between its values at the grid's sample times, is MoorDyn's water at
    the grid node there, within the dtM (2 ms) by which MoorDyn's clock may miss the sampling instant
    (its steepest slope x 2 ms)."""
    import moordyn as md_api

    from studies.comparisons import deck_currents as dc
    from studies.peers.quiet import Quiet

    text = dc.CHAIN.read_text()
    for old, new in (("2    Coupled     0        0     -70", "2    Coupled     30       0     -70"),
                     ("320      WtrDpth", "320      WtrDpth\n2        WaveKin")):
        assert old in text
        text = text.replace(old, new, 1)
    (tmp_path / "chain_spectrum.dat").write_text(text)
    rows = [(0.0, 0.0, 0.0), (0.25, 0.6, 0.2), (0.5, -0.3, 0.9), (0.625, 0.2, -0.4), (0.75, 0.0, 0.5), (1.0, 0.1, 0.0)]
    (tmp_path / "wave_frequencies.txt").write_text("".join(f"{w} {r} {i}\n" for w, r, i in rows))
    (tmp_path / "water_grid.txt").write_text("grid\nx y z\nlists\n1\n0.0 30.0 60.0\n1\n-1.0 0.0 1.0\n1\n-320 -70 0\n")
    period = 2 * math.pi / 0.125
    dt = period / 16
    c = CableFMU(fmu_file, parameters=dc.fmu_parameters(tmp_path / "chain_spectrum.dat"), logging_on=True)
    try:
        c.initialize(inputs={"tow.x": 30.0, "tow.y": 0.0, "tow.z": -70.0})
        assert any("WaveKin 2: the spectrum of wave_frequencies.txt, interpolated to equal frequency steps as "
                   "MoorDyn does, is 8 given components" in m for _, _, m in c.messages), c.messages
        samples = [c.get("waveElevation")]
        for k in range(1, 17):
            c.do_step(dt, (k - 1) * dt)
            samples.append(c.get("waveElevation"))
    finally:
        c.free()
    assert samples[-1] == pytest.approx(samples[0], abs=1e-9)  # periodic, as the transform is
    times = np.arange(0.0, 30.01, 0.5)
    theirs = []
    with Quiet():
        system = md_api.Create(str(tmp_path / "chain_spectrum.dat"))
        try:
            x = [30.0, 0.0, -70.0]
            md_api.Init(system, x, [0.0] * 3)
            waves = md_api.GetWaves(system)
            theirs.append(md_api.GetWavesKin(waves, 30.0, 0.0, -70.0)[2])
            for t in times[1:]:
                md_api.Step(system, x, [0.0] * 3, t - 0.5, 0.5)
                theirs.append(md_api.GetWavesKin(waves, 30.0, 0.0, -70.0)[2])
        finally:
            md_api.Close(system)
    ours = np.interp(times % period, np.arange(17) * dt, samples)
    slope = np.max(np.abs(np.diff(samples))) / dt  # the steepest slope of MoorDyn's interpolation
    assert np.ptp(theirs) > 0.5
    assert np.max(np.abs(ours - np.array(theirs))) < slope * 0.002 + 1e-6, (ours, theirs)


def test_wavekin_3_record_is_the_fmus_water_at_its_samples(fmu_file):
    """MoorDyn's public deck wavekin_3.txt (WaveKin 3, dtWave 0.15 s, Currents 1): the record of
    wave_elevation.txt (one period of a 15 s sine, 1 m, sampled every 0.15 s) becomes the Fourier
    components of its 100 samples up to 0.5 Hz; the FMU's waveElevation at the fairlead (x = 0, where the
    record is) is the record at its sample times, to 1e-9 m (the components above 0.5 Hz that are cut
    carry round-off only)."""
    deck = REPO_ROOT / "tests" / "data" / "decks" / "public" / "wavekin_3"
    record = np.loadtxt(deck / "wave_elevation.txt")
    c = CableFMU(fmu_file, parameters={"lineFile": str(deck / "wavekin_3.txt")}, logging_on=True)
    try:
        c.initialize(inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": -2.0})
        assert any("WaveKin 3: the record of wave_elevation.txt resampled at dtWave = 0.14999999999999999 s "
                   "(100 samples) is the sum of its 7 Fourier components up to 0.5 Hz" in m
                   for _, _, m in c.messages), c.messages
        ours = [c.get("waveElevation")]
        for k in range(1, 6):
            c.do_step(0.3, 0.3 * (k - 1))
            ours.append(c.get("waveElevation"))
    finally:
        c.free()
    assert np.max(np.abs(np.array(ours) - record[0:12:2, 1])) < 1e-9, (ours, record[0:12:2, 1])


def test_a_spread_sea_moves_the_cable_as_its_components_given_in_a_file(fmu_file, tmp_path):
    """waves.spreading (a cos-2s sea in 5 directions of 20 components) against the same 100 components
    given in waves.file with their directions (studies.references.sea, the documented generator): the same
    elevation to 1e-12 of Hs, and a hanging 50 m cable's tow tension through 20 s of the residual's
    kinematics (a polynomial per direction) the same within the integrator's local error bound,
    tensionTolerance (1e-5) of the tension: the two paths differ by round-off only."""
    from studies.references.sea import sea_state
    spread = {"waves.mode": 2, "waves.height": 2.0, "waves.period": 8.0, "waves.nComponents": 20,
              "waves.spreading": 2.0, "waves.nDirections": 5, "waves.direction": 0.5}
    common = {"waterDepth": 60.0, "gravity": G, "length": 50.0, "nElements": 6, "tensionTolerance": 1e-5,
              "initialDirection.x": 0.0, "initialDirection.z": -1.0}
    sea = sea_state({**spread, **common})
    assert sea.amplitude.size == 100 and len(set(sea.directions())) == 5
    (tmp_path / "spread.txt").write_text("".join(
        f"{float(w)!r} {float(a)!r} {float(p)!r} {float(b)!r}\n"
        for w, a, p, b in zip(sea.omega, sea.amplitude, sea.phase, sea.directions())))
    runs = []
    for params in (spread, {"waves.mode": 3, "waves.file": str(tmp_path / "spread.txt")}):
        with CableFMU(fmu_file, parameters={**params, **common}) as c:
            c.initialize(inputs={"tow.x": 3.0, "tow.y": -2.0, "tow.z": -2.0})
            record = []
            for k in range(40):
                c.do_step(0.5, 0.5 * k)
                record.append((c.get("waveElevation"), c.get("towTension")))
            runs.append(np.array(record))
    spread_run, given_run = runs
    assert np.ptp(spread_run[:, 0]) > 0.5 and np.ptp(spread_run[:, 1]) > 10.0  # the sea moves the cable
    assert np.abs(spread_run[:, 0] - given_run[:, 0]).max() < 1e-12 * 2.0
    assert np.abs(spread_run[:, 1] - given_run[:, 1]).max() < 1e-5 * spread_run[:, 1].mean()
