"""A seabed given as a grid of heights (seabed.file, a deck's SeafloorFile; docs/model.md "A seabed given as a
grid"): a grid that is a plane is the plane of seabedSlope; a line on a curved grid starts from the
discrete equilibrium; a file that cannot be read is refused naming it and its line."""

import math
from pathlib import Path

import numpy as np
import pytest

from ucable.fmu import CableFMU

DECKS = Path(__file__).resolve().parents[1] / "data" / "decks"
OUTPUTS = ["towTension", "endTension", "groundedLength", "touchdownArcLength", "endPosition.z", "shape.z[10]"]


def grid_text(xs, ys, height) -> str:
    """MoorDyn's SeafloorFile of height(x, y)."""
    rows = [f"{len(xs)} {len(ys)}", " ".join(f"{x:.17g}" for x in xs), " ".join(f"{y:.17g}" for y in ys)]
    rows += [f"{x:.17g} {y:.17g} {height(x, y):.17g}" for x in xs for y in ys]
    return "\n".join(rows) + "\n"


def moorpy_text(xs, ys, height) -> str:
    """MoorPy's bathymetry file of the same heights (depths positive down, a row per y)."""
    rows = ["--- MoorPy bathymetry ---", f"nGridX {len(xs)}", f"nGridY {len(ys)}", " ".join(f"{x:.17g}" for x in xs)]
    rows += [f"{y:.17g} " + " ".join(f"{-height(x, y):.17g}" for x in xs) for y in ys]
    return "\n".join(rows) + "\n"


def test_a_grid_that_is_a_plane_is_the_plane_of_seabed_slope(fmu_file, tmp_path):
    """seabed.file holding the plane z = -362.5 - 0.05 x (MoorDyn's format, and MoorPy's) is the seabed of
    waterDepth 362.5 m, seabedSlope atan 0.05: the chain of chain.dat starts and runs the same to round-off
    (its statics through the grid's local planes, its graded mesh from the profile on the plane under its
    touchdown). Before, seabed.file did not exist."""
    plane = lambda x, y: -362.5 - 0.05 * x  # noqa: E731
    xs, ys = np.linspace(-1000.0, 200.0, 13), [-100.0, 0.0, 100.0]
    (tmp_path / "md.txt").write_text(grid_text(xs, ys, plane))
    (tmp_path / "mp.txt").write_text(moorpy_text(xs, ys, plane))
    deck = str(DECKS / "chain.dat")
    cables = [CableFMU(fmu_file, parameters={"lineFile": deck, "seabed.file": str(tmp_path / name)}, logging_on=True)
              for name in ("md.txt", "mp.txt")]
    cables.append(CableFMU(fmu_file, parameters={"lineFile": deck, "waterDepth": 362.5,
                                                 "seabedSlope": math.degrees(math.atan(0.05)),
                                                 "seabedSlopeHeading": 0.0}))
    try:
        values, runs = [], []
        for c in cables:
            c.initialize(inputs={"tow.z": -70.0})
            values.append(c.get_reals(OUTPUTS))
            run = []
            for k in range(4):
                c.set({"tow.x": 1.0 * math.sin(0.4 * (k + 1)), "tow.vx": 0.4 * math.cos(0.4 * (k + 1))})
                c.do_step(0.5, 0.5 * k)
                run.append(c.get_reals(["towTension", "endTension", "groundedLength"]))
            runs.append(run)
        assert any("seabed.file" in m and "read: 13 x 3 points" in m for _, _, m in cables[0].messages)
        assert values[2][2] > 5.0  # part of the chain rests on the slope
        for k in (0, 1):
            np.testing.assert_allclose(values[k], values[2], rtol=1e-9, atol=1e-9)
            # in motion the integrator's error control sees residuals that differ by round-off: its steps may
            # differ, and the tensions agree to well within its tolerance; the grounded length, where the line
            # crosses half a diameter above a seabed it meets at a small angle, to a millimetre
            a, b = np.array(runs[k]), np.array(runs[2])
            np.testing.assert_allclose(a[:, :2], b[:, :2], rtol=1e-5)
            np.testing.assert_allclose(a[:, 2], b[:, 2], atol=1e-3)
    finally:
        for c in cables:
            c.free()


def test_a_line_on_a_curved_grid_starts_from_the_discrete_equilibrium(fmu_file, tmp_path):
    """The chain of chain.dat across a ridge (studies.comparisons.seabed_grid: the seabed curved along the
    line, the anchor 40 m below a crest it hangs over) given as the deck's SeafloorFile: the statics end at the
    equilibrium of the discrete line on the grid (5 s held at rest move the tensions by less than 1e-6 and
    the shape by less than a millimetre), the resting part on the grid's curved flank. Before, the deck was refused (its
    grid is not a plane)."""
    from studies.comparisons import seabed_grid as study

    (tmp_path / "grid.txt").write_text(study.seafloor_text(study.ridge))
    deck = tmp_path / "chain_grid.dat"
    deck.write_text(study.deck_text(study.ridge, "grid.txt"))
    c = CableFMU(fmu_file, parameters={"lineFile": str(deck)}, logging_on=True)
    try:
        c.initialize(inputs={"tow.z": study.FAIRLEAD_Z})
        assert any("its grid is not a plane" in m for _, _, m in c.messages)
        start, shape = c.get_reals(OUTPUTS), c.shape()
        assert start[2] > 100.0, start  # resting over the crest and down to the anchor
        assert c.get("endPosition.z") == pytest.approx(study.ridge(study.ANCHOR_X, 0.0), abs=0.05)
        c.do_step(5.0, 0.0)
        after, moved = c.get_reals(OUTPUTS), c.shape()
        np.testing.assert_allclose(after[:2], start[:2], rtol=1e-6)
        drift = max(np.max(np.abs(moved[k] - shape[k])) for k in ("shape.x", "shape.y", "shape.z"))
        assert drift < 1e-3, drift
        # no station below the grid; those on the curved flank below the crest, towards the anchor, on it
        # (the grid's interpolant, linear between the nodes along the line on the valley's level floor)
        floor = lambda x: np.interp(x, study.XS, [study.ridge(v, 0.0) for v in study.XS])  # noqa: E731
        for x, y, z in zip(shape["shape.x"], shape["shape.y"], shape["shape.z"]):
            assert abs(y) < 1.0 and z > floor(x) - 0.02, (x, y, z)
            if x < -650.0:  # (the cubic elements, 22 m, span the interpolant's kinks every 25 m by centimetres)
                assert z == pytest.approx(floor(x), abs=0.05), (x, z)
    finally:
        c.free()


def test_a_seabed_file_that_cannot_be_read_is_refused_naming_the_file_and_line(make_cable, tmp_path):
    (tmp_path / "down.txt").write_text("3 2\n0 10 5\n0 1\n")
    (tmp_path / "short.txt").write_text("2 2\n0 10\n0 1\n0 0 -50\n0 1 -50\n10 0 -50\n")
    (tmp_path / "mp.txt").write_text("title\nnGridX 2\nnGridY 2\n0 10\n0 50 50\n")
    cases = [("missing.txt", "seabed.file = '"),
             ("down.txt", "line 2: x = 5 after 10: the values must increase"),
             ("short.txt", "without the grid point (10, 1)"),
             ("mp.txt", "1 lines of depths where nGridY = 2")]
    for name, what in cases:
        c = make_cable(parameters={"seabed.file": str(tmp_path / name), "enableSeabed": True}, logging_on=True)
        with pytest.raises(Exception):
            c.initialize()
        said = [m for _, _, m in c.messages if what in m and (name in m or "cannot be read" not in m)]
        assert said and any(str(tmp_path / name) in m or name in m for m in said), (what, c.messages)
    # with a sloped plane at once: refused naming both
    c = make_cable(parameters={"seabed.file": str(tmp_path / "short.txt"), "enableSeabed": True, "seabedSlope": 3.0},
                   logging_on=True)
    with pytest.raises(Exception):
        c.initialize()
    assert any("seabedSlope = 3" in m and "seabed.file" in m for _, _, m in c.messages), c.messages


def test_the_chain_on_a_valley_against_moorpy_and_across_a_ridge_against_moordyn(fmu_file, tmp_path):
    """studies.comparisons.seabed_grid: on the valley (a floor of slope 0.04 along the line, on which MoorPy's
    chord between the seabed under the ends is exact) the FMU's statics are MoorPy's with its bathymetry file
    (measured 1.5e-5 at the fairlead, 1.7e-5 at the anchor: the catenary against 40 elements); across the
    ridge MoorDyn after its relaxation (its contact vertical) holds the suspended part as the FMU does
    (measured 3.4e-4 at the fairlead), the grounded length within a segment. Before, seabed.file and a
    SeafloorFile that is not a plane did not exist."""
    from studies.comparisons import seabed_grid as study

    fmu = study.fmu_statics(fmu_file, study.valley, tmp_path)
    moorpy = study.moorpy_statics(study.valley, tmp_path)
    assert fmu["fairlead"] == pytest.approx(moorpy["fairlead"], rel=1e-4)
    assert fmu["anchor"] == pytest.approx(moorpy["anchor"], rel=1e-4)
    assert fmu["fairlead after 5 s"] == pytest.approx(fmu["fairlead"], rel=1e-9)  # the start is at rest
    fmu = study.fmu_statics(fmu_file, study.ridge, tmp_path)
    moordyn = study.moordyn_relaxed(study.ridge, tmp_path)
    assert fmu["fairlead"] == pytest.approx(moordyn["fairlead"], rel=1e-3)
    assert abs(fmu["grounded"] - moordyn["grounded"]) < 900.0 / 40


def test_a_state_restored_into_a_new_instance_reads_the_grid_again(fmu_file, tmp_path):
    """The grid is not in the saved state: a new instance reads seabed.file when the state is set into it and
    runs on bit for bit."""
    from studies.comparisons import seabed_grid as study

    (tmp_path / "grid.txt").write_text(study.bathymetry_text(study.ridge))  # MoorPy's format
    deck = tmp_path / "chain.dat"
    deck.write_text(study.deck_text(study.ridge))
    parameters = {"lineFile": str(deck), "seabed.file": str(tmp_path / "grid.txt")}
    a = CableFMU(fmu_file, parameters=parameters)
    fresh = CableFMU(fmu_file, parameters=parameters, logging_on=True)
    try:
        a.initialize(inputs={"tow.z": study.FAIRLEAD_Z})
        fresh.initialize(inputs={"tow.z": study.FAIRLEAD_Z})
        for k in range(2):
            a.set({"tow.x": 0.5 * (k + 1), "tow.vx": 0.5})
            a.do_step(1.0, float(k))
        saved = a.serialize_state(a.get_state())
        expected = []
        for k in range(3):
            a.set({"tow.x": 1.0 - 0.3 * k, "tow.vx": -0.3})
            a.do_step(1.0, 2.0 + k)
            expected.append(a.get_reals(OUTPUTS))
        fresh.set_state(fresh.deserialize_state(saved))
        got = []
        for k in range(3):
            fresh.set({"tow.x": 1.0 - 0.3 * k, "tow.vx": -0.3})
            fresh.do_step(1.0, 2.0 + k)
            got.append(fresh.get_reals(OUTPUTS))
        assert np.array_equal(np.array(got), np.array(expected))
        assert any("seabed.file" in m and "read: 49 x 13 points" in m for _, _, m in fresh.messages)
    finally:
        a.free()
        fresh.free()


def test_a_mooring_system_deck_gives_each_line_the_grid(fmu_file, tmp_path):
    """The ridge deck with a second chain 40 m aside (on the valley's flank): a mooring system, each line on
    the grid; the first line starts as the one-line deck does, to round-off."""
    from studies.comparisons import seabed_grid as study

    (tmp_path / "grid.txt").write_text(study.seafloor_text(study.ridge))
    one = tmp_path / "one.dat"
    one.write_text(study.deck_text(study.ridge, "grid.txt"))
    point = "2    Coupled     0        0     -70     0      0       0      0"
    text = one.read_text().replace(point, point + f"\n3    Fixed       -850     40    {study.ridge(-850.0, 40.0):.6f}"
                                   "     0      0       0      0\n4    Coupled     0        40    -70     0      0       0      0")
    line = "1    chain     1        2        900       40       -"
    (tmp_path / "two.dat").write_text(text.replace(line, line + "\n2    chain     3        4        900       40       -"))
    single = CableFMU(fmu_file, parameters={"lineFile": str(one)})
    system = CableFMU(fmu_file, parameters={"lineFile": str(tmp_path / "two.dat")}, logging_on=True)
    try:
        single.initialize(inputs={"tow.z": study.FAIRLEAD_Z})
        system.initialize()
        lines = system.get_reals(["line[1].fairleadTension", "line[1].anchorTension", "line[2].fairleadTension"])
        np.testing.assert_allclose(lines[:2], single.get_reals(["towTension", "endTension"]), rtol=1e-9)
        assert lines[2] == pytest.approx(lines[0], rel=0.01)  # on the flank: its seabed 0.11 m higher
    finally:
        single.free()
        system.free()
