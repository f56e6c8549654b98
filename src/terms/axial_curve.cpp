// axial_curve.cpp - the monotone cubic tension-strain curve (axial_curve.h).
#include "terms/axial_curve.h"

#include <cmath>
#include <cstdio>

namespace uc {
namespace {

std::string point_text(int k, double strain, double tension) {
    char text[120];
    std::snprintf(text, sizeof text, "point %d (strain %.6g, tension %.6g N)", k, strain, tension);
    return text;
}

}  // namespace

bool AxialCurve::build(const double* eps, const double* T, int n, AxialCurve& c, std::string& error) {
    c = AxialCurve{};
    if (n < 2 || n > kMaxPoints - 1) {
        error = "a tension-strain curve has 2 to " + std::to_string(kMaxPoints - 1) + " points, not " + std::to_string(n);
        return false;
    }
    for (int k = 0; k < n; ++k) {
        if (!std::isfinite(eps[k]) || !std::isfinite(T[k]) || eps[k] < 0.0 || T[k] < 0.0) {
            error = point_text(k + 1, eps[k], T[k]) + ": strain and tension of a curve are finite and not negative";
            return false;
        }
        if (k > 0 && !(eps[k] > eps[k - 1])) {
            error = point_text(k + 1, eps[k], T[k]) + ": the strains increase from point to point (point " +
                    std::to_string(k) + " has strain " + std::to_string(eps[k - 1]) + ")";
            return false;
        }
        if (k > 0 && T[k] < T[k - 1]) {
            error = point_text(k + 1, eps[k], T[k]) + ": the tension falls from point " + std::to_string(k) +
                    " (a rope whose tension falls as it stretches has no unique equilibrium)";
            return false;
        }
    }
    if (eps[0] == 0.0 && T[0] != 0.0) {
        error = point_text(1, eps[0], T[0]) + ": a line carries no tension at zero strain";
        return false;
    }
    if (!(T[n - 1] > 0.0)) {
        error = point_text(n, eps[n - 1], T[n - 1]) + ": the curve carries no tension at all";
        return false;
    }
    if (eps[0] > 0.0) ++c.n;  // (0, 0) in front
    for (int k = 0; k < n; ++k) {
        c.strain[c.n] = eps[k];
        c.tension[c.n] = T[k];
        ++c.n;
    }
    // Fritsch-Carlson: the mean of the neighbouring secants inside (0 where the curve is flat on
    // either side), the end secants at the ends, then each interval's pair of slopes scaled into the
    // circle of radius 3 of the secant, which keeps the cubic monotone.
    double secant[kMaxPoints];
    for (int k = 0; k + 1 < c.n; ++k) secant[k] = (c.tension[k + 1] - c.tension[k]) / (c.strain[k + 1] - c.strain[k]);
    c.slope[0] = secant[0];
    c.slope[c.n - 1] = secant[c.n - 2];
    for (int k = 1; k + 1 < c.n; ++k)
        c.slope[k] = secant[k - 1] > 0.0 && secant[k] > 0.0 ? 0.5 * (secant[k - 1] + secant[k]) : 0.0;
    for (int k = 0; k + 1 < c.n; ++k) {
        if (secant[k] == 0.0) {
            c.slope[k] = c.slope[k + 1] = 0.0;
            continue;
        }
        const double a = c.slope[k] / secant[k], b = c.slope[k + 1] / secant[k], r2 = a * a + b * b;
        if (r2 > 9.0) {
            const double tau = 3.0 / std::sqrt(r2);
            c.slope[k] = tau * a * secant[k];
            c.slope[k + 1] = tau * b * secant[k];
        }
    }
    return true;
}

double AxialCurve::operator()(double eps, double* dT) const {
    const int last = n - 1;
    if (eps <= strain[0] || eps >= strain[last]) {
        const int k = eps <= strain[0] ? 0 : last;
        if (dT) *dT = slope[k];
        return tension[k] + slope[k] * (eps - strain[k]);
    }
    int lo = 0, hi = last;  // strain[lo] < eps < strain[hi]
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        (strain[mid] <= eps ? lo : hi) = mid;
    }
    const double h = strain[hi] - strain[lo], t = (eps - strain[lo]) / h, t2 = t * t, t3 = t2 * t;
    const double y0 = tension[lo], y1 = tension[hi], m0 = h * slope[lo], m1 = h * slope[hi];
    if (dT) *dT = ((6.0 * t2 - 6.0 * t) * (y0 - y1) + (3.0 * t2 - 4.0 * t + 1.0) * m0 + (3.0 * t2 - 2.0 * t) * m1) / h;
    return (2.0 * t3 - 3.0 * t2 + 1.0) * y0 + (t3 - 2.0 * t2 + t) * m0 + (-2.0 * t3 + 3.0 * t2) * y1 + (t3 - t2) * m1;
}

double AxialCurve::energy(double eps) const {
    // The curve starts at (0, 0) (build): below it the line of slope slope[0], above it the cubic pieces
    // (Simpson's rule is exact on a cubic), beyond the last point the line of its slope.
    if (eps <= 0.0) return 0.5 * slope[0] * eps * eps;
    double W = 0.0;
    for (int k = 0; k + 1 < n; ++k) {
        const double a = strain[k], b = std::fmin(eps, strain[k + 1]);
        W += (b - a) / 6.0 * ((*this)(a) + 4.0 * (*this)(0.5 * (a + b)) + (*this)(b));
        if (eps <= strain[k + 1]) return W;
    }
    const double d = eps - strain[n - 1];
    return W + tension[n - 1] * d + 0.5 * slope[n - 1] * d * d;
}

double AxialCurve::strain_at(double T) const {
    const int last = n - 1;
    if (T <= tension[0]) return slope[0] > 0.0 ? strain[0] + (T - tension[0]) / slope[0] : strain[0];
    if (T >= tension[last]) return slope[last] > 0.0 ? strain[last] + (T - tension[last]) / slope[last] : strain[last];
    double a = strain[0], b = strain[last];  // the tension is monotone: bisection
    for (int it = 0; it < 200 && b - a > 1e-15 * strain[last]; ++it) {
        const double m = 0.5 * (a + b);
        ((*this)(m) < T ? a : b) = m;
    }
    return 0.5 * (a + b);
}

}  // namespace uc
