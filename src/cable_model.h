// cable_model.h - the immutable cable model (element tables, DOF map, properties) and the
// assembly of the residual and banded Jacobian over the free DOFs (docs/model.md).
//
// Global nodal coordinates X: node i holds [r_i, r'_i] at X[6i .. 6i+5], i = 0..N (node 0 = tow
// point). Free DOFs q are what the integrator and the static solver see; every global DOF is
// either free, X[g] = coef[g] * q[free[g]] (coef is 1 except for a clamped top tangent, where
// r'_0 = a * topTangent with one free stretch a), or prescribed (tow point, anchor).
// The equations of prescribed DOFs are not solved: their residuals are the reaction forces.
#pragma once

#include <vector>

#include "cable_api.h"
#include "hermite_element.h"
#include "hydrodynamics.h"
#include "seabed.h"

namespace uc {

// Motion of a driven end (the tow point, or the far end of bottomEnd 3) over one communication
// step [t0, t0 + h]: a quintic in time from the end's state (p0, v0, a0) at t0 to a target state
// (p1, v1, a1) at t0 + h. Each step starts from the state where the previous one ended, so the
// end never jumps in position, velocity or acceleration (C2 across communication points): the
// equations the integrator solves stay continuous there and it keeps its step size and order.
// With h = 0 it is a point in time: p0 + v0 (t - t0) + a0 (t - t0)^2 / 2 for every t.
struct TowTrajectory {
    double t0 = 0.0, h = 0.0;
    Vec3 p0 = Vec3::Zero(), v0 = Vec3::Zero(), a0 = Vec3::Zero();  // state at t0
    Vec3 p1 = Vec3::Zero(), v1 = Vec3::Zero(), a1 = Vec3::Zero();  // state at t0 + h

    static TowTrajectory at_rest_in_time(const Vec3& p, const Vec3& v, const Vec3& a, double t);
    static TowTrajectory quintic(double t0, double h, const Vec3& p0, const Vec3& v0, const Vec3& a0,
                                 const Vec3& p1, const Vec3& v1, const Vec3& a1);
    // The same point in time (t0) with the velocity scaled by lambda and no acceleration (the
    // static solver's load continuation).
    TowTrajectory steady(double lambda) const;
    void evaluate(double t, Vec3& p, Vec3& v, Vec3& a) const;

private:
    // p(t0 + s) = p0 + v0 s + a0 s^2/2 + c3 s^3 + c4 s^4 + c5 s^5
    Vec3 c3_ = Vec3::Zero(), c4_ = Vec3::Zero(), c5_ = Vec3::Zero();
};

// Everything the residual needs besides the state: prescribed motion and environment.
struct Loads {
    TowTrajectory tow;
    TowTrajectory end;  // far end when bottomEnd = 3 (external body)
    CurrentField current;
    Vec3 endLoad = Vec3::Zero();
    // Velocity linearization of endLoad (a partner model's force, evaluated by the partner at the far-end
    // velocity endLoadVelocity): the force applied is endLoad - endLoadDamping (v_end - endLoadVelocity),
    // so its velocity dependence is integrated implicitly with the cable (docs/cosimulation.md).
    Vec3 endLoadVelocity = Vec3::Zero();
    Mat3 endLoadDamping = Mat3::Zero();
    Vec3 endCouple = Vec3::Zero();
    double torque = 0.0;  // H [N.m] (0 unless torsion is enabled)
    // Caps the axial stiffness factor of every strain mode (static solver only: equilibrium is
    // first found on a soft cable, whose large rotations do not turn into huge axial residuals,
    // then stiffened to the real EA).
    double axialStiffnessScale = 1.0;
    // Static solver only: use the two-sided axial law even when the cable is tension-only (the
    // continuation starts from a guess that may be slack, where a tension-only cable without
    // bending stiffness has no stiffness at all).
    bool twoSidedAxial = false;
};

// Residual contributions of one element and of the far-end node terms, kept for outputs.
struct ElementForces {
    std::vector<Vec12> element;  // per element, residual over its 12 DOFs
    Vec6 endNodeTerms = Vec6::Zero();  // body, end load and end couple residual at node N
};

class CableModel {
public:
    explicit CableModel(const UCParams& params);

    const UCParams& params() const { return params_; }
    int n_elements() const { return nElements_; }
    int n_nodes() const { return nElements_ + 1; }
    int n_global() const { return 6 * (nElements_ + 1); }
    int n_free() const { return nFree_; }
    int free_bandwidth() const { return bandwidth_; }  // max |i - j| of coupled free DOFs
    double element_length() const { return tables_.length; }
    const ElementTables& tables() const { return tables_; }
    const FluidProps& fluid() const { return fluid_; }
    double EI() const { return EI_; }
    const AxialProps& axial() const { return axial_; }
    const SeabedProps& seabed() const { return seabed_; }
    const CurrentProfile& current_profile() const { return profile_; }
    const SeaState& sea() const { return sea_; }
    bool far_end_prescribed() const;  // anchored or external

    int free_index(int g) const { return free_[g]; }
    double coefficient(int g) const { return coef_[g]; }

    // Global X, Xdot, Xddot from free q, v, a and the prescribed motion at time t.
    void expand(const double* q, const double* v, const double* a, const Loads& loads, double t,
                double* X, double* Xd, double* Xdd) const;
    // Free q, v from a global configuration (prescribed entries are ignored).
    void restrict_to_free(const double* X, double* q) const;

    // Residual of one element (12 values): mass, axial, bending, hydrodynamics.
    void element_residual(int e, const double* X, const double* Xd, const double* Xdd,
                          const Loads& loads, double* R) const;
    // Far-end node terms at node N ([r_N, r'_N] rows): towed body inertia, drag and weight minus
    // the end load; minus the generalized force of the end couple on r'_N.
    Vec6 end_node_residual(const double* X, const double* Xd, const double* Xdd, const Loads& loads) const;

    // Free residual R_free[j] = sum_g coef[g] R[g]; fills forces (may be null) for outputs.
    void residual(const double* X, const double* Xd, const double* Xdd, const Loads& loads,
                  double* Rfree, ElementForces* forces) const;

    // Jacobian blocks of the free residual with respect to q, v and a, delivered through
    // add(row, col, dq, dv, da) with free indices row, col.
    template <class Sink>
    void jacobian(const double* X, const double* Xd, const double* Xdd, const Loads& loads,
                  Sink&& add) const;

    // Element Jacobians (dR/dX, dR/dXdot, dR/dXddot) for tests and assembly.
    void element_jacobian(int e, const double* X, const double* Xd, const double* Xdd,
                          const Loads& loads, Mat12& K, Mat12& C, Mat12& M) const;
    void end_node_jacobian(const double* X, const double* Xd, const double* Xdd, const Loads& loads,
                           Mat6& K, Mat6& C, Mat6& M) const;

    // Straight line from p along `direction` (unstretched), as global X.
    void straight_line(const Vec3& p, const Vec3& direction, double* X) const;

private:
    AxialProps scaled_axial(const Loads& loads) const;

    UCParams params_;
    int nElements_;
    ElementTables tables_;
    FluidProps fluid_;
    AxialProps axial_;
    double EI_;
    double bendingDamping_ = 0.0;  // EI * axialDamping / EA [N.m2.s]
    Vec3 topTangent_;
    Vec3 anchor_;
    SeabedProps seabed_;
    CurrentProfile profile_;
    SeaState sea_;
    std::vector<int> free_;
    std::vector<double> coef_;
    int nFree_ = 0;
    int bandwidth_ = 0;
};

template <class Sink>
void CableModel::jacobian(const double* X, const double* Xd, const double* Xdd, const Loads& loads,
                          Sink&& add) const {
    Mat12 K, C, M;
    for (int e = 0; e < nElements_; ++e) {
        element_jacobian(e, X, Xd, Xdd, loads, K, C, M);
        const int g0 = 6 * e;
        for (int a = 0; a < 12; ++a) {
            const int ja = free_[g0 + a];
            if (ja < 0) continue;
            const double ca = coef_[g0 + a];
            for (int b = 0; b < 12; ++b) {
                const int jb = free_[g0 + b];
                if (jb < 0) continue;
                const double cab = ca * coef_[g0 + b];
                add(ja, jb, cab * K(a, b), cab * C(a, b), cab * M(a, b));
            }
        }
    }
    Mat6 Kn, Cn, Mn;
    end_node_jacobian(X, Xd, Xdd, loads, Kn, Cn, Mn);
    const int gN = 6 * nElements_;
    for (int a = 0; a < 6; ++a) {
        const int ja = free_[gN + a];
        if (ja < 0) continue;
        for (int b = 0; b < 6; ++b) {
            const int jb = free_[gN + b];
            if (jb < 0) continue;
            if (Kn(a, b) != 0.0 || Cn(a, b) != 0.0 || Mn(a, b) != 0.0) add(ja, jb, Kn(a, b), Cn(a, b), Mn(a, b));
        }
    }
}

}  // namespace uc
