// pushed_water.cpp - a mooring system's water pushed by the importer (water.source 1, docs/waves.md "Water
// pushed by the importer"): its lines' load points one after the other, in the system's line order (the
// deck's lines, then the lower parts of lines split at a point on them).
#include "system/mooring_system.h"

namespace uc {

std::size_t MooringSystem::water_points() const {
    std::size_t n = 0;
    for (const auto& line : lines_) n += line->water_points();
    return n;
}

void MooringSystem::water_positions(double* x, double* y, double* z) const {
    std::size_t at = 0;
    for (const auto& line : lines_) {
        line->water_positions(x + at, y + at, z + at);
        at += line->water_points();
    }
}

void MooringSystem::set_water(double t, const double* const u[3], const double* const a[3]) {
    std::size_t at = 0;
    for (const auto& line : lines_) {
        const double* const lu[3] = {u[0] + at, u[1] + at, u[2] + at};
        const double* const la[3] = {a[0] + at, a[1] + at, a[2] + at};
        line->set_water(t, lu, la);
        at += line->water_points();
    }
}

}  // namespace uc
