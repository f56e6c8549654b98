"""MoorDyn's kinematics options in a deck (docs/lines.md, "Options and environment"): what the FMU's sea
state can represent is read into it and does what MoorDyn does with the same files; the rest is refused
naming the option and its value (tests/core/test_line_file.cpp, the census of docs/systems_mooring.md)."""

import math

import numpy as np
import pytest

from studies.comparisons import deck_currents as dc
from studies.peers.quiet import Quiet
from ucable.fmu import CableFMU


def test_a_steady_current_profile_file_is_the_fmus_current_profile(fmu_file, tmp_path):
    """Currents 1: the four rows of current_profile.txt (z increasing) are the profile of two rows (depths
    0 and 200 m): the row at -100 m lies on the line between its neighbours, the row at -320 m repeats the
    one at -200 m beyond which the profile is constant. The deck gives bit for bit the statics of the
    still-water deck with that profile set as parameters."""
    deck = dc.fmu_statics(fmu_file, dc.write_case(tmp_path))
    assert any("Currents 1: the steady profile of current_profile.txt is the current profile "
               "currentProfile.* (2 rows" in m for m in deck["messages"]), deck["messages"]
    still_dir = tmp_path / "still"
    still_dir.mkdir()
    by_parameters = dc.fmu_statics(fmu_file, dc.write_case(still_dir, current=False), **{
        "currentProfileRows": 2, "currentProfile.depth[1]": 0.0, "currentProfile.y[1]": 0.8,
        "currentProfile.depth[2]": 200.0, "currentProfile.y[2]": 0.2})
    assert np.array_equal(deck["force"], by_parameters["force"])
    assert deck["force"][1] > 4000.0  # the current pushes the chain across its plane


def test_the_deck_current_loads_the_chain_as_moordyn_does(fmu_file, tmp_path):
    """The chain in the sheared current across its plane: the FMU's static fairlead force against
    MoorDyn's (40 segments, run to rest for 200 s with the fairlead held). Measured: the current's
    lateral force 4550.8 N against MoorDyn's 4560.2 N (0.21 %; 4553.7 N at 80 segments against the FMU's
    4551.4 N at 40 elements: converging on each other), the whole force 0.022 % apart (MoorDyn's
    still-water discretization error at 40 segments is 2e-4, docs/lines.md)."""
    r = dc.compare(fmu_file, tmp_path, segments=40, t_end=200.0)
    assert r["fmu"][1] == pytest.approx(r["moordyn"][1], rel=5e-3)
    assert r["difference"] < 5e-4
    assert abs(r["still"][1]) < 1e-6 * abs(r["fmu"][1])


def _wave_deck(tmp_path, waves: str):
    text = dc.CHAIN.read_text()
    for old, new in (("2    Coupled     0        0     -70", "2    Coupled     30       20    -70"),
                     ("320      WtrDpth", "320      WtrDpth\n7        WaveKin")):
        assert old in text
        text = text.replace(old, new, 1)
    (tmp_path / "wave_frequencies.txt").write_text(waves)
    path = tmp_path / "chain_wave.dat"
    path.write_text(text)
    return path


def test_one_wave_component_is_the_regular_wave_moordyn_sums(fmu_file, tmp_path):
    """WaveKin 7 with one component in wave_frequencies.txt (0.6 rad/s, A = 1.5 i, travelling at 0.3 rad):
    the FMU's regular wave (height 3 m, period 10.47 s, direction 0.3 rad, Wheeler stretching) has at the
    fairlead (30, 20) m the elevation MoorDyn computes from the same file, to its seven-digit dispersion
    relation."""
    import moordyn

    path = _wave_deck(tmp_path, "0.0 0.0 0.0\n0.6 0.0 1.5 0.3\n")
    c = CableFMU(fmu_file, parameters=dc.fmu_parameters(path), logging_on=True)
    times, ours = np.arange(0.0, 6.01, 0.5), []
    try:
        c.initialize(inputs={"tow.x": 30.0, "tow.y": 20.0, "tow.z": -70.0})
        assert any("the regular wave waves.mode 1, height 3 m" in t for _, _, t in c.messages)
        ours.append(c.get("waveElevation"))
        for t in times[1:]:
            c.do_step(0.5, t - 0.5)
            ours.append(c.get("waveElevation"))
    finally:
        c.free()
    theirs = []
    with Quiet():
        system = moordyn.Create(str(path))
        try:
            x = [30.0, 20.0, -70.0]
            moordyn.Init(system, x, [0.0] * 3)
            waves = moordyn.GetWaves(system)
            theirs.append(moordyn.GetWavesKin(waves, 30.0, 20.0, 0.0)[2])
            for t in times[1:]:
                moordyn.Step(system, x, [0.0] * 3, t - 0.5, 0.5)
                theirs.append(moordyn.GetWavesKin(waves, 30.0, 20.0, 0.0)[2])
        finally:
            moordyn.Close(system)
    ours, theirs = np.array(ours), np.array(theirs)
    assert np.ptp(ours) > 1.0
    assert np.max(np.abs(ours - theirs)) < 1e-6 * 3.0, (ours, theirs)
    k = 0.6 ** 2 / 9.81  # deep water at 320 m: the phase of the component at the fairlead
    assert ours[0] == pytest.approx(1.5 * math.cos(k * (30.0 * math.cos(0.3) + 20.0 * math.sin(0.3))), abs=1e-3)


def test_external_kinematics_leave_the_water_to_the_fmus_sea_state(fmu_file, tmp_path):
    """WaveKin 1 (MoorDyn's water set by the program driving it, still until it does): the deck's statics
    are the still-water deck's, bit for bit, and the FMU's current inputs move the water."""
    path = _wave_deck(tmp_path, "")
    text = path.read_text().replace("7        WaveKin", "1        WaveKin")
    external = tmp_path / "external.dat"
    external.write_text(text)
    still = tmp_path / "still.dat"
    still.write_text(text.replace("1        WaveKin", "0        WaveKin"))
    forces = []
    for deck, current in ((external, 0.0), (still, 0.0), (external, 0.5)):
        c = CableFMU(fmu_file, parameters=dc.fmu_parameters(deck), logging_on=True)
        try:
            c.initialize(inputs={"tow.x": 30.0, "tow.y": 20.0, "tow.z": -70.0, "current.y": current})
            forces.append(np.array([c.get(f"towForce.{k}") for k in "xyz"]))
        finally:
            c.free()
    assert np.array_equal(forces[0], forces[1])
    assert forces[2][1] - forces[0][1] > 1000.0  # the cable pushed along +y pulls the fairlead along +y


def test_a_system_deck_takes_its_current_profile_to_every_line(fmu_file, tmp_path):
    """The OC4 platform's three chains with `Currents` 1 and current_profile.txt: every line's tensions
    are bit for bit those of the still-water deck with the same profile set as parameters, and differ
    from the still water's."""
    from studies.comparisons import mooring_system as ms

    text = ms.OC4.read_text()
    assert "0.001    dtM" in text
    current = tmp_path / "current"
    current.mkdir()
    (current / "oc4.dat").write_text(text.replace("0.001    dtM", "0.001    dtM\n1        Currents", 1))
    (current / "current_profile.txt").write_text("header\nnames\nunits\n-200 0.3 0.2 0\n0 1.0 0.0 0\n")
    (tmp_path / "oc4.dat").write_text(text)
    base = ms.fmu_parameters(ms.read_system_deck(ms.OC4))
    profile = {"currentProfileRows": 2, "currentProfile.depth[1]": 0.0, "currentProfile.x[1]": 1.0,
               "currentProfile.y[1]": 0.0, "currentProfile.depth[2]": 200.0, "currentProfile.x[2]": 0.3,
               "currentProfile.y[2]": 0.2}
    tensions = []
    for deck, extra in ((current / "oc4.dat", {}), (tmp_path / "oc4.dat", profile), (tmp_path / "oc4.dat", {})):
        c = CableFMU(fmu_file, parameters=base | {"lineFile": str(deck)} | extra, logging_on=True)
        try:
            c.initialize()
            tensions.append([c.get(f"line[{k}].{n}") for k in (1, 2, 3) for n in ("fairleadTension", "anchorTension")])
        finally:
            c.free()
    assert tensions[0] == tensions[1]
    assert max(abs(a / b - 1) for a, b in zip(tensions[0], tensions[2])) > 1e-3
