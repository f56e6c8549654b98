// winch_mesh.cpp - the line's winch (docs/winch.md): the rate over a step, the constant-tension winch's
// rate, and the remesh (split, merge) with the nodes it makes balanced.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>

#include "line/simulation.h"
#include "line/simulation_internal.h"

#include "line/winch.h"

namespace uc {

// The constant-tension winch's rate for the tow tension T with the top element at topLength:
// (T - T_set) times the line's axial compliance over winch.timeConstant, within winch.maxRate and
// stopped at the length limits; slope = d rate / dT (0 where limited).
double CableSimulation::line_tension(const double* R) const {
    return -Eigen::Map<const Vec3>(R).dot(Eigen::Map<const Vec3>(X_.data() + 3).normalized());
}

double CableSimulation::tension_winch_rate(double tension, double topLength, double* slope) const {
    const UCParams& p = model_.params();
    const double gain = model_.axial_compliance() / p.winchTimeConstant;
    double rate = gain * (tension - winchTension_);
    double dRate = gain;
    if (std::abs(rate) > p.winchMaxRate) {
        rate = std::copysign(p.winchMaxRate, rate);
        dRate = 0.0;
    }
    const double length = state_.winchLength + (topLength - winchTopAtStep_);
    if ((length >= p.winchMaxLength && rate > 0.0) || (length <= p.winchMinLength && rate < 0.0)) {
        rate = 0.0;
        dRate = 0.0;
    }
    const double braked = braking_rate_limit(rate, length, winch_limits());  // in time for the limits
    if (braked != rate) {
        rate = braked;
        dRate = 0.0;
    }
    if (slope) *slope = dRate;
    return rate;
}

void CableSimulation::set_winch_time(double t) {
    if (!model_.winch()) return;
    model_.set_top_length(off_ ? y_[0] : state_.winchTop0 + state_.winchStep.length(t - state_.time));
    model_.set_top_rate(off_ ? y_[1] : state_.winchStep.rate(t - state_.time));
}

WinchLimits CableSimulation::winch_limits() const {
    const UCParams& p = model_.params();
    return WinchLimits{p.winchMinLength, p.winchMaxLength, p.winchMaxRate, p.winchMaxAcceleration};
}

bool CableSimulation::winch_rate(const LineEnvironment& env, double h, std::string& error) {
    const UCParams& p = model_.params();
    for (const auto& [name, value] : {std::pair<const char*, double>{"winch.rate", env.winchRate},
                                      std::pair<const char*, double>{"winch.tension", env.winchTension}}) {
        if (std::isfinite(value)) continue;
        char text[160];
        std::snprintf(text, sizeof text, "%s = %g: the winch's inputs must be finite numbers", name, value);
        error = text;
        return false;
    }
    const WinchLimits limits = winch_limits();
    state_.winchTop0 = model_.top_length();
    if (p.winchMode == UC_WINCH_TENSION) return true;  // the rate follows the tension, step by step
    const double requested = env.winchRate;
    if (!std::isfinite(env.winchRateRate)) {
        char text[160];
        std::snprintf(text, sizeof text, "der(winch.rate) = %g m/s2: the input derivative must be a finite number",
                      env.winchRateRate);
        error = text;
        return false;
    }
    state_.winchStep = plan_winch_step(requested, state_.winchRate, state_.winchLength, h, limits, env.winchRateRate);
    // maxRate cut the command: log the arrival once.
    if (state_.winchStep.rateLimited && !state_.winchRateLimited) {
        char text[300];
        std::snprintf(text, sizeof text,
                      "winch: at t = %.6g s winch.rate %.6g m/s is beyond winch.maxRate = %.6g m/s: the drum runs at "
                      "most at winch.maxRate (deployed length %.6g m)",
                      state_.time, requested + env.winchRateRate * h, limits.maxRate, state_.winchLength);
        add_event(text);
    }
    state_.winchRateLimited = state_.winchStep.rateLimited;
    // A length limit cut the request (not the speed limit): log the arrival once.
    const int limit = state_.winchStep.limit;
    if (limit != 0 && limit != state_.winchLimit) {
        char text[300];
        std::snprintf(text, sizeof text,
                      "winch: at t = %.6g s %s winch.%s = %.6g m: %s stops there (deployed length %.6g m at the "
                      "step's end; winch.rate %.6g m/s applied as %.6g m/s)",
                      state_.time, limits.maxAcceleration > 0.0 ? "the drum brakes to stop at" : "the deployed length reaches",
                      limit > 0 ? "maxLength" : "minLength", limit > 0 ? limits.maxLength : limits.minLength,
                      limit > 0 ? "paying out" : "hauling in", state_.winchLength + state_.winchStep.length(h), requested,
                      state_.winchStep.rate1);
        add_event(text);
    }
    state_.winchLimit = limit;
    if (limit != 0 && limits.maxAcceleration > 0.0 && state_.winchRate != 0.0 && state_.winchStep.rate1 == 0.0) {
        // braking along its envelope, the drum comes to rest at the limit within this step
        char text[200];
        std::snprintf(text, sizeof text, "winch: at t = %.6g s the drum stops at winch.%s = %.6g m",
                      state_.time + state_.winchStep.rampTime, limit > 0 ? "maxLength" : "minLength",
                      limit > 0 ? limits.maxLength : limits.minLength);
        add_event(text);
    }
    return true;
}

// Splits the top element when it has grown past 1.5 nominal lengths (the lower part becomes a
// nominal element, exactly the same cubic), merges it with the element below when it has shrunk
// under half of one (docs/winch.md). At a communication point; the integrator restarts.
namespace {

// Split above 1.5 nominal lengths, merge under 0.5 (remesh_action), and merge too when the step
// would haul the top element in below a quarter of a nominal length (change: of the top element
// over the step); no split that would leave it so short. Neither undoes the other.
RemeshAction next_remesh(double top, double nominal, int elements, double change) {
    RemeshAction action = remesh_action(top, nominal, elements > 1);
    const double end = top + change;
    if (action == RemeshAction::Split && end - nominal < 0.25 * nominal) action = RemeshAction::None;
    if (action == RemeshAction::None && elements > 1 && end < 0.25 * nominal) action = RemeshAction::Merge;
    return action;
}

}  // namespace

bool CableSimulation::remesh(double change, std::string& error) {
    const double nominal = model_.winch_nominal();
    // How many passes the step needs (a split makes the top element one nominal length shorter,
    // a merge one longer).
    int passes = 0;
    for (double top = model_.top_length(), elements = model_.winch_mesh().elements; passes < kMaxRemeshPasses;
         ++passes) {
        const RemeshAction action = next_remesh(top, nominal, static_cast<int>(elements), change);
        if (action == RemeshAction::None) break;
        top += action == RemeshAction::Split ? -nominal : nominal;
        elements += action == RemeshAction::Split ? 1 : -1;
    }
    for (int pass = 0; pass < passes; ++pass) {
        const RemeshAction action =
            next_remesh(model_.top_length(), nominal, model_.winch_mesh().elements, change);
        if (action == RemeshAction::None) break;
        // Only one remesh per step starts the line in balance: a winch that moves more than an
        // element per step on a fine mesh makes nodes faster than the balance can follow them.
        if (!remesh_once(action, passes == 1, error)) return false;
    }
    return true;
}

bool CableSimulation::remesh_once(RemeshAction action, bool balance, std::string& error) {
    const double top = model_.top_length(), nominal = model_.winch_nominal();
    const WinchMesh mesh = model_.winch_mesh();
    expand_integrator_state(state_.time, y_.data(), yp_.data());
    const int G = model_.n_global();
    std::vector<double> X, Xd, Xdd;
    WinchMesh next;
    if (action == RemeshAction::Split) {
        const double a = top - nominal;  // the new top element; the rest is nominal
        double node[3][6], material[12];
        hermite_split_node(X_.data(), top, a, node[0]);
        // the new node is material: the velocity of the material there, not of the mesh point
        model_.top_material_velocity(X_.data(), Xd_.data(), material);
        hermite_split_node(material, top, a, node[1]);
        hermite_split_node(Xdd_.data(), top, a, node[2]);
        const std::vector<double>* from[3] = {&X_, &Xd_, &Xdd_};
        std::vector<double>* to[3] = {&X, &Xd, &Xdd};
        for (int f = 0; f < 3; ++f) {
            to[f]->assign(from[f]->begin(), from[f]->begin() + 6);
            to[f]->insert(to[f]->end(), node[f], node[f] + 6);
            to[f]->insert(to[f]->end(), from[f]->begin() + 6, from[f]->begin() + G);
        }
        next = WinchMesh{mesh.elements + 1, a};
    } else {
        const std::vector<double>* from[3] = {&X_, &Xd_, &Xdd_};
        std::vector<double>* to[3] = {&X, &Xd, &Xdd};
        for (int f = 0; f < 3; ++f) {  // the node between the top element and the next one goes
            to[f]->assign(from[f]->begin(), from[f]->begin() + 6);
            to[f]->insert(to[f]->end(), from[f]->begin() + 12, from[f]->begin() + G);
        }
        next = WinchMesh{mesh.elements - 1, top + nominal};
    }
    rebuild(next);
    state_.winchTop0 = next.topLength;
    model_.set_top_length(state_.winchTop0);
    model_.set_top_rate(off_ ? state_.winchRate : state_.winchStep.rate0);
    if (balance) {
        // The tow node's tangent (unless clamped) and the first nodes below the top element (within
        // the first section): their equations of motion, with the accelerations the line had, decide
        // where they stand on the new mesh (docs/winch.md, "Split and merge").
        const bool hinged = model_.params().topEnd != UC_TOP_CLAMPED;
        const int nodes = std::min(kBalanceNodes, model_.winch_mesh().elements - 1);
        balance_dofs(hinged ? 3 : 6, (hinged ? 3 : 0) + 6 * nodes, X, Xd, Xdd);
    }
    model_.restrict_to_free(X.data(), q_.data());
    model_.restrict_to_free(Xd.data(), v_.data());
    // The accelerations of the new mesh's equations (the merged element has its own mass matrix).
    if (!restart_from(error)) return false;
    if (off_) {
        y_[0] = next.topLength;
        y_[1] = yp_[0] = state_.winchRate;
        yp_[1] = 0.0;
    }
    ++stateStamp_;
    return set_integrator_tolerances(error);
}

void CableSimulation::dof_residual(int g, int count, const std::vector<double>& X, const std::vector<double>& Xd,
                                   const std::vector<double>& Xdd, Eigen::VectorXd& R, Eigen::MatrixXd* J) {
    R.setZero();
    if (J) J->setZero();
    for (int e = 0; e < model_.n_elements(); ++e) {
        const int off = model_.element_offset(e);
        if (off + 12 <= g || off >= g + count) continue;
        double Re[12];
        Mat12 K, C, M;
        model_.element_residual(e, X.data(), Xd.data(), Xdd.data(), loads_, Re);
        if (J) model_.element_jacobian(e, X.data(), Xd.data(), Xdd.data(), loads_, K, C, M);
        for (int i = 0; i < count; ++i) {
            const int a = g + i - off;
            if (a < 0 || a >= 12) continue;
            R[i] += Re[a];
            if (!J) continue;
            for (int k = 0; k < count; ++k) {
                const int b = g + k - off;
                if (b >= 0 && b < 12) (*J)(i, k) += K(a, b);
            }
        }
    }
}

void CableSimulation::balance_dofs(int g, int count, std::vector<double>& X, const std::vector<double>& Xd,
                                   const std::vector<double>& Xdd) {
    // Newton with halving of the step while the residual does not fall; a step that finds nothing
    // better ends the search (the DOFs stay where the last accepted step left them).
    Eigen::MatrixXd J(count, count);
    Eigen::VectorXd R(count), trialR(count);
    std::vector<double> trial = X;
    dof_residual(g, count, X, Xd, Xdd, R, &J);
    double norm = R.norm();
    for (int iteration = 0; iteration < kMaxBalanceIterations && std::isfinite(norm) && norm > 0.0; ++iteration) {
        const Eigen::VectorXd dx = -J.partialPivLu().solve(R);
        if (!dx.allFinite()) return;
        bool accepted = false;
        for (double lambda = 1.0; lambda > 1e-3 && !accepted; lambda *= 0.5) {
            for (int i = 0; i < count; ++i) trial[g + i] = X[g + i] + lambda * dx[i];
            dof_residual(g, count, trial, Xd, Xdd, trialR, nullptr);
            accepted = std::isfinite(trialR.norm()) && trialR.norm() < norm;
        }
        if (!accepted) return;
        for (int i = 0; i < count; ++i) X[g + i] = trial[g + i];
        if (!(dx.lpNorm<Eigen::Infinity>() > 1e-13 * model_.winch_nominal())) return;
        dof_residual(g, count, X, Xd, Xdd, R, &J);
        norm = R.norm();
    }
}

}  // namespace uc
