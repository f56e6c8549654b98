// body_rods.h - the loads of a rigid rod's part under water (docs/lines.md, "Rods"): the one place that cuts a
// rod at the still water's surface z = 0, for a free rod's body and for the rods fixed to a free or pinned
// body, whose buoyancy, centre of buoyancy, Morison drag and added mass follow their draft as the body moves.
#pragma once

#include <functional>

#include "core/types.h"
#include "deck/line_file.h"

namespace uc {

// The part of the segment a -> b (earth frame) below z = 0: its share of the length, its ends' distances from a
// along the segment (s0 <= s1, in [0, |b - a|]), the centre of that part on the axis, and which ends are wet.
struct RodWetPart {
    double fraction = 0.0, s0 = 0.0, s1 = 0.0;
    Vec3 centre = Vec3::Zero();
    bool wetA = false, wetB = false;
    int wet_ends() const { return static_cast<int>(wetA) + static_cast<int>(wetB); }
};
RodWetPart rod_wet_part(const Vec3& a, const Vec3& b);

// The water's loads on rod `rod` fixed to a body whose reference point is at x with orientation R, moving at v,
// turning at w, accelerating at acc and alpha: its buoyancy rho g A times its wetted length, at the centroid of
// the water it displaces (a cut by the surface at a tilt shifts it across the axis by I tan(theta) / (A l) and
// along it by tan(theta)^2 I / (2 A l), I = pi d^4 / 64: the waterplane's restoring moment), its transverse drag
// 1/2 rho Cd d |u_n| u_n and added mass Ca rho A along its wet part (Gauss-Legendre points), at each wet end the
// axial drag 1/2 rho CdEnd A |u_t| u_t and added mass CaEnd rho pi d^3 / 12 (MoorDyn's half sphere), u the
// water's velocity (water(p)) less the rod's. Added to force and to moment (about x). The added mass's load is
// -(its mass) times the rod's acceleration a + alpha x r (the turning's centripetal part has none).
struct RodWater {
    double rho = 1025.0, g = 9.80665;
    std::function<Vec3(const Vec3&)> velocity;  // the water's velocity at a point (null: still water)
};
// add_rod_loads adds its buoyancy and drag, add_rod_inertia the load of its added mass.
void add_rod_loads(const MooringRod& rod, const Vec3& x, const Mat3& R, const Vec3& v, const Vec3& w,
                   const RodWater& water, Vec3& force, Vec3& moment);
void add_rod_inertia(const MooringRod& rod, const Vec3& x, const Mat3& R, const Vec3& acc, const Vec3& alpha,
                     double rho, Vec3& force, Vec3& moment);

}  // namespace uc
