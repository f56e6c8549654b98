// integrator.h - SUNDIALS IDA (variable-order BDF, band linear solver, analytic Jacobian) behind a
// small interface: one place for solver set-up, every flag checked, failures named.
#pragma once

#include <string>

#include <sundials/sundials_context.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>
#include <sundials/sundials_linearsolver.h>

namespace uc {

// The implicit system F(t, y, y') = 0 that IDA integrates.
class DaeSystem {
public:
    virtual ~DaeSystem() = default;
    // Return 0 on success, > 0 for a recoverable failure (IDA retries with a smaller step).
    virtual int residual(double t, const double* y, const double* yp, double* r) = 0;
    // J = dF/dy + cj dF/dy' into a band matrix.
    virtual int jacobian(double t, double cj, const double* y, const double* yp, SUNMatrix J) = 0;
};

struct IntegratorStats {
    double steps = 0, residualEvals = 0, jacobianEvals = 0, nonlinearFailures = 0, errorTestFailures = 0;
};

class Integrator {
public:
    Integrator(SUNContext context, int n, int bandwidth, double relTol, double absTol, DaeSystem* system);
    ~Integrator();
    Integrator(const Integrator&) = delete;
    Integrator& operator=(const Integrator&) = delete;

    // Restarts the integrator at (t, y, y') (first order, fresh step size selection).
    bool restart(double t, const double* y, const double* yp, std::string& error);
    // Integrates to exactly tEnd (used as the stop time). On failure error names the SUNDIALS
    // flag and the time reached; y, y' then hold the last successful state.
    bool advance(double tEnd, std::string& error);

    const double* y() const;
    const double* yp() const;
    int size() const { return n_; }
    // Statistics since the last restart.
    IntegratorStats stats() const;

private:
    static void error_handler(int code, const char* module, const char* function, char* msg, void* self);
    void release();

    int n_;
    void* ida_ = nullptr;
    N_Vector y_ = nullptr, yp_ = nullptr;
    SUNMatrix J_ = nullptr;
    SUNLinearSolver solver_ = nullptr;
    DaeSystem* system_;
    std::string lastMessage_;
};

}  // namespace uc
