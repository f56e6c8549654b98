"""The heave-lowering scene (VesselRAO FMU -> cable FMU): a 2 t body on 500 m of umbilical hanging from the
stern of a vessel in a regular head sea (H 2 m, T 10 s), 10 elements, 0.2 s communication steps, 60 s.

The umbilical is stiff (axial period ~0.5 s, against the 10 s wave): to within its elastic amplification
(omega / omega_n)^2 = 0.2 % the line and the body move as a rigid body with the stern, so
- the mean top tension over whole wave periods is the wet weight of the umbilical and the body;
- the top tension is that weight plus the inertia of the moving mass (body 2 t + added 0.5 t + line
  10 t) times the stern's vertical acceleration, plus a drag term in phase with the velocity;
- the body heaves with the stern.
"""

import math

import numpy as np
import pytest

from ucable import heave_lowering
from ucable.heave_lowering import Scene, run

RHO, G = 1025.0, 9.81


@pytest.fixture(scope="module")
def regular(fmu_file):
    scene = Scene(t_end=60.0, mode=1, hs=2.0, tp=10.0, components=1, ramp=10.0, n_elements=10, step=0.2)
    return run(scene, fmu_file)


def test_mean_top_tension_is_the_wet_weight(regular):
    """Over the four whole periods after the ramp the oscillating loads average out; the drag of a
    symmetric oscillation has no mean. Tolerance 1e-3: the horizontal pendulum and the line's quadratic
    drag leave a mean far below it."""
    body = regular.scene.body_mass - RHO * 0.5  # 2 t body of 0.5 m3
    line = 20.0 - RHO * math.pi * 0.1 ** 2 / 4
    weight = (body + line * 500.0) * G
    t = regular.time
    whole = (t >= 20.0) & (t < 60.0 - 1e-9)
    assert regular["cable.towTension"][whole].mean() == pytest.approx(weight, rel=1e-3)


def test_top_tension_is_weight_plus_inertia_of_the_moving_mass(regular):
    """Least-squares fit T = T0 + M a_z + c v_z over the settled part: M is the moving mass 12.5 t to 3 %
    (the elastic amplification 0.2 %, the wave loads on the upper line and the harmonics of the quadratic
    drag that the fit leaves out); c > 0 is a damping (drag)."""
    k = regular.time >= 20.0
    a, v = regular["vessel.tow.az"][k], regular["vessel.tow.vz"][k]
    A = np.column_stack([np.ones(k.sum()), a, v])
    (T0, M, c), *_ = np.linalg.lstsq(A, regular["cable.towTension"][k], rcond=None)
    assert M == pytest.approx(2000.0 + 500.0 + 20.0 * 500.0, rel=0.03)
    assert c > 0.0
    assert np.std(a) > 0.3  # the stern moves: the fit measures something


def test_the_body_heaves_with_the_stern(regular):
    """Body and stern heave: equal amplitude to 1 % (the line's stretch under the dynamic tension,
    ~5 kN x 500 m / EA = 5 mm of 1.4 m) and in phase (correlation > 0.999)."""
    k = regular.time >= 20.0
    body = regular["cable.endPosition.z"][k]
    stern = regular["vessel.tow.z"][k]
    assert np.std(body) / np.std(stern) == pytest.approx(1.0, abs=0.01)
    assert np.corrcoef(body, stern)[0, 1] > 0.999
    assert regular.snap_events() == []  # the least axial force stays positive (13 kN) in this sea


def test_the_scene_command_writes_its_csv_and_figure(fmu_file, tmp_path):
    from ucable.manoeuvre_cli import main
    assert main(["heave-lowering", "--t-end", "2", "--components", "10", "--nElements", "4",
                 "--fmu", str(fmu_file), "--out", str(tmp_path)]) == 0
    data = np.genfromtxt(tmp_path / "heave-lowering.csv", delimiter=",", names=True)
    assert len(data) == 11 and data.dtype.names[0] == "time"
    assert set(heave_lowering.COLUMNS) >= {"cable.minTension", "vessel.tow.z", "cable.endPosition.z"}
    assert (tmp_path / "heave-lowering.png").stat().st_size > 10000
