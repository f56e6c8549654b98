// cable_api.cpp - the C boundary: every call is wrapped so that no exception escapes.
#include "cable_api.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "line_file.h"
#include "params.h"
#include "simulation.h"

struct UCCable {
    explicit UCCable(const UCParams& p) : simulation(p) {}
    uc::CableSimulation simulation;
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
        cable = new UCCable(*p);
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
        return c->simulation.initialize(t0, *in, error);
    });
}

extern "C" int uc_do_step(UCCable* c, double t, double h, const UCInputs* in, char* msg, size_t msgSize) {
    return guarded(msg, msgSize, [&](std::string& error) {
        if (!c || !in) {
            error = "uc_do_step: NULL pointer";
            return false;
        }
        return c->simulation.step(t, h, *in, error);
    });
}

extern "C" int uc_take_event(UCCable* c, char* text, size_t size) {
    if (!c) return 0;
    const std::string event = c->simulation.take_event();
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
        return c->simulation.interface_derivative(seed, out, error);
    });
}

extern "C" void uc_tow_position(const UCCable* c, double p[3]) {
    if (!c || !p) return;
    const uc::Vec3 x = c->simulation.tow_position();
    for (int k = 0; k < 3; ++k) p[k] = x[k];
}

extern "C" double uc_time(const UCCable* c) { return c ? c->simulation.time() : 0.0; }

extern "C" void uc_get_outputs(const UCCable* c, UCOutputs* out) {
    if (c && out) *out = c->simulation.outputs();
}

extern "C" size_t uc_state_size(const UCCable* c) { return c ? c->simulation.state_size() : 0; }

extern "C" int uc_state_save(UCCable* c, void* buffer, size_t size) {
    if (!c || !buffer || size < c->simulation.state_size()) return 1;
    c->simulation.save_state(buffer);
    return 0;
}

extern "C" int uc_state_restore(UCCable* c, const void* buffer, size_t size, char* msg, size_t msgSize) {
    return guarded(msg, msgSize, [&](std::string& error) {
        if (!c || !buffer) {
            error = "uc_state_restore: NULL pointer";
            return false;
        }
        return c->simulation.restore_state(buffer, size, error);
    });
}

extern "C" int uc_line_file_apply(const char* text, size_t length, UCParams* p, double towPoint[3], char* notes,
                                  size_t notesSize, char* msg, size_t msgSize) {
    if (notes && notesSize) notes[0] = '\0';
    return guarded(msg, msgSize, [&](std::string& error) {
        if ((text == nullptr && length > 0) || p == nullptr) {
            error = "uc_line_file_apply: NULL pointer";
            return false;
        }
        uc::LineFileLine line;
        if (!uc::read_line_file(std::string_view(text ? text : "", length), p->lineFileElements, line, error) ||
            !uc::apply_line_file(line, *p, error)) {
            return false;
        }
        if (towPoint) std::copy(line.towPoint, line.towPoint + 3, towPoint);
        std::string joined;
        for (const std::string& note : line.notes) joined += (joined.empty() ? "" : "\n") + note;
        write_message(notes, notesSize, joined);
        return true;
    });
}
