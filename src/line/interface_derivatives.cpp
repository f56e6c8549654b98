// interface_derivatives.cpp - the interface derivatives over the next communication step
// (docs/cosimulation.md, "Interface derivatives").
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>

#include "line/simulation.h"
#include "line/simulation_internal.h"

namespace uc {

bool CableSimulation::prepare_derivatives(std::string& error) {
    if (off_) {
        error = "the interface derivatives are not available with the constant-tension winch (winchMode 2): its "
                "length is an unknown the linearization does not carry";
        return false;
    }
    if (!(state_.lastStepSize > 0.0)) {
        error = "the interface derivatives are over the next communication step, taken as long as the last one: "
                "they are available after the first fmi2DoStep";
        return false;
    }
    if (derivativeStamp_ == stateStamp_) return true;  // the state has not changed since
    const int n = model_.n_free(), N = model_.n_elements(), bw = model_.free_bandwidth();
    if (!derivativeK_) {
        for (auto& lu : derivativeLU_) lu = std::make_unique<UnpivotedBandLU>(n, bw);
        derivativeK_ = std::make_unique<BandMatrix>(n, bw);
        derivativeC_ = std::make_unique<BandMatrix>(n, bw);
        derivativeM_ = std::make_unique<BandMatrix>(n, bw);
        derivativeWork_.assign(11 * static_cast<size_t>(n) + 3 * kDerivativeInputs * static_cast<size_t>(n), 0.0);
    }
    BandMatrix &K = *derivativeK_, &C = *derivativeC_, &M = *derivativeM_;
    K.clear();
    C.clear();
    M.clear();
    // The cable's Jacobian at its present state.
    expand_integrator_state(state_.time, y_.data(), yp_.data());
    auto add = [&](int i, int k, double dq, double dv, double da) {
        K.add(i, k, dq);
        C.add(i, k, dv);
        M.add(i, k, da);
    };
    model_.jacobian(X_.data(), Xd_.data(), Xdd_.data(), loads_, add);
    // The driven ends' columns in the free rows, and the output rows (the driven nodes' position
    // rows of the end elements' residuals), come from the two end elements (and the end node's terms).
    const int elements[2] = {0, N - 1};
    for (int k = 0; k < 2; ++k)
    {
        model_.element_jacobian(elements[k], X_.data(), Xd_.data(), Xdd_.data(), loads_, derivativeKe_[k],
                                derivativeCe_[k], derivativeMe_[k]);
        model_.element_visco_jacobian(elements[k], X_.data(), Xd_.data(), loads_, derivativeVisco_[k]);
    }
    model_.end_node_jacobian(X_.data(), Xd_.data(), Xdd_.data(), loads_, derivativeKn_, derivativeCn_, derivativeMn_);
    if (model_.far_end().proxy) {
        // The force on the body (proxy_output) moves with the proxy's position p1 and velocity v1 at
        // t + h as follow + tracking do: dF = [(M / h) phi + D - M alpha / (2 h)] dv1 + (M alpha / h^2) dp1
        // (D the estimate's drag derivative; phi's own change with D left out).
        const double h = state_.lastStepSize;
        const Mat3 Mb = model_.body().inertia();
        const double alpha = model_.params().proxyTrackingGain;
        Mat3 D;
        state_.proxy.force(proxy_flow(vec(state_.outputs.endPosition), vec(state_.outputs.endVelocity), state_.time), &D);
        derivativeProxyVelocity_ = Mb / h * bernoulli_phi(Mb.inverse() * D * h) + D - Mb * alpha / (2.0 * h);
        derivativeProxyPosition_ = Mb * alpha / (h * h);
    }
    // The Newton matrix of one BDF2 substep, K + c C + c^2 M, factored for both substep sizes.
    for (int level = 0; level < 2; ++level) {
        const double c = 1.5 * (kDerivativeSubsteps << level) / state_.lastStepSize;
        UnpivotedBandLU& A = *derivativeLU_[level];
        double* a = A.values();
        const double *k = K.values(), *cc = C.values(), *m = M.values();
        for (size_t i = 0; i < A.value_count(); ++i) a[i] = k[i] + c * (cc[i] + c * m[i]);
        if (!A.factor()) {
            error = "the cable's step matrix has a vanishing pivot at this state";
            return false;
        }
    }
    for (bool& done : derivativeColumnDone_) done = false;
    derivativeStamp_ = stateStamp_;
    return true;
}

void CableSimulation::derivative_response(const double seed[kDerivativeInputs], double out[6]) {
    const int n = model_.n_free(), N = model_.n_elements(), bw = model_.free_bandwidth();
    const double h = state_.lastStepSize;
    const bool externalEnd = model_.far_end().driven;
    const bool proxyEnd = model_.far_end().proxy;
    // bottomEnd 4: the body's reported state enters the force on it through the tracking force alone
    // (the estimate moves after the step), linearly: -M alpha / h^2 per metre, -M (alpha + beta) / h
    // per metre per second; its acceleration not at all. The towForce rows stay 0: the cable does not
    // see the body within the step.
    Vec3 tracking = Vec3::Zero();
    const int elements[2] = {0, N - 1};
    double* w = derivativeWork_.data();
    double *qm = w, *q0 = w + n, *vm = w + 2 * n, *v0 = w + 3 * n, *rhs = w + 4 * n, *bq = w + 5 * n,
           *bv = w + 6 * n, *tmp = w + 7 * n, *forcing = w + 11 * n;
    // The seeds in the direction: the prescribed DOF each moves, the change of its end's target
    // (position, velocity, acceleration at t + h) per unit input, as DrivenEnd::next makes it, and
    // its forcing columns fK, fC, fM in the free rows.
    struct Active {
        int gp;
        double weight;
        TowTrajectory motion;
        double *fK, *fC, *fM;
    };
    std::vector<Active> active;
    for (int s = 0; s < kDerivativeInputs; ++s) {
        if (seed[s] == 0.0) continue;
        const bool tow = s < 6 || (s >= 12 && s < 15);
        const int comp = s % 3;
        const int kind = s >= 12 ? 2 : (s % 6) / 3;  // 0 position, 1 velocity, 2 acceleration
        if (!tow && proxyEnd && kind < 2) {
            const UCParams& pp = model_.params();
            const double gain = kind == 0 ? pp.proxyTrackingGain / (h * h) : (pp.proxyTrackingGain + pp.proxyTrackingDamping) / h;
            tracking -= seed[s] * gain * model_.body().inertia().col(comp);
        }
        if (!tow && !externalEnd) continue;  // the end inputs act on the cable only at a driven far end
        const DrivenEndState& end = tow ? state_.tow : state_.end;
        const int gp = (tow ? 0 : model_.end_offset()) + comp;
        double dp1 = 1.0, dv1 = 0.0, da1 = 0.0;
        if (kind == 2) {  // an acceleration as the master gives it (held over the step)
            dp1 = 0.5 * h * h;
            dv1 = h;
            da1 = 1.0;
        } else if (kind == 1) {
            if (end.lastAccelerationGiven) {
                dp1 = h;
                dv1 = 1.0;
            } else {  // the acceleration is the difference of the last two velocity inputs over h
                dp1 = 1.5 * h;
                dv1 = 2.0;
                da1 = 1.0 / h;
            }
        }
        double* f = forcing + 3 * static_cast<size_t>(active.size()) * n;
        Active a{gp, seed[s],
                 TowTrajectory::quintic(0.0, h, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3(dp1, 0.0, 0.0),
                                        Vec3(dv1, 0.0, 0.0), Vec3(da1, 0.0, 0.0)),
                 f, f + n, f + 2 * n};
        for (int j = 0; j < 3 * n; ++j) f[j] = 0.0;
        for (int k = 0; k < 2; ++k) {
            if (k == 1 && elements[1] == elements[0]) break;
            const int g0 = model_.element_offset(elements[k]);
            const int b = gp - g0;
            if (b < 0 || b >= 12) continue;
            for (int r = 0; r < 12; ++r) {
                const int j = model_.free_index(g0 + r);
                if (j < 0) continue;
                const double cr = model_.coefficient(g0 + r);
                a.fK[j] += cr * derivativeKe_[k](r, b);
                a.fC[j] += cr * derivativeCe_[k](r, b);
                a.fM[j] += cr * derivativeMe_[k](r, b);
            }
            const int gi = model_.internal_offset(elements[k]);  // the internal strain's row
            if (gi >= 0) {
                a.fK[model_.free_index(gi)] += derivativeVisco_[k].dI_dX[b];
                a.fC[model_.free_index(gi)] += derivativeVisco_[k].dI_dXd[b];
            }
        }
        if (!tow) {
            for (int r = 0; r < 6; ++r) {
                const int j = model_.free_index(model_.end_offset() + r);
                if (j < 0) continue;
                a.fK[j] += derivativeKn_(r, comp);
                a.fC[j] += derivativeCn_(r, comp);
                a.fM[j] += derivativeMn_(r, comp);
            }
        }
        active.push_back(a);
    }
    for (int i = 0; i < 6; ++i) out[i] = 0.0;
    for (int r = 0; r < 3; ++r) out[3 + r] = tracking[r];
    if (active.empty()) return;
    const int width = 2 * bw + 1;
    const BandMatrix &C = *derivativeC_, &M = *derivativeM_;
    double coarse[6] = {};
    std::vector<Vec3> p(active.size()), v(active.size()), acc(active.size());
    for (int level = 0; level < 2; ++level) {
        const int substeps = kDerivativeSubsteps << level;
        const double dt = h / substeps;
        const double c = 1.5 / dt;  // BDF2: v_{k+1} = c q_{k+1} + (q_{k-1} - 4 q_k) / (2 dt)
        double* result = level == 0 ? coarse : out;
        const UnpivotedBandLU& A = *derivativeLU_[level];
        // BDF2 from rest: the change starts with zero position, velocity and acceleration.
        for (int j = 0; j < n; ++j) qm[j] = q0[j] = vm[j] = v0[j] = 0.0;
        for (int step = 0; step < substeps; ++step) {
            for (size_t s = 0; s < active.size(); ++s) active[s].motion.evaluate((step + 1) * dt, p[s], v[s], acc[s]);
            for (int j = 0; j < n; ++j) {
                bq[j] = (qm[j] - 4.0 * q0[j]) / (2.0 * dt);
                bv[j] = (vm[j] - 4.0 * v0[j]) / (2.0 * dt);
                tmp[j] = c * bq[j] + bv[j];
            }
            const double *cv = C.values(), *mv = M.values();
            for (int i = 0; i < n; ++i) {
                double r = 0.0;
                for (size_t s = 0; s < active.size(); ++s) {
                    const Active& a = active[s];
                    r -= a.weight * (a.fK[i] * p[s][0] + a.fC[i] * v[s][0] + a.fM[i] * acc[s][0]);
                }
                const int k0 = std::max(0, i - bw), k1 = std::min(n - 1, i + bw);
                const double* ci = cv + static_cast<size_t>(i) * width + bw - i;  // ci[k] = C(i, k)
                const double* mi = mv + static_cast<size_t>(i) * width + bw - i;
                for (int k = k0; k <= k1; ++k) r -= ci[k] * bq[k] + mi[k] * tmp[k];
                rhs[i] = r;
            }
            A.solve(rhs);
            for (int j = 0; j < n; ++j) {
                qm[j] = q0[j];
                vm[j] = v0[j];
                q0[j] = rhs[j];
                v0[j] = c * rhs[j] + bq[j];
            }
        }
        // Accelerations at t + h, from the last substep.
        for (int j = 0; j < n; ++j) tmp[j] = c * v0[j] + bv[j];
        // towForce = -(rows 0..2 of element 0), endForce = -(rows 6..8 of element N - 1).
        for (int k = 0; k < 2; ++k) {
            const int g0 = model_.element_offset(elements[k]);
            const Mat12 &Ke = derivativeKe_[k], &Ce = derivativeCe_[k], &Me = derivativeMe_[k];
            for (int r = 0; r < 3; ++r) {
                const int a = (k == 0 ? 0 : 6) + r;
                double dR = 0.0;
                for (int b = 0; b < 12; ++b) {
                    const int g = g0 + b;
                    const int j = model_.free_index(g);
                    if (j >= 0) {
                        const double cb = model_.coefficient(g);
                        dR += cb * (Ke(a, b) * q0[j] + Ce(a, b) * v0[j] + Me(a, b) * tmp[j]);
                        continue;
                    }
                    for (size_t s = 0; s < active.size(); ++s)
                        if (g == active[s].gp)
                            dR += active[s].weight * (Ke(a, b) * p[s][0] + Ce(a, b) * v[s][0] + Me(a, b) * acc[s][0]);
                }
                const int gi = model_.internal_offset(elements[k]);
                if (gi >= 0) {
                    const int j = model_.free_index(gi);
                    dR += derivativeVisco_[k].dR_de1[a] * q0[j] + derivativeVisco_[k].dR_dr1[a] * v0[j];
                }
                result[3 * k + r] = -dR;
            }
        }
        if (proxyEnd) {  // the force on the body, from the proxy's state at t + h
            Vec3 dp, dv;
            for (int r = 0; r < 3; ++r) {
                const int j = model_.free_index(model_.end_offset() + r);
                dp[r] = q0[j];
                dv[r] = v0[j];
            }
            const Vec3 dF = derivativeProxyVelocity_ * dv + derivativeProxyPosition_ * dp;
            for (int r = 0; r < 3; ++r) result[3 + r] = dF[r];
        }
    }
    // BDF2's error falls as the square of the substep: Richardson's extrapolation of the two.
    for (int i = 0; i < 6; ++i) out[i] = (4.0 * out[i] - coarse[i]) / 3.0;
    for (int r = 0; r < 3; ++r) out[3 + r] += tracking[r];
}

bool CableSimulation::interface_derivative(const double seed[kDerivativeInputs], double out[6], std::string& error) {
    for (int i = 0; i < 6; ++i) out[i] = 0.0;
    if (!prepare_derivatives(error)) return false;
    int count = 0, single = -1;
    bool cached = true;
    for (int s = 0; s < kDerivativeInputs; ++s) {
        if (seed[s] == 0.0) continue;
        ++count;
        single = s;
        cached = cached && derivativeColumnDone_[s];
    }
    if (count == 1 && !cached) {  // a column: computed for a unit seed and kept
        double unit[kDerivativeInputs] = {};
        unit[single] = 1.0;
        derivative_response(unit, derivativeColumns_[single]);
        derivativeColumnDone_[single] = true;
        cached = true;
    }
    if (!cached) {  // a direction across columns not all known: one integration for the direction
        derivative_response(seed, out);
        return true;
    }
    for (int s = 0; s < kDerivativeInputs; ++s)
        if (seed[s] != 0.0)
            for (int i = 0; i < 6; ++i) out[i] += derivativeColumns_[s][i] * seed[s];
    return true;
}

}  // namespace uc
