// line_file.h - a line described by a MoorDyn v2 input file ("deck"): the text is parsed into one
// chain of lines from the vessel point to the far end, in this model's conventions, and written into
// the parameters. The supported subset of the format and every conversion of MoorDyn's conventions
// into ours are in docs/lines.md. No I/O here: the caller reads the file and hands over its text.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "cable_api.h"

namespace uc {

// One MoorDyn line as a section of our line, oriented from the tow point, in our conventions.
struct LineFileSection {
    std::string type;       // the name of its line type
    double length = 0.0;    // UnstrLen [m]
    double diameter = 0.0;  // Diam: MoorDyn's volume-equivalent diameter is ours (hydrodynamic and displacement)
    double massPerLength = 0.0;
    double EA = 0.0;
    double EI = 0.0;
    double axialDamping = 0.0;  // [N.s]: BA, or -zeta converted with MoorDyn's segment length
    double Cdn = 0.0, Cdt = 0.0, Can = 0.0, Cat = 0.0;  // Cd, CdAx, Ca, CaAx
    int numSegs = 0;        // MoorDyn's NumSegs
    int elements = 0;       // our cubic elements (docs/lines.md: the rule, or lineFileElements)
    int row = 0;            // line of the file of its LINES entry
};

// A Free point: a joint between two sections, or a body at the free far end.
struct LineFilePoint {
    int id = 0;
    double mass = 0.0;       // M [kg]
    double volume = 0.0;     // V [m3]
    double addedMass = 0.0;  // CA rho V [kg]
    double CdA = 0.0;        // [m2]
    int row = 0;
    bool empty() const { return mass == 0.0 && volume == 0.0 && addedMass == 0.0 && CdA == 0.0; }
};

enum class LineFileFarEnd { Anchored, Body, Free };

// The line of a deck: what the parameters need, plus notes for the log.
struct LineFileLine {
    std::vector<LineFileSection> sections;  // from the tow point
    std::vector<LineFilePoint> joints;      // joints[k] between sections k and k + 1
    LineFileFarEnd farEnd = LineFileFarEnd::Anchored;
    double anchor[3] = {0.0, 0.0, 0.0};     // the Fixed point (Anchored)
    LineFilePoint body;                     // the Free point at the far end (Body)
    double towPoint[3] = {0.0, 0.0, 0.0};   // the Vessel/Coupled point (the tow.* inputs drive it)
    double waterDepth = 0.0, gravity = 0.0, waterDensity = 0.0;
    std::vector<std::string> notes;         // "line <n>: ..." : what was ignored or adjusted
};

// MoorDyn's default options (what MoorDyn-C uses when the deck does not set them).
constexpr double kMoorDynGravity = 9.80665;
constexpr double kMoorDynWaterDensity = 1025.0;

// Our elements for a MoorDyn line of numSegs segments when lineFileElements = 0 (docs/lines.md).
int elements_for_segments(int numSegs);

// Parses the text of a MoorDyn v2 input file. elementsTotal is the parameter lineFileElements: 0, each
// line's elements from its NumSegs; N > 0, about N over the whole line in proportion to the lengths.
// Returns false with error = "line <n>: <what>" (or "<what>" for the deck as a whole) when the text is
// not a readable deck or describes something outside the supported subset.
bool read_line_file(std::string_view text, int elementsTotal, LineFileLine& line, std::string& error);

// Writes the line into the parameters (line properties, elements, far end, environment). False with a
// message when the parameters cannot describe it.
bool apply_line_file(const LineFileLine& line, UCParams& p, std::string& error);

}  // namespace uc
