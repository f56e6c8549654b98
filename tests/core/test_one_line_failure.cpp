// One line whose far end lets go (docs/line_failure.md, "One line"): the failure.* parameters of the single-line
// model, the release wave of a taut line against its closed form, the break by tension within a step, the step that
// ends at the break, and the state across it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "api/cable_api.h"

namespace {

// A taut horizontal line, neutrally buoyant (no weight, no sag), 200 m unstretched, EA 1e6 N, stretched 1 % (T0 =
// 1e4 N) from the tow point (held) to its anchor 100 m down; no axial damping, added mass or drag: the axial wave's speed
// is c = sqrt(EA / m) along the unstretched length.
constexpr double kL0 = 200.0, kEA = 1.0e6, kStrain = 0.01, kDiameter = 0.1;
const double kMass = 1025.0 * 3.14159265358979323846 / 4.0 * kDiameter * kDiameter;
const double kWaveSpeed = std::sqrt(kEA / kMass);

UCParams taut_line(int elements) {
    UCParams p;
    uc_params_default(&p);
    p.length = kL0;
    p.EA = kEA;
    p.axialDamping = 0.0;  // an elastic line: the wave's front unsmeared
    p.diameter = kDiameter;
    p.massPerLength = kMass;
    p.waterDensity = 1025.0;
    p.Cat = 0.0;
    p.Cdt = 0.0;
    p.nElements = elements;
    p.enableCompression = 0;
    p.enableSeabed = 0;
    p.waterDepth = 300.0;
    p.bottomEnd = UC_BOTTOM_ANCHORED;
    p.anchor[0] = kL0 * (1.0 + kStrain);
    p.anchor[1] = 0.0;
    p.anchor[2] = -100.0;
    return p;
}

UCInputs held_tow() {
    UCInputs in;
    uc_inputs_default(&in);
    in.tow[0] = 0.0;
    in.tow[1] = 0.0;
    in.tow[2] = -100.0;
    return in;
}

UCOutputs outputs(const UCCable* c) {
    UCOutputs o;
    uc_get_outputs(c, &o);
    return o;
}

}  // namespace

TEST(OneLineFailure, TheFailureParametersOfOneLineAreChecked) {
    char msg[512];
    auto refused = [&](UCParams p) {
        UCCable* c = uc_create(&p, msg, sizeof msg);
        uc_free(c);
        return c == nullptr ? std::string(msg) : std::string();
    };
    UCParams p = taut_line(10);
    p.failureLine = 2;
    p.failureTime = 1.0;
    EXPECT_EQ(refused(p).rfind("failure.line = 2: one line (no deck of several lines) is line 1", 0), 0u) << msg;
    p.failureLine = 1;
    p.failurePoint = 4;
    EXPECT_NE(refused(p).find("failure.point = 4: one line has no deck points"), std::string::npos) << msg;
    p.failurePoint = 0;
    p.failureTime = 0.0;
    EXPECT_NE(refused(p).find("failure.time and failure.tension are both 0"), std::string::npos) << msg;
    p.failureTime = 1.0;
    p.bottomEnd = UC_BOTTOM_FREE;
    EXPECT_NE(refused(p).find("bottomEnd = 0: the far end is free already"), std::string::npos) << msg;
    p.bottomEnd = UC_BOTTOM_ANCHORED;
    EXPECT_EQ(refused(p), "") << "accepted";
}

// The anchor lets go at 0.05 s: the release wave runs up the line at c and reaches the tow point L0/c later; until
// then the tow point holds T0, after it nothing (a line in tension only). The impulse the tow point gives the released
// line is T0 L0/c (its momentum then, m L0 times the speed eps c its material takes behind the wave): the tension's
// deficit's centroid (as docs/line_failure.md, Validation a) lies L0/c after the release. The discrete front comes early
// by about one and a half element transits (L0/(n c)) at every mesh (first order in the element length, as the
// anchor's in Validation a): the test allows two.
TEST(OneLineFailure, ATautLineReleasedAtItsAnchorUnloadsItsTowPointOneWaveTransitLater) {
    const int elements = 20;
    UCParams p = taut_line(elements);
    p.failureLine = 1;
    const double release = 0.05, transit = kL0 / kWaveSpeed, h = 0.0025;
    p.failureTime = release;
    char msg[512];
    UCCable* c = uc_create(&p, msg, sizeof msg);
    ASSERT_NE(c, nullptr) << msg;
    const UCInputs in = held_tow();
    ASSERT_EQ(uc_initialize(c, 0.0, &in, msg, sizeof msg), 0) << msg;
    const double T0 = outputs(c).towTension;
    EXPECT_NEAR(T0, kEA * kStrain, 1e-3 * kEA * kStrain);
    const double until = release + 1.35 * transit;
    double deficit = 0.0, t = 0.0, last = T0;
    char event[512] = "";
    std::string events;
    while (t < until - 1e-12) {
        ASSERT_EQ(uc_do_step(c, t, h, &in, msg, sizeof msg), 0) << msg << " at t = " << t;
        t += h;
        if (uc_take_event(c, event, sizeof event)) events += event;
        const UCOutputs o = outputs(c);
        deficit += 0.5 * h * ((T0 - last) + (T0 - o.towTension));  // trapezoid
        last = o.towTension;
        if (std::getenv("UC_DEBUG")) std::printf("%.4f %.2f %.4f\n", t, o.towTension, o.endPosition[0]);
        EXPECT_EQ(o.mooringLine[0].broken, t < release - 1e-12 ? 0.0 : 1.0) << t;
        if (t >= release - 1e-12) {
            EXPECT_EQ(o.mooringLine[0].breakTime, release);
        }
        if (t >= release + 1e-9) {
            // nothing, to the integrator's error in tension (tensionTolerance times the line's tension scale)
            EXPECT_LT(o.mooringLine[0].anchorTension, p.tensionTolerance * o.tensionScale) << "a bare end, t = " << t;
        }
    }
    EXPECT_NE(events.find("line failure 1 at t = 0.05 s: line 1's far end detached"), std::string::npos) << events;
    EXPECT_LT(last, 0.05 * T0) << "the tow point let go of after the wave's transit";
    const double centroid = until - deficit / T0 - release;
    std::printf("released at its anchor, %d elements: the tow tension's deficit centroid %.4f s after the release, "
                "L0/c = %.4f s (%.2f element transits early)\n", elements, centroid, transit,
                (transit - centroid) / (transit / elements));
    EXPECT_NEAR(centroid, transit, 2.0 * transit / elements);
    uc_free(c);
}

// By tension: the tow point pulled away (0.1 m/s along the line) raises the anchor's tension from 1e4 N by EA 0.1 t / L0
// = 500 N/s; the anchor lets go where it reaches 1.2e4 N (near 4 s), located within the step (the tension there within the tolerance of the
// threshold). A state saved before, at and after the break continues bit for bit in a fresh instance; with the stop at
// breaks the step ends at the break.
TEST(OneLineFailure, AnAnchorLetsGoAtItsTensionAndStatesAcrossTheBreakRestoreBitForBit) {
    UCParams p = taut_line(10);
    p.failureLine = 1;
    p.failureTension = 1.2e4;
    char msg[512];
    auto input = [](double t) {
        UCInputs in = held_tow();
        in.tow[0] = -0.1 * t;
        in.towVelocity[0] = -0.1;
        return in;
    };
    const double h = 0.25;
    UCCable* a = uc_create(&p, msg, sizeof msg);
    ASSERT_NE(a, nullptr) << msg;
    UCInputs in0 = input(0.0);
    ASSERT_EQ(uc_initialize(a, 0.0, &in0, msg, sizeof msg), 0) << msg;
    std::vector<std::vector<unsigned char>> saved;
    std::vector<double> savedAt;
    double t = 0.0, broke = -1.0;
    const int steps = 24;  // 6 s
    for (int k = 0; k < steps; ++k) {
        const UCOutputs o = outputs(a);
        if (k % 4 == 1 || (o.mooringLine[0].broken != 0.0 && broke < 0.0)) {
            saved.emplace_back(uc_state_size(a));
            ASSERT_EQ(uc_state_save(a, saved.back().data(), saved.back().size()), 0);
            savedAt.push_back(t);
        }
        if (o.mooringLine[0].broken != 0.0 && broke < 0.0) broke = o.mooringLine[0].breakTime;
        const UCInputs in = input(t);
        ASSERT_EQ(uc_do_step(a, t, h, &in, msg, sizeof msg), 0) << msg << " at t = " << t;
        t += h;
    }
    const UCOutputs last = outputs(a);
    ASSERT_EQ(last.mooringLine[0].broken, 1.0) << "the anchor's tension reached 1.2e4 N";
    std::printf("broke by tension at %.6f s\n", last.mooringLine[0].breakTime);
    ASSERT_GT(broke, 0.0);
    for (size_t i = 0; i < saved.size(); ++i) {
        UCCable* b = uc_create(&p, msg, sizeof msg);
        ASSERT_NE(b, nullptr);
        ASSERT_EQ(uc_state_restore(b, saved[i].data(), saved[i].size(), msg, sizeof msg), 0) << msg;
        for (double tt = savedAt[i]; tt < steps * h - 1e-9; tt += h) {
            for (size_t j = i + 1; j < saved.size(); ++j) {  // saved again where the first run saved (a save
                if (savedAt[j] != tt) continue;               // makes the next step evaluate a new Jacobian)
                std::vector<unsigned char> as(uc_state_size(b));
                ASSERT_EQ(uc_state_save(b, as.data(), as.size()), 0);
                EXPECT_TRUE(as == saved[j]) << "state " << j << " saved again from state " << i;
            }
            const UCInputs in = input(tt);
            ASSERT_EQ(uc_do_step(b, tt, h, &in, msg, sizeof msg), 0) << msg;
        }
        const UCOutputs o = outputs(b);
        EXPECT_EQ(std::memcmp(&o, &last, sizeof o), 0) << "state " << i << " saved at " << savedAt[i] << " s";
        uc_free(b);
    }
    // the step ends at the break where the importer allows it
    UCCable* s = uc_create(&p, msg, sizeof msg);
    ASSERT_EQ(uc_initialize(s, 0.0, &in0, msg, sizeof msg), 0) << msg;
    uc_set_stop_at_breaks(s, 1);
    double ts = 0.0;
    std::string events;
    char event[512];
    for (int k = 0; k < steps && outputs(s).mooringLine[0].broken == 0.0; ++k) {
        const UCInputs in = input(ts);
        ASSERT_EQ(uc_do_step(s, ts, h, &in, msg, sizeof msg), 0) << msg;
        ts = uc_time(s);
        if (uc_take_event(s, event, sizeof event)) events += event;
    }
    EXPECT_EQ(uc_time(s), last.mooringLine[0].breakTime);
    EXPECT_GT(std::fmod(uc_time(s), h), 0.0) << "within a step";
    // the anchor's tension at the break (the log's) within the tolerance of the threshold
    const size_t at = events.find("tension there ");
    ASSERT_NE(at, std::string::npos) << events;
    const double tension = std::atof(events.c_str() + at + 14);
    EXPECT_NEAR(tension, p.failureTension, p.tensionTolerance * outputs(s).tensionScale) << events;
    uc_free(s);
    uc_free(a);
}
