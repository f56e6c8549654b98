// deck_mesh.cpp - a deck's line whose NumSegs give too coarse a mesh for a right start: started on the finer
// mesh the mesh advice finds, with a warning (docs/lines.md, "Elements from NumSegs").
#include <algorithm>
#include <cstdio>
#include <string>

#include "line/simulation.h"
#include "model/params.h"

namespace uc {

namespace {

// The elements of each section of p, "3" or "6, 3, 3".
std::string element_counts(const UCParams& p) {
    if (p.nSections <= 1) return std::to_string(p.nElements);
    std::string counts;
    for (int k = 0; k < p.nSections; ++k) counts += (k ? ", " : "") + std::to_string(p.section[k].nElements);
    return counts;
}

}  // namespace

bool CableSimulation::start_on_finer_mesh(double t0, const EndMotion& tow, const EndMotion& far,
                                          const LineEnvironment& env, const std::optional<UCParams>& finer,
                                          const std::string& advice, std::string& error) {
    const UCParams deck = model_.params();
    // Only the elements the deck's NumSegs gave: an explicit lineFileElements is the user's choice, kept and refused.
    if (!finer || !refineDeckMesh_ || deck.lineFile[0] == '\0' || deck.lineFileElements != 0) {
        error += advice;
        return false;
    }
    std::string refusal = error;  // the start's check at the deck's elements, without its own "refusing ..."
    const size_t refusing = refusal.find("; refusing");
    if (refusing != std::string::npos) refusal.erase(refusing);
    // the line made again on finer's elements (as the trial that started it)
    if (!deckParams_) deckParams_ = std::make_unique<UCParams>(deck);
    remesh_deck_line(*finer);
    refineDeckMesh_ = false;  // (the trial's start, repeated: no second refinement from there)
    const bool started = initialize(t0, tow, far, env, error);
    refineDeckMesh_ = true;
    if (!started) return false;
    char text[1600];
    std::snprintf(text, sizeof text,
                  "warning: the deck's NumSegs give the line %s elements, too coarse for its start (%s); started on "
                  "%s elements instead, the first count that passes (tow tension %.6g N, far end %.6g N); set "
                  "lineFileElements to choose (an explicit one is kept, and refused where wrong)",
                  element_counts(deck).c_str(), refusal.c_str(), element_counts(*finer).c_str(),
                  state_.outputs.towTension, state_.outputs.endTension);
    add_event(text);
    return true;
}

void CableSimulation::remesh_deck_line(const UCParams& p) {
    replace_model(CableModel(p, nullptr, nullptr, model_.seabed_grid()));
    state_.graded = false;  // its graded layout made anew by the next grading
    layout_ = StaticLayout();
    if (releasedParams_) {  // what the line becomes where its end lets go: on the same elements, its sections
        // in the line's order or (the tow end let go) the other way round
        const int n = p.nSections;
        releasedParams_->nElements = p.nElements;
        for (int k = 0; k < n && k < releasedParams_->nSections; ++k)
            releasedParams_->section[k].nElements = p.section[releaseFlip_ ? n - 1 - k : k].nElements;
    }
}

bool CableSimulation::adopt_deck_mesh(int elements) {
    if (model_.winch() || elements < 1) return false;
    const UCParams held = state_.released != 0 && heldParams_ ? *heldParams_ : model_.params();
    if (held.lineFile[0] == '\0' || held.lineFileElements != 0) return false;
    const UCParams deck = deckParams_ ? *deckParams_ : held;
    UCParams mesh = deck;  // the deck's own mesh, or every deck line the same count, as the search gives them
    if (CableModel(deck).n_elements() != elements) {
        const int sections = std::max(1, deck.nSections);
        if (elements % sections != 0) return false;
        if (deck.nSections > 1) {
            for (int k = 0; k < deck.nSections; ++k) mesh.section[k].nElements = elements / sections;
        } else {
            mesh.nElements = elements;
        }
        if (!check_params(mesh).empty()) return false;
    }
    unrelease();  // (the held line's, made again on the state's mesh)
    if (!deckParams_) deckParams_ = std::make_unique<UCParams>(deck);
    remesh_deck_line(mesh);
    return true;
}

}  // namespace uc
