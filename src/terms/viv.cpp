// viv.cpp - vortex-induced vibration: lift at the load points, the phase's synchronisation at the midpoint.
// The derivatives come from forward-mode dual numbers through the same code as the values, so the
// Jacobian is the residual's derivative by construction.
#include "terms/viv.h"

#include <cmath>

namespace uc {
namespace {

// A value with its derivatives with respect to n inputs.
template <int n>
struct Dual {
    double v = 0.0;
    double d[n] = {};
    Dual() = default;
    Dual(double value) : v(value) {}  // a constant
    static Dual seed(double value, int k) {
        Dual x(value);
        x.d[k] = 1.0;
        return x;
    }
};
template <int n>
Dual<n> operator+(const Dual<n>& a, const Dual<n>& b) {
    Dual<n> r(a.v + b.v);
    for (int k = 0; k < n; ++k) r.d[k] = a.d[k] + b.d[k];
    return r;
}
template <int n>
Dual<n> operator-(const Dual<n>& a, const Dual<n>& b) {
    Dual<n> r(a.v - b.v);
    for (int k = 0; k < n; ++k) r.d[k] = a.d[k] - b.d[k];
    return r;
}
template <int n>
Dual<n> operator*(const Dual<n>& a, const Dual<n>& b) {
    Dual<n> r(a.v * b.v);
    for (int k = 0; k < n; ++k) r.d[k] = a.d[k] * b.v + a.v * b.d[k];
    return r;
}
template <int n>
Dual<n> operator/(const Dual<n>& a, const Dual<n>& b) {
    Dual<n> r(a.v / b.v);
    for (int k = 0; k < n; ++k) r.d[k] = (a.d[k] - r.v * b.d[k]) / b.v;
    return r;
}
template <int n>
Dual<n> chain(const Dual<n>& a, double value, double slope) {
    Dual<n> r(value);
    for (int k = 0; k < n; ++k) r.d[k] = slope * a.d[k];
    return r;
}
template <int n>
Dual<n> sqrt(const Dual<n>& a) {
    const double s = std::sqrt(a.v);
    return chain(a, s, 0.5 / s);
}
template <int n>
Dual<n> sin(const Dual<n>& a) {
    return chain(a, std::sin(a.v), std::cos(a.v));
}
template <int n>
Dual<n> cos(const Dual<n>& a) {
    return chain(a, std::cos(a.v), -std::sin(a.v));
}
inline double sqrt(double x) { return std::sqrt(x); }
inline double sin(double x) { return std::sin(x); }
inline double cos(double x) { return std::cos(x); }
inline double value(double x) { return x; }
template <int n>
double value(const Dual<n>& x) {
    return x.v;
}

template <class T>
struct V3 {
    T x[3];
    T dot(const V3& b) const { return x[0] * b.x[0] + x[1] * b.x[1] + x[2] * b.x[2]; }
};
template <class T>
V3<T> operator-(const V3<T>& a, const V3<T>& b) {
    return {{a.x[0] - b.x[0], a.x[1] - b.x[1], a.x[2] - b.x[2]}};
}
template <class T>
V3<T> scaled(const V3<T>& a, const T& s) {
    return {{a.x[0] * s, a.x[1] * s, a.x[2] * s}};
}
template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
    return {{a.x[1] * b.x[2] - a.x[2] * b.x[1], a.x[2] * b.x[0] - a.x[0] * b.x[2], a.x[0] * b.x[1] - a.x[1] * b.x[0]}};
}

// The relative flow across the line: t, u_n and |u_n| (floored as the drag's).
template <class T>
struct CrossFlow {
    V3<T> t, un;
    T speed;
};
template <class T>
CrossFlow<T> cross_flow(const V3<T>& U, const V3<T>& rp, const V3<T>& rd) {
    CrossFlow<T> f;
    f.t = scaled(rp, T(1.0) / sqrt(rp.dot(rp)));
    const V3<T> u = U - rd;
    f.un = u - scaled(f.t, f.t.dot(u));
    f.speed = sqrt(f.un.dot(f.un) + T(kDragVelocityFloor * kDragVelocityFloor));
    return f;
}

// Lift per length at a point at height z.
template <class T>
V3<T> lift(const FluidProps& p, const VivProps& v, const V3<T>& U, const T& z, const V3<T>& rp, const V3<T>& rd,
           const T& phase) {
    const CrossFlow<T> f = cross_flow(U, rp, rd);
    const double d = p.diameter;
    const T submerged = value(z) <= 0.0 ? T(1.0) : value(z) >= d ? T(0.0) : T(1.0) - z / T(d);
    return scaled(cross(f.t, f.un), submerged * T(0.5 * p.rho * d * v.Cl) * cos(phase) * f.speed);
}

// phi' of the synchronisation model.
template <class T>
T phase_rate(const FluidProps& p, const VivProps& v, const V3<T>& U, const V3<T>& rp, const V3<T>& rd,
             const V3<T>& rdd, const T& phase, const T& phaseRate) {
    const CrossFlow<T> f = cross_flow(U, rp, rd);
    const V3<T> c = scaled(cross(f.t, f.un), T(1.0) / f.speed);
    const T yd = rd.dot(c), ydd = rdd.dot(c);
    const T shedding = T(2.0 * kPi / p.diameter) * f.speed;  // 2 pi |u_n| / d
    // y'' / phi' (a rate that Newton's iterates took to zero or below: its floor, 1e-9 rad/s)
    const T y2 = ydd / (value(phaseRate) > 1e-9 ? phaseRate : T(1e-9));
    const T m = sqrt(yd * yd + y2 * y2 + T(kVivMotionFloor * kVivMotionFloor));
    const T s = (T(0.0) - y2 * cos(phase) - yd * sin(phase)) / m;  // sin(phi_y - phi)
    return shedding * (T(v.frequency) + T(v.range) * s);
}

V3<double> v3(const Vec3& a) { return {{a.x(), a.y(), a.z()}}; }

// A vector whose derivatives are the identity in inputs first .. first + 2.
template <int n>
V3<Dual<n>> seeded(const Vec3& a, int first) {
    return {{Dual<n>::seed(a.x(), first), Dual<n>::seed(a.y(), first + 1), Dual<n>::seed(a.z(), first + 2)}};
}

// The flow at r as a function of r (inputs 0 .. 2): U + dU (r - r0).
template <int n>
V3<Dual<n>> flow_of_r(const Vec3& U, const Mat3& dU) {
    V3<Dual<n>> out;
    for (int i = 0; i < 3; ++i) {
        out.x[i] = Dual<n>(U[i]);
        for (int j = 0; j < 3; ++j) out.x[i].d[j] = dU(i, j);
    }
    return out;
}

ShapeValues midpoint(const ElementTables& e) { return hermite_shape(0.5, e.length); }

}  // namespace

void add_viv_force(const ElementTables& e, const FluidProps& p, const VivProps& v, const CurrentField& current,
                   const double* X, const double* Xd, double phase, double* R, WaveExpansion* waveCache) {
    for (int g = 0; g < e.nLoad; ++g) {
        const QuadPoint& q = e.load[g];
        const Vec3 r = interpolate(q.shape.N, X);
        Vec3 U, A;
        current.flow(r, U, A, waveCache ? waveCache + g : nullptr);
        const V3<double> F = lift(p, v, v3(U), r.z(), v3(interpolate(q.shape.dN, X)), v3(interpolate(q.shape.N, Xd)), phase);
        for (int a = 0; a < 4; ++a)
            for (int i = 0; i < 3; ++i) R[3 * a + i] -= q.weight * q.shape.N[a] * F.x[i];
    }
}

void add_viv_jacobian(const ElementTables& e, const FluidProps& p, const VivProps& v, const CurrentField& current,
                      const double* X, const double* Xd, double phase, Mat12& K, Mat12& C, double* dPhase,
                      WaveExpansion* waveCache) {
    using D = Dual<10>;  // r, r', r_dot, phi
    for (int g = 0; g < e.nLoad; ++g) {
        const QuadPoint& q = e.load[g];
        const Vec3 r = interpolate(q.shape.N, X);
        Vec3 U, A;
        Mat3 dU, dA;
        current.flow(r, U, dU, A, dA, waveCache ? waveCache + g : nullptr);
        const V3<D> F = lift(p, v, flow_of_r<10>(U, dU), D::seed(r.z(), 2), seeded<10>(interpolate(q.shape.dN, X), 3),
                             seeded<10>(interpolate(q.shape.N, Xd), 6), D::seed(phase, 9));
        for (int a = 0; a < 4; ++a) {
            const double wa = q.weight * q.shape.N[a];
            for (int i = 0; i < 3; ++i) {
                const D& Fi = F.x[i];
                dPhase[3 * a + i] -= wa * Fi.d[9];
                for (int b = 0; b < 4; ++b)
                    for (int j = 0; j < 3; ++j) {
                        K(3 * a + i, 3 * b + j) -= wa * (q.shape.N[b] * Fi.d[j] + q.shape.dN[b] * Fi.d[3 + j]);
                        C(3 * a + i, 3 * b + j) -= wa * q.shape.N[b] * Fi.d[6 + j];
                    }
            }
        }
    }
}

double viv_phase_rate(const ElementTables& e, const FluidProps& p, const VivProps& v, const CurrentField& current,
                      const double* X, const double* Xd, const double* Xdd, double phase, double phaseRate) {
    const ShapeValues s = midpoint(e);
    const Vec3 r = interpolate(s.N, X);
    Vec3 U, A;
    current.flow(r, U, A);
    return phase_rate(p, v, v3(U), v3(interpolate(s.dN, X)), v3(interpolate(s.N, Xd)), v3(interpolate(s.N, Xdd)), phase,
                      phaseRate);
}

double viv_phase_residual(const ElementTables& e, const FluidProps& p, const VivProps& v, const CurrentField& current,
                          const double* X, const double* Xd, const double* Xdd, double phase, double phaseRate,
                          VivPhaseJacobian* J) {
    if (J == nullptr) return phaseRate - viv_phase_rate(e, p, v, current, X, Xd, Xdd, phase, phaseRate);
    using D = Dual<14>;  // r, r', r_dot, r_ddot, phi, phi'
    const ShapeValues s = midpoint(e);
    const Vec3 r = interpolate(s.N, X);
    Vec3 U, A;
    Mat3 dU, dA;
    current.flow(r, U, dU, A, dA);
    const D w = phase_rate(p, v, flow_of_r<14>(U, dU), seeded<14>(interpolate(s.dN, X), 3),
                           seeded<14>(interpolate(s.N, Xd), 6), seeded<14>(interpolate(s.N, Xdd), 9), D::seed(phase, 12),
                           D::seed(phaseRate, 13));
    for (int a = 0; a < 4; ++a)
        for (int j = 0; j < 3; ++j) {
            J->dX[3 * a + j] = -(s.N[a] * w.d[j] + s.dN[a] * w.d[3 + j]);
            J->dXd[3 * a + j] = -s.N[a] * w.d[6 + j];
            J->dXdd[3 * a + j] = -s.N[a] * w.d[9 + j];
        }
    J->dPhase = -w.d[12];
    J->dPhaseRate = 1.0 - w.d[13];
    return phaseRate - w.v;
}

}  // namespace uc
