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
//
// A sloped seabed rises towards the top by tan(beta) per metre across. The line rests from the lower
// end while its tangent would point into the slope, V(u) < H tan(beta), straight along the slope; on
// that frictionless slope its tension is the projection of (H, V(u)) on the slope's direction,
// H cos(beta) + V(u) sin(beta) (at the touchdown H / cos(beta), lower by w sin(beta) per metre
// towards the lower end), and it leaves the slope tangentially, with V = H tan(beta). A resting
// stretch further up (a second touchdown) carries its weight's normal part; its tangential part
// raises the tension along it, so H grows across it by w l sin(beta) cos(beta) (constant in each
// hanging part). With beta = 0 this is the flat seabed's walk, number for number.
#include "model/line_profile.h"

#include <algorithm>
#include <cmath>

namespace uc {
namespace {

// asinh(b) - asinh(a) without cancellation.
double asinh_difference(double a, double b) {
    return std::asinh(b * std::sqrt(1.0 + a * a) - a * std::sqrt(1.0 + b * b));
}

}  // namespace

double LineProfile::grounded_tension(const Piece& p, double l) const {
    return p.H * cosSlope_ + (p.V0 + p.weight * l) * sinSlope_;
}

void LineProfile::piece_offset(const Piece& p, double l, double& dx, double& dz) const {
    const double H = p.H;
    if (p.grounded) {
        if (sinSlope_ == 0.0) {
            dx = l * (1.0 + H / p.EA);
            dz = 0.0;
            return;
        }
        const double stretched = l + l * grounded_tension(p, 0.5 * l) / p.EA;  // the tension is linear in l
        dx = stretched * cosSlope_;
        dz = stretched * sinSlope_;
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

double LineProfile::surface_crossing(const Piece& p, double l, bool inAir) const {
    if (!std::isfinite(surfaceHeight_) || p.grounded) return l;
    // z is monotone on either side of the vertex (V = 0) inside the piece
    double ends[3] = {0.0, l, l};
    int n = 2;
    const double vertex = p.weight != 0.0 ? -p.V0 / p.weight : -1.0;
    if (vertex > 0.0 && vertex < l) {
        ends[1] = vertex;
        n = 3;
    }
    auto below = [&](double u) {  // height below the surface (positive: in water)
        double dx, dz;
        piece_offset(p, u, dx, dz);
        return surfaceHeight_ - (p.z0 + dz);
    };
    for (int k = 0; k + 1 < n; ++k) {
        double a = ends[k], b = ends[k + 1];
        const double fa = below(a), fb = below(b);
        // from the water up into the air (below goes from >= 0 to < 0), or down from the air; an
        // end on the surface (a tow point at z = 0) that round-off puts a hair across stays
        const double hair = 1e-9 * length_;
        const bool crosses = inAir ? (fa <= 0.0 && fb > hair) : (fa >= 0.0 && fb < -hair);
        if (!crosses) continue;
        for (int it = 0; it < 200 && b - a > 1e-13 * length_; ++it) {
            const double m = 0.5 * (a + b);
            ((below(m) > 0.0) == inAir ? b : a) = m;
        }
        return b;
    }
    return l;
}

void LineProfile::walk(double H, double v, const std::vector<double>& rests, std::vector<Piece>& pieces, double& x,
                       double& z, std::vector<double>* minima) const {
    pieces.clear();
    if (minima) minima->clear();
    x = z = 0.0;
    const double snap = 1e-12 * length_;
    double u = 0.0;
    double hanging = v;  // the vertical tension: v + W(u) from the lower end while it rests there
    double Hc = H;       // the horizontal tension of the hanging part (it grows across a rest on a slope)
    bool grounded = seabed_ && v < H * slope_;
    bool inAir = surfaceHeight_ < 0.0;  // the lower end above the water
    size_t ip = 0;
    int found = 0;         // local minima of the hanging line passed so far
    double restLeft = 0.0;  // of the resting stretch at the last minimum, across sections
    auto push = [&](const Piece& p, double l) {
        double dx, dz;
        piece_offset(p, l, dx, dz);
        pieces.push_back(p);
        pieces.back().length = l;
        x += dx;
        z += dz;
    };
    auto apply_points = [&](double upTo) {
        while (ip < points_.size() && points_[ip].s <= upTo + snap) {
            const double before = hanging;
            const double P = inAir && std::isfinite(points_[ip].dryWeight) ? points_[ip].dryWeight : points_[ip].weight;
            ++ip;
            if (grounded && P < 0.0) {
                // a buoy cannot rest: the line has lifted off by here (the solution lifts before it,
                // where v + W reaches 0). Lifted here, the line keeps the deficit v + W < 0 of the
                // tension it would have if it hung, so that the end conditions keep depending on v:
                // with V = P after the buoy they would not, Newton's method would find no way from
                // here to the solution, and lines with a buoy between two touchdowns went unsolved
                grounded = false;
                hanging += P;
                continue;
            }
            if (restLeft > 0.0 && P < 0.0) restLeft = 0.0;  // a buoy ends a resting stretch
            if (restLeft > 0.0) continue;                   // a clump on it rests
            hanging += P;
            if (!grounded && before < Hc * slope_ && hanging >= Hc * slope_) {
                // the line comes down to this point and rises from it: a local minimum; where it
                // rests on the seabed, the seabed's reaction rests[found] (>= 0, along the slope's
                // normal) takes part of its weight
                if (minima) minima->push_back(z - slope_ * x);
                if (found < static_cast<int>(rests.size())) {
                    const double R = std::max(rests[found], 0.0);
                    hanging -= R * cosSlope_;
                    Hc += R * sinSlope_;
                }
                ++found;
            }
        }
        if (grounded && hanging >= H * slope_) grounded = false;
    };
    for (const Segment& seg : segments_) {
        const double end = u + seg.length;
        while (u < end - snap) {
            apply_points(u);
            double next = ip < points_.size() ? std::min(end, points_[ip].s) : end;
            if (next <= u + snap) next = end;
            double l = next - u;
            if (restLeft > 0.0) {
                l = std::min(l, restLeft);
                push(Piece{u, l, seg.weight, seg.EA, hanging, x, z, true, Hc}, l);
                u += l;
                restLeft -= l;
                if (restLeft <= snap) restLeft = 0.0;
                // the weight's part along the slope raises the tension (flat: nothing changes)
                Hc += seg.weight * l * sinSlope_ * cosSlope_;
                hanging = Hc * slope_;
                continue;
            }
            if (grounded) {
                const double liftoff = H * slope_;  // V where the tangent leaves the slope
                const bool lifts = seg.weight > 0.0 && hanging + seg.weight * l > liftoff;
                if (lifts) l = (liftoff - hanging) / seg.weight;  // the touchdown inside this piece
                push(Piece{u, l, seg.weight, seg.EA, hanging, x, z, true, H}, l);
                u += l;
                hanging = lifts ? liftoff : hanging + seg.weight * l;
                if (lifts) grounded = false;
                continue;
            }
            const double w = inAir && std::isfinite(seg.dryWeight) ? seg.dryWeight : seg.weight;
            const double tangent = Hc * slope_;  // V where the line runs parallel to the seabed
            const bool vertex = hanging < tangent && w > 0.0 && hanging + w * l > tangent;
            const double lv = vertex ? (tangent - hanging) / w : l;
            const Piece piece{u, lv, w, seg.EA, hanging, x, z, false, Hc};
            const double lc = surface_crossing(piece, lv, inAir);
            if (lc < lv) {
                // the line crosses the water surface here: its weight per length changes
                push(piece, lc);
                u += lc;
                hanging += w * lc;
                inAir = !inAir;
                continue;
            }
            if (vertex) {
                // a local minimum inside this piece (above the seabed: where the tangent is parallel
                // to it; the vertex, V = 0, on a flat one); where it rests on the seabed, it lies
                // there for rests[found] (>= 0) of its length
                push(piece, lv);
                u += lv;
                hanging = tangent;
                if (minima) minima->push_back(z - slope_ * x);
                restLeft = found < static_cast<int>(rests.size()) ? std::max(rests[found], 0.0) : 0.0;
                ++found;
                continue;
            }
            push(piece, l);
            u += l;
            hanging += w * l;
        }
        u = end;
    }
}

bool LineProfile::solve(const Eigen::Vector3d& top, const Eigen::Vector3d& bottom, const std::vector<Segment>& segments,
                        const std::vector<PointLoad>& points, bool seabed, double seabedZ, double onSeabed,
                        std::string* why, double surfaceZ) {
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
    const double lineWeight = weight;  // without the point loads: the first guess's catenary
    if (!(X > 1e-9 * length_)) return fail("both ends on one vertical");
    segments_.assign(segments.rbegin(), segments.rend());
    points_.clear();
    for (const PointLoad& p : points) {
        if (p.s > 0.0 && p.s < length_) points_.push_back({length_ - p.s, p.weight, p.dryWeight});
        if (p.s > 0.0 && p.s < length_) weight += p.weight;
    }
    std::sort(points_.begin(), points_.end(), [](const PointLoad& a, const PointLoad& b) { return a.s < b.s; });
    bottom_ = bottom;
    u_ = Eigen::Vector3d(d.x() / X, d.y() / X, 0.0);
    slope_ = seabed ? gradient_.x() * u_.x() + gradient_.y() * u_.y() : 0.0;
    cosSlope_ = 1.0 / std::sqrt(1.0 + slope_ * slope_);
    sinSlope_ = slope_ * cosSlope_;
    seabed_ = seabed && bottom.z() - seabedZ <= onSeabed;
    seabedOn_ = seabed;
    seabedHeight_ = seabedZ - bottom.z();
    surfaceHeight_ = surfaceZ - bottom.z();
    bool sinks = weight > 0.0;  // every part of it (a buoyant part, a lazy wave's, may hold the rest up)
    for (const Segment& s : segments) sinks = sinks && s.weight >= 0.0;
    for (const PointLoad& p : points_) sinks = sinks && p.weight >= 0.0;
    if (seabed_ && slope_ == 0.0 && Z > 0.0 && length_ >= X + Z && sinks) {
        // Even inextensible it reaches down and across with length to spare: resting on a
        // frictionless seabed it has no tension and no one shape.
        return fail("longer than the way down and across");
    }

    // Starting values of H and v: a catenary of the mean weight, or a taut straight line.
    const double w = (lineWeight > 0.0 ? lineWeight : weight) / length_;
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
    // Newton's method on (log H, v, the contacts' rests) with a backtracking line search, several
    // starts for H; the contacts by an active set: a local minimum of the hanging line below the
    // seabed rests on it (one more unknown, its height the seabed's), one whose rest comes out
    // negative does not.
    const double scale = std::max(std::abs(weight), 1e-6 * EA);
    const double level = seabedHeight_;
    std::vector<Piece> pieces;
    std::vector<double> minima;
    auto residual = [&](const Eigen::VectorXd& y, Eigen::VectorXd& f) {
        const std::vector<double> rests(y.data() + 2, y.data() + y.size());
        double x, z;
        walk(std::exp(y[0]), y[1], rests, pieces, x, z, &minima);
        f.resize(y.size());
        f[0] = x - X;
        f[1] = z - Z;
        for (Eigen::Index j = 2; j < y.size(); ++j) {
            const size_t k = static_cast<size_t>(j - 2);
            f[j] = k < minima.size() ? minima[k] - level : y[j] / std::max(scale, 1.0);  // an unused rest goes to 0
        }
        return f.allFinite() ? f.norm() : INFINITY;
    };
    const double tolerance = 1e-11 * length_;
    auto newton = [&](Eigen::VectorXd& y) {
        Eigen::VectorXd f, g, trialY;
        double norm = residual(y, f);
        for (int it = 0; it < 100 && std::isfinite(norm) && norm > tolerance; ++it) {
            const Eigen::Index n = y.size();
            Eigen::MatrixXd J(n, n);
            for (Eigen::Index j = 0; j < n; ++j) {
                const double h = j == 0 ? 1e-7 : 1e-7 * std::max({std::abs(y[j]), scale, j == 1 ? std::exp(y[0]) : length_});
                Eigen::VectorXd yj = y;
                yj[j] += h;
                residual(yj, g);
                J.col(j) = (g - f) / h;
            }
            Eigen::VectorXd dy = J.fullPivLu().solve(-f);
            if (!dy.allFinite()) return norm;
            if (std::abs(dy[0]) > 2.0) dy *= 2.0 / std::abs(dy[0]);  // at most a factor e^2 in H per step
            double step = 1.0, trial = INFINITY;
            for (int k = 0; k < 30; ++k, step *= 0.5) {
                trialY = y + step * dy;
                trial = residual(trialY, g);
                if (trial < norm) break;
            }
            if (!(trial < norm)) return norm;
            y = trialY;
            f = g;
            norm = trial;
        }
        return norm;
    };
    Eigen::VectorXd fallback;  // the first solution without the contacts of the hanging line
    for (double factor : {1.0, 0.1, 10.0, 0.01, 100.0, 1e-3, 1e3}) {
        Eigen::VectorXd y(2);
        y << std::log(std::max(H0 * factor, 1e-9 * scale)), v0;
        double norm = newton(y);
        if (norm <= tolerance && fallback.size() == 0) fallback = y;
        for (int pass = 0; pass < 8; ++pass) {
            // contacts: activate the first minimum below the seabed beyond the active ones (also
            // where Newton's method stalled without it: a line that must rest twice has no
            // solution with one contact), or drop the first active one whose rest came out
            // negative (and all after it)
            const std::vector<double> rests(y.data() + 2, y.data() + y.size());
            double x, z;
            walk(std::exp(y[0]), y[1], rests, pieces, x, z, &minima);
            Eigen::Index drop = -1;
            for (Eigen::Index j = 2; j < y.size(); ++j)
                if (norm <= tolerance && y[j] < -tolerance * std::max(scale, 1.0)) {
                    drop = j;
                    break;
                }
            bool changed = false;
            if (drop >= 0) {
                y.conservativeResize(drop);
                changed = true;
            } else if (seabedOn_) {
                for (size_t k = static_cast<size_t>(y.size() - 2); k < minima.size(); ++k) {
                    if (minima[k] < level - 1e-9 * length_) {
                        y.conservativeResize(static_cast<Eigen::Index>(k) + 3);
                        y.tail(y.size() - 2 - static_cast<Eigen::Index>(rests.size())).setZero();
                        changed = true;
                        break;
                    }
                }
            }
            if (!changed) break;
            norm = newton(y);
        }
        if (norm <= tolerance) {
            settle(std::exp(y[0]), y[1], std::vector<double>(y.data() + 2, y.data() + y.size()), true);
            return true;
        }
    }
    if (fallback.size() == 2) {
        // Where the hanging line's contacts could not be solved, its profile without them (passing
        // below the seabed there): a guess, not exact (lowest_clearance() tells).
        settle(std::exp(fallback[0]), fallback[1], {}, false);
        return true;
    }
    return fail("no elastic catenary found for these ends (Newton's method did not converge)");
}

double LineProfile::touchdown() const {
    for (auto p = pieces_.rbegin(); p != pieces_.rend(); ++p)
        if (p->grounded) return length_ - (p->u0 + p->length);
    return length_;
}

std::vector<double> LineProfile::contacts() const {
    std::vector<double> s;
    for (size_t k = 0; k < pieces_.size(); ++k) {
        const Piece& p = pieces_[k];
        const bool before = k > 0 && pieces_[k - 1].grounded;
        if (k > 0 && p.grounded != before) s.push_back(length_ - p.u0);
        // a point load resting at a local minimum: V jumps from below 0 to the piece's start
        if (k > 0 && !p.grounded && !before) {
            const Piece& q = pieces_[k - 1];
            if (q.V0 + q.weight * q.length < q.H * slope_ && p.V0 >= p.H * slope_ &&
                std::abs(p.z0 - slope_ * p.x0 - seabedHeight_) < 1e-6 * length_)
                s.push_back(length_ - p.u0);
        }
    }
    std::sort(s.begin(), s.end());
    return s;
}

void LineProfile::settle(double H, double v, const std::vector<double>& rests, bool exact) {
    H_ = H;
    double x, z;
    walk(H, v, rests, pieces_, x, z, nullptr);
    grounded_ = 0.0;
    clearance_ = exact ? INFINITY : -INFINITY;
    for (const Piece& p : pieces_) {
        if (p.grounded) {
            grounded_ += p.length;
            continue;
        }
        if (!exact) continue;
        // heights above the seabed's line through the lower end's seabed: z - x tan(beta)
        double dx, dz;
        piece_offset(p, p.length, dx, dz);
        double zmin = std::min(p.z0 - slope_ * p.x0, p.z0 + dz - slope_ * (p.x0 + dx));
        const double vertex = p.weight != 0.0 ? (p.H * slope_ - p.V0) / p.weight : -1.0;
        if (vertex > 0.0 && vertex < p.length) {
            piece_offset(p, vertex, dx, dz);
            zmin = std::min(zmin, p.z0 + dz - slope_ * (p.x0 + dx));
        }
        clearance_ = std::min(clearance_, zmin - seabedHeight_);
    }
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
    piece_offset(p, l, dx, dz);
    r = bottom_ + (p.x0 + dx) * u_ + Eigen::Vector3d(0.0, 0.0, p.z0 + dz);
    if (p.grounded) {
        tangent = -(cosSlope_ * u_ + Eigen::Vector3d(0.0, 0.0, sinSlope_));
        return;
    }
    tangent = -(p.H * u_ + Eigen::Vector3d(0.0, 0.0, p.V0 + p.weight * l)).normalized();
}

double LineProfile::tension(double s) const {
    const double u = std::clamp(length_ - s, 0.0, length_);
    const Piece& p = piece_at(u);
    const double l = std::clamp(u - p.u0, 0.0, p.length);
    return p.grounded ? grounded_tension(p, l) : std::hypot(p.H, p.V0 + p.weight * l);
}

Eigen::Vector3d LineProfile::top_force() const {
    const Piece& p = pieces_.back();
    if (p.grounded) return -grounded_tension(p, p.length) * (cosSlope_ * u_ + Eigen::Vector3d(0.0, 0.0, sinSlope_));
    return -(p.H * u_ + Eigen::Vector3d(0.0, 0.0, p.V0 + p.weight * p.length));
}

Eigen::Vector3d LineProfile::bottom_force() const {
    const Piece& p = pieces_.front();
    if (p.grounded) return grounded_tension(p, 0.0) * (cosSlope_ * u_ + Eigen::Vector3d(0.0, 0.0, sinSlope_));
    return p.H * u_ + Eigen::Vector3d(0.0, 0.0, p.V0);
}

double LineProfile::turning(double s) const {
    // The tangent's angle above the horizontal is atan(V / H): it turns monotonically inside a
    // piece; summed over the pieces from the top end down to u (not the corners at point loads,
    // which sit on nodes of a mesh).
    const double u = std::clamp(length_ - s, 0.0, length_);
    double total = 0.0;
    for (auto p = pieces_.rbegin(); p != pieces_.rend(); ++p) {
        if (p->grounded) {
            if (u >= p->u0) break;
            continue;
        }
        const double top = std::atan2(p->V0 + p->weight * p->length, p->H);
        const double l = std::clamp(u - p->u0, 0.0, p->length);
        total += std::abs(top - std::atan2(p->V0 + p->weight * l, p->H));
        if (u >= p->u0) break;
    }
    return total;
}

}  // namespace uc
