// line_file.h - a line described by a MoorDyn v2 input file ("deck"): the text is parsed into one
// chain of lines from the vessel point to the far end, in this model's conventions, and written into
// the parameters. The supported subset of the format and every conversion of MoorDyn's conventions
// into ours are in docs/lines.md. No I/O here: the caller reads the file and hands over its text.
// The one header of deck/ for the rest of the core: the readers behind it (a file per table, the shared
// tokenizer) are internal to the folder (docs/architecture.md).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/types.h"
#include "model/parameters.h"
#include "terms/current_grid.h"
#include "terms/seabed_grid.h"

namespace uc {

// One MoorDyn line as a section of our line, oriented from the tow point, in our conventions.
struct LineFileSection {
    std::string type;       // the name of its line type
    double length = 0.0;    // UnstrLen [m]
    double diameter = 0.0;  // Diam: MoorDyn's volume-equivalent diameter is ours (hydrodynamic and displacement)
    double massPerLength = 0.0;
    double EA = 0.0;        // the constant EA, or the secant of the curve at its last point
    std::vector<double> curveStrain, curveTension;  // EA's tension-strain file (empty: none)
    double EAd = 0.0, EAslope = 0.0, BAd = 0.0;  // the viscoelastic model (EAd 0: none), as LineType's
    // the Syrope model (form 0: none), as LineType's, and the line's SYROPE IC
    int syropeForm = 0;
    double syropeK1 = 0.0, syropeK2 = 0.0, syropeTmax0 = 0.0, syropeTmean0 = 0.0;
    double EI = 0.0;
    double axialDamping = 0.0;  // [N.s]: BA, or -zeta converted with MoorDyn's segment length
    double Cdn = 0.0, Cdt = 0.0, Can = 0.0, Cat = 0.0;  // Cd, CdAx, Ca, CaAx
    double Cl = 0.0, vivFrequency = 0.18, vivFrequencyRange = 0.08;  // vortex-induced vibration: Cl, cF, dF
    double MBL = 0.0;       // minimum breaking load [N]: its type's MBL column or MoorPy's default (0: none)
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
    bool rigid = false;      // a joint that carries moment (a free zero-length rod both lines are clamped to)
    bool empty() const { return mass == 0.0 && volume == 0.0 && addedMass == 0.0 && CdA == 0.0; }
};

enum class LineFileFarEnd { Anchored, Body, Free };

// The water's motion a deck's kinematics options describe, in the FMU's terms (docs/lines.md, "Options and
// environment"): MoorDyn's steady current profile (Currents 1) as the currentProfile.* parameters, one
// wave component at MoorDyn's phase pi/2 (WaveKin 7) as the regular wave of waves.*, other components
// (WaveKin 2, 3, 7) as the given components of waves.mode 3.
struct LineFileSea {
    int profileRows = 0;  // > 0: the deck sets the current profile
    double profileDepth[UC_CURRENT_PROFILE_ROWS] = {}, profileX[UC_CURRENT_PROFILE_ROWS] = {},
           profileY[UC_CURRENT_PROFILE_ROWS] = {};
    bool regularWave = false;  // the deck sets waves.mode 1 with these
    double waveHeight = 0.0, wavePeriod = 0.0, waveDirection = 0.0;
    // not empty: the deck sets waves.mode 3 with these, each omega [rad/s], amplitude [m], phase [rad],
    // direction of travel [rad] in the FMU's convention a cos(k (x cos b + y sin b) - omega t + p)
    std::vector<std::array<double, 4>> waveComponents;
    // Currents 2 or 5: the current given as data (currents.mode), read from the companion file `currentsFile`
    // (its name beside the deck); a mooring system takes the grid itself, one line the file through the
    // parameters currents.mode and currents.file.
    int currentsMode = 0;
    std::string currentsFile;
    std::shared_ptr<const CurrentGrid> currentGrid;
};

// The rows "omega amplitude phase [direction]" of a waves.file (docs/waves.md, "Given components") into
// components as LineFileSea's (direction: the column, else `direction`); false with "line <n>: <what>".
bool read_wave_file(std::string_view text, double direction, std::vector<std::array<double, 4>>& components,
                    std::string& error);

// Writes given components into waves.mode 3 (waveComponentCount, waveComponents); false when more than
// UC_MAX_WAVE_COMPONENTS, naming the count and `from`.
bool apply_wave_components(const std::vector<std::array<double, 4>>& components, const char* from, UCParams& p,
                           std::string& error);

// The text of a file MoorDyn reads from the deck's directory (current_profile.txt, wave_frequencies.txt,
// wave_elevation.txt, a line type's tension-strain file).
struct LineFileCompanion {
    std::string name, text;
};
using LineFileCompanions = std::vector<LineFileCompanion>;

// The names of the files next to the deck that its options and line types ask for (empty when none): the caller reads
// them from the deck's directory and hands their text to read_line_file or read_mooring_deck.
std::vector<std::string> line_file_companions(std::string_view text);
// The files a companion `name` (with the text `companion`) of the deck `text` names in turn, relative to the deck:
// a Syrope settings file's original working curve (OWC); empty for any other file.
std::vector<std::string> line_file_nested_companions(std::string_view text, std::string_view name, std::string_view companion);

// MoorDyn's seabed, which is always there at WtrDpth (docs/lines.md, "Seabed"): kBot and cBot per unit of
// projected area [Pa/m, Pa s/m], the friction options; the deck's values, MoorDyn's defaults where it is
// silent. row: the line of the file that sets the option, 0 when the deck is silent.
struct LineFileSeabed {
    double kBot = 3.0e6, cBot = 3.0e5;  // MoorDyn's defaults
    double friction = 0.0, fricDamp = 200.0, statDynFricScale = 1.0;
    int kBotRow = 0, cBotRow = 0, frictionRow = 0, fricDampRow = 0, statDynFricScaleRow = 0;
    // SeafloorFile: its path as the deck gives it and, where its grid is a plane, that plane as the
    // FMU's sloped seabed (docs/lines.md): the depth under the origin, seabedSlope, seabedSlopeHeading.
    std::string seafloorFile;
    int seafloorFileRow = 0;
    bool plane = false;
    double planeDepth = 0.0, slope = 0.0, heading = 0.0;  // [m], [deg], [deg]
    // Where its grid is not a plane: the grid (seabed.file, the file by its name beside the deck) and the
    // water depth MoorDyn takes for it, its mean depth.
    std::shared_ptr<const SeabedGrid> grid;
    double meanDepth = 0.0;
};

// The line of a deck: what the parameters need, plus notes for the log.
struct LineFileLine {
    std::vector<LineFileSection> sections;  // from the tow point
    std::vector<LineFilePoint> joints;      // joints[k] between sections k and k + 1
    LineFileFarEnd farEnd = LineFileFarEnd::Anchored;
    double anchor[3] = {0.0, 0.0, 0.0};     // the Fixed point (Anchored)
    LineFilePoint body;                     // the Free point at the far end (Body)
    double towPoint[3] = {0.0, 0.0, 0.0};   // the Vessel/Coupled point (the tow.* inputs drive it)
    bool towFixed = false;                  // the tow point is the deck's Fixed point (no Vessel point)
    bool towClamped = false;                // the line is clamped at the tow point (on a Fixed rod): topEnd 1
    double towTangent[3] = {0.0, 0.0, 0.0}; // its direction there, into the line (topTangent)
    double waterDepth = 0.0, gravity = 0.0, waterDensity = 0.0;
    int waterDepthRow = 0, gravityRow = 0, waterDensityRow = 0;  // the rows that set them (0: MoorDyn's default)
    LineFileSeabed seabed;
    LineFileSea sea;
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
// companions: the files next to the deck that line_file_companions names (a missing one is an error naming it).
bool read_line_file(std::string_view text, int elementsTotal, LineFileLine& line, std::string& error,
                    const LineFileCompanions& companions = {});

// Writes the line into the parameters (line properties, elements, far end, environment, the seabed as
// MoorDyn has it: on at WtrDpth, seabedStiffness kBot x Diam, seabedDamping cBot x Diam, seabedFriction
// FrictionCoefficient, Diam that of the line's last section, the one on the seabed at its anchor). The
// environment and seabed parameters whose bit is set in p.deckKeep (UC_DECK_KEEP_*: set explicitly by the
// importer) keep the value p holds. False with a message when the parameters cannot describe it.
bool apply_line_file(const LineFileLine& line, UCParams& p, std::string& error);

// What the log says about the deck's environment and seabed against the parameters: for each of
// waterDepth, gravity, waterDensity, enableSeabed, seabedStiffness, seabedDamping, seabedFriction and
// enableCompression, which value is used (the deck's, or the importer's where its UC_DECK_KEEP_* bit is set
// in importer.deckKeep, the importer's value in `importer`) and why; lines starting "warning: " are
// fmi2Warnings (the friction law differs from MoorDyn's). bottomDiameter: Diam of the section on the seabed
// (0: a mooring system's, each line's own).
std::vector<std::string> deck_environment_notes(const LineFileLine& line, double bottomDiameter,
                                                const UCParams& importer);

// ------------------------------------------------------------------------------- mooring systems
// A deck of several lines, of lines on bodies, or with a BODIES section is a mooring system
// (docs/systems_mooring.md): each line runs from its fairlead, the end on a coupled body or a coupled
// point, to its anchor (a Fixed point) or to another coupled end.

// Where a line's end is held: on coupled body `body` (1-based, the deck's body ID; with no BODIES section
// the Vessel points ride body 1) at `position` in the body's frame, on coupled point `point` (its ID in
// the deck) at `position` (its place in the deck), fixed at `position`, or on free node `node` (0-based
// index into MooringDeck::nodes: a Free point where three or more lines meet; `position` is its place
// in the deck, the start of its static equilibrium's search).
struct MooringEnd {
    enum class Kind { Body, Point, Fixed, Node } kind = Kind::Fixed;
    int body = 0, point = 0, node = 0;
    double position[3] = {0.0, 0.0, 0.0};
};

// One of the system's lines: a chain of the deck's lines (its sections) from the fairlead through Free
// points that join two lines (its joints), to its far end.
struct MooringDeckLine {
    int id = 0, row = 0;                     // of its first deck line
    std::vector<LineFileSection> sections;   // from the fairlead
    std::vector<LineFilePoint> joints;       // joints[k] between sections k and k + 1
    std::vector<int> deckLines;              // the deck's line (0-based) of each section
    std::vector<bool> flipped;               // per section: the deck line's fairlead is at its far end
    MooringEnd fairlead, far;                // the line runs from its fairlead (s = 0) to its far end
    int fairleadPoint = 0, farPoint = 0;     // the deck points (IDs) of its ends (farPoint 0: a free far end)
    bool farFree = false;                    // the far end is a Free point: farBody (a towed body), or none
    bool farDetaches = false;                // a failure detaches its Fixed far end: the end is driven (held still until then)
    LineFilePoint farBody;
    bool fairleadClamped = false;            // clamped at a Fixed fairlead (a Fixed rod): topEnd 1
    double fairleadTangent[3] = {0.0, 0.0, 0.0};  // its direction there, into the line
};

// A rod fixed to a free or pinned body (docs/lines.md, "Rods"): its mass and inertia are the body's; its
// buoyancy, drag and added mass follow its part below z = 0 as the body moves (system/body_rods.h).
struct MooringRod {
    int id = 0;                                  // the deck's rod ID
    double a[3] = {0.0, 0.0, 0.0}, b[3] = {0.0, 0.0, 0.0};  // its ends in the body's frame [m]
    double diameter = 0.0, Cd = 0.0, Ca = 0.0, CdEnd = 0.0, CaEnd = 0.0;
};

// A Free point where three or more lines meet: its position is an unknown of the system, found from the
// equilibrium of its weight, buoyancy, drag and the lines' forces.
struct MooringNode {
    LineFilePoint point;                 // mass, volume, added mass, drag area (a body: its ID, mass, volume)
    double position[3] = {0.0, 0.0, 0.0};  // in the deck: the first guess (a body: its reference point)
    bool body = false;                   // a Free body: six unknowns, its points in its frame
    int failure = 0;                     // > 0: the massless free point failure `failure` (its ID) made
    double angles[3] = {0.0, 0.0, 0.0};  // a body's roll, pitch, yaw in the deck [rad] (R = Rx Ry Rz)
    double cg[3] = {0.0, 0.0, 0.0};      // a body's centre of gravity in its frame (its weight and buoyancy act there)
    double inertia[3] = {0.0, 0.0, 0.0}; // a body's moments of inertia about its centre of gravity, body axes [kg m2]
    double CdA[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};  // a body's drag areas in its axes: translations, rotations [m2]
    double Ca[3] = {0.0, 0.0, 0.0};      // a body's added-mass coefficients of translation in its axes (of rho V)
    // A pinned body (a CoupledPinned body, a pinned rod): its reference point held where `pin` is (on a coupled
    // body, on a free body: a node, or fixed), free to turn about it; its three unknowns its rotation. Its buoyancy acts at cb (its
    // centre of buoyancy in its frame; a free body's at its centre of gravity, as MoorDyn's).
    bool pinned = false;
    MooringEnd pin;
    double cb[3] = {0.0, 0.0, 0.0};
    double rodLength = 0.0;              // > 0: a free rod (docs/lines.md, "Rods") along the body's x axis, from
                                         // -rodLength/2 to rodLength/2: its buoyancy, drag and added mass follow
                                         // the part of it below z = 0
    std::vector<MooringRod> rods;        // the rods fixed to a free or pinned body (their loads apart from its own)
};

// A line failure (docs/line_failure.md): the ends of lines held at a deck point detach from it, at a time
// or when the tension of one of them there reaches a threshold, and go on a new massless free point.
struct MooringFailure {
    struct End {
        int line = 0;      // the system's line (0-based index into MooringDeck::lines)
        int end = 0;       // 0: its fairlead, 1: its far end
        int deckLine = 0;  // the deck's line (0-based)
    };
    int id = 0, row = 0;  // the FAILURE row's ID and line of the file (row 0: set by the failure.* parameters)
    int point = 0;        // the deck point (ID) the ends detach from
    std::vector<End> ends;
    double time = 0.0;     // [s] (0: not by time)
    double tension = 0.0;  // [N] (0: not by tension)
    double position = 0.0; // [m] > 0: a break along a line, this far from its anchor (point 0; MooringSystem)
};

struct MooringDeck {
    std::vector<MooringDeckLine> lines;  // in the order of their first deck line
    std::vector<MooringFailure> failures;  // the FAILURE rows, in their order
    std::vector<MooringNode> nodes;      // the free nodes, in the deck's order of points
    int deckLines = 0;                   // lines of the deck (line[k].* outputs: k in the deck's order)
    int bodies = 0;                      // coupled bodies 1 .. bodies are driven by the body[k].* inputs
    bool bodiesSection = false;          // false: the deck's Vessel points ride body 1
    bool nodesFromDeck = false;          // TmaxIC 0: the free nodes start at rest at their deck positions
    double waterDepth = 0.0, gravity = 0.0, waterDensity = 0.0;
    int waterDepthRow = 0, gravityRow = 0, waterDensityRow = 0;
    LineFileSeabed seabed;
    LineFileSea sea;
    std::vector<std::string> notes;
};

// deck_environment_notes for a mooring system (each line's seabed contact from its far-end section's Diam).
std::vector<std::string> mooring_environment_notes(const MooringDeck& deck, const UCParams& importer);

// True when the text is a deck (LINES and POINTS readable) with several lines, a point on a body or a
// BODIES row: a mooring system, not one line. Decks it is false for are read by read_line_file.
bool is_mooring_system_deck(std::string_view text);

// Reads a mooring system's deck: elementsPerLine is lineFileElements (0: each line's from its NumSegs;
// N > 0: N per line). False with error = "line <n>: <what>" when the deck is outside what a system holds.
bool read_mooring_deck(std::string_view text, int elementsPerLine, MooringDeck& deck, std::string& error,
                       const LineFileCompanions& companions = {});

// The failure of deck lines (0-based) at deck point `point` (its ID; 0: the fairlead of the first line) into
// f.ends: each line's end held there, on a coupled body, a coupled point or a free node. False (error naming
// the line and the point) where a line's end there is an anchor, a joint between two deck lines or a free end.
bool resolve_failure(const MooringDeck& deck, int point, const std::vector<int>& deckLines, MooringFailure& f,
                     std::string& error);

// The parameters of line k (0-based) of the system: base with the line's properties, environment and
// far end (anchored at its Fixed point; driven, bottomEnd 3, where it ends on a coupled object).
bool mooring_line_params(const MooringDeck& deck, int k, const UCParams& base, UCParams& p, std::string& error);

}  // namespace uc
