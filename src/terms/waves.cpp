// waves.cpp - Airy components, JONSWAP discretization, kinematics.
#include "terms/waves.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <utility>

#include "terms/sea_state.h"

namespace uc {
namespace {


// The bottom's image term of a component at depth z, e^{-k(2h + z)}, is left out where it is below
// this fraction of the component's own e^{kz} (lost in its round-off): near the surface of deep water,
// not near the bottom, where the two are equal.
constexpr double kNegligibleBottom = 1e-18;

// A component with k z below this (e^{kz} < 4e-18, and its depth factors below twice that) moves the
// water at z by less than 1e-17 of its surface motion: it is left out there. The components ascend in
// k (in frequency, and k grows with the frequency), so the sum stops at the first such one.
constexpr double kNegligibleDepthExponent = -40.0;

// The lattice of the Taylor expansions (WaveExpansion). A term whose exponent moves by x over a cell
// leaves a remainder of x^13 e^{2x} / 13! of its size in the velocity's polynomial of degree 12 and
// x^12 e^{2x} / 12! in its derivative in t (one e^x for the term's growth, one for a node up to half a
// side deeper than the point). A band's cells are the largest of half-side f kCellSpace / k_max and
// half-window f kCellTime / w_max whose summed remainders stay below kVelocityRemainder and kRemainder
// of the local scales (build_expansions); a single component reaches them at f = 1, x = 0.72.
constexpr double kCellSpace = 0.17;
constexpr double kCellTime = 0.55;
// Lattice indices beyond this (a point or time no run reaches, or not a number) are not formed.
constexpr double kLatticeReach = 1e15;
// The summed remainders of the velocity and of the acceleration stay below these fractions of their
// local scales. The image terms (the longest waves, whose exponents move less over a cell) enter the
// coefficients up to the lowest degree whose remainder_bound is below kRemainder; their higher ones
// are negligible.
constexpr double kVelocityRemainder = 6e-12;
constexpr double kRemainder = 1e-10;
// Seas of fewer components are summed directly: an evaluation of the polynomial costs about what a
// sum of 16 terms costs (about 1,000 instructions against 60 per term), and the cells' expansions come
// on top (a regular wave ran 30 % slower from the polynomial, a sea of 50 components 4 times faster).
constexpr size_t kPolynomialComponents = 16;
// A depth band leaves out the components that together move the water by less than this fraction
// of the local velocity scale at its top.
constexpr double kNegligibleTerms = 1e-12;

}  // namespace

double wave_number(double omega, double depth, double gravity) { return pm_wave_number(omega, depth, gravity); }

std::string given_waves_violation(const UCParams& p) {
    const char* from = p.wavesFile[0] != '\0' ? "waves.file" : "the lineFile deck";
    char text[400];
    if (p.waveComponentCount <= 0 || p.waveComponentCount > UC_MAX_WAVE_COMPONENTS) {
        if (p.waveComponentCount <= 0)
            return "waves.mode = 3 (given components) has none: set waves.file (rows omega [rad/s], amplitude [m], phase "
                   "[rad], [direction, rad]) or a lineFile deck with WaveKin 2, 3 or 7";
        std::snprintf(text, sizeof text, "waves.mode = 3: %d components of %s, the FMU holds %d", p.waveComponentCount,
                      from, UC_MAX_WAVE_COMPONENTS);
        return text;
    }
    if (!(p.gravity > 0.0)) {
        std::snprintf(text, sizeof text, "gravity = %.17g: waves need gravity, it sets their wavelength (w^2 = g k tanh(k h))",
                      p.gravity);
        return text;
    }
    for (int k = 0; k < p.waveComponentCount; ++k) {
        const double* c = p.waveComponents + 4 * k;
        const char* what = nullptr;
        if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]) || !std::isfinite(c[3])) {
            what = "a value is not a finite number";
        } else if (c[1] < 0.0) {
            what = "a negative amplitude (a phase of pi turns a component over)";
        } else if (c[1] > 0.0 && !(c[0] > 0.0)) {
            what = "a component of frequency 0 or below is not a wave (a mean level is not a wave)";
        }
        if (what != nullptr) {
            std::snprintf(text, sizeof text, "wave component %d of %s: omega = %.17g rad/s, amplitude = %.17g m, phase = "
                          "%.17g rad, direction = %.17g rad: %s", k + 1, from, c[0], c[1], c[2], c[3], what);
            return text;
        }
        if (c[1] == 0.0) continue;
        const double wavelength = 2.0 * kPi / wave_number(c[0], p.waterDepth, p.gravity);
        if (2.0 * c[1] > wavelength / 7.0) {
            std::snprintf(text, sizeof text, "wave component %d of %s: amplitude = %.17g m at omega = %.17g rad/s is "
                          "too steep in %.17g m of water: H / lambda = %.3g exceeds the breaking limit 1/7 (lambda = %.4g m)",
                          k + 1, from, c[1], c[0], p.waterDepth, 2.0 * c[1] / wavelength, wavelength);
            return text;
        }
    }
    return {};
}


void spreading_directions(double s, int n, std::vector<double>& offsets, std::vector<double>& weights) {
    offsets.assign(static_cast<size_t>(std::max(n, 0)), 0.0);
    weights.assign(offsets.size(), 0.0);
    // G(s) = Gamma(s + 1) / (2 sqrt(pi) Gamma(s + 1/2)), through lgamma for large s
    const double G = std::exp(std::lgamma(s + 1.0) - std::lgamma(s + 0.5)) / (2.0 * std::sqrt(kPi));
    const double band = 2.0 * kPi / n;
    for (int j = 0; j < n; ++j) {
        const double theta = -kPi + (j + 0.5) * band;
        offsets[static_cast<size_t>(j)] = theta;
        weights[static_cast<size_t>(j)] = G * std::pow(std::cos(0.5 * theta), 2.0 * s) * band;
    }
}

unsigned long long SplitMix64::next() {
    std::uint64_t state = state_;
    const std::uint64_t z = pm_splitmix64_next(&state);
    state_ = state;
    return z;
}

bool SeaState::build(const UCParams& p, std::string& error) {
    components_.clear();
    groups_.clear();
    if (p.wavesMode == 0 || (p.wavesMode != 3 && p.wavesHeight == 0.0)) return true;
    depth_ = p.waterDepth;
    rampTime_ = p.wavesRampTime;
    wheeler_ = p.wavesStretching != 0;
    gravity_ = p.gravity;
    if (p.wavesMode == 3) return build_given(p, error);
    const double g = p.gravity;
    // The components (sea_state.h, shared with the partner FMUs); a breaking sea is refused naming waves.height.
    const PMWaves waves = {p.wavesMode, p.wavesHeight, p.wavesPeriod, p.wavesGamma, p.wavesDirection,
                           static_cast<std::uint64_t>(p.wavesSeed), p.wavesNComponents, p.wavesRampTime, depth_, g};
    std::vector<PMWaveComponent> generated(pm_sea_size(&waves));
    char text[300];
    if (pm_sea_components(&waves, generated.data(), text, sizeof text) != 0) {
        error = text;
        return false;
    }
    std::vector<WaveComponent> components;
    for (const PMWaveComponent& c : generated) components.push_back({c.amplitude, c.omega, c.k, c.phase});
    const double wp = 2.0 * kPi / p.wavesPeriod;
    // The ladder of the JONSWAP frequencies w0 + (i + 1/2) dw (kinematics); a single component is its
    // own ladder.
    const double wp0 = 0.5 * wp;
    const double dwAll = p.wavesMode == 1 ? 0.0 : (3.0 * wp - wp0) / p.wavesNComponents;
    if (p.wavesMode == 2 && p.wavesSpreading > 0.0 && p.wavesNDirections > 1) {
        build_spread(p, components, wp0 + 0.5 * dwAll, dwAll);
        return true;
    }
    build_direction(std::move(components), p.wavesDirection, p.wavesMode == 1 ? wp : wp0 + 0.5 * dwAll, dwAll);
    return true;
}

void SeaState::build_spread(const UCParams& p, const std::vector<WaveComponent>& components, double alpha, double beta) {
    std::vector<double> offsets, weights;
    spreading_directions(p.wavesSpreading, p.wavesNDirections, offsets, weights);
    double total = 0.0;  // 1 up to the midpoint rule's error: the sea keeps Hs exactly
    for (double w : weights) total += w;
    const size_t main = static_cast<size_t>(std::max_element(weights.begin(), weights.end()) - weights.begin());
    // Phases: direction j, component i takes uniform number j n + i of the seed's sequence (direction 0's
    // are the long-crested sea's).
    SplitMix64 random(static_cast<unsigned long long>(p.wavesSeed));
    std::vector<WaveComponent> mainComponents;
    for (size_t j = 0; j < offsets.size(); ++j) {
        const double scale = std::sqrt(weights[j] / total);
        std::vector<WaveComponent> direction(components);
        for (WaveComponent& c : direction) c.amplitude *= scale, c.phase = 2.0 * kPi * random.uniform();
        if (!(weights[j] > 0.0)) continue;  // a direction the spreading leaves empty (underflow)
        if (j == main) {
            mainComponents = std::move(direction);
            continue;
        }
        SeaState group;
        group.depth_ = depth_, group.rampTime_ = rampTime_, group.wheeler_ = wheeler_, group.gravity_ = gravity_;
        group.build_direction(std::move(direction), p.wavesDirection + offsets[j], alpha, beta);
        groups_.push_back(std::move(group));
    }
    build_direction(std::move(mainComponents), p.wavesDirection + offsets[main], alpha, beta);
}

bool SeaState::build_given(const UCParams& p, std::string& error) {
    error = given_waves_violation(p);
    if (!error.empty()) return false;
    // one sea per direction of travel, in the order of their first component
    std::vector<double> directions;
    std::vector<std::vector<WaveComponent>> byDirection;
    for (int k = 0; k < p.waveComponentCount; ++k) {
        const double* c = p.waveComponents + 4 * k;
        if (c[1] == 0.0) continue;
        size_t d = 0;
        while (d < directions.size() && directions[d] != c[3]) ++d;
        if (d == directions.size()) directions.push_back(c[3]), byDirection.emplace_back();
        byDirection[d].push_back({c[1], c[0], wave_number(c[0], depth_, gravity_), c[2]});
    }
    if (directions.empty()) return true;  // calm: every amplitude is 0
    for (size_t d = 1; d < directions.size(); ++d) {
        SeaState group;
        group.depth_ = depth_, group.rampTime_ = rampTime_, group.wheeler_ = wheeler_, group.gravity_ = gravity_;
        group.build_direction(std::move(byDirection[d]), directions[d]);
        groups_.push_back(std::move(group));
    }
    build_direction(std::move(byDirection[0]), directions[0]);
    return true;
}

void SeaState::build_direction(std::vector<WaveComponent> components, double direction) {
    std::stable_sort(components.begin(), components.end(),
                     [](const WaveComponent& a, const WaveComponent& b) { return a.omega < b.omega; });
    // Equally spaced frequencies (to 1e-9 of the highest) climb the ladder of the deep-water
    // wavenumbers (kinematics); others climb a ladder of zeros, every e^{k zeta} then its own shift.
    const size_t n = components.size();
    const double w0 = components.front().omega, dw = n > 1 ? (components.back().omega - w0) / static_cast<double>(n - 1) : 0.0;
    bool even = n == 1 || dw > 0.0;
    for (size_t i = 0; i < n && even; ++i)
        even = std::fabs(components[i].omega - (w0 + dw * static_cast<double>(i))) <= 1e-9 * components.back().omega;
    build_direction(std::move(components), direction, even ? w0 : 0.0, even ? dw : 0.0);
}

void SeaState::build_direction(std::vector<WaveComponent> components, double direction, double alpha, double beta) {
    components_ = std::move(components);
    direction_ = direction;
    cosb_ = std::cos(direction);
    sinb_ = std::sin(direction);
    ladderAlpha_ = alpha;
    ladderBeta_ = beta;
    for (size_t i = 0; i < components_.size(); ++i) {
        WaveComponent& c = components_[i];
        c.kx = c.k * cosb_;
        c.ky = c.k * sinb_;
        const double image = std::exp(-2.0 * c.k * depth_);
        c.bottom = image;
        c.depthScale = 1.0 / (1.0 - image);
        c.velocityScale = c.amplitude * c.omega * c.depthScale;
        c.accelerationScale = c.velocityScale * c.omega;
        c.ladderShift = c.k - ladder_k(static_cast<double>(i));
        if (std::fabs(c.ladderShift) <= 4e-16 * c.k) c.ladderShift = 0.0;  // deep water: on the ladder to round-off
        c.deepMoments = std::fabs(c.k - c.omega * c.omega / gravity_) <= 1e-14 * c.k;
    }
    for (Phases* phases : {&phases_, &expansionPhases_}) {
        phases->cos.assign(components_.size(), 0.0);
        phases->sin.assign(components_.size(), 0.0);
        phases->valid = false;
    }
    build_expansions();
}

void SeaState::build_expansions() {
    constexpr int D = WaveExpansion::kDegree;
    double factorial[D + 1];
    factorial[0] = 1.0;
    for (int j = 1; j <= D; ++j) factorial[j] = factorial[j - 1] * j;
    taylorWeights_.assign(components_.size() * WaveExpansion::kTerms, 0.0);
    double kMax = 0.0;
    for (size_t i = 0; i < components_.size(); ++i) {
        const WaveComponent& c = components_[i];
        kMax = std::max(kMax, c.k);
        double* w = taylorWeights_.data() + i * WaveExpansion::kTerms;
        double km = 1.0;  // k^m
        for (int m = 0, j = 0; m <= D; ++m, km *= c.k) {
            double wn = 1.0;  // w^n
            for (int n = 0; n <= D - m; ++n, ++j, wn *= c.omega) w[j] = c.velocityScale * km * wn / (factorial[m] * factorial[n]);
        }
    }
    // Depth bands: [-2/kMax, 0], then each twice as deep as the one above; a band keeps the components
    // that matter at its top (the shallowest of its points), and sizes its cells by the largest k and
    // w among them: at depth the short waves are gone, and the cells grow.
    bands_.clear();
    const size_t n = components_.size();
    std::vector<double> tail(n + 1);
    for (double top = 0.0;; top = top == 0.0 ? -2.0 / kMax : 2.0 * top) {
        // the terms after the first `count`: sum 2 a w e^{kz} (the image is at most the term itself)
        tail[n] = 0.0;
        for (size_t i = n; i-- > 0;) tail[i] = tail[i + 1] + 2.0 * components_[i].velocityScale * std::exp(components_[i].k * top);
        size_t count = n;
        while (count > 1 && tail[count - 1] <= kNegligibleTerms * tail[0]) --count;
        DepthBand band;
        band.top = top;
        band.count = static_cast<int>(count);
        double k = 0.0, w = 0.0;
        for (size_t i = 0; i < count; ++i) k = std::max(k, components_[i].k), w = std::max(w, components_[i].omega);
        // Cells of half-side rho = f kCellSpace / k and half-window tau = f kCellTime / w: component i's
        // exponent moves by x_i = k_i rho + w_i tau (rho the farthest point of a square cell, side / sqrt 2).
        // The components' remainders add up, each in proportion to its size at the band's top (deeper,
        // the short waves fade first, so the sum only shrinks against the local scale; the bottom's image
        // at most doubles a term): the largest f whose summed remainders stay below kVelocityRemainder
        // of the local velocity scale and kRemainder of the acceleration's.
        bool image = false;
        for (size_t i = 0; i < count; ++i) image = image || components_[i].bottom > 0.0;
        auto within = [&](double f) {
            double ev = 0.0, sv = 0.0, ea = 0.0, sa = 0.0;
            for (size_t i = 0; i < count; ++i) {
                const WaveComponent& c = components_[i];
                const double rho = f * kCellSpace / k, x = c.k * rho + c.omega * f * kCellTime / w;
                const double size = std::exp(c.k * top);
                double b = std::exp(x + c.k * rho) * x / (WaveExpansion::kDegree + 1);  // x^13 e^{..} / 13!
                for (int j = 1; j <= WaveExpansion::kDegree; ++j) b *= x / j;
                ev += c.velocityScale * size * b, sv += c.velocityScale * size;
                ea += c.accelerationScale * size * b * (WaveExpansion::kDegree + 1) / x, sa += c.accelerationScale * size;
            }
            const double doubling = image ? 2.0 : 1.0;
            return doubling * ev <= kVelocityRemainder * sv && doubling * ea <= kRemainder * sa;
        };
        double f = 1.0;
        while (!within(f) && f > 0.1) f *= 0.95;
        while (f < 20.0 && within(1.05 * f)) f *= 1.05;
        band.cell = std::sqrt(2.0) * f * kCellSpace / k;
        band.window = 2.0 * f * kCellTime / w;
        bands_.push_back(band);
        if (count == 1 || bands_.size() == 64) break;  // deeper bands would be the same
    }
}

const SeaState::Phases& SeaState::phases_at(Phases& cache, double t) const {
    if (cache.valid && t == cache.time) return cache;
    for (size_t i = 0; i < components_.size(); ++i) {
        const double phi = components_[i].omega * t - components_[i].phase;
        cache.cos[i] = std::cos(phi);
        cache.sin[i] = std::sin(phi);
    }
    cache.time = t;
    cache.valid = true;
    return cache;
}

double SeaState::ramp(double t) const {
    double f, df, ddf;
    pm_sea_ramp(rampTime_, t, &f, &df, &ddf);  // the partners' ramp (sea_state.h): one sea for both
    return f;
}

double SeaState::elevation(double x, double y, double t) const {
    double eta = own_elevation(x, y, t);
    for (const SeaState& group : groups_) eta += group.own_elevation(x, y, t);
    return eta;
}

double SeaState::own_elevation(double x, double y, double t) const {
    if (components_.empty()) return 0.0;
    const Phases& ph = phases_at(phases_, t);
    double eta = 0.0;
    for (size_t i = 0; i < components_.size(); ++i) {  // cos(k.x - (w t - p))
        const WaveComponent& c = components_[i];
        const double kx = c.kx * x + c.ky * y;
        eta += c.amplitude * (std::cos(kx) * ph.cos[i] + std::sin(kx) * ph.sin[i]);
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

SeaState::Ladder::Ladder(const SeaState& sea, double z, double s)
    : sea_(sea), z_(z), s_(s), span_(std::fabs(z) + std::fabs(s)) {
    // R = exp((q_{i+1} - q_i)(z + i s)), the ratio of successive ladder values, grows by
    // Q = exp((q_{i+2} - 2 q_{i+1} + q_i)(z + i s)) per component.
    const double dd = 2.0 * sea.ladderBeta_ * sea.ladderBeta_ / sea.gravity_;
    if (sea.components_.size() > 1) cexp_scaled(dd, z, s, Qr_, Qi_);
}

void SeaState::Ladder::next(size_t i, double& Fr, double& Fi) {
    const WaveComponent& c = sea_.components_[i];
    if (i % kLadderRestart == 0) {
        const double q = sea_.ladder_k(static_cast<double>(i));
        cexp_scaled(q, z_, s_, Er_, Ei_);
        cexp_scaled(sea_.ladder_k(static_cast<double>(i) + 1.0) - q, z_, s_, Rr_, Ri_);
    } else {
        const double er = Er_ * Rr_ - Ei_ * Ri_, ei = Er_ * Ri_ + Ei_ * Rr_;
        const double rr = Rr_ * Qr_ - Ri_ * Qi_, ri = Rr_ * Qi_ + Ri_ * Qr_;
        Er_ = er, Ei_ = ei, Rr_ = rr, Ri_ = ri;
    }
    // F = exp(k (z + i s)) = E exp(shift (z + i s))
    Fr = Er_, Fi = Ei_;
    if (c.ladderShift != 0.0) {
        double xr = c.ladderShift * z_, xi = c.ladderShift * s_, gr, gi;
        if (std::fabs(c.ladderShift) * span_ < kSmallShift) {
            // 1 + x (1 + x/2 (1 + x/3 (1 + x/4)))
            double pr = 1.0 + 0.25 * xr, pi = 0.25 * xi;
            double tr = 1.0 + (xr * pr - xi * pi) / 3.0, ti = (xr * pi + xi * pr) / 3.0;
            pr = 1.0 + 0.5 * (xr * tr - xi * ti), pi = 0.5 * (xr * ti + xi * tr);
            gr = 1.0 + xr * pr - xi * pi, gi = xr * pi + xi * pr;
        } else {
            cexp_scaled(c.ladderShift, z_, s_, gr, gi);
        }
        Fr = Er_ * gr - Ei_ * gi, Fi = Er_ * gi + Ei_ * gr;
    }
}

void SeaState::kinematics(const Vec3& r, double t, Vec3& u, Vec3& a, Mat3* du, Mat3* da) const {
    u.setZero();
    a.setZero();
    if (du) du->setZero();
    if (da) da->setZero();
    if (components_.empty()) return;
    double z = std::min(r.z(), 0.0);
    if (wheeler_) {
        const double eta = elevation(r.x(), r.y(), t);
        z = std::min(depth_ * (r.z() - eta) / (depth_ + eta), 0.0);
    }
    add_kinematics(r, z, t, u, a, du, da);
    for (const SeaState& group : groups_) group.add_kinematics(r, z, t, u, a, du, da);
}

void SeaState::add_kinematics(const Vec3& r, double z, double t, Vec3& u, Vec3& a, Mat3* du, Mat3* da) const {
    const Phases& ph = phases_at(phases_, t);
    const double f = ramp(t);
    const double s = cosb_ * r.x() + sinb_ * r.y();  // along the direction of travel
    double uh = 0.0, w = 0.0, ah = 0.0, aw = 0.0;                  // along the direction of travel, vertical
    double duh_ds = 0.0, duh_dz = 0.0, dw_ds = 0.0, dw_dz = 0.0;     // gradients in (s, z)
    double dah_ds = 0.0, dah_dz = 0.0, daw_ds = 0.0, daw_dz = 0.0;
    const bool belowSurface = r.z() < 0.0 || wheeler_;
    const bool gradients = du != nullptr || da != nullptr;
    Ladder ladder(*this, z, s);
    for (size_t i = 0; i < components_.size(); ++i) {
        const WaveComponent& c = components_[i];
        if (c.k * z < kNegligibleDepthExponent) break;  // and so are all shorter components
        double Fr, Fi;  // exp(k (z + i s))
        ladder.next(i, Fr, Fi);
        // G = F exp(-i (w t - p)) = e^{kz} (cos theta + i sin theta), theta = k s - w t + p
        const double Gr = Fr * ph.cos[i] + Fi * ph.sin[i];
        const double Gi = Fi * ph.cos[i] - Fr * ph.sin[i];
        const double A1 = c.velocityScale, A2 = c.accelerationScale;
        const double G2 = Gr * Gr + Gi * Gi;  // e^{2kz}
        if (c.bottom < kNegligibleBottom * G2 && !gradients) {  // deep water, the residual's case: cosh, sinh -> e^{kz}
            uh += A1 * Gr;
            w += A1 * Gi;
            ah += A2 * Gi;
            aw -= A2 * Gr;
            continue;
        }
        // the bottom's image term: e^{-k(2h + z)} e^{i theta} = bottom G / |G|^2
        const double image = c.bottom > 0.0 ? c.bottom / G2 : 0.0;
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
    u += f * Vec3(uh * cosb_, uh * sinb_, w);
    a += f * Vec3(ah * cosb_, ah * sinb_, aw);
    // d/dx = cos(beta) d/ds, d/dy = sin(beta) d/ds (the stretching's own slope is left out).
    Mat3 g;
    if (du) {
        g << duh_ds * cosb_ * cosb_, duh_ds * cosb_ * sinb_, duh_dz * cosb_,
             duh_ds * sinb_ * cosb_, duh_ds * sinb_ * sinb_, duh_dz * sinb_,
             dw_ds * cosb_, dw_ds * sinb_, dw_dz;
        *du += f * g;
    }
    if (da) {
        g << dah_ds * cosb_ * cosb_, dah_ds * cosb_ * sinb_, dah_dz * cosb_,
             dah_ds * sinb_ * cosb_, dah_ds * sinb_ * sinb_, dah_dz * sinb_,
             daw_ds * cosb_, daw_ds * sinb_, daw_dz;
        *da += f * g;
    }
}

namespace {

typedef double Pair __attribute__((vector_size(16)));  // a complex number (real, imaginary), for SSE2

// The bound on the remainder of a velocity polynomial of degree d whose terms' exponents move by at
// most x over the cell, on its derivative in t (the weaker): x^d e^{2x} / d!, relative to the local
// acceleration scale (e^x for the term's growth, e^x for the node lying deeper than the point).
double remainder_bound(double x, int d) {
    double b = std::exp(2.0 * x);
    for (int j = 1; j <= d; ++j) b *= x / j;
    return b;
}

}  // namespace

void SeaState::expand(const DepthBand& band, double z, double s, double t, bool surface,
                      WaveExpansion::Polynomial& e) const {
    constexpr int D = WaveExpansion::kDegree, T = WaveExpansion::kTerms;
    // U = u_s + i w = sum a w (G + conj(H)): G = e^{k zeta - i (w t - p)}, and the bottom's image
    // H = e^{-k (2h + conj(zeta)) - i (w t - p)}, whose conjugate e^{-k (2h + zeta) + i (w t - p)} is
    // a function of zeta too. So U is one polynomial in (dzeta, dt): the coefficient of dzeta^m dt^n
    // is sum w_mn ((-i)^n G + (-1)^m i^n conj(H)), w_mn = a w k^m w^n / (m! n!), G and H at the node.
    Pair sumG[T], sumH[T], moment[2 * D + 1], imageMoment[2 * D + 1];
    for (int j = 0; j < T; ++j) sumG[j] = sumH[j] = Pair{0.0, 0.0};
    for (int j = 0; j <= 2 * D; ++j) moment[j] = imageMoment[j] = Pair{0.0, 0.0};
    // The image terms of the components with e^{-2k(h + z)} above kNegligibleBottom at the cell's
    // deepest point, half a side below the node (a prefix of the components: k ascends) ...
    const double deepest = z - 0.5 * band.cell;
    int nImage = 0;
    double kImage = 0.0, wImage = 0.0;
    for (int i = 0; i < band.count && !surface; ++i) {
        const WaveComponent& c = components_[i];
        if (c.bottom == 0.0 || -2.0 * c.k * (depth_ + deepest) < std::log(kNegligibleBottom)) break;
        nImage = i + 1, kImage = c.k, wImage = c.omega;
    }
    // ... which need fewer terms: they are the longest waves, whose exponents move less over the cell
    int imageDegree = -1;
    if (nImage > 0) {
        const double x = kImage * band.cell / std::sqrt(2.0) + wImage * 0.5 * band.window;
        imageDegree = 1;
        while (imageDegree < D && remainder_bound(x, imageDegree) > kRemainder) ++imageDegree;
    }
    // Deep-water components (k = w^2 / g): w_mn = a w^{2m + n + 1} / (g^m m! n!), so their sums need
    // only the moments sum a w^{j + 1} G (and H), j <= 2D.
    const Phases& ph = phases_at(expansionPhases_, t);
    Ladder ladder(*this, z, s);
    for (int i = 0; i < band.count; ++i) {
        const WaveComponent& c = components_[i];
        double Fr, Fi;  // e^{k zeta}
        ladder.next(static_cast<size_t>(i), Fr, Fi);
        const Pair G = {Fr * ph.cos[i] + Fi * ph.sin[i], Fi * ph.cos[i] - Fr * ph.sin[i]};
        const double* w = taylorWeights_.data() + static_cast<size_t>(i) * T;
        // the weights are a w k^m w^n / (m! n!): for the surface, a in place of a w (depth factor included)
        const double weight = surface ? c.amplitude : c.velocityScale;
        const Pair Gw = surface ? (c.amplitude / c.velocityScale) * G : G;
        if (c.deepMoments) {
            Pair p = weight * G;
            for (int j = 0; j <= 2 * D; ++j) moment[j] += p, p *= c.omega;
        } else {
            for (int j = 0; j < T; ++j) sumG[j] += w[j] * Gw;
        }
        if (i < nImage) {
            const double m2 = G[0] * G[0] + G[1] * G[1];  // e^{2kz}
            const Pair H = m2 > 1e-300 ? (c.bottom / m2) * G : Pair{0.0, 0.0};  // e^{-k(2h + z)} e^{i theta}
            if (c.deepMoments) {
                Pair p = c.velocityScale * H;
                for (int j = 0; j <= 2 * imageDegree; ++j) imageMoment[j] += p, p *= c.omega;
            } else {
                for (int mm = 0, j = 0; mm <= imageDegree; ++mm, j += D - imageDegree) {
                    for (int nn = 0; nn <= imageDegree - mm; ++nn, ++j) sumH[j] += w[j] * H;
                }
            }
        }
    }
    double gm = 1.0, fm = 1.0;  // g^m, m!
    for (int mm = 0, j = 0; mm <= D; ++mm, gm *= gravity_, fm *= mm) {
        double fn = 1.0;  // n!
        for (int nn = 0; nn <= D - mm; ++nn, ++j, fn *= nn) {
            const double scale = 1.0 / (fm * fn * gm);
            const Pair g = sumG[j] + scale * moment[2 * mm + nn];
            const Pair h = mm + nn <= imageDegree ? sumH[j] + scale * imageMoment[2 * mm + nn] : Pair{0.0, 0.0};
            // (-i)^n g + (-1)^m i^n conj(h)
            Pair ig = g, ih = {h[0], -h[1]};
            switch (nn % 4) {
                case 1: ig = Pair{g[1], -g[0]}, ih = Pair{h[1], h[0]}; break;      // -i g, i conj(h)
                case 2: ig = -g, ih = Pair{-h[0], h[1]}; break;
                case 3: ig = Pair{-g[1], g[0]}, ih = Pair{-h[1], -h[0]}; break;   // i g, -i conj(h)
                default: break;
            }
            const Pair coefficient = ig + ((mm % 2 == 0) ? ih : -ih);
            __builtin_memcpy(e.c + 2 * j, &coefficient, sizeof coefficient);
        }
    }
    e.z = z, e.s = s, e.t = t;
}

namespace {

// U = sum_m dzeta^m sum_n c[m][n] dt^n, its derivative in t (A) and, with Gradient, both derivatives in
// zeta (U', A'), by Horner's rule in dzeta over the rows m = M, ..., 0, each a polynomial in dt with
// its derivative. Rows of fixed length, so the compiler unrolls them.
struct Polynomial {
    Pair U = {0.0, 0.0}, A = {0.0, 0.0}, dU = {0.0, 0.0}, dA = {0.0, 0.0};
};

inline Pair times(const Pair& x, double zr, double zi) { return x * zr + Pair{x[1], x[0]} * Pair{-zi, zi}; }

template <int D, int M, bool Gradient>
inline void horner_rows(const double* c, double dt, double zr, double zi, Polynomial& p) {
    constexpr int begin = M * (D + 1) - M * (M - 1) / 2, length = D - M + 1;
    Pair q = {0.0, 0.0}, r = {0.0, 0.0};  // the row's polynomial in dt and its derivative
    for (int j = length - 1; j >= 0; --j) {
        Pair cj;
        __builtin_memcpy(&cj, c + 2 * (begin + j), sizeof cj);
        r = r * dt + q;
        q = q * dt + cj;
    }
    if constexpr (Gradient) {
        p.dU = times(p.dU, zr, zi) + p.U;
        p.dA = times(p.dA, zr, zi) + p.A;
    }
    p.U = times(p.U, zr, zi) + q;
    p.A = times(p.A, zr, zi) + r;
    if constexpr (M > 0) horner_rows<D, M - 1, Gradient>(c, dt, zr, zi, p);
}

}  // namespace

const WaveExpansion::Polynomial& SeaState::cell_polynomial(size_t b, double z, double s, double t, bool surface,
                                                         WaveExpansion::Polynomial& e) const {
    const DepthBand& band = bands_[b];
    const long long iz = static_cast<long long>(std::floor((band.top - z) / band.cell));
    const long long is = static_cast<long long>(std::floor(s / band.cell + 0.5));
    const long long it = static_cast<long long>(std::floor(t / band.window));
    const long long b64 = static_cast<long long>(b);
    if (e.node[0] != b64 || e.node[1] != iz || e.node[2] != is || e.node[3] != it) {
        expand(band, surface ? 0.0 : band.top - (static_cast<double>(iz) + 0.5) * band.cell,
               static_cast<double>(is) * band.cell, (static_cast<double>(it) + 0.5) * band.window, surface, e);
        e.node[0] = b64, e.node[1] = iz, e.node[2] = is, e.node[3] = it;
    }
    return e;
}

bool SeaState::reachable(const Vec3& r, double t) const {
    const double s = cosb_ * r.x() + sinb_ * r.y();
    const double top = bands_[0].cell, window = bands_[0].window;
    return std::fabs(r.z() / top) < kLatticeReach && std::fabs(s / top) < kLatticeReach && std::fabs(t / window) < kLatticeReach;
}

double SeaState::expanded_elevation(const Vec3& r, double t, WaveExpansion& cache) const {
    constexpr int D = WaveExpansion::kDegree;
    const double s = cosb_ * r.x() + sinb_ * r.y();
    const WaveExpansion::Polynomial& e = cell_polynomial(0, 0.0, s, t, true, cache.surface);
    Polynomial p;
    horner_rows<D, D, false>(e.c, t - e.t, 0.0, s - e.s, p);
    return p.U[0];
}

void SeaState::add_expanded(const Vec3& r, double z, double t, WaveExpansion& cache, Vec3& u, Vec3& a, Mat3* du,
                            Mat3* da) const {
    constexpr int D = WaveExpansion::kDegree;
    const double f = ramp(t);
    const double s = cosb_ * r.x() + sinb_ * r.y();
    size_t b = 0;
    while (b + 1 < bands_.size() && z < bands_[b + 1].top) ++b;
    const WaveExpansion::Polynomial& e = cell_polynomial(b, z, s, t, false, cache.water);
    const double dz = z - e.z, ds = s - e.s, dt = t - e.t;
    Polynomial p;
    const bool gradients = du != nullptr || da != nullptr;
    if (gradients) {
        horner_rows<D, D, true>(e.c, dt, dz, ds, p);
    } else {
        horner_rows<D, D, false>(e.c, dt, dz, ds, p);
    }
    u += f * Vec3(p.U[0] * cosb_, p.U[0] * sinb_, p.U[1]);
    a += f * Vec3(p.A[0] * cosb_, p.A[0] * sinb_, p.A[1]);
    if (!gradients) return;
    // U = u_s + i w is analytic in zeta = z + i s: d/dz = U', d/ds = i U'. Above the mean surface
    // without stretching the kinematics of z = 0, which do not change with z; the stretching's own
    // slope is left out (as in kinematics()).
    const double zScale = r.z() < 0.0 || wheeler_ ? 1.0 : 0.0;
    auto gradient = [&](const Pair& d, Mat3& out) {
        const double dus_dz = zScale * d[0], dw_dz = zScale * d[1], dus_ds = -d[1], dw_ds = d[0];
        Mat3 g;
        g << dus_ds * cosb_ * cosb_, dus_ds * cosb_ * sinb_, dus_dz * cosb_,
             dus_ds * sinb_ * cosb_, dus_ds * sinb_ * sinb_, dus_dz * sinb_,
             dw_ds * cosb_, dw_ds * sinb_, dw_dz;
        out += f * g;
    };
    if (du) gradient(p.dU, *du);
    if (da) gradient(p.dA, *da);
}

void SeaState::expanded_kinematics(const Vec3& r, double t, WaveExpansion& cache, Vec3& u, Vec3& a, Mat3* du,
                                   Mat3* da) const {
    // A short sum costs less than the polynomial: a sea (or a direction of a sea of several) of fewer
    // components is summed, and so is a point beyond the lattice's reach (or not a number).
    bool expand = components_.size() >= kPolynomialComponents && reachable(r, t);
    for (size_t g = 0; g < groups_.size() && expand; ++g)
        expand = groups_[g].components_.size() >= kPolynomialComponents && groups_[g].reachable(r, t);
    if (!expand) {
        kinematics(r, t, u, a, du, da);
        return;
    }
    if (cache.groups.size() != groups_.size()) cache.groups.resize(groups_.size());
    double z = std::min(r.z(), 0.0);
    if (wheeler_) {  // z stretched into the water column below the elevation, as kinematics() does
        double surface = expanded_elevation(r, t, cache);
        for (size_t g = 0; g < groups_.size(); ++g) surface += groups_[g].expanded_elevation(r, t, cache.groups[g]);
        const double eta = ramp(t) * surface;
        z = std::min(depth_ * (r.z() - eta) / (depth_ + eta), 0.0);
    }
    u.setZero();
    a.setZero();
    if (du) du->setZero();
    if (da) da->setZero();
    add_expanded(r, z, t, cache, u, a, du, da);
    for (size_t g = 0; g < groups_.size(); ++g) groups_[g].add_expanded(r, z, t, cache.groups[g], u, a, du, da);
}

}  // namespace uc
