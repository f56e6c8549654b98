// start.cpp - the start of a line: the checks of its geometry and strain, the static profile and the
// graded mesh, the initial guess, the statics and their verification, the mesh advice.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>

#include "line/simulation.h"
#include "line/simulation_internal.h"

#include "model/line_profile.h"
#include "model/mesh_grading.h"
#include "model/params.h"
#include "line/statics.h"
#include "terms/seabed.h"

namespace uc {

namespace {

// The tension scale of the error control: the largest tension of the initial state, at least the
// weight in air of the cable and the towed body (a cable released from rest has no tension yet;
// its weight is what it will carry), the Euler load pi^2 EI / L (a weightless rod) and the
// tension of a strain of 1e-6.
double tension_scale(const CableModel& model, const UCOutputs& initial) {
    const UCParams& p = model.params();
    const LineScales& line = model.line();
    double T = initial.towTension;
    for (double t : initial.tension) T = std::max(T, t);
    double body = model.far_end().body ? p.bodyMass : 0.0;
    for (const NodeAttachment& at : model.attachments()) body += at.body.mass;
    return std::max({T, (line.massPerLength * line.length + body) * p.gravity, kPi * kPi * line.EI / (line.length * line.length),
                     1e-6 * line.EA});
}

// Waves have no static equilibrium: the start solves the line in the steady water (the current) and the
// waves act from t0 on, as with waves.rampTime (MoorDyn's initial conditions leave them out too). Their
// velocity and acceleration at t0 taken as a steady flow set the line where that instant's flow would
// hold it: a grounded chain bowed across the waves, which the seabed's friction then keeps bowed, its
// mean tension raised for the whole run (docs/waves.md, "Against MoorDyn on its public deck wavekin_7").
class WavesAtRest {
  public:
    explicit WavesAtRest(CurrentField& water) : water_(water), sea_(water.sea) { water_.sea = nullptr; }
    ~WavesAtRest() { water_.sea = sea_; }
    WavesAtRest(const WavesAtRest&) = delete;
    WavesAtRest& operator=(const WavesAtRest&) = delete;

  private:
    CurrentField& water_;
    const SeaState* sea_;
};

// The water at rest: no current (uniform, profile, data, pushed by the importer) and no waves.
void still_water(CurrentField& current) {
    current.uniform.setZero();
    current.rate.setZero();
    current.profileScale = 0.0;
    current.scaleRate = 0.0;
    current.sea = nullptr;
    current.grid = nullptr;
    current.pushed = nullptr;
}

// The midpoint rule along an element: the height z of its centreline at kHeightPoints points, each standing
// for l / kHeightPoints of it (the waterline's and the wave zone's checks of the static shape).
constexpr int kHeightPoints = 64;
template <class F>
void for_each_height(const double* X, double l, F f) {
    for (int k = 0; k < kHeightPoints; ++k) f(interpolate(hermite_shape((k + 0.5) / kHeightPoints, l).N, X).z());
}

}  // namespace

// From the sections and attachments; the profile's top end is the higher of the two ends.
bool CableSimulation::static_profile(const Vec3& towPoint, const Vec3& anchor, LineProfile& profile, bool& towOnTop,
                                     std::string* why) const {
    const UCParams& p = model_.params();
    if (!model_.far_end().held || model_.winch()) return false;
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
    // the line weighs its dry weight above the water surface at z = 0, as the elements do; the
    // seabed's height under the lower end and its slope
    const Vec3& lower = towOnTop ? anchor : towPoint;
    const Vec3& upper = towOnTop ? towPoint : anchor;
    auto solve = [&](const Eigen::Vector2d& gradient) {
        profile.set_seabed_gradient(gradient);
        return profile.solve(upper, lower, segments, points, p.enableSeabed != 0,
                             model_.seabed_height(lower.x(), lower.y()), std::max(model_.line().diameter, 1e-3 * L), why,
                             0.0);
    };
    if (!model_.seabed_grid()) return solve(model_.seabed_gradient());
    // A grid: the profile on the local plane at the touchdown, through the seabed under the lower end and
    // under the touchdown (the profile sees the slope along its vertical plane only), found by a few
    // solves from the grid's gradient under the lower end; the statics on the grid close the rest.
    const Eigen::Vector2d toward(upper.x() - lower.x(), upper.y() - lower.y());
    const double span = toward.norm();
    if (!(span > 0.0)) return solve(model_.seabed_gradient(lower.x(), lower.y()));
    const Eigen::Vector2d u = toward / span;
    bool solved = solve(model_.seabed_gradient(lower.x(), lower.y()));
    for (int pass = 0; pass < 4 && solved && profile.grounded_length() > 0.0; ++pass) {
        Vec3 r, tangent;
        profile.at(profile.touchdown(), r, tangent);
        const double run = u.dot(Eigen::Vector2d(r.x() - lower.x(), r.y() - lower.y()));
        if (!(run > 1e-6 * L)) break;
        // the grid's height under the touchdown's point of the vertical plane, over the run from the lower end
        const double slope = (model_.seabed_height(lower.x() + run * u.x(), lower.y() + run * u.y()) -
                              model_.seabed_height(lower.x(), lower.y())) / run;
        const double previous = profile.touchdown();
        solved = solve(slope * u);
        if (solved && std::abs(profile.touchdown() - previous) <= 1e-3 * L) break;
    }
    return solved;
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

Vec3 CableSimulation::seabed_cross_slope() const {
    const SeabedProps& seabed = model_.seabed();
    if (!seabed.enabled || !seabed.sloped || !profile_.solved || !(profile_.profile.grounded_length() > 0.0))
        return Vec3::Zero();
    const Vec3 chord = state_.tow.p() - profile_.far;
    const Vec3 side = Vec3(-chord.y(), chord.x(), 0.0).normalized();  // horizontal, across the profile's plane
    // on a grid: its local plane under the touchdown
    Vec3 touchdown = profile_.far, tangent;
    if (seabed.grid) profile_.profile.at(profile_.profile.touchdown(), touchdown, tangent);
    const Vec3 n = seabed_normal(seabed, touchdown.x(), touchdown.y());
    if (!side.allFinite() || side.dot(n) == 0.0) return Vec3::Zero();
    return (side - side.dot(n) * n).normalized();
}

void CableSimulation::check_seabed_hold() {
    const UCParams& p = model_.params();
    const SeabedProps& seabed = model_.seabed();
    const int n = model_.n_free();
    std::vector<double> zero(n, 0.0), X(model_.n_global()), Xd(model_.n_global()), Xdd(model_.n_global());
    model_.expand(q_.data(), zero.data(), zero.data(), loads_, state_.time, X.data(), Xd.data(), Xdd.data());
    double worst = 0.0, at = 0.0;
    for (int e = 0; e < model_.n_elements(); ++e) {
        const ElementTables& tables = model_.tables(e);
        const int g0 = model_.element_offset(e);
        const ContactPoints points = contact_points(tables);
        for (int g = 0; g < points.count; ++g) {
            const QuadPoint& q = points.points[g];
            double hold = 0.0, normal = 0.0;
            seabed_hold_at(seabed, loads_.seabedHoldAcross, interpolate(q.shape.N, X.data() + g0),
                           interpolate(q.shape.N, seabedHeld_.data() + g0), hold, normal);
            if (normal > 0.0 && std::abs(hold) / normal > worst) {
                worst = std::abs(hold) / normal;
                at = model_.element_start(e) + 0.5 * model_.element_length(e);
            }
        }
    }
    if (!(worst > p.seabedFriction)) return;
    char slope[200];
    if (model_.seabed_grid())
        std::snprintf(slope, sizeof slope, "the grid of seabed.file '%.80s'", p.seabedFile);
    else
        std::snprintf(slope, sizeof slope, "seabedSlope %.6g deg, seabedSlopeHeading %.6g deg", p.seabedSlope,
                      p.seabedSlopeHeading);
    char text[500];
    std::snprintf(text, sizeof text,
                  "warning: seabedFriction = %.6g: the line rests across the slope (%s) and its static profile holds "
                  "there with a friction of %.3g of the seabed's normal force (in the element around arc length "
                  "%.6g m); the line slides sideways down the slope once the run starts",
                  p.seabedFriction, slope, worst, at);
    add_event(text);
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
        layout.anchorResting = ps.towOnTop && ps.profile.rests_at_bottom() && model_.far_end().anchored;
        const Vec3 resting(farPoint.x(), farPoint.y(), model_.resting_height(farPoint.x(), farPoint.y()));
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
        replace_model(CableModel(model_.params(), nullptr, graded ? &layout_ : nullptr, model_.seabed_grid()));
    }
    const Vec3 held = model_.far_end().anchored ? model_.anchor() : farPoint;
    if (apply && held != ps.far) solve_for(held);
}

// The direction of a line towed steadily with its far end free: the straight line at the critical
// angle of the flow past it (the water's velocity at the tow point less the tow's), where the normal
// drag 0.5 rho Cdn d U^2 sin^2(phi) balances the weight's normal part w cos(phi) (docs/model.md,
// "Initial equilibrium"): the exact steady shape of a uniform line with a free end, and near it with a
// towed body or a seabed. False (d unchanged) where there is no flow, no normal drag or the line does not sink.
bool CableSimulation::steady_tow_direction(Vec3& d) const {
    const FluidProps& fluid = model_.section(0).fluid;
    const double w = submerged_weight(fluid);
    Vec3 flow = loads_.current.velocity(state_.tow.p()) - state_.tow.v();
    flow.z() = 0.0;  // a vertical tow velocity is no steady tow along the horizontal
    const double U = flow.norm();
    const double a = 0.5 * fluid.rho * fluid.Cdn * fluid.diameter * U * U;
    if (!(w > 0.0) || !(U > 1e-6) || !(a > 0.0)) return false;  // without normal drag (Cdn 0) it hangs straight
    const double c = std::clamp((-w + std::sqrt(w * w + 4.0 * a * a)) / (2.0 * a), 0.0, 1.0);  // cos(phi)
    d = flow / U * c + Vec3(0.0, 0.0, -std::sqrt(std::max(0.0, 1.0 - c * c)));
    return true;
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
        // which the solver found folded equilibria). In a steady tow the line leaves the tow point
        // at the flow's critical angle (steady_tow_direction): from the line along initialDirection
        // (straight down by default) the solver swung the line back and settled, on some meshes,
        // into equilibria with a fold or a loop on the seabed (300 m in 200 m of water at 1 kn, 20
        // elements) or a second, wrong one (at 3 kn, 60 elements: 11 % above the tension of every
        // other mesh).
        Vec3 d = vec(p.initialDirection).normalized();
        const bool steady = p.initMode == UC_INIT_EQUILIBRIUM && steady_tow_direction(d);
        Vec3 trail = steady ? Vec3(d.x(), d.y(), 0.0) : Vec3(-state_.tow.v());
        trail.z() = 0.0;
        if (trail.norm() < 1e-9) trail = Vec3(d.x(), d.y(), 0.0);
        if (trail.norm() < 1e-9) trail = Vec3(-1.0, 0.0, 0.0);
        trail.normalize();
        if (steady) model_.straight_line(towPoint, d, X.data());
        // where the line along d meets the seabed (its height along the normal n falls at n.d per
        // metre); it trails along the seabed from there, the trail turned into its plane
        const Vec3 n = seabed_normal(model_.seabed(), towPoint.x(), towPoint.y());
        const double clearance = model_.seabed_grid()
                                     ? n.z() * (towPoint.z() - model_.seabed_height(towPoint.x(), towPoint.y()))
                                     : n.dot(towPoint) + p.waterDepth * n.z();
        const double reach = n.dot(d) < 0.0 ? clearance / -n.dot(d) : INFINITY;
        if (model_.seabed().sloped) trail = (trail - trail.dot(n) * n).normalized();
        for (int i = 0; i < model_.n_slots(); ++i) {
            const double s = model_.slot_arc_length(i);
            if (s <= reach) continue;
            Eigen::Map<Vec3>(X.data() + 6 * i) = towPoint + reach * d + (s - reach) * trail;
            Eigen::Map<Vec3>(X.data() + 6 * i + 3) = trail;
        }
    }
    if (p.enableSeabed) {
        // Start on or above the seabed: the guessed line lies on it where it would pass below.
        for (int i = 0; i < model_.n_slots(); ++i)
            X[6 * i + 2] = std::max(X[6 * i + 2], model_.seabed_height(X[6 * i], X[6 * i + 1]));
    }
    if (model_.n_internal() > 0) {  // the viscoelastic elements' internal strains at rest with the guess
        std::vector<double> Xd(X.size(), 0.0);
        model_.settle_internal(X.data(), Xd.data(), syropeHistory_.data());
    }
    for (int e = 0; e < model_.n_elements(); ++e)  // the VIV phases spread along the line
        if (model_.phase_offset(e) >= 0) X[model_.phase_offset(e)] = model_.initial_phase(e);
    model_.restrict_to_free(X.data(), q.data());
    return profile;
}

void CableSimulation::settle_phase_rates(double t, std::vector<double>& v) {
    // Each VIV phase starts turning at the rate its synchronisation model gives the line's start (q_, v and the
    // consistent accelerations a_, which the rate sees through the cross-flow motion's phase): the rate is an
    // algebraic unknown, and a start off it would be a jump the integrator's error test cannot pass.
    model_.expand(q_.data(), v.data(), a_.data(), loads_, t, X_.data(), Xd_.data(), Xdd_.data());
    for (int e = 0; e < model_.n_elements(); ++e) {
        const int g = model_.phase_offset(e);
        if (g < 0) continue;
        // the rate sets the motion's phase it is pulled by: a fixed point, from the shedding frequency at rest
        // (a contraction: the pull is the frequency range df, small against f0)
        const SectionProps& section = model_.element_section(e);
        Xd_[g] = 2.0 * kPi * section.viv.frequency * std::max(loads_.current.velocity(Vec3::Zero()).norm(), 0.01) /
                 section.fluid.diameter;
        for (int k = 0; k < 30; ++k)
            Xd_[g] -= model_.phase_residual(e, X_.data(), Xd_.data(), Xdd_.data(), loads_, nullptr);
        v[model_.free_index(g)] = Xd_[g];
    }
}

double CableSimulation::strain_survived(const SectionProps& section) {
    return section.fluid.massPerLength / section.fluid.area > kSteelDensity ? kSteelStrainRefused : kStrainRefused;
}

std::string CableSimulation::survived_text(const SectionProps& section) {
    char text[200];
    if (strain_survived(section) == kStrainRefused)
        std::snprintf(text, sizeof text,
                      "the %.3g %% a fibre rope survives (nylon, the most extensible, breaks at 20-25 %%)",
                      100.0 * kStrainRefused);
    else
        std::snprintf(text, sizeof text,
                      "the %.3g %% a line with steel in it survives (%.4g kg/m3 for its diameter: chain, wire rope "
                      "or an armoured cable, which break below 3 %%)",
                      100.0 * kSteelStrainRefused, section.fluid.massPerLength / section.fluid.area);
    return text;
}

bool CableSimulation::check_geometry(const Vec3& farPoint, std::string& error) const {
    const UCParams& p = model_.params();
    char buffer[700];
    const char* farName = model_.far_end().anchored ? "anchor.x/y/z" : "end.x/y/z";
    if (model_.far_end().held) {
        const Vec3 d = farPoint - state_.tow.p();
        // the line stretched to what each section survives at rest: no rope or steel line reaches farther
        double stretched = 0.0, unstretched = 0.0;
        for (int k = 0; k < model_.n_sections(); ++k) {
            stretched += (1.0 + strain_survived(model_.section(k))) * model_.section(k).length;
            unstretched += model_.section(k).length;
        }
        const double stretch = stretched / unstretched;  // 1 + the line's strain survived
        const double reach = stretch * model_.line().length;
        if (d.norm() > reach) {
            char together[80];
            std::snprintf(together, sizeof together, "the %.3g %% its sections survive together at rest",
                          100.0 * (stretch - 1.0));
            const std::string survived = model_.n_sections() > 1 ? together : survived_text(model_.section(0));
            if (p.lineFile[0] != '\0') {
                // A deck's points are where its author put them: the line's length is what is short.
                std::snprintf(buffer, sizeof buffer,
                              "the line is too short for where its ends are: %.6g m unstretched (the deck's "
                              "UnstrLen), its far end (%.6g, %.6g, %.6g) is %.6g m from the tow point (%.6g, %.6g, "
                              "%.6g), a stretch of %.3g %%, more than %s; lengthen the line to at least %.6g m or "
                              "bring its ends within %.6g m of each other",
                              model_.line().length, farPoint.x(), farPoint.y(), farPoint.z(), d.norm(),
                              state_.tow.p().x(), state_.tow.p().y(), state_.tow.p().z(),
                              100.0 * (d.norm() / model_.line().length - 1.0), survived.c_str(), d.norm() / stretch,
                              reach);
            } else {
                // Name the coordinate that is farthest off, with the range the others leave it, and the
                // length the line would need where the anchor is meant to be there.
                int k = 0;
                d.cwiseAbs().maxCoeff(&k);
                const double others = d.squaredNorm() - d[k] * d[k];
                const double half = std::sqrt(std::max(0.0, reach * reach - others));
                const char* prefix = model_.far_end().anchored ? "anchor" : "end";
                std::snprintf(buffer, sizeof buffer,
                              "%s.%c = %.17g is outside [%.6g, %.6g]: the far end must lie within the reach of the "
                              "stretched cable, %.4g x length = %.6g m from the tow point (it is %.6g m away; more "
                              "than %s); or the line is too short: %s = %.6g m, at least %.6g m reaches it",
                              prefix, "xyz"[k], farPoint[k], state_.tow.p()[k] - half, state_.tow.p()[k] + half,
                              stretch, reach, d.norm(), survived.c_str(),
                              p.nSections > 1 ? "the sections' length" : "length", model_.line().length,
                              d.norm() / stretch);
            }
            error = buffer;
            return false;
        }
    }
    if (!p.enableSeabed) return true;
    const double tolerance = 0.5 * model_.line().diameter;  // a point resting on the seabed sinks in slightly
    // where the seabed is: "z = -waterDepth = ..." or, sloped, its height under the point
    auto seabed_at = [&](const Vec3& r) {
        char where[160];
        if (model_.seabed_grid())
            std::snprintf(where, sizeof where, "at z = %.6g m under (%.6g, %.6g) (the grid of seabed.file '%.60s')",
                          model_.seabed_height(r.x(), r.y()), r.x(), r.y(), p.seabedFile);
        else if (model_.seabed().sloped)
            std::snprintf(where, sizeof where, "at z = %.6g m under (%.6g, %.6g) (waterDepth %.6g m, seabedSlope %.6g deg)",
                          model_.seabed_height(r.x(), r.y()), r.x(), r.y(), p.waterDepth, p.seabedSlope);
        else
            std::snprintf(where, sizeof where, "at z = -waterDepth = %.6g m", -p.waterDepth);
        return std::string(where);
    };
    const Vec3 tow = state_.tow.p();
    if (tow.z() < model_.seabed_height(tow.x(), tow.y()) - tolerance) {
        std::snprintf(buffer, sizeof buffer, "tow.z = %.6g m is below the seabed %s: the tow point must be in the water",
                      tow.z(), seabed_at(tow).c_str());
        error = buffer;
        return false;
    }
    if (model_.far_end().held && farPoint.z() < model_.seabed_height(farPoint.x(), farPoint.y()) - tolerance) {
        std::snprintf(buffer, sizeof buffer,
                      "%s: z = %.6g m is below the seabed %s: an anchor lies on the seabed, not under it", farName,
                      farPoint.z(), seabed_at(farPoint).c_str());
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
    // never over): the nodes' tangents carry the element's bending too, and are no measure of it. Refused
    // beyond what its section survives (the element farthest beyond it named), else warned of (the largest).
    double worst = 0.0, beyond = 1.0;
    int worstElement = -1, refusedElement = -1;
    for (int e = 0; e < model_.n_elements(); ++e) {
        const int g = model_.element_offset(e);
        const double chord = (Eigen::Map<const Vec3>(X_.data() + g + 6) - Eigen::Map<const Vec3>(X_.data() + g)).norm();
        const double strain = chord / model_.element_length(e) - 1.0;
        if (strain > worst) {
            worst = strain;
            worstElement = e;
        }
        if (strain / strain_survived(model_.element_section(e)) > beyond) {
            beyond = strain / strain_survived(model_.element_section(e));
            refusedElement = e;
        }
    }
    const bool refuse = refusedElement >= 0;
    if (refuse) {
        worstElement = refusedElement;
        worst = beyond * strain_survived(model_.element_section(refusedElement));
    }
    if (worstElement < 0 || !(worst > kStrainWarned)) return true;
    const SectionProps& section = model_.element_section(worstElement);
    char what[200];
    std::snprintf(what, sizeof what, "the line stretches %.3g %% at rest (%.6g N of tension over %.6g to %.6g m)",
                  100.0 * worst, section.axial.EA * worst, model_.element_start(worstElement),
                  model_.element_start(worstElement) + model_.element_length(worstElement));
    std::string why = "more than steel wire or chain stretches before it breaks (about 3 %)";
    if (refuse)
        why = "more than " + survived_text(section) + "; refusing the start";
    else if (strain_survived(section) == kStrainRefused)  // a rope: within what it survives, a pretension it may hold
        why += ", within " + survived_text(section);
    const std::string text = strain_message(model_, section_index(model_, section), worst, what, why.c_str());
    if (refuse) {
        error = text;
        return false;
    }
    add_event("warning: " + text);
    return true;
}

bool CableSimulation::check_waterline(std::string& error) const {
    // The ramp's buoyancy over that of the submerged length, rho A g int (phi(z) - [z <= 0]) ds, summed
    // per element by the midpoint rule on the elements that reach the ramp (0 < z < d): 64 points an element.
    double surplus = 0.0, thickest = 0.0;
    int worstElement = -1;
    for (int e = 0; e < model_.n_elements(); ++e) {
        const FluidProps& fluid = model_.element_section(e).fluid;
        const double* X = X_.data() + model_.element_offset(e);
        const double l = model_.element_length(e);
        if (std::max(X[2], X[8]) <= 0.0 || std::min(X[2], X[8]) >= fluid.diameter + 0.5 * l) continue;
        double ramp = 0.0;
        for_each_height(X, l, [&](double z) {
            if (z > 0.0) ramp += std::max(0.0, 1.0 - z / fluid.diameter);
        });
        const double added = fluid.rho * fluid.area * fluid.gravity * ramp * l / kHeightPoints;
        surplus += added;
        if (added > 0.0 && fluid.diameter > thickest) {
            thickest = fluid.diameter;
            worstElement = e;
        }
    }
    double largest = std::max(state_.outputs.towTension, state_.outputs.endTension);
    for (double t : state_.outputs.tension) largest = std::max(largest, t);
    if (worstElement < 0 || !(surplus > kWaterlineRefused * largest)) return true;
    char text[700];
    std::snprintf(text, sizeof text,
                  "the static equilibrium found rests on the waterline's buoyancy ramp: where the line (diameter "
                  "%.6g m, around arc length %.6g m) crosses the water surface, the buoyancy the model adds over "
                  "one diameter above z = 0 is %.4g N, %.3g %% of the line's largest tension %.6g N; a float this "
                  "thick standing through the surface is no slender line, and its start would depend on that ramp, "
                  "not on its submerged length (MoorDyn takes the geometric submerged length); refusing the start",
                  thickest, model_.element_start(worstElement) + 0.5 * model_.element_length(worstElement), surplus,
                  100.0 * surplus / largest, largest);
    error = text;
    return false;
}

namespace {

// The sums over a sea's components (the seas of the other directions of travel added) of the amplitudes
// a and of the squares a^2, and of the horizontal speeds of the water at the mean level,
// u = a w coth(k h) = velocityScale (1 + e^{-2kh}) (a w in deep water), and of their squares.
void wave_sums(const SeaState& sea, double sums[4]) {
    for (const WaveComponent& c : sea.components()) {
        const double u = c.velocityScale * (1.0 + c.bottom);
        sums[0] += c.amplitude;
        sums[1] += c.amplitude * c.amplitude;
        sums[2] += u;
        sums[3] += u * u;
    }
    for (const SeaState& group : sea.groups()) wave_sums(group, sums);
}

}  // namespace

bool CableSimulation::check_wave_zone(std::string& error) {
    // The line's length within the waves' reach of the surface (|z| < eta, 64 points an element, midpoint
    // rule), each metre weighted by the buoyancy and the normal drag of the fastest surface water, the loads
    // the waterline z = 0 puts on the wrong side of the moving surface (docs/waves.md, "The waterline").
    const SeaState& sea = model_.sea();
    if (sea.calm() || model_.params().waterSource == 1) return true;
    // The surface's reach and the water's speed there: at most the sum of the components' (all in phase);
    // for many components in random phases the surface is Gaussian of variance sum a^2 / 2, whose crests
    // pass 4 sigma (Hs) once in e^8 = 3000 waves: that bound is taken where it is the smaller.
    double sums[4] = {0.0, 0.0, 0.0, 0.0};
    wave_sums(sea, sums);
    const double reach = std::min(sums[0], 4.0 * std::sqrt(0.5 * sums[1]));
    const double speed = std::min(sums[2], 4.0 * std::sqrt(0.5 * sums[3]));
    double length = 0.0, load = 0.0;
    for (int e = 0; e < model_.n_elements(); ++e) {
        const FluidProps& fluid = model_.element_section(e).fluid;
        const double* X = X_.data() + model_.element_offset(e);
        const double l = model_.element_length(e);
        if (std::min(X[2], X[8]) >= reach + 0.5 * l || std::max(X[2], X[8]) <= -reach - 0.5 * l) continue;
        int inside = 0;
        for_each_height(X, l, [&](double z) { inside += std::abs(z) < reach; });
        const double zone = inside * l / kHeightPoints;
        length += zone;
        load += zone * (fluid.rho * fluid.area * fluid.gravity + 0.5 * fluid.rho * fluid.Cdn * fluid.diameter * speed * speed);
    }
    double largest = std::max(state_.outputs.towTension, state_.outputs.endTension);
    for (double t : state_.outputs.tension) largest = std::max(largest, t);
    if (!(load > kWaveZoneRefused * largest)) return true;
    // A line that goes through the zone (from a tow point or fairlead at the surface, or across it at more
    // than 30 degrees) has the misplaced loads over a few metres by its end; one that runs along it, over
    // more than twice the zone's height 2 eta, has them along much of its length: that one is refused.
    const bool along = length > kWaveZoneAlong * 2.0 * reach;
    char text[800];
    std::snprintf(text, sizeof text,
                  "%s%.4g m of the line lie within the waves' reach of the surface (|z| < %.4g m; the water there "
                  "up to %.4g m/s): the FMU wets a line below the mean water "
                  "level z = 0, not below the wave's surface, which would misplace up to %.4g N of buoyancy and wave "
                  "drag there, %.1f %% of its largest tension %.6g N; %s (set the waves off "
                  "(waves.mode 0, a deck's WaveKin 0) or keep the line below z = -%.4g m)",
                  along ? "" : "warning: ", length, reach, speed, load, 100.0 * load / largest, largest,
                  along ? "refusing the start of a line that runs along the surface" : "near the surface its loads are approximate",
                  reach);
    if (!along) {
        add_event(text);
        return true;
    }
    error = text;
    return false;
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
    if (model_.far_end().anchored && model_.line().EI == 0.0 &&
        std::abs(state_.outputs.endTension - axial) > kAnchorCheck * state_.outputs.endTension) {
        // Without bending stiffness the line's force on its anchor is its axial tension there: where
        // the two differ, the elements at the anchor do not hold the line's shape; where the axial force
        // is a compression, the loads along the line push it into its anchor.
        const bool current = !loads_.current.uniform.isZero(0.0) || p.currentProfileRows > 0 || loads_.current.grid != nullptr ||
                             loads_.current.pushed != nullptr;
        if (axial < 0.0 && current) {
            if (flowCompression_ == 0.0) flowCompression_ = -axial;  // the first grading's, as the refusal's
            std::snprintf(text, sizeof text,
                          "the static equilibrium found pushes the line into its anchor: its axial force there is a "
                          "compression of %.6g N (the force on the anchor %.6g N): the current's drag along the line "
                          "near the anchor exceeds what the rest of the line holds; refusing it as a start (a line "
                          "that takes no compression has no such equilibrium: start it in a weaker current)",
                          -axial, state_.outputs.endTension);
            error = text;
            return false;
        }
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
    // The elastic catenary has a constant EA: it is no answer for a line on a tension-strain curve.
    const bool still = stillWaterStart_ || (loads_.current.uniform.isZero(0.0) &&
                       (p.currentProfileRows == 0 || loads_.current.scale == 0.0) && model_.sea().calm() && !loads_.current.grid && !loads_.current.pushed);
    const bool exact = profileApplies_ && weakBending && !model_.axial_curve() && still && loads_.torque == 0.0 && profile_.solved &&
                       profile.lowest_clearance() > -model_.line().diameter &&
                       (seabedHeldStart_ || seabed_cross_slope().isZero(0.0)) &&
                       !model_.seabed_grid();  // on a grid the profile lies on one local plane: a start, no answer
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

std::string CableSimulation::mesh_advice(double t0, const EndMotion& tow, const EndMotion& far,
                                         const LineEnvironment& env, std::optional<UCParams>* starts,
                                         std::string* waveZone) const {
    const UCParams& p = model_.params();
    const bool sections = p.nSections > 1;
    // The trials share a budget of the static solver's work (kAdviceWork), so that a refusal comes back
    // within seconds: the element counts tried, and where the budget ran out, the advice says it was cut short.
    double work = kAdviceWork;
    std::string tried;
    auto cut_short = [&] {
        char text[300];
        std::snprintf(text, sizeof text,
                      "; the search for an element count that starts the line was cut short: its budget of %.0f "
                      "element iterations of the static solver was spent (tried %s)",
                      kAdviceWork, tried.c_str());
        return std::string(text);
    };
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
        if (model_.seabed_grid()) trial.set_seabed_grid(model_.seabed_grid());
        trial.adviseMesh_ = false;
        trial.staticWork_ = &work;
        tried += (tried.empty() ? "" : ", ") + std::to_string(sections ? q.section[0].nElements : q.nElements);
        std::string ignored;
        if (!trial.initialize(t0, tow, far, env, ignored)) {
            if (waveZone && !trial.waveZoneRefusal_.empty())
                *waveZone = trial.waveZoneRefusal_ + " (its start found on " + std::to_string(sections ? q.section[0].nElements : q.nElements) + " elements)";
            return false;
        }
        if (starts) *starts = q;
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
        // (n: the most of a section's, where the line has sections; nElements is not theirs)
        int n = sections ? 1 : p.nElements;
        if (sections)
            for (int k = 0; k < p.nSections; ++k) n = std::max(n, p.section[k].nElements);
        for (int count : {2 * n, 4 * n, 8 * n, 16 * n, n / 2, 1}) {
            if (count < 1 || count == n) continue;
            if (trial_starts([count](int) { return count; }, "lineFileElements = " + std::to_string(count), advice,
                             beyond))
                return advice;
            if (waveZone && !waveZone->empty()) return std::string();
            if (work <= 0.0) return cut_short();
        }
        return "; neither more nor fewer elements (lineFileElements) resolve the line";
    }
    for (int factor : {2, 4}) {
        if (trial_starts([factor](int elements) { return factor * elements; }, "", advice, beyond)) return advice;
        if (waveZone && !waveZone->empty()) return std::string();
        if (beyond) break;  // beyond the elements a line may have
        if (work <= 0.0) return cut_short();
    }
    return std::string("; neither twice nor four times the elements (") +
           (sections ? "section[k].nElements" : "nElements") +
           ") resolve the line: initMode = 1 starts from the guessed shape without equilibrium";
}

// The start when the flow at t0 has no static equilibrium (verify_statics: it pushes the line into its anchor):
// the line's equilibrium in still water, at rest, with the flow acting from t0, as MoorDyn starts every deck
// (its initial conditions are solved in still water). The statics' state is in q_ and y_, the flow back on in
// loads_; here the accelerations are those of the line at rest in it, and the start is warned of.
bool CableSimulation::start_in_still_water(double t0, std::string& error) {
    const double stillTow = state_.outputs.towTension, stillEnd = state_.outputs.endTension;
    const int n = model_.n_free();
    std::vector<double> v(n);
    for (int j = 0; j < n; ++j) v[j] = y_[2 * (j + off_) + 1];
    if (!solve_consistent_acceleration(model_, *staticSolver_, loads_, t0, q_, v, a_)) {
        error = "the mass matrix is singular: check massPerLength and the end conditions";
        return false;
    }
    if (model_.n_phases() > 0) settle_phase_rates(t0, v);
    for (int j = 0; j < n; ++j) {
        y_[2 * (j + off_) + 1] = v[j];
        yp_[2 * (j + off_)] = v[j];
        yp_[2 * (j + off_) + 1] = a_[j];
    }
    update_outputs();
    // within the FMU's message of 512 characters
    char text[500];
    std::snprintf(text, sizeof text,
                  "warning: no static equilibrium in the flow at t = %.6g s: it would push the line into its anchor "
                  "(a compression of %.6g N there: the current's drag along the line exceeds what the line holds); "
                  "the line starts from its equilibrium in still water (tow %.6g N, far end %.6g N), at rest, the "
                  "flow acting from t = %.6g s as in MoorDyn: not at rest in the flow, its first seconds are a start "
                  "transient",
                  t0, flowCompression_, stillTow, stillEnd, t0);
    add_event(text);
    return true;
}

bool CableSimulation::far_end_held_at_start() const {
    const UCParams& p = model_.params();
    return model_.far_end().held || (model_.far_end().proxy && p.initMode == UC_INIT_EQUILIBRIUM);
}

bool CableSimulation::initialize(double t0, const UCInputs& in, std::string& error) {
    return initialize(t0, tow_motion(in), far_motion(in), line_environment(in), error);
}

bool CableSimulation::initialize(double t0, const EndMotion& tow, const EndMotion& far, const LineEnvironment& env,
                                 std::string& error) {
    ++stateStamp_;  // the cached interface derivatives are stale from here on
    unrelease();     // initialized anew after its end let go: the line as built
    const UCParams& p = model_.params();
    if (p.currentsMode != 0 && currentGrid_ == nullptr) {
        error = "currents.mode = " + std::to_string(p.currentsMode) + ": the current's data (currents.file = '" +
                std::string(p.currentsFile) + "') were not given to the model (uc_set_current_text)";
        return false;
    }
    if (p.seabedFile[0] != '\0' && !model_.seabed_grid()) {
        error = "seabed.file = '" + std::string(p.seabedFile) + "': the seabed's grid was not given to the model "
                "(uc_set_seabed_text)";
        return false;
    }
    for (double v : {tow.position[0], tow.position[1], tow.position[2], tow.velocity[0], tow.velocity[1],
                     tow.velocity[2], tow.acceleration[0], tow.acceleration[1], tow.acceleration[2], env.endLoad[0],
                     env.endLoad[1], env.endLoad[2], env.endCouple[0], env.endCouple[1], env.endCouple[2],
                     env.current[0], env.current[1], far.position[0], far.position[1], far.position[2],
                     far.velocity[0], far.velocity[1], far.velocity[2]}) {
        if (!std::isfinite(v)) {
            error = "inputs must be finite numbers";
            return false;
        }
    }
    if (!end_load_linearization_finite(env)) {
        error = "endLoadVelocity and endLoadDamping inputs must be finite numbers";
        return false;
    }
    set_environment(env);
    loads_.current.rate.setZero();  // a current that changes within a step comes with the steps
    loads_.current.scaleRate = 0.0;
    if (!std::isfinite(env.currentScale)) {
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
    state_.tow.reset(tow.position, tow.velocity, tow.acceleration, tow.accelerationGiven != 0);
    loads_.tow = TowTrajectory::at_rest_in_time(state_.tow.p(), state_.tow.v(), state_.tow.a(), t0);
    state_.end.reset(far.position, far.velocity, Vec3::Zero(), false);
    loads_.end = TowTrajectory::at_rest_in_time(state_.end.p(), state_.end.v(), state_.end.a(), t0);
    const FarEnd farEnd = model_.far_end();  // a copy: grade_mesh may replace the model
    Vec3 farPoint = farEnd.external ? state_.end.p() : vec(p.anchor);
    state_.proxy = ProxyEstimate();
    loads_.endSpring = 0.0;
    if (!check_geometry(farPoint, error)) return false;
    if (!check_weight_strain(error)) return false;
    // An anchored line, or one whose far end is held at rest, starts from its static profile.
    profileApplies_ = farEnd.anchored || (farEnd.driven && state_.end.v().isZero(0.0));
    if (!std::isfinite(env.torque) || !std::isfinite(env.twist)) {
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
        if (stillWaterStart_) still_water(loads_.current);  // after grade_mesh, which sets the model's water
        if (farEnd.anchored) farPoint = model_.anchor();  // on the seabed: where the line rests
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
                            : pp.torqueMode == UC_TORQUE_PRESCRIBED ? env.torque
                            : pp.torqueMode == UC_TORQUE_ROTATION   ? model_.torque_for_twist(env.twist)
                                                                    : 0.0;
        }
        std::vector<double> v(n, 0.0);
        // A steady tow only when nothing holds the far end back: free end, internal body, or an
        // external end moving with the tow point. Otherwise the equilibrium is at rest.
        const bool steadyTow = farEnd.bare || (farEnd.body && !farEnd.proxy) ||
                               (farEnd.external && (state_.end.v() - state_.tow.v()).norm() <= 1e-12);
        if (p.initMode == UC_INIT_EQUILIBRIUM && steadyTow) {
            // Steady tow: every node moves with the tow point, tangents do not turn.
            for (int g = 0; g < 6 * model_.n_slots(); ++g) {
                const int j = model_.free_index(g);
                if (j >= 0 && g % 6 < 3) v[j] = state_.tow.v()[g % 6];
            }
        }
        if (p.initMode == UC_INIT_EQUILIBRIUM && !statics_applies(farPoint, error)) return false;
        if (p.initMode == UC_INIT_EQUILIBRIUM && farEnd.proxy) {
            const WavesAtRest steadyWater(loads_.current);
            if (!proxy_statics(t0, v, fromProfile, error)) return false;
        } else if (p.initMode == UC_INIT_EQUILIBRIUM) {
            // A line resting on a slope that falls across its profile's plane: the seabed's static
            // friction (seabedFriction > 0) holds it across the line where the profile lays it
            // (docs/model.md, "A sloped seabed"); frictionless, it slides down the slope sideways.
            const Vec3 across = fromProfile && p.seabedFriction > 0.0 ? seabed_cross_slope() : Vec3::Zero();
            seabedHeldStart_ = !across.isZero(0.0);
            if (seabedHeldStart_) {
                seabedHeld_ = X_;  // the profile's shape, expanded above
                loads_.seabedHold = seabedHeld_.data();
                loads_.seabedHoldAcross = across;
            }
            StaticsResult statics;
            {
                const WavesAtRest steadyWater(loads_.current);
                statics = solve_static_equilibrium(model_, *staticSolver_, loads_, t0, v, q_, fromProfile, staticWork_);
            }
            loads_.seabedHold = nullptr;
            if (!statics.converged) {
                error = statics.message;
                retry = true;
                return false;
            }
        }
        if (!syropeHistory_.empty()) {
            // A Syrope line starts from the deck's history (Tmax0) and mean tension (Tmean0), not from the
            // statics' rest: its slow strains at Tmean0 with the rates their equation gives (docs/model.md).
            std::vector<double> zero(n, 0.0);
            model_.initial_history(syropeHistory_.data());
            model_.expand(q_.data(), v.data(), zero.data(), loads_, t0, X_.data(), Xd_.data(), Xdd_.data());
            model_.settle_internal(X_.data(), Xd_.data(), syropeHistory_.data());
            model_.syrope_rates(X_.data(), Xd_.data(), syropeHistory_.data());
            model_.restrict_to_free(X_.data(), q_.data());
            model_.restrict_to_free(Xd_.data(), v.data());
        }
        if (!solve_consistent_acceleration(model_, *staticSolver_, loads_, t0, q_, v, a_)) {
            error = "the mass matrix is singular: check massPerLength and the end conditions";
            return false;
        }
        if (model_.n_phases() > 0) settle_phase_rates(t0, v);
        for (int j = 0; j < n; ++j) {
            y_[2 * (j + off_)] = q_[j];
            y_[2 * (j + off_) + 1] = v[j];
            yp_[2 * (j + off_)] = v[j];
            yp_[2 * (j + off_) + 1] = a_[j];
        }
        if (off_) {
            y_[0] = model_.top_length();
            winchTension_ = env.winchTension;
            winchTopAtStep_ = y_[0];
        }
        state_.time = t0;
        state_.lastStepSize = 0.0;
        state_.statsBase = IntegratorStats();
        state_.integratorStarted = false;
        state_.restartPending = true;
        state_.compressionWarned = false;
        state_.curveWarned = false;
        state_.rainflow.reset();
        update_outputs();
        if (p.initMode == UC_INIT_EQUILIBRIUM && !verify_statics(error)) {
            retry = true;
            return false;
        }
        if (seabedHeldStart_) check_seabed_hold();
        return true;
    };
    // A graded mesh whose equilibrium fails is graded again by the other gradings, with the same
    // elements (docs/model.md, "Initial equilibrium"); the refusal gives the first grading's reason.
    auto settle = [&] {
        std::string firstError;
        for (int grading = 0; !start(grading); ++grading) {
            if (grading == 0) firstError = error;
            if (!retry || !state_.graded || layout_.nodes.empty() || grading + 1 == kGradingCount) {
                if (grading > 0) {
                    error = firstError;
                    grade_mesh(state_.tow.p(), givenFar, profileApplies_, 0);
                }
                return false;
            }
        }
        return true;
    };
    flowCompression_ = 0.0;
    stillWaterStart_ = false;
    bool settled = settle();
    if (!settled && flowCompression_ > 0.0 && adviseMesh_) {
        // No static equilibrium in the flow: the line starts from its equilibrium in still water, at rest,
        // the flow acting from t0 (start_in_still_water). Not in mesh_advice's trials: they ask for the flow's.
        const CurrentField flow = loads_.current;
        const std::string inFlow = error;
        stillWaterStart_ = true;
        settled = settle();
        stillWaterStart_ = false;
        loads_.current = flow;  // the flow back on, in the water of the model as made again
        loads_.current.profile = &model_.current_profile();
        loads_.current.sea = &model_.sea();
        loads_.current.grid = currentGrid_.get();
        if (!settled) {
            error = inFlow + "; its start in still water (the flow acting from the start) failed too: " + error;
            return false;
        }
        if (!start_in_still_water(t0, error)) return false;
    }
    if (!settled) {  // a deck's line on too coarse a mesh starts on the first finer one that passes (deck_mesh.cpp)
        if (!retry || !adviseMesh_) return false;
        std::optional<UCParams> finer;
        std::string waveZone;
        const std::string advice = mesh_advice(t0, tow, far, env, &finer, &waveZone);
        if (!waveZone.empty()) {  // found on a finer mesh, and in the wave zone on any
            error = waveZone;
            return false;
        }
        return start_on_finer_mesh(t0, tow, far, env, finer, advice, error);
    }
    if (p.initMode == UC_INIT_EQUILIBRIUM && (!check_static_strain(error) || !check_waterline(error))) return false;
    waveZoneRefusal_.clear();
    if (p.initMode == UC_INIT_EQUILIBRIUM && !check_wave_zone(error)) {
        waveZoneRefusal_ = error;
        return false;
    }
    warn_beyond_curve();
    if (off_) {  // consistent: the winch runs at the rate of the initial tension
        double R[12];
        model_.element_residual(0, X_.data(), Xd_.data(), Xdd_.data(), loads_, R);
        y_[1] = yp_[0] = tension_winch_rate(line_tension(R), y_[0], nullptr);
        yp_[1] = 0.0;
        state_.winchRate = y_[1];
    }
    if (sn_.area > 0.0) state_.rainflow.add(state_.outputs.towTension, sn_);
    if (farEnd.proxy) {
        EndMotion body;  // h = 0: the cable force alone, not the body's motion
        body.position = far.position;
        body.velocity = far.velocity;
        proxy_output(0.0, Vec3::Zero(), Vec3::Zero(), body);
    }
    state_.outputs.towTensionMax = state_.outputs.towTensionMin = state_.outputs.towTension;
    state_.tensionScale = tension_scale(model_, state_.outputs);
    if (!set_integrator_tolerances(error)) return false;
    state_.outputs.tensionScale = state_.tensionScale;
    warn_outside_current_grid();
    return true;
}

}  // namespace uc
