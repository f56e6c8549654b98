// Shape functions, quadrature, and each element term against the finite difference of its
// energy (forces) or of its force (Jacobians).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "terms/hermite_element.h"
#include "terms/hydrodynamics.h"
#include "terms/seabed.h"

using namespace uc;

namespace {

// A bent, stretched, twisted element configuration: nodal r and r' of a helix-like curve.
Vec12 curved_element(double l, double stretch) {
    Vec12 X;
    auto curve = [&](double s) { return Vec3(stretch * s, 0.3 * std::sin(s / 3.0), -0.2 * s * s / 10.0); };
    auto tangent = [&](double s) { return Vec3(stretch, 0.1 * std::cos(s / 3.0), -0.04 * s); };
    X.segment<3>(0) = curve(1.0);
    X.segment<3>(3) = tangent(1.0);
    X.segment<3>(6) = curve(1.0 + l);
    X.segment<3>(9) = tangent(1.0 + l);
    return X;
}

Vec12 random_vector(std::mt19937& rng, double scale) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Vec12 v;
    for (int i = 0; i < 12; ++i) v[i] = scale * u(rng);
    return v;
}

// Central difference; the error is O(h^2) times third derivatives: relative 1e-6 is the bound
// for h = 1e-6 relative perturbations of smooth functions of O(1) curvature.
template <class F>
Vec12 numerical_gradient(F&& energy, Vec12 X, double h) {
    Vec12 g;
    for (int i = 0; i < 12; ++i) {
        const double xi = X[i];
        X[i] = xi + h;
        const double ep = energy(X);
        X[i] = xi - h;
        const double em = energy(X);
        X[i] = xi;
        g[i] = (ep - em) / (2 * h);
    }
    return g;
}

}  // namespace

TEST(HermiteShape, InterpolatesNodalValuesAndSlopes) {
    const double l = 2.5;
    const ShapeValues a = hermite_shape(0.0, l), b = hermite_shape(1.0, l);
    const double expectA[4] = {1, 0, 0, 0}, expectB[4] = {0, 0, 1, 0};
    const double slopeA[4] = {0, 1, 0, 0}, slopeB[4] = {0, 0, 0, 1};
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(a.N[k], expectA[k], 1e-15);
        EXPECT_NEAR(b.N[k], expectB[k], 1e-15);
        EXPECT_NEAR(a.dN[k], slopeA[k], 1e-15);
        EXPECT_NEAR(b.dN[k], slopeB[k], 1e-15);
    }
}

TEST(HermiteShape, ReproducesCubicsExactly) {
    // r(s) = s^3 - 2 s^2 + s + 1 on [0.5, 0.5 + l]: cubic Hermite interpolation is exact.
    const double s0 = 0.5, l = 1.7;
    auto f = [](double s) { return s * s * s - 2 * s * s + s + 1; };
    auto df = [](double s) { return 3 * s * s - 4 * s + 1; };
    auto d2f = [](double s) { return 6 * s - 4; };
    const double X[4] = {f(s0), df(s0), f(s0 + l), df(s0 + l)};
    for (double xi : {0.1, 0.37, 0.5, 0.8}) {
        const ShapeValues sv = hermite_shape(xi, l);
        double v = 0, dv = 0, d2v = 0;
        for (int a = 0; a < 4; ++a) {
            v += sv.N[a] * X[a];
            dv += sv.dN[a] * X[a];
            d2v += sv.d2N[a] * X[a];
        }
        const double s = s0 + xi * l;
        EXPECT_NEAR(v, f(s), 1e-13);
        EXPECT_NEAR(dv, df(s), 1e-13);
        EXPECT_NEAR(d2v, d2f(s), 1e-12);
    }
}

TEST(GaussRule, IntegratesPolynomialsOfDegree2nMinus1) {
    for (int n = 1; n <= 5; ++n) {
        const GaussRule rule = gauss_rule(n);
        for (int degree = 0; degree <= 2 * n - 1; ++degree) {
            double sum = 0;
            for (int g = 0; g < n; ++g) sum += rule.w[g] * std::pow(rule.xi[g], degree);
            EXPECT_NEAR(sum, 1.0 / (degree + 1), 1e-15) << "n = " << n << ", degree = " << degree;
        }
    }
}

TEST(ElementTables, MassMatrixIntegratesToTotalMass) {
    // Rigid translation: sum over position shape functions is 1, so 1^T M_pos 1 = l.
    const double l = 3.0;
    const ElementTables e = make_element_tables(l, 3, 3);
    EXPECT_NEAR(e.mass(0, 0) + e.mass(0, 2) + e.mass(2, 0) + e.mass(2, 2), l, 1e-13);
    // Classical consistent beam mass: M_11 = 13 l / 35.
    EXPECT_NEAR(e.mass(0, 0), 13.0 * l / 35.0, 1e-13);
    // Classical beam stiffness: K_11 = 12 / l^3.
    EXPECT_NEAR(e.bending(0, 0), 12.0 / (l * l * l), 1e-12);
}

TEST(AxialTerm, ForceIsGradientOfStrainEnergy) {
    const double l = 2.0, EA = 1e5;
    const ElementTables e = make_element_tables(l, 3, 3);
    const Vec12 X = curved_element(l, 1.01);
    Vec12 R = Vec12::Zero();
    const Vec12 zero = Vec12::Zero();
    add_axial_force(e, AxialProps{EA, 0.0}, X.data(), zero.data(), R.data());
    const Vec12 g = numerical_gradient([&](const Vec12& x) { return axial_energy(e, AxialProps{EA, 0.0}, x.data()); }, X, 1e-6);
    EXPECT_LT((R - g).norm(), 1e-6 * R.norm());
}

TEST(BendingTerm, ForceIsGradientOfBendingEnergy) {
    const double l = 2.0, EI = 300.0;
    const ElementTables e = make_element_tables(l, 3, 3);
    const Vec12 X = curved_element(l, 1.0);
    Vec12 R = Vec12::Zero();
    add_bending_force(e, EI, X.data(), R.data());
    const Vec12 g = numerical_gradient([&](const Vec12& x) { return bending_energy(e, EI, x.data()); }, X, 1e-6);
    EXPECT_LT((R - g).norm(), 1e-7 * R.norm());
}

TEST(AxialTerm, StraightStretchedElementCarriesEAEpsilon) {
    // Hand calculation: uniform strain eps gives T = EA eps; the nodal forces are -T t and +T t.
    const double l = 5.0, EA = 2e6, eps = 1e-3;
    const ElementTables e = make_element_tables(l, 3, 3);
    const Vec3 t = Vec3(1, 2, 2) / 3.0;
    Vec12 X;
    X << 0, 0, 0, (1 + eps) * t, (1 + eps) * l * t, (1 + eps) * t;
    Vec12 R = Vec12::Zero();
    const Vec12 zero = Vec12::Zero();
    add_axial_force(e, AxialProps{EA, 0.0}, X.data(), zero.data(), R.data());
    const Vec3 expectedEnd = EA * eps * t;
    EXPECT_LT((R.segment<3>(6) - expectedEnd).norm(), 1e-9 * EA * eps);
    EXPECT_LT((R.segment<3>(0) + expectedEnd).norm(), 1e-9 * EA * eps);
    EXPECT_LT(R.segment<3>(3).norm(), 1e-9 * EA * eps);  // no moment at the nodes
    EXPECT_LT(R.segment<3>(9).norm(), 1e-9 * EA * eps);
}

namespace {

// Finite-difference check of a 12x12 Jacobian: column by column, central differences.
template <class F>
void expect_jacobian_matches(F&& force, const Vec12& X, const Mat12& J, double h, double relTol,
                             const char* what) {
    Mat12 numeric;
    for (int i = 0; i < 12; ++i) {
        Vec12 xp = X, xm = X;
        xp[i] += h;
        xm[i] -= h;
        numeric.col(i) = (force(xp) - force(xm)) / (2 * h);
    }
    const double scale = std::max(J.norm(), 1e-300);
    EXPECT_LT((J - numeric).norm(), relTol * scale) << what << "\nanalytic\n" << J << "\nnumeric\n" << numeric;
}

// The axial term's Jacobians dR/dX and dR/dXdot against central differences of its force.
void expect_axial_jacobian_matches(const ElementTables& e, const AxialProps& props, const Vec12& X,
                                   const Vec12& Xd, double h, double tolX, double tolV) {
    Mat12 K = Mat12::Zero(), C = Mat12::Zero();
    add_axial_jacobian(e, props, X.data(), Xd.data(), K, C);
    auto forceX = [&](const Vec12& x) {
        Vec12 R = Vec12::Zero();
        add_axial_force(e, props, x.data(), Xd.data(), R.data());
        return R;
    };
    auto forceV = [&](const Vec12& v) {
        Vec12 R = Vec12::Zero();
        add_axial_force(e, props, X.data(), v.data(), R.data());
        return R;
    };
    expect_jacobian_matches(forceX, X, K, h, tolX, "dR/dX");
    expect_jacobian_matches(forceV, Xd, C, h, tolV, "dR/dXdot");
}

}  // namespace

TEST(AxialTerm, JacobianMatchesFiniteDifferences) {
    const double l = 2.0;
    const AxialProps props{1e5, 3e3};
    const ElementTables e = make_element_tables(l, 3, 3);
    std::mt19937 rng(7);
    const Vec12 X = curved_element(l, 1.02);
    const Vec12 Xd = random_vector(rng, 0.5);
    expect_axial_jacobian_matches(e, props, X, Xd, 1e-6, 1e-6, 1e-8);
}

TEST(AxialTerm, ProjectedStrainJacobianMatchesFiniteDifferences) {
    // The cable's own setting: mean strain at full EA, higher modes softened, and a mode cap
    // as used by the static solver.
    const double l = 3.0;
    ElementTables e = make_element_tables(l, 3, 3);
    e.axialModeWeight[1] = e.axialModeWeight[2] = 0.01;
    std::mt19937 rng(9);
    const Vec12 X = curved_element(l, 1.03);
    const Vec12 Xd = random_vector(rng, 0.5);
    for (double cap : {1.0, 0.05}) {
        const AxialProps props{1e5, 2e3, cap};
        expect_axial_jacobian_matches(e, props, X, Xd, 1e-6, 1e-6, 1e-8);
        Vec12 R = Vec12::Zero();
        const Vec12 zero = Vec12::Zero();
        add_axial_force(e, props, X.data(), zero.data(), R.data());
        const Vec12 g = numerical_gradient([&](const Vec12& x) { return axial_energy(e, props, x.data()); }, X, 1e-6);
        EXPECT_LT((R - g).norm(), 1e-6 * R.norm());
    }
}

namespace {

// A straight element along t whose stretch |r'| runs from 1 + e0 at node 0 to 1 + e1 at node 1
// (nodal tangents of those lengths, the node distance their mean), bent by `bend` at the nodes.
Vec12 graded_element(double l, double e0, double e1, double bend = 1e-3) {
    const Vec3 t = Vec3(1, 2, 2) / 3.0, n = Vec3(2, 1, -2) / 3.0;
    Vec12 X;
    X << 0, 0, 0, (1 + e0) * t + bend * n, (1 + 0.5 * (e0 + e1)) * l * t, (1 + e1) * t - bend * n;
    return X;
}

}  // namespace

TEST(AxialTerm, TensionOnlyLawIsAC1RampBetweenSlackAndTheTwoSidedLaw) {
    const double w = 2.0;
    EXPECT_EQ(slack_law(-5.0, w).tension, 0.0);
    EXPECT_EQ(slack_law(-5.0, w).slope, 0.0);
    EXPECT_EQ(slack_law(7.0, w).tension, 7.0);
    EXPECT_EQ(slack_law(7.0, w).slope, 1.0);
    EXPECT_DOUBLE_EQ(slack_law(0.0, w).tension, w / 4.0);  // the largest change of the law: w / 4
    EXPECT_DOUBLE_EQ(slack_law(0.0, w).slope, 0.5);
    for (double P : {-w, w}) {  // value and slope continuous at both ends of the ramp
        const double d = 1e-9 * w;
        EXPECT_NEAR(slack_law(P - d, w).tension, slack_law(P + d, w).tension, 2.001 * d);  // slope <= 1
        EXPECT_NEAR(slack_law(P - d, w).slope, slack_law(P + d, w).slope, 1e-8);
    }
}

TEST(AxialTerm, TensionOnlyElementCarriesNoCompressionAndAllTension) {
    const double l = 5.0, EA = 2e6;
    const ElementTables e = make_element_tables(l, 3, 3);
    const Vec12 zero = Vec12::Zero();
    AxialProps props{EA, 0.0};
    props.tensionOnly = true;
    for (double eps : {-1e-3, 1e-3}) {
        const Vec12 X = graded_element(l, eps, eps, 0.0);  // straight, uniform strain
        Vec12 R = Vec12::Zero(), R2 = Vec12::Zero();
        add_axial_force(e, props, X.data(), zero.data(), R.data());
        add_axial_force(e, AxialProps{EA, 0.0}, X.data(), zero.data(), R2.data());
        if (eps < 0)  // 1e-3 compression is 100 ramp widths below zero: slack (round-off remains)
            EXPECT_LT(R.norm(), 1e-12 * EA);
        else
            EXPECT_EQ((R - R2).norm(), 0.0);  // above the ramp the law is the two-sided one, bit for bit
    }
}

TEST(AxialTerm, TensionOnlyJacobianMatchesFiniteDifferences) {
    // Mean stretch slack, inside the ramp and taut, graded along the element (the higher strain
    // modes, two-sided), with strain rates of the ramp's size (damping 2 % of EA per 1/s). The law
    // is piecewise quadratic: central differences are exact up to round-off unless a perturbation
    // crosses a ramp end, so h = 1e-9 (round-off ~ eps F / h = 1e-7 of the entries).
    const double l = 3.0;
    ElementTables e = make_element_tables(l, 3, 3);
    e.axialModeWeight[1] = e.axialModeWeight[2] = 0.01;
    std::mt19937 rng(11);
    const Vec12 Xd = random_vector(rng, 2e-5);
    for (double cap : {1.0, 0.05}) {
        AxialProps props{1e5, 2e3, cap};
        props.tensionOnly = true;
        const double width = kSlackStrain * props.EA * cap;
        for (double mean : {-3.0, 0.3, 3.0}) {  // mean strain in ramp half-widths
            const double m = mean * kSlackStrain, grading = 50.0 * kSlackStrain;
            const Vec12 X = graded_element(l, m - grading, m + grading);
            double T[ElementTables::nAxial];
            axial_tensions(e, props, X.data(), Xd.data(), T);
            double Tmean = 0.0;
            for (int g = 0; g < ElementTables::nAxial; ++g) Tmean += e.axial[g].weight / l * T[g];
            if (mean < -1.0) {
                EXPECT_NEAR(Tmean, 0.0, 1e-12 * width);  // slack: no mean tension, whatever the grading
            } else if (mean > 1.0) {
                EXPECT_GT(Tmean, width);
            } else {
                EXPECT_GT(Tmean, 0.0);
            }
            expect_axial_jacobian_matches(e, props, X, Xd, 1e-9, 1e-5, 1e-5);
        }
    }
}

TEST(HydroTerm, JacobianMatchesFiniteDifferences) {
    const double l = 2.0, d = 0.05;
    FluidProps p{1025.0, 9.81, 4.0, 3.14159265358979 * d * d / 4, d, 1.4, 0.3, 1.0, 0.2, true};
    const ElementTables e = make_element_tables(l, 3, 3);
    std::mt19937 rng(11);
    Vec12 X = curved_element(l, 1.0);
    for (int a : {0, 2}) X[3 * a + 2] -= 10.0;  // submerged
    const Vec12 Xd = random_vector(rng, 1.0), Xdd = random_vector(rng, 0.3);
    CurrentField current;
    current.uniform = Vec3(0.4, -0.2, 0.0);
    Mat12 K = Mat12::Zero(), C = Mat12::Zero(), M = Mat12::Zero();
    add_hydro_jacobian(e, p, current, X.data(), Xd.data(), Xdd.data(), K, C, M);
    auto force = [&](const Vec12& x, const Vec12& v, const Vec12& a) {
        Vec12 R = Vec12::Zero();
        add_hydro_force(e, p, current, x.data(), v.data(), a.data(), R.data());
        return R;
    };
    expect_jacobian_matches([&](const Vec12& x) { return force(x, Xd, Xdd); }, X, K, 1e-6, 1e-6, "dR/dX");
    expect_jacobian_matches([&](const Vec12& v) { return force(X, v, Xdd); }, Xd, C, 1e-6, 1e-6, "dR/dXdot");
    expect_jacobian_matches([&](const Vec12& a) { return force(X, Xd, a); }, Xdd, M, 1e-6, 1e-8, "dR/dXddot");
}

namespace {

// A long graded top element of a line (l = 10 m, d = 0.1 m, 20 kg/m) in a current, moving.
struct WaterlineElement {
    double l = 10.0, d = 0.1, m = 20.0;
    FluidProps p{1025.0, 9.81, m, 3.14159265358979 * d * d / 4, d, 1.2, 0.1, 1.0, 0.3, true};
    ElementTables e = make_element_tables(l, 3, 3);
    CurrentField current;
    WaterlineElement() { current.uniform = Vec3(0.5, -0.3, 0.0); }
    // The element along x whose height is the cubic z(xi) = c0 + c1 xi + c2 xi^2 + c3 xi^3 (xi = s / l).
    Vec12 along(double c0, double c1, double c2, double c3) const {
        Vec12 X;
        const double zj = c0 + c1 + c2 + c3, slopeJ = c1 + 2.0 * c2 + 3.0 * c3;
        X << 0.0, 0.0, c0, 1.0, 0.0, c1 / l, l, 0.5, zj, 1.0, 0.05, slopeJ / l;
        return X;
    }
    Vec12 force(const Vec12& X, const Vec12& Xd, const Vec12& Xdd) const {
        Vec12 R = Vec12::Zero();
        add_hydro_force(e, p, current, X.data(), Xd.data(), Xdd.data(), R.data());
        return R;
    }
    // The Jacobians against central differences; h = 1e-8 m is far below every feature of the
    // load's shape here (the cuts' spacing, 1e-5 m at least), so the bound is round-off.
    void expect_jacobians_match(const Vec12& X, const char* what) const {
        std::mt19937 rng(3);
        const Vec12 Xd = random_vector(rng, 0.5), Xdd = random_vector(rng, 0.2);
        Mat12 K = Mat12::Zero(), C = Mat12::Zero(), M = Mat12::Zero();
        add_hydro_jacobian(e, p, current, X.data(), Xd.data(), Xdd.data(), K, C, M);
        expect_jacobian_matches([&](const Vec12& x) { return force(x, Xd, Xdd); }, X, K, 1e-8, 1e-6, what);
        expect_jacobian_matches([&](const Vec12& v) { return force(X, v, Xdd); }, Xd, C, 1e-8, 1e-6, what);
        expect_jacobian_matches([&](const Vec12& a) { return force(X, Xd, a); }, Xdd, M, 1e-8, 1e-6, what);
    }
};

}  // namespace

// A coarse straight element from 2 m above the water to 8 m below it, at rest: its load is the dry
// weight of its 2 m in air and the submerged weight of its 8 m in water, and the buoyancy of the
// ramp above the surface, where the submerged fraction falls from 1 at z = 0 to 0 at z = d (d / 2 of
// length on a vertical element). Its own three load points (at 0.87, -3.0 and -6.9 m) alone gave
// 2.78 m of dry and 7.22 m of submerged weight.
TEST(HydroTerm, AnElementAcrossTheWaterlineWeighsItsPartInAirDry) {
    WaterlineElement w;
    Vec12 X = Vec12::Zero();
    X.segment<3>(0) = Vec3(0.0, 0.0, 2.0);
    X.segment<3>(3) = Vec3(0.0, 0.0, -1.0);
    X.segment<3>(6) = Vec3(0.0, 0.0, 2.0 - w.l);
    X.segment<3>(9) = Vec3(0.0, 0.0, -1.0);
    w.current = CurrentField();
    const Vec12 zero = Vec12::Zero();
    const Vec12 R = w.force(X, zero, zero);
    const double rhoAg = w.p.rho * w.p.area * w.p.gravity;
    // N_0 + N_2 = 1: the node forces add up to the element's load; exact up to round-off.
    EXPECT_NEAR(R[2] + R[8], w.m * w.p.gravity * w.l - rhoAg * (8.0 + 0.5 * w.d), 1e-12 * w.m * w.p.gravity * w.l);
}

// The element's load and its Jacobian where the line crosses the waterline in every way the cubic
// can: near an end, at both levels of the ramp, six times, and tangentially (a sag or a crest just
// touching z = 0 or z = d from inside the ramp or from outside it).
TEST(HydroTerm, JacobianOfAnElementAcrossTheWaterlineMatchesFiniteDifferences) {
    WaterlineElement w;
    const double d = w.d;
    // Steep, from just above the surface (and just above the ramp) to 8 m down.
    w.expect_jacobians_match(w.along(1e-3, -8.0, 0.0, 0.0), "crossing z = 0 1 mm from its end");
    w.expect_jacobians_match(w.along(d + 1e-3, -8.0, 0.0, 0.0), "crossing z = d 1 mm from its end");
    w.expect_jacobians_match(w.along(-8.0, 8.0 + 0.5 * d, 0.0, 0.0), "ending inside the ramp");
    // d/2 + 60 d (xi - 0.15)(xi - 0.5)(xi - 0.85): crosses z = 0 and z = d three times each.
    const double A = 60.0 * d;
    w.expect_jacobians_match(w.along(0.5 * d - A * 0.06375, A * 0.8275, -A * 1.5, A), "six crossings");
    // A crest or a sag at xi = 0.4 touching a level of the ramp, 1e-4 d inside or outside it.
    for (double level : {0.0, d})
        for (double hair : {-1e-4 * d, 1e-4 * d}) {
            const double c = 2.0;  // curvature of z(xi)
            w.expect_jacobians_match(w.along(level + hair - c * 0.16, 2.0 * c * 0.4, -c, 0.0), "a crest touching");
            w.expect_jacobians_match(w.along(level - hair + c * 0.16, -2.0 * c * 0.4, c, 0.0), "a sag touching");
        }
}

// The load is continuous in the nodes as an element hanging from a tow point rises out of the water
// (its top node on the surface, z = 0, and at the ramp's top, z = d), as a crest of the line rises
// through z = 0 and z = d (two cuts appear at one point), and as the element's Bezier hull first
// reaches the ramp while the line itself stays below it (the load points' rule gives way to the
// exact integral), each approached from either side.
TEST(HydroTerm, TheLoadOfAnElementRisingOutOfTheWaterIsContinuous) {
    WaterlineElement w;
    const double d = w.d, eps = 1e-9, slope = 10.0 * w.m * w.p.gravity * w.l;  // |dR/dz| <= dry weight x l
    const Vec12 zero = Vec12::Zero();
    auto load = [&](const Vec12& X) { return w.force(X, zero, zero); };
    for (double z : {0.0, d}) {
        EXPECT_LT((load(w.along(z + eps, -w.l, 0.0, 0.0)) - load(w.along(z - eps, -w.l, 0.0, 0.0))).norm(), slope * eps) << z;
        EXPECT_LT((load(w.along(z + eps - 0.32, 1.6, -2.0, 0.0)) - load(w.along(z - eps - 0.32, 1.6, -2.0, 0.0))).norm(),
                  slope * eps)
            << "crest at " << z;
    }
    // z(xi) = -0.01 + 0.03 xi - 0.06 xi^2 peaks at -6.25 mm, while the Bezier control height of its
    // tangent at node i, b1 = -0.01 + 0.03 / 3, is 0: the hull reaches the ramp or not.
    for (double turn : {-eps, eps}) {
        const Vec12 X = w.along(-0.01, 0.03 + turn, -0.06, 0.0);
        const Vec12 Y = w.along(-0.01, 0.03 - turn, -0.06, 0.0);
        EXPECT_LT((load(X) - load(Y)).norm(), slope * 2.0 * eps);
    }
}

TEST(HydroTerm, JacobianAcrossTheSurfaceMatchesFiniteDifferences) {
    // Element crossing z = 0 within the one-diameter ramp of the submerged fraction.
    const double l = 0.04, d = 0.05;
    FluidProps p{1025.0, 9.81, 4.0, 3.14159265358979 * d * d / 4, d, 1.4, 0.3, 1.0, 0.2, true};
    const ElementTables e = make_element_tables(l, 3, 3);
    std::mt19937 rng(5);
    Vec12 X;
    X << 0, 0, 0.01, 0.6, 0, -0.8, 0.6 * l, 0, 0.01 - 0.8 * l, 0.6, 0.1, -0.8;
    const Vec12 Xd = random_vector(rng, 1.0), Xdd = random_vector(rng, 0.3);
    Mat12 K = Mat12::Zero(), C = Mat12::Zero(), M = Mat12::Zero();
    const CurrentField current;
    add_hydro_jacobian(e, p, current, X.data(), Xd.data(), Xdd.data(), K, C, M);
    auto force = [&](const Vec12& x) {
        Vec12 R = Vec12::Zero();
        add_hydro_force(e, p, current, x.data(), Xd.data(), Xdd.data(), R.data());
        return R;
    };
    expect_jacobian_matches(force, X, K, 1e-8, 1e-5, "dR/dX across the surface");
}

TEST(HydroTerm, DragOpposesRelativeMotionWithMorisonMagnitudes) {
    // A horizontal cable element moving down at 1 m/s in still water: pure normal drag
    // 0.5 rho Cdn d V^2 upward; moving along itself: tangential drag 0.5 rho Cdt pi d V^2.
    const double d = 0.0332, rho = 1025;
    FluidProps p{rho, 0.0, 2.7, 3.14159265358979 * d * d / 4, d, 1.649, 0.12, 0.0, 0.0, false};
    const Vec3 r(0, 0, -10), t(1, 0, 0), zero = Vec3::Zero();
    const Vec3 normal = point_load(p, r, t, Vec3(0, 0, -1), zero, zero, Mat3::Zero(), false, zero, Mat3::Zero(), nullptr);
    EXPECT_NEAR(-normal.z(), 0.5 * rho * 1.649 * d, 1e-9);  // residual F = -f_drag: drag up, F down
    const Vec3 tangential = point_load(p, r, t, Vec3(1, 0, 0), zero, zero, Mat3::Zero(), false, zero, Mat3::Zero(), nullptr);
    EXPECT_NEAR(tangential.x(), 0.5 * rho * 0.12 * 3.14159265358979 * d, 1e-9);
}

TEST(SeabedTerm, JacobianMatchesFiniteDifferences) {
    // Element lying partly in the contact band and partly below the seabed, sliding sideways.
    const double l = 2.0;
    const ElementTables e = make_element_tables(l, 3, 3);
    SeabedProps p;
    p.enabled = true;
    p.depth = 100.0;
    p.stiffness = 2e5;
    p.damping = 3e3;
    p.friction = 0.6;
    p.smoothing = 0.01;
    std::mt19937 rng(17);
    Vec12 X;
    X << 0, 0, -100.005, 1, 0, -0.004, l, 0.1, -100.012, 1, 0.05, -0.003;
    const Vec12 Xd = random_vector(rng, 0.05);
    Mat12 K = Mat12::Zero(), C = Mat12::Zero();
    add_seabed_jacobian(e, p, X.data(), Xd.data(), K, C);
    auto force = [&](const Vec12& x, const Vec12& v) {
        Vec12 R = Vec12::Zero();
        add_seabed_force(e, p, x.data(), v.data(), R.data());
        return R;
    };
    // h = 1e-7: well inside the 1 cm contact band, so the C1 blend is smooth at this scale.
    expect_jacobian_matches([&](const Vec12& x) { return force(x, Xd); }, X, K, 1e-7, 1e-6, "dR/dX");
    expect_jacobian_matches([&](const Vec12& v) { return force(X, v); }, Xd, C, 1e-7, 1e-6, "dR/dXdot");
}

TEST(SeabedTerm, ElementsAboveTheContactBandAreSkippedWithoutChangingABit) {
    // add_seabed_force / add_seabed_jacobian skip an element whose Bezier hull is above the contact
    // band. Against the sum over every sampling point, for random elements around the band (nodes
    // above it whose sag dips into it included): the same numbers, bit for bit.
    const double l = 12.5;
    const ElementTables e = make_element_tables(l, 3, 3);
    SeabedProps p;
    p.enabled = true;
    p.depth = 100.0;
    p.stiffness = 6e5;
    p.damping = 6e4;
    p.friction = 0.3;
    p.smoothing = 0.01;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> height(-0.05, 0.6), slope(-0.25, 0.25);
    int dipping = 0, skipped = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        Vec12 X;
        X << 0, 0, -p.depth + height(rng), 1, 0, slope(rng), l, 0, -p.depth + height(rng), 1, 0, slope(rng);
        const Vec12 Xd = random_vector(rng, 0.5);
        Vec12 R = Vec12::Zero(), Rref = Vec12::Zero();
        Mat12 K = Mat12::Zero(), C = Mat12::Zero(), Kref = Mat12::Zero(), Cref = Mat12::Zero();
        add_seabed_force(e, p, X.data(), Xd.data(), R.data());
        add_seabed_jacobian(e, p, X.data(), Xd.data(), K, C);
        bool touches = false;
        for (int g = 0; g < ElementTables::nAxial; ++g) {
            const QuadPoint& q = e.axial[g];
            SeabedJacobian J;
            const Vec3 F = seabed_load(p, interpolate(q.shape.N, X.data()), interpolate(q.shape.N, Xd.data()), &J);
            if (F.isZero(0.0) && J.dr.isZero(0.0)) continue;
            touches = true;
            for (int a = 0; a < 4; ++a) {
                Rref.segment<3>(3 * a) += (q.weight * q.shape.N[a]) * F;
                for (int b = 0; b < 4; ++b) {
                    const double w = q.weight * q.shape.N[a] * q.shape.N[b];
                    Kref.block<3, 3>(3 * a, 3 * b) += w * J.dr;
                    Cref.block<3, 3>(3 * a, 3 * b) += w * J.drd;
                }
            }
        }
        const bool nodesAbove = std::min(X[2], X[8]) > -p.depth + p.smoothing;
        dipping += nodesAbove && touches;
        skipped += !touches;
        for (int i = 0; i < 12; ++i) ASSERT_EQ(R[i], Rref[i]) << "trial " << trial << ", entry " << i;
        ASSERT_TRUE(K == Kref && C == Cref) << "trial " << trial;
    }
    // both kinds occur: elements clear of the band, and elements whose nodes are clear but not their sag
    EXPECT_GT(dipping, 20);
    EXPECT_GT(skipped, 200);
}

TEST(SeabedTerm, RestingCableCarriesItsWeightAndFrictionOpposesSliding) {
    SeabedProps p;
    p.enabled = true;
    p.depth = 50.0;
    p.stiffness = 1e5;
    p.damping = 0.0;
    p.friction = 0.5;
    p.smoothing = 0.001;
    // 1 cm penetration past the 1 mm ramp: k (p - delta / 2) = 950 N/m up; sliding at 1 m/s along
    // x: friction 475 N/m against it.
    const Vec3 F = seabed_load(p, Vec3(0, 0, -50.01), Vec3(1, 0, 0), nullptr);
    EXPECT_NEAR(-F.z(), 950.0, 1e-9);
    EXPECT_NEAR(F.x(), 475.0 / std::sqrt(1.0 + kFrictionVelocity * kFrictionVelocity), 1e-9);
    // inside the ramp: k p^2 / (2 delta)
    EXPECT_NEAR(-seabed_load(p, Vec3(0, 0, -50.0005), Vec3::Zero(), nullptr).z(), 1e5 * 0.0005 * 0.0005 / 0.002, 1e-9);
    // no force at the seabed or above it
    EXPECT_EQ(seabed_load(p, Vec3(0, 0, -50.0), Vec3(1, 0, 0), nullptr), Vec3::Zero());
    EXPECT_EQ(seabed_load(p, Vec3(0, 0, -49.9995), Vec3(1, 0, 0), nullptr), Vec3::Zero());
}

namespace {

// A sloped plane: the seabed of seabedSlope 12 deg descending along heading 30 deg.
SeabedProps sloped_seabed() {
    SeabedProps p;
    p.enabled = true;
    p.depth = 100.0;
    p.stiffness = 2e5;
    p.damping = 3e3;
    p.friction = 0.6;
    p.smoothing = 0.01;
    set_slope(p, 12.0, 30.0);
    return p;
}

}  // namespace

TEST(SeabedTerm, SlopedJacobianMatchesFiniteDifferences) {
    // An element lying partly in the contact band of a sloped seabed and partly below it, sliding
    // along and across the slope.
    const double l = 2.0;
    const ElementTables e = make_element_tables(l, 3, 3);
    const SeabedProps p = sloped_seabed();
    const Vec3 n = p.normal;
    const Vec3 along = Vec3(0.0, 1.0, 0.0).cross(n).normalized();  // a direction in the plane
    const Vec3 r0 = Vec3(3.0, 1.0, seabed_height(p, 3.0, 1.0)) - 0.005 * n;
    const Vec3 r1 = r0 + l * along - 0.007 * n + 0.1 * n.cross(along);
    Vec12 X;
    X << r0, along - 0.004 * n, r1, along - 0.003 * n;
    std::mt19937 rng(23);
    const Vec12 Xd = random_vector(rng, 0.05);
    Mat12 K = Mat12::Zero(), C = Mat12::Zero();
    add_seabed_jacobian(e, p, X.data(), Xd.data(), K, C);
    ASSERT_GT(K.norm(), 0.0);
    auto force = [&](const Vec12& x, const Vec12& v) {
        Vec12 R = Vec12::Zero();
        add_seabed_force(e, p, x.data(), v.data(), R.data());
        return R;
    };
    expect_jacobian_matches([&](const Vec12& x) { return force(x, Xd); }, X, K, 1e-7, 1e-6, "dR/dX");
    expect_jacobian_matches([&](const Vec12& v) { return force(X, v); }, Xd, C, 1e-7, 1e-6, "dR/dXdot");
}

TEST(SeabedTerm, HoldAcrossTheLineMatchesFiniteDifferencesAndOpposesTheSidewaysOffset) {
    // The statics' static friction on a slope (add_seabed_hold): an element partly in the contact band
    // and partly below it, moved sideways from where it is held; the force opposes the offset across
    // the line, along the surface, and its Jacobian is the residual's derivative.
    const double l = 2.0;
    const ElementTables e = make_element_tables(l, 3, 3);
    const SeabedProps p = sloped_seabed();
    const Vec3 n = p.normal;
    const Vec3 along = Vec3(0.0, 1.0, 0.0).cross(n).normalized();
    const Vec3 across = n.cross(along).normalized();
    const Vec3 r0 = Vec3(3.0, 1.0, seabed_height(p, 3.0, 1.0)) - 0.005 * n;
    const Vec3 r1 = r0 + l * along - 0.007 * n;
    Vec12 held;
    held << r0, along, r1, along;
    Vec12 X = held;
    X.segment<3>(0) += 0.02 * across + 0.03 * along;
    X.segment<3>(6) += 0.05 * across - 0.001 * n;
    X.segment<3>(9) += 0.01 * across;
    auto force = [&](const Vec12& x) {
        Vec12 R = Vec12::Zero();
        add_seabed_hold(e, p, across, x.data(), held.data(), R.data());
        return R;
    };
    const Vec12 R = force(X);
    // the residual is -f: it points along +across for an offset along +across, nothing along the line
    for (int a = 0; a < 4; a += 2) {
        EXPECT_GT(R.segment<3>(3 * a).dot(across), 0.0);
        EXPECT_LT(std::abs(R.segment<3>(3 * a).dot(along)), 1e-12 * R.norm());
        EXPECT_LT(std::abs(R.segment<3>(3 * a).dot(n)), 1e-12 * R.norm());
    }
    EXPECT_EQ(force(held).norm(), 0.0);  // nothing where it is held
    Mat12 K = Mat12::Zero();
    add_seabed_hold_jacobian(e, p, across, X.data(), held.data(), K);
    ASSERT_GT(K.norm(), 0.0);
    expect_jacobian_matches(force, X, K, 1e-7, 1e-6, "dR/dX");
    // lifted clear of the seabed: no hold
    Vec12 lifted = X;
    for (int a = 0; a < 4; a += 2) lifted.segment<3>(3 * a) += 0.5 * n;
    EXPECT_EQ(force(lifted).norm(), 0.0);
}

TEST(SeabedTerm, SlopedContactIsTheFlatOneTurnedOntoTheSlope) {
    // The same penetration and the same velocity relative to the surface give the flat seabed's load
    // turned by the rotation that takes e_z onto the slope's normal: pressure along the normal,
    // friction along the surface, damping on the normal rate.
    SeabedProps flat = sloped_seabed();
    set_slope(flat, 0.0, 0.0);
    const SeabedProps sloped = sloped_seabed();
    const Vec3 n = sloped.normal;
    EXPECT_NEAR(n.z(), std::cos(12.0 * kPi / 180.0), 1e-15);
    EXPECT_NEAR(std::atan2(n.y(), n.x()), 30.0 * kPi / 180.0, 1e-14);  // it leans the way it descends
    const Mat3 turn = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), n).toRotationMatrix();
    for (double depthIn : {0.004, 0.03}) {  // inside the smoothing band and beyond it
        const Vec3 flatPoint(0.0, 0.0, -flat.depth - depthIn), flatVelocity(0.3, -0.2, -0.05);
        SeabedJacobian Jf, Js;
        const Vec3 Ff = seabed_load(flat, flatPoint, flatVelocity, &Jf);
        // the point at that penetration below the sloped plane, above (7, -4)
        const Vec3 onPlane(7.0, -4.0, seabed_height(sloped, 7.0, -4.0));
        const Vec3 Fs = seabed_load(sloped, onPlane - depthIn * n, turn * flatVelocity, &Js);
        EXPECT_LT((Fs - turn * Ff).norm(), 1e-9 * Ff.norm()) << depthIn;
        EXPECT_LT((Js.dr - turn * Jf.dr * turn.transpose()).norm(), 1e-9 * Jf.dr.norm()) << depthIn;
        EXPECT_LT((Js.drd - turn * Jf.drd * turn.transpose()).norm(), 1e-9 * Jf.drd.norm()) << depthIn;
    }
    // nothing above the plane, even below z = -waterDepth where the seabed descends
    const Vec3 x(40.0, 0.0, -101.0);
    ASSERT_LT(seabed_height(sloped, x.x(), x.y()), x.z() - 1.0);
    EXPECT_EQ(seabed_load(sloped, x, Vec3(1.0, 0.0, 0.0), nullptr), Vec3::Zero());
}

TEST(SeabedTerm, SlopedElementsAboveTheContactBandAreSkippedWithoutChangingABit) {
    // The hull test on a sloped plane: against the sum over every sampling point, bit for bit, for
    // random elements around the band.
    const double l = 12.5;
    const ElementTables e = make_element_tables(l, 3, 3);
    const SeabedProps p = sloped_seabed();
    const Vec3 n = p.normal;
    const Vec3 along = Vec3(0.0, 1.0, 0.0).cross(n).normalized();
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> height(-0.05, 0.6), slope(-0.25, 0.25);
    int touched = 0, skipped = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        const Vec3 base(5.0, 2.0, seabed_height(p, 5.0, 2.0));
        Vec12 X;
        X << base + height(rng) * n, along + slope(rng) * n, base + l * along + height(rng) * n, along + slope(rng) * n;
        const Vec12 Xd = random_vector(rng, 0.5);
        Vec12 R = Vec12::Zero(), Rref = Vec12::Zero();
        add_seabed_force(e, p, X.data(), Xd.data(), R.data());
        bool touches = false;
        for (int g = 0; g < ElementTables::nAxial; ++g) {
            const QuadPoint& q = e.axial[g];
            const Vec3 F = seabed_load(p, interpolate(q.shape.N, X.data()), interpolate(q.shape.N, Xd.data()), nullptr);
            if (F.isZero(0.0)) continue;
            touches = true;
            for (int a = 0; a < 4; ++a) Rref.segment<3>(3 * a) += (q.weight * q.shape.N[a]) * F;
        }
        touched += touches;
        skipped += above_contact(e, p, X.data());
        for (int i = 0; i < 12; ++i) ASSERT_EQ(R[i], Rref[i]) << "trial " << trial << ", entry " << i;
    }
    EXPECT_GT(touched, 100);
    EXPECT_GT(skipped, 100);
}

TEST(TorqueTerm, JacobianMatchesFiniteDifferences) {
    const double l = 2.0, H = 35.0;
    const ElementTables e = make_element_tables(l, 3, 3);
    const Vec12 X = curved_element(l, 1.01);
    Mat12 K = Mat12::Zero();
    add_torque_jacobian(e, H, X.data(), K);
    auto force = [&](const Vec12& x) {
        Vec12 R = Vec12::Zero();
        add_torque_force(e, H, x.data(), R.data());
        return R;
    };
    expect_jacobian_matches(force, X, K, 1e-6, 1e-7, "dR/dX");
}

TEST(TorqueTerm, StraightElementCarriesNoTorqueForce) {
    // r' x r'' = 0 on a straight line: a torque alone does not move a straight cable.
    const ElementTables e = make_element_tables(3.0, 3, 3);
    Vec12 X;
    X << 0, 0, 0, 0.6, 0.8, 0, 1.8, 2.4, 0, 0.6, 0.8, 0;
    Vec12 R = Vec12::Zero();
    add_torque_force(e, 100.0, X.data(), R.data());
    EXPECT_LT(R.norm(), 1e-12);
}

// The seabed contact rule of seabedContactSpacing: 3-point Gauss rules on equal intervals of at most
// three spacings, only where that is denser than the five axial points, at most 48 points. Each
// 3-point rule is exact to degree 5, so the rule integrates N_a s^2 (degree 5) as exactly as the
// 5-point axial rule (exact to degree 9) does.
TEST(SeabedContactRule, SamplesAtTheAskedSpacingAndIntegratesDegreeFiveExactly) {
    const double l = 41.7;
    const ElementTables e = make_element_tables(l, 3, 3, 2.0);  // 7 intervals of 5.96 m
    ASSERT_EQ(e.nContact, 21);
    // arc length s at a point: the x coordinate of a straight element along x
    const double straight[12] = {0, 0, 0, 1, 0, 0, l, 0, 0, 1, 0, 0};
    auto arc = [&](const QuadPoint& q) { return interpolate(q.shape.N, straight).x(); };
    double length = 0.0;
    for (int g = 0; g < e.nContact; ++g) length += e.contact[g].weight;
    EXPECT_NEAR(length, l, 1e-12 * l);
    for (int a = 0; a < 4; ++a) {
        double dense = 0.0, axial = 0.0;
        for (int g = 0; g < e.nContact; ++g) dense += e.contact[g].weight * e.contact[g].shape.N[a] * std::pow(arc(e.contact[g]), 2);
        for (int g = 0; g < ElementTables::nAxial; ++g) axial += e.axial[g].weight * e.axial[g].shape.N[a] * std::pow(arc(e.axial[g]), 2);
        EXPECT_NEAR(dense, axial, 1e-12 * std::abs(axial)) << "shape function " << a;
    }
    EXPECT_EQ(make_element_tables(3.125, 3, 3, 2.0).nContact, 0);    // the axial points are closer already
    EXPECT_EQ(make_element_tables(l, 3, 3, 0.0).nContact, 0);        // 0: the axial points
    EXPECT_EQ(make_element_tables(1000.0, 3, 3, 0.5).nContact, 48);  // capped
}

// ------------------------------------------------------------------ non-linear axial stiffness (curve)

namespace {

// A stiffening rope's tension-strain points (its first strain above 0: (0, 0) goes in front).
const double kRopeStrain[] = {0.005, 0.012, 0.03, 0.045};
const double kRopeTension[] = {2.0e4, 6.0e4, 2.3e5, 4.2e5};

AxialCurve rope_curve() {
    AxialCurve c;
    std::string error;
    EXPECT_TRUE(AxialCurve::build(kRopeStrain, kRopeTension, 4, c, error)) << error;
    return c;
}

}  // namespace

TEST(AxialCurve, PassesThroughItsPointsMonotoneAndC1) {
    const AxialCurve c = rope_curve();
    ASSERT_EQ(c.n, 5);
    EXPECT_EQ(c.strain[0], 0.0);
    EXPECT_EQ(c.tension[0], 0.0);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(c(kRopeStrain[k]), kRopeTension[k], 1e-9 * kRopeTension[k]);
    double previous = c(0.0);
    for (int i = 1; i <= 6000; ++i) {  // monotone on a fine grid through and beyond the points
        const double eps = 0.06 * i / 6000.0, T = c(eps);
        EXPECT_GE(T, previous) << "at strain " << eps;
        previous = T;
    }
    for (int k = 1; k < 4; ++k) {  // the slope is continuous at the inner points
        const double d = 1e-10, x = kRopeStrain[k - 1];
        double left, right;
        c(x - d, &left);
        c(x + d, &right);
        EXPECT_NEAR(left, right, 1e-6 * std::max(left, right)) << "at point " << k;
    }
}

TEST(AxialCurve, SlopeIsTheDerivativeAndEnergyIntegratesTheTension) {
    const AxialCurve c = rope_curve();
    for (double eps : {-0.002, 0.003, 0.009, 0.02, 0.04, 0.06}) {
        double slope;
        c(eps, &slope);
        const double h = 1e-8;
        // central differences of a cubic: exact to round-off (eps T / h ~ 1e-8 T)
        EXPECT_NEAR(slope, (c(eps + h) - c(eps - h)) / (2 * h), 1e-5 * std::abs(slope)) << "at strain " << eps;
        EXPECT_NEAR(c(eps), (c.energy(eps + h) - c.energy(eps - h)) / (2 * h), 1e-5 * std::abs(c(eps)) + 1e-3)
            << "at strain " << eps;
        EXPECT_NEAR(c.strain_at(c(eps)), eps, 1e-12);
    }
}

TEST(AxialCurve, IsLinearBeyondItsEndsWithTheEndSlope) {
    const AxialCurve c = rope_curve();
    double endSlope;
    c(0.045, &endSlope);
    EXPECT_NEAR(endSlope, (4.2e5 - 2.3e5) / 0.015, 1e-9 * endSlope);  // Fritsch-Carlson: the end secant
    for (double d : {0.001, 0.05}) {
        double slope;
        EXPECT_NEAR(c(0.045 + d, &slope), 4.2e5 + endSlope * d, 1e-9 * 4.2e5);
        EXPECT_EQ(slope, endSlope);
    }
    double firstSlope;
    c(0.0, &firstSlope);
    EXPECT_NEAR(c(-0.001), -0.001 * firstSlope, 1e-9 * 2e4);  // compression: the first piece's slope
}

TEST(AxialCurve, TwoPointsAreTheConstantEA) {
    const double strain[] = {0.01}, tension[] = {1e5};
    AxialCurve c;
    std::string error;
    EXPECT_FALSE(AxialCurve::build(strain, tension, 1, c, error));  // one point is no curve
    EXPECT_EQ(error, "a tension-strain curve has 2 to 30 points, not 1");
    const double s2[] = {0.0, 0.01}, t2[] = {0.0, 1e5};
    ASSERT_TRUE(AxialCurve::build(s2, t2, 2, c, error)) << error;
    EXPECT_DOUBLE_EQ(c.secant(), 1e7);
    for (double eps : {-0.01, 0.004, 0.02}) EXPECT_NEAR(c(eps), 1e7 * eps, 1e-6);
}

TEST(AxialCurve, RefusesPointsThatMakeNoCurve) {
    AxialCurve c;
    std::string error;
    const double falling[] = {0.0, 1e5, 0.9e5}, up[] = {0.0, 0.01, 0.02};
    EXPECT_FALSE(AxialCurve::build(up, falling, 3, c, error));
    EXPECT_EQ(error, "point 3 (strain 0.02, tension 90000 N): the tension falls from point 2 (a rope whose tension "
                     "falls as it stretches has no unique equilibrium)");
    const double repeated[] = {0.0, 0.01, 0.01}, rising[] = {0.0, 1e5, 2e5};
    EXPECT_FALSE(AxialCurve::build(repeated, rising, 3, c, error));
    EXPECT_NE(error.find("point 3 (strain 0.01, tension 200000 N): the strains increase"), std::string::npos) << error;
    const double preloaded[] = {5e3, 1e5, 2e5};
    EXPECT_FALSE(AxialCurve::build(up, preloaded, 3, c, error));
    EXPECT_EQ(error, "point 1 (strain 0, tension 5000 N): a line carries no tension at zero strain");
    const double negative[] = {-0.01, 0.01, 0.02};
    EXPECT_FALSE(AxialCurve::build(negative, rising, 3, c, error));
}

TEST(AxialTerm, CurveJacobianMatchesFiniteDifferences) {
    // Inside the curve (a mean strain of about 2 %, inside its third piece) and beyond its last point
    // (7 %), two-sided and tension-only, at full stiffness and at the static solver's soft cap.
    const double l = 3.0;
    ElementTables e = make_element_tables(l, 3, 3);
    e.axialModeWeight[1] = e.axialModeWeight[2] = 0.01;
    const AxialCurve curve = rope_curve();
    std::mt19937 rng(13);
    const Vec12 Xd = random_vector(rng, 0.5);
    for (double stretch : {1.02, 1.07}) {
        const Vec12 X = curved_element(l, stretch);
        for (double cap : {1.0, 0.05}) {
            for (bool tensionOnly : {false, true}) {
                AxialProps props{curve.secant(), 3e5, cap, tensionOnly, &curve};  // c_a / EA = 0.03 s
                expect_axial_jacobian_matches(e, props, X, Xd, 1e-6, 1e-6, 1e-8);
            }
        }
    }
}

TEST(AxialTerm, CurveForceIsTheGradientOfItsEnergy) {
    const double l = 3.0;
    ElementTables e = make_element_tables(l, 3, 3);
    e.axialModeWeight[1] = e.axialModeWeight[2] = 0.01;
    const AxialCurve curve = rope_curve();
    const AxialProps props{curve.secant(), 0.0, 1.0, false, &curve};
    const Vec12 zero = Vec12::Zero();
    for (double stretch : {1.02, 1.07}) {
        const Vec12 X = curved_element(l, stretch);
        Vec12 R = Vec12::Zero();
        add_axial_force(e, props, X.data(), zero.data(), R.data());
        const Vec12 g = numerical_gradient([&](const Vec12& x) { return axial_energy(e, props, x.data()); }, X, 1e-6);
        EXPECT_LT((R - g).norm(), 1e-6 * R.norm());
    }
}

TEST(AxialTerm, TwoPointCurveIsTheConstantEA) {
    // A straight line through (0, 0) is the constant EA: the same forces to round-off, compressed or
    // stretched, and the same Jacobian.
    const double l = 2.0, EA = 1e6;
    ElementTables e = make_element_tables(l, 3, 3);
    e.axialModeWeight[1] = e.axialModeWeight[2] = 0.01;
    const double s[] = {0.0, 0.05}, t[] = {0.0, 0.05 * EA};
    AxialCurve curve;
    std::string error;
    ASSERT_TRUE(AxialCurve::build(s, t, 2, curve, error));
    std::mt19937 rng(17);
    const Vec12 Xd = random_vector(rng, 0.5);
    for (double stretch : {0.99, 1.03}) {
        const Vec12 X = curved_element(l, stretch);
        Vec12 R1 = Vec12::Zero(), R2 = Vec12::Zero();
        add_axial_force(e, AxialProps{EA, 5e2}, X.data(), Xd.data(), R1.data());
        add_axial_force(e, AxialProps{EA, 5e2, 1.0, false, &curve}, X.data(), Xd.data(), R2.data());
        EXPECT_LT((R1 - R2).norm(), 1e-12 * R1.norm());
        Mat12 K1 = Mat12::Zero(), C1 = Mat12::Zero(), K2 = Mat12::Zero(), C2 = Mat12::Zero();
        add_axial_jacobian(e, AxialProps{EA, 5e2}, X.data(), Xd.data(), K1, C1);
        add_axial_jacobian(e, AxialProps{EA, 5e2, 1.0, false, &curve}, X.data(), Xd.data(), K2, C2);
        EXPECT_LT((K1 - K2).norm(), 1e-12 * K1.norm());
        EXPECT_EQ(C1, C2);
    }
}
