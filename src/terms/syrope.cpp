// syrope.cpp - the Syrope rope model's curves (syrope.h).
#include "terms/syrope.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

namespace uc {
namespace {

std::string number(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

// The working curve's top and foot: eps_max (given), eps_min, and Tmax.
struct WorkingCurve {
    double top, foot, tensionMax;
};

WorkingCurve working_curve(const SyropeProps& s, double strainMax) {
    const double Tmax = s.owc(strainMax);
    const double eps0 = s.strain0;
    const double foot = s.form == kSyropeLinear && s.k1 >= 1.0 ? strainMax - Tmax / s.k1 : eps0 + s.k1 * (strainMax - eps0);
    return {strainMax, foot, Tmax};
}

// xi(u) of the form and dxi/du.
double form_xi(const SyropeProps& s, double u, double* dxi) {
    switch (s.form) {
        case kSyropeQuadratic: {
            // k2 xi^2 + (1 - k2) xi = u
            const double b = 1.0 - s.k2, root = std::sqrt(std::max(0.0, b * b + 4.0 * s.k2 * u));
            const double xi = (root - b) / (2.0 * s.k2);
            *dxi = 1.0 / root;  // 1 / (2 k2 xi + 1 - k2)
            return xi;
        }
        case kSyropeExp: {
            // u = (exp(k2 xi) - 1) / (exp(k2) - 1)
            const double g = std::expm1(s.k2), arg = 1.0 + u * g;
            *dxi = g / (s.k2 * arg);
            return std::log(arg) / s.k2;
        }
        default:
            *dxi = 1.0;
            return u;
    }
}

// Safeguarded Newton on an increasing f over [lo, hi] (hi may be infinite): the root of f.
template <class F>
double increasing_root(F f, double x, double lo, double hi, double scale) {
    for (int it = 0; it < 100; ++it) {
        double df = 0.0;
        const double v = f(x, &df);
        if (v == 0.0) return x;
        (v > 0.0 ? hi : lo) = x;
        double next = x - v / df;
        if (!(df > 0.0) || !std::isfinite(next) || !(next > lo && next < hi))
            next = std::isfinite(hi) ? 0.5 * (lo + hi) : x + std::abs(x) + scale;
        if (std::abs(next - x) <= 1e-15 * (std::abs(x) + scale)) return next;
        x = next;
    }
    return x;
}

}  // namespace

const char* syrope_form_name(int form) {
    switch (form) {
        case kSyropeLinear: return "LINEAR";
        case kSyropeQuadratic: return "QUADRATIC";
        case kSyropeExp: return "EXP";
        default: return "none";
    }
}

int syrope_form(const std::string& name) {
    std::string u = name;
    for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (u == "LINEAR") return kSyropeLinear;
    if (u == "QUADRATIC") return kSyropeQuadratic;
    if (u == "EXP") return kSyropeExp;
    return kSyropeNone;
}

double syrope_dynamic_strain(const SyropeProps& s, double T) {
    return s.beta > 0.0 ? std::log1p(s.beta * T / s.alpha) / s.beta : T / s.alpha;
}

double syrope_initial_history(const SyropeProps& s) { return s.owc.strain_at(s.tensionMax0); }

double syrope_working_strain(const SyropeProps& s, double strainMax, double T, double* dEps) {
    const WorkingCurve w = working_curve(s, strainMax);
    double dxi = 1.0;
    const double xi = form_xi(s, T / w.tensionMax, &dxi);
    if (dEps) *dEps = (w.top - w.foot) * dxi / w.tensionMax;
    return w.foot + (w.top - w.foot) * xi;
}

SyropeTension syrope_tension(const SyropeProps& s, double strainMax, double z) {
    const WorkingCurve w = working_curve(s, strainMax);
    const double zTop = w.top - syrope_dynamic_strain(s, w.tensionMax);
    SyropeTension out{};
    if (z > zTop) {
        // on the OWC: solve eps - eps_d(owc(eps)) = z for the total strain eps
        out.original = true;
        auto f = [&](double eps, double* d) {
            double slope = 0.0;
            const double T = s.owc(eps, &slope);
            *d = 1.0 - slope / (s.alpha + s.beta * T);
            return eps - syrope_dynamic_strain(s, T) - z;
        };
        const double eps = increasing_root(f, w.top + (z - zTop), w.top, std::numeric_limits<double>::infinity(), w.top);
        double slope = 0.0;
        out.tension = s.owc(eps, &slope);
        out.curveStrain = eps;
        out.slope = slope / (1.0 - slope / (s.alpha + s.beta * out.tension));
        return out;
    }
    if (z <= w.foot) {
        // below the working curve's foot (no tension there): its slope at the foot goes on
        double dEps = 0.0;
        syrope_working_strain(s, strainMax, 0.0, &dEps);
        const double dz = dEps - 1.0 / s.alpha;
        out.slope = std::isfinite(dz) && dz > 0.0 ? 1.0 / dz : 0.0;
        out.tension = out.slope * (z - w.foot);
        out.curveStrain = z + syrope_dynamic_strain(s, out.tension);
        return out;
    }
    auto f = [&](double T, double* d) {
        double dEps = 0.0;
        const double eps = syrope_working_strain(s, strainMax, T, &dEps);
        *d = dEps - 1.0 / (s.alpha + s.beta * T);
        return eps - syrope_dynamic_strain(s, T) - z;
    };
    const double guess = w.tensionMax * (z - w.foot) / (zTop - w.foot);
    out.tension = increasing_root(f, guess, 0.0, w.tensionMax, w.tensionMax);
    double dEps = 0.0;
    out.curveStrain = syrope_working_strain(s, strainMax, out.tension, &dEps);
    const double dz = dEps - 1.0 / (s.alpha + s.beta * out.tension);
    out.slope = std::isfinite(dz) && dz > 0.0 ? 1.0 / dz : 0.0;
    return out;
}

double syrope_slow_strain(const SyropeProps& s, double strainMax, double T) {
    const double Tmax = s.owc(strainMax);
    const double eps = T <= Tmax ? syrope_working_strain(s, strainMax, T) : s.owc.strain_at(T);
    return eps - syrope_dynamic_strain(s, T);
}

double syrope_history_after(const SyropeProps& s, double strainMax, double z) {
    const SyropeTension t = syrope_tension(s, strainMax, z);
    return t.original ? std::max(strainMax, t.curveStrain) : strainMax;
}

std::string syrope_check(const SyropeProps& s, const std::string& where) {
    const std::string form = where + "workingCurve " + syrope_form_name(s.form);
    if (s.form < kSyropeLinear || s.form > kSyropeExp)
        return where + "workingCurve = " + std::to_string(s.form) + ": the working curve's formula is 1 LINEAR, 2 QUADRATIC or 3 EXP";
    if (!std::isfinite(s.k1) || !std::isfinite(s.k2)) return form + ": k1 and k2 must be finite numbers";
    if (s.form == kSyropeLinear && s.k1 < 0.0)
        return form + ": " + where + "k1 = " + number(s.k1) + " must be >= 0 (below 1 the zero-tension strain's fraction of the "
               "top's, from 1 on the working curve's stiffness [N])";
    if (s.form == kSyropeQuadratic && (s.k1 < 0.0 || s.k1 >= 1.0 || s.k2 <= 0.0 || s.k2 > 1.0))
        return form + ": " + where + "k1 = " + number(s.k1) + ", " + where + "k2 = " + number(s.k2) +
               ": QUADRATIC needs 0 <= k1 < 1 and 0 < k2 <= 1";
    if (s.form == kSyropeExp && (s.k1 < 0.0 || s.k1 >= 1.0 || s.k2 <= 0.0))
        return form + ": " + where + "k1 = " + number(s.k1) + ", " + where + "k2 = " + number(s.k2) +
               ": EXP needs 0 <= k1 < 1 and k2 > 0";
    if (!(s.alpha > 0.0) || !(s.beta >= 0.0) || !std::isfinite(s.alpha) || !std::isfinite(s.beta))
        return "the dynamic stiffness EA_Dc = " + number(s.alpha) + " N must be above 0 and its slope EA_D_Lm = " +
               number(s.beta) + " not negative";
    if (s.owc.n < 2) return "the original working curve (axialCurve.*) needs at least two points";
    // the slow strain must rise with the tension along the OWC (MoorDyn's check)
    for (int k = 1; k < s.owc.n; ++k) {
        const double T = s.owc.tension[k];
        if (!(s.owc.slope[k] < s.alpha + s.beta * T))
            return "the original working curve at strain " + number(s.owc.strain[k]) + " (" + number(T) +
                   " N) is stiffer (" + number(s.owc.slope[k]) + " N) than the dynamic stiffness EA_Dc + EA_D_Lm T = " +
                   number(s.alpha + s.beta * T) + " N: the slow strain would not rise with the tension";
    }
    if (s.tensionMax0 < 0.0) return {};  // (the start's tensions not known yet)
    const double Tlast = s.owc.tension[s.owc.n - 1];
    if (!(s.tensionMax0 > 0.0) || !(s.tensionMax0 <= Tlast))
        return where + "tensionMax0 = " + number(s.tensionMax0) + " N: Tmax0 lies above 0 and within the original working "
               "curve (its last tension " + number(Tlast) + " N)";
    if (!(s.tensionMean0 >= 0.0) || !(s.tensionMean0 <= s.tensionMax0))
        return where + "tensionMean0 = " + number(s.tensionMean0) + " N: Tmean0 lies between 0 and Tmax0 (" +
               number(s.tensionMax0) + " N)";
    // and along the working curve of Tmax0
    const double top = syrope_initial_history(s);
    for (int k = 1; k <= 20; ++k) {
        const double T = s.tensionMax0 * k / 20.0;
        double dEps = 0.0;
        syrope_working_strain(s, top, T, &dEps);
        if (!(dEps > 1.0 / (s.alpha + s.beta * T)))
            return form + ": the working curve of Tmax0 at " + number(T) + " N is stiffer (" + number(1.0 / dEps) +
                   " N) than the dynamic stiffness " + number(s.alpha + s.beta * T) + " N: the slow strain would not rise "
                   "with the tension (" + where + "k1, " + where + "k2)";
    }
    return {};
}

}  // namespace uc
