// The layout-independent pieces of the winch: the exact split of a cubic Hermite element, the
// split/merge rule with its hysteresis, the element capacity and the rate limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <cstdint>
#include <string>

#include "api/cable_api.h"
#include "terms/hermite_element.h"
#include "line/simulation.h"
#include "line/winch.h"

namespace uc {
namespace {

// A curved, stretched element: nodal positions and tangents of no special form.
void curved_element(double (&X)[12]) {
    const double v[12] = {0.0, 0.0, 0.0, -0.80, 0.05, -0.62,
                          -10.2, 0.7, -9.1, -0.55, 0.08, -0.84};
    for (int k = 0; k < 12; ++k) X[k] = v[k];
}

struct Point {
    Vec3 r, dr, d2r;
};

Point evaluate(const double* X, double length, double s) {
    const ShapeValues sv = hermite_shape(s / length, length);
    Point p{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    for (int k = 0; k < 4; ++k) {
        const Eigen::Map<const Vec3> x(X + 3 * k);
        p.r += sv.N[k] * x;
        p.dr += sv.dN[k] * x;
        p.d2r += sv.d2N[k] * x;
    }
    return p;
}

// The two elements of a split: upper [r_i, r'_i, node] and lower [node, r_j, r'_j].
void split(const double* X, double length, double a, double (&upper)[12], double (&lower)[12]) {
    double node[6];
    hermite_split_node(X, length, a, node);
    for (int k = 0; k < 6; ++k) {
        upper[k] = X[k];
        upper[6 + k] = node[k];
        lower[k] = node[k];
        lower[6 + k] = X[6 + k];
    }
}

double quadratic_form(const Mat4& M, const double* X) {
    double q = 0.0;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
            q += M(a, b) * Eigen::Map<const Vec3>(X + 3 * a).dot(Eigen::Map<const Vec3>(X + 3 * b));
    return q;
}

TEST(WinchSplit, BothHalvesAreTheSameCubic) {
    double X[12];
    curved_element(X);
    const double l = 22.5;
    for (double a : {0.01 * l, 7.5, 0.5 * l, 15.0, 0.99 * l}) {
        double up[12], lo[12];
        split(X, l, a, up, lo);
        for (int k = 0; k <= 40; ++k) {
            const double s = l * k / 40.0;
            const Point want = evaluate(X, l, s);
            const Point got = s <= a ? evaluate(up, a, s) : evaluate(lo, l - a, s - a);
            // round-off of a cubic evaluated at O(10) m: 1e-12 relative to the element's size
            EXPECT_LT((got.r - want.r).norm(), 1e-12 * l) << "a " << a << " s " << s;
            EXPECT_LT((got.dr - want.dr).norm(), 1e-12) << "a " << a << " s " << s;
            // strain |r'| - 1 (and with it the tension) unchanged at every material point
            EXPECT_NEAR(got.dr.norm(), want.dr.norm(), 1e-12) << "a " << a << " s " << s;
            EXPECT_LT((got.d2r - want.d2r).norm(), 1e-12 * (1.0 + want.d2r.norm()) / std::min(a, l - a))
                << "a " << a << " s " << s;
        }
    }
}

TEST(WinchSplit, ConservesMassKineticEnergyAndBendingEnergy) {
    // The element mass and bending matrices are exact integrals, so the split (an exact
    // re-parametrisation of the same cubic) keeps int |v|^2 ds and int |r''|^2 ds to round-off;
    // the mass m l is kept because the lengths add.
    double X[12];
    curved_element(X);
    const double l = 22.5, a = 7.5;
    double up[12], lo[12];
    split(X, l, a, up, lo);
    const ElementTables whole = make_element_tables(l, 3, 3);
    const ElementTables upper = make_element_tables(a, 3, 3);
    const ElementTables lower = make_element_tables(l - a, 3, 3);
    EXPECT_DOUBLE_EQ(upper.length + lower.length, whole.length);
    const double mass_form = quadratic_form(whole.mass, X);
    EXPECT_NEAR(quadratic_form(upper.mass, up) + quadratic_form(lower.mass, lo), mass_form,
                1e-13 * mass_form);
    const double bending = quadratic_form(whole.bending, X);
    EXPECT_NEAR(quadratic_form(upper.bending, up) + quadratic_form(lower.bending, lo), bending,
                1e-11 * bending);
}

TEST(WinchRemesh, SplitAndMergeThresholdsWithHysteresis) {
    const double l0 = 15.0;
    EXPECT_EQ(remesh_action(1.0 * l0, l0, true), RemeshAction::None);
    EXPECT_EQ(remesh_action(1.5 * l0, l0, true), RemeshAction::None);
    EXPECT_EQ(remesh_action(1.5 * l0 + 1e-9, l0, true), RemeshAction::Split);
    EXPECT_EQ(remesh_action(0.5 * l0, l0, true), RemeshAction::None);
    EXPECT_EQ(remesh_action(0.5 * l0 - 1e-9, l0, true), RemeshAction::Merge);
    // a single element never merges (nothing below it)
    EXPECT_EQ(remesh_action(0.1 * l0, l0, false), RemeshAction::None);
    // what a split or a merge leaves behind needs nothing more
    for (double top = 1.5 * l0 + 1e-9; top < 1.7 * l0; top += 0.01 * l0)
        EXPECT_EQ(remesh_action(top - l0, l0, true), RemeshAction::None) << top;
    for (double top = 0.5 * l0 - 1e-9; top > 0.3 * l0; top -= 0.01 * l0)
        EXPECT_EQ(remesh_action(top + l0, l0, true), RemeshAction::None) << top;
}

TEST(WinchRemesh, CapacityHoldsTheLongestLine) {
    for (double l0 : {5.0, 15.0, 17.3}) {
        for (double maxLength : {50.0, 600.0, 1234.5}) {
            // the most elements: the top one just above 0.5 l0 (about to merge), the rest nominal
            const double top = 0.5 * l0;
            const int needed = 1 + static_cast<int>(std::ceil((maxLength - top) / l0));
            EXPECT_GE(winch_capacity(maxLength, l0), needed) << l0 << " " << maxLength;
        }
    }
}

TEST(WinchRate, SaturatesAtMaxRate) {
    const WinchLimits lim{50.0, 600.0, 1.0};
    WinchRate r = limit_winch_rate(0.5, 100.0, 0.5, lim);
    EXPECT_EQ(r.rate, 0.5);
    EXPECT_FALSE(r.saturated);
    r = limit_winch_rate(3.0, 100.0, 0.5, lim);
    EXPECT_EQ(r.rate, 1.0);
    EXPECT_TRUE(r.saturated);
    r = limit_winch_rate(-3.0, 100.0, 0.5, lim);
    EXPECT_EQ(r.rate, -1.0);
    EXPECT_TRUE(r.saturated);
}

TEST(WinchRate, StopsExactlyAtTheLengthLimits) {
    const WinchLimits lim{50.0, 600.0, 1.0};
    // pay-out that would cross maxLength within the step lands on it
    WinchRate r = limit_winch_rate(0.5, 599.9, 0.5, lim);
    EXPECT_TRUE(r.saturated);
    EXPECT_NEAR(599.9 + r.rate * 0.5, 600.0, 1e-12);
    // at the limit: no further pay-out, haul-in allowed
    r = limit_winch_rate(0.5, 600.0, 0.5, lim);
    EXPECT_EQ(r.rate, 0.0);
    EXPECT_TRUE(r.saturated);
    r = limit_winch_rate(-0.5, 600.0, 0.5, lim);
    EXPECT_EQ(r.rate, -0.5);
    EXPECT_FALSE(r.saturated);
    // haul-in onto minLength likewise
    r = limit_winch_rate(-0.8, 50.2, 0.5, lim);
    EXPECT_TRUE(r.saturated);
    EXPECT_NEAR(50.2 + r.rate * 0.5, 50.0, 1e-12);
    r = limit_winch_rate(-0.8, 50.0, 0.5, lim);
    EXPECT_EQ(r.rate, 0.0);
    r = limit_winch_rate(0.8, 50.0, 0.5, lim);
    EXPECT_EQ(r.rate, 0.8);
}

// A drum with an acceleration limit driven at full speed into each length limit from rest: the rate
// changes by at most A h per step, never exceeds maxRate, and the drum stops exactly at the limit.
TEST(WinchDrum, BrakesAtItsAccelerationToStopExactlyAtTheLimits) {
    const WinchLimits lim{50.0, 120.0, 1.0, 0.1};
    for (const double h : {0.5, 0.13, 2.0}) {
        for (const double request : {1.0, -1.0}) {
            double length = 100.0, rate = 0.0, farthest = length;
            for (int k = 0; k < static_cast<int>(200.0 / h); ++k) {
                const WinchStep s = plan_winch_step(request, rate, length, h, lim);
                ASSERT_EQ(s.rate0, rate) << "the drum's rate is continuous";
                EXPECT_LE(std::fabs(s.rate1 - s.rate0), lim.maxAcceleration * h * (1 + 1e-12));
                EXPECT_LE(std::fabs(s.rate1), lim.maxRate);
                for (int i = 1; i <= 8; ++i) {  // inside the step too
                    const double at = length + s.length(h * i / 8.0);
                    farthest = request > 0 ? std::max(farthest, at) : std::min(farthest, at);
                }
                length += s.length(h);
                rate = s.rate1;
            }
            const double limit = request > 0 ? lim.maxLength : lim.minLength;
            EXPECT_NEAR(length, limit, 1e-9) << "h " << h;
            EXPECT_NEAR(farthest, limit, 1e-9) << "h " << h;  // no overshoot
            EXPECT_EQ(rate, 0.0);
        }
    }
}

TEST(WinchDrum, WithoutAnAccelerationLimitItIsTheRateLimitOverTheStep) {
    const WinchLimits lim{50.0, 600.0, 1.0, 0.0};
    for (const double request : {0.5, 3.0, -3.0}) {
        for (const double length : {100.0, 599.9, 50.2}) {
            const WinchStep s = plan_winch_step(request, 0.3, length, 0.5, lim);
            const WinchRate r = limit_winch_rate(request, length, 0.5, lim);
            EXPECT_EQ(s.rate0, r.rate);
            EXPECT_EQ(s.rate1, r.rate);
            EXPECT_DOUBLE_EQ(s.length(0.5), r.rate * 0.5);
        }
    }
}

// A ramped command given with its slope (the master's input derivative of winch.rate): the drum
// follows the ramp exactly (its rate at every instant is the command's), while the same command held
// over each step (no derivative) leaves the drum a staircase behind it.
TEST(WinchDrum, FollowsARampedCommandGivenWithItsSlope) {
    const WinchLimits lim{50.0, 600.0, 1.0, 0.2};
    const double slope = 0.05, h = 0.5;  // 0 -> 0.5 m/s in 10 s
    double rate = 0.0, length = 100.0, held = 0.0;
    for (int k = 0; k < 20; ++k) {
        const double t0 = k * h, command = slope * t0;
        const WinchStep s = plan_winch_step(command, rate, length, h, lim, slope);
        for (int i = 0; i <= 8; ++i) {
            const double tau = h * i / 8.0;
            ASSERT_NEAR(s.rate(tau), slope * (t0 + tau), 1e-12) << "step " << k << " tau " << tau;
        }
        ASSERT_NEAR(s.length(h), slope * ((t0 + h) * (t0 + h) - t0 * t0) / 2.0, 1e-12);
        length += s.length(h);
        rate = s.rate1;
        const WinchStep staircase = plan_winch_step(command, held, length, h, lim);
        held = staircase.rate1;
        if (k > 0) {
            EXPECT_GT(std::fabs(staircase.rate(0.25 * h) - slope * (t0 + 0.25 * h)), 1e-3);
        }
    }
    EXPECT_NEAR(length, 100.0 + slope * 100.0 / 2.0, 1e-9);
}

// A drum behind the command catches up at +-A, then follows the command's slope; the rate stays
// continuous and never changes faster than A.
TEST(WinchDrum, CatchesUpWithARampAtItsAccelerationThenFollowsIt) {
    const WinchLimits lim{50.0, 600.0, 1.0, 0.2};
    const WinchStep s = plan_winch_step(0.3, 0.1, 100.0, 2.0, lim, 0.05);  // the command: 0.3 -> 0.4 m/s
    EXPECT_DOUBLE_EQ(s.rate0, 0.1);
    EXPECT_NEAR(s.rate1, 0.4, 1e-12);
    EXPECT_NEAR(s.rampTime, 0.2 / (0.2 - 0.05), 1e-12);  // closes 0.2 m/s at A - slope
    EXPECT_NEAR(s.rate(s.rampTime), 0.3 + 0.05 * s.rampTime, 1e-12);  // met the command
    for (int i = 1; i <= 40; ++i) {
        const double a = (s.rate(0.05 * i) - s.rate(0.05 * (i - 1))) / 0.05;
        EXPECT_LE(std::fabs(a), 0.2 * (1 + 1e-9));
    }
    // a slope steeper than A: the drum accelerates at A
    const WinchStep fast = plan_winch_step(0.0, 0.0, 100.0, 1.0, lim, 0.5);
    EXPECT_NEAR(fast.rate1, 0.2, 1e-12);
    EXPECT_NEAR(fast.length(1.0), 0.1, 1e-12);
}

// Without an acceleration limit the drum runs at the command, requested + slope t, within maxRate; a
// length limit in the way falls back to the rate limit over the step.
TEST(WinchDrum, WithoutAnAccelerationLimitRunsAtTheRampedCommand) {
    const WinchLimits lim{50.0, 600.0, 1.0, 0.0};
    const WinchStep s = plan_winch_step(0.2, 0.0, 100.0, 0.5, lim, 0.1);
    EXPECT_DOUBLE_EQ(s.rate(0.0), 0.2);
    EXPECT_NEAR(s.rate(0.5), 0.25, 1e-12);
    EXPECT_NEAR(s.length(0.5), 0.5 * (0.2 + 0.25) * 0.5, 1e-12);
    const WinchStep capped = plan_winch_step(0.2, 0.0, 599.95, 0.5, lim, 0.1);
    EXPECT_LE(599.95 + capped.length(0.5), 600.0 + 1e-12);
    EXPECT_GE(capped.length(0.5), 0.0);
}

// A drum at rest a round-off past its limit (the sum of a braking's steps) stays there: it neither
// hauls in nor pays out further, whatever it is asked.
TEST(WinchDrum, ADrumRestingPastALimitByRoundOffStaysThere) {
    const WinchLimits lim{95.0, 104.0, 0.8, 0.2};
    for (const double past : {1e-13, 1e-11}) {
        const WinchStep out = plan_winch_step(1.0, 0.0, 104.0 + past, 0.5, lim);
        EXPECT_EQ(out.rate1, 0.0);
        EXPECT_NEAR(out.length(0.5), 0.0, 1e-12);
        const WinchStep in = plan_winch_step(-1.0, 0.0, 95.0 - past, 0.5, lim);
        EXPECT_EQ(in.rate1, 0.0);
        EXPECT_NEAR(in.length(0.5), 0.0, 1e-12);
    }
}

// A command beyond maxRate is flagged (the simulation logs its arrival once).
TEST(WinchDrum, ACommandBeyondMaxRateIsFlagged) {
    const WinchLimits lim{50.0, 600.0, 1.0, 0.2};
    EXPECT_TRUE(plan_winch_step(1.5, 1.0, 100.0, 0.5, lim).rateLimited);
    EXPECT_TRUE(plan_winch_step(0.9, 0.9, 100.0, 0.5, lim, 0.5).rateLimited);  // 1.15 m/s at the step's end
    EXPECT_FALSE(plan_winch_step(0.9, 0.9, 100.0, 0.5, lim).rateLimited);
    EXPECT_NEAR(plan_winch_step(1.5, 1.0, 100.0, 0.5, lim).rate1, 1.0, 1e-15);
}

TEST(WinchRate, ConstantTensionPaysOutAboveTheTargetAndHaulsInBelow) {
    EXPECT_GT(constant_tension_rate(12e3, 10e3, 1e-4, 1.0), 0.0);
    EXPECT_LT(constant_tension_rate(8e3, 10e3, 1e-4, 1.0), 0.0);
    EXPECT_EQ(constant_tension_rate(10e3, 10e3, 1e-4, 1.0), 0.0);
    EXPECT_DOUBLE_EQ(constant_tension_rate(10.5e3, 10e3, 1e-4, 1.0), 0.05);
    EXPECT_EQ(constant_tension_rate(1e6, 10e3, 1e-4, 1.0), 1.0);
    EXPECT_EQ(constant_tension_rate(0.0, 10e3, 1e-4, 1.0), -1.0);
}

// A tow at 2 kn with the winch driven back and forth at random rates (a fixed sequence) through
// many splits and merges: the deployed unstretched length (the integral of the rate), the sum of
// the element lengths and the mass they carry agree to round-off at every communication point.
TEST(WinchLine, MassIsConservedThroughSplitsAndMerges) {
    UCParams p;
    uc_params_default(&p);
    p.length = 100.0;
    p.nElements = 7;
    p.bottomEnd = UC_BOTTOM_TOWED_BODY;
    p.bodyMass = 400.0;
    p.bodyVolume = 0.1;
    p.bodyCdA = 0.3;
    p.winchMode = UC_WINCH_RATE;
    p.winchMinLength = 40.0;
    p.winchMaxLength = 250.0;
    p.winchMaxRate = 2.0;
    p.winchMaxAcceleration = 0.0;  // the rate the test integrates is the drum's (no ramp)
    CableSimulation sim(p);
    UCInputs in{};
    const double V = 1852.0 / 3600.0 * 2.0, h = 0.5;
    in.towVelocity[0] = V;
    std::string error;
    ASSERT_TRUE(sim.initialize(0.0, in, error)) << error;
    std::uint64_t seed = 12345;
    double integral = p.length;
    int fewest = sim.model().n_elements(), most = fewest;
    for (int k = 0; k < 600; ++k) {
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        const double u = static_cast<double>(seed >> 11) / 9007199254740992.0;  // [0, 1)
        in.winchRate = k < 200 ? 1.5 * u - 0.1 : 0.1 - 1.5 * u;  // mostly out, then mostly in to the limit
        in.tow[0] = V * sim.time();
        const double before = sim.outputs().unstretchedLength;
        ASSERT_TRUE(sim.step(sim.time(), h, in, error)) << error;
        const double rate = std::clamp(in.winchRate, -2.0, 2.0);
        integral += std::clamp(before + rate * h, 40.0, 250.0) - before;
        const CableModel& m = sim.model();
        double sum = 0.0, mass = 0.0;
        for (int e = 0; e < m.n_elements(); ++e) {
            sum += m.element_length(e);
            mass += m.element_section(e).fluid.massPerLength * m.element_length(e);
        }
        const double L = sim.outputs().unstretchedLength;
        ASSERT_NEAR(L, integral, 1e-9) << "step " << k;
        ASSERT_NEAR(sum, L, 1e-9) << "step " << k;
        ASSERT_NEAR(mass, p.massPerLength * L, 1e-9 * p.massPerLength) << "step " << k;
        fewest = std::min(fewest, m.n_elements());
        most = std::max(most, m.n_elements());
    }
    EXPECT_GE(most, 11);   // splits happened (7 elements of 14.3 m at the start)
    EXPECT_LE(fewest, 4);  // and merges
}

}  // namespace
}  // namespace uc
