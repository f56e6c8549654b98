"""A clump weight dragged over the seabed converges under refinement (studies.cases.dragged_clump).

The tow speed steps from 0.45 to 0.5 m/s: the sliding clump rings on the chain's axial stiffness
(about a tenth of the tension) and the ringing decays. What converged means here: the steady
tension agrees between 40, 60 and 80 elements within 0.05 %; the extremes of the ringing agree
between 40 and 80 elements within 1 % of the tension (a tenth of the ringing) and between 60 and
80 within half that (the clump's kink and the touchdown that moves along the elements make the
convergence no better than second order, which would give a quarter); and the sliding is steady
once the ringing has decayed (the tension within 0.1 % of its mean). The clump resting at the
seabed's depth with the chain (seabedRest) swings further in the first seconds than one sunk below
it, and 20 elements do not hold that swing to a tenth (docs/model.md)."""

import pytest

from studies.cases import dragged_clump as D


@pytest.fixture(scope="module")
def meshes(fmu_file):
    return {n: D.windows(D.run(n, fmu_file)) for n in (40, 60, 80)}


@pytest.mark.parametrize("coarse, fine, bound", [(40, 80, 1e-2), (60, 80, 5e-3)])
def test_the_ringing_and_the_steady_tension_agree_between_meshes(meshes, coarse, fine, bound):
    for (lo, hi, mean_c, low_c, high_c), (_, _, mean_f, low_f, high_f) in zip(meshes[coarse], meshes[fine]):
        assert abs(mean_c - mean_f) < 5e-4 * mean_f, (lo, hi)
        assert abs(low_c - low_f) < bound * mean_f, (lo, hi)
        assert abs(high_c - high_f) < bound * mean_f, (lo, hi)


def test_the_disturbance_rings_and_decays_to_steady_sliding(meshes):
    for n, rows in meshes.items():
        first, *_, last = rows
        _, _, mean, low, high = first
        assert high - low > 0.05 * mean, n  # the speed step does disturb the clump
        _, _, mean, low, high = last
        assert high - low < 1e-3 * mean, n
