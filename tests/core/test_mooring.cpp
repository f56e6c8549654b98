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

namespace {

// MoorDyn's wavekin_2 chain (410 m, 1 MN, EA 1.674 GN) between an anchor 400 m off and 50 m down and a fairlead at
// the surface, tension-only, in a uniform current of `current` m/s along x (towards the anchor).
UCParams taut_chain(double current, UCInputs& in) {
    UCParams p = chain(20);  // anchored, without bending, on the seabed
    p.length = 410;
    p.diameter = 0.252;
    p.massPerLength = 390;
    p.EA = 1.674e9;
    p.enableCompression = 0;
    p.Cdn = 1.37;
    p.Cdt = 0.64;
    p.anchor[0] = -400;
    p.anchor[2] = -50;
    p.waterDepth = 50;
    p.seabedStiffness = 25200;  // the deck's kBot x Diam
    in = UCInputs{};
    in.current[0] = current;
    return p;
}

}  // namespace

TEST(StillWaterStart, NoEquilibriumInTheFlowStartsFromStillWaterAtRestAndWarns) {
    // At -5 m/s along x the tangential drag along the chain towards its anchor (about 6.5 kN/m over 410 m) is
    // more than the fairlead's pull: the equilibrium in that flow would push the chain into its anchor, which
    // a chain cannot hold. The line starts from its equilibrium in still water, at rest, the flow acting from
    // t = 0, and the start says so.
    UCInputs flowing, still;
    CableSimulation sim(taut_chain(-5.0, flowing));
    std::string error;
    ASSERT_TRUE(sim.initialize(0.0, flowing, error)) << error;
    const std::string event = sim.take_event();
    EXPECT_NE(event.find("warning: no static equilibrium in the flow at t = 0 s: it would push the line into its anchor"), std::string::npos) << event;
    EXPECT_NE(event.find("(a compression of "), std::string::npos) << event;
    EXPECT_NE(event.find("the line starts from its equilibrium in still water"), std::string::npos) << event;
    EXPECT_NE(event.find("start transient"), std::string::npos) << event;

    CableSimulation calm(taut_chain(0.0, still));
    ASSERT_TRUE(calm.initialize(0.0, still, error)) << error;
    EXPECT_EQ(calm.take_event().find("still water"), std::string::npos);
    // the same shape as the still-water start (the same statics), to round-off, at rest (the tensions, the
    // elements' end forces, also carry the flow's load on the line at rest in it: not compared)
    for (int k = 0; k < UC_NUM_STATIONS; ++k) {
        EXPECT_NEAR(sim.outputs().shapeX[k], calm.outputs().shapeX[k], 1e-9) << k;
        EXPECT_NEAR(sim.outputs().shapeZ[k], calm.outputs().shapeZ[k], 1e-9) << k;
    }
    for (double v : sim.outputs().endVelocity) EXPECT_EQ(v, 0.0);

    // The flow acts from t = 0: within a second the current drags the chain towards its anchor (the middle
    // station moves along -x by centimetres) and unloads the anchor, where the line at rest in still water
    // does not move.
    ASSERT_TRUE(sim.step(0.0, 1.0, flowing, error)) << error;
    ASSERT_TRUE(calm.step(0.0, 1.0, still, error)) << error;
    const int mid = UC_NUM_STATIONS / 2;
    EXPECT_LT(sim.outputs().shapeX[mid] - calm.outputs().shapeX[mid], -0.01);
    EXPECT_LT(sim.outputs().endTension, 0.9 * calm.outputs().endTension);
}

TEST(StillWaterStart, AFlowWithAnEquilibriumStartsInIt) {
    // At -0.5 m/s the drag along the chain (65 N/m) is held by the fairlead: the line starts in the flow, no
    // warning, its anchor tension below the still water's by about the drag along the line.
    UCInputs flowing, still;
    CableSimulation sim(taut_chain(-0.5, flowing)), calm(taut_chain(0.0, still));
    std::string error;
    ASSERT_TRUE(sim.initialize(0.0, flowing, error)) << error;
    ASSERT_TRUE(calm.initialize(0.0, still, error)) << error;
    EXPECT_EQ(sim.take_event().find("still water"), std::string::npos);
    EXPECT_LT(sim.outputs().endTension, calm.outputs().endTension - 1e4);
}

TEST(StillWaterStart, OtherRefusalsStayRefusals) {
    // EA in MN where N is meant, in the flow that has no equilibrium: refused for EA, as without the flow.
    UCInputs flowing;
    UCParams p = taut_chain(-5.0, flowing);
    p.EA = 1674;
    CableSimulation sim(p);
    std::string error;
    EXPECT_FALSE(sim.initialize(0.0, flowing, error));
    EXPECT_EQ(error.find("EA = 1674 N: "), 0u) << error;
    EXPECT_EQ(sim.take_event().find("still water"), std::string::npos);
}

namespace {

// A 13.3 mm chain (1.1 kg/m, EA 7.51 MN, Cdn 2.4) in 30 m of water, from the tow point `top` to the anchor
// `anchor`, in a regular wave 10 m high of 0.4 rad/s (surface water up to a w coth(k h) = 3.1 m/s): the
// chain of MoorDyn's wave_surface deck. Calm with height 0.
UCParams surface_chain(double length, const Vec3& anchor, double waveHeight) {
    UCParams p;
    uc_params_default(&p);
    p.length = length;
    p.diameter = 13.332e-3;
    p.massPerLength = 1.1;
    p.EA = 7.51e6;
    p.EI = 0;
    p.enableBending = 0;
    p.Cdn = 2.4;
    p.Cdt = 1.15;
    p.nElements = 25;
    p.bottomEnd = UC_BOTTOM_ANCHORED;
    for (int i = 0; i < 3; ++i) p.anchor[i] = anchor[i];
    p.waterDepth = 30;
    p.wavesMode = waveHeight > 0.0 ? 1 : 0;
    p.wavesHeight = waveHeight;
    p.wavesPeriod = 2.0 * kPi / 0.4;
    return p;
}

}  // namespace

TEST(WaveZone, AChainHangingThroughTheWavesIsRefusedNamingTheConvention) {
    // 50 m between points 40 m apart, 3 m above the water (wave_surface's line 4): it sags to about 9 m down,
    // some 20 m of it within 5 m of the surface, where each metre may take 1.4 N of buoyancy and about
    // 160 N of wave drag on the wrong side of the moving surface: ten times its tension (about 290 N).
    UCInputs in{};
    in.tow[2] = 3.0;
    std::string error;
    CableSimulation sim(surface_chain(50.0, Vec3(-40.0, 0.0, 3.0), 10.0));
    EXPECT_FALSE(sim.initialize(0.0, in, error));
    EXPECT_NE(error.find("m of the line lie within the waves' reach of the surface (|z| < 5 m;"), std::string::npos) << error;
    EXPECT_NE(error.find("the FMU wets a line below the mean water level z = 0, not below the wave's surface"),
              std::string::npos) << error;
    EXPECT_NE(error.find("refusing the start of a line that runs along the surface (set the waves off (waves.mode 0"),
              std::string::npos) << error;
    // The same line in calm water starts, partly in air.
    CableSimulation calm(surface_chain(50.0, Vec3(-40.0, 0.0, 3.0), 0.0));
    ASSERT_TRUE(calm.initialize(0.0, in, error)) << error;
    EXPECT_GT(calm.outputs().towTension, 200.0);
}

TEST(WaveZone, ALineGoingSteeplyDownFromTheSurfaceStartsInTheSameWaves) {
    // From the surface to an anchor 28 m down and 10 m across, stretched 0.3 % (about 22 kN): some 5.3 m of
    // it lie within the waves' reach, whose misplaced load (about 0.85 kN) is under a tenth of its tension.
    UCInputs in{};
    const Vec3 anchor(-10.0, 0.0, -28.0);
    std::string error;
    CableSimulation sim(surface_chain(anchor.norm() / 1.003, anchor, 10.0));
    ASSERT_TRUE(sim.initialize(0.0, in, error)) << error;
    EXPECT_GT(sim.outputs().towTension, 1.5e4);
}

TEST(WaveZone, ALineHangingFromTheSurfaceThroughTheWavesStartsWithAWarning) {
    // A slack chain from the surface to an anchor 28 m down and 5 m across: about 5 m of it lie within the
    // waves' reach (less than twice the zone's height, 20 m: it goes through the zone, not along it), whose
    // misplaced load (some 800 N) is several times its tension (about 300 N): a start, with a warning.
    UCInputs in{};
    const Vec3 anchor(-5.0, 0.0, -28.0);
    std::string error;
    UCParams p = surface_chain(1.05 * anchor.norm(), anchor, 10.0);
    p.nElements = 50;  // (25 leave the slack chain's anchor force 0.25 % off its tension)
    CableSimulation sim(p);
    ASSERT_TRUE(sim.initialize(0.0, in, error)) << error;
    std::string events;
    for (std::string e = sim.take_event(); !e.empty(); e = sim.take_event()) events += e + "\n";
    EXPECT_NE(events.find("warning: "), std::string::npos) << events;
    EXPECT_NE(events.find("m of the line lie within the waves' reach of the surface (|z| < 5 m;"), std::string::npos)
        << events;
    EXPECT_NE(events.find("near the surface its loads are approximate"), std::string::npos) << events;
}
