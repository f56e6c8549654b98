// simulation.cpp - one cable in time: its life cycle, the step, the residual and Jacobian the
// integrator calls, the outputs.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>

#include "line/simulation.h"
#include "line/simulation_internal.h"

#include "line/statics.h"
#include "numerics/sundials_compat.h"

namespace uc {

namespace {

IntegratorStats operator+(const IntegratorStats& a, const IntegratorStats& b) {
    IntegratorStats s;
    s.steps = a.steps + b.steps;
    s.residualEvals = a.residualEvals + b.residualEvals;
    s.jacobianEvals = a.jacobianEvals + b.jacobianEvals;
    s.nonlinearFailures = a.nonlinearFailures + b.nonlinearFailures;
    s.errorTestFailures = a.errorTestFailures + b.errorTestFailures;
    return s;
}

}  // namespace

LineEnvironment line_environment(const UCInputs& in) {
    LineEnvironment env;
    for (int k = 0; k < 2; ++k) {
        env.current[k] = in.current[k];
        env.currentRate[k] = in.currentRate[k];
    }
    env.currentScale = in.currentScale;
    env.currentScaleRate = in.currentScaleRate;
    for (int k = 0; k < 3; ++k) {
        env.endLoad[k] = in.endLoad[k];
        env.endLoadVelocity[k] = in.endLoadVelocity[k];
        env.endCouple[k] = in.endCouple[k];
    }
    env.endLoadDamping = in.endLoadDamping;
    env.torque = in.torque;
    env.twist = in.twist;
    env.winchRate = in.winchRate;
    env.winchRateRate = in.winchRateRate;
    env.winchTension = in.winchTension;
    env.stepBudget = in.stepBudget;
    return env;
}

EndMotion tow_motion(const UCInputs& in) {
    return {vec(in.tow), vec(in.towVelocity), vec(in.towAcceleration), in.towAccelerationGiven};
}

EndMotion far_motion(const UCInputs& in) {
    return {vec(in.end), vec(in.endVelocity), vec(in.endAcceleration), in.endAccelerationGiven};
}

// The linearization of the end load (12 inputs) is finite.
bool end_load_linearization_finite(const LineEnvironment& env) {
    const double* rows[3] = {env.endLoadDamping.x, env.endLoadDamping.y, env.endLoadDamping.z};
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(env.endLoadVelocity[i]) || !std::isfinite(rows[i][0]) || !std::isfinite(rows[i][1]) ||
            !std::isfinite(rows[i][2]))
            return false;
    return true;
}

CableSimulation::CableSimulation(const UCParams& params) : model_(params) {
    loads_.proxy = &state_.proxy;
    sn_.m = params.fatigueM;
    sn_.logK = params.fatigueLogK;
    sn_.area = params.fatigueArea;
    off_ = params.winchMode == UC_WINCH_TENSION ? 1 : 0;
    if (SUNContext_Create(UC_SUN_COMM_NULL, &context_) != 0 || context_ == nullptr) throw std::bad_alloc();
    try {
        allocate();
    } catch (...) {
        integrator_.reset();
        staticSolver_.reset();
        SUNContext_Free(&context_);
        throw;
    }
}

int CableSimulation::unknowns_bandwidth() const {
    int bandwidth = model_.free_bandwidth();
    if (off_ == 0) return bandwidth;
    for (int a = 0; a < 12; ++a) {  // the winch's unknown (index 0) couples to the top element's
        const int j = model_.free_index(model_.element_offset(0) + a);
        if (j >= 0) bandwidth = std::max(bandwidth, j + 1);
    }
    return bandwidth;
}

// Everything sized by the number of unknowns (at construction and at a remesh).
void CableSimulation::allocate() {
    const int n = model_.n_free(), unknowns = this->unknowns();
    integrator_ = std::make_unique<Integrator>(context_, unknowns, unknowns_bandwidth(), this);
    staticSolver_ = std::make_unique<BandSolver>(context_, n, model_.free_bandwidth());
    y_.assign(2 * unknowns, 0.0);
    yp_.assign(2 * unknowns, 0.0);
    syropeHistory_.assign(model_.history_size(), 0.0);
    model_.initial_history(syropeHistory_.data());
    loads_.syropeHistory = syropeHistory_.empty() ? nullptr : syropeHistory_.data();
    q_.assign(n, 0.0);
    v_.assign(n, 0.0);
    a_.assign(n, 0.0);
    R_.assign(n, 0.0);
    X_.assign(model_.n_global(), 0.0);
    Xd_.assign(model_.n_global(), 0.0);
    Xdd_.assign(model_.n_global(), 0.0);
    forces_.element.resize(model_.n_elements());
    outputWork_.nodeTension.resize(model_.n_elements() + 1);
}

CableSimulation::~CableSimulation() {
    integrator_.reset();
    staticSolver_.reset();
    if (context_) SUNContext_Free(&context_);
}

void CableSimulation::set_environment(const LineEnvironment& env) {
    loads_.current.uniform = Vec3(env.current[0], env.current[1], 0.0);
    loads_.current.scale = env.currentScale;
    loads_.current.profile = &model_.current_profile();
    loads_.current.sea = &model_.sea();
    loads_.current.grid = currentGrid_.get();
    loads_.endLoad = vec(env.endLoad);
    loads_.endLoadVelocity = vec(env.endLoadVelocity);
    const double* rows[3] = {env.endLoadDamping.x, env.endLoadDamping.y, env.endLoadDamping.z};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) loads_.endLoadDamping(i, j) = rows[i][j];
    loads_.endCouple = vec(env.endCouple);
}

double CableSimulation::cable_torque(const LineEnvironment& env) {
    const UCParams& p = model_.params();
    if (!p.enableTorsion || p.torqueMode == UC_TORQUE_FREE) return 0.0;
    if (p.torqueMode == UC_TORQUE_PRESCRIBED) return env.torque;
    // Mode 2: H = GJ (Phi - beta) / L with beta from the current shape, unwrapped continuously.
    free_state(q_, v_, a_);
    model_.expand(q_.data(), v_.data(), a_.data(), loads_, state_.time, X_.data(), Xd_.data(), Xdd_.data());
    const double raw = geometric_twist(model_, X_.data(), state_.twistRef);
    const double kTwoPi = 6.28318530717958647692;
    state_.lastBeta += std::remainder(raw - state_.lastBeta, kTwoPi);
    return model_.torque_for_twist(env.twist - state_.lastBeta);
}

void CableSimulation::set_current_grid(std::shared_ptr<const CurrentGrid> grid) {
    currentGrid_ = std::move(grid);
    loads_.current.grid = currentGrid_.get();
    loads_.current.gridOutside = 0;
    currentGridWarned_ = 0;
}

void CableSimulation::set_seabed_grid(std::shared_ptr<const SeabedGrid> grid) {
    replace_model(CableModel(model_.params(), nullptr, nullptr, std::move(grid)));
}

void CableSimulation::warn_outside_current_grid() {
    const unsigned fresh = loads_.current.gridOutside & ~currentGridWarned_;
    if (fresh == 0 || currentGrid_ == nullptr) return;
    currentGridWarned_ |= fresh;
    const CurrentGrid& g = *currentGrid_;
    char text[640];
    if (fresh & CurrentGrid::kOutsideSpace) {
        std::snprintf(text, sizeof text,
                      "warning: at t = %.6g s the line reaches outside the current's data (%s): the current there is "
                      "the data's at the nearest edge, held as MoorDyn holds it; extend the data over the water the line "
                      "moves in",
                      state_.time, g.describe().c_str());
        add_event(text);
    }
    if (fresh & CurrentGrid::kAfterRecord) {
        std::snprintf(text, sizeof text,
                      "warning: at t = %.6g s the run passes the current's last sample (t = %.6g s): the current is held "
                      "at its last values from there (MoorDyn would start the record over); extend the data over the "
                      "run",
                      state_.time, g.last_time());
        add_event(text);
    }
}

void CableSimulation::add_event(const std::string& text) {
    append_event(event_, text);
}

void CableSimulation::step_completed(double t, const double* y, const double* yp) {
    expand_integrator_state(t, y, yp);
    double R[12];
    model_.element_residual(0, X_.data(), Xd_.data(), Xdd_.data(), loads_, R);
    const double tension = std::sqrt(R[0] * R[0] + R[1] * R[1] + R[2] * R[2]);
    stepTensionMax_ = std::max(stepTensionMax_, tension);
    stepTensionMin_ = std::min(stepTensionMin_, tension);
    if (sn_.area > 0.0) state_.rainflow.add(tension, sn_);
    model_.advance_history(X_.data(), syropeHistory_.data());  // (a Syrope line's: the largest mean tension so far)
}

bool CableSimulation::step(double /*t*/, double h, const UCInputs& in, std::string& error) {
    return step(h, tow_motion(in), far_motion(in), line_environment(in), error);
}

bool CableSimulation::step(double h, const EndMotion& tow, const EndMotion& far, const LineEnvironment& env,
                           std::string& error) {
    ++stateStamp_;  // the cached interface derivatives are stale from here on
    for (double v : {tow.position[0], tow.position[1], tow.position[2], tow.velocity[0], tow.velocity[1], tow.velocity[2],
                     tow.acceleration[0], tow.acceleration[1], tow.acceleration[2], env.endLoad[0],
                     env.endLoad[1], env.endLoad[2], env.endCouple[0], env.endCouple[1], env.endCouple[2],
                     env.current[0], env.current[1], far.position[0], far.position[1], far.position[2], far.velocity[0],
                     far.velocity[1], far.velocity[2], h}) {
        if (!std::isfinite(v)) {
            error = "inputs and the step size must be finite numbers";
            return false;
        }
    }
    if (!end_load_linearization_finite(env)) {
        error = "endLoadVelocity and endLoadDamping inputs must be finite numbers";
        return false;
    }
    if (!(h >= UC_MIN_STEP_SIZE) || !(state_.time + h > state_.time)) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "the communication step size %.17g s is below %g s or does not advance the time t = %.17g s",
                      h, UC_MIN_STEP_SIZE, state_.time);
        error = text;
        return false;
    }
    const double winchLengthAtStart = state_.winchLength, winchRateAtStart = state_.winchRate;
    const double winchTop0AtStart = state_.winchTop0;
    set_environment(env);
    loads_.current.rate = Vec3(env.currentRate[0], env.currentRate[1], 0.0);
    loads_.current.rateStart = state_.time;
    loads_.current.scaleRate = env.currentScaleRate;
    if (!std::isfinite(env.currentScale) || !std::isfinite(env.currentScaleRate)) {
        error = "currentScale and its input derivative must be finite numbers";
        return false;
    }
    if (!loads_.current.rate.allFinite()) {
        error = "the input derivatives of current.x/y must be finite numbers";
        return false;
    }
    if (model_.winch()) {
        // A remesh happens at state_.time and must see nothing but the state there (a state restored into
        // a fresh instance has no previous step): the driven ends where they stand, the environment
        // of this step's inputs.
        loads_.tow = TowTrajectory::at_rest_in_time(state_.tow.p(), state_.tow.v(), state_.tow.a(), state_.time);
        loads_.end = TowTrajectory::at_rest_in_time(state_.end.p(), state_.end.v(), state_.end.a(), state_.time);
    }
    if (!std::isfinite(env.torque) || !std::isfinite(env.twist)) {
        error = "torque and twist inputs must be finite numbers";
        return false;
    }
    if (model_.winch()) {
        loads_.torque = cable_torque(env);
        set_winch_time(state_.time);
        if (!winch_rate(env, h, error)) return false;
        // how much the top element changes over the step (the constant-tension winch: at worst twice
        // its present haul-in rate)
        const double change = off_ ? std::min(0.0, 2.0 * y_[1] * h) : state_.winchStep.length(h);
        const int elements = model_.n_elements();
        if (!remesh(change, error)) return false;
        if (!off_ && state_.winchStep.rate0 != winchRateAtStart && elements == model_.n_elements()) {
            // The rate jumps here: the material at the sheave takes the new speed at once (an axial
            // wave). The accelerations of that state, and a restart, as after any discontinuity.
            set_winch_time(state_.time);
            free_state(q_, v_, a_);
            if (!restart_from(error)) return false;
        }
    }
    // Each driven end follows a quintic in time from where the previous step left it (position,
    // velocity and acceleration: it never jumps) to the master's inputs extrapolated to t + h.
    const Vec3 towVelocityInput = tow.velocity, endVelocityInput = far.velocity;
    Vec3 towAcceleration, endAcceleration;
    loads_.tow = state_.tow.next(state_.time, h, state_.lastStepSize, tow.position, towVelocityInput, tow.acceleration,
                           tow.accelerationGiven, towAcceleration);
    const bool externalEnd = model_.far_end().driven;
    if (externalEnd) {
        loads_.end = state_.end.next(state_.time, h, state_.lastStepSize, far.position, endVelocityInput, far.acceleration,
                               far.accelerationGiven, endAcceleration);
    }
    loads_.torque = cable_torque(env);

    if (state_.restartPending) {
        state_.statsBase = total_stats();
        if (!integrator_->restart(state_.time, y_.data(), yp_.data(), error)) return false;
        state_.integratorStarted = true;
        state_.restartPending = false;
    }
    const double tEnd = state_.time + h;
    const Vec3 proxyPosition = vec(state_.outputs.endPosition), proxyVelocity = vec(state_.outputs.endVelocity);
    stepTensionMax_ = stepTensionMin_ = state_.outputs.towTension;  // the tension at the step's start
    const RainflowCounter rainflowAtStart = state_.rainflow;
    syropeAtStep_ = syropeHistory_;  // (no allocation after the first step)
    winchTension_ = env.winchTension;
    const double topAtStart = model_.winch() ? model_.top_length() : 0.0;
    winchTopAtStep_ = topAtStart;
    if (!integrator_->advance(tEnd, error, env.stepBudget)) {
        state_.rainflow = rainflowAtStart;  // the state stays at the last communication point
        std::copy(syropeAtStep_.begin(), syropeAtStep_.end(), syropeHistory_.begin());  // (loads_ points at it)
        state_.restartPending = true;  // the state stays at the last communication point
        state_.winchLength = winchLengthAtStart;
        state_.winchRate = winchRateAtStart;
        state_.winchTop0 = winchTop0AtStart;
        state_.winchStep = WinchStep::hold(state_.winchRate);
        return false;
    }
    if (off_) {  // the constant-tension winch: its unknowns at the end of the step
        const double* end = integrator_->y();
        state_.winchRate = end[1];
        state_.winchTop0 = end[0];
        state_.winchLength = winchLengthAtStart + (end[0] - topAtStart);
    } else if (model_.winch()) {  // the length and the drum's rate at the end of the step
        const double topAtEnd = state_.winchTop0 + state_.winchStep.length(h);
        state_.winchLength = winchLengthAtStart + (topAtEnd - topAtStart);
        state_.winchTop0 = topAtEnd;
        state_.winchRate = state_.winchStep.rate1;
        state_.winchStep = WinchStep::hold(state_.winchRate);
    }
    const double* y = integrator_->y();
    const double* yp = integrator_->yp();
    for (size_t i = 0; i < y_.size(); ++i) {
        y_[i] = y[i];
        yp_[i] = yp[i];
    }
    state_.time = tEnd;
    state_.tow.advance(loads_.tow, towVelocityInput, towAcceleration, tow.accelerationGiven != 0);
    if (externalEnd) state_.end.advance(loads_.end, endVelocityInput, endAcceleration, far.accelerationGiven != 0);
    state_.lastStepSize = h;
    update_outputs();
    if (model_.far_end().proxy) proxy_output(h, proxyPosition, proxyVelocity, far);
    state_.outputs.towTensionMax = std::max(stepTensionMax_, state_.outputs.towTension);
    state_.outputs.towTensionMin = std::min(stepTensionMin_, state_.outputs.towTension);
    warn_of_compression();
    warn_beyond_curve();
    warn_outside_current_grid();
    return true;
}

// The two-sided axial law pushes with the full EA where a cable buckles or goes slack: the first
// time the line carries more compression than an element of it can before buckling (Euler, pinned
// over one element; and more than 1e-3 of the tension scale), the run says so once, with the law to
// use (docs/robustness.md: the slack-snap case peaks at 95 kN two-sided and 406 kN tension-only).
void CableSimulation::warn_of_compression() {
    const UCParams& p = model_.params();
    if (!p.enableCompression || state_.compressionWarned || !(state_.outputs.minTension < -1e-3 * state_.tensionScale)) return;
    double buckling = INFINITY;  // only where there is compression to judge
    for (int e = 0; e < model_.n_elements(); ++e) {
        const double l = model_.element_length(e);
        buckling = std::min(buckling, 9.8696044010893586 * model_.element_section(e).EI / (l * l));
    }
    const double limit = std::max(buckling, 1e-3 * state_.tensionScale);
    if (!(state_.outputs.minTension < -limit)) return;
    state_.compressionWarned = true;
    char text[400];
    std::snprintf(text, sizeof text,
                  "warning: at t = %.6g s the line carries %.4g N of axial compression (minTension), more than an "
                  "element of it carries before buckling (%.4g N): the two-sided axial law (enableCompression = "
                  "true) pushes where a cable goes slack; a line that can go slack wants enableCompression = false",
                  state_.time, -state_.outputs.minTension, buckling);
    add_event(text);
}

void CableSimulation::warn_beyond_curve() {
    if (state_.curveWarned || !model_.axial_curve()) return;
    for (int e = 0; e < model_.n_elements(); ++e) {
        const AxialCurve& curve = model_.element_section(e).curve;
        if (curve.n == 0) continue;
        // the element's mean strain, the one its tension follows: |r'| over its axial points
        const ElementTables& tables = model_.tables(e);
        const double* x = X_.data() + model_.element_offset(e);
        double stretch = 0.0;
        for (const QuadPoint& q : tables.axial) stretch += q.weight * interpolate(q.shape.dN, x).norm();
        const double strain = stretch / tables.length - 1.0;
        if (!(strain > curve.last_strain())) continue;
        state_.curveWarned = true;
        char text[500];
        std::snprintf(text, sizeof text,
                      "warning: at t = %.6g s the line stretches %.4g %% (arc length %.6g to %.6g m), beyond the last "
                      "point of its tension-strain curve (axialCurve: strain %.4g %%, %.6g N): the tension there is "
                      "the curve's straight continuation at its end slope (%.6g N), %.6g N; extend the curve to "
                      "the strains the line reaches",
                      state_.time, 100.0 * strain, model_.element_start(e), model_.element_start(e) + model_.element_length(e),
                      100.0 * curve.last_strain(), curve.tension[curve.n - 1], curve.slope[curve.n - 1], curve(strain));
        add_event(text);
        return;
    }
}

void CableSimulation::expand_integrator_state(double t, const double* y, const double* yp) {
    loads_.current.time = t;
    if (off_) {
        model_.set_top_length(y[0]);
        model_.set_top_rate(y[1]);
    } else {
        set_winch_time(t);
    }
    const int n = model_.n_free();
    for (int j = 0; j < n; ++j) {
        q_[j] = y[2 * (j + off_)];
        v_[j] = y[2 * (j + off_) + 1];
        a_[j] = yp[2 * (j + off_) + 1];
    }
    model_.expand(q_.data(), v_.data(), a_.data(), loads_, t, X_.data(), Xd_.data(), Xdd_.data());
}

int CableSimulation::residual(double t, const double* y, const double* yp, double* r) {
    if (off_ && !(y[0] > 1e-6 * model_.winch_nominal())) return 1;  // no line left in the top element: retry
    expand_integrator_state(t, y, yp);
    const int n = model_.n_free();
    model_.residual(X_.data(), Xd_.data(), Xdd_.data(), loads_, R_.data(), nullptr);
    bool finite = true;
    for (int j = 0; j < n; ++j) {
        const int i = j + off_;
        r[2 * i] = yp[2 * i] - y[2 * i + 1];
        r[2 * i + 1] = R_[j];
        finite = finite && std::isfinite(R_[j]);
    }
    if (off_) {  // the winch: its length changes at its rate, the rate follows the tension
        double Re[12];
        model_.element_residual(0, X_.data(), Xd_.data(), Xdd_.data(), loads_, Re);
        const double tension = line_tension(Re);
        r[0] = yp[0] - y[1];
        // the drum follows the commanded rate with the lag winch.timeConstant (a drum has inertia)
        r[1] = model_.params().winchTimeConstant * yp[1] + y[1] - tension_winch_rate(tension, y[0], nullptr);
        finite = finite && std::isfinite(r[1]);
    }
    return finite ? 0 : 1;  // non-finite: recoverable, IDA retries with a smaller step
}

int CableSimulation::jacobian(double t, const double* y, const double* yp, const EntrySink& sink) {
    expand_integrator_state(t, y, yp);
    if (off_ == 0) {
        model_.jacobian(X_.data(), Xd_.data(), Xdd_.data(), loads_, sink);
        return 0;
    }
    auto shifted = [&](int i, int k, double dq, double dv, double da) { sink(i + 1, k + 1, dq, dv, da); };
    model_.jacobian(X_.data(), Xd_.data(), Xdd_.data(), loads_, shifted);
    // The winch's rows and columns: the top element's residual through its length, the winch's
    // rate (tau a + v = commanded rate) through the tow tension (the reaction at the tow point, rows 0..2 of the top element).
    double Re[12], Rp[12];
    model_.element_residual(0, X_.data(), Xd_.data(), Xdd_.data(), loads_, Re);
    Mat12 K, C, M;
    model_.element_jacobian(0, X_.data(), Xd_.data(), Xdd_.data(), loads_, K, C, M);
    const double top = y[0], delta = 1e-7 * std::max(top, 1.0);
    model_.set_top_length(top + delta);
    model_.element_residual(0, X_.data(), Xd_.data(), Xdd_.data(), loads_, Rp);
    model_.set_top_length(top);
    // T = -R_0..2 . t with t the unit tangent at the tow node (line_tension): dT = u . dR - R . dt
    const double tension = line_tension(Re);
    const Eigen::Map<const Vec3> tangent(X_.data() + 3);
    const Vec3 u = -tangent.normalized();
    const Vec3 dTdTangent = -(Eigen::Map<const Vec3>(Re) - u * u.dot(Eigen::Map<const Vec3>(Re))) / tangent.norm();
    double slope = 0.0;
    tension_winch_rate(tension, top, &slope);
    const int g0 = model_.element_offset(0);
    // the top element's residual through the winch's rate: the material's velocity (set_top_rate)
    const Vec12 dRdc = C * model_.top_rate_direction(X_.data() + g0);
    double dTdl = 0.0, dTdc = 0.0;
    for (int a = 0; a < 3; ++a) {
        dTdl += u[a] * (Rp[a] - Re[a]) / delta;
        dTdc += u[a] * dRdc[a];
    }
    for (int b = 0; b < 12; ++b) {
        const int j = model_.free_index(g0 + b);
        if (j < 0) continue;
        const double cb = model_.coefficient(g0 + b);
        double dK = 0.0, dC = 0.0, dM = 0.0;
        for (int a = 0; a < 3; ++a) {
            dK += u[a] * K(a, b);
            dC += u[a] * C(a, b);
            dM += u[a] * M(a, b);
        }
        if (b >= 3 && b < 6) dK += dTdTangent[b - 3];
        sink(0, j + 1, -slope * cb * dK, -slope * cb * dC, -slope * cb * dM);
        sink(j + 1, 0, cb * (Rp[b] - Re[b]) / delta, cb * dRdc[b], 0.0);
    }
    sink(0, 0, -slope * dTdl, 1.0 - slope * dTdc, model_.params().winchTimeConstant);
    return 0;
}

IntegratorStats CableSimulation::total_stats() const {
    return state_.integratorStarted ? state_.statsBase + integrator_->stats() : state_.statsBase;
}

std::string CableSimulation::take_event() {
    std::string event;
    event.swap(event_);
    return event;
}

bool CableSimulation::restart_from(std::string& error) {
    if (!solve_consistent_acceleration(model_, *staticSolver_, loads_, state_.time, q_, v_, a_)) {
        error = "winch: the mass matrix of the line is singular";
        return false;
    }
    for (int j = 0; j < model_.n_free(); ++j) {
        y_[2 * (j + off_)] = q_[j];
        y_[2 * (j + off_) + 1] = v_[j];
        yp_[2 * (j + off_)] = v_[j];
        yp_[2 * (j + off_) + 1] = a_[j];
    }
    state_.restartPending = true;
    return true;
}

void CableSimulation::rebuild(const WinchMesh& mesh) { replace_model(CableModel(model_.params(), &mesh, nullptr, model_.seabed_grid())); }

void CableSimulation::replace_model(CableModel&& model) {
    state_.statsBase = total_stats();
    state_.integratorStarted = false;
    state_.restartPending = true;
    integrator_.reset();
    staticSolver_.reset();
    model_ = std::move(model);
    allocate();
    for (auto& lu : derivativeLU_) lu.reset();
    derivativeK_.reset();
    derivativeC_.reset();
    derivativeM_.reset();
    derivativeWork_.clear();
    derivativeStamp_ = -1;
    loads_.current.profile = &model_.current_profile();
    loads_.current.sea = &model_.sea();
    loads_.current.grid = currentGrid_.get();
}

void CableSimulation::free_state(std::vector<double>& q, std::vector<double>& v, std::vector<double>& a) const {
    const int n = model_.n_free();
    q.resize(n);
    v.resize(n);
    a.resize(n);
    for (int j = 0; j < n; ++j) {
        q[j] = y_[2 * (j + off_)];
        v[j] = y_[2 * (j + off_) + 1];
        a[j] = yp_[2 * (j + off_) + 1];
    }
}

void CableSimulation::store_section_ends() {
    sectionEnds_.assign(static_cast<size_t>(model_.n_sections()), Vec3::Zero());  // no allocation after the first call
    for (const ElementRun& run : model_.runs())  // along the line: a section's last run its last
        sectionEnds_[run.section] = Eigen::Map<const Vec3>(X_.data() + model_.element_offset(run.first + run.count - 1) + 6);
}

void CableSimulation::update_outputs() {
    expand_integrator_state(state_.time, y_.data(), yp_.data());
    model_.residual(X_.data(), Xd_.data(), Xdd_.data(), loads_, R_.data(), &forces_);
    compute_outputs(model_, X_.data(), Xd_.data(), syropeHistory_.data(), forces_, loads_.torque, outputWork_,
                    state_.outputs);
    store_section_ends();
    const IntegratorStats s = total_stats();
    state_.outputs.nSteps = s.steps;
    state_.outputs.nResidualEvals = s.residualEvals;
    state_.outputs.nJacobianEvals = s.jacobianEvals;
    state_.outputs.nNonlinearFailures = s.nonlinearFailures;
    state_.outputs.nErrorTestFailures = s.errorTestFailures;
    state_.outputs.tensionScale = state_.tensionScale;
    state_.outputs.fatigueDamage = sn_.area > 0.0 ? state_.rainflow.damage(sn_) : 0.0;
    state_.outputs.waveElevation = model_.sea().elevation(X_[0], X_[1], state_.time);
    state_.outputs.unstretchedLength = model_.winch() ? state_.winchLength : model_.line().length;
    complete_outputs(state_.outputs);
}

}  // namespace uc
