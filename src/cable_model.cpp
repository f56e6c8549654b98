// cable_model.cpp - DOF map, prescribed motion and assembly of the cable equations.
#include "cable_model.h"

#include <algorithm>
#include <cmath>

namespace uc {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kLoadQuadraturePoints = 3;

}  // namespace

AxialProps CableModel::scaled_axial(const Loads& loads) const {
    return AxialProps{axial_.EA, axial_.damping, loads.axialStiffnessScale,
                      axial_.tensionOnly && !loads.twoSidedAxial};
}

namespace {

// Membrane locking (docs/model.md): the axial strain of an element is projected onto
// Legendre modes (mean, linear, quadratic) in the element. The mean mode carries the full EA.
// At full EA the linear and quadratic modes compete with bending and lock (elastica tip error
// 1e-3 L at 10 elements); without any stiffness they leave the element's axial modes free
// (singular without bending) and cannot carry a tension gradient. At 1 % of EA they carry the
// distributed axial loads (the strain variation inside an element is then 100 times the
// physical one, a sub-millimetre effect on the shape of a tow cable; the mean strain and every
// force stay exact) and the elastica tip error at 10 elements is ~5e-5 L.
constexpr double kHigherStrainModeWeight = 0.01;

Vec3 unit(const double v[3]) {
    Vec3 d(v[0], v[1], v[2]);
    return d / d.norm();
}

}  // namespace

TowTrajectory TowTrajectory::at_rest_in_time(const Vec3& p, const Vec3& v, const Vec3& a, double t) {
    TowTrajectory traj;
    traj.t0 = t;
    traj.h = 0.0;
    traj.p0 = traj.p1 = p;
    traj.v0 = traj.v1 = v;
    traj.a0 = traj.a1 = a;
    return traj;
}

TowTrajectory TowTrajectory::quintic(double t0, double h, const Vec3& p0, const Vec3& v0, const Vec3& a0,
                                     const Vec3& p1, const Vec3& v1, const Vec3& a1) {
    TowTrajectory traj;
    traj.t0 = t0;
    traj.h = h;
    traj.p0 = p0;
    traj.v0 = v0;
    traj.a0 = a0;
    traj.p1 = p1;
    traj.v1 = v1;
    traj.a1 = a1;
    // Quintic Hermite: what the end state misses against the parabola from (p0, v0, a0) is made
    // up by the s^3..s^5 terms, which vanish at s = 0 with their first two derivatives.
    const Vec3 dp = p1 - (p0 + v0 * h + 0.5 * a0 * h * h);
    const Vec3 dv = (v1 - (v0 + a0 * h)) * h;
    const Vec3 da = (a1 - a0) * (h * h);
    const double h3 = h * h * h;
    traj.c3_ = (10.0 * dp - 4.0 * dv + 0.5 * da) / h3;
    traj.c4_ = (-15.0 * dp + 7.0 * dv - da) / (h3 * h);
    traj.c5_ = (6.0 * dp - 3.0 * dv + 0.5 * da) / (h3 * h * h);
    return traj;
}

TowTrajectory TowTrajectory::steady(double lambda) const {
    return at_rest_in_time(p0, lambda * v0, Vec3::Zero(), t0);
}

void TowTrajectory::evaluate(double t, Vec3& p, Vec3& v, Vec3& a) const {
    const double s = t - t0;  // Horner form; with h = 0 the cubic and higher terms are zero
    p = p0 + s * (v0 + s * (0.5 * a0 + s * (c3_ + s * (c4_ + s * c5_))));
    v = v0 + s * (a0 + s * (3.0 * c3_ + s * (4.0 * c4_ + s * (5.0 * c5_))));
    a = a0 + s * (6.0 * c3_ + s * (12.0 * c4_ + s * (20.0 * c5_)));
}

CableModel::CableModel(const UCParams& params)
    : params_(params), nElements_(params.nElements) {
    EI_ = params.enableBending ? params.EI : 0.0;
    tables_ = make_element_tables(params.length / nElements_, kLoadQuadraturePoints, 3);
    tables_.axialModeWeight[1] = tables_.axialModeWeight[2] = kHigherStrainModeWeight;
    fluid_.rho = params.waterDensity;
    fluid_.gravity = params.gravity;
    fluid_.massPerLength = params.massPerLength;
    fluid_.diameter = params.diameter;
    fluid_.area = kPi * params.diameter * params.diameter / 4.0;
    fluid_.Cdn = params.Cdn;
    fluid_.Cdt = params.Cdt;
    fluid_.Can = params.Can;
    fluid_.Cat = params.Cat;
    fluid_.addedMass = params.enableAddedMass != 0;
    axial_.EA = params.EA;
    axial_.damping = params.axialDamping;
    axial_.tensionOnly = params.enableCompression == 0;
    // The material's Kelvin-Voigt time constant axialDamping / EA damps bending as well: it
    // removes the element-scale bending waves (periods of milliseconds, which quadratic drag cannot
    // damp at small amplitude) that a torque keeps exciting, and is negligible for the slow modes.
    bendingDamping_ = EI_ * params.axialDamping / params.EA;
    topTangent_ = params.topEnd == UC_TOP_CLAMPED ? unit(params.topTangent) : Vec3(0, 0, -1);
    anchor_ = Vec3(params.anchor[0], params.anchor[1], params.anchor[2]);
    std::string waveError;  // the parameters' check has refused waves that cannot be built
    sea_.build(params, waveError);
    seabed_.enabled = params.enableSeabed != 0;
    seabed_.depth = params.waterDepth;
    seabed_.stiffness = params.seabedStiffness;
    seabed_.damping = params.seabedDamping;
    seabed_.friction = params.seabedFriction;
    seabed_.smoothing = 0.05 * params.diameter;
    profile_.rows = params.currentProfileRows;
    for (int k = 0; k < kCurrentProfileRows; ++k) {
        profile_.depth[k] = params.currentProfileDepth[k];
        profile_.ux[k] = params.currentProfileX[k];
        profile_.uy[k] = params.currentProfileY[k];
    }

    // DOF map, in global order so that the free Jacobian stays banded.
    free_.assign(n_global(), -1);
    coef_.assign(n_global(), 1.0);
    int next = 0;
    for (int i = 0; i <= nElements_; ++i) {
        for (int k = 0; k < 6; ++k) {
            const int g = 6 * i + k;
            const bool position = k < 3;
            if (i == 0 && position) continue;  // tow point: prescribed
            if (i == nElements_ && position &&
                (params.bottomEnd == UC_BOTTOM_ANCHORED || params.bottomEnd == UC_BOTTOM_EXTERNAL))
                continue;  // far end: prescribed
            if (i == 0 && params.topEnd == UC_TOP_CLAMPED) {
                // r'_0 = a * topTangent: one free stretch shared by the three components.
                if (k == 3) ++next;
                free_[g] = next - 1;
                coef_[g] = topTangent_[k - 3];
                continue;
            }
            free_[g] = next++;
        }
    }
    nFree_ = next;
    bandwidth_ = 0;
    for (int e = 0; e < nElements_; ++e) {
        int lo = nFree_, hi = -1;
        for (int a = 0; a < 12; ++a) {
            const int j = free_[6 * e + a];
            if (j < 0) continue;
            lo = std::min(lo, j);
            hi = std::max(hi, j);
        }
        if (hi >= lo) bandwidth_ = std::max(bandwidth_, hi - lo);
    }
}

void CableModel::expand(const double* q, const double* v, const double* a, const Loads& loads, double t,
                        double* X, double* Xd, double* Xdd) const {
    const int n = n_global();
    for (int g = 0; g < n; ++g) {
        const int j = free_[g];
        if (j < 0) continue;
        X[g] = coef_[g] * q[j];
        Xd[g] = coef_[g] * v[j];
        Xdd[g] = coef_[g] * a[j];
    }
    Vec3 p, pv, pa;
    loads.tow.evaluate(t, p, pv, pa);
    for (int k = 0; k < 3; ++k) {
        X[k] = p[k];
        Xd[k] = pv[k];
        Xdd[k] = pa[k];
    }
    const int gN = 6 * nElements_;
    if (params_.bottomEnd == UC_BOTTOM_ANCHORED) {
        for (int k = 0; k < 3; ++k) {
            X[gN + k] = anchor_[k];
            Xd[gN + k] = 0.0;
            Xdd[gN + k] = 0.0;
        }
    } else if (params_.bottomEnd == UC_BOTTOM_EXTERNAL) {
        loads.end.evaluate(t, p, pv, pa);
        for (int k = 0; k < 3; ++k) {
            X[gN + k] = p[k];
            Xd[gN + k] = pv[k];
            Xdd[gN + k] = pa[k];
        }
    }
}

void CableModel::restrict_to_free(const double* X, double* q) const {
    const bool clamped = params_.topEnd == UC_TOP_CLAMPED;
    const int n = n_global();
    for (int g = 0; g < n; ++g) {
        const int j = free_[g];
        if (j < 0) continue;
        if (clamped && g >= 3 && g < 6) {
            // The three components share one unknown a: r'_0 = a * topTangent.
            if (g == 3) q[j] = Eigen::Map<const Vec3>(X + 3).dot(topTangent_);
            continue;
        }
        q[j] = X[g];
    }
}

void CableModel::element_residual(int e, const double* X, const double* Xd, const double* Xdd,
                                  const Loads& loads, double* R) const {
    const int g0 = 6 * e;
    for (int a = 0; a < 12; ++a) R[a] = 0.0;
    add_mass_force(tables_, params_.massPerLength, Xdd + g0, R);
    add_axial_force(tables_, scaled_axial(loads), X + g0, Xd + g0, R);
    if (EI_ > 0.0) add_bending_force(tables_, EI_, X + g0, R);
    if (bendingDamping_ > 0.0) add_bending_force(tables_, bendingDamping_, Xd + g0, R);
    if (loads.torque != 0.0) add_torque_force(tables_, loads.torque, X + g0, R);
    add_hydro_force(tables_, fluid_, loads.current, X + g0, Xd + g0, Xdd + g0, R);
    if (seabed_.enabled) add_seabed_force(tables_, seabed_, X + g0, Xd + g0, R);
}

void CableModel::element_jacobian(int e, const double* X, const double* Xd, const double* Xdd,
                                  const Loads& loads, Mat12& K, Mat12& C, Mat12& M) const {
    const int g0 = 6 * e;
    K.setZero();
    C.setZero();
    M.setZero();
    add_mass_jacobian(tables_, params_.massPerLength, M);
    add_axial_jacobian(tables_, scaled_axial(loads), X + g0, Xd + g0, K, C);
    if (EI_ > 0.0) add_bending_jacobian(tables_, EI_, K);
    if (bendingDamping_ > 0.0) add_bending_jacobian(tables_, bendingDamping_, C);
    if (loads.torque != 0.0) add_torque_jacobian(tables_, loads.torque, X + g0, K);
    add_hydro_jacobian(tables_, fluid_, loads.current, X + g0, Xd + g0, Xdd + g0, K, C, M);
    if (seabed_.enabled) add_seabed_jacobian(tables_, seabed_, X + g0, Xd + g0, K, C);
}

bool CableModel::far_end_prescribed() const {
    return params_.bottomEnd == UC_BOTTOM_ANCHORED || params_.bottomEnd == UC_BOTTOM_EXTERNAL;
}

namespace {

Mat3 cross_matrix(const Vec3& v) {
    Mat3 m;
    m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return m;
}

}  // namespace

Vec6 CableModel::end_node_residual(const double* X, const double* Xd, const double* Xdd,
                                   const Loads& loads) const {
    const int gN = 6 * nElements_;
    Vec6 R = Vec6::Zero();
    const Vec3 rd = Eigen::Map<const Vec3>(Xd + gN);
    R.head<3>() = -loads.endLoad + loads.endLoadDamping * (rd - loads.endLoadVelocity);
    // End couple M: virtual work M . (t x dr')/|r'| = (M x r')/|r'|^2 . dr' on the end tangent.
    const Vec3 rp = Eigen::Map<const Vec3>(X + gN + 3);
    R.tail<3>() = -loads.endCouple.cross(rp) / rp.squaredNorm();
    if (params_.bottomEnd != UC_BOTTOM_TOWED_BODY) return R;
    const Vec3 rdd = Eigen::Map<const Vec3>(Xdd + gN);
    Vec3 U, A;
    Mat3 dU, dA;
    loads.current.flow(Eigen::Map<const Vec3>(X + gN), U, dU, A, dA);  // the body's drag in the current and waves
    const Vec3 u = U - rd;
    const double speed = std::sqrt(u.squaredNorm() + kDragVelocityFloor * kDragVelocityFloor);
    const double wet = (params_.bodyMass - fluid_.rho * params_.bodyVolume) * fluid_.gravity;
    R.head<3>() += (params_.bodyMass + params_.bodyAddedMass) * rdd;
    R.head<3>() -= 0.5 * fluid_.rho * params_.bodyCdA * speed * u;
    R.z() += wet;
    return R;
}

void CableModel::end_node_jacobian(const double* X, const double* Xd, const double* /*Xdd*/,
                                   const Loads& loads, Mat6& K, Mat6& C, Mat6& M) const {
    const int gN = 6 * nElements_;
    K.setZero();
    C.setZero();
    M.setZero();
    if (!loads.endCouple.isZero(0.0)) {
        const Vec3 rp = Eigen::Map<const Vec3>(X + gN + 3);
        const double n2 = rp.squaredNorm();
        K.block<3, 3>(3, 3) = -cross_matrix(loads.endCouple) * (Mat3::Identity() / n2 - 2.0 * rp * rp.transpose() / (n2 * n2));
    }
    C.block<3, 3>(0, 0) = loads.endLoadDamping;
    if (params_.bottomEnd != UC_BOTTOM_TOWED_BODY) return;
    Vec3 U, A;
    Mat3 dU, dA;
    loads.current.flow(Eigen::Map<const Vec3>(X + gN), U, dU, A, dA);
    const Vec3 u = U - Eigen::Map<const Vec3>(Xd + gN);
    const double speed = std::sqrt(u.squaredNorm() + kDragVelocityFloor * kDragVelocityFloor);
    const Mat3 dDrag_du = 0.5 * fluid_.rho * params_.bodyCdA * (speed * Mat3::Identity() + u * u.transpose() / speed);
    if (loads.current.waves()) {
        K.block<3, 3>(0, 0) -= dDrag_du * dU;  // drag of the body in the waves' and current's gradients
    } else {
        K.block<3, 3>(0, 0).col(2) -= dDrag_du * dU.col(2);  // drag of the body in a sheared current
    }
    C.block<3, 3>(0, 0) += 0.5 * fluid_.rho * params_.bodyCdA * (speed * Mat3::Identity() + u * u.transpose() / speed);
    M.block<3, 3>(0, 0) = (params_.bodyMass + params_.bodyAddedMass) * Mat3::Identity();
}

void CableModel::residual(const double* X, const double* Xd, const double* Xdd, const Loads& loads,
                          double* Rfree, ElementForces* forces) const {
    for (int j = 0; j < nFree_; ++j) Rfree[j] = 0.0;
    if (forces) forces->element.resize(nElements_);
    double Re[12];
    for (int e = 0; e < nElements_; ++e) {
        element_residual(e, X, Xd, Xdd, loads, Re);
        const int g0 = 6 * e;
        for (int a = 0; a < 12; ++a) {
            const int j = free_[g0 + a];
            if (j >= 0) Rfree[j] += coef_[g0 + a] * Re[a];
        }
        if (forces) forces->element[e] = Eigen::Map<const Vec12>(Re);
    }
    const Vec6 end = end_node_residual(X, Xd, Xdd, loads);
    const int gN = 6 * nElements_;
    for (int k = 0; k < 6; ++k) {
        const int j = free_[gN + k];
        if (j >= 0) Rfree[j] += end[k];
    }
    if (forces) forces->endNodeTerms = end;
}

void CableModel::straight_line(const Vec3& p, const Vec3& direction, double* X) const {
    const Vec3 d = direction.normalized();
    for (int i = 0; i <= nElements_; ++i) {
        Eigen::Map<Vec3>(X + 6 * i) = p + d * (tables_.length * i);
        Eigen::Map<Vec3>(X + 6 * i + 3) = d;
    }
    if (params_.topEnd == UC_TOP_CLAMPED) Eigen::Map<Vec3>(X + 3) = topTangent_;
}

}  // namespace uc
