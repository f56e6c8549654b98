// cable_model.cpp - DOF map, prescribed motion and assembly of the cable equations.
#include "model/cable_model.h"
#include "model/params.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace uc {
namespace {

constexpr int kLoadQuadraturePoints = CableModel::kLoadPoints;

}  // namespace

AxialProps CableModel::scaled_axial(const SectionProps& section, const Loads& loads) const {
    // The static solver's soft cable: the stiffness scale is a fraction of the line's largest EA,
    // so every section is softened to the same EA (a section already softer keeps its own), and
    // no section strains much more than the others on the way to equilibrium.
    double cap = loads.axialStiffnessScale;
    if (sections_.size() > 1 && cap < 1.0) cap = std::min(1.0, cap * line_.EA / section.axial.EA);
    return AxialProps{section.axial.EA, section.axial.damping, cap, section.axial.tensionOnly && !loads.twoSidedAxial,
                      section.curve.n > 0 ? &section.curve : nullptr};
}

AxialProps CableModel::element_axial(int e, const double* X, const double* Xd, const double* history) const {
    const SectionProps& sec = sections_[runs_[elementRun_[e]].section];
    AxialProps p = sec.axial;
    const int gi = internal_offset(e);
    if (gi >= 0) {
        p.visco = &sec.visco;
        p.internal[0] = X[gi];
        p.internal[1] = Xd[gi];
        if (sec.syrope.form != kSyropeNone) {
            p.syrope = &sec.syrope;
            p.history = history[e];
        }
    }
    return p;
}

AxialProps CableModel::axial_at(int e, const double* X, const double* Xd, const Loads& loads) const {
    AxialProps p = scaled_axial(sections_[runs_[elementRun_[e]].section], loads);
    const int gi = internal_offset(e);
    if (gi >= 0) {
        const SectionProps& sec = sections_[runs_[elementRun_[e]].section];
        p.visco = &sec.visco;
        p.internal[0] = X[gi];
        p.internal[1] = Xd[gi];
        if (sec.syrope.form != kSyropeNone) {
            p.syrope = &sec.syrope;
            p.history = loads.syropeHistory[e];
        }
    }
    return p;
}

void CableModel::settle_internal(double* X, double* Xd, const double* history) const {
    for (int e = 0; e < nElements_; ++e) {
        const int gi = internal_offset(e);
        if (gi < 0) continue;
        const SectionProps& sec = sections_[runs_[elementRun_[e]].section];
        if (sec.syrope.form != kSyropeNone) {
            X[gi] = syrope_slow_strain(sec.syrope, history[e], sec.syrope.tensionMean0);
            Xd[gi] = 0.0;
            continue;
        }
        const ElementTables& t = tables_[elementRun_[e]];
        // the mean strain of the element, then e1 with (EA_1 + EA_2) e1 = EA_2 e: EA_1 e1 = EA_s e, the
        // static spring's tension, so e1 = EA_s e / EA_1(e1), a fixed point (a contraction: EA_1 falls
        // slowly with e1); with a constant EA_2 the first iterate is exact
        double strain = 0.0;
        for (int g = 0; g < ElementTables::nAxial; ++g)
            strain += t.axial[g].weight / t.length * (interpolate(t.axial[g].shape.dN, X + elementOffset_[e]).norm() - 1.0);
        double e1 = sec.visco.EAs * strain / visco_stiffness(sec.visco, 0.0).EA1;
        for (int it = 0; it < 100; ++it) {
            const double next = sec.visco.EAs * strain / visco_stiffness(sec.visco, e1).EA1;
            const bool done = std::abs(next - e1) <= 1e-15 * std::abs(e1);
            e1 = next;
            if (done) break;
        }
        X[gi] = e1;
        Xd[gi] = 0.0;
    }
}

void CableModel::syrope_rates(const double* X, double* Xd, const double* history) const {
    for (int e = 0; e < nElements_; ++e) {
        const int gi = internal_offset(e);
        if (gi < 0 || sections_[runs_[elementRun_[e]].section].syrope.form == kSyropeNone) continue;
        Xd[gi] = 0.0;
        double Xm[12];
        AxialProps p = element_axial(e, X, Xd, history);
        const double rest = visco_residual(tables_[elementRun_[e]], p, X + elementOffset_[e], element_velocities(e, X, Xd, Xm));
        Xd[gi] = -rest / (p.damping + p.visco->dampingDynamic);
    }
}

void CableModel::initial_history(double* history) const {
    if (!syrope_) return;  // (history_size() 0)
    for (int e = 0; e < nElements_; ++e) {
        const SectionProps& sec = sections_[runs_[elementRun_[e]].section];
        history[e] = sec.syrope.form == kSyropeNone ? 0.0 : syrope_initial_history(sec.syrope);
    }
}

void CableModel::advance_history(const double* X, double* history) const {
    if (!syrope_) return;
    for (int e = 0; e < nElements_; ++e) {
        const int gi = internal_offset(e);
        const SectionProps& sec = sections_[runs_[elementRun_[e]].section];
        if (gi >= 0 && sec.syrope.form != kSyropeNone) history[e] = syrope_history_after(sec.syrope, history[e], X[gi]);
    }
}

namespace {

// Membrane locking (docs/model.md): the axial strain of an element is projected onto
// Legendre modes (mean, linear, quadratic) in the element. The mean mode carries the full EA.
// At full EA the linear and quadratic modes compete with bending and lock (elastica tip error
// 1e-3 L at 10 elements); without any stiffness they leave the element's axial modes free
// (singular without bending) and cannot carry a tension gradient. At 1 % of EA they carry the
// distributed axial loads (the strain variation inside an element is then 100 times the
// physical one, a sub-millimetre effect on the shape of a tow cable; the mean strain and every
// force stay exact) and the elastica tip error at 10 elements is ~5e-5 L.
constexpr double kHigherStrainModeWeight = 0.01;

Vec3 unit(const double v[3]) {
    Vec3 d(v[0], v[1], v[2]);
    return d / d.norm();
}

}  // namespace

TowTrajectory TowTrajectory::at_rest_in_time(const Vec3& p, const Vec3& v, const Vec3& a, double t) {
    TowTrajectory traj;
    traj.t0 = t;
    traj.h = 0.0;
    traj.p0 = traj.p1 = p;
    traj.v0 = traj.v1 = v;
    traj.a0 = traj.a1 = a;
    return traj;
}

TowTrajectory TowTrajectory::quintic(double t0, double h, const Vec3& p0, const Vec3& v0, const Vec3& a0,
                                     const Vec3& p1, const Vec3& v1, const Vec3& a1) {
    TowTrajectory traj;
    traj.t0 = t0;
    traj.h = h;
    traj.p0 = p0;
    traj.v0 = v0;
    traj.a0 = a0;
    traj.p1 = p1;
    traj.v1 = v1;
    traj.a1 = a1;
    // Quintic Hermite: what the end state misses against the parabola from (p0, v0, a0) is made
    // up by the s^3..s^5 terms, which vanish at s = 0 with their first two derivatives.
    const Vec3 dp = p1 - (p0 + v0 * h + 0.5 * a0 * h * h);
    const Vec3 dv = (v1 - (v0 + a0 * h)) * h;
    const Vec3 da = (a1 - a0) * (h * h);
    const double h3 = h * h * h;
    traj.c3_ = (10.0 * dp - 4.0 * dv + 0.5 * da) / h3;
    traj.c4_ = (-15.0 * dp + 7.0 * dv - da) / (h3 * h);
    traj.c5_ = (6.0 * dp - 3.0 * dv + 0.5 * da) / (h3 * h * h);
    return traj;
}

TowTrajectory TowTrajectory::steady(double lambda) const {
    return at_rest_in_time(p0, lambda * v0, Vec3::Zero(), t0);
}

void TowTrajectory::evaluate(double t, Vec3& p, Vec3& v, Vec3& a) const {
    const double s = t - t0;  // Horner form; with h = 0 the cubic and higher terms are zero
    p = p0 + s * (v0 + s * (0.5 * a0 + s * (c3_ + s * (c4_ + s * c5_))));
    v = v0 + s * (a0 + s * (3.0 * c3_ + s * (4.0 * c4_ + s * (5.0 * c5_))));
    a = a0 + s * (6.0 * c3_ + s * (12.0 * c4_ + s * (20.0 * c5_)));
}

CableModel::CableModel(const UCParams& params, const WinchMesh* winch, const StaticLayout* layout,
                       std::shared_ptr<const SeabedGrid> seabedGrid)
    : params_(params), seabedGrid_(std::move(seabedGrid)), farEnd_(FarEnd::of(params.bottomEnd)) {
    if (params.winchMode != 0) {
        const int n0 = params.nSections <= 1 ? params.nElements : params.section[0].nElements;
        const double l0 = params.nSections <= 1 ? params.length : params.section[0].length;
        winchNominal_ = l0 / n0;
        winchMesh_ = winch ? *winch : WinchMesh{n0, winchNominal_};
    }
    topTangent_ = params.topEnd == UC_TOP_CLAMPED ? unit(params.topTangent) : Vec3(0, 0, -1);
    build_sections(params);
    const bool laid = layout && params.winchMode == 0;
    build_mesh(params, laid && !layout->nodes.empty() ? &layout->nodes : nullptr);
    build_dof_map();
    for (int e = 0; e < nElements_ && !syrope_; ++e) syrope_ = sections_[runs_[elementRun_[e]].section].syrope.form != kSyropeNone;
    if (this->winch()) {
        slotArcBase_ = slotArc_;
        for (const ElementRun& run : runs_) runStartBase_.push_back(run.s0);
        for (const SectionProps& sec : sections_) sectionStartBase_.push_back(sec.s0);
        for (const NodeAttachment& at : attachments_) attachmentBase_.push_back(at.s);
        lineBase_ = line_;
        lineMassBase_ = line_.massPerLength * line_.length;
    }
    anchor_ = Vec3(params.anchor[0], params.anchor[1], params.anchor[2]);
    const SectionProps& last = sections_.back();
    if (laid && layout->anchorResting && farEnd_.anchored && last.seabed.enabled &&
        std::abs(anchor_.z() - uc::seabed_height(last.seabed, anchor_.x(), anchor_.y())) <= 0.5 * last.fluid.diameter) {
        // An anchor on the seabed with the line resting next to it sits at the height the line rests
        // at (within a few millimetres of z = -waterDepth): held lower or higher, the last element
        // would press into the seabed or hang above it, and its contact would load the anchor
        // vertically. A line that lifts off at the anchor keeps it where it is given.
        anchor_.z() = resting_height(anchor_.x(), anchor_.y());
        anchorResting_ = true;
    }
    body_ = PointBody{params.bodyMass, params.bodyVolume, params.bodyAddedMass, params.bodyCdA,
                      params.enableBodyFluidInertia != 0};
    const double* rows[3] = {params.bodyAddedMassMatrix.x, params.bodyAddedMassMatrix.y, params.bodyAddedMassMatrix.z};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) body_.addedMassMatrix(i, j) = rows[i][j];
    body_.anisotropic = !body_.addedMassMatrix.isZero(0.0);
    if (farEnd_.proxy) body_.CdA = 0.0;  // its drag is the external body's, estimated
    endContact_.seabed = last.seabed;
    if (farEnd_.body) {
        endContact_.footprint = body_footprint(body_.mass, body_.volume, last.fluid.diameter);
        endContact_.seabed.depth = params.waterDepth;
        endContact_.seabed.restWeight = 0.0;
        endContact_.seabed.smoothing = 0.05 * std::max(body_size(body_.mass, body_.volume), last.fluid.diameter);
        if (params.seabedRest == 1)
            rest_at_depth(endContact_.seabed,
                          (body_.mass - params.waterDensity * body_.volume) * params.gravity / endContact_.footprint);
    } else if (farEnd_.bare) {
        // The 5-point rule's outer point sits 0.0469 l from the element's end: the tip beyond it.
        endContact_.footprint = 0.0469101 * runs_.back().elementLength;
    }
    std::string waveError;  // the parameters' check has refused waves that cannot be built
    sea_.build(params, waveError);
    if (!sea_.calm()) {
        waveCache_.resize(static_cast<size_t>(nElements_) * kLoadQuadraturePoints + 1 + attachments_.size());
        for (WaveExpansion& cache : waveCache_) cache.groups.resize(sea_.groups().size());  // a polynomial per direction
    }
    profile_.rows = params.currentProfileRows;
    for (int k = 0; k < kCurrentProfileRows; ++k) {
        profile_.depth[k] = params.currentProfileDepth[k];
        profile_.ux[k] = params.currentProfileX[k];
        profile_.uy[k] = params.currentProfileY[k];
    }
}

namespace {

// The properties of one uniform piece of line, whether it comes from the scalar line parameters or
// from section[k].
struct SectionInput {
    double length, diameter, massPerLength, EA, EI, axialDamping, GJ, Cdn, Cdt, Can, Cat;
    int nElements, joint;
    double MBL;
    double EAdynamic, EAdynamicSlope, axialDampingDynamic;  // the viscoelastic model (EAdynamic 0: none)
    double Cl, vivFrequency, vivFrequencyRange;             // vortex-induced vibration (Cl 0: none)
};

SectionInput uniform_line(const UCParams& p) {
    return {p.length, p.diameter, p.massPerLength, p.EA, p.EI, p.axialDamping, p.GJ,
            p.Cdn, p.Cdt, p.Can, p.Cat, p.nElements, 0, p.MBL, p.EAdynamic, p.EAdynamicSlope, p.axialDampingDynamic,
            p.Cl, p.vivFrequency, p.vivFrequencyRange};
}

SectionInput section_input(const UCSection& s, double lineMBL) {
    return {s.length, s.diameter, s.massPerLength, s.EA, s.EI, s.axialDamping, s.GJ,
            s.Cdn, s.Cdt, s.Can, s.Cat, s.nElements, s.joint, s.MBL > 0.0 ? s.MBL : lineMBL,
            s.EAdynamic, s.EAdynamicSlope, s.axialDampingDynamic, s.Cl, s.vivFrequency, s.vivFrequencyRange};
}

}  // namespace

int CableModel::section_at(double s) const {
    const double snap = 1e-9 * line_.length;  // a point this close to a section's start is in it
    int k = 0;
    while (k + 1 < static_cast<int>(sections_.size()) && s >= sections_[k + 1].s0 - snap) ++k;
    return k;
}

double CableModel::resting_height(double x, double y) const {
    const SectionProps& last = sections_.back();
    const double weight = submerged_weight(last.fluid);
    // the penetration is along the normal: its height is that over n_z
    const double nz = seabed_normal(last.seabed, x, y).z();
    return uc::seabed_height(last.seabed, x, y) -
           (weight > 0.0 ? resting_penetration(last.seabed, weight, nz) / nz : 0.0);
}

double CableModel::seabed_height(double x, double y) const {
    SeabedProps given = sections_[0].seabed;
    given.depth = params_.waterDepth;
    given.restWeight = 0.0;
    return uc::seabed_height(given, x, y);
}

Eigen::Vector2d CableModel::seabed_gradient() const {
    const Vec3& n = sections_[0].seabed.normal;
    return Eigen::Vector2d(-n.x() / n.z(), -n.y() / n.z());
}

Eigen::Vector2d CableModel::seabed_gradient(double x, double y) const {
    if (!seabedGrid_) return seabed_gradient();
    double gx = 0.0, gy = 0.0;
    seabedGrid_->height(x, y, &gx, &gy);
    return Eigen::Vector2d(gx, gy);
}

void CableModel::build_sections(const UCParams& p) {
    std::vector<SectionInput> inputs;
    AxialCurve curve;
    if (p.nSections <= 1) {
        inputs.push_back(uniform_line(p));
        std::string error;  // check_params has refused a curve that cannot be built
        if (p.axialCurvePoints > 0 && AxialCurve::build(p.axialCurveStrain, p.axialCurveTension, p.axialCurvePoints, curve, error))
            inputs[0].EA = curve.secant();
    } else {
        for (int k = 0; k < p.nSections && k < UC_MAX_SECTIONS; ++k) inputs.push_back(section_input(p.section[k], p.MBL));
    }
    if (winchMesh_.elements > 0) {
        inputs[0].length = winchMesh_.topLength + (winchMesh_.elements - 1) * winchNominal_;
        inputs[0].nElements = winchMesh_.elements;
    }
    double s0 = 0.0;
    for (const SectionInput& in : inputs) {
        SectionProps s;
        s.s0 = s0;
        s.length = in.length;
        s.fluid.rho = p.waterDensity;
        s.fluid.gravity = p.gravity;
        s.fluid.massPerLength = in.massPerLength;
        s.fluid.diameter = in.diameter;
        s.fluid.area = kPi * in.diameter * in.diameter / 4.0;
        s.fluid.Cdn = in.Cdn;
        s.fluid.Cdt = in.Cdt;
        s.fluid.Can = in.Can;
        s.fluid.Cat = in.Cat;
        s.fluid.addedMass = p.enableAddedMass != 0;
        s.axial.EA = in.EA;
        if (sections_.empty()) s.curve = curve;
        if (in.EAdynamic > 0.0) s.visco = ViscoProps{in.EA, in.EAdynamic, in.EAdynamicSlope, in.axialDampingDynamic};
        if (sections_.empty()) syrope_from_params(p, s.syrope);  // (a uniform line's)
        if (in.Cl > 0.0) s.viv = VivProps{in.Cl, in.vivFrequency, in.vivFrequencyRange};
        s.axial.damping = in.axialDamping;
        s.axial.tensionOnly = p.enableCompression == 0;
        s.EI = p.enableBending ? in.EI : 0.0;
        // The material's Kelvin-Voigt time constant axialDamping / EA damps bending as well: it
        // removes the element-scale bending waves (periods of milliseconds, which quadratic drag
        // cannot damp at small amplitude) that a torque keeps exciting, and is negligible for the
        // slow modes.
        s.bendingDamping = s.EI * in.axialDamping / in.EA;
        s.GJ = in.GJ;
        s.nElements = in.nElements;
        s.joint = in.joint;
        s.MBL = in.MBL;
        s.seabed.enabled = p.enableSeabed != 0;
        s.seabed.depth = p.waterDepth;
        s.seabed.stiffness = p.seabedStiffness;
        s.seabed.damping = p.seabedDamping;
        s.seabed.friction = p.seabedFriction;
        s.seabed.smoothing = 0.05 * in.diameter;
        set_slope(s.seabed, p.seabedSlope, p.seabedSlopeHeading);
        set_grid(s.seabed, seabedGrid_.get());
        if (p.seabedRest == 1) rest_at_depth(s.seabed, submerged_weight(s.fluid));
        sections_.push_back(s);
        s0 += in.length;
    }
    sections_.back().joint = 0;
    if (sections_.size() == 1) {
        const SectionInput& in = inputs[0];
        line_ = LineScales{sections_[0].length, in.massPerLength, in.EA, sections_[0].EI, in.diameter};
    } else {
        double mass = 0.0;
        for (const SectionProps& s : sections_) {
            mass += s.fluid.massPerLength * s.length;
            line_.EA = std::max(line_.EA, s.axial.EA);
            line_.EI = std::max(line_.EI, s.EI);
            line_.diameter = std::max(line_.diameter, s.fluid.diameter);
        }
        line_.length = s0;
        line_.massPerLength = mass / s0;
    }
}

void CableModel::build_mesh(const UCParams& p, const std::vector<double>* nodes) {
    // Attachments on the line, by arc length; those inside a section split it so a node sits there.
    std::vector<std::pair<double, PointBody>> points;
    for (int k = 0; k < p.nAttachments && k < UC_MAX_ATTACHMENTS; ++k) {
        const UCAttachment& a = p.attachment[k];
        points.push_back({a.s, PointBody{a.mass, a.volume, a.addedMass, a.CdA, p.enableBodyFluidInertia != 0}});
    }
    std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    const double snap = 1e-9 * line_.length;  // an attachment this close to a node is on it
    int first = 0;
    if (nodes) {
        // The given nodes; elements of one length in a row share their tables.
        for (size_t i = 0; i + 1 < nodes->size(); ++i) {
            const double s0 = (*nodes)[i], l = (*nodes)[i + 1] - s0;
            const int k = section_at(s0);
            if (!runs_.empty() && runs_.back().section == k && runs_.back().elementLength == l) {
                ++runs_.back().count;
            } else {
                runs_.push_back(ElementRun{s0, l, first, 1, k});
            }
            ++first;
        }
    }
    for (int k = 0; k < static_cast<int>(sections_.size()) && !nodes; ++k) {
        const SectionProps& sec = sections_[k];
        std::vector<double> cuts{sec.s0};
        for (const auto& point : points)
            if (point.first > sec.s0 + snap && point.first < sec.s0 + sec.length - snap &&
                point.first > cuts.back() + snap)
                cuts.push_back(point.first);
        cuts.push_back(sec.s0 + sec.length);
        const int n = sec.nElements;
        if (k == 0 && winchMesh_.elements > 0) {  // the winch's top element, then the nominal ones
            runs_.push_back(ElementRun{0.0, winchMesh_.topLength, 0, 1, 0});
            if (n > 1) runs_.push_back(ElementRun{winchMesh_.topLength, winchNominal_, 1, n - 1, 0});
            first = n;
            continue;
        }
        for (size_t j = 0; j + 1 < cuts.size(); ++j) {
            ElementRun run;
            run.s0 = cuts[j];
            run.section = k;
            run.first = first;
            if (cuts.size() == 2) {
                run.count = n;
                run.elementLength = sec.length / n;
            } else {
                const double piece = cuts[j + 1] - cuts[j];
                run.count = std::max(1, static_cast<int>(std::lround(n * piece / sec.length)));
                run.elementLength = piece / run.count;
            }
            first += run.count;
            runs_.push_back(run);
        }
    }
    nElements_ = first;
    for (const ElementRun& run : runs_) {
        tables_.push_back(make_element_tables(run.elementLength, kLoadQuadraturePoints, 3, contact_spacing()));
        tables_.back().axialModeWeight[1] = tables_.back().axialModeWeight[2] = kHigherStrainModeWeight;
    }
    pinnedAttachments_.clear();
    for (const auto& point : points) {
        // Without bending stiffness a point load turns the line through a corner: its node is a
        // pinned joint, each side with its own tangent. Not at a section's end (a joint already).
        const int k = section_at(point.first);
        const bool inside = point.first > sections_[k].s0 + snap && point.first < sections_[k].s0 + sections_[k].length - snap;
        if (inside && sections_[k].EI == 0.0 && winchMesh_.elements == 0) pinnedAttachments_.push_back(point.first);
    }
    build_slots();
    place_attachments(points);
}

void CableModel::build_slots() {
    // Node slots: one per node, and a second one after the node of a pinned joint.
    elementRun_.resize(nElements_);
    elementOffset_.resize(nElements_);
    slotArc_.clear();
    duplicateSlot_.clear();
    std::vector<int> pinned;
    int slot = 0;
    const double snap = 1e-9 * line_.length;
    for (int r = 0; r < static_cast<int>(runs_.size()); ++r) {
        const ElementRun& run = runs_[r];
        for (int i = 0; i < run.count; ++i) {
            const int e = run.first + i;
            elementRun_[e] = r;
            elementOffset_[e] = 6 * slot;
            slotArc_.push_back(run.s0 + run.elementLength * i);
            duplicateSlot_.push_back(false);
            ++slot;
            const double end = run.s0 + run.elementLength * (i + 1);
            const bool lastOfSection = i + 1 == run.count &&
                                       (r + 1 == static_cast<int>(runs_.size()) || runs_[r + 1].section != run.section);
            bool pinnedHere = lastOfSection && sections_[run.section].joint == 1;
            for (double s : pinnedAttachments_)
                if (std::abs(s - end) <= snap && !lastOfSection) pinnedHere = true;
            if (pinnedHere) {
                slotArc_.push_back(end);  // the joint
                duplicateSlot_.push_back(false);
                ++slot;
                pinned.push_back(slot);  // the next element starts on a second slot at the same point
            }
        }
    }
    const ElementRun& last = runs_.back();
    slotArc_.push_back(last.s0 + last.elementLength * last.count);
    duplicateSlot_.push_back(false);
    nSlots_ = slot + 1;
    for (int i : pinned) duplicateSlot_[i] = true;
}

void CableModel::place_attachments(const std::vector<std::pair<double, PointBody>>& points) {
    // Attachments on their nodes (the first slot of a pinned joint).
    for (const auto& point : points) {
        NodeAttachment at;
        at.s = point.first;
        at.body = point.second;
        int best = 0;
        for (int i = 1; i < nSlots_; ++i)
            if (std::abs(slotArc_[i] - point.first) < std::abs(slotArc_[best] - point.first)) best = i;
        at.offset = 6 * best;
        const int k = section_at(point.first);
        const double d = sections_[k].fluid.diameter;
        at.contact.footprint = body_footprint(at.body.mass, at.body.volume, d);
        at.contact.seabed = sections_[k].seabed;
        at.contact.seabed.depth = params_.waterDepth;
        at.contact.seabed.restWeight = 0.0;
        at.contact.seabed.smoothing = 0.05 * std::max(body_size(at.body.mass, at.body.volume), d);
        if (params_.seabedRest == 1)
            rest_at_depth(at.contact.seabed, (at.body.mass - params_.waterDensity * at.body.volume) * params_.gravity /
                                                 at.contact.footprint);
        attachments_.push_back(at);
    }
}

void CableModel::build_dof_map() {
    // DOF map, in global order so that the free Jacobian stays banded.
    const UCParams& params = params_;
    // The internal strains of viscoelastic elements after the node slots (the free unknowns interleave them).
    nInternal_ = 0;
    internalOffset_.clear();
    std::vector<int> startsAt(nSlots_, -1);  // the viscoelastic or VIV element starting at each slot
    for (int e = 0; e < nElements_; ++e) {
        if (!sections_[runs_[elementRun_[e]].section].viscoelastic()) continue;
        if (internalOffset_.empty()) internalOffset_.assign(nElements_, -1);
        internalOffset_[e] = 6 * nSlots_ + nInternal_++;
        startsAt[elementOffset_[e] / 6] = e;
    }
    // The VIV phases after them, each also between its element's two nodes.
    nPhase_ = 0;
    phaseOffset_.clear();
    for (int e = 0; e < nElements_; ++e) {
        if (!sections_[runs_[elementRun_[e]].section].viv.on()) continue;
        if (phaseOffset_.empty()) phaseOffset_.assign(nElements_, -1);
        phaseOffset_[e] = 6 * nSlots_ + nInternal_ + nPhase_++;
        startsAt[elementOffset_[e] / 6] = e;
    }
    free_.assign(n_global(), -1);
    coef_.assign(n_global(), 1.0);
    int next = 0;
    for (int i = 0; i < nSlots_; ++i) {
        if (i > 0 && startsAt[i - 1] >= 0) {
            const int e = startsAt[i - 1];
            if (internal_offset(e) >= 0) free_[internal_offset(e)] = next++;
            if (phase_offset(e) >= 0) free_[phase_offset(e)] = next++;
        }
        for (int k = 0; k < 6; ++k) {
            const int g = 6 * i + k;
            const bool position = k < 3;
            if (i == 0 && position) continue;  // tow point: prescribed
            if (i == nSlots_ - 1 && position && farEnd_.held) continue;  // far end: prescribed
            if (position && duplicateSlot_[i]) {  // the second slot of a pinned joint: the same point
                free_[g] = free_[g - 6];
                continue;
            }
            if (i == 0 && params.topEnd == UC_TOP_CLAMPED) {
                // r'_0 = a * topTangent: one free stretch shared by the three components.
                if (k == 3) ++next;
                free_[g] = next - 1;
                coef_[g] = topTangent_[k - 3];
                continue;
            }
            free_[g] = next++;
        }
    }
    nFree_ = next;
    bandwidth_ = 0;
    for (int e = 0; e < nElements_; ++e) {
        int lo = nFree_, hi = -1;
        for (int a = 0; a < 12; ++a) {
            const int j = free_[elementOffset_[e] + a];
            if (j < 0) continue;
            lo = std::min(lo, j);
            hi = std::max(hi, j);
        }
        if (internal_offset(e) >= 0) {
            lo = std::min(lo, free_[internal_offset(e)]);
            hi = std::max(hi, free_[internal_offset(e)]);
        }
        if (phase_offset(e) >= 0) {
            lo = std::min(lo, free_[phase_offset(e)]);
            hi = std::max(hi, free_[phase_offset(e)]);
        }
        if (hi >= lo) bandwidth_ = std::max(bandwidth_, hi - lo);
    }
}

void CableModel::set_top_length(double length) {
    const double shift = length - winchMesh_.topLength;
    runs_[0].elementLength = length;
    tables_[0] = make_element_tables(length, kLoadQuadraturePoints, 3, contact_spacing());
    tables_[0].axialModeWeight[1] = tables_[0].axialModeWeight[2] = kHigherStrainModeWeight;
    for (size_t r = 1; r < runs_.size(); ++r) runs_[r].s0 = runStartBase_[r] + shift;
    sections_[0].length = winchMesh_.topLength + (winchMesh_.elements - 1) * winchNominal_ + shift;
    for (size_t k = 1; k < sections_.size(); ++k) sections_[k].s0 = sectionStartBase_[k] + shift;
    for (size_t i = 1; i < slotArc_.size(); ++i) slotArc_[i] = slotArcBase_[i] + shift;
    for (size_t a = 0; a < attachments_.size(); ++a) attachments_[a].s = attachmentBase_[a] + shift;
    line_.length = lineBase_.length + shift;
    line_.massPerLength = (lineMassBase_ + sections_[0].fluid.massPerLength * shift) / line_.length;
}

double CableModel::element_start(int e) const { return slotArc_[elementOffset_[e] / 6]; }

double CableModel::slot_fraction(int i) const {
    if (runs_.size() == 1 && nSlots_ == nElements_ + 1) return static_cast<double>(i) / nElements_;
    return slotArc_[i] / line_.length;
}

void CableModel::locate(double s, int& e, double& xi) const {
    size_t r = 0;
    while (r + 1 < runs_.size() && runs_[r + 1].s0 <= s) ++r;
    const ElementRun& run = runs_[r];
    const double local = (s - run.s0) / run.elementLength;
    const int i = std::max(0, std::min(run.count - 1, static_cast<int>(local)));
    e = run.first + i;
    xi = std::clamp(local - i, 0.0, 1.0);
}

double CableModel::torque_for_twist(double twist) const {
    if (sections_.size() == 1) return sections_[0].GJ * twist / sections_[0].length;
    double compliance = 0.0;
    for (const SectionProps& s : sections_) compliance += s.length / s.GJ;
    return twist / compliance;
}

double CableModel::axial_compliance() const {
    double compliance = 0.0;
    for (const SectionProps& s : sections_) compliance += s.length / s.axial.EA;
    return compliance;
}

void CableModel::twist_angles(int stations, double torque, double* angle) const {
    if (sections_.size() == 1) {
        const double GJ = sections_[0].GJ, length = sections_[0].length;
        for (int k = 0; k < stations; ++k) angle[k] = GJ > 0.0 ? torque * length * k / (stations - 1) / GJ : 0.0;
        return;
    }
    for (const SectionProps& sec : sections_) {
        if (sec.GJ <= 0.0) {
            std::fill(angle, angle + stations, 0.0);
            return;
        }
    }
    for (int k = 0; k < stations; ++k) {
        const double s = line_.length * k / (stations - 1);
        double sum = 0.0;
        for (const SectionProps& sec : sections_) sum += torque * std::clamp(s - sec.s0, 0.0, sec.length) / sec.GJ;
        angle[k] = sum;
    }
}

void CableModel::expand(const double* q, const double* v, const double* a, const Loads& loads, double t,
                        double* X, double* Xd, double* Xdd) const {
    const int n = n_global();
    for (int g = 0; g < n; ++g) {
        const int j = free_[g];
        if (j < 0) continue;
        X[g] = coef_[g] * q[j];
        Xd[g] = coef_[g] * v[j];
        Xdd[g] = coef_[g] * a[j];
    }
    Vec3 p, pv, pa;
    loads.tow.evaluate(t, p, pv, pa);
    for (int k = 0; k < 3; ++k) {
        X[k] = p[k];
        Xd[k] = pv[k];
        Xdd[k] = pa[k];
    }
    const int gN = end_offset();
    if (farEnd_.anchored) {
        for (int k = 0; k < 3; ++k) {
            X[gN + k] = anchor_[k];
            Xd[gN + k] = 0.0;
            Xdd[gN + k] = 0.0;
        }
    } else if (farEnd_.driven) {
        loads.end.evaluate(t, p, pv, pa);
        for (int k = 0; k < 3; ++k) {
            X[gN + k] = p[k];
            Xd[gN + k] = pv[k];
            Xdd[gN + k] = pa[k];
        }
    }
}

void CableModel::restrict_to_free(const double* X, double* q) const {
    const bool clamped = params_.topEnd == UC_TOP_CLAMPED;
    const int n = n_global();
    for (int g = 0; g < n; ++g) {
        const int j = free_[g];
        if (j < 0) continue;
        if (clamped && g >= 3 && g < 6) {
            // The three components share one unknown a: r'_0 = a * topTangent.
            if (g == 3) q[j] = Eigen::Map<const Vec3>(X + 3).dot(topTangent_);
            continue;
        }
        q[j] = X[g];
    }
}

const double* CableModel::pushed_water(const Loads& loads, int e) {
    return loads.current.pushed ? loads.current.pushed + static_cast<size_t>(6 * kLoadQuadraturePoints) * e : nullptr;
}

void CableModel::load_point_positions(const double* X, double* x, double* y, double* z) const {
    for (int e = 0; e < nElements_; ++e) {
        const ElementTables& tables = tables_[elementRun_[e]];
        for (int g = 0; g < tables.nLoad; ++g) {
            const Vec3 r = interpolate(tables.load[g].shape.N, X + elementOffset_[e]);
            const size_t i = static_cast<size_t>(e) * kLoadQuadraturePoints + g;
            x[i] = r.x();
            y[i] = r.y();
            z[i] = r.z();
        }
    }
}

WaveExpansion* CableModel::point_wave_cache(size_t i) const {
    return waveCache_.empty() ? nullptr : &waveCache_[static_cast<size_t>(nElements_) * kLoadQuadraturePoints + i];
}

const double* CableModel::element_velocities(int e, const double* X, const double* Xd, double* buffer) const {
    const int g0 = elementOffset_[e];
    if (e != 0 || topRate_ == 0.0) return Xd + g0;
    top_material_velocity(X + g0, Xd + g0, buffer);  // the top element moves with the material
    return buffer;
}

Vec12 CableModel::top_rate_direction(const double* X) const {
    const ShapeValues s = hermite_shape(0.0, top_length());
    Vec12 d = Vec12::Zero();
    d.segment<3>(0) = Eigen::Map<const Vec3>(X + 3);
    for (int k = 0; k < 4; ++k) d.segment<3>(3) += s.d2N[k] * Eigen::Map<const Vec3>(X + 3 * k);
    return d;
}

void CableModel::top_material_velocity(const double* X, const double* Xd, double* Xm) const {
    Eigen::Map<Vec12> out(Xm);
    out = Eigen::Map<const Vec12>(Xd) + topRate_ * top_rate_direction(X);
}

void CableModel::element_residual(int e, const double* X, const double* Xd, const double* Xdd,
                                  const Loads& loads, double* R) const {
    const int g0 = elementOffset_[e];
    double Xm[12];
    const double *x = X + g0, *xd = element_velocities(e, X, Xd, Xm), *xdd = Xdd + g0;
    const ElementTables& tables = tables_[elementRun_[e]];
    const SectionProps& sec = sections_[runs_[elementRun_[e]].section];
    for (int a = 0; a < 12; ++a) R[a] = 0.0;
    add_mass_force(tables, sec.fluid.massPerLength, xdd, R);
    add_axial_force(tables, axial_at(e, X, Xd, loads), x, xd, R);
    if (sec.EI > 0.0) add_bending_force(tables, sec.EI, x, R);
    if (sec.bendingDamping > 0.0) add_bending_force(tables, sec.bendingDamping, xd, R);
    if (loads.torque != 0.0) add_torque_force(tables, loads.torque, x, R);
    add_hydro_force(tables, sec.fluid, loads.current, x, xd, xdd, R,
                    waveCache_.empty() ? nullptr : &waveCache_[static_cast<size_t>(e) * kLoadQuadraturePoints],
                    pushed_water(loads, e));
    if (sec.seabed.enabled) add_seabed_force(tables, sec.seabed, x, xd, R, loads.axialContactOnly);
    if (loads.seabedHold && sec.seabed.enabled)
        add_seabed_hold(tables, sec.seabed, loads.seabedHoldAcross, x, loads.seabedHold + g0, R, loads.axialContactOnly);
    if (loads.viv && phase_offset(e) >= 0)
        add_viv_force(tables, sec.fluid, sec.viv, loads.current, x, xd, X[phase_offset(e)], R,
                      waveCache_.empty() ? nullptr : &waveCache_[static_cast<size_t>(e) * kLoadQuadraturePoints]);
}

double CableModel::phase_residual(int e, const double* X, const double* Xd, const double* Xdd, const Loads& loads,
                                  VivPhaseJacobian* J) const {
    const int gp = phase_offset(e), g0 = elementOffset_[e];
    if (!loads.viv) {  // the statics: the phase held at its start
        if (J) {
            *J = VivPhaseJacobian{};
            J->dPhase = 1.0;
        }
        return X[gp] - initial_phase(e);
    }
    const SectionProps& sec = sections_[runs_[elementRun_[e]].section];
    double Xm[12];
    return viv_phase_residual(tables_[elementRun_[e]], sec.fluid, sec.viv, loads.current, X + g0,
                              element_velocities(e, X, Xd, Xm), Xdd + g0, X[gp], Xd[gp], J);
}

double CableModel::initial_phase(int e) const {
    // spread over 0 .. 2 pi along the line by the element's midpoint, so that the lift starts without a
    // common phase, rising from the far end to the tow point as MoorDyn's phases rise from a line's end A (its
    // anchor) to its end B (its fairlead, our tow point): the locked-in mode depends on the direction
    // (docs/model.md, "Vortex-induced vibration")
    return 2.0 * kPi * (1.0 - (element_start(e) + 0.5 * element_length(e)) / line_.length);
}

void CableModel::element_jacobian(int e, const double* X, const double* Xd, const double* Xdd,
                                  const Loads& loads, Mat12& K, Mat12& C, Mat12& M) const {
    const int g0 = elementOffset_[e];
    if (e == 0 && topRate_ != 0.0) {
        // The material velocity depends on the positions too: dXm/dX = rate d(top_rate_direction)/dX
        // (r'0 in the tow node's velocity, r''0 = sum_k d2N_k(0) X_k in its tangent rate).
        double Xm[12];
        element_jacobian_at(e, axial_at(e, X, Xd, loads), X + g0, element_velocities(e, X, Xd, Xm), Xdd + g0, loads, K, C, M);
        const ShapeValues s = hermite_shape(0.0, top_length());
        const Eigen::Matrix<double, 12, 3> Cr = C.middleCols<3>(0), Ct = C.middleCols<3>(3);
        K.middleCols<3>(3) += topRate_ * Cr;
        for (int k = 0; k < 4; ++k) K.middleCols<3>(3 * k) += (topRate_ * s.d2N[k]) * Ct;
        return;
    }
    element_jacobian_at(e, axial_at(e, X, Xd, loads), X + g0, Xd + g0, Xdd + g0, loads, K, C, M);
    if (loads.viv && phase_offset(e) >= 0) {
        double unused[12] = {};
        const SectionProps& sec = sections_[runs_[elementRun_[e]].section];
        add_viv_jacobian(tables_[elementRun_[e]], sec.fluid, sec.viv, loads.current, X + g0, Xd + g0, X[phase_offset(e)], K,
                         C, unused, waveCache_.empty() ? nullptr : &waveCache_[static_cast<size_t>(e) * kLoadQuadraturePoints]);
    }
}

void CableModel::element_viv_phase_column(int e, const double* X, const double* Xd, const Loads& loads,
                                          double* dR) const {
    for (int a = 0; a < 12; ++a) dR[a] = 0.0;
    if (!loads.viv || phase_offset(e) < 0) return;
    const int g0 = elementOffset_[e];
    const SectionProps& sec = sections_[runs_[elementRun_[e]].section];
    Mat12 K = Mat12::Zero(), C = Mat12::Zero();
    double Xm[12];
    add_viv_jacobian(tables_[elementRun_[e]], sec.fluid, sec.viv, loads.current, X + g0, element_velocities(e, X, Xd, Xm),
                     X[phase_offset(e)], K, C, dR,
                     waveCache_.empty() ? nullptr : &waveCache_[static_cast<size_t>(e) * kLoadQuadraturePoints]);
}

void CableModel::element_jacobian_at(int e, const AxialProps& axial, const double* x, const double* xd,
                                     const double* xdd, const Loads& loads, Mat12& K, Mat12& C, Mat12& M) const {
    const ElementTables& tables = tables_[elementRun_[e]];
    const SectionProps& sec = sections_[runs_[elementRun_[e]].section];
    K.setZero();
    C.setZero();
    M.setZero();
    add_mass_jacobian(tables, sec.fluid.massPerLength, M);
    add_axial_jacobian(tables, axial, x, xd, K, C);
    if (sec.EI > 0.0) add_bending_jacobian(tables, sec.EI, K);
    if (sec.bendingDamping > 0.0) add_bending_jacobian(tables, sec.bendingDamping, C);
    if (loads.torque != 0.0) add_torque_jacobian(tables, loads.torque, x, K);
    add_hydro_jacobian(tables, sec.fluid, loads.current, x, xd, xdd, K, C, M,
                       waveCache_.empty() ? nullptr : &waveCache_[static_cast<size_t>(e) * kLoadQuadraturePoints],
                       pushed_water(loads, e));
    if (sec.seabed.enabled) add_seabed_jacobian(tables, sec.seabed, x, xd, K, C, loads.axialContactOnly);
    if (loads.seabedHold && sec.seabed.enabled)
        add_seabed_hold_jacobian(tables, sec.seabed, loads.seabedHoldAcross, x, loads.seabedHold + elementOffset_[e], K,
                                 loads.axialContactOnly);
}

FarEnd FarEnd::of(int bottomEnd) {
    FarEnd f;
    f.bare = bottomEnd == UC_BOTTOM_FREE;
    f.anchored = bottomEnd == UC_BOTTOM_ANCHORED;
    f.driven = bottomEnd == UC_BOTTOM_EXTERNAL;
    f.held = f.anchored || f.driven;
    f.body = bottomEnd == UC_BOTTOM_TOWED_BODY || bottomEnd == UC_BOTTOM_PROXY;
    f.proxy = bottomEnd == UC_BOTTOM_PROXY;
    f.external = f.driven || f.proxy;
    return f;
}

// The estimate the loads point at, or none (a zero force).
static const ProxyEstimate& proxy_estimate(const Loads& loads) {
    static const ProxyEstimate none{};
    return loads.proxy ? *loads.proxy : none;
}

Vec3 ProxyEstimate::force(const Vec3& u, Mat3* dF_du) const {
    const Vec3 cross(-u.y(), u.x(), 0.0);  // z x u
    const double speed = std::sqrt(u.squaredNorm() + kProxyFlowSmoothing * kProxyFlowSmoothing);
    const Vec3 flow = along * u + across * cross;
    if (dF_du) {
        Mat3 J = Mat3::Zero();  // d(z x u)/du
        J(0, 1) = -1.0;
        J(1, 0) = 1.0;
        *dF_du = speed * (along * Mat3::Identity() + across * J) + flow * u.transpose() / speed;
    }
    return Eigen::Map<const Vec3>(constant) + speed * flow;
}

void ProxyEstimate::add(const Vec3& dF, const Vec3& u) {
    // the basis |u| u, |u| z x u (orthogonal): each coefficient takes the share w of dF's component
    // along it, the constant part the rest
    const Vec3 cross(-u.y(), u.x(), 0.0);
    const double speed = std::sqrt(u.squaredNorm() + kProxyFlowSmoothing * kProxyFlowSmoothing);
    const double u2 = u.squaredNorm(), c2 = cross.squaredNorm(), s4 = std::pow(kProxyFlowScale, 4);
    // the share of each direction by its own flow: across by the horizontal flow alone, which
    // vanishes where the flow turns vertical (a heaving body), along by the whole
    const double wa = u2 * u2 / (u2 * u2 + s4), wc = c2 * c2 / (c2 * c2 + s4);
    // a drag takes energy out of the motion: along stays >= 0 (what would make it negative, a
    // transient pushing the body ahead of its flow, goes to the constant part)
    const double a = std::max(u2 > 0.0 ? wa * dF.dot(u) / (speed * u2) : 0.0, -along);
    const double c = c2 > 0.0 ? wc * dF.dot(cross) / (speed * c2) : 0.0;
    along += a;
    across += c;
    Eigen::Map<Vec3>{constant} += dF - speed * (a * u + c * cross);
}

Mat3 PointBody::inertia() const {
    Mat3 M = (mass + addedMass) * Mat3::Identity();
    if (anisotropic) M += addedMassMatrix;
    return M;
}


void add_point_body_residual(const PointBody& body, const FluidProps& fluid, const CurrentField& current, WaveExpansion* waveCache,
                             const double* r, const double* rd, const double* rdd, Vec3& R) {
    Vec3 U, A;
    current.flow(Eigen::Map<const Vec3>(r), U, A, waveCache);  // the body's drag in the current and waves (no gradients)
    const Vec3 u = U - Eigen::Map<const Vec3>(rd);
    const double speed = std::sqrt(u.squaredNorm() + kDragVelocityFloor * kDragVelocityFloor);
    const double wet = (body.mass - fluid.rho * body.volume) * fluid.gravity;
    R += (body.mass + body.addedMass) * Eigen::Map<const Vec3>(rdd);
    if (body.anisotropic) R += body.addedMassMatrix * Eigen::Map<const Vec3>(rdd);
    R -= 0.5 * fluid.rho * body.CdA * speed * u;
    R.z() += wet;
    if (body.fluidInertia && current.accelerates()) {
        R -= (fluid.rho * body.volume + body.addedMass) * A;
        if (body.anisotropic) R -= body.addedMassMatrix * A;
    }
}

void point_body_jacobian(const PointBody& body, const FluidProps& fluid, const CurrentField& current, WaveExpansion* waveCache,
                         const double* r, const double* rd, Mat3& K, Mat3& C, Mat3& M) {
    Vec3 U, A;
    Mat3 dU, dA;
    current.flow(Eigen::Map<const Vec3>(r), U, dU, A, dA, waveCache);
    const Vec3 u = U - Eigen::Map<const Vec3>(rd);
    const double speed = std::sqrt(u.squaredNorm() + kDragVelocityFloor * kDragVelocityFloor);
    const Mat3 dDrag_du = 0.5 * fluid.rho * body.CdA * (speed * Mat3::Identity() + u * u.transpose() / speed);
    K.setZero();
    if (current.waves()) {
        K -= dDrag_du * dU;  // drag of the body in the waves' and current's gradients
    } else {
        K.col(2) -= dDrag_du * dU.col(2);  // drag of the body in a sheared current
    }
    if (body.fluidInertia && current.waves()) {
        K -= (fluid.rho * body.volume + body.addedMass) * dA;
        if (body.anisotropic) K -= body.addedMassMatrix * dA;
    }
    C = dDrag_du;
    M = body.inertia();
}

Vec6 CableModel::end_node_residual(const double* X, const double* Xd, const double* Xdd,
                                   const Loads& loads) const {
    const int gN = end_offset();
    Vec6 R = Vec6::Zero();
    const Vec3 rd = Eigen::Map<const Vec3>(Xd + gN);
    R.head<3>() = -loads.endLoad + loads.endLoadDamping * (rd - loads.endLoadVelocity);
    if (farEnd_.proxy) {
        Vec3 U, A;
        loads.current.flow(Eigen::Map<const Vec3>(X + gN), U, A, point_wave_cache(0));
        R.head<3>() -= proxy_estimate(loads).force(U - rd);
        if (loads.endSpring > 0.0) R.head<3>() += loads.endSpring * (Eigen::Map<const Vec3>(X + gN) - loads.endSpringAnchor);
    }
    // End couple M: virtual work M . (t x dr')/|r'| = (M x r')/|r'|^2 . dr' on the end tangent.
    const Vec3 rp = Eigen::Map<const Vec3>(X + gN + 3);
    R.tail<3>() = -loads.endCouple.cross(rp) / rp.squaredNorm();
    if (endContact_.footprint > 0.0 && endContact_.seabed.enabled)
        R.head<3>() += point_contact_load(endContact_, Eigen::Map<const Vec3>(X + gN), rd, nullptr);
    if (!farEnd_.body) return R;
    Vec3 body = R.head<3>();
    add_point_body_residual(body_, fluid(), loads.current, point_wave_cache(0), X + gN, Xd + gN, Xdd + gN, body);
    R.head<3>() = body;
    return R;
}

void CableModel::end_node_jacobian(const double* X, const double* Xd, const double* /*Xdd*/,
                                   const Loads& loads, Mat6& K, Mat6& C, Mat6& M) const {
    const int gN = end_offset();
    K.setZero();
    C.setZero();
    M.setZero();
    if (!loads.endCouple.isZero(0.0)) {
        const Vec3 rp = Eigen::Map<const Vec3>(X + gN + 3);
        const double n2 = rp.squaredNorm();
        K.block<3, 3>(3, 3) = -skew(loads.endCouple) * (Mat3::Identity() / n2 - 2.0 * rp * rp.transpose() / (n2 * n2));
    }
    C.block<3, 3>(0, 0) = loads.endLoadDamping;
    if (farEnd_.proxy) {
        // the estimate's velocity dependence (its dependence on the position through the current's
        // gradients is left out: a Newton matrix, not the residual)
        Vec3 U, A;
        loads.current.flow(Eigen::Map<const Vec3>(X + gN), U, A, point_wave_cache(0));
        Mat3 dF_du;
        proxy_estimate(loads).force(U - Eigen::Map<const Vec3>(Xd + gN), &dF_du);
        C.block<3, 3>(0, 0) += dF_du;
        if (loads.endSpring > 0.0) K.block<3, 3>(0, 0) += loads.endSpring * Mat3::Identity();
    }
    if (endContact_.footprint > 0.0 && endContact_.seabed.enabled) {
        SeabedJacobian J;
        point_contact_load(endContact_, Eigen::Map<const Vec3>(X + gN), Eigen::Map<const Vec3>(Xd + gN), &J);
        K.block<3, 3>(0, 0) += J.dr;
        C.block<3, 3>(0, 0) += J.drd;
    }
    if (!farEnd_.body) return;
    Mat3 Kb, Cb, Mb;
    point_body_jacobian(body_, fluid(), loads.current, point_wave_cache(0), X + gN, Xd + gN, Kb, Cb, Mb);
    K.block<3, 3>(0, 0) += Kb;
    C.block<3, 3>(0, 0) += Cb;
    M.block<3, 3>(0, 0) = Mb;
}

void CableModel::residual(const double* X, const double* Xd, const double* Xdd, const Loads& loads,
                          double* Rfree, ElementForces* forces) const {
    for (int j = 0; j < nFree_; ++j) Rfree[j] = 0.0;
    if (forces) forces->element.resize(nElements_);
    double Re[12];
    for (int e = 0; e < nElements_; ++e) {
        element_residual(e, X, Xd, Xdd, loads, Re);
        const int g0 = elementOffset_[e];
        for (int a = 0; a < 12; ++a) {
            const int j = free_[g0 + a];
            if (j >= 0) Rfree[j] += coef_[g0 + a] * Re[a];
        }
        if (forces) forces->element[e] = Eigen::Map<const Vec12>(Re);
        const int gi = internal_offset(e);
        if (gi >= 0) {
            double Xm[12];
            Rfree[free_[gi]] += visco_residual(tables_[elementRun_[e]], axial_at(e, X, Xd, loads), X + g0,
                                               element_velocities(e, X, Xd, Xm));
        }
        const int gp = phase_offset(e);
        if (gp >= 0) Rfree[free_[gp]] += phase_residual(e, X, Xd, Xdd, loads, nullptr);
    }
    const Vec6 end = end_node_residual(X, Xd, Xdd, loads);
    const int gN = end_offset();
    for (int k = 0; k < 6; ++k) {
        const int j = free_[gN + k];
        if (j >= 0) Rfree[j] += end[k];
    }
    if (forces) forces->endNodeTerms = end;
    for (const NodeAttachment& at : attachments_) {
        Vec3 Ra = Vec3::Zero();
        add_point_body_residual(at.body, fluid(), loads.current, point_wave_cache(1 + (&at - attachments_.data())), X + at.offset,
                                Xd + at.offset, Xdd + at.offset, Ra);
        if (at.contact.seabed.enabled)
            Ra += point_contact_load(at.contact, Eigen::Map<const Vec3>(X + at.offset), Eigen::Map<const Vec3>(Xd + at.offset),
                                     nullptr);
        for (int k = 0; k < 3; ++k) {
            const int j = free_[at.offset + k];
            if (j >= 0) Rfree[j] += Ra[k];
        }
    }
}

void CableModel::straight_line(const Vec3& p, const Vec3& direction, double* X) const {
    const Vec3 d = direction.normalized();
    for (int i = 0; i < nSlots_; ++i) {
        Eigen::Map<Vec3>(X + 6 * i) = p + d * slotArc_[i];
        Eigen::Map<Vec3>(X + 6 * i + 3) = d;
    }
    if (params_.topEnd == UC_TOP_CLAMPED) Eigen::Map<Vec3>(X + 3) = topTangent_;
}

}  // namespace uc
