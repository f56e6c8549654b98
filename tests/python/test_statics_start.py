"""The static solver's starting shape for a heavy line between fixed ends: its catenary, lying on the
seabed up to the touchdown (docs/model.md, statics). From the former start (a parabola through the
ends) the stiff power cable of the benchmark settled at some meshes into a folded equilibrium."""

import pytest

from ucable import work_precision as wp
from ucable.fmu import CableFMU

STIFF = wp.make_cases()["stiff"]


def static_top_tension(fmu_file, n_elements):
    params = dict(STIFF.line)
    params.update(STIFF.fmu_params)
    params["nElements"] = n_elements
    x, v, _ = STIFF.traj.state(0.0)
    with CableFMU(fmu_file, parameters=params) as c:
        c.initialize(inputs=dict(zip(["tow.x", "tow.y", "tow.z", "tow.vx", "tow.vy", "tow.vz"], [*x, *v])))
        return c.get("towTension")


@pytest.mark.parametrize("n_elements", [16, 25, 30, 42, 49, 55])
def test_stiff_cable_at_rest_has_one_equilibrium_on_every_mesh(fmu_file, n_elements):
    """250 m of power cable (EI 2e4 N m2) from a fairlead 10 m deep to an anchor on the seabed at
    100 m, about 100 m lying on it. The top tension of the equilibrium converges with the mesh: from
    15 elements up it stays within 0.3 % of 45.1 kN (cubic elements' static error), so a mesh that
    finds more than 0.5 % away from the 20-element value found another equilibrium. These meshes did:
    a loop of excess length folded into the hanging part, the line short of the seabed, 56-180 kN."""
    reference = static_top_tension(fmu_file, 20)
    assert abs(static_top_tension(fmu_file, n_elements) / reference - 1.0) < 5e-3
