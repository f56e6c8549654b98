// Wave kinematics against the closed form of linear (Airy) theory, the portable generator, the
// JONSWAP discretization, and the Morison load's Jacobian in waves.
#include <gtest/gtest.h>

#include <cmath>

#include "api/cable_api.h"
#include "model/params.h"
#include "terms/hydrodynamics.h"
#include "terms/waves.h"

using namespace uc;

namespace {

using uc::kPi;
constexpr double g = 9.80665;

UCParams regular(double H, double T, double depth, double direction = 0.0) {
    UCParams p;
    uc_params_default(&p);
    p.wavesMode = 1;
    p.wavesHeight = H;
    p.wavesPeriod = T;
    p.waterDepth = depth;
    p.gravity = g;
    p.wavesDirection = direction;
    return p;
}

// The load's Jacobian with respect to r, r' and r_dot equals central differences (step 1e-6).
template <class Load>
void expect_jacobian_is_the_derivative(const Load& load, const Vec3& r, const Vec3& rp, const Vec3& rd, const Vec3& F,
                                        const PointLoadJacobian& J) {
    const double h = 1e-6;
    for (int c = 0; c < 3; ++c) {
        Vec3 e = Vec3::Zero();
        e[c] = h;
        const double scale = 1.0 + F.norm();
        EXPECT_LT(((load(r + e, rp, rd, nullptr) - load(r - e, rp, rd, nullptr)) / (2 * h) - J.dr.col(c)).norm(), 1e-6 * scale) << c;
        EXPECT_LT(((load(r, rp + e, rd, nullptr) - load(r, rp - e, rd, nullptr)) / (2 * h) - J.drp.col(c)).norm(), 1e-6 * scale) << c;
        EXPECT_LT(((load(r, rp, rd + e, nullptr) - load(r, rp, rd - e, nullptr)) / (2 * h) - J.drd.col(c)).norm(), 1e-6 * scale) << c;
    }
}

}  // namespace

TEST(Waves, WaveNumberSolvesTheDispersionRelation) {
    for (double depth : {5.0, 30.0, 100.0, 1000.0}) {
        for (double T : {4.0, 10.0, 20.0}) {
            const double w = 2 * kPi / T, k = wave_number(w, depth, g);
            EXPECT_NEAR(g * k * std::tanh(k * depth), w * w, 1e-13 * w * w) << depth << " " << T;
        }
    }
    EXPECT_NEAR(wave_number(2 * kPi / 8.0, 5000.0, g), std::pow(2 * kPi / 8.0, 2) / g, 1e-15);  // deep water
}

TEST(Waves, SplitMix64IsThePublishedGenerator) {
    SplitMix64 r(0);
    EXPECT_EQ(r.next(), 0xE220A8397B1DCDAFULL);  // the reference sequence of SplitMix64 from seed 0
    EXPECT_EQ(r.next(), 0x6E789E6AA1B965F4ULL);
    SplitMix64 u(12345);
    for (int i = 0; i < 1000; ++i) {
        const double x = u.uniform();
        ASSERT_TRUE(x >= 0.0 && x < 1.0);
    }
}

TEST(Waves, RegularWaveKinematicsEqualTheClosedForm) {
    // eta = H/2 cos(k (x cos b + y sin b) - w t), u = a w cosh(k(z+h))/sinh(kh) cos theta along the
    // direction of travel, w = a w sinh(k(z+h))/sinh(kh) sin theta, a = du/dt.
    for (double depth : {40.0, 2000.0}) {
        const double H = 3.0, T = 9.0, b = 0.4;
        SeaState sea;
        std::string error;
        ASSERT_TRUE(sea.build(regular(H, T, depth, b), error)) << error;
        const double w = 2 * kPi / T, k = wave_number(w, depth, g), a = H / 2;
        for (const Vec3& r : {Vec3(0, 0, -1), Vec3(13.0, -7.0, -10.0), Vec3(-40.0, 25.0, -30.0)}) {
            for (double t : {0.0, 2.3, 7.1}) {
                const double th = k * (r.x() * std::cos(b) + r.y() * std::sin(b)) - w * t;
                const double ch = std::cosh(k * (r.z() + depth)) / std::sinh(k * depth);
                const double sh = std::sinh(k * (r.z() + depth)) / std::sinh(k * depth);
                EXPECT_NEAR(sea.elevation(r.x(), r.y(), t), a * std::cos(th), 1e-12);
                Vec3 u, acc;
                sea.kinematics(r, t, u, acc, nullptr, nullptr);
                const Vec3 uExact(a * w * ch * std::cos(th) * std::cos(b), a * w * ch * std::cos(th) * std::sin(b),
                                  a * w * sh * std::sin(th));
                const Vec3 aExact(a * w * w * ch * std::sin(th) * std::cos(b), a * w * w * ch * std::sin(th) * std::sin(b),
                                  -a * w * w * sh * std::cos(th));
                EXPECT_LT((u - uExact).norm(), 1e-12) << depth;
                EXPECT_LT((acc - aExact).norm(), 1e-12) << depth;
            }
        }
    }
    SeaState crest;
    std::string error;
    ASSERT_TRUE(crest.build(regular(2.0, 8.0, 100.0), error));
    EXPECT_DOUBLE_EQ(crest.elevation(0.0, 0.0, 0.0), 1.0);  // a crest at the origin at t = 0
}

TEST(Waves, AccelerationAndGradientsAreTheDerivatives) {
    UCParams p = regular(2.0, 7.0, 60.0, 0.9);
    p.wavesMode = 2;  // an irregular sea exercises the sums
    p.wavesNComponents = 40;
    SeaState sea;
    std::string error;
    ASSERT_TRUE(sea.build(p, error)) << error;
    const Vec3 r(3.0, -2.0, -6.0);
    const double t = 11.0, h = 1e-5;
    Vec3 u, a, up, um, ap, am, dummy;
    Mat3 du, da;
    sea.kinematics(r, t, u, a, &du, &da);
    sea.kinematics(r, t + h, up, dummy, nullptr, nullptr);
    sea.kinematics(r, t - h, um, dummy, nullptr, nullptr);
    EXPECT_LT(((up - um) / (2 * h) - a).norm(), 1e-7 * (1.0 + a.norm()));
    for (int c = 0; c < 3; ++c) {
        Vec3 e = Vec3::Zero();
        e[c] = h;
        sea.kinematics(r + e, t, up, ap, nullptr, nullptr);
        sea.kinematics(r - e, t, um, am, nullptr, nullptr);
        EXPECT_LT(((up - um) / (2 * h) - du.col(c)).norm(), 1e-7 * (1.0 + du.norm())) << c;
        EXPECT_LT(((ap - am) / (2 * h) - da.col(c)).norm(), 1e-7 * (1.0 + da.norm())) << c;
    }
}

TEST(Waves, JonswapComponentsCarryTheSignificantHeightAndPeakAtTp) {
    UCParams p = regular(4.0, 10.0, 500.0);
    p.wavesMode = 2;
    p.wavesNComponents = 300;
    SeaState sea;
    std::string error;
    ASSERT_TRUE(sea.build(p, error)) << error;
    double m0 = 0.0, largest = 0.0, peak = 0.0;
    for (const WaveComponent& c : sea.components()) {
        m0 += 0.5 * c.amplitude * c.amplitude;
        if (c.amplitude > largest) largest = c.amplitude, peak = c.omega;
    }
    EXPECT_NEAR(4.0 * std::sqrt(m0), 4.0, 1e-12);                        // Hs = 4 sqrt(m0)
    EXPECT_NEAR(peak, 2 * kPi / 10.0, 2.5 * kPi / 10.0 / 300.0 + 1e-12);  // within a band of wp
    SeaState same;
    ASSERT_TRUE(same.build(p, error));
    EXPECT_EQ(same.elevation(10.0, 5.0, 33.0), sea.elevation(10.0, 5.0, 33.0));  // the seed makes the sea
    p.wavesSeed = 2;
    SeaState other;
    ASSERT_TRUE(other.build(p, error));
    EXPECT_NE(other.elevation(10.0, 5.0, 33.0), sea.elevation(10.0, 5.0, 33.0));
}

TEST(Waves, BreakingWavesAreRefusedNamingTheHeight) {
    UCParams p = regular(12.0, 6.0, 100.0);  // lambda = 56 m: H / lambda = 0.21
    char msg[400];
    EXPECT_NE(uc_params_check(&p, msg, sizeof msg), 0);
    EXPECT_NE(std::string(msg).find("waves.height"), std::string::npos) << msg;
    p.wavesHeight = 5.0;
    EXPECT_EQ(uc_params_check(&p, msg, sizeof msg), 0) << msg;
}

TEST(Waves, WavesWithoutGravityAreRefusedNamingGravity) {
    // Gravity sets the waves' length (w^2 = g k tanh(k h)): none, and the message names it, not the
    // height a zero gravity would make "too steep". Calm water needs none.
    UCParams p = regular(2.0, 8.0, 100.0);
    p.gravity = 0.0;
    char msg[400];
    EXPECT_NE(uc_params_check(&p, msg, sizeof msg), 0);
    EXPECT_NE(std::string(msg).find("gravity"), std::string::npos) << msg;
    EXPECT_EQ(std::string(msg).find("waves.height"), std::string::npos) << msg;
    p.wavesMode = 0;
    EXPECT_EQ(uc_params_check(&p, msg, sizeof msg), 0) << msg;
}

TEST(Waves, MorisonLoadJacobianInWavesMatchesFiniteDifferences) {
    UCParams prm = regular(3.0, 8.0, 80.0, 0.3);
    SeaState sea;
    std::string error;
    ASSERT_TRUE(sea.build(prm, error));
    CurrentField field;
    field.uniform = Vec3(0.4, -0.2, 0.0);
    field.sea = &sea;
    field.time = 4.2;
    FluidProps p{1025.0, g, 3.0, kPi * 0.04 * 0.04 / 4, 0.04, 1.6, 0.02, 1.0, 0.1, true};
    const Vec3 r(2.0, 1.0, -5.0), rp(0.6, 0.2, -0.8), rd(0.3, 0.1, -0.2), rdd(0.05, -0.02, 0.1);
    auto load = [&](const Vec3& rr, const Vec3& rrp, const Vec3& rrd, PointLoadJacobian* J) {
        Vec3 U, A;
        Mat3 dU, dA;
        field.flow(rr, U, dU, A, dA);
        return point_load(p, rr, rrp, rrd, rdd, U, dU, true, A, dA, J);
    };
    PointLoadJacobian J;
    const Vec3 F = load(r, rp, rd, &J);
    expect_jacobian_is_the_derivative(load, r, rp, rd, F, J);
    // The fluid inertia: the water's acceleration A pulls with rho A (1 + Can) on its normal component
    // and rho A (1 + Cat) on its tangential one (Can = 1, Cat = 0.1 here; the load F enters the
    // residual with the sign of a reaction).
    Vec3 U, A;
    Mat3 dU, dA;
    field.flow(r, U, dU, A, dA);
    const Vec3 t = rp.normalized();
    const Vec3 withWaves = point_load(p, r, rp, rd, rdd, U, dU, true, A, dA, nullptr);
    const Vec3 without = point_load(p, r, rp, rd, rdd, U, dU, false, A, dA, nullptr);
    const Vec3 expected = 1025.0 * p.area * (2.0 * (A - t.dot(A) * t) + 1.1 * t.dot(A) * t);
    EXPECT_LT((withWaves - without + expected).norm(), 1e-12 * (1.0 + withWaves.norm()));
}

// A uniform current changing over the step (the input derivatives of current.x/y) moves the whole
// column: the depth profile rides on it unchanged, its shear stays, and the water accelerates at the
// rate everywhere, which the Morison inertia feels; the load's Jacobian stays exact.
TEST(Waves, ChangingCurrentShiftsTheProfileAndAcceleratesTheWater) {
    CurrentProfile profile;
    profile.rows = 2;
    profile.depth[0] = 10.0;
    profile.depth[1] = 50.0;
    profile.ux[0] = 0.8;
    profile.uy[1] = 0.4;
    CurrentField field;
    field.uniform = Vec3(0.3, -0.1, 0.0);
    field.profile = &profile;
    field.rate = Vec3(0.02, 0.05, 0.0);
    field.rateStart = 3.0;
    field.time = 7.5;
    for (double z : {0.0, -10.0, -20.0, -50.0, -80.0}) {
        CurrentField still = field;
        still.rate.setZero();
        Vec3 slope, stillSlope;
        const Vec3 u = field.at(z, &slope);
        const Vec3 u0 = still.at(z, &stillSlope);
        EXPECT_LT((u - u0 - 4.5 * field.rate).norm(), 1e-15) << z;
        EXPECT_EQ(slope, stillSlope) << z;
    }
    const Vec3 mid = field.at(-30.0, nullptr);
    EXPECT_NEAR(mid.x(), 0.3 + 4.5 * 0.02 + 0.4, 1e-15);
    EXPECT_NEAR(mid.y(), -0.1 + 4.5 * 0.05 + 0.2, 1e-15);

    Vec3 U, A;
    Mat3 dU, dA;
    field.flow(Vec3(1.0, 2.0, -30.0), U, dU, A, dA);
    EXPECT_EQ(A, field.rate);
    EXPECT_TRUE(dA.isZero(0.0));
    EXPECT_TRUE(field.accelerates());
    EXPECT_FALSE(field.waves());

    FluidProps p{1025.0, g, 3.0, kPi * 0.04 * 0.04 / 4, 0.04, 1.6, 0.02, 1.0, 0.1, true};
    const Vec3 r(2.0, 1.0, -30.0), rp(0.6, 0.2, -0.8), rd(0.3, 0.1, -0.2), rdd(0.05, -0.02, 0.1);
    auto load = [&](const Vec3& rr, const Vec3& rrp, const Vec3& rrd, PointLoadJacobian* J) {
        Vec3 u, a;
        Mat3 du, da;
        field.flow(rr, u, du, a, da);
        return point_load(p, rr, rrp, rrd, rdd, u, du, field.accelerates(), a, da, J);
    };
    PointLoadJacobian J;
    const Vec3 F = load(r, rp, rd, &J);
    expect_jacobian_is_the_derivative(load, r, rp, rd, F, J);
    const Vec3 t = rp.normalized();
    const Vec3 still = point_load(p, r, rp, rd, rdd, U, dU, false, A, dA, nullptr);
    const Vec3 expected = 1025.0 * p.area * (2.0 * (A - t.dot(A) * t) + 1.1 * t.dot(A) * t);
    EXPECT_LT((F - still + expected).norm(), 1e-12 * (1.0 + F.norm()));
}

// A 3-hour record of the JONSWAP sea at a point, sampled every 0.5 s: its significant height
// 4 std(eta) and the peak of its periodogram (smoothed over 0.01 rad/s bands) are the targets within
// 3 %, the statistical spread of a 3-hour record.
TEST(Waves, ThreeHourRecordHasTheTargetHsAndTp) {
    UCParams p = regular(3.0, 10.0, 1000.0);
    p.wavesMode = 2;
    SeaState sea;
    std::string error;
    ASSERT_TRUE(sea.build(p, error)) << error;
    const double dt = 0.5;
    const int n = static_cast<int>(3 * 3600 / dt);
    std::vector<double> eta(n);
    double mean = 0.0;
    for (int i = 0; i < n; ++i) mean += (eta[i] = sea.elevation(0.0, 0.0, i * dt)) / n;
    double var = 0.0;
    for (double e : eta) var += (e - mean) * (e - mean) / n;
    EXPECT_NEAR(4.0 * std::sqrt(var), 3.0, 0.03 * 3.0);
    double best = 0.0, bestOmega = 0.0;
    for (double w0 = 0.3; w0 < 1.5; w0 += 0.01) {  // band-averaged periodogram
        double band = 0.0;
        for (int j = 0; j < 5; ++j) {
            const double w = w0 + 0.002 * j;
            double re = 0.0, im = 0.0;
            for (int i = 0; i < n; ++i) {
                re += eta[i] * std::cos(w * i * dt);
                im -= eta[i] * std::sin(w * i * dt);
            }
            band += re * re + im * im;
        }
        if (band > best) best = band, bestOmega = w0 + 0.004;
    }
    EXPECT_NEAR(2 * kPi / bestOmega, 10.0, 0.03 * 10.0);
}

// The kinematics as the plain sum of the closed form over every component (cosh and sinh through
// exponentials, as the deep water needs): velocity and acceleration.
static void direct_sum(const SeaState& sea, double depth, double b, const Vec3& r, double t, Vec3& u, Vec3& a) {
    double uh = 0.0, w = 0.0, ah = 0.0, aw = 0.0;
    const double z = std::min(r.z(), 0.0);
    for (const WaveComponent& c : sea.components()) {
        const double theta = c.k * (r.x() * std::cos(b) + r.y() * std::sin(b)) - c.omega * t + c.phase;
        const double image = std::exp(-2.0 * c.k * (z + depth)), scale = 1.0 / (1.0 - std::exp(-2.0 * c.k * depth));
        const double ch = std::exp(c.k * z) * (1.0 + image) * scale, sh = std::exp(c.k * z) * (1.0 - image) * scale;
        uh += c.amplitude * c.omega * ch * std::cos(theta);
        w += c.amplitude * c.omega * sh * std::sin(theta);
        ah += c.amplitude * c.omega * c.omega * ch * std::sin(theta);
        aw -= c.amplitude * c.omega * c.omega * sh * std::cos(theta);
    }
    u = Vec3(uh * std::cos(b), uh * std::sin(b), w);
    a = Vec3(ah * std::cos(b), ah * std::sin(b), aw);
}

TEST(Waves, IrregularKinematicsEqualTheDirectSum) {
    // The kinematics sum exp(k (z + i s)) along the deep-water ladder of the equally spaced
    // frequencies, corrected by each component's finite-depth shift (a Taylor polynomial when small,
    // else an exponential), restarted every 16 components. Against the plain sum: 1e-12 of the scale
    // sum a w^2 (the ladder's round-off ~16^2 ulp, the phases' k s ulp at s = 2 km). Shallow water
    // (every shift large), deep water far from the origin, 5000 components, a mixed case, a point
    // near the bottom (where the image terms of the short waves equal their direct terms).
    struct Case { double depth; int n; double x, y, z; };
    for (const Case& k : {Case{30.0, 200, 3.0, 1.0, -12.0}, Case{3000.0, 400, 1500.0, -1300.0, -35.0},
                          Case{3000.0, 5000, -20.0, 7.0, -3.0}, Case{150.0, 300, 250.0, 40.0, -60.0},
                          Case{150.0, 300, 250.0, 40.0, 2.0}, Case{150.0, 300, 250.0, 40.0, -146.0}}) {
        UCParams p = regular(2.0, 9.0, k.depth, 0.7);
        p.wavesMode = 2;
        p.wavesNComponents = k.n;
        SeaState sea;
        std::string error;
        ASSERT_TRUE(sea.build(p, error)) << error;
        double scale = 0.0;
        for (const WaveComponent& c : sea.components()) scale += c.amplitude * c.omega * c.omega;
        for (double t : {0.0, 41.5, 3000.25}) {
            const Vec3 r(k.x, k.y, k.z);
            Vec3 u, a, ur, ar;
            sea.kinematics(r, t, u, a, nullptr, nullptr);
            direct_sum(sea, k.depth, 0.7, r, t, ur, ar);
            EXPECT_LT((u - ur).norm(), 1e-12 * scale) << k.depth << " " << k.n << " " << t;
            EXPECT_LT((a - ar).norm(), 1e-12 * scale) << k.depth << " " << k.n << " " << t;
            Mat3 du, da;  // the gradients' sums take the same path
            Vec3 ug, ag;
            sea.kinematics(r, t, ug, ag, &du, &da);
            EXPECT_EQ(ug, u);
            EXPECT_EQ(ag, a);
        }
    }
}

TEST(Waves, DeepPointsLeaveOutOnlyComponentsBelowRoundOff) {
    // The sum stops at the first component with k z < -40: at depth the short waves are gone. Against
    // the full sum of the closed form (every component), the velocity and acceleration agree to 1e-15 of
    // their surface scale, sum a w^2 (the dropped terms are below 1e-17 of it; the rest is round-off).
    UCParams p = regular(3.0, 10.0, 3000.0, 0.3);
    p.wavesMode = 2;
    p.wavesNComponents = 200;
    SeaState sea;
    std::string error;
    ASSERT_TRUE(sea.build(p, error)) << error;
    double scale = 0.0;
    for (const WaveComponent& c : sea.components()) scale += c.amplitude * c.omega * c.omega;
    const double t = 37.0;
    for (double z : {-50.0, -150.0, -400.0, -900.0}) {
        const Vec3 r(12.0, -4.0, z);
        Vec3 u, a, ur, ar;
        sea.kinematics(r, t, u, a, nullptr, nullptr);
        direct_sum(sea, 3000.0, 0.3, r, t, ur, ar);
        EXPECT_LT((u - ur).norm(), 1e-15 * scale) << z;
        EXPECT_LT((a - ar).norm(), 1e-15 * scale) << z;
        int kept = 0;
        for (const WaveComponent& c : sea.components()) kept += c.k * z >= -40.0;
        if (z == -900.0) {
            EXPECT_LT(kept, 60);  // most components are left out there: the cut-off acts
        }
    }
}

TEST(Waves, ExpandedKinematicsEqualTheSumWithinTheirBound) {
    // The residual's kinematics: a Taylor polynomial of degree 12 in (z + i s, t) about the node of a
    // lattice cell, the cells sized so that the components' summed remainders stay below 6e-12 of the
    // local velocity scale sum a w (e^{kz} + e^{-k(2h + z)}) and 1e-10 of the acceleration scale
    // (waves.cpp); the components a depth band leaves out add 1e-12 of the
    // velocity scale (the acceleration's: times w_max / w_min < 6); the sum itself leaves out or
    // rounds 1e-15 of the surface scale (as kinematics()). Against the plain sum of the closed form: deep and finite
    // depth (where the bottom's image terms count), seas of 16 to 300 components (fewer are summed),
    // points above the surface, a cache reused along a moving point and a fresh one.
    struct Case { int mode; double depth, T; int n; };
    for (const Case& k : {Case{2, 3000.0, 10.0, 200}, Case{2, 30.0, 9.0, 120}, Case{2, 150.0, 12.0, 300},
                          Case{2, 20.0, 8.0, 16}, Case{2, 4000.0, 6.0, 16}}) {
        UCParams p = regular(2.5, k.T, k.depth, 0.7);
        p.wavesMode = k.mode;
        p.wavesNComponents = k.n;
        SeaState sea;
        std::string error;
        ASSERT_TRUE(sea.build(p, error)) << error;
        double surfaceU = 0.0, surfaceA = 0.0;
        for (const WaveComponent& c : sea.components()) {
            surfaceU += c.velocityScale * (1.0 + c.bottom);
            surfaceA += c.accelerationScale * (1.0 + c.bottom);
        }
        WaveExpansion moving;
        SplitMix64 random(7);
        double worstU = 0.0, worstA = 0.0;
        for (int j = 0; j < 400; ++j) {
            // a point drifting through cells (0.15 m and 0.07 s per call) and random fresh points
            const double depthFraction = random.uniform();
            const Vec3 r(200.0 * random.uniform() - 100.0, 50.0 * random.uniform(),
                         j % 10 == 0 ? 0.5 * random.uniform() : -depthFraction * depthFraction * 0.95 * k.depth);
            const double t = 500.0 * random.uniform();
            for (int step = 0; step < 5; ++step) {
                const Vec3 rs = r + Vec3(0.3, -0.2, 0.4) * step * 0.3;
                const double ts = t + 0.07 * step;
                Vec3 u, a, ue, ae, uf, af;
                direct_sum(sea, k.depth, 0.7, rs, ts, u, a);
                sea.expanded_kinematics(rs, ts, moving, ue, ae);
                WaveExpansion fresh;
                sea.expanded_kinematics(rs, ts, fresh, uf, af);
                EXPECT_EQ(ue, uf);  // a pure function of (r, t): the cache's history does not matter
                EXPECT_EQ(ae, af);
                const double z = std::min(rs.z(), 0.0);
                double su = 0.0, sa = 0.0;
                for (const WaveComponent& c : sea.components()) {
                    const double m = std::exp(c.k * z) + std::exp(-c.k * (2.0 * k.depth + z));
                    su += c.velocityScale * m;
                    sa += c.accelerationScale * m;
                }
                const double tolU = 7e-12 * su + 1e-15 * surfaceU, tolA = 1.06e-10 * sa + 1e-15 * surfaceA;
                worstU = std::max(worstU, (ue - u).norm() / tolU);
                worstA = std::max(worstA, (ae - a).norm() / tolA);
                EXPECT_LT((ue - u).norm(), tolU) << k.depth << " " << rs.transpose() << " " << ts;
                EXPECT_LT((ae - a).norm(), tolA) << k.depth << " " << rs.transpose() << " " << ts;
                // The gradients (the Jacobian's): the derivative in zeta of the polynomial, whose
                // remainder is that of the acceleration for du (1e-10 of sum a w k e^{kz}) and one
                // degree lower for da (3e-9 of sum a w^2 k e^{kz}); against kinematics().
                Mat3 du, da, due, dae;
                Vec3 ug, ag, ueg, aeg;
                sea.kinematics(rs, ts, ug, ag, &du, &da);
                sea.expanded_kinematics(rs, ts, moving, ueg, aeg, &due, &dae);
                EXPECT_EQ(ueg, ue);  // the same polynomial with or without gradients
                EXPECT_EQ(aeg, ae);
                double sdu = 0.0, sda = 0.0, surfaceDu = 0.0, surfaceDa = 0.0;
                for (const WaveComponent& c : sea.components()) {
                    const double m = std::exp(c.k * z) + std::exp(-c.k * (2.0 * k.depth + z));
                    sdu += c.velocityScale * c.k * m;
                    sda += c.accelerationScale * c.k * m;
                    surfaceDu += c.velocityScale * c.k * (1.0 + c.bottom);
                    surfaceDa += c.accelerationScale * c.k * (1.0 + c.bottom);
                }
                EXPECT_LT((due - du).norm(), 1.1e-10 * sdu + 1e-12 * surfaceDu) << k.depth << " " << rs.transpose();
                EXPECT_LT((dae - da).norm(), 3e-9 * sda + 1e-12 * surfaceDa) << k.depth << " " << rs.transpose();
            }
        }
        std::printf("depth %g m, %d components: largest error / tolerance: velocity %.2e, acceleration %.2e\n",
                    k.depth, k.n, worstU, worstA);
    }
}

TEST(Waves, ExpandedKinematicsWithStretchingFollowTheSum) {
    // Wheeler stretching: the elevation from its own polynomial (amplitudes a, z = 0; remainder below
    // 6e-12 of sum a), z stretched with it, then the water's polynomial at the stretched depth. Against
    // kinematics() (the same stretching with the summed elevation): the bounds of the unstretched case at
    // the stretched depth, plus the elevation's error times the kinematics' slope (k |U| 6e-12 sum a,
    // below 1e-12 of the local scale here), plus the sum's own 1e-12 round-off of the surface scale.
    for (double depth : {25.0, 400.0}) {
        UCParams p = regular(2.0, 9.0, depth, 0.2);
        p.wavesMode = 2;
        p.wavesNComponents = 80;
        p.wavesStretching = 1;
        SeaState sea;
        std::string error;
        ASSERT_TRUE(sea.build(p, error)) << error;
        double surfaceU = 0.0, surfaceA = 0.0, surfaceDu = 0.0, surfaceDa = 0.0;
        for (const WaveComponent& c : sea.components()) {
            surfaceU += c.velocityScale * (1.0 + c.bottom);
            surfaceA += c.accelerationScale * (1.0 + c.bottom);
            surfaceDu += c.velocityScale * c.k * (1.0 + c.bottom);
            surfaceDa += c.accelerationScale * c.k * (1.0 + c.bottom);
        }
        WaveExpansion cache;
        SplitMix64 random(3);
        for (int j = 0; j < 200; ++j) {
            const double x = 100.0 * random.uniform(), zeta = -0.9 * depth * random.uniform() * random.uniform();
            const Vec3 r(x, 10.0 * random.uniform(), j % 5 == 0 ? 1.5 * random.uniform() - 0.5 : zeta);
            const double t = 300.0 * random.uniform();
            Vec3 u, a, ue, ae;
            Mat3 du, da, due, dae;
            sea.kinematics(r, t, u, a, &du, &da);
            sea.expanded_kinematics(r, t, cache, ue, ae, &due, &dae);
            const double eta = sea.elevation(r.x(), r.y(), t);
            const double z = std::min(depth * (r.z() - eta) / (depth + eta), 0.0);
            double su = 0.0, sa = 0.0;
            for (const WaveComponent& c : sea.components()) {
                const double m = std::exp(c.k * z) + std::exp(-c.k * (2.0 * depth + z));
                su += c.velocityScale * m;
                sa += c.accelerationScale * m;
            }
            EXPECT_LT((ue - u).norm(), 8e-12 * su + 1e-12 * surfaceU) << depth << " " << r.transpose() << " " << t;
            EXPECT_LT((ae - a).norm(), 1.1e-10 * sa + 1e-12 * surfaceA) << depth << " " << r.transpose() << " " << t;
            double sdu = 0.0, sda = 0.0;  // the gradients' scales, sum a w k (...) and sum a w^2 k (...)
            for (const WaveComponent& c : sea.components()) {
                const double m = std::exp(c.k * z) + std::exp(-c.k * (2.0 * depth + z));
                sdu += c.velocityScale * c.k * m;
                sda += c.accelerationScale * c.k * m;
            }
            EXPECT_LT((due - du).norm(), 1.1e-10 * sdu + 1e-12 * surfaceDu) << depth << " " << r.transpose();
            EXPECT_LT((dae - da).norm(), 3e-9 * sda + 1e-12 * surfaceDa) << depth << " " << r.transpose();
        }
    }
}

TEST(Waves, AShortSeaIsSummed) {
    // Below 16 components (a regular wave included) the sum costs less than the polynomial: the
    // residual's kinematics are the sum itself.
    for (int n : {1, 15}) {
        UCParams p = regular(2.0, 9.0, 60.0, 0.4);
        p.wavesMode = n == 1 ? 1 : 2;
        p.wavesNComponents = n;
        SeaState sea;
        std::string error;
        ASSERT_TRUE(sea.build(p, error)) << error;
        WaveExpansion cache;
        const Vec3 r(4.0, -2.0, -7.0);
        Vec3 u, a, ue, ae;
        Mat3 du, da, due, dae;
        sea.kinematics(r, 33.0, u, a, &du, &da);
        sea.expanded_kinematics(r, 33.0, cache, ue, ae, &due, &dae);
        EXPECT_EQ(u, ue) << n;
        EXPECT_EQ(a, ae) << n;
        EXPECT_EQ(du, due) << n;
        EXPECT_EQ(da, dae) << n;
    }
}

TEST(Waves, ExpandedKinematicsBeyondTheLatticeAreTheSum) {
    // A point no run reaches (or not a number, while a diverging step is being rejected) forms no
    // lattice index: the sum itself answers.
    UCParams p = regular(2.0, 9.0, 3000.0, 0.2);
    p.wavesMode = 2;
    SeaState sea;
    std::string error;
    ASSERT_TRUE(sea.build(p, error)) << error;
    WaveExpansion cache;
    for (const Vec3& r : {Vec3(1e300, 0.0, -5.0), Vec3(0.0, -1e290, -5.0), Vec3(3.0, 0.0, -1e300)}) {
        Vec3 u, a, ue, ae;
        sea.kinematics(r, 12.0, u, a, nullptr, nullptr);
        sea.expanded_kinematics(r, 12.0, cache, ue, ae);
        EXPECT_EQ(u, ue);
        EXPECT_EQ(a, ae);
    }
    Vec3 ue, ae;
    sea.expanded_kinematics(Vec3(std::nan(""), 0.0, -5.0), 12.0, cache, ue, ae);
    EXPECT_FALSE(std::isfinite(ue.norm()));  // not a number in, not a number out (no lattice index formed)
}

namespace {

struct Given {
    double omega, amplitude, phase, direction;
};

UCParams given(const std::vector<Given>& components, double depth) {
    UCParams p;
    uc_params_default(&p);
    p.wavesMode = 3;
    p.waterDepth = depth;
    p.gravity = g;
    p.waveComponentCount = static_cast<int>(components.size());
    for (size_t k = 0; k < components.size(); ++k) {
        const Given& c = components[k];
        double* row = p.waveComponents + 4 * k;
        row[0] = c.omega, row[1] = c.amplitude, row[2] = c.phase, row[3] = c.direction;
    }
    return p;
}

// The closed-form Airy sum of the components at r, t: elevation, velocity, acceleration (below z = 0).
void airy_sum(const std::vector<Given>& components, double depth, const Vec3& r, double t, double& eta, Vec3& u, Vec3& a) {
    eta = 0.0;
    u.setZero();
    a.setZero();
    for (const Given& c : components) {
        const double k = wave_number(c.omega, depth, g), w = c.omega;
        const double th = k * (r.x() * std::cos(c.direction) + r.y() * std::sin(c.direction)) - w * t + c.phase;
        const double ch = std::cosh(k * (r.z() + depth)) / std::sinh(k * depth);
        const double sh = std::sinh(k * (r.z() + depth)) / std::sinh(k * depth);
        const Vec3 along(std::cos(c.direction), std::sin(c.direction), 0.0);
        eta += c.amplitude * std::cos(th);
        u += c.amplitude * w * ch * std::cos(th) * along + Vec3(0, 0, c.amplitude * w * sh * std::sin(th));
        a += c.amplitude * w * w * ch * std::sin(th) * along - Vec3(0, 0, c.amplitude * w * w * sh * std::cos(th));
    }
}

// The water's velocity and acceleration gradients at one point equal central differences (to 1e-8 of scale).
void expect_gradients_are_the_differences(const SeaState& sea, double scale) {
    const Vec3 r(10.0, -5.0, -20.0);
    Vec3 u, a, up, um, ap, am;
    Mat3 du, da;
    sea.kinematics(r, 5.0, u, a, &du, &da);
    for (int c = 0; c < 3; ++c) {
        const double h = 1e-4;
        Vec3 e = Vec3::Zero();
        e[c] = h;
        sea.kinematics(r + e, 5.0, up, ap, nullptr, nullptr);
        sea.kinematics(r - e, 5.0, um, am, nullptr, nullptr);
        EXPECT_LT(((up - um) / (2 * h) - du.col(c)).norm(), 1e-8 * scale) << c;
        EXPECT_LT(((ap - am) / (2 * h) - da.col(c)).norm(), 1e-8 * scale) << c;
    }
}

}  // namespace

TEST(WavesGiven, ComponentsOfSeveralDirectionsAndUnevenFrequenciesAreTheAirySum) {
    // MoorDyn's wavekin_7 pair (0.35 rad/s along x, 0.4 rad/s at 1.57 rad), with an uneven third
    // component, in 50 m and 3000 m of water: elevation, velocity and acceleration to 1e-12 of the scale
    // sum a w^2, gradients equal to finite differences.
    const std::vector<Given> waves = {{0.35, 1.0, 0.3, 0.0}, {0.4, 0.8, -1.2, 1.57}, {0.93, 0.25, 2.0, 0.0}, {0.61, 0.4, 0.5, 1.57}};
    for (double depth : {50.0, 3000.0}) {
        SeaState sea;
        std::string error;
        ASSERT_TRUE(sea.build(given(waves, depth), error)) << error;
        ASSERT_EQ(sea.groups().size(), 1u);  // two directions of travel
        double scale = 0.0;
        for (const Given& c : waves) scale += c.amplitude * c.omega * c.omega;
        for (const Vec3& r : {Vec3(0, 0, -1), Vec3(-400.0, 3.0, -30.0), Vec3(25.0, -70.0, -48.0)}) {
            for (double t : {0.0, 3.7, 41.0}) {
                double eta;
                Vec3 u, a, uRef, aRef;
                airy_sum(waves, depth, r, t, eta, uRef, aRef);
                EXPECT_NEAR(sea.elevation(r.x(), r.y(), t), eta, 1e-12 * scale);
                sea.kinematics(r, t, u, a, nullptr, nullptr);
                EXPECT_LT((u - uRef).norm(), 1e-12 * scale) << depth << " " << t;
                EXPECT_LT((a - aRef).norm(), 1e-12 * scale) << depth << " " << t;
                WaveExpansion cache;
                Vec3 ue, ae;
                sea.expanded_kinematics(r, t, cache, ue, ae);
                EXPECT_LT((ue - uRef).norm(), 1e-12 * scale);
                EXPECT_LT((ae - aRef).norm(), 1e-12 * scale);
            }
        }
        expect_gradients_are_the_differences(sea, scale);
    }
}

TEST(WavesGiven, ManyComponentsOfOneDirectionTakeThePolynomialsWithinTheirBounds) {
    // 60 components of one direction, equally spaced (the ladder) and unevenly spaced (each its own
    // e^{k zeta}): the expansions, as the residual uses them, against the closed form, within the
    // bounds of docs/waves.md (6e-12 of the velocity scale, 1e-10 of the acceleration's).
    for (bool even : {true, false}) {
        std::vector<Given> waves;
        SplitMix64 random(7);
        for (int i = 0; i < 60; ++i) {
            const double w = even ? 0.3 + 0.02 * i : 0.3 + 1.2 * random.uniform();
            waves.push_back({w, 0.05 + 0.1 * random.uniform(), 2 * kPi * random.uniform(), 0.7});
        }
        for (double depth : {60.0, 2000.0}) {
            SeaState sea;
            std::string error;
            ASSERT_TRUE(sea.build(given(waves, depth), error)) << error;
            ASSERT_TRUE(sea.groups().empty());
            double uScale = 0.0, aScale = 0.0;
            for (const Given& c : waves) uScale += c.amplitude * c.omega, aScale += c.amplitude * c.omega * c.omega;
            WaveExpansion cache;
            for (const Vec3& r : {Vec3(0, 0, -0.5), Vec3(-40.0, 3.0, -12.0), Vec3(250.0, -70.0, -55.0)}) {
                for (double t : {0.0, 3.7, 41.2, 41.3}) {
                    double eta;
                    Vec3 u, a, uRef, aRef;
                    airy_sum(waves, depth, r, t, eta, uRef, aRef);
                    EXPECT_NEAR(sea.elevation(r.x(), r.y(), t), eta, 1e-12 * uScale);
                    sea.kinematics(r, t, u, a, nullptr, nullptr);
                    EXPECT_LT((u - uRef).norm(), 1e-12 * aScale) << even << " " << depth;
                    EXPECT_LT((a - aRef).norm(), 1e-12 * aScale) << even << " " << depth;
                    sea.expanded_kinematics(r, t, cache, u, a);
                    EXPECT_LT((u - uRef).norm(), 6e-12 * uScale) << even << " " << depth;
                    EXPECT_LT((a - aRef).norm(), 1e-10 * aScale) << even << " " << depth;
                }
            }
        }
    }
}

TEST(WavesGiven, ComponentsThatMakeNoSeaAreRefusedNamingThem) {
    auto why = [](const UCParams& p) {
        SeaState sea;
        std::string error;
        EXPECT_FALSE(sea.build(p, error));
        EXPECT_EQ(error, given_waves_violation(p));
        return error;
    };
    EXPECT_NE(why(given({}, 50.0)).find("waves.mode = 3 (given components) has none: set waves.file"), std::string::npos);
    EXPECT_NE(why(given({{0.5, -1.0, 0.0, 0.0}}, 50.0)).find("wave component 1 of the lineFile deck: omega = 0.5 rad/s, "
                                                            "amplitude = -1 m"), std::string::npos);
    EXPECT_NE(why(given({{0.5, 1.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}}, 50.0)).find("wave component 2"), std::string::npos);
    EXPECT_NE(why(given({{2.0, 1.5, 0.0, 0.0}}, 50.0)).find("exceeds the breaking limit 1/7"), std::string::npos);
    SeaState calm;
    std::string error;
    ASSERT_TRUE(calm.build(given({{0.5, 0.0, 0.0, 0.0}}, 50.0), error)) << error;
    EXPECT_TRUE(calm.calm());
}

TEST(WavesSpread, SpreadingDiscretizationIntegratesToOneWithItsDirectionalSpread) {
    // cos-2s: D(theta) = G(s) cos^{2s}(theta / 2) integrates to 1 over the circle, its mean cos(theta) is
    // s / (s + 1), so its directional spread (Kuik's sigma = sqrt(2 (1 - m1))) is sqrt(2 / (s + 1)). For an
    // integer s, D is a trigonometric polynomial of degree s: the midpoint rule of n > s + 1 directions
    // integrates it and D cos(theta) exactly (to round-off).
    std::vector<double> offsets, weights;
    for (int s : {1, 2, 5, 10, 30}) {
        for (int n : {s + 2, s + 7, 36}) {
            if (n <= s + 1) continue;
            spreading_directions(s, n, offsets, weights);
            ASSERT_EQ(weights.size(), static_cast<size_t>(n));
            double sum = 0.0, m1 = 0.0, sinMoment = 0.0;
            for (int j = 0; j < n; ++j) sum += weights[j], m1 += weights[j] * std::cos(offsets[j]), sinMoment += weights[j] * std::sin(offsets[j]);
            EXPECT_NEAR(sum, 1.0, 1e-13) << s << " " << n;
            EXPECT_NEAR(m1, s / (s + 1.0), 1e-13) << s << " " << n;
            EXPECT_NEAR(sinMoment, 0.0, 1e-14) << s << " " << n;  // symmetric about the mean direction
            EXPECT_NEAR(std::sqrt(2.0 * (1.0 - m1)), std::sqrt(2.0 / (s + 1.0)), 1e-12) << s << " " << n;
        }
    }
    // Odd n: the middle direction is the mean direction; the bands cover the circle once.
    spreading_directions(4.0, 9, offsets, weights);
    EXPECT_EQ(offsets[4], 0.0);
    EXPECT_NEAR(offsets[0], -kPi + kPi / 9, 1e-15);
    EXPECT_NEAR(offsets[8], kPi - kPi / 9, 1e-15);
    // A non-integer s: |cos(theta / 2)|^{2s} is not smooth at theta = +-pi, where the midpoint rule's error
    // is of order n^{-(2s + 1)} times D's tiny values there; the continuous G(s) is the normalization
    // (the fine rule reaches it to round-off).
    for (double s : {0.5, 1.5, 2.5, 7.3, 60.0}) {
        for (int n : {72, 20001}) {
            spreading_directions(s, n, offsets, weights);
            double sum = 0.0, m1 = 0.0;
            for (size_t j = 0; j < weights.size(); ++j) sum += weights[j], m1 += weights[j] * std::cos(offsets[j]);
            // Near theta = +-pi, D = G (x / 2)^{2s} (x the distance from pi): the rule's error is of the order of
            // that term over a band of width h, G 2^{-2s} h^{2s + 1}
            const double G = std::exp(std::lgamma(s + 1.0) - std::lgamma(s + 0.5)) / (2.0 * std::sqrt(kPi));
            const double bound = std::max(G * std::pow(2.0, -2.0 * s) * std::pow(2.0 * kPi / n, 2.0 * s + 1.0), 1e-14);
            EXPECT_NEAR(sum, 1.0, bound) << s << " " << n;
            EXPECT_NEAR(m1, s / (s + 1.0), bound) << s << " " << n;
        }
    }
}

namespace {

// Every component of a sea with its direction of travel, as given components.
std::vector<Given> all_components(const SeaState& sea) {
    std::vector<Given> out;
    for (const WaveComponent& c : sea.components()) out.push_back({c.omega, c.amplitude, c.phase, sea.direction()});
    for (const SeaState& group : sea.groups())
        for (const WaveComponent& c : group.components()) out.push_back({c.omega, c.amplitude, c.phase, group.direction()});
    return out;
}

UCParams spread(double s, int directions, int components, double depth) {
    UCParams p = regular(3.0, 9.0, depth, 0.6);
    p.wavesMode = 2;
    p.wavesNComponents = components;
    p.wavesSpreading = s;
    p.wavesNDirections = directions;
    return p;
}

}  // namespace

TEST(WavesSpread, ASpreadSeaKeepsHsAndHasTheSpreadingsDirectionalMoments) {
    // Each direction carries the long-crested sea's amplitudes times sqrt(its weight): Hs = 4 sqrt(m0)
    // exactly, and the energy's mean cos(beta - waves.direction) is s / (s + 1) (n > s + 1 directions).
    for (int s : {1, 4, 10}) {
        const int n = 2 * s + 5;  // odd: the middle direction is waves.direction
        SeaState sea;
        std::string error;
        ASSERT_TRUE(sea.build(spread(s, n, 40, 80.0), error)) << error;
        const std::vector<Given> waves = all_components(sea);
        ASSERT_EQ(waves.size(), static_cast<size_t>(40 * n));
        ASSERT_EQ(sea.groups().size(), static_cast<size_t>(n - 1));
        double m0 = 0.0, c1 = 0.0, s1 = 0.0;
        for (const Given& c : waves) {
            m0 += 0.5 * c.amplitude * c.amplitude;
            c1 += 0.5 * c.amplitude * c.amplitude * std::cos(c.direction - 0.6);
            s1 += 0.5 * c.amplitude * c.amplitude * std::sin(c.direction - 0.6);
        }
        EXPECT_NEAR(4.0 * std::sqrt(m0), 3.0, 1e-12) << s;
        EXPECT_NEAR(c1 / m0, s / (s + 1.0), 1e-12) << s;
        EXPECT_NEAR(s1 / m0, 0.0, 1e-12) << s;
        // the most energetic direction is waves.direction itself (odd n), the sea's first
        EXPECT_NEAR(sea.direction(), 0.6, 1e-15);
        // each direction has the JONSWAP frequencies, its own phases
        EXPECT_EQ(sea.groups()[0].components()[3].omega, sea.components()[3].omega);
        EXPECT_NE(sea.groups()[0].components()[3].phase, sea.components()[3].phase);
    }
    // No spreading, or a single direction: the long-crested sea, component by component.
    SeaState longCrested, single;
    std::string error;
    ASSERT_TRUE(longCrested.build(spread(0.0, 15, 40, 80.0), error));
    ASSERT_TRUE(single.build(spread(4.0, 1, 40, 80.0), error));
    ASSERT_TRUE(longCrested.groups().empty());
    ASSERT_TRUE(single.groups().empty());
    for (size_t i = 0; i < 40; ++i) {
        EXPECT_EQ(single.components()[i].amplitude, longCrested.components()[i].amplitude);
        EXPECT_EQ(single.components()[i].phase, longCrested.components()[i].phase);
    }
    // The same seed, the same spread sea; another seed, other phases.
    SeaState again, other;
    ASSERT_TRUE(again.build(spread(4.0, 9, 40, 80.0), error));
    UCParams q = spread(4.0, 9, 40, 80.0);
    q.wavesSeed = 2;
    ASSERT_TRUE(other.build(q, error));
    SeaState first;
    ASSERT_TRUE(first.build(spread(4.0, 9, 40, 80.0), error));
    EXPECT_EQ(first.elevation(3.0, 4.0, 17.0), again.elevation(3.0, 4.0, 17.0));
    EXPECT_NE(first.elevation(3.0, 4.0, 17.0), other.elevation(3.0, 4.0, 17.0));
    // Refused with a regular wave or given components, naming waves.spreading.
    UCParams r = regular(2.0, 9.0, 80.0);
    r.wavesSpreading = 4.0;
    EXPECT_EQ(check_params(r).rfind("waves.spreading = 4 is outside {0} with waves.mode 1", 0), 0u) << check_params(r);
    r.wavesMode = 2;
    EXPECT_EQ(check_params(r), "");
    // At most 20000 components in all, naming waves.nComponents.
    r.wavesNComponents = 2000;
    r.wavesNDirections = 11;
    EXPECT_EQ(check_params(r).rfind("waves.nComponents = 2000 is outside [1, 1818] with waves.nDirections = 11", 0), 0u)
        << check_params(r);
    r.wavesNDirections = 10;
    EXPECT_EQ(check_params(r), "");
}

TEST(WavesSpread, SpreadSeaKinematicsAreTheClosedFormAirySum) {
    // A cos-2s sea (s 4, 9 directions of 24 JONSWAP components each), in 40 m and 1500 m of water: the
    // elevation, velocity and acceleration of the direct sum equal the closed-form Airy sum of all its
    // components to 1e-12 of sum a w^2; the expansions (one polynomial per direction, summed) within their
    // bounds per direction, summed (6e-12 of the velocity scale, 1e-10 of the acceleration's); their
    // gradients equal those of the direct sum within theirs; with Wheeler stretching they follow the sum.
    for (double depth : {40.0, 1500.0}) {
        SeaState sea;
        std::string error;
        ASSERT_TRUE(sea.build(spread(4.0, 9, 24, depth), error)) << error;
        const std::vector<Given> waves = all_components(sea);
        double uScale = 0.0, aScale = 0.0;
        for (const Given& c : waves) uScale += c.amplitude * c.omega, aScale += c.amplitude * c.omega * c.omega;
        WaveExpansion moving;
        for (const Vec3& r : {Vec3(0, 0, -0.5), Vec3(-40.0, 3.0, -12.0), Vec3(250.0, -70.0, -35.0), Vec3(5.0, 8.0, 0.4)}) {
            for (double t : {0.0, 3.7, 41.2, 41.3}) {
                double eta;
                Vec3 u, a, uRef, aRef;
                airy_sum(waves, depth, Vec3(r.x(), r.y(), std::min(r.z(), 0.0)), t, eta, uRef, aRef);
                EXPECT_NEAR(sea.elevation(r.x(), r.y(), t), eta, 1e-12 * uScale);
                sea.kinematics(r, t, u, a, nullptr, nullptr);
                EXPECT_LT((u - uRef).norm(), 1e-12 * aScale) << depth << " " << t;
                EXPECT_LT((a - aRef).norm(), 1e-12 * aScale) << depth << " " << t;
                Vec3 ue, ae, uf, af;
                sea.expanded_kinematics(r, t, moving, ue, ae);
                EXPECT_LT((ue - uRef).norm(), 6e-12 * uScale) << depth << " " << r.transpose() << " " << t;
                EXPECT_LT((ae - aRef).norm(), 1e-10 * aScale) << depth << " " << r.transpose() << " " << t;
                WaveExpansion fresh;
                sea.expanded_kinematics(r, t, fresh, uf, af);
                EXPECT_EQ(ue, uf);  // the cache's history does not matter
                EXPECT_EQ(ae, af);
                ASSERT_EQ(fresh.groups.size(), sea.groups().size());  // one polynomial per direction
                Mat3 du, da, due, dae;
                sea.kinematics(r, t, u, a, &du, &da);
                sea.expanded_kinematics(r, t, fresh, ue, ae, &due, &dae);
                double kMax = 0.0;
                for (const Given& c : waves) kMax = std::max(kMax, wave_number(c.omega, depth, g));
                EXPECT_LT((due - du).norm(), 1.1e-10 * kMax * uScale) << depth << " " << r.transpose();
                EXPECT_LT((dae - da).norm(), 3e-9 * kMax * aScale) << depth << " " << r.transpose();
            }
        }
        expect_gradients_are_the_differences(sea, aScale);
        // Wheeler: the stretched depth from the summed elevation of all directions
        UCParams p = spread(4.0, 9, 24, depth);
        p.wavesStretching = 1;
        SeaState stretched;
        ASSERT_TRUE(stretched.build(p, error)) << error;
        for (const Vec3& q : {Vec3(1.0, 2.0, 0.3), Vec3(-30.0, 7.0, -2.0), Vec3(60.0, -20.0, -15.0)}) {
            for (double t : {2.0, 19.5}) {
                Vec3 us, as, ue, ae;
                stretched.kinematics(q, t, us, as, nullptr, nullptr);
                WaveExpansion cache;
                stretched.expanded_kinematics(q, t, cache, ue, ae);
                EXPECT_LT((ue - us).norm(), 1e-11 * uScale) << depth << " " << q.transpose();
                EXPECT_LT((ae - as).norm(), 2e-10 * aScale) << depth << " " << q.transpose();
                const double eta = sea.elevation(q.x(), q.y(), t);
                double etaRef;
                Vec3 uz, az;
                // the stretched point's water is the closed form at the stretched depth
                const double zs = std::min(depth * (q.z() - eta) / (depth + eta), 0.0);
                airy_sum(waves, depth, Vec3(q.x(), q.y(), zs), t, etaRef, uz, az);
                EXPECT_LT((us - uz).norm(), 1e-12 * aScale) << depth << " " << q.transpose();
            }
        }
    }
}
