// Line failures in a mooring system (docs/line_failure.md): the deck's FAILURE rows, a break at a time and at a
// tension threshold (the step that contains it ends there), the platform's response, and the state across a break.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <cstring>
#include <string>
#include <vector>

#include "api/cable_api.h"
#include "chain_system_parameters.h"
#include "deck/line_file.h"
#include "system/mooring_system.h"

namespace {

// The OC4 DeepCwind semisubmersible's three chains (scenes/oc4_semi.dat: fairleads on body 1, points 4, 5, 6, lines
// 1, 2, 3 from anchors 1, 2, 3) with a FAILURE table after it, its rows given by the tests.
std::string oc4_deck() {
    std::ifstream file(UC_SOURCE_DIR "/scenes/oc4_semi.dat", std::ios::binary);
    EXPECT_TRUE(file.good()) << UC_SOURCE_DIR "/scenes/oc4_semi.dat";
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

const std::string kDeck = oc4_deck();
const std::string kFailureHeader = "---------------------- FAILURE ----------------\nID  Point  Line(s)  FailTime  FailTen\n"
                                   "()  ()  (,)  (s)  (N)\n";
// "line <n>: " of the first FAILURE row in messages
const std::string kRow = "line " + std::to_string(std::count(kDeck.begin(), kDeck.end(), '\n') + 4) + ":";

std::string spread(const std::string& failureRows) { return kDeck + kFailureHeader + failureRows + "---- end ----\n"; }

UCParams system_parameters() {
    UCParams p = chain_system_parameters();
    p.lineFileElements = 10;
    return p;
}

UCInputs platform_at(double x, double y, double vx, double vy) {
    UCInputs in;
    uc_inputs_default(&in);
    in.coupledBody[0].position[0] = x;
    in.coupledBody[0].position[1] = y;
    in.coupledBody[0].velocity[0] = vx;
    in.coupledBody[0].velocity[1] = vy;
    return in;
}

struct Built {
    uc::MooringDeck deck;
    std::unique_ptr<uc::MooringSystem> system;
};

Built build(const std::string& text, const UCParams& p = system_parameters()) {
    Built b;
    std::string error;
    EXPECT_TRUE(uc::read_mooring_deck(text, p.lineFileElements, b.deck, error)) << error;
    b.system = std::make_unique<uc::MooringSystem>(p, b.deck);
    EXPECT_TRUE(b.system->build(error)) << error;
    return b;
}

std::string refusal(const std::string& rows) {
    uc::MooringDeck deck;
    std::string error;
    EXPECT_FALSE(uc::read_mooring_deck(spread(rows), 0, deck, error));
    return error;
}

}  // namespace

TEST(LineFailureDeck, TheFailureTableIsReadAsMoorDynFWritesIt) {
    const Built b = build(spread("1  4  1  12.5  0\n2  P5  2  0  3.0e6\n"));
    ASSERT_EQ(b.deck.failures.size(), 2u);
    const uc::MooringFailure& f = b.deck.failures[0];
    EXPECT_EQ(f.id, 1);
    EXPECT_EQ(kRow, "line " + std::to_string(f.row) + ":");
    EXPECT_EQ(f.point, 4);
    ASSERT_EQ(f.ends.size(), 1u);
    EXPECT_EQ(f.ends[0].deckLine, 0);
    EXPECT_EQ(f.ends[0].end, 0);  // the fairlead
    EXPECT_DOUBLE_EQ(f.time, 12.5);
    EXPECT_DOUBLE_EQ(b.deck.failures[1].tension, 3.0e6);
    EXPECT_EQ(b.system->n_failures(), 2);
}

// A failure at an anchor (a Fixed point) is read: the line's far end detaches there.
TEST(LineFailureDeck, AFailureAtAnAnchorIsTheLinesFarEnd) {
    const Built b = build(spread("1  1  1  10  0\n2  P3  3  0  2e6\n"));
    ASSERT_EQ(b.deck.failures.size(), 2u);
    EXPECT_EQ(b.deck.failures[0].point, 1);
    EXPECT_EQ(b.deck.failures[0].ends[0].end, 1);
    EXPECT_EQ(b.deck.failures[1].ends[0].end, 1);
    EXPECT_EQ(b.system->n_failures(), 2);
}

TEST(LineFailureDeck, AMalformedRowIsRefusedNamingTheRow) {
    EXPECT_EQ(refusal("1  4  2  10  0\n").rfind(kRow + " Line(s) '2': line 2 is not attached to point 4", 0), 0u)
        << refusal("1  4  2  10  0\n");
    EXPECT_EQ(refusal("1  4  1  0  0\n").rfind(kRow + " FailTime and FailTen are both 0", 0), 0u);
    EXPECT_EQ(refusal("1  4  1,x  10  0\n").rfind(kRow + " Line(s) '1,x': 'x' is not a line ID", 0), 0u);
    EXPECT_EQ(refusal("1  4  1  -1  0\n").rfind(kRow + " FailTime = -1: must not be negative", 0), 0u);
    EXPECT_EQ(refusal("1  9  1  10  0\n").rfind(kRow + " Point '9': there is no point 9", 0), 0u);
    EXPECT_EQ(refusal("1  4  1  10\n").rfind(kRow + " a failure has the fields ID Point Line(s) FailTime FailTen", 0), 0u);
    EXPECT_EQ(refusal("2  4  1  10  0\n").rfind(kRow + "", 0), 0u);  // IDs 1, 2, ... in order
    EXPECT_NE(refusal("1  4  1  10  0\n2  4  1  0  1e6\n").find("that end already detaches in failure 1"), std::string::npos);
    // one line's deck: refused as a whole, naming the section
    UCParams p = system_parameters();
    uc::LineFileLine line;
    std::string error;
    const std::string one = "----- LINE TYPES -----\nName Diam MassDen EA BA EI Cd Ca CdAx CaAx\n(-) (m) (kg/m) (N) (-) (-) (-) (-) (-) (-)\n"
                            "main 0.0766 113.35 7.536E8 -1.0 0 2.0 0.8 0.4 0.25\n----- POINTS -----\nID Attachment X Y Z M V CdA CA\n"
                            "(-) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)\n1 Fixed 418.8 725.383 -200 0 0 0 0\n2 Vessel 20.4 35.4 -14 0 0 0 0\n"
                            "----- LINES -----\nID LineType AttachA AttachB UnstrLen NumSegs Outputs\n(-) (-) (-) (-) (m) (-) (-)\n"
                            "1 main 1 2 835.35 20 -\n----- FAILURE -----\nID Point Line(s) FailTime FailTen\n() () (,) (s) (N)\n1 2 1 10 0\n---- end ----\n";
    EXPECT_FALSE(uc::read_line_file(one, 0, line, error));
    EXPECT_NE(error.find("line failures are supported in a mooring system's deck only"), std::string::npos) << error;
    (void)p;
}

TEST(LineFailureDeck, TheFailureParametersAreCheckedAndTheOneLineModelRefusesASecondLine) {
    UCParams p = system_parameters();
    p.failureLine = 2;
    uc::MooringDeck deck;
    std::string error;
    ASSERT_TRUE(uc::read_mooring_deck(spread(""), 10, deck, error)) << error;
    {
        uc::MooringSystem s(p, deck);
        EXPECT_FALSE(s.build(error));
        EXPECT_EQ(error.rfind("failure.line = 2, failure.point = 0: failure.time and failure.tension are both 0", 0), 0u) << error;
    }
    p.failureTime = 5.0;
    p.failurePoint = 2;  // line 2's anchor
    {
        uc::MooringSystem s(p, deck);
        EXPECT_TRUE(s.build(error)) << error;
        ASSERT_EQ(s.n_failures(), 1);
        EXPECT_EQ(s.failure(0).ends[0].end, 1);
    }
    p.failurePoint = 0;  // the fairlead, point 5
    {
        uc::MooringSystem s(p, deck);
        EXPECT_TRUE(s.build(error)) << error;
        ASSERT_EQ(s.n_failures(), 1);
    }
    char msg[512];
    UCCable* one = uc_create(&p, msg, sizeof msg);
    EXPECT_EQ(one, nullptr);
    EXPECT_NE(std::string(msg).find("failure.line = 2: one line (no deck of several lines) is line 1"), std::string::npos) << msg;
    uc_free(one);
}

namespace {

// The platform free in surge and sway (its mass and added mass, a linear damping), moved by the lines' horizontal
// force on it after each step (semi-implicit Euler).
struct FreePlatform {
    double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0;
    UCInputs inputs() const { return platform_at(x, y, vx, vy); }
    void move(const UCOutputs& o, double h) {
        const double mass = 1.35e7 + 1.2e7, damping = 2.0e5;  // [kg], [N s/m]
        vx += h * (o.bodyLoad[0].force[0] - damping * vx) / mass;
        vy += h * (o.bodyLoad[0].force[1] - damping * vy) / mass;
        x += h * vx;
        y += h * vy;
    }
    // the distance moved away from anchor 1 (direction (0.5, 0.866)), and across that direction
    double away() const { return -(0.5 * x + 0.866 * y); }
    double across() const { return std::abs(-0.866 * x + 0.5 * y); }
};

}  // namespace

// Line 1 (fairlead at point 4, anchor 1 out at +60 degrees) breaks at 2.3 s, inside a step of 0.5 s: the step ends
// there, the line's fairlead tension falls to nothing, and a free platform (surge and sway, its mass and added mass,
// a linear damping) drifts away from the broken line's anchor, pulled by the other two.
TEST(LineFailure, ALineBreaksAtItsTimeAndThePlatformDriftsAway) {
    Built b = build(spread("1  4  1  2.3  0\n"));
    uc::MooringSystem& s = *b.system;
    std::string error;
    ASSERT_TRUE(s.initialize(0.0, platform_at(0, 0, 0, 0), error)) << error;
    FreePlatform platform;
    double t = 0.0;
    const double h = 0.5;
    const double T0 = s.outputs().mooringLine[0].fairleadTension;
    double before = 0.0;
    std::string events;
    for (int k = 0; k < 120; ++k) {  // 60 s
        ASSERT_TRUE(s.step(t, h, platform.inputs(), error)) << error << " at t = " << t;
        t += h;
        events += s.take_event();
        const UCOutputs& o = s.outputs();
        if (t < 2.3) {
            EXPECT_EQ(o.mooringLine[0].broken, 0.0);
            before = o.mooringLine[0].fairleadTension;
        } else {
            EXPECT_EQ(o.mooringLine[0].broken, 1.0) << t;
            EXPECT_EQ(o.mooringLine[0].breakTime, 2.3);
            EXPECT_EQ(o.mooringLine[1].broken, 0.0);
        }
        platform.move(o, h);
    }
    EXPECT_NE(events.find("line failure 1 at t = 2.3 s: line 1 detached from point 4"), std::string::npos) << events;
    EXPECT_GT(before, 0.9 * T0);
    const UCOutputs& o = s.outputs();
    EXPECT_LT(o.mooringLine[0].fairleadTension, 1e-3 * T0) << "a bare end carries no tension";
    // away from anchor 1 (direction (0.5, 0.866)): the other two lines' pretension pulls the platform off
    std::printf("after 60 s: x = %.3f m, y = %.3f m, line 1 tension %.3g N (%.3g N before)\n", platform.x, platform.y,
                o.mooringLine[0].fairleadTension, before);
    EXPECT_GT(platform.away(), 10.0) << "x = " << platform.x << ", y = " << platform.y;
    EXPECT_LT(platform.across(), 0.05 * platform.away()) << "along the broken line's direction";
    EXPECT_EQ(s.failure_state(0).broken, 1.0);
    EXPECT_EQ(s.failure_state(0).time, 2.3);
    // the platform's stiffness and interface derivatives, from the two lines left on it
    double K[36];
    std::string why;
    ASSERT_TRUE(s.body_stiffness(1, platform.inputs(), K, &why)) << why;
    for (double k : K) EXPECT_TRUE(std::isfinite(k));
    EXPECT_GT(K[0], 0.0);
    double d[6][UC_BODY_DERIVATIVE_INPUTS];
    ASSERT_TRUE(s.body_derivatives(1, d, error)) << error;
    for (const auto& row : d)
        for (double v : row) EXPECT_TRUE(std::isfinite(v));
}

namespace {

// Line 1's anchor (point 1) lets go at 2.3 s; the OC4 platform held, or free (FreePlatform), over `duration`, in steps
// of 0.5 s. Returns line 1's fairlead tension at the end of each step.
std::vector<double> anchor_lets_go(double duration, FreePlatform* free) {
    Built b = build(spread("1  1  1  2.3  0\n"));
    uc::MooringSystem& s = *b.system;
    std::string error;
    std::vector<double> tension;
    EXPECT_TRUE(s.initialize(0.0, platform_at(0, 0, 0, 0), error)) << error;
    const double T0 = s.outputs().mooringLine[0].fairleadTension;
    const double h = 0.5;
    std::string events;
    for (double t = 0.0; t < duration - 1e-9; t += h) {
        FreePlatform held;
        const bool stepped = s.step(t, h, (free ? *free : held).inputs(), error);
        EXPECT_TRUE(stepped) << error << " at t = " << t;
        if (!stepped) break;
        events += s.take_event();
        const UCOutputs& o = s.outputs();
        EXPECT_EQ(o.mooringLine[0].broken, t + h < 2.3 ? 0.0 : 1.0) << t + h;
        tension.push_back(o.mooringLine[0].fairleadTension);
        if (free) free->move(o, h);
    }
    EXPECT_NE(events.find("line failure 1 at t = 2.3 s: line 1 detached from point 1"), std::string::npos) << events;
    const UCOutputs& o = s.outputs();
    EXPECT_EQ(o.mooringLine[0].breakTime, 2.3);
    EXPECT_LT(o.mooringLine[0].anchorTension, 1e-3 * T0) << "a bare end carries no tension";
    std::printf("anchor 1 let go at 2.3 s: after %g s line 1's fairlead tension %.4g N (%.4g N before the break)\n",
                duration, o.mooringLine[0].fairleadTension, T0);
    return tension;
}

// The chain's weight in water per metre [N/m], and the weight of one of its 10 elements [N] (835.35 m of chain).
const double kChainWeight = (113.35 - 1025.0 * 3.14159265358979 / 4 * 0.0766 * 0.0766) * 9.80665;
const double kElementWeight = kChainWeight * 835.35 / 10;

}  // namespace

// Line 1's anchor lets go: the line's far end goes on bare and the line hangs from its fairlead. Once the chain has
// come to rest on the seabed (no horizontal tension at a bare end), the fairlead carries the chain hanging from it down
// to the seabed: w (186 m), the fairlead 14 m below the surface over 200 m of water. The touchdown lies inside an
// element, whose weight the seabed carries in part: half an element's weight is the comparison's accuracy.
TEST(LineFailure, AnAnchorThatLetsGoLeavesTheLineHangingFromItsFairlead) {
    const std::vector<double> T = anchor_lets_go(240.0, nullptr);
    ASSERT_EQ(T.size(), 480u);
    const double hanging = kChainWeight * (200.0 - 14.0);
    std::printf("held platform: fairlead tension %.4g N at 10 s, %.4g N at 60 s, %.4g N at 120 s, %.4g N at 140 s, %.4g N "
                "at 160 s, %.4g N at 220 s, %.4g N at 240 s; w (186 m) = %.4g N\n", T[19], T[119], T[239], T[279], T[319],
                T[439], T.back(), hanging);
    EXPECT_NEAR(T.back(), T[439], 0.01 * T.back()) << "the transient has died";
    EXPECT_NEAR(T.back(), hanging, 0.5 * kElementWeight);
}

// The same with the platform free (surge and sway): pulled by the other two lines it drifts away from anchor 1,
// dragging the broken chain; its fairlead tension falls from 1.1 MN towards w (186 m).
TEST(LineFailure, AnAnchorThatLetsGoLetsThePlatformDriftAway) {
    FreePlatform platform;
    const std::vector<double> T = anchor_lets_go(120.0, &platform);
    std::printf("free platform: %.3f m away from anchor 1 after 120 s\n", platform.away());
    EXPECT_GT(platform.away(), 10.0) << "x = " << platform.x << ", y = " << platform.y;
    EXPECT_LT(platform.across(), 0.05 * platform.away()) << "along the broken line's direction";
    EXPECT_LT(T.back(), 0.25 * T.front());
    EXPECT_GT(T.back(), kChainWeight * (200.0 - 14.0) - 0.5 * kElementWeight);
}

namespace {

// The platform pulled away from anchor 1 at 0.5 m/s (along (-0.5, -0.866)): line 1's fairlead tension rises.
UCInputs pulled(double t) {
    const double v = 0.5;
    return platform_at(-0.5 * v * t, -0.866 * v * t, -0.5 * v, -0.866 * v);
}

struct Break {
    double time, tension, tolerance, threshold;
};

// Line 1 breaks at 1.25 times its initial tension at point 4 (its fairlead) or 1 (its anchor) while the platform is
// pulled, with communication steps h.
double tension_at(const uc::MooringSystem& s, int point) {
    const UCMooringLine& l = s.outputs().mooringLine[0];
    return point == 4 ? l.fairleadTension : l.anchorTension;
}

// The system initialized with the platform pulled, stepped in steps of h until its failure 0 breaks (by tension at
// threshold): before the break its tension at the point stays below the threshold and its tolerance.
Break step_to_break(uc::MooringSystem& s, double h, double threshold) {
    std::string error;
    EXPECT_TRUE(s.initialize(0.0, pulled(0.0), error)) << error;
    double t = 0.0;
    while (s.failure_state(0).broken == 0.0 && t < 60.0) {
        EXPECT_TRUE(s.step(t, h, pulled(t), error)) << error;
        t += h;
        if (s.failure_state(0).broken == 0.0) {
            EXPECT_LT(s.failure_tension(0), threshold + s.failure_tolerance(0));
        }
    }
    return {s.failure_state(0).time, s.failure_state(0).tension, s.failure_tolerance(0), threshold};
}

Break break_by_tension(double h, double factor = 1.25, int point = 4) {
    Built probe = build(spread(""));
    std::string error;
    EXPECT_TRUE(probe.system->initialize(0.0, pulled(0.0), error)) << error;
    const double threshold = factor * tension_at(*probe.system, point);
    char row[80];
    std::snprintf(row, sizeof row, "1  %d  1  0  %.17g\n", point, threshold);
    Built b = build(spread(row));
    return step_to_break(*b.system, h, threshold);
}

}  // namespace

// The step in which the tension reaches the threshold ends where it does: the tension at the break is the threshold
// within the integrator's tolerance in tension, and the break time that of a run with a fine step, whatever the
// communication step.
TEST(LineFailure, ALineBreaksWhereItsTensionReachesTheThresholdWhateverTheStep) {
    const Break fine = break_by_tension(0.02);
    ASSERT_GT(fine.time, 1.0);
    for (double h : {0.1, 0.5, 1.0}) {
        const Break b = break_by_tension(h);
        EXPECT_LE(std::abs(b.tension - b.threshold), b.tolerance) << "h = " << h;
        // the tension rises at dT/dt: the tolerance in tension is a tolerance in time of tolerance / (dT/dt)
        const double rate = (fine.threshold - fine.threshold / 1.25) / fine.time;
        EXPECT_LE(std::abs(b.time - fine.time), 2.0 * b.tolerance / rate + 1e-3) << "h = " << h << ": " << b.time << " against " << fine.time;
        std::printf("h = %g s: break at %.6f s (fine step %.6f s), tension %.1f N, threshold %.1f N, tolerance %.1f N\n", h,
                    b.time, fine.time, b.tension, b.threshold, b.tolerance);
    }
}

// At the anchor as at the fairlead: the step ends where line 1's anchor tension reaches the threshold, within the
// integrator's tolerance in tension, at the time of a run with a fine step within that tolerance in time.
namespace {

// A break by tension at `factor` times the initial tension, located in steps of 0.5 s (b) and 0.1 s (fine): the tension
// at each within the tolerance of the threshold, the times within the tolerance in time (at the mean rate of rise).
void expect_located(const Break& fine, const Break& b, double factor, const char* where) {
    ASSERT_GT(fine.time, 1.0);
    EXPECT_LE(std::abs(fine.tension - fine.threshold), fine.tolerance);
    EXPECT_LE(std::abs(b.tension - b.threshold), b.tolerance);
    const double rate = (fine.threshold - fine.threshold / factor) / fine.time;
    EXPECT_LE(std::abs(b.time - fine.time), 2.0 * b.tolerance / rate + 1e-3) << b.time << " against " << fine.time;
    std::printf("%s: h = 0.5 s: break at %.6f s (h = 0.1 s: %.6f s), tension %.1f N, threshold %.1f N, tolerance "
                "%.1f N\n", where, b.time, fine.time, b.tension, b.threshold, b.tolerance);
}

}  // namespace

TEST(LineFailure, AnAnchorLetsGoWhereItsTensionReachesTheThreshold) {
    expect_located(break_by_tension(0.1, 1.25, 1), break_by_tension(0.5, 1.25, 1), 1.25, "anchor");
}

// States saved before, at and after a break restore into a fresh instance and continue bit for bit: the outputs and
// the state each saves next. (Saving makes each line's next step evaluate a new Jacobian, as a restore does: a
// continuation is compared with the run that saved at the same times.)
namespace {

// Runs 8 steps of 0.4 s with a failure at 0.9 s given by the FAILURE row; saves states before (0.4 s), just after
// (1.2 s) and after (2.0 s) the break, restores each in a fresh instance and in the instance that ran on, and checks
// that each continues bit for bit. Returns the instance that ran.
Built restore_across_a_break(const std::string& row) {
    const std::string deck = spread(row);
    Built a = build(deck);
    std::string error;
    EXPECT_TRUE(a.system->initialize(0.0, platform_at(0, 0, 0, 0), error)) << error;
    auto input = [](double t) { return platform_at(2.0 * std::sin(0.3 * t), 1.0 * std::sin(0.2 * t), 0.6 * std::cos(0.3 * t), 0.2 * std::cos(0.2 * t)); };
    const double h = 0.4;
    std::vector<std::vector<unsigned char>> saved;
    std::vector<double> savedAt;
    double t = 0.0;
    for (int k = 0; k < 8; ++k) {
        if (k == 1 || k == 3 || k == 5) {  // before (0.4 s), just after (1.2 s: the step of 0.8-1.2 s held it), after
            saved.emplace_back(a.system->state_size());
            a.system->save_state(saved.back().data());
            savedAt.push_back(t);
        }
        EXPECT_TRUE(a.system->step(t, h, input(t), error)) << error;
        t += h;
    }
    std::vector<unsigned char> end(a.system->state_size());
    a.system->save_state(end.data());
    const UCOutputs last = a.system->outputs();
    EXPECT_EQ(last.mooringLine[0].broken, 1.0);
    for (size_t i = 0; i < saved.size(); ++i) {
        Built b = build(deck);
        EXPECT_TRUE(b.system->restore_state(saved[i].data(), saved[i].size(), error)) << error;
        auto run_on = [&](uc::MooringSystem& s) {
            for (double tt = savedAt[i]; tt < 8 * h - 1e-9; tt += h) {
                for (size_t j = i + 1; j < saved.size(); ++j) {
                    if (savedAt[j] != tt) continue;
                    std::vector<unsigned char> as(s.state_size());
                    s.save_state(as.data());
                    EXPECT_TRUE(as == saved[j]) << "state " << j << " saved again from state " << i;
                }
                ASSERT_TRUE(s.step(tt, h, input(tt), error)) << error;
            }
        };
        run_on(*b.system);
        EXPECT_EQ(std::memcmp(&last, &b.system->outputs(), sizeof last), 0) << "state " << i;
        std::vector<unsigned char> again(b.system->state_size());
        b.system->save_state(again.data());
        EXPECT_TRUE(again == end) << "state " << i;
        // and the instance that ran on, taken back to before the break, continues as it did
        EXPECT_TRUE(a.system->restore_state(saved[i].data(), saved[i].size(), error)) << error;
        run_on(*a.system);
        EXPECT_EQ(std::memcmp(&last, &a.system->outputs(), sizeof last), 0) << "state " << i << " in the same instance";
    }
    return a;
}

}  // namespace

TEST(LineFailure, StatesAcrossABreakRestoreBitForBitInAFreshInstance) {
    Built a = restore_across_a_break("1  4  1  0.9  0\n");
    std::string error;
    std::vector<unsigned char> state(a.system->state_size());
    a.system->save_state(state.data());
    // a state of the format before the failures (version 3) is refused, saying so
    std::vector<unsigned char> old = state;
    const std::uint32_t three = 3;
    std::memcpy(old.data() + sizeof(std::uint32_t), &three, sizeof three);
    EXPECT_FALSE(a.system->restore_state(old.data(), old.size(), error));
    EXPECT_EQ(error.rfind("saved state is a mooring system's state of format version 3, this FMU reads version 6 (version 4 "
                          "added the line failures' state, 5 sized the state by the deck, 6 made a broken line's bare end "
                          "the line's own free end)", 0), 0u) << error;
    // and one of version 4 (a broken line's bare end on a free node), saying why
    const std::uint32_t four = 4;
    std::memcpy(old.data() + sizeof(std::uint32_t), &four, sizeof four);
    EXPECT_FALSE(a.system->restore_state(old.data(), old.size(), error));
    EXPECT_EQ(error.rfind("saved state is a mooring system's state of format version 4, this FMU reads version 6 (version 5 "
                          "sized the state by the deck, 6 made a broken line's bare end the line's own free end)", 0), 0u)
        << error;
    // and one of version 5 (sized by the deck, the bare end still on a free node)
    const std::uint32_t five = 5;
    std::memcpy(old.data() + sizeof(std::uint32_t), &five, sizeof five);
    EXPECT_FALSE(a.system->restore_state(old.data(), old.size(), error));
    EXPECT_EQ(error.rfind("saved state is a mooring system's state of format version 5, this FMU reads version 6 (version 6 "
                          "made a broken line's bare end the line's own free end)", 0), 0u) << error;
}

// A line that breaks alone goes on by itself: its bare end is the line's own free far end, integrated inside the
// line's own integrator (no free node, no coupled iteration), the line run from its anchor where its fairlead let
// go, its far end let go where its anchor did. One integrator restart at the break.
TEST(LineFailure, ALineThatBreaksAloneGoesOnWithItsOwnFreeEnd) {
    for (const char* row : {"1  4  1  2.3  0\n", "1  1  1  2.3  0\n"}) {
        const bool atFairlead = row[3] == '4';
        Built b = build(spread(row));
        uc::MooringSystem& s = *b.system;
        std::string error;
        ASSERT_TRUE(s.initialize(0.0, platform_at(0, 0, 0, 0), error)) << error;
        const double T0 = s.outputs().mooringLine[0].fairleadTension;
        const double A0 = s.outputs().mooringLine[0].anchorTension;
        double t = 0.0;
        const double h = 0.5;
        std::string events;
        FreePlatform held;
        double stepsBefore = 0.0, stepsAfter = 0.0;
        for (int k = 0; k < 12; ++k) {  // 6 s
            ASSERT_TRUE(s.step(t, h, held.inputs(), error)) << error << " at t = " << t;
            t += h;
            events += s.take_event();
            EXPECT_EQ(s.n_nodes(), 0) << "no free node at " << t;
            EXPECT_EQ(s.line(0).released(), t < 2.3 ? 0 : atFairlead ? 2 : 1) << t;
            if (t == 2.0) stepsBefore = s.line(0).outputs().nSteps;
            if (t == 4.5) stepsAfter = s.line(0).outputs().nSteps;
        }
        EXPECT_NE(events.find("its end goes on bare, the line's own free end"), std::string::npos) << events;
        const UCOutputs& o = s.outputs();
        EXPECT_EQ(o.mooringLine[0].broken, 1.0);
        EXPECT_EQ(o.mooringLine[0].breakTime, 2.3);
        // the bare end carries nothing; the end still held carries the chain
        // the bare end carries nothing (to the integrator's error in tension), the end still held the chain
        const double tolerance = s.failure_tolerance(0);
        if (atFairlead) {
            EXPECT_LT(o.mooringLine[0].fairleadTension, tolerance);
            EXPECT_GT(o.mooringLine[0].anchorTension, tolerance);
        } else {
            EXPECT_LT(o.mooringLine[0].anchorTension, tolerance);
            EXPECT_GT(o.mooringLine[0].fairleadTension, 0.1 * T0);
        }
        (void)A0;
        std::printf("%s: line 1's integrator took %.0f steps over the 2.5 s from 2 s (the break at 2.3 s); tensions at 6 s "
                    "%.4g N at the fairlead, %.4g N at the anchor\n", atFairlead ? "fairlead" : "anchor",
                    stepsAfter - stepsBefore, o.mooringLine[0].fairleadTension, o.mooringLine[0].anchorTension);
    }
}

// The same across an anchor that lets go (line 1's far end, point 1).
TEST(LineFailure, StatesAcrossABreakAtAnAnchorRestoreBitForBit) {
    const Built a = restore_across_a_break("1  1  1  0.9  0\n");
    EXPECT_EQ(a.system->failure(0).ends[0].end, 1);
}

// Two lines listed together stay joined at the new free point: lines 1 and 2 both on point 4 detach at 1.5 s; from
// then on their ends pull on each other alone (equal tensions at the point, the massless point's balance) and the
// platform carries line 3 only. The two taut lines snap together at a point without mass (in steps of 0.05 s here;
// of 0.5 s and 1 s below).
TEST(LineFailure, LinesThatBreakTogetherStayJoinedAtTheirFreePoint) {
    std::string deck = spread("1  4  1,2  1.5  0\n");
    const std::string line2 = "2         main        2         5";
    ASSERT_NE(deck.find(line2), std::string::npos);
    deck.replace(deck.find(line2), line2.size(), "2         main        2         4");
    Built b = build(deck);
    uc::MooringSystem& s = *b.system;
    std::string error;
    ASSERT_TRUE(s.initialize(0.0, platform_at(0, 0, 0, 0), error)) << error;
    double t = 0.0;
    for (int k = 0; k < 80; ++k) {
        ASSERT_TRUE(s.step(t, 0.05, platform_at(0, 0, 0, 0), error)) << error << " at t = " << t;
        t += 0.05;
    }
    const UCOutputs& o = s.outputs();
    EXPECT_EQ(o.mooringLine[0].broken, 1.0);
    EXPECT_EQ(o.mooringLine[1].broken, 1.0);
    EXPECT_EQ(o.mooringLine[1].breakTime, 1.5);
    EXPECT_EQ(o.mooringLine[2].broken, 0.0);
    const double T1 = o.mooringLine[0].fairleadTension, T2 = o.mooringLine[1].fairleadTension;
    EXPECT_GT(T1, 1e4) << "the two lines hold each other up";
    EXPECT_NEAR(T1, T2, 1e-4 * T1) << "the massless point's balance";
    const double body = std::hypot(std::hypot(o.bodyLoad[0].force[0], o.bodyLoad[0].force[1]), o.bodyLoad[0].force[2]);
    EXPECT_NEAR(body, o.mooringLine[2].fairleadTension, 1e-9 * body) << "the platform carries line 3 alone";
}

// ------------------------------------------------------------------------------- a break along a line (failure.position)
namespace {

// OC4 line 1 (835.35 m of chain, 10 elements) to break at `position` m from its anchor by the failure.* parameters.
UCParams along(double position, double time, double tension = 0.0, int elements = 10) {
    UCParams p = system_parameters();
    p.lineFileElements = elements;
    p.failureLine = 1;
    p.failurePosition = position;
    p.failureTime = time;
    p.failureTension = tension;
    return p;
}

const double kHalf = 835.35 / 2;  // [m]: 5 elements below, 5 above

// The platform moved in surge and sway from rest (a few metres over tens of seconds): the lines' tensions vary.
UCInputs swaying(double t) {
    return platform_at(4.0 * (1.0 - std::cos(0.2 * t)), 2.0 * (1.0 - std::cos(0.15 * t)), 0.8 * std::sin(0.2 * t),
                       0.3 * std::sin(0.15 * t));
}

struct Tensions {
    std::vector<double> fairlead, anchor;
    std::vector<UCMooringLine> others;  // lines 2 and 3 at the last step
};

Tensions sway(const std::string& deck, const UCParams& p, double duration, double h) {
    Built b = build(deck, p);
    std::string error;
    Tensions T;
    EXPECT_TRUE(b.system->initialize(0.0, swaying(0.0), error)) << error;
    for (double t = 0.0; t < duration - 1e-9; t += h) {
        const bool stepped = b.system->step(t, h, swaying(t), error);
        EXPECT_TRUE(stepped) << error << " at t = " << t;
        if (!stepped) break;
        T.fairlead.push_back(b.system->outputs().mooringLine[0].fairleadTension);
        T.anchor.push_back(b.system->outputs().mooringLine[0].anchorTension);
    }
    T.others = {b.system->outputs().mooringLine[1], b.system->outputs().mooringLine[2], b.system->outputs().mooringLine[3]};
    return T;
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0.0;
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) d = std::max(d, std::abs(a[i] - b[i]));
    return d;
}

}  // namespace

// failure.position cuts the line in two lines of its type joined at a massless free point: until the break they are
// the whole line to the size of its discretisation error: the difference from the unsplit line is within twice the
// unsplit line's own change from 10 to 20 elements (the joint is stepped by the free nodes' coupled iteration over
// each 0.5 s step, the parts' meshes graded each on its own; docs/line_failure.md gives the numbers). The other lines
// keep their outputs bit for bit (line[k] is the deck line's; the lower part adds no line[k]).
TEST(LineFailure, ALineBuiltToBreakAlongItIsTheWholeLineBeforeTheBreak) {
    const double h = 0.5, duration = 20.0;
    const Tensions split = sway(spread(""), along(kHalf, 1000.0), duration, h);
    UCParams whole = system_parameters();
    const Tensions ten = sway(spread(""), whole, duration, h);
    whole.lineFileElements = 20;
    const Tensions twenty = sway(spread(""), whole, duration, h);
    ASSERT_EQ(split.fairlead.size(), ten.fairlead.size());
    const double fairlead = largest_difference(split.fairlead, ten.fairlead), anchor = largest_difference(split.anchor, ten.anchor);
    const double meshF = largest_difference(twenty.fairlead, ten.fairlead), meshA = largest_difference(twenty.anchor, ten.anchor);
    std::printf("split at %.3f m against the whole line (10 elements): fairlead %.1f N, anchor %.1f N at most (of %.4g N, "
                "%.4g N); 20 elements against 10: %.1f N, %.1f N\n", kHalf, fairlead, anchor, ten.fairlead.back(),
                ten.anchor.back(), meshF, meshA);
    EXPECT_LE(fairlead, 2.0 * meshF);
    EXPECT_LE(anchor, 2.0 * meshA);
    EXPECT_EQ(std::memcmp(&split.others[0], &ten.others[0], 2 * sizeof(UCMooringLine)), 0) << "lines 2 and 3";
    EXPECT_EQ(split.others[2].fairleadTension, 0.0) << "no line[4]";
}

namespace {

// Line 1 breaks 417.675 m from its anchor at 2.3 s, the platform held, over `duration` in steps of h.
struct Parted {
    std::vector<double> fairlead, anchor;
    std::string events;
};

Parted part_line(double duration, double h) {
    Built b = build(spread(""), along(kHalf, 2.3));
    uc::MooringSystem& s = *b.system;
    std::string error;
    Parted r;
    EXPECT_TRUE(s.initialize(0.0, platform_at(0, 0, 0, 0), error)) << error;
    for (double t = 0.0; t < duration - 1e-9; t += h) {
        const bool stepped = s.step(t, h, platform_at(0, 0, 0, 0), error);
        EXPECT_TRUE(stepped) << error << " at t = " << t;
        if (!stepped) break;
        r.events += s.take_event();
        const UCMooringLine& o = s.outputs().mooringLine[0];
        EXPECT_EQ(o.broken, t + h < 2.3 ? 0.0 : 1.0) << t + h;
        if (o.broken != 0.0) {
            EXPECT_EQ(o.breakTime, 2.3);
        }
        r.fairlead.push_back(o.fairleadTension);
        r.anchor.push_back(o.anchorTension);
    }
    return r;
}

}  // namespace

// After the break the upper part hangs from the fairlead down to the seabed and lies on it beyond: its fairlead carries
// the chain hanging down to the seabed, w (186 m), within half an element's weight over the last 20 s of 160 s (the
// touchdown lies inside an element, whose weight the seabed carries in part, as at an anchor that lets go); the lower
// part lies on the seabed from its anchor, its tension there that of a chain on a flat seabed: nothing (below 1 % of
// w (186 m)).
TEST(LineFailure, ALineBrokenAlongItHangsFromItsFairleadAndItsLowerPartLiesOnTheSeabed) {
    const Parted r = part_line(160.0, 0.5);
    ASSERT_EQ(r.fairlead.size(), 320u);
    EXPECT_NE(r.events.find("line failure 1 at t = 2.3 s: line 1 parted 417.675 m from its anchor"), std::string::npos) << r.events;
    const double hanging = kChainWeight * (200.0 - 14.0);
    std::printf("broken 417.675 m from the anchor at 2.3 s (fairlead %.4g N, anchor %.4g N before): at 140 s fairlead %.4g N, "
                "at 160 s %.4g N (w (186 m) = %.4g N), anchor %.4g N\n", r.fairlead[3], r.anchor[3], r.fairlead[279],
                r.fairlead.back(), hanging, r.anchor.back());
    for (size_t i = 279; i < r.fairlead.size(); ++i) {  // the last 20 s
        EXPECT_NEAR(r.fairlead[i], hanging, 0.5 * kElementWeight) << "at " << 0.5 * (i + 1) << " s";
        EXPECT_LT(r.anchor[i], 0.01 * hanging) << "at " << 0.5 * (i + 1) << " s";
    }
}

// By tension at the point along the line: the step ends where the lower part's tension there reaches the threshold
// (1.25 times its initial value, the platform pulled away from anchor 1), within the integrator's tolerance in
// tension, at the time of a run in steps of 0.1 s within that tolerance in time.
TEST(LineFailure, ALineBreaksAlongItWhereItsTensionThereReachesTheThreshold) {
    auto run = [](double h) {
        Built probe = build(spread(""), along(kHalf, 1000.0));
        std::string error;
        EXPECT_TRUE(probe.system->initialize(0.0, pulled(0.0), error)) << error;
        const double threshold = 1.25 * probe.system->failure_tension(0);
        Built b = build(spread(""), along(kHalf, 0.0, threshold));
        return step_to_break(*b.system, h, threshold);
    };
    expect_located(run(0.1), run(0.5), 1.25, "along the line");
}

// A break along a line is refused where it cannot be made, naming the parameter and the value.
TEST(LineFailureDeck, ABreakAlongALineIsRefusedBeyondItsLengthOrWithAPoint) {
    uc::MooringDeck deck;
    std::string error;
    ASSERT_TRUE(uc::read_mooring_deck(spread(""), 10, deck, error)) << error;
    UCParams p = along(900.0, 5.0);
    {
        uc::MooringSystem s(p, deck);
        EXPECT_FALSE(s.build(error));
        EXPECT_EQ(error, "failure.line = 1, failure.position = 900 m: beyond line 1's unstretched length, 835.35 m (the "
                         "position is measured from its anchor)");
    }
    p = along(400.0, 5.0);
    p.failurePoint = 4;
    {
        uc::MooringSystem s(p, deck);
        EXPECT_FALSE(s.build(error));
        EXPECT_EQ(error.rfind("failure.line = 1, failure.position = 400 m: failure.point = 4: a break along the line", 0), 0u) << error;
    }
}

// A system told to stop at breaks (FMI 3.0's early return) ends the step that holds a break at the break: its time is
// FailTime exactly, its state the state at the break (the line broken, the outputs there); the next step goes on
// from there. A step whose break is at its end, and a system not told, reach the step's end.
TEST(LineFailure, ASystemToldToStopAtBreaksEndsTheStepAtTheBreak) {
    Built b = build(spread("1  4  1  2.3  0\n2  5  2  3.0  0\n"));
    uc::MooringSystem& s = *b.system;
    std::string error;
    ASSERT_TRUE(s.initialize(0.0, platform_at(0, 0, 0, 0), error)) << error;
    s.set_stop_at_breaks(true);
    for (double t = 0.0; t < 2.0 - 1e-9; t += 0.5) ASSERT_TRUE(s.step(t, 0.5, platform_at(0, 0, 0, 0), error)) << error;
    ASSERT_TRUE(s.step(2.0, 0.5, platform_at(0, 0, 0, 0), error)) << error;
    EXPECT_EQ(s.time(), 2.3);
    EXPECT_EQ(s.outputs().mooringLine[0].broken, 1.0);
    EXPECT_EQ(s.outputs().mooringLine[0].breakTime, 2.3);
    // the state at the break: the line has not moved yet (its anchor holds it as before), its bare end carries nothing
    EXPECT_GT(s.outputs().mooringLine[0].anchorTension, 1e5) << "the state at the break: the line has not moved yet";
    EXPECT_LT(s.outputs().mooringLine[0].fairleadTension, s.failure_tolerance(0));
    ASSERT_TRUE(s.step(2.3, 0.7, platform_at(0, 0, 0, 0), error)) << error;  // line 2 breaks at 3.0, the step's end
    EXPECT_NEAR(s.time(), 3.0, 1e-12) << "the step's end (to round-off), not earlier";
    EXPECT_EQ(s.outputs().mooringLine[1].broken, 1.0);
    EXPECT_EQ(s.outputs().mooringLine[1].breakTime, 3.0);
}


// The same in communication steps of 0.5 s and 1 s: the step of the snap is split into up to kMaxSplitSubsteps
// substeps where the point's coupled iteration does not converge in fewer (32 at 0.5 s), and the run agrees with the
// run in steps of 0.05 s at the common points, within the free nodes' own error control: kNodeStepError in the point's
// position, times the chain's axial stiffness at its end (EA over an element's length) in tension.
TEST(LineFailure, LinesThatBreakTogetherRunInStepsOfHalfASecondAndOfOne) {
    std::string deck = spread("1  4  1,2  1.5  0\n");
    const std::string line2 = "2         main        2         5";
    deck.replace(deck.find(line2), line2.size(), "2         main        2         4");
    auto run = [&](double h) {
        Built b = build(deck);
        uc::MooringSystem& s = *b.system;
        std::string error;
        std::vector<double> T;  // lines 1 and 2 at 1, 2, 3, 4 s
        EXPECT_TRUE(s.initialize(0.0, platform_at(0, 0, 0, 0), error)) << error;
        const int n = static_cast<int>(std::lround(4.0 / h)), every = static_cast<int>(std::lround(1.0 / h));
        for (int k = 1; k <= n; ++k) {
            const bool stepped = s.step((k - 1) * h, h, platform_at(0, 0, 0, 0), error);
            EXPECT_TRUE(stepped) << error << " at t = " << (k - 1) * h << " in steps of " << h << " s";
            if (!stepped) break;
            if (k % every == 0) {
                T.push_back(s.outputs().mooringLine[0].fairleadTension);
                T.push_back(s.outputs().mooringLine[1].fairleadTension);
            }
        }
        return T;
    };
    const std::vector<double> fine = run(0.05);
    const double tolerance = uc::MooringSystem::kNodeStepError * 7.536e8 / (835.35 / 10);  // [N]
    for (double h : {0.5, 1.0}) {
        const std::vector<double> T = run(h);
        ASSERT_EQ(T.size(), fine.size()) << "h = " << h;
        for (size_t i = 0; i < T.size(); ++i) {
            EXPECT_NEAR(T[i], fine[i], tolerance) << "h = " << h << ", line " << i % 2 + 1 << " at " << i / 2 + 1 << " s";
            std::printf("h = %g s: line %zu at %zu s: %.1f N (0.05 s: %.1f N)\n", h, i % 2 + 1, i / 2 + 1, T[i], fine[i]);
        }
    }
}
