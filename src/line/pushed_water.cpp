// pushed_water.cpp - the water pushed by the importer (water.source 1, docs/waves.md "Water pushed by the
// importer"): where the line's load points stand, and their water for the coming step.
#include <cstring>

#include "line/simulation.h"

namespace uc {

std::size_t CableSimulation::water_points() const {
    return model_.params().waterSource == UC_WATER_PUSHED ? static_cast<std::size_t>(model_.n_load_points()) : 0;
}

// From the state alone (the integrator's vectors and the ends where they stand), so that a restored state
// gives the positions the saved one gave.
void CableSimulation::water_positions(double* x, double* y, double* z) const {
    const int n = model_.n_free(), global = model_.n_global();
    waterScratch_.resize(3 * static_cast<std::size_t>(n) + 3 * static_cast<std::size_t>(global));
    double *q = waterScratch_.data(), *v = q + n, *a = v + n, *X = a + n, *Xd = X + global, *Xdd = Xd + global;
    for (int j = 0; j < n; ++j) {
        q[j] = y_[2 * (j + off_)];
        v[j] = y_[2 * (j + off_) + 1];
        a[j] = yp_[2 * (j + off_) + 1];
    }
    Loads at = loads_;
    at.tow = TowTrajectory::at_rest_in_time(state_.tow.p(), state_.tow.v(), state_.tow.a(), state_.time);
    at.end = TowTrajectory::at_rest_in_time(state_.end.p(), state_.end.v(), state_.end.a(), state_.time);
    model_.expand(q, v, a, at, state_.time, X, Xd, Xdd);
    model_.load_point_positions(X, x, y, z);
}

void CableSimulation::set_water(double t, const double* const u[3], const double* const a[3]) {
    const std::size_t n = water_points();
    if (n == 0) return;
    pushedWater_.resize(6 * n);  // the same size at every step: no allocation after the first
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            pushedWater_[6 * i + c] = u[c][i];
            pushedWater_[6 * i + 3 + c] = a[c][i];
        }
    loads_.current.pushed = pushedWater_.data();
    loads_.current.pushedTime = t;
}

}  // namespace uc
