// error_control.cpp - the integrator's tolerances from the physical ones: element scales and the
// projected error blocks.
#include <algorithm>
#include <cmath>

#include "line/simulation.h"

namespace uc {

namespace {
constexpr double kVivPhaseTolerance = 1e-3;  // [rad] the VIV phases' absolute error per step
}  // namespace

// The integrator's absolute tolerance of each unknown from the physical ones. A local error of
// tensionTolerance x the tension scale in tension is a strain error eps = that / EA: eps x the
// element length in a node position, eps in a tangent; positionTolerance bounds a node position,
// and over the element length a tangent (an angle); the smaller of the two counts. A velocity
// error delta / tau makes as large an error in the cable's internal damping force as a position
// error delta makes in its elastic force (tau = axialDamping / EA, the Kelvin-Voigt time
// constant), so velocities get the position tolerances over tau, with tau at least the time an
// axial wave takes along an element (the shortest time scale the mesh resolves). IDA tests the
// root mean square of the weighted local errors of all 2n unknowns, which a single unknown can
// exceed sqrt(2n) times: the tolerances are divided by sqrt(2n), so that each unknown meets its own.
CableSimulation::ElementScales CableSimulation::element_scales(int e, double rms) const {
    const SectionProps& section = model_.element_section(e);
    // the winch's top element changes length: its tolerances are those of a nominal element, so
    // that they depend on the mesh only (a restored state gets the ones it was integrated with)
    const double l = e == 0 && model_.winch() ? model_.winch_nominal() : model_.element_length(e);
    const double EA = section.axial.EA;
    const double wave = l / std::sqrt(EA / section.fluid.massPerLength);
    return {l, rms * model_.params().tensionTolerance * state_.tensionScale / EA, std::max(section.axial.damping / EA, wave)};
}

bool CableSimulation::set_integrator_tolerances(std::string& error) {
    const UCParams& p = model_.params();
    const double rms = 1.0 / std::sqrt(2.0 * unknowns());
    std::vector<double>& atol = toleranceBuffer_;
    atol.assign(2 * unknowns(), INFINITY);
    // relTol |y| counts |y| at least at the unknown's scale: the line's length for a node position
    // (and the winch's length), 1 for a tangent, these over tau for their rates, which pass through 0
    std::vector<double> magnitude(2 * unknowns(), 0.0);
    const double lineScale = model_.line().length;
    // Each unknown gets the tolerance of the elements it belongs to (the smaller one at a node
    // between two sections).
    for (int e = 0; e < model_.n_elements(); ++e) {
        const ElementScales scales = element_scales(e, rms);
        const double l = scales.length, strain = scales.strain, tau = scales.tau;
        for (int k = 0; k < 12; ++k) {
            const int m = model_.free_index(model_.element_offset(e) + k);
            if (m < 0) continue;
            const int j = m + off_;
            const bool position = k % 6 < 3;
            const double a = position ? std::min(rms * p.positionTolerance, strain * l)
                                      : std::min(rms * p.positionTolerance / l, strain);
            atol[2 * j] = std::min(atol[2 * j], a);
            atol[2 * j + 1] = std::min(atol[2 * j + 1], a / tau);
            const double y = position ? lineScale : 1.0;
            magnitude[2 * j] = std::max(magnitude[2 * j], y);
            magnitude[2 * j + 1] = std::max(magnitude[2 * j + 1], y / tau);
            // the winch's length and rate: those of the top element's positions
            if (off_ && e == 0 && position) {
                atol[0] = std::min(atol[0], a);
                atol[1] = std::min(atol[1], a / tau);
                magnitude[0] = lineScale;
                magnitude[1] = std::max(magnitude[1], lineScale / tau);
            }
        }
    }
    // A viscoelastic element's internal strain e1: its error makes EA_1 times as large an error in the tension,
    // the rate's over the model's relaxation time (c + c_d) / (EA_1 + EA_2), at least the element's wave time.
    for (int e = 0; e < model_.n_elements(); ++e) {
        if (model_.internal_offset(e) < 0) continue;
        const ElementScales scales = element_scales(e, rms);
        const SectionProps& section = model_.element_section(e);
        // (Syrope: the slow strain's tension slope is about the original working curve's secant EA, its
        // relaxation through the dynamic stiffness EA_Dc)
        const ViscoStiffness k = section.syrope.form != kSyropeNone
                                     ? ViscoStiffness{section.axial.EA, section.syrope.alpha, 0.0, 0.0}
                                     : visco_stiffness(section.visco, 0.0);
        const double relax = (section.axial.damping + section.visco.dampingDynamic) / (k.EA1 + k.EA2);
        const double wave = scales.length / std::sqrt(k.EA2 / section.fluid.massPerLength);
        const double a = scales.strain * section.axial.EA / k.EA1, tau = std::max(relax, wave);
        const int j = model_.free_index(model_.internal_offset(e)) + off_;
        atol[2 * j] = a;
        atol[2 * j + 1] = a / tau;
        magnitude[2 * j] = 1.0;
        magnitude[2 * j + 1] = 1.0 / tau;
    }
    // A VIV phase: an error of kVivPhaseTolerance rad moves the lift by that fraction of its amplitude; its
    // rate's over the shedding period at 1 m/s of cross flow (2 pi f0 / d).
    for (int e = 0; e < model_.n_elements(); ++e) {
        if (model_.phase_offset(e) < 0) continue;
        const SectionProps& section = model_.element_section(e);
        const double rate = 2.0 * kPi * section.viv.frequency / section.fluid.diameter;
        const int j = model_.free_index(model_.phase_offset(e)) + off_;
        atol[2 * j] = kVivPhaseTolerance;
        atol[2 * j + 1] = kVivPhaseTolerance * rate;
        magnitude[2 * j] = 2.0 * kPi;
        magnitude[2 * j + 1] = rate;
    }
    if (!integrator_->set_tolerances(atol, p.relTol, p.absTol, error, &magnitude)) return false;
    if (!integrator_->set_max_order(p.solverMaxOrder, error)) return false;
    return integrator_->set_projected_tolerances(projected_blocks(), error);
}

std::vector<Integrator::ProjectedBlock> CableSimulation::projected_blocks() const {
    std::vector<Integrator::ProjectedBlock> blocks;
    const UCParams& p = model_.params();
    if (!p.projectedErrorControl) return blocks;
    const double rms = 1.0 / std::sqrt(2.0 * unknowns());
    // At each node whose tangent is free: along the tangent the tolerance of set_integrator_tolerances
    // (its length is 1 + strain), across it the position tolerance over the element length (its
    // direction turns, which strains nothing to first order); the smaller of the elements that share
    // the node. Node positions keep the componentwise test: projected too, the chain mooring's error
    // left the tolerance (docs/error_control.md).
    for (int e = 0; e < model_.n_elements(); ++e) {
        const ElementScales scales = element_scales(e, rms);
        const double l = scales.length, strain = scales.strain, tau = scales.tau;
        for (int node = 0; node < 2; ++node) {
            const int g = model_.element_offset(e) + 6 * node + 3;  // the node's tangent
            const int j = model_.free_index(g);
            if (j < 0 || model_.free_index(g + 1) != j + 1 || model_.free_index(g + 2) != j + 2) continue;
            Integrator::ProjectedBlock b;
            b.q = b.direction = j + off_;
            b.across = rms * p.positionTolerance / l;
            b.along = std::min(b.across, strain);
            b.alongRate = b.along / tau;
            b.acrossRate = b.across / tau;
            auto it = std::find_if(blocks.begin(), blocks.end(), [&](const Integrator::ProjectedBlock& o) { return o.q == b.q; });
            if (it == blocks.end()) {
                blocks.push_back(b);
            } else {
                it->along = std::min(it->along, b.along);
                it->across = std::min(it->across, b.across);
                it->alongRate = std::min(it->alongRate, b.alongRate);
                it->acrossRate = std::min(it->acrossRate, b.acrossRate);
            }
        }
    }
    return blocks;
}

}  // namespace uc
