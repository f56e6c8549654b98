// integrator.cpp - IDA set-up and stepping.
#include "integrator.h"

#include <ida/ida.h>
#include <nvector/nvector_serial.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>

namespace uc {
namespace {

int residual_callback(double t, N_Vector y, N_Vector yp, N_Vector r, void* user) {
    auto* system = static_cast<SecondOrderSystem*>(user);
    return system->residual(t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), N_VGetArrayPointer(r));
}

// The shells handed to IDA: the matrix only carries a pointer to the Integrator (IDA zeroes it
// before each Jacobian evaluation: a no-op), the linear solver factors and solves the reduced form.
SUNMatrix_ID shell_matrix_id(SUNMatrix) { return SUNMATRIX_CUSTOM; }
int shell_matrix_zero(SUNMatrix) { return 0; }
void shell_matrix_destroy(SUNMatrix A) { SUNMatFreeEmpty(A); }
SUNLinearSolver_Type shell_solver_type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID shell_solver_id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int shell_solver_initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }
int shell_solver_free(SUNLinearSolver S) {
    SUNLinSolFreeEmpty(S);
    return SUNLS_SUCCESS;
}

// IDAGetReturnFlagName returns a string allocated with malloc that the caller must free.
std::string flag_name(int flag) {
    char* name = IDAGetReturnFlagName(flag);
    std::string copy = name ? name : "IDA_UNKNOWN_FLAG";
    std::free(name);
    return copy;
}

// Steps per communication interval before IDA gives up (a 1 s step of a stiff cable needs < 1000).
constexpr long kMaxStepsPerCall = 100000;

}  // namespace

Integrator::Integrator(SUNContext context, int n, int bandwidth, double relTol, double absTol,
                       SecondOrderSystem* system)
    : n_(n), bandwidth_(bandwidth), schur_(n, bandwidth), schurLU_(n, bandwidth), D_(n, bandwidth), system_(system) {
    pivoted_ = std::make_unique<BandSolver>(context, n, bandwidth);
    rhs_.assign(n, 0.0);
    y_ = N_VNew_Serial(2 * n, context);
    yp_ = N_VNew_Serial(2 * n, context);
    J_ = SUNMatNewEmpty(context);
    solver_ = SUNLinSolNewEmpty(context);
    ida_ = IDACreate(context);
    if (!y_ || !yp_ || !J_ || !solver_ || !ida_) {
        release();
        throw std::bad_alloc();
    }
    J_->content = this;
    J_->ops->getid = shell_matrix_id;
    J_->ops->zero = shell_matrix_zero;
    J_->ops->destroy = shell_matrix_destroy;
    solver_->content = this;
    solver_->ops->gettype = shell_solver_type;
    solver_->ops->getid = shell_solver_id;
    solver_->ops->initialize = shell_solver_initialize;
    solver_->ops->setup = &Integrator::ls_setup;
    solver_->ops->solve = &Integrator::ls_solve;
    solver_->ops->free = shell_solver_free;
    N_VConst(0.0, y_);
    N_VConst(0.0, yp_);
    bool ok = true;
    ok = ok && IDASetErrHandlerFn(ida_, &Integrator::error_handler, this) == IDA_SUCCESS;
    ok = ok && IDAInit(ida_, residual_callback, 0.0, y_, yp_) == IDA_SUCCESS;
    ok = ok && IDASStolerances(ida_, relTol, absTol) == IDA_SUCCESS;
    ok = ok && IDASetUserData(ida_, system_) == IDA_SUCCESS;
    ok = ok && IDASetLinearSolver(ida_, solver_, J_) == IDA_SUCCESS;
    ok = ok && IDASetJacFn(ida_, &Integrator::jacobian_callback) == IDA_SUCCESS;
    ok = ok && IDASetMaxNumSteps(ida_, kMaxStepsPerCall) == IDA_SUCCESS;
    if (!ok) {
        release();
        throw std::bad_alloc();
    }
}

Integrator::~Integrator() { release(); }

void Integrator::release() {
    if (ida_) IDAFree(&ida_);
    if (solver_) SUNLinSolFree(solver_);
    if (J_) SUNMatDestroy(J_);
    if (y_) N_VDestroy(y_);
    if (yp_) N_VDestroy(yp_);
    ida_ = nullptr;
    solver_ = nullptr;
    J_ = nullptr;
    y_ = yp_ = nullptr;
}

// Fills the reduced matrices: A = K + cj D = dR/dq + cj dR/dv + cj^2 dR/da and D = dR/dv + cj dR/da.
int Integrator::jacobian_callback(double t, double cj, N_Vector y, N_Vector yp, N_Vector /*r*/, SUNMatrix J,
                                  void* /*user*/, N_Vector, N_Vector, N_Vector) {
    auto* self = static_cast<Integrator*>(J->content);
    self->schur_.clear();
    self->D_.clear();
    self->cj_ = cj;
    UnpivotedBandLU& A = self->schur_;
    BandMatrix& D = self->D_;
    auto add = [&](int i, int k, double dq, double dv, double da) {
        const double d = dv + cj * da;
        D.add(i, k, d);
        A.add(i, k, dq + cj * d);
    };
    return self->system_->jacobian(t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), SecondOrderSystem::EntrySink(add));
}

int Integrator::ls_setup(SUNLinearSolver S, SUNMatrix /*A*/) {
    auto* self = static_cast<Integrator*>(S->content);
    if (!self->alwaysPivot_) {
        self->schurLU_ = self->schur_;
        self->usePivoted_ = !self->schurLU_.factor();
        if (!self->usePivoted_) return SUNLS_SUCCESS;
    }
    self->usePivoted_ = true;
    ++self->pivotedFactorizations_;
    const int n = self->n_, b = self->bandwidth_;
    self->pivoted_->clear();
    for (int i = 0; i < n; ++i)
        for (int k = std::max(0, i - b); k <= std::min(n - 1, i + b); ++k) self->pivoted_->add(i, k, self->schur_.get(i, k));
    return self->pivoted_->factor() ? SUNLS_SUCCESS : SUNLS_LUFACT_FAIL;  // > 0: IDA retries smaller
}

// Solves [cj I, -I; K, D] (x_q, x_v) = (b_q, b_v) (interleaved): x_v = cj x_q - b_q, and
// (K + cj D) x_q = b_v + D b_q.
int Integrator::ls_solve(SUNLinearSolver S, SUNMatrix /*A*/, N_Vector x, N_Vector b, double /*tol*/) {
    auto* self = static_cast<Integrator*>(S->content);
    const int n = self->n_, bandwidth = self->bandwidth_;
    const double* bb = N_VGetArrayPointer(b);
    double* xx = N_VGetArrayPointer(x);
    const BandMatrix& D = self->D_;
    double* rhs = self->rhs_.data();
    for (int i = 0; i < n; ++i) {
        double s = bb[2 * i + 1];
        const int k0 = std::max(0, i - bandwidth), k1 = std::min(n - 1, i + bandwidth);
        for (int k = k0; k <= k1; ++k) s += D.get(i, k) * bb[2 * k];
        rhs[i] = s;
    }
    if (self->usePivoted_) {
        if (!self->pivoted_->solve(rhs)) return SUNLS_PACKAGE_FAIL_UNREC;
    } else {
        self->schurLU_.solve(rhs);
    }
    for (int i = 0; i < n; ++i) {
        xx[2 * i + 1] = self->cj_ * rhs[i] - bb[2 * i];
        xx[2 * i] = rhs[i];
    }
    return SUNLS_SUCCESS;
}

void Integrator::error_handler(int code, const char* /*module*/, const char* function, char* msg, void* self) {
    auto* integrator = static_cast<Integrator*>(self);
    char buffer[600];
    // The code SUNDIALS passes here is not always the flag the call returns (IDA 6.4 reports "mxstep
    // steps taken" with IDA_ILL_INPUT although IDASolve returns IDA_TOO_MUCH_WORK), so only the
    // function and the text are kept; advance() names the returned flag.
    (void)code;
    std::snprintf(buffer, sizeof buffer, "%s: %s", function ? function : "IDA", msg ? msg : "");
    integrator->lastMessage_ = buffer;
}

bool Integrator::restart(double t, const double* y, const double* yp, std::string& error) {
    double* yy = N_VGetArrayPointer(y_);
    double* yyp = N_VGetArrayPointer(yp_);
    for (int i = 0; i < 2 * n_; ++i) {
        yy[i] = y[i];
        yyp[i] = yp[i];
    }
    const int flag = IDAReInit(ida_, t, y_, yp_);
    if (flag != IDA_SUCCESS) {
        error = "IDAReInit failed: " + flag_name(flag);
        return false;
    }
    return true;
}

bool Integrator::advance(double tEnd, std::string& error) {
    int flag = IDASetStopTime(ida_, tEnd);
    double tReached = 0.0;
    while (flag >= 0) {
        flag = IDASolve(ida_, tEnd, &tReached, y_, yp_, IDA_NORMAL);
        if (flag == IDA_TSTOP_RETURN || (flag == IDA_SUCCESS && tReached >= tEnd)) {
            return true;
        }
    }
    char buffer[900];
    std::snprintf(buffer, sizeof buffer, "integrator failed with %s at t = %.9g s (target %.9g s): %s",
                  flag_name(flag).c_str(), tReached, tEnd, lastMessage_.c_str());
    error = buffer;
    return false;
}

const double* Integrator::y() const { return N_VGetArrayPointer(y_); }
const double* Integrator::yp() const { return N_VGetArrayPointer(yp_); }

IntegratorStats Integrator::stats() const {
    long steps = 0, res = 0, jac = 0, ncf = 0, etf = 0;
    IDAGetNumSteps(ida_, &steps);
    IDAGetNumResEvals(ida_, &res);
    IDAGetNumJacEvals(ida_, &jac);
    IDAGetNumNonlinSolvConvFails(ida_, &ncf);
    IDAGetNumErrTestFails(ida_, &etf);
    IntegratorStats s;
    s.steps = static_cast<double>(steps);
    s.residualEvals = static_cast<double>(res);
    s.jacobianEvals = static_cast<double>(jac);
    s.nonlinearFailures = static_cast<double>(ncf);
    s.errorTestFailures = static_cast<double>(etf);
    return s;
}

}  // namespace uc
