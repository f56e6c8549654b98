// proxy_end.cpp - bottomEnd 4: the proxy of an external body at the far end: its statics, the force
// on the body and the estimate of the body's other forces.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>

#include "line/simulation.h"
#include "line/simulation_internal.h"
#include "line/statics.h"

namespace uc {

namespace {

// bottomEnd 4: the estimate's low-pass spans at least this many communication steps. Under Jacobi the
// body feels the proxy's force a step late; a faster estimate then feeds that lag back into the proxy
// (the model problem in docs/cosimulation.md: 5 steps keep the gains stable with +-50 % inertia error
// and no drag at all, 3 do not).
constexpr double kProxyFilterSteps = 5.0;

}  // namespace

// The spring is ten times as stiff as the stiffest element's axial spring: the equilibrium found with
// it is well conditioned, and the end stands off the body's position by a tenth of what the cable
// would stretch under the same force. The anchor is then moved by that offset and the statics solved
// again from there (each pass takes the offset down by that factor, to round-off in a few passes).
bool CableSimulation::proxy_statics(double t0, const std::vector<double>& v, bool fromProfile, std::string& error) {
    constexpr int kPasses = 8;
    double shortest = model_.element_length(0);
    for (const ElementRun& run : model_.runs()) shortest = std::min(shortest, run.elementLength);
    const Vec3 target = state_.end.p();
    loads_.endSpring = 10.0 * model_.line().EA / shortest;
    loads_.endSpringAnchor = target;
    const int gN = model_.end_offset();
    const double tolerance = 1e-9 * std::max(model_.line().length, target.norm());
    for (int pass = 0; pass < kPasses; ++pass) {
        const StaticsResult statics =
            solve_static_equilibrium(model_, *staticSolver_, loads_, t0, v, q_, fromProfile || pass > 0, staticWork_);
        if (!statics.converged) {
            loads_.endSpring = 0.0;
            error = statics.message;
            return false;
        }
        std::vector<double> zero(model_.n_free(), 0.0);
        model_.expand(q_.data(), v.data(), zero.data(), loads_, t0, X_.data(), Xd_.data(), Xdd_.data());
        const Vec3 offset = Eigen::Map<const Vec3>(X_.data() + gN) - target;
        if (offset.norm() <= tolerance) break;
        loads_.endSpringAnchor -= offset;
    }
    // The spring's force becomes the proxy's estimated force: the residual, and so the equilibrium,
    // stay as solved (to round-off).
    const Vec3 spring = -loads_.endSpring * (Eigen::Map<const Vec3>(X_.data() + gN) - loads_.endSpringAnchor);
    state_.proxy.add(spring, proxy_flow(Eigen::Map<const Vec3>(X_.data() + gN), Eigen::Map<const Vec3>(Xd_.data() + gN), t0));
    loads_.endSpring = 0.0;
    return true;
}

// The flow relative to the proxy at its position r and velocity v at time t.
Vec3 CableSimulation::proxy_flow(const Vec3& r, const Vec3& v, double t) const {
    CurrentField current = loads_.current;
    current.time = t;
    Vec3 U, A;
    current.flow(r, U, A);
    return U - v;
}

// phi(A) = A (e^A - I)^-1 = g(A)^-1 with g(A) = (e^A - I) / A = I + A/2 + A^2/6 + ..., which is
// entire and invertible where A's eigenvalues are real (a drag's derivative has no vertical part:
// A is singular, and phi is I there). g by its Taylor series on A / 2^s, then doubled s times:
// g(2B) = g(B) (e^B + I) / 2, e^(2B) = (e^B)^2.
Mat3 bernoulli_phi(const Mat3& A) {
    const double norm = A.lpNorm<Eigen::Infinity>();
    int squarings = 0;
    while (norm / std::ldexp(1.0, squarings) > 0.25) ++squarings;
    const Mat3 B = A / std::ldexp(1.0, squarings);
    Mat3 E = Mat3::Identity(), g = Mat3::Identity(), power = Mat3::Identity();
    double factorial = 1.0;
    for (int k = 1; k <= 14; ++k) {  // |B| <= 1/4: the remainders are below 1e-17
        power = power * B;
        factorial *= k;
        E += power / factorial;
        g += power / (factorial * (k + 1));
    }
    for (int k = 0; k < squarings; ++k) {
        g = 0.5 * g * (E + Mat3::Identity());
        E = E * E;
    }
    return g.inverse();
}

// The force that makes the body follow the proxy. The body integrates M v' = F + (its other forces)
// with F held over the step; with its other forces as the estimate says (linearized at the proxy's
// new velocity v1: the estimate's value there less D (v - v1), D its drag derivative), the held force
// that takes a body starting at the proxy's old velocity v0 to v1 is
//   F = -(M / h) phi(M^-1 D h) (v0 - v1) - estimate(v1) - proxy weight,
// phi(A) = A (e^A - I)^-1 (= M (v1 - v0) / h less the mean of the other forces when D = 0): exact for
// a body whose drag time M / D is shorter than the step, which a force from the mean acceleration is
// not. The tracking force corrects what remains, at a fraction of the one-step gains:
// T = M [alpha (e + h e' + d) / h^2 + beta e' / h], e and e' the proxy's position and velocity less
// the body's at the step's start, d the proxy's departure from a trapezoidal path over the step.
// What the body needs beyond that in the long run is the estimate's error: the estimate integrates
// the tracking force (a low-pass of time constant proxy.filterTime, at least kProxyFilterSteps
// steps). docs/cosimulation.md derives the gains' stability. h = 0: at initialization (the cable
// force alone).
void CableSimulation::proxy_output(double h, const Vec3& p0, const Vec3& v0, const EndMotion& external) {
    const UCParams& p = model_.params();
    const PointBody& body = model_.body();
    const Vec3 weight(0.0, 0.0, -(body.mass - model_.fluid().rho * body.volume) * model_.fluid().gravity);
    const Vec3 flow = proxy_flow(vec(state_.outputs.endPosition), vec(state_.outputs.endVelocity), state_.time);
    Mat3 D;
    const Vec3 estimate = state_.proxy.force(flow, &D);
    if (h > 0.0) {
        const Mat3 M = body.inertia();
        const Vec3 p1 = vec(state_.outputs.endPosition), v1 = vec(state_.outputs.endVelocity);
        const Vec3 follow = -(M / h) * bernoulli_phi(M.inverse() * D * h) * (v0 - v1) - estimate - weight;
        const Vec3 e = p0 - external.position, ev = v0 - external.velocity;
        const Vec3 departure = p1 - p0 - 0.5 * h * (v0 + v1);
        const Vec3 tracking = M * (p.proxyTrackingGain * (e + h * ev + departure) / (h * h) + p.proxyTrackingDamping * ev / h);
        const Vec3 force = follow + tracking;
        for (int k = 0; k < 3; ++k) state_.outputs.endForce[k] = force[k];
        const double tau = std::max(p.proxyFilterTime, kProxyFilterSteps * h);
        state_.proxy.add(-h / (tau + h) * tracking, flow);
    }
    const Vec3 total = state_.proxy.force(flow) + weight;
    for (int k = 0; k < 3; ++k) state_.outputs.bodyForceEstimate[k] = total[k];
}

}  // namespace uc
