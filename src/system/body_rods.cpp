// body_rods.cpp - a rigid rod's part under water and the water's loads on it (body_rods.h).
#include "system/body_rods.h"

#include "system/mooring_system.h"

#include <algorithm>
#include <cmath>

namespace uc {

RodWetPart rod_wet_part(const Vec3& a, const Vec3& b) {
    RodWetPart p;
    const double L = (b - a).norm();
    if (std::max(a.z(), b.z()) <= 0.0) {  // all under water
        p.fraction = 1.0, p.s0 = 0.0, p.s1 = L, p.wetA = p.wetB = true;
    } else if (std::min(a.z(), b.z()) >= 0.0) {  // all above
        p.fraction = 0.0, p.s0 = p.s1 = 0.0;
    } else {  // through the surface: the part from its lower end up to z = 0
        p.fraction = -std::min(a.z(), b.z()) / std::abs(b.z() - a.z());
        p.wetA = a.z() < b.z();
        p.wetB = !p.wetA;
        p.s0 = p.wetA ? 0.0 : (1.0 - p.fraction) * L;
        p.s1 = p.wetA ? p.fraction * L : L;
    }
    const Vec3 t = L > 0.0 ? Vec3((b - a) / L) : Vec3::Zero();
    p.centre = p.fraction > 0.0 ? Vec3(a + 0.5 * (p.s0 + p.s1) * t) : Vec3(0.5 * (a + b));
    return p;
}

namespace {

// The rod's loads of either kind: buoyancy and drag (inertia false), or its added mass's (inertia true).
void rod_loads(const MooringRod& rod, const Vec3& x, const Mat3& R, const Vec3& v, const Vec3& w, const Vec3& acc,
               const Vec3& alpha, const RodWater& water, bool inertia, Vec3& force, Vec3& moment) {
    const Vec3 a = x + R * Vec3(rod.a[0], rod.a[1], rod.a[2]), b = x + R * Vec3(rod.b[0], rod.b[1], rod.b[2]);
    const RodWetPart wet = rod_wet_part(a, b);
    if (!(wet.fraction > 0.0)) return;  // in the air: its weight alone (the body's)
    const double L = (b - a).norm(), d = rod.diameter, A = 0.25 * kPi * d * d, rho = water.rho;
    const Vec3 t = (b - a) / L;
    auto add = [&](const Vec3& at, const Vec3& f) {
        force += f;
        moment += (at - x).cross(f);
    };
    auto flow = [&](const Vec3& p) {  // the water's velocity relative to the rod at p
        const Vec3 u = water.velocity ? water.velocity(p) : Vec3::Zero();
        return Vec3(u - v - w.cross(p - x));
    };
    // buoyancy: the displaced water's weight at its centroid; where the surface cuts the rod at a tilt theta
    // from the vertical, the water line runs across the section, which shifts the centroid off the axis point
    const double l = wet.s1 - wet.s0, B = rho * water.g * A * l;
    Vec3 centroid = wet.centre;
    if (wet.fraction < 1.0 && !inertia) {
        const Vec3 E = wet.wetA ? a : b, u = wet.wetA ? t : Vec3(-t);  // the wet end, up the rod from it
        const double uz = u.z(), I = kPi * std::pow(d, 4) / 64.0;
        // tan(theta) n = (z - uz u) / uz, n the section's direction most upward; the shift holds while the water
        // line crosses the side, not an end cap: tan(theta) at most the ends' distances over the radius
        const double tanTheta = std::sqrt(std::max(1.0 - uz * uz, 0.0)) / uz;
        const double reach = std::min(l, L - l) / (0.5 * d);
        const double scale = tanTheta > reach ? reach / tanTheta : 1.0;
        const Vec3 across = scale * (Vec3::UnitZ() - uz * u) / uz;  // tan(theta) n
        centroid = E + u * (0.5 * l + across.squaredNorm() * I / (2.0 * A * l)) - across * I / (A * l);
    }
    if (!inertia) add(centroid, Vec3(0.0, 0.0, B));
    // along its wet part: transverse drag and added mass (Gauss-Legendre, 6 points)
    static const double kNodes[6] = {-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                                     0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
    static const double kWeights[6] = {0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                                       0.4679139345726910, 0.3607615730481386, 0.1713244923791704};
    const Mat3 across = Mat3::Identity() - t * t.transpose();
    for (int i = 0; i < 6; ++i) {
        const double s = wet.s0 + 0.5 * l * (1.0 + kNodes[i]), ds = 0.5 * l * kWeights[i];
        const Vec3 p = a + s * t;
        if (inertia) {
            add(p, -ds * rod.Ca * rho * A * (across * (acc + alpha.cross(p - x))));
        } else {
            const Vec3 u = across * flow(p);
            add(p, ds * 0.5 * rho * rod.Cd * d * u.norm() * u);
        }
    }
    // at each wet end: axial drag and added mass
    const double endVolume = kPi * d * d * d / 12.0;
    for (int e = 0; e < 2; ++e) {
        if (!(e == 0 ? wet.wetA : wet.wetB)) continue;
        const Vec3& p = e == 0 ? a : b;
        if (inertia) {
            add(p, -rod.CaEnd * rho * endVolume * t.dot(acc + alpha.cross(p - x)) * t);
        } else {
            const Vec3 u = t.dot(flow(p)) * t;
            add(p, 0.5 * rho * rod.CdEnd * A * u.norm() * u);
        }
    }
}

}  // namespace

void add_rod_loads(const MooringRod& rod, const Vec3& x, const Mat3& R, const Vec3& v, const Vec3& w,
                   const RodWater& water, Vec3& force, Vec3& moment) {
    rod_loads(rod, x, R, v, w, Vec3::Zero(), Vec3::Zero(), water, false, force, moment);
}

void add_rod_inertia(const MooringRod& rod, const Vec3& x, const Mat3& R, const Vec3& acc, const Vec3& alpha,
                     double rho, Vec3& force, Vec3& moment) {
    RodWater water;
    water.rho = rho;
    rod_loads(rod, x, R, Vec3::Zero(), Vec3::Zero(), acc, alpha, water, true, force, moment);
}

}  // namespace uc

// ----------------------------------------------------------------------- the system's bodies with rods

namespace uc {

namespace {
Vec3 v3(const double v[3]) { return Vec3(v[0], v[1], v[2]); }
}  // namespace

void MooringSystem::add_body_rod_loads(int n, const Vec3& x, const Mat3& R, const Vec3& v, const Vec3& omega,
                                       const UCInputs& in, Vec3& force, Vec3& moment) const {
    const FluidProps& fluid = lines_[0]->model().fluid();
    RodWater water;
    water.rho = fluid.rho;
    water.g = fluid.gravity;
    water.velocity = [&](const Vec3& p) { return water_velocity(p, in); };
    for (const MooringRod& rod : deck_.nodes[n].rods) add_rod_loads(rod, x, R, v, omega, water, force, moment);
}

void MooringSystem::add_body_rod_inertia(int n, const Vec3& x, const Mat3& R, const Vec3& acc, const Vec3& alpha,
                                         Vec3& force, Vec3& moment) const {
    const double rho = lines_[0]->model().fluid().rho;
    for (const MooringRod& rod : deck_.nodes[n].rods) add_rod_inertia(rod, x, R, acc, alpha, rho, force, moment);
}

void MooringSystem::body_point_motion(const MooringEnd& end, Vec3& x, Vec3& v, Vec3& a) const {
    const FreeNodeMotion& m = motion_[end.node];
    const Vec3 arm = Eigen::Map<const Mat3>(m.rotation) * v3(end.position), w = v3(m.omega);
    x = v3(m.position) + arm;
    v = v3(m.velocity) + w.cross(arm);
    a = v3(m.acceleration) + v3(m.alpha).cross(arm) + w.cross(w.cross(arm));
}

void MooringSystem::add_pin_reaction(int n, const Vec3& force, Eigen::VectorXd& r) const {
    const MooringEnd& pin = deck_.nodes[n].pin;
    const FreeNodeMotion& holder = motion_[pin.node];
    const int o = nodeOffset_[pin.node];
    r.segment<3>(o) += force;
    r.segment<3>(o + 3) += (Eigen::Map<const Mat3>(holder.rotation) * v3(pin.position)).cross(force);
}

}  // namespace uc
