// A line on a tension-strain curve (axialCurve.*): a hanging line's static elongation against the closed
// form, the warning beyond the curve, and the parameters' checks.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "api/cable_api.h"
#include "line/simulation.h"
#include "model/cable_model.h"
#include "model/params.h"

using namespace uc;

namespace {

// A soft rope, T = k eps^1.5 sampled every 0.5 % up to 6 %: its top tension hanging 100 m in water
// (w = 29.3 N/m) stretches it about 4 %, well into the curve's bend.
constexpr int kPoints = 12;
constexpr double kPowerLawStiffness = 3.7e5;  // k [N]

UCParams hanging_rope(int elements) {
    UCParams p;
    uc_params_default(&p);
    p.length = 100.0;
    p.nElements = elements;
    p.diameter = 0.05;
    p.massPerLength = 5.0;
    p.bottomEnd = UC_BOTTOM_FREE;
    p.enableSeabed = 0;
    p.axialDamping = 1e3;
    p.axialCurvePoints = kPoints;
    for (int k = 0; k < kPoints; ++k) {
        const double eps = 0.005 * (k + 1);
        p.axialCurveStrain[k] = eps;
        p.axialCurveTension[k] = kPowerLawStiffness * std::pow(eps, 1.5);
    }
    return p;
}

double submerged_weight(const UCParams& p) {
    return (p.massPerLength - p.waterDensity * kPi * p.diameter * p.diameter / 4.0) * p.gravity;
}

// Closed form: at rest the tension at s (from the top) is the weight below, w (L - s), so the elongation
// is int_0^L eps(w (L - s)) ds = (1 / w) int_0^{wL} eps(T) dT, with eps the curve inverted (Simpson's rule
// on 20000 intervals: converged to 1e-12 of it).
double closed_form_elongation(const UCParams& p) {
    AxialCurve curve;
    std::string error;
    EXPECT_TRUE(AxialCurve::build(p.axialCurveStrain, p.axialCurveTension, p.axialCurvePoints, curve, error));
    const double w = submerged_weight(p), top = w * p.length;
    const int n = 20000;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double factor = i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += factor * curve.strain_at(top * i / n);
    }
    return sum * (top / n) / 3.0 / w;
}

double static_elongation(const UCParams& p) {
    CableSimulation sim(p);
    std::string error;
    UCInputs in{};
    EXPECT_TRUE(sim.initialize(0.0, in, error)) << error;
    return -sim.outputs().endPosition[2] - p.length;
}

}  // namespace

TEST(AxialCurveLine, HangingRopeStretchesAsTheClosedFormSays) {
    // The element's mean strain carries the curve at its mean tension, not the mean of eps(T) over the
    // element: the error shrinks with the elements (measured +0.053 % at 10, -0.030 % at 20, -0.0017 % at
    // 80; docs/model.md, "Non-linear axial stiffness"); the bounds are a tenth and a twentieth of a percent.
    const UCParams p10 = hanging_rope(10), p20 = hanging_rope(20);
    const double exact = closed_form_elongation(p10);
    const double e10 = static_elongation(p10), e20 = static_elongation(p20);
    EXPECT_GT(exact, 2.0);  // a stretch the curve's bend shapes, not a linear one
    EXPECT_NEAR(e10, exact, 1e-3 * exact) << "10 elements: " << e10 << " m against " << exact << " m";
    EXPECT_NEAR(e20, exact, 5e-4 * exact) << "20 elements: " << e20 << " m against " << exact << " m";
    // The constant EA of the curve's secant would stretch it otherwise: the curve is what the line used.
    const double secant = p10.axialCurveTension[kPoints - 1] / p10.axialCurveStrain[kPoints - 1];
    const double w = submerged_weight(p10);
    EXPECT_GT(std::abs(0.5 * w * p10.length * p10.length / secant - exact), 0.2 * exact);
}

TEST(AxialCurveLine, StretchingBeyondTheCurveWarnsOnce) {
    UCParams p = hanging_rope(10);
    p.axialCurvePoints = 6;  // up to 3 %: the hanging rope passes it at its top
    CableSimulation sim(p);
    std::string error;
    UCInputs in{};
    ASSERT_TRUE(sim.initialize(0.0, in, error)) << error;
    const std::string first = sim.take_event();
    EXPECT_NE(first.find("warning: at t = 0 s the line stretches"), std::string::npos) << first;
    EXPECT_NE(first.find("beyond the last point of its tension-strain curve (axialCurve: strain 3 %"), std::string::npos)
        << first;
    ASSERT_TRUE(sim.step(0.0, 0.5, in, error)) << error;
    EXPECT_EQ(sim.take_event().find("tension-strain curve"), std::string::npos);  // once
    // Inside the curve: no warning.
    CableSimulation inside(hanging_rope(10));
    ASSERT_TRUE(inside.initialize(0.0, in, error)) << error;
    EXPECT_EQ(inside.take_event().find("tension-strain curve"), std::string::npos);
}

TEST(AxialCurveLine, ParametersThatMakeNoCurveAreRefused) {
    UCParams p = hanging_rope(10);
    EXPECT_EQ(check_params(p), "");
    p.axialCurveTension[4] = 0.5 * p.axialCurveTension[3];
    EXPECT_EQ(check_params(p).rfind("axialCurve.strain/tension[1..12], point 5 (strain 0.025, tension ", 0), 0u)
        << check_params(p);
    p = hanging_rope(10);
    p.axialCurvePoints = 1;
    EXPECT_EQ(check_params(p), "axialCurvePoints = 1 is outside {0} or [2, 30]: a curve needs two points");
    p = hanging_rope(10);
    p.nSections = 2;
    p.section[0].length = p.section[1].length = 50.0;
    EXPECT_EQ(check_params(p), "axialCurvePoints = 12 is outside {0} with nSections >= 2: the tension-strain "
                               "curve describes a uniform line (nSections 1)");
}
