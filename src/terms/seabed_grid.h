// seabed_grid.h - a seabed given as a grid of heights (docs/model.md, "A seabed given as a grid"): MoorDyn's
// SeafloorFile (a line "nx ny", the nx x values, the ny y values, then nx ny rows "x y z", z the seabed's
// height) or MoorPy's bathymetry file (a title line, "nGridX nx", "nGridY ny", the x values, then ny rows
// "y d_1 ... d_nx", d the depth, positive down). Interpolated bilinearly in each cell as both codes do, held
// at the edge values outside the grid (the height of the nearest edge point: level across the edge).
//
// Immutable once read: the lines of a model share one through a shared pointer, outside the saved state
// (the file is read again when a state is restored into a new instance).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace uc {

class SeabedGrid {
public:
    // Axes strictly ascending (a single value: level along that axis) and the heights at the nodes,
    // z[ix * ny + iy] [m, up].
    SeabedGrid(std::vector<double> x, std::vector<double> y, std::vector<double> z);

    // MoorDyn's SeafloorFile or MoorPy's bathymetry file (told apart by the first line: two whole numbers
    // in MoorDyn's); null with error = "line <n>: <what>" where the text is no such grid.
    static std::shared_ptr<const SeabedGrid> read(std::string_view text, std::string& error);

    // The height [m] at (x, y), with its gradient (dz/dx, dz/dy) where asked: the bilinear interpolant of
    // the cell that holds the point (the cell on the point's +x, +y side on a grid line), clamped to the
    // grid outside it (there the gradient across the edge is 0).
    double height(double x, double y, double* dzdx = nullptr, double* dzdy = nullptr) const;

    // The highest node height [m] of the cells that meet the box [x0, x1] x [y0, y1] (clamped to the
    // grid): no point of the interpolant over the box is higher.
    double highest(double x0, double x1, double y0, double y1) const;

    // The largest gradient magnitude of any cell's interpolant (at a cell's corners: it is linear in the
    // other coordinate along each edge), and the mean of the node heights (MoorDyn's average depth).
    double steepest() const { return steepest_; }
    double mean_height() const { return mean_; }

    const std::vector<double>& x() const { return x_; }
    const std::vector<double>& y() const { return y_; }
    double node(size_t ix, size_t iy) const { return z_[ix * y_.size() + iy]; }
    // One line for the log: the grid's size, extent and heights.
    std::string describe() const;

private:
    std::vector<double> x_, y_, z_;
    double steepest_ = 0.0, mean_ = 0.0;
};

}  // namespace uc
