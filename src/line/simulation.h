// simulation.h - one cable in time: the CableModel plus the evolving state (LineState, line/line_state.h,
// and the IDA vectors) and the workspace, allocated once. Save/restore of the state is a plain byte
// copy (the MuJoCo mjModel/mjData split).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <sundials/sundials_context.h>

#include "numerics/band_solver.h"
#include "model/parameters.h"
#include "model/cable_model.h"
#include "numerics/integrator.h"
#include "model/line_profile.h"
#include "line/outputs.h"
#include "line/rainflow.h"
#include "line/torsion.h"
#include "line/simulation_interface.h"
#include "line/winch.h"
#include "line/line_state.h"

namespace uc {

// How far two acceleration inputs disagree with the velocity inputs between them (uc_acceleration_disagreement
// in api/cable_api.h says exactly how): 0 when they agree within the allowance.
double acceleration_disagreement(double a0, double a1, double dv, double h);

// A driven end as Eigen vectors (a mooring system's body references): DrivenEndState's steps.
struct DrivenEnd {
    Vec3 position = Vec3::Zero(), velocity = Vec3::Zero(), acceleration = Vec3::Zero();
    Vec3 lastVelocityInput = Vec3::Zero(), lastAccelerationInput = Vec3::Zero();
    bool lastAccelerationGiven = false;

    void reset(const Vec3& p, const Vec3& v, const Vec3& a, bool accelerationGiven);
    // As DrivenEndState::next and advance.
    TowTrajectory next(double t, double h, double lastStep, const Vec3& positionInput, const Vec3& velocityInput,
                       const Vec3& accelerationInput, int accelerationGiven, Vec3& acceleration) const;
    void advance(const TowTrajectory& traj, const Vec3& velocityInput, const Vec3& acceleration,
                 bool accelerationGiven);
    void save(DrivenEndState& s) const;
    void load(const DrivenEndState& s);
};

// One end's kinematics for a step: the master's inputs for it at the step's end (what UCInputs holds
// in tow*, or end* for the far end).
struct EndMotion {
    Vec3 position = Vec3::Zero(), velocity = Vec3::Zero(), acceleration = Vec3::Zero();
    int accelerationGiven = 0;  // as UCInputs.towAccelerationGiven: 0, or bit 0 and UC_ACCELERATION_AS_INPUT bits
};

// What else acts on a line over a step, beside its ends' motion (the UCInputs fields of the same names;
// a mooring system gives every line the master's).
struct LineEnvironment {
    double current[2] = {0.0, 0.0}, currentRate[2] = {0.0, 0.0};  // [m/s], [m/s2]
    double currentScale = 0.0, currentScaleRate = 0.0;
    double endLoad[3] = {0.0, 0.0, 0.0}, endLoadVelocity[3] = {0.0, 0.0, 0.0}, endCouple[3] = {0.0, 0.0, 0.0};
    UCEndLoadDamping endLoadDamping{};
    double torque = 0.0, twist = 0.0;
    double winchRate = 0.0, winchRateRate = 0.0, winchTension = 0.0;
    int stepBudget = 0;
};
// The environment part of the FMU's inputs.
LineEnvironment line_environment(const UCInputs& in);
// The FMU's inputs for the tow point (tow*) and for the far end (end*).
EndMotion tow_motion(const UCInputs& in);
EndMotion far_motion(const UCInputs& in);

class CableSimulation : public SecondOrderSystem, public Simulation {
public:
    explicit CableSimulation(const UCParams& params);
    ~CableSimulation() override;
    CableSimulation(const CableSimulation&) = delete;
    CableSimulation& operator=(const CableSimulation&) = delete;

    const CableModel& model() const { return model_; }
    // The Syrope elements' history (eps_max per element; empty without a Syrope element): part of the state.
    const std::vector<double>& syrope_history() const { return syropeHistory_; }
    double time() const override { return state_.time; }
    const UCOutputs& outputs() const override { return state_.outputs; }
    Vec3 tow_position() const override { return state_.tow.p(); }
    // The far end of bottomEnd 3 (end.*): where the last step left it.
    bool driven_position(int kind, int index, Vec3& p) const override {
        (void)index;
        if (kind != UC_DRIVEN_END || !model_.far_end().driven) return false;
        p = state_.end.p();
        return true;
    }
    EndInputs end_inputs() const override { return {model_.far_end().external, model_.far_end().driven}; }
    // Where the tow point (far false) or a driven far end (far true) stands and moves at time().
    const DrivenEndState& driven_end(bool far) const { return far ? state_.end : state_.tow; }

    // The FMU's initialize: unpacks in into the ends' motion and the environment and takes initialize below.
    bool initialize(double t0, const UCInputs& in, std::string& error) override;
    // The line at rest (or in its steady tow) at t0 with its tow end and far end where given (the far
    // end's motion acts where the far end is driven or external), in the environment env; the ends'
    // given accelerations seed the tow point's trajectory.
    bool initialize(double t0, const EndMotion& tow, const EndMotion& far, const LineEnvironment& env,
                    std::string& error);
    // Whether initialize may start a deck line refused on its NumSegs' elements on the finer mesh the
    // mesh advice finds, with a warning (on by default; a mooring system's trial positions of its free
    // points turn it off: a refusal there only rejects the trial).
    void refine_deck_mesh(bool on) { refineDeckMesh_ = on; }
    // The FMU's step: unpacks in into the ends' motion and the environment and takes step below.
    bool step(double t, double h, const UCInputs& in, std::string& error) override;
    // One communication step of h seconds from time() with the tow end and the far end (its motion
    // acts where the far end is driven: bottomEnd 3, and the external body of bottomEnd 4) moving
    // as given, in the environment env.
    bool step(double h, const EndMotion& tow, const EndMotion& far, const LineEnvironment& env, std::string& error);
    // The event of the last step to log (a winch limit reached), or empty; cleared by the call.
    std::string take_event() override;
    void set_current_grid(std::shared_ptr<const CurrentGrid> grid) override;
    void set_seabed_grid(std::shared_ptr<const SeabedGrid> grid) override;
    const CurrentGrid* current_grid() const { return currentGrid_.get(); }
    std::size_t water_points() const override;
    void water_positions(double* x, double* y, double* z) const override;
    void set_water(double t, const double* const u[3], const double* const a[3]) override;

    size_t state_size() const override;
    void save_state(void* buffer) override;
    // false (error) for a state of another size or version before anything changes; *changed (if given)
    // tells whether the failure came after the line had started taking the state (its mesh, its history).
    bool restore_state(const void* buffer, size_t size, std::string& error, bool* changed = nullptr) override;

    // The interface derivatives over the next communication step (docs/cosimulation.md,
    // "Interface derivatives"): out[i] = sum_j d output_i (t + h) / d input_j (t) seed[j], outputs
    // i = towForce x, y, z, endForce x, y, z, inputs j = tow x, y, z, vx, vy, vz (0-5), end x, y,
    // z, vx, vy, vz (6-11), tow ax, ay, az (12-14), end ax, ay, az (15-17) (the end inputs act
    // only when bottomEnd = 3 or 4), for a next step as long as the last one: the cable linearized about
    // its present state, driven by the change of the driven end's quintic that the input change
    // makes, integrated over the step by BDF2 with kDerivativeSubsteps and twice as many substeps,
    // extrapolated (Richardson) to a third-order result. Only the requested direction is computed:
    // one integration per call, whatever the number of inputs in it; a column (one input) is kept
    // until the state changes, so a master asking column by column pays once per column.
    static constexpr int kDerivativeSubsteps = 64;
    bool interface_derivative(const double seed[kDerivativeInputs], double out[6], std::string& error) override;

    // The axial force at an end of element e (far: at its second node) in the state of the last outputs:
    // the tension a line of several sections has at its joints (a mooring system's line[k].* outputs).
    double element_end_tension(int e, bool far) const { return forces_.element[e].segment<3>(far ? 6 : 0).norm(); }
    // Where section j's far end stands in the state of the last outputs (or of a restored state): the joint
    // between sections j and j + 1 (a mooring system's point[k].position of a free point two lines join).
    const Vec3& section_end_position(int j) const { return sectionEnds_[j]; }

    // A held end that lets go (docs/line_failure.md): the line goes on with a bare far end (bottomEnd 0) inside its
    // own integrator, the model made again and the nodes' state carried over, one restart of the integrator.
    // prepare_release, once after construction, gives what the line becomes: released, the parameters of the
    // line with a bare far end; flip false: the far end lets go (released's sections as the line's); flip true:
    // the tow end lets go, released describing the line run from its far end (its sections in reverse order),
    // whose new tow point is held where the far end stands. release() lets go now (false, error, where the
    // released model's nodes are not the held one's); a saved state says whether the end is released, and a
    // restore or an initialization makes the model the state's. released(): 0 held, 1 the far end let go,
    // 2 the tow end let go (the line flipped).
    void prepare_release(const UCParams& released, bool flip);
    bool release(double time, std::string& error);  // time: the break's (release_time())
    int released() const { return state_.released; }
    // The force of a bare far end on what would hold it, in the state of the last outputs: its last element's end
    // force with the end node's own terms (its seabed contact), the tension at a free end (0 to the integrator's
    // error; endForce, the element's alone, also carries the contact's share there).
    Vec3 bare_end_force() const {
        return -(forces_.element.back().segment<3>(6) + forces_.endNodeTerms.head<3>());
    }
    double release_time() const { return state_.releaseTime; }
    // The size of the last step taken (0: none since the initialization) [s].
    double last_step_size() const { return state_.lastStepSize; }

    // Free positions q and velocities v of the current state (for tests).
    void free_state(std::vector<double>& q, std::vector<double>& v, std::vector<double>& a) const;
    // The global coordinates X and their rates Xd the last outputs were made from (for tests).
    const std::vector<double>& global_coordinates() const { return X_; }
    const std::vector<double>& global_rates() const { return Xd_; }
    // The time integrator (for tests of its linear algebra paths).
    Integrator& integrator() { return *integrator_; }

protected:
    // Where the line's outputs are made anew (update_outputs, a restored state), a subclass completes its own
    // outputs in them: once there, not on every read of outputs().
    virtual void complete_outputs(UCOutputs& out) const { (void)out; }

private:
    // The methods below live in one file per stage of the line:
    //   simulation.cpp             life cycle, the step, residual and Jacobian, outputs
    //   start.cpp                  initialize: checks, static profile, graded mesh, statics, mesh advice
    //   driven_end.cpp             DrivenEndState / DrivenEnd, acceleration_disagreement
    //   error_control.cpp          tolerances, element scales, projected error blocks
    //   winch_mesh.cpp             the winch's rate, the constant-tension winch, remesh and balance
    //   proxy_end.cpp              bottomEnd 4: proxy statics, the force on the body, the estimate
    //   interface_derivatives.cpp  the interface derivatives
    //   state.cpp                  save_state / restore_state
    int residual(double t, const double* y, const double* yp, double* r) override;
    int jacobian(double t, const double* y, const double* yp, const EntrySink& sink) override;
    void step_completed(double t, const double* y, const double* yp) override;
    // q_, v_, a_ and the global X_, Xd_, Xdd_ from the integrator's y, y' at time t.
    void expand_integrator_state(double t, const double* y, const double* yp);

    void set_environment(const LineEnvironment& env);
    // True where the guess is the line's static profile (near the equilibrium).
    bool initial_guess(const Vec3& towPoint, const Vec3& farPoint, std::vector<double>& q) const;
    // A steady tow's line: its direction at the flow's critical angle (start.cpp).
    bool steady_tow_direction(Vec3& d) const;
    // The far end is held at the start: anchored, external, or the proxy of an external body whose
    // statics hold it where the body is (bottomEnd 4, initMode 0).
    bool far_end_held_at_start() const;
    // bottomEnd 4, initMode 0: the statics with the proxy held at the body's position by a spring,
    // whose force then becomes the estimate of the body's other forces (the start is in equilibrium).
    bool proxy_statics(double t0, const std::vector<double>& v, bool fromProfile, std::string& error);
    // bottomEnd 4, after a step from the proxy's state (p0, v0): the force on the external body
    // (the force that takes it along the proxy's velocity, plus the tracking force) and the
    // estimate's update.
    void proxy_output(double h, const Vec3& p0, const Vec3& v0, const EndMotion& external);
    Vec3 proxy_flow(const Vec3& r, const Vec3& v, double t) const;
    // The static profile of the line from the tow point to its held far end (src/model/line_profile.h),
    // bending, current and waves left out; false where it does not apply, with the reason in why.
    bool static_profile(const Vec3& towPoint, const Vec3& farPoint, LineProfile& profile, bool& towOnTop,
                        std::string* why) const;
    bool profile_guess(double* X) const;  // from profile_, false where it was not solved
    // The direction along a sloped seabed across the plane of the line's static profile, where the
    // profile rests on a slope that falls across that plane; zero where it does not.
    Vec3 seabed_cross_slope() const;
    // After statics held by the seabed's static friction: a warning where the hold needs more than
    // seabedFriction of the normal contact force.
    void check_seabed_hold();
    // The mesh graded by the static profile where `apply` and the profile does (else each section's
    // own), the model built again where that changes it.
    // `grading`: which of kGradings (src/model/mesh_grading.h) places the nodes.
    void grade_mesh(const Vec3& towPoint, const Vec3& farPoint, bool apply, int grading = 0);
    // Before the static solver: false, with the reason, where the line has no static equilibrium.
    bool statics_applies(const Vec3& farPoint, std::string& error) const;
    // After it, on the outputs: false, with the reason, where its answer is not the line's state.
    bool verify_statics(std::string& error) const;
    // No static equilibrium in the flow (verify_statics found the line pushed into its anchor by it): the
    // compression found at the anchor [N], 0 where not. The start then falls back on the line's equilibrium in
    // still water, at rest, the flow acting from the start (start_in_still_water; docs/model.md).
    mutable double flowCompression_ = 0.0;
    bool stillWaterStart_ = false;  // the statics of this start see still water (no current, no waves)
    // After that start, the flow back on: the accelerations of the line at rest in it at t0, the outputs and
    // the warning; false (with the reason) where the line at rest in the flow has no consistent accelerations.
    bool start_in_still_water(double t0, std::string& error);
    // After a static state not found or refused, for a line given by parameters: the finer mesh
    // (twice, then four times the elements of every section) on which the same line starts, as
    // advice to append to the message; which knob to turn where no such mesh was found.
    // starts (if given): the parameters of the trial that started, where one did. waveZone (if given): where a
    // trial's start is found but lies in the wave zone (check_wave_zone), that refusal (no mesh helps it):
    // the search stops there.
    std::string mesh_advice(double t0, const EndMotion& tow, const EndMotion& far, const LineEnvironment& env,
                            std::optional<UCParams>* starts = nullptr, std::string* waveZone = nullptr) const;
    std::string waveZoneRefusal_;  // check_wave_zone's refusal of this start, else empty
    bool adviseMesh_ = true;  // off in the trial runs of mesh_advice
    bool refineDeckMesh_ = true;
    // The deck's own parameters of a line started on a finer mesh (start_on_finer_mesh), else null.
    std::unique_ptr<UCParams> deckParams_;
    // A restore of a state whose line has `elements` elements where this deck line (its elements from NumSegs)
    // has others: the line made again on the state's mesh, the deck's or a finer one that started it (every
    // deck line the same count). False where it is neither.
    bool adopt_deck_mesh(int elements);
    // The line made again on p's elements (what it becomes where its end lets go too).
    void remesh_deck_line(const UCParams& p);
    // A deck's line on its NumSegs' elements (lineFileElements 0) whose start was refused (refusal) and
    // on which finer (mesh_advice's trial) starts: the line made again on finer's elements and started,
    // with a warning naming both counts and the refusal (deck_mesh.cpp). False (error the refusal with
    // the advice) where the elements are the user's or no count started the line.
    bool start_on_finer_mesh(double t0, const EndMotion& tow, const EndMotion& far, const LineEnvironment& env,
                             const std::optional<UCParams>& finer, const std::string& advice, std::string& error);
    // The trials' shared work budget of mesh_advice [element iterations of the static solver]: a trial
    // run's static solves draw on it (null: no limit).
    double* staticWork_ = nullptr;
    // The budget: 30 000 element iterations (a Newton iteration on a line of n elements counts n), about
    // 3 s of one core (0.1 ms an element iteration, measured on chains of 25 to 100 elements).
    static constexpr double kAdviceWork = 3e4;
    // Largest relative difference of the end tensions from the exact static profile [-].
    static constexpr double kStaticsCheck = 0.01;
    // The check applies to a line with bending stiffness whose bending length at its smallest
    // tension is at most this fraction of its length [-].
    static constexpr double kWeakBending = 1e-3;
    // Largest relative difference between the anchor force and the axial tension at the anchor of
    // a line without bending stiffness: the acceptance's 0.2 % (both measure the anchor tension).
    static constexpr double kAnchorCheck = 2e-3;
    // The VIV phases' rates (v, free) from the synchronisation model at q_, v, a_ at time t.
    void settle_phase_rates(double t, std::vector<double>& v);
    // Before the statics: false, naming the line's length and the distance, where the held ends are farther
    // apart than the line reaches stretched to what each section survives (strain_survived); false where an
    // end is under the seabed.
    bool check_geometry(const Vec3& farPoint, std::string& error) const;
    // After the static state is accepted: its strains (an element's chord over its length). Beyond what a
    // section survives (strain_survived), false with the section, its EA and the likely cause (EA in the
    // wrong unit); beyond kStrainWarned, a warning event.
    bool check_static_strain(std::string& error);
    // After it: false, with the section and the numbers, where the buoyancy the waterline's ramp adds
    // (phi falling over one diameter above z = 0, docs/model.md, "Lines in air and water") exceeds
    // kWaterlineRefused of the line's largest tension: a thick float standing through the surface,
    // whose start would rest on the ramp, not on its submerged length.
    bool check_waterline(std::string& error) const;
    static constexpr double kWaterlineRefused = 0.1;
    // After it, in waves (the line's own sea, not water pushed by the importer): false, with the length
    // and the load, where the line's length within the waves' reach of the surface (|z| below the sum of
    // the components' amplitudes, or Hs where that is less), times the buoyancy and the normal drag of the fastest surface water per
    // metre, exceeds kWaveZoneRefused of the line's largest tension. The model wets a line below z = 0,
    // not below the moving surface (docs/waves.md, "The waterline"): that load is what it may put on the
    // wrong side of the surface. A tenth keeps the error this may make in the line's tension near a tenth
    // (a load moved on a line changes its end forces by at most about as much, less over a catenary's
    // slope), as kWaterlineRefused does for the ramp; wave_surface's chains through the crest, whose
    // misplaced load is several times their tension, are 19-27 % off MoorDyn in mean tension.
    // A line that only goes through the zone (at most kWaveZoneAlong times its height 2 eta in it: from an end at
    // the surface, or across it steeper than 30 degrees) starts with a warning; the tow cable hanging from a
    // vessel at the surface has its few metres there, the misplaced loads by its tow point.
    bool check_wave_zone(std::string& error);
    static constexpr double kWaveZoneRefused = 0.1;
    static constexpr double kWaveZoneAlong = 2.0;
    // Appends a message to the step's events (one a line, append_event).
    void add_event(const std::string& text);
    // Before the static solver: false where the line's whole weight in water over a section's EA
    // exceeds kWeightStrainRefused (EA in the wrong unit), which no static solve would settle.
    bool check_weight_strain(std::string& error) const;
    static constexpr double kWeightStrainRefused = 1.0;
    // The strain a line survives at rest, one policy for where its ends are (check_geometry) and for its
    // static state (check_static_strain; docs/model.md, "Strain at rest"): nylon, the most extensible rope
    // moored or towed with, breaks at about 20-25 % elongation, so no fibre rope rests beyond a quarter ...
    static constexpr double kStrainRefused = 0.25;
    // ... and a section as heavy for its diameter as a line with steel in it (above kSteelDensity: chain,
    // wire rope, an armoured cable; fibre ropes are 1000-1400 kg/m3) breaks below 3 %: none rests beyond 10 %.
    static constexpr double kSteelStrainRefused = 0.10;
    static constexpr double kSteelDensity = 2000.0;  // [kg/m3]: mass per length over pi d^2 / 4
    static double strain_survived(const SectionProps& section);
    // "the 25 % a fibre rope survives (...)": what a section survives at rest and why, for the messages.
    static std::string survived_text(const SectionProps& section);
    // Beyond it every steel line and most fibre ropes are past breaking at rest: worth a word.
    static constexpr double kStrainWarned = 0.05;
    void update_outputs();
    void warn_of_compression();
    // The first time an element's mean strain (the mean of |r'| - 1 over it) passes the last point of its
    // section's tension-strain curve, a warning: the tension there is the curve's linear continuation.
    void warn_beyond_curve();
    // Warns once of each way the run has left the current grid's data (CurrentField::gridOutside).
    void warn_outside_current_grid();
    bool set_integrator_tolerances(std::string& error);
    // An element's length (the winch's nominal one for its top element), the strain tolerance
    // (tensionTolerance x the tension scale / EA, times rms) and the time scale tau over which a
    // velocity error matters as a position error does (the Kelvin-Voigt time, at least an axial wave's
    // transit of the element).
    struct ElementScales {
        double length, strain, tau;
    };
    ElementScales element_scales(int e, double rms) const;
    // The projected error blocks of projectedErrorControl (empty when it is off).
    std::vector<Integrator::ProjectedBlock> projected_blocks() const;
    double cable_torque(const LineEnvironment& env);
    IntegratorStats total_stats() const;
    // The winch (docs/winch.md): the top element's length at time t; the rate for the step ahead;
    // splitting or merging the top element at a communication point; a new mesh, with everything
    // sized by the number of unknowns made again (at a remesh or a restore only).
    void set_winch_time(double t);
    // The constant-tension winch (winchMode 2): the top element's length is an unknown of the
    // integrator (index 0, before the line's); its rate follows, with the lag winch.timeConstant, the
    // rate the tow tension commands, implicitly with the line.
    int unknowns() const { return model_.n_free() + off_; }
    int unknowns_bandwidth() const;
    void allocate();
    double tension_winch_rate(double tension, double topLength, double* slope) const;
    // The tension the constant-tension winch controls: the force of the cable on the tow point along
    // the line's tangent there (R: the top element's residual at the expanded state X_), negative
    // in compression, so that a compressed line is hauled in, never paid out.
    double line_tension(const double* R) const;
    bool winch_rate(const LineEnvironment& env, double h, std::string& error);
    WinchLimits winch_limits() const;
    bool remesh(double change, std::string& error);  // change: of the top element over the step ahead
    bool remesh_once(RemeshAction action, bool balance, std::string& error);
    static constexpr int kMaxRemeshPasses = 100000;
    // Moves the global DOFs [g, g + count) of X (count <= 12) to where their own equations
    // of motion hold with the velocities Xd and accelerations Xdd (Newton on the elements that share
    // them): a node the remesh makes or changes starts in the motion the line had there.
    void balance_dofs(int g, int count, std::vector<double>& X, const std::vector<double>& Xd,
                      const std::vector<double>& Xdd);
    static constexpr int kMaxBalanceIterations = 8;
    // Nodes below the top element balanced after a remesh: each one more takes the transient of
    // the new mesh's discretization a node further from the tow point (a split on 15 m elements:
    // 0.053, 0.029, 0.0017, 0.0017, 0.0011 % of the tension with 1 to 5 nodes).
    static constexpr int kBalanceNodes = 4;
    // The residual rows of the global DOFs [g, g + count) and (J not null) their Jacobian block.
    void dof_residual(int g, int count, const std::vector<double>& X, const std::vector<double>& Xd,
                      const std::vector<double>& Xdd, Eigen::VectorXd& R, Eigen::MatrixXd* J);
    // From the positions q_ and velocities v_ at time_: the consistent accelerations, the state
    // y_, yp_, and a restart of the integrator.
    bool restart_from(std::string& error);
    void rebuild(const WinchMesh& mesh);
    void replace_model(CableModel&& model);
    // The released model (released 1 or 2, src/line/release.cpp) built from the held one in model_ (false, error,
    // where its nodes are not the held model's, mirrored where flipped), and back (the held model again).
    bool build_released(int released, std::string& error);
    void unrelease();
    std::unique_ptr<UCParams> releasedParams_;  // prepare_release's (null: the line has no end that lets go)
    bool releaseFlip_ = false;
    std::unique_ptr<UCParams> heldParams_;  // the parameters the line was built with, while released

    CableModel model_;
    int off_ = 0;  // 1: the constant-tension winch's unknown comes first in the integrator's vectors
    SUNContext context_ = nullptr;
    std::unique_ptr<Integrator> integrator_;
    std::unique_ptr<BandSolver> staticSolver_;

    // --- state (what save/restore copies: line/line_state.h) ---
    LineState state_;
    std::vector<double> y_, yp_;  // IDA vectors at state_.time: y = [q_0, v_0, q_1, v_1, ...]
    // The Syrope elements' history at state_.time (CableModel::history_size values: eps_max per element, beside
    // the internal strains among the unknowns it pairs with; empty without a Syrope element). Made again with
    // the model (allocate), grown after each internal step (step_completed), read by the model through
    // loads_.syropeHistory.
    std::vector<double> syropeHistory_;
    // The line's vectors (all sized by the model), in the order a saved state holds them after LineState: what
    // save_state and restore_state copy besides LineState and the integrator's history.
    std::array<std::vector<double>*, 3> line_vectors() { return {&y_, &yp_, &syropeHistory_}; }
    std::array<const std::vector<double>*, 3> line_vectors() const { return {&y_, &yp_, &syropeHistory_}; }

    // --- derived at initialization or from the state (not saved) ---
    std::string event_;  // the step's event text (taken by the caller; a message, not state)
    // The current given as data (shared by the lines of a system; parameters, not state) and the
    // CurrentGrid::Outside bits already warned of (a message, not state).
    std::shared_ptr<const CurrentGrid> currentGrid_;
    // The water pushed by the importer (water.source 1): 6 values per load point (CurrentField::pushed), and a
    // scratch of the state's global vectors for water_positions (sized on first use, not in the hot path).
    std::vector<double> pushedWater_;
    mutable std::vector<double> waterScratch_;
    unsigned currentGridWarned_ = 0;
    StaticLayout layout_;  // the graded mesh's nodes (made again from state_.grading at a restore)
    bool profileApplies_ = false;  // an anchored line, or a far end held at rest
    // The static profile for the ends the model holds (grade_mesh solves it once per initialization).
    struct ProfileState {
        LineProfile profile;
        bool solved = false, towOnTop = true;
        std::string why;  // why it was not solved
        Vec3 far = Vec3::Zero();  // the far end it was solved for
    };
    ProfileState profile_;
    // The statics' hold of a line resting across a sloped seabed (seabed_hold_across): the held shape,
    // and whether this start held it (initialization only, not state).
    std::vector<double> seabedHeld_;
    bool seabedHeldStart_ = false;

    // --- per-step environment and workspace ---
    SNCurve sn_;  // from the fatigue.* parameters
    // set by every step from its inputs and state, before it is integrated
    double winchTension_ = 0.0;    // the constant-tension winch's set tension over the step
    double winchTopAtStep_ = 0.0;  // the top element's length at the step's start
    double stepTensionMax_ = 0.0, stepTensionMin_ = 0.0;  // over the internal steps of the current step
    Loads loads_;
    std::vector<double> q_, v_, a_, X_, Xd_, Xdd_, R_;
    ElementForces forces_;
    OutputWorkspace outputWork_;
    std::vector<Vec3> sectionEnds_;  // section_end_position, from X_ at update_outputs and restore_state
    void store_section_ends();
    std::vector<double> historyBuffer_;  // the integrator's history on its way to/from a saved state
    std::vector<double> syropeAtStep_;   // syropeHistory_ at the step's start (a failed step's)
    std::vector<double> toleranceBuffer_;
    // interface derivatives (allocated at their first use): the linearization at the present
    // state, the step matrices of the two substep sizes factored, and the columns computed so far
    bool prepare_derivatives(std::string& error);
    void derivative_response(const double seed[kDerivativeInputs], double out[6]);
    std::unique_ptr<UnpivotedBandLU> derivativeLU_[2];
    std::unique_ptr<BandMatrix> derivativeK_, derivativeC_, derivativeM_;
    Mat12 derivativeKe_[2], derivativeCe_[2], derivativeMe_[2];
    ViscoJacobian derivativeVisco_[2];  // the end elements' internal strain couplings (viscoelastic line)
    Mat6 derivativeKn_, derivativeCn_, derivativeMn_;
    // bottomEnd 4: the force on the body by the proxy's velocity and position at t + h
    Mat3 derivativeProxyVelocity_ = Mat3::Zero(), derivativeProxyPosition_ = Mat3::Zero();
    std::vector<double> derivativeWork_;
    double derivativeColumns_[kDerivativeInputs][6] = {};
    bool derivativeColumnDone_[kDerivativeInputs] = {};
    long derivativeStamp_ = -1;  // stateStamp_ of the linearization and the columns
    long stateStamp_ = 0;        // changes whenever the state does (step, initialization, restore)
};

}  // namespace uc
