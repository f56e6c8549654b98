// winch.cpp - see winch.h.
#include "winch.h"

#include <algorithm>
#include <cmath>

#include "hermite_element.h"

namespace uc {

void hermite_split_node(const double* X, double length, double a, double* node) {
    const ShapeValues s = hermite_shape(a / length, length);
    for (int c = 0; c < 3; ++c) {
        double r = 0.0, dr = 0.0;
        for (int k = 0; k < 4; ++k) {
            r += s.N[k] * X[3 * k + c];
            dr += s.dN[k] * X[3 * k + c];
        }
        node[c] = r;
        node[3 + c] = dr;
    }
}

RemeshAction remesh_action(double topLength, double nominal, bool hasNext) {
    if (topLength > kSplitFactor * nominal) return RemeshAction::Split;
    if (hasNext && topLength < kMergeFactor * nominal) return RemeshAction::Merge;
    return RemeshAction::None;
}

int winch_capacity(double maxLength, double nominal) {
    return static_cast<int>(std::ceil(maxLength / nominal)) + 2;
}

WinchRate limit_winch_rate(double requested, double length, double h, const WinchLimits& limits) {
    double rate = std::clamp(requested, -limits.maxRate, limits.maxRate);
    if (h > 0.0) {
        // the end of the step stays within the limits (and a length already outside is not pushed
        // further out)
        const double up = std::max(0.0, (limits.maxLength - length) / h);
        const double down = std::min(0.0, (limits.minLength - length) / h);
        rate = std::clamp(rate, down, up);
    }
    return {rate, rate != requested};
}

double constant_tension_rate(double tension, double target, double gain, double maxRate) {
    return std::clamp(gain * (tension - target), -maxRate, maxRate);
}

}  // namespace uc
