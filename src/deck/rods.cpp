// rods.cpp - the ROD TYPES and RODS sections of a MoorDyn v2 deck (docs/lines.md, "Rods"): each rod read
// as the points, joints and bodies the FMU has (a rod's ends are points; a zero-length rod one point), the
// lines clamped to rods noted, and the rods the FMU has no counterpart for refused naming the rod.
#include "deck/tables.h"

#include "core/types.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace uc {
namespace deck {

namespace {

// A number for a message about a rod (6 significant digits).
std::string short_number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
    return buffer;
}

const char* kind_text(RodKind kind) {
    switch (kind) {
        case RodKind::Fixed: return "Fixed";
        case RodKind::Coupled: return "Coupled";
        case RodKind::Free: return "Free";
        case RodKind::Pinned: return "Pinned";
        default: return "Body";
    }
}

std::string rod_name(const Rod& r) {
    return "rod " + std::to_string(r.id) + " (" +
           (r.kind == RodKind::Pinned && r.body > 0 ? "Body" + std::to_string(r.body) + "Pinned" : kind_text(r.kind)) +
           (r.kind == RodKind::Body ? std::to_string(r.body) : std::string()) +
           (r.numSegs == 0 ? ", zero length)" : ", " + short_number(r.length) + " m)");
}

// The attachment word of a rod: letters, a number, letters (Body2Pinned), as MoorDyn splits it.
bool read_rod_kind(Fields& f, std::string_view word, Rod& r) {
    const std::string u = upper(word);
    size_t i = 0;
    while (i < u.size() && std::isalpha(static_cast<unsigned char>(u[i]))) ++i;
    const std::string head = u.substr(0, i);
    size_t j = i;
    while (j < u.size() && std::isdigit(static_cast<unsigned char>(u[j]))) ++j;
    const std::string digits = u.substr(i, j - i), tail = u.substr(j);
    const std::string id = "rod " + std::to_string(r.id);
    if (is_one_of(head, {"VESSELPINNED", "VESPIN", "CPLDPIN", "COUPLEDPINNED"})) {
        return f.fail(id + " is coupled and pinned (" + quoted(word) + ": its end A moved by the program driving it, "
                      "free to turn about it): not supported (a rod pinned to the ground, 'Pinned', or to a coupled "
                      "or fixed body, 'Body<k>Pinned', is)");
    }
    if (is_one_of(head, {"PINNED", "PIN"}) && digits.empty() && tail.empty()) {
        r.kind = RodKind::Pinned;  // to the ground: its end A fixed
        r.body = 0;
        return true;
    }
    if (head == "BODY" && !digits.empty() && digits.size() < 9 && is_one_of(tail, {"PINNED", "PIN"})) {
        r.kind = RodKind::Pinned;
        r.body = std::stoi(digits);
        return true;
    }
    if (!tail.empty()) return f.fail("unknown rod attachment " + quoted(word));
    if (is_one_of(head, {"ANCHOR", "FIXED", "FIX"}) && digits.empty()) {
        r.kind = RodKind::Fixed;
    } else if (is_one_of(head, {"VESSEL", "VES", "COUPLED", "CPLD"}) && digits.empty()) {
        r.kind = RodKind::Coupled;
    } else if (is_one_of(head, {"POINT", "CON", "FREE"}) && digits.empty()) {
        r.kind = RodKind::Free;
    } else if (head == "BODY" && !digits.empty() && digits.size() < 9) {
        r.kind = RodKind::Body;
        r.body = std::stoi(digits);
    } else {
        return f.fail("unknown rod attachment " + quoted(word) + " (Fixed, Coupled, Free, Pinned, Body<ID> or "
                      "Body<ID>Pinned)");
    }
    return true;
}

}  // namespace

bool read_rod_type(const Row& row, RodType& t, std::string& error) {
    Fields f(row, error);
    if (row.tokens.size() < 7) {
        return f.fail("a rod type has the fields TypeName Diam Mass/m Cd Ca CdEnd CaEnd; this row has " +
                      std::to_string(row.tokens.size()));
    }
    t.name = std::string(row.tokens[0]);
    t.row = row.number;
    t.diameter = f.positive(1, "Diam");
    t.massPerLength = f.non_negative(2, "Mass/m");
    t.Cd = f.non_negative(3, "Cd");
    t.Ca = f.non_negative(4, "Ca");
    t.CdEnd = f.non_negative(5, "CdEnd");
    t.CaEnd = f.non_negative(6, "CaEnd");
    return f.ok();
}

bool read_rod(const Row& row, int expectedId, const std::vector<RodType>& types, Rod& r, std::string& error) {
    Fields f(row, error);
    if (row.tokens.size() < 10) {
        return f.fail("a rod has the fields ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs; this row has " +
                      std::to_string(row.tokens.size()));
    }
    if (!read_id(f, "rod", expectedId, r.id)) return false;
    r.row = row.number;
    r.type = -1;
    for (size_t k = 0; k < types.size(); ++k) {
        if (types[k].name == row.tokens[1]) r.type = static_cast<int>(k);
    }
    if (r.type < 0) {
        std::string known;
        for (const RodType& t : types) known += (known.empty() ? "" : ", ") + quoted(t.name);
        return f.fail("rod type " + quoted(row.tokens[1]) + " is not among the ROD TYPES (" +
                      (known.empty() ? std::string("none") : known) + ")");
    }
    if (!read_rod_kind(f, row.tokens[2], r)) return false;
    static const char* const kColumns[] = {"Xa", "Ya", "Za", "Xb", "Yb", "Zb"};
    for (int k = 0; k < 3; ++k) {
        r.a[k] = f.number(3 + k, kColumns[k]);
        r.b[k] = f.number(6 + k, kColumns[3 + k]);
    }
    r.numSegs = f.integer(9, "NumSegs", 0, 100000, "must be between 0 and 100000");
    if (!f.ok()) return false;
    double d[3], n = 0.0;
    for (int k = 0; k < 3; ++k) {
        d[k] = r.numSegs == 0 ? r.b[k] : r.b[k] - r.a[k];  // zero length: B is the direction (MoorDyn)
        n += d[k] * d[k];
    }
    n = std::sqrt(n);
    if (r.numSegs > 0 && !(n > 0.0))
        return f.fail("rod " + std::to_string(r.id) + ": its ends A and B are the same point with NumSegs " +
                      std::to_string(r.numSegs) + " (a zero-length rod has NumSegs 0)");
    if (!(n > 0.0))
        return f.fail("rod " + std::to_string(r.id) + ": Xb Yb Zb, the direction of a zero-length rod, is (0, 0, 0)");
    for (int k = 0; k < 3; ++k) r.axis[k] = d[k] / n;
    r.length = r.numSegs == 0 ? 0.0 : n;
    if (r.numSegs == 0) std::copy(r.a, r.a + 3, r.b);
    return true;
}

bool rods_as_points(std::vector<Rod>& rods, int firstBody, bool system, std::vector<Point>& points,
                    std::string& error) {
    int nextBody = firstBody;
    for (Rod& r : rods) {
        if (!system && (r.kind == RodKind::Body || r.kind == RodKind::Pinned || (r.kind == RodKind::Free && r.numSegs > 0))) {
            error = at_line(r.row, rod_name(r) + ": a rod on a body, a pinned rod or a free rod of non-zero length "
                                   "makes the deck a mooring system; here it is read as one line (a BODIES section is "
                                   "refused)");
            return false;
        }
        if (r.kind == RodKind::Pinned && r.numSegs == 0) {
            error = at_line(r.row, rod_name(r) + ": a pinned rod of zero length (NumSegs 0) has nothing to turn: give "
                                   "it its end B and NumSegs > 0, or attach the lines to the point it is pinned to");
            return false;
        }
        if ((r.kind == RodKind::Free && r.numSegs > 0) || r.kind == RodKind::Pinned) r.freeBody = nextBody++;
        const int ends = r.numSegs == 0 ? 1 : 2;
        for (int e = 0; e < ends; ++e) {
            Point p;
            p.id = static_cast<int>(points.size()) + 1;
            p.row = r.row;
            p.rod = r.id;
            const double* at = e == 0 ? r.a : r.b;
            switch (r.kind) {
                case RodKind::Fixed: p.kind = PointKind::Fixed; break;
                case RodKind::Coupled: p.kind = PointKind::Vessel; break;
                case RodKind::Body: p.kind = PointKind::Body; p.body = r.body; break;
                case RodKind::Free:
                    if (r.numSegs == 0) {
                        p.kind = PointKind::Free;
                    } else {  // a point of its free body, in the body's frame: along its x axis from its centre
                        p.kind = PointKind::Body;
                        p.body = r.freeBody;
                    }
                    break;
                case RodKind::Pinned:  // a point of its pinned body, whose reference point is its end A
                    p.kind = PointKind::Body;
                    p.body = r.freeBody;
                    break;
            }
            if (r.kind == RodKind::Pinned) {
                p.position[0] = e == 0 ? 0.0 : r.length;
            } else if (r.kind == RodKind::Free && r.numSegs > 0) {
                p.position[0] = (e == 0 ? -0.5 : 0.5) * r.length;
            } else {
                std::copy(at, at + 3, p.position);
            }
            r.point[e] = static_cast<int>(points.size());
            points.push_back(p);
        }
        if (ends == 1) r.point[1] = r.point[0];
    }
    return true;
}

void clamp_lines_to_rods(std::vector<Rod>& rods, const std::vector<RodType>& rodTypes,
                         const std::vector<LineType>& types, std::vector<Point>& points, std::vector<Line>& lines,
                         std::vector<std::string>& notes) {
    // a rod's end that holds no line is no point (a Fixed rod's free end, a can's end without a line)
    std::vector<int> index(points.size(), -1);
    std::vector<Point> kept;
    for (size_t i = 0; i < points.size(); ++i) {
        if (points[i].rod > 0 && points[i].lines.empty()) continue;
        index[i] = static_cast<int>(kept.size());
        kept.push_back(points[i]);
        kept.back().id = static_cast<int>(kept.size());
    }
    points = std::move(kept);
    for (Line& l : lines)
        for (int& e : l.end) e = index[e];
    for (Rod& r : rods)
        for (int& e : r.point) e = index[e];
    for (const Rod& r : rods) {
        std::string at;
        for (int e = 0; e < (r.numSegs == 0 ? 1 : 2); ++e) {
            if (r.point[e] < 0) continue;
            at += std::string(at.empty() ? "" : " and ") + "point " + std::to_string(points[r.point[e]].id) +
                  (r.numSegs == 0 ? "" : e == 0 ? " (end A)" : " (end B)");
        }
        if (at.empty()) at = "no point (no line is attached to it)";
        std::string what;
        switch (r.kind) {
            case RodKind::Fixed: what = "Fixed " + at + ": its own weight and loads go to the ground"; break;
            case RodKind::Coupled:
                what = "coupled " + at + (r.numSegs == 0 ? "" : ", each given its own motion") +
                       "; its own mass and loads are ignored (its motion is given)";
                break;
            case RodKind::Body: what = at + " on body " + std::to_string(r.body); break;
            case RodKind::Pinned:
                what = "pinned body " + std::to_string(r.freeBody) + " (its end A held " +
                       (r.body > 0 ? "by body " + std::to_string(r.body) : std::string("fixed")) +
                       ", free to turn about it), with " + at + " on the body's x axis";
                break;
            case RodKind::Free:
                what = r.numSegs == 0 ? "a free " + at : "free body " + std::to_string(r.freeBody) + ", with " + at +
                                                             " on the body's x axis";
                break;
        }
        notes.push_back(at_line(r.row, rod_name(r) + " read as " + what));
    }
    for (Line& l : lines) {
        for (int e = 0; e < 2; ++e) {
            if (l.rod[e] == 0) continue;
            const Rod& r = rods[(l.rod[e] - 1) / 2];
            const bool atB = (l.rod[e] - 1) % 2 == 1;
            l.rod[e] = r.id;
            // MoorDyn: a line with bending stiffness leaves a rod's end along the rod's axis (out of end B
            // along it, out of end A against it); one without is pinned there
            l.clamped[e] = types[l.type].EI > 0.0;
            for (int k = 0; k < 3; ++k) l.tangent[e][k] = (atB ? 1.0 : -1.0) * r.axis[k];
        }
    }
    // A Free zero-length rod with two lines clamped to it, one at each end: a rigid joint (MoorDyn's rod
    // turns to balance their moments, so it passes the moment from one line to the other).
    for (const Rod& r : rods) {
        if (r.kind != RodKind::Free || r.numSegs != 0 || r.point[0] < 0) continue;
        Point& p = points[r.point[0]];
        std::string joined;
        for (int q : p.lines) joined += (joined.empty() ? "" : ", ") + std::to_string(lines[q].id);
        if (p.lines.size() == 2) {
            const Line& l0 = lines[p.lines[0]];
            const Line& l1 = lines[p.lines[1]];
            const int e0 = l0.end[0] == r.point[0] && l0.rod[0] == r.id ? 0 : 1;
            const int e1 = l1.end[0] == r.point[0] && l1.rod[0] == r.id ? 0 : 1;
            double dot = 0.0;
            for (int k = 0; k < 3; ++k) dot += l0.tangent[e0][k] * l1.tangent[e1][k];
            p.rigid = l0.clamped[e0] && l1.clamped[e1] && dot < 0.0;
        }
        const RodType& t = rodTypes[r.type];
        const double area = 0.25 * kPi * t.diameter * t.diameter;
        std::string what = p.rigid ? "a rigid joint between lines " + joined + " (it passes their bending moment)"
                                   : "a pinned point of lines " + joined;
        notes.push_back(at_line(r.row, "rod " + std::to_string(r.id) + " (Free, zero length): " + what +
                                           "; its end drag and added mass along its axis (2 CdEnd A = " +
                                           short_number(2.0 * t.CdEnd * area) + " m2, 2 CaEnd " +
                                           "rho pi d^3/12 per unit density = " +
                                           short_number(2.0 * t.CaEnd * kPi * std::pow(t.diameter, 3) / 12.0) +
                                           " m3) are left out"));
    }
}

void note_pinned_clamps(const Deck& deck, const std::vector<std::pair<int, int>>& held,
                        std::vector<std::string>& notes) {
    for (size_t i = 0; i < deck.lines.size(); ++i) {
        const Line& l = deck.lines[i];
        for (int e = 0; e < 2; ++e) {
            if (!l.clamped[e]) continue;
            if (std::find(held.begin(), held.end(), std::make_pair(static_cast<int>(i), e)) != held.end()) continue;
            const Point& p = deck.points[l.end[e]];
            if (p.rigid) continue;  // a rigid joint: the moment passes from one line to the other
            if (p.kind == PointKind::Free && p.lines.size() == 2) {
                // a free zero-length rod turns to balance its lines' moments: with one line clamped it follows
                // that line's end, which then carries no moment (pinned, exactly)
                const Line& o = deck.lines[p.lines[0] == static_cast<int>(i) ? p.lines[1] : p.lines[0]];
                const int oe = o.end[0] == l.end[e] ? 0 : 1;
                if (!o.clamped[oe]) continue;
            }
            notes.push_back("warning: " + at_line(l.row, "line " + std::to_string(l.id) + " (EI " +
                                                             short_number(deck.types[l.type].EI) + " N m2): its end " +
                                                             (e == 0 ? "A" : "B") + " is clamped to rod " +
                                                             std::to_string(l.rod[e]) + "'s axis in MoorDyn, pinned "
                                                             "at point " + std::to_string(p.id) + " here (the bending "
                                                             "moment it carries into the rod is left out)"));
        }
    }
}

namespace {

// R = Rx(a0) Ry(a1) Rz(a2) applied to v (MoorDyn's orientation of a body).
void rotate_body(const double a[3], const double v[3], double out[3]) {
    const double cx = std::cos(a[0]), sx = std::sin(a[0]), cy = std::cos(a[1]), sy = std::sin(a[1]),
                 cz = std::cos(a[2]), sz = std::sin(a[2]);
    const double z1[3] = {cz * v[0] - sz * v[1], sz * v[0] + cz * v[1], v[2]};
    const double y1[3] = {cy * z1[0] + sy * z1[2], z1[1], -sy * z1[0] + cy * z1[2]};
    out[0] = y1[0];
    out[1] = cx * y1[1] - sx * y1[2];
    out[2] = sx * y1[1] + cx * y1[2];
}

// A straight rod's rigid-body description about its centre, its axis along body axis `axis` (0, 1, 2):
// mass, displaced volume, moments of inertia (with the transverse added inertia Ca rho A L^3 / 12 of the
// water it accelerates as it turns: a free body has no rotational added mass), drag areas (translations, rotations) and added volumes (added mass / rho) of
// translation, each along the body's axes. The Morison loads of the rod integrated along its length:
// transverse drag Cd d L, axial drag on its two ends 2 CdEnd A (MoorDyn applies CdEnd at each end),
// turning drag about a transverse axis Cd d L^4 / 32 (the integral of |r|^3), transverse added mass Ca rho V,
// axial 2 CaEnd rho pi d^3 / 12 (MoorDyn's half-sphere at each end).
struct RodBody {
    double mass = 0.0, volume = 0.0, inertia[3] = {}, CdA[6] = {}, addedVolume[3] = {};
};

RodBody rod_body(const Rod& r, const RodType& t, int axis, double rho) {
    RodBody b;
    const double d = t.diameter, L = r.length, A = 0.25 * kPi * d * d;
    b.mass = t.massPerLength * L;
    b.volume = A * L;
    const double endVolume = 2.0 * t.CaEnd * kPi * d * d * d / 12.0;
    for (int k = 0; k < 3; ++k) {
        const bool along = k == axis;
        b.inertia[k] = along ? b.mass * d * d / 8.0
                             : b.mass * (L * L / 12.0 + d * d / 16.0) + t.Ca * rho * A * L * L * L / 12.0;
        b.CdA[k] = along ? 2.0 * t.CdEnd * A : t.Cd * d * L;
        b.CdA[3 + k] = along ? 0.0 : t.Cd * d * std::pow(L, 4) / 32.0;
        b.addedVolume[k] = along ? endVolume : t.Ca * b.volume;
    }
    return b;
}

// The body axis (0, 1, 2) a unit vector lies along, -1 if none.
int body_axis(const double v[3]) {
    for (int k = 0; k < 3; ++k) {
        if (std::abs(std::abs(v[k]) - 1.0) < 1e-9) return k;
    }
    return -1;
}

// A rod of type t from ea to eb in body b's frame: its mass at its centre and its inertia (m d^2 / 8 about its
// axis, m (L^2 / 12 + d^2 / 16) across) added to the body's, the centre of gravity and the inertia about it
// recombined. False (b unchanged) where the sum is not diagonal in the body's axes.
bool add_rod_mass(DeckBody& b, const RodType& t, const Vec3& ea, const Vec3& eb) {
    const double d = t.diameter, L = (eb - ea).norm();
    const double m = t.massPerLength * L;
    const Vec3 cRod = 0.5 * (ea + eb), cBody(b.cg[0], b.cg[1], b.cg[2]), along = (eb - ea) / L;
    const double M = b.mass + m;
    const Vec3 cg = M > 0.0 ? Vec3((b.mass * cBody + m * cRod) / M) : Vec3::Zero();
    const Mat3 rodInertia = m * (L * L / 12.0 + d * d / 16.0) * (Mat3::Identity() - along * along.transpose()) +
                            m * d * d / 8.0 * along * along.transpose();
    auto shifted = [](const Mat3& I, double mass, const Vec3& by) {
        return Mat3(I + mass * (by.squaredNorm() * Mat3::Identity() - by * by.transpose()));
    };
    const Mat3 I = shifted(Vec3(b.inertia[0], b.inertia[1], b.inertia[2]).asDiagonal(), b.mass, cBody - cg) +
                   shifted(rodInertia, m, cRod - cg);
    const double scale = I.diagonal().cwiseAbs().maxCoeff();
    if ((I - Mat3(I.diagonal().asDiagonal())).cwiseAbs().maxCoeff() > 1e-9 * std::max(scale, 1e-300)) return false;
    for (int k = 0; k < 3; ++k) {
        b.inertia[k] = I(k, k);
        b.cg[k] = cg[k];
    }
    b.mass = M;
    return true;
}

// A rod of type t added to pinned body b, along body axis `axis` from s1 to s2 on it (its axis through the body's reference
// point, the pin): its mass at its centre (the body's centre of gravity and inertia about it recombined), its
// buoyancy at its centre (the body's centre of buoyancy recombined), its added mass of translation at the
// reference point, its Morison loads as it turns about the reference point: the added inertia
// Ca rho A (s2^3 - s1^3) / 3 and the drag area Cd d (s2|s2|^3 - s1|s1|^3) / 4 about the transverse axes (the
// integrals of r^2 and |r|^3 along it). False where the combined inertia is not diagonal in the body's axes.
bool add_rod_to_pinned(DeckBody& b, const RodType& t, int axis, double s1, double s2, double rho) {
    const double d = t.diameter, L = s2 - s1, A = 0.25 * kPi * d * d;
    const double V = A * L, sc = 0.5 * (s1 + s2);
    const Vec3 cRod = sc * Vec3::Unit(axis);
    const double addedInertia = t.Ca * rho * A * (s2 * s2 * s2 - s1 * s1 * s1) / 3.0;
    if (!add_rod_mass(b, t, Vec3(s1 * Vec3::Unit(axis)), Vec3(s2 * Vec3::Unit(axis)))) return false;
    for (int k = 0; k < 3; ++k) {
        if (k != axis) b.inertia[k] += addedInertia;
    }
    const double Vb = b.volume;
    const Vec3 cb = Vb + V > 0.0 ? Vec3((Vb * Vec3(b.cb[0], b.cb[1], b.cb[2]) + V * cRod) / (Vb + V)) : Vec3::Zero();
    const double endVolume = 2.0 * t.CaEnd * kPi * d * d * d / 12.0;
    auto cube = [](double x) { return x * std::abs(x) * x * x; };  // s |s|^3: the integral of |s|^3 is s |s|^3 / 4
    for (int k = 0; k < 3; ++k) {
        const bool along = k == axis;
        const double addedVolume = along ? endVolume : t.Ca * V;
        b.Ca[k] = Vb + V > 0.0 ? (b.Ca[k] * Vb + addedVolume) / (Vb + V) : 0.0;
        b.CdA[k] += along ? 2.0 * t.CdEnd * A : t.Cd * d * L;
        b.CdA[3 + k] += along ? 0.0 : t.Cd * d * (cube(s2) - cube(s1)) / 4.0;
        b.cb[k] = cb[k];
    }
    b.volume = Vb + V;
    return true;
}

// A rod of type t from ea to eb (the body's frame) fixed to body b whose buoyancy, drag and added mass follow
// its part under water (a rod on a Free body, a pinned rod): its mass and inertia added to the body's, the rest
// a MooringRod of the body (system/body_rods.h). False where the inertia is not diagonal in the body's axes.
bool add_wet_rod(DeckBody& b, const Rod& r, const RodType& t, const Vec3& ea, const Vec3& eb) {
    if (!add_rod_mass(b, t, ea, eb)) return false;
    MooringRod rod;
    rod.id = r.id;
    for (int k = 0; k < 3; ++k) {
        rod.a[k] = ea[k];
        rod.b[k] = eb[k];
    }
    rod.diameter = t.diameter;
    rod.Cd = t.Cd;
    rod.Ca = t.Ca;
    rod.CdEnd = t.CdEnd;
    rod.CaEnd = t.CaEnd;
    b.rods.push_back(rod);
    return true;
}

// A rod's body appended at its ID (after the deck's), body 1 first where the Vessel points ride it.
void append_body(std::vector<DeckBody>& bodies, const DeckBody& b) {
    while (static_cast<int>(bodies.size()) + 1 < b.id) {  // body 1: the platform the Vessel points ride
        DeckBody platform;
        platform.id = static_cast<int>(bodies.size()) + 1;
        bodies.push_back(platform);
    }
    bodies.push_back(b);
}

}  // namespace

bool rods_into_bodies(const Deck& deck, std::vector<DeckBody>& bodies, std::vector<std::string>& notes,
                      std::string& error) {
    const double rho = deck.waterDensity;
    for (const Rod& r : deck.rods) {
        if (r.numSegs == 0 || (r.kind != RodKind::Body && r.kind != RodKind::Free && r.kind != RodKind::Pinned)) continue;
        const RodType& t = deck.rodTypes[r.type];
        const std::string name = rod_name(r);
        auto refuse = [&](const std::string& why) {
            error = at_line(r.row, name + ": " + why);
            return false;
        };
        // its ends in the earth frame at the deck's pose: a rod read as a rigid body must stay under water
        // (a free body's buoyancy is constant; through the waterline it would change with the draft)
        double ends[2][3];
        double ax[3];
        if (r.kind == RodKind::Pinned) {
            // its end A held by body r.body (0: the ground), its ends in the earth frame at that body's pose
            const DeckBody* holder = nullptr;
            if (r.body > 0) {
                if (r.body > static_cast<int>(bodies.size()))
                    return refuse("it is pinned to body " + std::to_string(r.body) + ", which the BODIES table does not have");
                holder = &bodies[r.body - 1];
                if (holder->kind == BodyKind::Pinned)
                    return refuse("it is pinned to CoupledPinned body " + std::to_string(r.body) + ": a pinned rod on a "
                                  "pinned body is not supported (pinned rods are held by a Coupled, Fixed or Free body or "
                                  "by the ground)");
            }
            for (int e = 0; e < 2; ++e) {
                const double* at = e == 0 ? r.a : r.b;
                if (holder) {
                    rotate_body(holder->pose + 3, at, ends[e]);
                    for (int k = 0; k < 3; ++k) ends[e][k] += holder->pose[k];
                } else {
                    std::copy(at, at + 3, ends[e]);
                }
            }
        } else if (r.kind == RodKind::Body) {
            if (r.body < 1 || r.body > static_cast<int>(bodies.size()))
                return refuse("it is on body " + std::to_string(r.body) + ", which the BODIES table does not have");
            const DeckBody& b = bodies[r.body - 1];
            if (b.kind != BodyKind::Free && b.kind != BodyKind::Pinned) {
                if (b.kind == BodyKind::Coupled)
                    notes.push_back(at_line(r.row, name + ": its mass and loads are ignored, as coupled body " +
                                                       std::to_string(b.id) + "'s own (its motion is given)"));
                continue;
            }
            for (int e = 0; e < 2; ++e) {
                rotate_body(b.pose + 3, e == 0 ? r.a : r.b, ends[e]);
                for (int k = 0; k < 3; ++k) ends[e][k] += b.pose[k];
            }
            std::copy(r.axis, r.axis + 3, ax);
        } else {
            for (int k = 0; k < 3; ++k) {
                ends[0][k] = r.a[k];
                ends[1][k] = r.b[k];
            }
        }
        const double top = std::max(ends[0][2], ends[1][2]) + 0.5 * t.diameter;
        if (top > 0.0 && r.kind == RodKind::Body && bodies[r.body - 1].kind == BodyKind::Pinned)
            return refuse("it reaches z = " + short_number(top) + " m (its top end and radius) at the deck's pose: a rod "
                          "on a CoupledPinned body through or above the waterline is not supported (it keeps its full "
                          "buoyancy there; a rod on a Free body, a free rod and a pinned rod follow the waterline)");
        if (r.kind == RodKind::Body && bodies[r.body - 1].kind == BodyKind::Pinned) {
            DeckBody& b = bodies[r.body - 1];
            const int axis = body_axis(ax);
            if (axis < 0)
                return refuse("its axis is not along one of pinned body " + std::to_string(b.id) + "'s axes: its drag and "
                              "added mass have no per-axis form in the body's axes");
            for (int k = 0; k < 3; ++k) {
                if (k != axis && (std::abs(r.a[k]) > 1e-9 || std::abs(r.b[k]) > 1e-9))
                    return refuse("its axis does not pass through pinned body " + std::to_string(b.id) + "'s reference "
                                  "point (its pin): its ends' coordinates across its axis must be 0");
            }
            const double sa = r.a[axis], sb = r.b[axis];
            if (!add_rod_to_pinned(b, t, axis, std::min(sa, sb), std::max(sa, sb), rho))
                return refuse("added to pinned body " + std::to_string(b.id) + " it makes an inertia that is not diagonal "
                              "in the body's axes (the body's own centre of gravity off the rod's axis)");
            notes.push_back(at_line(r.row, name + ": added to pinned body " + std::to_string(b.id) + ": mass " +
                                               short_number(t.massPerLength * r.length) + " kg at " +
                                               short_number(0.5 * (sa + sb)) + " m along its axis from the pin, its "
                                               "inertia, buoyancy, drag and added mass about the pin"));
        } else if (r.kind == RodKind::Pinned) {
            DeckBody b;
            b.id = r.freeBody;
            b.kind = BodyKind::Pinned;
            b.row = r.row;
            std::copy(ends[0], ends[0] + 3, b.pose);
            double axis[3];
            for (int k = 0; k < 3; ++k) axis[k] = (ends[1][k] - ends[0][k]) / r.length;
            b.pose[5] = std::asin(std::clamp(axis[1], -1.0, 1.0));
            b.pose[4] = std::cos(b.pose[5]) > 1e-12 ? std::atan2(-axis[2], axis[0]) : 0.0;
            const DeckBody* holder = r.body > 0 ? &bodies[r.body - 1] : nullptr;
            if (holder && holder->kind == BodyKind::Free) {  // its pin moves with the free body, its reaction loads it
                b.pinBody = r.body;
                std::copy(r.a, r.a + 3, b.pinAt);
            } else if (holder && holder->kind == BodyKind::Coupled) {
                if (r.body > UC_MAX_BODIES)
                    return refuse("it is pinned to coupled body " + std::to_string(r.body) + ": the bodies' inputs "
                                  "body[k].* go up to k = " + std::to_string(UC_MAX_BODIES));
                b.pinBody = r.body;
                std::copy(r.a, r.a + 3, b.pinAt);
            } else {  // the ground, or a Fixed body: the pin stands still where it is
                b.pinBody = 0;
                std::copy(ends[0], ends[0] + 3, b.pinAt);
            }
            // a rod alone (its inertia diagonal): its buoyancy, drag and added mass from its part under water
            add_wet_rod(b, r, t, Vec3::Zero(), Vec3(r.length, 0.0, 0.0));
            if (!(t.massPerLength > 0.0)) return refuse("a pinned rod needs Mass/m > 0 (its moments of inertia)");
            append_body(bodies, b);
            notes.push_back(at_line(r.row, name + ": pinned body " + std::to_string(b.id) + " of mass " +
                                               short_number(b.mass) + " kg and volume " +
                                               short_number(0.25 * kPi * t.diameter * t.diameter * r.length) +
                                               " m3, turning about its end A (" +
                                               (b.pinBody > 0 ? std::string(holder && holder->kind == BodyKind::Free
                                                                                ? "held by free body "
                                                                                : "held by body ") +
                                                                    std::to_string(b.pinBody)
                                                              : std::string("held still")) +
                                               "), its buoyancy, drag and added mass from its part under water"));
        } else if (r.kind == RodKind::Body) {
            DeckBody& b = bodies[r.body - 1];
            if (!add_wet_rod(b, r, t, Vec3(r.a[0], r.a[1], r.a[2]), Vec3(r.b[0], r.b[1], r.b[2])))
                return refuse("added to Free body " + std::to_string(b.id) + " it makes an inertia that is not diagonal in "
                              "the body's axes (a free body's I* is about its axes; the rod's axis or its centre off them)");
            notes.push_back(at_line(r.row, name + ": added to Free body " + std::to_string(b.id) + ": mass " +
                                               short_number(t.massPerLength * r.length) + " kg (the body's centre of "
                                               "gravity now at " + short_number(b.cg[0]) + ", " + short_number(b.cg[1]) +
                                               ", " + short_number(b.cg[2]) + " m), its inertia; its buoyancy, drag and "
                                               "added mass from its part under water as the body moves"));
        } else {
            DeckBody b;
            b.id = r.freeBody;
            b.kind = BodyKind::Free;
            b.row = r.row;
            for (int k = 0; k < 3; ++k) b.pose[k] = 0.5 * (ends[0][k] + ends[1][k]);
            // R = Rx(0) Ry(p) Rz(y) turns the body's x axis onto the rod's: (cos p cos y, sin y, -sin p cos y)
            b.pose[5] = std::asin(std::clamp(r.axis[1], -1.0, 1.0));
            b.pose[4] = std::cos(b.pose[5]) > 1e-12 ? std::atan2(-r.axis[2], r.axis[0]) : 0.0;
            const RodBody rb = rod_body(r, t, 0, rho);
            b.mass = rb.mass;
            b.volume = rb.volume;
            for (int k = 0; k < 3; ++k) {
                b.inertia[k] = rb.inertia[k];
                b.Ca[k] = rb.addedVolume[k] / rb.volume;
            }
            std::copy(rb.CdA, rb.CdA + 6, b.CdA);
            b.rodLength = r.length;  // its buoyancy, drag and added mass follow its part under water
            if (!(b.mass > 0.0)) return refuse("a free rod needs Mass/m > 0 (its moments of inertia)");
            append_body(bodies, b);
            notes.push_back(at_line(r.row, name + ": free body " + std::to_string(b.id) + " of mass " +
                                               short_number(b.mass) + " kg and volume " + short_number(b.volume) +
                                               " m3 at its centre, its drag and added mass integrated along it (its "
                                               "turning drag apart from its translation's)"));
        }
    }
    // a pinned body turns under its loads: it needs an inertia about each axis (its own or its rods')
    static const char* const kAxes[3] = {"x", "y", "z"};
    for (const DeckBody& b : bodies) {
        if (b.kind != BodyKind::Pinned) continue;
        for (int k = 0; k < 3; ++k) {
            if (!(b.inertia[k] > 0.0)) {
                error = at_line(b.row, "pinned body " + std::to_string(b.id) + ": its moment of inertia about its " +
                                           kAxes[k] + " axis is " + short_number(b.inertia[k]) + " kg m2 (I* and its "
                                           "rods'); it must be positive: it turns about its pin under its loads");
                return false;
            }
        }
        for (int k = 0; k < 6; ++k) {
            if (b.CdA[k] < 0.0 || (k < 3 && b.Ca[k] < 0.0)) {
                error = at_line(b.row, "pinned body " + std::to_string(b.id) + ": CdA* and Ca* must not be negative");
                return false;
            }
        }
    }
    return true;
}

}  // namespace deck
}  // namespace uc
