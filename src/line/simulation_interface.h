// simulation_interface.h - the one contract between the C boundary (api/cable_api.cpp) and what it drives:
// one line (CableSimulation) or a mooring system of several (MooringSystem, src/system/mooring_system.h).
// The boundary holds one Simulation and calls it without asking which it is; a capability that only one
// of them has (a line's interface derivatives, a system's body derivatives and stiffness) has a default
// here that says what lacks it.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "core/types.h"
#include "model/parameters.h"
#include "terms/current_grid.h"
#include "terms/seabed_grid.h"

namespace uc {

// Appends one event (or the lines of several) to the events of a step, one a line (Simulation::take_event).
inline void append_event(std::string& events, const std::string& text) {
    if (!text.empty()) events += (events.empty() ? "" : "\n") + text;
}

class Simulation {
public:
    virtual ~Simulation() = default;

    // Initial state at time t0 from the inputs (api/cable_api.h, uc_initialize); false with the reason.
    virtual bool initialize(double t0, const UCInputs& in, std::string& error) = 0;
    // From t (the present time) to exactly t + h (uc_do_step); false with the reason.
    virtual bool step(double t, double h, const UCInputs& in, std::string& error) = 0;
    // Whether a step may end early, at a line failure's break (FMI 3.0's early return, uc_set_stop_at_breaks):
    // then time() after step() is the break's, short of t + h. A line without a failure never breaks: nothing to set.
    virtual void set_stop_at_breaks(bool) {}
    // Every output of the FMU: the single-line outputs, and line[k].*, body[k].*, point[k].*.
    virtual const UCOutputs& outputs() const = 0;
    virtual double time() const = 0;
    // Where the tow point (a system: line 1's fairlead) stands now (uc_tow_position).
    virtual Vec3 tow_position() const = 0;
    // Where driven input `kind` (UC_DRIVEN_END, UC_DRIVEN_BODY, UC_DRIVEN_POINT; index 1-based for the last
    // two) stands now, as the lines follow it (uc_driven_position); false where there is no such input.
    virtual bool driven_position(int kind, int index, Vec3& p) const {
        (void)kind;
        (void)index;
        (void)p;
        return false;
    }
    // Which end.* inputs the model reads (uc_end_inputs), as a line's model decided its far end once from
    // bottomEnd (CableModel::far_end()): an external body's (external), which the far end moves with
    // (driven). A system reads none.
    struct EndInputs {
        bool external = false, driven = false;
    };
    virtual EndInputs end_inputs() const { return {}; }
    // The events of the last step worth a log line, one a line, or empty; cleared by the call. A line that
    // starts "warning: " is a warning (the FMU logs it with status fmi2Warning), any other an event.
    virtual std::string take_event() = 0;
    // A current given as data (currents.mode 2 or 5, or a deck's Currents 2 or 5), added to the water
    // of every line from here on; null: none. Not state: a restored instance is given it again.
    virtual void set_current_grid(std::shared_ptr<const CurrentGrid> grid) = 0;
    // The water pushed by the importer (water.source 1, docs/waves.md "Water pushed by the importer"): the
    // load points of every line (3 per element from the tow end, lines in deck order; 0 with water.source 0),
    // where they stand at time() (n of them in each of x, y, z), and their water from time t on (velocity u
    // and local acceleration a, one array per component, the first water_points() values of each). Not state:
    // the importer pushes it before every step.
    virtual std::size_t water_points() const { return 0; }
    virtual void water_positions(double* x, double* y, double* z) const {
        (void)x;
        (void)y;
        (void)z;
    }
    virtual void set_water(double t, const double* const u[3], const double* const a[3]) {
        (void)t;
        (void)u;
        (void)a;
    }

    // The seabed given as a grid (seabed.file, a deck's SeafloorFile) in place of the plane of the
    // parameters, before the first initialize; null: the plane. Not state: a restored instance is given it
    // again.
    virtual void set_seabed_grid(std::shared_ptr<const SeabedGrid> grid) = 0;

    // The exact state (uc_state_save): its size in bytes, written into buffer, taken back. restore_state
    // refuses (false, error) a state of another size, version or model before anything changes; *changed
    // (if given) tells whether a later failure left it partly restored (then no longer usable).
    virtual std::size_t state_size() const = 0;
    virtual void save_state(void* buffer) = 0;
    virtual bool restore_state(const void* buffer, std::size_t size, std::string& error,
                               bool* changed = nullptr) = 0;

    // A line's interface derivatives of towForce and endForce (uc_interface_derivative): seed over the
    // kDerivativeInputs inputs, out over the 6 outputs.
    static constexpr int kDerivativeInputs = 18;
    virtual bool interface_derivative(const double seed[kDerivativeInputs], double out[6], std::string& error) {
        (void)seed;
        (void)out;
        error = "the interface derivatives of towForce and endForce belong to a single line";
        return false;
    }
    // A mooring system's interface derivatives of coupled body `body` (1-based) (uc_body_derivatives).
    virtual bool body_derivatives(int body, double d[6][UC_BODY_DERIVATIVE_INPUTS], std::string& error) {
        (void)body;
        (void)d;
        error = "the body[k].* derivatives belong to a mooring system (lineFile with several lines or bodies)";
        return false;
    }
    // A mooring system's body[k].stiffness, brought up to date and written into out (uc_update_stiffness).
    // Without coupled bodies there is none to compute: out is left as it is, and that is no error.
    virtual bool update_stiffness(UCOutputs& out, std::string& error) {
        (void)out;
        (void)error;
        return true;
    }
};

}  // namespace uc
