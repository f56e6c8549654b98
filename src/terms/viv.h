// viv.h - vortex-induced vibration: the cross-flow lift of MoorDyn's VIV model and the synchronisation
// model of its phase (docs/model.md, "Vortex-induced vibration").
//
// Each element of a line whose lift coefficient Cl is positive carries one phase phi of its vortex
// shedding. At the element's load points the lift per unstretched length is
//   f_L = phi_sub 0.5 rho d Cl cos(phi) |u_n| (t x u_n),
// u_n the flow relative to the line across it (as the drag's), t the tangent, phi_sub the submerged
// fraction; it enters the residual as -f_L. The phase turns at
//   phi' = 2 pi |u_n| / d (f0 + df sin(phi_y - phi)),
// where phi_y is the phase of the cross-flow motion at the element's midpoint, from its cross-flow velocity
// y' and acceleration y'' along c = t x u_n / |u_n|: cos phi_y = y' / m, sin phi_y = -y'' / (phi' m), with
// m = sqrt(y'^2 + (y'' / phi')^2 + eps^2): for a motion at the shedding's frequency phi', the phase of its
// velocity (MoorDyn divides y' and y'' by their running RMS values instead, whose ratio is the motion's frequency).
#pragma once

#include "terms/hydrodynamics.h"

namespace uc {

struct VivProps {
    double Cl = 0.0;         // lift coefficient (0: off)
    double frequency = 0.18; // f0, the centre of the non-dimensional shedding frequencies (MoorDyn's cF)
    double range = 0.08;     // df, their half width (MoorDyn's dF)
    bool on() const { return Cl > 0.0; }
};

// eps above [m/s]: a cross-flow motion far below it leaves the phase turning at the shedding frequency
// f0 |u_n| / d, so that the phase's equation stays smooth where the line is at rest.
constexpr double kVivMotionFloor = 1e-4;

// R_a -= int N_a f_L ds over the element's load points.
void add_viv_force(const ElementTables& e, const FluidProps& p, const VivProps& v, const CurrentField& current,
                   const double* X, const double* Xd, double phase, double* R, WaveExpansion* waveCache = nullptr);
// Its derivatives: K += dR/dX, C += dR/dXdot, dPhase[a] += dR_a/dphi (12 values).
void add_viv_jacobian(const ElementTables& e, const FluidProps& p, const VivProps& v, const CurrentField& current,
                      const double* X, const double* Xd, double phase, Mat12& K, Mat12& C, double* dPhase,
                      WaveExpansion* waveCache = nullptr);

// The rate the synchronisation model gives the element's phase (phi' above), at its midpoint, with the phase
// turning at phaseRate (which sets the motion's phase).
double viv_phase_rate(const ElementTables& e, const FluidProps& p, const VivProps& v, const CurrentField& current,
                      const double* X, const double* Xd, const double* Xdd, double phase, double phaseRate);
// The phase's equation R = phaseRate - viv_phase_rate(...) and its derivatives.
struct VivPhaseJacobian {
    double dX[12], dXd[12], dXdd[12], dPhase, dPhaseRate;
};
double viv_phase_residual(const ElementTables& e, const FluidProps& p, const VivProps& v, const CurrentField& current,
                          const double* X, const double* Xd, const double* Xdd, double phase, double phaseRate,
                          VivPhaseJacobian* J = nullptr);

}  // namespace uc
