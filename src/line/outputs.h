// outputs.h - end forces (reactions from the eliminated equations), shape and tension at the
// UC_NUM_STATIONS stations, extreme values.
#pragma once

#include <vector>

#include "model/parameters.h"
#include "model/cable_model.h"

namespace uc {

// Where the outputs sample the line: the element, local coordinate and shape functions of each of
// the UC_NUM_STATIONS stations, and the shape functions at the line's two ends and one seabed sample
// before the far end. They depend on the mesh only, which stays the same over most communication
// steps: they are kept for the mesh they were found on (the line's length and its runs of elements)
// and found again when it changes (a winch changes the top element's length and the arc lengths
// below it at every step, a remesh or new parameters rebuild the runs).
class StationShapes {
public:
    struct Station {
        int element = 0;
        double xi = 0.0;
        ShapeValues shape{};
    };
    // Makes the stations those of model's mesh; no allocation unless the number of runs grows.
    void update(const CableModel& model);
    const Station& station(int k) const { return stations_[k]; }
    const ShapeValues& top() const { return top_; }          // xi = 0 of the first element
    const ShapeValues& bottom() const { return bottom_; }    // xi = 1 of the last element
    const ShapeValues& near_bottom() const { return nearBottom_; }  // xi = 7/8 of the last element

private:
    bool same_mesh(const CableModel& model) const;

    double length_ = -1.0;
    std::vector<ElementRun> runs_;  // the mesh the stations were found on
    Station stations_[UC_NUM_STATIONS];
    ShapeValues top_{}, bottom_{}, nearBottom_{};
};

// What compute_outputs keeps between calls: sized at the first call, then reused.
struct OutputWorkspace {
    std::vector<double> nodeTension;  // the N + 1 nodal tensions
    StationShapes stations;
};

// X, Xd, Xdd: global configuration; syropeHistory: the Syrope elements' history (CableModel::history_size
// values, null without a Syrope element); forces: per-element residuals at that configuration
// (CableModel::residual), so reported forces close the discrete equilibrium exactly.
void compute_outputs(const CableModel& model, const double* X, const double* Xd, const double* syropeHistory,
                     const ElementForces& forces, double torque, OutputWorkspace& work, UCOutputs& out);

// Axial force at every node: T_i = F_i . t_i with F_i the force that the cable beyond node i
// exerts on the cable before it (node 0: the tow point's pull), t_i the unit tangent.
void nodal_tensions(const CableModel& model, const double* X, const ElementForces& forces, double* T);

}  // namespace uc
