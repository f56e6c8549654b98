// mooring_system.h - a mooring system read from a deck (docs/systems_mooring.md): several lines, each
// from its fairlead on a coupled body or a coupled point to an anchor (or another coupled end). Lines
// joined only through prescribed motion do not act on each other, so each is integrated by its own
// CableSimulation, exactly as a single line is; the system turns the bodies' and points' inputs into each
// line's end motion and sums the lines' forces into the bodies' loads and their quasi-static stiffness.
// Free points where three or more lines meet and free bodies (free nodes) end the lines there: their
// statics are solved by Newton's method on the lines' static solutions, and the free nodes are stepped
// with their lines, the node's motion found within each step from its equation of motion.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "deck/line_file.h"
#include "model/line_profile.h"
#include "line/simulation.h"
#include "line/simulation_interface.h"

namespace uc {

// R = Rx(roll) Ry(pitch) Rz(yaw): a body's orientation from its angles, MoorDyn's convention.
Mat3 body_rotation(double roll, double pitch, double yaw);
// The rotation by the angle |turn| about turn's direction (a rotation vector).
Mat3 turn_matrix(const Vec3& turn);

// A coupled body's orientation from its inputs as bodyOrientation reads them: UC_ORIENTATION_ANGLES_XYZ
// body_rotation of its angles, UC_ORIENTATION_QUATERNION its quaternion q0..q3 (scalar first) normalized,
// UC_ORIENTATION_ANGLES_ZYX R = Rz(yaw) Ry(pitch) Rx(roll) (OpenFAST's and MoorPy's).
Mat3 coupled_body_rotation(const UCCoupledBody& body, int orientation);

// The system's kinds of line, decided here once from the deck (mooring_line_params gives each line the bottomEnd
// that follows from them): a line's far end is held where held_far_end says (at its anchor, bottomEnd 1; on a
// coupled body or point or on a free node, driven, bottomEnd 3), or it hangs from its fairlead (nullptr: bottomEnd
// 0, or 2 with a towed body). A line with an end on a free node is stepped with the nodes (on_free_node).
const MooringEnd* held_far_end(const MooringDeckLine& l);
// A free node's unknowns: 3 for a point (its position) and a pinned body (its rotation), 6 for a free body.
inline int node_unknowns(const MooringNode& n) { return n.body && !n.pinned ? 6 : 3; }
bool on_free_node(const MooringDeckLine& l);

// The breaking strength of sections firstSection..lastSection of a line (docs/design_checks.md): the MBL at
// either end, the smallest given, and the largest tension over MBL at its elements' ends in the state of
// the line's last outputs (0 where no MBL is given).
struct LineStrength {
    double fairleadMBL = 0.0, anchorMBL = 0.0, smallestMBL = 0.0;  // [N]
    double maxUtilisation = 0.0;
};
LineStrength line_strength(const CableSimulation& line, int firstSection, int lastSection);

// line[k].* of a line, or of one section of it, whose ends' tensions are fairlead and anchor, from the
// outputs of the line it is (its minimum tension and grounded length are the whole line's) and its strength.
void set_mooring_line_outputs(UCMooringLine& out, double fairlead, double anchor, const UCOutputs& line,
                              const LineStrength& strength);

// One line given by its parameters, as the boundary sees it: a system of one line, whose line[1].* outputs
// are its own (its outputs otherwise the line's), filled where the line makes its outputs.
// With failure.line = 1 its far end (an anchor, a towed body, a driven end) lets go at failure.time or where the
// far end's tension reaches failure.tension, whichever comes first, and the line goes on with a bare far end
// (docs/line_failure.md, "One line"): the step that holds the break is taken in pieces that end at it, as a mooring
// system's (src/system/failure.cpp).
class OneLineSystem final : public CableSimulation {
public:
    explicit OneLineSystem(const UCParams& params);
    // The failure.* parameters of one line: empty where they are accepted, else why not (one line).
    static std::string check_failure(const UCParams& p);

    using CableSimulation::step;
    bool step(double t, double h, const UCInputs& in, std::string& error) override;
    void set_stop_at_breaks(bool stop) override { stopAtBreaks_ = stop; }
    std::string take_event() override;
    // Trials of a step's piece that located the last step's break by tension.
    int failure_evaluations() const { return failureEvaluations_; }
    static constexpr int kLocateIterations = 40;  // as a mooring system's

private:
    void complete_outputs(UCOutputs& out) const override;
    bool breaks_ = false;  // failure.line = 1
    double failTime_ = 0.0, failTension_ = 0.0;
    bool stopAtBreaks_ = false;  // (a setting of the importer's, not of the state)
    int failureEvaluations_ = 0;
    std::string event_;
    std::vector<unsigned char> buffer_;  // the state at a piece's start (a break by tension located)
};

// The motion of a free node (docs/systems_mooring.md, "Dynamics"): all of it that a step changes and the next
// step starts from, in plain doubles. A step's start is a copy of the nodes' motions and a saved state holds
// their bytes: whatever belongs to a node's motion is in here, and so saved and restored with it.
struct FreeNodeMotion {
    double position[3], velocity[3], acceleration[3];  // of its reference point
    // the inputs that its lines' ends at a free point are given (their extrapolation to the step's end is the
    // point's motion there)
    double inputPosition[3], inputVelocity[3], inputAcceleration[3];
    double rotation[9];         // a free body's orientation, column by column (identity for a point)
    double omega[3], alpha[3];  // a free body's angular velocity and acceleration
    double step;                // of the step the motion is at the end of (0: at rest)
};
static_assert(std::is_trivially_copyable_v<FreeNodeMotion>, "a free node's motion is saved as its bytes");

// The state of a line failure (docs/line_failure.md), in plain doubles: saved with the nodes' motion. From
// its break on, its lines' ends are on a free node of its own (massless), after the deck's free nodes and
// the nodes of the failures before it that broke.
struct FailureState {
    double broken;   // 1 from the break on, 0 before
    double time;     // of the break [s]
    double tension;  // the largest tension of its lines at the point, at the break [N]
};
static_assert(std::is_trivially_copyable_v<FailureState> && sizeof(FailureState) == 3 * sizeof(double),
              "a failure's state is saved as its bytes");

class MooringSystem final : public Simulation {
public:
    // The lines' parameters are base with each line's deck properties; false (error) where one is refused.
    MooringSystem(const UCParams& base, const MooringDeck& deck);
    bool build(std::string& error);  // once, after construction

    bool initialize(double t0, const UCInputs& in, std::string& error) override;
    bool step(double t, double h, const UCInputs& in, std::string& error) override;
    std::string take_event() override;
    void set_current_grid(std::shared_ptr<const CurrentGrid> grid) override;
    // The water pushed by the importer: every line's load points one after the other (system/pushed_water.cpp).
    std::size_t water_points() const override;
    void water_positions(double* x, double* y, double* z) const override;
    void set_water(double t, const double* const u[3], const double* const a[3]) override;
    void set_seabed_grid(std::shared_ptr<const SeabedGrid> grid) override;
    // A step with a break strictly inside it ends at the break (time() then the break's), the state there.
    void set_stop_at_breaks(bool stop) override { stopAtBreaks_ = stop; }

    double time() const override { return lines_.empty() ? 0.0 : lines_[0]->time(); }
    // The system's outputs: the single-line outputs are line 1's, line[k].* each deck line's.
    const UCOutputs& outputs() const override { return outputs_; }
    // (line 1 run from its anchor after its fairlead let go: the fairlead is its bare far end)
    Vec3 tow_position() const override {
        const CableSimulation& l = *lines_[0];
        return l.released() == 2 ? Vec3(l.outputs().endPosition[0], l.outputs().endPosition[1], l.outputs().endPosition[2])
                                 : l.tow_position();
    }
    // A coupled body's reference point (as its fairleads are extrapolated), a coupled point (the end of a
    // line that it holds).
    bool driven_position(int kind, int index, Vec3& p) const override;
    int n_lines() const { return static_cast<int>(lines_.size()); }
    // line[k].* of the deck's line k (0-based), for every line of the deck: the first UC_MAX_LINES are also
    // the FMU's outputs, the others are simulated alike but have no FMU variables (docs/systems_mooring.md).
    const UCMooringLine& line_outputs(int deckLine) const {
        return deckLine < UC_MAX_LINES ? outputs_.mooringLine[deckLine] : moreLines_[deckLine - UC_MAX_LINES];
    }
    const CableSimulation& line(int k) const { return *lines_[k]; }

    size_t state_size() const override;
    void save_state(void* buffer) override;
    // Refuses (false, error naming the first value that differs) a state saved by a system built from
    // another deck: a state carries every value the system was built from (its description). A refusal
    // of a state's size, version or deck values comes before anything changes; *changed (if given) tells
    // whether a later failure (a line's integrator history) left the system partly restored.
    bool restore_state(const void* buffer, size_t size, std::string& error, bool* changed = nullptr) override;

    // Every number the system was built from, named: each line's parameters (the deck's line with the
    // instance's parameters), its ends, the free nodes' mass, volume, drag, added mass, inertia and pose,
    // the deck's environment. Saved with each state; a restore compares it bit for bit.
    struct DescribedValue {
        std::string name;  // "line 2 (deck row 14): length" ...
        double value;
    };
    const std::vector<DescribedValue>& description() const { return description_; }

    // The quasi-static 6x6 stiffness of the lines on body b (1-based) at the body pose of the inputs:
    // K[6 i + j] = -d(force, moment)_i / d(x, y, z, theta_x, theta_y, theta_z)_j with theta a small
    // rotation about the earth axes from the present orientation (at zero angles the angles' own
    // derivatives), the free nodes its lines reach re-balanced where they stand (their coordinates
    // condensed), the other coupled bodies and points held at their inputs; by central differences of
    // the lines' static profiles (src/model/line_profile.h; src/system/mooring_stiffness.cpp). False where a line's
    // profile is not solved there or the nodes' stiffness is singular.
    bool body_stiffness(int b, const UCInputs& in, double K[36], std::string* why) const;
    // body[k].stiffness of every coupled body into the outputs, at the last inputs' poses: computed when
    // asked, once per step (it costs a fifth of a step; docs/systems_mooring.md). A body where
    // body_stiffness fails gets 0, and an event says why (once per run).
    void update_stiffness();
    // update_stiffness, and body[k].stiffness copied into out.
    bool update_stiffness(UCOutputs& out, std::string& error) override;

    // The interface derivatives of body b (1-based) over the next communication step, taken as long as
    // the last one: d[i][j] = d (force, moment)_i (t + h) / d input_j (t), inputs j = x, y, z, roll,
    // pitch, yaw, vx, vy, vz, wx, wy, wz, q0, q1, q2, q3 of the body (UC_BODY_DERIVATIVE_INPUTS; the
    // orientation inputs that bodyOrientation does not read have 0): each line's own interface
    // derivatives (CableSimulation::interface_derivatives) through the fairleads' motion on the body, and
    // the moment arms' change. Available after the first step.
    bool body_derivatives(int b, double d[6][UC_BODY_DERIVATIVE_INPUTS], std::string& error) override;
    // Refused: a system's coupled bodies have theirs (body_derivatives).
    bool interface_derivative(const double seed[kDerivativeInputs], double out[6], std::string& error) override;

    // Steps of the central differences of body_stiffness: of each line's ends [m] (with the other end held,
    // where a short taut line, a bridle's pennant of sag 0.5 m, is strongly non-linear: truncation ~
    // (step / sag)^2, 4e-5 of the diagonal at 0.01 m, 4e-7 at 1 mm; docs/systems_mooring.md), and of a free
    // body's own weight in its rotation [rad].
    static constexpr double kStiffnessStep = 0.001, kStiffnessAngle = 1e-5;
    // The stiffness re-balances the free nodes on the lines' profiles until a Newton step moves them by
    // less than kStiffnessBalance [m, rad], each step moving a node by at most kStiffnessReach [m].
    static constexpr double kStiffnessBalance = 1e-8, kStiffnessReach = 2.0;
    // A quaternion input (bodyOrientation 1) is refused where its norm is off 1 by more than this, and
    // normalized (reported once) where by more than kQuaternionReportedNorm.
    static constexpr double kQuaternionNormTolerance = 0.01, kQuaternionReportedNorm = 1e-6;
    // The free points' statics stop when a Newton step with the lines' solutions moves them less [m].
    // (and the dynamics' when a Newton correction moves them less), in at most kNodeIterations.
    static constexpr double kNodeTolerance = 1e-6;
    static constexpr int kNodeIterations = 20, kJacobianRefreshes = 4;
    static constexpr double kMaxCorrection = 0.2;
    static constexpr double kMaxTurn = 0.2;  // [rad] a free body turns by at most this per Newton step
    // The free nodes' step is split into at most kMaxSubsteps substeps where its estimated error in the nodes'
    // positions exceeds kNodeStepError [m], and into 2, 4, ... up to kMaxSplitSubsteps where its coupled iteration
    // does not converge (a snap: two taut lines let go at a massless point move it metres within hundredths of a
    // second; docs/line_failure.md).
    static constexpr int kMaxSubsteps = 16;
    static constexpr int kMaxSplitSubsteps = 256;
    static constexpr double kNodeStepError = 0.01;
    // A break by tension is located within its step in at most this many trials of the step's piece.
    static constexpr int kLocateIterations = 40;

    // The free nodes (Free points where three or more lines meet): their positions, found at the
    // initialization by the static equilibrium of each node (docs/systems_mooring.md, "Free points").
    int n_nodes() const { return static_cast<int>(motion_.size()); }
    Vec3 node_position(int n) const { return Vec3(motion_[n].position); }
    // The net static force on the free nodes (3 per node) with the nodes at x: their weight and
    // buoyancy, the current's drag and the lines' end forces, from the lines' exact static profiles
    // (profile = true: elastic catenaries, no current on the lines) or from the lines' own static
    // solutions (profile = false: each line initialized with its ends there). False where a line has no
    // solution there.
    bool node_residual(const Eigen::VectorXd& x, const UCInputs& in, bool profile, Eigen::VectorXd& r,
                       std::string& error);
    Vec3 node_velocity(int n) const { return Vec3(motion_[n].velocity); }
    Mat3 node_rotation(int n) const { return Eigen::Map<const Mat3>(motion_[n].rotation); }  // (identity for a point)
    const FreeNodeMotion& node_motion(int n) const { return motion_[n]; }
    // The line failures (the deck's FAILURE rows, then the failure.* parameters') and their states.
    int n_failures() const { return static_cast<int>(failures_.size()); }
    const MooringFailure& failure(int f) const { return failures_[f]; }
    const FailureState& failure_state(int f) const { return failureState_[f]; }
    // The largest tension of failure f's lines at its point (each line's end tension there) [N].
    double failure_tension(int f) const;
    // The tension within which a break by tension is located: the integrator's tolerance in tension of
    // failure f's lines (tensionTolerance times their tension scale) [N].
    double failure_tolerance(int f) const;
    // Steps with a break located within the last communication step (0 or 1) and the evaluations it took.
    int failure_evaluations() const { return failureEvaluations_; }
    // Newton iterations of the statics (of the last initialization) or of the last step's dynamics, and
    // the statics' residual left (largest component, N).
    int node_iterations() const { return nodeIterations_; }
    int node_substeps() const { return nodeSubsteps_; }  // of the last step (1: in one piece)
    double node_residual_norm() const { return nodeResidual_; }

private:
    struct Motion {
        Vec3 position, velocity, acceleration;
        bool accelerationGiven;
    };
    // Where an end of a line stands and moves for these inputs.
    Motion end_motion(const MooringEnd& end, const UCInputs& in) const;
    // Line k's ends as the line takes them (CableSimulation's line-level initialize and step): where they stand
    // and move for these inputs, each acceleration marked given where its body's or point's is.
    struct LineEnds {
        EndMotion tow, far;
    };
    LineEnds line_ends(int k, const UCInputs& in) const;
    bool check_inputs(const UCInputs& in, std::string& error);  // reports a normalized quaternion once
    void update_outputs();
    // What body b's stiffness moves (src/system/mooring_stiffness.cpp): the body (holder 0) and the free nodes
    // its lines reach, each with its generalized coordinates from offset (3 for a point, 6 for a body:
    // its reference point and a small rotation about the earth axes) and its pose.
    struct Holder {
        int node, offset, dofs;  // node: the free node (-1: body b)
        Vec3 reference;
        Mat3 rotation;
    };
    std::vector<Holder> stiffness_holders(int b, const UCInputs& in) const;
    // The holder of a line's end (-1: held where it is), nodeHolder[n] that of node n (-1: none).
    int stiffness_holder(const MooringEnd& e, int b, const std::vector<int>& nodeHolder) const;
    // Where end e stands with the holders at their poses (a held end: at its inputs).
    Vec3 stiffness_place(const MooringEnd& e, int b, const std::vector<Holder>& holders,
                         const std::vector<int>& nodeHolder, const UCInputs& in) const;
    // G += line k's static end forces on the holders (on a 6-dof holder also their moment about its reference
    // point), J += their derivatives in the holders' coordinates: the forces differenced in the ends'
    // positions (src/model/line_profile.h), chained through the holders' rigid motion, and the turning arms.
    bool add_line_jacobian(int k, int b, const std::vector<Holder>& holders, const std::vector<int>& nodeHolder,
                           const UCInputs& in, Eigen::VectorXd& G, Eigen::MatrixXd& J, std::string* why) const;
    // G += a node's own weight, buoyancy and current drag at rest (a free body's weight at its centre of gravity).
    void add_node_loads(const Holder& holder, const UCInputs& in, Eigen::VectorXd& G) const;
    // The static forces of line k on its fairlead and far end with them at top and far, from its
    // profile (a line with a free far end: its weight on the fairlead).
    bool profile_end_forces(int k, const Vec3& top, const Vec3& far, Vec3& onTop, Vec3& onFar, std::string* why) const;
    // The free nodes' static equilibrium (Newton with a line search), the lines initialized there.
    bool solve_nodes(double t0, const UCInputs& in, std::string& error);
    // The current's velocity at x.
    Vec3 water_velocity(const Vec3& x, const UCInputs& in) const;
    // The weight, buoyancy and current drag on node n (a point) at x moving at v.
    Vec3 node_load(int n, const Vec3& x, const UCInputs& in, const Vec3& v = Vec3::Zero()) const;
    // The loads on free body n other than its lines' and its inertia, as MoorDyn v2 has them, at x with
    // orientation R moving at v and turning at omega: force, and moment about the reference point.
    void body_load(int n, const Vec3& x, const Mat3& R, const Vec3& v, const Vec3& omega, const UCInputs& in,
                   Vec3& force, Vec3& moment) const;
    // Where pinned node n's pin stands, moves and accelerates tau after the communication step's start of
    // the inputs `in`: its holder's point extrapolated with its acceleration (given, or the difference of the
    // last two velocity inputs, as a driven end takes it).
    void pin_motion(int n, const UCInputs& in, double tau, Vec3& x, Vec3& v, Vec3& a) const;
    // The force pinned node n puts on what holds it, in its present motion: its loads (its lines', weight,
    // buoyancy, drag) less its inertia of translation (MoorDyn's coupled pinned body's output).
    Vec3 pin_force(int n, const UCInputs& in) const;
    // Free body n's added mass of translation (rho V Ca in its axes) in the earth axes at orientation R.
    Mat3 body_added_mass(int n, const Vec3& x, const Mat3& R) const;
    // The rods fixed to body n (system/body_rods.cpp): force and moment about x += their buoyancy and drag, or
    // the load of their added mass as the body accelerates at acc and alpha, from their parts under water.
    void add_body_rod_loads(int n, const Vec3& x, const Mat3& R, const Vec3& v, const Vec3& omega, const UCInputs& in,
                            Vec3& force, Vec3& moment) const;
    void add_body_rod_inertia(int n, const Vec3& x, const Mat3& R, const Vec3& acc, const Vec3& alpha, Vec3& force,
                              Vec3& moment) const;
    // A point of a free body (end.node, at end.position in its frame) in the body's present motion.
    void body_point_motion(const MooringEnd& end, Vec3& x, Vec3& v, Vec3& a) const;
    // r += force, pinned body n's load on its pin, on the free body holding it (and its moment there).
    void add_pin_reaction(int n, const Vec3& force, Eigen::VectorXd& r) const;
    // One communication step of the lines that end at free nodes, coupled implicitly through the nodes'
    // equations of motion (docs/systems_mooring.md, "Dynamics").
    // The error of the step just taken from start over h in the nodes' positions (a body's: at the reach
    // of its points), estimated from the change of their accelerations [m].
    double node_step_error(double h, const std::vector<FreeNodeMotion>& start) const;
    // The states of the lines at free nodes (empty for the others).
    void save_node_lines(std::vector<std::vector<unsigned char>>& into);
    // (In one piece, or in substeps where its error estimate is too large or its coupled iteration does
    // not converge.)
    // offset >= 0: a piece of the communication step that starts offset after its start (a break's).
    bool step_nodes(double t, double h, const UCInputs& in, std::string& error, double offset = -1.0);
    // Every line and node over h from their present time; offset as step_nodes'.
    bool advance(double t, double h, double offset, const UCInputs& in, std::string& error);
    // --- line failures (src/system/failure.cpp, docs/line_failure.md) ---
    // failures_ from the deck's rows and the failure.* parameters (false: error names the refusal), their states,
    // and the far ends of the lines whose anchor detaches marked (built driven).
    bool build_failures(std::string& error);
    void describe_failures();  // appends each failure's values to the description
    void failure_outputs();    // line[k].broken and line[k].breakTime of the broken failures' lines
    // The failures' states written at out (returns the place after them), and read from at (present: the state
    // holds this system's failures; else none is broken) with the free nodes they and the deck make into nodes.
    unsigned char* save_failures(unsigned char* out) const;
    std::vector<FailureState> saved_failures(const unsigned char* at, bool present, size_t& nodes) const;
    void undo_breaks();  // no failure broken (the deck's lines and nodes as read)
    // A break along a line (failure.position): system line k cut at `position` [m] of unstretched length from its
    // far end into two lines of its type joined at a new massless free node, the upper (line k, fairlead to the
    // node) and the lower (appended, node to the far end); f detaches the lower one's top from the node.
    bool split_line(int k, double position, MooringFailure& f, std::string& error);
    struct SplitLine {
        int upper, lower;  // the system's lines (upper: the deck line's own index; lower: after the deck's)
    };
    std::vector<SplitLine> splits_;
    void split_outputs();  // line[k].* of a split deck line: the two parts' as one line's
    // A communication step with failures pending: in pieces that end at each break (docs/line_failure.md).
    // taken: the step's length taken (h, or to a break within it where the step stops at breaks).
    bool step_with_failures(double t, double h, const UCInputs& in, double& taken, std::string& error);
    // Failure f breaks now, at time t: one line's end becomes the line's own bare far end (released_end), or the
    // lines' ends go on a new free node that starts where they are. False (error) where the line cannot let go.
    bool break_failure(int f, double t, std::string& error);
    // The end of failure f that lets go as its line's own bare far end (the line built to release it:
    // CableSimulation::prepare_release), or null where the failure's ends go on a free node (lines broken
    // together, a break along a line, a line with a free far end broken at its fairlead).
    const MooringFailure::End* released_end(int f) const;
    // Line k as it goes on when its fairlead (flip) or its far end lets go: run from its far end, or with a
    // free far end; the bare end has no point.
    static MooringDeckLine released_line(const MooringDeckLine& l, bool flip);
    // The free nodes with these failures' states: the deck's and one per broken failure that makes one.
    size_t node_count(const std::vector<FailureState>& states) const;
    std::vector<char> releases_;  // per failure: released_end's answer, decided once from the deck
    // The deck's lines and nodes as the failures' states make them (deck0_ with the broken failures' ends on
    // their nodes); motion_ must hold the nodes' motion in that order.
    void apply_failures();
    int failure_node(int f) const;  // the index of failure f's node among the nodes (where it is or would be)
    bool failures_pending() const;
    // One step of h from the nodes' and the lines' present time by the coupled iteration; shift >= 0: a
    // substep that starts shift after the communication step's, the coupled ends extrapolated there.
    // worst: the node that moves most in the last correction (named where it fails).
    bool node_step(double h, double shift, const UCInputs& in, int& worst, std::string& error);
    // Line k's ends (for the communication step's start) with those on coupled bodies and points
    // extrapolated by shift with their accelerations (given, or the difference of the last two velocity
    // inputs, as a driven end takes it), the accelerations marked as given.
    void shift_coupled_ends(int k, double shift, LineEnds& ends) const;

    UCParams base_;
    MooringDeck deck_;
    MooringDeck deck0_;  // as read (the deck_'s lines' ends and nodes before any failure)
    std::vector<MooringFailure> failures_;
    // --- state (with motion_ below) ---
    std::vector<FailureState> failureState_;
    bool stopAtBreaks_ = false;  // (a setting of the importer's, not of the state)
    int failureEvaluations_ = 0;
    std::vector<unsigned char> failureBuffer_;  // the system's state at a piece's start (event location)
    std::vector<std::unique_ptr<CableSimulation>> lines_;
    // The current given as data (the deck's Currents 2 or 5, or currents.file), every line's too, and the
    // time its free nodes take it at: the initial time, then the end of the step being taken.
    std::shared_ptr<const CurrentGrid> currentGrid_;
    // The seabed given as a grid (the deck's SeafloorFile that is not a plane, or seabed.file), every line's.
    std::shared_ptr<const SeabedGrid> seabedGrid_;
    double waterTime_ = 0.0;
    // per line: its sections and joints for its static profile, from the fairlead (s from there)
    std::vector<std::vector<LineProfile::Segment>> segments_;
    std::vector<std::vector<LineProfile::PointLoad>> pointLoads_;
    std::vector<double> hangingWeight_;  // per line with a free far end: its submerged weight and its body's
    std::vector<DescribedValue> description_;  // see description()
    void describe_line(int k, const UCParams& p);  // appends line k's values (its parameters p, its ends)
    void describe_nodes();                         // appends the deck's environment and the free nodes'
    // Whether the description saved at `saved` is this system's (else false, error naming what differs).
    bool same_description(const unsigned char* saved, std::string& error) const;
    // --- state ---
    std::vector<DrivenEnd> references_;  // each body's reference point, extrapolated as the fairleads are
    std::vector<FreeNodeMotion> motion_;  // of each free node
    std::vector<int> nodeOffset_;        // of each node's unknowns (3 for a point, 6 for a body)
    int nodeUnknowns_ = 0;
    std::vector<std::vector<unsigned char>> nodeLineStart_;  // the node lines' states at the step's start
    int nodeIterations_ = 0, nodeSubsteps_ = 1;
    double nodeResidual_ = 0.0;
    double t0_ = 0.0;
    double lastStep_ = 0.0;
    UCInputs lastInputs_{};  // of the last step (or the initialization)
    UCOutputs outputs_{};
    std::vector<UCMooringLine> moreLines_;  // line_outputs of the deck's lines beyond UC_MAX_LINES
    UCMooringLine& line_output(int deckLine) {
        return deckLine < UC_MAX_LINES ? outputs_.mooringLine[deckLine] : moreLines_[deckLine - UC_MAX_LINES];
    }
    bool stiffnessWarned_ = false, substepsReported_ = false;
    bool quaternionNormalized_ = false;  // a quaternion input off unit norm was reported (once)
    bool stiffnessCurrent_ = false;  // outputs_'s body stiffness is that of the present state
    std::string event_;
    std::vector<unsigned char> lineBuffer_;
    // body_derivatives of each body for the state of stamp_ (a master asks column by column)
    long stamp_ = 0;
    std::vector<long> derivativeStamp_;
    std::vector<std::array<double, 6 * UC_BODY_DERIVATIVE_INPUTS>> derivativeCache_;
};

}  // namespace uc
