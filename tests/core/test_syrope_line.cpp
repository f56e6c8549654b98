// The Syrope model of a polyester rope (syrope.*, axialCurve.* its original working curve, EAdynamic and
// EAdynamicSlope its dynamic stiffness; docs/model.md, "Syrope fibre-rope model"): the working curves' closed
// forms, the element's couplings against finite differences, a ramp then unload and reload against the
// hand-computed curves, the history in the saved state (carried forward into a fresh instance, and set back
// before a peak), and the parameters' checks.
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
#include "weightless_rope.h"

using namespace uc;

namespace {

// A straight original working curve T = 1e8 eps (to 6 %), so that every curve has a closed form; a dynamic
// stiffness alpha + beta T well above it.
constexpr double kOwcStiffness = 1e8, kAlpha = 4e8, kBeta = 20.0;
constexpr double kTmax0 = 1e6, kTmean0 = 5e5;

SyropeProps rope(int form, double k1, double k2) {
    SyropeProps s;
    s.form = form;
    s.k1 = k1;
    s.k2 = k2;
    s.alpha = kAlpha;
    s.beta = kBeta;
    s.tensionMax0 = kTmax0;
    s.tensionMean0 = kTmean0;
    const double eps[2] = {0.0, 0.06}, T[2] = {0.0, 0.06 * kOwcStiffness};
    std::string error;
    EXPECT_TRUE(AxialCurve::build(eps, T, 2, s.owc, error)) << error;
    return s;
}

double dynamic_strain(double T) { return std::log1p(kBeta * T / kAlpha) / kBeta; }

// A weightless, dragless rope of one element between an anchor at the origin and the tow point on +x, with
// little damping (relaxation time (c + c_d) / alpha = 0.04 ms): its slow strain follows the curves.
constexpr double kLength = 10.0;

UCParams syrope_rope(int form, double k1, double k2) {
    UCParams p = weightless_rope(kLength, 0.1, 1.0);
    p.axialCurvePoints = 2;
    p.axialCurveStrain[0] = 0.0;
    p.axialCurveStrain[1] = 0.06;
    p.axialCurveTension[0] = 0.0;
    p.axialCurveTension[1] = 0.06 * kOwcStiffness;
    p.EAdynamic = kAlpha;
    p.EAdynamicSlope = kBeta;
    p.axialDamping = 1e4;
    p.axialDampingDynamic = 5e3;
    p.syropeWorkingCurve = form;
    p.syropeK1 = k1;
    p.syropeK2 = k2;
    p.syropeTensionMax0 = kTmax0;
    p.syropeTensionMean0 = kTmean0;
    p.enableCompression = 1;
    return p;
}

UCInputs tow_at(double x, double v) {
    UCInputs in{};
    in.tow[0] = x;
    in.towVelocity[0] = v;
    return in;
}

}  // namespace

TEST(SyropeCurves, WorkingCurvesAreTheFormulasAndTheTensionInvertsTheSlowStrain) {
    // Tmax0 = 1e6 N on the straight OWC: eps_max = 0.01. At half the top's strain span (xi = 0.5), by hand:
    // LINEAR k1 0.5: eps_min 0.005, T = 0.5 Tmax; LINEAR k1 2e8 (a stiffness): eps_min = 0.01 - 1e6 / 2e8;
    // QUADRATIC k1 0.2, k2 0.6: T = Tmax 0.5 (0.6 0.5 + 0.4) = 0.35 Tmax; EXP k1 0.2, k2 1.5: T = Tmax (1 -
    // e^0.75) / (1 - e^1.5).
    struct Case {
        SyropeProps s;
        double foot, u;  // eps_min, T / Tmax at xi = 0.5
    };
    const Case cases[] = {{rope(kSyropeLinear, 0.5, 0.0), 0.005, 0.5},
                          {rope(kSyropeLinear, 2e8, 0.0), 0.01 - 1e6 / 2e8, 0.5},
                          {rope(kSyropeQuadratic, 0.2, 0.6), 0.002, 0.35},
                          {rope(kSyropeExp, 0.2, 1.5), 0.002, (1.0 - std::exp(0.75)) / (1.0 - std::exp(1.5))}};
    for (const Case& c : cases) {
        ASSERT_EQ(syrope_check(c.s, "syrope."), "") << syrope_form_name(c.s.form);
        const double top = syrope_initial_history(c.s);
        EXPECT_NEAR(top, 0.01, 1e-15);
        EXPECT_NEAR(syrope_working_strain(c.s, top, 0.0), c.foot, 1e-15) << syrope_form_name(c.s.form);
        EXPECT_NEAR(syrope_working_strain(c.s, top, c.u * kTmax0), 0.5 * (c.foot + 0.01), 1e-14) << syrope_form_name(c.s.form);
        EXPECT_NEAR(syrope_working_strain(c.s, top, kTmax0), 0.01, 1e-15);
        // the slow strain z = eps_c(T) - eps_d(T) and back, on the working curve and on the OWC above Tmax
        for (double T : {0.05 * kTmax0, 0.3 * kTmax0, 0.8 * kTmax0, kTmax0, 1.7 * kTmax0, 4.0 * kTmax0}) {
            const double z = syrope_slow_strain(c.s, top, T);
            const double eps = T <= kTmax0 ? syrope_working_strain(c.s, top, T) : T / kOwcStiffness;
            EXPECT_NEAR(z, eps - dynamic_strain(T), 1e-15);
            const SyropeTension t = syrope_tension(c.s, top, z);
            EXPECT_NEAR(t.tension, T, 1e-7 * kTmax0) << syrope_form_name(c.s.form) << " T " << T;
            EXPECT_NEAR(t.curveStrain, eps, 1e-14);
            EXPECT_EQ(t.original, T > kTmax0 * (1.0 + 1e-12));
            // dT/dz against central differences
            const double h = 1e-9;
            const double fd = (syrope_tension(c.s, top, z + h).tension - syrope_tension(c.s, top, z - h).tension) / (2 * h);
            if (T != kTmax0) {  // (the slope jumps at the top, from the working curve's to the OWC's)
                EXPECT_NEAR(t.slope, fd, 1e-5 * std::abs(fd)) << syrope_form_name(c.s.form) << " T " << T;
            }
        }
        // the history: a slow strain above the top's moves the top to the OWC's strain there, one below leaves it
        const double zUp = syrope_slow_strain(c.s, top, 2e6);
        EXPECT_NEAR(syrope_history_after(c.s, top, zUp), 0.02, 1e-14);
        EXPECT_EQ(syrope_history_after(c.s, top, syrope_slow_strain(c.s, top, 0.5e6)), top);
    }
}

TEST(SyropeElement, CouplingsAreTheDerivativesOfTheResiduals) {
    const ElementTables e = make_element_tables(2.0, 3, 3);
    const SyropeProps s = rope(kSyropeQuadratic, 0.25, 0.8);
    ViscoProps v{kOwcStiffness, kAlpha, kBeta, 5e3};
    AxialProps p{kOwcStiffness, 1e4};
    p.visco = &v;
    p.syrope = &s;
    p.history = syrope_initial_history(s);
    double X[12] = {0, 0, 0, 1.01, 0.02, 0, 2.02, 0.05, 0.01, 0.99, 0.03, 0.01};
    double Xd[12] = {0, 0, 0, 0.1, -0.2, 0, 0.3, 0.1, 0, -0.1, 0.2, 0.05};
    // on the working curve (z below the top's), and on the OWC above it
    for (double z : {syrope_slow_strain(s, p.history, 0.6e6), syrope_slow_strain(s, p.history, 1.5e6)}) {
        p.internal[0] = z;
        p.internal[1] = 0.03;
        ViscoJacobian J;
        visco_jacobian(e, p, X, Xd, J);
        const double h = 1e-9;
        double Rp[12], Rm[12];
        for (int which = 0; which < 2; ++which) {
            AxialProps up = p, down = p;
            up.internal[which] += h;
            down.internal[which] -= h;
            for (int a = 0; a < 12; ++a) Rp[a] = Rm[a] = 0.0;
            add_axial_force(e, up, X, Xd, Rp);
            add_axial_force(e, down, X, Xd, Rm);
            const double* analytic = which == 0 ? J.dR_de1 : J.dR_dr1;
            for (int a = 0; a < 12; ++a)
                EXPECT_NEAR(analytic[a], (Rp[a] - Rm[a]) / (2 * h), 1e-5 * kAlpha) << "dR/d" << (which ? "r1 " : "e1 ") << a;
            const double dI = (visco_residual(e, up, X, Xd) - visco_residual(e, down, X, Xd)) / (2 * h);
            EXPECT_NEAR(which == 0 ? J.dI_de1 : J.dI_dr1, dI, 1e-5 * kAlpha) << "dI/d" << (which ? "r1" : "e1");
        }
        for (int b = 0; b < 12; ++b) {
            for (int rate = 0; rate < 2; ++rate) {
                const double hx = 1e-7;
                double xp[12], xm[12];
                const double* base = rate ? Xd : X;
                for (int k = 0; k < 12; ++k) xp[k] = xm[k] = base[k];
                xp[b] += hx;
                xm[b] -= hx;
                const double dI = rate ? (visco_residual(e, p, X, xp) - visco_residual(e, p, X, xm)) / (2 * hx)
                                       : (visco_residual(e, p, xp, Xd) - visco_residual(e, p, xm, Xd)) / (2 * hx);
                EXPECT_NEAR(rate ? J.dI_dXd[b] : J.dI_dX[b], dI, 1e-6 * kAlpha) << "dI/dX" << (rate ? "d " : " ") << b;
            }
        }
    }
}

TEST(SyropeLine, ARampThenUnloadFollowsTheOriginalThenTheWorkingCurve) {
    // LINEAR k1 0.5, Tmax0 1e6 N (eps_max 0.01), Tmean0 5e5 N: the rope starts at the strain of Tmean0 on the
    // working curve, 0.0075. Stretched slowly (1 s ramps against a relaxation time of 0.04 ms, so the slow strain
    // sits on the curves and the dashpot adds c eps' = 1e4 x 0.02 / s = 200 N):
    //   to 0.03: the working curve of Tmax0 to 0.01 (T = Tmax0 (eps - 0.005) / 0.005), then the OWC, 1e8 eps;
    //   back to 0.02: the working curve of Tmax = 3e6 N, eps_min = 0.015: T = 3e6 (eps - 0.015) / 0.015;
    //   up to 0.03 again: the same curve, then the OWC from 3e6 N on, to 0.035.
    const UCParams p = syrope_rope(kSyropeLinear, 0.5, 0.0);
    ASSERT_EQ(check_params(p), "");
    CableSimulation sim(p);
    std::string error;
    const double e0 = 0.0075;
    ASSERT_TRUE(sim.initialize(0.0, tow_at(kLength * (1.0 + e0), 0.0), error)) << error;
    EXPECT_NEAR(sim.outputs().towTension, kTmean0, 1e-6 * kTmean0);
    auto expected = [](double eps, double Tmax) {
        if (eps >= Tmax / kOwcStiffness) return kOwcStiffness * eps;
        const double top = Tmax / kOwcStiffness, foot = 0.5 * top;
        return eps <= foot ? 0.0 : Tmax * (eps - foot) / (top - foot);
    };
    const double legs[][2] = {{e0, 0.03}, {0.03, 0.02}, {0.02, 0.035}};
    double Tmax = kTmax0, t = 0.0;
    const int steps = 200;
    double worst = 0.0;
    for (const auto& leg : legs) {
        const double rate = (leg[1] - leg[0]) / 1.0;
        for (int s = 1; s <= steps; ++s) {
            // the inputs at the step's start (the line extrapolates them over the step), the strain at its end
            const double start = leg[0] + (leg[1] - leg[0]) * (s - 1) / steps, eps = leg[0] + (leg[1] - leg[0]) * s / steps;
            ASSERT_TRUE(sim.step(t, 1.0 / steps, tow_at(kLength * (1.0 + start), kLength * rate), error)) << error;
            t += 1.0 / steps;
            if (s < 5) continue;  // (the tow point's start of each leg: its velocity jumps)
            const double T = expected(eps, Tmax), got = sim.outputs().towTension;
            worst = std::max(worst, std::abs(got - T - 1e4 * rate));
            EXPECT_NEAR(got, T + 1e4 * rate, 2e-3 * 3e6) << "strain " << eps << ", Tmax " << Tmax;
            Tmax = std::max(Tmax, T);
        }
    }
    EXPECT_NEAR(Tmax, 3.5e6, 1.0);
    // the history: the top of the working curve at the largest strain of the OWC reached
    ASSERT_EQ(sim.syrope_history().size(), 1u);
    EXPECT_NEAR(sim.syrope_history()[0], 0.035, 1e-5);
    RecordProperty("largest difference [N]", std::to_string(worst));
}

TEST(SyropeLine, ASavedStateCarriesTheHistory) {
    // Loaded past Tmax0, saved, then unloaded: a fresh instance restored from the state unloads on the same
    // working curve (the one of the new Tmax), bit for bit; without the history it would take Tmax0's.
    const UCParams p = syrope_rope(kSyropeExp, 0.2, 1.5);
    ASSERT_EQ(check_params(p), "");
    const double e0 = syrope_working_strain(rope(kSyropeExp, 0.2, 1.5), 0.01, kTmean0);
    CableSimulation a(p);
    std::string error;
    ASSERT_TRUE(a.initialize(0.0, tow_at(kLength * (1.0 + e0), 0.0), error)) << error;
    double t = 0.0;
    for (int s = 0; s < 50; ++s, t += 0.02)
        ASSERT_TRUE(a.step(t, 0.02, tow_at(kLength * (1.0 + e0 + (0.025 - e0) * s / 50), kLength * (0.025 - e0)), error)) << error;
    std::vector<unsigned char> saved(a.state_size());
    a.save_state(saved.data());
    CableSimulation b(p);
    ASSERT_TRUE(b.initialize(0.0, tow_at(kLength * (1.0 + e0), 0.0), error)) << error;
    ASSERT_TRUE(b.restore_state(saved.data(), saved.size(), error)) << error;
    EXPECT_EQ(b.syrope_history(), a.syrope_history());
    EXPECT_GT(a.syrope_history()[0], 0.0249);
    for (int s = 0; s < 20; ++s, t += 0.02) {
        const UCInputs in = tow_at(kLength * (1.0 + 0.025 - 0.005 * s / 20), -kLength * 0.25);
        ASSERT_TRUE(a.step(t, 0.02, in, error)) << error;
        ASSERT_TRUE(b.step(t, 0.02, in, error)) << error;
        EXPECT_EQ(a.outputs().towTension, b.outputs().towTension);
    }
    // on the working curve of Tmax = 2.5e6 N, well below the OWC's 2e6 N at strain 0.02
    EXPECT_LT(a.outputs().towTension, 1.9e6);
    // a state of another version is refused naming what the versions added
    std::vector<unsigned char> old = saved;
    const std::uint32_t version = 14;
    std::memcpy(old.data() + sizeof(std::uint32_t), &version, sizeof version);
    EXPECT_FALSE(b.restore_state(old.data(), old.size(), error));
    EXPECT_NE(error.find("format version 14, this FMU reads 17"), std::string::npos) << error;
    EXPECT_NE(error.find("15 the Syrope elements' history"), std::string::npos) << error;
}

TEST(SyropeLine, RestoringAStateFromBeforeAPeakTakesTheHistoryBack) {
    // LINEAR k1 0.5 (the curves of the ramp test above): stretched from Tmean0's strain 0.0075 to 0.009, below the
    // top of Tmax0's working curve (0.01), saved; on to 0.03 (the history grows to it), then the state of 0.009 set
    // back into the same instance: its history is Tmax0's again, and unloading to 0.006 runs bit for bit as a twin
    // that never passed the peak (kept at the peak's history, 0.03, it unloads on that working curve: 1.23e6 N
    // against 7.5e5 N at the first step).
    const UCParams p = syrope_rope(kSyropeLinear, 0.5, 0.0);
    ASSERT_EQ(check_params(p), "");
    const double e0 = 0.0075, h = 0.02;
    CableSimulation a(p), twin(p);
    std::string error;
    ASSERT_TRUE(a.initialize(0.0, tow_at(kLength * (1.0 + e0), 0.0), error)) << error;
    ASSERT_TRUE(twin.initialize(0.0, tow_at(kLength * (1.0 + e0), 0.0), error)) << error;
    // the strain from `from` to `to` in n steps of h from time t (the inputs at each step's start)
    auto leg = [&](CableSimulation& s, double from, double to, int n, double& t) {
        for (int k = 0; k < n; ++k, t += h)
            ASSERT_TRUE(s.step(t, h, tow_at(kLength * (1.0 + from + (to - from) * k / n), kLength * (to - from) / (n * h)),
                               error)) << error;
    };
    double ta = 0.0, tt = 0.0;
    leg(a, e0, 0.009, 20, ta);
    leg(twin, e0, 0.009, 20, tt);
    ASSERT_EQ(a.syrope_history().size(), 1u);
    const std::vector<double> before = a.syrope_history();
    EXPECT_NEAR(before[0], 0.01, 1e-12);  // Tmax0's: not passed yet
    std::vector<unsigned char> saved(a.state_size()), twinSaved(twin.state_size());
    a.save_state(saved.data());
    twin.save_state(twinSaved.data());  // (a save makes the next step evaluate a new Jacobian: the twin's too)
    EXPECT_TRUE(saved == twinSaved);
    const double tSaved = ta;
    leg(a, 0.009, 0.03, 50, ta);
    EXPECT_GT(a.syrope_history()[0], 0.029);  // the peak moved the history
    ASSERT_TRUE(a.restore_state(saved.data(), saved.size(), error)) << error;
    EXPECT_EQ(a.syrope_history(), before);
    ta = tSaved;
    for (int k = 0; k < 20; ++k, ta += h, tt += h) {
        const UCInputs in = tow_at(kLength * (1.0 + 0.009 - 0.003 * k / 20), -kLength * 0.003 / (20 * h));
        ASSERT_TRUE(a.step(ta, h, in, error)) << error;
        ASSERT_TRUE(twin.step(tt, h, in, error)) << error;
        ASSERT_EQ(a.outputs().towTension, twin.outputs().towTension) << "step " << k;
    }
    EXPECT_GT(a.outputs().towTension, 1e5);  // on Tmax0's working curve, T = 2e8 (0.006 - 0.005) less the dashpot
    std::vector<unsigned char> bytesA(a.state_size()), bytesTwin(twin.state_size());
    a.save_state(bytesA.data());
    twin.save_state(bytesTwin.data());
    EXPECT_TRUE(bytesA == bytesTwin) << "the set-back line saves other bytes than its twin";
}

TEST(SyropeLine, ParametersThatMakeNoRopeAreRefusedNamingTheField) {
    UCParams p = syrope_rope(kSyropeLinear, 0.5, 0.0);
    EXPECT_EQ(check_params(p), "");
    p.syropeWorkingCurve = kSyropeQuadratic;
    p.syropeK1 = 1.2;
    p.syropeK2 = 0.5;
    EXPECT_NE(check_params(p).find("syrope.k1 = 1.2, syrope.k2 = 0.5: QUADRATIC needs 0 <= k1 < 1 and 0 < k2 <= 1"),
              std::string::npos)
        << check_params(p);
    p.syropeWorkingCurve = kSyropeExp;
    p.syropeK1 = 0.2;
    p.syropeK2 = 0.0;
    EXPECT_NE(check_params(p).find("EXP needs 0 <= k1 < 1 and k2 > 0"), std::string::npos) << check_params(p);
    p = syrope_rope(kSyropeLinear, 0.5, 0.0);
    p.syropeTensionMean0 = 2e6;
    EXPECT_NE(check_params(p).find("syrope.tensionMean0 = 2e+06 N: Tmean0 lies between 0 and Tmax0"), std::string::npos)
        << check_params(p);
    p = syrope_rope(kSyropeLinear, 0.5, 0.0);
    p.axialCurvePoints = 0;
    EXPECT_NE(check_params(p).find("the Syrope model needs its original working curve"), std::string::npos) << check_params(p);
    p = syrope_rope(kSyropeLinear, 0.5, 0.0);
    p.EAdynamic = 0.9e8;  // softer than the OWC's 1e8: the slow strain would fall as the tension rises
    EXPECT_NE(check_params(p).find("stiffer"), std::string::npos) << check_params(p);
}
