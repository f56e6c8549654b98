// Whole-cable checks through the core: steady tow against the closed form, equilibrium closure,
// the elastica, assembled Jacobian, and exact state save/restore.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "api/cable_api.h"
#include "model/cable_model.h"
#include "line/simulation.h"
#include "cantilever.h"

using namespace uc;
using uc::testing::cantilever;

namespace {

constexpr double kKnot = 1852.0 / 3600.0;
using uc::kPi;

UCInputs tow_inputs(double speed) {
    UCInputs in{};
    in.towVelocity[0] = speed;
    return in;
}

UCParams hopland() {
    UCParams p;
    uc_params_default(&p);
    return p;
}

// Free-end towed cable in still water (docs/model.md): a straight line at the angle theta
// below the horizontal where normal drag balances the normal weight component,
// cn V^2 sin^2(theta) = w cos(theta); the tension grows linearly, T(0) = L (w sin + ct V^2 cos^2).
struct SteadyTow {
    double theta, topTension;
};

SteadyTow closed_form_tow(const UCParams& p, double V) {
    const double A = kPi * p.diameter * p.diameter / 4;
    const double w = (p.massPerLength - p.waterDensity * A) * p.gravity;
    const double cn = 0.5 * p.waterDensity * p.Cdn * p.diameter * V * V;
    const double ct = 0.5 * p.waterDensity * p.Cdt * kPi * p.diameter * V * V;
    // cn (1 - c^2) = w c  ->  c = cos(theta)
    const double c = (-w + std::sqrt(w * w + 4 * cn * cn)) / (2 * cn);
    const double theta = std::acos(c);
    return {theta, p.length * (w * std::sin(theta) + ct * c * c)};
}

}  // namespace

class SteadyTowTest : public ::testing::TestWithParam<double> {};

TEST_P(SteadyTowTest, FreeEndTowIsStraightAtTheCriticalAngle) {
    const double V = GetParam() * kKnot;
    UCParams p = hopland();
    CableSimulation sim(p);
    std::string error;
    ASSERT_TRUE(sim.initialize(0.0, tow_inputs(V), error)) << error;
    const SteadyTow exact = closed_form_tow(p, V);
    const UCOutputs& out = sim.outputs();
    // The only modelling difference from the closed form is the submerged-fraction ramp over one
    // diameter at the surface: a load deficit of about d/(8 sin theta) of cable, ~1e-4 relative.
    EXPECT_NEAR(out.towTension, exact.topTension, 1e-4 * exact.topTension);
    const double angle = std::atan2(-out.endPosition[2], -out.endPosition[0]);
    EXPECT_NEAR(angle, exact.theta, 1e-4);
    // Straight: every station on the chord.
    for (int k = 0; k < UC_NUM_STATIONS; ++k) {
        const double along = std::hypot(out.shapeX[k], out.shapeZ[k]);
        EXPECT_NEAR(std::atan2(-out.shapeZ[k], -out.shapeX[k]), exact.theta, k == 0 ? 10.0 : 1e-4 * 300 / along);
    }
    // A free end carries no tension and nothing along the cable is in compression.
    EXPECT_GE(out.minTension, -1e-6 * exact.topTension);
    // Tension linear along the cable, zero at the free end.
    EXPECT_NEAR(out.tension[UC_NUM_STATIONS - 1], 0.0, 1e-6 * exact.topTension);
    EXPECT_NEAR(out.tension[10], 0.5 * exact.topTension, 2e-4 * exact.topTension);
}

INSTANTIATE_TEST_SUITE_P(HoplandSpeeds, SteadyTowTest, ::testing::Values(1.1, 2.4));

TEST(SteadyTow, StaysSteadyWhenTowedAtConstantSpeed) {
    const double V = 2.4 * kKnot;
    CableSimulation sim(hopland());
    std::string error;
    UCInputs in = tow_inputs(V);
    ASSERT_TRUE(sim.initialize(0.0, in, error)) << error;
    const double T0 = sim.outputs().towTension;
    for (int k = 0; k < 40; ++k) {
        in.tow[0] = V * 0.5 * k;
        ASSERT_TRUE(sim.step(0.5 * k, 0.5, in, error)) << error;
    }
    // relTol 1e-6 on positions of O(300 m): tension drift bounded by EA * 1e-6 * 300 / 15 / 300 ~ 1e-4 T
    EXPECT_NEAR(sim.outputs().towTension, T0, 1e-3 * T0);
}

TEST(Equilibrium, TowReactionEqualsTotalExternalLoadToRoundOff) {
    const double V = 1.1 * kKnot;
    UCParams p = hopland();
    p.bottomEnd = UC_BOTTOM_TOWED_BODY;
    p.bodyMass = 500;
    p.bodyVolume = 0.1;
    p.bodyCdA = 0.5;
    CableSimulation sim(p);
    std::string error;
    UCInputs in = tow_inputs(V);
    in.current[1] = 0.2;  // cross current: a 3D shape
    ASSERT_TRUE(sim.initialize(0.0, in, error)) << error;

    // Residual of all external loads on the cable (hydro and inertia terms of every element's
    // position blocks, since the position shape functions sum to one) plus the body's terms.
    // The residual carries -f_external, and the free rows vanish at equilibrium, so the
    // reaction left at the tow point balances it: towForce + loadResidual = 0.
    const CableModel& m = sim.model();
    std::vector<double> q, v, a;
    sim.free_state(q, v, a);
    std::vector<double> X(m.n_global()), Xd(m.n_global()), Xdd(m.n_global());
    Loads loads;
    loads.tow = TowTrajectory::at_rest_in_time(Vec3::Zero(), Vec3(V, 0, 0), Vec3::Zero(), 0.0);
    loads.current.uniform = Vec3(0, 0.2, 0);
    m.expand(q.data(), v.data(), a.data(), loads, 0.0, X.data(), Xd.data(), Xdd.data());
    Vec3 loadResidual = m.end_node_residual(X.data(), Xd.data(), Xdd.data(), loads).head<3>();
    for (int e = 0; e < m.n_elements(); ++e) {
        Vec12 R = Vec12::Zero();
        const int g0 = m.element_offset(e);
        add_hydro_force(m.tables(e), m.element_section(e).fluid, loads.current, X.data() + g0, Xd.data() + g0,
                        Xdd.data() + g0, R.data());
        add_mass_force(m.tables(e), p.massPerLength, Xdd.data() + g0, R.data());
        loadResidual += R.segment<3>(0) + R.segment<3>(6);
    }
    const UCOutputs& out = sim.outputs();
    const Vec3 towForce(out.towForce[0], out.towForce[1], out.towForce[2]);
    // Internal forces cancel exactly (translation invariance); what is left is round-off of
    // sums of O(EA eps) terms: 1e-10 of the tension is ~1e3 times machine epsilon.
    EXPECT_LT((towForce + loadResidual).norm(), 1e-10 * towForce.norm());
    EXPECT_GT(std::abs(out.towForce[1]), 1.0);  // the cross current really acts
}

namespace {

// Jacobian of the assembled free residual against central finite differences (in the model's waves,
// if it has any, at t = 3 s).
// topRate: the winch's speed, with which the top element's material moves (winchMode != 0).
void check_assembled_jacobian(const UCParams& p, double topRate = 0.0, const CurrentGrid* grid = nullptr) {
    CableModel m(p);
    m.set_top_rate(topRate);
    const int n = m.n_free();
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> X(m.n_global());
    m.straight_line(Vec3(0, 0, -5), Vec3(-0.5, 0.1, -1), X.data());
    std::vector<double> q(n), v(n), a(n);
    m.restrict_to_free(X.data(), q.data());
    for (int j = 0; j < n; ++j) {
        q[j] += 0.05 * u(rng);
        v[j] = 0.5 * u(rng);
        a[j] = 0.2 * u(rng);
    }
    Loads loads;
    loads.tow = TowTrajectory::at_rest_in_time(Vec3(0, 0, -5), Vec3(1, 0, 0), Vec3(0.1, 0, 0), 0.0);
    loads.current.uniform = Vec3(0.2, -0.3, 0);
    loads.current.sea = &m.sea();
    loads.current.grid = grid;
    loads.current.time = 3.0;
    loads.endLoad = Vec3(10, 0, -20);
    loads.endLoadVelocity = Vec3(0.7, -0.2, 0.1);
    loads.endLoadDamping << 30, 2, -1, 0, 15, 0, 4, -3, 20;  // a drag-like matrix with a lift-like coupling
    loads.endCouple = Vec3(3, -40, 7);
    loads.torque = 25.0;
    std::vector<double> Xd(m.n_global()), Xdd(m.n_global()), R(n), Rp(n), Rm(n);
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), C = K, M = K;
    m.expand(q.data(), v.data(), a.data(), loads, 0.0, X.data(), Xd.data(), Xdd.data());
    m.jacobian(X.data(), Xd.data(), Xdd.data(), loads, [&](int i, int j, double dq, double dv, double da) {
        ASSERT_LE(std::abs(i - j), m.free_bandwidth());
        K(i, j) += dq;
        C(i, j) += dv;
        M(i, j) += da;
    });
    auto residual = [&](std::vector<double>& qq, std::vector<double>& vv, std::vector<double>& aa,
                        std::vector<double>& out) {
        m.expand(qq.data(), vv.data(), aa.data(), loads, 0.0, X.data(), Xd.data(), Xdd.data());
        m.residual(X.data(), Xd.data(), Xdd.data(), loads, out.data(), nullptr);
    };
    for (auto [which, J] : {std::pair<int, Eigen::MatrixXd*>{0, &K}, {1, &C}, {2, &M}}) {
        Eigen::MatrixXd numeric(n, n);
        // Positions: h = 1e-6 of O(1) coordinates. Velocities and accelerations enter only drag
        // (smooth, quadratic) and inertia (linear): h = 1e-4 and 1e-3 keep the truncation error
        // below 1e-6 relative while the cancellation error of O(EA eps) residuals stays negligible.
        const double h = which == 0 ? 1e-6 : which == 1 ? 1e-4 : 1e-3;
        for (int j = 0; j < n; ++j) {
            std::vector<double>* x = which == 0 ? &q : which == 1 ? &v : &a;
            const double x0 = (*x)[j];
            (*x)[j] = x0 + h;
            residual(q, v, a, Rp);
            (*x)[j] = x0 - h;
            residual(q, v, a, Rm);
            (*x)[j] = x0;
            for (int i = 0; i < n; ++i) numeric(i, j) = (Rp[i] - Rm[i]) / (2 * h);
        }
        // Truncation ~h^2 times third derivatives; cancellation ~1e-16 |R| / h with |R| ~ EA * 0.05.
        EXPECT_LT((*J - numeric).norm(), 1e-6 * J->norm()) << "block " << which;
    }
}

}  // namespace

TEST(AssembledJacobian, MatchesFiniteDifferencesFreeEndHinged) {
    UCParams p = hopland();
    p.nElements = 5;
    p.length = 20;
    p.axialDamping = 1e4;
    check_assembled_jacobian(p);
}

namespace {

// A 20 m line of 4 elements with a towed body.
UCParams towed_body_line() {
    UCParams p = hopland();
    p.nElements = 4;
    p.length = 20;
    p.bottomEnd = UC_BOTTOM_TOWED_BODY;
    p.bodyMass = 100;
    p.bodyVolume = 0.02;
    p.bodyAddedMass = 20;
    p.bodyCdA = 0.3;
    return p;
}

}  // namespace

TEST(AssembledJacobian, MatchesFiniteDifferencesInACurrentGivenOnAGrid) {
    // a current varying in x, y, z and t (currents.mode 5): its gradient and its rate's enter the Jacobian
    std::string text = "4 2 4 3\n-30 -12 -4 6\n-3 3\n-40 -18 -9 0\n0 2 5\n";
    int k = 0;
    for (double x : {-30.0, -12.0, -4.0, 6.0})
        for (double y : {-3.0, 3.0})
            for (double z : {-40.0, -18.0, -9.0, 0.0})
                for (double t : {0.0, 2.0, 5.0}) {
                    const double ux = 0.3 + 0.2 * std::sin(0.7 * k), uy = -0.2 + 0.15 * std::cos(1.3 * k), uz = 0.02 * std::sin(k);
                    text += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + " " + std::to_string(t) +
                            " " + std::to_string(ux) + " " + std::to_string(uy) + " " + std::to_string(uz) + "\n";
                    ++k;
                }
    std::string error;
    const auto grid = CurrentGrid::read(5, text, error);
    ASSERT_TRUE(grid) << error;
    UCParams p = hopland();
    p.nElements = 5;
    p.length = 20;
    p.axialDamping = 1e4;
    check_assembled_jacobian(p, 0.0, grid.get());
}

TEST(AssembledJacobian, MatchesFiniteDifferencesWinchPayingOut) {
    // The top element's velocity is the material's, v0 + c r'0 and v'0 + c r''0: it depends on the
    // positions too.
    UCParams p = towed_body_line();
    p.winchMode = UC_WINCH_RATE;
    p.winchMinLength = 5.0;
    p.winchMaxLength = 100.0;
    p.axialDamping = 1e4;
    check_assembled_jacobian(p, 0.8);
}

TEST(AssembledJacobian, MatchesFiniteDifferencesTowedBodyWithAddedMassMatrix) {
    // An anisotropic, non-diagonal added mass: the mass block is the residual's derivative too.
    UCParams p = towed_body_line();
    const double rows[3][3] = {{30, 5, -2}, {5, 60, 4}, {-2, 4, 90}};
    for (int j = 0; j < 3; ++j) {
        p.bodyAddedMassMatrix.x[j] = rows[0][j];
        p.bodyAddedMassMatrix.y[j] = rows[1][j];
        p.bodyAddedMassMatrix.z[j] = rows[2][j];
    }
    check_assembled_jacobian(p);
}

TEST(AssembledJacobian, MatchesFiniteDifferencesProxyFarEnd) {
    // bottomEnd 4: the proxy carries the body's inertia and weight, no drag of its own.
    UCParams p = towed_body_line();
    p.bottomEnd = UC_BOTTOM_PROXY;
    check_assembled_jacobian(p);
}

TEST(AssembledJacobian, MatchesFiniteDifferencesTowedBodyClamped) {
    UCParams p = towed_body_line();
    p.topEnd = UC_TOP_CLAMPED;
    p.topTangent[0] = 0.3;
    check_assembled_jacobian(p);
}

namespace {

// An irregular sea of 40 components, Hs 3 m, Tp 6 s, in 40 m of water (where the image terms count).
UCParams in_waves(UCParams p) {
    p.wavesMode = 2;
    p.wavesHeight = 3.0;
    p.wavesPeriod = 6.0;
    p.wavesNComponents = 40;
    p.waterDepth = 40.0;
    return p;
}

// Sea water around a point body (the line's own properties do not enter its loads).
FluidProps point_body_water() { return FluidProps{1025.0, 9.81, 0.0, 0.0, 0.1, 1.0, 0.0, 1.0, 0.0, true}; }

}  // namespace

TEST(AssembledJacobian, MatchesFiniteDifferencesTowedBodyInWaves) {
    // A line with a towed body and an attachment in waves (the water's motion from the waves'
    // polynomials, in finite depth): the assembly stays the residual's derivative. The waves' own
    // terms are small against the line's stiffness here; they are checked at the point level
    // (PointBody.JacobianInWavesIsTheDerivative, Waves.MorisonLoadJacobianInWavesMatchesFiniteDifferences).
    UCParams p = towed_body_line();
    p.nAttachments = 1;
    p.attachment[0].s = 10.0;
    p.attachment[0].mass = 50;
    p.attachment[0].volume = 0.08;
    p.attachment[0].addedMass = 60;
    p.attachment[0].CdA = 0.2;
    check_assembled_jacobian(in_waves(p));
}

TEST(AssembledJacobian, MatchesFiniteDifferencesAnchored) {
    UCParams p = hopland();
    p.nElements = 4;
    p.length = 20;
    p.bottomEnd = UC_BOTTOM_ANCHORED;
    p.anchor[0] = -10;
    p.anchor[2] = -20;
    check_assembled_jacobian(p);
}

TEST(PointBody, AcceleratingWaterPushesTheBodyUnlessSwitchedOff) {
    // A uniform current accelerating at A pushes a body of volume V and added mass ma with
    // (rho V + ma) A: the residual (force balance) changes by minus that, and not at all when
    // enableBodyFluidInertia is false.
    const FluidProps fluid = point_body_water();
    const double volume = 0.05, addedMass = 40.0;
    const double r[3] = {1, 2, -30}, rd[3] = {0.3, 0, 0}, rdd[3] = {0, 0, 0.1};
    CurrentField still;
    still.uniform = Vec3(0.5, 0, 0);
    CurrentField accelerating = still;
    accelerating.rate = Vec3(0.2, -0.1, 0.05);
    for (bool on : {true, false}) {
        const PointBody body{100.0, volume, addedMass, 0.3, on};
        Vec3 R0 = Vec3::Zero(), R1 = Vec3::Zero();
        add_point_body_residual(body, fluid, still, nullptr, r, rd, rdd, R0);
        add_point_body_residual(body, fluid, accelerating, nullptr, r, rd, rdd, R1);
        const Vec3 expected = on ? Vec3(-(fluid.rho * volume + addedMass) * accelerating.rate) : Vec3::Zero();
        EXPECT_LT((R1 - R0 - expected).norm(), 1e-12 * (1.0 + expected.norm())) << on;
    }
}

TEST(PointBody, JacobianInWavesIsTheDerivative) {
    // dR/dr of a body in waves: the drag in the water's velocity gradient and the push of the
    // accelerating water (rho V + ma) dA/dr, from the waves' polynomial (as in the residual), against
    // central differences of the residual (h = 1e-4 m: truncation ~h^2 k^2 ~ 1e-10 relative).
    const CableModel m(in_waves(hopland()));
    const FluidProps fluid = point_body_water();
    CurrentField water;
    water.uniform = Vec3(0.2, 0.1, 0);
    water.sea = &m.sea();
    water.time = 7.3;
    const double rd[3] = {0.3, -0.1, 0.2};
    for (bool on : {true, false}) {
        const PointBody body{100.0, 0.5, 500.0, 0.3, on};
        WaveExpansion cache;
        const double r[3] = {1.0, 2.0, -3.0};
        Mat3 K, C, M;
        point_body_jacobian(body, fluid, water, &cache, r, rd, K, C, M);
        Mat3 numeric;
        const double h = 1e-4;
        for (int c = 0; c < 3; ++c) {
            double rp[3] = {r[0], r[1], r[2]}, rm[3] = {r[0], r[1], r[2]};
            rp[c] += h;
            rm[c] -= h;
            Vec3 Rp = Vec3::Zero(), Rm = Vec3::Zero();
            add_point_body_residual(body, fluid, water, &cache, rp, rd, rd, Rp);
            add_point_body_residual(body, fluid, water, &cache, rm, rd, rd, Rm);
            numeric.col(c) = (Rp - Rm) / (2 * h);
        }
        EXPECT_GT(K.norm(), on ? 100.0 : 20.0) << on;  // the waves' gradients make it far from zero
        EXPECT_LT((K - numeric).norm(), 1e-6 * K.norm()) << on << "\n" << K << "\n" << numeric;
    }
}

namespace {

// Paper Table 1 cantilever; exact tips from tests/data/elastica.json.
struct ElasticaCase {
    double P, xTip, yTip;
};
constexpr ElasticaCase kElastica[] = {{20, 9.16015744189, -3.65103793133},
                                      {40, 7.85696019238, -5.60624938203},
                                      {60, 6.83193067184, -6.60032424241},
                                      {80, 6.0756744513, -7.1710085355}};

double elastica_tip_error(const ElasticaCase& c, int nElements) {
    const UCParams p = cantilever(nElements);
    CableSimulation sim(p);
    UCInputs in{};
    in.tow[2] = -50;  // fully submerged
    in.endLoad[2] = -c.P;
    std::string error;
    if (!sim.initialize(0.0, in, error)) ADD_FAILURE() << error;
    const UCOutputs& out = sim.outputs();
    // The exact elastica is inextensible; the axial strain P/EA ~ 1e-6 shifts the tip by < 1e-5 m.
    return std::hypot(out.endPosition[0] - c.xTip, out.endPosition[2] + 50 - c.yTip) / p.length;
}

}  // namespace

TEST(Elastica, TipWithin1e4LengthWithTenElements) {
    for (const ElasticaCase& c : kElastica) EXPECT_LT(elastica_tip_error(c, 10), 1e-4) << "P = " << c.P;
}

TEST(Elastica, TipWithin1e5LengthWithFortyElements) {
    for (const ElasticaCase& c : kElastica) EXPECT_LT(elastica_tip_error(c, 40), 1e-5) << "P = " << c.P;
}

namespace {

// Saves a's state after 10 steps of an accelerating tow and restores it into b: both continue alike.
void expect_bit_identical_continuation(const UCParams& p, UCOutputs* end = nullptr) {
    CableSimulation a(p), b(p);
    std::string error;
    UCInputs in = tow_inputs(1.1 * kKnot);
    ASSERT_TRUE(a.initialize(0.0, in, error)) << error;
    ASSERT_TRUE(b.initialize(0.0, in, error)) << error;
    auto advance = [&](CableSimulation& s, int from, int count) {
        for (int k = from; k < from + count; ++k) {
            UCInputs step = in;
            step.towVelocity[0] = (1.1 + 0.02 * k) * kKnot;  // accelerating: a non-trivial history
            step.tow[0] = s.outputs().shapeX[0];
            ASSERT_TRUE(s.step(s.time(), 0.5, step, error)) << error;
        }
    };
    advance(a, 0, 10);
    std::vector<unsigned char> saved(a.state_size());
    a.save_state(saved.data());
    advance(a, 10, 10);
    ASSERT_TRUE(b.restore_state(saved.data(), saved.size(), error)) << error;
    advance(b, 10, 10);
    EXPECT_EQ(std::memcmp(&a.outputs(), &b.outputs(), sizeof(UCOutputs)), 0);
    EXPECT_EQ(a.time(), b.time());
    if (end) *end = a.outputs();
}

}  // namespace

TEST(StateSaveRestore, ContinuationIsBitIdentical) {
    UCParams p = hopland();
    p.nElements = 10;
    expect_bit_identical_continuation(p);
}

TEST(StateSaveRestore, ContinuationIsBitIdenticalWithProjectedErrorControl) {
    // the error norm's directions come from the state: a restored run takes the same steps
    UCParams p = hopland();
    p.nElements = 10;
    p.projectedErrorControl = 1;
    UCOutputs projected{}, componentwise{};
    expect_bit_identical_continuation(p, &projected);
    p.projectedErrorControl = 0;
    expect_bit_identical_continuation(p, &componentwise);
    EXPECT_NE(projected.nSteps, componentwise.nSteps);  // the option is in effect
}

namespace {

// Cantilever (the elastica's cable) bent by a couple M about +y at its free end: the exact shape
// is a circular arc of radius EI/M. Returns the largest distance of the 21 output stations from
// the arc, relative to the length.
double end_couple_arc_error(double turns, int nElements) {
    const UCParams p = cantilever(nElements);
    CableSimulation sim(p);
    UCInputs in{};
    in.tow[2] = -50;
    const double M = 2 * kPi * turns * p.EI / p.length;
    in.endCouple[1] = M;
    std::string error;
    if (!sim.initialize(0.0, in, error)) ADD_FAILURE() << error;
    const double R = p.EI / M;
    const UCOutputs& out = sim.outputs();
    double worst = 0;
    for (int k = 0; k < UC_NUM_STATIONS; ++k) {
        const double phi = p.length * k / (UC_NUM_STATIONS - 1) / R;
        const double x = R * std::sin(phi), z = -50 - R * (1 - std::cos(phi));
        worst = std::max(worst, std::hypot(out.shapeX[k] - x, out.shapeZ[k] - z));
    }
    return worst / p.length;
}

}  // namespace

TEST(EndCouple, BendsTheCantileverIntoACircularArcUpToAFullRing) {
    // Measured at 20 elements: 2e-6 L (quarter ring), 5e-6 L (half), 2.1e-5 L (full ring); the
    // full ring at 10 elements is 6e-4 L (18 deg per element), so 20 elements is the resolution
    // where the bound is meaningful. The floor (~2e-5 L at 40 elements) is the station positions
    // along the arc: with the softened higher strain modes, |r'| varies slightly inside an element.
    for (double turns : {0.25, 0.5, 1.0}) EXPECT_LT(end_couple_arc_error(turns, 20), 1e-4) << turns << " turns";
    EXPECT_LT(end_couple_arc_error(1.0, 20), end_couple_arc_error(1.0, 10) / 10) << "refinement must pay";
}
