// line_profile.h - the static profile of a line without bending stiffness, at rest and without
// current, between its top point and a lower end (the anchor): the multi-segment elastic catenary
// with point loads (clump weights, buoys), lying on a flat frictionless seabed from the lower end up
// to its touchdown where it reaches it (docs/model.md, "Initial equilibrium"). It is exact for such a
// line, so it serves three purposes: the static solver's starting shape, the placement of the nodes
// (one at the touchdown, graded where the line turns), and the check of the solver's answer.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace uc {

class LineProfile {
public:
    struct Segment {
        double length;  // unstretched [m]
        double weight;  // submerged weight per unstretched length [N/m] (negative: buoyant)
        double EA;      // [N]
        double dryWeight = NAN;  // weight per unstretched length in air [N/m] (NaN: `weight`)
    };
    struct PointLoad {
        double s;       // unstretched arc length from the top end [m]
        double weight;  // submerged weight [N] (negative: a buoy)
        double dryWeight = NAN;  // weight in air [N] (NaN: `weight`)
    };

    // Segments in order from the top end. With `seabed`, a lower end within `onSeabed` of the seabed
    // at z = seabedZ rests on it, and so does the line from there up to the touchdown. False, with the
    // reason in `why`, where no profile applies: both ends on one vertical, or a line that rests on
    // the seabed with no tension at all (longer than the way down and across), or no solution found.
    // Above the water surface at z = surfaceZ the line and its point loads weigh their dry weight,
    // below it their submerged weight (the surface splits a piece where the line crosses it).
    bool solve(const Eigen::Vector3d& top, const Eigen::Vector3d& bottom, const std::vector<Segment>& segments,
               const std::vector<PointLoad>& points, bool seabed, double seabedZ, double onSeabed,
               std::string* why = nullptr, double surfaceZ = INFINITY);
    // A sloped plane seabed for the next solve: the horizontal gradient (dz/dx, dz/dy) of its height,
    // seabedZ then being its height under the lower end. In the vertical plane of the ends it rises
    // towards the top end by tan(beta) = gradient . u per metre across; a frictionless slope: the
    // resting line's tension changes by w sin(beta) per length along it, and it leaves the seabed
    // where its tangent leaves the slope (V = H tan(beta)).
    void set_seabed_gradient(const Eigen::Vector2d& gradient) { gradient_ = gradient; }

    // Position and unit tangent (pointing from the top end towards the lower end) at unstretched
    // arc length s from the top end.
    void at(double s, Eigen::Vector3d& r, Eigen::Vector3d& tangent) const;
    double length() const { return length_; }
    // Arc length from the top end where the line first reaches the seabed (length(): it does not
    // rest), and every point where it reaches or leaves it (or a point load rests on it), from the top.
    double touchdown() const;
    std::vector<double> contacts() const;
    double grounded_length() const { return grounded_; }
    bool rests_at_bottom() const { return !pieces_.empty() && pieces_.front().grounded; }
    // Tension [N] just above arc length s (from the top), and the forces of the line on its ends.
    double tension(double s) const;
    Eigen::Vector3d top_force() const;
    Eigen::Vector3d bottom_force() const;
    // Angle [rad] the tangent turns through from the top end to arc length s, leaving out the
    // corners at point loads.
    double turning(double s) const;
    // Lowest height of the hanging part above the seabed [m] (negative: it would pass through it;
    // -infinity where the contacts of the hanging line could not be solved, and the profile is a
    // guess that passes below the seabed).
    double lowest_clearance() const { return clearance_; }

private:
    // A piece of constant weight per length between breakpoints, walked from the lower end.
    struct Piece {
        double u0, length;  // from the lower end [m]
        double weight, EA;
        double V0;          // vertical tension at its lower end (after a point load there)
        double x0, z0;      // position of its lower end in the plane (x from the lower end to the top)
        bool grounded;
        // horizontal tension of a hanging piece [N]; on a grounded one the tension along the slope
        // is H cos(beta) + V sin(beta), V growing by the weight from V0 (H: the hanging part's above)
        double H;
    };
    // The pieces for H, v and the rests of the contacts after the lower end's (the j-th local
    // minimum of the hanging line: inside a piece its resting length, at a point load the seabed's
    // reaction there); the heights of those minima into `minima`.
    void walk(double H, double v, const std::vector<double>& rests, std::vector<Piece>& pieces, double& x, double& z,
              std::vector<double>* minima) const;
    void piece_offset(const Piece& p, double l, double& dx, double& dz) const;
    double grounded_tension(const Piece& p, double l) const;  // along the slope at l into piece p
    // Length along piece p (of length l) to where it first crosses the surface, from the side
    // `inAir` says it starts on; l where it does not.
    double surface_crossing(const Piece& p, double l, bool inAir) const;
    const Piece& piece_at(double u) const;
    // The solution's pieces, grounded length and clearance (-infinity where it is not exact).
    void settle(double H, double v, const std::vector<double>& rests, bool exact);

    std::vector<Segment> segments_;  // from the lower end
    std::vector<PointLoad> points_;  // arc length from the lower end
    std::vector<Piece> pieces_;
    Eigen::Vector3d bottom_ = Eigen::Vector3d::Zero(), u_ = Eigen::Vector3d::UnitX();
    double length_ = 0.0, H_ = 0.0, grounded_ = 0.0, clearance_ = 0.0, seabedHeight_ = 0.0;
    double surfaceHeight_ = INFINITY;  // of the water surface above the lower end [m]
    bool seabed_ = false;    // the lower end rests on the seabed
    bool seabedOn_ = false;  // there is a seabed
    Eigen::Vector2d gradient_ = Eigen::Vector2d::Zero();  // of the seabed's height (set_seabed_gradient)
    double slope_ = 0.0, cosSlope_ = 1.0, sinSlope_ = 0.0;  // tan, cos, sin of beta in the plane
};

}  // namespace uc
