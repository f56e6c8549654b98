// winch.h - the pieces of a winch at the tow point that do not depend on the line's layout:
// splitting a cubic Hermite element exactly, when to split or merge the variable-length top
// element, the element capacity for the longest line, and the winch rate with its limits
// (docs/winch.md).
#pragma once

#include <cstdint>

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
    double maxAcceleration = 0.0; // [m/s2] of the drum, both directions; 0: none
};

struct WinchRate {
    double rate;     // [m/s] the rate applied over the step, + pays out
    bool saturated;  // the request was cut by maxRate or by a length limit
};

// The rate applied over a step of h seconds from unstretched length `length`: `requested`
// limited to +-maxRate and so that the length at the end of the step stays within the limits.
// requested must be finite (the adapter refuses NaN and infinities before).
WinchRate limit_winch_rate(double requested, double length, double h, const WinchLimits& limits);

// The drum's motion over a step of h seconds with a finite acceleration A: from `rate0` it
// accelerates at `acceleration` (+-A) until rampTime, then follows the command's slope `follow`
// (|follow| <= A; 0 for a command held over the step) to `rate1` at the step's end.
struct WinchStep {
    double rate0 = 0.0, rate1 = 0.0, acceleration = 0.0;  // acceleration: +-A, or 0 once rate1 holds
    double rampTime = 0.0;                                // when the drum has caught up with the command
    double follow = 0.0;                                  // [m/s2] the acceleration after rampTime
    double rateCaught = 0.0;                              // [m/s] the rate at rampTime
    std::int32_t limit = 0;    // -1 / +1: a length limit (minLength / maxLength) cut it
    bool saturated = false;    // the request was cut by maxRate or by a length limit
    bool rateLimited = false;  // maxRate cut the request
    char unused[2] = {};       // no padding: a line's saved state is its bytes (line/line_state.h)
    // Paid out since the step's start after tau seconds, and the rate then.
    double length(double tau) const;
    double rate(double tau) const;
    // A drum holding `rate` (the state between steps).
    static WinchStep hold(double rate) {
        WinchStep s;
        s.rate0 = s.rate1 = s.rateCaught = rate;
        return s;
    }
};

// The step of a drum at `rate0` asked for `requested`, `length` deployed: the requested rate within
// +-maxRate and what the acceleration reaches in h, and no faster than lets the drum brake at A to a
// stop at the length limits (it stops exactly there). `slope`: the command's derivative over the step
// (the master's input derivative of winch.rate; 0 when not given): the command at the step's end is
// requested + slope h, and the drum, once it has caught up with the command at +-A, follows its
// slope (within +-A) instead of holding, so a ramped command reaches the drum as a ramp. Without an
// acceleration limit (A = 0) the drum runs at the command, requested + slope t, within the limits.
WinchStep plan_winch_step(double requested, double rate0, double length, double h, const WinchLimits& limits,
                          double slope = 0.0);

// The braking envelope of a drum with acceleration A: the fastest rate (+ pays out) at `length` from
// which it can still stop within the limits; the constant-tension winch's command is held within it.
double braking_rate_limit(double rate, double length, const WinchLimits& limits);

// Constant-tension winch: the rate that drives the tow tension towards `target`: pays out
// (positive) when the tension is above it, hauls in below, gain [m/s per N], within +-maxRate.
double constant_tension_rate(double tension, double target, double gain, double maxRate);

}  // namespace uc
