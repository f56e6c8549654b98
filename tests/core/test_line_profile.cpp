// The static profile of a line without bending stiffness (multi-segment elastic catenary with point
// loads and a frictionless seabed): its geometry (ends, stretched arc length, tangents, touchdown),
// its balance of forces, the touchdown of a chain mooring solved independently, and the arch a buoy
// lifts between two touchdowns against its closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "model/line_profile.h"

using uc::LineProfile;
using Eigen::Vector3d;

namespace {

constexpr double kRigid = 1e15;  // EA of an inextensible line [N]

// Walks the curve in n chords: their summed length, the largest gap between the chord direction
// and the mean of the tangents at its ends, and the stretched length (1 + T / EA) du by the
// midpoint rule.
struct Walk {
    double length = 0.0, tangentGap = 0.0, stretched = 0.0;
};

Walk walk(const LineProfile& p, double EA, int n) {
    Walk w;
    const double L = p.length();
    Vector3d r0, t0, r1, t1;
    p.at(0.0, r0, t0);
    for (int k = 1; k <= n; ++k) {
        p.at(L * k / n, r1, t1);
        const Vector3d chord = r1 - r0;
        w.length += chord.norm();
        w.tangentGap = std::max(w.tangentGap, (chord.normalized() - (0.5 * (t0 + t1)).normalized()).norm());
        w.stretched += (L / n) * (1.0 + p.tension(L * (k - 0.5) / n) / EA);
        r0 = r1;
        t0 = t1;
    }
    return w;
}

LineProfile solved(const Vector3d& top, const Vector3d& bottom, const std::vector<LineProfile::Segment>& segments,
                   const std::vector<LineProfile::PointLoad>& points, bool seabed, double seabedZ) {
    LineProfile p;
    std::string why;
    EXPECT_TRUE(p.solve(top, bottom, segments, points, seabed, seabedZ, 0.1, &why)) << why;
    return p;
}

}  // namespace

TEST(LineProfile, HangsBetweenItsEndsWithItsStretchedLengthAndTangents) {
    const Vector3d top(10.0, -5.0, -10.0), bottom(-190.0, 40.0, -90.0);  // ends at different heights
    const double EA = 2e6;  // soft enough to stretch by about 1 %
    const LineProfile p = solved(top, bottom, {{120.0, 300.0, EA}, {180.0, 150.0, EA}}, {}, false, -1000.0);
    Vector3d r, t;
    p.at(0.0, r, t);
    EXPECT_LT((r - top).norm(), 1e-9 * p.length());
    p.at(p.length(), r, t);
    EXPECT_LT((r - bottom).norm(), 1e-9 * p.length());
    // chords of length l miss the arc by l^2 kappa^2 / 24 of it: 1e-7 at 3,000 chords; the
    // midpoint rule for the stretch is as close
    const Walk w = walk(p, EA, 3000);
    EXPECT_NEAR(w.length, w.stretched, 1e-6 * p.length());
    EXPECT_GT(w.stretched - p.length(), 1e-3 * p.length());  // it did stretch
    EXPECT_LT(w.tangentGap, 1e-5);
    EXPECT_EQ(p.grounded_length(), 0.0);
}

TEST(LineProfile, EndForcesBalanceTheWeightAndPointLoads) {
    const Vector3d top(0.0, 0.0, -5.0), bottom(-400.0, 0.0, -100.0);
    // a buoy and a clump on a chain-wire line, no seabed
    const LineProfile p = solved(top, bottom, {{200.0, 400.0, 5e8}, {250.0, 1000.0, 1e9}},
                                 {{150.0, -20000.0}, {320.0, 30000.0}}, false, -1e4);
    const double weight = 200.0 * 400.0 + 250.0 * 1000.0 - 20000.0 + 30000.0;
    const Vector3d sum = p.top_force() + p.bottom_force();
    EXPECT_NEAR(sum.x(), 0.0, 1e-9 * weight);
    EXPECT_NEAR(sum.z(), -weight, 1e-9 * weight);
    // the tangent turns at a point load: the vertical tension jumps by its weight
    Vector3d r1, t1, r2, t2;
    p.at(320.0 - 1e-9, r1, t1);
    p.at(320.0 + 1e-9, r2, t2);
    EXPECT_LT((r1 - r2).norm(), 1e-6);
    const double H = p.bottom_force().x();
    const double V1 = -t1.z() / -t1.x() * H, V2 = -t2.z() / -t2.x() * H;  // vertical tension above and below
    EXPECT_NEAR(V1 - V2, 30000.0, 1e-6 * 30000.0);
}

TEST(LineProfile, LiesOnTheSeabedUpToItsTouchdown) {
    // The chain mooring of the benchmark: fairlead 20 m below the surface, anchor on the seabed at
    // 200 m depth, 800 m away, 835 m of chain. Solved independently (the inextensible catenary by
    // bisection in double precision, outside this code): a = H / w = 1004.36 m, 627.67 m hang.
    const Vector3d top(0.0, 0.0, -20.0), bottom(-800.0, 0.0, -200.0);
    const double w = 1000.0, L = 835.0;
    const LineProfile p = solved(top, bottom, {{L, w, kRigid}}, {}, true, -200.0);
    EXPECT_NEAR(p.bottom_force().x() / w, 1004.36, 0.01);
    EXPECT_NEAR(p.touchdown(), 627.67, 0.01);
    EXPECT_NEAR(p.bottom_force().z(), 0.0, 1e-12 * w * L);  // the anchor is pulled horizontally
    Vector3d r, t;
    p.at(p.touchdown() + 50.0, r, t);  // on the seabed, pointing along it towards the anchor
    EXPECT_DOUBLE_EQ(r.z(), -200.0);
    EXPECT_LT((t - Vector3d(-1.0, 0.0, 0.0)).norm(), 1e-12);
    p.at(p.touchdown() - 1e-9, r, t);  // leaves it horizontally
    EXPECT_NEAR(r.z(), -200.0, 1e-9);
    EXPECT_LT(std::abs(t.z()), 1e-9);
    EXPECT_NEAR(p.lowest_clearance(), 0.0, 1e-9);
    // the tangent turns from the fairlead's angle to horizontal, and no further on the seabed
    const Vector3d f = p.top_force();
    EXPECT_NEAR(p.turning(L), std::atan2(-f.z(), -f.x()), 1e-12);
    EXPECT_DOUBLE_EQ(p.turning(L), p.turning(p.touchdown()));
}

TEST(LineProfile, LiftsOffAtAClumpResting) {
    // A wire with a heavy clump where it leaves the seabed: the clump's weight is shared between the
    // seabed and the hanging part, so the line lifts off at the clump, turning a corner there.
    const Vector3d top(0.0, 0.0, -10.0), bottom(-450.0, 0.0, -150.0);
    const double w = 260.0, clump = 25000.0;
    const LineProfile p = solved(top, bottom, {{500.0, w, 5.5e8}}, {{240.0, clump}}, true, -150.0);
    EXPECT_NEAR(p.touchdown(), 240.0, 1e-9);
    Vector3d r, above, below;
    p.at(240.0 - 1e-9, r, above);
    p.at(240.0 + 1e-9, r, below);
    EXPECT_LT(std::abs(below.z()), 1e-12);  // resting beyond it
    EXPECT_GT(std::abs(above.z()), 0.05);   // rising before it
    const double V = -above.z() / -above.x() * p.bottom_force().x();
    EXPECT_GT(V, 0.0);
    EXPECT_LT(V, clump);  // part of the clump rests on the seabed
}

TEST(LineProfile, RefusesShapesItCannotHave) {
    LineProfile p;
    std::string why;
    // the ends on one vertical
    EXPECT_FALSE(p.solve(Vector3d(0, 0, 0), Vector3d(0, 0, -50), {{80.0, 100.0, 1e8}}, {}, false, 0.0, 0.1, &why));
    // longer than the way down to the seabed and across it: no tension, no one shape
    EXPECT_FALSE(p.solve(Vector3d(0, 0, -10), Vector3d(-100, 0, -100), {{200.0, 100.0, 1e8}}, {}, true, -100.0, 0.1, &why));
    EXPECT_EQ(why, "longer than the way down and across");
    // a lazy wave longer than that (BodiesAndRods' cable: 200 m of cable, 50 m buoyant, 50 m of cable from an
    // anchor 193 m across and 61.5 m down) is held up by its buoyant part: a shape with tension, balanced
    const std::vector<LineProfile::Segment> lazy = {{50.0, 150.5, 7.51e8}, {50.0, -141.2, 7.51e8}, {200.0, 150.5, 7.51e8}};
    ASSERT_TRUE(p.solve(Vector3d(-7.0566, 0, -8.4687), Vector3d(-200, 0, -70), lazy, {}, true, -70.0, 0.175, &why)) << why;
    const double weight = 50.0 * 150.5 - 50.0 * 141.2 + 200.0 * 150.5;
    EXPECT_NEAR((p.top_force() + p.bottom_force()).x(), 0.0, 1e-6 * weight);
    EXPECT_GT(p.top_force().norm(), 0.0);
    // the same line without the seabed hangs free below it
    EXPECT_TRUE(p.solve(Vector3d(0, 0, -10), Vector3d(-100, 0, -100), {{200.0, 100.0, 1e8}}, {}, false, -100.0, 0.1));
    EXPECT_LT(p.lowest_clearance(), 0.0);
    // taut: shorter than the chord, it stretches (so light that it sags by 2 mm)
    ASSERT_TRUE(p.solve(Vector3d(0, 0, 0), Vector3d(-100, 0, -50), {{0.999 * std::hypot(100.0, 50.0), 1e-3, 1e6}},
                        {}, false, -1e4, 0.1));
    EXPECT_NEAR(p.tension(50.0), 1e6 * (1.0 / 0.999 - 1.0), 0.1);
}

TEST(LineProfile, ABuoyOnTheGroundedPartLiftsTheLineAndItTouchesDownAgain) {
    // A wire rope (44.03 kg/m, displacement diameter 0.1076 m, EA 8.08e8 N) of 578.9 m from a
    // fairlead 24.35 m deep to an anchor 421.8 m away on a 234 m seabed, with a buoy (1680 kg,
    // 5.464 m3) at s = 395.3 m: without it some 300 m would rest; the buoy lifts the line between
    // two touchdowns. MoorPy (a system of two lines and the buoy as a free point, rigid seabed)
    // gives 87,528.5 N at the fairlead and 16,158.7 N at the anchor, 213.3 m grounded in all.
    const double rho = 1025.0, g = 9.81, d = 0.10762016294747695;
    const double w = (44.02761599378772 - rho * 3.14159265358979 * d * d / 4.0) * g;
    const double buoy = (1680.1347326032826 - rho * 5.463852788953765) * g;
    const Vector3d top(0.0, 0.0, -24.34589837580009), bottom(-421.78162345848614, 0.0, -233.99777534568773);
    const LineProfile p = solved(top, bottom, {{578.9028840088951, w, 807685908.3689377}}, {{395.33852500261077, buoy}},
                                 true, -233.99777534568773);
    // MoorPy's own tolerance: its points balance to 1e-5 of the tension
    EXPECT_NEAR(p.top_force().norm(), 87528.54567174417, 1e-4 * 87528.5);
    EXPECT_NEAR(p.bottom_force().norm(), 16158.669104640067, 1e-4 * 16158.7);
    EXPECT_NEAR(p.grounded_length(), 213.2543899783769, 1e-3 * 578.9);
    EXPECT_GT(p.lowest_clearance(), -1e-9 * 578.9);  // nowhere below the seabed
    EXPECT_EQ(p.contacts().size(), 3u);              // the touchdown, the lift-off, the touchdown
}

namespace {

// A line whose buoy lifts an arch between two touchdowns, with the arch inside one section of weight
// w per length: the profile against MoorPy (its points balance to 1e-5 of the tension) and against
// what such a line must be, each piece between contacts checked by its own balance of forces.
struct ArchLine {
    Vector3d top, bottom;  // the anchor on the seabed, in -x of the fairlead
    std::vector<LineProfile::Segment> segments;
    double buoyS, lift;    // arc length from the top [m], net lift [N]
    double fairlead, anchor, grounded;  // MoorPy
};

// the section at arc length s from the top
const LineProfile::Segment& section_at(const ArchLine& a, double s) {
    double start = 0.0;
    for (const LineProfile::Segment& seg : a.segments) {
        if (s < start + seg.length) return seg;
        start += seg.length;
    }
    return a.segments.back();
}

// the weight of the line between arc lengths s0 < s1 from the top
double weight_between(const ArchLine& a, double s0, double s1) {
    double start = 0.0, W = 0.0;
    for (const LineProfile::Segment& seg : a.segments) {
        W += seg.weight * std::max(0.0, std::min(s1, start + seg.length) - std::max(s0, start));
        start += seg.length;
    }
    return W;
}

void check_arch(const ArchLine& a) {
    const double seabed = a.bottom.z();
    const LineProfile p = solved(a.top, a.bottom, a.segments, {{a.buoyS, -a.lift}}, true, seabed);
    const double L = p.length();
    EXPECT_NEAR(p.top_force().norm(), a.fairlead, 1e-4 * a.fairlead);
    EXPECT_NEAR(p.bottom_force().norm(), a.anchor, 1e-4 * a.anchor);
    EXPECT_NEAR(p.grounded_length(), a.grounded, 1e-4 * L);

    // the end conditions to round-off (Newton's method stops at 1e-11 of the length)
    Vector3d r, t;
    p.at(0.0, r, t);
    EXPECT_LT((r - a.top).norm(), 1e-10 * L);
    p.at(L, r, t);
    EXPECT_LT((r - a.bottom).norm(), 1e-10 * L);

    // From the top: the line hangs down to a touchdown, rests, lifts off into the buoy's arch, lands
    // again and rests to the anchor. With no seabed under the arch, its ends horizontal (V = 0) and one
    // weight per length, the arch carries exactly the buoy's lift, half on either side of it: an
    // elastic catenary of parameter a = H / w whose closed form gives its length, span and height.
    const std::vector<double> c = p.contacts();
    ASSERT_EQ(c.size(), 3u);
    const double H = p.bottom_force().x(), w = section_at(a, a.buoyS).weight, EA = section_at(a, a.buoyS).EA;
    ASSERT_GT(H, 0.0);
    ASSERT_EQ(&section_at(a, c[1]), &section_at(a, c[2]));  // the arch inside one section
    const double cat = H / w, half = 0.5 * a.lift / w;  // the arch's half length
    EXPECT_NEAR(c[2] - c[1], 2.0 * half, 1e-9 * L);
    EXPECT_NEAR(a.buoyS - c[1], half, 1e-9 * L);
    Vector3d lo, hi, buoy;
    p.at(c[1], hi, t);
    p.at(c[2], lo, t);
    p.at(a.buoyS, buoy, t);
    const double span = 2.0 * (cat * std::asinh(half / cat) + H * half / EA);
    const double height = cat * (std::sqrt(1.0 + std::pow(half / cat, 2)) - 1.0) + w * half * half / (2.0 * EA);
    EXPECT_NEAR((hi - lo).norm(), span, 1e-9 * L);
    EXPECT_NEAR(buoy.z() - seabed, height, 1e-9 * L);
    // the hanging part above the first touchdown carries its own weight, the rest of the line pulls
    // horizontally on it: the force at the top is (-H, -W(0, c0))
    const double total = weight_between(a, 0.0, L);
    EXPECT_NEAR(-p.top_force().z(), weight_between(a, 0.0, c[0]), 1e-9 * total);
    EXPECT_NEAR(p.top_force().x(), -H, 1e-12 * H);
    // the anchor is pulled horizontally; the seabed carries the weight of the resting parts (a
    // non-negative reaction everywhere: the buoy is not among them, and every contact is tangential,
    // so no point of the line pulls on the seabed or presses on it with a point force)
    EXPECT_NEAR(p.bottom_force().z(), 0.0, 1e-9 * total);
    EXPECT_NEAR(total - a.lift + p.top_force().z(), weight_between(a, c[0], c[1]) + weight_between(a, c[2], L),
                1e-9 * total);
    EXPECT_NEAR(p.grounded_length(), (L - c[2]) + (c[1] - c[0]), 1e-9 * L);
    EXPECT_GT(a.buoyS, c[1]);
    EXPECT_LT(a.buoyS, c[2]);
    for (double s : c) {
        p.at(s, r, t);
        EXPECT_NEAR(r.z(), seabed, 1e-9 * L);
        EXPECT_LT(std::abs(t.z()), 1e-9);
    }
    // nowhere below the seabed
    EXPECT_GT(p.lowest_clearance(), -1e-9 * L);
    double lowest = INFINITY;
    for (int k = 0; k <= 4000; ++k) {
        p.at(L * k / 4000.0, r, t);
        lowest = std::min(lowest, r.z() - seabed);
    }
    EXPECT_GT(lowest, -1e-9 * L);
}

}  // namespace

TEST(LineProfile, ABuoyLiftsAnArchOfAVerySlackUniformLineBetweenTwoTouchdowns) {
    // A wire rope of 128.05 m, 23 % longer than the chord, from a fairlead 3 m deep to an anchor
    // 99.5 m away on a 33.5 m seabed; a buoy lifting 2,460 N at s = 102.88 m sits where the line
    // would rest without it (line 71 of the statics benchmark). MoorPy (two lines and the buoy as a
    // free point, rigid seabed): 6,569.91 N at the fairlead, 526.84 N at the anchor, 82.52 m grounded.
    check_arch({Vector3d(0.0, 0.0, -3.0), Vector3d(-99.51402445951304, 0.0, -33.54743067882633),
                {{128.05272891081387, 197.82729738220632, 469336853.5510821}},
                102.87997527160142, 2459.674633295815,
                6569.913547768416, 526.8435826872867, 82.51588769050176});
}

TEST(LineProfile, ABuoyLiftsAnArchOfAVerySlackTwoSectionLineRestingAcrossItsJoint) {
    // Wire rope (49.0 m, 79.8 N/m) over polyester (57.9 m, 23.3 N/m), 24 % longer than the chord,
    // a buoy lifting 367 N at s = 86.72 m in the polyester (line 295 of the statics benchmark): the
    // line rests across the joint, and again from the arch to the anchor. MoorPy: 3,216.41 N at the
    // fairlead, 315.104 N at the anchor, 51.04 m grounded (the joint resting on the seabed).
    check_arch({Vector3d(0.0, 0.0, -5.9191992955538515), Vector3d(-77.92721886310859, 0.0, -42.26963720961942),
                {{49.02183626323599, 79.81561728654988, 189359159.1110524},
                 {57.88751308075679, 23.27591639057052, 67918603.01226915}},
                86.71596898400803, 366.85683593190504,
                3216.409155744423, 315.10357558075725, 51.04398590597529});
}

// A sloped seabed: in the plane of the ends it rises towards the fairlead by tan(beta) per metre
// across. A chain of 430 / 470 m (1,000 N/m, EA 5e8 N) from a fairlead 5 m deep to an anchor 400 m
// away on the seabed 100 m deep. MoorPy's catenary with the seabed's angle (alpha = atan(tan beta),
// frictionless, CB = 0, Tol 1e-10): anchor downslope (tan beta 0.1, 430 m) 13,934.9086 N across and
// 1,393.4909 N up at the anchor (along the slope), 47,252.5411 / 98,217.1666 N at the fairlead,
// 336.508 m on the seabed; anchor upslope (tan beta -0.08, 470 m) 70,682.3835 / -5,654.5907 N and
// 46,278.7160 / 159,299.5647 N, 306.998 m on the seabed.
TEST(LineProfile, RestsOnASlopeAsMoorPysInclinedCatenary) {
    struct Case {
        double tanBeta, length, anchorH, anchorV, topH, topV, grounded;
    };
    for (const Case& c : {Case{0.1, 430.0, 13934.908620037344, 1393.4908620037345, 47252.541051135784,
                               98217.16655101936, 336.50808755409423},
                          Case{-0.08, 470.0, 70682.38353033441, -5654.590682426754, 46278.715964472685,
                               159299.56474430172, 306.9981379785405}}) {
        const Vector3d top(0.0, 0.0, -5.0), bottom(-400.0, 0.0, -100.0);
        LineProfile p;
        // the seabed's height grows along +x (towards the fairlead) by tan(beta)
        p.set_seabed_gradient(Eigen::Vector2d(c.tanBeta, 0.0));
        std::string why;
        ASSERT_TRUE(p.solve(top, bottom, {{c.length, 1000.0, 5e8}}, {}, true, -100.0, 0.1, &why)) << why;
        const double scale = c.topV;
        EXPECT_NEAR(p.bottom_force().x(), c.anchorH, 1e-7 * scale) << c.tanBeta;
        EXPECT_NEAR(p.bottom_force().z(), c.anchorV, 1e-7 * scale) << c.tanBeta;
        EXPECT_NEAR(-p.top_force().x(), c.topH, 1e-7 * scale) << c.tanBeta;
        EXPECT_NEAR(-p.top_force().z(), c.topV, 1e-7 * scale) << c.tanBeta;
        EXPECT_NEAR(p.grounded_length(), c.grounded, 1e-6 * c.length) << c.tanBeta;
        // the grounded part lies on the slope, and the tension along it grows by w sin(beta) per metre
        const double sinBeta = c.tanBeta / std::sqrt(1.0 + c.tanBeta * c.tanBeta);
        Vector3d r, t;
        const double s = c.length - 0.5 * c.grounded;  // from the fairlead: the middle of the resting part
        p.at(s, r, t);
        EXPECT_NEAR(r.z(), -100.0 + c.tanBeta * (r.x() + 400.0), 1e-9 * c.length);
        EXPECT_NEAR(p.tension(s - 1.0) - p.tension(s + 1.0), 2.0 * 1000.0 * sinBeta, 1e-6 * scale);
        EXPECT_GT(p.lowest_clearance(), -1e-9 * c.length);
    }
}

TEST(LineProfile, ASlopeAcrossTheLinesPlaneIsTheFlatSeabedForItsProfile) {
    // The seabed tilted only across the plane of the ends (gradient along y, the line along x): in
    // the plane the seabed is flat, and the profile is the flat one number for number.
    const Vector3d top(0.0, 0.0, -5.0), bottom(-400.0, 0.0, -100.0);
    LineProfile flat, tilted;
    std::string why;
    ASSERT_TRUE(flat.solve(top, bottom, {{430.0, 1000.0, 5e8}}, {}, true, -100.0, 0.1, &why)) << why;
    tilted.set_seabed_gradient(Eigen::Vector2d(0.0, 0.2));
    ASSERT_TRUE(tilted.solve(top, bottom, {{430.0, 1000.0, 5e8}}, {}, true, -100.0, 0.1, &why)) << why;
    EXPECT_EQ(flat.top_force(), tilted.top_force());
    EXPECT_EQ(flat.bottom_force(), tilted.bottom_force());
    EXPECT_EQ(flat.grounded_length(), tilted.grounded_length());
}
