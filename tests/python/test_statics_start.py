"""The static solver's starting shape for a heavy line between fixed ends: its catenary, lying on the
seabed up to the touchdown (docs/model.md, statics). From the former start (a parabola through the
ends) the stiff power cable of the benchmark settled at some meshes into a folded equilibrium."""

import pytest

from studies.benchmarks import work_precision as wp
from studies.reports.lines_figure import section_parameters

STIFF = wp.make_cases()["stiff"]
PROPERTIES = ("diameter", "massPerLength", "EA", "EI", "Cdn", "Cdt", "Can", "Cat")


def halves(n_elements):
    """The same cable as two 125 m sections joined rigidly, n_elements in all."""
    p = {"nSections": 2}
    for k, n in ((1, n_elements // 2), (2, n_elements - n_elements // 2)):
        p.update(section_parameters(k, length=125.0, nElements=n, joint=0,
                                    **{key: STIFF.line[key] for key in PROPERTIES}))
    return p


def static_top_tension(fmu_file, n_elements, two_sections=False):
    return wp.static_top_tension(fmu_file, STIFF, n_elements, **(halves(n_elements) if two_sections else {}))


@pytest.mark.parametrize("n_elements", [16, 25, 30, 42, 49, 55])
def test_stiff_cable_at_rest_has_one_equilibrium_on_every_mesh(fmu_file, n_elements):
    """250 m of power cable (EI 2e4 N m2) from a fairlead 10 m deep to an anchor on the seabed at
    100 m, about 100 m lying on it. The top tension of the equilibrium converges with the mesh: from
    15 elements up it stays within 0.3 % of 45.1 kN (cubic elements' static error), so a mesh that
    finds more than 0.5 % away from the 20-element value found another equilibrium. These meshes did:
    a loop of excess length folded into the hanging part, the line short of the seabed, 56-180 kN."""
    reference = static_top_tension(fmu_file, 20)
    assert abs(static_top_tension(fmu_file, n_elements) / reference - 1.0) < 5e-3


@pytest.mark.parametrize("n_elements", [16, 36, 54, 58])
def test_stiff_cable_in_two_sections_at_rest_has_one_equilibrium_on_every_mesh(fmu_file, n_elements):
    """The same cable described as two equal sections (a line of sinking sections starts from the
    catenary of a uniform line too): the same equilibrium as the uniform 20-element line, within the
    same 0.5 %. From the parabola these meshes found 63-180 kN."""
    reference = static_top_tension(fmu_file, 20)
    assert abs(static_top_tension(fmu_file, n_elements, two_sections=True) / reference - 1.0) < 5e-3
