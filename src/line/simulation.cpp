// simulation.cpp - initialization, stepping, outputs and exact state save/restore of one cable.
#include "line/simulation.h"


#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>

#include "model/line_profile.h"
#include "model/mesh_grading.h"
#include "line/outputs.h"
#include "model/params.h"
#include "line/rainflow.h"
#include "line/statics.h"
#include "numerics/sundials_compat.h"
#include "line/winch.h"

namespace uc {
namespace {

constexpr std::uint32_t kStateMagic = 0x55434142;  // "UCAB"
constexpr std::uint32_t kStateVersion = 11;
// bottomEnd 4: the estimate's low-pass spans at least this many communication steps. Under Jacobi the
// body feels the proxy's force a step late; a faster estimate then feeds that lag back into the proxy
// (the model problem in docs/cosimulation.md: 5 steps keep the gains stable with +-50 % inertia error
// and no drag at all, 3 do not).
constexpr double kProxyFilterSteps = 5.0;

// Fixed-layout header of a saved state: what it belongs to (the sizes and the winch's mesh, which
// the model holds); followed by LineState, y, y' and the integrator's history.
struct StateHeader {
    std::uint32_t magic;
    std::uint32_t version;
    std::int32_t nFree;
    std::int32_t nElements;
    std::int32_t winchElements;  // the winch's mesh: elements of the first section, top length at its build
    std::int32_t stateBytes;     // sizeof(LineState)
    double winchMeshTop;
};

IntegratorStats operator+(const IntegratorStats& a, const IntegratorStats& b) {
    IntegratorStats s;
    s.steps = a.steps + b.steps;
    s.residualEvals = a.residualEvals + b.residualEvals;
    s.jacobianEvals = a.jacobianEvals + b.jacobianEvals;
    s.nonlinearFailures = a.nonlinearFailures + b.nonlinearFailures;
    s.errorTestFailures = a.errorTestFailures + b.errorTestFailures;
    return s;
}

Vec3 vec(const double v[3]) { return Vec3(v[0], v[1], v[2]); }

// The jerk of a driven end at the current inputs, from the acceleration inputs of this step and
// the previous one (both given by the master), trusted per component only as far as the
// velocity inputs confirm it: an acceleration that changes linearly over the previous step
// changes the velocity by the trapezoid h (a + aLast) / 2. Where it does not (an acceleration
// that jumped, as at the start or end of a ramp), extrapolating the jerk would overshoot; the
// weight falls linearly from 1 to 0 as the trapezoid's miss grows to half of h |a - aLast| / 2
// (a jump at a communication point misses by all of it, a smooth heave sampled 10 times per
// period by 5 %).
Vec3 jerk_estimate(const Vec3& a, const Vec3& aLast, const Vec3& v, const Vec3& vLast, double hLast) {
    Vec3 j = Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
        const double da = a[k] - aLast[k];
        const double scale = 0.5 * hLast * std::fabs(da);
        if (!(scale > 0.0)) continue;
        const double miss = std::fabs(v[k] - vLast[k] - 0.5 * hLast * (a[k] + aLast[k]));
        const double weight = std::max(0.0, 1.0 - 2.0 * miss / scale);
        j[k] = weight * da / hLast;
    }
    return j;
}

}  // namespace

double acceleration_disagreement(double a0, double a1, double dv, double h) {
    if (!(h > 0.0)) return 0.0;
    const double mean = dv / h;
    const double low = std::min(a0, a1), high = std::max(a0, a1);
    const double miss = mean < low ? low - mean : mean > high ? mean - high : 0.0;
    const double allowance =
        UC_ACCELERATION_FLOOR + UC_ACCELERATION_MARGIN * std::max({std::fabs(mean), std::fabs(a0), std::fabs(a1)});
    return miss > allowance ? miss : 0.0;
}


void DrivenEndState::reset(const Vec3& p, const Vec3& v, const Vec3& a, bool accelerationGiven) {
    Eigen::Map<Vec3>{position} = p;
    Eigen::Map<Vec3>{velocity} = v;
    Eigen::Map<Vec3>{acceleration} = a;
    Eigen::Map<Vec3>{lastVelocityInput} = v;
    Eigen::Map<Vec3>{lastAccelerationInput} = a;
    lastAccelerationGiven = accelerationGiven ? 1.0 : 0.0;
}

TowTrajectory DrivenEndState::next(double t, double h, double lastStep, const Vec3& positionInput,
                                   const Vec3& velocityInput, const Vec3& accelerationInput, int accelerationFlags,
                                   Vec3& a) const {
    const Vec3 lastVelocityInput = vec(this->lastVelocityInput), lastAccelerationInput = vec(this->lastAccelerationInput);
    const bool lastAccelerationGiven = this->lastAccelerationGiven != 0.0;
    // The acceleration is the master's input derivative when given; otherwise the difference of
    // the last two velocity inputs (0 before there are two), so that an accelerating tow sampled
    // at communication points is still followed smoothly. A component set as the input tow.a* (not
    // an input derivative) to 0 here and at the previous communication point while its velocity
    // input changed over the step (beyond acceleration_disagreement's allowance) is a master
    // that fills every input with 0, not an acceleration: it is estimated from the velocities too
    // (docs/interface.md, "How the FMU reads a driven end").
    const bool accelerationGiven = accelerationFlags != 0;
    const Vec3 estimate = lastStep > 0.0 ? Vec3((velocityInput - lastVelocityInput) / lastStep) : Vec3::Zero();
    a = accelerationGiven ? accelerationInput : estimate;  // what the next step remembers
    Vec3 used = a;
    bool zeroHeld[3] = {false, false, false};
    if (accelerationGiven && lastAccelerationGiven && lastStep > 0.0) {
        for (int k = 0; k < 3; ++k) {
            zeroHeld[k] = (accelerationFlags & UC_ACCELERATION_AS_INPUT(k)) != 0 && accelerationInput[k] == 0.0 &&
                          lastAccelerationInput[k] == 0.0 &&
                          acceleration_disagreement(0.0, 0.0, velocityInput[k] - lastVelocityInput[k], lastStep) > 0.0;
            if (zeroHeld[k]) used[k] = estimate[k];
        }
    }
    Vec3 j = accelerationGiven && lastAccelerationGiven && lastStep > 0.0
                 ? jerk_estimate(used, lastAccelerationInput, velocityInput, lastVelocityInput, lastStep)
                 : Vec3::Zero();
    for (int k = 0; k < 3; ++k)
        if (zeroHeld[k]) j[k] = 0.0;
    const Vec3 p1 = positionInput + h * (velocityInput + h * (0.5 * used + h * (j / 6.0)));
    const Vec3 v1 = velocityInput + h * (used + h * (0.5 * j));
    const Vec3 a1 = used + h * j;
    return TowTrajectory::quintic(t, h, p(), v(), this->a(), p1, v1, a1);
}

void DrivenEndState::advance(const TowTrajectory& traj, const Vec3& velocityInput, const Vec3& a,
                             bool accelerationGiven) {
    Eigen::Map<Vec3>{position} = traj.p1;
    Eigen::Map<Vec3>{velocity} = traj.v1;
    Eigen::Map<Vec3>{acceleration} = traj.a1;
    Eigen::Map<Vec3>{lastVelocityInput} = velocityInput;
    Eigen::Map<Vec3>{lastAccelerationInput} = a;
    lastAccelerationGiven = accelerationGiven ? 1.0 : 0.0;
}

void DrivenEnd::reset(const Vec3& p, const Vec3& v, const Vec3& a, bool accelerationGiven) {
    position = p;
    velocity = v;
    acceleration = a;
    lastVelocityInput = v;
    lastAccelerationInput = a;
    lastAccelerationGiven = accelerationGiven;
}

TowTrajectory DrivenEnd::next(double t, double h, double lastStep, const Vec3& positionInput,
                              const Vec3& velocityInput, const Vec3& accelerationInput, int accelerationGiven,
                              Vec3& a) const {
    DrivenEndState s;
    save(s);
    return s.next(t, h, lastStep, positionInput, velocityInput, accelerationInput, accelerationGiven, a);
}

void DrivenEnd::advance(const TowTrajectory& traj, const Vec3& velocityInput, const Vec3& a, bool accelerationGiven) {
    DrivenEndState s;
    save(s);
    s.advance(traj, velocityInput, a, accelerationGiven);
    load(s);
}

void DrivenEnd::save(DrivenEndState& s) const {
    for (int k = 0; k < 3; ++k) {
        s.position[k] = position[k];
        s.velocity[k] = velocity[k];
        s.acceleration[k] = acceleration[k];
        s.lastVelocityInput[k] = lastVelocityInput[k];
        s.lastAccelerationInput[k] = lastAccelerationInput[k];
    }
    s.lastAccelerationGiven = lastAccelerationGiven ? 1.0 : 0.0;
}

void DrivenEnd::load(const DrivenEndState& s) {
    position = vec(s.position);
    velocity = vec(s.velocity);
    acceleration = vec(s.acceleration);
    lastVelocityInput = vec(s.lastVelocityInput);
    lastAccelerationInput = vec(s.lastAccelerationInput);
    lastAccelerationGiven = s.lastAccelerationGiven != 0.0;
}

namespace {

// The linearization of the end load (12 inputs) is finite.
bool end_load_linearization_finite(const UCInputs& in) {
    const double* rows[3] = {in.endLoadDamping.x, in.endLoadDamping.y, in.endLoadDamping.z};
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(in.endLoadVelocity[i]) || !std::isfinite(rows[i][0]) || !std::isfinite(rows[i][1]) ||
            !std::isfinite(rows[i][2]))
            return false;
    return true;
}

// The tension scale of the error control: the largest tension of the initial state, at least the
// weight in air of the cable and the towed body (a cable released from rest has no tension yet;
// its weight is what it will carry), the Euler load pi^2 EI / L (a weightless rod) and the
// tension of a strain of 1e-6.
double tension_scale(const CableModel& model, const UCOutputs& initial) {
    const UCParams& p = model.params();
    const LineScales& line = model.line();
    double T = initial.towTension;
    for (double t : initial.tension) T = std::max(T, t);
    double body = model.far_end_carries_body() ? p.bodyMass : 0.0;
    for (const NodeAttachment& at : model.attachments()) body += at.body.mass;
    return std::max({T, (line.massPerLength * line.length + body) * p.gravity, kPi * kPi * line.EI / (line.length * line.length),
                     1e-6 * line.EA});
}

}  // namespace

CableSimulation::CableSimulation(const UCParams& params) : model_(params) {
    loads_.proxy = &state_.proxy;
    sn_.m = params.fatigueM;
    sn_.logK = params.fatigueLogK;
    sn_.area = params.fatigueArea;
    off_ = params.winchMode == UC_WINCH_TENSION ? 1 : 0;
    if (SUNContext_Create(UC_SUN_COMM_NULL, &context_) != 0 || context_ == nullptr) throw std::bad_alloc();
    try {
        allocate();
    } catch (...) {
        integrator_.reset();
        staticSolver_.reset();
        SUNContext_Free(&context_);
        throw;
    }
}

int CableSimulation::unknowns_bandwidth() const {
    int bandwidth = model_.free_bandwidth();
    if (off_ == 0) return bandwidth;
    for (int a = 0; a < 12; ++a) {  // the winch's unknown (index 0) couples to the top element's
        const int j = model_.free_index(model_.element_offset(0) + a);
        if (j >= 0) bandwidth = std::max(bandwidth, j + 1);
    }
    return bandwidth;
}

// Everything sized by the number of unknowns (at construction and at a remesh).
void CableSimulation::allocate() {
    const int n = model_.n_free(), unknowns = this->unknowns();
    integrator_ = std::make_unique<Integrator>(context_, unknowns, unknowns_bandwidth(), this);
    staticSolver_ = std::make_unique<BandSolver>(context_, n, model_.free_bandwidth());
    y_.assign(2 * unknowns, 0.0);
    yp_.assign(2 * unknowns, 0.0);
    q_.assign(n, 0.0);
    v_.assign(n, 0.0);
    a_.assign(n, 0.0);
    R_.assign(n, 0.0);
    X_.assign(model_.n_global(), 0.0);
    Xd_.assign(model_.n_global(), 0.0);
    Xdd_.assign(model_.n_global(), 0.0);
    forces_.element.resize(model_.n_elements());
    outputWork_.nodeTension.resize(model_.n_elements() + 1);
}

// The constant-tension winch's rate for the tow tension T with the top element at topLength:
// (T - T_set) times the line's axial compliance over winch.timeConstant, within winch.maxRate and
// stopped at the length limits; slope = d rate / dT (0 where limited).
double CableSimulation::line_tension(const double* R) const {
    return -Eigen::Map<const Vec3>(R).dot(Eigen::Map<const Vec3>(X_.data() + 3).normalized());
}

double CableSimulation::tension_winch_rate(double tension, double topLength, double* slope) const {
    const UCParams& p = model_.params();
    const double gain = model_.axial_compliance() / p.winchTimeConstant;
    double rate = gain * (tension - winchTension_);
    double dRate = gain;
    if (std::abs(rate) > p.winchMaxRate) {
        rate = std::copysign(p.winchMaxRate, rate);
        dRate = 0.0;
    }
    const double length = state_.winchLength + (topLength - winchTopAtStep_);
    if ((length >= p.winchMaxLength && rate > 0.0) || (length <= p.winchMinLength && rate < 0.0)) {
        rate = 0.0;
        dRate = 0.0;
    }
    const double braked = braking_rate_limit(rate, length, winch_limits());  // in time for the limits
    if (braked != rate) {
        rate = braked;
        dRate = 0.0;
    }
    if (slope) *slope = dRate;
    return rate;
}

CableSimulation::~CableSimulation() {
    integrator_.reset();
    staticSolver_.reset();
    if (context_) SUNContext_Free(&context_);
}

void CableSimulation::set_environment(const UCInputs& in) {
    loads_.current.uniform = Vec3(in.current[0], in.current[1], 0.0);
    loads_.current.scale = in.currentScale;
    loads_.current.profile = &model_.current_profile();
    loads_.current.sea = &model_.sea();
    loads_.endLoad = vec(in.endLoad);
    loads_.endLoadVelocity = vec(in.endLoadVelocity);
    const double* rows[3] = {in.endLoadDamping.x, in.endLoadDamping.y, in.endLoadDamping.z};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) loads_.endLoadDamping(i, j) = rows[i][j];
    loads_.endCouple = vec(in.endCouple);
}

// From the sections and attachments; the profile's top end is the higher of the two ends.
bool CableSimulation::static_profile(const Vec3& towPoint, const Vec3& anchor, LineProfile& profile, bool& towOnTop,
                                     std::string* why) const {
    const UCParams& p = model_.params();
    if (!model_.far_end_prescribed() || model_.winch()) return false;
    towOnTop = towPoint.z() >= anchor.z();
    std::vector<LineProfile::Segment> segments;
    for (int k = 0; k < model_.n_sections(); ++k) {
        const SectionProps& sec = model_.section(k);
        segments.push_back({sec.length, submerged_weight(sec.fluid), sec.axial.EA, dry_weight(sec.fluid)});
    }
    std::vector<LineProfile::PointLoad> points;
    const double L = model_.line().length;
    for (const NodeAttachment& at : model_.attachments()) {
        const double weight = (at.body.mass - model_.fluid().rho * at.body.volume) * model_.fluid().gravity;
        points.push_back({towOnTop ? at.s : L - at.s, weight, at.body.mass * model_.fluid().gravity});
    }
    if (!towOnTop) std::reverse(segments.begin(), segments.end());
    // the line weighs its dry weight above the water surface at z = 0, as the elements do
    return profile.solve(towOnTop ? towPoint : anchor, towOnTop ? anchor : towPoint, segments, points,
                         p.enableSeabed != 0, -p.waterDepth, std::max(model_.line().diameter, 1e-3 * L), why, 0.0);
}

// An anchored line starts from its static profile, into X; false where that does not apply. From
// the parabola of initial_guess, the continuation of a stiff power cable settled at some meshes (16,
// 25, 30, ... of 250 m) into a folded equilibrium at up to four times the tension, and lines resting
// on a stiff seabed often found none; from the profile it finds the one a user expects.
bool CableSimulation::profile_guess(double* X) const {
    if (!profile_.solved) return false;
    const LineProfile& profile = profile_.profile;
    const bool towOnTop = profile_.towOnTop;
    const double L = model_.line().length;
    Vec3 r, tangent;
    for (int i = 0; i < model_.n_slots(); ++i) {
        const double s = model_.slot_arc_length(i);
        // the second slot of a pinned node takes the tangent below it
        const bool below = i + 1 < model_.n_slots() && model_.slot_arc_length(i + 1) == s;
        const double eps = below ? 1e-9 * L : -1e-9 * L;
        profile.at(towOnTop ? std::clamp(s - eps, 0.0, L) : std::clamp(L - s + eps, 0.0, L), r, tangent);
        Eigen::Map<Vec3>(X + 6 * i) = r;
        Eigen::Map<Vec3>(X + 6 * i + 3) = towOnTop ? tangent : Vec3(-tangent);
    }
    return true;
}

// Nodes graded by the static profile for an anchored line that rests on the seabed or carries
// attachments (src/model/mesh_grading.h); the model is built again where its mesh changes. The profile is
// kept (profile_) for the ends the model holds: the guess, the refusal and the check read it.
void CableSimulation::grade_mesh(const Vec3& towPoint, const Vec3& farPoint, bool apply, int grading) {
    ProfileState& ps = profile_;
    auto solve_for = [&](const Vec3& far) {
        ps.far = far;
        ps.why.clear();
        ps.solved = static_profile(towPoint, far, ps.profile, ps.towOnTop, &ps.why);
    };
    StaticLayout layout;
    ps.solved = false;
    if (apply) solve_for(farPoint);
    if (ps.solved) {
        // the anchor is the lower end, held where the line rests (CableModel): graded for that point
        layout.anchorResting = ps.towOnTop && ps.profile.rests_at_bottom() && model_.params().bottomEnd == UC_BOTTOM_ANCHORED;
        const Vec3 resting(farPoint.x(), farPoint.y(), model_.resting_height());
        if (layout.anchorResting && std::abs(farPoint.z() - resting.z()) <= 0.5 * model_.line().diameter) solve_for(resting);
        const int mode = model_.params().meshGrading;
        if (ps.solved && mode != 0 && (ps.profile.grounded_length() > 0.0 || !model_.attachments().empty()))
            layout.nodes = graded_nodes(model_, ps.profile, ps.towOnTop, mode == 2, kGradings[grading]);
    }
    Eigen::Map<Vec3>{state_.meshTow} = towPoint;
    Eigen::Map<Vec3>{state_.meshFar} = farPoint;
    state_.grading = grading;
    const bool graded = !layout.nodes.empty() || layout.anchorResting;
    if (graded != state_.graded || !(layout == layout_)) {
        state_.graded = graded;
        layout_ = layout;
        replace_model(CableModel(model_.params(), nullptr, graded ? &layout_ : nullptr));
    }
    const Vec3 held = model_.params().bottomEnd == UC_BOTTOM_ANCHORED ? model_.anchor() : farPoint;
    if (apply && held != ps.far) solve_for(held);
}

bool CableSimulation::initial_guess(const Vec3& towPoint, const Vec3& farPoint, std::vector<double>& q) const {
    const UCParams& p = model_.params();
    std::vector<double> X(model_.n_global());
    model_.straight_line(towPoint, vec(p.initialDirection), X.data());
    const bool profile = profileApplies_ && profile_guess(X.data());
    if (far_end_held_at_start() && !profile) {
        // Chord from the tow point to the far end, sagging in its vertical plane when the line is
        // slack (a parabola whose length is about the cable length).
        const Vec3 chord = farPoint - towPoint;
        const double D = chord.norm(), L = model_.line().length;
        Vec3 sagDirection = Vec3(0, 0, -1) - chord.normalized() * chord.normalized().z();
        if (sagDirection.norm() < 1e-6) sagDirection = Vec3(1, 0, 0);
        sagDirection.normalize();
        const double sag = D < L ? D * std::sqrt(0.375 * (L / D - 1.0)) : 0.0;
        for (int i = 0; i < model_.n_slots(); ++i) {
            const double xi = model_.slot_fraction(i);
            Eigen::Map<Vec3>(X.data() + 6 * i) = towPoint + xi * chord + 4.0 * sag * xi * (1.0 - xi) * sagDirection;
            const Vec3 drdxi = chord + 4.0 * sag * (1.0 - 2.0 * xi) * sagDirection;
            Eigen::Map<Vec3>(X.data() + 6 * i + 3) = drdxi.normalized() * std::max(D / L, 1.0);
        }
    }
    if (p.enableSeabed && !far_end_held_at_start()) {
        // A free end that reaches the seabed: the straight line bends there and trails along it
        // behind the tow (a line clamped to the seabed instead piles its end into one point, from
        // which the solver found folded equilibria).
        const Vec3 d = vec(p.initialDirection).normalized();
        Vec3 trail = -state_.tow.v();
        trail.z() = 0.0;
        if (trail.norm() < 1e-9) trail = Vec3(d.x(), d.y(), 0.0);
        if (trail.norm() < 1e-9) trail = Vec3(-1.0, 0.0, 0.0);
        trail.normalize();
        const double reach = d.z() < 0.0 ? (towPoint.z() + p.waterDepth) / -d.z() : INFINITY;
        for (int i = 0; i < model_.n_slots(); ++i) {
            const double s = model_.slot_arc_length(i);
            if (s <= reach) continue;
            Eigen::Map<Vec3>(X.data() + 6 * i) = towPoint + reach * d + (s - reach) * trail;
            Eigen::Map<Vec3>(X.data() + 6 * i + 3) = trail;
        }
    }
    if (p.enableSeabed) {
        // Start on or above the seabed: the guessed line lies on it where it would pass below.
        for (int i = 0; i < model_.n_slots(); ++i) X[6 * i + 2] = std::max(X[6 * i + 2], -p.waterDepth);
    }
    model_.restrict_to_free(X.data(), q.data());
    return profile;
}

double CableSimulation::cable_torque(const UCInputs& in) {
    const UCParams& p = model_.params();
    if (!p.enableTorsion || p.torqueMode == UC_TORQUE_FREE) return 0.0;
    if (p.torqueMode == UC_TORQUE_PRESCRIBED) return in.torque;
    // Mode 2: H = GJ (Phi - beta) / L with beta from the current shape, unwrapped continuously.
    free_state(q_, v_, a_);
    model_.expand(q_.data(), v_.data(), a_.data(), loads_, state_.time, X_.data(), Xd_.data(), Xdd_.data());
    const double raw = geometric_twist(model_, X_.data(), state_.twistRef);
    const double kTwoPi = 6.28318530717958647692;
    state_.lastBeta += std::remainder(raw - state_.lastBeta, kTwoPi);
    return model_.torque_for_twist(in.twist - state_.lastBeta);
}

bool CableSimulation::check_geometry(const Vec3& farPoint, std::string& error) const {
    const UCParams& p = model_.params();
    char buffer[600];
    const char* farName = p.bottomEnd == UC_BOTTOM_ANCHORED ? "anchor.x/y/z" : "end.x/y/z";
    if (model_.far_end_prescribed()) {
        const Vec3 d = farPoint - state_.tow.p();
        const double reach = 1.1 * model_.line().length;
        if (d.norm() > reach) {
            if (p.lineFile[0] != '\0') {
                // A deck's points are where its author put them: the line's length is what is short.
                std::snprintf(buffer, sizeof buffer,
                              "the line is too short for where its ends are: %.6g m unstretched (the deck's "
                              "UnstrLen), its far end (%.6g, %.6g, %.6g) is %.6g m from the tow point (%.6g, %.6g, "
                              "%.6g), a stretch of %.3g %%, more than the 10 %% any cable survives; lengthen the "
                              "line to at least %.6g m or bring its ends within %.6g m of each other",
                              model_.line().length, farPoint.x(), farPoint.y(), farPoint.z(), d.norm(),
                              state_.tow.p().x(), state_.tow.p().y(), state_.tow.p().z(),
                              100.0 * (d.norm() / model_.line().length - 1.0), d.norm() / 1.1, reach);
            } else {
                // Name the coordinate that is farthest off, with the range the others leave it, and the
                // length the line would need where the anchor is meant to be there.
                int k = 0;
                d.cwiseAbs().maxCoeff(&k);
                const double others = d.squaredNorm() - d[k] * d[k];
                const double half = std::sqrt(std::max(0.0, reach * reach - others));
                const char* prefix = p.bottomEnd == UC_BOTTOM_ANCHORED ? "anchor" : "end";
                std::snprintf(buffer, sizeof buffer,
                              "%s.%c = %.17g is outside [%.6g, %.6g]: the far end must lie within the reach of the "
                              "stretched cable, 1.1 x length = %.6g m from the tow point (it is %.6g m away; more "
                              "than 10 %% strain, which no cable survives); or the line is too short: %s = %.6g m, "
                              "at least %.6g m reaches it",
                              prefix, "xyz"[k], farPoint[k], state_.tow.p()[k] - half, state_.tow.p()[k] + half, reach,
                              d.norm(), p.nSections > 1 ? "the sections' length" : "length", model_.line().length,
                              d.norm() / 1.1);
            }
            error = buffer;
            return false;
        }
    }
    if (!p.enableSeabed) return true;
    const double tolerance = 0.5 * model_.line().diameter;  // a point resting on the seabed sinks in slightly
    if (state_.tow.p().z() < -p.waterDepth - tolerance) {
        std::snprintf(buffer, sizeof buffer,
                      "tow.z = %.6g m is below the seabed at z = -waterDepth = %.6g m: the tow point must be in the water",
                      state_.tow.p().z(), -p.waterDepth);
        error = buffer;
        return false;
    }
    if (model_.far_end_prescribed() && farPoint.z() < -p.waterDepth - tolerance) {
        std::snprintf(buffer, sizeof buffer,
                      "%s: z = %.6g m is below the seabed at z = -waterDepth = %.6g m: an anchor lies on the seabed, "
                      "not under it",
                      farName, farPoint.z(), -p.waterDepth);
        error = buffer;
        return false;
    }
    return true;
}

namespace {

// "<EA's name> = <EA> N<where>: <what>, <why>; <cause>": a strain no line of that EA should have, and the
// unit EA was likely meant in (the factor of 1e3, 1e6 or 1e9 that brings the strain below a percent).
std::string strain_message(const CableModel& model, int section, double strain, const std::string& what,
                           const char* why) {
    const UCParams& p = model.params();
    const double EA = model.section(section).axial.EA;
    const std::string name = model.n_sections() > 1 ? "section[" + std::to_string(section + 1) + "].EA" : "EA";
    const std::string where = p.lineFile[0] != '\0' && model.n_sections() > 1
                                  ? " (the deck's line " + std::to_string(section + 1) + " from the fairlead)"
                                  : "";
    std::string cause = "; check EA, its unit and the line's weight";
    for (const auto& [factor, unit] : {std::pair<double, const char*>{1e3, "kN"}, {1e6, "MN"}, {1e9, "GN"}}) {
        if (strain / factor < 0.01) {
            char text[200];
            std::snprintf(text, sizeof text, ": did you mean %.6g %s (%.6g N)?", EA, unit, EA * factor);
            cause = text;
            break;
        }
    }
    char head[200];
    std::snprintf(head, sizeof head, "%s = %.6g N%s: ", name.c_str(), EA, where.c_str());
    return head + what + ", " + why + cause;
}

int section_index(const CableModel& model, const SectionProps& section) {
    for (int k = 0; k < model.n_sections(); ++k)
        if (&model.section(k) == &section) return k;
    return 0;
}

}  // namespace

void CableSimulation::add_event(const std::string& text) {
    event_ = event_.empty() ? text : event_ + "; " + text;
}

bool CableSimulation::check_weight_strain(std::string& error) const {
    // The line's whole weight in water over a section's EA: a tension the line may carry (all of it
    // hanging), so a strain it may reach; beyond 100 % no line of that EA carries its own weight.
    double weight = 0.0;
    for (int k = 0; k < model_.n_sections(); ++k)
        weight += std::abs(submerged_weight(model_.section(k).fluid)) * model_.section(k).length;
    for (int k = 0; k < model_.n_sections(); ++k) {
        const double strain = weight / model_.section(k).axial.EA;
        if (!(strain > kWeightStrainRefused)) continue;
        char what[200];
        std::snprintf(what, sizeof what, "the line's weight in water (%.6g N) would stretch it %.3g %%", weight,
                      100.0 * strain);
        error = strain_message(model_, k, strain, what, "far beyond what any cable, chain or rope stretches");
        return false;
    }
    return true;
}

bool CableSimulation::check_static_strain(std::string& error) {
    // Each element's mean strain from its chord (at most its arc: a curved element's is underestimated,
    // never over): the nodes' tangents carry the element's bending too, and are no measure of it.
    double worst = 0.0;
    int worstElement = -1;
    for (int e = 0; e < model_.n_elements(); ++e) {
        const int g = model_.element_offset(e);
        const double chord = (Eigen::Map<const Vec3>(X_.data() + g + 6) - Eigen::Map<const Vec3>(X_.data() + g)).norm();
        const double strain = chord / model_.element_length(e) - 1.0;
        if (strain > worst) {
            worst = strain;
            worstElement = e;
        }
    }
    if (worstElement < 0 || !(worst > kStrainWarned)) return true;
    const SectionProps& section = model_.element_section(worstElement);
    const bool refuse = worst > kStrainRefused;
    char what[200];
    std::snprintf(what, sizeof what, "the line stretches %.3g %% at rest (%.6g N of tension over %.6g to %.6g m)",
                  100.0 * worst, section.axial.EA * worst, model_.element_start(worstElement),
                  model_.element_start(worstElement) + model_.element_length(worstElement));
    const std::string text =
        strain_message(model_, section_index(model_, section), worst, what,
                       refuse ? "more than any cable, chain or rope stretches before it breaks (nylon, the most "
                                "extensible, at about 25 %); refusing the start"
                              : "more than steel wire or chain stretches before it breaks (about 3 %)");
    if (refuse) {
        error = text;
        return false;
    }
    add_event("warning: " + text);
    return true;
}

// A line without bending stiffness that is longer than the way down to the seabed and across to
// its anchor rests on a frictionless seabed with no tension at all, in no one shape: refused with
// the lengths that would give it one.
bool CableSimulation::statics_applies(const Vec3& farPoint, std::string& error) const {
    if (!profileApplies_ || model_.line().EI > 0.0 || profile_.solved || profile_.why != "longer than the way down and across")
        return true;
    const Vec3 d = state_.tow.p() - farPoint;
    const double X = std::hypot(d.x(), d.y()), h = std::abs(d.z()), L = model_.line().length;
    char text[600];
    std::snprintf(text, sizeof text,
                  "no static equilibrium: the line (%.6g m unstretched) is longer than the way down to the seabed "
                  "and across to the far end (%.6g m + %.6g m = %.6g m), so on a frictionless seabed it rests with no "
                  "tension and in no one shape; shorten it below %.6g m or move the far end more than %.6g m away "
                  "horizontally",
                  L, h, X, h + X, h + X, L - h);
    error = text;
    return false;
}

// The static state is checked before it is given out (docs/model.md, "Initial equilibrium"): no
// element folded back on itself, the anchor's force its axial tension (without bending stiffness),
// and where the line's static profile is exact (no bending stiffness or a bending length under a
// thousandth of the line, no current, calm water, at rest) the fairlead and anchor tensions within
// 1 % of it.
bool CableSimulation::verify_statics(std::string& error) const {
    char text[700];
    for (int e = 0; e < model_.n_elements(); ++e) {
        const int g = model_.element_offset(e);
        const double chord = (Eigen::Map<const Vec3>(X_.data() + g + 6) - Eigen::Map<const Vec3>(X_.data() + g)).norm();
        if (chord < 0.5 * model_.element_length(e)) {
            std::snprintf(text, sizeof text,
                          "the static equilibrium found is folded: element %d (arc length %.6g to %.6g m) spans %.3g m "
                          "for %.3g m of cable; refusing it as a start",
                          e + 1, model_.element_start(e), model_.element_start(e) + model_.element_length(e), chord,
                          model_.element_length(e));
            error = text;
            return false;
        }
    }
    const UCParams& p = model_.params();
    const double axial = state_.outputs.tension[UC_NUM_STATIONS - 1];
    if (p.bottomEnd == UC_BOTTOM_ANCHORED && model_.line().EI == 0.0 &&
        std::abs(state_.outputs.endTension - axial) > kAnchorCheck * state_.outputs.endTension) {
        // Without bending stiffness the line's force on its anchor is its axial tension there: where
        // the two differ, the elements at the anchor do not hold the line's shape.
        std::snprintf(text, sizeof text,
                      "the static equilibrium found does not hold together at the anchor: the force on the anchor "
                      "(%.6g N) and the line's axial tension there (%.6g N) differ by %.2f %%; refusing it as a "
                      "start (the mesh does not resolve the line near its anchor)",
                      state_.outputs.endTension, axial, 100.0 * std::abs(state_.outputs.endTension - axial) / state_.outputs.endTension);
        error = text;
        return false;
    }
    const LineProfile& profile = profile_.profile;
    const bool towOnTop = profile_.towOnTop;
    // Bending stiffness acts over the bending length sqrt(EI / T) at the ends and the touchdown; where
    // that is a thousandth of the line at its smallest tension, the catenary holds its end tensions
    // far inside the check (a chain's nominal EI; the stiff power cable's 2e4 N m² moves them 1e-4).
    const double leastTension = profile_.solved ? std::min(profile.top_force().norm(), profile.bottom_force().norm()) : 0.0;
    const bool weakBending = model_.line().EI == 0.0 ||
                             (leastTension > 0.0 && std::sqrt(model_.line().EI / leastTension) <=
                                                        kWeakBending * model_.line().length);
    const bool exact = profileApplies_ && weakBending && loads_.current.uniform.isZero(0.0) &&
                       (p.currentProfileRows == 0 || loads_.current.scale == 0.0) && model_.sea().calm() &&
                       loads_.torque == 0.0 && profile_.solved &&
                       profile.lowest_clearance() > -model_.line().diameter;
    if (!exact) return true;
    const double top = (towOnTop ? profile.top_force() : profile.bottom_force()).norm();
    const double bottom = (towOnTop ? profile.bottom_force() : profile.top_force()).norm();
    const double topError = state_.outputs.towTension / top - 1.0, bottomError = state_.outputs.endTension / bottom - 1.0;
    if (std::abs(topError) <= kStaticsCheck && std::abs(bottomError) <= kStaticsCheck) return true;
    std::snprintf(text, sizeof text,
                  "the static equilibrium found differs from the line's elastic catenary, which is exact for it: "
                  "tension %.6g N at the tow point and %.6g N at the far end against %.6g N and %.6g N (%+.2f %% and "
                  "%+.2f %%); refusing a wrong start",
                  state_.outputs.towTension, state_.outputs.endTension, top, bottom, 100.0 * topError, 100.0 * bottomError);
    error = text;
    return false;
}

std::string CableSimulation::mesh_advice(double t0, const UCInputs& in) const {
    const UCParams& p = model_.params();
    const bool sections = p.nSections > 1;
    // The same line with each section's elements as `count` gives them; true with the advice where it
    // starts. Out of the parameters' range: `beyond`.
    auto trial_starts = [&](auto&& count, const std::string& named, std::string& advice, bool& beyond) {
        UCParams q = p;
        if (sections) {
            for (int k = 0; k < p.nSections; ++k) q.section[k].nElements = count(p.section[k].nElements);
        } else {
            q.nElements = count(p.nElements);
        }
        beyond = !check_params(q).empty();
        if (beyond) return false;
        CableSimulation trial(q);
        trial.adviseMesh_ = false;
        std::string ignored;
        if (!trial.initialize(t0, in, ignored)) return false;
        std::string counts = named;
        if (counts.empty() && sections) {
            for (int k = 0; k < p.nSections; ++k)
                counts += (k ? ", " : "") + std::string("section[") + std::to_string(k + 1) +
                          "].nElements = " + std::to_string(q.section[k].nElements);
        } else if (counts.empty()) {
            counts = "nElements = " + std::to_string(q.nElements);
        }
        char text[300];
        std::snprintf(text, sizeof text, "; with %s the same line starts (tow tension %.6g N, far end %.6g N)",
                      counts.c_str(), trial.state_.outputs.towTension, trial.state_.outputs.endTension);
        advice = text;
        return true;
    };
    std::string advice;
    bool beyond = false;
    if (p.lineFile[0] != '\0') {
        // A deck's line: lineFileElements gives every deck line (section) the same count. More
        // elements resolve a sharp touchdown; fewer can settle a short, very stiff line whose
        // elements are far stiffer in bending than its weight can bend.
        int n = p.nElements;
        if (sections)
            for (int k = 0; k < p.nSections; ++k) n = std::max(n, p.section[k].nElements);
        for (int count : {2 * n, 4 * n, 8 * n, 16 * n, n / 2, 1}) {
            if (count < 1 || count == n) continue;
            if (trial_starts([count](int) { return count; }, "lineFileElements = " + std::to_string(count), advice,
                             beyond))
                return advice;
        }
        return "; neither more nor fewer elements (lineFileElements) resolve the line";
    }
    for (int factor : {2, 4}) {
        if (trial_starts([factor](int elements) { return factor * elements; }, "", advice, beyond)) return advice;
        if (beyond) break;  // beyond the elements a line may have
    }
    return std::string("; neither twice nor four times the elements (") +
           (sections ? "section[k].nElements" : "nElements") +
           ") resolve the line: initMode = 1 starts from the guessed shape without equilibrium";
}

bool CableSimulation::initialize(double t0, const UCInputs& in, std::string& error) {
    ++stateStamp_;  // the cached interface derivatives are stale from here on
    const UCParams& p = model_.params();
    for (double v : {in.tow[0], in.tow[1], in.tow[2], in.towVelocity[0], in.towVelocity[1], in.towVelocity[2],
                     in.towAcceleration[0], in.towAcceleration[1], in.towAcceleration[2], in.endLoad[0],
                     in.endLoad[1], in.endLoad[2], in.endCouple[0], in.endCouple[1], in.endCouple[2],
                     in.current[0], in.current[1], in.end[0], in.end[1], in.end[2], in.endVelocity[0],
                     in.endVelocity[1], in.endVelocity[2]}) {
        if (!std::isfinite(v)) {
            error = "inputs must be finite numbers";
            return false;
        }
    }
    if (!end_load_linearization_finite(in)) {
        error = "endLoadVelocity and endLoadDamping inputs must be finite numbers";
        return false;
    }
    set_environment(in);
    loads_.current.rate.setZero();  // a current that changes within a step comes with the steps
    loads_.current.scaleRate = 0.0;
    if (!std::isfinite(in.currentScale)) {
        error = "currentScale must be a finite number";
        return false;
    }
    loads_.current.time = t0;
    if (model_.winch()) {  // the run starts at the line's own length, every element nominal
        const WinchMesh start{model_.params().nSections <= 1 ? model_.params().nElements
                                                             : model_.params().section[0].nElements,
                              model_.winch_nominal()};
        if (model_.winch_mesh().elements != start.elements || model_.winch_mesh().topLength != start.topLength)
            rebuild(start);
        state_.winchRate = 0.0;
        state_.winchStep = WinchStep::hold(0.0);
        state_.winchTop0 = start.topLength;
        state_.winchLimit = 0;
        state_.winchRateLimited = false;
        model_.set_top_length(state_.winchTop0);
        state_.winchLength = model_.line().length;
    }
    state_.tow.reset(vec(in.tow), vec(in.towVelocity), vec(in.towAcceleration), in.towAccelerationGiven != 0);
    loads_.tow = TowTrajectory::at_rest_in_time(state_.tow.p(), state_.tow.v(), state_.tow.a(), t0);
    state_.end.reset(vec(in.end), vec(in.endVelocity), Vec3::Zero(), false);
    loads_.end = TowTrajectory::at_rest_in_time(state_.end.p(), state_.end.v(), state_.end.a(), t0);
    const bool proxy = p.bottomEnd == UC_BOTTOM_PROXY;
    Vec3 farPoint = p.bottomEnd == UC_BOTTOM_EXTERNAL || proxy ? state_.end.p() : vec(p.anchor);
    state_.proxy = ProxyEstimate();
    loads_.endSpring = 0.0;
    if (!check_geometry(farPoint, error)) return false;
    if (!check_weight_strain(error)) return false;
    // An anchored line, or one whose far end is held at rest, starts from its static profile.
    profileApplies_ = p.bottomEnd == UC_BOTTOM_ANCHORED ||
                      (p.bottomEnd == UC_BOTTOM_EXTERNAL && state_.end.v().isZero(0.0));
    if (!std::isfinite(in.torque) || !std::isfinite(in.twist)) {
        error = "torque and twist inputs must be finite numbers";
        return false;
    }
    const Vec3 givenFar = farPoint;
    // The line at rest on the mesh the grading-th of kGradings places (where the mesh is graded):
    // false with the reason, `retry` where the static solve or its check failed.
    bool retry = false;
    auto start = [&](int grading) {
        retry = false;
        farPoint = givenFar;
        grade_mesh(state_.tow.p(), farPoint, profileApplies_, grading);
        if (p.bottomEnd == UC_BOTTOM_ANCHORED) farPoint = model_.anchor();  // on the seabed: where the line rests
        const int n = model_.n_free();
        const bool fromProfile = initial_guess(state_.tow.p(), farPoint, q_);
        {
            // Twist reference frames from the initial guess (planar: no geometric twist).
            std::vector<double> zero(n, 0.0);
            model_.expand(q_.data(), zero.data(), zero.data(), loads_, t0, X_.data(), Xd_.data(), Xdd_.data());
            state_.twistRef = make_twist_reference(model_, X_.data());
            state_.lastBeta = 0.0;
            const UCParams& pp = model_.params();
            loads_.torque = !pp.enableTorsion ? 0.0
                            : pp.torqueMode == UC_TORQUE_PRESCRIBED ? in.torque
                            : pp.torqueMode == UC_TORQUE_ROTATION   ? model_.torque_for_twist(in.twist)
                                                                    : 0.0;
        }
        std::vector<double> v(n, 0.0);
        // A steady tow only when nothing holds the far end back: free end, internal body, or an
        // external end moving with the tow point. Otherwise the equilibrium is at rest.
        const bool steadyTow = p.bottomEnd == UC_BOTTOM_FREE || p.bottomEnd == UC_BOTTOM_TOWED_BODY ||
                               ((p.bottomEnd == UC_BOTTOM_EXTERNAL || proxy) && (state_.end.v() - state_.tow.v()).norm() <= 1e-12);
        if (p.initMode == UC_INIT_EQUILIBRIUM && steadyTow) {
            // Steady tow: every node moves with the tow point, tangents do not turn.
            for (int g = 0; g < model_.n_global(); ++g) {
                const int j = model_.free_index(g);
                if (j >= 0 && g % 6 < 3) v[j] = state_.tow.v()[g % 6];
            }
        }
        if (p.initMode == UC_INIT_EQUILIBRIUM && !statics_applies(farPoint, error)) return false;
        if (p.initMode == UC_INIT_EQUILIBRIUM && proxy) {
            if (!proxy_statics(t0, v, fromProfile, error)) return false;
        } else if (p.initMode == UC_INIT_EQUILIBRIUM) {
            const StaticsResult statics = solve_static_equilibrium(model_, *staticSolver_, loads_, t0, v, q_, fromProfile);
            if (!statics.converged) {
                error = statics.message;
                retry = true;
                return false;
            }
        }
        if (!solve_consistent_acceleration(model_, *staticSolver_, loads_, t0, q_, v, a_)) {
            error = "the mass matrix is singular: check massPerLength and the end conditions";
            return false;
        }
        for (int j = 0; j < n; ++j) {
            y_[2 * (j + off_)] = q_[j];
            y_[2 * (j + off_) + 1] = v[j];
            yp_[2 * (j + off_)] = v[j];
            yp_[2 * (j + off_) + 1] = a_[j];
        }
        if (off_) {
            y_[0] = model_.top_length();
            winchTension_ = in.winchTension;
            winchTopAtStep_ = y_[0];
        }
        state_.time = t0;
        state_.lastStepSize = 0.0;
        state_.statsBase = IntegratorStats();
        state_.integratorStarted = false;
        state_.restartPending = true;
        state_.compressionWarned = false;
        state_.rainflow.reset();
        update_outputs();
        if (p.initMode == UC_INIT_EQUILIBRIUM && !verify_statics(error)) {
            retry = true;
            return false;
        }
        return true;
    };
    // A graded mesh whose equilibrium fails is graded again by the other gradings, with the same
    // elements (docs/model.md, "Initial equilibrium"); the refusal gives the first grading's reason.
    std::string firstError;
    for (int grading = 0; !start(grading); ++grading) {
        if (grading == 0) firstError = error;
        if (!retry || !state_.graded || layout_.nodes.empty() || grading + 1 == kGradingCount) {
            if (grading > 0) {
                error = firstError;
                grade_mesh(state_.tow.p(), givenFar, profileApplies_, 0);
            }
            if (retry && adviseMesh_) error += mesh_advice(t0, in);
            return false;
        }
    }
    if (p.initMode == UC_INIT_EQUILIBRIUM && !check_static_strain(error)) return false;
    if (off_) {  // consistent: the winch runs at the rate of the initial tension
        double R[12];
        model_.element_residual(0, X_.data(), Xd_.data(), Xdd_.data(), loads_, R);
        y_[1] = yp_[0] = tension_winch_rate(line_tension(R), y_[0], nullptr);
        yp_[1] = 0.0;
        state_.winchRate = y_[1];
    }
    if (sn_.area > 0.0) state_.rainflow.add(state_.outputs.towTension, sn_);
    if (proxy) proxy_output(0.0, Vec3::Zero(), Vec3::Zero(), in);
    state_.outputs.towTensionMax = state_.outputs.towTensionMin = state_.outputs.towTension;
    state_.tensionScale = tension_scale(model_, state_.outputs);
    if (!set_integrator_tolerances(error)) return false;
    state_.outputs.tensionScale = state_.tensionScale;
    return true;
}

void CableSimulation::step_completed(double t, const double* y, const double* yp) {
    expand_integrator_state(t, y, yp);
    double R[12];
    model_.element_residual(0, X_.data(), Xd_.data(), Xdd_.data(), loads_, R);
    const double tension = std::sqrt(R[0] * R[0] + R[1] * R[1] + R[2] * R[2]);
    stepTensionMax_ = std::max(stepTensionMax_, tension);
    stepTensionMin_ = std::min(stepTensionMin_, tension);
    if (sn_.area > 0.0) state_.rainflow.add(tension, sn_);
}

bool CableSimulation::step(double /*t*/, double h, const UCInputs& in, std::string& error) {
    ++stateStamp_;  // the cached interface derivatives are stale from here on
    for (double v : {in.tow[0], in.tow[1], in.tow[2], in.towVelocity[0], in.towVelocity[1], in.towVelocity[2],
                     in.towAcceleration[0], in.towAcceleration[1], in.towAcceleration[2], in.endLoad[0],
                     in.endLoad[1], in.endLoad[2], in.endCouple[0], in.endCouple[1], in.endCouple[2],
                     in.current[0], in.current[1], in.end[0], in.end[1], in.end[2], in.endVelocity[0],
                     in.endVelocity[1], in.endVelocity[2], h}) {
        if (!std::isfinite(v)) {
            error = "inputs and the step size must be finite numbers";
            return false;
        }
    }
    if (!end_load_linearization_finite(in)) {
        error = "endLoadVelocity and endLoadDamping inputs must be finite numbers";
        return false;
    }
    if (!(h >= UC_MIN_STEP_SIZE) || !(state_.time + h > state_.time)) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "the communication step size %.17g s is below %g s or does not advance the time t = %.17g s",
                      h, UC_MIN_STEP_SIZE, state_.time);
        error = text;
        return false;
    }
    const double winchLengthAtStart = state_.winchLength, winchRateAtStart = state_.winchRate;
    const double winchTop0AtStart = state_.winchTop0;
    set_environment(in);
    loads_.current.rate = Vec3(in.currentRate[0], in.currentRate[1], 0.0);
    loads_.current.rateStart = state_.time;
    loads_.current.scaleRate = in.currentScaleRate;
    if (!std::isfinite(in.currentScale) || !std::isfinite(in.currentScaleRate)) {
        error = "currentScale and its input derivative must be finite numbers";
        return false;
    }
    if (!loads_.current.rate.allFinite()) {
        error = "the input derivatives of current.x/y must be finite numbers";
        return false;
    }
    if (model_.winch()) {
        // A remesh happens at state_.time and must see nothing but the state there (a state restored into
        // a fresh instance has no previous step): the driven ends where they stand, the environment
        // of this step's inputs.
        loads_.tow = TowTrajectory::at_rest_in_time(state_.tow.p(), state_.tow.v(), state_.tow.a(), state_.time);
        loads_.end = TowTrajectory::at_rest_in_time(state_.end.p(), state_.end.v(), state_.end.a(), state_.time);
    }
    if (!std::isfinite(in.torque) || !std::isfinite(in.twist)) {
        error = "torque and twist inputs must be finite numbers";
        return false;
    }
    if (model_.winch()) {
        loads_.torque = cable_torque(in);
        set_winch_time(state_.time);
        if (!winch_rate(in, h, error)) return false;
        // how much the top element changes over the step (the constant-tension winch: at worst twice
        // its present haul-in rate)
        const double change = off_ ? std::min(0.0, 2.0 * y_[1] * h) : state_.winchStep.length(h);
        const int elements = model_.n_elements();
        if (!remesh(change, error)) return false;
        if (!off_ && state_.winchStep.rate0 != winchRateAtStart && elements == model_.n_elements()) {
            // The rate jumps here: the material at the sheave takes the new speed at once (an axial
            // wave). The accelerations of that state, and a restart, as after any discontinuity.
            set_winch_time(state_.time);
            free_state(q_, v_, a_);
            if (!restart_from(error)) return false;
        }
    }
    // Each driven end follows a quintic in time from where the previous step left it (position,
    // velocity and acceleration: it never jumps) to the master's inputs extrapolated to t + h.
    const Vec3 towVelocityInput = vec(in.towVelocity), endVelocityInput = vec(in.endVelocity);
    Vec3 towAcceleration, endAcceleration;
    loads_.tow = state_.tow.next(state_.time, h, state_.lastStepSize, vec(in.tow), towVelocityInput, vec(in.towAcceleration),
                           in.towAccelerationGiven, towAcceleration);
    const bool externalEnd = model_.params().bottomEnd == UC_BOTTOM_EXTERNAL;
    if (externalEnd) {
        loads_.end = state_.end.next(state_.time, h, state_.lastStepSize, vec(in.end), endVelocityInput, vec(in.endAcceleration),
                               in.endAccelerationGiven, endAcceleration);
    }
    loads_.torque = cable_torque(in);

    if (state_.restartPending) {
        state_.statsBase = total_stats();
        if (!integrator_->restart(state_.time, y_.data(), yp_.data(), error)) return false;
        state_.integratorStarted = true;
        state_.restartPending = false;
    }
    const double tEnd = state_.time + h;
    const Vec3 proxyPosition = vec(state_.outputs.endPosition), proxyVelocity = vec(state_.outputs.endVelocity);
    stepTensionMax_ = stepTensionMin_ = state_.outputs.towTension;  // the tension at the step's start
    const RainflowCounter rainflowAtStart = state_.rainflow;
    winchTension_ = in.winchTension;
    const double topAtStart = model_.winch() ? model_.top_length() : 0.0;
    winchTopAtStep_ = topAtStart;
    if (!integrator_->advance(tEnd, error, in.stepBudget)) {
        state_.rainflow = rainflowAtStart;  // the state stays at the last communication point
        state_.restartPending = true;  // the state stays at the last communication point
        state_.winchLength = winchLengthAtStart;
        state_.winchRate = winchRateAtStart;
        state_.winchTop0 = winchTop0AtStart;
        state_.winchStep = WinchStep::hold(state_.winchRate);
        return false;
    }
    if (off_) {  // the constant-tension winch: its unknowns at the end of the step
        const double* end = integrator_->y();
        state_.winchRate = end[1];
        state_.winchTop0 = end[0];
        state_.winchLength = winchLengthAtStart + (end[0] - topAtStart);
    } else if (model_.winch()) {  // the length and the drum's rate at the end of the step
        const double topAtEnd = state_.winchTop0 + state_.winchStep.length(h);
        state_.winchLength = winchLengthAtStart + (topAtEnd - topAtStart);
        state_.winchTop0 = topAtEnd;
        state_.winchRate = state_.winchStep.rate1;
        state_.winchStep = WinchStep::hold(state_.winchRate);
    }
    const double* y = integrator_->y();
    const double* yp = integrator_->yp();
    for (size_t i = 0; i < y_.size(); ++i) {
        y_[i] = y[i];
        yp_[i] = yp[i];
    }
    state_.time = tEnd;
    state_.tow.advance(loads_.tow, towVelocityInput, towAcceleration, in.towAccelerationGiven != 0);
    if (externalEnd) state_.end.advance(loads_.end, endVelocityInput, endAcceleration, in.endAccelerationGiven != 0);
    state_.lastStepSize = h;
    update_outputs();
    if (model_.params().bottomEnd == UC_BOTTOM_PROXY) proxy_output(h, proxyPosition, proxyVelocity, in);
    state_.outputs.towTensionMax = std::max(stepTensionMax_, state_.outputs.towTension);
    state_.outputs.towTensionMin = std::min(stepTensionMin_, state_.outputs.towTension);
    warn_of_compression();
    return true;
}

// The two-sided axial law pushes with the full EA where a cable buckles or goes slack: the first
// time the line carries more compression than an element of it can before buckling (Euler, pinned
// over one element; and more than 1e-3 of the tension scale), the run says so once, with the law to
// use (docs/robustness.md: the slack-snap case peaks at 95 kN two-sided and 406 kN tension-only).
void CableSimulation::warn_of_compression() {
    const UCParams& p = model_.params();
    if (!p.enableCompression || state_.compressionWarned || !(state_.outputs.minTension < -1e-3 * state_.tensionScale)) return;
    double buckling = INFINITY;  // only where there is compression to judge
    for (int e = 0; e < model_.n_elements(); ++e) {
        const double l = model_.element_length(e);
        buckling = std::min(buckling, 9.8696044010893586 * model_.element_section(e).EI / (l * l));
    }
    const double limit = std::max(buckling, 1e-3 * state_.tensionScale);
    if (!(state_.outputs.minTension < -limit)) return;
    state_.compressionWarned = true;
    char text[400];
    std::snprintf(text, sizeof text,
                  "warning: at t = %.6g s the line carries %.4g N of axial compression (minTension), more than an "
                  "element of it carries before buckling (%.4g N): the two-sided axial law (enableCompression = "
                  "true) pushes where a cable goes slack; a line that can go slack wants enableCompression = false",
                  state_.time, -state_.outputs.minTension, buckling);
    add_event(text);
}

// The integrator's absolute tolerance of each unknown from the physical ones. A local error of
// tensionTolerance x the tension scale in tension is a strain error eps = that / EA: eps x the
// element length in a node position, eps in a tangent; positionTolerance bounds a node position,
// and over the element length a tangent (an angle); the smaller of the two counts. A velocity
// error delta / tau makes as large an error in the cable's internal damping force as a position
// error delta makes in its elastic force (tau = axialDamping / EA, the Kelvin-Voigt time
// constant), so velocities get the position tolerances over tau, with tau at least the time an
// axial wave takes along an element (the shortest time scale the mesh resolves). IDA tests the
// root mean square of the weighted local errors of all 2n unknowns, which a single unknown can
// exceed sqrt(2n) times: the tolerances are divided by sqrt(2n), so that each unknown meets its own.
CableSimulation::ElementScales CableSimulation::element_scales(int e, double rms) const {
    const SectionProps& section = model_.element_section(e);
    // the winch's top element changes length: its tolerances are those of a nominal element, so
    // that they depend on the mesh only (a restored state gets the ones it was integrated with)
    const double l = e == 0 && model_.winch() ? model_.winch_nominal() : model_.element_length(e);
    const double EA = section.axial.EA;
    const double wave = l / std::sqrt(EA / section.fluid.massPerLength);
    return {l, rms * model_.params().tensionTolerance * state_.tensionScale / EA, std::max(section.axial.damping / EA, wave)};
}

bool CableSimulation::set_integrator_tolerances(std::string& error) {
    const UCParams& p = model_.params();
    const double rms = 1.0 / std::sqrt(2.0 * unknowns());
    std::vector<double>& atol = toleranceBuffer_;
    atol.assign(2 * unknowns(), INFINITY);
    // relTol |y| counts |y| at least at the unknown's scale: the line's length for a node position
    // (and the winch's length), 1 for a tangent, these over tau for their rates, which pass through 0
    std::vector<double> magnitude(2 * unknowns(), 0.0);
    const double lineScale = model_.line().length;
    // Each unknown gets the tolerance of the elements it belongs to (the smaller one at a node
    // between two sections).
    for (int e = 0; e < model_.n_elements(); ++e) {
        const ElementScales scales = element_scales(e, rms);
        const double l = scales.length, strain = scales.strain, tau = scales.tau;
        for (int k = 0; k < 12; ++k) {
            const int m = model_.free_index(model_.element_offset(e) + k);
            if (m < 0) continue;
            const int j = m + off_;
            const bool position = k % 6 < 3;
            const double a = position ? std::min(rms * p.positionTolerance, strain * l)
                                      : std::min(rms * p.positionTolerance / l, strain);
            atol[2 * j] = std::min(atol[2 * j], a);
            atol[2 * j + 1] = std::min(atol[2 * j + 1], a / tau);
            const double y = position ? lineScale : 1.0;
            magnitude[2 * j] = std::max(magnitude[2 * j], y);
            magnitude[2 * j + 1] = std::max(magnitude[2 * j + 1], y / tau);
            // the winch's length and rate: those of the top element's positions
            if (off_ && e == 0 && position) {
                atol[0] = std::min(atol[0], a);
                atol[1] = std::min(atol[1], a / tau);
                magnitude[0] = lineScale;
                magnitude[1] = std::max(magnitude[1], lineScale / tau);
            }
        }
    }
    if (!integrator_->set_tolerances(atol, p.relTol, p.absTol, error, &magnitude)) return false;
    if (!integrator_->set_max_order(p.solverMaxOrder, error)) return false;
    return integrator_->set_projected_tolerances(projected_blocks(), error);
}

std::vector<Integrator::ProjectedBlock> CableSimulation::projected_blocks() const {
    std::vector<Integrator::ProjectedBlock> blocks;
    const UCParams& p = model_.params();
    if (!p.projectedErrorControl) return blocks;
    const double rms = 1.0 / std::sqrt(2.0 * unknowns());
    // At each node whose tangent is free: along the tangent the tolerance of set_integrator_tolerances
    // (its length is 1 + strain), across it the position tolerance over the element length (its
    // direction turns, which strains nothing to first order); the smaller of the elements that share
    // the node. Node positions keep the componentwise test: projected too, the chain mooring's error
    // left the tolerance (docs/error_control.md).
    for (int e = 0; e < model_.n_elements(); ++e) {
        const ElementScales scales = element_scales(e, rms);
        const double l = scales.length, strain = scales.strain, tau = scales.tau;
        for (int node = 0; node < 2; ++node) {
            const int g = model_.element_offset(e) + 6 * node + 3;  // the node's tangent
            const int j = model_.free_index(g);
            if (j < 0 || model_.free_index(g + 1) != j + 1 || model_.free_index(g + 2) != j + 2) continue;
            Integrator::ProjectedBlock b;
            b.q = b.direction = j + off_;
            b.across = rms * p.positionTolerance / l;
            b.along = std::min(b.across, strain);
            b.alongRate = b.along / tau;
            b.acrossRate = b.across / tau;
            auto it = std::find_if(blocks.begin(), blocks.end(), [&](const Integrator::ProjectedBlock& o) { return o.q == b.q; });
            if (it == blocks.end()) {
                blocks.push_back(b);
            } else {
                it->along = std::min(it->along, b.along);
                it->across = std::min(it->across, b.across);
                it->alongRate = std::min(it->alongRate, b.alongRate);
                it->acrossRate = std::min(it->acrossRate, b.acrossRate);
            }
        }
    }
    return blocks;
}

void CableSimulation::expand_integrator_state(double t, const double* y, const double* yp) {
    loads_.current.time = t;
    if (off_) {
        model_.set_top_length(y[0]);
        model_.set_top_rate(y[1]);
    } else {
        set_winch_time(t);
    }
    const int n = model_.n_free();
    for (int j = 0; j < n; ++j) {
        q_[j] = y[2 * (j + off_)];
        v_[j] = y[2 * (j + off_) + 1];
        a_[j] = yp[2 * (j + off_) + 1];
    }
    model_.expand(q_.data(), v_.data(), a_.data(), loads_, t, X_.data(), Xd_.data(), Xdd_.data());
}

int CableSimulation::residual(double t, const double* y, const double* yp, double* r) {
    if (off_ && !(y[0] > 1e-6 * model_.winch_nominal())) return 1;  // no line left in the top element: retry
    expand_integrator_state(t, y, yp);
    const int n = model_.n_free();
    model_.residual(X_.data(), Xd_.data(), Xdd_.data(), loads_, R_.data(), nullptr);
    bool finite = true;
    for (int j = 0; j < n; ++j) {
        const int i = j + off_;
        r[2 * i] = yp[2 * i] - y[2 * i + 1];
        r[2 * i + 1] = R_[j];
        finite = finite && std::isfinite(R_[j]);
    }
    if (off_) {  // the winch: its length changes at its rate, the rate follows the tension
        double Re[12];
        model_.element_residual(0, X_.data(), Xd_.data(), Xdd_.data(), loads_, Re);
        const double tension = line_tension(Re);
        r[0] = yp[0] - y[1];
        // the drum follows the commanded rate with the lag winch.timeConstant (a drum has inertia)
        r[1] = model_.params().winchTimeConstant * yp[1] + y[1] - tension_winch_rate(tension, y[0], nullptr);
        finite = finite && std::isfinite(r[1]);
    }
    return finite ? 0 : 1;  // non-finite: recoverable, IDA retries with a smaller step
}

int CableSimulation::jacobian(double t, const double* y, const double* yp, const EntrySink& sink) {
    expand_integrator_state(t, y, yp);
    if (off_ == 0) {
        model_.jacobian(X_.data(), Xd_.data(), Xdd_.data(), loads_, sink);
        return 0;
    }
    auto shifted = [&](int i, int k, double dq, double dv, double da) { sink(i + 1, k + 1, dq, dv, da); };
    model_.jacobian(X_.data(), Xd_.data(), Xdd_.data(), loads_, shifted);
    // The winch's rows and columns: the top element's residual through its length, the winch's
    // rate (tau a + v = commanded rate) through the tow tension (the reaction at the tow point, rows 0..2 of the top element).
    double Re[12], Rp[12];
    model_.element_residual(0, X_.data(), Xd_.data(), Xdd_.data(), loads_, Re);
    Mat12 K, C, M;
    model_.element_jacobian(0, X_.data(), Xd_.data(), Xdd_.data(), loads_, K, C, M);
    const double top = y[0], delta = 1e-7 * std::max(top, 1.0);
    model_.set_top_length(top + delta);
    model_.element_residual(0, X_.data(), Xd_.data(), Xdd_.data(), loads_, Rp);
    model_.set_top_length(top);
    // T = -R_0..2 . t with t the unit tangent at the tow node (line_tension): dT = u . dR - R . dt
    const double tension = line_tension(Re);
    const Eigen::Map<const Vec3> tangent(X_.data() + 3);
    const Vec3 u = -tangent.normalized();
    const Vec3 dTdTangent = -(Eigen::Map<const Vec3>(Re) - u * u.dot(Eigen::Map<const Vec3>(Re))) / tangent.norm();
    double slope = 0.0;
    tension_winch_rate(tension, top, &slope);
    const int g0 = model_.element_offset(0);
    // the top element's residual through the winch's rate: the material's velocity (set_top_rate)
    const Vec12 dRdc = C * model_.top_rate_direction(X_.data() + g0);
    double dTdl = 0.0, dTdc = 0.0;
    for (int a = 0; a < 3; ++a) {
        dTdl += u[a] * (Rp[a] - Re[a]) / delta;
        dTdc += u[a] * dRdc[a];
    }
    for (int b = 0; b < 12; ++b) {
        const int j = model_.free_index(g0 + b);
        if (j < 0) continue;
        const double cb = model_.coefficient(g0 + b);
        double dK = 0.0, dC = 0.0, dM = 0.0;
        for (int a = 0; a < 3; ++a) {
            dK += u[a] * K(a, b);
            dC += u[a] * C(a, b);
            dM += u[a] * M(a, b);
        }
        if (b >= 3 && b < 6) dK += dTdTangent[b - 3];
        sink(0, j + 1, -slope * cb * dK, -slope * cb * dC, -slope * cb * dM);
        sink(j + 1, 0, cb * (Rp[b] - Re[b]) / delta, cb * dRdc[b], 0.0);
    }
    sink(0, 0, -slope * dTdl, 1.0 - slope * dTdc, model_.params().winchTimeConstant);
    return 0;
}

IntegratorStats CableSimulation::total_stats() const {
    return state_.integratorStarted ? state_.statsBase + integrator_->stats() : state_.statsBase;
}

std::string CableSimulation::take_event() {
    std::string event;
    event.swap(event_);
    return event;
}

void CableSimulation::set_winch_time(double t) {
    if (!model_.winch()) return;
    model_.set_top_length(off_ ? y_[0] : state_.winchTop0 + state_.winchStep.length(t - state_.time));
    model_.set_top_rate(off_ ? y_[1] : state_.winchStep.rate(t - state_.time));
}

WinchLimits CableSimulation::winch_limits() const {
    const UCParams& p = model_.params();
    return WinchLimits{p.winchMinLength, p.winchMaxLength, p.winchMaxRate, p.winchMaxAcceleration};
}

bool CableSimulation::winch_rate(const UCInputs& in, double h, std::string& error) {
    const UCParams& p = model_.params();
    for (const auto& [name, value] : {std::pair<const char*, double>{"winch.rate", in.winchRate},
                                      std::pair<const char*, double>{"winch.tension", in.winchTension}}) {
        if (std::isfinite(value)) continue;
        char text[160];
        std::snprintf(text, sizeof text, "%s = %g: the winch's inputs must be finite numbers", name, value);
        error = text;
        return false;
    }
    const WinchLimits limits = winch_limits();
    state_.winchTop0 = model_.top_length();
    if (p.winchMode == UC_WINCH_TENSION) return true;  // the rate follows the tension, step by step
    const double requested = in.winchRate;
    if (!std::isfinite(in.winchRateRate)) {
        char text[160];
        std::snprintf(text, sizeof text, "der(winch.rate) = %g m/s2: the input derivative must be a finite number",
                      in.winchRateRate);
        error = text;
        return false;
    }
    state_.winchStep = plan_winch_step(requested, state_.winchRate, state_.winchLength, h, limits, in.winchRateRate);
    // maxRate cut the command: log the arrival once.
    if (state_.winchStep.rateLimited && !state_.winchRateLimited) {
        char text[300];
        std::snprintf(text, sizeof text,
                      "winch: at t = %.6g s winch.rate %.6g m/s is beyond winch.maxRate = %.6g m/s: the drum runs at "
                      "most at winch.maxRate (deployed length %.6g m)",
                      state_.time, requested + in.winchRateRate * h, limits.maxRate, state_.winchLength);
        add_event(text);
    }
    state_.winchRateLimited = state_.winchStep.rateLimited;
    // A length limit cut the request (not the speed limit): log the arrival once.
    const int limit = state_.winchStep.limit;
    if (limit != 0 && limit != state_.winchLimit) {
        char text[300];
        std::snprintf(text, sizeof text,
                      "winch: at t = %.6g s %s winch.%s = %.6g m: %s stops there (deployed length %.6g m at the "
                      "step's end; winch.rate %.6g m/s applied as %.6g m/s)",
                      state_.time, limits.maxAcceleration > 0.0 ? "the drum brakes to stop at" : "the deployed length reaches",
                      limit > 0 ? "maxLength" : "minLength", limit > 0 ? limits.maxLength : limits.minLength,
                      limit > 0 ? "paying out" : "hauling in", state_.winchLength + state_.winchStep.length(h), requested,
                      state_.winchStep.rate1);
        add_event(text);
    }
    state_.winchLimit = limit;
    if (limit != 0 && limits.maxAcceleration > 0.0 && state_.winchRate != 0.0 && state_.winchStep.rate1 == 0.0) {
        // braking along its envelope, the drum comes to rest at the limit within this step
        char text[200];
        std::snprintf(text, sizeof text, "winch: at t = %.6g s the drum stops at winch.%s = %.6g m",
                      state_.time + state_.winchStep.rampTime, limit > 0 ? "maxLength" : "minLength",
                      limit > 0 ? limits.maxLength : limits.minLength);
        add_event(text);
    }
    return true;
}

// Splits the top element when it has grown past 1.5 nominal lengths (the lower part becomes a
// nominal element, exactly the same cubic), merges it with the element below when it has shrunk
// under half of one (docs/winch.md). At a communication point; the integrator restarts.
namespace {

// Split above 1.5 nominal lengths, merge under 0.5 (remesh_action), and merge too when the step
// would haul the top element in below a quarter of a nominal length (change: of the top element
// over the step); no split that would leave it so short. Neither undoes the other.
RemeshAction next_remesh(double top, double nominal, int elements, double change) {
    RemeshAction action = remesh_action(top, nominal, elements > 1);
    const double end = top + change;
    if (action == RemeshAction::Split && end - nominal < 0.25 * nominal) action = RemeshAction::None;
    if (action == RemeshAction::None && elements > 1 && end < 0.25 * nominal) action = RemeshAction::Merge;
    return action;
}

}  // namespace

bool CableSimulation::remesh(double change, std::string& error) {
    const double nominal = model_.winch_nominal();
    // How many passes the step needs (a split makes the top element one nominal length shorter,
    // a merge one longer).
    int passes = 0;
    for (double top = model_.top_length(), elements = model_.winch_mesh().elements; passes < kMaxRemeshPasses;
         ++passes) {
        const RemeshAction action = next_remesh(top, nominal, static_cast<int>(elements), change);
        if (action == RemeshAction::None) break;
        top += action == RemeshAction::Split ? -nominal : nominal;
        elements += action == RemeshAction::Split ? 1 : -1;
    }
    for (int pass = 0; pass < passes; ++pass) {
        const RemeshAction action =
            next_remesh(model_.top_length(), nominal, model_.winch_mesh().elements, change);
        if (action == RemeshAction::None) break;
        // Only one remesh per step starts the line in balance: a winch that moves more than an
        // element per step on a fine mesh makes nodes faster than the balance can follow them.
        if (!remesh_once(action, passes == 1, error)) return false;
    }
    return true;
}

bool CableSimulation::remesh_once(RemeshAction action, bool balance, std::string& error) {
    const double top = model_.top_length(), nominal = model_.winch_nominal();
    const WinchMesh mesh = model_.winch_mesh();
    expand_integrator_state(state_.time, y_.data(), yp_.data());
    const int G = model_.n_global();
    std::vector<double> X, Xd, Xdd;
    WinchMesh next;
    if (action == RemeshAction::Split) {
        const double a = top - nominal;  // the new top element; the rest is nominal
        double node[3][6], material[12];
        hermite_split_node(X_.data(), top, a, node[0]);
        // the new node is material: the velocity of the material there, not of the mesh point
        model_.top_material_velocity(X_.data(), Xd_.data(), material);
        hermite_split_node(material, top, a, node[1]);
        hermite_split_node(Xdd_.data(), top, a, node[2]);
        const std::vector<double>* from[3] = {&X_, &Xd_, &Xdd_};
        std::vector<double>* to[3] = {&X, &Xd, &Xdd};
        for (int f = 0; f < 3; ++f) {
            to[f]->assign(from[f]->begin(), from[f]->begin() + 6);
            to[f]->insert(to[f]->end(), node[f], node[f] + 6);
            to[f]->insert(to[f]->end(), from[f]->begin() + 6, from[f]->begin() + G);
        }
        next = WinchMesh{mesh.elements + 1, a};
    } else {
        const std::vector<double>* from[3] = {&X_, &Xd_, &Xdd_};
        std::vector<double>* to[3] = {&X, &Xd, &Xdd};
        for (int f = 0; f < 3; ++f) {  // the node between the top element and the next one goes
            to[f]->assign(from[f]->begin(), from[f]->begin() + 6);
            to[f]->insert(to[f]->end(), from[f]->begin() + 12, from[f]->begin() + G);
        }
        next = WinchMesh{mesh.elements - 1, top + nominal};
    }
    rebuild(next);
    state_.winchTop0 = next.topLength;
    model_.set_top_length(state_.winchTop0);
    model_.set_top_rate(off_ ? state_.winchRate : state_.winchStep.rate0);
    if (balance) {
        // The tow node's tangent (unless clamped) and the first nodes below the top element (within
        // the first section): their equations of motion, with the accelerations the line had, decide
        // where they stand on the new mesh (docs/winch.md, "Split and merge").
        const bool hinged = model_.params().topEnd != UC_TOP_CLAMPED;
        const int nodes = std::min(kBalanceNodes, model_.winch_mesh().elements - 1);
        balance_dofs(hinged ? 3 : 6, (hinged ? 3 : 0) + 6 * nodes, X, Xd, Xdd);
    }
    model_.restrict_to_free(X.data(), q_.data());
    model_.restrict_to_free(Xd.data(), v_.data());
    // The accelerations of the new mesh's equations (the merged element has its own mass matrix).
    if (!restart_from(error)) return false;
    if (off_) {
        y_[0] = next.topLength;
        y_[1] = yp_[0] = state_.winchRate;
        yp_[1] = 0.0;
    }
    ++stateStamp_;
    return set_integrator_tolerances(error);
}

bool CableSimulation::restart_from(std::string& error) {
    if (!solve_consistent_acceleration(model_, *staticSolver_, loads_, state_.time, q_, v_, a_)) {
        error = "winch: the mass matrix of the line is singular";
        return false;
    }
    for (int j = 0; j < model_.n_free(); ++j) {
        y_[2 * (j + off_)] = q_[j];
        y_[2 * (j + off_) + 1] = v_[j];
        yp_[2 * (j + off_)] = v_[j];
        yp_[2 * (j + off_) + 1] = a_[j];
    }
    state_.restartPending = true;
    return true;
}

void CableSimulation::dof_residual(int g, int count, const std::vector<double>& X, const std::vector<double>& Xd,
                                   const std::vector<double>& Xdd, Eigen::VectorXd& R, Eigen::MatrixXd* J) {
    R.setZero();
    if (J) J->setZero();
    for (int e = 0; e < model_.n_elements(); ++e) {
        const int off = model_.element_offset(e);
        if (off + 12 <= g || off >= g + count) continue;
        double Re[12];
        Mat12 K, C, M;
        model_.element_residual(e, X.data(), Xd.data(), Xdd.data(), loads_, Re);
        if (J) model_.element_jacobian(e, X.data(), Xd.data(), Xdd.data(), loads_, K, C, M);
        for (int i = 0; i < count; ++i) {
            const int a = g + i - off;
            if (a < 0 || a >= 12) continue;
            R[i] += Re[a];
            if (!J) continue;
            for (int k = 0; k < count; ++k) {
                const int b = g + k - off;
                if (b >= 0 && b < 12) (*J)(i, k) += K(a, b);
            }
        }
    }
}

void CableSimulation::balance_dofs(int g, int count, std::vector<double>& X, const std::vector<double>& Xd,
                                   const std::vector<double>& Xdd) {
    // Newton with halving of the step while the residual does not fall; a step that finds nothing
    // better ends the search (the DOFs stay where the last accepted step left them).
    Eigen::MatrixXd J(count, count);
    Eigen::VectorXd R(count), trialR(count);
    std::vector<double> trial = X;
    dof_residual(g, count, X, Xd, Xdd, R, &J);
    double norm = R.norm();
    for (int iteration = 0; iteration < kMaxBalanceIterations && std::isfinite(norm) && norm > 0.0; ++iteration) {
        const Eigen::VectorXd dx = -J.partialPivLu().solve(R);
        if (!dx.allFinite()) return;
        bool accepted = false;
        for (double lambda = 1.0; lambda > 1e-3 && !accepted; lambda *= 0.5) {
            for (int i = 0; i < count; ++i) trial[g + i] = X[g + i] + lambda * dx[i];
            dof_residual(g, count, trial, Xd, Xdd, trialR, nullptr);
            accepted = std::isfinite(trialR.norm()) && trialR.norm() < norm;
        }
        if (!accepted) return;
        for (int i = 0; i < count; ++i) X[g + i] = trial[g + i];
        if (!(dx.lpNorm<Eigen::Infinity>() > 1e-13 * model_.winch_nominal())) return;
        dof_residual(g, count, X, Xd, Xdd, R, &J);
        norm = R.norm();
    }
}

void CableSimulation::rebuild(const WinchMesh& mesh) { replace_model(CableModel(model_.params(), &mesh)); }

void CableSimulation::replace_model(CableModel&& model) {
    state_.statsBase = total_stats();
    state_.integratorStarted = false;
    state_.restartPending = true;
    integrator_.reset();
    staticSolver_.reset();
    model_ = std::move(model);
    allocate();
    for (auto& lu : derivativeLU_) lu.reset();
    derivativeK_.reset();
    derivativeC_.reset();
    derivativeM_.reset();
    derivativeWork_.clear();
    derivativeStamp_ = -1;
    loads_.current.profile = &model_.current_profile();
    loads_.current.sea = &model_.sea();
}

void CableSimulation::free_state(std::vector<double>& q, std::vector<double>& v, std::vector<double>& a) const {
    const int n = model_.n_free();
    q.resize(n);
    v.resize(n);
    a.resize(n);
    for (int j = 0; j < n; ++j) {
        q[j] = y_[2 * (j + off_)];
        v[j] = y_[2 * (j + off_) + 1];
        a[j] = yp_[2 * (j + off_) + 1];
    }
}

bool CableSimulation::far_end_held_at_start() const {
    const UCParams& p = model_.params();
    return model_.far_end_prescribed() || (p.bottomEnd == UC_BOTTOM_PROXY && p.initMode == UC_INIT_EQUILIBRIUM);
}

// The spring is ten times as stiff as the stiffest element's axial spring: the equilibrium found with
// it is well conditioned, and the end stands off the body's position by a tenth of what the cable
// would stretch under the same force. The anchor is then moved by that offset and the statics solved
// again from there (each pass takes the offset down by that factor, to round-off in a few passes).
bool CableSimulation::proxy_statics(double t0, const std::vector<double>& v, bool fromProfile, std::string& error) {
    constexpr int kPasses = 8;
    double shortest = model_.element_length(0);
    for (const ElementRun& run : model_.runs()) shortest = std::min(shortest, run.elementLength);
    const Vec3 target = state_.end.p();
    loads_.endSpring = 10.0 * model_.line().EA / shortest;
    loads_.endSpringAnchor = target;
    const int gN = model_.end_offset();
    const double tolerance = 1e-9 * std::max(model_.line().length, target.norm());
    for (int pass = 0; pass < kPasses; ++pass) {
        const StaticsResult statics =
            solve_static_equilibrium(model_, *staticSolver_, loads_, t0, v, q_, fromProfile || pass > 0);
        if (!statics.converged) {
            loads_.endSpring = 0.0;
            error = statics.message;
            return false;
        }
        std::vector<double> zero(model_.n_free(), 0.0);
        model_.expand(q_.data(), v.data(), zero.data(), loads_, t0, X_.data(), Xd_.data(), Xdd_.data());
        const Vec3 offset = Eigen::Map<const Vec3>(X_.data() + gN) - target;
        if (offset.norm() <= tolerance) break;
        loads_.endSpringAnchor -= offset;
    }
    // The spring's force becomes the proxy's estimated force: the residual, and so the equilibrium,
    // stay as solved (to round-off).
    const Vec3 spring = -loads_.endSpring * (Eigen::Map<const Vec3>(X_.data() + gN) - loads_.endSpringAnchor);
    state_.proxy.add(spring, proxy_flow(Eigen::Map<const Vec3>(X_.data() + gN), Eigen::Map<const Vec3>(Xd_.data() + gN), t0));
    loads_.endSpring = 0.0;
    return true;
}

// The flow relative to the proxy at its position r and velocity v at time t.
Vec3 CableSimulation::proxy_flow(const Vec3& r, const Vec3& v, double t) const {
    CurrentField current = loads_.current;
    current.time = t;
    Vec3 U, A;
    current.flow(r, U, A);
    return U - v;
}

namespace {

// phi(A) = A (e^A - I)^-1 = g(A)^-1 with g(A) = (e^A - I) / A = I + A/2 + A^2/6 + ..., which is
// entire and invertible where A's eigenvalues are real (a drag's derivative has no vertical part:
// A is singular, and phi is I there). g by its Taylor series on A / 2^s, then doubled s times:
// g(2B) = g(B) (e^B + I) / 2, e^(2B) = (e^B)^2.
Mat3 bernoulli_phi(const Mat3& A) {
    const double norm = A.lpNorm<Eigen::Infinity>();
    int squarings = 0;
    while (norm / std::ldexp(1.0, squarings) > 0.25) ++squarings;
    const Mat3 B = A / std::ldexp(1.0, squarings);
    Mat3 E = Mat3::Identity(), g = Mat3::Identity(), power = Mat3::Identity();
    double factorial = 1.0;
    for (int k = 1; k <= 14; ++k) {  // |B| <= 1/4: the remainders are below 1e-17
        power = power * B;
        factorial *= k;
        E += power / factorial;
        g += power / (factorial * (k + 1));
    }
    for (int k = 0; k < squarings; ++k) {
        g = 0.5 * g * (E + Mat3::Identity());
        E = E * E;
    }
    return g.inverse();
}

}  // namespace

// The force that makes the body follow the proxy. The body integrates M v' = F + (its other forces)
// with F held over the step; with its other forces as the estimate says (linearized at the proxy's
// new velocity v1: the estimate's value there less D (v - v1), D its drag derivative), the held force
// that takes a body starting at the proxy's old velocity v0 to v1 is
//   F = -(M / h) phi(M^-1 D h) (v0 - v1) - estimate(v1) - proxy weight,
// phi(A) = A (e^A - I)^-1 (= M (v1 - v0) / h less the mean of the other forces when D = 0): exact for
// a body whose drag time M / D is shorter than the step, which a force from the mean acceleration is
// not. The tracking force corrects what remains, at a fraction of the one-step gains:
// T = M [alpha (e + h e' + d) / h^2 + beta e' / h], e and e' the proxy's position and velocity less
// the body's at the step's start, d the proxy's departure from a trapezoidal path over the step.
// What the body needs beyond that in the long run is the estimate's error: the estimate integrates
// the tracking force (a low-pass of time constant proxy.filterTime, at least kProxyFilterSteps
// steps). docs/cosimulation.md derives the gains' stability. h = 0: at initialization (the cable
// force alone).
void CableSimulation::proxy_output(double h, const Vec3& p0, const Vec3& v0, const UCInputs& in) {
    const UCParams& p = model_.params();
    const PointBody& body = model_.body();
    const Vec3 weight(0.0, 0.0, -(body.mass - model_.fluid().rho * body.volume) * model_.fluid().gravity);
    const Vec3 flow = proxy_flow(vec(state_.outputs.endPosition), vec(state_.outputs.endVelocity), state_.time);
    Mat3 D;
    const Vec3 estimate = state_.proxy.force(flow, &D);
    if (h > 0.0) {
        const Mat3 M = body.inertia();
        const Vec3 p1 = vec(state_.outputs.endPosition), v1 = vec(state_.outputs.endVelocity);
        const Vec3 follow = -(M / h) * bernoulli_phi(M.inverse() * D * h) * (v0 - v1) - estimate - weight;
        const Vec3 e = p0 - vec(in.end), ev = v0 - vec(in.endVelocity);
        const Vec3 departure = p1 - p0 - 0.5 * h * (v0 + v1);
        const Vec3 tracking = M * (p.proxyTrackingGain * (e + h * ev + departure) / (h * h) + p.proxyTrackingDamping * ev / h);
        const Vec3 force = follow + tracking;
        for (int k = 0; k < 3; ++k) state_.outputs.endForce[k] = force[k];
        const double tau = std::max(p.proxyFilterTime, kProxyFilterSteps * h);
        state_.proxy.add(-h / (tau + h) * tracking, flow);
    }
    const Vec3 total = state_.proxy.force(flow) + weight;
    for (int k = 0; k < 3; ++k) state_.outputs.bodyForceEstimate[k] = total[k];
}

void CableSimulation::update_outputs() {
    expand_integrator_state(state_.time, y_.data(), yp_.data());
    model_.residual(X_.data(), Xd_.data(), Xdd_.data(), loads_, R_.data(), &forces_);
    compute_outputs(model_, X_.data(), Xd_.data(), forces_, loads_.torque, outputWork_, state_.outputs);
    const IntegratorStats s = total_stats();
    state_.outputs.nSteps = s.steps;
    state_.outputs.nResidualEvals = s.residualEvals;
    state_.outputs.nJacobianEvals = s.jacobianEvals;
    state_.outputs.nNonlinearFailures = s.nonlinearFailures;
    state_.outputs.nErrorTestFailures = s.errorTestFailures;
    state_.outputs.tensionScale = state_.tensionScale;
    state_.outputs.fatigueDamage = sn_.area > 0.0 ? state_.rainflow.damage(sn_) : 0.0;
    state_.outputs.waveElevation = model_.sea().elevation(X_[0], X_[1], state_.time);
    state_.outputs.unstretchedLength = model_.winch() ? state_.winchLength : model_.line().length;
}

size_t CableSimulation::state_size() const {
    return sizeof(StateHeader) + sizeof(LineState) + (2 * y_.size() + integrator_->history_size()) * sizeof(double);
}

void CableSimulation::save_state(void* buffer) {
    StateHeader header{};
    header.magic = kStateMagic;
    header.version = kStateVersion;
    header.nFree = model_.n_free();
    header.nElements = model_.n_elements();
    header.winchElements = model_.winch_mesh().elements;
    header.winchMeshTop = model_.winch_mesh().topLength;
    header.stateBytes = static_cast<std::int32_t>(sizeof(LineState));
    // The integrator's history, when it belongs to this state: the run continues from here
    // without a restart, exactly as a restored copy will (both evaluate a new Jacobian first).
    // The saved statistics are the totals (the restored integrator's own are taken off again).
    const bool history = state_.integratorStarted && !state_.restartPending;
    LineState saved = state_;
    saved.statsBase = total_stats();
    saved.integratorStarted = history;
    saved.restartPending = !history;
    historyBuffer_.assign(integrator_->history_size(), 0.0);
    if (history) integrator_->save_history(historyBuffer_.data());
    auto* out = static_cast<unsigned char*>(buffer);
    std::memcpy(out, &header, sizeof header);
    out += sizeof header;
    std::memcpy(out, &saved, sizeof saved);
    out += sizeof saved;
    std::memcpy(out, y_.data(), y_.size() * sizeof(double));
    out += y_.size() * sizeof(double);
    std::memcpy(out, yp_.data(), yp_.size() * sizeof(double));
    out += yp_.size() * sizeof(double);
    std::memcpy(out, historyBuffer_.data(), historyBuffer_.size() * sizeof(double));
}

bool CableSimulation::restore_state(const void* buffer, size_t size, std::string& error, bool* changed) {
    bool ignored = false;
    bool& touched = changed ? *changed : ignored;
    touched = false;
    ++stateStamp_;  // the cached interface derivatives are stale from here on
    const auto* in = static_cast<const unsigned char*>(buffer);
    StateHeader header{};
    LineState saved;
    const bool complete = size >= sizeof(StateHeader) + sizeof(LineState);
    if (complete) {
        std::memcpy(&header, in, sizeof header);
        std::memcpy(&saved, in + sizeof header, sizeof saved);
    }
    const bool ours = complete && header.magic == kStateMagic && header.version == kStateVersion &&
                      header.stateBytes == static_cast<std::int32_t>(sizeof(LineState));
    if (model_.winch() && ours) {
        // A state of a winch's line may have another mesh than the present one: take its mesh first.
        const WinchMesh mesh = model_.winch_mesh();
        if (header.winchElements > 0 && header.winchElements <= 100000 && std::isfinite(header.winchMeshTop) &&
            header.winchMeshTop > 0.0 &&
            (header.winchElements != mesh.elements || header.winchMeshTop != mesh.topLength)) {
            touched = true;
            rebuild(WinchMesh{header.winchElements, header.winchMeshTop});
        }
    }
    if (ours) {
        // A graded mesh is graded again for the tow point it was made for.
        const Vec3 tow = vec(saved.meshTow), far = vec(saved.meshFar);
        if (tow.allFinite() && far.allFinite() && saved.grading >= 0 && saved.grading < kGradingCount &&
            (saved.graded != state_.graded || tow != vec(state_.meshTow) || far != vec(state_.meshFar) ||
             saved.grading != state_.grading)) {
            touched = true;
            grade_mesh(tow, far, saved.graded, saved.grading);
        }
    }
    if (size != state_size()) {
        error = "saved state has the wrong size for this cable (different nElements or end conditions)";
        return false;
    }
    if (!ours || header.nFree != model_.n_free() || header.nElements != model_.n_elements()) {
        error = "saved state does not belong to this cable model (magic, version or sizes differ)";
        return false;
    }
    touched = true;
    in += sizeof header + sizeof saved;
    std::memcpy(y_.data(), in, y_.size() * sizeof(double));
    in += y_.size() * sizeof(double);
    std::memcpy(yp_.data(), in, yp_.size() * sizeof(double));
    in += yp_.size() * sizeof(double);
    const bool history = saved.integratorStarted;
    state_ = saved;
    if (state_.tensionScale > 0.0 && !set_integrator_tolerances(error)) {  // 0: saved before initialization
        state_.restartPending = true;
        return false;
    }
    if (history) {
        historyBuffer_.resize(integrator_->history_size());
        std::memcpy(historyBuffer_.data(), in, historyBuffer_.size() * sizeof(double));
        if (!integrator_->restore_history(historyBuffer_.data(), error)) {
            state_.restartPending = true;
            return false;
        }
    }
    set_winch_time(state_.time);
    if (history) {
        // The restored integrator carries the saver's counters since its last restart.
        const IntegratorStats since = integrator_->stats();
        state_.statsBase.steps -= since.steps;
        state_.statsBase.residualEvals -= since.residualEvals;
        state_.statsBase.jacobianEvals -= since.jacobianEvals;
        state_.statsBase.nonlinearFailures -= since.nonlinearFailures;
        state_.statsBase.errorTestFailures -= since.errorTestFailures;
    }
    return true;
}

}  // namespace uc

namespace uc {

bool CableSimulation::prepare_derivatives(std::string& error) {
    if (off_) {
        error = "the interface derivatives are not available with the constant-tension winch (winchMode 2): its "
                "length is an unknown the linearization does not carry";
        return false;
    }
    if (!(state_.lastStepSize > 0.0)) {
        error = "the interface derivatives are over the next communication step, taken as long as the last one: "
                "they are available after the first fmi2DoStep";
        return false;
    }
    if (derivativeStamp_ == stateStamp_) return true;  // the state has not changed since
    const int n = model_.n_free(), N = model_.n_elements(), bw = model_.free_bandwidth();
    if (!derivativeK_) {
        for (auto& lu : derivativeLU_) lu = std::make_unique<UnpivotedBandLU>(n, bw);
        derivativeK_ = std::make_unique<BandMatrix>(n, bw);
        derivativeC_ = std::make_unique<BandMatrix>(n, bw);
        derivativeM_ = std::make_unique<BandMatrix>(n, bw);
        derivativeWork_.assign(11 * static_cast<size_t>(n) + 3 * kDerivativeInputs * static_cast<size_t>(n), 0.0);
    }
    BandMatrix &K = *derivativeK_, &C = *derivativeC_, &M = *derivativeM_;
    K.clear();
    C.clear();
    M.clear();
    // The cable's Jacobian at its present state.
    expand_integrator_state(state_.time, y_.data(), yp_.data());
    auto add = [&](int i, int k, double dq, double dv, double da) {
        K.add(i, k, dq);
        C.add(i, k, dv);
        M.add(i, k, da);
    };
    model_.jacobian(X_.data(), Xd_.data(), Xdd_.data(), loads_, add);
    // The driven ends' columns in the free rows, and the output rows (the driven nodes' position
    // rows of the end elements' residuals), come from the two end elements (and the end node's terms).
    const int elements[2] = {0, N - 1};
    for (int k = 0; k < 2; ++k)
        model_.element_jacobian(elements[k], X_.data(), Xd_.data(), Xdd_.data(), loads_, derivativeKe_[k],
                                derivativeCe_[k], derivativeMe_[k]);
    model_.end_node_jacobian(X_.data(), Xd_.data(), Xdd_.data(), loads_, derivativeKn_, derivativeCn_, derivativeMn_);
    if (model_.params().bottomEnd == UC_BOTTOM_PROXY) {
        // The force on the body (proxy_output) moves with the proxy's position p1 and velocity v1 at
        // t + h as follow + tracking do: dF = [(M / h) phi + D - M alpha / (2 h)] dv1 + (M alpha / h^2) dp1
        // (D the estimate's drag derivative; phi's own change with D left out).
        const double h = state_.lastStepSize;
        const Mat3 Mb = model_.body().inertia();
        const double alpha = model_.params().proxyTrackingGain;
        Mat3 D;
        state_.proxy.force(proxy_flow(vec(state_.outputs.endPosition), vec(state_.outputs.endVelocity), state_.time), &D);
        derivativeProxyVelocity_ = Mb / h * bernoulli_phi(Mb.inverse() * D * h) + D - Mb * alpha / (2.0 * h);
        derivativeProxyPosition_ = Mb * alpha / (h * h);
    }
    // The Newton matrix of one BDF2 substep, K + c C + c^2 M, factored for both substep sizes.
    for (int level = 0; level < 2; ++level) {
        const double c = 1.5 * (kDerivativeSubsteps << level) / state_.lastStepSize;
        UnpivotedBandLU& A = *derivativeLU_[level];
        double* a = A.values();
        const double *k = K.values(), *cc = C.values(), *m = M.values();
        for (size_t i = 0; i < A.value_count(); ++i) a[i] = k[i] + c * (cc[i] + c * m[i]);
        if (!A.factor()) {
            error = "the cable's step matrix has a vanishing pivot at this state";
            return false;
        }
    }
    for (bool& done : derivativeColumnDone_) done = false;
    derivativeStamp_ = stateStamp_;
    return true;
}

void CableSimulation::derivative_response(const double seed[kDerivativeInputs], double out[6]) {
    const int n = model_.n_free(), N = model_.n_elements(), bw = model_.free_bandwidth();
    const double h = state_.lastStepSize;
    const bool externalEnd = model_.params().bottomEnd == UC_BOTTOM_EXTERNAL;
    const bool proxyEnd = model_.params().bottomEnd == UC_BOTTOM_PROXY;
    // bottomEnd 4: the body's reported state enters the force on it through the tracking force alone
    // (the estimate moves after the step), linearly: -M alpha / h^2 per metre, -M (alpha + beta) / h
    // per metre per second; its acceleration not at all. The towForce rows stay 0: the cable does not
    // see the body within the step.
    Vec3 tracking = Vec3::Zero();
    const int elements[2] = {0, N - 1};
    double* w = derivativeWork_.data();
    double *qm = w, *q0 = w + n, *vm = w + 2 * n, *v0 = w + 3 * n, *rhs = w + 4 * n, *bq = w + 5 * n,
           *bv = w + 6 * n, *tmp = w + 7 * n, *forcing = w + 11 * n;
    // The seeds in the direction: the prescribed DOF each moves, the change of its end's target
    // (position, velocity, acceleration at t + h) per unit input, as DrivenEnd::next makes it, and
    // its forcing columns fK, fC, fM in the free rows.
    struct Active {
        int gp;
        double weight;
        TowTrajectory motion;
        double *fK, *fC, *fM;
    };
    std::vector<Active> active;
    for (int s = 0; s < kDerivativeInputs; ++s) {
        if (seed[s] == 0.0) continue;
        const bool tow = s < 6 || (s >= 12 && s < 15);
        const int comp = s % 3;
        const int kind = s >= 12 ? 2 : (s % 6) / 3;  // 0 position, 1 velocity, 2 acceleration
        if (!tow && proxyEnd && kind < 2) {
            const UCParams& pp = model_.params();
            const double gain = kind == 0 ? pp.proxyTrackingGain / (h * h) : (pp.proxyTrackingGain + pp.proxyTrackingDamping) / h;
            tracking -= seed[s] * gain * model_.body().inertia().col(comp);
        }
        if (!tow && !externalEnd) continue;  // the end inputs act on the cable only at a driven far end
        const DrivenEndState& end = tow ? state_.tow : state_.end;
        const int gp = (tow ? 0 : model_.end_offset()) + comp;
        double dp1 = 1.0, dv1 = 0.0, da1 = 0.0;
        if (kind == 2) {  // an acceleration as the master gives it (held over the step)
            dp1 = 0.5 * h * h;
            dv1 = h;
            da1 = 1.0;
        } else if (kind == 1) {
            if (end.lastAccelerationGiven) {
                dp1 = h;
                dv1 = 1.0;
            } else {  // the acceleration is the difference of the last two velocity inputs over h
                dp1 = 1.5 * h;
                dv1 = 2.0;
                da1 = 1.0 / h;
            }
        }
        double* f = forcing + 3 * static_cast<size_t>(active.size()) * n;
        Active a{gp, seed[s],
                 TowTrajectory::quintic(0.0, h, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3(dp1, 0.0, 0.0),
                                        Vec3(dv1, 0.0, 0.0), Vec3(da1, 0.0, 0.0)),
                 f, f + n, f + 2 * n};
        for (int j = 0; j < 3 * n; ++j) f[j] = 0.0;
        for (int k = 0; k < 2; ++k) {
            if (k == 1 && elements[1] == elements[0]) break;
            const int g0 = model_.element_offset(elements[k]);
            const int b = gp - g0;
            if (b < 0 || b >= 12) continue;
            for (int r = 0; r < 12; ++r) {
                const int j = model_.free_index(g0 + r);
                if (j < 0) continue;
                const double cr = model_.coefficient(g0 + r);
                a.fK[j] += cr * derivativeKe_[k](r, b);
                a.fC[j] += cr * derivativeCe_[k](r, b);
                a.fM[j] += cr * derivativeMe_[k](r, b);
            }
        }
        if (!tow) {
            for (int r = 0; r < 6; ++r) {
                const int j = model_.free_index(model_.end_offset() + r);
                if (j < 0) continue;
                a.fK[j] += derivativeKn_(r, comp);
                a.fC[j] += derivativeCn_(r, comp);
                a.fM[j] += derivativeMn_(r, comp);
            }
        }
        active.push_back(a);
    }
    for (int i = 0; i < 6; ++i) out[i] = 0.0;
    for (int r = 0; r < 3; ++r) out[3 + r] = tracking[r];
    if (active.empty()) return;
    const int width = 2 * bw + 1;
    const BandMatrix &C = *derivativeC_, &M = *derivativeM_;
    double coarse[6] = {};
    std::vector<Vec3> p(active.size()), v(active.size()), acc(active.size());
    for (int level = 0; level < 2; ++level) {
        const int substeps = kDerivativeSubsteps << level;
        const double dt = h / substeps;
        const double c = 1.5 / dt;  // BDF2: v_{k+1} = c q_{k+1} + (q_{k-1} - 4 q_k) / (2 dt)
        double* result = level == 0 ? coarse : out;
        const UnpivotedBandLU& A = *derivativeLU_[level];
        // BDF2 from rest: the change starts with zero position, velocity and acceleration.
        for (int j = 0; j < n; ++j) qm[j] = q0[j] = vm[j] = v0[j] = 0.0;
        for (int step = 0; step < substeps; ++step) {
            for (size_t s = 0; s < active.size(); ++s) active[s].motion.evaluate((step + 1) * dt, p[s], v[s], acc[s]);
            for (int j = 0; j < n; ++j) {
                bq[j] = (qm[j] - 4.0 * q0[j]) / (2.0 * dt);
                bv[j] = (vm[j] - 4.0 * v0[j]) / (2.0 * dt);
                tmp[j] = c * bq[j] + bv[j];
            }
            const double *cv = C.values(), *mv = M.values();
            for (int i = 0; i < n; ++i) {
                double r = 0.0;
                for (size_t s = 0; s < active.size(); ++s) {
                    const Active& a = active[s];
                    r -= a.weight * (a.fK[i] * p[s][0] + a.fC[i] * v[s][0] + a.fM[i] * acc[s][0]);
                }
                const int k0 = std::max(0, i - bw), k1 = std::min(n - 1, i + bw);
                const double* ci = cv + static_cast<size_t>(i) * width + bw - i;  // ci[k] = C(i, k)
                const double* mi = mv + static_cast<size_t>(i) * width + bw - i;
                for (int k = k0; k <= k1; ++k) r -= ci[k] * bq[k] + mi[k] * tmp[k];
                rhs[i] = r;
            }
            A.solve(rhs);
            for (int j = 0; j < n; ++j) {
                qm[j] = q0[j];
                vm[j] = v0[j];
                q0[j] = rhs[j];
                v0[j] = c * rhs[j] + bq[j];
            }
        }
        // Accelerations at t + h, from the last substep.
        for (int j = 0; j < n; ++j) tmp[j] = c * v0[j] + bv[j];
        // towForce = -(rows 0..2 of element 0), endForce = -(rows 6..8 of element N - 1).
        for (int k = 0; k < 2; ++k) {
            const int g0 = model_.element_offset(elements[k]);
            const Mat12 &Ke = derivativeKe_[k], &Ce = derivativeCe_[k], &Me = derivativeMe_[k];
            for (int r = 0; r < 3; ++r) {
                const int a = (k == 0 ? 0 : 6) + r;
                double dR = 0.0;
                for (int b = 0; b < 12; ++b) {
                    const int g = g0 + b;
                    const int j = model_.free_index(g);
                    if (j >= 0) {
                        const double cb = model_.coefficient(g);
                        dR += cb * (Ke(a, b) * q0[j] + Ce(a, b) * v0[j] + Me(a, b) * tmp[j]);
                        continue;
                    }
                    for (size_t s = 0; s < active.size(); ++s)
                        if (g == active[s].gp)
                            dR += active[s].weight * (Ke(a, b) * p[s][0] + Ce(a, b) * v[s][0] + Me(a, b) * acc[s][0]);
                }
                result[3 * k + r] = -dR;
            }
        }
        if (proxyEnd) {  // the force on the body, from the proxy's state at t + h
            Vec3 dp, dv;
            for (int r = 0; r < 3; ++r) {
                const int j = model_.free_index(model_.end_offset() + r);
                dp[r] = q0[j];
                dv[r] = v0[j];
            }
            const Vec3 dF = derivativeProxyVelocity_ * dv + derivativeProxyPosition_ * dp;
            for (int r = 0; r < 3; ++r) result[3 + r] = dF[r];
        }
    }
    // BDF2's error falls as the square of the substep: Richardson's extrapolation of the two.
    for (int i = 0; i < 6; ++i) out[i] = (4.0 * out[i] - coarse[i]) / 3.0;
    for (int r = 0; r < 3; ++r) out[3 + r] += tracking[r];
}

bool CableSimulation::interface_derivative(const double seed[kDerivativeInputs], double out[6], std::string& error) {
    for (int i = 0; i < 6; ++i) out[i] = 0.0;
    if (!prepare_derivatives(error)) return false;
    int count = 0, single = -1;
    bool cached = true;
    for (int s = 0; s < kDerivativeInputs; ++s) {
        if (seed[s] == 0.0) continue;
        ++count;
        single = s;
        cached = cached && derivativeColumnDone_[s];
    }
    if (count == 1 && !cached) {  // a column: computed for a unit seed and kept
        double unit[kDerivativeInputs] = {};
        unit[single] = 1.0;
        derivative_response(unit, derivativeColumns_[single]);
        derivativeColumnDone_[single] = true;
        cached = true;
    }
    if (!cached) {  // a direction across columns not all known: one integration for the direction
        derivative_response(seed, out);
        return true;
    }
    for (int s = 0; s < kDerivativeInputs; ++s)
        if (seed[s] != 0.0)
            for (int i = 0; i < 6; ++i) out[i] += derivativeColumns_[s][i] * seed[s];
    return true;
}

}  // namespace uc
