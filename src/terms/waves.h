// waves.h - linear (Airy) wave kinematics: a regular wave, a JONSWAP sea or given components (waves.mode 3)
// as a sum of components, with finite-depth dispersion and optional Wheeler stretching (docs/waves.md).
//
// Convention: a component of amplitude a, frequency w, wavenumber k, direction of travel beta
// (from +x toward +y) and phase p has the elevation a cos(k (x cos beta + y sin beta) - w t + p); the
// regular wave has p = 0 (a crest at the origin at t = 0). Irregular phases come from the seed
// through SplitMix64 (a stated 64-bit generator, identical on every platform).
#pragma once

#include <string>
#include <vector>

#include "core/types.h"
#include "generated/uc_schema.h"

namespace uc {

struct WaveComponent {
    double amplitude = 0.0, omega = 0.0, k = 0.0, phase = 0.0;
    // precomputed by SeaState::build: k along x and y, exp(-2 k h), 1 / (1 - exp(-2 k h)), and k minus
    // the deep-water ladder value of its index (SeaState::ladder_k)
    double kx = 0.0, ky = 0.0, bottom = 0.0, depthScale = 1.0, ladderShift = 0.0;
    double velocityScale = 0.0, accelerationScale = 0.0;  // a w / (1 - e^{-2kh}), a w^2 / (1 - e^{-2kh})
    bool deepMoments = false;  // k = w^2 / g to 1e-14: its Taylor weights follow from powers of w
};

// The water's motion near one load point as a Taylor polynomial about a node of a lattice in (z, s, t)
// (SeaState::expanded_kinematics); the model keeps one per load point, reused while the point stays
// in the node's cell. U = u_s + i w (horizontal velocity along the direction of travel, vertical
// velocity) is a sum of terms a w e^{k zeta - i (w t - p)} in zeta = z + i s, plus in finite depth the
// conjugates of the bottom's image terms, a w e^{-k (2h + zeta) + i (w t - p)}: an analytic function
// of zeta, whose coefficients are those of the polynomial in (zeta - zeta_node, t - t_node).
struct WaveExpansion {
    static constexpr int kDegree = 12;  // total degree of the polynomials
    static constexpr int kTerms = (kDegree + 1) * (kDegree + 2) / 2;
    // Where row m (the terms dzeta^m dt^n) begins in a polynomial of degree kDegree
    static constexpr int offset(int m) { return m * (kDegree + 1) - m * (m - 1) / 2; }
    struct Polynomial {
        long long node[4] = {-1, 0, 0, 0};  // depth band, then the cell's indices in z, s and t
        double z = 0.0, s = 0.0, t = 0.0;  // the node
        // The coefficient of dzeta^m dt^n as (real, imaginary) pairs, rows m ascending, n ascending
        double c[2 * kTerms] = {};
    };
    Polynomial water;    // U = u_s + i w
    Polynomial surface;  // sum a e^{i (k s - w t + p)}, whose real part is the elevation (Wheeler stretching)
    // The polynomials of the seas of the other directions of travel (SeaState::groups), one each, in order
    std::vector<WaveExpansion> groups;
};

// The wavenumber of frequency omega in water of depth h: omega^2 = g k tanh(k h), solved by Newton's
// method to round-off.
double wave_number(double omega, double depth, double gravity);

// The cos-2s directional spreading D(theta) = G(s) cos^{2s}(theta / 2) about the mean direction, with
// G(s) = Gamma(s + 1) / (2 sqrt(pi) Gamma(s + 1/2)) so that it integrates to 1 over the circle, at the
// midpoints theta_j = -pi + (j + 1/2) 2 pi / n of n equal bands: offsets[j] = theta_j and weights[j] =
// D(theta_j) 2 pi / n (the midpoint rule, exact for a trigonometric polynomial of degree below n: for an
// integer s and n > s the weights sum to 1, and for n > s + 1 their mean cos(theta) is s / (s + 1)).
// For odd n the middle direction is the mean direction itself.
void spreading_directions(double s, int n, std::vector<double>& offsets, std::vector<double>& weights);

// waves.mode 3: empty when the given components (waveComponentCount, waveComponents) make a sea;
// otherwise why not, naming the component, its value, unit and the likely cause.
std::string given_waves_violation(const UCParams& p);

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
    // Calm unless waves.mode is 1 (regular), 2 (JONSWAP) or 3 (the given components waveComponents);
    // false with a message naming the parameter when the waves cannot be built (breaking steepness).
    bool build(const UCParams& p, std::string& error);
    bool calm() const { return components_.empty(); }
    // The components travelling along the first direction (all of them but for given components of
    // several directions: the others are in groups()), frequency ascending.
    const std::vector<WaveComponent>& components() const { return components_; }
    double direction() const { return direction_; }
    // Given components of other directions of travel: one sea per direction, summed with this one.
    const std::vector<SeaState>& groups() const { return groups_; }

    double elevation(double x, double y, double t) const;
    // Water velocity u and acceleration a (local, du/dt) at r and t, and their gradients du/dr, da/dr
    // (rows: components, columns: x, y, z). Above the mean surface without stretching, the kinematics
    // of z = 0; with Wheeler stretching those of z stretched into the water column below the elevation.
    void kinematics(const Vec3& r, double t, Vec3& u, Vec3& a, Mat3* du, Mat3* da) const;
    // The same velocity, acceleration and (when non-null) gradients from the Taylor polynomial of the
    // lattice cell holding (r, t), computed into `cache` when it holds another cell: within 1e-10 of
    // the local scale of each (docs/waves.md), at a fraction of the cost when a point stays in its
    // cell for many evaluations. A pure function of (r, t): the cache changes the cost, not the
    // result. With Wheeler stretching the elevation comes from a polynomial of its own (z stretched
    // with it, as kinematics() does). A sea of fewer than 16 components is summed (kinematics()); the seas
    // of several directions are each expanded (cache.groups) and summed.
    void expanded_kinematics(const Vec3& r, double t, WaveExpansion& cache, Vec3& u, Vec3& a, Mat3* du = nullptr,
                             Mat3* da = nullptr) const;
    // The depth bands of the lattice: below its top z, the components after the first `count` move
    // the water by less than 1e-12 of the local velocity scale; cells of side `cell` [m] in z and s,
    // and of `window` [s] in t, make every kept term's exponent move by at most kCellSpace +
    // kCellTime from the node's.
    struct DepthBand {
        double top = 0.0, cell = 0.0, window = 0.0;
        int count = 0;
    };
    const std::vector<DepthBand>& depth_bands() const { return bands_; }

private:
    double ramp(double t) const;
    // The components of one direction of travel (sorted here by frequency), their precomputed
    // factors, the ladder when the frequencies are equally spaced, and the expansions.
    bool build_given(const UCParams& p, std::string& error);
    // waves.spreading > 0: the JONSWAP components (amplitudes and frequencies of the long-crested sea,
    // its ladder alpha + beta i) in waves.nDirections directions, each scaled by the square root of its
    // share of the spreading and given its own phases; the most energetic direction is this sea.
    void build_spread(const UCParams& p, const std::vector<WaveComponent>& components, double alpha, double beta);
    // The expansions of this direction's sea alone: its complex elevation's real part (not ramped), and
    // its velocity, acceleration and gradients at r (z: the depth they are taken at) added, ramped, to
    // u, a, du, da; false where the point lies beyond the lattice's reach (then the direct sum serves).
    bool reachable(const Vec3& r, double t) const;
    double expanded_elevation(const Vec3& r, double t, WaveExpansion& cache) const;
    void add_expanded(const Vec3& r, double z, double t, WaveExpansion& cache, Vec3& u, Vec3& a, Mat3* du, Mat3* da) const;
    void build_direction(std::vector<WaveComponent> components, double direction);
    void build_direction(std::vector<WaveComponent> components, double direction, double ladderAlpha, double ladderBeta);
    // This direction's sum of the elevation, and its kinematics at r (z: the depth they are taken at,
    // stretched or not) added to u, a, du, da.
    double own_elevation(double x, double y, double t) const;
    void add_kinematics(const Vec3& r, double z, double t, Vec3& u, Vec3& a, Mat3* du, Mat3* da) const;
    // The deep-water wavenumber (alpha + beta i)^2 / g of component i of equally spaced frequencies
    // alpha + beta i: quadratic in i, so exp(k_i (z + i s)) follows from its predecessor by two complex
    // multiplications (kinematics); the true k_i differs from it by the component's ladderShift.
    double ladder_k(double i) const { return (ladderAlpha_ + ladderBeta_ * i) * (ladderAlpha_ + ladderBeta_ * i) / gravity_; }
    // cos and sin of (omega t - phase) per component at a time: computed once per time, as the
    // integrator evaluates every quadrature point at one time (a cache of this instance's model, which
    // no other instance shares). One for kinematics(), one for the expansions' node times.
    struct Phases {
        std::vector<double> cos, sin;
        double time = 0.0;
        bool valid = false;
    };
    const Phases& phases_at(Phases& cache, double t) const;
    // exp(k_i (z + i s)) of the components i = 0, 1, 2, ... in turn (k ascends): along the deep-water
    // ladder ladder_k, which follows from its predecessor by two complex multiplications, times the
    // component's finite-depth shift exp(ladderShift (z + i s)) (a Taylor polynomial when small);
    // restarted from a direct evaluation every kLadderRestart components to bound its round-off.
    class Ladder {
    public:
        Ladder(const SeaState& sea, double z, double s);
        void next(size_t i, double& Fr, double& Fi);

    private:
        const SeaState& sea_;
        double z_, s_, span_;
        double Er_ = 0.0, Ei_ = 0.0, Rr_ = 0.0, Ri_ = 0.0, Qr_ = 1.0, Qi_ = 0.0;
    };
    void build_expansions();
    // The coefficients of the node (z, s, t) of a cell of the band into e: of U, or with surface of the
    // complex elevation (amplitudes a instead of a w, no image terms, z = 0).
    void expand(const DepthBand& band, double z, double s, double t, bool surface, WaveExpansion::Polynomial& e) const;
    // The polynomial of the lattice cell of band b holding (z, s, t), computed into e if it holds another.
    const WaveExpansion::Polynomial& cell_polynomial(size_t b, double z, double s, double t, bool surface,
                                                     WaveExpansion::Polynomial& e) const;
    std::vector<WaveComponent> components_;
    std::vector<SeaState> groups_;
    mutable Phases phases_, expansionPhases_;
    double depth_ = 0.0, rampTime_ = 0.0, cosb_ = 1.0, sinb_ = 0.0, direction_ = 0.0;
    double gravity_ = 9.81, ladderAlpha_ = 0.0, ladderBeta_ = 0.0;
    bool wheeler_ = false;
    // Taylor weights a w k^m w^n / (m! n!) of each component, kTerms per component (expand), and the
    // lattice's depth bands (each the top of the next; the last reaches down without end).
    std::vector<double> taylorWeights_;
    std::vector<DepthBand> bands_;
};

}  // namespace uc
