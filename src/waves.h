// waves.h - linear (Airy) wave kinematics: a regular wave or a JONSWAP sea as a sum of components,
// with finite-depth dispersion and optional Wheeler stretching (docs/waves.md).
//
// Convention: a component of amplitude a, frequency w, wavenumber k, direction of travel beta
// (from +x toward +y) and phase p has the elevation a cos(k (x cos beta + y sin beta) - w t + p); the
// regular wave has p = 0 (a crest at the origin at t = 0). Irregular phases come from the seed
// through SplitMix64 (a stated 64-bit generator, identical on every platform).
#pragma once

#include <string>
#include <vector>

#include "hermite_element.h"
#include "uc_schema.h"

namespace uc {

struct WaveComponent {
    double amplitude = 0.0, omega = 0.0, k = 0.0, phase = 0.0;
    // precomputed by SeaState::build: k along x and y, exp(-2 k h), 1 / (1 - exp(-2 k h)), and k minus
    // the deep-water ladder value of its index (SeaState::ladder_k)
    double kx = 0.0, ky = 0.0, bottom = 0.0, depthScale = 1.0, ladderShift = 0.0;
    double velocityScale = 0.0, accelerationScale = 0.0;  // a w / (1 - e^{-2kh}), a w^2 / (1 - e^{-2kh})
};

// The wavenumber of frequency omega in water of depth h: omega^2 = g k tanh(k h), solved by Newton's
// method to round-off.
double wave_number(double omega, double depth, double gravity);

// The uniform [0, 1) doubles of SplitMix64 from a seed (53 bits of each 64-bit output).
class SplitMix64 {
public:
    explicit SplitMix64(unsigned long long seed) : state_(seed) {}
    unsigned long long next();
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

private:
    unsigned long long state_;
};

class SeaState {
public:
    // Calm unless waves.mode is 1 (regular) or 2 (JONSWAP); false with a message naming the parameter
    // when the waves cannot be built (breaking steepness).
    bool build(const UCParams& p, std::string& error);
    bool calm() const { return components_.empty(); }
    const std::vector<WaveComponent>& components() const { return components_; }

    double elevation(double x, double y, double t) const;
    // Water velocity u and acceleration a (local, du/dt) at r and t, and their gradients du/dr, da/dr
    // (rows: components, columns: x, y, z). Above the mean surface without stretching, the kinematics
    // of z = 0; with Wheeler stretching those of z stretched into the water column below the elevation.
    void kinematics(const Vec3& r, double t, Vec3& u, Vec3& a, Mat3* du, Mat3* da) const;

private:
    double ramp(double t) const;
    // The deep-water wavenumber (alpha + beta i)^2 / g of component i of equally spaced frequencies
    // alpha + beta i: quadratic in i, so exp(k_i (z + i s)) follows from its predecessor by two complex
    // multiplications (kinematics); the true k_i differs from it by the component's ladderShift.
    double ladder_k(double i) const { return (ladderAlpha_ + ladderBeta_ * i) * (ladderAlpha_ + ladderBeta_ * i) / gravity_; }
    // cos and sin of (omega t - phase) per component at time t: computed once per time, as the
    // integrator evaluates every quadrature point at one time (a cache of this instance's model,
    // which no other instance shares).
    void phases_at(double t) const;
    std::vector<WaveComponent> components_;
    mutable std::vector<double> cosPhase_, sinPhase_;
    mutable double phaseTime_ = 0.0;
    mutable bool phaseValid_ = false;
    double depth_ = 0.0, rampTime_ = 0.0, cosb_ = 1.0, sinb_ = 0.0;
    double gravity_ = 9.81, ladderAlpha_ = 0.0, ladderBeta_ = 0.0;
    bool wheeler_ = false;
};

}  // namespace uc
