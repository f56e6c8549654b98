// seabed.cpp - penalty contact, damping and regularized friction on a plane seabed, flat or sloped, or on
// the local plane of a grid.
#include "terms/seabed.h"

#include <algorithm>
#include <cmath>

namespace uc {
namespace {

// C1 ramp that starts at the seabed: 0 above it (p <= 0), p^2 / (2 delta) over the first delta of
// penetration, p - delta / 2 beyond; and its derivative (the contact fraction). No force acts above
// the seabed: a line leaving an anchor on the seabed at a small angle is not pushed up by a band
// above it (a band centred on the seabed pushed with k delta / 4 at zero penetration, which moved
// the anchor tension of a nearly horizontal departure by 1.7 % on 80 elements).
double contact_ramp(double p, double delta, double* slope) {
    if (p <= 0.0) {
        *slope = 0.0;
        return 0.0;
    }
    if (p >= delta) {
        *slope = 1.0;
        return p - 0.5 * delta;
    }
    *slope = p / delta;
    return 0.5 * p * p / delta;
}

// Round-off allowance of above_contact [m]: the heights interpolated at the sampling points are
// sums of terms of a few hundred metres at most, exact to far below a micrometre.
constexpr double kHullMargin = 1e-6;

}  // namespace

double body_size(double mass, double volume) {
    const double steel = 7850.0;  // [kg/m3]
    return std::cbrt(std::max(volume, mass / steel));
}

double body_footprint(double mass, double volume, double diameter) {
    const double b = body_size(mass, volume);
    return b * b / diameter;
}

Vec3 point_contact_load(const PointContact& c, const Vec3& r, const Vec3& rd, SeabedJacobian* J) {
    const Vec3 F = c.footprint * seabed_load(c.seabed, r, rd, J);
    if (J) {
        J->dr *= c.footprint;
        J->drd *= c.footprint;
    }
    return F;
}

void set_slope(SeabedProps& p, double slopeDeg, double headingDeg) {
    p.sloped = slopeDeg != 0.0;
    const double a = slopeDeg * kPi / 180.0, psi = headingDeg * kPi / 180.0;
    // descending along (cos psi, sin psi): the normal leans that way
    p.normal = p.sloped ? Vec3(std::sin(a) * std::cos(psi), std::sin(a) * std::sin(psi), std::cos(a)) : Vec3::UnitZ();
}

void set_grid(SeabedProps& p, const SeabedGrid* grid) {
    p.grid = grid;
    if (grid) {
        p.sloped = true;
        p.normal = Vec3::UnitZ();
    }
}

double resting_penetration(const SeabedProps& p, double weight, double nz) {
    // k g(p) = w n_z (the weight's part along the normal) on the branches of contact_ramp
    const double ramp = weight * nz / p.stiffness;
    if (ramp >= 0.5 * p.smoothing) return ramp + 0.5 * p.smoothing;
    return std::sqrt(2.0 * p.smoothing * ramp);
}

double resting_penetration(const SeabedProps& p, double weight) { return resting_penetration(p, weight, p.normal.z()); }

void rest_at_depth(SeabedProps& p, double weight) {
    if (!(p.enabled && p.stiffness > 0.0 && weight > 0.0)) return;
    // a grid: raised under each point (local_penetration)
    if (p.grid) {
        p.restWeight = weight;
        return;
    }
    // raised by the penetration along the normal: the plane's depth under the origin by that over n_z
    p.depth -= resting_penetration(p, weight) / p.normal.z();
}

double local_penetration(const SeabedProps& p, const Vec3& r, Vec3& n) {
    if (!p.grid) {
        n = p.sloped ? p.normal : Vec3::UnitZ();
        return p.sloped ? -p.depth * n.z() - n.dot(r) : -p.depth - r.z();
    }
    double gx = 0.0, gy = 0.0;
    const double h = p.grid->height(r.x(), r.y(), &gx, &gy);
    const double nz = 1.0 / std::sqrt(1.0 + gx * gx + gy * gy);
    n = Vec3(-gx * nz, -gy * nz, nz);
    const double rest = p.restWeight > 0.0 ? resting_penetration(p, p.restWeight, nz) : 0.0;
    return nz * (h - r.z()) + rest;
}

double grid_contact_height(const SeabedProps& p, double x, double y) {
    double gx = 0.0, gy = 0.0;
    const double h = p.grid->height(x, y, &gx, &gy);
    if (!(p.restWeight > 0.0)) return h;
    const double nz = 1.0 / std::sqrt(1.0 + gx * gx + gy * gy);
    return h + resting_penetration(p, p.restWeight, nz) / nz;
}

Vec3 seabed_normal(const SeabedProps& p, double x, double y) {
    Vec3 n;
    local_penetration(p, Vec3(x, y, 0.0), n);
    return n;
}

// The cubic Hermite curve is the Bezier curve with control points r0, r0 + l t0 / 3, r1 - l t1 / 3,
// r1, and lies in their convex hull: it is nowhere lower than the lowest of their heights.
// On a sloped plane the same holds for the height along its normal, n.r, a linear function.
bool above_contact(const ElementTables& e, const SeabedProps& p, const double* X) {
    const double third = e.length / 3.0;
    if (p.grid) {
        // the control points' lowest height against the highest node of the cells under their box, raised
        // by the largest rest penetration over the steepest cell's n_z (resting_penetration grows with n_z)
        double lowest = HUGE_VAL, x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
        for (int c = 0; c < 4; ++c) {
            const double* r = X + (c < 2 ? 0 : 6);
            const double* t = X + (c < 2 ? 3 : 9);
            const double step = c == 1 ? third : c == 2 ? -third : 0.0;
            const double x = r[0] + step * t[0], y = r[1] + step * t[1], z = r[2] + step * t[2];
            lowest = std::min(lowest, z);
            x0 = std::min(x0, x);
            x1 = std::max(x1, x);
            y0 = std::min(y0, y);
            y1 = std::max(y1, y);
        }
        const double steepest = p.grid->steepest();
        const double lift = p.restWeight > 0.0 ? resting_penetration(p, p.restWeight, 1.0) * std::sqrt(1.0 + steepest * steepest) : 0.0;
        return lowest > p.grid->highest(x0, x1, y0, y1) + lift + kHullMargin;
    }
    if (p.sloped) {
        const Vec3 n = p.normal;
        const double a = n.dot(Eigen::Map<const Vec3>(X)), ta = n.dot(Eigen::Map<const Vec3>(X + 3));
        const double b = n.dot(Eigen::Map<const Vec3>(X + 6)), tb = n.dot(Eigen::Map<const Vec3>(X + 9));
        const double lowest = std::min(std::min(a, a + third * ta), std::min(b - third * tb, b));
        return lowest > -p.depth * n.z() + kHullMargin;
    }
    const double lowest = std::min(std::min(X[2], X[2] + third * X[5]), std::min(X[8] - third * X[11], X[8]));
    return lowest > -p.depth + kHullMargin;
}

namespace {

// The contact on a local plane (a sloped plane, or a grid's under r): the flat seabed's law along its
// normal n, friction along its surface. On a grid the Jacobian leaves out the normal's turning across a
// cell (a force of the order of the weight per length times the cell's twist, beside the contact's
// stiffness).
Vec3 sloped_load(const SeabedProps& p, const Vec3& r, const Vec3& rd, SeabedJacobian* J) {
    Vec3 n;
    const double penetration = local_penetration(p, r, n);
    double fraction = 0.0;
    const double ramp = contact_ramp(penetration, p.smoothing, &fraction);
    if (fraction == 0.0) return Vec3::Zero();
    const double fractionSlope = penetration > 0.0 && penetration < p.smoothing ? 1.0 / p.smoothing : 0.0;
    const double spring = p.stiffness * ramp;
    const double vn = n.dot(rd);
    const double normal = spring - p.damping * fraction * vn;
    const Vec3 vt = rd - vn * n;
    const double speed = std::sqrt(vt.squaredNorm() + kFrictionVelocity * kFrictionVelocity);
    // f = normal n - mu spring vt / speed; residual F = -f.
    Vec3 F = -normal * n + (p.friction * spring / speed) * vt;
    if (J) {
        // dp/dr = -n^T
        const double dNormal_dp = p.stiffness * fraction - p.damping * fractionSlope * vn;
        J->dr = (dNormal_dp * n) * n.transpose() - (p.friction * p.stiffness * fraction / speed) * vt * n.transpose();
        J->drd = (p.damping * fraction) * n * n.transpose();
        if (p.friction != 0.0) {
            const Mat3 tangential = Mat3::Identity() - n * n.transpose();
            J->drd += (p.friction * spring / speed) * (tangential - vt * (vt.transpose() * tangential) / (speed * speed));
        }
    }
    return F;
}

}  // namespace

Vec3 seabed_load(const SeabedProps& p, const Vec3& r, const Vec3& rd, SeabedJacobian* J) {
    if (J) {
        J->dr.setZero();
        J->drd.setZero();
    }
    if (p.sloped) return sloped_load(p, r, rd, J);
    const double penetration = -p.depth - r.z();
    double fraction = 0.0;
    const double ramp = contact_ramp(penetration, p.smoothing, &fraction);
    if (fraction == 0.0) return Vec3::Zero();
    // d(fraction)/dp inside the blend band
    const double fractionSlope = penetration > 0.0 && penetration < p.smoothing ? 1.0 / p.smoothing : 0.0;
    const double spring = p.stiffness * ramp;
    const double normal = spring - p.damping * fraction * rd.z();
    const Vec3 vh(rd.x(), rd.y(), 0.0);
    const double speed = std::sqrt(vh.squaredNorm() + kFrictionVelocity * kFrictionVelocity);
    // f = normal e_z - mu spring vh / speed; residual F = -f.
    Vec3 F = -normal * Vec3::UnitZ() + (p.friction * spring / speed) * vh;
    if (J) {
        // dp/dz = -1
        const double dNormal_dz = -(p.stiffness * fraction) + p.damping * fractionSlope * rd.z();
        J->dr(2, 2) = -dNormal_dz;
        const double dSpring_dz = -p.stiffness * fraction;
        J->dr.col(2) += (p.friction * dSpring_dz / speed) * vh;
        J->drd(2, 2) = p.damping * fraction;
        if (p.friction != 0.0) {
            Mat3 dvh = Mat3::Zero();
            dvh(0, 0) = dvh(1, 1) = 1.0;
            J->drd += (p.friction * spring / speed) * (dvh - vh * vh.transpose() / (speed * speed));
        }
    }
    return F;
}

void add_seabed_force(const ElementTables& e, const SeabedProps& p, const double* X, const double* Xd, double* R,
                      bool axialOnly) {
    if (above_contact(e, p, X)) return;
    const ContactPoints points = contact_points(e, axialOnly);
    for (int g = 0; g < points.count; ++g) {
        const QuadPoint& q = points.points[g];
        const Vec3 F = seabed_load(p, interpolate(q.shape.N, X), interpolate(q.shape.N, Xd), nullptr);
        if (F.isZero(0.0)) continue;
        for (int a = 0; a < 4; ++a) Eigen::Map<Vec3>(R + 3 * a) += (q.weight * q.shape.N[a]) * F;
    }
}

void add_seabed_jacobian(const ElementTables& e, const SeabedProps& p, const double* X, const double* Xd,
                         Mat12& K, Mat12& C, bool axialOnly) {
    if (above_contact(e, p, X)) return;
    SeabedJacobian J;
    const ContactPoints points = contact_points(e, axialOnly);
    for (int g = 0; g < points.count; ++g) {
        const QuadPoint& q = points.points[g];
        const Vec3 F = seabed_load(p, interpolate(q.shape.N, X), interpolate(q.shape.N, Xd), &J);
        if (F.isZero(0.0) && J.dr.isZero(0.0)) continue;
        for (int a = 0; a < 4; ++a) {
            for (int b = 0; b < 4; ++b) {
                const double w = q.weight * q.shape.N[a] * q.shape.N[b];
                K.block<3, 3>(3 * a, 3 * b) += w * J.dr;
                C.block<3, 3>(3 * a, 3 * b) += w * J.drd;
            }
        }
    }
}

namespace {

// Penetration [m] along the normal of the seabed's local plane.
double penetration_at(const SeabedProps& p, const Vec3& r) {
    Vec3 n;
    return local_penetration(p, r, n);
}

}  // namespace

void seabed_hold_at(const SeabedProps& p, const Vec3& across, const Vec3& r, const Vec3& r0, double& hold,
                    double& normal) {
    double fraction = 0.0;
    normal = p.stiffness * contact_ramp(penetration_at(p, r), p.smoothing, &fraction);
    hold = normal * across.dot(r - r0) / p.smoothing;
}

void add_seabed_hold(const ElementTables& e, const SeabedProps& p, const Vec3& across, const double* X,
                     const double* held, double* R, bool axialOnly) {
    if (above_contact(e, p, X)) return;
    const ContactPoints points = contact_points(e, axialOnly);
    for (int g = 0; g < points.count; ++g) {
        const QuadPoint& q = points.points[g];
        double hold = 0.0, normal = 0.0;
        seabed_hold_at(p, across, interpolate(q.shape.N, X), interpolate(q.shape.N, held), hold, normal);
        if (hold == 0.0) continue;
        // residual F = -f = +k g'(p) (across.d) across
        for (int a = 0; a < 4; ++a) Eigen::Map<Vec3>(R + 3 * a) += (q.weight * q.shape.N[a] * hold) * across;
    }
}

void add_seabed_hold_jacobian(const ElementTables& e, const SeabedProps& p, const Vec3& across, const double* X,
                              const double* held, Mat12& K, bool axialOnly) {
    if (above_contact(e, p, X)) return;
    const ContactPoints points = contact_points(e, axialOnly);
    for (int g = 0; g < points.count; ++g) {
        const QuadPoint& q = points.points[g];
        const Vec3 r = interpolate(q.shape.N, X);
        Vec3 n;
        const double pen = local_penetration(p, r, n);
        double fraction = 0.0;
        const double ramp = contact_ramp(pen, p.smoothing, &fraction);
        if (fraction == 0.0) continue;
        const double offset = across.dot(r - interpolate(q.shape.N, held));
        // d/dr of k g(p) (across.d) across / delta, with dp/dr = -n^T
        const Mat3 J = (p.stiffness / p.smoothing) *
                       (ramp * across * across.transpose() - (fraction * offset) * across * n.transpose());
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b) K.block<3, 3>(3 * a, 3 * b) += (q.weight * q.shape.N[a] * q.shape.N[b]) * J;
    }
}

}  // namespace uc
