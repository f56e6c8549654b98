"""Partner models for co-simulation scenes with the UnderwaterCable FMU (plain Python classes).

Each model has a state vector `x`, `derivatives(t, x, ...)` and `step(h, ...)` that advances the
state by one communication step with classical RK4 substeps (the coupling force from the cable is
given at both ends of the step and interpolated linearly in between, which is what a Gauss-Seidel
master knows after the cable has stepped).
"""

from .rk4 import rk4_step  # noqa: F401
from .vessel import Vessel, VesselParameters, Autopilot  # noqa: F401
from .towed_body import TowedBody, TowedBodyParameters  # noqa: F401
