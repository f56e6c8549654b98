// current_grid.h - a current given as data (docs/waves.md, "A current given as data"): MoorDyn's
// current profile changing in time (Currents 2, current_profile_dynamic.txt: depth x time) and its
// current on a grid in x, y, z and time (Currents 5, current_profile_4d.txt), interpolated as MoorDyn
// interpolates them: linear in each of x, y, z and t, held at the edge values outside the grid in
// space; in time sampled from t = 0 at the smallest interval of the file (MoorDyn's dtWave) and held
// at the last sample after it (MoorDyn starts the record over: the FMU warns once instead).
//
// Immutable once read: the lines of a model share one through a shared pointer, outside the saved
// state (the file is read again when a state is restored into a new instance).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/types.h"

namespace uc {

class CurrentGrid {
public:
    // Where a point lies against the data (bits of at()'s result).
    enum Outside : unsigned { kOutsideSpace = 1u, kAfterRecord = 2u };

    // Axes ascending (x and y may hold a single value: no variation along them) and the velocities at
    // the nodes, u[((ix * ny + iy) * nz + iz) * nt + it]; times t[k] = k dt from 0 (MoorDyn's samples).
    CurrentGrid(std::vector<double> x, std::vector<double> y, std::vector<double> z, double dt, int nt,
                std::vector<Vec3> u);

    // MoorDyn's current_profile_dynamic.txt (mode 2) or current_profile_4d.txt (mode 5) into a grid; null
    // with error = "line <n>: <what>" (or "<what>") when the text is not such a file.
    static std::shared_ptr<const CurrentGrid> read(int mode, std::string_view text, std::string& error);

    // The velocity at r and t; with du (rows: components, columns: x, y, z) its gradient, with dudt its
    // rate in time (the interpolant's: constant in time between samples), with drate the rate's
    // gradient. Returns the Outside bits of (r, t): outside the grid in x, y or z, or after the last
    // sample.
    unsigned at(const Vec3& r, double t, Vec3& u, Mat3* du = nullptr, Vec3* dudt = nullptr, Mat3* drate = nullptr) const;

    int mode() const { return mode_; }
    double last_time() const { return dt_ * (nt_ - 1); }
    double dt() const { return dt_; }
    int nt() const { return nt_; }
    const std::vector<double>& x() const { return x_; }
    const std::vector<double>& y() const { return y_; }
    const std::vector<double>& z() const { return z_; }
    // One line for the log: the grid's sizes and extent.
    std::string describe() const;

private:
    std::vector<double> x_, y_, z_;
    double dt_ = 1.0;
    int nt_ = 1;
    int mode_ = 0;
    std::vector<Vec3> u_;
};

}  // namespace uc
