// simulation.h - one cable in time: the immutable CableModel plus the mutable state (time,
// IDA vectors, prescribed-end state, statistics, outputs) and the workspace, allocated once.
// Save/restore of the state is a plain byte copy (the MuJoCo mjModel/mjData split).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <sundials/sundials_context.h>

#include "band_solver.h"
#include "cable_api.h"
#include "cable_model.h"
#include "integrator.h"
#include "torsion.h"

namespace uc {

class CableSimulation : public SecondOrderSystem {
public:
    explicit CableSimulation(const UCParams& params);
    ~CableSimulation() override;
    CableSimulation(const CableSimulation&) = delete;
    CableSimulation& operator=(const CableSimulation&) = delete;

    const CableModel& model() const { return model_; }
    double time() const { return time_; }
    const UCOutputs& outputs() const { return outputs_; }

    bool initialize(double t0, const UCInputs& in, std::string& error);
    bool step(double t, double h, const UCInputs& in, std::string& error);

    size_t state_size() const;
    void save_state(void* buffer);
    bool restore_state(const void* buffer, size_t size, std::string& error);

    // Free positions q and velocities v of the current state (for tests).
    void free_state(std::vector<double>& q, std::vector<double>& v, std::vector<double>& a) const;
    // The time integrator (for tests of its linear algebra paths).
    Integrator& integrator() { return *integrator_; }

private:
    int residual(double t, const double* y, const double* yp, double* r) override;
    int jacobian(double t, const double* y, const double* yp, const EntrySink& sink) override;

    void set_environment(const UCInputs& in);
    void initial_guess(const Vec3& towPoint, const Vec3& farPoint, std::vector<double>& q) const;
    bool check_geometry(const Vec3& farPoint, std::string& error) const;
    void update_outputs();
    double cable_torque(const UCInputs& in);
    IntegratorStats total_stats() const;

    CableModel model_;
    SUNContext context_ = nullptr;
    std::unique_ptr<Integrator> integrator_;
    std::unique_ptr<BandSolver> staticSolver_;

    // --- state (what save/restore copies) ---
    double time_ = 0.0;
    Vec3 towPosition_ = Vec3::Zero(), towVelocity_ = Vec3::Zero();  // prescribed end at time_
    Vec3 lastVelocityInput_ = Vec3::Zero();  // tow velocity input of the previous step ...
    double lastStepSize_ = 0.0;              // ... and its step size (0: no history yet)
    Vec3 endPosition_ = Vec3::Zero(), endVelocity_ = Vec3::Zero();  // prescribed far end (bottomEnd 3)
    Vec3 lastEndVelocityInput_ = Vec3::Zero();
    TwistReference twistRef_;  // end frames at initialization (torqueMode 2)
    double lastBeta_ = 0.0;    // geometric twist at the last evaluation, for unwrapping past +-pi
    std::vector<double> y_, yp_;  // IDA vectors at time_: y = [q_0, v_0, q_1, v_1, ...]
    IntegratorStats statsBase_;   // statistics folded in at integrator restarts
    bool integratorStarted_ = false;  // the integrator's own counters belong to this state
    UCOutputs outputs_{};
    bool restartPending_ = true;

    // --- per-step environment and workspace ---
    Loads loads_;
    std::vector<double> q_, v_, a_, X_, Xd_, Xdd_, R_;
    ElementForces forces_;
    std::vector<double> nodeTension_;  // output workspace
};

}  // namespace uc
