// environment_notes.cpp - what the log says about a deck's environment and seabed against the parameters
// (docs/lines.md, "Seabed"): the deck's value or the importer's, and why.
#include "deck/line_file.h"

#include <cstdio>

namespace uc {

std::vector<std::string> deck_environment_notes(const LineFileLine& line, double bottomDiameter,
                                                const UCParams& importer) {
    std::vector<std::string> out;
    auto brief = [](double v) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.9g", v);
        return std::string(buffer);
    };
    const int keep = importer.deckKeep;
    const LineFileSeabed& bed = line.seabed;
    // "<option> <value> (line n)" or "<option> <value> (MoorDyn's default: the deck does not set it)"
    auto option = [&](const char* name, double value, const char* unit, int row) {
        return std::string(name) + " " + brief(value) + unit +
               (row > 0 ? " (line " + std::to_string(row) + ")" : " (MoorDyn's default: the deck does not set it)");
    };
    auto kept = [&](const char* parameter, double value, const std::string& deck) {
        out.push_back(std::string(parameter) + " = " + brief(value) + " set through the FMI is used, not " + deck +
                      ": a parameter the importer sets explicitly overrides the deck");
    };
    if (keep & UC_DECK_KEEP_WATER_DEPTH) kept("waterDepth", importer.waterDepth, option("WtrDpth", line.waterDepth, " m", line.waterDepthRow));
    if (keep & UC_DECK_KEEP_GRAVITY) kept("gravity", importer.gravity, option("g", line.gravity, " m/s2", line.gravityRow));
    if (keep & UC_DECK_KEEP_WATER_DENSITY) {
        kept("waterDensity", importer.waterDensity, option("rho", line.waterDensity, " kg/m3", line.waterDensityRow));
    }
    if (keep & UC_DECK_KEEP_ENABLE_COMPRESSION) {
        out.push_back(std::string("enableCompression = ") + (importer.enableCompression ? "true" : "false") +
                      " set through the FMI is used, not MoorDyn's tension-only lines: a parameter the importer sets "
                      "explicitly overrides the deck");
    }
    // bottomDiameter 0: a mooring system, each line's own
    const std::string diam = bottomDiameter > 0.0 ? " x Diam " + brief(bottomDiameter) + " m"
                                                  : " x Diam of each line's section at its far end";
    if (keep & UC_DECK_KEEP_ENABLE_SEABED) {
        out.push_back(std::string("enableSeabed = ") + (importer.enableSeabed ? "true" : "false") +
                      " set through the FMI is used, not the deck's seabed (MoorDyn always has one at WtrDpth): a "
                      "parameter the importer sets explicitly overrides the deck");
    } else if (bed.kBot <= 0.0) {
        out.push_back(option("kBot", bed.kBot, " Pa/m", bed.kBotRow) + ": no seabed contact (enableSeabed = false), "
                      "as MoorDyn has none with a zero stiffness");
    } else {
        out.push_back("the seabed is on at WtrDpth as MoorDyn has it (enableSeabed = true, unless set through the FMI)");
    }
    if (bed.kBot > 0.0) {
        if (keep & UC_DECK_KEEP_SEABED_STIFFNESS) {
            kept("seabedStiffness", importer.seabedStiffness, option("kBot", bed.kBot, " Pa/m", bed.kBotRow) + diam);
        } else {
            out.push_back("seabedStiffness = " + (bottomDiameter > 0.0 ? brief(bed.kBot * bottomDiameter) + " N/m2" : "") + " from " +
                          option("kBot", bed.kBot, " Pa/m", bed.kBotRow) + diam);
        }
        if (keep & UC_DECK_KEEP_SEABED_DAMPING) {
            kept("seabedDamping", importer.seabedDamping, option("cBot", bed.cBot, " Pa s/m", bed.cBotRow) + diam);
        } else {
            out.push_back("seabedDamping = " + (bottomDiameter > 0.0 ? brief(bed.cBot * bottomDiameter) + " N.s/m2" : "") + " from " +
                          option("cBot", bed.cBot, " Pa s/m", bed.cBotRow) + diam);
        }
        bool several = false;
        for (const LineFileSection& s : line.sections) several = several || s.diameter != bottomDiameter;
        if (several && bottomDiameter > 0.0) {
            out.push_back("the sections' diameters differ: the seabed contact per unit length is that of Diam " +
                          brief(bottomDiameter) + " m, the section at the far end (MoorDyn's is each line's "
                          "own; the static state does not depend on it, seabedRest)");
        }
    }
    if (keep & UC_DECK_KEEP_SEABED_FRICTION) {
        kept("seabedFriction", importer.seabedFriction, option("FrictionCoefficient", bed.friction, "", bed.frictionRow));
    } else if (bed.friction > 0.0) {
        out.push_back("warning: seabedFriction = " + option("FrictionCoefficient", bed.friction, "", bed.frictionRow) +
                      ": the FMU's seabed friction is Coulomb's, regularized below 0.01 m/s; MoorDyn's is a damping "
                      "of each node's sliding, FricDamp x FrictionCoefficient x speed (" +
                      option("FricDamp", bed.fricDamp, " N.s/m", bed.fricDampRow) + "), saturating at " +
                      option("StatDynFricScale", bed.statDynFricScale, "", bed.statDynFricScaleRow) +
                      " x the Coulomb force, and so weaker at slow sliding: statics agree, motions on the seabed "
                      "do not (set seabedFriction = 0 for a line sliding as in MoorDyn at low speed)");
    } else if (bed.fricDampRow > 0 || bed.statDynFricScaleRow > 0) {
        out.push_back("FricDamp and StatDynFricScale have no effect: FrictionCoefficient is 0 (no seabed friction, "
                      "as in MoorDyn)");
    }
    return out;
}

std::vector<std::string> mooring_environment_notes(const MooringDeck& deck, const UCParams& importer) {
    LineFileLine env;
    env.waterDepth = deck.waterDepth;
    env.gravity = deck.gravity;
    env.waterDensity = deck.waterDensity;
    env.waterDepthRow = deck.waterDepthRow;
    env.gravityRow = deck.gravityRow;
    env.waterDensityRow = deck.waterDensityRow;
    env.seabed = deck.seabed;
    return deck_environment_notes(env, 0.0, importer);
}

}  // namespace uc
