// options.cpp - the OPTIONS section of a MoorDyn v2 deck (docs/lines.md, "Options and environment").
#include "deck/tables.h"

namespace uc {
namespace deck {

bool read_options(const Section& section, Options& options, std::vector<std::string>& notes, std::string& error) {
    for (const Row& row : section.rows) {
        Fields f(row, error);
        if (row.tokens.size() < 2) {
            notes.push_back(at_line(row.number, "ignored: an option is a value followed by its name"));
            continue;
        }
        const std::string name = lower(row.tokens[1]);
        const std::string name_shown(row.tokens[1]);
        if (name == "wtrdpth") {
            if (!to_number(row.tokens[0])) {
                return f.fail("WtrDpth " + quoted(row.tokens[0]) +
                              " is not a number (a bathymetry file is not supported: the seabed is flat)");
            }
            options.waterDepth = f.number(0, "WtrDpth", 0.0, HUGE_VAL, "a water depth must not be negative");
            options.waterDepthRow = row.number;
        } else if (is_one_of(name, {"g", "gravity"})) {
            options.gravity = f.number(0, name_shown.c_str(), 0.0, HUGE_VAL, "gravity must not be negative");
            options.gravityRow = row.number;
        } else if (is_one_of(name, {"rho", "rhow", "wtrdnsty"})) {
            options.waterDensity = f.number(0, name_shown.c_str(), 0.0, HUGE_VAL, "a density must not be negative");
            options.waterDensityRow = row.number;
        } else if (is_one_of(name, {"wavekin", "currents"})) {
            const int v = f.integer(0, name_shown.c_str(), 0, 1000, "an option number");
            if (f.ok()) (name == "wavekin" ? options.waveKin : options.currents) = {v, row.number};
        } else if (name == "seafloorfile") {
            options.seabed.seafloorFile = std::string(row.tokens[0]);  // read from the companions (read_seafloor)
            options.seabed.seafloorFileRow = row.number;
        } else if (is_one_of(name, {"kbot", "kb"})) {
            options.seabed.kBot = f.number(0, name_shown.c_str(), 0.0, HUGE_VAL, "a seabed stiffness must not be negative");
            options.seabed.kBotRow = row.number;
        } else if (is_one_of(name, {"cbot", "cb"})) {
            options.seabed.cBot = f.number(0, name_shown.c_str(), 0.0, HUGE_VAL, "a seabed damping must not be negative");
            options.seabed.cBotRow = row.number;
        } else if (name == "frictioncoefficient") {
            options.seabed.friction = f.number(0, name_shown.c_str(), 0.0, 10.0, "a friction coefficient in [0, 10]");
            options.seabed.frictionRow = row.number;
        } else if (name == "fricdamp") {
            options.seabed.fricDamp = f.number(0, name_shown.c_str(), 0.0, HUGE_VAL, "must not be negative");
            options.seabed.fricDampRow = row.number;
        } else if (name == "statdynfricscale") {
            options.seabed.statDynFricScale = f.number(0, name_shown.c_str(), 0.0, HUGE_VAL, "must not be negative");
            options.seabed.statDynFricScaleRow = row.number;
        } else if (is_one_of(name, {"dtm", "dt", "cfl", "tscheme", "dtout"})) {
            notes.push_back(at_line(row.number, name_shown + " ignored, not applicable: MoorDyn's own time step, scheme or output "
                                                        "period; the FMU's integrator chooses its steps from its "
                                                        "tolerances between communication points"));
        } else if (is_one_of(name, {"tmaxic", "ictmax"}) && to_number(row.tokens[0]) && *to_number(row.tokens[0]) == 0.0) {
            options.noInitialConditions = true;
            notes.push_back(at_line(row.number, name_shown + " 0: free points where three or more lines meet start at "
                                                        "rest where the deck places them (as MoorDyn starts them "
                                                        "without generating initial conditions); otherwise ignored"));
        } else if (is_one_of(name, {"dtic", "icdt", "tmaxic", "ictmax", "cdscaleic", "icdfac", "threshic", "icthresh",
                                    "gendynamicic", "icgendynamic", "fileic", "icfile"})) {
            notes.push_back(at_line(row.number, name_shown + " ignored, not applicable: it steers MoorDyn's generation of "
                                                        "initial conditions; the FMU solves the static equilibrium "
                                                        "itself (initMode)"));
        } else if (is_one_of(name, {"writelog", "writeunits", "disableoutput", "disableouttime"})) {
            notes.push_back(at_line(row.number, name_shown + " ignored, not applicable: MoorDyn's own files and output"));
        } else if (name == "dtwave") {
            options.dtWave = f.number(0, name_shown.c_str(), 0.0, HUGE_VAL, "a time step must be positive");
            if (f.ok() && !(options.dtWave > 0.0)) return f.fail("dtWave = 0 s: a time step must be positive");
            options.dtWaveRow = row.number;
        } else if (name == "unifycurrentgrid") {
            notes.push_back(at_line(row.number, name_shown + " ignored, not applicable: it concerns MoorDyn's grids of wave and "
                                                        "current kinematics, which the FMU does not make (WaveKin, Currents)"));
        } else {
            notes.push_back(at_line(row.number, "unknown option " + quoted(row.tokens[1]) +
                                                    " ignored (MoorDyn ignores it too, with a warning)"));
        }
        if (!f.ok()) return false;
    }
    return true;
}

}  // namespace deck
}  // namespace uc
