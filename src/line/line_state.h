// line_state.h - everything that evolves in one line, in one trivially copyable struct: a saved state
// is a header (magic, version, sizes) and one copy of LineState, followed by the line's vectors sized by the
// mesh (the unknowns y, y' and the Syrope elements' history: CableSimulation::line_vectors) and the
// integrator's history (line/state.cpp). What a line holds beside it is the model (rebuilt from the state's
// winch mesh and grading where those change), derived data and per-step workspace; a field that a
// step changes belongs here, or a state restored into a fresh instance continues differently
// (tests/core/test_line_state.cpp catches that).
#pragma once

#include <cstdint>
#include <type_traits>

#include "core/types.h"
#include "model/cable_model.h"
#include "model/parameters.h"
#include "numerics/integrator.h"
#include "line/rainflow.h"
#include "line/torsion.h"
#include "line/winch.h"

namespace uc {

// A driven end (the tow point; the far end of bottomEnd 3) driven by the master's inputs: where its
// trajectory stands at the current time, and the inputs of the previous step. Plain doubles (a
// fixed layout, also in a mooring system's saved state).
struct DrivenEndState {
    double position[3], velocity[3], acceleration[3], lastVelocityInput[3], lastAccelerationInput[3];
    double lastAccelerationGiven;  // 1 or 0

    void reset(const Vec3& p, const Vec3& v, const Vec3& a, bool accelerationGiven);
    // The trajectory over [t, t + h] towards the inputs (position, velocity and, if given, the
    // acceleration) extrapolated to t + h; lastStep is the previous step's size (0: none).
    // accelerationGiven: as UCInputs.towAccelerationGiven (0, or bit 0 and UC_ACCELERATION_AS_INPUT bits).
    TowTrajectory next(double t, double h, double lastStep, const Vec3& positionInput, const Vec3& velocityInput,
                       const Vec3& accelerationInput, int accelerationGiven, Vec3& acceleration) const;
    // After a successful step along traj with these inputs.
    void advance(const TowTrajectory& traj, const Vec3& velocityInput, const Vec3& acceleration,
                 bool accelerationGiven);
    Vec3 p() const { return Vec3(position[0], position[1], position[2]); }
    Vec3 v() const { return Vec3(velocity[0], velocity[1], velocity[2]); }
    Vec3 a() const { return Vec3(acceleration[0], acceleration[1], acceleration[2]); }
};

// The evolving state of one line (CableSimulation). Not in it: the event text of a step (a message
// taken by the caller, not state), the model (its winch mesh is in the saved header, its graded mesh
// is made again from graded/grading/meshTow/meshFar), the static profile and layout of the start
// (derived), the line's vectors and the integrator's history (saved after this struct) and every per-step
// workspace.
struct LineState {
    double time = 0.0;
    double lastStepSize = 0.0;  // of the previous step (0: no input history yet)
    // the driven ends: the tow point, and the far end of bottomEnd 3 (external)
    DrivenEndState tow{}, end{};
    // torsion (torqueMode 2): the end frames at initialization, the geometric twist at the last
    // evaluation (for unwrapping past +-pi)
    TwistReference twistRef;
    double lastBeta = 0.0;
    // the integrator's statistics folded in at its restarts (a saved state holds the totals)
    IntegratorStats statsBase;
    double tensionScale = 0.0;  // of the error control, fixed at initialization
    RainflowCounter rainflow;   // online fatigue count of the tow tension (fatigue.area > 0)
    ProxyEstimate proxy;        // bottomEnd 4: the estimate of the external body's other forces
    // the winch: over a step from time the top element's length is winchTop0 + winchStep.length(t - time)
    double winchLength = 0.0;  // deployed unstretched length at time
    double winchRate = 0.0, winchTop0 = 0.0;  // the rate at time (rate winch: the drum's)
    WinchStep winchStep;        // the rate winch's drum over the step from time (a hold between steps)
    // the mesh graded by the static profile at initialization (graded 0: each section's own), the
    // tow point and far end it was graded for (a restored state's mesh is graded again from them)
    double meshTow[3] = {0.0, 0.0, 0.0}, meshFar[3] = {0.0, 0.0, 0.0};
    UCOutputs outputs{};
    double releaseTime = 0.0;  // when the end let go (released != 0) [s]
    std::int32_t winchLimit = 0;  // -1 / +1: at the shortest / longest length (logged once per arrival)
    std::int32_t grading = 0;     // which of kGradings graded the mesh (the first whose equilibrium passed)
    bool graded = false;
    bool winchRateLimited = false;   // winch.maxRate cut the command (logged once per arrival)
    bool compressionWarned = false;  // the compression warning is given once per instance
    bool integratorStarted = false;  // the integrator's own counters belong to this state
    bool restartPending = true;      // the next step restarts the integrator from y, y'
    bool curveWarned = false;        // the warning of a strain beyond the tension-strain curve, once
    std::uint8_t released = 0;       // 0: the ends held; 1: the far end let go; 2: the tow end let go (flipped)
    char unused[1] = {};             // no padding (below): the same state saves the same bytes
};

static_assert(std::is_trivially_copyable_v<LineState>, "a line's state is saved and restored as bytes");
// No padding byte anywhere (padding would carry whatever the memory held into the saved state): the
// size is the sum of the fields'. A field added above is added here too, or this fails.
static_assert(sizeof(WinchStep) == 6 * sizeof(double) + sizeof(std::int32_t) + 2 * sizeof(bool) + 2, "WinchStep");
static_assert(sizeof(RainflowCounter) == (RainflowCounter::kCapacity + 3) * sizeof(double) + 16, "RainflowCounter");
static_assert(sizeof(DrivenEndState) == 16 * sizeof(double) && sizeof(TwistReference) == 12 * sizeof(double) &&
                  sizeof(IntegratorStats) == 5 * sizeof(double) && sizeof(ProxyEstimate) == 5 * sizeof(double),
              "plain doubles");
static_assert(sizeof(LineState) == 2 * sizeof(double) + 2 * sizeof(DrivenEndState) + sizeof(TwistReference) +
                                       sizeof(double) + sizeof(IntegratorStats) + sizeof(double) +
                                       sizeof(RainflowCounter) + sizeof(ProxyEstimate) + 3 * sizeof(double) +
                                       sizeof(WinchStep) + 6 * sizeof(double) + sizeof(UCOutputs) + sizeof(double) +
                                       2 * sizeof(std::int32_t) + 6 * sizeof(bool) + 1 + 1,
              "LineState has padding, or a field the sum leaves out");

}  // namespace uc
