// winch.h - the pieces of a winch at the tow point that do not depend on the line's layout:
// splitting a cubic Hermite element exactly, when to split or merge the variable-length top
// element, the element capacity for the longest line, and the winch rate with its limits
// (docs/winch.md).
#pragma once

namespace uc {

// The node that splits a cubic Hermite element exactly. X: the element's 12 nodal values
// [r_i, r'_i, r_j, r'_j] of any field interpolated by the element (positions, velocities or
// accelerations; ' = d/ds in unstretched arc length), length l, split at arc length a from node i
// (0 < a < l). Writes the field and its arc-length derivative at a (6 values). The elements
// [r_i, r'_i, node] of length a and [node, r_j, r'_j] of length l - a represent the same cubic.
void hermite_split_node(const double* X, double length, double a, double* node);

enum class RemeshAction { None, Split, Merge };

// What the top element (unstretched length topLength) needs, for elements of nominal length
// `nominal`: split above 1.5 nominal, merge with the element below under 0.5 nominal when there is
// one (hasNext). A split leaves topLength - nominal >= 0.5 nominal and a merge topLength + nominal
// < 1.5 nominal, so neither triggers the other at once.
constexpr double kSplitFactor = 1.5;
constexpr double kMergeFactor = 0.5;
RemeshAction remesh_action(double topLength, double nominal, bool hasNext);

// Elements needed for the longest line: every element but the top one has the nominal length, the
// top one at most kSplitFactor nominal before it splits, plus one for a step that overshoots.
int winch_capacity(double maxLength, double nominal);

struct WinchLimits {
    double minLength, maxLength;  // [m] unstretched length
    double maxRate;               // [m/s] in both directions
};

struct WinchRate {
    double rate;     // [m/s] the rate applied over the step, + pays out
    bool saturated;  // the request was cut by maxRate or by a length limit
};

// The rate applied over a step of h seconds from unstretched length `length`: `requested`
// limited to +-maxRate and so that the length at the end of the step stays within the limits.
// requested must be finite (the adapter refuses NaN and infinities before).
WinchRate limit_winch_rate(double requested, double length, double h, const WinchLimits& limits);

// Constant-tension winch: the rate that drives the tow tension towards `target`: pays out
// (positive) when the tension is above it, hauls in below, gain [m/s per N], within +-maxRate.
double constant_tension_rate(double tension, double target, double gain, double maxRate);

}  // namespace uc
