// cable_api.cpp - the C boundary: every call is wrapped so that no exception escapes.
#include "api/cable_api.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <utility>

#include "deck/line_file.h"
#include "line/simulation_interface.h"
#include "model/params.h"
#include "system/mooring_system.h"

// One line, or a mooring system of several (docs/systems_mooring.md): the calls below take either
// through the one contract, uc::Simulation.
struct UCCable {
    explicit UCCable(std::unique_ptr<uc::Simulation> s) : simulation(std::move(s)) {}
    std::unique_ptr<uc::Simulation> simulation;
};

namespace {

void write_message(char* msg, size_t size, const std::string& text) {
    if (msg && size) std::snprintf(msg, size, "%s", text.c_str());
}

// Runs f (returning bool, filling std::string error); converts exceptions into messages.
template <class F>
int guarded(char* msg, size_t size, F&& f) {
    std::string error;
    try {
        if (f(error)) return 0;
    } catch (const std::bad_alloc&) {
        error = "out of memory";
    } catch (const std::exception& e) {
        error = std::string("internal error: ") + e.what();
    } catch (...) {
        error = "internal error";
    }
    write_message(msg, size, error.empty() ? std::string("unknown error") : error);
    return 1;
}

}  // namespace

extern "C" UCCable* uc_create(const UCParams* p, char* msg, size_t msgSize) {
    UCCable* cable = nullptr;
    guarded(msg, msgSize, [&](std::string& error) {
        if (p == nullptr) {
            error = "parameters: NULL pointer";
            return false;
        }
        error = uc::check_params(*p);
        if (!error.empty()) return false;
        error = uc::OneLineSystem::check_failure(*p);  // docs/line_failure.md, "One line"
        if (!error.empty()) return false;
        cable = new UCCable(std::make_unique<uc::OneLineSystem>(*p));
        return true;
    });
    return cable;
}

extern "C" void uc_free(UCCable* c) { delete c; }

extern "C" int uc_initialize(UCCable* c, double t0, const UCInputs* in, char* msg, size_t msgSize) {
    return guarded(msg, msgSize, [&](std::string& error) {
        if (!c || !in) {
            error = "uc_initialize: NULL pointer";
            return false;
        }
        return c->simulation->initialize(t0, *in, error);
    });
}

extern "C" int uc_do_step(UCCable* c, double t, double h, const UCInputs* in, char* msg, size_t msgSize) {
    return guarded(msg, msgSize, [&](std::string& error) {
        if (!c || !in) {
            error = "uc_do_step: NULL pointer";
            return false;
        }
        return c->simulation->step(t, h, *in, error);
    });
}

extern "C" int uc_take_event(UCCable* c, char* text, size_t size) {
    if (!c) return 0;
    const std::string event = c->simulation->take_event();
    if (event.empty()) return 0;
    if (text && size) std::snprintf(text, size, "%s", event.c_str());
    return 1;
}

extern "C" int uc_interface_derivative(UCCable* c, const double seed[18], double out[6], char* msg, size_t msgSize) {
    return guarded(msg, msgSize, [&](std::string& error) {
        if (!c || !seed || !out) {
            error = "uc_interface_derivative: NULL pointer";
            return false;
        }
        return c->simulation->interface_derivative(seed, out, error);
    });
}

extern "C" int uc_body_derivatives(UCCable* c, int body, double d[6 * UC_BODY_DERIVATIVE_INPUTS], char* msg,
                                   size_t msgSize) {
    return guarded(msg, msgSize, [&](std::string& error) {
        if (!c || !d) {
            error = "uc_body_derivatives: NULL pointer";
            return false;
        }
        // d as the call leaves it (a refusal before anything is computed leaves it as it was)
        double m[6][UC_BODY_DERIVATIVE_INPUTS];
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < UC_BODY_DERIVATIVE_INPUTS; ++j) m[i][j] = d[UC_BODY_DERIVATIVE_INPUTS * i + j];
        const bool ok = c->simulation->body_derivatives(body, m, error);
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < UC_BODY_DERIVATIVE_INPUTS; ++j) d[UC_BODY_DERIVATIVE_INPUTS * i + j] = m[i][j];
        return ok;
    });
}

extern "C" void uc_tow_position(const UCCable* c, double p[3]) {
    if (!c || !p) return;
    const uc::Vec3 x = c->simulation->tow_position();
    for (int k = 0; k < 3; ++k) p[k] = x[k];
}

extern "C" int uc_driven_position(const UCCable* c, int kind, int index, double p[3]) {
    if (!c || !p) return 0;
    uc::Vec3 x;
    if (!c->simulation->driven_position(kind, index, x)) return 0;
    for (int k = 0; k < 3; ++k) p[k] = x[k];
    return 1;
}

extern "C" int uc_end_inputs(const UCCable* c) {
    if (!c) return 0;
    const uc::Simulation::EndInputs e = c->simulation->end_inputs();
    return (e.external ? UC_END_INPUTS_EXTERNAL : 0) | (e.driven ? UC_END_INPUTS_DRIVEN : 0);
}

extern "C" void uc_set_stop_at_breaks(UCCable* c, int on) {
    if (c) c->simulation->set_stop_at_breaks(on != 0);
}

extern "C" size_t uc_water_points(const UCCable* c) {
    return c ? c->simulation->water_points() : 0;
}

extern "C" void uc_water_positions(const UCCable* c, double* x, double* y, double* z) {
    if (c && x && y && z) c->simulation->water_positions(x, y, z);
}

extern "C" void uc_set_water(UCCable* c, double t, const double* const u[3], const double* const a[3]) {
    if (c && u && a) c->simulation->set_water(t, u, a);
}

extern "C" double uc_time(const UCCable* c) {
    return c ? c->simulation->time() : 0.0;
}

extern "C" void uc_get_outputs(const UCCable* c, UCOutputs* out) {
    if (!c || !out) return;
    *out = c->simulation->outputs();
    out->waterPointCount = static_cast<double>(c->simulation->water_points());
}

extern "C" int uc_update_stiffness(UCCable* c, UCOutputs* out, char* msg, size_t msgSize) {
    if (!c || !out) return 0;
    return guarded(msg, msgSize, [&](std::string& error) { return c->simulation->update_stiffness(*out, error); });
}

extern "C" size_t uc_state_size(const UCCable* c) {
    return c ? c->simulation->state_size() : 0;
}

extern "C" int uc_state_save(UCCable* c, void* buffer, size_t size) {
    if (!c || !buffer || size < uc_state_size(c)) return 1;
    c->simulation->save_state(buffer);
    return 0;
}

extern "C" int uc_state_restore(UCCable* c, const void* buffer, size_t size, char* msg, size_t msgSize) {
    bool changed = false;
    const int rc = guarded(msg, msgSize, [&](std::string& error) {
        if (!c || !buffer) {
            error = "uc_state_restore: NULL pointer";
            return false;
        }
        return c->simulation->restore_state(buffer, size, error, &changed);
    });
    return rc != 0 && changed ? 2 : rc;
}

namespace {

uc::LineFileCompanions companion_texts(const UCLineFileCompanion* companions, int n) {
    uc::LineFileCompanions out;
    for (int k = 0; companions && k < n; ++k) {
        if (!companions[k].name || (!companions[k].text && companions[k].length > 0)) continue;
        out.push_back({companions[k].name, std::string(companions[k].text ? companions[k].text : "", companions[k].length)});
    }
    return out;
}

}  // namespace

extern "C" int uc_line_file_companions(const char* text, size_t length, char* names, size_t namesSize) {
    try {
        const std::vector<std::string> found =
            text ? uc::line_file_companions(std::string_view(text, length)) : std::vector<std::string>();
        std::string joined;
        for (const std::string& name : found) joined += name + "\n";
        write_message(names, namesSize, joined);
        return static_cast<int>(found.size());
    } catch (...) {
        write_message(names, namesSize, "");
        return 0;
    }
}

extern "C" int uc_line_file_nested_companions(const char* text, size_t length, const char* name, const char* companion,
                                              size_t companionLength, char* names, size_t namesSize) {
    try {
        const std::vector<std::string> found =
            text && name && companion ? uc::line_file_nested_companions(std::string_view(text, length), name,
                                                                        std::string_view(companion, companionLength))
                                      : std::vector<std::string>();
        std::string joined;
        for (const std::string& n : found) joined += n + "\n";
        write_message(names, namesSize, joined);
        return static_cast<int>(found.size());
    } catch (...) {
        write_message(names, namesSize, "");
        return 0;
    }
}

extern "C" int uc_wave_file_apply(const char* text, size_t length, UCParams* p, char* msg, size_t msgSize) {
    try {
        std::vector<std::array<double, 4>> components;
        std::string error;
        if (!p || !text || !uc::read_wave_file(std::string_view(text, length), p->wavesDirection, components, error) ||
            !uc::apply_wave_components(components, "waves.file", *p, error)) {
            write_message(msg, msgSize, error.empty() ? std::string("no text or parameters") : error);
            return 1;
        }
        return 0;
    } catch (const std::exception& e) {
        write_message(msg, msgSize, e.what());
        return 1;
    }
}

namespace {

// Data read from a file's text and given to the simulation (a current's grid, a seabed's grid): `read`
// turns the text into the data or null with error set, `give` hands the data to c's simulation.
template <class Read, class Give>
int set_text(const char* function, UCCable* c, const char* text, size_t length, char* msg, size_t msgSize, Read read,
             Give give) {
    try {
        std::string error;
        if (!c || (!text && length > 0)) {
            write_message(msg, msgSize, std::string(function) + ": NULL pointer");
            return 1;
        }
        auto data = read(std::string_view(text ? text : "", length), error);
        if (!data) {
            write_message(msg, msgSize, error);
            return 1;
        }
        write_message(msg, msgSize, data->describe());
        give(*c->simulation, std::move(data));
        return 0;
    } catch (const std::exception& e) {
        write_message(msg, msgSize, e.what());
        return 1;
    }
}

}  // namespace

extern "C" int uc_set_current_text(UCCable* c, int mode, const char* text, size_t length, char* msg, size_t msgSize) {
    return set_text(
        "uc_set_current_text", c, text, length, msg, msgSize,
        [mode](std::string_view t, std::string& error) { return uc::CurrentGrid::read(mode, t, error); },
        [](uc::Simulation& s, std::shared_ptr<const uc::CurrentGrid> grid) { s.set_current_grid(std::move(grid)); });
}

extern "C" int uc_set_seabed_text(UCCable* c, const char* text, size_t length, char* msg, size_t msgSize) {
    return set_text(
        "uc_set_seabed_text", c, text, length, msg, msgSize,
        [](std::string_view t, std::string& error) { return uc::SeabedGrid::read(t, error); },
        [](uc::Simulation& s, std::shared_ptr<const uc::SeabedGrid> grid) { s.set_seabed_grid(std::move(grid)); });
}

extern "C" int uc_line_file_apply(const char* text, size_t length, UCParams* p, double towPoint[3], char* notes,
                                  size_t notesSize, char* msg, size_t msgSize) {
    return uc_line_file_apply_with(text, length, nullptr, 0, p, towPoint, notes, notesSize, msg, msgSize);
}

extern "C" int uc_line_file_apply_with(const char* text, size_t length, const UCLineFileCompanion* companions, int n,
                                       UCParams* p, double towPoint[3], char* notes, size_t notesSize, char* msg,
                                       size_t msgSize) {
    if (notes && notesSize) notes[0] = '\0';
    return guarded(msg, msgSize, [&](std::string& error) {
        if ((text == nullptr && length > 0) || p == nullptr) {
            error = "uc_line_file_apply: NULL pointer";
            return false;
        }
        uc::LineFileLine line;
        if (!uc::read_line_file(std::string_view(text ? text : "", length), p->lineFileElements, line, error,
                                companion_texts(companions, n)) ||
            !uc::apply_line_file(line, *p, error)) {
            return false;
        }
        if (towPoint) std::copy(line.towPoint, line.towPoint + 3, towPoint);
        for (std::string& note : uc::deck_environment_notes(line, line.sections.back().diameter, *p))
            line.notes.push_back(std::move(note));
        std::string joined;
        for (const std::string& note : line.notes) joined += (joined.empty() ? "" : "\n") + note;
        write_message(notes, notesSize, joined);
        return true;
    });
}

extern "C" int uc_line_file_is_system(const char* text, size_t length) {
    try {
        return text != nullptr && uc::is_mooring_system_deck(std::string_view(text, length)) ? 1 : 0;
    } catch (...) {
        return 0;
    }
}

extern "C" UCCable* uc_create_system(const UCParams* p, const char* text, size_t length, char* notes, size_t notesSize,
                                     char* msg, size_t msgSize) {
    return uc_create_system_with(p, text, length, nullptr, 0, notes, notesSize, msg, msgSize);
}

extern "C" UCCable* uc_create_system_with(const UCParams* p, const char* text, size_t length,
                                          const UCLineFileCompanion* companions, int n, char* notes, size_t notesSize,
                                          char* msg, size_t msgSize) {
    if (notes && notesSize) notes[0] = '\0';
    UCCable* cable = nullptr;
    guarded(msg, msgSize, [&](std::string& error) {
        if (p == nullptr || (text == nullptr && length > 0)) {
            error = "uc_create_system: NULL pointer";
            return false;
        }
        uc::MooringDeck deck;
        if (!uc::read_mooring_deck(std::string_view(text ? text : "", length), p->lineFileElements, deck, error,
                                   companion_texts(companions, n)))
            return false;
        auto system = std::make_unique<uc::MooringSystem>(*p, deck);
        if (!system->build(error)) return false;
        auto made = std::make_unique<UCCable>(std::move(system));
        for (std::string& note : uc::mooring_environment_notes(deck, *p)) deck.notes.push_back(std::move(note));
        std::string joined;
        for (const std::string& note : deck.notes) joined += (joined.empty() ? "" : "\n") + note;
        write_message(notes, notesSize, joined);
        cable = made.release();
        return true;
    });
    return cable;
}

// The defaults are the start values of the schema (schema/variables.toml): the Hopland 1993 tow
// cable (massPerLength = 3121 kg/m3 x A, EA = 77.5 GPa x A for d = 33.2 mm), where the reasons for
// the numerical defaults are written down too (relTol, axialDamping, seabed constants).
extern "C" void uc_params_default(UCParams* p) {
    if (p == nullptr) return;
    std::memset(p, 0, sizeof *p);
#define UC_SET_DEFAULT(member, value) p->member = value;
    UC_SCHEMA_PARAMETER_DEFAULTS(UC_SET_DEFAULT)
#undef UC_SET_DEFAULT
}

extern "C" void uc_inputs_default(UCInputs* in) {
    if (in == nullptr) return;
    std::memset(in, 0, sizeof *in);
#define UC_SET_DEFAULT(member, value) in->member = value;
    UC_SCHEMA_INPUT_DEFAULTS(UC_SET_DEFAULT)
#undef UC_SET_DEFAULT
}

extern "C" int uc_params_check(const UCParams* p, char* msg, size_t msgSize) {
    std::string m = p ? uc::check_params(*p) : std::string("parameters: NULL pointer");
    if (m.empty()) return 0;
    if (msg && msgSize) std::snprintf(msg, msgSize, "%s", m.c_str());
    return 1;
}

extern "C" double uc_acceleration_disagreement(double a0, double a1, double dv, double h) {
    return uc::acceleration_disagreement(a0, a1, dv, h);
}
