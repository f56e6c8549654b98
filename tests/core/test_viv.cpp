// Vortex-induced vibration (Cl, vivFrequency, vivFrequencyRange; docs/model.md, "Vortex-induced vibration"):
// the lift's and the phase's derivatives against finite differences, the lift on an element at rest against
// the closed form, a taut line in a uniform current lifting at the Strouhal frequency with the closed-form
// amplitude, the statics without lift, the saved state, and the parameters' checks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "api/cable_api.h"
#include "line/simulation.h"
#include "model/cable_model.h"
#include "model/params.h"
#include "terms/viv.h"

using namespace uc;

namespace {

constexpr double kRho = 1025.0, kD = 0.05, kCl = 0.9;

FluidProps fluid() {
    FluidProps f{};
    f.rho = kRho;
    f.gravity = 9.81;
    f.massPerLength = 2.0;
    f.diameter = kD;
    f.area = kPi * kD * kD / 4.0;
    f.Cdn = 1.2;
    f.Cdt = 0.1;
    f.Can = 1.0;
    f.Cat = 0.0;
    f.addedMass = true;
    return f;
}

// A current that changes with depth (its gradient enters the derivatives).
struct ShearedCurrent {
    CurrentProfile profile;
    CurrentField field;
    ShearedCurrent() {
        profile.rows = 2;
        profile.depth[0] = 0.0;
        profile.depth[1] = 20.0;
        profile.ux[0] = 0.6;
        profile.ux[1] = 0.2;
        profile.uy[0] = 0.1;
        profile.uy[1] = -0.1;
        field.profile = &profile;
    }
};

// A bent element under water, moving.
const double kX[12] = {0, 0, -10, 0.05, 0.1, 1.0, 0.3, 0.2, -8.0, 0.1, 0.02, 0.99};
const double kXd[12] = {0.01, -0.02, 0.0, 0.01, 0.0, 0.0, -0.03, 0.05, 0.01, 0.0, 0.02, 0.0};
const double kXdd[12] = {0.2, -0.1, 0.05, 0.0, 0.1, 0.0, -0.3, 0.2, 0.0, 0.05, 0.0, 0.0};

}  // namespace

TEST(VivTerm, LiftDerivativesAreTheResidualsDerivatives) {
    const ElementTables e = make_element_tables(2.0, 3, 3);
    const FluidProps f = fluid();
    const VivProps v{kCl, 0.18, 0.08};
    ShearedCurrent c;
    const double phase = 0.7;
    Mat12 K = Mat12::Zero(), C = Mat12::Zero();
    double dPhase[12] = {};
    add_viv_jacobian(e, f, v, c.field, kX, kXd, phase, K, C, dPhase);
    auto lift = [&](const double* X, const double* Xd, double ph, int a) {
        double R[12] = {};
        add_viv_force(e, f, v, c.field, X, Xd, ph, R);
        return R[a];
    };
    const double h = 1e-7;
    double scale = 0.0;
    for (int a = 0; a < 12; ++a) scale = std::max(scale, std::abs(lift(kX, kXd, 0.0, a)));
    ASSERT_GT(scale, 0.1);
    const double tol = 1e-6 * scale;
    for (int a = 0; a < 12; ++a) {
        EXPECT_NEAR(dPhase[a], (lift(kX, kXd, phase + h, a) - lift(kX, kXd, phase - h, a)) / (2 * h), tol) << a;
        for (int b = 0; b < 12; ++b) {
            double xp[12], xm[12];
            for (int k = 0; k < 12; ++k) xp[k] = xm[k] = kX[k];
            xp[b] += h;
            xm[b] -= h;
            EXPECT_NEAR(K(a, b), (lift(xp, kXd, phase, a) - lift(xm, kXd, phase, a)) / (2 * h), tol) << "K " << a << " " << b;
            for (int k = 0; k < 12; ++k) xp[k] = xm[k] = kXd[k];
            xp[b] += h;
            xm[b] -= h;
            EXPECT_NEAR(C(a, b), (lift(kX, xp, phase, a) - lift(kX, xm, phase, a)) / (2 * h), tol) << "C " << a << " " << b;
        }
    }
}

TEST(VivTerm, PhaseDerivativesAreTheResidualsDerivatives) {
    const ElementTables e = make_element_tables(2.0, 3, 3);
    const FluidProps f = fluid();
    const VivProps v{kCl, 0.18, 0.08};
    ShearedCurrent c;
    const double phase = 2.1, rate = 5.0;
    VivPhaseJacobian J;
    const double R = viv_phase_residual(e, f, v, c.field, kX, kXd, kXdd, phase, rate, &J);
    EXPECT_EQ(R, viv_phase_residual(e, f, v, c.field, kX, kXd, kXdd, phase, rate));
    const double h = 1e-7, tol = 1e-5;  // rad/s: the rate is about 2 pi 0.18 0.5 / 0.05 = 11 rad/s
    auto at = [&](const double* X, const double* Xd, const double* Xdd, double ph) {
        return viv_phase_residual(e, f, v, c.field, X, Xd, Xdd, ph, rate);
    };
    EXPECT_NEAR(J.dPhase, (at(kX, kXd, kXdd, phase + h) - at(kX, kXd, kXdd, phase - h)) / (2 * h), tol);
    EXPECT_GT(std::abs(J.dPhase), 0.1);  // the motion's phase pulls the shedding's
    const double dRate = (viv_phase_residual(e, f, v, c.field, kX, kXd, kXdd, phase, rate + h) -
                          viv_phase_residual(e, f, v, c.field, kX, kXd, kXdd, phase, rate - h)) / (2 * h);
    EXPECT_NEAR(J.dPhaseRate, dRate, tol);
    EXPECT_NE(J.dPhaseRate, 1.0);  // the rate sets the motion's phase too
    for (int b = 0; b < 12; ++b) {
        for (int which = 0; which < 3; ++which) {
            const double* base = which == 0 ? kX : which == 1 ? kXd : kXdd;
            double xp[12], xm[12];
            for (int k = 0; k < 12; ++k) xp[k] = xm[k] = base[k];
            xp[b] += h;
            xm[b] -= h;
            const double fd = which == 0   ? (at(xp, kXd, kXdd, phase) - at(xm, kXd, kXdd, phase)) / (2 * h)
                              : which == 1 ? (at(kX, xp, kXdd, phase) - at(kX, xm, kXdd, phase)) / (2 * h)
                                           : (at(kX, kXd, xp, phase) - at(kX, kXd, xm, phase)) / (2 * h);
            const double analytic = which == 0 ? J.dX[b] : which == 1 ? J.dXd[b] : J.dXdd[b];
            EXPECT_NEAR(analytic, fd, tol) << "d/d" << (which == 0 ? "X" : which == 1 ? "Xd" : "Xdd") << " " << b;
        }
    }
}

TEST(VivTerm, LiftOnAnElementAtRestIsTheClosedForm) {
    // A straight vertical element at rest in a uniform current U along x: the lift per length is
    // 0.5 rho d U^2 Cl cos(phase) along t x u = z x x = +y, whatever the phase; its nodal forces sum to
    // minus the lift over the element (the residual carries -f_L; N_0 + N_2 = 1).
    const double L = 3.0, U = 0.8;
    const ElementTables e = make_element_tables(L, 3, 3);
    const FluidProps f = fluid();
    const VivProps v{kCl, 0.18, 0.08};
    CurrentField c;
    c.uniform = Vec3(U, 0.0, 0.0);
    const double X[12] = {0, 0, -20, 0, 0, 1, 0, 0, -20 + L, 0, 0, 1};
    const double Xd[12] = {};
    for (double phase : {0.0, 0.4, 2.0, kPi}) {
        double R[12] = {};
        add_viv_force(e, f, v, c, X, Xd, phase, R);
        const double expected = 0.5 * kRho * kD * U * U * kCl * std::cos(phase) * L;
        EXPECT_NEAR(-(R[1] + R[7]), expected, 1e-9 * 0.5 * kRho * kD * U * U * kCl * L) << phase;
        EXPECT_NEAR(R[0] + R[6], 0.0, 1e-12);
        EXPECT_NEAR(R[2] + R[8], 0.0, 1e-12);
    }
    // at rest the phase turns at the shedding frequency 2 pi f0 U / d
    const double Xdd[12] = {};
    EXPECT_NEAR(viv_phase_rate(e, f, v, c, X, Xd, Xdd, 1.0, 5.0), 2.0 * kPi * 0.18 * U / kD, 1e-9);
}

namespace {

// A taut vertical line of one element, gravity off, between an anchor and a tow point 1 % above its
// unstretched length, in a uniform current along x: its transverse natural frequency (T / (m + m_a))^0.5 / 2 L
// = 25 Hz is far above the shedding frequency 0.18 U / d = 1.8 Hz, so the two ends take the lift quasi-statically.
constexpr double kLength = 10.0, kU = 0.5, kEA = 1e8, kZ0 = -50.0;

UCParams taut_line(double range) {
    UCParams p;
    uc_params_default(&p);
    p.length = kLength;
    p.nElements = 1;
    p.diameter = kD;
    p.massPerLength = 2.0;
    p.gravity = 0.0;
    p.Cdn = 1.2;
    p.Cdt = 0.0;
    p.Can = 1.0;
    p.Cat = 0.0;
    p.waterDensity = kRho;
    p.waterDepth = 100.0;
    p.enableSeabed = 0;
    p.enableBending = 0;
    p.bottomEnd = UC_BOTTOM_ANCHORED;
    p.anchor[0] = p.anchor[1] = 0.0;
    p.anchor[2] = kZ0;
    p.EA = kEA;
    p.Cl = kCl;
    p.vivFrequency = 0.18;
    p.vivFrequencyRange = range;
    return p;
}

UCInputs tow_in_current() {
    UCInputs in{};
    in.tow[2] = kZ0 + kLength * 1.01;
    in.current[0] = kU;
    return in;
}

}  // namespace

TEST(VivLine, TautLineInAUniformCurrentLiftsAtTheStrouhalFrequencyWithTheClosedFormAmplitude) {
    // vivFrequencyRange 0: the shedding does not synchronise, the phase turns at 2 pi f0 U / d and the line's
    // ends carry the lift 0.5 rho d U^2 Cl L cos(phase) across the flow (y), less the line's inertia
    // ((1.8 / 25)^2 = 0.5 % of it).
    const UCParams p = taut_line(0.0);
    ASSERT_EQ(check_params(p), "");
    CableSimulation sim(p);
    std::string error;
    const UCInputs in = tow_in_current();
    ASSERT_TRUE(sim.initialize(0.0, in, error)) << error;
    ASSERT_EQ(sim.model().n_phases(), 1);
    const int j = sim.model().free_index(sim.model().phase_offset(0));
    const double w = 2.0 * kPi * 0.18 * kU / kD, period = 2.0 * kPi / w, h = period / 50.0;
    std::vector<double> ts, Fs;
    for (int s = 0; s < 50 * 6; ++s) {
        ASSERT_TRUE(sim.step(s * h, h, in, error)) << error;
        ts.push_back((s + 1) * h);
        Fs.push_back(-(sim.outputs().towForce[1] + sim.outputs().endForce[1]));  // the line's lift, on the ends
    }
    std::vector<double> q, v, a;
    sim.free_state(q, v, a);
    // the phase's rate: the Strouhal frequency of the relative flow, whose speed across the line the line's own
    // motion raises by (v_y / U)^2 / 2 ~ 2e-6 (v_y ~ 1e-3 m/s)
    EXPECT_NEAR(v[j], w, 1e-5 * w);
    // fit F = m + b cos(w t) + c sin(w t) over the last 4 periods
    double A[3][3] = {}, r[3] = {};
    for (size_t i = 2 * 50; i < ts.size(); ++i) {
        const double fx[3] = {1.0, std::cos(w * ts[i]), std::sin(w * ts[i])};
        for (int m = 0; m < 3; ++m) {
            r[m] += fx[m] * Fs[i];
            for (int k = 0; k < 3; ++k) A[m][k] += fx[m] * fx[k];
        }
    }
    for (int m = 0; m < 3; ++m)
        for (int i = m + 1; i < 3; ++i) {
            const double f = A[i][m] / A[m][m];
            for (int k = m; k < 3; ++k) A[i][k] -= f * A[m][k];
            r[i] -= f * r[m];
        }
    double x[3];
    for (int m = 2; m >= 0; --m) {
        x[m] = r[m];
        for (int k = m + 1; k < 3; ++k) x[m] -= A[m][k] * x[k];
        x[m] /= A[m][m];
    }
    const double amplitude = std::hypot(x[1], x[2]), expected = 0.5 * kRho * kD * kU * kU * kCl * kLength;
    EXPECT_NEAR(amplitude, expected, 0.01 * expected) << "lift amplitude";
    EXPECT_NEAR(x[0], 0.0, 0.01 * expected) << "mean";
    // the lift is at that frequency alone: the fit leaves little
    double rest = 0.0;
    for (size_t i = 2 * 50; i < ts.size(); ++i) {
        const double fit = x[0] + x[1] * std::cos(w * ts[i]) + x[2] * std::sin(w * ts[i]);
        rest = std::max(rest, std::abs(Fs[i] - fit));
    }
    EXPECT_LT(rest, 0.02 * expected);
}

TEST(VivLine, TheSynchronisedRateStaysInTheModelsRange) {
    // vivFrequencyRange 0.08 on a line of several elements that the lift moves: each phase turns between
    // 2 pi (f0 - df) |u_n| / d and 2 pi (f0 + df) |u_n| / d, and away from f0 where the motion pulls it.
    UCParams p = taut_line(0.08);
    p.nElements = 6;
    p.EA = 2e5;  // a softer line (T = 2 kN): the lift moves it
    CableSimulation sim(p);
    std::string error;
    const UCInputs in = tow_in_current();
    ASSERT_TRUE(sim.initialize(0.0, in, error)) << error;
    ASSERT_EQ(sim.model().n_phases(), 6);
    const double w = 2.0 * kPi * 0.18 * kU / kD, h = 0.02;
    double lo = INFINITY, hi = -INFINITY;
    for (int s = 0; s < 200; ++s) {
        ASSERT_TRUE(sim.step(s * h, h, in, error)) << error;
        std::vector<double> q, v, a;
        sim.free_state(q, v, a);
        for (int e = 0; e < 6; ++e) {
            const double rate = v[sim.model().free_index(sim.model().phase_offset(e))];
            lo = std::min(lo, rate);
            hi = std::max(hi, rate);
        }
    }
    // |u_n| within a few % of U (the line's own motion across the flow)
    EXPECT_GT(lo, 0.9 * w * (0.18 - 0.08) / 0.18);
    EXPECT_LT(hi, 1.1 * w * (0.18 + 0.08) / 0.18);
    EXPECT_GT(hi - lo, 0.1 * w * 0.08 / 0.18);  // the synchronisation moved them
}

TEST(VivLine, ASavedStateContinuesExactlyAndAnotherLayoutIsRefused) {
    UCParams p = taut_line(0.08);
    p.nElements = 4;
    p.EA = 2e5;
    const UCInputs in = tow_in_current();
    CableSimulation a(p);
    std::string error;
    ASSERT_TRUE(a.initialize(0.0, in, error)) << error;
    ASSERT_TRUE(a.step(0.0, 0.05, in, error)) << error;
    std::vector<unsigned char> saved(a.state_size());
    a.save_state(saved.data());
    ASSERT_TRUE(a.step(0.05, 0.05, in, error)) << error;
    ASSERT_TRUE(a.step(0.1, 0.05, in, error)) << error;
    CableSimulation b(p);
    ASSERT_TRUE(b.initialize(0.0, in, error)) << error;
    ASSERT_TRUE(b.restore_state(saved.data(), saved.size(), error)) << error;
    ASSERT_TRUE(b.step(0.05, 0.05, in, error)) << error;
    ASSERT_TRUE(b.step(0.1, 0.05, in, error)) << error;
    EXPECT_EQ(a.outputs().towForce[1], b.outputs().towForce[1]);
    std::vector<unsigned char> sa(a.state_size()), sb(b.state_size());
    a.save_state(sa.data());
    b.save_state(sb.data());
    EXPECT_EQ(sa, sb);
    // the phases are among the saved unknowns: the same line without VIV does not take the state
    UCParams plain = p;
    plain.Cl = 0.0;
    CableSimulation c(plain);
    ASSERT_TRUE(c.initialize(0.0, in, error)) << error;
    EXPECT_FALSE(c.restore_state(saved.data(), saved.size(), error));
    // a state of the format before the phases is refused naming what the new one adds
    std::vector<unsigned char> old = saved;
    const std::uint32_t previous = 14;
    std::memcpy(old.data() + 4, &previous, sizeof previous);
    EXPECT_FALSE(b.restore_state(old.data(), old.size(), error));
    EXPECT_NE(error.find("format version 14"), std::string::npos) << error;
    EXPECT_NE(error.find("vortex-induced vibration phases"), std::string::npos) << error;
}

TEST(VivLine, WithoutClTheLineHasNoPhases) {
    UCParams p = taut_line(0.08);
    p.Cl = 0.0;
    CableModel m(p);
    EXPECT_EQ(m.n_phases(), 0);
    EXPECT_EQ(m.phase_offset(0), -1);
    UCParams withViv = taut_line(0.08);
    CableModel v(withViv);
    EXPECT_EQ(v.n_free(), m.n_free() + 1);
}

TEST(VivParams, ClIsRefusedWhereItCannotApply) {
    UCParams p = taut_line(0.08);
    p.winchMode = 1;
    EXPECT_NE(check_params(p).find("Cl = 0.9"), std::string::npos) << check_params(p);
    EXPECT_NE(check_params(p).find("winchMode"), std::string::npos);
}
