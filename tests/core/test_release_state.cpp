// A held end that lets go (docs/line_failure.md) carries each element's state over, not only its nodes': the
// internal strain of a viscoelastic element, the slow strain and the history (the largest mean tension so far) of a
// Syrope element, element by element, mirrored where the tow end lets go and the line is run from its far end. So
// the axial tension in every element is the same just after the release as just before: only the end's force goes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "api/cable_api.h"
#include "line/simulation.h"
#include "model/cable_model.h"
#include "model/params.h"
#include "terms/hermite_element.h"
#include "terms/syrope.h"

using namespace uc;

namespace {

// A heavy fibre line of six elements, 100 m, from the tow point at the origin to its anchor 20 m across and 98.8 m
// down (0.8 % stretched): its tension grows by its submerged weight (about 5.8e5 N) from the anchor to the tow
// point, so each element's internal strain is its own.
UCParams heavy_line() {
    UCParams p;
    uc_params_default(&p);
    p.length = 100.0;
    p.nElements = 6;
    p.diameter = 0.1;
    p.massPerLength = 600.0;
    p.waterDepth = 300.0;
    p.enableSeabed = 0;
    p.enableCompression = 1;
    p.bottomEnd = UC_BOTTOM_ANCHORED;
    p.anchor[0] = 20.0;
    p.anchor[1] = 0.0;
    p.anchor[2] = -98.776;
    return p;
}

// Viscoelastic: static EA 1e8 N, dynamic 3e8 N, the internal strain relaxing in about 0.1 s (lagging the tow).
UCParams viscoelastic_line() {
    UCParams p = heavy_line();
    p.EA = 1e8;
    p.EAdynamic = 3e8;
    p.axialDamping = 2e7;
    p.axialDampingDynamic = 2e7;
    return p;
}

// Syrope (LINEAR, k1 0.5): the original working curve 1e8 eps, Tmax0 1e6 N, Tmean0 5e5 N; pulled above Tmax0 at
// the top, the history of the upper elements grows, that of the lower ones does not.
UCParams syrope_line() {
    UCParams p = heavy_line();
    p.axialCurvePoints = 2;
    p.axialCurveStrain[0] = 0.0;
    p.axialCurveStrain[1] = 0.06;
    p.axialCurveTension[0] = 0.0;
    p.axialCurveTension[1] = 0.06 * 1e8;
    p.EAdynamic = 4e8;
    p.EAdynamicSlope = 20.0;
    p.axialDamping = 2e7;
    p.axialDampingDynamic = 2e7;
    p.syropeWorkingCurve = kSyropeLinear;
    p.syropeK1 = 0.5;
    p.syropeTensionMax0 = 1e6;
    p.syropeTensionMean0 = 5e5;
    return p;
}

UCInputs tow_at(double z, double vz) {
    UCInputs in{};
    in.tow[2] = z;
    in.towVelocity[2] = vz;
    return in;
}

using Tensions = std::vector<std::array<double, ElementTables::nAxial>>;

// Every element's axial tension at its axial points, from the state the line's outputs were made from.
Tensions element_tensions(const CableSimulation& sim) {
    const CableModel& m = sim.model();
    const double *X = sim.global_coordinates().data(), *Xd = sim.global_rates().data();
    const double* history = sim.syrope_history().empty() ? nullptr : sim.syrope_history().data();
    Tensions T(m.n_elements());
    for (int e = 0; e < m.n_elements(); ++e) {
        double material[12];
        axial_tensions(m.tables(e), m.element_axial(e, X, Xd, history), X + m.element_offset(e),
                       m.element_velocities(e, X, Xd, material), T[e].data());
    }
    return T;
}

// Each element's internal strain and its rate, in the integrator's unknowns.
std::vector<std::array<double, 2>> internal_strains(const CableSimulation& sim) {
    std::vector<double> q, v, a;
    sim.free_state(q, v, a);
    std::vector<std::array<double, 2>> strains;
    for (int e = 0; e < sim.model().n_elements(); ++e) {
        const int g = sim.model().internal_offset(e);
        EXPECT_GE(g, 0) << "element " << e << " has an internal strain";
        const int j = g < 0 ? -1 : sim.model().free_index(g);
        if (j >= 0) strains.push_back({q[j], v[j]});
    }
    return strains;
}

// The line pulled up 0.1 m in 0.5 s (its internal strains behind their equilibrium), then the far end (flip false)
// or the tow end (flip true) lets go: the elements' internal strains, history and axial tensions just after against
// just before (element e after is element n - 1 - e before where the tow end let go, its axial points reversed).
void release_keeps_the_elements_state(const UCParams& p, bool flip, const char* name) {
    SCOPED_TRACE(std::string(name) + (flip ? ", the tow end lets go" : ", the far end lets go"));
    CableSimulation sim(p);
    sim.prepare_release(p, flip);
    std::string error;
    ASSERT_TRUE(sim.initialize(0.0, tow_at(0.0, 0.0), error)) << error;
    const std::vector<double> history0 = sim.syrope_history();
    const double h = 0.05, speed = 0.2;
    double t = 0.0;
    for (int s = 0; s < 10; ++s, t += h) ASSERT_TRUE(sim.step(t, h, tow_at(speed * t, speed), error)) << error;
    const Tensions before = element_tensions(sim);
    const auto strainsBefore = internal_strains(sim);
    const std::vector<double> historyBefore = sim.syrope_history();
    const double endBefore = flip ? sim.outputs().towTension : sim.outputs().endTension;
    const int n = sim.model().n_elements();
    ASSERT_EQ(static_cast<int>(strainsBefore.size()), n);
    // (the state is worth carrying: the strains differ along the line and, for Syrope, the history grew unevenly)
    EXPECT_GT(std::abs(strainsBefore.front()[0] - strainsBefore.back()[0]), 1e-4);
    if (!historyBefore.empty()) {
        EXPECT_GT(historyBefore.front(), history0.front() * (1.0 + 1e-3)) << "the top element's history grew";
        EXPECT_EQ(historyBefore.back(), history0.back()) << "the bottom element's did not";
    }

    ASSERT_TRUE(sim.release(t, error)) << error;
    ASSERT_EQ(sim.released(), flip ? 2 : 1);
    const Tensions after = element_tensions(sim);
    const auto strainsAfter = internal_strains(sim);
    const std::vector<double> historyAfter = sim.syrope_history();
    ASSERT_EQ(static_cast<int>(strainsAfter.size()), n);
    ASSERT_EQ(historyAfter.size(), historyBefore.size());
    double scale = 0.0, jump = 0.0;
    for (const auto& element : before)
        for (double T : element) scale = std::max(scale, std::abs(T));
    for (int e = 0; e < n; ++e) {
        const int h0 = flip ? n - 1 - e : e;
        EXPECT_EQ(strainsAfter[e][0], strainsBefore[h0][0]) << "element " << e << "'s internal strain";
        EXPECT_EQ(strainsAfter[e][1], strainsBefore[h0][1]) << "element " << e << "'s internal strain rate";
        if (!historyAfter.empty()) {
            EXPECT_EQ(historyAfter[e], historyBefore[h0]) << "element " << e << "'s history";
        }
        for (int k = 0; k < ElementTables::nAxial; ++k) {
            const double T0 = before[h0][flip ? ElementTables::nAxial - 1 - k : k], T1 = after[e][k];
            jump = std::max(jump, std::abs(T1 - T0));
            // round-off: the strain from a tangent negated, the same velocities
            EXPECT_NEAR(T1, T0, 1e-9 * scale) << "element " << e << ", axial point " << k;
        }
    }
    EXPECT_LT(sim.outputs().endTension, 1e-9 * scale) << "the released end's force, gone";
    std::printf("%s, %s end lets go: the largest jump of an element's axial tension %.3g N (of %.3g N); the end's "
                "tension %.4g N before, %.3g N after\n", name, flip ? "tow" : "far", jump, scale, endBefore,
                sim.outputs().endTension);
    const std::string key = std::string("largest tension jump [N], ") + name + (flip ? ", tow end" : ", far end");
    ::testing::Test::RecordProperty(key, std::to_string(jump));
}

}  // namespace

TEST(ReleaseState, AViscoelasticLineKeepsItsInternalStrainsWhenAnEndLetsGo) {
    release_keeps_the_elements_state(viscoelastic_line(), false, "viscoelastic");
    release_keeps_the_elements_state(viscoelastic_line(), true, "viscoelastic");
}

TEST(ReleaseState, ASyropeLineKeepsItsSlowStrainsAndHistoryWhenAnEndLetsGo) {
    release_keeps_the_elements_state(syrope_line(), false, "Syrope");
    release_keeps_the_elements_state(syrope_line(), true, "Syrope");
}
