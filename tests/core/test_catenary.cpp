// The catenary that starts the static solver of moorings: its geometry (ends, arc length,
// tangents, touchdown) and the touchdown point of a chain mooring solved independently.
#include <gtest/gtest.h>

#include <cmath>

#include "catenary.h"

using uc::Catenary;
using Eigen::Vector3d;

namespace {

// Walks the curve in n chords: their summed length, and the largest gap between the chord
// direction and the mean of the tangents at its ends.
struct Walk {
    double length = 0.0, tangentGap = 0.0;
};

Walk walk(const Catenary& c, double L, int n) {
    Walk w;
    Vector3d r0, t0, r1, t1;
    c.at(0.0, r0, t0);
    for (int k = 1; k <= n; ++k) {
        c.at(L * k / n, r1, t1);
        const Vector3d chord = r1 - r0;
        w.length += chord.norm();
        w.tangentGap = std::max(w.tangentGap, (chord.normalized() - (0.5 * (t0 + t1)).normalized()).norm());
        r0 = r1;
        t0 = t1;
    }
    return w;
}

}  // namespace

TEST(Catenary, HangsBetweenItsEndsWithItsLengthAndTangents) {
    const Vector3d top(10.0, -5.0, -10.0), bottom(-190.0, 40.0, -90.0);  // ends at different heights
    const double L = 300.0;
    Catenary c;
    ASSERT_TRUE(c.solve(top, bottom, L, false, -1000.0, 1.0));
    EXPECT_EQ(c.laid_length(), 0.0);
    Vector3d r, t;
    c.at(0.0, r, t);
    EXPECT_LT((r - top).norm(), 1e-9 * L);
    c.at(L, r, t);
    EXPECT_LT((r - bottom).norm(), 1e-9 * L);
    // chords of length l miss the arc by l^2 kappa^2 / 24 of it: 1e-7 at 3,000 chords
    const Walk w = walk(c, L, 3000);
    EXPECT_NEAR(w.length, L, 1e-6 * L);
    EXPECT_LT(w.tangentGap, 1e-6);
    c.at(0.5 * L, r, t);
    EXPECT_NEAR(t.norm(), 1.0, 1e-12);
}

TEST(Catenary, LiesOnTheSeabedUpToItsTouchdown) {
    // The chain mooring of the benchmark: fairlead 20 m below the surface, anchor on the seabed at
    // 200 m depth, 800 m away, 835 m of chain. Solved independently (the same equations by
    // bisection in double precision, outside this code): a = H / w = 1004.36 m, 627.67 m hang.
    const Vector3d top(0.0, 0.0, -20.0), bottom(-800.0, 0.0, -200.0);
    const double L = 835.0;
    Catenary c;
    ASSERT_TRUE(c.solve(top, bottom, L, true, -200.0, 1.0));
    EXPECT_NEAR(c.parameter(), 1004.36, 0.01);
    EXPECT_NEAR(L - c.laid_length(), 627.67, 0.01);
    Vector3d r, t;
    c.at(L, r, t);
    EXPECT_LT((r - bottom).norm(), 1e-9 * L);
    c.at(0.0, r, t);
    EXPECT_LT((r - top).norm(), 1e-9 * L);
    const double touchdown = L - c.laid_length();
    c.at(touchdown + 50.0, r, t);  // on the seabed, pointing along it towards the anchor
    EXPECT_DOUBLE_EQ(r.z(), -200.0);
    EXPECT_LT((t - Vector3d(-1.0, 0.0, 0.0)).norm(), 1e-12);
    c.at(touchdown - 1e-9, r, t);  // leaves it horizontally
    EXPECT_NEAR(r.z(), -200.0, 1e-9);
    EXPECT_LT(std::abs(t.z()), 1e-9);
    const Walk w = walk(c, L, 8000);
    EXPECT_NEAR(w.length, L, 1e-6 * L);
    // the curvature jumps from 0 to 1 / a at the touchdown: there a chord of length l misses the
    // mean of its end tangents by up to about l / (8 a)
    EXPECT_LT(w.tangentGap, 0.25 * (L / 8000) / c.parameter());
}

TEST(Catenary, RefusesShapesItCannotHave) {
    Catenary c;
    // taut: no longer than the chord
    EXPECT_FALSE(c.solve(Vector3d(0, 0, 0), Vector3d(-100, 0, -50), std::hypot(100.0, 50.0), false, 0.0, 1.0));
    // the ends on one vertical
    EXPECT_FALSE(c.solve(Vector3d(0, 0, 0), Vector3d(0, 0, -50), 80.0, false, 0.0, 1.0));
    // longer than the way down to the seabed and across it: slack beyond any catenary
    EXPECT_FALSE(c.solve(Vector3d(0, 0, -10), Vector3d(-100, 0, -100), 200.0, true, -100.0, 1.0));
    // the same line without the seabed hangs free below it
    EXPECT_TRUE(c.solve(Vector3d(0, 0, -10), Vector3d(-100, 0, -100), 200.0, false, -100.0, 1.0));
}
