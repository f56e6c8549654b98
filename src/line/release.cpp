// release.cpp - a held end that lets go (docs/line_failure.md): the line's model made again with a bare far end,
// its state carried over (node by node and element by element: internal strains, VIV phases and Syrope history;
// mirrored where the tow end lets go and the line is run from its far end), the integrator restarted once from there.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "line/simulation.h"
#include "line/simulation_internal.h"

namespace uc {

namespace {

// What an element carries besides its nodes: its own unknowns (the internal strain of a viscoelastic element or
// the slow strain of a Syrope element, the VIV phase), each with its rate, and its Syrope history (the largest mean
// tension so far, as a strain). A released line's element takes it over from the held line's element it is.
struct ElementState {
    double unknown[2][2] = {};      // [internal strain, phase][value, rate]
    bool has[2] = {false, false};   // the element has the unknown
    double history = 0.0;           // (a line without a Syrope element has none)

    static int offset(const CableModel& model, int e, int k) {
        return k == 0 ? model.internal_offset(e) : model.phase_offset(e);
    }
    ElementState(const CableModel& model, int e, const std::vector<double>& X, const std::vector<double>& Xd,
                 const std::vector<double>& histories) {
        for (int k = 0; k < 2; ++k) {
            const int g = offset(model, e, k);
            has[k] = g >= 0;
            if (has[k]) {
                unknown[k][0] = X[g];
                unknown[k][1] = Xd[g];
            }
        }
        if (!histories.empty()) history = histories[e];
    }
    void put(const CableModel& model, int e, std::vector<double>& X, std::vector<double>& Xd,
             std::vector<double>& histories) const {
        for (int k = 0; k < 2; ++k) {
            const int g = offset(model, e, k);
            if (g < 0 || !has[k]) continue;
            X[g] = unknown[k][0];
            Xd[g] = unknown[k][1];
        }
        if (!histories.empty()) histories[e] = history;
    }
};

}  // namespace

void CableSimulation::prepare_release(const UCParams& released, bool flip) {
    releasedParams_ = std::make_unique<UCParams>(released);
    releasedParams_->bottomEnd = UC_BOTTOM_FREE;
    releaseFlip_ = flip;
}

void CableSimulation::unrelease() {
    if (state_.released == 0) return;
    replace_model(CableModel(*heldParams_, nullptr, state_.graded ? &layout_ : nullptr, model_.seabed_grid()));
    state_.released = 0;
    std::string error;  // (the held model's tolerances were accepted when it was initialized)
    if (state_.tensionScale > 0.0) set_integrator_tolerances(error);
}

bool CableSimulation::build_released(int released, std::string& error) {
    if (!releasedParams_ || released != (releaseFlip_ ? 2 : 1) || model_.winch()) {
        error = "the state is of a line whose " + std::string(released == 2 ? "tow end" : "far end") +
                " let go, and this line's does not (it is another line)";
        return false;
    }
    const CableModel& held = model_;
    // the nodes of the held mesh, as arc lengths from the new tow point
    std::vector<double> nodes;
    for (int i = 0; i < held.n_slots(); ++i)
        if (nodes.empty() || held.slot_arc_length(i) != nodes.back()) nodes.push_back(held.slot_arc_length(i));
    StaticLayout layout;
    if (releaseFlip_) {
        const double L = CableModel(*releasedParams_).line().length;  // (its sections summed the other way round)
        std::vector<double> mirrored;
        for (auto s = nodes.rbegin(); s != nodes.rend(); ++s) mirrored.push_back(L - *s);
        mirrored.front() = 0.0;
        mirrored.back() = L;
        layout.nodes = mirrored;
    } else if (state_.graded) {
        layout.nodes = layout_.nodes;
    }
    CableModel model(*releasedParams_, nullptr, layout.nodes.empty() ? nullptr : &layout, model_.seabed_grid());
    bool same = model.n_slots() == held.n_slots() && model.n_elements() == held.n_elements();
    const double L = held.line().length;
    for (int j = 0; same && j < model.n_slots(); ++j) {
        const double s = held.slot_arc_length(releaseFlip_ ? held.n_slots() - 1 - j : j);
        same = std::abs(model.slot_arc_length(j) - (releaseFlip_ ? L - s : s)) <= 1e-9 * L;
    }
    if (!same) {
        char text[200];
        std::snprintf(text, sizeof text, "the line with its end let go has %d node slots, not the %d of the held line "
                      "at the same arc lengths: its state cannot be carried over", model.n_slots(), held.n_slots());
        error = text;
        return false;
    }
    heldParams_ = std::make_unique<UCParams>(held.params());
    replace_model(std::move(model));
    state_.released = static_cast<std::uint8_t>(released);
    return state_.tensionScale <= 0.0 || set_integrator_tolerances(error);  // (0: not initialized)
}

bool CableSimulation::release(double time, std::string& error) {
    if (state_.released != 0) return true;
    // the state at time(), as global coordinates of the held model
    expand_integrator_state(state_.time, y_.data(), yp_.data());
    const std::vector<double> X = X_, Xd = Xd_;
    const int slots = model_.n_slots();
    const Vec3 far(X[model_.end_offset()], X[model_.end_offset() + 1], X[model_.end_offset() + 2]);
    std::vector<ElementState> held;
    for (int e = 0; e < model_.n_elements(); ++e) held.emplace_back(model_, e, X, Xd, syropeHistory_);
    if (!build_released(releaseFlip_ ? 2 : 1, error)) return false;
    const int elements = model_.n_elements();
    for (int e = 0; e < elements; ++e)  // flipped: element e is the held element elements - 1 - e
        held[releaseFlip_ ? elements - 1 - e : e].put(model_, e, X_, Xd_, syropeHistory_);
    for (int j = 0; j < slots; ++j) {  // flipped: slot j is the held slot slots - 1 - j, its tangent reversed
        const int i = releaseFlip_ ? slots - 1 - j : j;
        const double sign = releaseFlip_ ? -1.0 : 1.0;
        for (int c = 0; c < 6; ++c) {
            X_[6 * j + c] = (c < 3 ? 1.0 : sign) * X[6 * i + c];
            Xd_[6 * j + c] = (c < 3 ? 1.0 : sign) * Xd[6 * i + c];
        }
    }
    model_.restrict_to_free(X_.data(), q_.data());
    model_.restrict_to_free(Xd_.data(), v_.data());
    if (releaseFlip_) {  // the new tow point: held where the far end stands
        state_.tow.reset(far, Vec3::Zero(), Vec3::Zero(), false);
        loads_.tow = TowTrajectory::at_rest_in_time(far, Vec3::Zero(), Vec3::Zero(), state_.time);
    }
    if (!restart_from(error)) return false;
    state_.releaseTime = time;
    ++stateStamp_;
    update_outputs();
    return true;
}

}  // namespace uc
