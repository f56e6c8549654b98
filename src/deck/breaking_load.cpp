// breaking_load.cpp - a line type's minimum breaking load where the deck gives none: MoorPy's line
// property formulas (MoorProps_default.yaml) for the material its name names (docs/design_checks.md).
#include <cmath>
#include <cstdio>

#include "deck/tables.h"

namespace uc {
namespace deck {
namespace {

// One material of MoorPy's MoorProps_default.yaml: MBL = MBL_d d + MBL_d2 d^2 + MBL_d3 d^3 [N] at the
// nominal diameter d [m], and the mass per length mass_d2 d^2 [kg/m] that gives d from Mass/m.
struct Material {
    const char* keyword;  // in the lower-cased type name
    const char* what;     // for the log
    double massD2, mblD, mblD2, mblD3;
};

// Looked up in this order: "studlink" before "chain".
constexpr Material kMaterials[] = {
    {"studlink", "R4 studlink chain", 21.9e3, 9.11e2, 1.21e9, -2.19e9},
    {"chain", "R4 studless chain", 20.0e3, 9.11e2, 1.21e9, -2.19e9},
    {"wire", "wire rope", 5293.0, 0.0, 1022e6, 0.0},
    {"polyester", "polyester rope", 679.0, 0.0, 308e6, 0.0},
    {"poly", "polyester rope", 679.0, 0.0, 308e6, 0.0},
    {"nylon", "nylon rope", 585.0, 0.0, 207e6, 230e6},
};

std::string general(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", v);
    return text;
}

std::string formula(const Material& m) {
    std::string f;
    const double c[3] = {m.mblD, m.mblD2, m.mblD3};
    const char* powers[3] = {" d", " d^2", " d^3"};
    for (int i = 0; i < 3; ++i) {
        if (c[i] == 0.0) continue;
        if (!f.empty()) f += c[i] < 0.0 ? " - " : " + ";
        else if (c[i] < 0.0) f += "-";
        f += general(std::abs(c[i])) + powers[i];
    }
    return f + " N";
}

}  // namespace

double default_breaking_load(const LineType& t, std::string& note) {
    const std::string name = lower(t.name);
    for (const Material& m : kMaterials) {
        if (name.find(m.keyword) == std::string::npos) continue;
        const double d = std::sqrt(t.massPerLength / m.massD2);
        const double mbl = d * (m.mblD + d * (m.mblD2 + d * m.mblD3));
        const std::string said = "line type " + quoted(t.name) + ": no MBL column: MoorPy's " + m.what + ", MBL = " +
                                 formula(m) + " at the nominal diameter d = sqrt(Mass/m / " + general(m.massD2) +
                                 " kg/m3) = " + general(d) + " m";
        if (!(mbl > 0.0)) {
            note = "warning: " + said + " gives " + general(mbl) + " N (the fit holds below about 0.36 m): no MBL";
            return 0.0;
        }
        note = said + ": MBL = " + general(mbl) + " N";
        return mbl;
    }
    note = "line type " + quoted(t.name) + ": no MBL column and its name names no material of MoorPy's (chain, "
           "studlink, wire, polyester, nylon): the parameter MBL is used (0: no utilisation outputs)";
    return 0.0;
}

}  // namespace deck
}  // namespace uc
