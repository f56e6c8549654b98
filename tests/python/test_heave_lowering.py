"""The heave-lowering scene (VesselRAO FMU -> cable FMU): the 2 t body on 500 m of umbilical of the
lowering_in_waves scene file hanging from the stern of a vessel in a regular head sea (H 2 m, T 10 s),
10 elements, 0.2 s communication steps, 60 s, the winch held; and the scene itself lowers the body.

Against a 10 s wave the line is stiff: its axial spring EA / L carries the body (and the added mass and
a third of the line) at a natural frequency omega_n well above the wave's, so
- the mean top tension over whole wave periods is the wet weight of the umbilical and the body;
- the top tension is that weight plus the moving mass (body + added mass + line) times the stern's
  vertical acceleration, plus a drag term in phase with the velocity;
- the body heaves in phase with the stern, amplified by the spring: 1 / (1 - omega^2 / omega_n^2).
"""

import math

import numpy as np
import pytest

from studies.cases import heave_lowering
from studies.cases.heave_lowering import HeaveLoweringCase, run

from ucable.units import GRAVITY as G, WATER_DENSITY as RHO

PERIOD = 10.0


@pytest.fixture(scope="module")
def regular(fmu_file):
    # the winch held (lower_rate 0): the analysis below is of a line of fixed length
    scene = HeaveLoweringCase(t_end=60.0, mode=1, hs=2.0, tp=PERIOD, components=1, ramp=10.0, n_elements=10, step=0.2,
                  lower_rate=0.0)
    return run(scene, fmu_file)


def masses(line):
    body = line["body.mass"] + line["body.addedMass"]
    return body, line["massPerLength"] * line["length"]


def test_mean_top_tension_is_the_wet_weight(regular):
    """Over the four whole periods after the ramp the oscillating loads average out; the drag of a
    symmetric oscillation has no mean. Tolerance 1e-3: the horizontal pendulum and the quadratic drag
    leave a mean far below it."""
    line = regular.scene.line()
    body = line["body.mass"] - RHO * line["body.volume"]
    wet = line["massPerLength"] - RHO * math.pi * line["diameter"] ** 2 / 4
    weight = (body + wet * line["length"]) * G
    t = regular.time
    whole = (t >= 20.0) & (t < 60.0 - 1e-9)
    assert regular["cable.towTension"][whole].mean() == pytest.approx(weight, rel=1e-3)


def test_top_tension_is_weight_plus_inertia_of_the_moving_mass(regular):
    """Least-squares fit T = T0 + M a_z + c v_z over the settled part: M is the moving mass, body + added
    mass + line = 4 t, to 3 % (the spring amplifies the body's motion by 2.2 %, see below; the wave loads
    on the upper line and the harmonics of the quadratic drag stay out of the fit); c > 0 is a damping."""
    k = regular.time >= 20.0
    a, v = regular["vessel.tow.az"][k], regular["vessel.tow.vz"][k]
    A = np.column_stack([np.ones(k.sum()), a, v])
    (T0, M, c), *_ = np.linalg.lstsq(A, regular["cable.towTension"][k], rcond=None)
    assert M == pytest.approx(sum(masses(regular.scene.line())), rel=0.03)
    assert c > 0.0
    assert np.std(a) > 0.3  # the stern moves: the fit measures something


def test_the_body_heaves_with_the_stern_amplified_by_the_line_spring(regular):
    """Body over stern heave amplitude = 1 / (1 - (omega / omega_n)^2), omega_n^2 = (EA / L) / (body +
    added mass + line / 3) (the line's mass as a spring's, a third of it at the end): 1.022 here, to
    0.5 % (drag damps the oscillator: a second-order change at this frequency ratio), in phase
    (correlation > 0.999)."""
    line = regular.scene.line()
    body, m_line = masses(line)
    wn2 = line["EA"] / line["length"] / (body + m_line / 3)
    expected = 1.0 / (1.0 - (2 * math.pi / PERIOD) ** 2 / wn2)
    k = regular.time >= 20.0
    body_z, stern = regular["cable.endPosition.z"][k], regular["vessel.tow.z"][k]
    assert np.std(body_z) / np.std(stern) == pytest.approx(expected, rel=0.005)
    assert np.corrcoef(body_z, stern)[0, 1] > 0.999
    assert regular.snap_events() == []  # the least axial force stays positive (12.8 kN) in this sea


def test_the_scene_command_writes_its_csv_and_figure(fmu_file, tmp_path):
    from studies.cosim.manoeuvre_cli import main
    assert main(["heave-lowering", "--t-end", "2", "--components", "10", "--nElements", "4",
                 "--fmu", str(fmu_file), "--out", str(tmp_path)]) == 0
    data = np.genfromtxt(tmp_path / "heave-lowering.csv", delimiter=",", names=True)
    assert len(data) == 11 and data.dtype.names[0] == "time"
    assert set(heave_lowering.COLUMNS) >= {"cable.minTension", "vessel.tow.z", "cable.endPosition.z"}
    assert (tmp_path / "heave-lowering.png").stat().st_size > 10000


def test_the_system_file_is_the_scene_and_libcosim_runs_it(fmu_file):
    """systems/heave_lowering/OspSystemStructure.xml holds the scene's start values (the sea, Integer
    parameters included, identical in both units) and libcosim runs it: the vessel's tow point is the
    closed form the fmpy scene records (to round-off: the two masters accumulate time differently), and the top tension follows the fmpy run within what the
    missing input derivatives allow: libcosim passes no der(tow.v*), so the cable takes the top
    acceleration a step late, an error of at most the moving mass (4 t) times the largest change of the
    stern's acceleration over one step."""
    from ucable import system as S

    system = S.SystemStructure.parse(S.systems_dir() / "heave_lowering" / "OspSystemStructure.xml")
    scene = HeaveLoweringCase(t_end=10.0, ramp=20.0)
    assert system.simulators["vessel"].initial == scene.vessel_parameters()
    assert system.simulators["cable"].initial == scene.cable_parameters()
    assert system.step == scene.step
    for s in system.simulators.values():
        s.source = S.fmu_path() if s.source.name == "UnderwaterCable.fmu" else S.partner_fmu(s.source.stem)
    osp = S.run_libcosim(system, {}, scene.step, scene.t_end)
    ref = run(HeaveLoweringCase(t_end=10.0), fmu_file)
    assert np.max(np.abs(osp["vessel.tow.z"] - ref["vessel.tow.z"])) < 1e-12  # the same closed form
    az = ref["vessel.tow.az"]
    bound = 4000.0 * np.max(np.abs(np.diff(az)))
    assert np.max(np.abs(osp["cable.towTension"] - ref["cable.towTension"])) < bound
    assert np.std(ref["vessel.tow.z"]) > 0.05  # the ramp has begun: the sea moves the stern


def test_the_scene_lowers_the_body(fmu_file):
    """The default scene pays out at 0.25 m/s: 5 m in 20 s less the 0.16 m the drum loses taking up
    the rate at its default acceleration (winch.maxAcceleration 0.2 m/s2: 0.25^2 / (2 x 0.2)), and the
    body goes down with the line (the line stretches by T / EA per metre:
    20 kN / 3e7 N = 0.07 %, 0.4 m over 500 m, hence 0.5 m)."""
    r = run(HeaveLoweringCase(t_end=20.0, mode=1, hs=0.5, components=1, n_elements=10), fmu_file)
    L = r["cable.unstretchedLength"]
    assert L[-1] - L[0] == pytest.approx(0.25 * 20.0 - 0.25 ** 2 / (2.0 * 0.2), rel=1e-3)
    depth = -r["cable.endPosition.z"]
    assert depth[-1] - depth[0] == pytest.approx(5.0, abs=0.5)
