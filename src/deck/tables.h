// tables.h - the tables of a MoorDyn v2 deck (options, line types, points, lines, bodies) as rows checked
// one by one, and the deck they make together: what the readers of one line (deck/one_line.cpp) and of
// a mooring system (deck/mooring_deck.cpp) share. Internal to deck/ (the public header is
// deck/line_file.h); the supported subset of the format is in docs/lines.md.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "deck/line_file.h"
#include "deck/tokenizer.h"

namespace uc {
namespace deck {

// ------------------------------------------------------------------------------------------- options (deck/options.cpp)
struct Options {
    double waterDepth = 0.0;  // MoorDyn's default: 0, then the depth of the deepest point
    double gravity = kMoorDynGravity;
    double waterDensity = kMoorDynWaterDensity;
    bool noInitialConditions = false;  // TmaxIC 0: MoorDyn generates no initial conditions
    std::pair<int, int> waveKin{0, 0}, currents{0, 0};  // MoorDyn's kinematics options: (value, line of the file)
    double dtWave = 0.25;  // [s] MoorDyn's resampling of an elevation record (WaveKin 3); its default 0.25 s
    int dtWaveRow = 0;
    int waterDepthRow = 0, gravityRow = 0, waterDensityRow = 0;
    LineFileSeabed seabed;  // MoorDyn's seabed (its defaults where the deck is silent)
};

// The OPTIONS rows: MoorDyn's environment, seabed and kinematics options read, the others noted as ignored.
bool read_options(const Section& section, Options& options, std::vector<std::string>& notes, std::string& error);

// ------------------------------------------------------------------------------------------- kinematics (deck/kinematics.cpp)
// The deck's kinematics options (WaveKin, Currents) into the FMU's sea state, reading the companion files
// they name, or the refusal naming the option and why.
bool read_sea(const Options& options, const LineFileCompanions& companions, LineFileSea& sea,
              std::vector<std::string>& notes, std::string& error);
// The SeafloorFile MoorDyn's option names (its grid: nx ny, the x values, the y values, then rows x y z):
// a grid that is a plane becomes the sloped seabed (seabed.plane ...), any other is refused naming how far
// it is from one. Nothing where the deck names no SeafloorFile.
bool read_seafloor(const LineFileCompanions& companions, LineFileSeabed& seabed, std::vector<std::string>& notes,
                   std::string& error);

// ------------------------------------------------------------------------------------------- line types (deck/line_types.cpp)
struct LineType {
    std::string name;
    double diameter, massPerLength, EA, BA, EI, Cd, Ca, CdAx, CaAx;
    double MBL;  // minimum breaking load [N]: the MBL column's, else MoorPy's default for its name (0: none)
    int row;
    // EA given as a file of strain-tension points (empty: the constant EA); EA is then the curve's
    // secant at its last point, as MoorDyn takes it.
    std::vector<double> curveStrain, curveTension;
    // The viscoelastic model (EA as EA_s|EA_d or EA_s|EA_Dc|EA_D_Lm, BA as BA_s|BA_d): the dynamic stiffness
    // (0: none), its slope in the mean load, the dynamic damping [N s]; EA is EA_s, BA is BA_s.
    double EAd = 0.0, EAslope = 0.0, BAd = 0.0;
    // The Syrope model (EA as SYROPE:<settings file>|EA_Dc|EA_D_Lm): the working curve's formula (0: none), k1,
    // k2; the curve is then the original working curve, EAd and EAslope EA_Dc and EA_D_Lm, EA its secant.
    int syropeForm = 0;
    double syropeK1 = 0.0, syropeK2 = 0.0;
    // Vortex-induced vibration (MoorDyn's Cl, cF, dF columns after CaAx): Cl 0, none; cF and dF default to
    // Thorsen's 0.18 and 0.08 as MoorDyn's.
    double Cl = 0.0, cF = 0.18, dF = 0.08;
};

// A LINE TYPES row: a constant EA or a tension-strain file (one of companions), BA or -zeta, EI; other
// axial, damping and bending models refused.
// columns: the table's line of column names; a column named MBL (after the ten of MoorDyn) is the
// minimum breaking load [N], which must be positive.
bool read_line_type(const Row& row, const Row& columns, const LineFileCompanions& companions, LineType& t,
                    std::string& error);
// The name of the tension-strain file a LINE TYPES row gives as its EA, or of its Syrope settings file (empty: none).
std::string_view tension_strain_file(const Row& row);
// MoorDyn's Syrope settings file: rows "value name" for OWC (the original working curve's file, relative to the
// deck), WCType (LINEAR, QUADRATIC, EXP), k1 and k2; false with what is wrong, naming the row or the field.
bool read_syrope_settings(std::string_view text, const std::string& name, std::string& owc, int& form, double& k1,
                          double& k2, std::string& what);

// ------------------------------------------------------------------------------ breaking load (deck/breaking_load.cpp)
// MoorPy's minimum breaking load of a line type named for its material (MoorProps_default.yaml: R4 studless
// and studlink chain, wire rope, polyester, nylon) at the nominal diameter its mass per length gives
// (d = sqrt(Mass/m / mass_d2)); 0 when the name names none of them. note: what the log says (formula,
// diameter, value), or why there is none.
double default_breaking_load(const LineType& t, std::string& note);

// ------------------------------------------------------------------------------------------- points (deck/points.cpp)
enum class PointKind { Fixed, Vessel, Free, Body };

struct Point {
    int id = 0;
    PointKind kind = PointKind::Free;
    int body = 0;  // Body: the deck's body ID (its position is relative to the body)
    double position[3] = {0.0, 0.0, 0.0};
    double mass = 0.0, volume = 0.0, CdA = 0.0, Ca = 0.0;
    int row = 0;
    std::vector<int> lines;  // indices of the lines attached
    int rod = 0;         // > 0: the end of rod `rod` (its ID) this point stands for (deck/rods.cpp), row its RODS row
    bool rigid = false;  // a Free zero-length rod whose two lines are clamped to it: a rigid joint
};

// A POINTS row; bodies: a mooring system's deck (points on bodies, Body<ID>, are read).
bool read_point(const Row& row, int expectedId, bool bodies, Point& p, std::vector<std::string>& notes,
                std::string& error);

// "Fixed", "Vessel", "Body" or "Free", for messages.
const char* kind_name(PointKind kind);

// A Free point's mass, volume, added mass (CA rho V) and drag area.
LineFilePoint point_body(const Point& p, double waterDensity);

// ------------------------------------------------------------------------------------------- lines (deck/lines.cpp)
struct Line {
    int id = 0;
    int type = 0;           // index into the line types
    int end[2] = {0, 0};    // point indices of AttachA, AttachB
    double length = 0.0;
    int numSegs = 0;
    int row = 0;
    int rod[2] = {0, 0};    // per end: the rod (its ID) whose end it is attached to, 0 for a point
    bool clamped[2] = {false, false};  // per end: on a rod with EI > 0: MoorDyn clamps the line's tangent to the rod's axis
    double tangent[2][3] = {};         // per end, where clamped: the line's direction away from the rod (unit)
    double syropeTmax0 = -1.0, syropeTmean0 = -1.0;  // its SYROPE IC row (a Syrope line's; -1: none)
};

// The SYROPE IC rows (Line(s) Tmax0 Tmean0) onto the lines; notes for rows of lines without the model.
bool read_syrope_ic(const std::vector<Row>& rows, const std::vector<LineType>& types, std::vector<Line>& lines,
                    std::vector<std::string>& notes, std::string& error);

struct Rod;

// A point ID as AttachA/AttachB (and FAILURE's Point) spell it ("3", "P3", "Point3", "C3", "Con3") into its
// index among the nPoints points; a rod end ("R1A", "Rod2B") into the point that stands for it (rods:
// the deck's rods, read by read_rod; nullptr: rod ends refused), *rodEnd = 2 (ID - 1) + (0 for A, 1 for B).
bool read_attachment(Fields& f, std::string_view word, const char* column, int nPoints, int& index,
                     const std::vector<Rod>* rods = nullptr, int* rodEnd = nullptr);

// A LINES row: its line type among `types`, its ends among the nPoints points of the deck or the rods' ends.
bool read_line(const Row& row, int expectedId, const std::vector<LineType>& types, int nPoints, Line& l,
               std::string& error, const std::vector<Rod>* rods = nullptr);

// One MoorDyn line as a section of ours, in our conventions.
LineFileSection section_of(const Line& l, const LineType& t);

// ------------------------------------------------------------------------------------------- failures (deck/failures.cpp)
// A FAILURE row as MoorDyn-F writes it: ID Point Line(s) FailTime FailTen (docs/line_failure.md).
struct Failure {
    int id = 0;
    int point = 0;            // index of the point the lines detach from
    std::vector<int> lines;   // indices of the lines that detach there
    double time = 0.0;        // FailTime [s] (0: not by time)
    double tension = 0.0;     // FailTen [N] (0: not by tension)
    int row = 0;
};

// A FAILURE row: its point among the deck's points, its lines (comma-separated IDs) among nLines, each
// attached to the point, FailTime and FailTen not negative and not both 0.
bool read_failure(const Row& row, int expectedId, const std::vector<Point>& points, const std::vector<Line>& lines,
                  Failure& f, std::string& error);

// ------------------------------------------------------------------------------------------- bodies (deck/bodies.cpp)
// Pinned: MoorDyn's CoupledPinned body (its reference point held by the body[k] inputs, free to turn about it),
// or a pinned rod (Body<k>Pinned: its end A held by coupled body k, free to turn about it).
enum class BodyKind { Coupled, Fixed, Free, Pinned };

struct DeckBody {
    int id = 0;
    BodyKind kind = BodyKind::Coupled;
    double pose[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};  // X0 Y0 Z0 [m], r0 p0 y0 [rad]
    double mass = 0.0, volume = 0.0, cg[3] = {0.0, 0.0, 0.0};  // a Free body's
    double inertia[3] = {0.0, 0.0, 0.0};
    double CdA[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};  // body axes: translations x, y, z, rotations about them
    double Ca[3] = {0.0, 0.0, 0.0};                  // translations in body axes
    double rodLength = 0.0;                          // a free rod's body: its length along the body's x axis
    // A Pinned body: the coupled body that holds its reference point (its own ID for a CoupledPinned body) and
    // where, in that body's frame; its centre of buoyancy in its frame (a Free body's is its centre of gravity).
    int pinBody = 0;
    double pinAt[3] = {0.0, 0.0, 0.0};
    double cb[3] = {0.0, 0.0, 0.0};
    std::vector<MooringRod> rods;  // rods fixed to a Free body, a pinned rod: loads from their part under water
    int row = 0;
};

// MoorDyn's BODIES row: ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca* (angles in degrees).
bool read_body(const Row& row, int expectedId, DeckBody& b, std::vector<std::string>& notes, std::string& error);

// ------------------------------------------------------------------------------------------- rods (deck/rods.cpp)
struct RodType {
    std::string name;
    double diameter = 0.0, massPerLength = 0.0, Cd = 0.0, Ca = 0.0, CdEnd = 0.0, CaEnd = 0.0;
    int row = 0;
};

// A ROD TYPES row: TypeName Diam Mass/m Cd Ca CdEnd CaEnd.
bool read_rod_type(const Row& row, RodType& t, std::string& error);

enum class RodKind { Fixed, Coupled, Free, Body, Pinned };  // Pinned: Body<k>Pinned

// A RODS row (docs/lines.md, "Rods"): a rigid cylinder from end A to end B; NumSegs 0 is MoorDyn's
// zero-length rod at A, whose B coordinates are its direction.
struct Rod {
    int id = 0, type = 0, row = 0, numSegs = 0;
    RodKind kind = RodKind::Fixed;
    int body = 0;                   // Body: the deck's body ID (its ends in the body's frame)
    double a[3] = {}, b[3] = {};    // its ends (zero length: b = a)
    double axis[3] = {};            // unit vector from A to B (zero length: the direction given)
    double length = 0.0;
    int point[2] = {-1, -1};        // the points (indices) that stand for its ends A and B (the same one at zero length)
    int freeBody = 0;               // a Free rod of non-zero length (a Pinned rod): the ID of the free (pinned) body it becomes
};

// A RODS row: ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs. Pinned rods (Pinned,
// CoupledPinned, Body<k>Pinned) are refused: a rod free in rotation about a held end has no counterpart.
bool read_rod(const Row& row, int expectedId, const std::vector<RodType>& types, Rod& r, std::string& error);

// The points that stand for the rods' ends, appended to `points` (IDs after the deck's). firstBody: the ID of the free body the first Free rod of non-zero length
// becomes. system: a mooring system's deck (rods on bodies and free rods of non-zero length are read).
bool rods_as_points(std::vector<Rod>& rods, int firstBody, bool system, std::vector<Point>& points,
                    std::string& error);

// After the lines are read: the rods' ends that hold no line dropped from the points (the others renumbered),
// what each rod became noted, which line ends are clamped to a rod (a line type with EI > 0) and in which
// direction, and which Free zero-length rods are rigid joints.
void clamp_lines_to_rods(std::vector<Rod>& rods, const std::vector<RodType>& rodTypes,
                         const std::vector<LineType>& types, std::vector<Point>& points, std::vector<Line>& lines,
                         std::vector<std::string>& notes);


// ------------------------------------------------------------------------------------------- the deck (deck/tables.cpp)
// The tables of a deck, checked row by row, and its environment (MoorDyn's defaults, its water depth
// raised to the deepest point). system: a mooring system's deck (BODIES rows and points on bodies are
// read); otherwise they are refused as outside one line.
struct Deck {
    std::vector<LineType> types;
    std::vector<Point> points;
    std::vector<Line> lines;
    std::vector<Row> bodies;  // the BODIES rows (system only)
    std::vector<Failure> failures;  // the FAILURE rows (system only)
    std::vector<RodType> rodTypes;
    std::vector<Rod> rods;          // the RODS rows; their ends are points after the deck's (rods_as_points)
    int deckPoints = 0;             // the POINTS table's rows (the points after them stand for rod ends)
    int bodiesHeader = 0;
    double waterDepth = 0.0, gravity = 0.0, waterDensity = 0.0;
    int waterDepthRow = 0, gravityRow = 0, waterDensityRow = 0;
    bool noInitialConditions = false;
    LineFileSeabed seabed;
    LineFileSea sea;
};

// Free rods of non-zero length as free bodies (appended to `bodies`, IDs as rods_as_points gave them), rods of
// non-zero length on a Free body added to it (mass, volume, inertia, drag, added mass along its axes); rods on
// Coupled bodies noted as ignored. Refused, naming the rod: a rod through or above the waterline, a rod on a
// free body off the body's axes or away from its reference point and centre of gravity.
bool rods_into_bodies(const Deck& deck, std::vector<DeckBody>& bodies, std::vector<std::string>& notes,
                      std::string& error);

// A warning for each line end MoorDyn clamps to a rod that the FMU holds pinned: every clamped end but those
// in `held` (line index, end: the clamps the reader represented, a tow point's topEnd 1) and those at a rigid
// joint or at a free zero-length rod whose other line is not clamped (pinned there in MoorDyn too).
void note_pinned_clamps(const Deck& deck, const std::vector<std::pair<int, int>>& held, std::vector<std::string>& notes);

bool parse_deck(std::string_view text, bool system, const LineFileCompanions& companions, Deck& deck,
                std::vector<std::string>& notes, std::string& error);

}  // namespace deck
}  // namespace uc
