// winch.cpp - see winch.h.
#include "line/winch.h"

#include <algorithm>
#include <cmath>

#include "terms/hermite_element.h"

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

double WinchStep::length(double tau) const {
    const double ramp = std::min(tau, rampTime), after = std::max(0.0, tau - rampTime);
    return rate0 * ramp + 0.5 * acceleration * ramp * ramp + rateCaught * after + 0.5 * follow * after * after;
}

double WinchStep::rate(double tau) const {
    return tau < rampTime ? rate0 + acceleration * tau : rateCaught + follow * (tau - rampTime);
}

namespace {

// The step from rate0 to rate1 at the step's end (h): at +-A until it meets the command, whose slope
// `follow` (|follow| <= A, |rate1 - rate0| <= A h) it follows after that; follow 0: at +-A to rate1,
// then held.
WinchStep ramp_to(double rate0, double rate1, double A, double follow = 0.0, double h = 0.0) {
    WinchStep s;
    s.rate0 = s.rateCaught = rate0;
    s.rate1 = rate1;
    if (follow == 0.0) {
        s.rampTime = std::fabs(rate1 - rate0) / A;
        s.acceleration = rate1 > rate0 ? A : rate1 < rate0 ? -A : 0.0;
        s.rateCaught = rate1;
        return s;
    }
    // rate0 + a r + follow (h - r) = rate1 with a = +-A: the drum catches up in r, then follows
    const double D = rate1 - rate0 - follow * h;
    s.follow = follow;
    if (D == 0.0) return s;
    s.acceleration = D > 0.0 ? A : -A;
    s.rampTime = std::min(h, std::fabs(D) / (A - (D > 0.0 ? follow : -follow)));
    s.rateCaught = rate0 + s.acceleration * s.rampTime;
    return s;
}

// The farthest the line gets paid out (above the step's start) along the step and a braking at A
// after it, and the farthest it gets hauled in (negative): both grow with the end rate.
struct Reach {
    double out, in;
};
Reach reach(const WinchStep& s, double A, double h) {
    const double end = s.length(h);
    Reach r{std::max(0.0, end), std::min(0.0, end)};
    auto see = [&r](double x) {
        r.out = std::max(r.out, x);
        r.in = std::min(r.in, x);
    };
    // where the rate passes 0 inside the step (the length turns there)
    if (s.acceleration != 0.0 && s.rate0 * s.acceleration < 0.0 && -s.rate0 / s.acceleration < s.rampTime) {
        see(-s.rate0 * s.rate0 / (2.0 * s.acceleration));
    }
    if (s.follow != 0.0 && s.rateCaught * s.follow < 0.0) {
        const double turn = s.rampTime - s.rateCaught / s.follow;
        if (turn < h) see(s.length(turn));
    }
    const double stop = std::isfinite(A) ? s.rate1 * s.rate1 / (2.0 * A) : 0.0;
    if (s.rate1 > 0.0) r.out = std::max(r.out, end + stop);
    if (s.rate1 < 0.0) r.in = std::min(r.in, end - stop);
    return r;
}

constexpr int kBisections = 80;

// The boundary between `good` (fits) and `bad` (does not), by bisection: the last point that fits.
template <class Fits>
double boundary(double good, double bad, Fits fits) {
    for (int k = 0; k < kBisections; ++k) {
        const double m = 0.5 * (good + bad);
        (fits(m) ? good : bad) = m;
    }
    return good;
}
constexpr double kLengthSlack = 1e-12;  // relative to the deployed length

// The drum without an acceleration limit: at the rate limit_winch_rate allows over the whole step.
WinchStep hard_step(double requested, double length, double h, const WinchLimits& limits) {
    const WinchRate r = limit_winch_rate(requested, length, h, limits);
    WinchStep s = WinchStep::hold(r.rate);
    s.saturated = r.saturated;
    const double wanted = std::clamp(requested, -limits.maxRate, limits.maxRate);
    s.limit = r.rate < wanted ? 1 : r.rate > wanted ? -1 : 0;
    return s;
}

// Without an acceleration limit and with a command that changes over the step: the drum runs at the
// command (within +-maxRate) when that keeps the length within the limits; else it holds the rate
// hard_step allows for the command's mean over the step.
WinchStep free_step(double requested, double rate0, double slope, double length, double h,
                    const WinchLimits& limits) {
    double r0 = std::clamp(requested, -limits.maxRate, limits.maxRate);
    // a command that continues the drum's rate (to round-off) does not jump it: no axial shock, no restart
    if (std::fabs(r0 - rate0) <= 1e-12 * std::max(1.0, std::fabs(rate0))) r0 = rate0;
    const double r1 = std::clamp(requested + slope * h, -limits.maxRate, limits.maxRate);
    WinchStep s;
    s.rate0 = r0;
    s.rate1 = s.rateCaught = r1;
    s.rampTime = h;
    s.acceleration = (r1 - r0) / h;
    const Reach r = reach(s, INFINITY, h);
    if (r.out <= limits.maxLength - length && r.in >= limits.minLength - length) return s;
    return hard_step(requested + 0.5 * slope * h, length, h, limits);
}

// plan_winch_step with the drum following the command's slope `follow` once caught up (0: holding).
WinchStep plan_step(double command, double rate0, double length, double h, const WinchLimits& limits,
                    double follow) {
    const double A = limits.maxAcceleration;
    const double wanted = std::clamp(command, -limits.maxRate, limits.maxRate);
    double lo = rate0 - A * h, hi = rate0 + A * h;
    // the largest end rate whose pay-out stays within the room to maxLength, the smallest whose
    // haul-in stays within that to minLength (slack: how far past them a drum may be)
    // (a length past a limit by round-off stays there: it is neither pushed further nor pulled back)
    const double room = std::max(0.0, limits.maxLength - length), roomIn = std::min(0.0, limits.minLength - length);
    // (the drum at +-A to its end rate, then holding it)
    auto fits_out = [&](double r, double slack) { return reach(ramp_to(rate0, r, A), A, h).out <= room + slack; };
    auto fits_in = [&](double r, double slack) { return reach(ramp_to(rate0, r, A), A, h).in >= roomIn - slack; };
    // A drum already too fast to brake in time (a state from before the limit was set, a length
    // outside the limits) stops at the limit at once, as without an acceleration limit. The slack
    // is the round-off of a drum braking along its envelope (its stop distance computed two ways).
    const double slack = kLengthSlack * std::max(1.0, std::fabs(length));
    if (follow != 0.0) {
        // following the command when that keeps the drum able to brake within the limits (to
        // round-off: a ramp that ends on a limit); else, near a limit, the drum brakes along its
        // envelope, holding its rate between its ramps
        WinchStep s = ramp_to(rate0, std::clamp(wanted, lo, hi), A, follow, h);
        const Reach r = reach(s, A, h);
        if (!(r.out <= room + slack && r.in >= roomIn - slack)) {
            return plan_step(command, rate0, length, h, limits, 0.0);
        }
        s.saturated = s.rate1 != command;
        return s;
    }
    if (!fits_out(lo, slack) || !fits_in(hi, slack)) return hard_step(command, length, h, limits);
    const bool cutOut = !fits_out(hi, 0.0), cutIn = !fits_in(lo, 0.0);
    const double outLo = lo, inHi = hi;  // the bisections start from what fits
    if (cutOut) hi = boundary(outLo, hi, [&](double r) { return fits_out(r, 0.0); });
    if (cutIn) lo = boundary(inHi, lo, [&](double r) { return fits_in(r, 0.0); });
    double rate1 = std::clamp(wanted, lo, hi);
    // braking onto a limit: the bisection's last bits of a rate are a drum at rest
    if ((cutOut || cutIn) && std::fabs(rate1) <= kLengthSlack * A * h) rate1 = 0.0;
    WinchStep s = ramp_to(rate0, rate1, A);
    s.saturated = rate1 != command;
    s.limit = (rate1 < wanted && cutOut) ? 1 : (rate1 > wanted && cutIn) ? -1 : 0;
    return s;
}

}  // namespace

WinchStep plan_winch_step(double requested, double rate0, double length, double h, const WinchLimits& limits,
                          double slope) {
    const double A = limits.maxAcceleration;
    const double command = requested + slope * h;  // the command at the step's end
    WinchStep s;
    if (!(A > 0.0)) {
        s = slope == 0.0 ? hard_step(requested, length, h, limits)
                         : free_step(requested, rate0, slope, length, h, limits);
    } else {
        // the drum follows the command's slope while the command is within +-maxRate
        const bool within = std::fabs(command) <= limits.maxRate && std::fabs(requested) <= limits.maxRate;
        s = plan_step(command, rate0, length, h, limits, within ? std::clamp(slope, -A, A) : 0.0);
    }
    s.rateLimited = std::fabs(requested) > limits.maxRate || std::fabs(command) > limits.maxRate;
    return s;
}

double braking_rate_limit(double rate, double length, const WinchLimits& limits) {
    const double A = limits.maxAcceleration;
    if (!(A > 0.0)) return rate;
    const double up = std::sqrt(2.0 * A * std::max(0.0, limits.maxLength - length));
    const double down = -std::sqrt(2.0 * A * std::max(0.0, length - limits.minLength));
    return std::clamp(rate, down, up);
}

double constant_tension_rate(double tension, double target, double gain, double maxRate) {
    return std::clamp(gain * (tension - target), -maxRate, maxRate);
}

}  // namespace uc
