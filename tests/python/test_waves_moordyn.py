"""The riser in waves against MoorDyn fed the same wave components (docs/waves.md, "Against MoorDyn").

The chain of the comparison is checked link by link: the FMU's sea is the documented generator
(studies.references.sea, written again in Python) to round-off; MoorDyn, given those components as complex
amplitudes, computes the same water velocity, acceleration and elevation; then the two codes'
tensions agree within what their meshes resolve.
"""

import math

import numpy as np
import pytest

from studies.comparisons import waves_moordyn as wm
from ucable.fmu import CableFMU
from studies.references.sea import SplitMix64, sea_state

pytest.importorskip("moordyn")


def test_splitmix64_is_the_published_generator():
    # the first outputs of the reference implementation (Vigna's splitmix64.c) for seeds 0 and 1234567
    g = SplitMix64(0)
    assert [g.next() for _ in range(2)] == [0xE220A8397B1DCDAF, 0x6E789E6AA1B965F4]
    g = SplitMix64(1234567)
    assert [g.next() for _ in range(3)] == [6457827717110365317, 3203168211198807973, 9817491932198370423]


@pytest.mark.parametrize("params", [
    {"waves.mode": 2, "waves.height": 3.0, "waves.period": 9.0, "waves.seed": 7, "waves.nComponents": 40,
     "waterDepth": 120.0, "waves.direction": 0.4, "waves.gamma": 2.0},
    {"waves.mode": 1, "waves.height": 2.5, "waves.period": 7.0, "waterDepth": 30.0, "waves.direction": -1.1},
    {"waves.mode": 2, "waves.height": 3.0, "waves.period": 9.0, "waves.seed": 7, "waves.nComponents": 20,
     "waterDepth": 120.0, "waves.direction": 0.4, "waves.spreading": 3.0, "waves.nDirections": 7},
])
def test_the_fmu_sea_is_the_documented_generator(fmu_file, params):
    """waveElevation at the tow point of the FMU equals the elevation of studies.references.sea's components."""
    params = {**params, "gravity": 9.80665, "length": 20.0}
    x, y, dt = 13.0, -4.0, 0.5
    with CableFMU(fmu_file, parameters=params) as c:
        c.initialize(0.0, inputs={"tow.x": x, "tow.y": y})
        eta = [c.get("waveElevation")]
        for k in range(30):
            c.set({"tow.x": x, "tow.y": y})
            c.do_step(dt, k * dt)
            eta.append(c.get("waveElevation"))
    sea = sea_state(params)
    expected = sea.elevation(x, y, np.arange(len(eta)) * dt)
    assert np.ptp(eta) > 0.5
    assert np.abs(np.array(eta) - expected).max() < 1e-12 * params["waves.height"]


@pytest.mark.parametrize("waves", [wm.REGULAR, wm.IRREGULAR, wm.SPREAD], ids=lambda w: w.name)
def test_moordyn_computes_the_same_water(waves):
    """MoorDyn's kinematics of the components (WaveKin 7, Wheeler stretching) are our closed form.
    MoorDyn solves the dispersion relation to seven digits (Newman's one-step method, its docs), so
    the irregular sea's 50 components agree to ~1e-8 relative, the regular wave to ~1e-11."""
    riser = wm.Riser()
    bound = 1e-10 if waves.mode == 1 else 1e-6
    with wm.MoorDynRiser(riser, waves, 10) as md:
        for t in (0.0, 3.7):
            if t > 0.0:
                md.step(0.0, t)
            for point in ((0.0, 0.0, -5.0), (0.0, 0.0, -40.0), (12.0, 3.0, -70.0), (0.0, 0.0, -99.0)):
                u, a, eta = md.kinematics(*point)
                U, A, ETA = md.sea.kinematics(*point, t, riser.depth)
                assert np.abs(u - U).max() < bound * np.abs(U).max()
                assert np.abs(a - A).max() < bound * np.abs(A).max()
                assert abs(eta - ETA) < bound * waves.height


def stats(h, t_from):
    """(top RMS, top amplitude, bottom RMS, bottom amplitude) and the fluctuations (means removed)."""
    st = wm.statistics(h, t_from)
    sel = h.t >= t_from - 1e-9
    values = np.array([st[e][k] for e in ("top", "bottom") for k in ("rms", "amplitude")])
    return values, {e: getattr(h, e)[sel] - getattr(h, e)[sel].mean() for e in ("top", "bottom")}


def check_agreement(fmu_file, case, elements, segments):
    """Each code on two meshes; the finer runs of the two codes must agree within the sum of their
    discretization errors, estimated from the two meshes: ours by the change from the coarser mesh
    (the Hermite elements converge fast: the change bounds the error), MoorDyn's by Richardson's
    estimate of a second-order method, change / 3 (its lumped masses: the measured changes fall
    4x per halving of the segments, docs/waves.md). A factor 1.5 covers the estimates' own
    uncertainty. The codes solve the same equations, so no model difference is allowed for."""
    riser, waves = case.riser, case.waves
    f0, f1 = (wm.run_fmu(fmu_file, riser, waves, n) for n in elements)
    m0, m1 = (wm.run_moordyn(riser, waves, n) for n in segments)
    (F0, _), (F1, h_f), (M0, _), (M1, h_m) = (stats(h, waves.t_from) for h in (f0, f1, m0, m1))
    bound = 1.5 * (np.abs(F1 - F0) + np.abs(M1 - M0) / 3.0)
    assert np.all(np.abs(F1 - M1) <= bound), (F1, M1, bound)
    # the histories: the RMS of the difference of the fluctuations, by the triangle inequality
    for end in ("top", "bottom"):
        err = lambda a, b: float(np.sqrt(np.mean((a - b) ** 2)))  # noqa: E731
        _, g_f = stats(f0, waves.t_from)
        _, g_m = stats(m0, waves.t_from)
        hist_bound = 1.5 * (err(h_f[end], g_f[end]) + err(h_m[end], g_m[end]) / 3.0)
        assert err(h_f[end], h_m[end]) <= hist_bound, (end, err(h_f[end], h_m[end]), hist_bound)
    return F1, M1


CASES = {c.name: c for c in wm.CASES}


def test_riser_in_a_regular_wave_agrees_with_moordyn(fmu_file):
    """The taut riser in the regular wave (100 s, statistics over the last 60 s) on coarse meshes:
    ours 5 and 10 elements, MoorDyn's 10 and 20 segments (about 1.5 s of CPU)."""
    ours, theirs = check_agreement(fmu_file, CASES["taut, regular"], (5, 10), (10, 20))
    assert np.all(np.abs(ours / theirs - 1.0) < 0.03)  # and they are close in the first place


@pytest.mark.slow
def test_riser_in_an_irregular_sea_agrees_with_moordyn(fmu_file):
    """The taut riser in the irregular sea (240 s, statistics over 200 s): ours 10 and 20 elements,
    MoorDyn's 20 and 40 segments (about 90 s of CPU)."""
    check_agreement(fmu_file, CASES["taut, irregular"], (10, 20), (20, 40))


@pytest.mark.slow
def test_hanging_umbilical_in_a_regular_wave_agrees_with_moordyn(fmu_file):
    """The hanging umbilical in the regular wave (250 s, statistics over the last 100 s): ours 5 and
    10 elements, MoorDyn's 20 and 40 segments (about 12 s of CPU). At the body MoorDyn's tension is
    its last segment's, half a segment above: that offset is a discretization error of its own,
    which the two meshes measure like the others."""
    check_agreement(fmu_file, CASES["hanging, regular"], (5, 10), (20, 40))


def test_spread_sea_reference_has_the_spreadings_moments():
    """The Python generator of a spread sea (written from docs/waves.md): Hs = 4 sqrt(m0) and the energy's
    mean cos(theta - beta) = s / (s + 1) of cos-2s (n > s + 1 directions: the midpoint rule is exact)."""
    sea = sea_state({"waves.mode": 2, "waves.height": 3.0, "waves.period": 9.0, "waves.nComponents": 30,
                     "waterDepth": 80.0, "waves.direction": 0.6, "waves.spreading": 4.0, "waves.nDirections": 9})
    assert sea.amplitude.size == 270
    assert abs(sea.hs() - 3.0) < 1e-12
    energy = 0.5 * sea.amplitude ** 2
    assert abs(np.sum(energy * np.cos(sea.directions() - 0.6)) / np.sum(energy) - 4.0 / 5.0) < 1e-12


@pytest.mark.slow
def test_riser_in_a_spread_sea_agrees_with_moordyn(fmu_file):
    """The taut riser in a short-crested sea (cos-2s, s = 2, 5 directions of 20 components; 120 s,
    statistics over the last 80 s): ours 5 and 10 elements, MoorDyn's 10 and 20 segments fed the same
    100 components with their directions (about 30 s of CPU)."""
    riser = wm.Riser()
    ours, theirs = check_agreement(fmu_file, wm.Case("taut, spread", riser, wm.SPREAD), (5, 10), (10, 20))
    assert np.all(np.abs(ours / theirs - 1.0) < 0.03)
