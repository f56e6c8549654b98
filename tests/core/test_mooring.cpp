// Mooring lines: the elastic catenary with seabed touchdown (Irvine) against the core's
// equilibrium, the current profile and the external far end.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "api/cable_api.h"
#include "line/simulation.h"

using namespace uc;

namespace {

using uc::kPi;

// Elastic catenary lying on a frictionless seabed: a grounded part of unstretched length Lb
// (horizontal tension H throughout) and a suspended part Ls = L - Lb rising from the touchdown
// point with zero slope to the fairlead at height h and horizontal distance X from the anchor.
// w is the wet weight per unstretched length. Independent of the FE model.
struct Catenary {
    double H, suspended, fairleadTension;
};

double suspended_height(double H, double w, double EA, double Ls) {
    const double a = w * Ls / H;
    return H / w * (std::sqrt(1 + a * a) - 1) + w * Ls * Ls / (2 * EA);
}

double suspended_span(double H, double w, double EA, double Ls) {
    return H / w * std::asinh(w * Ls / H) + H * Ls / EA;
}

Catenary touchdown_catenary(double L, double w, double EA, double X, double h) {
    // For a given H, the suspended length follows from the height (monotonic in Ls); H then
    // from the horizontal span (bisection in log H).
    auto suspended_for = [&](double H) {
        double lo = 0, hi = L;
        for (int i = 0; i < 200; ++i) {
            const double mid = 0.5 * (lo + hi);
            (suspended_height(H, w, EA, mid) < h ? lo : hi) = mid;
        }
        return 0.5 * (lo + hi);
    };
    double lo = std::log(1e-3 * w * L), hi = std::log(1e3 * w * L);
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi), H = std::exp(mid);
        const double Ls = suspended_for(H);
        const double span = (L - Ls) * (1 + H / EA) + suspended_span(H, w, EA, Ls);
        (span < X ? lo : hi) = mid;
    }
    const double H = std::exp(0.5 * (lo + hi));
    const double Ls = suspended_for(H);
    return {H, Ls, std::hypot(H, w * Ls)};
}

// The mooring scene: a chain-like line, fairlead 70 m deep in 320 m of water.
UCParams chain(int nElements) {
    UCParams p;
    uc_params_default(&p);
    p.length = 900;
    p.diameter = 0.0766;
    p.massPerLength = 113;
    p.EA = 7.5e8;
    p.EI = 0;
    p.enableBending = 0;
    p.Cdn = 2.4;
    p.Cdt = 0.2;
    p.nElements = nElements;
    p.bottomEnd = UC_BOTTOM_ANCHORED;
    p.anchor[0] = -850;
    p.anchor[1] = 0;
    p.anchor[2] = -320;
    p.enableSeabed = 1;
    p.waterDepth = 320;
    // Stiff enough that the grounded chain sinks only w/k = 1 mm into the seabed.
    p.seabedStiffness = 1e6;
    return p;
}

}  // namespace

namespace {

struct TouchdownResult {
    double tensionError;   // relative
    double groundedError;  // relative to the length
};

TouchdownResult touchdown_errors(int nElements) {
    UCParams p = chain(nElements);
    CableSimulation sim(p);
    UCInputs in{};
    in.tow[2] = -70;
    std::string error;
    if (!sim.initialize(0.0, in, error)) ADD_FAILURE() << error;
    const double A = kPi * p.diameter * p.diameter / 4;
    const double w = (p.massPerLength - p.waterDensity * A) * p.gravity;
    const Catenary exact = touchdown_catenary(p.length, w, p.EA, 850.0, 250.0);
    const UCOutputs& out = sim.outputs();
    const double grounded = p.length - out.touchdownArcLength;
    // The FMU's touchdown is where the line comes within half a diameter of the seabed: the exact
    // catenary's point at that height, a few metres up from its tangent point.
    double lo = 0.0, hi = exact.suspended;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (suspended_height(exact.H, w, p.EA, mid) < 0.5 * p.diameter ? lo : hi) = mid;
    }
    const double groundedExact = p.length - exact.suspended + 0.5 * (lo + hi);
    return {out.towTension / exact.fairleadTension - 1, (grounded - groundedExact) / p.length};
}

}  // namespace

TEST(Catenary, TouchdownMatchesTheElasticCatenary) {
    // With a node at the touchdown (the mesh graded by the static profile) the suspended elements
    // hold a smooth catenary and the grounded ones lie straight: the fairlead tension is as exact as
    // a suspended line's. The grounded length is then set by the contact model, not the mesh: the
    // chain sinks w/k = 1 mm and the contact's smoothing band is 4 mm, and where the catenary rises
    // z = sigma^2 / 2a (a = H / w, about 300 m) past the half-diameter height that defines the
    // touchdown output, 5 mm of height move that point by a dz / sigma = 0.3 m = 3.5e-4 L.
    // On 10 elements of 90 m the output's sampling of the rising part adds to that (measured
    // 9e-4 L); the tension stays within 1e-4 (measured 2e-5).
    for (int n : {10, 20, 40}) {
        const TouchdownResult r = touchdown_errors(n);
        EXPECT_LT(std::abs(r.tensionError), 1e-4) << n << " elements";
        if (n >= 20) {
            EXPECT_LT(std::abs(r.groundedError), 3.5e-4) << n << " elements";
        }
    }
}

TEST(Start, InWavesIsTheEquilibriumInCalmWater) {
    // Waves have no static equilibrium: the line starts where it rests in the steady water (here calm)
    // and the waves act on it from t0 on. A swell of 20 s reaching the chain's upper part (0.5 m/s at
    // the fairlead), along the line and across it: the start's shape equals calm water's to the statics'
    // round-off (its tensions, from the elements' reactions, also carry the waves' load at t0 and the
    // line's acceleration), and the waves then move the line.
    for (double direction : {0.0, 0.5 * kPi}) {
        UCParams calm = chain(20);
        UCParams waves = calm;
        waves.wavesMode = 1;
        waves.wavesHeight = 6.0;
        waves.wavesPeriod = 20.0;
        waves.wavesDirection = direction;
        waves.wavesStretching = 1;
        CableSimulation still(calm), moving(waves);
        UCInputs in{};
        in.tow[2] = -70;
        std::string error;
        ASSERT_TRUE(still.initialize(0.0, in, error)) << error;
        ASSERT_TRUE(moving.initialize(0.0, in, error)) << error;
        const UCOutputs &a = still.outputs(), &b = moving.outputs();
        const double T0 = a.towTension;
        for (int k = 0; k < UC_NUM_STATIONS; ++k) {
            const double moved = std::hypot(b.shapeX[k] - a.shapeX[k], b.shapeY[k] - a.shapeY[k], b.shapeZ[k] - a.shapeZ[k]);
            EXPECT_LT(moved, 1e-9 * calm.length) << direction << " station " << k + 1;
        }
        ASSERT_TRUE(still.step(0.0, 5.0, in, error)) << error;
        ASSERT_TRUE(moving.step(0.0, 5.0, in, error)) << error;
        EXPECT_GT(std::abs(moving.outputs().towTension - still.outputs().towTension), 1e-4 * T0) << direction;
    }
}
