// outputs.h - end forces (reactions from the eliminated equations), shape and tension at the
// UC_NUM_STATIONS stations, extreme values.
#pragma once

#include <vector>

#include "cable_api.h"
#include "cable_model.h"

namespace uc {

// X, Xd, Xdd: global configuration; forces: per-element residuals at that configuration
// (CableModel::residual), so reported forces close the discrete equilibrium exactly. nodeTension:
// workspace for the N + 1 nodal tensions (sized here once).
void compute_outputs(const CableModel& model, const double* X, const double* Xd, const ElementForces& forces,
                     double torque, std::vector<double>& nodeTension, UCOutputs& out);

// Axial force at every node: T_i = F_i . t_i with F_i the force that the cable beyond node i
// exerts on the cable before it (node 0: the tow point's pull), t_i the unit tangent.
void nodal_tensions(const CableModel& model, const double* X, const ElementForces& forces, double* T);

}  // namespace uc
