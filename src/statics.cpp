// statics.cpp - Newton with line search and adaptive load continuation, all banded.
#include "statics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace uc {
namespace {

constexpr int kMaxNewtonIterations = 60;
constexpr int kMaxContinuationSteps = 200;

struct Workspace {
    std::vector<double> X, Xd, Xdd, R, zero, v;
    explicit Workspace(const CableModel& m)
        : X(m.n_global()), Xd(m.n_global()), Xdd(m.n_global()), R(m.n_free()),
          zero(m.n_free(), 0.0), v(m.n_free()) {}
};

double max_abs(const std::vector<double>& x) {
    double m = 0.0;
    for (double xi : x) m = std::max(m, std::abs(xi));
    return m;
}

// Loads with the relative flow and end load scaled by lambda.
Loads scaled_loads(const Loads& loads, double lambda) {
    Loads s = loads;
    s.current *= lambda;
    s.endLoad *= lambda;
    s.tow.v0 *= lambda;
    s.tow.v1 *= lambda;
    s.tow.a0.setZero();
    return s;
}

double residual_norm(const CableModel& model, const Loads& loads, double t, const std::vector<double>& q,
                     Workspace& w) {
    model.expand(q.data(), w.v.data(), w.zero.data(), loads, t, w.X.data(), w.Xd.data(), w.Xdd.data());
    model.residual(w.X.data(), w.Xd.data(), w.Xdd.data(), loads, w.R.data(), nullptr);
    for (double r : w.R)
        if (!std::isfinite(r)) return INFINITY;
    return max_abs(w.R);
}

// A force scale for convergence tests: weight of the whole cable, end load, tension scale.
double force_scale(const CableModel& model, const Loads& loads) {
    const UCParams& p = model.params();
    const double weight = p.massPerLength * p.gravity * p.length;
    return std::max({weight, loads.endLoad.norm(), p.bodyMass * p.gravity, 1.0});
}

// Newton iterations at fixed loads. True when the residual reaches round-off level.
bool newton(const CableModel& model, BandSolver& solver, const Loads& loads, double t,
            std::vector<double>& q, Workspace& w, StaticsResult& result) {
    const int n = model.n_free();
    const double scale = force_scale(model, loads);
    const double length = model.params().length;
    std::vector<double> dq(n), trial(n);
    double norm = residual_norm(model, loads, t, q, w);
    for (int it = 0; it < kMaxNewtonIterations; ++it) {
        if (!std::isfinite(norm)) return false;
        solver.clear();
        model.jacobian(w.X.data(), w.Xd.data(), w.Xdd.data(), loads,
                       [&](int i, int j, double dq_, double, double) { solver.add(i, j, dq_); });
        for (int j = 0; j < n; ++j) dq[j] = -w.R[j];
        if (!solver.factor_and_solve(dq.data())) return false;
        ++result.newtonIterations;
        // Backtracking line search on the max-norm of the residual.
        double alpha = 1.0, trialNorm = INFINITY;
        for (int ls = 0; ls < 30; ++ls) {
            for (int j = 0; j < n; ++j) trial[j] = q[j] + alpha * dq[j];
            trialNorm = residual_norm(model, loads, t, trial, w);
            if (trialNorm < (1.0 - 1e-4 * alpha) * norm || trialNorm <= 1e-12 * scale) break;
            alpha *= 0.5;
        }
        const double stepSize = alpha * max_abs(dq);
        if (!(trialNorm < norm) && !(stepSize <= 1e-13 * length)) {
            // No decrease possible: converged if already at round-off, otherwise failed.
            residual_norm(model, loads, t, q, w);  // leave w consistent with q
            result.residualNorm = norm;
            return norm <= 1e-9 * scale;
        }
        q.swap(trial);
        norm = trialNorm;
        // Quadratic convergence ends at round-off: a full step that no longer moves the solution.
        if (alpha == 1.0 && stepSize <= 1e-13 * length) break;
        if (norm <= 1e-13 * scale) break;
    }
    result.residualNorm = norm;
    return norm <= 1e-9 * scale;
}

}  // namespace

StaticsResult solve_static_equilibrium(const CableModel& model, BandSolver& solver, const Loads& loads,
                                       double t, const std::vector<double>& vSteady,
                                       std::vector<double>& q) {
    StaticsResult result;
    Workspace w(model);
    std::vector<double> accepted = q;
    double lambda = 0.0, step = 1.0;
    bool first = true;
    while (result.continuationSteps < kMaxContinuationSteps) {
        const double target = first ? 0.0 : std::min(1.0, lambda + step);
        const Loads scaled = scaled_loads(loads, target);
        for (int j = 0; j < model.n_free(); ++j) w.v[j] = target * vSteady[j];
        ++result.continuationSteps;
        if (newton(model, solver, scaled, t, q, w, result)) {
            accepted = q;
            lambda = target;
            if (!first) step = std::min(1.0, 2.0 * step);
            first = false;
            if (lambda >= 1.0) {
                result.converged = true;
                return result;
            }
        } else {
            q = accepted;
            if (first) {
                // Gravity alone did not converge from the initial guess: go straight to full loads.
                first = false;
                continue;
            }
            step *= 0.25;
            if (step < 1e-4) break;
        }
    }
    char buffer[256];
    std::snprintf(buffer, sizeof buffer,
                  "static equilibrium not found: load continuation stalled at %.4g of the full loads "
                  "(residual %.3g N after %d Newton iterations); try initMode = 1 or another initialDirection",
                  lambda, result.residualNorm, result.newtonIterations);
    result.message = buffer;
    return result;
}

bool solve_consistent_acceleration(const CableModel& model, BandSolver& solver, const Loads& loads,
                                   double t, const std::vector<double>& q,
                                   const std::vector<double>& v, std::vector<double>& a) {
    Workspace w(model);
    model.expand(q.data(), v.data(), w.zero.data(), loads, t, w.X.data(), w.Xd.data(), w.Xdd.data());
    model.residual(w.X.data(), w.Xd.data(), w.Xdd.data(), loads, w.R.data(), nullptr);
    solver.clear();
    model.jacobian(w.X.data(), w.Xd.data(), w.Xdd.data(), loads,
                   [&](int i, int j, double, double, double da) { solver.add(i, j, da); });
    a.resize(model.n_free());
    for (int j = 0; j < model.n_free(); ++j) a[j] = -w.R[j];
    return solver.factor_and_solve(a.data());
}

}  // namespace uc
