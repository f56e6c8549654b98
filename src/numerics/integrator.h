// integrator.h - SUNDIALS IDA (variable-order BDF, analytic Jacobian) for the cable's
// second-order system behind a small interface: one place for solver set-up, every flag checked,
// failures named. The Newton systems are solved through their n x n Schur complement (the
// velocity unknowns eliminated): a band LU of half the size and half the bandwidth of IDA's
// 2n x 2n iteration matrix, about 8 times fewer operations.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>

#include "numerics/band_solver.h"

namespace uc {

// The implicit system IDA integrates, for n generalized coordinates q with velocities v. The
// 2n unknowns interleave y = (q_0, v_0, q_1, v_1, ...); residual row 2j is q_j' - v_j, row 2j + 1
// is R_j(t, q, v, a = v').
class SecondOrderSystem {
public:
    virtual ~SecondOrderSystem() = default;
    // Return 0 on success, > 0 for a recoverable failure (IDA retries with a smaller step).
    virtual int residual(double t, const double* y, const double* yp, double* r) = 0;
    // Receives dR_i/dq_k, dR_i/dv_k, dR_i/da_k for |i - k| <= the bandwidth (repeated (i, k) add
    // up). A non-owning reference to a callable (never allocates, unlike std::function).
    class EntrySink {
    public:
        template <class F>
        explicit EntrySink(F& f) : object_(&f), call_([](void* o, int i, int k, double dq, double dv, double da) {
              (*static_cast<F*>(o))(i, k, dq, dv, da);
          }) {}
        void operator()(int i, int k, double dq, double dv, double da) const { call_(object_, i, k, dq, dv, da); }

    private:
        void* object_;
        void (*call_)(void*, int, int, double, double, double);
    };
    virtual int jacobian(double t, const double* y, const double* yp, const EntrySink& sink) = 0;
    // Called after every successful internal step with the state reached (for extremes and counts
    // that must see more than the communication points).
    virtual void step_completed(double /*t*/, const double* /*y*/, const double* /*yp*/) {}
};

struct IntegratorStats {
    double steps = 0, residualEvals = 0, jacobianEvals = 0, nonlinearFailures = 0, errorTestFailures = 0;
};

class Integrator {
public:
    // n coordinates whose Jacobian entries couple i and k only for |i - k| <= bandwidth. The
    // tolerances are set with set_tolerances before the first restart.
    Integrator(SUNContext context, int n, int bandwidth, SecondOrderSystem* system);
    ~Integrator();
    Integrator(const Integrator&) = delete;
    Integrator& operator=(const Integrator&) = delete;

    // Per-component absolute tolerances of the local error test (2n values, interleaved like y):
    // IDA's error weights become 1 / atol_i, or 1 / min(atol_i, relTol max(|y_i|, scale_i) + absTol)
    // where the scalar tolerances are positive (they can only tighten the test); `scales` (2n
    // values, null: 0) are the unknowns' magnitudes, below which relTol does not tighten further.
    bool set_tolerances(const std::vector<double>& atol, double relTol, double absTol, std::string& error,
                        const std::vector<double>* scales = nullptr);

    // The highest order of the BDF formulas (1-5; IDA's default is 5). Orders above 2 are not
    // A-stable: lightly damped fast modes can hold their steps at a loose tolerance.
    bool set_max_order(int order, std::string& error);

    // Optional error norm projected on directions (an error test along and across a cable): each
    // block is three coordinates q, q + 1, q + 2 (y indices 2q, 2q + 2, 2q + 4; their velocities
    // 2q + 1, ...) whose error is split along the unit vector of the three coordinates `direction`,
    // +1, +2 at the start of each step and across it. The along part is measured against `along`
    // (`alongRate` for the velocities), the across part against `across` (`acrossRate`); the other
    // unknowns against atol as usual. Replaces their share of IDA's weighted RMS norm (error test,
    // Newton convergence, step size selection); not used while relTol or absTol is positive (their
    // componentwise test applies). An empty list: the componentwise norm.
    struct ProjectedBlock {
        int q = 0, direction = 0;
        double along = 0.0, across = 0.0, alongRate = 0.0, acrossRate = 0.0;
    };
    bool set_projected_tolerances(const std::vector<ProjectedBlock>& blocks, std::string& error);
    // The weighted RMS norm of x (2n values) with the projected blocks, at the directions of the
    // present step (the vector operation IDA calls while this integrator advances).
    double projected_norm(const double* x, const double* w) const;
    bool projected() const { return !blocks_.empty() && relTol_ == 0.0 && absTol_ == 0.0; }

    // Restarts the integrator at (t, y, y') (first order, fresh step size selection).
    bool restart(double t, const double* y, const double* yp, std::string& error);
    // Integrates to exactly tEnd (used as the stop time). On failure error names the SUNDIALS
    // flag and the time reached; y, y' then hold the last successful state. maxSteps > 0: at most
    // that many steps (else the integrator's own limit), failing with IDA_TOO_MUCH_WORK.
    bool advance(double tEnd, std::string& error, long maxSteps = 0);

    // The integrator's history (IDA's divided differences, step size, order, coefficients and
    // counters) as a block of history_size() doubles, so that a saved state continues exactly as
    // the run that saved it, without a restart. Saving and restoring both make the next step
    // evaluate a new Jacobian (so that neither needs the factored matrices).
    size_t history_size() const;
    void save_history(double* out);
    // False (error says why) if the block does not fit this integrator.
    bool restore_history(const double* in, std::string& error);

    const double* y() const;
    const double* yp() const;
    int size() const { return 2 * n_; }
    // Statistics since the last restart.
    IntegratorStats stats() const;
    // Always factor with partial pivoting (the fallback path; for tests).
    void always_pivot(bool on) { alwaysPivot_ = on; }
    // Factorizations that fell back to (or were forced onto) the pivoting LU since construction.
    long pivoted_factorizations() const { return pivotedFactorizations_; }

    // SUNDIALS' own messages (IDA's errors and warnings, the linear solvers' errors) arrive here instead of
    // the process's stdout or stderr; the last one is part of the report of a failure.
    void record_message(const char* function, const char* text);

private:
    bool route_messages();
    void unroute_messages();
    static int error_weights(N_Vector y, N_Vector ewt, void* self);
    static int residual_callback(double t, N_Vector y, N_Vector yp, N_Vector r, void* self);
    static int jacobian_callback(double t, double cj, N_Vector y, N_Vector yp, N_Vector r, SUNMatrix J,
                                 void* self, N_Vector, N_Vector, N_Vector);
    static int ls_setup(SUNLinearSolver S, SUNMatrix A);
    static int ls_solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, double tol);
    void release();

    int n_, bandwidth_;
    void* ida_ = nullptr;
    N_Vector y_ = nullptr, yp_ = nullptr;
    // IDA's iteration matrix [cj I, -I; K, D] (K = dR/dq, D = dR/dv + cj dR/da) is kept reduced:
    // the Schur complement A = K + cj D (factored) and D, both n x n banded; the SUNMatrix and
    // SUNLinearSolver handed to IDA are shells around them.
    SUNMatrix J_ = nullptr;
    SUNLinearSolver solver_ = nullptr;
    UnpivotedBandLU schur_, schurLU_;      // assembled A, and its LU (without pivoting) ...
    std::unique_ptr<BandSolver> pivoted_;  // ... or with partial pivoting when a pivot is too small
    bool usePivoted_ = false, alwaysPivot_ = false;
    long pivotedFactorizations_ = 0;
    BandMatrix D_;
    // dR/dq, dR/dv, dR/da at the last evaluation of the cable's Jacobian. A new Newton matrix for a
    // new cj (IDA asks for one when its step size changed) is formed from them without evaluating
    // the Jacobian again, unless the Newton iteration failed to converge since, or
    // kStepsPerJacobian steps have passed (CVODE's policy, which IDA does not have).
    BandMatrix K_, C_, M_;
    bool jacobianCurrent_ = false;   // K_, C_, M_ belong to the present run (not before a restart)
    long stepAtJacobian_ = 0, failuresAtJacobian_ = 0;
    long jacobianEvaluations_ = 0;   // since the last restart (the solver.nJacobianEvals statistic)
    std::vector<double> rhs_;
    std::vector<double> positions_;  // the position part of a right-hand side, contiguous
    double cj_ = 0.0;  // of the stored matrices
    std::vector<double> atol_;  // per-component absolute tolerances (empty: IDA's scalar ones)
    double relTol_ = 0.0, absTol_ = 0.0;
    std::vector<double> scale_;  // of each unknown, the floor of |y| in relTol |y|
    std::vector<ProjectedBlock> blocks_;
    std::vector<char> inBlock_;        // per unknown: 1 if a block measures it
    std::vector<double> directions_;   // unit direction of each block at the start of the step
    std::vector<double> blockWeights_; // per block: 1 / along^2, 1 / across^2, 1 / alongRate^2, 1 / acrossRate^2
    void update_directions();
    SecondOrderSystem* system_;
    SUNContext context_;
    std::string lastMessage_;
};

}  // namespace uc
