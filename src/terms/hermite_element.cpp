// hermite_element.cpp - cubic Hermite element: shape functions, quadrature, axial and bending terms.
#include "terms/hermite_element.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace uc {

ShapeValues hermite_shape(double xi, double l) {
    const double x2 = xi * xi, x3 = x2 * xi;
    ShapeValues s;
    // H1 = 1 - 3x^2 + 2x^3, H2 = x - 2x^2 + x^3 (times l), H3 = 3x^2 - 2x^3, H4 = x^3 - x^2 (times l).
    s.N[0] = 1.0 - 3.0 * x2 + 2.0 * x3;
    s.N[1] = l * (xi - 2.0 * x2 + x3);
    s.N[2] = 3.0 * x2 - 2.0 * x3;
    s.N[3] = l * (x3 - x2);
    // d/ds = (1/l) d/dxi
    s.dN[0] = (-6.0 * xi + 6.0 * x2) / l;
    s.dN[1] = 1.0 - 4.0 * xi + 3.0 * x2;
    s.dN[2] = (6.0 * xi - 6.0 * x2) / l;
    s.dN[3] = 3.0 * x2 - 2.0 * xi;
    s.d2N[0] = (-6.0 + 12.0 * xi) / (l * l);
    s.d2N[1] = (-4.0 + 6.0 * xi) / l;
    s.d2N[2] = (6.0 - 12.0 * xi) / (l * l);
    s.d2N[3] = (6.0 * xi - 2.0) / l;
    return s;
}

GaussRule gauss_rule(int n) {
    // Points and weights on [-1, 1], mapped to [0, 1].
    static constexpr double p1[] = {0.0};
    static constexpr double w1[] = {2.0};
    static constexpr double p2[] = {-0.57735026918962576451, 0.57735026918962576451};
    static constexpr double w2[] = {1.0, 1.0};
    static constexpr double p3[] = {-0.77459666924148337704, 0.0, 0.77459666924148337704};
    static constexpr double w3[] = {0.55555555555555555556, 0.88888888888888888889, 0.55555555555555555556};
    static constexpr double p4[] = {-0.86113631159405257522, -0.33998104358485626480,
                                    0.33998104358485626480, 0.86113631159405257522};
    static constexpr double w4[] = {0.34785484513745385737, 0.65214515486254614263,
                                    0.65214515486254614263, 0.34785484513745385737};
    static constexpr double p5[] = {-0.90617984593866399280, -0.53846931010568309104, 0.0,
                                    0.53846931010568309104, 0.90617984593866399280};
    static constexpr double w5[] = {0.23692688505618908751, 0.47862867049936646804,
                                    0.56888888888888888889, 0.47862867049936646804,
                                    0.23692688505618908751};
    const double* const points[] = {p1, p2, p3, p4, p5};
    const double* const weights[] = {w1, w2, w3, w4, w5};
    if (n < 1) n = 1;
    if (n > 5) n = 5;
    GaussRule rule{};
    rule.n = n;
    for (int i = 0; i < n; ++i) {
        rule.xi[i] = 0.5 * (points[n - 1][i] + 1.0);
        rule.w[i] = 0.5 * weights[n - 1][i];
    }
    return rule;
}

ElementTables make_element_tables(double length, int loadPoints, int axialModes, double contactSpacing) {
    ElementTables e;
    e.length = length;
    e.axialModes = axialModes < 1 ? 1 : (axialModes > 3 ? 3 : axialModes);
    const GaussRule axial = gauss_rule(ElementTables::nAxial);
    for (int g = 0; g < axial.n; ++g) {
        const double xi = axial.xi[g];
        e.axial[g].shape = hermite_shape(xi, length);
        e.axial[g].weight = axial.w[g] * length;
        e.legendre[0][g] = 1.0;
        e.legendre[1][g] = std::sqrt(3.0) * (2.0 * xi - 1.0);
        e.legendre[2][g] = std::sqrt(5.0) * (6.0 * xi * xi - 6.0 * xi + 1.0);
    }
    // Contact sampled at most contactSpacing apart: 3-point rules on intervals of at most three
    // spacings, where that takes more than the five axial points (their largest gap is 0.23 l).
    if (contactSpacing > 0.0) {
        const int intervals = std::min(ElementTables::kMaxContact / 3,
                                       static_cast<int>(std::ceil(length / (3.0 * contactSpacing))));
        if (3 * intervals > ElementTables::nAxial) {
            const GaussRule rule = gauss_rule(3);
            e.nContact = 3 * intervals;
            for (int m = 0; m < intervals; ++m)
                for (int g = 0; g < 3; ++g) {
                    QuadPoint& q = e.contact[3 * m + g];
                    q.shape = hermite_shape((m + rule.xi[g]) / intervals, length);
                    q.weight = rule.w[g] * length / intervals;
                }
        }
    }
    const GaussRule load = gauss_rule(loadPoints);
    e.nLoad = load.n;
    for (int g = 0; g < load.n; ++g) {
        e.load[g].shape = hermite_shape(load.xi[g], length);
        e.load[g].weight = load.w[g] * length;
    }
    // N_a N_b is degree 6 and N''_a N''_b degree 2: 4 points integrate both exactly.
    const GaussRule exact = gauss_rule(4);
    e.mass.setZero();
    e.bending.setZero();
    for (int g = 0; g < exact.n; ++g) {
        const ShapeValues s = hermite_shape(exact.xi[g], length);
        const double w = exact.w[g] * length;
        for (int a = 0; a < 4; ++a) {
            for (int b = 0; b < 4; ++b) {
                e.mass(a, b) += w * s.N[a] * s.N[b];
                e.bending(a, b) += w * s.d2N[a] * s.d2N[b];
            }
        }
    }
    return e;
}

namespace {

// Strain state at the axial sampling points of one element.
struct AxialSamples {
    Vec3 t[ElementTables::nAxial];
    double stretch[ElementTables::nAxial];
    Vec3 rpd[ElementTables::nAxial];
    double strainMode[3] = {0, 0, 0};  // Legendre coefficients of the strain (1/l int eps phi_k ds)
    double rateMode[3] = {0, 0, 0};    // ... and of the strain rate
};

// withDerivatives: also r' at the points into rpOut (a compile-time choice: the residual's and the
// Jacobian's copies stay without it).
template <bool withDerivatives = false>
AxialSamples sample_axial(const ElementTables& e, const double* X, const double* Xd, Vec3* rpOut = nullptr) {
    AxialSamples s;
    const double l = e.length;
    for (int g = 0; g < ElementTables::nAxial; ++g) {
        const QuadPoint& q = e.axial[g];
        const Vec3 rp = interpolate(q.shape.dN, X);
        if constexpr (withDerivatives) rpOut[g] = rp;
        s.rpd[g] = interpolate(q.shape.dN, Xd);
        s.stretch[g] = rp.norm();
        s.t[g] = rp / s.stretch[g];
        const double strain = s.stretch[g] - 1.0, rate = s.t[g].dot(s.rpd[g]);
        for (int k = 0; k < e.axialModes; ++k) {
            s.strainMode[k] += q.weight / l * e.legendre[k][g] * strain;
            s.rateMode[k] += q.weight / l * e.legendre[k][g] * rate;
        }
    }
    return s;
}

double mode_weight(const ElementTables& e, const AxialProps& p, int k) {
    return std::min(e.axialModeWeight[k], p.modeCap);
}

// Half-width of the tension-only ramp: kSlackStrain of the (continuation-scaled) mean-mode EA.
double slack_width(const ElementTables& e, const AxialProps& p) {
    return kSlackStrain * p.EA * mode_weight(e, p, 0);
}

// Tension of strain mode k (its Legendre coefficient) and its slope with respect to the mode's
// two-sided value: the tension-only law acts on the element's mean tension (mode 0), the force the
// element transmits, like a lumped-mass line's segment; the softened higher modes, which only
// shape the strain inside the element, stay two-sided, so a slack element keeps its shape
// stiffness (without it a slack element without bending stiffness has free tangents: the
// snapping chain's response then changes by 20 % of its tension between integrator tolerances).
// stiffness[k]: the elastic tension's slope in the mode's strain, EA or the curve's slope.
struct ModeTensions {
    SlackLaw mode[3];
    double stiffness[3];
};

ModeTensions mode_tensions(const ElementTables& e, const AxialProps& p, const AxialSamples& s) {
    ModeTensions m;
    for (int k = 0; k < e.axialModes; ++k) {
        m.stiffness[k] = p.EA;
        double P;
        if (k == 0 && p.visco) {
            // the first Kelvin-Voigt pair carries the tension: no direct dependence on the strain
            m.stiffness[0] = 0.0;
            const double held = p.syrope ? syrope_tension(*p.syrope, p.history, p.internal[0]).tension
                                         : visco_stiffness(*p.visco, p.internal[0]).EA1 * p.internal[0];
            P = mode_weight(e, p, 0) * (held + p.damping * p.internal[1]);
        } else {
            const double elastic = k == 0 && p.curve ? (*p.curve)(s.strainMode[0], &m.stiffness[0]) : p.EA * s.strainMode[k];
            P = mode_weight(e, p, k) * (elastic + p.damping * s.rateMode[k]);
        }
        m.mode[k] = p.tensionOnly && k == 0 ? slack_law(P, slack_width(e, p)) : SlackLaw{P, 1.0};
    }
    return m;
}

// Projected tension at sampling point g.
double projected_tension(const ElementTables& e, const ModeTensions& m, int g) {
    double T = 0.0;
    for (int k = 0; k < e.axialModes; ++k) T += e.legendre[k][g] * m.mode[k].tension;
    return T;
}

// Strain mode k's derivatives in the nodal values: G_b = sum_g w_g phi_k dN_b t_g (times the element's length)
// and, for its rate, H_b = sum_g w_g phi_k dN_b (I - t t^T) r'dot / |r'|.
void mode_gradients(const ElementTables& e, const AxialSamples& s, int k, Vec3 G[4], Vec3 H[4]) {
    for (int a = 0; a < 4; ++a) {
        G[a].setZero();
        H[a].setZero();
    }
    for (int g = 0; g < ElementTables::nAxial; ++g) {
        const QuadPoint& q = e.axial[g];
        const double wphi = q.weight * e.legendre[k][g];
        const Vec3 rotationRate = (s.rpd[g] - s.t[g] * s.t[g].dot(s.rpd[g])) / s.stretch[g];
        for (int a = 0; a < 4; ++a) {
            G[a] += (wphi * q.shape.dN[a]) * s.t[g];
            H[a] += (wphi * q.shape.dN[a]) * rotationRate;
        }
    }
}

}  // namespace

void add_axial_force(const ElementTables& e, const AxialProps& p, const double* X, const double* Xd,
                     double* R) {
    const AxialSamples s = sample_axial(e, X, Xd);
    const ModeTensions m = mode_tensions(e, p, s);
    for (int g = 0; g < ElementTables::nAxial; ++g) {
        const QuadPoint& q = e.axial[g];
        const Vec3 f = (q.weight * projected_tension(e, m, g)) * s.t[g];
        for (int a = 0; a < 4; ++a) Eigen::Map<Vec3>(R + 3 * a) += q.shape.dN[a] * f;
    }
}

void add_axial_jacobian(const ElementTables& e, const AxialProps& p, const double* X, const double* Xd,
                        Mat12& K, Mat12& C) {
    const AxialSamples s = sample_axial(e, X, Xd);
    const ModeTensions m = mode_tensions(e, p, s);
    const double l = e.length;
    // Geometric part: the projected tension times the rotation of t at each point.
    for (int g = 0; g < ElementTables::nAxial; ++g) {
        const QuadPoint& q = e.axial[g];
        const Mat3 geometric = (projected_tension(e, m, g) / s.stretch[g]) *
                               (Mat3::Identity() - s.t[g] * s.t[g].transpose());
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b)
                K.block<3, 3>(3 * a, 3 * b) += (q.weight * q.shape.dN[a] * q.shape.dN[b]) * geometric;
    }
    // Material part: d(mode k)/dX_b = G_kb / l, with G_kb = sum_g w_g l phi_k dN_b t_g, and for the
    // strain rate additionally H_kb = sum_g w_g l phi_k dN_b (I - t t^T) r'dot / |r'|.
    for (int k = 0; k < e.axialModes; ++k) {
        Vec3 G[4], H[4];
        mode_gradients(e, s, k, G, H);
        // d(mode tension)/d(two-sided mode value): 1, or the tension-only law's slope for mode 0.
        const double weight = mode_weight(e, p, k) / l * m.mode[k].slope;
        for (int a = 0; a < 4; ++a) {
            for (int b = 0; b < 4; ++b) {
                K.block<3, 3>(3 * a, 3 * b) += (weight * m.stiffness[k]) * G[a] * G[b].transpose();
                if (p.damping != 0.0 && !(k == 0 && p.visco)) {
                    K.block<3, 3>(3 * a, 3 * b) += (weight * p.damping) * G[a] * H[b].transpose();
                    C.block<3, 3>(3 * a, 3 * b) += (weight * p.damping) * G[a] * G[b].transpose();
                }
            }
        }
    }
}

void axial_tensions(const ElementTables& e, const AxialProps& p, const double* X, const double* Xd,
                    double* T, Vec3* rp) {
    const AxialSamples s = rp ? sample_axial<true>(e, X, Xd, rp) : sample_axial(e, X, Xd);
    const ModeTensions m = mode_tensions(e, p, s);
    for (int g = 0; g < ElementTables::nAxial; ++g) T[g] = projected_tension(e, m, g);
}

ViscoStiffness visco_stiffness(const ViscoProps& v, double e1) {
    ViscoStiffness k{v.EAd, v.EAd, 0.0, 0.0};
    if (v.slope != 0.0 && e1 > 0.0) {
        // EA_2 = EA_d + beta EA_1 e1 with EA_1 = EA_2 EA_s / (EA_2 - EA_s): the root above EA_s of
        // EA_2^2 - b EA_2 + EA_d EA_s = 0, b = EA_d + EA_s (1 + beta e1). A compressed first spring
        // (e1 <= 0) carries no mean load: EA_2 = EA_d, continuous at e1 = 0 (EA_d > EA_s).
        const double b = v.EAd + v.EAs * (1.0 + v.slope * e1);
        const double root = std::sqrt(b * b - 4.0 * v.EAd * v.EAs);
        k.EA2 = 0.5 * (b + root);
        k.dEA2 = 0.5 * v.slope * v.EAs * (1.0 + b / root);
    }
    const double gap = k.EA2 - v.EAs;
    k.EA1 = k.EA2 * v.EAs / gap;
    k.dEA1 = -v.EAs * v.EAs / (gap * gap) * k.dEA2;
    return k;
}

void visco_modulus(const ViscoProps& v, double damping, double w, double& storage, double& loss) {
    const ViscoStiffness k = visco_stiffness(v, 0.0);
    const std::complex<double> i(0.0, 1.0);
    const std::complex<double> E =
        (k.EA1 + i * w * damping) * (k.EA2 + i * w * v.dampingDynamic) / (k.EA1 + k.EA2 + i * w * (damping + v.dampingDynamic));
    storage = E.real();
    loss = E.imag();
}

double visco_residual(const ElementTables& e, const AxialProps& p, const double* X, const double* Xd) {
    const AxialSamples s = sample_axial(e, X, Xd);
    const ViscoProps& v = *p.visco;
    const double e1 = p.internal[0], r1 = p.internal[1];
    if (p.syrope) {
        const SyropeTension t = syrope_tension(*p.syrope, p.history, e1);
        return (p.damping + v.dampingDynamic) * r1 - (p.syrope->alpha + p.syrope->beta * t.tension) * (s.strainMode[0] - t.curveStrain) -
               v.dampingDynamic * s.rateMode[0];
    }
    const ViscoStiffness k = visco_stiffness(v, e1);
    return (p.damping + v.dampingDynamic) * r1 - k.EA2 * s.strainMode[0] + (k.EA1 + k.EA2) * e1 -
           v.dampingDynamic * s.rateMode[0];
}

void visco_jacobian(const ElementTables& e, const AxialProps& p, const double* X, const double* Xd, ViscoJacobian& J) {
    const AxialSamples s = sample_axial(e, X, Xd);
    const ModeTensions m = mode_tensions(e, p, s);
    const ViscoProps& v = *p.visco;
    const double e1 = p.internal[0], l = e.length;
    Vec3 G[4], H[4];
    mode_gradients(e, s, 0, G, H);  // (the mean mode: phi_0 = 1)
    const double scale = mode_weight(e, p, 0) * m.mode[0].slope;
    if (p.syrope) {
        // eps_c(T(z)) = z + eps_d(T(z)): d/dz = 1 + T' / (alpha + beta T)
        const SyropeTension t = syrope_tension(*p.syrope, p.history, e1);
        const double K = p.syrope->alpha + p.syrope->beta * t.tension;
        for (int a = 0; a < 4; ++a)
            for (int c = 0; c < 3; ++c) {
                J.dR_de1[3 * a + c] = scale * t.slope * G[a][c];
                J.dR_dr1[3 * a + c] = scale * p.damping * G[a][c];
                J.dI_dX[3 * a + c] = -(K * G[a][c] + v.dampingDynamic * H[a][c]) / l;
                J.dI_dXd[3 * a + c] = -v.dampingDynamic * G[a][c] / l;
            }
        J.dI_de1 = -p.syrope->beta * t.slope * (s.strainMode[0] - t.curveStrain) + K + t.slope;
        J.dI_dr1 = p.damping + v.dampingDynamic;
        return;
    }
    const ViscoStiffness k = visco_stiffness(v, e1);
    for (int a = 0; a < 4; ++a)
        for (int c = 0; c < 3; ++c) {
            J.dR_de1[3 * a + c] = scale * (k.EA1 + e1 * k.dEA1) * G[a][c];
            J.dR_dr1[3 * a + c] = scale * p.damping * G[a][c];
            J.dI_dX[3 * a + c] = -(k.EA2 * G[a][c] + v.dampingDynamic * H[a][c]) / l;
            J.dI_dXd[3 * a + c] = -v.dampingDynamic * G[a][c] / l;
        }
    J.dI_de1 = k.EA1 + k.EA2 + e1 * (k.dEA1 + k.dEA2) - k.dEA2 * s.strainMode[0];
    J.dI_dr1 = p.damping + v.dampingDynamic;
}

double axial_energy(const ElementTables& e, const AxialProps& p, const double* X) {
    const Vec12 zero = Vec12::Zero();
    const AxialSamples s = sample_axial(e, X, zero.data());
    double energy = 0.0;
    for (int k = 0; k < e.axialModes; ++k)
        energy += mode_weight(e, p, k) * e.length *
                  (k == 0 && p.curve ? p.curve->energy(s.strainMode[0]) : 0.5 * p.EA * s.strainMode[k] * s.strainMode[k]);
    return energy;
}

void add_bending_force(const ElementTables& e, double EI, const double* X, double* R) {
    for (int a = 0; a < 4; ++a) {
        Vec3 f = Vec3::Zero();
        for (int b = 0; b < 4; ++b) f += e.bending(a, b) * Eigen::Map<const Vec3>(X + 3 * b);
        Eigen::Map<Vec3>(R + 3 * a) += EI * f;
    }
}

void add_bending_jacobian(const ElementTables& e, double EI, Mat12& K) {
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) K.block<3, 3>(3 * a, 3 * b).diagonal().array() += EI * e.bending(a, b);
}

double bending_energy(const ElementTables& e, double EI, const double* X) {
    double energy = 0.0;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
            energy += 0.5 * EI * e.bending(a, b) *
                      Eigen::Map<const Vec3>(X + 3 * a).dot(Eigen::Map<const Vec3>(X + 3 * b));
    return energy;
}

void add_torque_force(const ElementTables& e, double H, const double* X, double* R) {
    // (r' x r'') dN_a is a polynomial of degree 5: the 5 axial points integrate it exactly.
    for (int g = 0; g < ElementTables::nAxial; ++g) {
        const QuadPoint& q = e.axial[g];
        const Vec3 f = (-H * q.weight) * interpolate(q.shape.dN, X).cross(interpolate(q.shape.d2N, X));
        for (int a = 0; a < 4; ++a) Eigen::Map<Vec3>(R + 3 * a) += q.shape.dN[a] * f;
    }
}

void add_torque_jacobian(const ElementTables& e, double H, const double* X, Mat12& K) {
    for (int g = 0; g < ElementTables::nAxial; ++g) {
        const QuadPoint& q = e.axial[g];
        // d(a x b) = -[b]x da + [a]x db with a = r', b = r''.
        const Mat3 dA = -skew(interpolate(q.shape.d2N, X));
        const Mat3 dB = skew(interpolate(q.shape.dN, X));
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b)
                K.block<3, 3>(3 * a, 3 * b) +=
                    (-H * q.weight * q.shape.dN[a]) * (q.shape.dN[b] * dA + q.shape.d2N[b] * dB);
    }
}

void add_mass_force(const ElementTables& e, double massPerLength, const double* Xdd, double* R) {
    for (int a = 0; a < 4; ++a) {
        Vec3 f = Vec3::Zero();
        for (int b = 0; b < 4; ++b) f += e.mass(a, b) * Eigen::Map<const Vec3>(Xdd + 3 * b);
        Eigen::Map<Vec3>(R + 3 * a) += massPerLength * f;
    }
}

void add_mass_jacobian(const ElementTables& e, double massPerLength, Mat12& M) {
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
            M.block<3, 3>(3 * a, 3 * b).diagonal().array() += massPerLength * e.mass(a, b);
}

}  // namespace uc
