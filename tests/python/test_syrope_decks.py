"""MoorDyn's Syrope decks (tests/Mooring/syrope/{linear_wc,quadratic_wc,exp_wc}/line.txt, copied in
tests/data/decks/public/syrope with their settings and original working curve) load, and their tension under a
slow stretch, hold, unload and reload of the Coupled point with a wave-frequency strain on top follows MoorDyn
run on the same decks (docs/model.md, "Syrope fibre-rope model")."""

import numpy as np
import pytest

from studies.comparisons import syrope
from ucable.fmu import CableFMU
from ucable.paths import REPO_ROOT

FOLDER = REPO_ROOT / "tests" / "data" / "decks" / "public" / "syrope"


def closed_form_start(case) -> float:
    """The tension at the start by hand: the slow strain at Tmean0 on the working curve of Tmax0 (MoorDyn's
    definition: the curve's foot eps_min = eps_0 + k1 (eps_max - eps_0), eps_0 the first point of owc.dat as MoorDyn
    reads it, after three header lines; eps_max the table's strain at Tmax0), and the slow strain's rate at rest
    (c + c_d) z' = (alpha + beta T) (eps - eps_c(T)), the rope carrying T + c z'."""
    table = np.loadtxt(FOLDER / "owc.dat", skiprows=3)
    settings = {row.split()[1].lower(): row.split()[0] for row in (FOLDER / case / "syrope.dat").read_text().splitlines()}
    form, k1, k2 = settings["wctype"].upper(), float(settings["k1"]), float(settings["k2"])
    Tmax0, Tmean0, alpha, beta, c, cd = 1.3886e6, 4.339e5, 1.53e8, 23.12, 5e10, 1e5
    top = np.interp(Tmax0, table[:, 1], table[:, 0])
    foot = top - Tmax0 / k1 if form == "LINEAR" and k1 >= 1 else table[0, 0] + k1 * (top - table[0, 0])
    u = Tmean0 / Tmax0
    if form == "QUADRATIC":
        xi = (np.sqrt((1 - k2) ** 2 + 4 * k2 * u) - (1 - k2)) / (2 * k2)
    elif form == "EXP":
        xi = np.log1p(u * np.expm1(k2)) / k2
    else:
        xi = u
    eps_c = foot + (top - foot) * xi
    return Tmean0 + (alpha + beta * Tmean0) * (syrope.initial_strain(FOLDER / case / "line.txt") - eps_c) * c / (c + cd)


@pytest.mark.parametrize("case", syrope.CASES)
def test_a_syrope_deck_loads_and_starts_from_its_initial_tensions(fmu_file, case):
    """The deck's SYROPE IC: every element on the working curve of Tmax0 = 1.3886e6 N at Tmean0 = 4.339e5 N. The
    tension at the start against the closed form within 500 N (measured 40 to 70 N: the FMU's original working
    curve is the monotone cubic through the table's points, the closed form's the straight lines, which put eps_max
    a little apart at Tmax0, turned into tension by the dynamic stiffness 1.6e8 N)."""
    c = CableFMU(fmu_file, parameters={"lineFile": str(FOLDER / case / "line.txt")}, logging_on=True)
    try:
        c.initialize(inputs={"tow.x": 1.0 + syrope.initial_strain(FOLDER / case / "line.txt"), "tow.z": -5.0})
        assert c.get("towTension") == pytest.approx(closed_form_start(case), abs=500.0)
    finally:
        c.free()


def _compare(case, settings, rms_bound):
    r = syrope.compute(FOLDER, settings, cases=(case,))["cases"][0]
    assert r["rms"] < rms_bound * r["range"], r
    return r


@pytest.mark.parametrize("case", syrope.CASES)
def test_the_tension_follows_moordyns_through_a_stretch_unload_and_reload(case):
    """Legs of 150 s (half a relaxation time of the slow strain): the RMS difference from MoorDyn within 0.2 % of
    the tension's range (measured 0.02 %: MoorDyn interpolates its curves linearly between the table's points and
    its working curve on 30 points, the FMU the monotone cubic; docs/model.md)."""
    pytest.importorskip("moordyn")
    _compare(case, syrope.Settings(segment=150.0), 0.002)


@pytest.mark.slow
@pytest.mark.parametrize("case", syrope.CASES)
def test_the_tension_follows_moordyns_over_the_documented_profile(case):
    pytest.importorskip("moordyn")
    _compare(case, syrope.Settings(), 0.002)


def _run(c, deck_strain, t0, t1, s):
    """Steps the Coupled point along the study's profile from t0 to t1; the tension after every step."""
    out = []
    for k in range(int(round((t1 - t0) / s.comm_step))):
        t = t0 + k * s.comm_step
        e, de = syrope.strain(t, deck_strain, s)
        c.set({"tow.x": 1.0 + e, "tow.vx": de})
        c.do_step(s.comm_step, t=t)
        out.append(c.get("towTension"))
    return np.array(out)


def test_a_state_set_back_before_the_peak_takes_the_history_back(fmu_file):
    """The largest mean tension so far (the working curve's top) is part of the FMU state: a state got at 150 s,
    before the ramp to 3 eps0 (its tension peaks at 5.0e6 N, far above Tmax0 = 1.39e6 N: the history grows), set back
    after the peak, continues bit for bit as a second instance that stopped at 150 s, over the next 150 s held at
    eps0; so does the state serialized and deserialized. (With the history left out of the state the set-back rope
    unloads on the peak's working curve: 4.7e5 N off.)"""
    deck = FOLDER / "linear_wc" / "line.txt"
    eps0 = syrope.initial_strain(deck)
    s = syrope.Settings(segment=150.0)
    start = {"tow.x": 1.0 + eps0, "tow.z": -5.0}
    a = CableFMU(fmu_file, parameters={"lineFile": str(deck)})
    b = CableFMU(fmu_file, parameters={"lineFile": str(deck)})
    try:
        a.initialize(inputs=start)
        b.initialize(inputs=start)
        _run(a, eps0, 0.0, 150.0, s)
        _run(b, eps0, 0.0, 150.0, s)
        state = a.get_state()
        b.free_state(b.get_state())  # (getting a state makes the next step evaluate a new Jacobian: b's too)
        serialized = a.serialize_state(state)
        peak = _run(a, eps0, 150.0, 450.0, s)
        assert peak.max() > 3e6
        # the profile held at eps0 from 150 s on: the same inputs for both
        flat = syrope.Settings(segment=1e9)
        a.set_state(state, time=150.0)
        after = _run(a, eps0, 150.0, 300.0, flat)
        expected = _run(b, eps0, 150.0, 300.0, flat)
        assert np.array_equal(after, expected), np.max(np.abs(after - expected))
        restored = a.deserialize_state(serialized)
        a.set_state(restored, time=150.0)
        assert np.array_equal(_run(a, eps0, 150.0, 300.0, flat), expected)
        a.free_state(restored)
        a.free_state(state)
    finally:
        a.free()
        b.free()
