// seabed.h - a plane seabed through z = -waterDepth under the origin, flat or sloped, or a seabed given as a
// grid of heights (SeabedGrid): penalty contact per unit length with damping and regularized Coulomb
// friction (docs/model.md). Residual sign: F = -f_seabed.
//
// With the seabed's upward unit normal n (e_z where it is flat), the penetration is
// p = -n.(r - (0, 0, -waterDepth)) (-waterDepth - z on a flat seabed). The normal force per length is
// k g(p) n with g a C1 ramp that starts at the seabed: 0 above it, p^2 / (2 delta) over the first
// delta = 5 % of the diameter of penetration, p - delta / 2 beyond, so that Newton and BDF see a
// smooth contact; the damping c (-n.r_dot) acts with the same contact fraction g'(p) in [0, 1].
// Friction opposes the velocity along the surface v_t = r_dot - (n.r_dot) n with magnitude
// mu k g(p) |v_t| / sqrt(|v_t|^2 + v_eps^2): regularized Coulomb, the same coefficient axially and
// laterally.
//
// On a grid the same law acts in the local plane under each contact point: the tangent plane of the grid's
// bilinear interpolant at (x, y), its upward normal n = (-dz/dx, -dz/dy, 1) / |.|, the penetration along it
// n_z (h(x, y) - z); one code path with the sloped plane, whose local plane is the plane itself.
#pragma once

#include "terms/hermite_element.h"
#include "terms/seabed_grid.h"

namespace uc {

struct SeabedProps {
    bool enabled = false;
    double depth = 0.0;      // waterDepth [m]
    double stiffness = 0.0;  // [N/m2]: force per length per metre of penetration
    double damping = 0.0;    // [N.s/m2]
    double friction = 0.0;   // Coulomb coefficient
    double smoothing = 0.0;  // delta [m]
    // A sloped plane (seabedSlope > 0): its upward unit normal, tilted towards the heading in which it
    // descends. Flat: e_z, and the contact takes the flat seabed's shorter path.
    bool sloped = false;
    Vec3 normal = Vec3::UnitZ();
    // A seabed given as a grid (seabed.file, a deck's SeafloorFile): its heights in place of the plane
    // (`sloped` is set, `normal` is e_z and `depth` unused); `restWeight`, the weight per length of
    // footprint the contact surface is raised for (rest_at_depth), 0 for none. Owned by the model.
    const SeabedGrid* grid = nullptr;
    double restWeight = 0.0;
};

// Gives the seabed the grid (null: the plane of its parameters): sets `grid` and `sloped`.
void set_grid(SeabedProps& p, const SeabedGrid* grid);

// The local plane of the contact under r: its upward unit normal n and the penetration along it [m]
// (positive below the contact surface); the plane itself on a plane seabed.
double local_penetration(const SeabedProps& p, const Vec3& r, Vec3& n);

// The seabed's upward unit normal under (x, y): e_z flat, the plane's, the grid's local one.
Vec3 seabed_normal(const SeabedProps& p, double x, double y);

// The plane of seabedSlope [deg] descending along seabedSlopeHeading [deg] (from +x towards +y):
// sets `sloped` and `normal` (flat at a zero slope).
void set_slope(SeabedProps& p, double slopeDeg, double headingDeg);

double grid_contact_height(const SeabedProps& p, double x, double y);

// Height [m] of the contact surface above (x, y): -depth on a flat seabed; on a grid its height raised by
// the rest penetration (rest_at_depth) over its local n_z.
inline double seabed_height(const SeabedProps& p, double x, double y) {
    if (!p.sloped) return -p.depth;
    if (p.grid) return grid_contact_height(p, x, y);
    return -p.depth - (p.normal.x() * x + p.normal.y() * y) / p.normal.z();
}

// Friction regularization velocity [m/s]: below it friction grows linearly with sliding speed.
constexpr double kFrictionVelocity = 0.01;

struct SeabedJacobian {
    Mat3 dr, drd;  // dF/dr, dF/dr_dot
};

// Per-length residual contribution at a point; fills J when non-null. Zero above the seabed.
Vec3 seabed_load(const SeabedProps& p, const Vec3& r, const Vec3& rd, SeabedJacobian* J);

// The seabed contact of a point (an attachment, a towed body, the tip of a free end): the line's
// contact per length times a footprint [m], the length of line with the same contact area. The
// seabedStiffness per length is a stiffness per area (MoorDyn's kBot) times the diameter, so a body
// of size b (the cube root of its volume, or of a steel body's of its mass) presses on b^2 / d.
struct PointContact {
    SeabedProps seabed{};
    double footprint = 0.0;
};
double body_size(double mass, double volume);                        // b [m]
double body_footprint(double mass, double volume, double diameter);  // b^2 / d [m]
Vec3 point_contact_load(const PointContact& c, const Vec3& r, const Vec3& rd, SeabedJacobian* J);

// Penetration [m] at which a line of this submerged weight per length [N/m] rests on the seabed
// (along its normal: a sloped seabed carries the weight's normal part, weight n_z; on a grid, where its
// normal's vertical part is nz).
double resting_penetration(const SeabedProps& p, double weight);
double resting_penetration(const SeabedProps& p, double weight, double nz);

// `seabedRest` 1: the contact surface raised by the rest penetration of this weight per length
// (of contact footprint), so that what rests there lies at z = -waterDepth (on a grid at its height,
// raised under each point by the rest penetration of its local plane). Nothing for a buoyant or
// weightless part, or a disabled seabed.
void rest_at_depth(SeabedProps& p, double weight);

// True when no point of the element (its 12 DOFs at X) can touch the contact band, so that
// seabed_load is exactly zero at every sampling point, which can then be skipped without changing a
// bit of the result.
bool above_contact(const ElementTables& e, const SeabedProps& p, const double* X);

// The points at which an element's contact is integrated: its contact rule where it has one (and
// `axialOnly` is not set), else its axial points.
struct ContactPoints {
    const QuadPoint* points;
    int count;
};
inline ContactPoints contact_points(const ElementTables& e, bool axialOnly = false) {
    if (e.nContact > 0 && !axialOnly) return {e.contact, e.nContact};
    return {e.axial, ElementTables::nAxial};
}

// Element integrals over the element's contact points (contact_points: the 5 axial sampling points
// unless seabedContactSpacing asks for more; contact is sampled more finely than the hydrodynamic
// loads because it switches on and off along the cable).
void add_seabed_force(const ElementTables& e, const SeabedProps& p, const double* X, const double* Xd, double* R,
                      bool axialOnly = false);
void add_seabed_jacobian(const ElementTables& e, const SeabedProps& p, const double* X, const double* Xd,
                         Mat12& K, Mat12& C, bool axialOnly = false);

// Static solver only: the static friction of a sloped seabed holding what rests on it across the line,
// where the line's planar static profile laid it (docs/model.md, "A sloped seabed"). `held` is the
// element's 12 DOFs in the held shape, `across` the unit direction along the seabed's surface across
// the profile's vertical plane. At each contact point, with the offset d = r - r0 from the held
// point r0 and the normal contact force per length k g(p) there, the force per length
// -k g(p) (across.d) / delta across: static friction of stiffness k g(p) / delta, which needs the
// coefficient |across.d| / delta, nothing off the seabed.
void add_seabed_hold(const ElementTables& e, const SeabedProps& p, const Vec3& across, const double* X,
                     const double* held, double* R, bool axialOnly = false);
void add_seabed_hold_jacobian(const ElementTables& e, const SeabedProps& p, const Vec3& across, const double* X,
                              const double* held, Mat12& K, bool axialOnly = false);

// The holding force per length of add_seabed_hold at a point (along `across`), and the normal contact
// force per length there (k g(p)): their ratio is the static friction coefficient the hold needs.
void seabed_hold_at(const SeabedProps& p, const Vec3& across, const Vec3& r, const Vec3& r0, double& hold,
                    double& normal);

}  // namespace uc
