// statics.h - equilibrium of the discrete cable (initMode 0): Newton's method on the free
// positions with a banded Jacobian, a backtracking line search and load continuation.
// A steady tow is a static equilibrium in the tow frame: every node moves with the tow
// velocity, so the relative flow is current - v_tow and the accelerations vanish.
#pragma once

#include <string>
#include <vector>

#include "numerics/band_solver.h"
#include "model/cable_model.h"

namespace uc {

struct StaticsResult {
    bool converged = false;
    int newtonIterations = 0;
    int continuationSteps = 0;
    double residualNorm = 0.0;  // max-norm of the free residual at the solution [N]
    // The residual's round-off floor at the last Jacobian [N]: machine epsilon times the largest row sum of
    // |dR_i/dq_j q_j|, the size of the terms that cancel in an equation (bending forces EI B X of a stiff
    // float, axial forces EA r' of a stiff tether); a residual below it is no worse than its evaluation.
    double residualFloor = 0.0;
    bool budgetSpent = false;  // stopped because the work budget given ran out
    std::string message;
};

// q: initial guess in, equilibrium out (free DOFs). vSteady: free velocities of the steady
// motion (tow velocity on every position DOF for a towed cable, zero when anchored).
// Continuation parameter lambda in [0, 1] scales the relative flow (tow velocity and current)
// and the end load from 0 (gravity only) to their actual values.
// nearGuess: q is close to the equilibrium (the line's static profile): Newton's method on the real
// cable at the full loads first, the continuation only where that fails.
// work (null: no limit): the work left [element iterations], each Newton iteration taking the model's
// number of elements from it; where it runs out the solve stops unconverged with budgetSpent set.
StaticsResult solve_static_equilibrium(const CableModel& model, BandSolver& solver, const Loads& loads,
                                       double t, const std::vector<double>& vSteady,
                                       std::vector<double>& q, bool nearGuess = false, double* work = nullptr);

// Accelerations a (free) consistent with the equations of motion at (q, v): M a = -R(q, v, 0).
bool solve_consistent_acceleration(const CableModel& model, BandSolver& solver, const Loads& loads,
                                   double t, const std::vector<double>& q,
                                   const std::vector<double>& v, std::vector<double>& a);

}  // namespace uc
