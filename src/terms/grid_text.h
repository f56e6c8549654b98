// grid_text.h - what the readers of gridded data (current_grid, seabed_grid) share: a text's lines, the
// numbers of one line, the check that an axis ascends, and the interval of an axis that holds a value, as
// MoorDyn finds it (linear between the nodes, the edge value held outside).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace uc {

std::string number_text(double v);  // "%.9g"

// The lines of a text (without their line ends).
std::vector<std::string_view> split_lines(std::string_view text);

// The numbers of one line (separated by blanks, tabs or commas); false with error = "line <number>: ..."
// at a token that is not a finite number.
bool numbers(std::string_view line, int number, std::vector<double>& out, std::string& error);

// False with error = "line <number>: <name> = <v> after <u>: the values must increase ..." where the axis
// does not strictly ascend.
bool ascending(const std::vector<double>& axis, const char* name, int number, std::string& error);

// The interval of an axis holding v, as MoorDyn finds it: nodes lo and hi (equal on an axis of one
// value), the weight f of hi, clamped to [0, 1] outside (the edge value held), and 1 / (hi - lo) where
// v is strictly inside (else 0: the held value has no slope).
struct Bracket {
    int lo = 0, hi = 0;
    double f = 0.0, slope = 0.0;
    bool outside = false;
};
Bracket bracket(const std::vector<double>& axis, double v);

}  // namespace uc
