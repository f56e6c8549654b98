// torsion.cpp - parallel transport of frames along the cable.
#include "line/torsion.h"

#include <cmath>

namespace uc {
namespace {

// Parallel transport is sampled this many times per element (tangent rotations of a few
// degrees per sample on a strongly bent cable; transport is exact for piecewise-constant steps).
constexpr int kTransportSamples = 16;

Vec3 unit_tangent(const ShapeValues& s, const double* Xe) { return interpolate(s.dN, Xe).normalized(); }

}  // namespace

Vec3 transport(const Vec3& d, const Vec3& from, const Vec3& to) {
    const Vec3 axis = from.cross(to);
    const double c = from.dot(to);
    if (c < -1.0 + 1e-12) return -d;  // half turn: any axis normal to `from` (none preferred)
    // Rodrigues for the rotation taking `from` to `to`: d + axis x d + axis x (axis x d) / (1 + c).
    return d + axis.cross(d) + axis.cross(axis.cross(d)) / (1.0 + c);
}

Vec3 any_normal(const Vec3& t) {
    const Vec3 seed = std::abs(t.z()) < 0.9 ? Vec3::UnitZ() : Vec3::UnitX();
    return (seed - t * t.dot(seed)).normalized();
}

Vec3 transport_along(const CableModel& model, const double* X, const Vec3& d0) {
    Vec3 d = d0;
    Vec3 t = unit_tangent(hermite_shape(0.0, model.element_length(0)), X);
    for (int e = 0; e < model.n_elements(); ++e) {
        const double l = model.element_length(e);
        for (int k = 0; k <= kTransportSamples; ++k) {
            // k = 0 matters only across a pinned joint, where the next section's tangent turns
            // (elsewhere the transport to the same tangent is the identity).
            if (k == 0 && (e == 0 || model.element_offset(e) == model.element_offset(e - 1) + 6)) continue;
            const Vec3 next = unit_tangent(hermite_shape(static_cast<double>(k) / kTransportSamples, l), X + model.element_offset(e));
            d = transport(d, t, next);
            d = (d - next * next.dot(d)).normalized();  // keep it a unit normal against round-off
            t = next;
        }
    }
    return d;
}

TwistReference make_twist_reference(const CableModel& model, const double* X) {
    const int N = model.n_elements();
    const Vec3 topTangent = unit_tangent(hermite_shape(0.0, model.element_length(0)), X);
    const Vec3 topNormal = any_normal(topTangent);
    const Vec3 endTangent = unit_tangent(hermite_shape(1.0, model.element_length(N - 1)), X + model.element_offset(N - 1));
    const Vec3 endNormal = transport_along(model, X, topNormal);
    TwistReference ref;
    Eigen::Map<Vec3>{ref.topTangent} = topTangent;
    Eigen::Map<Vec3>{ref.topNormal} = topNormal;
    Eigen::Map<Vec3>{ref.endTangent} = endTangent;
    Eigen::Map<Vec3>{ref.endNormal} = endNormal;
    return ref;
}

double geometric_twist(const CableModel& model, const double* X, const TwistReference& ref) {
    const int N = model.n_elements();
    const Vec3 t0 = unit_tangent(hermite_shape(0.0, model.element_length(0)), X);
    const Vec3 tL = unit_tangent(hermite_shape(1.0, model.element_length(N - 1)), X + model.element_offset(N - 1));
    const Vec3 top = transport(Vec3(ref.topNormal[0], ref.topNormal[1], ref.topNormal[2]),
                                Vec3(ref.topTangent[0], ref.topTangent[1], ref.topTangent[2]), t0);
    const Vec3 carried = transport_along(model, X, (top - t0 * t0.dot(top)).normalized());
    Vec3 far = transport(Vec3(ref.endNormal[0], ref.endNormal[1], ref.endNormal[2]),
                         Vec3(ref.endTangent[0], ref.endTangent[1], ref.endTangent[2]), tL);
    far = (far - tL * tL.dot(far)).normalized();
    return std::atan2(tL.dot(carried.cross(far)), carried.dot(far));
}

}  // namespace uc
