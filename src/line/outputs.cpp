// outputs.cpp - reactions, stations, extremes.
#include "line/outputs.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "terms/seabed.h"

namespace uc {
namespace {

Vec3 at(const double* X, int g) { return Eigen::Map<const Vec3>(X + g); }

double curvature(const Vec3& rp, const Vec3& rpp) {
    const double n = rp.norm();
    return rp.cross(rpp).norm() / (n * n * n);
}

// Samples per element for the seabed outputs (the contact is resolved to l/8 in arc length).
constexpr int kSeabedSamples = 8;

// The shape functions at xi = k / (n - 1), k = 0..n-1, of the last element length asked for: the
// elements of a run share them (one evaluation per run, not per element, at every output).
template <int n>
class SampleShapes {
public:
    const ShapeValues& at(int k, double l) {
        if (l != length_) {
            length_ = l;
            for (int i = 0; i < n; ++i) values_[i] = hermite_shape(static_cast<double>(i) / (n - 1), l);
        }
        return values_[k];
    }

private:
    double length_ = -1.0;
    ShapeValues values_[n];
};

// Lowest height n.r of an element's centreline along the unit vector n (e_z: its height z): its
// cubic's value at the ends and where its slope in the element coordinate xi vanishes inside.
double lowest_height(const double* Xe, double l, const Vec3& n) {
    const double z0 = n.dot(at(Xe, 0)), m0 = l * n.dot(at(Xe, 3)), z1 = n.dot(at(Xe, 6)), m1 = l * n.dot(at(Xe, 9));
    const double b = m0, c = 3.0 * (z1 - z0) - 2.0 * m0 - m1, d = 2.0 * (z0 - z1) + m0 + m1;
    auto z = [&](double xi) { return z0 + xi * (b + xi * (c + xi * d)); };
    double lowest = std::min(z0, z1);
    auto consider = [&](double xi) {
        if (xi > 0.0 && xi < 1.0) lowest = std::min(lowest, z(xi));
    };
    if (std::abs(d) < 1e-14 * (std::abs(b) + std::abs(c) + 1e-300)) {
        if (c != 0.0) consider(-b / (2.0 * c));
    } else {  // 3 d xi^2 + 2 c xi + b = 0
        const double disc = c * c - 3.0 * d * b;
        if (disc >= 0.0) {
            const double q = -(c + std::copysign(std::sqrt(disc), c));
            if (q != 0.0) consider(b / q);
            consider(q / (3.0 * d));
        }
    }
    return lowest;
}

// Seabed outputs. A point of the line rests on the seabed when its centreline is within half a
// diameter of the seabed. The contact is a penalty that starts at the seabed, sampled at quadrature
// points, so a line at rest sinks a little into it and its cubic shape may wave by millimetres
// between the points: a test against zero clearance misses such a line; half a diameter does not,
// at every seabed stiffness, and marks the touchdown point of a catenary within a few metres (where
// its height above the seabed reaches half a diameter). Between samples the clearance is interpolated
// linearly. The contact force is integrated with the quadrature the equations use.
// The clearance below which a point of the line rests on the seabed (see seabed_outputs).
double resting_clearance(const SectionProps& section) {
    return std::max(section.seabed.smoothing, 0.5 * section.fluid.diameter);
}

void seabed_outputs(const CableModel& model, const double* X, const double* Xd, UCOutputs& out) {
    const UCParams& p = model.params();
    out.touchdownArcLength = model.line().length;
    out.minSeabedClearance = INFINITY;
    out.groundedLength = 0.0;
    out.seabedContactForce = 0.0;
    bool touched = false;
    double previousS = 0.0, previousGap = 0.0;
    SampleShapes<kSeabedSamples + 1> shapes;
    // heights along the seabed's normal above the seabed as given (the plane through z = -waterDepth
    // under the origin; e_z where it is flat)
    const Vec3 n = model.seabed().normal;
    const double base = p.waterDepth * n.z();
    // on a grid: the height along the local normal above the grid (seabed_height: the grid as given)
    const bool grid = model.seabed_grid() != nullptr;
    auto clearance_of = [&](const Vec3& r) {
        if (!grid) return n.dot(r) + base;
        return seabed_normal(model.seabed(), r.x(), r.y()).z() * (r.z() - model.seabed_height(r.x(), r.y()));
    };
    for (int e = 0; e < model.n_elements(); ++e) {
        const SectionProps& section = model.element_section(e);
        const double l = model.element_length(e);
        const double s0 = model.element_start(e);
        const double reach = resting_clearance(section);
        const double ds = l / kSeabedSamples;
        const double* Xe = X + model.element_offset(e);
        if (!grid) out.minSeabedClearance = std::min(out.minSeabedClearance, lowest_height(Xe, l, n) + base);
        for (int k = e == 0 ? 0 : 1; k <= kSeabedSamples; ++k) {
            const double xi = static_cast<double>(k) / kSeabedSamples;
            const double s = model.runs().size() == 1 ? (e + xi) * l : s0 + xi * l;
            const Vec3 r = interpolate(shapes.at(k, l).N, Xe);
            const double clearance = clearance_of(r);
            if (grid) out.minSeabedClearance = std::min(out.minSeabedClearance, clearance);  // at the samples
            const double gap = clearance - reach;  // <= 0: resting on the seabed
            if (p.enableSeabed && s > 0.0) {
                if (gap <= 0.0 && previousGap <= 0.0) {
                    out.groundedLength += ds;
                } else if (gap <= 0.0 || previousGap <= 0.0) {  // a touchdown or lift-off in between
                    const double crossing = previousGap / (previousGap - gap);
                    out.groundedLength += gap <= 0.0 ? (1.0 - crossing) * ds : crossing * ds;
                }
            }
            if (p.enableSeabed && !touched && gap <= 0.0) {
                touched = true;
                out.touchdownArcLength =
                    s > 0.0 && previousGap > 0.0 ? previousS + (s - previousS) * previousGap / (previousGap - gap) : s;
            }
            previousS = s;
            previousGap = gap;
        }
        // above the contact band every load is zero: q.weight * 0 subtracts nothing
        if (!p.enableSeabed || above_contact(model.tables(e), section.seabed, Xe)) continue;
        const ContactPoints points = contact_points(model.tables(e));  // as the residual integrates it
        double material[12];  // the winch's top element moves with the material, as in the residual
        const double* Xde = model.element_velocities(e, X, Xd, material);
        for (int g = 0; g < points.count; ++g) {  // the residual holds minus the load
            const QuadPoint& q = points.points[g];
            const Vec3 r = interpolate(q.shape.N, Xe);
            const Vec3 normal = grid ? seabed_normal(section.seabed, r.x(), r.y()) : n;
            out.seabedContactForce -= q.weight * normal.dot(seabed_load(section.seabed, r, interpolate(q.shape.N, Xde), nullptr));
        }
    }
}

// Layback, the cable's direction at the tow point and its angle at an anchor.
void geometry_outputs(const CableModel& model, const double* X, const StationShapes& shapes, UCOutputs& out) {
    const UCParams& p = model.params();
    const int gN = model.end_offset();
    const Vec3 top = at(X, 0), end = at(X, gN);
    out.layback = std::hypot(end.x() - top.x(), end.y() - top.y());
    const Vec3 t0 = at(X, 3).normalized();  // down the cable from the tow point
    out.topDeclination = std::acos(std::clamp(-t0.z(), -1.0, 1.0));
    out.topAzimuth = std::hypot(t0.x(), t0.y()) > 1e-12 ? std::atan2(t0.y(), t0.x()) : 0.0;
    out.anchorUplift = 0.0;
    if (model.far_end().anchored) {
        // Lying on the seabed at the anchor: the line one seabed sample before it (l/8) still
        // resting on the seabed, as seabed_outputs counts it.
        const int last = model.n_elements() - 1;
        // heights and the angle along the seabed's normal (e_z where it is flat)
        const Vec3 near = interpolate(shapes.near_bottom().N, X + gN - 6);
        const Vec3 n = seabed_normal(model.seabed(), near.x(), near.y());
        const double clearance = model.seabed_grid() ? n.z() * (near.z() - model.seabed_height(near.x(), near.y()))
                                                     : n.dot(near) + p.waterDepth * n.z();
        const bool grounded = p.enableSeabed && clearance <= resting_clearance(model.element_section(last));
        const Vec3 up = -at(X, gN + 3).normalized();  // from the anchor up the cable
        out.anchorUplift = grounded ? 0.0 : std::asin(std::clamp(n.dot(up), -1.0, 1.0));
    }
}

}  // namespace

bool StationShapes::same_mesh(const CableModel& model) const {
    const std::vector<ElementRun>& runs = model.runs();
    if (model.line().length != length_ || runs.size() != runs_.size()) return false;
    for (size_t r = 0; r < runs.size(); ++r) {
        const ElementRun &a = runs[r], &b = runs_[r];
        if (a.s0 != b.s0 || a.elementLength != b.elementLength || a.first != b.first || a.count != b.count ||
            a.section != b.section)
            return false;
    }
    return true;
}

void StationShapes::update(const CableModel& model) {
    if (same_mesh(model)) return;
    length_ = model.line().length;
    runs_ = model.runs();
    for (int k = 0; k < UC_NUM_STATIONS; ++k) {
        Station& station = stations_[k];
        model.locate(model.line().length * k / (UC_NUM_STATIONS - 1), station.element, station.xi);
        station.shape = hermite_shape(station.xi, model.element_length(station.element));
    }
    const int last = model.n_elements() - 1;
    top_ = hermite_shape(0.0, model.element_length(0));
    bottom_ = hermite_shape(1.0, model.element_length(last));
    nearBottom_ = hermite_shape(1.0 - 1.0 / kSeabedSamples, model.element_length(last));
}

void nodal_tensions(const CableModel& model, const double* X, const ElementForces& forces, double* T) {
    const int N = model.n_elements();
    // Node 0: the cable pulls the tow point along +t_0 with the force -R_0 (reaction).
    T[0] = (-forces.element[0].segment<3>(0)).dot(at(X, 3).normalized());
    for (int i = 1; i <= N; ++i)
        T[i] = forces.element[i - 1].segment<3>(6).dot(at(X, model.element_offset(i - 1) + 9).normalized());
}

// Internal moment at an element end: bending EI r' x r'' / |r'|^3 minus the torque along t. The
// sign follows from the residual: its torque term +(H r' x r'')' puts -H r' x r'' into the internal
// force n, and the moment balance M' + r' x n = 0 then needs M = EI r' x r'' - H t. It is
// the moment that the cable beyond the point exerts on the cable before it. sv: the shape functions
// at the end of element e.
Vec3 internal_moment(const CableModel& model, int e, const double* X, const ShapeValues& sv, double torque) {
    const double* Xe = X + model.element_offset(e);
    const Vec3 rp = interpolate(sv.dN, Xe);
    const double n = rp.norm();
    return model.element_section(e).EI * rp.cross(interpolate(sv.d2N, Xe)) / (n * n * n) - torque * rp / n;
}

void compute_outputs(const CableModel& model, const double* X, const double* Xd, const double* syropeHistory,
                     const ElementForces& forces, double torque, OutputWorkspace& work, UCOutputs& out) {
    const int N = model.n_elements();
    const int gN = model.end_offset();
    const Vec3 towForce = -forces.element[0].segment<3>(0);
    Vec3 endForce = -forces.element[N - 1].segment<3>(6);
    if (model.anchor_resting() && model.element_section(N - 1).EI == 0.0) {
        // A line without bending stiffness pulls its anchor along its tangent only. On a line that
        // rests on the seabed at its anchor the element's reaction also carries its share of the
        // contact, which differs from the weight wherever the mesh is too coarse for the seabed's
        // transition (a clump sunk into the seabed on the line's last elements): projected on the
        // tangent, that imbalance does not reach the anchor force. (On a hanging anchor the
        // reaction is the more accurate: the nodal tangent's own error would show.)
        const Vec3 t = Eigen::Map<const Vec3>(X + gN + 3).normalized();
        endForce = endForce.dot(t) * t;
    }
    for (int k = 0; k < 3; ++k) {
        out.towForce[k] = towForce[k];
        out.endForce[k] = endForce[k];
        out.endPosition[k] = X[gN + k];
        out.endVelocity[k] = Xd[gN + k];
    }
    out.towTension = towForce.norm();
    out.endTension = endForce.norm();

    std::vector<double>& T = work.nodeTension;
    T.resize(N + 1);  // no allocation after the first call
    nodal_tensions(model, X, forces, T.data());

    const StationShapes& shapes = work.stations;
    work.stations.update(model);
    for (int k = 0; k < UC_NUM_STATIONS; ++k) {
        const StationShapes::Station& station = shapes.station(k);
        const int e = station.element;
        const double xi = station.xi;
        const ShapeValues& sv = station.shape;
        const double* Xe = X + model.element_offset(e);
        const Vec3 r = interpolate(sv.N, Xe);
        out.shapeX[k] = r.x();
        out.shapeY[k] = r.y();
        out.shapeZ[k] = r.z();
        out.tension[k] = (1.0 - xi) * T[e] + xi * T[e + 1];
        out.curvature[k] = curvature(interpolate(sv.dN, Xe), interpolate(sv.d2N, Xe));
    }

    double minTension = *std::min_element(T.begin(), T.end());
    double maxCurvature = 0.0, maxBendingMoment = 0.0;
    SampleShapes<2> ends;  // xi = 0 and 1
    // Minimum tension over the nodes (exact reactions of the discrete equations) and the element
    // means (the projected strain's mean mode). The pointwise projected tension also carries the
    // softened higher strain modes, whose strain is 100 times the physical variation inside an
    // element: not a tension to report (it dips to -23 N at a free end that carries none).
    for (int e = 0; e < N; ++e) {
        const double* Xe = X + model.element_offset(e);
        const ElementTables& tables = model.tables(e);
        const SectionProps& section = model.element_section(e);
        const double l = model.element_length(e);
        double axialTension[ElementTables::nAxial];
        Vec3 rp[ElementTables::nAxial];  // r' at the axial points, which the tensions interpolate anyway
        double material[12];  // the winch's top element: the velocities of the material in it
        axial_tensions(tables, model.internal_offset(e) >= 0 ? model.element_axial(e, X, Xd, syropeHistory) : section.axial, Xe,
                       model.element_velocities(e, X, Xd, material), axialTension, rp);
        double mean = 0.0, elementCurvature = 0.0;
        for (int g = 0; g < ElementTables::nAxial; ++g) {
            mean += tables.axial[g].weight / l * axialTension[g];
            elementCurvature = std::max(elementCurvature, curvature(rp[g], interpolate(tables.axial[g].shape.d2N, Xe)));
        }
        minTension = std::min(minTension, mean);
        for (int end = 0; end < 2; ++end) {
            const ShapeValues& sv = ends.at(end, l);
            elementCurvature = std::max(elementCurvature, curvature(interpolate(sv.dN, Xe), interpolate(sv.d2N, Xe)));
        }
        maxCurvature = std::max(maxCurvature, elementCurvature);
        maxBendingMoment = std::max(maxBendingMoment, section.EI * elementCurvature);
    }
    seabed_outputs(model, X, Xd, out);
    geometry_outputs(model, X, shapes, out);
    out.cableTorque = torque;
    model.twist_angles(UC_NUM_STATIONS, torque, out.twistAngle);
    // The cable pulls on the tow fitting with the internal moment at s = 0 and on the far-end
    // fitting with minus the internal moment at s = L.
    const Vec3 towMoment = internal_moment(model, 0, X, shapes.top(), torque);
    const Vec3 endMoment = -internal_moment(model, N - 1, X, shapes.bottom(), torque);
    for (int k = 0; k < 3; ++k) {
        out.towMoment[k] = towMoment[k];
        out.endMoment[k] = endMoment[k];
    }
    out.minTension = minTension;
    out.maxCurvature = maxCurvature;
    out.maxBendingMoment = maxBendingMoment;
}

}  // namespace uc
