// integrator.cpp - IDA set-up and stepping.
#include "integrator.h"

#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunmatrix/sunmatrix_band.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>

namespace uc {
namespace {

int residual_callback(double t, N_Vector y, N_Vector yp, N_Vector r, void* user) {
    auto* system = static_cast<DaeSystem*>(user);
    return system->residual(t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), N_VGetArrayPointer(r));
}

int jacobian_callback(double t, double cj, N_Vector y, N_Vector yp, N_Vector /*r*/, SUNMatrix J,
                      void* user, N_Vector, N_Vector, N_Vector) {
    auto* system = static_cast<DaeSystem*>(user);
    return system->jacobian(t, cj, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), J);
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
                       DaeSystem* system)
    : n_(n), system_(system) {
    y_ = N_VNew_Serial(n, context);
    yp_ = N_VNew_Serial(n, context);
    J_ = SUNBandMatrix(n, bandwidth, bandwidth, context);
    ida_ = IDACreate(context);
    if (!y_ || !yp_ || !J_ || !ida_) {
        release();
        throw std::bad_alloc();
    }
    N_VConst(0.0, y_);
    N_VConst(0.0, yp_);
    solver_ = SUNLinSol_Band(y_, J_, context);
    bool ok = solver_ != nullptr;
    ok = ok && IDASetErrHandlerFn(ida_, &Integrator::error_handler, this) == IDA_SUCCESS;
    ok = ok && IDAInit(ida_, residual_callback, 0.0, y_, yp_) == IDA_SUCCESS;
    ok = ok && IDASStolerances(ida_, relTol, absTol) == IDA_SUCCESS;
    ok = ok && IDASetUserData(ida_, system_) == IDA_SUCCESS;
    ok = ok && IDASetLinearSolver(ida_, solver_, J_) == IDA_SUCCESS;
    ok = ok && IDASetJacFn(ida_, jacobian_callback) == IDA_SUCCESS;
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
    for (int i = 0; i < n_; ++i) {
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
