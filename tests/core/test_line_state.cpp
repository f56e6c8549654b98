// A line's whole evolving state is its LineState (line/line_state.h): a state saved at step k and
// restored into a fresh instance (never initialized) continues exactly as the line it was saved from:
// every output bit for bit, the same events (a winch limit or the rate cut logged once per arrival),
// and the same saved bytes afterwards. The scenes exercise what evolves in a line: the rate winch
// (remeshes, the drum, the length limit and the rate cut), the constant-tension winch, torsion from
// the twist input (the unwrapped twist), the rainflow count, waves, a driven far end with given
// accelerations and the proxy far end's estimate. A field that a step changes and the state does not
// hold shows up here as a difference.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "api/cable_api.h"
#include "line/simulation.h"

using namespace uc;

namespace {

constexpr double kSceneCurveLastStrain = 6e-5;

struct Scene {
    const char* name;
    UCParams params;
    std::function<void(int k, double t, UCInputs& in)> inputs;  // the inputs of step k (from time t)
    double h;
};

UCParams base_line() {
    UCParams p;
    uc_params_default(&p);
    p.length = 60.0;
    p.nElements = 8;
    p.bottomEnd = UC_BOTTOM_TOWED_BODY;
    p.bodyMass = 400.0;
    p.bodyVolume = 0.1;
    p.bodyCdA = 0.3;
    return p;
}

std::vector<Scene> scenes() {
    std::vector<Scene> all;
    {  // rate winch paying out past its rate and into its longest length, torsion, fatigue, a regular wave
        UCParams p = base_line();
        p.winchMode = UC_WINCH_RATE;
        p.winchMinLength = 30.0;
        p.winchMaxLength = 66.0;
        p.winchMaxRate = 1.0;
        p.winchMaxAcceleration = 0.5;
        p.enableTorsion = 1;
        p.torqueMode = UC_TORQUE_ROTATION;
        p.fatigueArea = 1e-4;
        p.wavesMode = 1;
        p.wavesHeight = 2.0;
        p.wavesPeriod = 6.0;
        all.push_back({"winch_torsion_fatigue", p,
                       [](int k, double t, UCInputs& in) {
                           in.towVelocity[0] = 1.0 + 0.01 * k;
                           in.tow[0] = t * in.towVelocity[0];
                           in.tow[2] = 0.3 * std::sin(0.7 * t);
                           in.towVelocity[2] = 0.21 * std::cos(0.7 * t);
                           in.winchRate = k < 40 ? 1.5 : -0.5;  // beyond winch.maxRate, then hauling in
                           in.twist = 4.0 * std::sin(0.05 * k);  // past +-pi: the unwrapping counts
                       },
                       0.25});
    }
    {  // constant-tension winch
        UCParams p = base_line();
        p.winchMode = UC_WINCH_TENSION;
        p.winchMinLength = 30.0;
        p.winchMaxLength = 100.0;
        p.winchMaxRate = 2.0;
        p.winchTimeConstant = 0.5;
        p.fatigueArea = 1e-4;
        all.push_back({"tension_winch", p,
                       [](int k, double t, UCInputs& in) {
                           in.towVelocity[0] = 1.0;
                           in.tow[0] = t;
                           in.winchTension = 3000.0 + 500.0 * std::sin(0.2 * k);
                       },
                       0.25});
    }
    {  // a far end driven with its accelerations given
        UCParams p = base_line();
        p.bottomEnd = UC_BOTTOM_EXTERNAL;
        all.push_back({"external_end", p,
                       [](int k, double t, UCInputs& in) {
                           (void)k;
                           for (int i = 0; i < 3; ++i) in.tow[i] = 0.0;
                           in.tow[2] = 0.5 * std::sin(0.8 * t);
                           in.towVelocity[2] = 0.4 * std::cos(0.8 * t);
                           in.towAcceleration[2] = -0.32 * std::sin(0.8 * t);
                           in.towAccelerationGiven = 1;
                           in.end[0] = -40.0 + 0.2 * std::sin(0.5 * t);
                           in.end[2] = -30.0;
                           in.endVelocity[0] = 0.1 * std::cos(0.5 * t);
                           in.endAcceleration[0] = -0.05 * std::sin(0.5 * t);
                           in.endAccelerationGiven = 1;
                       },
                       0.25});
    }
    {  // the proxy far end of an external body, the body off the proxy (the estimate moves)
        UCParams p = base_line();
        p.bottomEnd = UC_BOTTOM_PROXY;
        all.push_back({"proxy_end", p,
                       [](int k, double t, UCInputs& in) {
                           (void)k;
                           in.towVelocity[0] = 1.0;
                           in.tow[0] = t;
                           in.end[0] = -50.0 + t + 0.05 * std::sin(t);
                           in.end[2] = -30.0;
                           in.endVelocity[0] = 1.0 + 0.05 * std::cos(t);
                       },
                       0.25});
    }
    {  // a tension-strain curve that the towed line passes as it speeds up (the warning after the restore)
        UCParams p = base_line();
        p.axialCurvePoints = 3;
        // at rest on its way the line carries up to 3984 N (strain 5.8e-5), from step 30 on it speeds up
        const double strain[] = {2e-5, 4e-5, kSceneCurveLastStrain}, tension[] = {1200.0, 2500.0, 4150.0};
        for (int k = 0; k < 3; ++k) {
            p.axialCurveStrain[k] = strain[k];
            p.axialCurveTension[k] = tension[k];
        }
        all.push_back({"axial_curve", p,
                       [](int k, double t, UCInputs& in) {
                           const int m = k < 30 ? 0 : k - 30;  // the speed rises 0.1 m/s a step from step 30
                           in.towVelocity[0] = 0.5 + 0.1 * m;
                           in.tow[0] = 0.5 * t + 0.025 * 0.5 * m * (m + 1);
                       },
                       0.25});
    }
    return all;
}

std::vector<unsigned char> saved(CableSimulation& s) {
    std::vector<unsigned char> bytes(s.state_size());
    s.save_state(bytes.data());
    return bytes;
}

// Steps a and b alike from time t for n steps: the same success, outputs and events at every step.
void expect_same_run(const Scene& scene, CableSimulation& a, CableSimulation& b, int from, int n) {
    for (int k = from; k < from + n; ++k) {
        UCInputs ia{}, ib{};
        scene.inputs(k, a.time(), ia);
        scene.inputs(k, b.time(), ib);
        std::string ea, eb;
        const bool okA = a.step(a.time(), scene.h, ia, ea), okB = b.step(b.time(), scene.h, ib, eb);
        ASSERT_TRUE(okA) << scene.name << " step " << k << ": " << ea;
        ASSERT_EQ(okA, okB) << scene.name << " step " << k << ": " << eb;
        ASSERT_EQ(a.time(), b.time()) << scene.name << " step " << k;
        ASSERT_EQ(std::memcmp(&a.outputs(), &b.outputs(), sizeof(UCOutputs)), 0) << scene.name << " step " << k;
        ASSERT_EQ(a.take_event(), b.take_event()) << scene.name << " step " << k;
    }
}

void expect_restored_line_continues_exactly(const Scene& scene, int before, int after) {
    CableSimulation a(scene.params);
    std::string error;
    UCInputs in{};
    scene.inputs(0, 0.0, in);
    ASSERT_TRUE(a.initialize(0.0, in, error)) << scene.name << ": " << error;
    a.take_event();
    for (int k = 0; k < before; ++k) {
        scene.inputs(k, a.time(), in);
        ASSERT_TRUE(a.step(a.time(), scene.h, in, error)) << scene.name << " step " << k << ": " << error;
        a.take_event();
    }
    const std::vector<unsigned char> atK = saved(a);
    CableSimulation b(scene.params);  // fresh: never initialized
    ASSERT_TRUE(b.restore_state(atK.data(), atK.size(), error)) << scene.name << ": " << error;
    EXPECT_TRUE(saved(b) == atK) << scene.name << ": the restored state saves other bytes";
    EXPECT_TRUE(saved(a) == atK) << scene.name << ": the same state saves other bytes";
    ASSERT_EQ(std::memcmp(&a.outputs(), &b.outputs(), sizeof(UCOutputs)), 0) << scene.name;
    expect_same_run(scene, a, b, before, after);
    EXPECT_TRUE(saved(a) == saved(b)) << scene.name << ": the saved states differ after " << after << " steps";
}

}  // namespace

TEST(LineState, ARestoredLineContinuesBitForBitWithTheSameEventsAndSavedBytes) {
    for (const Scene& scene : scenes()) expect_restored_line_continues_exactly(scene, 30, 30);
}

TEST(LineState, TheScenesExerciseWhatEvolves) {
    // the test above means something only where the scenes reach the winch's limits, the rate cut,
    // remeshes, the unwrapped twist, cycles of the rainflow count and a moving proxy estimate
    const std::vector<Scene> all = scenes();
    const Scene& winch = all[0];
    CableSimulation s(winch.params);
    std::string error;
    UCInputs in{};
    winch.inputs(0, 0.0, in);
    ASSERT_TRUE(s.initialize(0.0, in, error)) << error;
    s.take_event();
    std::string events;
    const int elements = s.model().n_elements();
    int most = elements;
    double largestTwist = 0.0;
    for (int k = 0; k < 60; ++k) {
        winch.inputs(k, s.time(), in);
        ASSERT_TRUE(s.step(s.time(), winch.h, in, error)) << error;
        events += s.take_event() + "\n";
        most = std::max(most, s.model().n_elements());
        largestTwist = std::max(largestTwist, std::fabs(in.twist));
    }
    EXPECT_NE(events.find("maxRate"), std::string::npos) << events;
    EXPECT_NE(events.find("maxLength"), std::string::npos) << events;
    EXPECT_GT(most, elements);
    EXPECT_GT(largestTwist, kPi);
    EXPECT_GT(s.outputs().fatigueDamage, 0.0);
    EXPECT_NE(s.outputs().cableTorque, 0.0);
}

TEST(LineStep, TheLineLevelStepIsTheFmuStepBitForBit) {
    // step(h, tow, far, env) with the ends and the environment filled field by field here: the same
    // run as step(t, h, UCInputs), in every scene (the winch's rate and tension, torsion, the end
    // load, the driven far end and the proxy's body).
    for (const Scene& scene : scenes()) {
        CableSimulation a(scene.params), b(scene.params);
        std::string error;
        UCInputs in{};
        scene.inputs(0, 0.0, in);
        in.endLoad[2] = -50.0;
        in.endCouple[1] = 5.0;
        in.current[0] = 0.2;
        ASSERT_TRUE(a.initialize(0.0, in, error)) << scene.name << ": " << error;
        ASSERT_TRUE(b.initialize(0.0, in, error)) << scene.name << ": " << error;
        for (int k = 0; k < 20; ++k) {
            scene.inputs(k, a.time(), in);
            in.currentRate[1] = 0.01;
            in.stepBudget = 0;
            ASSERT_TRUE(a.step(a.time(), scene.h, in, error)) << scene.name << " step " << k << ": " << error;
            EndMotion tow, far;
            tow.position = Vec3(in.tow[0], in.tow[1], in.tow[2]);
            tow.velocity = Vec3(in.towVelocity[0], in.towVelocity[1], in.towVelocity[2]);
            tow.acceleration = Vec3(in.towAcceleration[0], in.towAcceleration[1], in.towAcceleration[2]);
            tow.accelerationGiven = in.towAccelerationGiven;
            far.position = Vec3(in.end[0], in.end[1], in.end[2]);
            far.velocity = Vec3(in.endVelocity[0], in.endVelocity[1], in.endVelocity[2]);
            far.acceleration = Vec3(in.endAcceleration[0], in.endAcceleration[1], in.endAcceleration[2]);
            far.accelerationGiven = in.endAccelerationGiven;
            LineEnvironment env;
            env.current[0] = in.current[0];
            env.currentRate[1] = in.currentRate[1];
            env.currentScale = in.currentScale;
            env.endLoad[2] = in.endLoad[2];
            env.endCouple[1] = in.endCouple[1];
            env.twist = in.twist;
            env.winchRate = in.winchRate;
            env.winchTension = in.winchTension;
            ASSERT_TRUE(b.step(scene.h, tow, far, env, error)) << scene.name << " step " << k << ": " << error;
            ASSERT_EQ(std::memcmp(&a.outputs(), &b.outputs(), sizeof(UCOutputs)), 0) << scene.name << " step " << k;
            ASSERT_EQ(a.take_event(), b.take_event()) << scene.name << " step " << k;
        }
    }
}

TEST(LineState, TheCurveScenePassesItsCurveAfterTheSave) {
    // the warning beyond the tension-strain curve (curveWarned, in LineState) comes after the save at
    // step 30, so the restored copy must give it at the same step, once
    const std::vector<Scene> all = scenes();
    const Scene& scene = all.back();
    ASSERT_STREQ(scene.name, "axial_curve");
    CableSimulation s(scene.params);
    std::string error;
    UCInputs in{};
    scene.inputs(0, 0.0, in);
    ASSERT_TRUE(s.initialize(0.0, in, error)) << error;
    EXPECT_EQ(s.take_event().find("tension-strain curve"), std::string::npos);
    int warnedAt = -1, warnings = 0;
    for (int k = 0; k < 60; ++k) {
        scene.inputs(k, s.time(), in);
        ASSERT_TRUE(s.step(s.time(), scene.h, in, error)) << error;
        if (s.take_event().find("tension-strain curve") != std::string::npos) {
            ++warnings;
            if (warnedAt < 0) warnedAt = k;
        }
    }
    EXPECT_GT(warnedAt, 30);
    EXPECT_EQ(warnings, 1);
}
