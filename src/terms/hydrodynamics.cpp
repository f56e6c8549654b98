// hydrodynamics.cpp - weight/buoyancy, Morison drag and added mass at quadrature points.
#include "terms/hydrodynamics.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace uc {
namespace {


// d(phi)/dz of the submerged fraction.
double submerged_fraction_slope(double z, double diameter) {
    return (z > 0.0 && z < diameter) ? -1.0 / diameter : 0.0;
}

// The element's height z(xi) = c[0] + c[1] xi + c[2] xi^2 + c[3] xi^3 on xi in [0, 1] (Hermite, the
// tangents scaled by the length).
struct Height {
    double c[4];
    double at(double xi) const { return c[0] + xi * (c[1] + xi * (c[2] + xi * c[3])); }
};

Height element_height(double l, const double* X) {
    const double zi = X[2], ti = l * X[5], zj = X[8], tj = l * X[11];
    return {{zi, ti, -3.0 * zi - 2.0 * ti + 3.0 * zj - tj, 2.0 * zi + ti - 2.0 * zj + tj}};
}

// Cuts of [0, 1] at every crossing of z = 0 and z = d, sorted, 0 and 1 included; returns their
// number. On each piece between two cuts phi(z(xi)) is 1, 0 or 1 - z/d: a polynomial.
constexpr int kMaxWaterlineCuts = 2 + 6;  // a cubic crosses each level at most three times
int waterline_cuts(const Height& z, double d, double* cuts) {
    // Monotone pieces of z between its extrema inside (0, 1): roots of c1 + 2 c2 xi + 3 c3 xi^2.
    const double qa = 3.0 * z.c[3], qb = 2.0 * z.c[2], qc = z.c[1];
    double ends[4] = {0.0};
    int ne = 1;
    double extrema[2];
    int nx = 0;
    if (std::abs(qa) > 1e-14 * (std::abs(qb) + std::abs(qc))) {
        const double disc = qb * qb - 4.0 * qa * qc;
        if (disc > 0.0) {
            const double root = std::sqrt(disc);
            extrema[nx++] = (-qb - root) / (2.0 * qa);
            extrema[nx++] = (-qb + root) / (2.0 * qa);
        }
    } else if (qb != 0.0) {
        extrema[nx++] = -qc / qb;
    }
    std::sort(extrema, extrema + nx);
    for (int k = 0; k < nx; ++k)
        if (extrema[k] > 0.0 && extrema[k] < 1.0) ends[ne++] = extrema[k];
    ends[ne++] = 1.0;
    int n = 0;
    cuts[n++] = 0.0;
    for (int k = 0; k + 1 < ne; ++k) {
        for (double level : {0.0, d}) {
            double a = ends[k], b = ends[k + 1];
            const double fa = z.at(a) - level, fb = z.at(b) - level;
            if (!((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0))) continue;
            // Bisection to round-off: phi is continuous at the cut, so a cut off by dxi moves the
            // integral by O(dxi^2).
            while (b - a > 4e-16) {
                const double m = 0.5 * (a + b);
                if (m <= a || m >= b) break;
                ((z.at(m) - level < 0.0) == (fa < 0.0) ? a : b) = m;
            }
            cuts[n++] = 0.5 * (a + b);
        }
    }
    cuts[n++] = 1.0;
    for (int i = 1; i < n; ++i)  // insertion sort: at most eight values
        for (int j = i; j > 0 && cuts[j] < cuts[j - 1]; --j) std::swap(cuts[j], cuts[j - 1]);
    return n;
}

// Whether the element's centreline may reach the band 0 < z < d where phi ramps: its Bezier control
// heights bound the cubic. Most elements are entirely below or above it and return false here.
bool reaches_waterline(double l, double d, const double* X) {
    const double zi = X[2], zj = X[8], b1 = zi + l * X[5] / 3.0, b2 = zj - l * X[11] / 3.0;
    return std::max({zi, zj, b1, b2}) > 0.0 && std::min({zi, zj, b1, b2}) < d;
}

// The buoyancy of an element that reaches the waterline band, integrated exactly:
// R_a,z -= rho A g int N_a phi(z) ds and, with K non-null, K_az,bz -= rho A g int N_a phi'(z) N_b ds.
// phi is continuous, so the integral is continuously differentiable in the nodes and its derivative
// has no term from the moving cuts (the boundary terms of the two pieces at a cut cancel). On each
// piece the integrands are polynomials of degree at most 6, which 4 Gauss points integrate exactly:
// the sum is the integral whatever the cuts, and an element reaching the band, leaving it or touching
// it tangentially changes the load continuously.
void add_waterline_buoyancy(const ElementTables& e, const FluidProps& p, const double* X, double* R, Mat12* K) {
    const double l = e.length, d = p.diameter, rhoAg = p.rho * p.area * p.gravity;
    const Height z = element_height(l, X);
    double cuts[kMaxWaterlineCuts];
    const int n = waterline_cuts(z, d, cuts);
    const GaussRule rule = gauss_rule(4);
    for (int k = 0; k + 1 < n; ++k) {
        const double a = cuts[k], width = cuts[k + 1] - cuts[k];
        if (!(width > 0.0)) continue;
        const double zMid = z.at(a + 0.5 * width);
        if (zMid >= d) continue;  // dry
        const bool ramp = zMid > 0.0;
        for (int g = 0; g < rule.n; ++g) {
            const ShapeValues s = hermite_shape(a + width * rule.xi[g], l);
            const double w = rule.w[g] * width * l;
            if (R) {
                const double zg = s.N[0] * X[2] + s.N[1] * X[5] + s.N[2] * X[8] + s.N[3] * X[11];
                const double phi = ramp ? 1.0 - zg / d : 1.0;
                for (int i = 0; i < 4; ++i) R[3 * i + 2] -= rhoAg * w * phi * s.N[i];
            }
            if (K && ramp) {
                for (int i = 0; i < 4; ++i)
                    for (int j = 0; j < 4; ++j) (*K)(3 * i + 2, 3 * j + 2) += rhoAg * w * s.N[i] * s.N[j] / d;
            }
        }
    }
}

}  // namespace

Vec3 CurrentField::at(double z, Vec3* slope, Vec3* acceleration) const {
    Vec3 u = uniform;
    if (!rate.isZero(0.0)) u += rate * (time - rateStart);  // a current changing over the step
    if (slope) slope->setZero();
    if (acceleration) *acceleration = rate;  // a uniform current changing over the step accelerates the water
    if (profile == nullptr || profile->rows == 0) return u;
    const CurrentProfile& p = *profile;
    // The profile times currentScale, which may change linearly over the step.
    const double factor = profileScale * (scale + scaleRate * (time - rateStart));
    const double depth = -z;
    int i = 0;
    while (i + 1 < p.rows && p.depth[i + 1] < depth) ++i;
    Vec3 shape;  // the profile's velocity at this depth
    if (p.rows == 1 || depth <= p.depth[0] || depth >= p.depth[p.rows - 1]) {
        const int k = depth <= p.depth[0] ? 0 : p.rows - 1;
        shape = Vec3(p.ux[k], p.uy[k], 0.0);
    } else {
        const double span = p.depth[i + 1] - p.depth[i];
        const double w = (depth - p.depth[i]) / span;
        const Vec3 lo(p.ux[i], p.uy[i], 0.0), hi(p.ux[i + 1], p.uy[i + 1], 0.0);
        if (slope) *slope = -factor * (hi - lo) / span;  // d/dz = -d/d(depth)
        shape = (1.0 - w) * lo + w * hi;
    }
    if (acceleration && scaleRate != 0.0) *acceleration += profileScale * scaleRate * shape;
    return u + factor * shape;
}

Vec3 CurrentField::velocity(const Vec3& r) const {
    Vec3 u = at(r.z(), nullptr);
    if (grid == nullptr) return u;
    Vec3 g;
    gridOutside |= grid->at(r, time, g);
    return u + profileScale * g;
}

void CurrentField::flow(const Vec3& r, Vec3& U, Mat3& dU, Vec3& A, Mat3& dA, WaveExpansion* cache) const {
    Vec3 slope;
    U = at(r.z(), &slope, &A);
    dU.setZero();
    dU.col(2) = slope;
    dA.setZero();
    if (grid != nullptr) {
        Vec3 g, rate;
        Mat3 dg, drate;
        gridOutside |= grid->at(r, time, g, &dg, &rate, &drate);
        U += profileScale * g;
        dU += profileScale * dg;
        A += profileScale * rate;
        dA += profileScale * drate;
    }
    if (!waves()) return;
    Vec3 u, a;
    Mat3 du, da;
    if (cache) {
        sea->expanded_kinematics(r, time, *cache, u, a, &du, &da);
    } else {
        sea->kinematics(r, time, u, a, &du, &da);
    }
    U += u;
    dU += du;
    A += a;  // the waves' acceleration on top of the changing current's
    dA += da;
}

void CurrentField::flow(const Vec3& r, Vec3& U, Vec3& A, WaveExpansion* cache) const {
    U = at(r.z(), nullptr, &A);
    if (grid != nullptr) {
        Vec3 g, rate;
        gridOutside |= grid->at(r, time, g, nullptr, &rate);
        U += profileScale * g;
        A += profileScale * rate;
    }
    if (!waves()) return;
    Vec3 u, a;
    if (cache) {
        sea->expanded_kinematics(r, time, *cache, u, a);
    } else {
        sea->kinematics(r, time, u, a, nullptr, nullptr);
    }
    U += u;
    A += a;
}

double submerged_fraction(double z, double diameter) {
    return std::clamp(1.0 - z / diameter, 0.0, 1.0);
}

Vec3 point_load(const FluidProps& p, const Vec3& r, const Vec3& rp, const Vec3& rd, const Vec3& rdd, const Vec3& current,
                const Mat3& dU, bool waves, const Vec3& A, const Mat3& dA, PointLoadJacobian* J, bool buoyancy) {
    const double phi = submerged_fraction(r.z(), p.diameter);
    const double stretch = rp.norm();
    const Vec3 t = rp / stretch;
    const Vec3 u = current - rd;
    const double a = t.dot(u);
    const Vec3 un = u - a * t;
    const double sn = std::sqrt(un.squaredNorm() + kDragVelocityFloor * kDragVelocityFloor);
    const double sa = std::sqrt(a * a + kDragVelocityFloor * kDragVelocityFloor);
    const double cn = 0.5 * p.rho * p.Cdn * p.diameter;
    const double ct = 0.5 * p.rho * p.Cdt * kPi * p.diameter;
    const Vec3 drag = cn * sn * un + ct * sa * a * t;
    const double rhoA = p.rho * p.area;
    const Vec3 weight(0.0, 0.0, -(p.massPerLength - (buoyancy ? phi * rhoA : 0.0)) * p.gravity);

    Vec3 inertia = Vec3::Zero();
    const double ta = t.dot(rdd);
    if (p.addedMass) inertia = rhoA * (p.Can * (rdd - ta * t) + p.Cat * ta * t);

    // Fluid inertia, Froude-Krylov plus added mass: rho A ((1 + Can) A_n + (1 + Cat) A_t). The
    // tangential Froude-Krylov part belongs with the buoyancy taken as a load per length (effective
    // tension): both are the pressure of the water around a closed section.
    const double kn = rhoA * (1.0 + p.Can), kt = rhoA * (1.0 + p.Cat);
    const double At = waves ? t.dot(A) : 0.0;
    if (waves) inertia -= kn * (A - At * t) + kt * At * t;

    const Vec3 F = phi * inertia - weight - phi * drag;
    if (J == nullptr) return F;

    const Mat3 I = Mat3::Identity();
    const Mat3 tt = t * t.transpose();
    const Mat3 P = I - tt;
    // Drag: d/du and d/dt (t a unit vector), then dt/dr' = P/|r'|.
    const Mat3 dFn_dun = cn * (sn * I + un * un.transpose() / sn);
    const double dsaa = sa + a * a / sa;  // d(sa a)/da
    const Mat3 dDrag_du = dFn_dun * P + ct * dsaa * tt;
    const Mat3 dDrag_dt = -dFn_dun * (t * u.transpose() + a * I) + ct * (dsaa * t * u.transpose() + sa * a * I);
    Mat3 dInertia_dt = Mat3::Zero();
    Mat3 dInertia_drdd = Mat3::Zero();
    if (p.addedMass) {
        dInertia_drdd = rhoA * (p.Can * P + p.Cat * tt);
        dInertia_dt = rhoA * (p.Cat - p.Can) * (t * rdd.transpose() + ta * I);
    }
    if (waves) dInertia_dt += (kn - kt) * (t * A.transpose() + At * I);  // d(-kn A_n - kt A_t)/dt
    const Mat3 dt_drp = P / stretch;
    // u = U - r_dot: dF/dr_dot = + phi dDrag/du.
    J->drd = phi * dDrag_du;
    J->drp = phi * (dInertia_dt - dDrag_dt) * dt_drp;
    J->drdd = phi * dInertia_drdd;
    // F depends on r through the water's motion: dF/dr = -phi dDrag/du dU/dr - phi (kn P + kt t t^T) dA/dr.
    J->dr.setZero();
    if (waves) {
        J->dr = -phi * dDrag_du * dU - phi * (kn * P + kt * tt) * dA;
    } else {
        J->dr.col(2) = -phi * dDrag_du * dU.col(2);
    }
    const double dphi = submerged_fraction_slope(r.z(), p.diameter);
    if (dphi != 0.0) {
        Vec3 dF_dphi = inertia - drag;
        if (buoyancy) dF_dphi.z() += -rhoA * p.gravity;  // -d(weight)/dphi: weight_z = -(m - phi rho A) g
        J->dr.col(2) += dF_dphi * dphi;
    }
    return F;
}

namespace {

// The element's load points' loads, each with the water flow(g, r, U, A, dU, dA) gives it (dU, dA null: the
// residual needs no gradients). One instance per source of water: the FMU's own water compiles as it did
// before there was another.
template <class Flow>
void hydro_force(const ElementTables& e, const FluidProps& p, bool accelerates, const double* X, const double* Xd,
                 const double* Xdd, double* R, Flow flow) {
    const bool waterline = reaches_waterline(e.length, p.diameter, X);
    if (waterline) add_waterline_buoyancy(e, p, X, R, nullptr);
    for (int g = 0; g < e.nLoad; ++g) {
        const QuadPoint& q = e.load[g];
        const Vec3 r = interpolate(q.shape.N, X);
        Vec3 U, A;
        flow(g, r, U, A, nullptr, nullptr);
        const Mat3 unused = Mat3::Zero();
        const Vec3 F = point_load(p, r, interpolate(q.shape.dN, X), interpolate(q.shape.N, Xd),
                                  interpolate(q.shape.N, Xdd), U, unused, accelerates, A, unused, nullptr,
                                  !waterline);
        for (int a = 0; a < 4; ++a) Eigen::Map<Vec3>(R + 3 * a) += (q.weight * q.shape.N[a]) * F;
    }
}

template <class Flow>
void hydro_jacobian(const ElementTables& e, const FluidProps& p, bool accelerates, const double* X, const double* Xd,
                    const double* Xdd, Mat12& K, Mat12& C, Mat12& M, Flow flow) {
    PointLoadJacobian J;
    const bool waterline = reaches_waterline(e.length, p.diameter, X);
    if (waterline) add_waterline_buoyancy(e, p, X, nullptr, &K);
    for (int g = 0; g < e.nLoad; ++g) {
        const QuadPoint& q = e.load[g];
        const Vec3 r = interpolate(q.shape.N, X);
        Vec3 U, A;
        Mat3 dU, dA;
        flow(g, r, U, A, &dU, &dA);
        point_load(p, r, interpolate(q.shape.dN, X), interpolate(q.shape.N, Xd), interpolate(q.shape.N, Xdd), U,
                   dU, accelerates, A, dA, &J, !waterline);
        for (int a = 0; a < 4; ++a) {
            const double wa = q.weight * q.shape.N[a];
            for (int b = 0; b < 4; ++b) {
                K.block<3, 3>(3 * a, 3 * b) += wa * (q.shape.N[b] * J.dr + q.shape.dN[b] * J.drp);
                C.block<3, 3>(3 * a, 3 * b) += (wa * q.shape.N[b]) * J.drd;
                if (p.addedMass) M.block<3, 3>(3 * a, 3 * b) += (wa * q.shape.N[b]) * J.drdd;
            }
        }
    }
}

}  // namespace

void add_hydro_force(const ElementTables& e, const FluidProps& p, const CurrentField& current, const double* X,
                     const double* Xd, const double* Xdd, double* R, WaveExpansion* waveCache, const double* pushed) {
    if (pushed) {  // the water the importer pushed, at each load point
        hydro_force(e, p, true, X, Xd, Xdd, R, [&](int g, const Vec3&, Vec3& U, Vec3& A, Mat3*, Mat3*) {
            current.pushed_flow(pushed + 6 * g, U, A);
        });
        return;
    }
    hydro_force(e, p, current.accelerates(), X, Xd, Xdd, R, [&](int g, const Vec3& r, Vec3& U, Vec3& A, Mat3*, Mat3*) {
        current.flow(r, U, A, waveCache ? waveCache + g : nullptr);  // the load without its Jacobian needs no gradients of the flow
    });
}

void add_hydro_jacobian(const ElementTables& e, const FluidProps& p, const CurrentField& current,
                        const double* X, const double* Xd, const double* Xdd, Mat12& K, Mat12& C,
                        Mat12& M, WaveExpansion* waveCache, const double* pushed) {
    if (pushed) {  // the pushed water goes with the load point: no gradient
        hydro_jacobian(e, p, true, X, Xd, Xdd, K, C, M, [&](int g, const Vec3&, Vec3& U, Vec3& A, Mat3* dU, Mat3* dA) {
            current.pushed_flow(pushed + 6 * g, U, A);
            dU->setZero();
            dA->setZero();
        });
        return;
    }
    hydro_jacobian(e, p, current.accelerates(), X, Xd, Xdd, K, C, M,
                   [&](int g, const Vec3& r, Vec3& U, Vec3& A, Mat3* dU, Mat3* dA) {
                       current.flow(r, U, *dU, A, *dA, waveCache ? waveCache + g : nullptr);
                   });
}

}  // namespace uc
