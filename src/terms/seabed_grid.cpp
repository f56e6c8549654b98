// seabed_grid.cpp - see seabed_grid.h.
#include "terms/seabed_grid.h"

#include <algorithm>
#include <cmath>

#include "terms/grid_text.h"

namespace uc {
namespace {

// Grids larger than this are refused: 8 bytes a node.
constexpr double kMaxNodes = 1.0e7;

// The lines that hold something, with their numbers (from 1).
struct TextLine {
    std::string_view text;
    int number;
};

std::vector<TextLine> filled_lines(std::string_view text) {
    std::vector<TextLine> out;
    int number = 0;
    for (std::string_view line : split_lines(text)) {
        ++number;
        if (line.find_first_not_of(" \t,") != std::string_view::npos) out.push_back({line, number});
    }
    return out;
}

std::string at_line(int number, const std::string& what) { return "line " + std::to_string(number) + ": " + what; }

bool whole_count(double v, int number, const char* name, size_t& n, std::string& error) {
    if (!(v >= 1.0 && v == std::floor(v) && v <= kMaxNodes)) {
        error = at_line(number, std::string(name) + " = " + number_text(v) + ": the number of grid values along an "
                                                                               "axis must be a whole number of at least 1");
        return false;
    }
    n = static_cast<size_t>(v);
    return true;
}

// The index of the axis value v is (within a millionth of the axis' spacing); npos where none.
size_t tick(const std::vector<double>& axis, double v) {
    const double span = axis.size() > 1 ? axis.back() - axis.front() : std::max(1.0, std::abs(axis[0]));
    const double tolerance = 1e-6 * span / static_cast<double>(std::max<size_t>(1, axis.size() - 1));
    const size_t k = static_cast<size_t>(std::lower_bound(axis.begin(), axis.end(), v - tolerance) - axis.begin());
    return k < axis.size() && std::abs(axis[k] - v) <= tolerance ? k : std::string::npos;
}

// MoorDyn's SeafloorFile: "nx ny", the x values, the y values, then nx ny rows "x y z".
std::shared_ptr<const SeabedGrid> read_moordyn(const std::vector<TextLine>& lines, std::string& error) {
    std::vector<double> head, x, y, row;
    if (!numbers(lines[0].text, lines[0].number, head, error)) return nullptr;
    size_t nx = 0, ny = 0;
    if (!whole_count(head[0], lines[0].number, "nx", nx, error) || !whole_count(head[1], lines[0].number, "ny", ny, error))
        return nullptr;
    if (lines.size() < 3) {
        error = at_line(lines.back().number, "the file ends before the y values (MoorDyn's SeafloorFile: a line nx ny, "
                                             "the nx x values, the ny y values, then nx ny lines x y z)");
        return nullptr;
    }
    if (!numbers(lines[1].text, lines[1].number, x, error) || !numbers(lines[2].text, lines[2].number, y, error))
        return nullptr;
    if (x.size() != nx || y.size() != ny) {
        const bool inX = x.size() != nx;
        error = at_line(lines[inX ? 1 : 2].number,
                        std::to_string(inX ? x.size() : y.size()) + " " + (inX ? "x" : "y") + " values where the first "
                        "line gives " + (inX ? "nx = " + std::to_string(nx) : "ny = " + std::to_string(ny)));
        return nullptr;
    }
    if (!ascending(x, "x", lines[1].number, error) || !ascending(y, "y", lines[2].number, error)) return nullptr;
    std::vector<double> z(nx * ny, 0.0);
    std::vector<int> given(nx * ny, 0);
    for (size_t k = 3; k < lines.size(); ++k) {
        const int number = lines[k].number;
        if (!numbers(lines[k].text, number, row, error)) return nullptr;
        if (row.size() != 3) {
            error = at_line(number, std::to_string(row.size()) + " values: a grid point is a line x y z");
            return nullptr;
        }
        const size_t ix = tick(x, row[0]), iy = tick(y, row[1]);
        if (ix == std::string::npos || iy == std::string::npos) {
            error = at_line(number, std::string(ix == std::string::npos ? "x = " + number_text(row[0])
                                                                        : "y = " + number_text(row[1])) +
                                        " is none of the grid's " + (ix == std::string::npos ? "x" : "y") +
                                        " values (lines " + std::to_string(lines[1].number) + " and " +
                                        std::to_string(lines[2].number) + ")");
            return nullptr;
        }
        if (given[ix * ny + iy]) {
            error = at_line(number, "the grid point (" + number_text(row[0]) + ", " + number_text(row[1]) +
                                        ") is given a second time (first on line " +
                                        std::to_string(given[ix * ny + iy]) + ")");
            return nullptr;
        }
        given[ix * ny + iy] = number;
        z[ix * ny + iy] = row[2];
    }
    for (size_t ix = 0; ix < nx; ++ix)
        for (size_t iy = 0; iy < ny; ++iy)
            if (!given[ix * ny + iy]) {
                error = at_line(lines.back().number,
                                "the file ends without the grid point (" + number_text(x[ix]) + ", " +
                                    number_text(y[iy]) + ") (" + std::to_string(nx * ny) + " lines x y z expected, " +
                                    std::to_string(lines.size() - 3) + " given; MoorDyn would take 0 for it)");
                return nullptr;
            }
    return std::make_shared<const SeabedGrid>(std::move(x), std::move(y), std::move(z));
}

// MoorPy's bathymetry file: a title line, "nGridX nx", "nGridY ny", the x values, then ny rows "y d_1 .. d_nx".
std::shared_ptr<const SeabedGrid> read_moorpy(const std::vector<TextLine>& lines, std::string& error) {
    size_t n[2] = {0, 0};
    for (int a = 0; a < 2; ++a) {
        if (lines.size() < static_cast<size_t>(a + 2)) {
            error = at_line(lines.back().number, "the file ends before its grid's size (MoorPy's bathymetry file: a title "
                                                 "line, nGridX nx, nGridY ny, the x values, then ny lines y d_1 .. d_nx)");
            return nullptr;
        }
        const TextLine& line = lines[static_cast<size_t>(a + 1)];
        const size_t gap = line.text.find_first_of(" \t", line.text.find_first_not_of(" \t"));
        std::vector<double> value;
        if (gap == std::string_view::npos || !numbers(line.text.substr(gap), line.number, value, error) ||
            value.size() != 1) {
            if (error.empty())
                error = at_line(line.number, std::string("expected ") + (a == 0 ? "nGridX nx" : "nGridY ny") +
                                                 " (MoorPy's bathymetry file; MoorDyn's SeafloorFile starts with the line nx ny)");
            return nullptr;
        }
        if (!whole_count(value[0], line.number, a == 0 ? "nGridX" : "nGridY", n[a], error)) return nullptr;
    }
    const size_t nx = n[0], ny = n[1];
    if (lines.size() != 4 + ny) {
        error = at_line(lines.back().number, std::to_string(lines.size() < 4 ? 0 : lines.size() - 4) +
                                                 " lines of depths where nGridY = " + std::to_string(ny) +
                                                 " (a line y d_1 .. d_nx for each y)");
        return nullptr;
    }
    std::vector<double> x, y(ny), row;
    if (!numbers(lines[3].text, lines[3].number, x, error)) return nullptr;
    if (x.size() != nx) {
        error = at_line(lines[3].number, std::to_string(x.size()) + " x values where nGridX = " + std::to_string(nx));
        return nullptr;
    }
    if (!ascending(x, "x", lines[3].number, error)) return nullptr;
    std::vector<double> z(nx * ny);
    for (size_t iy = 0; iy < ny; ++iy) {
        const TextLine& line = lines[4 + iy];
        if (!numbers(line.text, line.number, row, error)) return nullptr;
        if (row.size() != nx + 1) {
            error = at_line(line.number, std::to_string(row.size()) + " values where a line of depths holds y and nGridX = " +
                                             std::to_string(nx) + " depths");
            return nullptr;
        }
        y[iy] = row[0];
        if (iy > 0 && !(y[iy] > y[iy - 1])) {
            error = at_line(line.number, "y = " + number_text(y[iy]) + " after " + number_text(y[iy - 1]) +
                                             ": the values must increase (the grid is interpolated between them in "
                                             "that order)");
            return nullptr;
        }
        for (size_t ix = 0; ix < nx; ++ix) z[ix * ny + iy] = -row[ix + 1];  // depth, positive down
    }
    return std::make_shared<const SeabedGrid>(std::move(x), std::move(y), std::move(z));
}

}  // namespace

SeabedGrid::SeabedGrid(std::vector<double> x, std::vector<double> y, std::vector<double> z)
    : x_(std::move(x)), y_(std::move(y)), z_(std::move(z)) {
    const size_t nx = x_.size(), ny = y_.size();
    double sum = 0.0;
    for (double v : z_) sum += v;
    mean_ = sum / static_cast<double>(z_.size());
    // the gradient of a cell's interpolant is linear along each of its edges: largest at a corner
    for (size_t ix = 0; ix < nx; ++ix) {
        for (size_t iy = 0; iy < ny; ++iy) {
            const size_t jx = ix + 1 < nx ? ix + 1 : ix, jy = iy + 1 < ny ? iy + 1 : iy;
            const size_t kx = ix > 0 ? ix - 1 : ix, ky = iy > 0 ? iy - 1 : iy;
            for (size_t ax : {kx, jx}) {
                for (size_t ay : {ky, jy}) {
                    const double gx = ax != ix ? (node(ax, iy) - node(ix, iy)) / (x_[ax] - x_[ix]) : 0.0;
                    const double gy = ay != iy ? (node(ix, ay) - node(ix, iy)) / (y_[ay] - y_[iy]) : 0.0;
                    steepest_ = std::max(steepest_, std::hypot(gx, gy));
                }
            }
        }
    }
}

std::shared_ptr<const SeabedGrid> SeabedGrid::read(std::string_view text, std::string& error) {
    error.clear();
    const std::vector<TextLine> lines = filled_lines(text);
    if (lines.empty()) {
        error = "the file is empty (a seabed grid: MoorDyn's SeafloorFile or MoorPy's bathymetry file)";
        return nullptr;
    }
    // MoorDyn's first line is "nx ny"; MoorPy's a title
    std::vector<double> head;
    std::string ignored;
    if (numbers(lines[0].text, lines[0].number, head, ignored) && head.size() == 2) return read_moordyn(lines, error);
    if (lines.size() > 1 && lines[1].text.find("nGrid") != std::string_view::npos) return read_moorpy(lines, error);
    error = at_line(lines[0].number, "neither MoorDyn's SeafloorFile (its first line: nx ny, two whole numbers) nor "
                                     "MoorPy's bathymetry file (a title line, then nGridX nx and nGridY ny)");
    return nullptr;
}

double SeabedGrid::height(double x, double y, double* dzdx, double* dzdy) const {
    const Bracket bx = bracket(x_, x), by = bracket(y_, y);
    const size_t ny = y_.size();
    const double c00 = z_[bx.lo * ny + by.lo], c01 = z_[bx.lo * ny + by.hi];
    const double c10 = z_[bx.hi * ny + by.lo], c11 = z_[bx.hi * ny + by.hi];
    // MoorDyn's order of the sums (interp2): along x first, then along y
    const double c0 = c00 * (1.0 - bx.f) + c10 * bx.f;
    const double c1 = c01 * (1.0 - bx.f) + c11 * bx.f;
    if (dzdx) *dzdx = bx.slope * ((1.0 - by.f) * (c10 - c00) + by.f * (c11 - c01));
    if (dzdy) *dzdy = by.slope * (c1 - c0);
    return c0 * (1.0 - by.f) + c1 * by.f;
}

double SeabedGrid::highest(double x0, double x1, double y0, double y1) const {
    const Bracket a = bracket(x_, x0), b = bracket(x_, x1), c = bracket(y_, y0), d = bracket(y_, y1);
    const size_t ny = y_.size();
    double top = -HUGE_VAL;
    for (int ix = a.lo; ix <= b.hi; ++ix)
        for (int iy = c.lo; iy <= d.hi; ++iy) top = std::max(top, z_[static_cast<size_t>(ix) * ny + static_cast<size_t>(iy)]);
    return top;
}

std::string SeabedGrid::describe() const {
    const auto [low, high] = std::minmax_element(z_.begin(), z_.end());
    return std::to_string(x_.size()) + " x " + std::to_string(y_.size()) + " points over x " + number_text(x_.front()) +
           " to " + number_text(x_.back()) + " m, y " + number_text(y_.front()) + " to " + number_text(y_.back()) +
           " m, heights " + number_text(*low) + " to " + number_text(*high) + " m (steepest gradient " +
           number_text(steepest_) + ")";
}

}  // namespace uc
