// one_line_failure.cpp - one line whose far end lets go (docs/line_failure.md, "One line"): the failure.*
// parameters checked, the step that holds the break taken in pieces that end at it, the break itself (the line's far
// end made bare: CableSimulation::release).
#include <cmath>
#include <cstdio>

#include "numerics/locate_crossing.h"
#include "system/mooring_system.h"

namespace uc {

std::string OneLineSystem::check_failure(const UCParams& p) {
    if (p.failureLine == 0) return "";
    const std::string line = "failure.line = " + std::to_string(p.failureLine) + ": ";
    char text[300];
    if (p.failureLine != 1) return line + "one line (no deck of several lines) is line 1: set failure.line = 1 or 0";
    if (p.failurePoint != 0) {
        return line + "failure.point = " + std::to_string(p.failurePoint) + ": one line has no deck points; the end "
               "that detaches is its far end (failure.point = 0)";
    }
    if (p.failurePosition > 0.0) {
        std::snprintf(text, sizeof text, "failure.position = %.9g m: a break along one line is supported in a mooring "
                      "system only; one line's far end detaches (failure.position = 0)", p.failurePosition);
        return line + text;
    }
    if (p.failureTime == 0.0 && p.failureTension == 0.0) {
        return line + "failure.time and failure.tension are both 0: the line would never break (give a time in s, a "
               "tension in N, or both: the first reached breaks it)";
    }
    if (p.bottomEnd == UC_BOTTOM_FREE) {
        return line + "bottomEnd = 0: the far end is free already, nothing holds it to let go (its far end detaches: "
               "bottomEnd 1, 2, 3 or 4)";
    }
    if (p.winchMode != UC_WINCH_FIXED) {
        return line + "winchMode = " + std::to_string(p.winchMode) + ": a line whose far end lets go has no winch "
               "(winchMode 0)";
    }
    return "";
}

OneLineSystem::OneLineSystem(const UCParams& params) : CableSimulation(params) {
    if (params.failureLine != 1) return;
    breaks_ = true;
    failTime_ = params.failureTime;
    failTension_ = params.failureTension;
    prepare_release(params, false);
}

std::string OneLineSystem::take_event() {
    std::string events;
    events.swap(event_);
    append_event(events, CableSimulation::take_event());
    return events;
}

bool OneLineSystem::step(double t, double h, const UCInputs& in, std::string& error) {
    failureEvaluations_ = 0;
    if (!breaks_ || released() != 0) return CableSimulation::step(t, h, in, error);
    const EndMotion tow = tow_motion(in), far = far_motion(in);
    const LineEnvironment env = line_environment(in);
    const bool drivenFar = model().far_end().driven;
    // a piece from `offset` after the step's start (offset < 0: the whole step): the driven ends' inputs extrapolated
    // to its start with their accelerations (given, or the difference of the last two velocity inputs), as a mooring
    // system's coupled ends
    const DrivenEndState towAtStart = driven_end(false), farAtStart = driven_end(true);
    const double lastStep = last_step_size();
    auto shifted = [&](EndMotion e, const DrivenEndState& last, double shift) {
        for (int c = 0; c < 3; ++c) {
            if (!e.accelerationGiven)
                e.acceleration[c] = lastStep > 0.0 ? (e.velocity[c] - last.lastVelocityInput[c]) / lastStep : 0.0;
            e.position[c] += shift * (e.velocity[c] + 0.5 * shift * e.acceleration[c]);
            e.velocity[c] += shift * e.acceleration[c];
        }
        e.accelerationGiven = 1;
        return e;
    };
    auto advance = [&](double offset, double length) {
        if (offset < 0.0) return CableSimulation::step(length, tow, far, env, error);
        return CableSimulation::step(length, shifted(tow, towAtStart, offset),
                                     drivenFar ? shifted(far, farAtStart, offset) : far, env, error);
    };
    const double tolerance = model().params().tensionTolerance * outputs().tensionScale;
    auto crossing = [&]() { return (outputs().endTension - failTension_) / tolerance; };
    const double eps = 1e-12 * std::max(1.0, std::abs(t + h));  // times closer than this are one
    double done = 0.0;  // of h
    while (true) {
        if (released() == 0) {  // breaks where the piece starts: its time reached, its tension within the tolerance
            const bool byTime = failTime_ > 0.0 && failTime_ <= t + done + eps;
            if (byTime || (failTension_ > 0.0 && outputs().endTension >= failTension_ - tolerance)) {
                const double at = byTime && failTime_ >= t + done - eps ? failTime_ : t + done;  // its time exactly
                const double tension = outputs().endTension;
                if (!release(at, error)) return false;
                char text[300];
                std::snprintf(text, sizeof text, "line failure 1 at t = %.9g s: line 1's far end detached, tension there "
                              "%.6g N (failure.time %.6g s, failure.tension %.6g N); the line goes on with a bare far end",
                              at, tension, failTime_, failTension_);
                append_event(event_, text);
                if (stopAtBreaks_ && done > 0.0 && done < h) return true;  // the step ends at the break
            }
        }
        if (done >= h) return true;
        if (released() != 0) return advance(done > 0.0 ? done : -1.0, h - done);
        double end = h;  // the piece ends at the failure's time within the step
        if (failTime_ > 0.0 && failTime_ - t < end) end = failTime_ - t;
        if (end > h - eps) end = h;
        const double offset = done > 0.0 || end < h ? done : -1.0;
        const bool byTension = failTension_ > 0.0;
        const double g0 = byTension ? crossing() : -HUGE_VAL;
        if (byTension) {  // the piece's start, to locate a break within it
            buffer_.resize(state_size());
            save_state(buffer_.data());
        }
        if (!advance(offset, end - done)) return false;
        double g = byTension ? crossing() : -HUGE_VAL;
        if (g <= 1.0) {
            done = end;
            continue;
        }
        double tau = end - done;
        const bool located = locate_crossing(g0, end - done, g, kLocateIterations, [&](double length, double& trialG) {
            if (!restore_state(buffer_.data(), buffer_.size(), error) || !advance(done, length)) return false;
            ++failureEvaluations_;
            trialG = crossing();
            return true;
        }, tau, g);
        if (!located) return false;
        done += tau;
    }
}

}  // namespace uc
