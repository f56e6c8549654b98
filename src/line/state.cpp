// state.cpp - save and restore of a line's state: a header, one copy of LineState, the line's vectors (the
// unknowns y, y' and the Syrope elements' history) and the integrator's history (line/line_state.h).
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "model/mesh_grading.h"
#include "line/simulation.h"
#include "line/simulation_internal.h"

namespace uc {

namespace {

constexpr std::uint32_t kStateMagic = 0x55434142;  // "UCAB"
constexpr std::uint32_t kStateVersion = 17;  // 13: the viscoelastic elements' internal strains among the unknowns;
                                             // 14: LineState::released;
                                             // 15: the Syrope elements' history after the integrator's;
                                             // 16: the VIV phases among the unknowns;
                                             // 17: the Syrope elements' history beside y, y' (before the
                                             // integrator's history)
// What each version added (named when a state of another version is refused).
const char* const kStateVersions =
    "version 13 added the viscoelastic internal strains, 14 the released end, 15 the Syrope elements' history, "
    "16 the vortex-induced vibration phases among the unknowns, 17 moved the Syrope history before the integrator's";

// Fixed-layout header of a saved state: what it belongs to (the sizes and the winch's mesh, which
// the model holds); followed by LineState, the line's vectors (y, y' and the Syrope elements' history, one per
// element of a line that has the model: CableSimulation::line_vectors) and the integrator's history.
struct StateHeader {
    std::uint32_t magic;
    std::uint32_t version;
    std::int32_t nFree;
    std::int32_t nElements;
    std::int32_t winchElements;  // the winch's mesh: elements of the first section, top length at its build
    std::int32_t stateBytes;     // sizeof(LineState)
    double winchMeshTop;
};

}  // namespace

size_t CableSimulation::state_size() const {
    size_t doubles = integrator_->history_size();
    for (const std::vector<double>* v : line_vectors()) doubles += v->size();
    return sizeof(StateHeader) + sizeof(LineState) + doubles * sizeof(double);
}

void CableSimulation::save_state(void* buffer) {
    StateHeader header{};
    header.magic = kStateMagic;
    header.version = kStateVersion;
    header.nFree = model_.n_free();
    header.nElements = model_.n_elements();
    header.winchElements = model_.winch_mesh().elements;
    header.winchMeshTop = model_.winch_mesh().topLength;
    header.stateBytes = static_cast<std::int32_t>(sizeof(LineState));
    // The integrator's history, when it belongs to this state: the run continues from here
    // without a restart, exactly as a restored copy will (both evaluate a new Jacobian first).
    // The saved statistics are the totals (the restored integrator's own are taken off again).
    const bool history = state_.integratorStarted && !state_.restartPending;
    LineState saved = state_;
    saved.statsBase = total_stats();
    saved.integratorStarted = history;
    saved.restartPending = !history;
    historyBuffer_.assign(integrator_->history_size(), 0.0);
    if (history) integrator_->save_history(historyBuffer_.data());
    auto* out = static_cast<unsigned char*>(buffer);
    std::memcpy(out, &header, sizeof header);
    out += sizeof header;
    std::memcpy(out, &saved, sizeof saved);
    out += sizeof saved;
    for (const std::vector<double>* v : line_vectors()) {
        std::memcpy(out, v->data(), v->size() * sizeof(double));
        out += v->size() * sizeof(double);
    }
    std::memcpy(out, historyBuffer_.data(), historyBuffer_.size() * sizeof(double));
}

bool CableSimulation::restore_state(const void* buffer, size_t size, std::string& error, bool* changed) {
    bool ignored = false;
    bool& touched = changed ? *changed : ignored;
    touched = false;
    ++stateStamp_;  // the cached interface derivatives are stale from here on
    const auto* in = static_cast<const unsigned char*>(buffer);
    StateHeader header{};
    LineState saved;
    const bool complete = size >= sizeof(StateHeader) + sizeof(LineState);
    if (complete) {
        std::memcpy(&header, in, sizeof header);
        std::memcpy(&saved, in + sizeof header, sizeof saved);
    }
    const bool ours = complete && header.magic == kStateMagic && header.version == kStateVersion &&
                      header.stateBytes == static_cast<std::int32_t>(sizeof(LineState));
    if (complete && header.magic == kStateMagic && header.version != kStateVersion) {
        error = "saved state is of format version " + std::to_string(header.version) + ", this FMU reads " +
                std::to_string(kStateVersion) + " (" + kStateVersions + ")";
        return false;
    }
    if (model_.winch() && ours) {
        // A state of a winch's line may have another mesh than the present one: take its mesh first.
        const WinchMesh mesh = model_.winch_mesh();
        if (header.winchElements > 0 && header.winchElements <= 100000 && std::isfinite(header.winchMeshTop) &&
            header.winchMeshTop > 0.0 &&
            (header.winchElements != mesh.elements || header.winchMeshTop != mesh.topLength)) {
            touched = true;
            rebuild(WinchMesh{header.winchElements, header.winchMeshTop});
        }
    }
    if (ours && header.nElements != model_.n_elements() && adopt_deck_mesh(header.nElements))
        touched = true;  // a deck line's state on a finer mesh than its NumSegs' (deck_mesh.cpp), or the other way
    if (ours) {
        // A graded mesh is graded again for the tow point it was made for (on the held line: a released
        // line's mesh is its held mesh's, made again from it).
        const Vec3 tow = vec(saved.meshTow), far = vec(saved.meshFar);
        const bool regrade = tow.allFinite() && far.allFinite() && saved.grading >= 0 && saved.grading < kGradingCount &&
                             (saved.graded != state_.graded || tow != vec(state_.meshTow) ||
                              far != vec(state_.meshFar) || saved.grading != state_.grading);
        if (state_.released != 0 && (regrade || saved.released != state_.released)) {
            touched = true;
            unrelease();
        }
        if (regrade) {
            touched = true;
            grade_mesh(tow, far, saved.graded, saved.grading);
        }
        if (saved.released != state_.released) {
            touched = true;
            if (!build_released(saved.released, error)) return false;
        }
    }
    if (size != state_size()) {
        error = "saved state has the wrong size for this cable (different nElements or end conditions)";
        return false;
    }
    if (!ours || header.nFree != model_.n_free() || header.nElements != model_.n_elements()) {
        error = "saved state does not belong to this cable model (magic, version or sizes differ)";
        if (complete && header.magic == kStateMagic && header.version != kStateVersion)
            error += ": it has format version " + std::to_string(header.version) + ", this FMU reads " +
                     std::to_string(kStateVersion) + " (" + kStateVersions + ")";
        return false;
    }
    touched = true;
    in += sizeof header + sizeof saved;
    for (std::vector<double>* v : line_vectors()) {  // (sized by the model: no reallocation, loads_ points at them)
        std::memcpy(v->data(), in, v->size() * sizeof(double));
        in += v->size() * sizeof(double);
    }
    const bool history = saved.integratorStarted;
    state_ = saved;
    complete_outputs(state_.outputs);
    if (state_.tensionScale > 0.0 && !set_integrator_tolerances(error)) {  // 0: saved before initialization
        state_.restartPending = true;
        return false;
    }
    if (history) {
        historyBuffer_.resize(integrator_->history_size());
        std::memcpy(historyBuffer_.data(), in, historyBuffer_.size() * sizeof(double));
        if (!integrator_->restore_history(historyBuffer_.data(), error)) {
            state_.restartPending = true;
            return false;
        }
    }
    set_winch_time(state_.time);
    expand_integrator_state(state_.time, y_.data(), yp_.data());  // the restored nodes (section_end_position)
    store_section_ends();
    if (history) {
        // The restored integrator carries the saver's counters since its last restart.
        const IntegratorStats since = integrator_->stats();
        state_.statsBase.steps -= since.steps;
        state_.statsBase.residualEvals -= since.residualEvals;
        state_.statsBase.jacobianEvals -= since.jacobianEvals;
        state_.statsBase.nonlinearFailures -= since.nonlinearFailures;
        state_.statsBase.errorTestFailures -= since.errorTestFailures;
    }
    return true;
}

}  // namespace uc
