"""The census in motion (docs/systems_mooring.md, "The census in motion"): each deck the census loads under a
prescribed surge, in the FMU and in MoorDyn fed the same file (studies.comparisons.census_dynamics).

In CI: the study's machinery on decks kept in tests/data/decks/public (what moves, MoorDyn's coupled degrees
of freedom, a Fixed tow point made Coupled, the chain's ends, a MoorDyn blow-up reported as one) and the
OC3-Hywind deck `lines.txt` against MoorDyn within MoorDyn's own change when its mesh is refined. The full
census is a slow test: it needs the MoorDyn and MoorPy checkouts (UC_MOORDYN_CHECKOUT, UC_MOORPY_CHECKOUT).
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import numpy as np
import pytest

from studies.comparisons import census_dynamics as cd
from studies.comparisons import public_decks as pd
from studies.peers import moordyn

PUBLIC = pd.PUBLIC


def test_the_deck_reading_of_the_study():
    assert cd.line_lengths(PUBLIC / "md_tests_Mooring_lines.txt") == [902.2, 902.2, 902.2]
    assert cd.line_lengths(PUBLIC / "mp_tests_case2.dat") == [500.0, 380.0]  # its LINES table names the columns otherwise
    assert cd.has_bodies(PUBLIC / "md_example_body.txt") and not cd.has_bodies(PUBLIC / "md_tests_Mooring_lines.txt")
    # the amplitude: 1 % of the longest line, at most 2 m
    assert cd.amplitude(PUBLIC / "md_tests_Mooring_lines.txt", cd.Settings()) == 2.0
    assert cd.amplitude(PUBLIC / "md_tests_Mooring_pendulum.txt", cd.Settings()) == pytest.approx(1.005)
    # the pendulum's Fixed point 1 becomes Coupled for MoorDyn, nothing else changes
    before = (PUBLIC / "md_tests_Mooring_pendulum.txt").read_text().splitlines()
    after = cd.coupled_tow_text(PUBLIC / "md_tests_Mooring_pendulum.txt", 1).splitlines()
    changed = [(a, b) for a, b in zip(before, after) if a != b]
    assert len(after) == len(before) and len(changed) == 1
    assert changed[0][0].split()[:2] == ["1", "Fixed"] and changed[0][1].split()[:2] == ["1", "Coupled"]


def test_the_chain_of_deck_lines_from_the_tow_point():
    # points 1 (anchor, line 1 end A), 2 (joins line 1 end B and line 2 end A), 3 (tow point, line 2 end B)
    attached = cd._attached("1.0;1.1 2.0;2.1")
    assert cd.chain_ends(attached, 3) == ((2, 1), (1, 0))
    # a clump between lines, the tow point at end A of the first line
    assert cd.chain_ends(cd._attached("1.0;1.1 2.1;2.0"), 1) == ((1, 0), (2, 0))


# wavekin_4/hanging_lines's tables (two of its ten chains): each hangs from a Fixed point at its end A, its end B free
HANGING_LINES = """----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain       13.332E-3  1.1        7.51E6     -0.5        0        0.0    0.0      0.0     1.0
----------------------- POINTS ------------------------------------------------
Node      Type      X        Y         Z        M        V         CdA   CA
(-)       (-)      (m)      (m)       (m)      (kg)     (m^3)     (m^2)  (-)
1 fixed -50 0.0 -16.6 0 0 0 0
2 free -50 0.0 -26.6 0 0 0 0
3 fixed -40 0.0 -16.6 0 0 0 0
4 free -40 0.0 -26.6 0 0 0 0
-------------------------- LINES ----------------------------------------------
Line     LineType NodeA     NodeB  UnstrLen  NumSegs     Flags/Outputs
(-)      (-)       (-)       (-)   (m)         (-)          (-)
1 chain 1 2 10 10 p,tUD
2 chain 3 4 10 10 p,tUD
-------------------------- SOLVER OPTIONS---------------------------------------
0.00050   dtM          - time step to use in mooring integration
3.0e6     kb           - bottom stiffness
3.0e5     cb           - bottom damping
4000      WtrDpth      - water depth
0.0       TmaxIC       - threshold for IC convergence
------------------------- need this line --------------------------------------
"""


def test_moordyn_hangs_the_chains_still_at_a_quarter_of_the_decks_time_step(tmp_path):
    """hanging_lines's difference from the FMU is MoorDyn's time step (docs/systems_mooring.md, "The census in
    motion"): at the deck's dtM 0.5 ms its chains chatter axially (their top tension swings by hundreds of N);
    at 0.125 ms they hang still at their wet weight, the FMU's 93.8 N, within 0.5 %."""
    weight = (1.1 - 1025.0 * np.pi / 4.0 * 13.332e-3 ** 2) * 9.80665 * 10.0  # wet weight of 10 m of chain [N]
    deck = tmp_path / "hanging_lines.txt"
    deck.write_text(HANGING_LINES)
    n, h = 120, 0.1
    coarse = moordyn.driven(deck, h, n, timeout=300)
    fine = moordyn.driven(deck, h, n, text=HANGING_LINES.replace("0.00050   dtM", "0.000125  dtM"), timeout=300)
    late = np.arange(n + 1) * h >= 8.0
    assert coarse["error"] == "" and fine["error"] == ""
    assert np.ptp(coarse["tension"][0][late, 0]) > 100.0
    assert np.max(np.abs(fine["tension"][0][late] / weight - 1.0)) < 0.005
    assert np.max(np.abs(fine["tension"][1][late])) < 0.005 * weight


def test_the_fmu_line_ends_are_read_from_the_deck(tmp_path):
    """Which MoorDyn end of deck line k the FMU's line[k].fairleadTension and anchorTension are, by the FMU's rule
    on the deck's points: a chain hanging from a Fixed point at its end A has its fairlead there; a coupled end
    is the fairlead (end B where both are); a deck line reached through a Free point that joins two deck lines
    has its fairlead where the FMU's walk from the coupled end enters it."""
    deck = tmp_path / "hanging_lines.txt"
    deck.write_text(HANGING_LINES)
    assert cd.fmu_line_ends(deck) == [((1, 0), (1, 1)), ((2, 0), (2, 1))]
    assert cd.fmu_line_ends(PUBLIC / "md_tests_Mooring_lines.txt") == [((k, 1), (k, 0)) for k in (1, 2, 3)]
    # two lines from two Vessel points (both end A) joined at a Free point: each line's fairlead is its end A
    assert cd.fmu_line_ends(PUBLIC / "md_tests_Mooring_local_euler_hanging.txt") == [((1, 0), (1, 1)), ((2, 0), (2, 1))]
    # anchor segments (deck lines 1, 3, 5: Fixed A, Free B) entered at the Free point from the upper segments
    assert cd.fmu_line_ends(PUBLIC / "mp_examples_MoordynSemiTautUpd.dat") == [((k, 1), (k, 0)) for k in range(1, 7)]
    # the same anchor segment with its ends given the other way round: still entered at the Free point (end A)
    flipped = tmp_path / "semitaut_flipped.dat"
    text = (PUBLIC / "mp_examples_MoordynSemiTautUpd.dat").read_text()
    flipped.write_text(re.sub(r"^(1\s+0\s+)1(\s+)2(\s)", r"\g<1>2\g<2>1\3", text, count=1, flags=re.M))
    assert flipped.read_text() != text
    assert cd.fmu_line_ends(flipped)[0] == ((1, 0), (1, 1))


def test_the_fmu_line_ends_through_zero_length_rods(tmp_path):
    """local_euler/complex_system's tables (its rods' and points' kinds, its lines' ends): a Free rod of no
    segments is one free point joining two lines, a point on a Free body a free node; the FMU walks from the
    Coupled point 4 (line 7's end B) through rods 4, 3, 2 to the body, entering each line at its end B, then
    from the body's point 3 to the Fixed points 2 and 1 (through rod 1), again at end B."""
    deck = tmp_path / "complex_system.txt"
    deck.write_text("""---------------------------- BODIES ------------------------------
ID   Attachment  X0     Y0    Z0     r0      p0     y0     Mass  CG*   I*      Volume   CdA*    Ca
(#)     (-)      (m)    (m)   (m)   (deg)   (deg)  (deg)   (kg)  (m)  (kg-m^2)  (m^3)   (m^2)   (-)
1      Free      452.0   0  -313.0   0       0      0      29.5   0    0.098    0.014   0.5|0.5 1.0
---------------------- ROD TYPES ----------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
conn          0.1      0.0       0.0    0.0     0.0      0.0
---------------------- RODS ----------------------------------------
ID   RodType  Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs  RodOutputs
(#)  (name)    (#/key)    (m)   (m)   (m)   (m)   (m)   (m)  (-)       (-)
1    conn        Free     455.5  0  -313.0  455.5  0  -313.0  0         -
2    conn        Free     448.5  0  -313.0  448.5  0  -313.0  0         -
3    conn        Free     375.0  0  -250.0  375.0  0  -250.0  0         -
4    conn        Free     290.0  0  -215.0  290.0  0  -215.0  0         -
----------------------- POINTS ------------------------------------
Node      Type      X        Y         Z        M        V         CdA   CA
(-)       (-)      (m)      (m)       (m)      (kg)     (m^3)     (m^2)  (-)
1         Fixed    600.0     0      -320.0       0        0          0     0
2         Fixed    452.0     0      -320.0       0        0          0     0
3         Body1    0.0       0         0.0       0        0          0     0
4         Coupled  0.0       0       -63.6       0        0          0     0
-------------------------- LINES ----------------------------------
Line     LineType NodeA     NodeB  UnstrLen   NumSegs     Flags/Outputs
(-)      (-)       (-)       (-)    (m)         (-)          (-)
1        nylon       2         3      7.0        7           -
2        cable       1       R1A    147.0       15           -
3      stiffner    R1B         3     3.12        2           -
4      stiffner    3         R2A     3.12        2           -
5        cable     R2B       R3A    107.0       11           -
6      bouyancy    R3B       R4A     80.0        8           -
7        cable     R4B         4    340.0       34           -
""")
    assert cd.fmu_line_ends(deck) == [((k, 1), (k, 0)) for k in range(1, 8)]
    assert [key for ends in cd.line_end_roles(deck) for key, _ in ends][:6] == ["2", "3", "1", "R1", "R1", "3"]
    assert dict(e for ends in cd.line_end_roles(deck) for e in ends) == {
        "1": "fixed", "2": "fixed", "3": "node", "4": "coupled", "R1": "free", "R2": "free", "R3": "free", "R4": "free"}


def test_the_pairing_follows_the_deck_not_the_tensions(tmp_path):
    """hanging_lines: the FMU's chain at rest at its wet weight (93.8 N at the Fixed end, nothing at the free
    end) against MoorDyn's swinging 93.8 +- 200 N at its end A. A pairing by the closer mean would keep
    MoorDyn's free end B against the FMU's fairlead; the deck says the fairlead is end A."""
    deck = tmp_path / "hanging_lines.txt"
    deck.write_text(HANGING_LINES)
    t = np.arange(401) * 0.1
    fmu = {"system": True, "tension": np.stack([np.zeros((401, 2)), np.full((401, 2), 93.8)])}
    swing = 93.8 + 200.0 * np.sin(2.0 * np.pi * t / 3.0)
    md = {"tension": np.stack([np.column_stack([swing, swing]), np.zeros((401, 2))])}
    for label, fa, ff, ma, mf in cd.pairs(fmu, md, None, cd.fmu_line_ends(deck)):
        assert np.array_equal(mf, swing) and not ma.any(), label


def test_moordyn_driven_reports_its_coupled_objects_and_a_blow_up(tmp_path):
    """MoorDyn in its own process: lines.txt's three Vessel points are its coupled degrees of freedom and follow
    the surge (the force on them changes); the same deck at dtM 0.5 s blows up, which is a result, not a crash
    of the study."""
    deck = PUBLIC / "md_tests_Mooring_lines.txt"
    n, calls = 10, 2
    starts = np.arange(n * calls) / calls * 0.1
    shift = np.array([0.5 * (1.0 - np.cos(2.0 * np.pi * starts / 2.0)), 0.5 * np.pi * np.sin(2.0 * np.pi * starts / 2.0)])
    run = moordyn.driven(deck, 0.1, n, calls=calls, shift=shift, timeout=300)
    assert run["error"] == "" and run["layout"] == "point 4, point 5, point 6"
    assert run["tension"].shape == (2, n + 1, 3) and np.all(np.isfinite(run["tension"]))
    assert np.ptp(run["tension"][1][:, 0]) > 1e4  # 1 m of surge along line 1 pulls its fairlead by tens of kN
    held = moordyn.driven(deck, 0.1, n, timeout=300)
    assert np.ptp(held["tension"][1][:, 0]) < 0.1 * np.ptp(run["tension"][1][:, 0])
    unstable = deck.read_text().replace("0.002         dtM", "0.5           dtM")
    assert unstable != deck.read_text()
    bad = moordyn.driven(deck, 0.1, n, text=unstable, timeout=300)
    assert bad["error"], bad


def test_a_chain_between_two_fixed_points_is_towed_by_its_higher_one(fmu_file):
    """A one-line deck of three deck lines through two free points between two Fixed points (MoorPy's case4):
    the FMU moves `tow` (the higher Fixed point, 4), MoorDyn the same point made Coupled; the tow tension is
    compared with MoorDyn's at point 4 and the far-end tension at point 1 (its chain's other end)."""
    r = cd.run_deck(fmu_file, "case4", PUBLIC / "mp_tests_case4.dat",
                    settings=cd.Settings(t_end=2.0, t_from=1.0, period=4.0))
    assert r["status"] == "ok", r
    assert r["moved"] == "tow" and r["moordyn_layout"] == "point 4" and not r["system"]
    assert [row["label"] for row in r["rows"]] == ["tow point"]
    assert r["amplitude"] == 2.0  # 1 % of its 360 m lines is 3.6 m: the cap


def test_oc3_hywind_in_surge_agrees_with_moordyn_within_its_mesh_change(fmu_file):
    """lines.txt (the OC3-Hywind chains, 20 segments each, the FMU's body 1 carrying the three Vessel points)
    surging 2 m over 10 s: the FMU's fairlead and anchor tensions against MoorDyn's differ, RMS over the mean,
    by no more than twice what MoorDyn itself changes when its mesh is refined twice (its discretization error
    at the deck's mesh; measured over 10-20 s: FMU 0.27 % and 0.34 % from MoorDyn at fairlead and anchor,
    MoorDyn 2x finer 0.30 % and 0.31 % from MoorDyn, 4x finer the same), with a floor of 0.1 % for the two codes'
    time integration; the peaks likewise (0.10 % and 0.15 % against MoorDyn's change of 0.31 % and 0.38 %)."""
    settings = cd.Settings(t_end=20.0)
    r = cd.run_deck(fmu_file, "lines", PUBLIC / "md_tests_Mooring_lines.txt", settings=settings)
    assert r["status"] == "ok" and r["moved"] == "body[1]" and r["system"], r
    surge = cd.lfv.Surge(amplitude=r["amplitude"], period=settings.period)
    coarse = cd.moordyn_run(PUBLIC / "md_tests_Mooring_lines.txt", None, None, ["body[1]"], surge, settings)
    fine = cd.moordyn_run(PUBLIC / "md_tests_Mooring_lines.txt", None, None, ["body[1]"], surge,
                          cd.Settings(t_end=20.0, moordyn_refine=2))
    change = [cd.statistics(coarse["t"], "", fine["tension"][0][:, k], fine["tension"][1][:, k],
                            coarse["tension"][0][:, k], coarse["tension"][1][:, k], settings.t_from) for k in range(3)]
    for end in ("fairlead", "anchor"):
        own = max(c[end]["rel_mean"] for c in change)
        assert r["worst"][f"{end}.rel_mean"] < 2.0 * max(own, 1e-3), (end, r["worst"], own)
        own_peak = max(abs(c[end]["peak"]) for c in change)
        assert r["worst"][f"{end}.peak"] < 2.0 * max(own_peak, 1e-3), (end, r["worst"], own_peak)


def test_the_table_names_every_loaded_deck_and_what_failed():
    data = {"settings": {"period": 10.0, "fraction": 0.01, "cap": 2.0, "t_end": 40.0, "t_from": 10.0},
            "moordyn_version": "2.x", "decks": [
                {"deck": "a", "status": "refused", "amplitude": 1.0, "reason": "no"},
                {"deck": "b", "status": "moordyn", "amplitude": 1.0, "moved": "tow", "moordyn_error": "blew up",
                 "cpu_fmu": 0.1, "cpu_moordyn": 0.0, "cpu_moordyn_init": 0.0, "fmu_error": ""},
                {"deck": "c", "status": "ok", "amplitude": 2.0, "moved": "nothing", "until": 40.0, "t_end": 40.0,
                 "worst": {f"{e}.{k}": 0.01 for e in ("fairlead", "anchor") for k in ("peak", "rel_mean", "rel_range",
                                                                                         "start")},
                 "cpu_fmu": 0.1, "cpu_moordyn": 1.0, "cpu_moordyn_init": 0.5, "moordyn_error": "", "fmu_error": ""}]}
    text = cd.markdown(data)
    assert text.startswith("2 decks the FMU loads (of 3); compared with MoorDyn 2.x: 1; MoorDyn fails on 1")
    rows = [r for r in text.splitlines() if r.startswith("| `")]
    assert [r.split("`")[1] for r in rows] == ["b", "c"]
    assert "MoorDyn: blew up" in rows[0] and "unforced" in rows[1] and "1.00 %" in rows[1]


def _checkouts():
    md, mp = os.environ.get("UC_MOORDYN_CHECKOUT"), os.environ.get("UC_MOORPY_CHECKOUT")
    if not md or not mp or not Path(md).is_dir() or not Path(mp).is_dir():
        pytest.skip("the census needs the MoorDyn and MoorPy checkouts (UC_MOORDYN_CHECKOUT, UC_MOORPY_CHECKOUT)")
    return Path(md), Path(mp)


# The decks whose difference from MoorDyn docs/systems_mooring.md ("The census in motion") explains: MoorDyn's
# initial conditions, its seabed, its time scheme or its beam's vibration, not the FMU.
EXPLAINED = {
    # MoorDyn's initial conditions are not the statics
    "md:example/MHK_RM1_Floating/MHK_RM1_Floating_MoorDyn.dat", "md:tests/Mooring/lifting.txt", "md:tests/Mooring/local_euler/complex_system.txt",
    "md:tests/Mooring/local_euler/hanging.txt", "md:tests/Mooring/riser/riser_ic1.txt", "mp:tests/case2.dat",
    "mp:tests/case3.dat", "mp:tests/case4.dat", "mp:tests/case6.dat", "md:tests/Mooring/wavekin_7/wavekin_7.txt",
    # (BodiesAndRods: MoorDyn's run drops its free body from the deck's pose, its cans 2 m above the water)
    "md:tests/Mooring/BodiesAndRods.dat",
    # MoorDyn's local Euler step on the finer of two identical lines; its axially driven beam's vibration
    "md:tests/Mooring/local_euler/duplicated.txt", "md:tests/Mooring/BeamSimplySupported.txt",
    # seabed: MoorDyn's vertical contact on a slope; its friction against the FMU's Coulomb friction at the anchors
    "md:tests/Mooring/seafloor.txt", "md:tests/Mooring/WD0050_Chain.txt", "md:tests/Mooring/WD0200_Chain.txt",
    "md:tests/Mooring/WD0600_Chain.txt", "md:tests/Mooring/wavekin_2/wavekin_2.txt",
    "md:tests/Mooring/wavekin_2/wavekin_2_curr2.txt", "md:tests/Mooring/wavekin_2/wavekin_3.txt",
    "md:tests/Mooring/wavekin_2/wavekin_3_curr2.txt", "md:tests/Mooring/wavekin_current_1.txt",
    "md:tests/Mooring/wavekin_wave_1.txt",
    # a current with no static equilibrium: both start in still water; MoorDyn reads the 4-D file one row short,
    # the friction models differ under the current's drag along the grounded chain (docs/waves.md)
    "md:tests/Mooring/wavekin_2/wavekin_2_curr5.txt", "md:tests/Mooring/wavekin_2/wavekin_3_curr5.txt",
    # an anchor that is a free end with no tension; MoorDyn's axial chatter at the deck's dtM (hanging_lines)
    "md:tests/Mooring/wavekin_3/test_dynamic_currents.txt", "md:tests/Mooring/wavekin_4/hanging_lines.txt",
}


@pytest.mark.slow
def test_the_whole_census_in_motion(fmu_file):
    """Every deck the census loads runs in both codes or says why not; where both run, the FMU is within 5 % of
    MoorDyn, RMS of the difference over MoorDyn's mean at every line end, but for the decks the documentation
    explains (EXPLAINED)."""
    cases = cd.census_cases(*_checkouts())
    data = cd.compute(fmu_file, cases)
    loaded = [d for d in data["decks"] if d["status"] != "refused"]
    assert len(loaded) >= 44
    for d in loaded:
        assert d["status"] in ("ok", "moordyn", "fmu")
        if d["status"] != "ok":
            assert d["moordyn_error"] or d["fmu_error"], d
        elif d["deck"] not in EXPLAINED:
            for end in ("fairlead", "anchor"):
                worst = d["worst"][f"{end}.rel_mean"]
                assert not worst > 0.05, (d["deck"], end, worst)
    text = cd.markdown(data)
    assert sum(r.startswith("| `") for r in text.splitlines()) == len(loaded)
