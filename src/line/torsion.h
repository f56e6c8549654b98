// torsion.h - torque of the cable for the three torque modes (docs/model.md).
//
// The torque H is constant along the cable (no distributed torque; the paper's eq. 10).
// Mode 0: swivel, H = 0. Mode 1: H is the `torque` input. Mode 2: the far end's material frame
// is turned by the `twist` input Phi relative to the tow point's, and H = GJ (Phi - beta) / L,
// where beta is the geometric part of the end-to-end rotation: the angle between the tow point's
// reference normal carried along the cable by parallel transport (the twist-free Bishop frame)
// and the far end's reference normal. Parallel transport is defined wherever the tangent is,
// so straight stretches (zero curvature, where the Frenet torsion of the paper's eq. 8 is 0/0)
// are harmless. The two reference normals follow their end tangents by minimal rotation (the end
// fittings do not spin about the cable axis). In mode 2, H is evaluated at the start of every
// communication step and held over the step (explicit in the rotation, implicit in the shape).
#pragma once

#include "model/cable_model.h"

namespace uc {

// Minimal rotation carrying unit vector `from` onto unit vector `to`, applied to d.
Vec3 transport(const Vec3& d, const Vec3& from, const Vec3& to);

// A unit normal to t (deterministic).
Vec3 any_normal(const Vec3& t);

// Carries normal d0 (at s = 0) along the cable X by parallel transport; returns it at s = L.
Vec3 transport_along(const CableModel& model, const double* X, const Vec3& d0);

// Reference frames of the ends, fixed when the cable is initialized.
// Plain doubles (trivially copyable: part of the line's saved state, line/line_state.h).
struct TwistReference {
    double topTangent[3] = {0.0, 0.0, 1.0}, topNormal[3] = {1.0, 0.0, 0.0};
    double endTangent[3] = {0.0, 0.0, 1.0}, endNormal[3] = {1.0, 0.0, 0.0};
};

TwistReference make_twist_reference(const CableModel& model, const double* X);

// beta: signed angle about the far-end tangent from the transported tow-point reference normal
// to the far end's reference normal (the sign makes a buckled helix, whose writhe takes up part
// of the prescribed rotation, lower the torque: checked in tests/core/test_torsion.cpp).
double geometric_twist(const CableModel& model, const double* X, const TwistReference& ref);

}  // namespace uc
