// statics.cpp - Newton with line search and adaptive load continuation, all banded.
#include "line/statics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace uc {
namespace {

constexpr int kMaxNewtonIterations = 400;
// Beyond this pseudo time step [s] the fictitious inertia is dropped: pure Newton.
constexpr double kNewtonTimeScale = 1e6;
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
    s.current.uniform *= lambda;
    s.current.profileScale *= lambda;
    s.end = loads.end.steady(lambda);
    s.endLoad *= lambda;
    s.endLoadVelocity *= lambda;  // the linearized end load scales with the flow as well
    s.endCouple *= lambda;
    s.torque *= lambda;
    s.tow = loads.tow.steady(lambda);
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
    const LineScales& line = model.line();
    const double weight = line.massPerLength * p.gravity * line.length;
    return std::max({weight, loads.endLoad.norm(), loads.endCouple.norm() / line.length, p.bodyMass * p.gravity, 1.0});
}

// Pseudo-transient continuation (implicit steps of a fictitious motion from rest, SER rule):
// solve (K + M / dtau^2) dq = -R. For small dtau the mass limits the step where the cable has
// little stiffness (a hanging cable swinging back in the flow); as the residual falls, dtau grows
// and the iteration becomes Newton's method with quadratic convergence. Converged when the
// correction reaches round-off (|dq| <= 1e-11 L) or the residual reaches the round-off level of
// the axial forces or its floor (StaticsResult::residualFloor).
bool newton(const CableModel& model, BandSolver& solver, const Loads& loads, double t,
            std::vector<double>& q, Workspace& w, StaticsResult& result, double* work) {
    const int n = model.n_free();
    const UCParams& p = model.params();
    const double length = model.line().length;
    double shortest = model.element_length(0);
    for (const ElementRun& run : model.runs()) shortest = std::min(shortest, run.elementLength);
    double norm = residual_norm(model, loads, t, q, w);
    // Round-off of the axial forces: |r'| comes from shape-function sums of coordinates of size
    // |X| with weights ~1/l, so it carries an error of about eps |X| / l, times EA.
    double coordinate = length;
    for (int g = 0; g < 6 * model.n_slots(); g += 6) coordinate = std::max(coordinate, Eigen::Map<const Vec3>(w.X.data() + g).norm());
    const double roundOff = std::max(1e-12 * force_scale(model, loads),
                                     64.0 * model.line().EA * std::min(1.0, loads.axialStiffnessScale) * std::numeric_limits<double>::epsilon() *
                                         (1.0 + coordinate / shortest));
    std::vector<double> dq(n), trial(n), terms(n);
    double dtau = 0.1 * std::sqrt(length / std::max(p.gravity, 0.1));
    for (int it = 0; it < kMaxNewtonIterations; ++it) {
        result.residualNorm = norm;
        if (!std::isfinite(norm)) return false;
        if (norm <= roundOff) return true;
        solver.clear();
        const double inertia = dtau < kNewtonTimeScale ? 1.0 / (dtau * dtau) : 0.0;
        std::fill(terms.begin(), terms.end(), 0.0);
        model.jacobian(w.X.data(), w.Xd.data(), w.Xdd.data(), loads,
                       [&](int i, int j, double dR_dq, double, double dR_da) {
                           solver.add(i, j, dR_dq + inertia * dR_da);
                           terms[i] += std::abs(dR_dq * q[j]);
                       });
        result.residualFloor = std::numeric_limits<double>::epsilon() * max_abs(terms);
        if (norm <= result.residualFloor) return true;
        for (int j = 0; j < n; ++j) dq[j] = -w.R[j];
        if (!solver.factor_and_solve(dq.data())) return false;
        ++result.newtonIterations;
        if (work && (*work -= model.n_elements()) <= 0.0) {
            result.budgetSpent = true;
            return false;
        }
        if (inertia == 0.0 && max_abs(dq) <= 1e-11 * length) {
            for (int j = 0; j < n; ++j) q[j] += dq[j];
            result.residualNorm = residual_norm(model, loads, t, q, w);
            return true;
        }
        for (int j = 0; j < n; ++j) trial[j] = q[j] + dq[j];
        const double trialNorm = residual_norm(model, loads, t, trial, w);
        // PTC steps need not decrease the residual (the fictitious motion may first swing the
        // cable); only a blow-up is rejected. Pure Newton steps must decrease it.
        const bool accept = inertia > 0.0 ? trialNorm < 10.0 * norm : trialNorm < norm;
        if (accept) {
            q.swap(trial);
            dtau *= std::clamp(norm / trialNorm, 2.0, 10.0);
            norm = trialNorm;
        } else {
            residual_norm(model, loads, t, q, w);  // leave the workspace consistent with q
            if (inertia == 0.0 && max_abs(dq) <= 1e-8 * length) return norm <= 1e3 * roundOff;
            dtau = std::min(dtau, kNewtonTimeScale) * 0.25;
            if (dtau < 1e-8) return false;
        }
    }
    result.residualNorm = norm;
    return false;
}

// Pure Newton steps at the final loads for as long as they still reduce the residual: the
// convergence tests above stop at an estimate of the round-off level, and where the structure
// is very compliant (a long cantilever's tip) the remaining residual still moves the solution.
void polish(const CableModel& model, BandSolver& solver, const Loads& loads, double t, std::vector<double>& q,
            Workspace& w, StaticsResult& result) {
    const int n = model.n_free();
    std::vector<double> dq(n), trial(n);
    double norm = residual_norm(model, loads, t, q, w);
    for (int it = 0; it < 5; ++it) {
        solver.clear();
        model.jacobian(w.X.data(), w.Xd.data(), w.Xdd.data(), loads,
                       [&](int i, int j, double dR_dq, double, double) { solver.add(i, j, dR_dq); });
        for (int j = 0; j < n; ++j) dq[j] = -w.R[j];
        if (!solver.factor_and_solve(dq.data())) break;
        for (int j = 0; j < n; ++j) trial[j] = q[j] + dq[j];
        const double trialNorm = residual_norm(model, loads, t, trial, w);
        if (!(trialNorm < norm)) break;
        q.swap(trial);
        norm = trialNorm;
        ++result.newtonIterations;
    }
    residual_norm(model, loads, t, q, w);
    result.residualNorm = norm;
}

// Sets the failure message (printf format) and returns the result.
template <class... Args>
StaticsResult failed(StaticsResult& result, const char* format, Args... args) {
    char buffer[400];
    std::snprintf(buffer, sizeof buffer, format, args...);
    result.message = buffer;
    return result;
}

// The stages after the continuation, on the real EA: the dense seabed contact, then the
// tension-only law, then the final Newton polish. False with the message set.
bool final_stages(const CableModel& model, BandSolver& solver, const Loads& loads, double t, Loads& staged,
                  std::vector<double>& q, Workspace& w, StaticsResult& result, double* work) {
    if (staged.axialContactOnly) {
        staged.axialContactOnly = false;
        ++result.continuationSteps;
        if (!newton(model, solver, staged, t, q, w, result, work)) {
            failed(result, "static equilibrium not found with the seabed contact sampled every "
                           "seabedContactSpacing: residual %.3g N after %d iterations",
                   result.residualNorm, result.newtonIterations);
            return false;
        }
    }
    if (model.section(0).axial.tensionOnly) {
        // The tension-only law differs only where the two-sided equilibrium is in compression or
        // within 1e-5 strain of it: start from that equilibrium.
        staged.twoSidedAxial = false;
        ++result.continuationSteps;
        if (!newton(model, solver, staged, t, q, w, result, work)) {
            failed(result, "static equilibrium not found with the tension-only law (enableCompression = "
                           "false): residual %.3g N after %d iterations; part of the line is slack at rest, "
                           "where a line without bending stiffness has no one shape",
                   result.residualNorm, result.newtonIterations);
            return false;
        }
    }
    polish(model, solver, loads, t, q, w, result);
    result.converged = true;
    return true;
}

}  // namespace

StaticsResult solve_static_equilibrium(const CableModel& model, BandSolver& solver, const Loads& dynamicLoads,
                                       double t, const std::vector<double>& vSteady,
                                       std::vector<double>& q, bool nearGuess, double* work) {
    Loads loads = dynamicLoads;
    loads.viv = false;  // no lift at rest, the VIV phases held at their start (as MoorDyn's initial conditions)
    StaticsResult result;
    Workspace w(model);
    auto first_stage = [&] {
        Loads staged = loads;
        staged.twoSidedAxial = true;  // a tension-only cable switches to its law at the end
        // With contact sampled densely the continuation from a guess that lies partly below the
        // seabed can settle into another equilibrium (excess length stored in a bump on the seabed,
        // measured on a stiff power cable at 40 to 80 elements); on the elements' axial points it
        // does not, and the dense contact then only moves the answer a little: it is switched on at
        // the end.
        staged.axialContactOnly = model.dense_contact();
        return staged;
    };
    Loads staged = first_stage();
    for (int j = 0; j < model.n_free(); ++j) w.v[j] = vSteady[j];
    const std::vector<double> guess = q;
    if (nearGuess) {
        // From the line's static profile: Newton's method on the real cable at the full loads,
        // with the continuation below only where that fails.
        ++result.continuationSteps;
        if (newton(model, solver, staged, t, q, w, result, work) && final_stages(model, solver, loads, t, staged, q, w, result, work))
            return result;
        if (result.budgetSpent) return failed(result, "static equilibrium not found within the work budget");
        q = guess;
        result = StaticsResult();
        staged = first_stage();
    }
    // Stiffness continuation: first a soft cable (about 1 % strain under the loads), on which
    // large rotations are cheap, then EA grows tenfold per stage to its real value.
    const double EA = model.line().EA;
    double stiffness = std::min(1.0, 100.0 * force_scale(model, loads) / EA);
    std::vector<double> accepted = q;
    double lambda = 0.0, step = 1.0;
    bool first = true;
    staged.axialStiffnessScale = stiffness;
    // Load continuation on the soft cable: lambda scales the relative flow and the end load.
    while (result.continuationSteps < kMaxContinuationSteps) {
        const double target = first ? 1.0 : std::min(1.0, lambda + step);
        Loads scaled = scaled_loads(staged, target);
        for (int j = 0; j < model.n_free(); ++j) w.v[j] = target * vSteady[j];
        ++result.continuationSteps;
        if (newton(model, solver, scaled, t, q, w, result, work)) {
            accepted = q;
            lambda = target;
            step = std::min(1.0, 2.0 * step);
            if (lambda >= 1.0) break;
        } else if (result.budgetSpent) {
            return failed(result, "static equilibrium not found within the work budget");
        } else {
            q = accepted;
            step = first ? 0.25 : 0.25 * step;
            if (step < 1e-4) break;
        }
        first = false;
    }
    if (lambda < 1.0) {
        return failed(result, "static equilibrium not found: Newton's method from the %s stalled at %.4g of the "
                              "full flow and end loads (residual %.3g N after %d iterations)",
                      nearGuess ? "line's static profile and then the continuation" : "continuation", lambda,
                      result.residualNorm, result.newtonIterations);
    }
    for (int j = 0; j < model.n_free(); ++j) w.v[j] = vSteady[j];
    while (stiffness < 1.0) {
        stiffness = std::min(1.0, 10.0 * stiffness);
        staged.axialStiffnessScale = stiffness;
        ++result.continuationSteps;
        if (!newton(model, solver, staged, t, q, w, result, work)) {
            return failed(result, "static equilibrium not found: stiffening the cable to %.3g of EA failed "
                                  "(residual %.3g N after %d iterations)",
                          stiffness, result.residualNorm, result.newtonIterations);
        }
    }
    final_stages(model, solver, loads, t, staged, q, w, result, work);
    return result;
}

bool solve_consistent_acceleration(const CableModel& model, BandSolver& solver, const Loads& loads,
                                   double t, const std::vector<double>& q,
                                   const std::vector<double>& v, std::vector<double>& a) {
    Workspace w(model);
    model.expand(q.data(), v.data(), w.zero.data(), loads, t, w.X.data(), w.Xd.data(), w.Xdd.data());
    model.residual(w.X.data(), w.Xd.data(), w.Xdd.data(), loads, w.R.data(), nullptr);
    solver.clear();
    // An internal strain's or a VIV phase's equation has no acceleration of its own (its rate is the given
    // one): a' = 0 there (a phase's row, which sees the nodes' accelerations, left out).
    std::vector<char> firstOrder(model.n_free(), 0);
    for (int e = 0; e < model.n_elements(); ++e)
        for (const int g : {model.internal_offset(e), model.phase_offset(e)})
            if (g >= 0) firstOrder[model.free_index(g)] = 1;
    model.jacobian(w.X.data(), w.Xd.data(), w.Xdd.data(), loads, [&](int i, int j, double, double, double da) {
        if (!firstOrder[i]) solver.add(i, j, da);
    });
    for (int j = 0; j < model.n_free(); ++j)
        if (firstOrder[j]) {
            solver.add(j, j, 1.0);
            w.R[j] = 0.0;
        }
    a.resize(model.n_free());
    for (int j = 0; j < model.n_free(); ++j) a[j] = -w.R[j];
    return solver.factor_and_solve(a.data());
}

}  // namespace uc
