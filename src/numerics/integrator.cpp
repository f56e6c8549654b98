// integrator.cpp - IDA set-up and stepping.
#include "numerics/integrator.h"

#include "numerics/sundials_compat.h"

#include <ida/ida.h>
#include <ida/ida_impl.h>     // IDAMemRec: the history saved with the FMU state
#include <ida/ida_ls_impl.h>  // IDALsMemRec: its Jacobian counter
#include <nvector/nvector_serial.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdarg>
#include <cstdlib>
#include <new>

// IDA's one-time set-up before the first step: exported by the library (ida.c) but not declared
// in its headers.
extern "C" int IDAInitialSetup(IDAMem ida_mem);

namespace uc {
namespace {

// The shells handed to IDA: the matrix only carries a pointer to the Integrator (IDA zeroes it
// before each Jacobian evaluation: a no-op), the linear solver factors and solves the reduced form.
SUNMatrix_ID shell_matrix_id(SUNMatrix) { return SUNMATRIX_CUSTOM; }
int shell_matrix_zero(SUNMatrix) { return 0; }
void shell_matrix_destroy(SUNMatrix A) { SUNMatFreeEmpty(A); }
SUNLinearSolver_Type shell_solver_type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID shell_solver_id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int shell_solver_initialize(SUNLinearSolver) { return kLinearSolverSuccess; }
int shell_solver_free(SUNLinearSolver S) {
    SUNLinSolFreeEmpty(S);
    return kLinearSolverSuccess;
}

// The vector operations IDA spends its own time in, as plain loops compiled with the core. The
// serial N_Vector of the SUNDIALS packages this builds against is compiled without optimization
// (about 20 instructions per element for a weighted norm, measured with callgrind), and on the
// heave case IDA's vector work was 40 % of all instructions. IDA's vectors are clones of y_ and
// yp_, so they carry these operations.
sunindextype length(N_Vector v) { return N_VGetLength(v); }

void linear_sum(double a, N_Vector x, double b, N_Vector y, N_Vector z) {
    const double *xx = N_VGetArrayPointer(x), *yy = N_VGetArrayPointer(y);
    double* zz = N_VGetArrayPointer(z);
    const sunindextype n = length(z);
    for (sunindextype i = 0; i < n; ++i) zz[i] = a * xx[i] + b * yy[i];
}

void scale(double c, N_Vector x, N_Vector z) {
    const double* xx = N_VGetArrayPointer(x);
    double* zz = N_VGetArrayPointer(z);
    const sunindextype n = length(z);
    for (sunindextype i = 0; i < n; ++i) zz[i] = c * xx[i];
}

void constant(double c, N_Vector z) {
    double* zz = N_VGetArrayPointer(z);
    const sunindextype n = length(z);
    for (sunindextype i = 0; i < n; ++i) zz[i] = c;
}

double weighted_square_sum(N_Vector x, N_Vector w) {
    const double *xx = N_VGetArrayPointer(x), *ww = N_VGetArrayPointer(w);
    const sunindextype n = length(x);
    double sum = 0.0;
    for (sunindextype i = 0; i < n; ++i) {
        const double p = xx[i] * ww[i];
        sum += p * p;
    }
    return sum;
}

// The integrator advancing on this thread, while it advances (its error norm may be projected).
thread_local const Integrator* advancing = nullptr;

struct Advancing {
    explicit Advancing(const Integrator* i) { advancing = i; }
    ~Advancing() { advancing = nullptr; }
};

double weighted_rms_norm(N_Vector x, N_Vector w) {
    if (advancing && advancing->projected() && length(x) == advancing->size())
        return advancing->projected_norm(N_VGetArrayPointer(x), N_VGetArrayPointer(w));
    return std::sqrt(weighted_square_sum(x, w) / static_cast<double>(length(x)));
}

// z = sum c_k X_k (z may be one of the X_k: each element of z is written after all are read).
int linear_combination(int m, double* c, N_Vector* X, N_Vector z) {
    constexpr int kMax = 8;  // IDA combines at most maxord + 1 = 6 vectors
    if (m > kMax) return -1;
    const double* x[kMax];
    for (int k = 0; k < m; ++k) x[k] = N_VGetArrayPointer(X[k]);
    double* zz = N_VGetArrayPointer(z);
    const sunindextype n = length(z);
    for (sunindextype i = 0; i < n; ++i) {
        double sum = 0.0;
        for (int k = 0; k < m; ++k) sum += c[k] * x[k][i];
        zz[i] = sum;
    }
    return 0;
}

int linear_sum_vector_array(int m, double a, N_Vector* X, double b, N_Vector* Y, N_Vector* Z) {
    for (int k = 0; k < m; ++k) linear_sum(a, X[k], b, Y[k], Z[k]);
    return 0;
}

int scale_vector_array(int m, double* c, N_Vector* X, N_Vector* Z) {
    for (int k = 0; k < m; ++k) scale(c[k], X[k], Z[k]);
    return 0;
}

void use_compiled_vector_operations(N_Vector v) {
    v->ops->nvlinearsum = linear_sum;
    v->ops->nvscale = scale;
    v->ops->nvconst = constant;
    v->ops->nvwrmsnorm = weighted_rms_norm;
    v->ops->nvwsqrsumlocal = weighted_square_sum;
    v->ops->nvlinearcombination = linear_combination;
    v->ops->nvlinearsumvectorarray = linear_sum_vector_array;
    v->ops->nvscalevectorarray = scale_vector_array;
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

// Newton iterations stop when their estimated error is below this fraction of the local error
// test (IDA's default is 0.33). A master that repeats a step with corrected inputs (an iterative
// co-simulation master) needs outputs that move smoothly with the inputs; with 0.33 the number of
// Newton iterations of a step changes with the inputs often enough to leave mN steps in the
// tension of the Hopland cable; 0.1 costs about 5 % more residual evaluations.
constexpr double kNewtonConvergence = 0.1;

// A step that would end within this factor of its size before the communication point is
// stretched to end there (see advance).
constexpr double kStretch = 1.1;

// At most this many steps between evaluations of the cable's Jacobian (CVODE's default is 51).
constexpr long kStepsPerJacobian = 20;

// The fields of IDA's memory that determine how it continues from the current point (besides
// the divided differences phi): everything else is scratch, recomputed at each step (the
// error weights, the predictor, the Newton corrections) or fixed at set-up. The layout is that
// of the SUNDIALS release the core is built with (ida_impl.h); the block is only ever read back
// by the same build (the state's version and sizes are checked by the caller).
constexpr int kHistoryScalars = 16, kHistoryCounters = 13, kHistoryArrays = 5, kHistoryOwn = 1;

void copy_scalars(IDAMem m, double* v, bool save) {
    double* fields[kHistoryScalars] = {&m->ida_tn,      &m->ida_tretlast, &m->ida_hh,     &m->ida_hused,
                                       &m->ida_eta,     &m->ida_h0u,      &m->ida_cj,     &m->ida_cjlast,
                                       &m->ida_cjold,   &m->ida_cjratio,  &m->ida_ss,     &m->ida_oldnrm,
                                       &m->ida_epsNewt, &m->ida_toldel,   &m->ida_tolsf,  &m->ida_hin};
    for (int i = 0; i < kHistoryScalars; ++i) {
        if (save) v[i] = *fields[i];
        else *fields[i] = v[i];
    }
}

template <class Int>
void copy_counter(Int& field, double& v, bool save) {
    if (save) v = static_cast<double>(field);
    else field = static_cast<Int>(v);
}

void copy_counters(IDAMem m, double* v, bool save) {
    auto* ls = static_cast<IDALsMem>(m->ida_lmem);
    copy_counter(m->ida_kk, v[0], save);
    copy_counter(m->ida_kused, v[1], save);
    copy_counter(m->ida_knew, v[2], save);
    copy_counter(m->ida_phase, v[3], save);
    copy_counter(m->ida_ns, v[4], save);
    copy_counter(m->ida_nst, v[5], save);
    copy_counter(m->ida_nre, v[6], save);
    copy_counter(m->ida_ncfn, v[7], save);
    copy_counter(m->ida_netf, v[8], save);
    copy_counter(m->ida_nni, v[9], save);
    copy_counter(m->ida_nnf, v[10], save);
    copy_counter(m->ida_nsetups, v[11], save);
    copy_counter(ls->nje, v[12], save);
}

}  // namespace

Integrator::Integrator(SUNContext context, int n, int bandwidth, SecondOrderSystem* system)
    : n_(n), bandwidth_(bandwidth), schur_(n, bandwidth), schurLU_(n, bandwidth), D_(n, bandwidth),
      K_(n, bandwidth), C_(n, bandwidth), M_(n, bandwidth), system_(system), context_(context) {
    pivoted_ = std::make_unique<BandSolver>(context, n, bandwidth);
    rhs_.assign(n, 0.0);
    positions_.assign(n, 0.0);
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
    use_compiled_vector_operations(y_);
    use_compiled_vector_operations(yp_);
    N_VConst(0.0, y_);
    N_VConst(0.0, yp_);
    bool ok = true;
    ok = ok && route_messages();
    ok = ok && IDAInit(ida_, &Integrator::residual_callback, 0.0, y_, yp_) == IDA_SUCCESS;
    if (ok) {
        // IDA fills the history arrays beyond phi[1] only as the order rises, and allocates them without
        // initializing them: zeroed here, a saved history holds no stale heap bytes (states are the same
        // bytes for the same run).
        auto* m = static_cast<IDAMem>(ida_);
        for (int j = 2; j < MXORDP1; ++j)
            if (m->ida_phi[j]) N_VConst(0.0, m->ida_phi[j]);
    }
    ok = ok && IDASetUserData(ida_, this) == IDA_SUCCESS;
    ok = ok && IDASetLinearSolver(ida_, solver_, J_) == IDA_SUCCESS;
    ok = ok && IDASetJacFn(ida_, &Integrator::jacobian_callback) == IDA_SUCCESS;
    ok = ok && IDASetMaxNumSteps(ida_, kMaxStepsPerCall) == IDA_SUCCESS;  // advance counts its own
    ok = ok && IDASetNonlinConvCoef(ida_, kNewtonConvergence) == IDA_SUCCESS;

    if (!ok) {
        release();
        throw std::bad_alloc();
    }
}

Integrator::~Integrator() { release(); }

void Integrator::release() {
    unroute_messages();
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

int Integrator::residual_callback(double t, N_Vector y, N_Vector yp, N_Vector r, void* self) {
    return static_cast<Integrator*>(self)->system_->residual(t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp),
                                                             N_VGetArrayPointer(r));
}

// Fills the reduced matrices: A = K + cj D = dR/dq + cj dR/dv + cj^2 dR/da and D = dR/dv + cj dR/da,
// from the cable's Jacobian evaluated now or at an earlier step (see K_, C_, M_).
int Integrator::jacobian_callback(double t, double cj, N_Vector y, N_Vector yp, N_Vector /*r*/, SUNMatrix J,
                                  void* /*user*/, N_Vector, N_Vector, N_Vector) {
    auto* self = static_cast<Integrator*>(J->content);
    auto* m = static_cast<IDAMem>(self->ida_);
    long newtonFailures = 0;  // of the Newton iteration in progress (a retry with a bad Jacobian)
    SUNNonlinSolGetNumConvFails(m->NLS, &newtonFailures);
    const bool evaluate = !self->jacobianCurrent_ || newtonFailures > 0 || m->ida_ncfn > self->failuresAtJacobian_ ||
                          m->ida_nst - self->stepAtJacobian_ >= kStepsPerJacobian;
    if (evaluate) {
        self->K_.clear();
        self->C_.clear();
        self->M_.clear();
        BandMatrix &K = self->K_, &C = self->C_, &M = self->M_;
        auto add = [&](int i, int k, double dq, double dv, double da) {
            K.add(i, k, dq);
            C.add(i, k, dv);
            M.add(i, k, da);
        };
        const int flag =
            self->system_->jacobian(t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), SecondOrderSystem::EntrySink(add));
        if (flag != 0) return flag;
        self->jacobianCurrent_ = true;
        self->stepAtJacobian_ = m->ida_nst;
        self->failuresAtJacobian_ = m->ida_ncfn;
        ++self->jacobianEvaluations_;
    }
    self->cj_ = cj;
    const double *K = self->K_.values(), *C = self->C_.values(), *M = self->M_.values();
    double *A = self->schur_.values(), *D = self->D_.values();
    const size_t count = self->D_.value_count();
    for (size_t i = 0; i < count; ++i) {
        D[i] = C[i] + cj * M[i];
        A[i] = K[i] + cj * D[i];
    }
    return 0;
}

int Integrator::ls_setup(SUNLinearSolver S, SUNMatrix /*A*/) {
    auto* self = static_cast<Integrator*>(S->content);
    if (!self->alwaysPivot_) {
        self->schurLU_ = self->schur_;
        self->usePivoted_ = !self->schurLU_.factor();
        if (!self->usePivoted_) return kLinearSolverSuccess;
    }
    self->usePivoted_ = true;
    ++self->pivotedFactorizations_;
    const int n = self->n_, b = self->bandwidth_;
    self->pivoted_->clear();
    for (int i = 0; i < n; ++i)
        for (int k = std::max(0, i - b); k <= std::min(n - 1, i + b); ++k) self->pivoted_->add(i, k, self->schur_.get(i, k));
    return self->pivoted_->factor() ? kLinearSolverSuccess : kLinearSolverSingular;  // > 0: IDA retries smaller
}

// Solves [cj I, -I; K, D] (x_q, x_v) = (b_q, b_v) (interleaved): x_v = cj x_q - b_q, and
// (K + cj D) x_q = b_v + D b_q.
int Integrator::ls_solve(SUNLinearSolver S, SUNMatrix /*A*/, N_Vector x, N_Vector b, double /*tol*/) {
    auto* self = static_cast<Integrator*>(S->content);
    const int n = self->n_;
    const double* bb = N_VGetArrayPointer(b);
    double* xx = N_VGetArrayPointer(x);
    double* rhs = self->rhs_.data();
    double* positions = self->positions_.data();
    for (int i = 0; i < n; ++i) {
        rhs[i] = bb[2 * i + 1];
        positions[i] = bb[2 * i];
    }
    self->D_.add_product(positions, rhs);
    if (self->usePivoted_) {
        if (!self->pivoted_->solve(rhs)) return kLinearSolverUnrecoverable;
    } else {
        self->schurLU_.solve(rhs);
    }
    for (int i = 0; i < n; ++i) {
        xx[2 * i + 1] = self->cj_ * rhs[i] - bb[2 * i];
        xx[2 * i] = rhs[i];
    }
    return kLinearSolverSuccess;
}

void Integrator::record_message(const char* function, const char* msg) {
    char buffer[600];
    std::snprintf(buffer, sizeof buffer, "%s: %s", function ? function : "IDA", msg ? msg : "");
    // IDA 6.4 builds some messages from fragments that both end in a comma ("At t = 3, , mxstep
    // steps taken ..."): print one.
    std::string text = buffer;
    for (size_t at = text.find(", ,"); at != std::string::npos; at = text.find(", ,", at)) text.erase(at, 2);
    lastMessage_ = text;
}

#if SUNDIALS_VERSION_MAJOR >= 7
// 7.x hands errors through the context's error handlers to the context's logger, and IDA's warnings
// straight to it; the logger prints errors to stderr and warnings to stdout, which an FMU must not. Its
// message operation (an overridable member of the logger) is replaced by one that records errors and
// warnings with the integrator that uses the context (one at a time: a remesh frees the old integrator
// before it makes the new one) and drops the rest.
namespace {
SUNErrCode logger_message(SUNLogger logger, SUNLogLevel level, const char* /*scope*/, const char* label,
                          const char* format, va_list args) {
    auto* integrator = static_cast<Integrator*>(logger->content);
    if (integrator == nullptr || (level != SUN_LOGLEVEL_ERROR && level != SUN_LOGLEVEL_WARNING)) return SUN_SUCCESS;
    char text[512];
    std::vsnprintf(text, sizeof text, format, args);
    integrator->record_message(label, text);
    return SUN_SUCCESS;
}
}  // namespace

bool Integrator::route_messages() {
    SUNLogger logger = nullptr;
    if (SUNContext_GetLogger(context_, &logger) != SUN_SUCCESS || logger == nullptr) return false;
    logger->content = this;
    logger->queuemsg = logger_message;
    return true;
}

void Integrator::unroute_messages() {
    SUNLogger logger = nullptr;
    if (SUNContext_GetLogger(context_, &logger) == SUN_SUCCESS && logger != nullptr && logger->content == this)
        logger->content = nullptr;
}
#else
// 6.x hands IDA's errors and warnings to the error handler of the IDA memory. The code it passes is not
// always the flag the call returns (IDA 6.4 reports "mxstep steps taken" with IDA_ILL_INPUT although
// IDASolve returns IDA_TOO_MUCH_WORK), so only the function and the text are kept; advance() names the
// returned flag.
namespace {
void error_handler(int /*code*/, const char* /*module*/, const char* function, char* msg, void* self) {
    static_cast<Integrator*>(self)->record_message(function, msg);
}
}  // namespace

bool Integrator::route_messages() { return IDASetErrHandlerFn(ida_, error_handler, this) == IDA_SUCCESS; }

void Integrator::unroute_messages() {}
#endif

bool Integrator::restart(double t, const double* y, const double* yp, std::string& error) {
    double* yy = N_VGetArrayPointer(y_);
    double* yyp = N_VGetArrayPointer(yp_);
    for (int i = 0; i < 2 * n_; ++i) {
        yy[i] = y[i];
        yyp[i] = yp[i];
    }
    const int flag = IDAReInit(ida_, t, y_, yp_);
    jacobianCurrent_ = false;
    jacobianEvaluations_ = 0;
    if (flag != IDA_SUCCESS) {
        error = "IDAReInit failed: " + flag_name(flag);
        return false;
    }
    return true;
}

bool Integrator::advance(double tEnd, std::string& error, long maxSteps) {
    const Advancing guard(this);
    const long limit = maxSteps > 0 ? std::min(maxSteps, kMaxStepsPerCall) : kMaxStepsPerCall;
    int flag = IDASetStopTime(ida_, tEnd);
    double tReached = 0.0;
    long steps = 0;
    auto* m = static_cast<IDAMem>(ida_);
    while (flag >= 0) {
        if (++steps > limit) {
            flag = IDA_TOO_MUCH_WORK;
            char text[200];
            std::snprintf(text, sizeof text, "%ld steps taken before reaching the end of the communication step",
                          limit);
            lastMessage_ = text;
            break;
        }
        // A step that would end just short of the communication point (within a tenth of it)
        // is stretched to end there: IDA would otherwise add a sliver of a step and start the
        // next communication step from that sliver's size, doubling it back over several steps.
        const double remaining = tEnd - m->ida_tn;
        if (m->ida_nst > 0 && remaining > m->ida_hh && remaining <= kStretch * m->ida_hh) m->ida_hh = remaining;
        if (projected()) update_directions();
        flag = IDASolve(ida_, tEnd, &tReached, y_, yp_, IDA_ONE_STEP);
        if (flag >= 0) system_->step_completed(tReached, N_VGetArrayPointer(y_), N_VGetArrayPointer(yp_));
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

size_t Integrator::history_size() const {
    return kHistoryScalars + kHistoryCounters + kHistoryOwn + kHistoryArrays * MXORDP1 +
           static_cast<size_t>(MXORDP1) * 2 * n_;
}

void Integrator::save_history(double* out) {
    auto* m = static_cast<IDAMem>(ida_);
    // The next step evaluates a new Jacobian, here and after a restore alike: cj / cjold is then
    // out of IDA's bounds for reusing the factored matrix, which the saved block does not hold.
    m->ida_cjold = 0.0;
    jacobianCurrent_ = false;
    copy_scalars(m, out, true);
    out += kHistoryScalars;
    copy_counters(m, out, true);
    out += kHistoryCounters;
    *out++ = static_cast<double>(jacobianEvaluations_);
    const double* arrays[kHistoryArrays] = {m->ida_psi, m->ida_alpha, m->ida_beta, m->ida_sigma, m->ida_gamma};
    for (const double* a : arrays) {
        std::copy(a, a + MXORDP1, out);
        out += MXORDP1;
    }
    for (int j = 0; j < MXORDP1; ++j) {
        const double* phi = N_VGetArrayPointer(m->ida_phi[j]);
        std::copy(phi, phi + 2 * n_, out);
        out += 2 * n_;
    }
}

bool Integrator::restore_history(const double* in, std::string& error) {
    auto* m = static_cast<IDAMem>(ida_);
    if (m->ida_maxord_alloc < MAXORD_DEFAULT || !m->ida_phi[MXORDP1 - 1]) {
        error = "the integrator cannot hold the saved history";
        return false;
    }
    copy_scalars(m, const_cast<double*>(in), false);
    in += kHistoryScalars;
    double* counters = const_cast<double*>(in);
    copy_counters(m, counters, false);
    in += kHistoryCounters;
    jacobianEvaluations_ = static_cast<long>(*in++);
    jacobianCurrent_ = false;
    double* arrays[kHistoryArrays] = {m->ida_psi, m->ida_alpha, m->ida_beta, m->ida_sigma, m->ida_gamma};
    for (double* a : arrays) {
        std::copy(in, in + MXORDP1, a);
        in += MXORDP1;
    }
    for (int j = 0; j < MXORDP1; ++j) {
        std::copy(in, in + 2 * n_, N_VGetArrayPointer(m->ida_phi[j]));
        in += 2 * n_;
    }
    // The solution at the saved point, as IDASolve returned it there.
    N_VScale(1.0, m->ida_phi[0], y_);
    if (!m->ida_SetupDone) {
        // An instance that never stepped: IDA's one-time set-up (linear and nonlinear solver
        // initialization, first error weights), which IDASolve skips once steps were taken.
        if (IDAInitialSetup(m) != IDA_SUCCESS) {
            error = "integrator set-up failed while restoring a state";
            return false;
        }
        m->ida_SetupDone = SUNTRUE;
        copy_counters(m, counters, false);  // the set-up reset the linear solver's counter
    }
    return true;
}

bool Integrator::set_max_order(int order, std::string& error) {
    if (IDASetMaxOrd(ida_, order) != IDA_SUCCESS) {
        error = "solver.maxOrder = " + std::to_string(order) + " is not an order the integrator has (1 to 5)";
        return false;
    }
    return true;
}

bool Integrator::set_tolerances(const std::vector<double>& atol, double relTol, double absTol, std::string& error,
                                const std::vector<double>* scales) {
    if (atol.size() != static_cast<size_t>(2 * n_) || (scales && scales->size() != atol.size())) {
        error = "internal: wrong number of tolerances";
        return false;
    }
    for (double a : atol) {
        if (!(a > 0.0) || !std::isfinite(a)) {
            error = "the integrator's absolute tolerances must be positive (check EA, the tolerances and the tension scale)";
            return false;
        }
    }
    atol_ = atol;
    if (scales) {
        scale_ = *scales;
    } else {
        scale_.assign(atol.size(), 0.0);
    }
    relTol_ = relTol;
    absTol_ = absTol;
    const int flag = IDAWFtolerances(ida_, &Integrator::error_weights);
    if (flag != IDA_SUCCESS) {
        error = "IDAWFtolerances failed: " + flag_name(flag);
        return false;
    }
    // IDAWFtolerances leaves the weight function's data pointer to IDA's set-up before the first
    // step, which an integrator continuing a restored history does not run again.
    static_cast<IDAMem>(ida_)->ida_edata = this;
    return true;
}

bool Integrator::set_projected_tolerances(const std::vector<ProjectedBlock>& blocks, std::string& error) {
    std::vector<char> in(2 * n_, 0);
    for (const ProjectedBlock& b : blocks) {
        const bool inside = b.q >= 0 && b.q + 2 < n_ && b.direction >= 0 && b.direction + 2 < n_;
        const bool positive = b.along > 0.0 && b.across > 0.0 && b.alongRate > 0.0 && b.acrossRate > 0.0 &&
                              std::isfinite(b.along + b.across + b.alongRate + b.acrossRate);
        if (!inside || !positive) {
            error = "internal: a projected error block outside the unknowns or with a tolerance that is not positive";
            return false;
        }
        for (int k = 0; k < 3; ++k) {
            for (int v = 0; v < 2; ++v) {
                char& c = in[2 * (b.q + k) + v];
                if (c) {
                    error = "internal: an unknown in two projected error blocks";
                    return false;
                }
                c = 1;
            }
        }
    }
    blocks_ = blocks;
    inBlock_ = std::move(in);
    blockWeights_.clear();
    for (const ProjectedBlock& b : blocks_) {
        for (double a : {b.along, b.across, b.alongRate, b.acrossRate}) blockWeights_.push_back(1.0 / (a * a));
    }
    directions_.assign(3 * blocks_.size(), 0.0);
    return true;
}

void Integrator::update_directions() {
    const double* y = N_VGetArrayPointer(y_);
    for (size_t k = 0; k < blocks_.size(); ++k) {
        const int i = 2 * blocks_[k].direction;
        const double d0 = y[i], d1 = y[i + 2], d2 = y[i + 4];
        const double norm = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
        // a degenerate direction (never a cable tangent): no along part, everything across
        const double s = norm > 0.0 && std::isfinite(norm) ? 1.0 / norm : 0.0;
        directions_[3 * k] = s * d0;
        directions_[3 * k + 1] = s * d1;
        directions_[3 * k + 2] = s * d2;
    }
}

double Integrator::projected_norm(const double* x, const double* w) const {
    double sum = 0.0;
    for (int i = 0; i < 2 * n_; ++i) {
        if (inBlock_[i]) continue;
        const double p = x[i] * w[i];
        sum += p * p;
    }
    for (size_t k = 0; k < blocks_.size(); ++k) {
        const double* d = &directions_[3 * k];
        const double* weight = &blockWeights_[4 * k];
        for (int v = 0; v < 2; ++v) {  // coordinates, then their velocities
            const int i = 2 * blocks_[k].q + v;
            const double e0 = x[i], e1 = x[i + 2], e2 = x[i + 4];
            const double along = d[0] * e0 + d[1] * e1 + d[2] * e2;
            const double across2 = std::max(0.0, e0 * e0 + e1 * e1 + e2 * e2 - along * along);
            sum += along * along * weight[2 * v] + across2 * weight[2 * v + 1];
        }
    }
    return std::sqrt(sum / static_cast<double>(2 * n_));
}

int Integrator::error_weights(N_Vector y, N_Vector ewt, void* user) {
    auto* self = static_cast<Integrator*>(user);
    const double* yy = N_VGetArrayPointer(y);
    double* w = N_VGetArrayPointer(ewt);
    const bool scalar = self->relTol_ > 0.0 || self->absTol_ > 0.0;
    for (int i = 0; i < 2 * self->n_; ++i) {
        double tol = self->atol_[i];
        if (scalar) {
            // relative to |y|, but never to less than the unknown's scale: a velocity or a tangent
            // component passing through 0 would otherwise ask for an error of 0
            const double s = self->relTol_ * std::max(std::fabs(yy[i]), self->scale_[i]) + self->absTol_;
            if (s > 0.0) tol = std::min(tol, s);
        }
        if (!(tol > 0.0)) return -1;
        w[i] = 1.0 / tol;
    }
    return 0;
}

const double* Integrator::y() const { return N_VGetArrayPointer(y_); }
const double* Integrator::yp() const { return N_VGetArrayPointer(yp_); }

IntegratorStats Integrator::stats() const {
    long steps = 0, res = 0, jac = 0, ncf = 0, etf = 0;
    IDAGetNumSteps(ida_, &steps);
    IDAGetNumResEvals(ida_, &res);
    jac = jacobianEvaluations_;
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
