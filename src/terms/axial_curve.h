// axial_curve.h - a non-linear axial stiffness: the tension as a function of the axial strain, a monotone
// C1 cubic through the points of a tension-strain table (docs/model.md, "Non-linear axial stiffness").
#pragma once

#include <string>

namespace uc {

// Fritsch-Carlson monotone cubic Hermite interpolant of (strain, tension) points: C1, monotone where the
// table is, so the Newton iterations of the integrator and the static solver see a tension whose slope is
// continuous and never negative. Beyond the last point (and below the first) the tension goes on linearly
// with the end's slope. Plain fixed-size data: no allocation, copied with the section that owns it.
struct AxialCurve {
    static constexpr int kMaxPoints = 31;  // the FMU's 30 points, and (0, 0) put in front
    int n = 0;                            // 0: no curve (a constant EA)
    double strain[kMaxPoints] = {};
    double tension[kMaxPoints] = {};
    double slope[kMaxPoints] = {};  // dT/dstrain at each point [N]

    // The curve through n points (strains strictly increasing, tensions non-decreasing, n >= 2); (0, 0)
    // is put in front when the first strain is above 0. False with the reason (which point, its values)
    // when the points do not make a curve.
    static bool build(const double* strain, const double* tension, int n, AxialCurve& curve, std::string& error);

    // The tension at `eps` and, if dT is not null, its slope.
    double operator()(double eps, double* dT = nullptr) const;
    // int_0^eps T de [N]: the strain energy per unstretched length (exact for the cubic pieces).
    double energy(double eps) const;
    // The strain at which the tension is T (the curve inverted; its continuation beyond the ends).
    double strain_at(double T) const;
    // The secant stiffness at the last point, T_n / eps_n [N]: the line's reference EA (scales,
    // tolerances, the higher strain modes of an element).
    double secant() const { return tension[n - 1] / strain[n - 1]; }
    double last_strain() const { return strain[n - 1]; }
};

}  // namespace uc
