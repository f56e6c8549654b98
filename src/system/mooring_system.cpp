// mooring_system.cpp - the lines of a mooring system driven by the coupled bodies and points
// (docs/systems_mooring.md).
#include "system/mooring_system.h"
#include "system/body_rods.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "terms/hydrodynamics.h"
#include "model/params.h"

namespace uc {
namespace {

constexpr std::uint32_t kSystemMagic = 0x5543534D;  // "UCSM"
// 4: the failures' states (FailureState) after the last inputs, the nodes of the broken ones with the others
// 5: sized by the deck: the lines' state sizes after the header (as many as the system has lines), the
//    outputs of the deck's lines beyond UC_MAX_LINES after the system's outputs
// 6: a line's end that lets go alone is its own bare far end (the line's state says so), no free node
constexpr std::uint32_t kSystemVersion = 6;

// What the versions after `version` added, for the message that refuses an older state: " (version 4 added
// ..., 5 ...)", or nothing for a state of a later version.
std::string what_later_versions_added(std::uint32_t version) {
    static const char* const added[] = {"4 added the line failures' state", "5 sized the state by the deck",
                                        "6 made a broken line's bare end the line's own free end"};
    std::string text;
    for (std::uint32_t v = std::max<std::uint32_t>(version + 1, 4); v <= kSystemVersion; ++v)
        text += std::string(text.empty() ? " (version " : ", ") + added[v - 4];
    return text.empty() ? text : text + ")";
}

struct SystemHeader {
    std::uint32_t magic, version;
    std::int32_t lines, bodies, nodes, failures;
    double lastStep;
    std::uint64_t described;  // values of the system's description that follow the line sizes
};

Vec3 vec3(const double v[3]) { return Vec3(v[0], v[1], v[2]); }
void put(double to[3], const Vec3& v) {
    for (int c = 0; c < 3; ++c) to[c] = v[c];
}
Mat3 rotation(const FreeNodeMotion& m) { return Eigen::Map<const Mat3>(m.rotation); }
void put_rotation(FreeNodeMotion& m, const Mat3& R) { Eigen::Map<Mat3>(m.rotation) = R; }

}  // namespace

const MooringEnd* held_far_end(const MooringDeckLine& l) { return l.farFree ? nullptr : &l.far; }

bool on_free_node(const MooringDeckLine& l) {
    const MooringEnd* far = held_far_end(l);
    return l.fairlead.kind == MooringEnd::Kind::Node || (far && far->kind == MooringEnd::Kind::Node);
}

Mat3 turn_matrix(const Vec3& turn) {
    const double angle = turn.norm();
    return Eigen::AngleAxisd(angle, angle > 0.0 ? Vec3(turn / angle) : Vec3::UnitX()).toRotationMatrix();
}

Mat3 body_rotation(double roll, double pitch, double yaw) {
    return (Eigen::AngleAxisd(roll, Vec3::UnitX()) * Eigen::AngleAxisd(pitch, Vec3::UnitY()) *
            Eigen::AngleAxisd(yaw, Vec3::UnitZ()))
        .toRotationMatrix();
}

Mat3 coupled_body_rotation(const UCCoupledBody& body, int orientation) {
    const double* a = body.rotation;
    if (orientation == UC_ORIENTATION_QUATERNION) {
        const double* q = body.quaternion;
        return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
    }
    if (orientation == UC_ORIENTATION_ANGLES_ZYX) {
        return (Eigen::AngleAxisd(a[2], Vec3::UnitZ()) * Eigen::AngleAxisd(a[1], Vec3::UnitY()) *
                Eigen::AngleAxisd(a[0], Vec3::UnitX()))
            .toRotationMatrix();
    }
    return body_rotation(a[0], a[1], a[2]);
}

LineStrength line_strength(const CableSimulation& line, int firstSection, int lastSection) {
    const CableModel& model = line.model();
    LineStrength s;
    s.fairleadMBL = model.section(firstSection).MBL;
    s.anchorMBL = model.section(lastSection).MBL;
    for (int j = firstSection; j <= lastSection; ++j) {
        const double mbl = model.section(j).MBL;
        if (mbl > 0.0 && (s.smallestMBL == 0.0 || mbl < s.smallestMBL)) s.smallestMBL = mbl;
    }
    for (const ElementRun& run : model.runs()) {
        const double mbl = model.section(run.section).MBL;
        if (run.section < firstSection || run.section > lastSection || !(mbl > 0.0)) continue;
        for (int e = run.first; e < run.first + run.count; ++e) {
            const double t = std::max(line.element_end_tension(e, false), line.element_end_tension(e, true));
            s.maxUtilisation = std::max(s.maxUtilisation, t / mbl);
        }
    }
    return s;
}

void set_mooring_line_outputs(UCMooringLine& out, double fairlead, double anchor, const UCOutputs& line,
                              const LineStrength& strength) {
    out.fairleadTension = fairlead;
    out.anchorTension = anchor;
    out.minTension = line.minTension;
    out.groundedLength = line.groundedLength;
    out.MBL = strength.smallestMBL;
    out.fairleadUtilisation = strength.fairleadMBL > 0.0 ? fairlead / strength.fairleadMBL : 0.0;
    out.anchorUtilisation = strength.anchorMBL > 0.0 ? anchor / strength.anchorMBL : 0.0;
    // the ends' tensions (the outputs' own, at the end nodes) belong to the largest too
    out.maxUtilisation = std::max({strength.maxUtilisation, out.fairleadUtilisation, out.anchorUtilisation});
}

void OneLineSystem::complete_outputs(UCOutputs& out) const {
    set_mooring_line_outputs(out.mooringLine[0], out.towTension, out.endTension, out,
                             line_strength(*this, 0, model().n_sections() - 1));
    if (released() != 0) out.mooringLine[0].anchorTension = bare_end_force().norm();  // (as a system's broken line)
    out.mooringLine[0].broken = released() != 0 ? 1.0 : 0.0;
    out.mooringLine[0].breakTime = released() != 0 ? release_time() : 0.0;
}

MooringSystem::MooringSystem(const UCParams& base, const MooringDeck& deck)
    : base_(base), deck_(deck), currentGrid_(deck.sea.currentGrid), seabedGrid_(deck.seabed.grid) {}

void MooringSystem::set_seabed_grid(std::shared_ptr<const SeabedGrid> grid) {
    seabedGrid_ = std::move(grid);
    for (auto& line : lines_) line->set_seabed_grid(seabedGrid_);
}

void MooringSystem::set_current_grid(std::shared_ptr<const CurrentGrid> grid) {
    currentGrid_ = std::move(grid);
    for (auto& line : lines_) line->set_current_grid(currentGrid_);
}

bool MooringSystem::build(std::string& error) {
    if (base_.winchMode != UC_WINCH_FIXED) {
        error = "winchMode = " + std::to_string(base_.winchMode) + ": a winch is not supported in a mooring system "
                "(winchMode 0)";
        return false;
    }
    if (!build_failures(error)) return false;
    for (size_t k = 0; k < deck_.lines.size(); ++k) {
        UCParams p;
        if (!mooring_line_params(deck_, static_cast<int>(k), base_, p, error)) return false;
        error = check_params(p);
        if (!error.empty()) {  // the deck's line of the file, as the reader names it
            error = "line " + std::to_string(deck_.lines[k].row) + ": line " + std::to_string(deck_.lines[k].id) +
                    ": " + error;
            return false;
        }
        lines_.push_back(std::make_unique<CableSimulation>(p));
        if (currentGrid_) lines_.back()->set_current_grid(currentGrid_);
        if (seabedGrid_) lines_.back()->set_seabed_grid(seabedGrid_);
        for (size_t f = 0; f < failures_.size(); ++f) {  // what the line becomes where its end lets go
            const MooringFailure::End* e = released_end(static_cast<int>(f));
            if (!e || e->line != static_cast<int>(k)) continue;
            MooringDeck released = deck_;
            released.lines[k] = released_line(deck_.lines[k], e->end == 0);
            UCParams r;
            if (!mooring_line_params(released, static_cast<int>(k), base_, r, error)) return false;
            lines_.back()->prepare_release(r, e->end == 0);
        }
        const CableModel& model = lines_.back()->model();
        std::vector<LineProfile::Segment> segments;
        double weight = 0.0;
        for (int j = 0; j < model.n_sections(); ++j) {
            const SectionProps& s = model.section(j);
            segments.push_back({s.length, submerged_weight(s.fluid), s.axial.EA, dry_weight(s.fluid)});
            weight += s.length * submerged_weight(s.fluid);
        }
        std::vector<LineProfile::PointLoad> points;
        for (const NodeAttachment& at : model.attachments()) {
            const double w = (at.body.mass - model.fluid().rho * at.body.volume) * model.fluid().gravity;
            points.push_back({at.s, w, at.body.mass * model.fluid().gravity});
            weight += w;
        }
        if (model.far_end().body && !model.far_end().proxy) weight += (p.bodyMass - p.waterDensity * p.bodyVolume) * p.gravity;
        segments_.push_back(segments);
        pointLoads_.push_back(points);
        hangingWeight_.push_back(weight);
        describe_line(static_cast<int>(k), p);
    }
    deck0_ = deck_;
    moreLines_.assign(static_cast<size_t>(std::max(0, deck_.deckLines - UC_MAX_LINES)), UCMooringLine{});
    describe_nodes();
    references_.assign(static_cast<size_t>(deck_.bodies), DrivenEnd());
    for (const MooringNode& n : deck_.nodes) {
        FreeNodeMotion m{};  // at rest
        put(m.position, vec3(n.position));
        put(m.inputPosition, vec3(n.position));
        put_rotation(m, n.body ? body_rotation(n.angles[0], n.angles[1], n.angles[2]) : Mat3::Identity());
        motion_.push_back(m);
        nodeOffset_.push_back(nodeUnknowns_);
        nodeUnknowns_ += node_unknowns(n);
    }
    nodeLineStart_.resize(lines_.size());
    derivativeStamp_.assign(static_cast<size_t>(deck_.bodies), -1);
    derivativeCache_.assign(static_cast<size_t>(deck_.bodies), {});
    return true;
}

// The numeric parameters of the schema (Strings, such as lineFile itself, name no value of the system).
#define UC_DESCRIBE_VARIABLE(vr, name, TYPE, CAUSALITY, member) UC_DESCRIBE_##CAUSALITY##_##TYPE(name, member)
#define UC_DESCRIBE_PARAMETER_REAL(name, member) add(name, p.member);
#define UC_DESCRIBE_PARAMETER_INTEGER(name, member) add(name, p.member);
#define UC_DESCRIBE_PARAMETER_BOOLEAN(name, member) add(name, p.member);
#define UC_DESCRIBE_PARAMETER_STRING(name, member)
#define UC_DESCRIBE_INPUT_REAL(name, member)
#define UC_DESCRIBE_INPUT_INTEGER(name, member)
#define UC_DESCRIBE_INPUT_BOOLEAN(name, member)
#define UC_DESCRIBE_INPUT_STRING(name, member)
#define UC_DESCRIBE_OUTPUT_REAL(name, member)
#define UC_DESCRIBE_OUTPUT_INTEGER(name, member)
#define UC_DESCRIBE_OUTPUT_BOOLEAN(name, member)
#define UC_DESCRIBE_OUTPUT_STRING(name, member)

void MooringSystem::describe_line(int k, const UCParams& p) {
    const MooringDeckLine& l = deck_.lines[k];
    const std::string prefix = "line " + std::to_string(l.id) + " (deck row " + std::to_string(l.row) + "): ";
    auto add = [&](const std::string& name, double value) { description_.push_back({prefix + name, value}); };
    UC_SCHEMA_VARIABLES(UC_DESCRIBE_VARIABLE)
    const MooringEnd* ends[2] = {&l.fairlead, &l.far};
    static const char* const kEnds[2] = {"fairlead", "far end"};
    for (int e = 0; e < 2; ++e) {
        const std::string end = kEnds[e];
        add(end + " kind", static_cast<double>(ends[e]->kind));
        add(end + " body", ends[e]->body);
        add(end + " point", ends[e]->point);
        add(end + " node", ends[e]->node);
        for (int i = 0; i < 3; ++i) add(end + " position[" + std::to_string(i) + "] [m]", ends[e]->position[i]);
    }
    add("far end free", l.farFree ? 1.0 : 0.0);
    add("far body mass [kg]", l.farBody.mass);
    add("far body volume [m3]", l.farBody.volume);
    add("far body added mass [kg]", l.farBody.addedMass);
    add("far body CdA [m2]", l.farBody.CdA);
}

void MooringSystem::describe_nodes() {
    auto add = [&](const std::string& name, double value) { description_.push_back({name, value}); };
    add("deck: lines", deck_.deckLines);
    add("deck: coupled bodies", deck_.bodies);
    add("deck: BODIES section", deck_.bodiesSection ? 1.0 : 0.0);
    add("deck: free nodes start at the deck's positions (TmaxIC 0)", deck_.nodesFromDeck ? 1.0 : 0.0);
    add("deck: WtrDpth [m]", deck_.waterDepth);
    add("deck: gravity [m/s2]", deck_.gravity);
    add("deck: water density [kg/m3]", deck_.waterDensity);
    for (const MooringNode& n : deck_.nodes) {
        const std::string prefix = (n.body ? "free body " : "free point ") + std::to_string(n.point.id) +
                                   " (deck row " + std::to_string(n.point.row) + "): ";
        auto three = [&](const std::string& name, const double* v, int count = 3) {
            for (int i = 0; i < count; ++i) add(prefix + name + "[" + std::to_string(i) + "]", v[i]);
        };
        add(prefix + "mass [kg]", n.point.mass);
        add(prefix + "volume [m3]", n.point.volume);
        add(prefix + "added mass [kg]", n.point.addedMass);
        add(prefix + "CdA [m2]", n.point.CdA);
        three("position [m]", n.position);
        add(prefix + "body", n.body ? 1.0 : 0.0);
        three("angles [rad]", n.angles);
        three("CG [m]", n.cg);
        three("inertia [kg m2]", n.inertia);
        three("CdA [m2]", n.CdA, 6);
        three("Ca [-]", n.Ca);
        if (!n.pinned) continue;  // (a pinned body's own values after the free bodies', whose description is kept)
        add(prefix + "pinned", 1.0);
        add(prefix + "pin kind", static_cast<double>(n.pin.kind));
        add(prefix + "pin body", n.pin.body);
        three("pin position [m]", n.pin.position);
        three("CB [m]", n.cb);
    }
    describe_failures();
}

MooringSystem::Motion MooringSystem::end_motion(const MooringEnd& end, const UCInputs& in) const {
    const Vec3 local = vec3(end.position);
    switch (end.kind) {
        case MooringEnd::Kind::Fixed:
            return {local, Vec3::Zero(), Vec3::Zero(), false};
        case MooringEnd::Kind::Node: {
            const FreeNodeMotion& m = motion_[end.node];
            if (deck_.nodes[end.node].body) {  // the point on the body at t + h, as inputs extrapolated there
                const Vec3 arm = rotation(m) * local, w = vec3(m.omega);
                const Vec3 P = vec3(m.position) + arm, V = vec3(m.velocity) + w.cross(arm),
                           A = vec3(m.acceleration) + vec3(m.alpha).cross(arm) + w.cross(w.cross(arm));
                const double h = m.step;
                const Vec3 v = V - h * A;
                return {P - h * v - 0.5 * h * h * A, v, A, true};
            }
            return {vec3(m.inputPosition), vec3(m.inputVelocity), vec3(m.inputAcceleration), true};
        }
        case MooringEnd::Kind::Point: {
            const int k = end.point - 1;
            const UCCoupledPoint& p = in.coupledPoint[k];
            return {vec3(p.position), vec3(p.velocity), vec3(in.pointAcceleration + 3 * k),
                    in.pointAccelerationGiven[k] != 0};
        }
        case MooringEnd::Kind::Body:
        default: {
            const int k = end.body - 1;
            const UCCoupledBody& b = in.coupledBody[k];
            const Vec3 arm = coupled_body_rotation(b, base_.bodyOrientation) * local;
            const Vec3 w = vec3(b.angularVelocity);
            const Vec3 a = vec3(in.bodyAcceleration + 6 * k), alpha = vec3(in.bodyAcceleration + 6 * k + 3);
            return {vec3(b.position) + arm, vec3(b.velocity) + w.cross(arm), a + alpha.cross(arm) + w.cross(w.cross(arm)),
                    in.bodyAccelerationGiven[k] != 0};
        }
    }
}

bool MooringSystem::driven_position(int kind, int index, Vec3& p) const {
    if (kind == UC_DRIVEN_BODY) {
        if (index < 1 || index > static_cast<int>(references_.size())) return false;
        p = references_[index - 1].position;
        return true;
    }
    if (kind != UC_DRIVEN_POINT) return false;
    for (size_t k = 0; k < lines_.size(); ++k) {
        const MooringDeckLine& l = deck_.lines[k];
        if (l.fairlead.kind == MooringEnd::Kind::Point && l.fairlead.point == index) {
            p = lines_[k]->tow_position();
            return true;
        }
        if (l.far.kind == MooringEnd::Kind::Point && l.far.point == index &&
            lines_[k]->driven_position(UC_DRIVEN_END, 0, p))
            return true;
    }
    return false;
}

MooringSystem::LineEnds MooringSystem::line_ends(int k, const UCInputs& in) const {
    const MooringDeckLine& l = deck_.lines[k];
    // each end's acceleration from its body's or point's input derivatives where the master gives them,
    // else estimated from its velocity inputs (DrivenEnd)
    auto drive = [](const Motion& m) {
        return EndMotion{m.position, m.velocity, m.accelerationGiven ? m.acceleration : Vec3::Zero(),
                         m.accelerationGiven ? 1 : 0};
    };
    LineEnds ends{drive(end_motion(l.fairlead, in)), drive(end_motion(l.far, in))};
    // a line run from its anchor after its fairlead let go: its tow point held where the anchor held it
    if (lines_[k]->released() == 2 && l.fairlead.kind == MooringEnd::Kind::Fixed) ends.tow.position = lines_[k]->tow_position();
    return ends;
}

bool MooringSystem::check_inputs(const UCInputs& in, std::string& error) {
    for (int b = 0; b < deck_.bodies; ++b) {
        const UCCoupledBody& body = in.coupledBody[b];
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(body.position[c]) || !std::isfinite(body.rotation[c]) ||
                !std::isfinite(body.velocity[c]) || !std::isfinite(body.angularVelocity[c])) {
                error = "body[" + std::to_string(b + 1) + "].* inputs must be finite numbers";
                return false;
            }
        }
        if (base_.bodyOrientation != UC_ORIENTATION_QUATERNION) continue;
        // The quaternion is normalized; one whose norm is off 1 by more than kQuaternionNormTolerance is
        // no unit quaternion carried with round-off or drift (vector-first order, angles, a zero left in).
        const double* q = body.quaternion;
        const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        const std::string name = "body[" + std::to_string(b + 1) + "].q0/q1/q2/q3";
        if (!std::isfinite(norm) || std::abs(norm - 1.0) > kQuaternionNormTolerance) {
            char text[256];
            std::snprintf(text, sizeof text, "%s = (%.9g, %.9g, %.9g, %.9g) has norm %.9g: not a unit quaternion "
                          "(bodyOrientation = 1 reads the body's orientation as (cos(phi/2), n sin(phi/2)), scalar "
                          "first; the norm may differ from 1 by %g)", name.c_str(), q[0], q[1], q[2], q[3], norm,
                          kQuaternionNormTolerance);
            error = text;
            return false;
        }
        if (std::abs(norm - 1.0) > kQuaternionReportedNorm && !quaternionNormalized_) {
            quaternionNormalized_ = true;
            char text[200];
            std::snprintf(text, sizeof text, "%s has norm %.12g at t = %g s: normalized (reported once)",
                          name.c_str(), norm, time());
            append_event(event_, text);
        }
    }
    for (const MooringDeckLine& l : deck_.lines) {
        for (const MooringEnd* e : {&l.fairlead, &l.far}) {
            if (e->kind != MooringEnd::Kind::Point) continue;
            const UCCoupledPoint& p = in.coupledPoint[e->point - 1];
            for (int c = 0; c < 3; ++c) {
                if (!std::isfinite(p.position[c]) || !std::isfinite(p.velocity[c])) {
                    error = "point[" + std::to_string(e->point) + "].* inputs must be finite numbers";
                    return false;
                }
            }
        }
    }
    return true;
}

bool MooringSystem::initialize(double t0, const UCInputs& in, std::string& error) {
    ++stamp_;
    if (!check_inputs(in, error)) return false;
    undo_breaks();  // initialized again after a break: the deck's lines and nodes as read
    const LineEnvironment env = line_environment(in);
    for (size_t k = 0; k < lines_.size(); ++k) {
        if (on_free_node(deck_.lines[k])) continue;  // initialized at the nodes' equilibrium
        const LineEnds ends = line_ends(static_cast<int>(k), in);
        if (!lines_[k]->initialize(t0, ends.tow, ends.far, env, error)) {
            error = "mooring line " + std::to_string(deck_.lines[k].id) + ": " + error;
            return false;
        }
    }
    t0_ = t0;
    lastStep_ = 0.0;  // (a pin's acceleration, where not given, is estimated from the steps' inputs: none yet)
    waterTime_ = t0;
    if (!motion_.empty() && !solve_nodes(t0, in, error)) return false;
    for (int b = 0; b < deck_.bodies; ++b) {
        const UCCoupledBody& body = in.coupledBody[b];
        const bool given = in.bodyAccelerationGiven[b] != 0;
        references_[b].reset(vec3(body.position), vec3(body.velocity),
                             given ? vec3(in.bodyAcceleration + 6 * b) : Vec3::Zero(), given);
    }
    lastStep_ = 0.0;
    lastInputs_ = in;
    stiffnessWarned_ = false;
    update_outputs();
    return true;
}

bool MooringSystem::advance(double t, double h, double offset, const UCInputs& in, std::string& error) {
    const LineEnvironment env = line_environment(in);
    for (size_t k = 0; k < lines_.size(); ++k) {
        if (on_free_node(deck_.lines[k])) continue;  // stepped with the nodes
        LineEnds ends = line_ends(static_cast<int>(k), in);
        if (offset >= 0.0) shift_coupled_ends(static_cast<int>(k), offset, ends);
        if (!lines_[k]->step(h, ends.tow, ends.far, env, error)) {
            error = "mooring line " + std::to_string(deck_.lines[k].id) + ": " + error;
            return false;
        }
    }
    return motion_.empty() || step_nodes(t, h, in, error, offset);
}

bool MooringSystem::step(double t, double h, const UCInputs& in, std::string& error) {
    ++stamp_;
    if (!check_inputs(in, error)) return false;
    failureEvaluations_ = 0;
    double taken = h;  // (short of h where the step stops at a break)
    if (failures_pending() ? !step_with_failures(t, h, in, taken, error) : !advance(t, h, -1.0, in, error)) return false;
    for (int b = 0; b < deck_.bodies; ++b) {
        const UCCoupledBody& body = in.coupledBody[b];
        const bool given = in.bodyAccelerationGiven[b] != 0;
        Vec3 a;
        const TowTrajectory traj = references_[b].next(t, taken, lastStep_, vec3(body.position), vec3(body.velocity),
                                                       vec3(in.bodyAcceleration + 6 * b), given, a);
        references_[b].advance(traj, vec3(body.velocity), a, given);
    }
    lastStep_ = taken;
    lastInputs_ = in;
    update_outputs();
    return true;
}

std::string MooringSystem::take_event() {
    std::string events;
    events.swap(event_);
    for (size_t k = 0; k < lines_.size(); ++k) {
        // each of the line's events named after it, after the "warning: " that marks a warning
        std::istringstream lines(lines_[k]->take_event());
        for (std::string e; std::getline(lines, e);) {
            const bool warning = e.rfind("warning: ", 0) == 0;
            append_event(events, std::string(warning ? "warning: " : "") + "mooring line " +
                                     std::to_string(deck_.lines[k].id) + ": " + e.substr(warning ? 9 : 0));
        }
    }
    return events;
}

void MooringSystem::update_outputs() {
    outputs_ = lines_[0]->outputs();  // the single-line outputs are line 1's
    std::memset(outputs_.mooringLine, 0, sizeof outputs_.mooringLine);
    std::memset(outputs_.bodyLoad, 0, sizeof outputs_.bodyLoad);
    std::memset(outputs_.pointLoad, 0, sizeof outputs_.pointLoad);
    std::fill(moreLines_.begin(), moreLines_.end(), UCMooringLine{});
    for (size_t k = 0; k < lines_.size(); ++k) {
        const UCOutputs& o = lines_[k]->outputs();
        const MooringDeckLine& l = deck_.lines[k];
        const CableModel& model = lines_[k]->model();
        const int sections = static_cast<int>(l.deckLines.size());
        for (int j = 0; j < sections; ++j) {
            // the elements of section j, whose end forces are the deck line's end tensions at the joints
            int first = model.n_elements(), last = -1;
            for (const ElementRun& run : model.runs()) {
                if (run.section != j) continue;
                first = std::min(first, run.first);
                last = std::max(last, run.first + run.count - 1);
            }
            const double start = j == 0 ? o.towTension : lines_[k]->element_end_tension(first, false);
            // (a bare end after a break: the tension at it, the seabed's contact at its tip left out)
            const double far = lines_[k]->released() != 0 ? lines_[k]->bare_end_force().norm() : o.endTension;
            const double end = j + 1 == sections ? far : lines_[k]->element_end_tension(last, true);
            set_mooring_line_outputs(line_output(l.deckLines[j]), l.flipped[j] ? end : start,
                                     l.flipped[j] ? start : end, o, line_strength(*lines_[k], j, j));
        }
        // the fairlead where the line's tow point stands, the far end where its end does
        const std::pair<const MooringEnd*, std::pair<Vec3, Vec3>> ends[2] = {
            {&l.fairlead, {vec3(o.towForce), lines_[k]->tow_position()}},
            {&l.far, {vec3(o.endForce), vec3(o.endPosition)}}};
        for (const auto& [end, load] : ends) {
            const auto& [force, at] = load;
            if (end->kind == MooringEnd::Kind::Point) {
                for (int c = 0; c < 3; ++c) outputs_.pointLoad[end->point - 1].force[c] += force[c];
            } else if (end->kind == MooringEnd::Kind::Body) {
                UCBodyLoad& b = outputs_.bodyLoad[end->body - 1];
                const Vec3 moment = (at - references_[end->body - 1].position).cross(force);
                for (int c = 0; c < 3; ++c) {
                    b.force[c] += force[c];
                    b.moment[c] += moment[c];
                }
            }
        }
    }
    split_outputs();
    failure_outputs();
    for (size_t n = 0; n < motion_.size(); ++n) {
        const MooringNode& node = deck_.nodes[n];
        if (!node.pinned || node.pin.kind != MooringEnd::Kind::Body) continue;
        // the pinned body's load on the coupled body that holds it, at the pin (no moment about the pin)
        const Vec3 force = pin_force(static_cast<int>(n), lastInputs_);
        const bool atReference = vec3(node.pin.position).squaredNorm() == 0.0;  // a CoupledPinned body's own pin
        const Vec3 moment = atReference ? Vec3::Zero()
                                        : Vec3((node_position(static_cast<int>(n)) - references_[node.pin.body - 1].position).cross(force));
        UCBodyLoad& b = outputs_.bodyLoad[node.pin.body - 1];
        for (int c = 0; c < 3; ++c) {
            b.force[c] += force[c];
            b.moment[c] += moment[c];
        }
    }
    for (size_t n = 0; n < motion_.size(); ++n) {
        const int id = deck_.nodes[n].point.id;
        if (deck_.nodes[n].failure > 0) continue;  // a failure's free end: no output of its own
        if (deck_.nodes[n].body) {
            if (id > UC_MAX_BODIES) continue;  // beyond the outputs body[k].pose.*
            const Mat3 R = rotation(motion_[n]);  // R = Rx Ry Rz: R(0,2) = sin(pitch)
            const double angles[3] = {std::atan2(-R(1, 2), R(2, 2)), std::asin(std::clamp(R(0, 2), -1.0, 1.0)),
                                      std::atan2(-R(0, 1), R(0, 0))};
            for (int c = 0; c < 3; ++c) {
                outputs_.bodyLoad[id - 1].posePosition[c] = motion_[n].position[c];
                outputs_.bodyLoad[id - 1].poseAngles[c] = angles[c];
            }
            continue;
        }
        if (id > UC_MAX_POINTS) continue;  // beyond the outputs point[k].position.*
        for (int c = 0; c < 3; ++c) outputs_.pointLoad[id - 1].position[c] = motion_[n].position[c];
    }
    // the free points one or two lines meet at: a joint between two deck lines (a clump, a buoy), a free far end
    for (size_t k = 0; k < lines_.size(); ++k) {
        const MooringDeckLine& l = deck_.lines[k];
        auto put_point = [&](int id, const Vec3& at) {
            if (id >= 1 && id <= UC_MAX_POINTS) put(outputs_.pointLoad[id - 1].position, at);
        };
        for (size_t j = 0; j < l.joints.size(); ++j) put_point(l.joints[j].id, lines_[k]->section_end_position(static_cast<int>(j)));
        if (l.farFree) put_point(l.farBody.id, vec3(lines_[k]->outputs().endPosition));
    }
    stiffnessCurrent_ = false;  // body[k].stiffness: computed when read (update_stiffness)
}

namespace {

// The tensions at the two ends of a line whose ends lie on one vertical, D apart (the catenary has no
// answer there: LineProfile refuses "both ends on one vertical"), its segments from the upper end, under
// water, without point loads: the elastic hanging line, T(s) = T0 + the weight below s. Where it would be
// slack at its lower end, which rests on the seabed (`grounded`), the line hangs taut to the seabed and
// the rest lies there without tension (T0 = 0); false where that does not apply (a buoyant segment, a
// slack line in mid-water). upper and lower: the tensions at the two ends [N].
bool vertical_line_tensions(const std::vector<LineProfile::Segment>& segments, double D, bool grounded,
                            double& upper, double& lower) {
    for (const LineProfile::Segment& s : segments)
        if (!(s.weight >= 0.0) || !(s.EA > 0.0) || !(s.length > 0.0)) return false;
    // the stretched length of the part hanging over the lowest `hanging` metres, at lower-end tension T0
    auto stretched = [&](double hanging, double T0) {
        double below = 0.0, weight = 0.0, length = 0.0;
        for (auto s = segments.rbegin(); s != segments.rend() && below < hanging; ++s) {
            const double l = std::min(s->length, hanging - below);
            length += l + (T0 * l + weight * l + 0.5 * s->weight * l * l) / s->EA;
            weight += s->weight * l;
            below += l;
        }
        return length;
    };
    double L = 0.0, W = 0.0, compliance = 0.0;
    for (const LineProfile::Segment& s : segments) {
        L += s.length;
        W += s.weight * s.length;
        compliance += s.length / s.EA;
    }
    const double T0 = (D - stretched(L, 0.0)) / compliance;  // linear in T0
    if (T0 >= 0.0) {
        lower = T0;
        upper = T0 + W;
        return true;
    }
    if (!grounded || !(D > 0.0)) return false;
    // slack: the hanging part's length h with stretched(h, 0) = D, by bisection (monotone in h)
    double a = 0.0, b = L;
    for (int i = 0; i < 200 && b - a > 1e-12 * L; ++i) {
        const double h = 0.5 * (a + b);
        (stretched(h, 0.0) < D ? a : b) = h;
    }
    const double h = 0.5 * (a + b);
    double below = 0.0, weight = 0.0;
    for (auto s = segments.rbegin(); s != segments.rend() && below < h; ++s) {
        const double l = std::min(s->length, h - below);
        weight += s->weight * l;
        below += l;
    }
    lower = 0.0;
    upper = weight;
    return true;
}

}  // namespace

bool MooringSystem::profile_end_forces(int k, const Vec3& top, const Vec3& far, Vec3& onTop, Vec3& onFar,
                                       std::string* why) const {
    const MooringDeckLine& l = deck_.lines[k];
    const UCParams& p = lines_[k]->model().params();
    if (!held_far_end(l)) {  // hanging from its fairlead: its weight, wherever the fairlead stands
        onTop = Vec3(0.0, 0.0, -hangingWeight_[k]);
        onFar.setZero();
        return true;
    }
    const bool topHigher = top.z() >= far.z();
    const double L = lines_[k]->model().line().length;
    std::vector<LineProfile::Segment> segments = segments_[k];
    std::vector<LineProfile::PointLoad> points = pointLoads_[k];
    if (!topHigher) {  // the profile runs from the higher end
        std::reverse(segments.begin(), segments.end());
        for (LineProfile::PointLoad& q : points) q.s = L - q.s;
    }
    const Vec3& lower = topHigher ? far : top;
    const Vec3& upper = topHigher ? top : far;
    // both ends on one vertical, or within the central differences' reach of it (a slack line on the
    // frictionless seabed has no catenary there): the hanging line's tensions, along its chord
    auto vertical = [&] {
        const Vec3 chord = upper - lower;
        if (!(std::hypot(chord.x(), chord.y()) <= 1e-2 * chord.z()) || !points.empty() || upper.z() > 0.0) return false;
        const double rest = lines_[k]->model().seabed_height(lower.x(), lower.y());
        const bool grounded = p.enableSeabed != 0 && lower.z() <= rest + std::max(lines_[k]->model().line().diameter, 1e-3 * L);
        double Tu = 0.0, Tl = 0.0;
        if (!vertical_line_tensions(segments, chord.norm(), grounded, Tu, Tl)) return false;
        const Vec3 t = chord.normalized();
        onTop = topHigher ? Vec3(-Tu * t) : Vec3(Tl * t);
        onFar = topHigher ? Vec3(Tl * t) : Vec3(-Tu * t);
        return true;
    };
    if (std::hypot(upper.x() - lower.x(), upper.y() - lower.y()) <= 1e-9 * L && vertical()) return true;
    LineProfile profile;
    profile.set_seabed_gradient(lines_[k]->model().seabed_gradient(lower.x(), lower.y()));
    if (!profile.solve(upper, lower, segments, points, p.enableSeabed != 0,
                       lines_[k]->model().seabed_height(lower.x(), lower.y()),
                       std::max(lines_[k]->model().line().diameter, 1e-3 * L), why, 0.0))
        return vertical();
    onTop = topHigher ? profile.top_force() : profile.bottom_force();
    onFar = topHigher ? profile.bottom_force() : profile.top_force();
    return true;
}

Vec3 MooringSystem::water_velocity(const Vec3& x, const UCInputs& in) const {
    CurrentField current;
    current.uniform = Vec3(in.current[0], in.current[1], 0.0);
    current.profile = &lines_[0]->model().current_profile();
    current.scale = in.currentScale;
    current.grid = currentGrid_.get();
    current.time = waterTime_;
    return current.velocity(x);
}

Vec3 MooringSystem::node_load(int n, const Vec3& x, const UCInputs& in, const Vec3& v) const {
    const LineFilePoint& p = deck_.nodes[n].point;
    const FluidProps& fluid = lines_[0]->model().fluid();
    const Vec3 w = water_velocity(x, in) - v;  // the water's velocity relative to the node
    return Vec3(0.0, 0.0, -(p.mass - fluid.rho * p.volume) * fluid.gravity) + 0.5 * fluid.rho * p.CdA * w.norm() * w;
}

namespace {

// A free rod's part below z = 0 (docs/lines.md, "Rods"): the fraction of its length, its centre, and how many
// of its two ends are under water. The rod lies along its body's x axis from -L/2 to L/2 about x.
void rod_under_water(const MooringNode& node, const Vec3& x, const Mat3& R, double& fraction, Vec3& centre,
                     int& wetEnds) {
    const Vec3 half = 0.5 * node.rodLength * R.col(0);
    const RodWetPart wet = rod_wet_part(x - half, x + half);
    fraction = wet.fraction, centre = wet.centre, wetEnds = wet.wet_ends();
}

}  // namespace

void MooringSystem::body_load(int n, const Vec3& x, const Mat3& R, const Vec3& v, const Vec3& omega,
                              const UCInputs& in, Vec3& force, Vec3& moment) const {
    const MooringNode& node = deck_.nodes[n];
    const FluidProps& fluid = lines_[0]->model().fluid();
    if (node.rodLength > 0.0) {  // a free rod: buoyancy, drag and added mass of its part under water
        double wet = 1.0;
        int wetEnds = 2;
        Vec3 centre = x;
        rod_under_water(node, x, R, wet, centre, wetEnds);
        const Vec3 weight(0.0, 0.0, -node.point.mass * fluid.gravity);
        const Vec3 buoyancy(0.0, 0.0, fluid.rho * node.point.volume * wet * fluid.gravity);
        const Vec3 u = R.transpose() * (water_velocity(x, in) - v), spin = R.transpose() * omega;
        const Vec3 dragArea(node.CdA[0] * 0.5 * wetEnds, node.CdA[1] * wet, node.CdA[2] * wet);
        const Vec3 turnArea(node.CdA[3] * wet, node.CdA[4] * wet, node.CdA[5] * wet);
        force = weight + buoyancy + 0.5 * fluid.rho * u.norm() * (R * dragArea.cwiseProduct(u));
        moment = (R * Vec3(node.cg[0], node.cg[1], node.cg[2])).cross(weight) + (centre - x).cross(buoyancy) -
                 0.5 * fluid.rho * spin.norm() * (R * turnArea.cwiseProduct(spin));
        return;
    }
    if (node.pinned) {  // its weight at its centre of gravity, its buoyancy at its centre of buoyancy
        const Vec3 weight(0.0, 0.0, -node.point.mass * fluid.gravity);
        const Vec3 buoyancy(0.0, 0.0, fluid.rho * node.point.volume * fluid.gravity);
        const Vec3 u = R.transpose() * (water_velocity(x, in) - v), spin = R.transpose() * omega;
        const Vec3 dragArea(node.CdA[0], node.CdA[1], node.CdA[2]), turnArea(node.CdA[3], node.CdA[4], node.CdA[5]);
        force = weight + buoyancy + 0.5 * fluid.rho * u.norm() * (R * dragArea.cwiseProduct(u));
        moment = (R * vec3(node.cg)).cross(weight) + (R * vec3(node.cb)).cross(buoyancy) -
                 0.5 * fluid.rho * spin.norm() * (R * turnArea.cwiseProduct(spin));
        add_body_rod_loads(n, x, R, v, omega, in, force, moment);
        return;
    }
    // weight and buoyancy together at the centre of gravity, as MoorDyn v2 applies them (with rods on it, whose
    // mass moved its centre of gravity, its own buoyancy at its own centre, cb)
    const Vec3 net(0.0, 0.0, (fluid.rho * node.point.volume - node.point.mass) * fluid.gravity);
    // drag in the body's axes: of translation at the reference point in the water's velocity relative to it,
    // of rotation against the angular velocity (MoorDyn's CdA* of rotation, its moment 1/2 rho CdA w |w|)
    const Vec3 u = R.transpose() * (water_velocity(x, in) - v), spin = R.transpose() * omega;
    const Vec3 dragArea(node.CdA[0], node.CdA[1], node.CdA[2]), turnArea(node.CdA[3], node.CdA[4], node.CdA[5]);
    force = net + 0.5 * fluid.rho * u.norm() * (R * dragArea.cwiseProduct(u));
    moment = (R * Vec3(node.cg[0], node.cg[1], node.cg[2])).cross(net) -
             0.5 * fluid.rho * spin.norm() * (R * turnArea.cwiseProduct(spin));
    if (!node.rods.empty()) {
        moment += (R * (vec3(node.cb) - vec3(node.cg))).cross(Vec3(0.0, 0.0, fluid.rho * node.point.volume * fluid.gravity));
        add_body_rod_loads(n, x, R, v, omega, in, force, moment);
    }
}

Mat3 MooringSystem::body_added_mass(int n, const Vec3& x, const Mat3& R) const {
    const MooringNode& node = deck_.nodes[n];
    const double rhoV = lines_[0]->model().fluid().rho * node.point.volume;
    if (node.rodLength > 0.0) {  // a free rod: the added mass of its part under water, its axial at its wet ends
        double wet = 1.0;
        int wetEnds = 2;
        Vec3 centre = x;
        rod_under_water(node, x, R, wet, centre, wetEnds);
        const Vec3 ca(node.Ca[0] * 0.5 * wetEnds, node.Ca[1] * wet, node.Ca[2] * wet);
        return R * (rhoV * ca).asDiagonal() * R.transpose();
    }
    return R * (rhoV * Vec3(node.Ca[0], node.Ca[1], node.Ca[2])).asDiagonal() * R.transpose();
}

void MooringSystem::pin_motion(int n, const UCInputs& in, double tau, Vec3& x, Vec3& v, Vec3& a) const {
    const MooringEnd& pin = deck_.nodes[n].pin;
    if (pin.kind == MooringEnd::Kind::Node) {  // on a free body: its point in the body's present motion
        body_point_motion(pin, x, v, a);
        return;
    }
    const Motion m = end_motion(pin, in);
    a = m.acceleration;
    if (!m.accelerationGiven)  // as a driven end estimates it: the difference of the last two velocity inputs
        a = lastStep_ > 0.0 ? Vec3((m.velocity - end_motion(pin, lastInputs_).velocity) / lastStep_) : Vec3::Zero();
    x = m.position + tau * (m.velocity + 0.5 * tau * a);
    v = m.velocity + tau * a;
}

Vec3 MooringSystem::pin_force(int n, const UCInputs& in) const {
    const MooringNode& node = deck_.nodes[n];
    const FreeNodeMotion& m = motion_[n];
    const Mat3 R = rotation(m);
    const Vec3 x = vec3(m.position), a = vec3(m.acceleration), w = vec3(m.omega), c = R * vec3(node.cg);
    Vec3 force, moment;
    body_load(n, x, R, vec3(m.velocity), w, in, force, moment);
    for (size_t k = 0; k < lines_.size(); ++k) {
        const MooringDeckLine& l = deck_.lines[k];
        const MooringEnd* ends[2] = {&l.fairlead, held_far_end(l)};
        const UCOutputs& o = lines_[k]->outputs();
        for (int e = 0; e < 2; ++e) {
            if (ends[e] && ends[e]->kind == MooringEnd::Kind::Node && ends[e]->node == n)
                force += vec3(e == 0 ? o.towForce : o.endForce);
        }
    }
    const Vec3 acg = a + vec3(m.alpha).cross(c) + w.cross(w.cross(c));
    add_body_rod_inertia(n, x, R, a, vec3(m.alpha), force, moment);
    // its added mass at its centre of buoyancy, moved by the pin and by its turning
    return force - node.point.mass * acg - body_added_mass(n, x, R) * (a + vec3(m.alpha).cross(R * vec3(node.cb)));
}

bool MooringSystem::node_residual(const Eigen::VectorXd& x, const UCInputs& in, bool profile, Eigen::VectorXd& r,
                                  std::string& error) {
    r.setZero(x.size());
    for (size_t n = 0; n < motion_.size(); ++n) {
        const MooringNode& node = deck_.nodes[n];
        const int o = nodeOffset_[n];
        FreeNodeMotion& m = motion_[n];
        if (node.pinned) {  // x holds its rotation about the earth axes from the deck's orientation, at its pin
            Vec3 pin, v, a;
            pin_motion(static_cast<int>(n), in, 0.0, pin, v, a);
            put(m.position, pin);
            put(m.velocity, v);
            put(m.acceleration, a);
            const Mat3 R = turn_matrix(x.segment<3>(o)) * body_rotation(node.angles[0], node.angles[1], node.angles[2]);
            put_rotation(m, R);
            Vec3 force, moment;
            body_load(static_cast<int>(n), pin, R, Vec3::Zero(), Vec3::Zero(), in, force, moment);
            r.segment<3>(o) = moment;
            continue;
        }
        const Vec3 at = x.segment<3>(o);
        put(m.position, at);
        put(m.inputPosition, at);
        put(m.inputVelocity, Vec3::Zero());
        put(m.inputAcceleration, Vec3::Zero());
        if (!node.body) {
            r.segment<3>(o) = node_load(static_cast<int>(n), at, in);
            continue;
        }
        // a body: x holds a rotation about the earth axes from the deck's orientation; its weight and
        // buoyancy at its centre of gravity, its drag in the current at its reference point (body_load)
        const Mat3 R = turn_matrix(x.segment<3>(o + 3)) * body_rotation(node.angles[0], node.angles[1], node.angles[2]);
        put_rotation(m, R);
        Vec3 force, moment;
        body_load(static_cast<int>(n), at, R, Vec3::Zero(), Vec3::Zero(), in, force, moment);
        r.segment<3>(o) = force;
        r.segment<3>(o + 3) = moment;
    }
    const LineEnvironment env = line_environment(in);
    std::vector<Vec3> onPinned(motion_.size(), Vec3::Zero());  // the lines' forces on each pinned body
    for (size_t k = 0; k < lines_.size(); ++k) {
        const MooringDeckLine& l = deck_.lines[k];
        if (!on_free_node(l)) continue;
        Vec3 onEnd[2];
        if (profile) {
            const Vec3 top = end_motion(l.fairlead, in).position;
            const Vec3 far = held_far_end(l) ? end_motion(*held_far_end(l), in).position : top;
            if (!profile_end_forces(static_cast<int>(k), top, far, onEnd[0], onEnd[1], &error)) {
                error = "mooring line " + std::to_string(l.id) + ": " + error;
                return false;
            }
        } else {
            const LineEnds ends = line_ends(static_cast<int>(k), in);
            if (!lines_[k]->initialize(t0_, ends.tow, ends.far, env, error)) {
                error = "mooring line " + std::to_string(l.id) + ": " + error;
                return false;
            }
            onEnd[0] = vec3(lines_[k]->outputs().towForce);
            onEnd[1] = vec3(lines_[k]->outputs().endForce);
        }
        const MooringEnd* ends[2] = {&l.fairlead, held_far_end(l)};
        for (int e = 0; e < 2; ++e) {
            if (!ends[e] || ends[e]->kind != MooringEnd::Kind::Node) continue;
            const int n = ends[e]->node, o = nodeOffset_[n];
            const Vec3 arm = end_motion(*ends[e], in).position - node_position(n);
            if (deck_.nodes[n].pinned) {  // its moment about its pin only
                r.segment<3>(o) += arm.cross(onEnd[e]);
                onPinned[n] += onEnd[e];
                continue;
            }
            r.segment<3>(o) += onEnd[e];
            if (deck_.nodes[n].body) r.segment<3>(o + 3) += arm.cross(onEnd[e]);
        }
    }
    for (size_t n = 0; n < motion_.size(); ++n) {  // a pinned body on a free body: its load at rest on its pin
        if (!deck_.nodes[n].pinned || deck_.nodes[n].pin.kind != MooringEnd::Kind::Node) continue;
        Vec3 force, moment;
        body_load(static_cast<int>(n), node_position(static_cast<int>(n)), rotation(motion_[n]), Vec3::Zero(),
                  Vec3::Zero(), in, force, moment);
        add_pin_reaction(static_cast<int>(n), force + onPinned[n], r);
    }
    return true;
}

bool MooringSystem::solve_nodes(double t0, const UCInputs& in, std::string& error) {
    t0_ = t0;
    for (FreeNodeMotion& m : motion_) {  // at rest
        m.step = 0.0;
        put(m.velocity, Vec3::Zero());
        put(m.acceleration, Vec3::Zero());
        put(m.omega, Vec3::Zero());
        put(m.alpha, Vec3::Zero());
    }
    const int m = nodeUnknowns_;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(m), r(m), rt(m), xt(m);
    bool pinned = false;  // a pinned body's rotation: its unknowns start at the deck's orientation
    for (size_t n = 0; n < motion_.size(); ++n) {
        pinned = pinned || deck_.nodes[n].pinned;
        x.segment<3>(nodeOffset_[n]) = deck_.nodes[n].pinned ? Vec3::Zero() : vec3(deck_.nodes[n].position);
    }
    // the force scale: the weights of the lines and nodes that meet at the nodes
    double scale = 0.0, shortest = 1e300;
    for (size_t k = 0; k < lines_.size(); ++k) {
        if (!on_free_node(deck_.lines[k])) continue;
        scale += std::abs(hangingWeight_[k]);
        shortest = std::min(shortest, lines_[k]->model().line().length);
    }
    for (size_t n = 0; n < motion_.size(); ++n)
        scale += node_load(static_cast<int>(n), deck_.nodes[n].pinned ? vec3(deck_.nodes[n].position)
                                                                       : Vec3(x.segment<3>(nodeOffset_[n])), in).norm() +
                 deck_.nodes[n].point.mass * lines_[0]->model().fluid().gravity;
    const double maxStep = 0.25 * shortest;  // a Newton step moves a node by at most this [m]
    Eigen::MatrixXd J(m, m);
    bool haveJacobian = false, fresh = false;  // fresh: J is that of the present x
    // Levenberg-Marquardt's damping of the lines' phase, relative to each unknown's own stiffness (where no
    // Newton step lowers |r|: a leg at the kink between slack and taut), and the Jacobian taken again where
    // the chord method's old one no longer lowers |r| by half a step
    double damping = 0.0;
    constexpr int kStaticIterations = 200;
    nodeIterations_ = 0;
    // Newton's method with a backtracking line search on |r|; the Jacobian by central differences of
    // the residual (kept through the iterations with the lines' own static solutions, where each
    // evaluation is a static solve of the lines: a chord method that converges linearly and fast, the
    // profiles' Jacobian being that of the lines' solutions within their discretization).
    // a deck's line refused on its NumSegs' elements at the nodes' positions starts on a finer mesh, with a warning
    // (docs/lines.md), at those positions (the nodes' first and last residuals), not at a Newton step's trial
    auto refine_lines = [&](bool on) {
        for (auto& line : lines_) line->refine_deck_mesh(on);
    };
    auto newton = [&](bool profile, double tolerance, std::string& why) -> bool {
        refine_lines(true);
        if (!node_residual(x, in, profile, r, why)) return false;
        for (int it = 0; it < kStaticIterations; ++it, ++nodeIterations_) {
            if (r.lpNorm<Eigen::Infinity>() <= tolerance) return true;
            refine_lines(false);  // a trial position's refusal rejects the trial (not the deck's mesh)
            if (profile || !haveJacobian) {
                // [m]: the profiles are smooth (truncation ~d^2); the lines' solutions get 10 um, within the
                // slack law's ramp of a stiff tether (1e-5 strain), which 1 mm steps straddle
                const double d = profile ? 1e-3 : 1e-5;
                Eigen::VectorXd rp(m), rm(m);
                for (int j = 0; j < m; ++j) {
                    xt = x;
                    xt[j] += d;
                    if (!node_residual(xt, in, profile, rp, why)) return false;
                    xt[j] = x[j] - d;
                    if (!node_residual(xt, in, profile, rm, why)) return false;
                    J.col(j) = (rp - rm) / (2.0 * d);
                }
                haveJacobian = true;
                fresh = true;
            }
            Eigen::MatrixXd Jd = J;
            for (int j = 0; j < m; ++j) Jd(j, j) -= damping * std::abs(J(j, j));
            // (a pinned body hanging still has no stiffness about its vertical axis: the least-norm step there)
            Eigen::VectorXd dx = pinned ? Eigen::VectorXd(-Jd.completeOrthogonalDecomposition().solve(r))
                                        : Eigen::VectorXd(-Jd.fullPivLu().solve(r));
            if (!dx.allFinite()) {
                why = "the free points' stiffness is singular";
                return false;
            }
            // a node moves by at most maxStep, a body turns by at most kMaxTurn, per step
            double shrink = 1.0;
            for (size_t n = 0; n < motion_.size(); ++n) {
                const int o = nodeOffset_[n];
                if (deck_.nodes[n].pinned) {
                    shrink = std::min(shrink, kMaxTurn / std::max(dx.segment<3>(o).lpNorm<Eigen::Infinity>(), 1e-300));
                    continue;
                }
                shrink = std::min(shrink, maxStep / std::max(dx.segment<3>(o).lpNorm<Eigen::Infinity>(), 1e-300));
                if (deck_.nodes[n].body)
                    shrink = std::min(shrink, kMaxTurn / std::max(dx.segment<3>(o + 3).lpNorm<Eigen::Infinity>(), 1e-300));
            }
            dx *= shrink;
            double a = 1.0;
            bool accepted = false;
            for (int halving = 0; halving < 30 && !accepted; ++halving, a *= 0.5) {
                xt = x + a * dx;
                std::string trial;
                accepted = node_residual(xt, in, profile, rt, trial) && rt.norm() < (1.0 - 1e-4 * a) * r.norm();
            }
            refine_lines(true);
            if (!accepted && !profile && !fresh) {
                haveJacobian = false;
                continue;
            }
            if (!accepted && !profile && damping < 1e6) {
                damping = std::max(4.0 * damping, 1e-3);
                continue;
            }
            if (!accepted && !profile && damping == 0.0 && dx.lpNorm<Eigen::Infinity>() < 10.0 * kNodeTolerance &&
                r.lpNorm<Eigen::Infinity>() < 1e-4 * scale)
                return true;  // at the level of the lines' static solutions' own tolerance
            if (!accepted) {
                why = "the line search found no smaller residual (" + std::to_string(r.norm()) + " N)";
                return false;
            }
            const double reduction = rt.norm() / r.norm();
            x = xt;
            r = rt;
            fresh = profile;
            if (!profile && damping == 0.0 && (a * dx).lpNorm<Eigen::Infinity>() < kNodeTolerance) return true;
            damping = damping < 1e-3 ? 0.0 : 0.25 * damping;
            if (!profile && reduction > 0.5) haveJacobian = false;
        }
        why = "no convergence in " + std::to_string(kStaticIterations) + " iterations (residual " +
              std::to_string(r.lpNorm<Eigen::Infinity>()) + " N)";
        return false;
    };
    std::string why;
    // the exact catenaries first (where every line at a node has one), then the lines' own solutions
    // (x moves only by accepted steps: where the profiles stop short, the lines' solutions go on from there);
    // none where the deck starts the nodes where it places them
    if (!deck_.nodesFromDeck) newton(true, 1e-12 * scale, why);
    if (!deck_.nodesFromDeck && !newton(false, 1e-9 * scale, why)) {
        error = "the static equilibrium of the free points: " + why;
        return false;
    }
    // the lines stand initialized where the last residual put them: at x, unless a trial came after it
    refine_lines(true);
    if (!node_residual(x, in, false, r, error)) return false;
    nodeResidual_ = r.lpNorm<Eigen::Infinity>();
    return true;
}

bool MooringSystem::step_nodes(double t, double h, const UCInputs& in, std::string& error, double offset) {
    // The step in one piece first; where its error estimate exceeds kNodeStepError, again from the step's
    // start in as many substeps as bring it within, and where its coupled iteration does not converge in
    // 2, 4, ... equal substeps (the same step on each, the coupled ends of the nodes' lines extrapolated
    // from their inputs to each substep's start).
    std::vector<std::vector<unsigned char>> start;
    save_node_lines(start);
    const std::vector<FreeNodeMotion> state0 = motion_;
    waterTime_ = t + h;
    std::string why;
    int worst = 0;
    double estimate = 0.0;  // of the step in one piece where it is split for its error
    for (int pieces = 1; pieces <= kMaxSplitSubsteps; pieces *= 2) {
        if (pieces > 1) {  // back to the step's start
            for (size_t k = 0; k < lines_.size(); ++k) {
                if (!start[k].empty() && !lines_[k]->restore_state(start[k].data(), start[k].size(), error)) return false;
            }
            motion_ = state0;
        }
        const double hs = h / pieces;
        bool ok = true;
        for (int j = 0; j < pieces && ok; ++j)
            ok = node_step(hs, offset >= 0.0 ? offset + j * hs : pieces > 1 ? j * hs : -1.0, in, worst, why);
        if (ok && pieces == 1) {
            // its error estimated from the change of the accelerations, as h^3: the substeps that bring
            // it within kNodeStepError (each then errs by 1 / pieces^3 of the step's)
            estimate = node_step_error(h, state0);
            if (estimate > kNodeStepError) {
                int want = 2;
                while (want < kMaxSubsteps && want * want * want * kNodeStepError < estimate) want *= 2;
                pieces = want / 2;  // the loop doubles it
                continue;
            }
        }
        if (ok) {
            nodeSubsteps_ = pieces;
            if (pieces > 1 && !substepsReported_) {
                substepsReported_ = true;
                append_event(event_, "from t = " + std::to_string(t) + " s the free nodes' step of " + std::to_string(h) + " s is split into " +
                         std::to_string(pieces) + " substeps where " +
                         (estimate > kNodeStepError ? "its estimated error in one piece (" + std::to_string(estimate) + " m) exceeds " +
                                                          std::to_string(kNodeStepError) + " m"
                                                    : std::string("its coupled iteration does not converge in one")) +
                         " (reported once)");
            }
            return true;
        }
    }
    const MooringNode& node = deck_.nodes[worst];
    error = (node.failure > 0 ? "the free end of failure " + std::to_string(node.failure) + " (at point " +
                                    std::to_string(node.point.id) + ")"
                              : (node.body ? "free body " : "free point ") + std::to_string(node.point.id)) +
            ": " + why + "; also in " +
            std::to_string(kMaxSplitSubsteps) + " substeps of " + std::to_string(h / kMaxSplitSubsteps) +
            " s: take a shorter communication step";
    return false;
}

void MooringSystem::shift_coupled_ends(int k, double shift, LineEnds& ends) const {
    const MooringDeckLine& l = deck_.lines[k];
    const LineEnds last = line_ends(k, lastInputs_);
    auto shifted = [&](EndMotion& e, const Vec3& lastV) {
        for (int c = 0; c < 3; ++c) {  // the acceleration a driven end would take from its inputs
            if (!e.accelerationGiven) e.acceleration[c] = lastStep_ > 0.0 ? (e.velocity[c] - lastV[c]) / lastStep_ : 0.0;
            e.position[c] += shift * (e.velocity[c] + 0.5 * shift * e.acceleration[c]);
            e.velocity[c] += shift * e.acceleration[c];
        }
        e.accelerationGiven = 1;
    };
    auto coupled = [](const MooringEnd& e) { return e.kind == MooringEnd::Kind::Body || e.kind == MooringEnd::Kind::Point; };
    if (coupled(l.fairlead)) shifted(ends.tow, last.tow.velocity);
    if (held_far_end(l) && coupled(l.far)) shifted(ends.far, last.far.velocity);
}

double MooringSystem::node_step_error(double h, const std::vector<FreeNodeMotion>& start) const {
    // Newmark's average acceleration errs in position over a step by about h^2 / 12 times the change of
    // the acceleration over it; a body's turn by as much of its angular acceleration's, times the reach
    // of its points
    double e = 0.0;
    for (size_t n = 0; n < motion_.size(); ++n) {
        const MooringNode& node = deck_.nodes[n];
        if (!node.pinned)  // (a pinned body's reference point follows its pin)
            e = std::max(e, h * h / 12.0 * (vec3(motion_[n].acceleration) - vec3(start[n].acceleration)).norm());
        if (!node.body) continue;
        // a pinned body's reach: also twice its centre of gravity's distance from the pin (a rod's far end)
        double reach = node.pinned ? 2.0 * vec3(node.cg).norm() : 0.0;
        for (const MooringDeckLine& l : deck_.lines) {
            for (const MooringEnd* end : {&l.fairlead, &l.far}) {
                if (end->kind == MooringEnd::Kind::Node && end->node == static_cast<int>(n)) reach = std::max(reach, vec3(end->position).norm());
            }
        }
        e = std::max(e, h * h / 12.0 * (vec3(motion_[n].alpha) - vec3(start[n].alpha)).norm() * reach);
    }
    return e;
}

void MooringSystem::save_node_lines(std::vector<std::vector<unsigned char>>& into) {
    into.resize(lines_.size());
    for (size_t k = 0; k < lines_.size(); ++k) {
        if (!on_free_node(deck_.lines[k])) continue;
        into[k].resize(lines_[k]->state_size());
        lines_[k]->save_state(into[k].data());
    }
}

bool MooringSystem::node_step(double h, double shift, const UCInputs& in, int& worst, std::string& error) {
    const int m = nodeUnknowns_;
    save_node_lines(nodeLineStart_);
    const std::vector<FreeNodeMotion> start = motion_;
    for (FreeNodeMotion& m : motion_) m.step = h;
    // The nodes move as Newmark's average acceleration has them (trapezoidal: second order, no numerical
    // damping, unconditionally stable): with the acceleration A at t + h,
    //   v(t + h) = v0 + h (a0 + A) / 2,   x(t + h) = x0 + h v0 + h^2 (a0 + A) / 4,
    // and the lines' ends follow them (the driven end's quintic from (x0, v0, a0) to that state). A solves
    // the nodes' equations of motion at t + h, (M + added mass) A = weight, buoyancy, drag + the lines'
    // forces at t + h, by Newton's method with the Jacobian by differences of the lines' steps.
    // A free body turns the same way: its angular velocity and the small rotation over the step,
    //   w(t + h) = w0 + h (alpha0 + alpha) / 2,   R(t + h) = Rot(h w0 + h^2 (alpha0 + alpha) / 4) R0,
    // its equations about its reference point with its centre of gravity c = R CG (its inertia I about it):
    //   M a_cg + m_a a = F,   c x M a_cg + I alpha + w x (I w) = the moment of the loads,
    //   a_cg = a + alpha x c + w x (w x c).
    // A pinned body's reference point follows its pin (at the step's end tau after the communication step's
    // start), its unknowns its angular acceleration, its equation the moment about the pin.
    const double tau = std::max(shift, 0.0) + h;
    auto residual = [&](const Eigen::VectorXd& A, Eigen::VectorXd& r, std::string& why) -> bool {
        std::vector<Vec3> v1(motion_.size());
        for (size_t n = 0; n < motion_.size(); ++n) {
            const MooringNode& node = deck_.nodes[n];
            const int o = nodeOffset_[n];
            const FreeNodeMotion& s = start[n];
            FreeNodeMotion& m = motion_[n];
            if (node.pinned) {
                Vec3 x1, a;
                pin_motion(static_cast<int>(n), in, tau, x1, v1[n], a);
                const Vec3 w0 = vec3(s.omega), alpha = A.segment<3>(o), spin = 0.5 * (vec3(s.alpha) + alpha);
                const Vec3 w = w0 + h * spin;
                const Mat3 R = turn_matrix(h * w0 + 0.5 * h * h * spin) * rotation(s);
                put(m.position, x1);
                put(m.velocity, v1[n]);
                put(m.acceleration, a);
                put_rotation(m, R);
                put(m.omega, w);
                put(m.alpha, alpha);
                const Vec3 c = R * vec3(node.cg);
                const Mat3 I = R * vec3(node.inertia).asDiagonal() * R.transpose();
                const Vec3 acg = a + alpha.cross(c) + w.cross(w.cross(c));
                Vec3 force, moment;
                body_load(static_cast<int>(n), x1, R, v1[n], w, in, force, moment);
                // the water its added mass moves as the pin accelerates, at its centre of buoyancy (a rod's
                // transverse added mass along it: its moment about the pin; its share as it turns is in I)
                const Vec3 fluid = body_added_mass(static_cast<int>(n), x1, R) * a;
                add_body_rod_inertia(static_cast<int>(n), x1, R, a, alpha, force, moment);
                r.segment<3>(o) = moment - c.cross(node.point.mass * acg) - I * alpha - w.cross(I * w) -
                                  (R * vec3(node.cb)).cross(fluid);
                continue;
            }
            const Vec3 x0 = vec3(s.position), v0 = vec3(s.velocity);
            const Vec3 a = A.segment<3>(o), mean = 0.5 * (vec3(s.acceleration) + a);
            v1[n] = v0 + h * mean;
            const Vec3 x1 = x0 + h * v0 + 0.5 * h * h * mean;
            put(m.position, x1);
            // the inputs whose extrapolation to t + h is that state: x + v h + a h^2 / 2, v + a h, a
            const Vec3 v = v1[n] - h * a;
            put(m.inputPosition, x1 - h * v - 0.5 * h * h * a);
            put(m.inputVelocity, v);
            put(m.inputAcceleration, a);
            const LineFilePoint& p = node.point;
            if (!node.body) {
                r.segment<3>(o) = node_load(static_cast<int>(n), x1, in, v1[n]) - (p.mass + p.addedMass) * a;
                continue;
            }
            const Vec3 w0 = vec3(s.omega);
            const Vec3 alpha = A.segment<3>(o + 3), spin = 0.5 * (vec3(s.alpha) + alpha);
            const Vec3 w = w0 + h * spin, turn = h * w0 + 0.5 * h * h * spin;
            const Mat3 R = turn_matrix(turn) * rotation(s);
            put_rotation(m, R);
            put(m.velocity, v1[n]);
            put(m.acceleration, a);
            put(m.omega, w);
            put(m.alpha, alpha);
            const Vec3 c = R * vec3(node.cg);
            const Mat3 I = R * Vec3(node.inertia[0], node.inertia[1], node.inertia[2]).asDiagonal() * R.transpose();
            const Vec3 acg = a + alpha.cross(c) + w.cross(w.cross(c));
            Vec3 force, moment;
            body_load(static_cast<int>(n), x1, R, v1[n], w, in, force, moment);
            add_body_rod_inertia(static_cast<int>(n), x1, R, a, alpha, force, moment);
            r.segment<3>(o) = force - p.mass * acg - body_added_mass(static_cast<int>(n), x1, R) * a;
            r.segment<3>(o + 3) = moment - c.cross(p.mass * acg) - I * alpha - w.cross(I * w);
        }
        const LineEnvironment env = line_environment(in);
        for (size_t k = 0; k < lines_.size(); ++k) {
            const MooringDeckLine& l = deck_.lines[k];
            if (!on_free_node(l)) continue;
            LineEnds drive = line_ends(static_cast<int>(k), in);
            if (shift >= 0.0) shift_coupled_ends(static_cast<int>(k), shift, drive);
            if (!lines_[k]->restore_state(nodeLineStart_[k].data(), nodeLineStart_[k].size(), why) ||
                !lines_[k]->step(h, drive.tow, drive.far, env, why)) {
                why = "mooring line " + std::to_string(l.id) + ": " + why;
                return false;
            }
            const UCOutputs& o = lines_[k]->outputs();
            const MooringEnd* ends[2] = {&l.fairlead, held_far_end(l)};
            const Vec3 force[2] = {vec3(o.towForce), vec3(o.endForce)};
            for (int e = 0; e < 2; ++e) {
                if (!ends[e] || ends[e]->kind != MooringEnd::Kind::Node) continue;
                const int n = ends[e]->node, at = nodeOffset_[n];
                if (deck_.nodes[n].pinned) {  // its moment about the pin
                    r.segment<3>(at) += (rotation(motion_[n]) * vec3(ends[e]->position)).cross(force[e]);
                    continue;
                }
                r.segment<3>(at) += force[e];
                if (deck_.nodes[n].body)
                    r.segment<3>(at + 3) += (rotation(motion_[n]) * vec3(ends[e]->position)).cross(force[e]);
            }
        }
        for (size_t n = 0; n < motion_.size(); ++n) put(motion_[n].velocity, v1[n]);
        for (size_t n = 0; n < motion_.size(); ++n) {  // a pinned body on a free body: its load on its pin
            if (deck_.nodes[n].pinned && deck_.nodes[n].pin.kind == MooringEnd::Kind::Node)
                add_pin_reaction(static_cast<int>(n), pin_force(static_cast<int>(n), in), r);
        }
        return true;
    };
    Eigen::VectorXd A(m), r(m), rp(m);
    for (size_t n = 0; n < motion_.size(); ++n) {
        if (deck_.nodes[n].pinned) {
            A.segment<3>(nodeOffset_[n]) = vec3(start[n].alpha);
            continue;
        }
        A.segment<3>(nodeOffset_[n]) = vec3(start[n].acceleration);
        if (deck_.nodes[n].body) A.segment<3>(nodeOffset_[n] + 3) = vec3(start[n].alpha);
    }
    if (!residual(A, r, error)) return false;
    // the Jacobian by one-sided differences, each moving the nodes by 1e-4 m (a body: turning it by 1e-4
    // rad) at t + h; taken again where the corrections shrink slowly (a body's rotation, a snap)
    const double d = 4e-4 / (h * h);
    Eigen::MatrixXd J(m, m);
    Eigen::FullPivLU<Eigen::MatrixXd> lu;
    auto jacobian = [&](std::string& why) -> bool {
        for (int j = 0; j < m; ++j) {
            Eigen::VectorXd Ap = A;
            Ap[j] += d;
            if (!residual(Ap, rp, why)) return false;
            J.col(j) = (rp - r) / d;
        }
        lu.compute(J);
        return true;
    };
    if (!jacobian(error)) return false;
    int refreshed = 0;
    // Converged when a correction moves the nodes by less than kNodeTolerance at t + h, or when the
    // corrections stop shrinking below 100 times that: the lines' forces carry the noise of their
    // integrators' error control (each trial steps them anew), which the corrections then follow.
    double moved = HUGE_VAL;
    bool converged = false;
    for (nodeIterations_ = 1; nodeIterations_ <= kNodeIterations && !converged; ++nodeIterations_) {
        Eigen::VectorXd dA = -lu.solve(r);
        if (!dA.allFinite()) {
            error = "its equations of motion: singular Jacobian";
            return false;
        }
        // a correction moves the nodes at t + h by at most kMaxCorrection (m, or rad for a body's turn):
        // trials far off would make the lines' integrators work through motions they never have
        const double reach = 0.25 * h * h * dA.lpNorm<Eigen::Infinity>();
        if (reach > kMaxCorrection) dA *= kMaxCorrection / reach;
        A += dA;
        if (!residual(A, r, error)) return false;  // the lines stand at the last A
        const double last = moved;
        moved = 0.25 * h * h * dA.lpNorm<Eigen::Infinity>();
        for (size_t n = 0; n < motion_.size(); ++n) {  // the node that moves most: named where it fails
            const int size = node_unknowns(deck_.nodes[n]);
            if (0.25 * h * h * dA.segment(nodeOffset_[n], size).lpNorm<Eigen::Infinity>() >= moved) worst = static_cast<int>(n);
        }
        converged = moved < kNodeTolerance || (moved < 100.0 * kNodeTolerance && moved > 0.5 * last);
        if (!converged && moved > 0.25 * last && refreshed < kJacobianRefreshes) {
            ++refreshed;
            if (!jacobian(error)) return false;  // the next correction steps the lines anew from A
        }
    }
    if (!converged) {
        error = "its equations of motion did not converge in " + std::to_string(kNodeIterations) +
                " iterations over a step of " + std::to_string(h) + " s (last correction " + std::to_string(moved) +
                " m or rad)";
        return false;
    }
    for (size_t n = 0; n < motion_.size(); ++n) {
        if (!deck_.nodes[n].pinned) put(motion_[n].acceleration, A.segment<3>(nodeOffset_[n]));  // (a pin's: set)
    }
    return true;
}

namespace {

// d(R r)/d(the orientation inputs) of a coupled body, as bodyOrientation reads them: the columns for roll,
// pitch, yaw (R = Rx Ry Rz or Rz Ry Rx; the fourth 0) or for q0..q3 (R of the normalized quaternion).
Eigen::Matrix<double, 3, 4> rotation_derivative(const UCCoupledBody& body, int orientation, const Vec3& r) {
    Eigen::Matrix<double, 3, 4> d = Eigen::Matrix<double, 3, 4>::Zero();
    if (orientation == UC_ORIENTATION_QUATERNION) {
        // R r = r + 2 q0 (v x r) + 2 v x (v x r) for a unit q = (q0, v); q = p / |p| of the input p
        const double* p = body.quaternion;
        const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]);
        const Eigen::Vector4d q = Eigen::Vector4d(p[0], p[1], p[2], p[3]) / n;
        const Vec3 v = q.tail<3>();
        d.col(0) = 2.0 * v.cross(r);
        d.rightCols<3>() = -2.0 * q[0] * skew(r) + 2.0 * (v.dot(r) * Mat3::Identity() + v * r.transpose() -
                                                          2.0 * r * v.transpose());
        return d * (Eigen::Matrix4d::Identity() - q * q.transpose()) / n;
    }
    const double* a = body.rotation;
    const Mat3 Rx = Eigen::AngleAxisd(a[0], Vec3::UnitX()).toRotationMatrix();
    const Mat3 Ry = Eigen::AngleAxisd(a[1], Vec3::UnitY()).toRotationMatrix();
    const Mat3 Rz = Eigen::AngleAxisd(a[2], Vec3::UnitZ()).toRotationMatrix();
    if (orientation == UC_ORIENTATION_ANGLES_ZYX) {
        d.col(0) = Rz * Ry * Rx * skew(Vec3::UnitX()) * r;
        d.col(1) = Rz * Ry * skew(Vec3::UnitY()) * Rx * r;
        d.col(2) = Rz * skew(Vec3::UnitZ()) * Ry * Rx * r;
        return d;
    }
    d.col(0) = skew(Vec3::UnitX()) * Rx * Ry * Rz * r;
    d.col(1) = Rx * skew(Vec3::UnitY()) * Ry * Rz * r;
    d.col(2) = Rx * Ry * skew(Vec3::UnitZ()) * Rz * r;
    return d;
}

}  // namespace

bool MooringSystem::interface_derivative(const double[kDerivativeInputs], double[6], std::string& error) {
    error = "the interface derivatives of towForce and endForce are not available for a mooring system "
            "(its bodies' loads have theirs: body[k].force/moment with respect to body[k].*)";
    return false;
}

bool MooringSystem::body_derivatives(int b, double d[6][UC_BODY_DERIVATIVE_INPUTS], std::string& error) {
    constexpr int N = UC_BODY_DERIVATIVE_INPUTS;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < N; ++j) d[i][j] = 0.0;
    if (b < 1 || b > deck_.bodies) {
        error = "body " + std::to_string(b) + " is not a coupled body of the deck";
        return false;
    }
    for (const MooringNode& node : deck_.nodes) {
        if (!node.pinned) continue;
        error = "the interface derivatives of a system with a pinned body (free body " + std::to_string(node.point.id) +
                ") are not computed: its pin's load on the body that holds it has no derivatives yet";
        return false;
    }
    const double h = lastStep_;
    if (!(h > 0.0)) {
        error = "the interface derivatives are over the next communication step, taken as long as the last one: "
                "they are available after the first fmi2DoStep";
        return false;
    }
    std::array<double, 6 * N>& cache = derivativeCache_[b - 1];
    if (derivativeStamp_[b - 1] == stamp_) {
        std::memcpy(&d[0][0], cache.data(), sizeof(double) * 6 * N);
        return true;
    }
    const UCCoupledBody& body = lastInputs_.coupledBody[b - 1];
    const Mat3 R = coupled_body_rotation(body, base_.bodyOrientation);
    const Vec3 w = vec3(body.angularVelocity);
    using Mat3N = Eigen::Matrix<double, 3, N>;
    // the orientation inputs' columns: roll, pitch, yaw (3 to 5) or q0..q3 (12 to 15)
    const bool quaternion = base_.bodyOrientation == UC_ORIENTATION_QUATERNION;
    const int turn = quaternion ? 12 : 3, turns = quaternion ? 4 : 3;
    // The reference point at t + h moves with its inputs as a driven end does: 1 per unit position,
    // 1.5 h per unit velocity (the acceleration from the last two velocity inputs, cosimulation.md).
    // (h alone where the master gives the acceleration)
    const double velocityWeight = references_[b - 1].lastAccelerationGiven ? h : 1.5 * h;
    Mat3N dReference = Mat3N::Zero();
    dReference.block<3, 3>(0, 0).setIdentity();
    dReference.block<3, 3>(0, 6) = velocityWeight * Mat3::Identity();
    const bool accelerations = references_[b - 1].lastAccelerationGiven;
    const Vec3 alpha = vec3(lastInputs_.bodyAcceleration + 6 * (b - 1) + 3);
    Eigen::Matrix<double, 6, N> D = Eigen::Matrix<double, 6, N>::Zero();
    for (size_t k = 0; k < lines_.size(); ++k) {
        const MooringDeckLine& l = deck_.lines[k];
        const MooringEnd* ends[2] = {&l.fairlead, &l.far};
        bool on[2];
        for (int e = 0; e < 2; ++e) on[e] = ends[e]->kind == MooringEnd::Kind::Body && ends[e]->body == b;
        if (!on[0] && !on[1]) continue;
        // each end's input (position, velocity, and where the master gives them its acceleration
        // a + alpha x arm + w x (w x arm)) per unit body input, and its position at t + h
        Eigen::Matrix<double, 9, N> T[2];
        Mat3N dPosition[2];
        for (int e = 0; e < 2; ++e) {
            T[e].setZero();
            dPosition[e].setZero();
            if (!on[e]) continue;
            const Vec3 arm = R * vec3(ends[e]->position);
            const Eigen::Matrix<double, 3, 4> dArm = rotation_derivative(body, base_.bodyOrientation,
                                                                         vec3(ends[e]->position));
            T[e].block<3, 3>(0, 0).setIdentity();
            T[e].block<3, 3>(3, 6).setIdentity();
            T[e].block<3, 3>(3, 9) = -skew(arm);
            for (int c = 0; c < turns; ++c) {
                T[e].block<3, 1>(0, turn + c) = dArm.col(c);
                T[e].block<3, 1>(3, turn + c) = skew(w) * dArm.col(c);
                if (accelerations) T[e].block<3, 1>(6, turn + c) = (skew(alpha) + skew(w) * skew(w)) * dArm.col(c);
            }
            if (accelerations) T[e].block<3, 3>(6, 9) = -skew(w.cross(arm)) - skew(w) * skew(arm);
            dPosition[e] = T[e].topRows<3>() + velocityWeight * T[e].middleRows<3>(3) +
                           (accelerations ? 0.5 * h * h : 0.0) * T[e].bottomRows<3>();
        }
        // the line's interface derivatives in the directions of the body's inputs (one integration each;
        // none for the orientation inputs that bodyOrientation does not read)
        Eigen::Matrix<double, 6, N> lineD = Eigen::Matrix<double, 6, N>::Zero();
        for (int j = 0; j < N; ++j) {
            if (T[0].col(j).isZero(0.0) && T[1].col(j).isZero(0.0)) continue;
            double seed[CableSimulation::kDerivativeInputs] = {0.0}, out[6];
            for (int i = 0; i < 6; ++i) {
                seed[i] = T[0](i, j);
                seed[6 + i] = T[1](i, j);
            }
            for (int i = 0; i < 3; ++i) {
                seed[12 + i] = T[0](6 + i, j);
                seed[15 + i] = T[1](6 + i, j);
            }
            if (!lines_[k]->interface_derivative(seed, out, error)) {
                error = "mooring line " + std::to_string(l.id) + ": " + error;
                return false;
            }
            for (int i = 0; i < 6; ++i) lineD(i, j) = out[i];
        }
        const UCOutputs& o = lines_[k]->outputs();
        const Vec3 force[2] = {vec3(o.towForce), vec3(o.endForce)};
        const Vec3 at[2] = {lines_[k]->tow_position(), vec3(o.endPosition)};
        for (int e = 0; e < 2; ++e) {
            if (!on[e]) continue;
            const Mat3N dForce = lineD.middleRows<3>(3 * e);  // this end's force per unit body input
            const Vec3 arm = at[e] - references_[b - 1].position;
            D.topRows<3>() += dForce;
            D.bottomRows<3>() += skew(arm) * dForce - skew(force[e]) * (dPosition[e] - dReference);
        }
    }
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < N; ++j) cache[N * i + j] = d[i][j] = D(i, j);
    derivativeStamp_[b - 1] = stamp_;
    return true;
}

size_t MooringSystem::state_size() const {
    size_t size = sizeof(SystemHeader) + lines_.size() * sizeof(std::uint64_t) + description_.size() * sizeof(double) +
                  references_.size() * sizeof(DrivenEndState) + sizeof(UCOutputs) +
                  moreLines_.size() * sizeof(UCMooringLine) + sizeof(UCInputs) +
                  failureState_.size() * sizeof(FailureState) + motion_.size() * sizeof(FreeNodeMotion);
    for (const auto& line : lines_) size += line->state_size();
    return size;
}

void MooringSystem::save_state(void* buffer) {
    SystemHeader header{};
    header.magic = kSystemMagic;
    header.version = kSystemVersion;
    header.lines = static_cast<std::int32_t>(lines_.size());
    header.bodies = static_cast<std::int32_t>(references_.size());
    header.nodes = static_cast<std::int32_t>(motion_.size());
    header.failures = static_cast<std::int32_t>(failureState_.size());
    header.lastStep = lastStep_;
    header.described = description_.size();
    auto* out = static_cast<unsigned char*>(buffer);
    std::memcpy(out, &header, sizeof header);
    out += sizeof header;
    for (const auto& line : lines_) {
        const std::uint64_t lineSize = line->state_size();
        std::memcpy(out, &lineSize, sizeof lineSize);
        out += sizeof lineSize;
    }
    for (const DescribedValue& d : description_) {
        std::memcpy(out, &d.value, sizeof d.value);
        out += sizeof d.value;
    }
    for (const DrivenEnd& e : references_) {
        DrivenEndState s{};
        e.save(s);
        std::memcpy(out, &s, sizeof s);
        out += sizeof s;
    }
    std::memcpy(out, &outputs_, sizeof outputs_);
    out += sizeof outputs_;
    if (!moreLines_.empty()) std::memcpy(out, moreLines_.data(), moreLines_.size() * sizeof(UCMooringLine));
    out += moreLines_.size() * sizeof(UCMooringLine);
    std::memcpy(out, &lastInputs_, sizeof lastInputs_);
    out += sizeof lastInputs_;
    out = save_failures(out);
    if (!motion_.empty()) std::memcpy(out, motion_.data(), motion_.size() * sizeof(FreeNodeMotion));
    out += motion_.size() * sizeof(FreeNodeMotion);
    for (auto& line : lines_) {
        line->save_state(out);
        out += line->state_size();
    }
}

// Bit for bit: a state continues exactly as saved only on the very system it was saved from.
bool MooringSystem::same_description(const unsigned char* saved, std::string& error) const {
    size_t differ = 0, first = 0;
    double then = 0.0;
    for (size_t i = 0; i < description_.size(); ++i) {
        double value;
        std::memcpy(&value, saved + i * sizeof value, sizeof value);
        if (std::memcmp(&value, &description_[i].value, sizeof value) == 0) continue;
        if (differ++ == 0) {
            first = i;
            then = value;
        }
    }
    if (differ == 0) return true;
    char text[160];
    std::snprintf(text, sizeof text, " = %.17g now, %.17g in the state", description_[first].value, then);
    error = "the deck is not the one the state was saved with: " + description_[first].name + text +
            (differ > 1 ? " (and " + std::to_string(differ - 1) + " more values differ)" : std::string()) +
            "; restore the deck the state was saved with, or initialize anew";
    return false;
}

bool MooringSystem::restore_state(const void* buffer, size_t size, std::string& error, bool* changed) {
    if (changed) *changed = false;
    ++stamp_;  // (only what the cached derivatives were computed for: computed again)
    SystemHeader header;
    if (size < sizeof header) {
        error = "saved state is too short for this mooring system";
        return false;
    }
    const auto* in = static_cast<const unsigned char*>(buffer);
    std::memcpy(&header, in, sizeof header);
    if (header.magic != kSystemMagic) {
        error = "saved state is not a state of a mooring system (its magic number differs)";
        return false;
    }
    if (header.version != kSystemVersion) {
        error = "saved state is a mooring system's state of format version " + std::to_string(header.version) +
                ", this FMU reads version " + std::to_string(kSystemVersion) +
                what_later_versions_added(header.version) +
                ": it cannot be restored; initialize anew (or restore with the FMU that saved it)";
        return false;
    }
    // the free nodes: the deck's and one per broken failure
    const size_t failureBytes = failureState_.size() * sizeof(FailureState);
    const size_t sizesAt = sizeof header, describedAt = sizesAt + lines_.size() * sizeof(std::uint64_t);
    const size_t failureAt = describedAt + description_.size() * sizeof(double) +
                             references_.size() * sizeof(DrivenEndState) + sizeof(UCOutputs) +
                             moreLines_.size() * sizeof(UCMooringLine) + sizeof(UCInputs);
    size_t nodes = 0;
    const std::vector<FailureState> failureState = saved_failures(
        in + failureAt, header.failures == static_cast<std::int32_t>(failureState_.size()) && size >= failureAt + failureBytes,
        nodes);
    if (header.lines != static_cast<std::int32_t>(lines_.size()) ||
        header.bodies != static_cast<std::int32_t>(references_.size()) ||
        header.failures != static_cast<std::int32_t>(failureState_.size()) ||
        header.nodes != static_cast<std::int32_t>(nodes) || header.described != description_.size()) {
        error = "the deck is not the one the state was saved with: it makes " + std::to_string(lines_.size()) +
                " lines, " + std::to_string(references_.size()) + " coupled bodies, " + std::to_string(failureState_.size()) +
                " failures and " + std::to_string(nodes) + " free nodes (with the state's failures) now, the state's " +
                std::to_string(header.lines) + ", " + std::to_string(header.bodies) + ", " +
                std::to_string(header.failures) + " and " + std::to_string(header.nodes);
        return false;
    }
    size_t expected = failureAt + failureBytes + nodes * sizeof(FreeNodeMotion);
    std::vector<std::uint64_t> lineSize(lines_.size(), 0);
    if (size >= describedAt) {
        if (!lineSize.empty()) std::memcpy(lineSize.data(), in + sizesAt, lineSize.size() * sizeof(std::uint64_t));
        for (const std::uint64_t s : lineSize) {
            if (s > size) break;  // (the sum below cannot wrap)
            expected += s;
        }
    }
    if (size != expected) {
        error = "saved state has the wrong size for this mooring system";
        return false;
    }
    in += describedAt;
    if (!same_description(in, error)) return false;
    in += description_.size() * sizeof(double);
    std::vector<DrivenEnd> references(references_.size());
    for (DrivenEnd& e : references) {
        DrivenEndState s;
        std::memcpy(&s, in, sizeof s);
        e.load(s);
        in += sizeof s;
    }
    UCOutputs outputs;
    std::memcpy(&outputs, in, sizeof outputs);
    in += sizeof outputs;
    std::vector<UCMooringLine> moreLines(moreLines_.size());
    if (!moreLines.empty()) std::memcpy(moreLines.data(), in, moreLines.size() * sizeof(UCMooringLine));
    in += moreLines.size() * sizeof(UCMooringLine);
    UCInputs lastInputs;
    std::memcpy(&lastInputs, in, sizeof lastInputs);
    in += sizeof lastInputs;
    in += failureBytes;  // (read above)
    std::vector<FreeNodeMotion> motion(nodes);
    if (!motion.empty()) std::memcpy(motion.data(), in, motion.size() * sizeof(FreeNodeMotion));
    in += motion.size() * sizeof(FreeNodeMotion);
    for (size_t k = 0; k < lines_.size(); ++k) {
        bool lineChanged = false;
        if (!lines_[k]->restore_state(in, lineSize[k], error, &lineChanged)) {
            if (changed) *changed = k > 0 || lineChanged;
            error = "mooring line " + std::to_string(deck_.lines[k].id) + ": " + error;
            return false;
        }
        in += lineSize[k];
    }
    references_ = references;
    stiffnessCurrent_ = false;
    failureState_ = failureState;
    motion_ = motion;
    apply_failures();
    outputs_ = outputs;
    moreLines_ = moreLines;
    lastInputs_ = lastInputs;
    lastStep_ = header.lastStep;
    return true;
}

}  // namespace uc
