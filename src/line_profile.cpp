// line_profile.cpp - the multi-segment elastic catenary with point loads and seabed (line_profile.h).
//
// In the vertical plane of the two ends, u is the unstretched arc length from the lower end, x the
// horizontal distance from it towards the top and z the height above it. The line's tension at u is
// (H, V(u)): H is the same everywhere (no horizontal load), V grows with the submerged weight above
// the lower end, V(u) = v + W(u), and jumps by a point's weight where it hangs. A piece of constant
// weight w per length stretches by T / EA (Irvine's elastic catenary):
//   dx/du = H / T + H / EA,  dz/du = V / T + V / EA,  T = sqrt(H^2 + V^2).
// On a frictionless seabed the line rests (V = 0, straight) from the lower end for as long as the
// tension it would have if it hung, v + W(u), points down: the touchdown is where that first
// reaches 0, inside a piece or at a point load (a clump on which the line lifts off).
// H and v are found by Newton's method on the two end conditions.
#include "line_profile.h"

#include <algorithm>
#include <cmath>

namespace uc {
namespace {

// asinh(b) - asinh(a) without cancellation.
double asinh_difference(double a, double b) {
    return std::asinh(b * std::sqrt(1.0 + a * a) - a * std::sqrt(1.0 + b * b));
}

}  // namespace

void LineProfile::piece_offset(const Piece& p, double H, double l, double& dx, double& dz) {
    if (p.grounded) {
        dx = l * (1.0 + H / p.EA);
        dz = 0.0;
        return;
    }
    const double Va = p.V0, Vb = p.V0 + p.weight * l;
    const double Ta = std::hypot(H, Va), Tb = std::hypot(H, Vb);
    dz = (Va + Vb) * l / (Ta + Tb) + 0.5 * (Va + Vb) * l / p.EA;
    if (std::abs(p.weight * l) <= 1e-6 * std::max(Ta, Tb))
        dx = H * l / std::hypot(H, 0.5 * (Va + Vb));  // straight to O((w l / T)^2)
    else
        dx = H * asinh_difference(Va / H, Vb / H) / p.weight;
    dx += H * l / p.EA;
}

void LineProfile::walk(double H, double v, std::vector<Piece>& pieces, double& x, double& z) const {
    pieces.clear();
    x = z = 0.0;
    const double snap = 1e-12 * length_;
    double u = 0.0;
    double hanging = v;  // v + W(u): the vertical tension if the line hung from here
    bool grounded = seabed_ && v < 0.0;
    size_t ip = 0;
    auto apply_points = [&](double upTo) {
        while (ip < points_.size() && points_[ip].s <= upTo + snap) {
            hanging += points_[ip].weight;
            ++ip;
        }
        if (grounded && hanging >= 0.0) grounded = false;
    };
    for (const Segment& seg : segments_) {
        const double end = u + seg.length;
        while (u < end - snap) {
            apply_points(u);
            double next = ip < points_.size() ? std::min(end, points_[ip].s) : end;
            if (next <= u + snap) next = end;
            double l = next - u;
            bool lifts = false;
            if (grounded && seg.weight > 0.0 && hanging + seg.weight * l > 0.0) {
                l = -hanging / seg.weight;  // the touchdown inside this piece
                lifts = true;
            }
            Piece p{u, l, seg.weight, seg.EA, grounded ? 0.0 : hanging, x, z, grounded};
            double dx, dz;
            piece_offset(p, H, l, dx, dz);
            pieces.push_back(p);
            x += dx;
            z += dz;
            u += l;
            hanging = lifts ? 0.0 : hanging + seg.weight * l;
            if (lifts) grounded = false;
        }
        u = end;
    }
}

bool LineProfile::solve(const Eigen::Vector3d& top, const Eigen::Vector3d& bottom, const std::vector<Segment>& segments,
                        const std::vector<PointLoad>& points, bool seabed, double seabedZ, double onSeabed,
                        std::string* why) {
    auto fail = [&](const char* reason) {
        if (why) *why = reason;
        return false;
    };
    const Eigen::Vector3d d = top - bottom;
    const double X = std::hypot(d.x(), d.y()), Z = d.z();
    length_ = 0.0;
    double weight = 0.0, EA = INFINITY;
    for (const Segment& s : segments) {
        if (!(s.length > 0.0) || !(s.EA > 0.0)) return fail("a segment without length or stiffness");
        length_ += s.length;
        weight += s.weight * s.length;
        EA = std::min(EA, s.EA);
    }
    if (!(X > 1e-9 * length_)) return fail("both ends on one vertical");
    segments_.assign(segments.rbegin(), segments.rend());
    points_.clear();
    for (const PointLoad& p : points) {
        if (p.s > 0.0 && p.s < length_) points_.push_back({length_ - p.s, p.weight});
        if (p.s > 0.0 && p.s < length_) weight += p.weight;
    }
    std::sort(points_.begin(), points_.end(), [](const PointLoad& a, const PointLoad& b) { return a.s < b.s; });
    bottom_ = bottom;
    u_ = Eigen::Vector3d(d.x() / X, d.y() / X, 0.0);
    seabed_ = seabed && bottom.z() - seabedZ <= onSeabed;
    seabedHeight_ = seabedZ - bottom.z();
    if (seabed_ && Z > 0.0 && length_ >= X + Z && weight > 0.0) {
        // Even inextensible it reaches down and across with length to spare: resting on a
        // frictionless seabed it has no tension and no one shape.
        return fail("longer than the way down and across");
    }

    // Starting values of H and v: a catenary of the mean weight, or a taut straight line.
    const double w = weight / length_;
    const double chord = d.norm();
    double H0, v0;
    const double strain = std::max(chord / length_ - 1.0, 1e-4);
    H0 = EA * strain * X / chord;
    v0 = EA * strain * Z / chord - 0.5 * weight;
    if (length_ > chord * (1.0 + 1e-6) && w > 0.0) {
        // inextensible: 2 a sinh(X / 2a) = sqrt(L^2 - Z^2) for the line hanging free
        const double ratio = std::sqrt(length_ * length_ - Z * Z) / X;
        double lo = 0.0, hi = 1.0;
        while (std::sinh(hi) / hi < ratio && hi < 700.0) hi *= 2.0;
        for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
            const double mid = 0.5 * (lo + hi);
            (std::sinh(mid) / mid < ratio ? lo : hi) = mid;
        }
        const double a = X / (lo + hi);
        const double vertex = 0.5 * X - a * std::atanh(std::clamp(Z / length_, -1.0 + 1e-15, 1.0 - 1e-15));
        H0 = a * w;
        v0 = -w * a * std::sinh(vertex / a);
    }
    // Newton's method on (log H, v) with a backtracking line search; several starts for H.
    const double scale = std::max(std::abs(weight), 1e-6 * EA);
    std::vector<Piece> pieces;
    auto residual = [&](double logH, double v, double& fx, double& fz) {
        double x, z;
        walk(std::exp(logH), v, pieces, x, z);
        fx = x - X;
        fz = z - Z;
        return std::isfinite(fx) && std::isfinite(fz) ? std::hypot(fx, fz) : INFINITY;
    };
    const double tolerance = 1e-11 * length_;
    for (double factor : {1.0, 0.1, 10.0, 0.01, 100.0, 1e-3, 1e3}) {
        double logH = std::log(std::max(H0 * factor, 1e-9 * scale)), v = v0;
        double fx, fz;
        double norm = residual(logH, v, fx, fz);
        for (int it = 0; it < 100 && std::isfinite(norm) && norm > tolerance; ++it) {
            const double hH = 1e-7, hv = 1e-7 * std::max({std::abs(v), scale, std::exp(logH)});
            double ax, az, bx, bz;
            residual(logH + hH, v, ax, az);
            residual(logH, v + hv, bx, bz);
            const double J00 = (ax - fx) / hH, J10 = (az - fz) / hH, J01 = (bx - fx) / hv, J11 = (bz - fz) / hv;
            const double det = J00 * J11 - J01 * J10;
            if (!(std::abs(det) > 0.0) || !std::isfinite(det)) break;
            double dlogH = -(J11 * fx - J01 * fz) / det, dv = -(-J10 * fx + J00 * fz) / det;
            // at most a factor e^2 in H per step
            const double limit = std::abs(dlogH) > 2.0 ? 2.0 / std::abs(dlogH) : 1.0;
            dlogH *= limit;
            dv *= limit;
            double step = 1.0, trial = INFINITY, tx = 0.0, tz = 0.0;
            for (int k = 0; k < 30; ++k, step *= 0.5) {
                trial = residual(logH + step * dlogH, v + step * dv, tx, tz);
                if (trial < norm) break;
            }
            if (!(trial < norm)) break;
            logH += step * dlogH;
            v += step * dv;
            norm = trial;
            fx = tx;
            fz = tz;
        }
        if (norm <= tolerance) {
            H_ = std::exp(logH);
            v_ = v;
            walk(H_, v_, pieces_, fx, fz);
            grounded_ = 0.0;
            for (const Piece& p : pieces_)
                if (p.grounded) grounded_ += p.length;
            clearance_ = INFINITY;
            for (const Piece& p : pieces_) {
                if (p.grounded) continue;
                double zmin = p.z0, dx, dz;
                piece_offset(p, H_, p.length, dx, dz);
                zmin = std::min(zmin, p.z0 + dz);
                const double vertex = p.weight != 0.0 ? -p.V0 / p.weight : -1.0;
                if (vertex > 0.0 && vertex < p.length) {
                    piece_offset(p, H_, vertex, dx, dz);
                    zmin = std::min(zmin, p.z0 + dz);
                }
                clearance_ = std::min(clearance_, zmin - seabedHeight_);
            }
            return true;
        }
    }
    return fail("no elastic catenary found for these ends (Newton's method did not converge)");
}

const LineProfile::Piece& LineProfile::piece_at(double u) const {
    for (size_t k = 0; k + 1 < pieces_.size(); ++k)
        if (u < pieces_[k].u0 + pieces_[k].length) return pieces_[k];
    return pieces_.back();
}

void LineProfile::at(double s, Eigen::Vector3d& r, Eigen::Vector3d& tangent) const {
    const double u = std::clamp(length_ - s, 0.0, length_);
    const Piece& p = piece_at(u);
    const double l = std::clamp(u - p.u0, 0.0, p.length);
    double dx, dz;
    piece_offset(p, H_, l, dx, dz);
    r = bottom_ + (p.x0 + dx) * u_ + Eigen::Vector3d(0.0, 0.0, p.z0 + dz);
    const double V = p.grounded ? 0.0 : p.V0 + p.weight * l;
    tangent = -(H_ * u_ + Eigen::Vector3d(0.0, 0.0, V)).normalized();
}

double LineProfile::tension(double s) const {
    const double u = std::clamp(length_ - s, 0.0, length_);
    const Piece& p = piece_at(u);
    const double l = std::clamp(u - p.u0, 0.0, p.length);
    return std::hypot(H_, p.grounded ? 0.0 : p.V0 + p.weight * l);
}

Eigen::Vector3d LineProfile::top_force() const {
    const Piece& p = pieces_.back();
    const double V = p.grounded ? 0.0 : p.V0 + p.weight * p.length;
    return -(H_ * u_ + Eigen::Vector3d(0.0, 0.0, V));
}

Eigen::Vector3d LineProfile::bottom_force() const {
    const Piece& p = pieces_.front();
    return H_ * u_ + Eigen::Vector3d(0.0, 0.0, p.grounded ? 0.0 : p.V0);
}

double LineProfile::turning(double s) const {
    // The tangent's angle above the horizontal is atan(V / H): it turns monotonically inside a
    // piece; summed over the pieces from the top end down to u (not the corners at point loads,
    // which sit on nodes of a mesh).
    const double u = std::clamp(length_ - s, 0.0, length_);
    double total = 0.0;
    for (auto p = pieces_.rbegin(); p != pieces_.rend(); ++p) {
        if (p->grounded) break;
        const double top = std::atan2(p->V0 + p->weight * p->length, H_);
        const double l = std::clamp(u - p->u0, 0.0, p->length);
        total += std::abs(top - std::atan2(p->V0 + p->weight * l, H_));
        if (u >= p->u0) break;
    }
    return total;
}

}  // namespace uc
