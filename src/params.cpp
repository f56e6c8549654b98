// params.cpp - defaults (DESIGN.md section 4) and the single place where parameters are validated.
#include "params.h"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace uc {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string format_violation(const char* name, double value, const char* range, const char* why) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, "%s = %.17g is outside %s: %s", name, value, range, why);
    return buffer;
}

// Each check returns true when the value violates it and then fills `message`.
bool positive(std::string& message, const char* name, double v, const char* why) {
    if (std::isfinite(v) && v > 0.0) return false;
    message = format_violation(name, v, "(0, inf)", why);
    return true;
}

bool non_negative(std::string& message, const char* name, double v, const char* why) {
    if (std::isfinite(v) && v >= 0.0) return false;
    message = format_violation(name, v, "[0, inf)", why);
    return true;
}

bool in_range(std::string& message, const char* name, double v, double lo, double hi,
              const char* range, const char* why) {
    if (std::isfinite(v) && v >= lo && v <= hi) return false;
    message = format_violation(name, v, range, why);
    return true;
}

bool finite(std::string& message, const char* name, double v) {
    if (std::isfinite(v)) return false;
    message = format_violation(name, v, "(-inf, inf)", "it must be a finite number");
    return true;
}

bool unit_direction(std::string& message, const char* name, const double v[3]) {
    for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(v[k])) {
            char component[128];
            std::snprintf(component, sizeof component, "%s.%c", name, "xyz"[k]);
            message = format_violation(component, v[k], "(-inf, inf)", "it must be a finite number");
            return true;
        }
    }
    const double norm = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (norm > 1e-12) return false;
    char what[128];
    std::snprintf(what, sizeof what, "|%s|", name);
    message = format_violation(what, norm, "(0, inf)", "a direction needs a non-zero vector");
    return true;
}

}  // namespace

std::string check_params(const UCParams& p) {
    std::string m;
    if (positive(m, "length", p.length, "the cable must have a positive length") ||
        positive(m, "diameter", p.diameter, "drag, buoyancy and added mass need a positive diameter") ||
        positive(m, "massPerLength", p.massPerLength, "the cable must have mass (the mass matrix must be positive definite)") ||
        positive(m, "EA", p.EA, "the axial stiffness carries the tension") ||
        non_negative(m, "EI", p.EI, "a bending stiffness cannot be negative") ||
        non_negative(m, "axialDamping", p.axialDamping, "internal damping must dissipate energy") ||
        non_negative(m, "Cdn", p.Cdn, "drag must oppose the relative flow") ||
        non_negative(m, "Cdt", p.Cdt, "drag must oppose the relative flow") ||
        non_negative(m, "Can", p.Can, "added mass cannot be negative") ||
        non_negative(m, "Cat", p.Cat, "added mass cannot be negative") ||
        non_negative(m, "waterDensity", p.waterDensity, "a fluid density cannot be negative") ||
        non_negative(m, "gravity", p.gravity, "gravity points along -z; give its magnitude") ||
        in_range(m, "relTol", p.relTol, 1e-12, 1e-1, "[1e-12, 0.1]", "the integrator needs a meaningful relative tolerance") ||
        in_range(m, "absTol", p.absTol, 1e-14, 1.0, "[1e-14, 1]", "the integrator needs a meaningful absolute tolerance") ||
        in_range(m, "nElements", p.nElements, 1, 1000, "[1, 1000]", "the cable needs at least one element; more than 1000 is never needed for a cable") ||
        in_range(m, "bottomEnd", p.bottomEnd, 0, 3, "{0 free, 1 anchored, 2 towed body, 3 external}", "unknown far-end condition") ||
        in_range(m, "topEnd", p.topEnd, 0, 1, "{0 hinged, 1 clamped}", "unknown top-end condition") ||
        in_range(m, "initMode", p.initMode, 0, 1, "{0 equilibrium, 1 straight at rest}", "unknown initialization mode") ||
        in_range(m, "enableBending", p.enableBending, 0, 1, "{0, 1}", "a switch is on or off") ||
        in_range(m, "enableAddedMass", p.enableAddedMass, 0, 1, "{0, 1}", "a switch is on or off") ||
        in_range(m, "enableSeabed", p.enableSeabed, 0, 1, "{0, 1}", "a switch is on or off") ||
        positive(m, "waterDepth", p.waterDepth, "the seabed lies below the surface (z = -waterDepth)") ||
        non_negative(m, "seabedStiffness", p.seabedStiffness, "a contact stiffness cannot be negative") ||
        non_negative(m, "seabedDamping", p.seabedDamping, "contact damping must dissipate energy") ||
        non_negative(m, "seabedFriction", p.seabedFriction, "a friction coefficient cannot be negative") ||
        in_range(m, "currentProfileRows", p.currentProfileRows, 0, UC_CURRENT_PROFILE_ROWS, "[0, 10]",
                 "the profile has at most 10 rows") ||
        in_range(m, "enableTorsion", p.enableTorsion, 0, 1, "{0, 1}", "a switch is on or off") ||
        non_negative(m, "GJ", p.GJ, "a torsional stiffness cannot be negative") ||
        in_range(m, "enableCompression", p.enableCompression, 0, 1, "{0, 1}", "a switch is on or off") ||
        in_range(m, "torqueMode", p.torqueMode, 0, 2, "{0 swivel, 1 prescribed torque, 2 prescribed rotation}",
                 "unknown torque mode") ||
        unit_direction(m, "initialDirection", p.initialDirection) ||
        finite(m, "anchor.x", p.anchor[0]) || finite(m, "anchor.y", p.anchor[1]) ||
        finite(m, "anchor.z", p.anchor[2])) {
        return m;
    }
    if (p.topEnd == UC_TOP_CLAMPED && unit_direction(m, "topTangent", p.topTangent)) return m;
    if (p.enableTorsion && p.torqueMode == UC_TORQUE_ROTATION &&
        positive(m, "GJ", p.GJ, "a prescribed end rotation makes a torque only through GJ"))
        return m;
    if (p.enableSeabed && positive(m, "seabedStiffness", p.seabedStiffness, "an enabled seabed needs a contact stiffness"))
        return m;
    for (int k = 0; k < UC_CURRENT_PROFILE_ROWS; ++k) {
        char name[64];
        std::snprintf(name, sizeof name, "currentProfile.depth[%d]", k + 1);
        if (finite(m, name, p.currentProfileDepth[k])) return m;
        std::snprintf(name, sizeof name, "currentProfile.x[%d]", k + 1);
        if (finite(m, name, p.currentProfileX[k])) return m;
        std::snprintf(name, sizeof name, "currentProfile.y[%d]", k + 1);
        if (finite(m, name, p.currentProfileY[k])) return m;
        if (k > 0 && k < p.currentProfileRows && !(p.currentProfileDepth[k] > p.currentProfileDepth[k - 1])) {
            std::snprintf(name, sizeof name, "currentProfile.depth[%d]", k + 1);
            char range[96];
            std::snprintf(range, sizeof range, "(%.17g, inf)", p.currentProfileDepth[k - 1]);
            m = format_violation(name, p.currentProfileDepth[k], range, "profile depths must increase row by row");
            return m;
        }
    }
    if (p.bottomEnd == UC_BOTTOM_TOWED_BODY) {
        if (non_negative(m, "body.mass", p.bodyMass, "a body mass cannot be negative") ||
            non_negative(m, "body.volume", p.bodyVolume, "a displaced volume cannot be negative") ||
            non_negative(m, "body.addedMass", p.bodyAddedMass, "added mass cannot be negative") ||
            non_negative(m, "body.CdA", p.bodyCdA, "drag must oppose the relative flow")) {
            return m;
        }
    } else if (!std::isfinite(p.bodyMass) || !std::isfinite(p.bodyVolume) ||
               !std::isfinite(p.bodyAddedMass) || !std::isfinite(p.bodyCdA)) {
        return "body.* parameters must be finite numbers even when unused";
    }
    return std::string();
}

}  // namespace uc

extern "C" void uc_params_default(UCParams* p) {
    if (p == nullptr) return;
    std::memset(p, 0, sizeof *p);
    const double area = uc::kPi * uc::kHoplandDiameter * uc::kHoplandDiameter / 4.0;
    p->length = 300.0;
    p->diameter = uc::kHoplandDiameter;
    p->massPerLength = uc::kHoplandDensity * area;  // 2.70186 kg/m
    p->EA = uc::kHoplandModulus * area;             // 6.70919e7 N
    p->EI = 1000.0;
    // Kelvin-Voigt damping with a 0.01 s time constant: damps the axial waves that a stiff cable
    // rings with after every kink of the tow trajectory (without it the integrator resolves them
    // forever: 660 s of the Hopland manoeuvre cost 177 000 steps instead of 2 500), while the
    // quasi-static strain rates of a manoeuvre (~1e-7 /s) make it a ~0.1 N effect.
    p->axialDamping = 0.01 * p->EA;
    p->Cdn = 1.649;
    p->Cdt = 0.12;
    p->Can = 1.0;
    p->Cat = 0.0;
    p->waterDensity = 1025.0;
    p->gravity = 9.81;
    p->nElements = 20;
    // Tension is EA times a difference of node positions hundreds of metres from the origin, so
    // it needs tight relative accuracy: measured on the Hopland manoeuvre (N = 20), relTol 1e-8
    // is both the most accurate and the cheapest (0.34 s CPU, 0.14 N tension error) of the
    // settings tried; looser ones let axial noise in and need more steps.
    p->relTol = 1e-8;
    p->absTol = 1e-6;
    p->bottomEnd = UC_BOTTOM_FREE;
    p->topEnd = UC_TOP_HINGED;
    p->topTangent[2] = -1.0;
    p->anchor[2] = -300.0;
    p->initMode = UC_INIT_EQUILIBRIUM;
    p->initialDirection[2] = -1.0;
    p->enableBending = 1;
    p->enableAddedMass = 1;
    p->enableSeabed = 0;
    p->waterDepth = 1000.0;
    // 1e5 N/m2: the default cable (16 N/m wet) sinks 0.2 mm, a 1000 N/m chain 1 cm.
    p->seabedStiffness = 1e5;
    // About critical for a metre of the default cable on the default stiffness, 2 sqrt(k m).
    p->seabedDamping = 1e3;
    p->seabedFriction = 0.0;
    p->currentProfileRows = 0;
    p->enableTorsion = 0;
    // Typical of an armoured cable: GJ of the same order as EI.
    p->GJ = 1000.0;
    p->torqueMode = UC_TORQUE_FREE;
    p->enableCompression = 1;
}

extern "C" int uc_params_check(const UCParams* p, char* msg, size_t msgSize) {
    std::string m = p ? uc::check_params(*p) : std::string("parameters: NULL pointer");
    if (m.empty()) return 0;
    if (msg && msgSize) std::snprintf(msg, msgSize, "%s", m.c_str());
    return 1;
}
