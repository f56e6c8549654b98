"""seabedContactSpacing: the seabed contact integrated at points at most that far apart along the cable
(3-point Gauss rules on equal intervals) instead of the five axial points of each element
(docs/model.md, contact sampling). Off by default: the golden results keep their bits."""

import pytest

from studies.benchmarks import work_precision as wp

STIFF = wp.make_cases()["stiff"]


def static_top_tension(fmu_file, n_elements, spacing):
    return wp.static_top_tension(fmu_file, STIFF, n_elements, seabedContactSpacing=spacing)


@pytest.mark.parametrize("n_elements, spacing", [(10, 2.0), (40, 0.5), (80, 0.3)])
def test_dense_contact_finds_the_same_static_equilibrium(fmu_file, n_elements, spacing):
    """The stiff power cable of the benchmark (250 m, about 100 m on the seabed) at rest. The two
    contact rules differ only in how they integrate the contact across the touchdown's smoothing
    band, about sqrt(2 delta / kappa) = 1.7 m of cable carrying a small part of the line's weight
    (delta = 1 cm, kappa = 7e-3 1/m): the top tension moves by far less than 1e-3 of its 45 kN.
    A static solution path that started on the dense contact ended at 40 and 80 elements in another
    equilibrium, excess length stored in a bump on the seabed near the anchor (67 and 91 kN)."""
    dense = static_top_tension(fmu_file, n_elements, spacing)
    axial = static_top_tension(fmu_file, n_elements, 0.0)
    assert abs(dense / axial - 1.0) < 1e-3, (dense, axial)
