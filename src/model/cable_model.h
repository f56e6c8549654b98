// cable_model.h - the compiled line description (sections, element tables, attachments, DOF map),
// immutable once built from the parameters, and the assembly of the residual and banded Jacobian
// over the free DOFs (docs/model.md, docs/lines.md).
//
// Global nodal coordinates X: node slot i holds [r_i, r'_i] at X[6i .. 6i+5]; element e spans the
// two slots from element_offset(e) (its 12 DOFs are contiguous). An element of a viscoelastic section
// has one more unknown, its internal strain, at X[internal_offset(e)] after all the node slots (its
// free index between those of the element's two nodes, so the Jacobian stays banded). Slot 0 is the tow point. A pinned
// joint between two sections has two slots: the second repeats the position (both map to the same
// free unknowns) and carries the tangent of the next section, so no moment passes the joint; every
// other node is one slot. Free DOFs q are what the integrator and the static solver see; every
// global DOF is either free, X[g] = coef[g] * q[free[g]] (coef is 1 except for a clamped top
// tangent, where r'_0 = a * topTangent with one free stretch a), or prescribed (tow point, anchor).
// The equations of prescribed DOFs are not solved: their residuals are the reaction forces.
#pragma once

#include <memory>
#include <vector>

#include "model/parameters.h"
#include "terms/hermite_element.h"
#include "terms/hydrodynamics.h"
#include "terms/seabed.h"
#include "terms/viv.h"

namespace uc {

// Motion of a driven end (the tow point, or the far end of bottomEnd 3) over one communication
// step [t0, t0 + h]: a quintic in time from the end's state (p0, v0, a0) at t0 to a target state
// (p1, v1, a1) at t0 + h. Each step starts from the state where the previous one ended, so the
// end never jumps in position, velocity or acceleration (C2 across communication points): the
// equations the integrator solves stay continuous there and it keeps its step size and order.
// With h = 0 it is a point in time: p0 + v0 (t - t0) + a0 (t - t0)^2 / 2 for every t.
struct TowTrajectory {
    double t0 = 0.0, h = 0.0;
    Vec3 p0 = Vec3::Zero(), v0 = Vec3::Zero(), a0 = Vec3::Zero();  // state at t0
    Vec3 p1 = Vec3::Zero(), v1 = Vec3::Zero(), a1 = Vec3::Zero();  // state at t0 + h

    static TowTrajectory at_rest_in_time(const Vec3& p, const Vec3& v, const Vec3& a, double t);
    static TowTrajectory quintic(double t0, double h, const Vec3& p0, const Vec3& v0, const Vec3& a0,
                                 const Vec3& p1, const Vec3& v1, const Vec3& a1);
    // The same point in time (t0) with the velocity scaled by lambda and no acceleration (the
    // static solver's load continuation).
    TowTrajectory steady(double lambda) const;
    void evaluate(double t, Vec3& p, Vec3& v, Vec3& a) const;

private:
    // p(t0 + s) = p0 + v0 s + a0 s^2/2 + c3 s^3 + c4 s^4 + c5 s^5
    Vec3 c3_ = Vec3::Zero(), c4_ = Vec3::Zero(), c5_ = Vec3::Zero();
};

// Everything the residual needs besides the state: prescribed motion and environment.
// bottomEnd 4: the proxy's estimate of the external body's forces other than the cable's, weight
// and buoyancy beyond the proxy's own. A hydrodynamic force (drag, a depressor's lift) turns with the
// flow and grows with its square, so the estimate keeps that part in the flow's frame: with u the
// flow relative to the body,
//   F(u) = constant + |u| (along u + across (z x u)),
// a drag law whose coefficients are estimated. The estimate's changes go to the law with the share
// w = |f|^4 / (|f|^4 + s^4) (s = kProxyFlowScale; f the flow of the term: u along, the horizontal
// flow across) and to the constant part otherwise: what is learnt at a crawl is not blown up by the
// square of a later speed. The law's along coefficient stays >= 0 (a drag, never a push along the
// flow, which would feed the proxy's motion). Applied at the proxy's velocity inside
// the implicit step, as a drag.
// Plain doubles (trivially copyable: part of the line's saved state).
struct ProxyEstimate {
    double constant[3] = {0.0, 0.0, 0.0};  // [N]
    double along = 0.0, across = 0.0;  // [N s^2/m^2]
    // The force at the relative flow u (Earth frame) and, if dF_du is not null, its derivative.
    Vec3 force(const Vec3& u, Mat3* dF_du = nullptr) const;
    // Adds the force change dF at the flow u: the share w of its components along u and z x u to the
    // law, the rest to the constant part. force(u) grows by dF (to round-off).
    void add(const Vec3& dF, const Vec3& u);
};
constexpr double kProxyFlowScale = 0.25;       // [m/s] s above
constexpr double kProxyFlowSmoothing = 1e-3;  // [m/s] |u| as sqrt(|u|^2 + this^2): smooth at rest

// What the line's far end is, decided once from bottomEnd when the model is built (the physics asks
// these questions, never the parameter's number).
struct FarEnd {
    bool bare = false;      // nothing is at it: a free tip (0)
    bool anchored = false;  // held at anchor.x/y/z (1)
    bool driven = false;    // moves with the master's end.* inputs (3)
    bool held = false;      // its position is prescribed, no unknowns: anchored or driven
    bool body = false;      // it carries a point body: the internal towed body (2) or the proxy (4)
    bool proxy = false;     // the body is the cable's proxy of an external body (4)
    bool external = false;  // an external body is at it, where the end.* inputs say: driven or proxy
    static FarEnd of(int bottomEnd);
};

struct Loads {
    TowTrajectory tow;
    TowTrajectory end;  // far end when bottomEnd = 3 (external body)
    CurrentField current;
    Vec3 endLoad = Vec3::Zero();
    // Velocity linearization of endLoad (a partner model's force, evaluated by the partner at the far-end
    // velocity endLoadVelocity): the force applied is endLoad - endLoadDamping (v_end - endLoadVelocity),
    // so its velocity dependence is integrated implicitly with the cable (docs/cosimulation.md).
    Vec3 endLoadVelocity = Vec3::Zero();
    Mat3 endLoadDamping = Mat3::Zero();
    Vec3 endCouple = Vec3::Zero();
    // bottomEnd 4: the estimate of the external body's other forces, applied to the proxy at the far end
    // (the line's state holds it; null: none, a zero force).
    const ProxyEstimate* proxy = nullptr;
    // Static solver only (bottomEnd 4): a spring of this stiffness [N/m] holds the far end at
    // endSpringAnchor, so that the statics put the proxy where the external body is.
    double endSpring = 0.0;
    Vec3 endSpringAnchor = Vec3::Zero();
    double torque = 0.0;  // H [N.m] (0 unless torsion is enabled)
    // Caps the axial stiffness factor of every strain mode (static solver only: equilibrium is
    // first found on a soft cable, whose large rotations do not turn into huge axial residuals,
    // then stiffened to the real EA).
    double axialStiffnessScale = 1.0;
    // Static solver only: use the two-sided axial law even when the cable is tension-only (the
    // continuation starts from a guess that may be slack, where a tension-only cable without
    // bending stiffness has no stiffness at all).
    bool twoSidedAxial = false;
    // Static solver only: seabed contact at the elements' axial points even where a denser contact
    // rule is asked for (seabedContactSpacing): the continuation runs on the coarser contact.
    bool axialContactOnly = false;
    // Static solver only: the seabed's static friction holds what rests on it across the line where the
    // line's planar profile laid it (add_seabed_hold): the held DOFs (n_global, null: no hold) and the
    // direction along the seabed across the profile's plane.
    const double* seabedHold = nullptr;
    Vec3 seabedHoldAcross = Vec3::Zero();
    // Vortex-induced vibration acts (the lift, the phases' synchronisation); false in the static solver:
    // no lift, each phase held at its start (CableModel::initial_phase).
    bool viv = true;
    // The Syrope elements' history, eps_max per element (the line's state, beside the internal strains it pairs
    // with; CableModel::history_size); null where the model has no Syrope element.
    const double* syropeHistory = nullptr;
};

// Residual contributions of one element and of the far-end node terms, kept for outputs.
struct ElementForces {
    std::vector<Vec12> element;  // per element, residual over its 12 DOFs
    Vec6 endNodeTerms = Vec6::Zero();  // body, end load and end couple residual at node N
};

// A point body: an attachment on a node, or the towed body at the far end.
struct PointBody {
    double mass = 0.0, volume = 0.0, addedMass = 0.0, CdA = 0.0;
    bool fluidInertia = false;  // accelerating water pushes it (enableBodyFluidInertia)
    // An added-mass matrix (Earth frame) on top of addedMass I; used only when anisotropic, so a body
    // without one computes exactly as before.
    Mat3 addedMassMatrix = Mat3::Zero();
    bool anisotropic = false;
    // (mass + addedMass) I + addedMassMatrix: the inertia of its translation.
    Mat3 inertia() const;
};

// Residual terms of a point body at position r (velocity rd, acceleration rdd) in the water: inertia
// (mass and added mass), submerged weight, drag on the velocity relative to the current and waves, and
// with fluidInertia the push of accelerating water (rho V + added mass) A (Froude-Krylov plus added
// mass). Added to R (3 values) in that order. waveCache: null, or the body's slot for the waves' expansion.
void add_point_body_residual(const PointBody& body, const FluidProps& fluid, const CurrentField& current, WaveExpansion* waveCache,
                             const double* r, const double* rd, const double* rdd, Vec3& R);
// Its derivatives with respect to r, rd and rdd.
void point_body_jacobian(const PointBody& body, const FluidProps& fluid, const CurrentField& current, WaveExpansion* waveCache,
                         const double* r, const double* rd, Mat3& K, Mat3& C, Mat3& M);

// One section of the line, compiled from the parameters: what the element physics reads.
struct SectionProps {
    double s0 = 0.0;      // arc length of its start from the tow point [m]
    double length = 0.0;  // unstretched [m]
    FluidProps fluid{};   // mass per length, diameter, coefficients (and the water's density, gravity)
    AxialProps axial{};
    AxialCurve curve{};    // n 0: the constant axial.EA; else the tension-strain curve (axial.EA its secant)
    ViscoProps visco{};    // EAd 0: none; else the viscoelastic model (axial.EA = visco.EAs, the static EA)
    SyropeProps syrope{};  // form 0: none; else the Syrope model (visco: its internal strain, the slow strain)
    bool viscoelastic() const { return visco.EAd > 0.0; }
    VivProps viv{};        // Cl 0: no vortex-induced vibration
    SeabedProps seabed{};  // the contact's smoothing depends on the diameter
    double EI = 0.0;       // 0 when bending is disabled
    double bendingDamping = 0.0;  // EI * axialDamping / EA [N.m2.s]
    double GJ = 0.0;
    int nElements = 0;  // before attachments cut it (the winch's mesh for the first section)
    int joint = 0;  // to the next section: 0 rigid (one node), 1 pinned (two slots)
    double MBL = 0.0;  // minimum breaking load [N] (0: not given), for the utilisation outputs
};

// Elements of equal length in a row: one section, or the part of one between attachments.
struct ElementRun {
    double s0 = 0.0, elementLength = 0.0;
    int first = 0, count = 0;
    int section = 0;
};

struct NodeAttachment {
    int offset = 0;  // global index of the node's position
    double s = 0.0;  // arc length [m]
    PointBody body;
    PointContact contact;  // its own seabed contact (docs/model.md, "Seabed")
};

// Whole-line scales for tolerances, continuation and guesses. For a uniform line they are its
// parameters; for sections: the total length, the mean mass per length (total mass / length) and the
// largest EA, EI and diameter.
struct LineScales {
    double length = 0.0, massPerLength = 0.0, EA = 0.0, EI = 0.0, diameter = 0.0;
};

// The winch's mesh of the first section (docs/winch.md): `elements` elements, the top one (at the
// tow point) of unstretched length topLength, the others of the nominal length.
struct WinchMesh {
    int elements = 0;
    double topLength = 0.0;
};

// What the static profile of a line held at both ends sets before the model is built
// (src/model/mesh_grading.h): where the nodes go, and whether the line rests on the seabed at its anchor.
struct StaticLayout {
    // Arc lengths of the nodes from the tow point (0 first, the length last), with every section
    // end and attachment among them; empty: each section's elements of equal length.
    std::vector<double> nodes;
    // An anchor on the seabed is held at the height the line rests at next to it.
    bool anchorResting = false;
    bool operator==(const StaticLayout& o) const { return nodes == o.nodes && anchorResting == o.anchorResting; }
};

class CableModel {
public:
    // winch: the first section's mesh when winchMode != 0 (null: the start, all elements nominal).
    // layout: the mesh graded by the static profile and the anchor's resting height (null: each
    // section's elements of equal length between its attachments, the anchor where it is given).
    // seabedGrid: the seabed given as a grid (seabed.file, a deck's SeafloorFile), null for the plane of
    // the parameters.
    explicit CableModel(const UCParams& params, const WinchMesh* winch = nullptr,
                        const StaticLayout* layout = nullptr, std::shared_ptr<const SeabedGrid> seabedGrid = nullptr);

    // The winch (winchMode != 0): only the top element's length changes between remeshes; it is
    // the one mutable part of the description (its tables and the arc lengths below it follow).
    bool winch() const { return winchMesh_.elements > 0; }
    const WinchMesh& winch_mesh() const { return winchMesh_; }  // as built (topLength: at the build)
    double winch_nominal() const { return winchNominal_; }       // nominal element length
    double top_length() const { return runs_[0].elementLength; }
    // seabedContactSpacing where the seabed is on (0 otherwise: no contact rule to build).
    double contact_spacing() const { return params().enableSeabed ? params().seabedContactSpacing : 0.0; }
    void set_top_length(double length);  // no allocation
    // The winch's speed (+ pays out): the line runs through the sheave at it, so the material at
    // the tow node moves with the sheave plus `rate` along the line. The top element's velocity
    // field is the material's: at the tow node velocity v0 + rate r'0 and tangent rate
    // v'0 + rate r''0 (docs/winch.md, "The top element's velocity").
    void set_top_rate(double rate) { topRate_ = winch() ? rate : 0.0; }
    double top_rate() const { return topRate_; }
    // The top element's 12 nodal velocities of the material (Xd of the element where the rate is 0).
    void top_material_velocity(const double* X, const double* Xd, double* Xm) const;
    // d(top_material_velocity)/d(rate): [r'0, r''0, 0, 0] of the top element.
    Vec12 top_rate_direction(const double* X) const;
    // The 12 velocities element e's forces see: Xd's, or the material's in the winch's top element
    // (written to buffer).
    const double* element_velocities(int e, const double* X, const double* Xd, double* buffer) const;

    const UCParams& params() const { return params_; }
    int n_elements() const { return nElements_; }
    // The load points (the Morison terms' quadrature points): kLoadPoints per element, element-major.
    static constexpr int kLoadPoints = 3;
    int n_load_points() const { return kLoadPoints * nElements_; }
    // Their positions at the global vector X, into x, y, z (n_load_points() each).
    void load_point_positions(const double* X, double* x, double* y, double* z) const;
    // Element e's slice of the water pushed by the importer (CurrentField::pushed), or null.
    static const double* pushed_water(const Loads& loads, int e);
    int n_slots() const { return nSlots_; }  // node slots: nodes plus one per pinned joint
    int n_global() const { return 6 * nSlots_ + nInternal_ + nPhase_; }
    int n_internal() const { return nInternal_; }  // internal strains (viscoelastic elements)
    // Global index of element e's internal strain, -1 where it has none.
    int internal_offset(int e) const { return internalOffset_.empty() ? -1 : internalOffset_[e]; }
    // Global index of element e's VIV phase [rad] (its rate the phase's rate), -1 where it has none.
    int phase_offset(int e) const { return phaseOffset_.empty() ? -1 : phaseOffset_[e]; }
    int n_phases() const { return nPhase_; }
    // The phase's equation of element e (R = phi' - the synchronisation model's rate; with loads.viv false
    // R = phi - initial_phase(e)) and, J non-null, its derivatives.
    double phase_residual(int e, const double* X, const double* Xd, const double* Xdd, const Loads& loads,
                          VivPhaseJacobian* J) const;
    // The phase element e starts with: 2 pi times the arc length of its midpoint over the line's length.
    double initial_phase(int e) const;
    // dR/dphi of element e's 12 residuals (the lift's phase column; zeros where it has none).
    void element_viv_phase_column(int e, const double* X, const double* Xd, const Loads& loads, double* dR) const;
    // Every element's internal strain at equilibrium with its present mean strain (X), rate 0 (Xd); a Syrope
    // element's slow strain at the start's mean tension (syrope.tensionMean0) on the working curve of its history.
    void settle_internal(double* X, double* Xd, const double* history) const;
    // A Syrope element's slow strain rate at X, Xd, from its internal equation with the rate term out (the start:
    // the slow strain need not be at rest with the element's strain). Writes Xd of every Syrope element.
    void syrope_rates(const double* X, double* Xd, const double* history) const;
    // The Syrope elements' history: per element the original working curve's strain at the largest mean tension
    // so far (terms/syrope.h), history_size() values (0: no Syrope element; 0 for an element of another model).
    // The model holds none: it is the line's state (CableSimulation, saved with the unknowns), which the model
    // reads through Loads::syropeHistory or the argument `history`.
    int history_size() const { return syrope_ ? nElements_ : 0; }
    void initial_history(double* history) const;  // the start's (syrope.tensionMax0)
    // After a step that reached X: the history of each Syrope element whose slow strain passed onto the
    // original working curve grows to it.
    void advance_history(const double* X, double* history) const;
    // The axial properties element e's tension comes from at X, Xd (and the Syrope history): the section's (with
    // its viscoelastic model and internal strain where it has one).
    AxialProps element_axial(int e, const double* X, const double* Xd, const double* history) const;
    int n_free() const { return nFree_; }
    int free_bandwidth() const { return bandwidth_; }  // max |i - j| of coupled free DOFs
    const LineScales& line() const { return line_; }
    int n_sections() const { return static_cast<int>(sections_.size()); }
    const SectionProps& section(int k) const { return sections_[k]; }
    // True when a section's axial stiffness is a tension-strain curve.
    bool axial_curve() const {
        for (const SectionProps& s : sections_)
            if (s.curve.n > 0) return true;
        return false;
    }
    const std::vector<ElementRun>& runs() const { return runs_; }
    const std::vector<NodeAttachment>& attachments() const { return attachments_; }

    // The compiled description of element e.
    int element_offset(int e) const { return elementOffset_[e]; }  // global index of its first DOF
    int end_offset() const { return 6 * nSlots_ - 6; }              // the far end's node
    double element_length(int e) const { return runs_[elementRun_[e]].elementLength; }
    double element_start(int e) const;                               // arc length of its first node
    const ElementTables& tables(int e) const { return tables_[elementRun_[e]]; }
    // True when some element integrates its seabed contact at more points than its axial ones.
    bool dense_contact() const {
        for (const ElementTables& t : tables_)
            if (t.nContact > 0) return true;
        return false;
    }
    const SectionProps& element_section(int e) const { return sections_[runs_[elementRun_[e]].section]; }
    // The element holding arc length s (clamped to the line) and the local coordinate xi there.
    void locate(double s, int& e, double& xi) const;
    // Arc length of node slot i as a fraction of the line length; exactly i / N for a uniform line.
    double slot_fraction(int i) const;

    const FluidProps& fluid() const { return sections_[0].fluid; }  // water density and gravity
    const SeabedProps& seabed() const { return sections_[0].seabed; }
    const CurrentProfile& current_profile() const { return profile_; }
    const SeaState& sea() const { return sea_; }
    const FarEnd& far_end() const { return farEnd_; }  // what the far end is
    const PointBody& body() const { return body_; }
    // The anchor's position: anchor.x/y/z, or on the seabed the height the line rests at there.
    const Vec3& anchor() const { return anchor_; }
    bool anchor_resting() const { return anchorResting_; }  // held at the line's resting height
    // The height at which the last section rests on the seabed above (x, y) (the seabed's height there,
    // z = -waterDepth where it is flat, less its resting penetration under its own submerged weight).
    double resting_height(double x, double y) const;
    // The seabed as given (parameters, not raised by a rest penetration): its height above (x, y),
    // -waterDepth where it is flat, and the horizontal gradient of that height (zero where flat).
    double seabed_height(double x, double y) const;
    Eigen::Vector2d seabed_gradient() const;
    // The gradient under (x, y): the plane's, or the grid's local one.
    Eigen::Vector2d seabed_gradient(double x, double y) const;
    const std::shared_ptr<const SeabedGrid>& seabed_grid() const { return seabedGrid_; }
    // Torque of torqueMode 2 for a twist angle of the far end against the tow point: the line's
    // torsional compliance is the sum of L_k / GJ_k over its sections.
    double torque_for_twist(double twist) const;
    // Axial compliance of the whole line, the sum of L_k / EA_k over its sections [m/N].
    double axial_compliance() const;
    // Twist angle under the torque H (0 when a section has no torsional stiffness) at each of
    // `stations` stations spread evenly over the line, into angle[0 .. stations - 1].
    void twist_angles(int stations, double torque, double* angle) const;
    // Arc length of node slot i (both slots of a pinned joint have the joint's).
    double slot_arc_length(int i) const { return slotArc_[i]; }

    int free_index(int g) const { return free_[g]; }
    double coefficient(int g) const { return coef_[g]; }

    // Global X, Xdot, Xddot from free q, v, a and the prescribed motion at time t.
    void expand(const double* q, const double* v, const double* a, const Loads& loads, double t,
                double* X, double* Xd, double* Xdd) const;
    // Free q, v from a global configuration (prescribed entries are ignored).
    void restrict_to_free(const double* X, double* q) const;

    // Residual of one element (12 values): mass, axial, bending, hydrodynamics.
    void element_residual(int e, const double* X, const double* Xd, const double* Xdd,
                          const Loads& loads, double* R) const;
    // Far-end node terms at node N ([r_N, r'_N] rows): towed body inertia, drag and weight minus
    // the end load; minus the generalized force of the end couple on r'_N.
    Vec6 end_node_residual(const double* X, const double* Xd, const double* Xdd, const Loads& loads) const;

    // Free residual R_free[j] = sum_g coef[g] R[g]; fills forces (may be null) for outputs.
    void residual(const double* X, const double* Xd, const double* Xdd, const Loads& loads,
                  double* Rfree, ElementForces* forces) const;

    // Jacobian blocks of the free residual with respect to q, v and a, delivered through
    // add(row, col, dq, dv, da) with free indices row, col.
    template <class Sink>
    void jacobian(const double* X, const double* Xd, const double* Xdd, const Loads& loads,
                  Sink&& add) const;

    // Element Jacobians (dR/dX, dR/dXdot, dR/dXddot) for tests and assembly.
    void element_jacobian(int e, const double* X, const double* Xd, const double* Xdd,
                          const Loads& loads, Mat12& K, Mat12& C, Mat12& M) const;
    // Element e's internal strain couplings (viscoelastic elements; false where it has none).
    bool element_visco_jacobian(int e, const double* X, const double* Xd, const Loads& loads, ViscoJacobian& J) const {
        if (internal_offset(e) < 0) return false;
        double Xm[12];
        visco_jacobian(tables(e), axial_at(e, X, Xd, loads), X + elementOffset_[e], element_velocities(e, X, Xd, Xm), J);
        return true;
    }
    void end_node_jacobian(const double* X, const double* Xd, const double* Xdd, const Loads& loads,
                           Mat6& K, Mat6& C, Mat6& M) const;

    // Straight line from p along `direction` (unstretched), as global X.
    void straight_line(const Vec3& p, const Vec3& direction, double* X) const;

private:
    AxialProps scaled_axial(const SectionProps& section, const Loads& loads) const;
    // scaled_axial of element e's section with its viscoelastic model and internal strain at X, Xd.
    AxialProps axial_at(int e, const double* X, const double* Xd, const Loads& loads) const;
    // element_jacobian at the element's own 12 values x, xd, xdd (the velocities as given).
    void element_jacobian_at(int e, const AxialProps& axial, const double* x, const double* xd, const double* xdd,
                             const Loads& loads, Mat12& K, Mat12& C, Mat12& M) const;
    void build_sections(const UCParams& p);
    void build_mesh(const UCParams& p, const std::vector<double>* nodes);
    void build_slots();
    int section_at(double s) const;  // the section holding arc length s (its start belongs to it)
    void place_attachments(const std::vector<std::pair<double, PointBody>>& points);
    void build_dof_map();

    UCParams params_;
    std::shared_ptr<const SeabedGrid> seabedGrid_;
    FarEnd farEnd_;
    int nElements_ = 0;
    int nSlots_ = 0;
    LineScales line_;
    std::vector<SectionProps> sections_;
    std::vector<ElementRun> runs_;
    std::vector<ElementTables> tables_;  // one per run
    std::vector<int> elementRun_, elementOffset_;
    std::vector<double> slotArc_;
    std::vector<bool> duplicateSlot_;  // the second slot of a pinned joint
    std::vector<double> pinnedAttachments_;  // arc lengths of attachments on pinned nodes
    std::vector<NodeAttachment> attachments_;
    // The winch's mesh and the arc lengths at its build, which set_top_length shifts.
    WinchMesh winchMesh_;
    double winchNominal_ = 0.0;
    double topRate_ = 0.0;
    std::vector<double> slotArcBase_, runStartBase_, sectionStartBase_, attachmentBase_;
    LineScales lineBase_;
    double lineMassBase_ = 0.0;
    PointBody body_;  // the towed body (bottomEnd 2)
    // The seabed contact of a free end's node (the towed body's, or the tip beyond the last
    // element's outer contact point), footprint 0 where it has none.
    PointContact endContact_;
    Vec3 topTangent_;
    Vec3 anchor_;
    bool anchorResting_ = false;
    CurrentProfile profile_;
    SeaState sea_;
    // The waves' expansion at each load point (element-major), then at the towed body and at each
    // attachment, reused while the point stays in its lattice cell: a cache of pure functions of
    // position and time, so it changes no result.
    mutable std::vector<WaveExpansion> waveCache_;
    // Slot i of the point bodies (0 the towed body, 1 + k attachment k); null in calm water.
    WaveExpansion* point_wave_cache(size_t i) const;
    std::vector<int> free_;
    std::vector<double> coef_;
    int nInternal_ = 0;
    std::vector<int> internalOffset_;  // per element (empty: no viscoelastic element)
    bool syrope_ = false;              // an element has the Syrope model (history_size)
    int nPhase_ = 0;
    std::vector<int> phaseOffset_;  // per element (empty: no element with VIV)
    int nFree_ = 0;
    int bandwidth_ = 0;
};

template <class Sink>
void CableModel::jacobian(const double* X, const double* Xd, const double* Xdd, const Loads& loads,
                          Sink&& add) const {
    Mat12 K, C, M;
    for (int e = 0; e < nElements_; ++e) {
        element_jacobian(e, X, Xd, Xdd, loads, K, C, M);
        const int g0 = elementOffset_[e];
        for (int a = 0; a < 12; ++a) {
            const int ja = free_[g0 + a];
            if (ja < 0) continue;
            const double ca = coef_[g0 + a];
            for (int b = 0; b < 12; ++b) {
                const int jb = free_[g0 + b];
                if (jb < 0) continue;
                const double cab = ca * coef_[g0 + b];
                add(ja, jb, cab * K(a, b), cab * C(a, b), cab * M(a, b));
            }
        }
        const int gp = phase_offset(e);
        if (gp >= 0) {
            // the VIV phase's couplings: its row (the rate, and the acceleration through the cross-flow
            // motion's phase), its column in the element's rows (the lift)
            const int jp = free_[gp];
            VivPhaseJacobian P;
            phase_residual(e, X, Xd, Xdd, loads, &P);
            double dLift[12];
            element_viv_phase_column(e, X, Xd, loads, dLift);
            for (int a = 0; a < 12; ++a) {
                const int ja = free_[g0 + a];
                if (ja < 0) continue;
                const double ca = coef_[g0 + a];
                add(ja, jp, ca * dLift[a], 0.0, 0.0);
                add(jp, ja, ca * P.dX[a], ca * P.dXd[a], ca * P.dXdd[a]);
            }
            add(jp, jp, P.dPhase, P.dPhaseRate, 0.0);
        }
        const int gi = internal_offset(e);
        if (gi < 0) continue;
        // the internal strain's couplings: its row (no acceleration), its column in the element's rows
        const int ji = free_[gi];
        double Xm[12];
        ViscoJacobian J;
        visco_jacobian(tables(e), axial_at(e, X, Xd, loads), X + g0, element_velocities(e, X, Xd, Xm), J);
        for (int a = 0; a < 12; ++a) {
            const int ja = free_[g0 + a];
            if (ja < 0) continue;
            const double ca = coef_[g0 + a];
            add(ja, ji, ca * J.dR_de1[a], ca * J.dR_dr1[a], 0.0);
            add(ji, ja, ca * J.dI_dX[a], ca * J.dI_dXd[a], 0.0);
        }
        add(ji, ji, J.dI_de1, J.dI_dr1, 0.0);
    }
    Mat6 Kn, Cn, Mn;
    end_node_jacobian(X, Xd, Xdd, loads, Kn, Cn, Mn);
    const int gN = end_offset();
    for (int a = 0; a < 6; ++a) {
        const int ja = free_[gN + a];
        if (ja < 0) continue;
        for (int b = 0; b < 6; ++b) {
            const int jb = free_[gN + b];
            if (jb < 0) continue;
            if (Kn(a, b) != 0.0 || Cn(a, b) != 0.0 || Mn(a, b) != 0.0) add(ja, jb, Kn(a, b), Cn(a, b), Mn(a, b));
        }
    }
    for (const NodeAttachment& at : attachments_) {
        Mat3 Ka, Ca, Ma;
        point_body_jacobian(at.body, fluid(), loads.current, point_wave_cache(1 + (&at - attachments_.data())), X + at.offset, Xd + at.offset, Ka, Ca, Ma);
        if (at.contact.seabed.enabled) {
            SeabedJacobian J;
            point_contact_load(at.contact, Eigen::Map<const Vec3>(X + at.offset), Eigen::Map<const Vec3>(Xd + at.offset), &J);
            Ka += J.dr;
            Ca += J.drd;
        }
        for (int a = 0; a < 3; ++a) {
            const int ja = free_[at.offset + a];
            if (ja < 0) continue;
            for (int b = 0; b < 3; ++b) {
                const int jb = free_[at.offset + b];
                if (jb >= 0) add(ja, jb, Ka(a, b), Ca(a, b), Ma(a, b));
            }
        }
    }
}

}  // namespace uc
