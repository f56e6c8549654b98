// Rods on free and pinned bodies (src/system/body_rods.cpp, docs/lines.md "Rods"): the part of a rod under
// water, its buoyancy at the centroid of the water it displaces (against a brute-force integral over its
// section), its added mass as it translates and turns, and what the deck makes of rods on a free body and of a
// rod pinned to one.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "deck/line_file.h"
#include "system/body_rods.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

uc::MooringRod rod(double L, double d) {
    uc::MooringRod r;
    r.b[2] = L;  // along the body's z axis from its reference point
    r.diameter = d;
    return r;
}

uc::Mat3 pitch(double p) {  // Ry(p)
    uc::Mat3 R;
    R << std::cos(p), 0.0, std::sin(p), 0.0, 1.0, 0.0, -std::sin(p), 0.0, std::cos(p);
    return R;
}

TEST(BodyRods, TheWetPartIsTheRodBelowTheSurface) {
    const uc::RodWetPart all = uc::rod_wet_part(uc::Vec3(0, 0, -10), uc::Vec3(0, 0, -2));
    EXPECT_EQ(all.fraction, 1.0);
    EXPECT_EQ(all.wet_ends(), 2);
    EXPECT_DOUBLE_EQ(all.centre.z(), -6.0);
    const uc::RodWetPart none = uc::rod_wet_part(uc::Vec3(0, 0, 1), uc::Vec3(0, 0, 3));
    EXPECT_EQ(none.fraction, 0.0);
    EXPECT_EQ(none.wet_ends(), 0);
    // end B down: 3 m of its 4 m under water, from s = 1 to 4 along A -> B
    const uc::RodWetPart part = uc::rod_wet_part(uc::Vec3(0, 0, 1), uc::Vec3(0, 0, -3));
    EXPECT_DOUBLE_EQ(part.fraction, 0.75);
    EXPECT_TRUE(part.wetB && !part.wetA);
    EXPECT_DOUBLE_EQ(part.s0, 1.0);
    EXPECT_DOUBLE_EQ(part.s1, 4.0);
    EXPECT_DOUBLE_EQ(part.centre.z(), -1.5);
}

TEST(BodyRods, AnUprightRodThroughTheSurfaceFloatsOnItsDraft) {
    // 12 m from the body's reference point 8 m down: 8 m of it wet, buoyancy rho g A 8 m at 4 m depth
    const double rho = 1025.0, g = 9.80665, d = 3.0, A = kPi * d * d / 4;
    uc::RodWater water;
    water.rho = rho;
    water.g = g;
    uc::Vec3 force = uc::Vec3::Zero(), moment = uc::Vec3::Zero();
    uc::add_rod_loads(rod(12.0, d), uc::Vec3(0, 0, -8), uc::Mat3::Identity(), uc::Vec3::Zero(), uc::Vec3::Zero(),
                      water, force, moment);
    EXPECT_NEAR(force.z(), rho * g * A * 8.0, 1e-9 * force.z());
    EXPECT_NEAR(force.head<2>().norm(), 0.0, 1e-9);
    EXPECT_NEAR(moment.norm(), 0.0, 1e-6);
    // in the air: nothing
    force.setZero();
    uc::add_rod_loads(rod(12.0, d), uc::Vec3(0, 0, 1), uc::Mat3::Identity(), uc::Vec3::Zero(), uc::Vec3::Zero(), water,
                      force, moment);
    EXPECT_EQ(force.norm(), 0.0);
}

TEST(BodyRods, ATiltedRodsBuoyancyActsAtTheCentroidOfTheWaterItDisplaces) {
    // a rod 10 m x 2 m from the reference point 6 m down, pitched by 20 deg: the surface cuts its side slanted
    // (tan 20 deg x 1 m < the ends' distances). Its displaced volume and that volume's moment about the
    // reference point, integrated over its section on a 600 x 600 grid, against the closed form.
    const double rho = 1025.0, g = 9.80665, d = 2.0, L = 10.0, p = 20.0 * kPi / 180.0;
    const uc::Vec3 x(0.5, 0.0, -6.0);
    const uc::Mat3 R = pitch(p);
    uc::RodWater water;
    water.rho = rho;
    water.g = g;
    uc::Vec3 force = uc::Vec3::Zero(), moment = uc::Vec3::Zero();
    uc::add_rod_loads(rod(L, d), x, R, uc::Vec3::Zero(), uc::Vec3::Zero(), water, force, moment);
    const uc::Vec3 t = R.col(2), n1 = R.col(0), n2 = R.col(1);
    const int N = 600;
    double volume = 0.0;
    uc::Vec3 first = uc::Vec3::Zero();  // the integral of (position - x) over the displaced water
    for (int i = 0; i < N; ++i) {
        for (int j = 0; j < N; ++j) {
            const double e1 = -0.5 * d + (i + 0.5) * d / N, e2 = -0.5 * d + (j + 0.5) * d / N;
            if (e1 * e1 + e2 * e2 > 0.25 * d * d) continue;
            const uc::Vec3 foot = x + e1 * n1 + e2 * n2;  // on end A's face
            const double wet = std::clamp(-foot.z() / t.z(), 0.0, L), dA = (d / N) * (d / N);
            volume += wet * dA;
            first += (foot - x + 0.5 * wet * t) * wet * dA;
        }
    }
    const double B = rho * g * volume;
    EXPECT_NEAR(force.z(), B, 2e-4 * B);
    EXPECT_NEAR(force.x(), 0.0, 1e-9 * B);
    const uc::Vec3 expected = (rho * g * first).cross(uc::Vec3::UnitZ());
    EXPECT_NEAR(moment.y(), expected.y(), 1e-3 * std::abs(expected.y())) << moment.transpose() << " / " << expected.transpose();
    EXPECT_NEAR(moment.x(), 0.0, 1e-6 * std::abs(expected.y()));
    // the waterplane's share: without the cut's slant (the centroid on the axis) the moment is this much smaller
    const double wet = -x.z() / std::cos(p), axisOnly = rho * g * kPi * d * d / 4 * wet * (0.5 * wet * std::sin(p));
    EXPECT_GT(std::abs(moment.y() - axisOnly), 0.05 * std::abs(axisOnly));
}

TEST(BodyRods, TheAddedMassOfTheWetPartFollowsItsDraftAndItsTurning) {
    // upright, 8 m of 12 m wet: heave moves only the wet end's CaEnd rho pi d^3 / 12; surge Ca rho A 8 m; a turn
    // about y at alpha moves the wet part's water by Ca rho A alpha (the integral of r^2 over 0..8 m)
    const double rho = 1025.0, d = 3.0, A = kPi * d * d / 4;
    uc::MooringRod r = rod(12.0, d);
    r.Ca = 0.8;
    r.CaEnd = 0.6;
    const uc::Vec3 x(0, 0, -8);
    uc::Vec3 force = uc::Vec3::Zero(), moment = uc::Vec3::Zero();
    uc::add_rod_inertia(r, x, uc::Mat3::Identity(), uc::Vec3(0, 0, 1), uc::Vec3::Zero(), rho, force, moment);
    EXPECT_NEAR(force.z(), -0.6 * rho * kPi * d * d * d / 12, 1e-9);
    force.setZero();
    uc::add_rod_inertia(r, x, uc::Mat3::Identity(), uc::Vec3(1, 0, 0), uc::Vec3::Zero(), rho, force, moment);
    EXPECT_NEAR(force.x(), -0.8 * rho * A * 8.0, 1e-8);
    force.setZero();
    moment.setZero();
    uc::add_rod_inertia(r, x, uc::Mat3::Identity(), uc::Vec3::Zero(), uc::Vec3(0, 2, 0), rho, force, moment);
    EXPECT_NEAR(moment.y(), -0.8 * rho * A * 2.0 * 512.0 / 3.0, 1e-6);
    EXPECT_NEAR(force.x(), -0.8 * rho * A * 2.0 * 32.0, 1e-7);  // the wet part's water moved at 2 r
}

const char* const kSpar = R"(--- MoorDyn Input File ---
a spar: a rod through the waterline on a free body, a rod pinned to it
---------------------- LINE TYPES ----
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
pendant 0.05 10 1e7 0 0 0 0 0 0
---------------------- ROD TYPES ----
TypeName Diam Mass/m Cd Ca CdEnd CaEnd
(name) (m) (kg/m) (-) (-) (-) (-)
can 6 1000 0.6 1.0 1.2 1.0
---------------------- BODIES ----
ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca
(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)
1 Free 0 0 -7 0 0 0 2e5 0 1e8 0 0 0
---------------------- RODS ----
ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs
(#) (name) (#/key) (m) (m) (m) (m) (m) (m) (-) (-)
1 can Body1 0 0 0 0 0 18 6 -
2 can Body1Pinned 4 0 0 4 0 12 4 -
---------------------- POINTS ----
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Body1 0 0 0 0 0 0 0
2 Free 0 0 -12 0 0 0 0
---------------------- LINES ----
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1 pendant 1 2 5 4 -
---------------------- OPTIONS ----
100 WtrDpth
------------------------- need this line ----
)";

TEST(BodyRods, ARodThroughTheWaterlineOnAFreeBodyAndARodPinnedToItAreRead) {
    uc::MooringDeck deck;
    std::string error;
    ASSERT_TRUE(uc::read_mooring_deck(kSpar, 0, deck, error)) << error;
    ASSERT_EQ(deck.nodes.size(), 2u);
    const uc::MooringNode& b = deck.nodes[0];
    // rod 1's mass at 9 m up its axis: the centre of gravity moved there, the inertia recombined about it
    const double m = 18000.0, M = 2e5 + m, z = m * 9.0 / M, d = 6.0;
    EXPECT_DOUBLE_EQ(b.point.mass, M);
    EXPECT_NEAR(b.cg[2], z, 1e-12);
    EXPECT_EQ(b.cb[2], 0.0);  // its own buoyancy (none here) where the deck put its centre of gravity
    const double across = 1e8 + 2e5 * z * z + m * (18.0 * 18.0 / 12 + d * d / 16) + m * (9.0 - z) * (9.0 - z);
    EXPECT_NEAR(b.inertia[0], across, 1e-9 * across);
    EXPECT_NEAR(b.inertia[2], 1e8 + m * d * d / 8, 1e-6);
    EXPECT_EQ(b.point.volume, 0.0);  // the rod's buoyancy, drag and added mass are its own
    EXPECT_EQ(b.CdA[1], 0.0);
    ASSERT_EQ(b.rods.size(), 1u);
    EXPECT_EQ(b.rods[0].b[2], 18.0);
    EXPECT_EQ(b.rods[0].CdEnd, 1.2);
    // rod 2 pinned to the free body: a pinned body whose pin is the free body's point (4, 0, 0)
    const uc::MooringNode& p = deck.nodes[1];
    EXPECT_TRUE(p.pinned);
    EXPECT_EQ(p.pin.kind, uc::MooringEnd::Kind::Node);
    EXPECT_EQ(p.pin.node, 0);
    EXPECT_EQ(p.pin.position[0], 4.0);
    ASSERT_EQ(p.rods.size(), 1u);
    EXPECT_EQ(p.rods[0].b[0], 12.0);  // along its x axis from its pin
    EXPECT_EQ(p.point.volume, 0.0);
}

}  // namespace
