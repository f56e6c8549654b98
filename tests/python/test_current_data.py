"""A current given as data (docs/waves.md, "A current given as data"): currents.mode 2 (MoorDyn's
current_profile_dynamic.txt, depth x time) and 5 (its current_profile_4d.txt, x, y, z, t) from the parameter
currents.file or from a MoorDyn deck's Currents 2 or 5; the data are not in the saved state."""

import numpy as np
import pytest

from ucable.fmu import CableFMU

DECK = """--------------------- MoorDyn Input File ------------------------------------
a chain hanging from a fixed point in a current changing in time
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.0133  1.1        7.51E6     -0.5        0          2.4    0.0    0.1     0.0
----------------------- POINTS ------------------------------------------------
Node      Type      X        Y         Z        M        V         CdA   CA
(-)       (-)      (m)      (m)       (m)      (kg)     (m^3)     (m^2)  (-)
1         fixed     18       5         -10      0        0         0     0
2         free      18       5         -40      0        0         0     0
-------------------------- LINES -----------------------------------------------
Line     LineType NodeA     NodeB  UnstrLen  NumSegs     Flags/Outputs
(-)      (-)       (-)       (-)    (m)         (-)          (-)
1        chain     1         2      30          10           -
-------------------------- OPTIONS ---------------------------------------------
400       WtrDpth      - water depth
2         Currents     - current_profile_dynamic.txt
------------------------- need this line ---------------------------------------
"""
TOP = {"tow.x": 18.0, "tow.y": 5.0, "tow.z": -10.0}


def dynamic_profile(z, t, f) -> str:
    """current_profile_dynamic.txt of ux = f(z, t) (uy = 0): depths on line 5, rows t ux(z) uy(z) from line 7."""
    rows = "".join(f"{float(ti)!r} " + " ".join(repr(float(f(zi, ti))) for zi in z) + " " + " ".join("0.0" for _ in z)
                   + "\n" for ti in t)
    return "--- MoorDyn dynamic currents ---\ncomment\n2\n3\n" + " ".join(repr(float(v)) for v in z) + "\n\n" + rows


def run(c: CableFMU, steps: int, h: float, t0: float = 0.0) -> list:
    out = []
    for k in range(steps):
        c.do_step(h, t0 + k * h)
        out.append(c.get("towTension"))
    return out


def test_a_currents_file_is_the_same_water_as_the_current_inputs(fmu_file, tmp_path):
    """currents.mode 2 with a current uniform in depth and constant in time, 0.6 m/s along x, is the input
    current.x = 0.6: the same statics at t = 0 (the line starts in the current) and the same run, to the
    static solver's and integrator's round-off."""
    (tmp_path / "c.txt").write_text(dynamic_profile([-300.0, 0.0], [0.0, 100.0], lambda z, t: 0.6))
    base = {"length": 40.0, "nElements": 8}
    by_data = CableFMU(fmu_file, parameters={**base, "currents.mode": 2, "currents.file": str(tmp_path / "c.txt")},
                       logging_on=True)
    by_inputs = CableFMU(fmu_file, parameters=base)
    calm = CableFMU(fmu_file, parameters=base)
    try:
        by_data.initialize()
        by_inputs.initialize(inputs={"current.x": 0.6})
        calm.initialize()
        assert any("currents.file" in m and "read: a profile of 2 depths" in m for _, _, m in by_data.messages)
        a, b = by_data.get("towTension"), by_inputs.get("towTension")
        assert a == pytest.approx(b, rel=1e-9)
        assert abs(a - calm.get("towTension")) > 1.0  # the current matters
        assert run(by_data, 5, 1.0) == pytest.approx(run(by_inputs, 5, 1.0), rel=1e-6)
    finally:
        by_data.free()
        by_inputs.free()
        calm.free()


def test_a_deck_with_currents_2_reads_its_file_beside_it_and_warns_once_past_the_data(fmu_file, tmp_path):
    """A deck's Currents 2: current_profile_dynamic.txt beside the deck is currents.mode 2. The data end at
    4 s: past them the current is held, with one warning."""
    (tmp_path / "deck.txt").write_text(DECK)
    (tmp_path / "current_profile_dynamic.txt").write_text(
        dynamic_profile([-41.0, 0.0], [0.0, 2.0, 4.0], lambda z, t: 0.2 * t))
    c = CableFMU(fmu_file, parameters={"lineFile": str(tmp_path / "deck.txt")}, logging_on=True)
    try:
        c.initialize(inputs=TOP)
        text = c.log_text()
        assert "Currents 2: current_profile_dynamic.txt, a profile of 2 depths" in text
        assert f"currents.file {tmp_path / 'current_profile_dynamic.txt'} read" in text
        run(c, 6, 1.0)
        passes = [m for _, _, m in c.messages if "passes the current's last sample (t = 4 s)" in m]
        assert len(passes) == 1, passes
    finally:
        c.free()


@pytest.mark.parametrize("logging_on", [True, False])
def test_a_warning_of_a_step_reaches_the_logger_as_a_warning(fmu_file, tmp_path, logging_on):
    """A warning the core raises while stepping (here: the run passes the current data's last sample) is
    logged with status fmi2Warning in category logStatusWarning, its "warning: " mark dropped, whether
    logging is on or off (a warning is always emitted). (fmi2DoStep returns fmi2OK: the step was taken, as
    with the input checks' warnings, docs/interface.md.)"""
    (tmp_path / "deck.txt").write_text(DECK)
    (tmp_path / "current_profile_dynamic.txt").write_text(
        dynamic_profile([-41.0, 0.0], [0.0, 2.0, 4.0], lambda z, t: 0.2 * t))
    with CableFMU(fmu_file, parameters={"lineFile": str(tmp_path / "deck.txt")}, logging_on=logging_on) as c:
        c.initialize(inputs=TOP)
        run(c, 6, 1.0)
        passes = [(status, category, m) for status, category, m in c.messages
                  if "passes the current's last sample (t = 4 s)" in m]
    assert passes == [("WARNING", "logStatusWarning", passes[0][2])], passes
    assert passes[0][2].startswith("fmi2DoStep: at t = ")  # no "warning: " left in the text


def test_saved_states_hold_no_data_and_restore_where_the_file_is(fmu_file, tmp_path):
    """The data are parameters outside the saved state: a state is as large with 4920 values as with 4 (to
    1 % of the data's size), a
    restore into a new instance continues bit for bit (the file read again), and without the file the
    restore is refused naming currents.file."""
    data = tmp_path / "c.txt"
    data.write_text(dynamic_profile(list(np.linspace(-200.0, 0.0, 41)), list(np.arange(0.0, 60.0, 0.5)),
                                    lambda z, t: 0.3 + 0.002 * z + 0.2 * np.sin(0.3 * t)))
    # the same kind of current from four values: the serialized state stores runs of zeros compactly, so its
    # size depends on what is zero in it; a current of the same kind leaves the same entries zero
    small = tmp_path / "small.txt"
    small.write_text(dynamic_profile([-200.0, 0.0], [0.0, 59.5], lambda z, t: 0.3 + 0.002 * z + 0.2 * np.sin(0.3 * t)))
    base = {"length": 40.0, "nElements": 8}
    with_data = {**base, "currents.mode": 2, "currents.file": str(data)}
    a = CableFMU(fmu_file, parameters=with_data)
    plain = CableFMU(fmu_file, parameters={**base, "currents.mode": 2, "currents.file": str(small)})
    fresh = CableFMU(fmu_file, parameters=with_data, logging_on=True)
    try:
        a.initialize()
        plain.initialize()
        fresh.initialize()
        run(a, 4, 0.5)
        run(plain, 4, 0.5)
        saved = a.serialize_state(a.get_state())
        # 4920 values of data against 4: in the state they would add (4920 - 4) x 8 bytes; the run-length
        # coding of zeros moves the sizes by a few words
        assert abs(len(saved) - len(plain.serialize_state(plain.get_state()))) < 0.01 * (4920 - 4) * 8
        expected = run(a, 6, 0.5, t0=2.0)
        fresh.set_state(fresh.deserialize_state(saved))
        assert run(fresh, 6, 0.5, t0=2.0) == expected  # bit for bit
        data.unlink()
        gone = CableFMU(fmu_file, parameters=base, logging_on=True)
        try:
            gone.initialize()
            with pytest.raises(Exception):
                gone.set_state(gone.deserialize_state(saved))
            assert any("fmi2SetFMUstate: currents.file = '" + str(data) + "' cannot be read" in m
                       for _, _, m in gone.messages), gone.messages
        finally:
            gone.free()
    finally:
        a.free()
        plain.free()
        fresh.free()


def test_currents_data_that_cannot_be_read_are_refused_naming_the_file_and_line(make_cable, tmp_path):
    (tmp_path / "bad.txt").write_text("2 1 1 1\n0 1\n0\n0\n0\n0 0 0 0 1 0 0\n")
    cases = [(5, "missing.txt", "currents.file = '"),
             (5, "bad.txt", "1 rows of nodes, the grid 2 x 1 x 1 x 1 has 2"),
             (2, "bad.txt", "(currents.mode 2), no rows \"t ux(z) [uy(z) [uz(z)]]\" from line 7")]
    for mode, name, what in cases:
        c = make_cable(parameters={"currents.mode": mode, "currents.file": str(tmp_path / name)}, logging_on=True)
        with pytest.raises(Exception):
            c.initialize()
        assert [m for _, _, m in c.messages if what in m], (what, c.messages)


def test_lines_without_normal_drag_hang_straight_in_a_current_given_as_data(make_cable, tmp_path):
    """Two chains with Cd 0 hanging from fixed points to free points (a mooring system) in a 4D current:
    the current makes no normal drag, each line starts hanging straight, its top tension its wet weight
    (the start's direction in the flow was 0 / 0 without normal drag)."""
    deck = DECK.replace("2.4    0.0    0.1     0.0", "0.0    0.0    0.0     0.0")
    deck = deck.replace("2         free      18       5         -40      0        0         0     0",
                        "2         free      18       5         -40      0        0         0     0\n"
                        "3         fixed     30       5         -10      0        0         0     0\n"
                        "4         free      30       5         -40      0        0         0     0")
    deck = deck.replace("1        chain     1         2      30          10           -",
                        "1        chain     1         2      30          10           -\n"
                        "2        chain     3         4      30          10           -")
    deck = deck.replace("2         Currents     - current_profile_dynamic.txt", "5         Currents     - 4D")
    (tmp_path / "deck.txt").write_text(deck)
    nodes = "".join(f"{x} {y} {z} {t} {0.1 * x + 0.1 * t} 0 0\n"
                    for x in (0.0, 50.0) for y in (0.0, 10.0) for z in (-50.0, 0.0) for t in (0.0, 10.0))
    (tmp_path / "current_profile_4d.txt").write_text("2 2 2 2\n0 50\n0 10\n-50 0\n0 10\n" + nodes)
    c = make_cable(parameters={"lineFile": str(tmp_path / "deck.txt")}, logging_on=True)
    c.initialize(inputs=TOP)
    wet = (1.1 - 1025.0 * np.pi * 0.0133 ** 2 / 4) * 9.80665 * 30.0
    for k in (1, 2):
        assert c.get(f"line[{k}].fairleadTension") == pytest.approx(wet, rel=1e-3)
