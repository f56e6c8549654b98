// hermite_element.h - cubic Hermite cable element: shape functions, quadrature, and the
// internal forces (axial, bending) with their exact Jacobians (docs/model.md).
//
// Element DOF order (12): [r_i, r'_i, r_j, r'_j], each a 3-vector; block a = 0..3.
// r(xi) = H1 r_i + l H2 r'_i + H3 r_j + l H4 r'_j,  xi = (s - s_i)/l in [0, 1].
// Every force here is a *residual* contribution: R = M r'' + f_internal - f_external.
#pragma once

#include "core/types.h"
#include "terms/axial_curve.h"
#include "terms/syrope.h"

namespace uc {

// Scalar shape functions N_a and their arc-length derivatives dN_a/ds, d2N_a/ds2 at one point.
struct ShapeValues {
    double N[4];
    double dN[4];
    double d2N[4];
};

ShapeValues hermite_shape(double xi, double length);

// Gauss-Legendre rule mapped to [0, 1]; weights sum to 1. n = 1..5.
struct GaussRule {
    int n;
    double xi[5];
    double w[5];
};

GaussRule gauss_rule(int n);

// A quadrature point of an element: shape values and weight * element length.
struct QuadPoint {
    ShapeValues shape;
    double weight;  // w * l: integrates over unstretched arc length
};

// Precomputed, immutable element tables of one element length (one per run of equal elements).
struct ElementTables {
    double length = 0.0;
    // Axial strain: sampled at 5 Gauss points and projected (L2, per element) onto the first
    // `axialModes` Legendre polynomials; the tension is the projected field. Projecting onto
    // fewer modes than the strain has removes membrane locking (docs/model.md).
    static constexpr int nAxial = 5;
    QuadPoint axial[nAxial];
    int axialModes = 3;
    double axialModeWeight[3] = {1.0, 1.0, 1.0};  // stiffness factor of each projected strain mode
    double legendre[3][nAxial];  // orthonormal Legendre polynomials on [0, 1] at the axial points
    int nLoad = 0;
    QuadPoint load[5];
    // Seabed contact: nContact points (3-point Gauss rules on equal intervals) when the line asks
    // for contact sampled more densely than the axial points (seabedContactSpacing); 0: the axial
    // points serve.
    static constexpr int kMaxContact = 48;
    int nContact = 0;
    QuadPoint contact[kMaxContact];
    Mat4 mass;     // int N_a N_b ds (exact)
    Mat4 bending;  // int N''_a N''_b ds (exact)
};

// contactSpacing > 0: seabed contact sampled at most that far apart (see ElementTables::contact).
ElementTables make_element_tables(double length, int loadPoints, int axialModes, double contactSpacing = 0.0);

// The matrix of the cross product with v: skew(v) w = v x w.
inline Mat3 skew(const Vec3& v) {
    Mat3 m;
    m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return m;
}

// Interpolates a 3-vector field from the element's 12 nodal values.
inline Vec3 interpolate(const double (&N)[4], const double* X) {
    Vec3 r = Vec3::Zero();
    for (int a = 0; a < 4; ++a) r += N[a] * Eigen::Map<const Vec3>(X + 3 * a);
    return r;
}

// Axial tension P = EA (|r'| - 1) + c d|r'|/dt, projected (see ElementTables); with a curve the
// mean strain mode's elastic part is curve(mean strain). Two-sided
// (compression allowed) by default; tension-only (a chain or rope that goes slack) when
// tensionOnly is set: the element's mean tension is slack_law(P mean), a C1 ramp that equals it
// above kSlackStrain EA and is 0 below -kSlackStrain EA (so the law shifts the stretch by at most
// kSlackStrain where it matters); the softened higher strain modes stay two-sided.
// MoorDyn's viscoelastic (static-dynamic) axial model of a fibre rope (docs/model.md, "Viscoelastic
// axial model"): a Kelvin-Voigt pair (spring EA_1, dashpot c = the line's axial damping) in series with
// a second pair (spring EA_2, dashpot c_d). The element's internal strain e1 is the first pair's: the
// tension is EA_1 e1 + c e1', and the pairs carry the same tension,
//   (c + c_d) e1' = EA_2 e - (EA_1 + EA_2) e1 + c_d e',   e the element's mean strain.
// At rest EA_2 e = (EA_1 + EA_2) e1: the static stiffness is EA_s, the series of the two springs. EA_2 is
// the dynamic stiffness EA_d, constant, or with a slope beta in the mean load EA_1 e1 (MoorDyn's
// EA_s|EA_Dc|EA_D_Lm): EA_2 = EA_d + beta EA_1 e1, EA_1 = EA_2 EA_s / (EA_2 - EA_s).
struct ViscoProps {
    double EAs = 0.0;      // static stiffness [N]
    double EAd = 0.0;      // dynamic stiffness (with slope: its value at zero mean load) [N], > EAs
    double slope = 0.0;    // beta [-]: d EA_2 / d(mean load)
    double dampingDynamic = 0.0;  // c_d [N s]
};

// EA_1, EA_2 at the internal strain e1 and their derivatives in e1.
struct ViscoStiffness {
    double EA1, EA2, dEA1, dEA2;
};
ViscoStiffness visco_stiffness(const ViscoProps& v, double e1);

// The complex modulus of the model at the angular frequency w (constant EA_2): the tension per unit
// harmonic strain, T = E(w) e, E = (EA_1 + i w c)(EA_2 + i w c_d) / (EA_1 + EA_2 + i w (c + c_d)).
// storage: Re E, loss: Im E.
void visco_modulus(const ViscoProps& v, double damping, double w, double& storage, double& loss);

struct AxialProps {
    double EA;
    double damping;
    // Caps every strain mode's stiffness factor (the static solver starts on a soft cable).
    double modeCap = 1.0;
    bool tensionOnly = false;
    // A non-linear stiffness (null: the constant EA): the element's mean strain mode carries
    // curve(strain) instead of EA strain; its higher (softened) modes keep EA, the curve's secant.
    const AxialCurve* curve = nullptr;
    // The viscoelastic model (null: none): the mean strain mode carries EA_1 e1 + damping e1' with the
    // element's internal strain e1 and its rate e1' (internal[0], internal[1]), the higher modes EA (EA_s).
    const ViscoProps* visco = nullptr;
    double internal[2] = {0.0, 0.0};
    // The Syrope model (with visco set; null: none): the internal strain is the slow strain z, the mean mode
    // carries T(z) + damping z' with T on the curves of the element's history eps_max (terms/syrope.h).
    const SyropeProps* syrope = nullptr;
    double history = 0.0;
};

constexpr double kSlackStrain = 1e-5;

// The tension-only law T(P) and its slope dT/dP, for the half-width `width` of the ramp:
// 0 below -width, (P + width)^2 / (4 width) inside, P above.
struct SlackLaw {
    double tension, slope;
};
inline SlackLaw slack_law(double P, double width) {
    if (P >= width) return {P, 1.0};
    if (P <= -width) return {0.0, 0.0};
    const double u = P + width;
    return {u * u / (4.0 * width), u / (2.0 * width)};
}

// Adds int T t dN_a ds (t = r'/|r'|, T the projected tension) to R (12 values).
void add_axial_force(const ElementTables& e, const AxialProps& p, const double* X, const double* Xd,
                     double* R);
// Adds dR/dX to K and dR/dXdot to C.
void add_axial_jacobian(const ElementTables& e, const AxialProps& p, const double* X, const double* Xd,
                        Mat12& K, Mat12& C);
// Projected tension at the ElementTables::nAxial sampling points; rp (may be null) receives r' there.
void axial_tensions(const ElementTables& e, const AxialProps& p, const double* X, const double* Xd,
                    double* T, Vec3* rp = nullptr);
// The viscoelastic element's internal equation (its residual, in N): (c + c_d) e1' - EA_2 e + (EA_1 + EA_2) e1
// - c_d e', with e the mean strain mode (p.visco set); Syrope's (p.syrope set): (c + c_d) z' - (alpha + beta T)
// (e - eps_c(T)) - c_d e', T = T(z).
double visco_residual(const ElementTables& e, const AxialProps& p, const double* X, const double* Xd);
// Its couplings: the element's 12 residuals in e1 (dR_de1) and e1' (dR_dr1); the internal residual in X
// (dI_dX), Xdot (dI_dXd), e1 (dI_de1) and e1' (dI_dr1).
struct ViscoJacobian {
    double dR_de1[12], dR_dr1[12], dI_dX[12], dI_dXd[12];
    double dI_de1, dI_dr1;
};
void visco_jacobian(const ElementTables& e, const AxialProps& p, const double* X, const double* Xd, ViscoJacobian& J);
// Axial strain energy 0.5 EA int (projected strain)^2 ds, the curve's energy for the mean mode (for tests).
double axial_energy(const ElementTables& e, const AxialProps& p, const double* X);

// Bending: R_a += EI sum_b B_ab X_b with B = int N''_a N''_b ds, energy 0.5 EI int |r''|^2 ds.
void add_bending_force(const ElementTables& e, double EI, const double* X, double* R);
void add_bending_jacobian(const ElementTables& e, double EI, Mat12& K);
double bending_energy(const ElementTables& e, double EI, const double* X);

// Torque H (constant along the cable, Garrett's rod; the paper's eq. 9):
// the strong-form term -(H r' x r'')' gives, after integration by parts, the residual
// R_a -= H int (r' x r'') dN_a ds. Its Jacobian is not symmetric (a constant torque is not
// conservative under general end conditions).
void add_torque_force(const ElementTables& e, double H, const double* X, double* R);
void add_torque_jacobian(const ElementTables& e, double H, const double* X, Mat12& K);

// Structural (consistent) mass: R_a += m sum_b M_ab Xdd_b.
void add_mass_force(const ElementTables& e, double massPerLength, const double* Xdd, double* R);
void add_mass_jacobian(const ElementTables& e, double massPerLength, Mat12& M);

}  // namespace uc
