// The viscoelastic axial model (EAdynamic, EAdynamicSlope, axialDampingDynamic; docs/model.md, "Viscoelastic
// axial model"): the element's couplings against finite differences, a harmonic strain against the model's
// complex modulus, a step of strain against the closed-form relaxation, the statics with the static EA, the
// saved state, and the parameters' checks.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "api/cable_api.h"
#include "line/simulation.h"
#include "model/cable_model.h"
#include "model/params.h"
#include "weightless_rope.h"

using namespace uc;

namespace {

// A weightless, dragless rope of one element between an anchor at the origin and the tow point on +x,
// prestrained: only its axial law acts (the mass, 0.01 kg/m, puts its first axial mode near 2700 rad/s).
constexpr double kLength = 10.0, kPrestrain = 0.01;
constexpr double kEAs = 1e6, kEAd = 3e6, kDamping = 1e5, kDampingDynamic = 1e4;

UCParams taut_rope() {
    UCParams p = weightless_rope(kLength, 0.02, 0.01);
    p.EA = kEAs;
    p.axialDamping = kDamping;
    p.EAdynamic = kEAd;
    p.axialDampingDynamic = kDampingDynamic;
    p.enableCompression = 1;
    return p;
}

UCInputs tow_at(double x, double v, double a) {
    UCInputs in{};
    in.tow[0] = x;
    in.towVelocity[0] = v;
    in.towAcceleration[0] = a;
    in.towAccelerationGiven = 1;
    return in;
}

// The tow point's motion at the start of a step (CableSimulation::step's EndMotion: the master's inputs, which
// the line extrapolates over the step with the acceleration given and the jerk of the last two).
EndMotion motion_at(double x, double v, double a) {
    EndMotion m;
    m.position = Vec3(x, 0.0, 0.0);
    m.velocity = Vec3(v, 0.0, 0.0);
    m.acceleration = Vec3(a, 0.0, 0.0);
    m.accelerationGiven = 1;
    return m;
}

bool step_to(CableSimulation& sim, double h, const EndMotion& tow, std::string& error) {
    return sim.step(h, tow, EndMotion{}, LineEnvironment{}, error);
}

ViscoProps props() { return ViscoProps{kEAs, kEAd, 0.0, kDampingDynamic}; }

// The least-squares fit T = m + b cos(w t) + c sin(w t) of samples (t, T).
void fit_harmonic(const std::vector<double>& t, const std::vector<double>& T, double w, double& b, double& c) {
    double A[3][3] = {}, r[3] = {};
    for (size_t i = 0; i < t.size(); ++i) {
        const double f[3] = {1.0, std::cos(w * t[i]), std::sin(w * t[i])};
        for (int j = 0; j < 3; ++j) {
            r[j] += f[j] * T[i];
            for (int k = 0; k < 3; ++k) A[j][k] += f[j] * f[k];
        }
    }
    for (int j = 0; j < 3; ++j)  // Gauss elimination (the normal matrix is well conditioned over whole periods)
        for (int i = j + 1; i < 3; ++i) {
            const double m = A[i][j] / A[j][j];
            for (int k = j; k < 3; ++k) A[i][k] -= m * A[j][k];
            r[i] -= m * r[j];
        }
    double x[3];
    for (int j = 2; j >= 0; --j) {
        x[j] = r[j];
        for (int k = j + 1; k < 3; ++k) x[j] -= A[j][k] * x[k];
        x[j] /= A[j][j];
    }
    b = x[1];
    c = x[2];
}

}  // namespace

TEST(ViscoelasticElement, CouplingsAreTheDerivativesOfTheResiduals) {
    // Load-dependent dynamic stiffness (the slope makes EA_1 and EA_2 functions of e1): every coupling
    // against central differences.
    const ElementTables e = make_element_tables(2.0, 3, 3);
    ViscoProps v{kEAs, 1.2e6, 0.4, kDampingDynamic};
    AxialProps p{kEAs, kDamping};
    p.visco = &v;
    p.internal[0] = 0.004;
    p.internal[1] = 0.03;
    double X[12] = {0, 0, 0, 1.01, 0.02, 0, 2.02, 0.05, 0.01, 0.99, 0.03, 0.01};
    double Xd[12] = {0, 0, 0, 0.1, -0.2, 0, 0.3, 0.1, 0, -0.1, 0.2, 0.05};
    ViscoJacobian J;
    visco_jacobian(e, p, X, Xd, J);
    const double h = 1e-7;
    auto forces = [&](const AxialProps& q, const double* x, const double* xd, double* R) {
        for (int a = 0; a < 12; ++a) R[a] = 0.0;
        add_axial_force(e, q, x, xd, R);
    };
    double Rp[12], Rm[12];
    for (int which = 0; which < 2; ++which) {
        AxialProps up = p, down = p;
        up.internal[which] += h;
        down.internal[which] -= h;
        forces(up, X, Xd, Rp);
        forces(down, X, Xd, Rm);
        const double* analytic = which == 0 ? J.dR_de1 : J.dR_dr1;
        for (int a = 0; a < 12; ++a)
            EXPECT_NEAR(analytic[a], (Rp[a] - Rm[a]) / (2 * h), 1e-6 * kEAd) << "dR/d" << (which ? "r1" : "e1") << " " << a;
        const double dI = (visco_residual(e, up, X, Xd) - visco_residual(e, down, X, Xd)) / (2 * h);
        EXPECT_NEAR(which == 0 ? J.dI_de1 : J.dI_dr1, dI, 1e-6 * kEAd) << "dI/d" << (which ? "r1" : "e1");
    }
    for (int b = 0; b < 12; ++b) {
        for (int rate = 0; rate < 2; ++rate) {
            double xp[12], xm[12];
            double* base = rate ? Xd : X;
            for (int k = 0; k < 12; ++k) xp[k] = xm[k] = base[k];
            xp[b] += h;
            xm[b] -= h;
            const double dI = rate ? (visco_residual(e, p, X, xp) - visco_residual(e, p, X, xm)) / (2 * h)
                                   : (visco_residual(e, p, xp, Xd) - visco_residual(e, p, xm, Xd)) / (2 * h);
            EXPECT_NEAR(rate ? J.dI_dXd[b] : J.dI_dX[b], dI, 1e-6 * kEAd) << "dI/dX" << (rate ? "d " : " ") << b;
        }
    }
    // at e1 = 0 the dynamic stiffness is EA_Dc; with the slope it rises as MoorDyn's closed form has it
    EXPECT_EQ(visco_stiffness(v, 0.0).EA2, 1.2e6);
    const ViscoStiffness k = visco_stiffness(v, 0.01);
    EXPECT_NEAR(k.EA2, 1.2e6 + 0.4 * k.EA1 * 0.01, 1e-9 * k.EA2);  // EA_2 = EA_Dc + beta x mean load
    EXPECT_NEAR(k.EA1 * k.EA2 / (k.EA1 + k.EA2), kEAs, 1e-9 * kEAs);  // the series is the static EA
}

TEST(ViscoelasticLine, AtRestTheRopeHasTheStaticStiffnessAndStaysAtRest) {
    const UCParams p = taut_rope();
    CableSimulation sim(p);
    std::string error;
    const double x0 = kLength * (1.0 + kPrestrain);
    ASSERT_TRUE(sim.initialize(0.0, tow_at(x0, 0.0, 0.0), error)) << error;
    // the internal strain at equilibrium with the static tension: EA_s eps, not EA_d eps
    EXPECT_NEAR(sim.outputs().towTension, kEAs * kPrestrain, 1e-9 * kEAs * kPrestrain);
    const int gi = sim.model().internal_offset(0);
    ASSERT_GE(gi, 0);
    std::vector<double> q, v, a;
    sim.free_state(q, v, a);
    const int j = sim.model().free_index(gi);
    const ViscoStiffness k = visco_stiffness(props(), 0.0);
    EXPECT_NEAR(q[j], k.EA2 * kPrestrain / (k.EA1 + k.EA2), 1e-12);
    EXPECT_EQ(v[j], 0.0);
    for (int s = 0; s < 10; ++s) ASSERT_TRUE(sim.step(0.1 * s, 0.1, tow_at(x0, 0.0, 0.0), error)) << error;
    EXPECT_NEAR(sim.outputs().towTension, kEAs * kPrestrain, 1e-9 * kEAs * kPrestrain);
}

constexpr int kStepsPerPeriod = 100;

TEST(ViscoelasticLine, HarmonicStrainFollowsTheComplexModulus) {
    // eps = eps0 + (a / L) (1 - cos(w t)), from rest: after the transient (relaxation time (c + c_d) /
    // (EA_1 + EA_2) = 0.024 s, 10 periods of 0.2 s before the fit) T - T_mean = -(a / L) (E' cos(w t) -
    // E'' sin(w t)).
    // Errors: the rope's inertia (w / w_axial)^2 ~ 1e-4 and the integrator (tensionTolerance 1e-3 of the
    // tension scale); the bound, 3e-3 of |E|, is above both.
    const UCParams p = taut_rope();
    CableSimulation sim(p);
    std::string error;
    const double x0 = kLength * (1.0 + kPrestrain), amp = 0.01, w = 2.0 * kPi * 5.0, dt = 0.2 / kStepsPerPeriod;
    ASSERT_TRUE(sim.initialize(0.0, tow_at(x0, 0.0, amp * w * w), error)) << error;
    std::vector<double> ts, Ts;
    for (int s = 1; s <= kStepsPerPeriod * 14; ++s) {
        const double t = s * dt, t0 = t - dt;  // the inputs at the step's start
        ASSERT_TRUE(step_to(sim, dt, motion_at(x0 + amp * (1.0 - std::cos(w * t0)), amp * w * std::sin(w * t0),
                                               amp * w * w * std::cos(w * t0)), error))
            << error;
        if (s > kStepsPerPeriod * 10) {
            ts.push_back(t);
            Ts.push_back(-sim.outputs().towForce[0]);
        }
    }
    double b, c, storage, loss;
    fit_harmonic(ts, Ts, w, b, c);
    visco_modulus(props(), kDamping, w, storage, loss);
    const double strain = amp / kLength, modulus = std::hypot(storage, loss);
    EXPECT_NEAR(-b / strain, storage, 3e-3 * modulus) << "storage modulus";
    EXPECT_NEAR(c / strain, loss, 3e-3 * modulus) << "loss modulus";
    // between the static and the dynamic stiffness, and a loss well resolved by the fit
    EXPECT_GT(storage, kEAs);
    EXPECT_LT(storage, kEAd);
    EXPECT_GT(loss, 0.1 * storage);
}

TEST(ViscoelasticLine, AStepOfStrainRelaxesAsTheClosedFormExponential) {
    // A ramp of 2 ms (a tenth of the relaxation time; a quintic, at rest at both ends, so the rope's inertia
    // does not load the tow point after it) to eps1, then held: the internal strain's equation
    // is linear with a constant forcing, so T(t) - EA_s eps1 = (T(t_r) - EA_s eps1) exp(-(t - t_r) / tau),
    // tau = (c + c_d) / (EA_1 + EA_2), whatever the ramp did.
    const UCParams p = taut_rope();
    CableSimulation sim(p);
    std::string error;
    const double x0 = kLength * (1.0 + kPrestrain), dx = 0.02, ramp = 0.002;
    ASSERT_TRUE(sim.initialize(0.0, tow_at(x0, 0.0, 0.0), error)) << error;
    const int rampSteps = 20;
    for (int s = 1; s <= rampSteps; ++s) {  // x = x0 + dx (10 u^3 - 15 u^4 + 6 u^5)
        const double u = static_cast<double>(s - 1) / rampSteps, h = ramp / rampSteps, u2 = u * u;
        ASSERT_TRUE(step_to(sim, h,
                            motion_at(x0 + dx * u2 * u * (10 - 15 * u + 6 * u2), dx * 30 * u2 * (1 - u) * (1 - u) / ramp,
                                      dx * 60 * u * (1 - u) * (1 - 2 * u) / (ramp * ramp)),
                            error))
            << error;
    }
    const ViscoStiffness k = visco_stiffness(props(), 0.0);
    const double tau = (kDamping + kDampingDynamic) / (k.EA1 + k.EA2);
    const double Tinf = kEAs * (kPrestrain + dx / kLength);
    const double h = tau / 20;
    // the first steps of the hold bring the tow point from the ramp's extrapolated end to x0 + dx (and the
    // rope's axial vibration dies out): the exponential is checked from one relaxation time on
    for (int s = 0; s < 20; ++s) ASSERT_TRUE(step_to(sim, h, motion_at(x0 + dx, 0.0, 0.0), error)) << error;
    const double t1 = ramp + 20 * h, T0 = sim.outputs().towTension - Tinf;
    EXPECT_GT(T0, 0.5 * std::exp(-1.0) * (kEAd - kEAs) * dx / kLength);  // still a dynamic overshoot
    double t = t1;
    for (int s = 1; s <= 180; ++s) {  // 9 tau
        ASSERT_TRUE(step_to(sim, h, motion_at(x0 + dx, 0.0, 0.0), error)) << error;
        t += h;
        const double expected = T0 * std::exp(-(t - t1) / tau);
        // the integrator's tolerance: 1e-3 of the tension scale (the static tension here)
        EXPECT_NEAR(sim.outputs().towTension - Tinf, expected, 2e-3 * Tinf) << "t = " << t;
    }
}

TEST(ViscoelasticLine, ASavedStateContinuesExactly) {
    const UCParams p = taut_rope();
    CableSimulation a(p);
    std::string error;
    const double x0 = kLength * (1.0 + kPrestrain);
    ASSERT_TRUE(a.initialize(0.0, tow_at(x0, 0.0, 0.0), error)) << error;
    ASSERT_TRUE(a.step(0.0, 0.01, tow_at(x0 + 0.01, 1.0, 0.0), error)) << error;
    std::vector<unsigned char> saved(a.state_size());
    a.save_state(saved.data());
    ASSERT_TRUE(a.step(0.01, 0.01, tow_at(x0 + 0.02, 0.0, 0.0), error)) << error;
    CableSimulation b(p);
    ASSERT_TRUE(b.initialize(0.0, tow_at(x0, 0.0, 0.0), error)) << error;
    ASSERT_TRUE(b.restore_state(saved.data(), saved.size(), error)) << error;
    ASSERT_TRUE(b.step(0.01, 0.01, tow_at(x0 + 0.02, 0.0, 0.0), error)) << error;
    EXPECT_EQ(a.outputs().towTension, b.outputs().towTension);
    // the internal strain is among the saved unknowns: a constant-EA line's state does not fit
    UCParams constant = p;
    constant.EAdynamic = 0.0;
    CableSimulation c(constant);
    ASSERT_TRUE(c.initialize(0.0, tow_at(x0, 0.0, 0.0), error)) << error;
    EXPECT_FALSE(c.restore_state(saved.data(), saved.size(), error));
    EXPECT_EQ(error, "saved state has the wrong size for this cable (different nElements or end conditions)");
}

TEST(ViscoelasticLine, TheInternalStrainsAreUnknownsBetweenTheirElementsNodes) {
    UCParams p = taut_rope();
    p.nElements = 4;
    const CableModel visco(p);
    p.EAdynamic = 0.0;
    const CableModel constant(p);
    EXPECT_EQ(visco.n_free(), constant.n_free() + 4);
    EXPECT_EQ(visco.free_bandwidth(), constant.free_bandwidth() + 1);  // banded as before, one wider
    EXPECT_EQ(constant.internal_offset(0), -1);
}

TEST(ViscoelasticLine, ParametersThatMakeNoModelAreRefused) {
    UCParams p = taut_rope();
    EXPECT_EQ(check_params(p), "");
    p.EAdynamic = kEAs;
    EXPECT_EQ(check_params(p).rfind("EAdynamic = 1000000 is outside (1e+06, 1e13] (above EA, the static stiffness)", 0), 0u)
        << check_params(p);
    p = taut_rope();
    p.axialDamping = p.axialDampingDynamic = 0.0;
    EXPECT_NE(check_params(p).find("axialDampingDynamic = 0 is outside"), std::string::npos) << check_params(p);
    p = taut_rope();
    p.nSections = 2;
    p.section[0].length = p.section[1].length = 5.0;
    EXPECT_NE(check_params(p).find("viscoelastic model describes a uniform line"), std::string::npos) << check_params(p);
    // a section's model: section[k].EAdynamic above section[k].EA
    p.EAdynamic = 0.0;
    for (int k = 0; k < 2; ++k) {
        p.section[k].EA = kEAs;
        p.section[k].axialDamping = kDamping;
        p.section[k].nElements = 2;
        p.section[k].diameter = p.diameter;
        p.section[k].massPerLength = p.massPerLength;
    }
    p.section[1].EAdynamic = 0.5 * kEAs;
    EXPECT_EQ(check_params(p).rfind("section[2].EAdynamic = 500000 is outside (1e+06, 1e13] (above its EA", 0), 0u)
        << check_params(p);
    p.section[1].EAdynamic = kEAd;
    EXPECT_EQ(check_params(p), "");
    const CableModel sections(p);
    EXPECT_EQ(sections.internal_offset(0), -1);  // section 1 keeps its constant EA
    EXPECT_EQ(sections.internal_offset(1), -1);
    EXPECT_GE(sections.internal_offset(2), 0);
    EXPECT_GE(sections.internal_offset(3), 0);
    EXPECT_EQ(sections.n_internal(), 2);
}
