// catenary.h - the inextensible catenary of a heavy uniform line between two fixed points, with
// its lower part lying on a flat seabed where it reaches it: the starting shape of the static
// solver for moorings (docs/model.md, statics). Neither stretch nor bending nor current: a guess
// near the equilibrium, from which the solver does not wander into another one.
#pragma once

#include <Eigen/Dense>

namespace uc {

class Catenary {
public:
    // The line of unstretched `length` from `top` to `bottom` (the lower end), hanging in their
    // vertical plane; with a seabed at z = seabedZ that `bottom` lies on (within `onSeabed`), the
    // part that does not hang lies on it towards `bottom`. False (and nothing to evaluate) where no
    // catenary applies: the line no longer than the chord, the ends on one vertical, or so slack
    // that it would hang down to the seabed and lie back up to the top.
    bool solve(const Eigen::Vector3d& top, const Eigen::Vector3d& bottom, double length, bool seabed,
               double seabedZ, double onSeabed);

    // Position and unit tangent (pointing from the top end towards the bottom end) at unstretched
    // arc length s from the top end.
    void at(double s, Eigen::Vector3d& r, Eigen::Vector3d& tangent) const;

    double laid_length() const { return laid_; }  // on the seabed [m]
    double parameter() const { return a_; }       // H / w [m]

private:
    Eigen::Vector3d bottom_ = Eigen::Vector3d::Zero(), u_ = Eigen::Vector3d::UnitX();  // u: horizontal, bottom -> top
    double length_ = 0.0, a_ = 0.0, laid_ = 0.0;
    double vertex_ = 0.0;  // horizontal distance of the vertex from the bottom end (its start on the seabed)
};

}  // namespace uc
