// failure.cpp - line failures in a mooring system (docs/line_failure.md): the failures of the deck's FAILURE rows
// and of the failure.* parameters, the communication step taken in pieces that end at each break (a break by
// tension located by regula falsi), the break itself (the lines' ends onto a new massless free node), the
// deck's lines and nodes as the failures' states make them, and the failures' part of the outputs, the
// description and the saved state.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "numerics/locate_crossing.h"
#include "system/mooring_system.h"

namespace uc {

bool MooringSystem::build_failures(std::string& error) {
    failures_ = deck_.failures;
    if (base_.failureLine > 0) {  // the failure.* parameters' failure, after the deck's
        char text[160];
        if (base_.failurePosition > 0.0) {
            std::snprintf(text, sizeof text, "failure.line = %d, failure.position = %.9g m: ", base_.failureLine,
                          base_.failurePosition);
        } else {
            std::snprintf(text, sizeof text, "failure.line = %d, failure.point = %d: ", base_.failureLine, base_.failurePoint);
        }
        if (base_.failureLine > deck_.deckLines) {
            error = text + std::string("the deck has ") + std::to_string(deck_.deckLines) + " lines";
            return false;
        }
        if (base_.failureTime == 0.0 && base_.failureTension == 0.0) {
            error = text + std::string("failure.time and failure.tension are both 0: the line would never break "
                                       "(give a time in s, a tension in N, or both: the first reached breaks it)");
            return false;
        }
        MooringFailure f;
        f.id = static_cast<int>(failures_.size()) + 1;
        f.time = base_.failureTime;
        f.tension = base_.failureTension;
        if (base_.failurePosition > 0.0 && base_.failurePoint != 0) {
            error = text + std::string("failure.point = ") + std::to_string(base_.failurePoint) +
                    ": a break along the line is at failure.position, not at a point (give one of them)";
            return false;
        }
        int k = -1;  // the system's line that holds the deck line
        for (size_t j = 0; j < deck_.lines.size(); ++j) {
            const std::vector<int>& d = deck_.lines[j].deckLines;
            if (std::find(d.begin(), d.end(), base_.failureLine - 1) != d.end()) k = static_cast<int>(j);
        }
        if (base_.failurePosition > 0.0 ? !split_line(k, base_.failurePosition, f, error)
                                        : !resolve_failure(deck_, base_.failurePoint, {base_.failureLine - 1}, f, error)) {
            error = text + error;
            return false;
        }
        failures_.push_back(f);
    }
    for (const MooringFailure& f : failures_) {  // an anchor that detaches: its line's far end is driven
        for (const MooringFailure::End& e : f.ends) {
            MooringDeckLine& l = deck_.lines[e.line];
            if (e.end == 1 && !l.farFree && l.far.kind == MooringEnd::Kind::Fixed) l.farDetaches = true;
        }
    }
    // A failure of one line's end lets go as the line's own bare far end, where the line is in no other failure
    // and can be run from its far end (its fairlead letting go: a far end that is held).
    releases_.assign(failures_.size(), 0);
    for (size_t f = 0; f < failures_.size(); ++f) {
        const MooringFailure& fail = failures_[f];
        if (fail.ends.size() != 1 || fail.position > 0.0) continue;
        const MooringFailure::End& e = fail.ends[0];
        int uses = 0;
        for (const MooringFailure& g : failures_)
            for (const MooringFailure::End& o : g.ends) uses += o.line == e.line ? 1 : 0;
        for (const SplitLine& split : splits_) uses += split.upper == e.line || split.lower == e.line ? 1 : 0;
        if (uses == 1 && !(e.end == 0 && deck_.lines[e.line].farFree)) releases_[f] = 1;
    }
    failureState_.assign(failures_.size(), FailureState{0.0, 0.0, 0.0});
    return true;
}

const MooringFailure::End* MooringSystem::released_end(int f) const {
    return releases_[f] ? &failures_[f].ends[0] : nullptr;
}

MooringDeckLine MooringSystem::released_line(const MooringDeckLine& l, bool flip) {
    MooringDeckLine r = l;
    if (flip) {  // run from its far end: the sections, their joints and their deck lines the other way round
        std::reverse(r.sections.begin(), r.sections.end());
        std::reverse(r.joints.begin(), r.joints.end());
        std::reverse(r.deckLines.begin(), r.deckLines.end());
        r.flipped.assign(l.flipped.rbegin(), l.flipped.rend());
        r.flipped.flip();
        r.fairlead = l.far;
        r.fairleadPoint = l.farPoint;
        r.fairleadClamped = false;
        std::fill(r.fairleadTangent, r.fairleadTangent + 3, 0.0);
    }
    r.far = MooringEnd();
    r.farPoint = 0;
    r.farFree = true;
    r.farBody = LineFilePoint();
    r.farDetaches = false;
    return r;
}

size_t MooringSystem::node_count(const std::vector<FailureState>& states) const {
    size_t nodes = deck0_.nodes.size();
    for (size_t f = 0; f < states.size(); ++f) nodes += states[f].broken != 0.0 && !releases_[f] ? 1 : 0;
    return nodes;
}

bool MooringSystem::split_line(int k, double position, MooringFailure& f, std::string& error) {
    MooringDeckLine& l = deck_.lines[k];
    if (l.sections.size() != 1 || l.farFree) {
        error = "line " + std::to_string(l.id) + (l.farFree ? " has a free far end" : " is one line of several deck lines "
                "joined at free points") + ": a break along a line is supported on a line from its fairlead to an "
                "anchor or another held end (give failure.point instead)";
        return false;
    }
    const double length = l.sections[0].length;
    if (!(position < length)) {
        char text[200];
        std::snprintf(text, sizeof text, "beyond line %d's unstretched length, %.9g m (the position is measured from "
                      "its anchor)", l.id, length);
        error = text;
        return false;
    }
    for (const MooringFailure& g : failures_) {
        for (const MooringFailure::End& e : g.ends) {
            if (e.line == k) {
                error = "line " + std::to_string(l.id) + " already breaks in failure " + std::to_string(g.id) +
                        " (one failure per line where it breaks along the line)";
                return false;
            }
        }
    }
    // the joint: a massless free node, first guessed on the chord at that length from the far end (above the seabed)
    MooringNode joint;
    joint.failure = f.id;
    const double r = position / length;
    for (int c = 0; c < 3; ++c) joint.position[c] = l.far.position[c] + r * (l.fairlead.position[c] - l.far.position[c]);
    joint.position[2] = std::max(joint.position[2], -deck_.waterDepth);
    const int node = static_cast<int>(deck_.nodes.size());
    deck_.nodes.push_back(joint);
    // the elements shared out in proportion to the parts' lengths, at least one each
    const int elements = l.sections[0].elements;
    const int below = std::clamp(static_cast<int>(std::lround(elements * r)), 1, std::max(1, elements - 1));
    MooringDeckLine lower = l;
    lower.sections[0].length = position;
    lower.sections[0].elements = below;
    lower.fairlead = MooringEnd();
    lower.fairlead.kind = MooringEnd::Kind::Node;
    lower.fairlead.node = node;
    std::copy(joint.position, joint.position + 3, lower.fairlead.position);
    lower.fairleadPoint = 0;
    l.sections[0].length = length - position;
    l.sections[0].elements = std::max(1, elements - below);
    l.far = lower.fairlead;
    l.farPoint = 0;
    l.farDetaches = false;
    splits_.push_back({k, static_cast<int>(deck_.lines.size())});
    f.point = 0;
    f.position = position;
    f.ends = {MooringFailure::End{splits_.back().lower, 0, l.deckLines[0]}};
    deck_.lines.push_back(lower);
    return true;
}

void MooringSystem::split_outputs() {
    for (const SplitLine& s : splits_) {
        const MooringDeckLine& l = deck_.lines[s.upper];
        const UCOutputs& up = lines_[s.upper]->outputs();
        const UCOutputs& low = lines_[s.lower]->outputs();
        const double fairlead = up.towTension, anchor = low.endTension;
        UCMooringLine& out = line_output(l.deckLines[0]);
        LineStrength strength = line_strength(*lines_[s.upper], 0, 0);
        strength.maxUtilisation = std::max(strength.maxUtilisation, line_strength(*lines_[s.lower], 0, 0).maxUtilisation);
        set_mooring_line_outputs(out, l.flipped[0] ? anchor : fairlead, l.flipped[0] ? fairlead : anchor, up, strength);
        out.minTension = std::min(up.minTension, low.minTension);
        out.groundedLength = up.groundedLength + low.groundedLength;
    }
}

void MooringSystem::describe_failures() {
    auto add = [&](const std::string& name, double value) { description_.push_back({name, value}); };
    for (const MooringFailure& f : failures_) {
        const std::string prefix = "failure " + std::to_string(f.id) +
                                   (f.row > 0 ? " (deck row " + std::to_string(f.row) + "): " : " (failure.*): ");
        add(prefix + "point", f.point);
        add(prefix + "FailTime [s]", f.time);
        add(prefix + "FailTen [N]", f.tension);
        if (f.position > 0.0) add(prefix + "position [m]", f.position);
        for (const MooringFailure::End& e : f.ends) {
            add(prefix + "line", e.deckLine + 1);
            add(prefix + "end", e.end);
        }
    }
}

void MooringSystem::failure_outputs() {
    for (size_t f = 0; f < failures_.size(); ++f) {
        if (failureState_[f].broken == 0.0) continue;
        for (const MooringFailure::End& e : failures_[f].ends) {
            UCMooringLine& out = line_output(e.deckLine);
            if (out.broken != 0.0 && out.breakTime <= failureState_[f].time) continue;  // broke before, at its other end
            out.broken = 1.0;
            out.breakTime = failureState_[f].time;
        }
    }
}

unsigned char* MooringSystem::save_failures(unsigned char* out) const {
    if (!failureState_.empty()) std::memcpy(out, failureState_.data(), failureState_.size() * sizeof(FailureState));
    return out + failureState_.size() * sizeof(FailureState);
}

std::vector<FailureState> MooringSystem::saved_failures(const unsigned char* at, bool present, size_t& nodes) const {
    std::vector<FailureState> failureState(failureState_.size());
    if (present && !failureState.empty()) std::memcpy(failureState.data(), at, failureState.size() * sizeof(FailureState));
    nodes = node_count(failureState);
    return failureState;
}

void MooringSystem::undo_breaks() {
    if (!std::any_of(failureState_.begin(), failureState_.end(), [](const FailureState& s) { return s.broken != 0.0; }))
        return;
    failureState_.assign(failures_.size(), FailureState{0.0, 0.0, 0.0});
    motion_.resize(deck0_.nodes.size());
    apply_failures();
}

double MooringSystem::failure_tension(int f) const {
    double tension = 0.0;
    for (const MooringFailure::End& e : failures_[f].ends) {
        const UCOutputs& o = lines_[e.line]->outputs();
        tension = std::max(tension, e.end == 0 ? o.towTension : o.endTension);
    }
    return tension;
}

double MooringSystem::failure_tolerance(int f) const {
    double tolerance = 0.0;
    for (const MooringFailure::End& e : failures_[f].ends) {
        const CableSimulation& line = *lines_[e.line];
        tolerance = std::max(tolerance, line.model().params().tensionTolerance * line.outputs().tensionScale);
    }
    return tolerance;
}

bool MooringSystem::failures_pending() const {
    for (const FailureState& s : failureState_)
        if (s.broken == 0.0) return true;
    return false;
}

int MooringSystem::failure_node(int f) const {
    int n = static_cast<int>(deck0_.nodes.size());
    for (int g = 0; g < f; ++g) n += failureState_[g].broken != 0.0 && !releases_[g] ? 1 : 0;
    return n;
}

void MooringSystem::apply_failures() {
    deck_.lines = deck0_.lines;
    deck_.nodes = deck0_.nodes;
    for (size_t f = 0; f < failures_.size(); ++f) {
        if (failureState_[f].broken == 0.0) continue;
        if (const MooringFailure::End* e = released_end(static_cast<int>(f))) {  // the line's own bare far end
            deck_.lines[e->line] = released_line(deck0_.lines[e->line], e->end == 0);
            continue;
        }
        MooringNode node;  // no mass, volume or drag: the lines joined, or a line's bare end
        node.failure = failures_[f].id;
        node.point.id = failures_[f].point;
        const int n = static_cast<int>(deck_.nodes.size());
        deck_.nodes.push_back(node);
        for (const MooringFailure::End& e : failures_[f].ends) {
            MooringEnd& end = e.end == 0 ? deck_.lines[e.line].fairlead : deck_.lines[e.line].far;
            end = MooringEnd();
            end.kind = MooringEnd::Kind::Node;
            end.node = n;
        }
    }
    nodeOffset_.clear();
    nodeUnknowns_ = 0;
    for (const MooringNode& node : deck_.nodes) {
        nodeOffset_.push_back(nodeUnknowns_);
        nodeUnknowns_ += node_unknowns(node);
    }
}

bool MooringSystem::break_failure(int f, double t, std::string& error) {
    const MooringFailure& fail = failures_[f];
    if (const MooringFailure::End* e = released_end(f)) {  // the line goes on by itself, its end bare
        const double tension = failure_tension(f);
        const MooringDeckLine& l = deck_.lines[e->line];
        if (!lines_[e->line]->release(t, error)) {
            error = "line failure " + std::to_string(fail.id) + " at t = " + std::to_string(t) + " s: mooring line " +
                    std::to_string(l.id) + ": " + error;
            return false;
        }
        failureState_[f] = FailureState{1.0, t, tension};
        apply_failures();
        char text[400];
        std::snprintf(text, sizeof text, "line failure %d at t = %.9g s: line %d detached from point %d, tension there "
                      "%.6g N (FailTime %.6g s, FailTen %.6g N); its end goes on bare, the line's own free end%s",
                      fail.id, t, e->deckLine + 1, fail.point, tension, fail.time, fail.tension,
                      e->end == 0 ? " (the line run from its anchor)" : "");
        append_event(event_, text);
        return true;
    }
    // the new node starts where its ends stand and move (they share the point)
    const MooringFailure::End& first = fail.ends[0];
    const DrivenEndState& at = lines_[first.line]->driven_end(first.end == 1);
    FreeNodeMotion m{};
    Eigen::Map<Vec3>(m.position) = at.p();
    Eigen::Map<Vec3>(m.velocity) = at.v();
    Eigen::Map<Vec3>(m.acceleration) = at.a();
    Eigen::Map<Vec3>(m.inputPosition) = at.p();
    Eigen::Map<Vec3>(m.inputVelocity) = at.v();
    Eigen::Map<Vec3>(m.inputAcceleration) = at.a();
    Eigen::Map<Mat3>(m.rotation) = Mat3::Identity();
    const double tension = failure_tension(f);
    const int n = failure_node(f);
    failureState_[f] = FailureState{1.0, t, tension};
    motion_.insert(motion_.begin() + n, m);
    apply_failures();
    std::string lines;
    for (const MooringFailure::End& e : fail.ends) lines += (lines.empty() ? "" : ", ") + std::to_string(e.deckLine + 1);
    char text[400];
    if (fail.position > 0.0) {
        std::snprintf(text, sizeof text, "line failure %d at t = %.9g s: line %s parted %.6g m from its anchor, tension "
                      "there %.6g N (FailTime %.6g s, FailTen %.6g N); both parts go on with bare ends", fail.id, t,
                      lines.c_str(), fail.position, tension, fail.time, fail.tension);
    } else {
        std::snprintf(text, sizeof text, "line failure %d at t = %.9g s: line%s %s detached from point %d, tension there "
                      "%.6g N (FailTime %.6g s, FailTen %.6g N); %s on a massless free point", fail.id, t,
                      fail.ends.size() > 1 ? "s" : "", lines.c_str(), fail.point, tension, fail.time, fail.tension,
                      fail.ends.size() > 1 ? "they go on joined" : "its end goes on bare");
    }
    append_event(event_, text);
    return true;
}

bool MooringSystem::step_with_failures(double t, double h, const UCInputs& in, double& taken, std::string& error) {
    const double eps = 1e-12 * std::max(1.0, std::abs(t + h));  // times closer than this are one
    // how far the pending failures by tension are from their thresholds, the largest, in their tolerances
    auto crossing = [&]() {
        double g = -HUGE_VAL;
        for (size_t f = 0; f < failures_.size(); ++f) {
            if (failureState_[f].broken != 0.0 || failures_[f].tension <= 0.0) continue;
            const int i = static_cast<int>(f);
            g = std::max(g, (failure_tension(i) - failures_[f].tension) / failure_tolerance(i));
        }
        return g;
    };
    double done = 0.0;  // of h
    while (true) {
        // what breaks where the piece starts: its time reached, its tension at its threshold within the tolerance
        bool broke = false;
        for (size_t f = 0; f < failures_.size(); ++f) {
            if (failureState_[f].broken != 0.0) continue;
            const MooringFailure& fail = failures_[f];
            const int i = static_cast<int>(f);
            const bool byTime = fail.time > 0.0 && fail.time <= t + done + eps;
            if (byTime || (fail.tension > 0.0 && failure_tension(i) >= fail.tension - failure_tolerance(i))) {
                if (!break_failure(i, byTime && fail.time >= t + done - eps ? fail.time : t + done, error))  // its time exactly
                    return false;
                broke = true;
            }
        }
        if (broke && stopAtBreaks_ && done > 0.0 && done < h) {  // the step ends at the break, the state there
            taken = done;
            return true;
        }
        if (done >= h) return true;
        if (!failures_pending()) return advance(t + done, h - done, done > 0.0 ? done : -1.0, in, error);
        double end = h;  // the piece ends at the first failure's time within the step
        for (size_t f = 0; f < failures_.size(); ++f) {
            const double time = failures_[f].time - t;
            if (failureState_[f].broken == 0.0 && failures_[f].time > 0.0 && time < end) end = time;
        }
        if (end > h - eps) end = h;
        const double offset = done > 0.0 || end < h ? done : -1.0;
        const double g0 = crossing();
        const bool byTension = g0 > -HUGE_VAL;
        if (byTension) {  // the piece's start, to locate a break within it
            failureBuffer_.resize(state_size());
            save_state(failureBuffer_.data());
        }
        if (!advance(t + done, end - done, offset, in, error)) return false;
        double g = byTension ? crossing() : -HUGE_VAL;
        if (g <= 1.0) {  // no threshold passed by more than the tolerance: the piece stands
            done = end;
            continue;
        }
        // A threshold was passed within the piece: the time where the tension reaches it, by regula falsi
        // (Illinois) on the piece's length, each trial the piece taken anew from its start.
        double tau = end - done;
        const bool located = locate_crossing(g0, end - done, g, kLocateIterations, [&](double length, double& trialG) {
            if (!restore_state(failureBuffer_.data(), failureBuffer_.size(), error) || !advance(t + done, length, done, in, error))
                return false;
            ++failureEvaluations_;
            trialG = crossing();
            return true;
        }, tau, g);
        if (!located) return false;
        if (std::abs(g) > 1.0) {
            char text[300];
            std::snprintf(text, sizeof text, "the break by tension within the step from t = %.9g s was located to "
                          "%.3g of its tolerance after %d trials (at t = %.9g s)", t + done, g, kLocateIterations,
                          t + done + tau);
            append_event(event_, text);
        }
        done += tau;  // the loop's start breaks what reached its threshold there
    }
}

}  // namespace uc
