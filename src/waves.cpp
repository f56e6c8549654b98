// waves.cpp - Airy components, JONSWAP discretization, kinematics.
#include "waves.h"

#include <cmath>
#include <cstdio>

namespace uc {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The bottom's image term e^{-2kh} below this is lost in the round-off of e^{kz} near the surface.
constexpr double kNegligibleBottom = 1e-18;

// A component with k z below this (e^{kz} < 4e-18, and its depth factors below twice that) moves the
// water at z by less than 1e-17 of its surface motion: it is left out there. The components ascend in
// k (in frequency, and k grows with the frequency), so the sum stops at the first such one.
constexpr double kNegligibleDepthExponent = -40.0;

// JONSWAP spectral shape (unscaled) at omega for peak wp and peakedness gamma.
double jonswap_shape(double w, double wp, double gamma) {
    const double sigma = w <= wp ? 0.07 : 0.09;
    const double r = std::exp(-(w - wp) * (w - wp) / (2.0 * sigma * sigma * wp * wp));
    return std::pow(w, -5.0) * std::exp(-1.25 * std::pow(wp / w, 4.0)) * std::pow(gamma, r);
}

}  // namespace

double wave_number(double omega, double depth, double gravity) {
    double k = omega * omega / gravity;  // deep water
    if (k * depth < 10.0) k = std::max(k, omega / std::sqrt(gravity * depth));
    for (int i = 0; i < 100; ++i) {
        const double th = std::tanh(k * depth);
        const double f = gravity * k * th - omega * omega;
        const double df = gravity * (th + k * depth * (1.0 - th * th));
        const double step = f / df;
        k -= step;
        if (std::fabs(step) <= 1e-15 * k) break;
    }
    return k;
}

unsigned long long SplitMix64::next() {
    unsigned long long z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

bool SeaState::build(const UCParams& p, std::string& error) {
    components_.clear();
    if (p.wavesMode == 0 || p.wavesHeight == 0.0) return true;
    depth_ = p.waterDepth;
    rampTime_ = p.wavesRampTime;
    wheeler_ = p.wavesStretching != 0;
    cosb_ = std::cos(p.wavesDirection);
    sinb_ = std::sin(p.wavesDirection);
    const double g = p.gravity;
    const double wp = 2.0 * kPi / p.wavesPeriod;
    const double kp = wave_number(wp, depth_, g);
    const double steepness = p.wavesHeight * kp / (2.0 * kPi);
    if (steepness > 1.0 / 7.0) {
        char text[300];
        std::snprintf(text, sizeof text,
                      "waves.height = %.17g is too steep for waves.period = %.17g s in %.17g m of water: H / lambda = "
                      "%.3g exceeds the breaking limit 1/7 (lambda = %.4g m)",
                      p.wavesHeight, p.wavesPeriod, depth_, steepness, 2.0 * kPi / kp);
        error = text;
        return false;
    }
    if (p.wavesMode == 1) {
        components_.push_back({0.5 * p.wavesHeight, wp, kp, 0.0});
    } else {
        // JONSWAP: n components at the midpoints of equal bands over [0.5, 3] wp, amplitudes
        // sqrt(2 S dw) with S scaled so that 4 sqrt(m0) = Hs; phases from the seed.
        const int n = p.wavesNComponents;
        const double w0 = 0.5 * wp, w1 = 3.0 * wp, dw = (w1 - w0) / n;
        std::vector<double> S(n);
        double m0 = 0.0;
        for (int i = 0; i < n; ++i) {
            S[i] = jonswap_shape(w0 + (i + 0.5) * dw, wp, p.wavesGamma);
            m0 += S[i] * dw;
        }
        const double scale = p.wavesHeight * p.wavesHeight / 16.0 / m0;
        SplitMix64 random(static_cast<unsigned long long>(p.wavesSeed));
        for (int i = 0; i < n; ++i) {
            const double w = w0 + (i + 0.5) * dw;
            components_.push_back({std::sqrt(2.0 * scale * S[i] * dw), w, wave_number(w, depth_, g), 2.0 * kPi * random.uniform()});
        }
    }
    // The ladder of the JONSWAP frequencies w0 + (i + 1/2) dw (kinematics); a single component is its
    // own ladder.
    gravity_ = g;
    const double wp0 = 0.5 * wp;
    const double dwAll = p.wavesMode == 1 ? 0.0 : (3.0 * wp - wp0) / p.wavesNComponents;
    ladderAlpha_ = p.wavesMode == 1 ? wp : wp0 + 0.5 * dwAll;
    ladderBeta_ = dwAll;
    for (size_t i = 0; i < components_.size(); ++i) {
        WaveComponent& c = components_[i];
        c.kx = c.k * cosb_;
        c.ky = c.k * sinb_;
        const double image = std::exp(-2.0 * c.k * depth_);
        c.bottom = image > kNegligibleBottom ? image : 0.0;
        c.depthScale = 1.0 / (1.0 - image);
        c.velocityScale = c.amplitude * c.omega * c.depthScale;
        c.accelerationScale = c.velocityScale * c.omega;
        c.ladderShift = c.k - ladder_k(static_cast<double>(i));
        if (std::fabs(c.ladderShift) <= 4e-16 * c.k) c.ladderShift = 0.0;  // deep water: on the ladder to round-off
    }
    cosPhase_.assign(components_.size(), 0.0);
    sinPhase_.assign(components_.size(), 0.0);
    phaseValid_ = false;
    return true;
}

void SeaState::phases_at(double t) const {
    if (phaseValid_ && t == phaseTime_) return;
    for (size_t i = 0; i < components_.size(); ++i) {
        const double phi = components_[i].omega * t - components_[i].phase;
        cosPhase_[i] = std::cos(phi);
        sinPhase_[i] = std::sin(phi);
    }
    phaseTime_ = t;
    phaseValid_ = true;
}

double SeaState::ramp(double t) const {
    if (!(rampTime_ > 0.0) || t >= rampTime_) return 1.0;
    if (t <= 0.0) return 0.0;
    return 0.5 * (1.0 - std::cos(kPi * t / rampTime_));
}

double SeaState::elevation(double x, double y, double t) const {
    if (components_.empty()) return 0.0;
    phases_at(t);
    double eta = 0.0;
    for (size_t i = 0; i < components_.size(); ++i) {  // cos(k.x - (w t - p))
        const WaveComponent& c = components_[i];
        const double kx = c.kx * x + c.ky * y;
        eta += c.amplitude * (std::cos(kx) * cosPhase_[i] + std::sin(kx) * sinPhase_[i]);
    }
    return ramp(t) * eta;
}

namespace {

// exp(x (z + i s)) = e^{x z} (cos x s + i sin x s) for real x: (re, im).
inline void cexp_scaled(double x, double z, double s, double& re, double& im) {
    const double m = std::exp(x * z);
    re = m * std::cos(x * s);
    im = m * std::sin(x * s);
}

// Components between two direct evaluations of the ladder (bounds its round-off to ~16^2 / 2 ulp).
constexpr size_t kLadderRestart = 16;
// Below this |x| = |shift (z + i s)|, exp(x) is its Taylor polynomial of degree 4 (error < 1e-17).
constexpr double kSmallShift = 1e-3;

}  // namespace

void SeaState::kinematics(const Vec3& r, double t, Vec3& u, Vec3& a, Mat3* du, Mat3* da) const {
    u.setZero();
    a.setZero();
    if (du) du->setZero();
    if (da) da->setZero();
    if (components_.empty()) return;
    phases_at(t);
    double z = std::min(r.z(), 0.0);
    if (wheeler_) {
        const double eta = elevation(r.x(), r.y(), t);
        z = std::min(depth_ * (r.z() - eta) / (depth_ + eta), 0.0);
    }
    const double f = ramp(t);
    const double s = cosb_ * r.x() + sinb_ * r.y();  // along the direction of travel
    double uh = 0.0, w = 0.0, ah = 0.0, aw = 0.0;                  // along the direction of travel, vertical
    double duh_ds = 0.0, duh_dz = 0.0, dw_ds = 0.0, dw_dz = 0.0;     // gradients in (s, z)
    double dah_ds = 0.0, dah_dz = 0.0, daw_ds = 0.0, daw_dz = 0.0;
    const bool belowSurface = r.z() < 0.0 || wheeler_;
    const bool gradients = du != nullptr || da != nullptr;
    // E = exp(q_i (z + i s)) on the deep-water ladder q_i, and its ratio R = exp((q_{i+1} - q_i)(z + i s)),
    // which itself grows by Q = exp((q_{i+2} - 2 q_{i+1} + q_i)(z + i s)) per component.
    const double dd = 2.0 * ladderBeta_ * ladderBeta_ / gravity_;
    double Er = 0.0, Ei = 0.0, Rr = 0.0, Ri = 0.0, Qr = 1.0, Qi = 0.0;
    if (components_.size() > 1) cexp_scaled(dd, z, s, Qr, Qi);
    const double span = std::fabs(z) + std::fabs(s);
    for (size_t i = 0; i < components_.size(); ++i) {
        const WaveComponent& c = components_[i];
        if (c.k * z < kNegligibleDepthExponent) break;  // and so are all shorter components
        if (i % kLadderRestart == 0) {
            const double q = ladder_k(static_cast<double>(i));
            cexp_scaled(q, z, s, Er, Ei);
            cexp_scaled(ladder_k(static_cast<double>(i) + 1.0) - q, z, s, Rr, Ri);
        } else {
            const double er = Er * Rr - Ei * Ri, ei = Er * Ri + Ei * Rr;
            const double rr = Rr * Qr - Ri * Qi, ri = Rr * Qi + Ri * Qr;
            Er = er, Ei = ei, Rr = rr, Ri = ri;
        }
        // F = exp(k (z + i s)) = E exp(shift (z + i s))
        double Fr = Er, Fi = Ei;
        if (c.ladderShift != 0.0) {
            double xr = c.ladderShift * z, xi = c.ladderShift * s, gr, gi;
            if (std::fabs(c.ladderShift) * span < kSmallShift) {
                // 1 + x (1 + x/2 (1 + x/3 (1 + x/4)))
                double pr = 1.0 + 0.25 * xr, pi = 0.25 * xi;
                double tr = 1.0 + (xr * pr - xi * pi) / 3.0, ti = (xr * pi + xi * pr) / 3.0;
                pr = 1.0 + 0.5 * (xr * tr - xi * ti), pi = 0.5 * (xr * ti + xi * tr);
                gr = 1.0 + xr * pr - xi * pi, gi = xr * pi + xi * pr;
            } else {
                cexp_scaled(c.ladderShift, z, s, gr, gi);
            }
            Fr = Er * gr - Ei * gi, Fi = Er * gi + Ei * gr;
        }
        // G = F exp(-i (w t - p)) = e^{kz} (cos theta + i sin theta), theta = k s - w t + p
        const double Gr = Fr * cosPhase_[i] + Fi * sinPhase_[i];
        const double Gi = Fi * cosPhase_[i] - Fr * sinPhase_[i];
        const double A1 = c.velocityScale, A2 = c.accelerationScale;
        if (c.bottom == 0.0 && !gradients) {  // deep water, the residual's case: cosh, sinh -> e^{kz}
            uh += A1 * Gr;
            w += A1 * Gi;
            ah += A2 * Gi;
            aw -= A2 * Gr;
            continue;
        }
        // the bottom's image term: e^{-k(2h + z)} e^{i theta} = bottom G / |G|^2
        const double image = c.bottom > 0.0 ? c.bottom / (Gr * Gr + Gi * Gi) : 0.0;
        const double chco = Gr * (1.0 + image), chsi = Gi * (1.0 + image);  // / depthScale
        const double shco = Gr * (1.0 - image), shsi = Gi * (1.0 - image);
        uh += A1 * chco;
        w += A1 * shsi;
        ah += A2 * chsi;
        aw -= A2 * shco;
        if (gradients) {
            duh_ds -= A1 * chsi * c.k;
            dw_ds += A1 * shco * c.k;
            dah_ds += A2 * chco * c.k;
            daw_ds += A2 * shsi * c.k;
            if (belowSurface) {  // above the surface (no stretching) the kinematics do not change with z
                duh_dz += A1 * shco * c.k;
                dw_dz += A1 * chsi * c.k;
                dah_dz += A2 * shsi * c.k;
                daw_dz -= A2 * chco * c.k;
            }
        }
    }
    u = f * Vec3(uh * cosb_, uh * sinb_, w);
    a = f * Vec3(ah * cosb_, ah * sinb_, aw);
    // d/dx = cos(beta) d/ds, d/dy = sin(beta) d/ds (the stretching's own slope is left out).
    if (du) {
        *du << duh_ds * cosb_ * cosb_, duh_ds * cosb_ * sinb_, duh_dz * cosb_,
               duh_ds * sinb_ * cosb_, duh_ds * sinb_ * sinb_, duh_dz * sinb_,
               dw_ds * cosb_, dw_ds * sinb_, dw_dz;
        *du *= f;
    }
    if (da) {
        *da << dah_ds * cosb_ * cosb_, dah_ds * cosb_ * sinb_, dah_dz * cosb_,
               dah_ds * sinb_ * cosb_, dah_ds * sinb_ * sinb_, dah_dz * sinb_,
               daw_ds * cosb_, daw_ds * sinb_, daw_dz;
        *da *= f;
    }
}

}  // namespace uc
