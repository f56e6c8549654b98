// hydrodynamics.h - distributed external loads per unit unstretched length: submerged weight,
// Morison drag on the relative velocity, added mass (docs/model.md).
//
// Residual sign: the load enters R = M r'' + f_int - f_ext as
//   F = m_a r'' - f_weight - f_drag,   m_a = phi rho A (Can (I - t t^T) + Cat t t^T),
// f_weight = -(m - phi rho A) g e_z, f_drag = phi (0.5 rho Cdn d |u_n| u_n + 0.5 rho Cdt pi d |u_t| u_t),
// u = U - r_dot, t = r'/|r'|, and phi(z) the submerged fraction of the cross-section: 1 in the water
// (z <= 0; the waterline is z = 0, waves move the water, not the surface), ramping linearly to 0 over
// the diameter above it (0 < z < d), so weight and drag are continuous across the surface. Drag and
// the fluid's inertia take phi at the load points; the buoyancy of an element that reaches the ramp
// is integrated exactly (docs/model.md, "Lines in air and water").
#pragma once

#include "terms/current_grid.h"
#include "terms/hermite_element.h"
#include "terms/waves.h"

namespace uc {

struct FluidProps {
    double rho;           // water density [kg/m3]
    double gravity;       // [m/s2]
    double massPerLength; // [kg/m]
    double area;          // pi d^2 / 4 [m2]
    double diameter;      // [m]
    double Cdn, Cdt, Can, Cat;
    bool addedMass;
};

// Number of rows of the depth profile of the current (parameters currentProfile.*[1..10]).
constexpr int kCurrentProfileRows = 10;

// Current velocity as a function of depth: a uniform part (the current.* inputs) plus a profile
// interpolated linearly in depth between the rows (depths increasing, constant beyond the ends).
struct CurrentProfile {
    int rows = 0;
    double depth[kCurrentProfileRows] = {};  // [m], positive down
    double ux[kCurrentProfileRows] = {};
    double uy[kCurrentProfileRows] = {};
};

struct CurrentField {
    Vec3 uniform = Vec3::Zero();
    const CurrentProfile* profile = nullptr;
    double profileScale = 1.0;  // load continuation of the static solver
    Vec3 rate = Vec3::Zero();  // d(uniform)/dt over the step from rateStart (input derivatives of current.*)
    double rateStart = 0.0;
    double scale = 1.0;      // factor on the profile at rateStart (input currentScale)
    double scaleRate = 0.0;  // its rate over the step (input derivative of currentScale)
    const SeaState* sea = nullptr;  // waves (calm when null or without components)
    // A current given as data (currents.mode 2 or 5), added to the rest, times profileScale (the static
    // solver's continuation) but not currentScale; null: none.
    const CurrentGrid* grid = nullptr;
    double time = 0.0;              // of the wave kinematics and of the grid
    // The water pushed by the importer (water.source 1, docs/waves.md): 6 values per load point of the line
    // (velocity, local acceleration), given at pushedTime at the load points' positions then. The line's load
    // points take it in place of everything else here (add_hydro_force's `pushed`); point bodies do not.
    // Null: none.
    const double* pushed = nullptr;
    double pushedTime = 0.0;
    // One load point's pushed water from its 6 values: the velocity carried on by the acceleration over the
    // step, u + a (time - pushedTime), the acceleration held; times profileScale (the statics' continuation).
    void pushed_flow(const double* values, Vec3& U, Vec3& A) const {
        A = profileScale * Eigen::Map<const Vec3>(values + 3);
        U = profileScale * Eigen::Map<const Vec3>(values) + (time - pushedTime) * A;
    }
    // Where the points asked for lay against the grid since the owner last cleared it (CurrentGrid's
    // Outside bits): what the line warns of once.
    mutable unsigned gridOutside = 0;
    // Velocity of the current at height z; slope = dU/dz and acceleration = dU/dt (the changing
    // uniform current's and profile's) when non-null. Without the grid (velocity() adds it).
    Vec3 at(double z, Vec3* slope, Vec3* acceleration = nullptr) const;
    // The current's velocity at r (at() and the grid's), without the waves.
    Vec3 velocity(const Vec3& r) const;
    bool waves() const { return sea != nullptr && !sea->calm(); }
    // The water accelerates: waves, a uniform current or a scaled profile changing over the step, a grid.
    bool accelerates() const {
        return waves() || !rate.isZero(0.0) || (scaleRate != 0.0 && profile != nullptr && profile->rows > 0) ||
               grid != nullptr;
    }
    // The water's velocity U (current and waves) and local acceleration A (waves, and the rate of a
    // changing current) at r, with their gradients dU/dr and dA/dr (dA is zero in calm water).
    void flow(const Vec3& r, Vec3& U, Mat3& dU, Vec3& A, Mat3& dA, WaveExpansion* cache = nullptr) const;
    // The same without the gradients (the residual needs none). With a cache, the waves' part of
    // either from its Taylor expansion (SeaState::expanded_kinematics).
    void flow(const Vec3& r, Vec3& U, Vec3& A, WaveExpansion* cache = nullptr) const;
};

// Derivatives of the per-length load F with respect to r, r', r_dot, r_ddot.
struct PointLoadJacobian {
    Mat3 dr, drp, drd, drdd;
};

// Regularisation of |w| in the quadratic drag (m/s): keeps the Jacobian smooth at zero relative flow.
constexpr double kDragVelocityFloor = 1e-6;

double submerged_fraction(double z, double diameter);

// Weight less buoyancy per unit length of a fully submerged line [N/m] (negative: it floats).
inline double submerged_weight(const FluidProps& f) { return (f.massPerLength - f.rho * f.area) * f.gravity; }
// Weight per unit length in air [N/m].
inline double dry_weight(const FluidProps& f) { return f.massPerLength * f.gravity; }

// Per-length load F at one point in water moving with velocity U (gradient dU = dU/dr) and, when
// `waves` (the water accelerates), accelerating with A (gradient dA): Morison drag on the relative
// velocity and the fluid inertia rho A ((1 + Can) A_n + (1 + Cat) A_t) (Froude-Krylov plus added
// mass). Fills J when non-null. buoyancy false: without the buoyancy phi rho A g (an element that
// reaches the waterline integrates it exactly instead).
Vec3 point_load(const FluidProps& p, const Vec3& r, const Vec3& rp, const Vec3& rd, const Vec3& rdd, const Vec3& U,
                const Mat3& dU, bool waves, const Vec3& A, const Mat3& dA, PointLoadJacobian* J,
                bool buoyancy = true);

// Element integrals: R_a += int N_a F ds; K, C, M get dR/dX, dR/dXdot, dR/dXddot. waveCache (null, or
// one slot per load point) holds the waves' expansions of the element's load points. An element whose
// Bezier hull is entirely below z = 0 or above z = d takes its load points alone (phi is 1 or 0 on
// it); one that reaches the ramp has its buoyancy integrated exactly, piecewise between the crossings
// of z = 0 and z = d, with its exact Jacobian.
// pushed (null, or 6 values per load point of the element: CurrentField::pushed) replaces the current's water
// at the load points; its gradient is zero (the values go with the load point over the step).
void add_hydro_force(const ElementTables& e, const FluidProps& p, const CurrentField& current, const double* X,
                     const double* Xd, const double* Xdd, double* R, WaveExpansion* waveCache = nullptr,
                     const double* pushed = nullptr);
void add_hydro_jacobian(const ElementTables& e, const FluidProps& p, const CurrentField& current,
                        const double* X, const double* Xd, const double* Xdd, Mat12& K, Mat12& C,
                        Mat12& M, WaveExpansion* waveCache = nullptr, const double* pushed = nullptr);

}  // namespace uc
