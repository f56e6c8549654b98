// Streaming rainflow counting against hand-counted histories and against an independent offline
// count (the three-point algorithm of ASTM E1049-85, section 5.4.4, written out below).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <type_traits>
#include <utility>
#include <vector>

#include "line/rainflow.h"

namespace {

using uc::RainflowCounter;
using uc::SNCurve;

// m = 1 and K = 1 with area 1e-6 m2: the damage of a cycle is its range in N, so damages are sums
// of ranges and can be checked by hand.
SNCurve linear_curve() {
    SNCurve c;
    c.m = 1.0;
    c.logK = 0.0;
    c.area = 1e-6;
    return c;
}

double stream(const std::vector<double>& history, const SNCurve& curve) {
    RainflowCounter counter;
    for (double x : history) counter.add(x, curve);
    return counter.damage(curve);
}

// ASTM E1049 three-point rainflow: (range, count) with count 1 or 0.5.
std::vector<std::pair<double, double>> astm_cycles(const std::vector<double>& history) {
    std::vector<double> reversals;
    for (double x : history) {
        if (!reversals.empty() && x == reversals.back()) continue;
        if (reversals.size() >= 2) {
            const double a = reversals[reversals.size() - 2], b = reversals.back();
            if ((b - a) * (x - b) > 0.0) {  // same direction: b was no reversal
                reversals.back() = x;
                continue;
            }
        }
        reversals.push_back(x);
    }
    std::vector<std::pair<double, double>> cycles;
    std::vector<double> stack;
    for (double point : reversals) {
        stack.push_back(point);
        while (stack.size() >= 3) {
            const size_t n = stack.size();
            const double X = std::fabs(stack[n - 1] - stack[n - 2]);
            const double Y = std::fabs(stack[n - 2] - stack[n - 3]);
            if (X < Y) break;
            if (n == 3) {  // Y contains the starting point: a half cycle, discard the start
                cycles.emplace_back(Y, 0.5);
                stack.erase(stack.begin());
            } else {
                cycles.emplace_back(Y, 1.0);
                stack.erase(stack.end() - 3, stack.end() - 1);
            }
        }
    }
    for (size_t k = 1; k < stack.size(); ++k) cycles.emplace_back(std::fabs(stack[k] - stack[k - 1]), 0.5);
    return cycles;
}

double astm_damage(const std::vector<double>& history, const SNCurve& curve) {
    double d = 0.0;
    for (const auto& [range, count] : astm_cycles(history)) d += count * curve.cycle_damage(range);
    return d;
}

TEST(Rainflow, NestedCycleIsClosedAndTheRestIsHalfCycles) {
    // 0 -> 10 -> 5 -> 20: the 10-5 leg is a closed cycle of range 5; the residue 0 -> 20 a half cycle.
    EXPECT_DOUBLE_EQ(stream({0, 10, 5, 20}, linear_curve()), 5.0 + 0.5 * 20.0);
}

TEST(Rainflow, MonotoneHistoryIsOneHalfCycle) {
    EXPECT_DOUBLE_EQ(stream({1, 2, 3, 4, 7}, linear_curve()), 0.5 * 6.0);
}

TEST(Rainflow, RepeatedFullCyclesCountOnceEach) {
    // 0 10 0 10 0 10 0: ASTM gives half cycles 10 at both ends and full cycles in between: total
    // damage of three full cycles of range 10.
    std::vector<double> h{0, 10, 0, 10, 0, 10, 0};
    EXPECT_DOUBLE_EQ(stream(h, linear_curve()), 30.0);
    EXPECT_DOUBLE_EQ(astm_damage(h, linear_curve()), 30.0);
}

TEST(Rainflow, AstmExampleOfTheStandard) {
    // ASTM E1049 Fig. 6: -2 1 -3 5 -1 3 -4 4 -2 gives ranges 3 (0.5), 4 (1.5), 6 (0.5), 8 (1.0), 9 (0.5).
    std::vector<double> h{-2, 1, -3, 5, -1, 3, -4, 4, -2};
    const double expected = 0.5 * 3 + 1.5 * 4 + 0.5 * 6 + 1.0 * 8 + 0.5 * 9;
    EXPECT_DOUBLE_EQ(astm_damage(h, linear_curve()), expected);
    EXPECT_DOUBLE_EQ(stream(h, linear_curve()), expected);
}

TEST(Rainflow, StreamingEqualsOfflineCountAfterEverySampleOfRandomHistories) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> noise(0.0, 1.0);
    SNCurve curve;  // m = 3: a non-linear curve, so equal damage means equal cycles, not equal sums
    curve.area = 1e-3;
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<double> history;
        RainflowCounter counter;
        double x = 0.0;
        for (int k = 0; k < 400; ++k) {
            x = 0.7 * x + noise(rng) * 1e4 + (k % 50 == 0 ? 5e4 : 0.0);
            history.push_back(x);
            counter.add(x, curve);
            const double offline = astm_damage(history, curve);
            ASSERT_NEAR(counter.damage(curve), offline, 1e-12 * (1.0 + offline)) << "trial " << trial << " sample " << k;
        }
    }
}

TEST(Rainflow, CopyOfTheStateContinuesBitForBit) {
    SNCurve curve;
    curve.area = 1e-3;
    RainflowCounter a;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1e5);
    for (int k = 0; k < 300; ++k) a.add(u(rng), curve);
    RainflowCounter b = a;  // what FMU state save/restore does
    for (int k = 0; k < 300; ++k) {
        const double v = u(rng);
        a.add(v, curve);
        b.add(v, curve);
    }
    EXPECT_EQ(a.damage(curve), b.damage(curve));
}

TEST(Rainflow, GrowingAmplitudeBeyondTheCapacityKeepsCountingWithoutOverflow) {
    // An ever-growing oscillation never closes a cycle: the residue grows by one turning point per
    // reversal, past the capacity; the oldest ranges leave as half cycles, so the damage stays the
    // offline one exactly.
    std::vector<double> h;
    for (int k = 0; k < 3 * RainflowCounter::kCapacity; ++k) h.push_back((k % 2 ? 1.0 : -1.0) * (k + 1));
    EXPECT_DOUBLE_EQ(stream(h, linear_curve()), astm_damage(h, linear_curve()));
}

// Saved FMU states carry the counter's bytes, and a state saved on Linux must restore on Windows and
// back: the layout must not depend on the platform's `long` or on padding (whose bytes are
// unspecified). Fixed-width fields, no padding: the same 1064 bytes on every 64-bit platform.
TEST(RainflowState, LayoutIsFixedWidthWithoutPadding) {
    static_assert(std::is_trivially_copyable<RainflowCounter>::value, "saved by a byte copy");
    static_assert(std::is_standard_layout<RainflowCounter>::value, "offsets are meaningful");
    static_assert(std::is_same<decltype(RainflowCounter::samples), std::int64_t>::value, "8 bytes everywhere");
    static_assert(std::is_same<decltype(RainflowCounter::size), std::int32_t>::value, "4 bytes everywhere");
    static_assert(std::is_same<decltype(RainflowCounter::direction), std::int32_t>::value, "4 bytes everywhere");
    constexpr std::size_t fields = RainflowCounter::kCapacity * sizeof(double) + 3 * sizeof(double) +
                                   sizeof(std::int64_t) + 2 * sizeof(std::int32_t);
    EXPECT_EQ(sizeof(RainflowCounter), fields);
    EXPECT_EQ(fields, 1064u);
    EXPECT_EQ(offsetof(RainflowCounter, samples), 1048u);
    EXPECT_EQ(offsetof(RainflowCounter, size), 1056u);
    EXPECT_EQ(offsetof(RainflowCounter, direction), 1060u);
}

TEST(Rainflow, NoAreaMeansNoDamage) {
    SNCurve off;
    EXPECT_EQ(stream({0, 1e6, 0, 1e6}, off), 0.0);
}

}  // namespace
