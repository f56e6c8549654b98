// current_grid.cpp - see current_grid.h.
#include "terms/current_grid.h"
#include "terms/grid_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace uc {
namespace {

// Grids larger than this (nodes after the resampling in time) are refused: 24 bytes a node.
constexpr double kMaxNodes = 4.0e6;

// MoorDyn's samples of a record given at the times `times` (ascending): t_k = k dt from 0, dt the
// smallest interval of the record, k = 0 .. nt - 1 up to its last time (sample() gives the values:
// linear between the record's times, held at its ends).
void resample(const std::vector<double>& times, double& dt, int& nt) {
    dt = 1.0;
    nt = 1;
    if (times.size() < 2) return;
    dt = HUGE_VAL;
    for (size_t k = 1; k < times.size(); ++k) dt = std::min(dt, times[k] - times[k - 1]);
    nt = static_cast<int>(std::floor(times.back() / dt)) + 1;
}

Vec3 sample(const std::vector<double>& times, const std::vector<Vec3>& series, double t) {
    if (times.size() == 1) return series[0];
    const Bracket b = bracket(times, t);
    return series[b.lo] + b.f * (series[b.hi] - series[b.lo]);
}

// current_profile_dynamic.txt: depths z on the fifth line, then from the seventh rows
// "t ux(z1..zn) [uy(z1..zn) [uz(z1..zn)]]".
std::shared_ptr<const CurrentGrid> read_dynamic(std::string_view text, std::string& error) {
    const std::vector<std::string_view> lines = split_lines(text);
    if (lines.size() < 7) {
        error = "a profile changing in time has its depths on line 5 and its rows \"t ux(z) [uy(z) [uz(z)]]\" from line 7; "
                "the text has " + std::to_string(lines.size()) + " lines";
        return nullptr;
    }
    std::vector<double> z;
    if (!numbers(lines[4], 5, z, error)) return nullptr;
    if (z.empty()) {
        error = "line 5: no depths z (the heights of the profile's rows, m, increasing)";
        return nullptr;
    }
    if (!ascending(z, "z", 5, error)) return nullptr;
    const size_t nz = z.size();
    std::vector<double> times, row;
    std::vector<std::vector<Vec3>> series(nz);  // per depth, per time of the file
    for (size_t i = 6; i < lines.size(); ++i) {
        const int number = static_cast<int>(i) + 1;
        if (!numbers(lines[i], number, row, error)) return nullptr;
        if (row.empty()) continue;
        if (row.size() != nz + 1 && row.size() != 2 * nz + 1 && row.size() != 3 * nz + 1) {
            error = "line " + std::to_string(number) + ": " + std::to_string(row.size()) + " numbers; a row is t and " +
                    std::to_string(nz) + " values of ux (then as many of uy, then of uz), " + std::to_string(nz + 1) +
                    ", " + std::to_string(2 * nz + 1) + " or " + std::to_string(3 * nz + 1) + " numbers";
            return nullptr;
        }
        if (!times.empty() && !(row[0] > times.back())) {
            error = "line " + std::to_string(number) + ": t = " + number_text(row[0]) + " s: the times must increase row by row";
            return nullptr;
        }
        times.push_back(row[0]);
        for (size_t k = 0; k < nz; ++k) {
            const double uy = row.size() > 2 * nz ? row[1 + nz + k] : 0.0;
            const double uz = row.size() > 3 * nz ? row[1 + 2 * nz + k] : 0.0;
            series[k].push_back(Vec3(row[1 + k], uy, uz));
        }
    }
    if (times.empty()) {
        error = "no rows \"t ux(z) [uy(z) [uz(z)]]\" from line 7";
        return nullptr;
    }
    double dt = 1.0;
    int nt = 1;
    resample(times, dt, nt);
    if (static_cast<double>(nt) * static_cast<double>(nz) > kMaxNodes) {
        error = std::to_string(nt) + " samples of " + number_text(dt) + " s (the smallest interval of the rows' times) "
                "at " + std::to_string(nz) + " depths: more than the FMU holds (" + number_text(kMaxNodes) + " values)";
        return nullptr;
    }
    std::vector<Vec3> u(nz * static_cast<size_t>(nt));
    for (size_t k = 0; k < nz; ++k)
        for (int j = 0; j < nt; ++j) u[k * nt + j] = sample(times, series[k], j * dt);
    return std::make_shared<const CurrentGrid>(std::vector<double>{0.0}, std::vector<double>{0.0}, z, dt, nt, std::move(u));
}

// current_profile_4d.txt: "nx ny nz nt", the axes x, y, z, t on lines 2 to 5, then one row
// "x y z t ux uy uz" per node of the grid, in any order.
std::shared_ptr<const CurrentGrid> read_4d(std::string_view text, std::string& error) {
    const std::vector<std::string_view> lines = split_lines(text);
    std::vector<double> counts;
    if (lines.empty() || !numbers(lines[0], 1, counts, error)) {
        if (error.empty()) error = "an empty text";
        return nullptr;
    }
    if (counts.size() != 4) {
        error = "line 1: the grid's sizes nx ny nz nt (4 numbers), not " + std::to_string(counts.size());
        return nullptr;
    }
    for (double c : counts) {
        if (!(c >= 1.0 && c == std::floor(c) && c <= kMaxNodes)) {
            error = "line 1: " + number_text(c) + " is not a size of the grid (a whole number of at least 1)";
            return nullptr;
        }
    }
    if (counts[0] * counts[1] * counts[2] * counts[3] > kMaxNodes) {
        error = "line 1: a grid of more than " + number_text(kMaxNodes) + " nodes";
        return nullptr;
    }
    if (lines.size() < 5) {
        error = "the axes x, y, z and t are on lines 2 to 5; the text has " + std::to_string(lines.size()) + " lines";
        return nullptr;
    }
    static const char* names[4] = {"x", "y", "z", "t"};
    std::vector<double> axes[4];
    for (int a = 0; a < 4; ++a) {
        if (!numbers(lines[1 + a], 2 + a, axes[a], error)) return nullptr;
        if (axes[a].size() != static_cast<size_t>(counts[a])) {
            error = "line " + std::to_string(2 + a) + ": " + std::to_string(axes[a].size()) + " values of " + names[a] +
                    ", line 1 gives " + number_text(counts[a]);
            return nullptr;
        }
        if (!ascending(axes[a], names[a], 2 + a, error)) return nullptr;
    }
    const size_t n[4] = {axes[0].size(), axes[1].size(), axes[2].size(), axes[3].size()};
    const size_t total = n[0] * n[1] * n[2] * n[3];
    std::vector<Vec3> given(total);
    std::vector<int> seenAt(total, 0);
    std::vector<double> row;
    size_t count = 0;
    for (size_t i = 5; i < lines.size(); ++i) {
        const int number = static_cast<int>(i) + 1;
        if (!numbers(lines[i], number, row, error)) return nullptr;
        if (row.empty()) continue;
        if (row.size() != 7) {
            error = "line " + std::to_string(number) + ": a row is x y z t ux uy uz (7 numbers), not " +
                    std::to_string(row.size());
            return nullptr;
        }
        size_t index = 0;
        for (int a = 0; a < 4; ++a) {
            const std::vector<double>& axis = axes[a];
            const double tolerance = 1e-9 * std::max(std::abs(axis.front()), std::abs(axis.back()));
            auto it = std::lower_bound(axis.begin(), axis.end(), row[a] - tolerance);
            if (it == axis.end() || std::abs(*it - row[a]) > tolerance) {
                error = "line " + std::to_string(number) + ": " + names[a] + " = " + number_text(row[a]) +
                        " is not a value of the " + names[a] + " axis on line " + std::to_string(2 + a);
                return nullptr;
            }
            index = index * n[a] + static_cast<size_t>(it - axis.begin());
        }
        if (seenAt[index] != 0) {
            error = "line " + std::to_string(number) + ": the node (" + number_text(row[0]) + ", " + number_text(row[1]) +
                    ", " + number_text(row[2]) + ", " + number_text(row[3]) + ") again (first on line " +
                    std::to_string(seenAt[index]) + ")";
            return nullptr;
        }
        seenAt[index] = number;
        given[index] = Vec3(row[4], row[5], row[6]);
        ++count;
    }
    if (count != total) {
        error = std::to_string(count) + " rows of nodes, the grid " + std::to_string(n[0]) + " x " + std::to_string(n[1]) +
                " x " + std::to_string(n[2]) + " x " + std::to_string(n[3]) + " has " + std::to_string(total);
        return nullptr;
    }
    double dt = 1.0;
    int nt = 1;
    resample(axes[3], dt, nt);
    const size_t space = n[0] * n[1] * n[2];
    if (static_cast<double>(nt) * static_cast<double>(space) > kMaxNodes) {
        error = std::to_string(nt) + " samples of " + number_text(dt) + " s (the smallest interval of the t axis) at " +
                std::to_string(space) + " points: more than the FMU holds (" + number_text(kMaxNodes) + " values)";
        return nullptr;
    }
    std::vector<Vec3> u(space * static_cast<size_t>(nt)), series(n[3]);
    for (size_t s = 0; s < space; ++s) {
        for (size_t k = 0; k < n[3]; ++k) series[k] = given[s * n[3] + k];
        for (int j = 0; j < nt; ++j) u[s * nt + j] = sample(axes[3], series, j * dt);
    }
    return std::make_shared<const CurrentGrid>(axes[0], axes[1], axes[2], dt, nt, std::move(u));
}

}  // namespace

CurrentGrid::CurrentGrid(std::vector<double> x, std::vector<double> y, std::vector<double> z, double dt, int nt,
                         std::vector<Vec3> u)
    : x_(std::move(x)), y_(std::move(y)), z_(std::move(z)), dt_(dt), nt_(nt), u_(std::move(u)) {
    mode_ = x_.size() == 1 && y_.size() == 1 ? 2 : 5;
}

std::shared_ptr<const CurrentGrid> CurrentGrid::read(int mode, std::string_view text, std::string& error) {
    error.clear();
    if (mode == 2) return read_dynamic(text, error);
    if (mode == 5) return read_4d(text, error);
    error = "current data of mode " + std::to_string(mode) + ": 2 (a profile changing in time) or 5 (a grid in x, y, z and t)";
    return nullptr;
}

unsigned CurrentGrid::at(const Vec3& r, double t, Vec3& u, Mat3* du, Vec3* dudt, Mat3* drate) const {
    const Bracket bx = bracket(x_, r.x()), by = bracket(y_, r.y()), bz = bracket(z_, r.z());
    unsigned outside = (bx.outside || by.outside || bz.outside) ? kOutsideSpace : 0u;
    // time: the samples k dt; held at the first before 0 and at the last after the record
    Bracket bt;
    if (nt_ > 1) {
        const double q = t / dt_;
        if (!(q > 0.0)) {
            bt.hi = 1;
        } else if (!(q < nt_ - 1)) {
            bt.lo = nt_ - 2;
            bt.hi = nt_ - 1;
            bt.f = 1.0;
            if (q > nt_ - 1) outside |= kAfterRecord;
        } else {
            bt.lo = static_cast<int>(std::floor(q));
            bt.hi = bt.lo + 1;
            bt.f = q - bt.lo;
            bt.slope = 1.0 / dt_;
        }
    }
    const int ny = static_cast<int>(y_.size()), nz = static_cast<int>(z_.size());
    const Bracket* b[4] = {&bx, &by, &bz, &bt};
    u.setZero();
    if (du) du->setZero();
    if (dudt) dudt->setZero();
    if (drate) drate->setZero();
    for (int corner = 0; corner < 16; ++corner) {
        int idx[4];
        double w[4], dw[4];
        for (int a = 0; a < 4; ++a) {
            const bool up = (corner >> a) & 1;
            idx[a] = up ? b[a]->hi : b[a]->lo;
            w[a] = up ? b[a]->f : 1.0 - b[a]->f;
            dw[a] = up ? b[a]->slope : -b[a]->slope;
        }
        const Vec3& value = u_[((static_cast<size_t>(idx[0]) * ny + idx[1]) * nz + idx[2]) * nt_ + idx[3]];
        const double weight = w[0] * w[1] * w[2] * w[3];
        if (weight != 0.0) u += weight * value;
        if (du) {
            if (bx.slope != 0.0) du->col(0) += (dw[0] * w[1] * w[2] * w[3]) * value;
            if (by.slope != 0.0) du->col(1) += (w[0] * dw[1] * w[2] * w[3]) * value;
            if (bz.slope != 0.0) du->col(2) += (w[0] * w[1] * dw[2] * w[3]) * value;
        }
        if (dudt && bt.slope != 0.0) *dudt += (w[0] * w[1] * w[2] * dw[3]) * value;
        if (drate && bt.slope != 0.0) {
            if (bx.slope != 0.0) drate->col(0) += (dw[0] * w[1] * w[2] * dw[3]) * value;
            if (by.slope != 0.0) drate->col(1) += (w[0] * dw[1] * w[2] * dw[3]) * value;
            if (bz.slope != 0.0) drate->col(2) += (w[0] * w[1] * dw[2] * dw[3]) * value;
        }
    }
    return outside;
}

std::string CurrentGrid::describe() const {
    std::string text = mode_ == 2 ? "a profile of " + std::to_string(z_.size()) + " depths (z " + number_text(z_.front()) +
                                        " to " + number_text(z_.back()) + " m)"
                                  : "a grid of " + std::to_string(x_.size()) + " x " + std::to_string(y_.size()) + " x " +
                                        std::to_string(z_.size()) + " points (x " + number_text(x_.front()) + " to " +
                                        number_text(x_.back()) + " m, y " + number_text(y_.front()) + " to " +
                                        number_text(y_.back()) + " m, z " + number_text(z_.front()) + " to " +
                                        number_text(z_.back()) + " m)";
    text += nt_ > 1 ? ", " + std::to_string(nt_) + " samples of " + number_text(dt_) + " s up to t = " + number_text(last_time()) + " s"
                    : ", steady";
    return text;
}

}  // namespace uc
