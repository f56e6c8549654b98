// locate_crossing.h - where a function of a step's length crosses its threshold within the step: regula falsi
// (Illinois) on the length, each trial taken anew from the step's start (docs/line_failure.md, "The break ends its
// step"; a mooring system's failures and one line's).
#pragma once

#include <algorithm>
#include <cmath>

namespace uc {

// g in units of its tolerance (|g| <= 1 stands), g(0) = ga <= 1 < gb = g(b). trial(tau, g) takes the step of length
// tau from its start and gives g there (false: the trial failed, and so does the call). At most `trials` trials, each
// kept within [a + 1e-3 span, b - 1e-3 span] of the bracket; tau and g: the last trial's (b and gb with none).
template <class Trial>
bool locate_crossing(double ga, double b, double gb, int trials, Trial&& trial, double& tau, double& g) {
    double a = 0.0;
    tau = b;
    g = gb;
    int side = 0;
    for (int it = 0; it < trials && std::abs(g) > 1.0; ++it) {
        const double span = b - a;
        tau = std::clamp((a * gb - b * ga) / (gb - ga), a + 1e-3 * span, b - 1e-3 * span);
        if (!trial(tau, g)) return false;
        if (g > 0.0) {
            b = tau;
            gb = g;
            if (side > 0) ga *= 0.5;
            side = 1;
        } else {
            a = tau;
            ga = g;
            if (side < 0) gb *= 0.5;
            side = -1;
        }
    }
    return true;
}

}  // namespace uc
