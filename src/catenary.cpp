// catenary.cpp - the inextensible catenary with touchdown (catenary.h).
//
// Coordinates in the vertical plane of the two ends: xi horizontal from the bottom end towards the
// top, z up from the bottom end. Measured from its vertex, a catenary of parameter a = H / w has
// arc length sigma = a sinh(xi / a) and height a (cosh(xi / a) - 1) = sqrt(a^2 + sigma^2) - a, and
// its slope is sigma / a.
#include "catenary.h"

#include <cmath>

namespace uc {

namespace {

// Bisection for the root of an increasing f on [lo, hi] with f(lo) <= 0 <= f(hi), to round-off.
template <class F>
double bisect(F f, double lo, double hi) {
    for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) < 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

bool Catenary::solve(const Eigen::Vector3d& top, const Eigen::Vector3d& bottom, double length, bool seabed,
                     double seabedZ, double onSeabed) {
    const Eigen::Vector3d d = top - bottom;
    const double X = std::hypot(d.x(), d.y());
    if (!(length > d.norm() * (1.0 + 1e-9)) || !(X > 1e-9 * length)) return false;
    bottom_ = bottom;
    u_ = Eigen::Vector3d(d.x() / X, d.y() / X, 0.0);
    length_ = length;
    laid_ = 0.0;
    const double L = length;
    if (seabed && bottom.z() - seabedZ <= onSeabed) {
        // Touchdown: the line leaves the seabed horizontally where it starts to hang, a suspended
        // length s = sqrt(h^2 + 2 h a) rising h to the top, the rest lying straight on the seabed.
        const double h = top.z() - seabedZ;
        if (h > 0.0 && L > h) {
            const double aMax = (L * L - h * h) / (2.0 * h);  // the whole line hangs
            auto span = [&](double a) {  // horizontal distance covered, less the one to cover
                const double s = std::sqrt(h * h + 2.0 * h * a);
                return (L - s) + a * std::asinh(s / a) - X;
            };
            if (L - h - X >= 0.0) return false;  // longer than the way down and across: no taut shape
            if (span(aMax) >= 0.0) {
                a_ = bisect(span, 0.0, aMax);
                laid_ = L - std::sqrt(h * h + 2.0 * h * a_);
                bottom_.z() = seabedZ;
                vertex_ = laid_;
                return true;
            }
        }
    }
    // Hanging free between the ends: 2 a sinh(X / 2a) = sqrt(L^2 - h^2), i.e. sinh(b) / b = ratio
    // with b = X / 2a, and the vertex where tanh((X - 2 xi0) / 2a) = h / L.
    const double h = d.z();
    const double ratio = std::sqrt(L * L - h * h) / X;
    double hi = 1.0;
    while (std::sinh(hi) / hi < ratio && hi < 700.0) hi *= 2.0;
    const double b = bisect([&](double v) { return std::sinh(v) / v - ratio; }, 0.0, hi);
    a_ = X / (2.0 * b);
    vertex_ = 0.5 * X - a_ * std::atanh(h / L);
    return true;
}

void Catenary::at(double s, Eigen::Vector3d& r, Eigen::Vector3d& tangent) const {
    const double S = length_ - s;  // from the bottom end
    if (laid_ > 0.0 && S <= laid_) {
        r = bottom_ + S * u_;
        tangent = -u_;
        return;
    }
    // arc length from the vertex: at the bottom end sigma0 (negative where the vertex lies beyond
    // it), or 0 at the touchdown
    const double sigma0 = laid_ > 0.0 ? 0.0 : -a_ * std::sinh(vertex_ / a_);
    const double sigma = sigma0 + (S - laid_);
    const double root = std::sqrt(a_ * a_ + sigma * sigma);
    const double xi = vertex_ + a_ * std::asinh(sigma / a_);
    r = bottom_ + xi * u_ + Eigen::Vector3d(0.0, 0.0, root - std::sqrt(a_ * a_ + sigma0 * sigma0));
    tangent = -(a_ * u_ + Eigen::Vector3d(0.0, 0.0, sigma)) / root;
}

}  // namespace uc
