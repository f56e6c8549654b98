// params.cpp - defaults (the start values of schema/variables.toml) and the single place where parameters are validated.
#include "model/params.h"
#include "terms/axial_curve.h"
#include "terms/syrope.h"
#include "terms/waves.h"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace uc {
namespace {

// The components of a spread sea, waves.nComponents in each of waves.nDirections directions: each carries
// 91 Taylor weights (0.7 KB), summed per load point and cell.
constexpr int kMaxSpreadComponents = 20000;

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

bool in_range(std::string& message, const char* name, double v, double lo, double hi,
              const char* range, const char* why) {
    if (std::isfinite(v) && v >= lo && v <= hi) return false;
    message = format_violation(name, v, range, why);
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

// The interval of the schema (schema/variables.toml), open or closed at each end.
bool outside_schema_range(std::string& message, const char* name, double v, double lo, double hi, bool loOpen,
                          bool hiOpen, const char* range, const char* why) {
    const bool inside = std::isfinite(v) && (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
    if (inside) return false;
    message = format_violation(name, v, range, why);
    return true;
}

}  // namespace

std::string check_params(const UCParams& p) {
    std::string m;
#define UC_CHECK_RANGE(member, name, lo, hi, loOpen, hiOpen, range, why) \
    if (outside_schema_range(m, name, static_cast<double>(p.member), lo, hi, loOpen, hiOpen, range, why)) return m;
    UC_SCHEMA_PARAMETER_RANGES(UC_CHECK_RANGE)
#undef UC_CHECK_RANGE
#define UC_CHECK_BOOLEAN(member, name) \
    if (in_range(m, name, p.member, 0, 1, "{0, 1}", "a switch is on or off")) return m;
    UC_SCHEMA_BOOLEAN_PARAMETERS(UC_CHECK_BOOLEAN)
#undef UC_CHECK_BOOLEAN
    // Conditions between parameters, beyond the ranges of the schema.
    if (unit_direction(m, "initialDirection", p.initialDirection)) return m;
    if (p.topEnd == UC_TOP_CLAMPED && unit_direction(m, "topTangent", p.topTangent)) return m;
    if (p.enableTorsion && p.torqueMode == UC_TORQUE_ROTATION &&
        positive(m, "GJ", p.GJ, "a prescribed end rotation makes a torque only through GJ"))
        return m;
    if (p.enableSeabed && positive(m, "seabedStiffness", p.seabedStiffness, "an enabled seabed needs a contact stiffness"))
        return m;
    const bool ownSea = p.wavesMode == 1 || p.wavesMode == 2;  // waves.mode 3: given components
    if (ownSea && p.wavesHeight > 0.0 &&
        positive(m, "gravity", p.gravity, "waves need gravity: it sets their wavelength (w^2 = g k tanh(k h))"))
        return m;
    if (p.wavesMode == 3) {
        const std::string given = given_waves_violation(p);
        if (!given.empty()) return given;
    } else if (p.wavesFile[0] != '\0') {
        return "waves.file = '" + std::string(p.wavesFile) + "' is set with waves.mode = " + std::to_string(p.wavesMode) +
               ": its components are the sea of waves.mode 3 only (set waves.mode 3, or leave waves.file empty)";
    }
    if (p.wavesSpreading > 0.0 && p.wavesMode != 2 && p.wavesMode != 0)
        return format_violation("waves.spreading", p.wavesSpreading, p.wavesMode == 1 ? "{0} with waves.mode 1" : "{0} with waves.mode 3",
                                "the directional spreading spreads the JONSWAP sea of waves.mode 2 (given components "
                                "carry their own directions, a regular wave has one)");
    if (p.wavesMode == 2 && p.wavesSpreading > 0.0 && p.wavesNDirections > 1 &&
        p.wavesNComponents * p.wavesNDirections > kMaxSpreadComponents) {
        char range[160];
        std::snprintf(range, sizeof range, "[1, %d] with waves.nDirections = %d (at most %d components in all)",
                      kMaxSpreadComponents / p.wavesNDirections, p.wavesNDirections, kMaxSpreadComponents);
        return format_violation("waves.nComponents", p.wavesNComponents, range,
                                "a spread sea carries waves.nComponents components in each direction: fewer components "
                                "or directions");
    }
    if (p.currentsMode != 0 && p.currentsMode != 2 && p.currentsMode != 5)
        return format_violation("currents.mode", p.currentsMode, "{0, 2, 5}",
                                "current data are a profile changing in time (2) or a grid in x, y, z and t (5), "
                                "MoorDyn's Currents 2 and 5 (Currents 1, a steady profile, is currentProfile.*)");
    if (p.currentsMode != 0 && p.currentsFile[0] == '\0')
        return "currents.mode = " + std::to_string(p.currentsMode) + " needs the file of its data: currents.file is empty "
               "(set it, or leave currents.mode 0)";
    if (p.currentsMode == 0 && p.currentsFile[0] != '\0')
        return "currents.file = '" + std::string(p.currentsFile) + "' is set with currents.mode = 0: set currents.mode 2 "
               "(a profile changing in time) or 5 (a grid in x, y, z and t), or leave currents.file empty";
    if (p.seabedFile[0] != '\0' && p.seabedSlope != 0.0)
        return "seabed.file = '" + std::string(p.seabedFile) + "' is set with seabedSlope = " + std::to_string(p.seabedSlope) +
               " deg: the grid is the seabed in place of the plane (set seabedSlope 0, or leave seabed.file empty)";
    if (p.seabedFile[0] != '\0' && p.enableSeabed == 0)
        return "seabed.file = '" + std::string(p.seabedFile) + "' is set with enableSeabed = 0: set enableSeabed 1 for "
               "the seabed of the grid, or leave seabed.file empty";
    if (ownSea && p.wavesHeight > 0.0) {  // breaking: H over the (peak) wavelength above 1/7
        const double k = wave_number(2.0 * kPi / p.wavesPeriod, p.waterDepth, p.gravity);
        const double limit = 2.0 * kPi / k / 7.0;
        if (p.wavesHeight > limit) {
            char range[160];
            std::snprintf(range, sizeof range, "[0, %.6g] (a seventh of the wavelength of waves.period in waterDepth)", limit);
            return format_violation("waves.height", p.wavesHeight, range, "steeper waves break");
        }
    }
    // A tension-strain curve: a uniform line's, through points that make a monotone curve.
    if (p.axialCurvePoints > 0) {
        if (p.nSections >= 2)
            return format_violation("axialCurvePoints", p.axialCurvePoints, "{0} with nSections >= 2",
                                    "the tension-strain curve describes a uniform line (nSections 1)");
        if (p.axialCurvePoints < 2)
            return format_violation("axialCurvePoints", p.axialCurvePoints, "{0} or [2, 30]", "a curve needs two points");
        AxialCurve curve;
        std::string why;
        if (!AxialCurve::build(p.axialCurveStrain, p.axialCurveTension, p.axialCurvePoints, curve, why))
            return "axialCurve.strain/tension[1.." + std::to_string(p.axialCurvePoints) + "], " + why;
    }
    if (p.waterSource == UC_WATER_PUSHED && p.winchMode != 0)
        return format_violation("water.source", p.waterSource, "{0} with winchMode != 0",
                                "a winch's line changes its elements and so the load points whose water the importer "
                                "pushes");
    // The Syrope model: a uniform line's, its original working curve axialCurve.*, its dynamic stiffness
    // EAdynamic + EAdynamicSlope T.
    const bool syrope = p.syropeWorkingCurve != 0;
    if (syrope) {
        if (p.nSections >= 2)
            return format_violation("syrope.workingCurve", p.syropeWorkingCurve, "{0} with nSections >= 2",
                                    "the Syrope model describes a uniform line (nSections 1)");
        if (p.axialCurvePoints == 0)
            return format_violation("syrope.workingCurve", p.syropeWorkingCurve, "{0} with axialCurvePoints = 0",
                                    "the Syrope model needs its original working curve in axialCurve.*");
        if (!(p.EAdynamic > 0.0))
            return format_violation("EAdynamic", p.EAdynamic, "(0, 1e13] with syrope.workingCurve != 0",
                                    "the Syrope model's dynamic stiffness EA_Dc is above 0");
        if (p.winchMode != 0)
            return format_violation("syrope.workingCurve", p.syropeWorkingCurve, "{0} with winchMode != 0",
                                    "a winch's line changes its elements, which would lose their tension history");
        SyropeProps s;
        syrope_from_params(p, s);
        const std::string why = syrope_check(s, "syrope.");
        if (!why.empty()) return why;
        if (!(p.axialDamping + p.axialDampingDynamic > 0.0))
            return format_violation("axialDamping", p.axialDamping, "(0, 1e13] with no axialDampingDynamic",
                                    "the Syrope model's slow strain moves through a dashpot: the static or the "
                                    "dynamic damping is above 0");
    }
    // The viscoelastic model: a uniform line's (EAdynamic) or a section's (section[k].EAdynamic), its dynamic
    // stiffness above the static one.
    if (p.EAdynamic > 0.0 && p.nSections >= 2)
        return format_violation("EAdynamic", p.EAdynamic, "{0} with nSections >= 2",
                                "the line's viscoelastic model describes a uniform line (nSections 1; sections have "
                                "section[k].EAdynamic)");
    for (int k = 0; k < (p.nSections >= 2 ? p.nSections : 1) && k < UC_MAX_SECTIONS; ++k) {
        const bool line = p.nSections < 2;
        const double EAd = line ? p.EAdynamic : p.section[k].EAdynamic;
        if (!(EAd > 0.0) || syrope) continue;
        const double EA = line ? p.EA : p.section[k].EA;
        const double c = line ? p.axialDamping : p.section[k].axialDamping;
        const double cd = line ? p.axialDampingDynamic : p.section[k].axialDampingDynamic;
        char name[64], dampingName[64];
        std::snprintf(name, sizeof name, line ? "EAdynamic" : "section[%d].EAdynamic", k + 1);
        std::snprintf(dampingName, sizeof dampingName, line ? "axialDampingDynamic" : "section[%d].axialDampingDynamic", k + 1);
        if (p.axialCurvePoints > 0)
            return format_violation(name, EAd, "{0} with axialCurvePoints > 0",
                                    "the viscoelastic model's static stiffness is the constant EA, not a tension-strain curve");
        if (p.winchMode != 0)
            return format_violation(name, EAd, "{0} with winchMode != 0",
                                    "a winch's line changes its elements, which would lose their internal strains");
        if (!(EAd > EA)) {
            char range[120];
            std::snprintf(range, sizeof range, "(%.6g, 1e13] (above %s, the static stiffness)", EA, line ? "EA" : "its EA");
            return format_violation(name, EAd, range,
                                    "the dynamic spring is in series with another: it is stiffer than the static EA");
        }
        if (!(c + cd > 0.0))
            return format_violation(dampingName, cd, "(0, 1e13] with no static damping",
                                    "the viscoelastic model's internal strain moves through a dashpot: the static or the "
                                    "dynamic damping is above 0");
    }
    // Vortex-induced vibration: a uniform line's (Cl) or a section's (section[k].Cl).
    if (p.Cl > 0.0 && p.nSections >= 2)
        return format_violation("Cl", p.Cl, "{0} with nSections >= 2",
                                "the line's lift coefficient describes a uniform line (nSections 1; sections have "
                                "section[k].Cl)");
    for (int k = 0; k < (p.nSections >= 2 ? p.nSections : 1) && k < UC_MAX_SECTIONS; ++k) {
        const bool line = p.nSections < 2;
        const double Cl = line ? p.Cl : p.section[k].Cl;
        if (!(Cl > 0.0)) continue;
        char name[64];
        std::snprintf(name, sizeof name, line ? "Cl" : "section[%d].Cl", k + 1);
        if (p.winchMode != 0)
            return format_violation(name, Cl, "{0} with winchMode != 0",
                                    "a winch's line changes its elements, which would lose their vortex-shedding phases");
    }
    // Sections and attachments: every section in use has a length; attachments lie on the line.
    double lineLength = p.length;
    if (p.nSections >= 2) {
        lineLength = 0.0;
        for (int k = 0; k < p.nSections; ++k) {
            char name[64];
            std::snprintf(name, sizeof name, "section[%d].length", k + 1);
            if (!(p.section[k].length > 0.0))
                return format_violation(name, p.section[k].length, "(0, 1e5]", "every section in use (k <= nSections) needs a positive length");
            if (p.enableTorsion && p.torqueMode == UC_TORQUE_ROTATION) {
                std::snprintf(name, sizeof name, "section[%d].GJ", k + 1);
                if (positive(m, name, p.section[k].GJ, "a prescribed end rotation makes a torque only through GJ")) return m;
            }
            lineLength += p.section[k].length;
        }
    }
    for (int k = 0; k < p.nAttachments; ++k) {
        const double s = p.attachment[k].s;
        if (s > 0.0 && s <= lineLength * (1.0 + 1e-12)) continue;
        char name[64], range[96];
        std::snprintf(name, sizeof name, "attachment[%d].s", k + 1);
        std::snprintf(range, sizeof range, "(0, %.17g] (the line's length)", lineLength);
        return format_violation(name, s, range, "an attachment lies on the line, beyond the tow point");
    }
    if (p.winchMode != 0) {
        char range[160];
        if (!(p.winchMinLength < p.winchMaxLength)) {
            std::snprintf(range, sizeof range, "(0, %.17g) (below winch.maxLength)", p.winchMaxLength);
            return format_violation("winch.minLength", p.winchMinLength, range, "the winch needs room between its limits");
        }
        if (lineLength < p.winchMinLength || lineLength > p.winchMaxLength) {
            std::snprintf(range, sizeof range, "[%.17g, %.17g] (winch.minLength, winch.maxLength)", p.winchMinLength,
                          p.winchMaxLength);
            return format_violation(p.nSections >= 2 ? "section[1].length" : "length", lineLength, range,
                                    "the run starts with the line's length, within the winch's limits");
        }
        const double first = p.nSections >= 2 ? p.section[0].length : p.length;
        const double below = lineLength - first;  // the sections the winch cannot haul in
        if (p.winchMinLength <= below) {
            std::snprintf(range, sizeof range, "(%.17g, %.17g) (beyond the sections after the first)", below,
                          p.winchMaxLength);
            return format_violation("winch.minLength", p.winchMinLength, range,
                                    "the winch hauls in the first section only");
        }
        for (int k = 0; k < p.nAttachments; ++k) {
            if (p.attachment[k].s >= first) continue;
            char name[64];
            std::snprintf(name, sizeof name, "attachment[%d].s", k + 1);
            std::snprintf(range, sizeof range, "[%.17g, %.17g] (beyond the first section, which the winch pays out)",
                          first, lineLength);
            return format_violation(name, p.attachment[k].s, range, "the winch's section cannot carry attachments");
        }
    }
    if (p.bottomEnd == UC_BOTTOM_PROXY && !(p.bodyMass + p.bodyAddedMass > 0.0))
        return format_violation("body.mass", p.bodyMass, "(0, 1e8] (with body.addedMass)",
                                "the proxy of an external body (bottomEnd 4) carries the body's inertia: it needs one");
    {
        // (m + m_a) I + A: symmetric and positive definite, or the body's inertia has no meaning.
        const double* A[3] = {p.bodyAddedMassMatrix.x, p.bodyAddedMassMatrix.y, p.bodyAddedMassMatrix.z};
        double M[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) M[i][j] = A[i][j] + (i == j ? p.bodyMass + p.bodyAddedMass : 0.0);
        const char* names[3][3] = {{"xx", "xy", "xz"}, {"yx", "yy", "yz"}, {"zx", "zy", "zz"}};
        char name[64];
        for (int i = 0; i < 3; ++i)
            for (int j = i + 1; j < 3; ++j) {
                if (A[i][j] == A[j][i]) continue;
                std::snprintf(name, sizeof name, "body.addedMassMatrix.%s", names[j][i]);
                char range[64];
                std::snprintf(range, sizeof range, "{%.17g} (body.addedMassMatrix.%s)", A[i][j], names[i][j]);
                return format_violation(name, A[j][i], range, "an added-mass matrix is symmetric");
            }
        const bool any = A[0][0] != 0.0 || A[0][1] != 0.0 || A[0][2] != 0.0 || A[1][1] != 0.0 || A[1][2] != 0.0 || A[2][2] != 0.0;
        // leading minors of the symmetric matrix (Sylvester)
        const double d1 = M[0][0], d2 = M[0][0] * M[1][1] - M[0][1] * M[1][0];
        const double d3 = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                          M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
        if (any && !(d1 > 0.0 && d2 > 0.0 && d3 > 0.0))
            return format_violation("body.addedMassMatrix.xx", A[0][0], "a matrix that leaves (body.mass + body.addedMass) I + A positive definite",
                                    "the body's inertia must be positive in every direction");
    }
    for (int k = 1; k < p.currentProfileRows; ++k) {
        if (p.currentProfileDepth[k] > p.currentProfileDepth[k - 1]) continue;
        char name[64], range[96];
        std::snprintf(name, sizeof name, "currentProfile.depth[%d]", k + 1);
        std::snprintf(range, sizeof range, "(%.17g, inf)", p.currentProfileDepth[k - 1]);
        return format_violation(name, p.currentProfileDepth[k], range, "profile depths must increase row by row");
    }
    return std::string();
}

bool syrope_from_params(const UCParams& p, SyropeProps& s) {
    s = SyropeProps{};
    if (p.syropeWorkingCurve == 0 || p.nSections >= 2) return false;
    s.form = p.syropeWorkingCurve;
    s.k1 = p.syropeK1;
    s.k2 = p.syropeK2;
    s.alpha = p.EAdynamic;
    s.beta = p.EAdynamicSlope;
    s.tensionMax0 = p.syropeTensionMax0;
    s.tensionMean0 = p.syropeTensionMean0;
    s.strain0 = p.axialCurvePoints > 0 ? p.axialCurveStrain[0] : 0.0;
    std::string error;
    return AxialCurve::build(p.axialCurveStrain, p.axialCurveTension, p.axialCurvePoints, s.owc, error);
}

}  // namespace uc
