// rainflow.cpp - see rainflow.h.
#include "line/rainflow.h"

#include <cmath>

namespace uc {
namespace {

// Removes the closed cycles at the top of a turning-point stack (the four-point rule) and returns
// their damage; counts them into *cycles.
double close_cycles(double* s, std::int32_t& n, const SNCurve& curve, double* cycles) {
    double damage = 0.0;
    while (n >= 4) {
        const double x1 = s[n - 4], x2 = s[n - 3], x3 = s[n - 2], x4 = s[n - 1];
        const double inner = std::fabs(x3 - x2);
        if (inner > std::fabs(x2 - x1) || inner > std::fabs(x4 - x3)) break;
        damage += curve.cycle_damage(inner);
        *cycles += 1.0;
        s[n - 3] = x4;
        n -= 2;
    }
    return damage;
}

}  // namespace

double SNCurve::cycle_damage(double tensionRange) const {
    if (!(area > 0.0) || !(tensionRange > 0.0)) return 0.0;
    const double stressRangeMPa = tensionRange / area * 1e-6;
    return std::pow(stressRangeMPa, m) * std::pow(10.0, -logK);
}

void RainflowCounter::push_turning_point(double value, const SNCurve& curve) {
    if (size >= kCapacity - 1) {  // room for it and the moving end: the oldest range leaves as a half cycle
        closedDamage += 0.5 * curve.cycle_damage(std::fabs(stack[1] - stack[0]));
        closedCycles += 0.5;
        for (int k = 1; k < size; ++k) stack[k - 1] = stack[k];
        --size;
    }
    stack[size++] = value;
    closedDamage += close_cycles(stack, size, curve, &closedCycles);
}

void RainflowCounter::add(double value, const SNCurve& curve) {
    ++samples;
    if (samples == 1) {
        stack[0] = value;
        size = 1;
        last = value;
        return;
    }
    if (value == last) return;
    const int d = value > last ? 1 : -1;
    if (direction == 0 || d == direction) {
        // Still moving the same way: the newest turning point moves with the signal. It is not a
        // turning point of the stack yet unless the stack holds only the start.
        if (direction == 0) {
            stack[size++] = value;
        } else {
            stack[size - 1] = value;
        }
    } else {
        // A reversal at `last` (already the top of the stack): close what it closes, then start
        // the new leg.
        const double top = stack[size - 1];
        --size;
        push_turning_point(top, curve);
        stack[size++] = value;
    }
    direction = d;
    last = value;
}

double RainflowCounter::damage(const SNCurve& curve) const {
    // The newest sample ends the history: as an offline count would, treat it as a turning point
    // (on a copy: later samples may still move it).
    double copy[kCapacity];
    std::int32_t n = size;
    for (int k = 0; k < n; ++k) copy[k] = stack[k];
    double cycles = 0.0;
    double d = closedDamage + close_cycles(copy, n, curve, &cycles);
    for (int k = 1; k < n; ++k) d += 0.5 * curve.cycle_damage(std::fabs(copy[k] - copy[k - 1]));
    return d;
}

}  // namespace uc
