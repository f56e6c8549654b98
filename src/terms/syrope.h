// syrope.h - the Syrope model of a polyester rope (MoorDyn's ELASTIC_SYROPE; docs/model.md, "Syrope fibre-rope
// model"): the rope's mean tension follows its original working curve (OWC, a tension-strain table) the first
// time it is loaded, and a working curve below the largest mean tension reached so far (Tmax) on unloading
// and reloading; a slow strain z relaxes towards the curve through a dashpot, a dynamic spring alpha + beta T
// carries the fast motion.
//
// With eps_d(T) = ln(1 + beta T / alpha) / beta the dynamic spring's strain at the tension T, the slow strain
// on a curve eps_c(T) is z_c(T) = eps_c(T) - eps_d(T); the element's mean tension is T(z), the inverse of z_c,
// on the working curve of Tmax where z <= z_owc(Tmax), on the OWC above (Tmax then grows with it, after each
// step). The slow strain moves as
//   (c + c_d) z' = (alpha + beta T) (e - eps_c(T)) + c_d e',   e the element's mean strain,
// and the element carries T + c z' (c the line's axial damping, c_d the dynamic one).
#pragma once

#include <string>

#include "terms/axial_curve.h"

namespace uc {

// The working curve's formula in u = T / Tmax and xi = (eps - eps_min) / (eps_max - eps_min), eps_max the OWC's
// strain at Tmax, eps_min = eps_0 + k1 (eps_max - eps_0), eps_0 the OWC table's first strain (MoorDyn's first point
// read) (LINEAR with k1 >= 1: eps_max - Tmax / k1, k1 a stiffness):
// LINEAR u = xi, QUADRATIC u = xi (k2 xi + 1 - k2), EXP u = (1 - exp(k2 xi)) / (1 - exp(k2)).
enum SyropeForm { kSyropeNone = 0, kSyropeLinear = 1, kSyropeQuadratic = 2, kSyropeExp = 3 };

struct SyropeProps {
    int form = kSyropeNone;
    double k1 = 0.0, k2 = 0.0;
    double alpha = 0.0, beta = 0.0;  // the dynamic stiffness alpha + beta T [N], MoorDyn's EA_Dc and EA_D_Lm
    double tensionMax0 = 0.0, tensionMean0 = 0.0;  // the SYROPE IC: Tmax and the mean tension at the start [N]
    AxialCurve owc;                  // the original working curve
    double strain0 = 0.0;            // eps_0: its first point's strain as given (before (0, 0) is put in front)
};

// The form's name (LINEAR, QUADRATIC, EXP) and back (case-insensitive; kSyropeNone when unknown).
const char* syrope_form_name(int form);
int syrope_form(const std::string& name);

// Empty when the model's numbers make a rope (MoorDyn's checks: LINEAR k1 >= 0, QUADRATIC 0 <= k1 < 1 and
// 0 < k2 <= 1, EXP 0 <= k1 < 1 and k2 > 0; alpha > 0, beta >= 0, 0 <= Tmean0 <= Tmax0 <= the OWC's last
// tension, the slow strain rising along the OWC and along the working curve of Tmax0); else what is wrong,
// naming the field and its value. `where` prefixes the field names (e.g. "syrope." or ""). tensionMax0 < 0: the
// start's tensions are not known yet (not checked).
std::string syrope_check(const SyropeProps& s, const std::string& where);

// The dynamic spring's strain at the tension T, and its slope 1 / (alpha + beta T).
double syrope_dynamic_strain(const SyropeProps& s, double T);

// An element's history is the OWC's strain at Tmax, eps_max (Tmax = owc(eps_max)): the working curve's top.
// The strain of the start's Tmax0.
double syrope_initial_history(const SyropeProps& s);

// The total strain on the working curve whose top is eps_max at the tension T (0 <= T <= Tmax), and its slope
// d eps / dT (infinite at T = 0 for QUADRATIC with k2 = 1).
double syrope_working_strain(const SyropeProps& s, double strainMax, double T, double* dEps = nullptr);

// The element's mean tension at the slow strain z, with the history eps_max. Below the working curve's
// zero-tension strain the tension goes on with its slope there (0 where that is 0).
struct SyropeTension {
    double tension;      // T(z) [N]
    double slope;        // dT / dz [N]
    double curveStrain;  // eps_c(T), the total strain of the curve at T
    bool original;       // on the OWC (z above that of Tmax): Tmax follows T after the step
};
SyropeTension syrope_tension(const SyropeProps& s, double strainMax, double z);

// The slow strain at the mean tension T (>= 0) on the working curve of eps_max (T <= Tmax) or on the OWC above.
double syrope_slow_strain(const SyropeProps& s, double strainMax, double T);

// The history after a step that ended at the slow strain z: eps_max grows where z passed the working curve's
// top onto the OWC.
double syrope_history_after(const SyropeProps& s, double strainMax, double z);

}  // namespace uc
