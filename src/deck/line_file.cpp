// line_file.cpp - the reader of MoorDyn v2 input files (docs/lines.md): rows of the text by section,
// then the tables (options, line types, points, lines) checked row by row, then the chain of lines from
// the vessel point to the far end, converted into our conventions.
#include "deck/line_file.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <optional>

namespace uc {
namespace {

// ------------------------------------------------------------------------------------------- text
struct Row {
    int number = 0;                        // 1-based line of the file
    std::vector<std::string_view> tokens;  // up to the first token holding '#', MoorDyn's comment mark
};

std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    size_t begin = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\n' && text[i] != '\r') continue;
        lines.push_back(text.substr(begin, i - begin));
        if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
        begin = i + 1;
    }
    if (begin < text.size()) lines.push_back(text.substr(begin));
    return lines;
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

std::vector<std::string_view> tokenize(std::string_view line) {
    std::vector<std::string_view> tokens;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_blank(line[i])) ++i;
        const size_t begin = i;
        while (i < line.size() && !is_blank(line[i])) ++i;
        if (i == begin) break;
        const std::string_view token = line.substr(begin, i - begin);
        if (token.find('#') != std::string_view::npos) break;
        tokens.push_back(token);
    }
    return tokens;
}

std::string upper(std::string_view s) {
    std::string u(s);
    for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return u;
}

std::string lower(std::string_view s) {
    std::string u(s);
    for (char& c : u) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return u;
}

// A token as it may appear in a message: printable, and short.
std::string quoted(std::string_view token) {
    std::string q = "'";
    for (size_t i = 0; i < token.size() && i < 40; ++i) {
        const unsigned char c = static_cast<unsigned char>(token[i]);
        q += std::isprint(c) ? static_cast<char>(c) : '?';
    }
    if (token.size() > 40) q += "...";
    return q + "'";
}

// A number as the deck spells it (for messages).
std::string shown(std::string_view token) {
    const std::string q = quoted(token);
    return q.substr(1, q.size() - 2);
}

std::string at_line(int row, const std::string& what) { return "line " + std::to_string(row) + ": " + what; }

std::string number_text(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

// A finite number, the whole token (locale-independent, unlike strtod).
std::optional<double> to_number(std::string_view token) {
    if (!token.empty() && token[0] == '+') token.remove_prefix(1);
    double v = 0.0;
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, v);
    if (ec != std::errc() || ptr != end || !std::isfinite(v)) return std::nullopt;
    return v;
}

// ------------------------------------------------------------------------------------------- sections
enum class Kind { Options, LineTypes, RodTypes, Bodies, Rods, Points, Lines, Failure, Control, ExternalLoads,
                  SyropeIC, Outputs, Other };

struct SectionName {
    Kind kind;
    const char* keyword;  // as MoorDyn finds it: in the upper-cased header line
};

// The header words MoorDyn v2 recognizes, more specific first ("LINE TYPES" before "LINES").
constexpr SectionName kSectionNames[] = {
    {Kind::LineTypes, "LINE TYPES"}, {Kind::LineTypes, "LINE DICTIONARY"},
    {Kind::RodTypes, "ROD TYPES"}, {Kind::RodTypes, "ROD DICTIONARY"},
    {Kind::Bodies, "BODIES"}, {Kind::Bodies, "BODY LIST"}, {Kind::Bodies, "BODY PROPERTIES"},
    {Kind::Rods, "RODS"}, {Kind::Rods, "ROD LIST"}, {Kind::Rods, "ROD PROPERTIES"},
    {Kind::Points, "POINTS"}, {Kind::Points, "POINT LIST"}, {Kind::Points, "POINT PROPERTIES"},
    {Kind::Points, "CONNECTION PROPERTIES"}, {Kind::Points, "NODE PROPERTIES"},
    {Kind::Lines, "LINES"}, {Kind::Lines, "LINE LIST"}, {Kind::Lines, "LINE PROPERTIES"},
    {Kind::Options, "OPTIONS"}, {Kind::Failure, "FAILURE"}, {Kind::Control, "CONTROL"},
    {Kind::ExternalLoads, "EXTERNAL LOADS"}, {Kind::SyropeIC, "SYROPE IC"}, {Kind::Outputs, "OUTPUT"},
};

const char* title(Kind kind) {
    switch (kind) {
        case Kind::Options: return "OPTIONS";
        case Kind::LineTypes: return "LINE TYPES";
        case Kind::RodTypes: return "ROD TYPES";
        case Kind::Bodies: return "BODIES";
        case Kind::Rods: return "RODS";
        case Kind::Points: return "POINTS";
        case Kind::Lines: return "LINES";
        case Kind::Failure: return "FAILURE";
        case Kind::Control: return "CONTROL";
        case Kind::ExternalLoads: return "EXTERNAL LOADS";
        case Kind::SyropeIC: return "SYROPE IC";
        case Kind::Outputs: return "OUTPUTS";
        default: return "?";
    }
}

// Sections whose rows describe objects outside the supported subset, and why.
const char* unsupported(Kind kind) {
    switch (kind) {
        case Kind::Bodies: return "bodies are not supported";
        case Kind::Rods: return "rods are not supported";
        case Kind::Failure: return "line failures are not supported";
        case Kind::Control: return "line length control is not supported";
        case Kind::ExternalLoads: return "external loads on points, rods and bodies are not supported";
        case Kind::SyropeIC: return "the Syrope model is not supported";
        default: return nullptr;
    }
}

Kind classify_header(std::string_view line) {
    const std::string u = upper(line);
    for (const SectionName& s : kSectionNames) {
        if (u.find(s.keyword) != std::string::npos) return s.kind;
    }
    return Kind::Other;
}

struct Section {
    int header = 0;  // line of its header
    std::vector<Row> rows;
};

// The rows of the text by section. A header is a line holding "---"; text outside the known sections
// (the front matter, blocks MoorDyn does not read) is skipped, as MoorDyn does. Tables have a line of
// column names and a line of units after the header; options and outputs do not.
bool collect_sections(std::string_view text, std::vector<std::optional<Section>>& sections, std::string& error) {
    sections.assign(static_cast<size_t>(Kind::Other) + 1, std::nullopt);
    const std::vector<std::string_view> lines = split_lines(text);
    Section* current = nullptr;
    Kind kind = Kind::Other;
    int headerLinesLeft = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
        const int number = static_cast<int>(i) + 1;
        if (lines[i].find("---") != std::string_view::npos) {
            if (current && headerLinesLeft > 0) {
                error = at_line(current->header, std::string("the ") + title(kind) +
                                                     " table needs a line of column names and a line of units");
                return false;
            }
            kind = classify_header(lines[i]);
            current = nullptr;
            if (kind == Kind::Other) continue;
            auto& slot = sections[static_cast<size_t>(kind)];
            if (slot) {
                error = at_line(number, std::string("a second ") + title(kind) + " section (the first is at line " +
                                            std::to_string(slot->header) + ")");
                return false;
            }
            slot = Section{number, {}};
            current = &*slot;
            headerLinesLeft = (kind == Kind::Options || kind == Kind::Outputs) ? 0 : 2;
            continue;
        }
        if (current == nullptr) continue;
        if (headerLinesLeft > 0) {
            --headerLinesLeft;
            continue;
        }
        Row row{number, tokenize(lines[i])};
        if (row.tokens.empty()) continue;
        if (kind == Kind::Outputs && upper(row.tokens[0]) == "END") {
            current = nullptr;  // MoorDyn stops reading outputs at END
            continue;
        }
        current->rows.push_back(std::move(row));
    }
    if (current && headerLinesLeft > 0) {
        error = at_line(current->header,
                        std::string("the ") + title(kind) + " table needs a line of column names and a line of units");
        return false;
    }
    return true;
}

// ------------------------------------------------------------------------------------------- fields
// Reads the fields of one row; the first failure is kept with its line and column name.
class Fields {
public:
    Fields(const Row& row, std::string& error) : row_(row), error_(error) {}

    bool ok() const { return ok_; }
    bool fail(const std::string& what) {
        if (ok_) error_ = at_line(row_.number, what);
        ok_ = false;
        return false;
    }
    std::string_view token(size_t i) const { return i < row_.tokens.size() ? row_.tokens[i] : std::string_view(); }

    // A finite number in [lo, hi] (bounds in the message as the column's rule).
    double number(size_t i, const char* column, double lo = -HUGE_VAL, double hi = HUGE_VAL, const char* rule = nullptr) {
        if (!ok_) return 0.0;
        const std::optional<double> v = to_number(token(i));
        if (!v) {
            fail(std::string(column) + " " + quoted(token(i)) + " is not a number");
            return 0.0;
        }
        if (*v < lo || *v > hi) {
            fail(std::string(column) + " = " + shown(token(i)) + ": " + (rule ? rule : "out of range"));
            return 0.0;
        }
        return *v;
    }
    double non_negative(size_t i, const char* column) { return number(i, column, 0.0, HUGE_VAL, "must not be negative"); }
    double positive(size_t i, const char* column) {
        const double v = number(i, column, 0.0, HUGE_VAL, "must be positive");
        if (ok_ && !(v > 0.0)) fail(std::string(column) + " = " + shown(token(i)) + ": must be positive");
        return v;
    }
    // A whole number in [lo, hi] ("20" or "20.0", as MoorDyn's atoi reads the former).
    int integer(size_t i, const char* column, int lo, int hi, const char* rule) {
        const double v = number(i, column);
        if (!ok_) return 0;
        if (v != std::floor(v)) {
            fail(std::string(column) + " " + quoted(token(i)) + " is not a whole number");
            return 0;
        }
        if (v < lo || v > hi) {
            fail(std::string(column) + " = " + shown(token(i)) + ": " + rule);
            return 0;
        }
        return static_cast<int>(v);
    }

private:
    const Row& row_;
    std::string& error_;
    bool ok_ = true;
};

// ------------------------------------------------------------------------------------------- tables
struct Options {
    double waterDepth = 0.0;  // MoorDyn's default: 0, then the depth of the deepest point
    double gravity = kMoorDynGravity;
    double waterDensity = kMoorDynWaterDensity;
    bool noInitialConditions = false;  // TmaxIC 0: MoorDyn generates no initial conditions
    std::pair<int, int> waveKin{0, 0}, currents{0, 0};  // MoorDyn's kinematics options: (value, line of the file)
    int waterDepthRow = 0, gravityRow = 0, waterDensityRow = 0;
    LineFileSeabed seabed;  // MoorDyn's seabed (its defaults where the deck is silent)
};

bool is_one_of(const std::string& name, std::initializer_list<const char*> names) {
    for (const char* n : names) {
        if (name == n) return true;
    }
    return false;
}

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
            return f.fail("SeafloorFile: a bathymetry file is not supported (the seabed is flat, at WtrDpth)");
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
        } else if (is_one_of(name, {"dtwave", "unifycurrentgrid"})) {
            notes.push_back(at_line(row.number, name_shown + " ignored, not applicable: it concerns MoorDyn's grids of wave and "
                                                        "current kinematics, which the FMU refuses (WaveKin, Currents)"));
        } else {
            notes.push_back(at_line(row.number, "unknown option " + quoted(row.tokens[1]) +
                                                    " ignored (MoorDyn ignores it too, with a warning)"));
        }
        if (!f.ok()) return false;
    }
    return true;
}

// ------------------------------------------------------------------------------------------- kinematics
// MoorDyn's WaveKin and Currents options (docs/lines.md, "Options and environment"): what the FMU's sea
// state holds is read into it, the rest refused naming the option, its value and why.
const char* kCurrentProfileFile = "current_profile.txt";
const char* kWaveFrequenciesFile = "wave_frequencies.txt";

const LineFileCompanion* companion(const LineFileCompanions& companions, const char* name) {
    for (const LineFileCompanion& c : companions) {
        if (c.name == name) return &c;
    }
    return nullptr;
}

// The rows of numbers of a companion file from its line `first` (1-based), blank lines skipped.
struct NumberRow {
    int number = 0;
    std::vector<double> values;
};

bool number_rows(const LineFileCompanion& file, int first, std::vector<NumberRow>& rows, std::string& what) {
    const std::vector<std::string_view> lines = split_lines(file.text);
    for (size_t i = static_cast<size_t>(first - 1); i < lines.size(); ++i) {
        NumberRow row{static_cast<int>(i) + 1, {}};
        for (std::string_view token : tokenize(lines[i])) {
            const std::optional<double> v = to_number(token);
            if (!v) {
                what = file.name + " line " + std::to_string(row.number) + ": " + quoted(token) + " is not a number";
                return false;
            }
            row.values.push_back(*v);
        }
        if (!row.values.empty()) rows.push_back(row);
    }
    return true;
}

// Drops the rows of a piecewise-linear profile (depth increasing) that the others give by MoorDyn's
// interpolation (linear between rows, constant beyond the ends) to round-off of the largest speed.
void drop_redundant_rows(std::vector<std::array<double, 3>>& rows) {
    double scale = 0.0;
    for (const auto& r : rows) scale = std::max({scale, std::abs(r[1]), std::abs(r[2])});
    const double tol = 1e-9 * std::max(scale, 1e-300);
    auto same = [&](const std::array<double, 3>& a, const std::array<double, 3>& b) {
        return std::abs(a[1] - b[1]) <= tol && std::abs(a[2] - b[2]) <= tol;
    };
    while (rows.size() > 1 && same(rows[rows.size() - 1], rows[rows.size() - 2])) rows.pop_back();
    while (rows.size() > 1 && same(rows[0], rows[1])) rows.erase(rows.begin());
    std::vector<std::array<double, 3>> kept{rows.front()};
    for (size_t i = 1; i + 1 < rows.size(); ++i) {
        // row i may go when every row from the last kept one to row i + 1 lies on their chord
        const auto& a = kept.back();
        const auto& b = rows[i + 1];
        bool onChord = true;
        for (size_t j = 0; j <= i && onChord; ++j) {
            const auto& r = rows[j];
            if (r[0] <= a[0]) continue;
            const double f = (r[0] - a[0]) / (b[0] - a[0]);
            std::array<double, 3> line{r[0], a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])};
            onChord = same(r, line);
        }
        if (!onChord) kept.push_back(rows[i]);
    }
    if (rows.size() > 1) kept.push_back(rows.back());
    rows = kept;
}

// Currents 1: MoorDyn's steady profile, rows "z ux [uy [uz]]" from the file's fourth line, z increasing,
// linear in z between rows and constant beyond; as the FMU's profile of depths -z.
bool read_current_profile(const LineFileCompanion& file, LineFileSea& sea, std::string& what) {
    std::vector<NumberRow> rows;
    if (!number_rows(file, 4, rows, what)) return false;
    if (rows.empty()) {
        what = file.name + " has no rows of the profile (\"z ux uy uz\" from its fourth line)";
        return false;
    }
    std::vector<std::array<double, 3>> profile;  // depth, ux, uy; depth increasing
    for (size_t i = 0; i < rows.size(); ++i) {
        const NumberRow& r = rows[i];
        const std::string at = file.name + " line " + std::to_string(r.number) + ": ";
        if (r.values.size() < 2 || r.values.size() > 4) {
            what = at + "a row is z ux [uy [uz]]";
            return false;
        }
        if (r.values.size() == 4 && r.values[3] != 0.0) {
            what = at + "uz = " + number_text(r.values[3]) + ": a vertical current is not supported (the FMU's "
                        "current is horizontal)";
            return false;
        }
        if (i > 0 && !(r.values[0] > rows[i - 1].values[0])) {
            what = at + "z = " + number_text(r.values[0]) + ": z must increase row by row (MoorDyn interpolates "
                        "between rows in that order)";
            return false;
        }
        profile.insert(profile.begin(), {-r.values[0], r.values[1], r.values.size() > 2 ? r.values[2] : 0.0});
    }
    const size_t given = profile.size();
    drop_redundant_rows(profile);
    if (profile.size() > UC_CURRENT_PROFILE_ROWS) {
        what = file.name + ": a profile of " + std::to_string(given) + " rows, " + std::to_string(profile.size()) +
               " of them off the straight lines between their neighbours: the FMU's current profile "
               "(currentProfile.*) holds " + std::to_string(UC_CURRENT_PROFILE_ROWS) + " rows";
        return false;
    }
    sea.profileRows = static_cast<int>(profile.size());
    for (size_t k = 0; k < profile.size(); ++k) {
        sea.profileDepth[k] = profile[k][0];
        sea.profileX[k] = profile[k][1];
        sea.profileY[k] = profile[k][2];
    }
    return true;
}

// WaveKin 7: MoorDyn sums the components "omega Re(A) Im(A) [direction]" of the file, each the elevation
// |A| sin(omega t - k x + arg A) (x along the direction); one component with arg A = pi/2 is the FMU's
// regular wave of amplitude |A|, a cos(k x - omega t), crest at the origin at t = 0.
bool read_wave_components(const LineFileCompanion& file, LineFileSea& sea, std::string& what) {
    std::vector<NumberRow> rows;
    if (!number_rows(file, 1, rows, what)) return false;
    std::vector<const NumberRow*> waves;
    for (const NumberRow& r : rows) {
        if (r.values.size() < 3 || r.values.size() > 4) {
            what = file.name + " line " + std::to_string(r.number) + ": a row is omega Re(A) Im(A) [direction]";
            return false;
        }
        if (r.values[1] != 0.0 || r.values[2] != 0.0) waves.push_back(&r);
    }
    if (waves.size() != 1) {
        what = file.name + " has " + std::to_string(waves.size()) + " components of non-zero amplitude: the FMU's "
               "waves are one regular wave (waves.mode 1) or a JONSWAP sea of its own components (waves.mode 2), "
               "not a given list of components";
        return false;
    }
    const NumberRow& w = *waves[0];
    const double omega = w.values[0], re = w.values[1], im = w.values[2], amplitude = std::hypot(re, im);
    const std::string at = file.name + " line " + std::to_string(w.number) + ": ";
    if (!(omega > 0.0)) {
        what = at + "a component of frequency " + number_text(omega) + " rad/s is not a wave";
        return false;
    }
    if (!(im > 0.0) || std::abs(re) > 1e-12 * amplitude) {
        what = at + "the component's phase arg A = " + number_text(std::atan2(im, re)) + " rad: the FMU's regular "
               "wave has its crest at the origin at t = 0 (arg A = pi/2, A = i |A|)";
        return false;
    }
    sea.regularWave = true;
    sea.waveHeight = 2.0 * amplitude;
    sea.wavePeriod = 2.0 * kPi / omega;
    sea.waveDirection = w.values.size() > 3 ? w.values[3] : 0.0;
    return true;
}

// The deck's kinematics options into the FMU's sea state, or the refusal naming the option and why.
bool read_sea(const Options& options, const LineFileCompanions& companions, LineFileSea& sea,
              std::vector<std::string>& notes, std::string& error) {
    const auto [waveKin, waveRow] = options.waveKin;
    const auto [currents, currentRow] = options.currents;
    auto refuse = [&](int row, const char* name, int value, const std::string& why) {
        error = at_line(row, std::string(name) + " = " + std::to_string(value) + ": " + why);
        return false;
    };
    auto file = [&](int row, const char* name, int value, const char* fileName, const LineFileCompanion*& out) {
        out = companion(companions, fileName);
        if (out) return true;
        return refuse(row, name, value, std::string("MoorDyn reads ") + fileName + " from the deck's directory: "
                                                    "it could not be read there");
    };
    const LineFileCompanion* text = nullptr;
    std::string what;
    switch (waveKin) {
        case 0: break;
        case 1:
            notes.push_back(at_line(waveRow, "WaveKin 1 (water kinematics set by the program driving MoorDyn): the "
                                             "water moves as the FMU's sea state, waves.* and current.*, set by the "
                                             "importer"));
            break;
        case 2:
            return refuse(waveRow, "WaveKin", waveKin, "waves from the spectrum of wave_frequencies.txt precomputed on "
                          "the grid of water_grid.txt are not supported: the FMU's waves are a regular wave (waves.mode "
                          "1) or a JONSWAP sea of its own components (waves.mode 2); WaveKin 7 with one component is "
                          "read as the regular wave");
        case 3:
            return refuse(waveRow, "WaveKin", waveKin, "waves from the elevation record wave_elevation.txt are not "
                          "supported: the FMU's waves are a regular wave (waves.mode 1) or a JONSWAP sea of its own "
                          "components (waves.mode 2)");
        case 4: case 5: case 6:
            return refuse(waveRow, "WaveKin", waveKin, "not implemented in MoorDyn v2 either");
        case 7:
            if (!file(waveRow, "WaveKin", waveKin, kWaveFrequenciesFile, text)) return false;
            if (!read_wave_components(*text, sea, what)) return refuse(waveRow, "WaveKin", waveKin, what);
            notes.push_back(at_line(waveRow, "WaveKin 7: the one component of wave_frequencies.txt is the regular "
                                             "wave waves.mode 1, height " + number_text(sea.waveHeight) + " m, period " +
                                             number_text(sea.wavePeriod) + " s, direction " +
                                             number_text(sea.waveDirection) + " rad, Wheeler stretching (in place of "
                                             "the parameters waves.*)"));
            break;
        default:
            return refuse(waveRow, "WaveKin", waveKin, "not a MoorDyn v2 option (0 to 7)");
    }
    switch (currents) {
        case 0: break;
        case 1:
            if (!file(currentRow, "Currents", currents, kCurrentProfileFile, text)) return false;
            if (!read_current_profile(*text, sea, what)) return refuse(currentRow, "Currents", currents, what);
            notes.push_back(at_line(currentRow, "Currents 1: the steady profile of current_profile.txt is the current "
                                                "profile currentProfile.* (" + std::to_string(sea.profileRows) +
                                                " rows, in place of the parameters'; added to the inputs current.x/y)"));
            break;
        case 2:
            return refuse(currentRow, "Currents", currents, "a current profile changing in time "
                          "(current_profile_dynamic.txt) is not supported: the FMU's profile is steady (Currents 1), "
                          "scaled in time only by the input currentScale");
        case 3: case 4:
            return refuse(currentRow, "Currents", currents, "not implemented in MoorDyn v2 either");
        case 5:
            return refuse(currentRow, "Currents", currents, "a current on a grid in x, y, z and time "
                          "(current_profile_4d.txt) is not supported: the FMU's current varies with depth only");
        default:
            return refuse(currentRow, "Currents", currents, "not a MoorDyn v2 option (0 to 5)");
    }
    return true;
}

struct LineType {
    std::string name;
    double diameter, massPerLength, EA, BA, EI, Cd, Ca, CdAx, CaAx;
    int row;
};

bool read_line_type(const Row& row, LineType& t, std::string& error) {
    Fields f(row, error);
    const size_t n = row.tokens.size();
    if (n != 10 && n != 11 && n != 13) {
        return f.fail("a line type has 10 fields (TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx), "
                      "optionally followed by Cl or by Cl dF cF; this row has " + std::to_string(n));
    }
    t.name = std::string(row.tokens[0]);
    t.row = row.number;
    t.diameter = f.positive(1, "Diam");
    t.massPerLength = f.positive(2, "Mass/m");
    const std::string_view ea = f.token(3), ba = f.token(4);
    if (ea.find('|') != std::string_view::npos || upper(ea).rfind("SYROPE:", 0) == 0) {
        return f.fail("EA " + quoted(ea) + ": viscoelastic and Syrope axial models are not supported (a constant EA)");
    }
    if (!to_number(ea)) return f.fail("EA " + quoted(ea) + ": a non-linear stiffness (table) is not supported (a constant EA)");
    t.EA = f.positive(3, "EA");
    if (ba.find('|') != std::string_view::npos) {
        return f.fail("BA/-zeta " + quoted(ba) + ": viscoelastic damping is not supported (one BA or -zeta)");
    }
    if (!to_number(ba)) {
        return f.fail("BA/-zeta " + quoted(ba) + ": a non-linear damping (table) is not supported (one BA or -zeta)");
    }
    t.BA = f.number(4, "BA/-zeta");
    if (!to_number(f.token(5))) {
        return f.fail("EI " + quoted(f.token(5)) + ": a non-linear bending stiffness (table) is not supported");
    }
    t.EI = f.non_negative(5, "EI");
    t.Cd = f.non_negative(6, "Cd");
    t.Ca = f.non_negative(7, "Ca");
    t.CdAx = f.non_negative(8, "CdAx");
    t.CaAx = f.non_negative(9, "CaAx");
    if (n > 10) {
        const double cl = f.number(10, "Cl");
        if (f.ok() && cl != 0.0) return f.fail("Cl = " + shown(f.token(10)) + ": vortex-induced vibration is not supported");
        if (n == 13) {
            f.number(11, "dF");
            f.number(12, "cF");
        }
    }
    return f.ok();
}

enum class PointKind { Fixed, Vessel, Free, Body };

struct Point {
    int id = 0;
    PointKind kind = PointKind::Free;
    int body = 0;  // Body: the deck's body ID (its position is relative to the body)
    double position[3] = {0.0, 0.0, 0.0};
    double mass = 0.0, volume = 0.0, CdA = 0.0, Ca = 0.0;
    int row = 0;
    std::vector<int> lines;  // indices of the lines attached
};

// The attachment word of a point: letters (case-insensitive), maybe followed by a number (Body2).
// The row's first field, its ID: 1, 2, 3, ... in the order of the section's rows (`what`: "point",
// "line", "body"). False (the error set) where it is not.
bool read_id(Fields& f, const char* what, int expectedId, int& id) {
    id = f.integer(0, "ID", 1, 1 << 30, "must be positive");
    if (f.ok() && id != expectedId) {
        return f.fail(std::string(what) + " ID " + std::to_string(id) + ": IDs must be 1, 2, 3, ... in order (expected " +
                      std::to_string(expectedId) + ")");
    }
    return f.ok();
}

bool read_point_kind(Fields& f, std::string_view word, bool bodies, PointKind& kind, int& body) {
    const std::string u = upper(word);
    size_t letters = 0;
    while (letters < u.size() && std::isalpha(static_cast<unsigned char>(u[letters]))) ++letters;
    const std::string head = u.substr(0, letters);
    if (is_one_of(head, {"ANCHOR", "FIXED", "FIX"})) {
        kind = PointKind::Fixed;
    } else if (is_one_of(head, {"FAIRLEAD", "VESSEL", "VES", "COUPLED", "CPLD"})) {
        kind = PointKind::Vessel;
    } else if (is_one_of(head, {"POINT", "CONNECT", "CON", "FREE"})) {
        kind = PointKind::Free;
    } else if (bodies && head == "BODY" && letters < u.size()) {
        const std::string digits = u.substr(letters);
        if (digits.size() > 8 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
            return f.fail("unknown point attachment " + quoted(word) + " (Body<ID>, Fixed, Vessel, Coupled or Free)");
        kind = PointKind::Body;
        body = std::stoi(digits);
    } else if (head == "BODY" || head == "TURBINE") {
        return f.fail("a point attached to " + quoted(word) + ": bodies are not supported (Fixed, Vessel, Coupled "
                      "or Free points only)");
    } else {
        return f.fail("unknown point attachment " + quoted(word) + " (Fixed, Vessel, Coupled or Free)");
    }
    return true;
}

bool read_point(const Row& row, int expectedId, bool bodies, Point& p, std::vector<std::string>& notes,
                std::string& error) {
    Fields f(row, error);
    const size_t n = row.tokens.size();
    if (n != 9 && n != 12) {
        return f.fail("a point has 9 fields (ID Attachment X Y Z Mass Volume CdA CA), or 12 with FX FY FZ after "
                      "Volume; this row has " + std::to_string(n));
    }
    if (!read_id(f, "point", expectedId, p.id) || !read_point_kind(f, row.tokens[1], bodies, p.kind, p.body))
        return false;
    static const char* const kAxes[] = {"X", "Y", "Z"};
    for (int k = 0; k < 3; ++k) p.position[k] = f.number(2 + k, kAxes[k]);
    p.mass = f.non_negative(5, "Mass");
    p.volume = f.non_negative(6, "Volume");
    const size_t c = n == 12 ? 10 : 7;
    if (n == 12) {
        const double force[3] = {f.number(7, "FX"), f.number(8, "FY"), f.number(9, "FZ")};
        if (f.ok() && (force[0] != 0.0 || force[1] != 0.0 || force[2] != 0.0)) {
            if (p.kind == PointKind::Free) return f.fail("a steady force on a Free point is not supported");
            notes.push_back(at_line(row.number, "FX FY FZ of a Fixed or Vessel point ignored (its motion is given)"));
        }
    }
    p.CdA = f.non_negative(c, "CdA");
    p.Ca = f.non_negative(c + 1, "CA");
    p.row = row.number;
    if (f.ok() && p.kind != PointKind::Free && (p.mass != 0.0 || p.volume != 0.0 || p.CdA != 0.0 || p.Ca != 0.0)) {
        notes.push_back(at_line(row.number, "Mass, Volume, CdA and CA of a Fixed or Vessel point ignored (its motion "
                                            "is given)"));
    }
    return f.ok();
}

struct Line {
    int id = 0;
    int type = 0;           // index into the line types
    int end[2] = {0, 0};    // point indices of AttachA, AttachB
    double length = 0.0;
    int numSegs = 0;
    int row = 0;
};

// AttachA/AttachB: a point ID ("3", "P3", "Point3", "C3", "Con3"); rod ends ("R1A") are not supported.
bool read_attachment(Fields& f, std::string_view word, const char* column, int nPoints, int& index) {
    const std::string u = upper(word);
    size_t letters = 0;
    while (letters < u.size() && std::isalpha(static_cast<unsigned char>(u[letters]))) ++letters;
    const std::string head = u.substr(0, letters), digits = u.substr(letters);
    if (is_one_of(head, {"R", "ROD"})) {
        return f.fail(std::string(column) + " " + quoted(word) + ": rods are not supported (lines join points)");
    }
    const bool numeric = !digits.empty() && digits.size() < 9 &&
                         std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!is_one_of(head, {"", "P", "POINT", "C", "CON"}) || !numeric) {
        return f.fail(std::string(column) + " " + quoted(word) + " is not a point ID");
    }
    const int id = std::stoi(digits);
    if (id < 1 || id > nPoints) {
        return f.fail(std::string(column) + " " + quoted(word) + ": there is no point " + std::to_string(id) +
                      " (the POINTS table has " + std::to_string(nPoints) + ")");
    }
    index = id - 1;
    return true;
}

bool read_line(const Row& row, int expectedId, const std::vector<LineType>& types, int nPoints, Line& l,
               std::string& error) {
    Fields f(row, error);
    if (row.tokens.size() < 6) {
        return f.fail("a line has the fields ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs; this row has " +
                      std::to_string(row.tokens.size()));
    }
    if (!read_id(f, "line", expectedId, l.id)) return false;
    l.type = -1;
    for (size_t k = 0; k < types.size(); ++k) {
        if (types[k].name == row.tokens[1]) l.type = static_cast<int>(k);
    }
    if (l.type < 0) {
        std::string known;
        for (const LineType& t : types) known += (known.empty() ? "" : ", ") + quoted(t.name);
        return f.fail("line type " + quoted(row.tokens[1]) + " is not among the LINE TYPES (" + known + ")");
    }
    if (!read_attachment(f, row.tokens[2], "AttachA", nPoints, l.end[0]) ||
        !read_attachment(f, row.tokens[3], "AttachB", nPoints, l.end[1])) {
        return false;
    }
    if (l.end[0] == l.end[1]) return f.fail("AttachA and AttachB are the same point");
    l.length = f.positive(4, "UnstrLen");
    l.numSegs = f.integer(5, "NumSegs", 1, 100000, "must be between 1 and 100000");
    l.row = row.number;
    return f.ok();
}

// ------------------------------------------------------------------------------------------- the chain
const char* kind_name(PointKind kind) {
    switch (kind) {
        case PointKind::Fixed: return "Fixed";
        case PointKind::Vessel: return "Vessel";
        case PointKind::Body: return "Body";
        default: return "Free";
    }
}

// The lines in order from the vessel point: (line index, reversed) pairs, and the far-end point. A deck
// without a Vessel or Coupled point starts at a Fixed point (towFixed): the higher of two (on a tie, the
// one at AttachB of its line, MoorDyn's fairlead end), the other the anchor; or the one, the line hanging
// from it to a Free end.
bool walk_chain(const std::vector<Point>& points, const std::vector<Line>& lines,
                std::vector<std::pair<int, bool>>& chain, int& farPoint, bool& towFixed, std::string& error) {
    int vessel = -1;
    std::vector<int> fixed;
    auto refuse = [&](int q, int first, const char* which, const char* rule) {
        error = at_line(points[q].row, std::string("a ") + which + " " + kind_name(points[q].kind) + " point (the first is point " +
                                           std::to_string(points[first].id) + "): " + rule);
        return false;
    };
    const char* oneLine = "one line from one vessel point to one anchor is supported";
    for (size_t i = 0; i < points.size(); ++i) {
        const Point& p = points[i];
        if (p.kind == PointKind::Vessel) {
            if (vessel >= 0) return refuse(static_cast<int>(i), vessel, "second", oneLine);
            vessel = static_cast<int>(i);
        } else if (p.kind == PointKind::Fixed) {
            if (vessel >= 0 && !fixed.empty()) return refuse(static_cast<int>(i), fixed[0], "second", oneLine);
            fixed.push_back(static_cast<int>(i));
        }
    }
    if (vessel >= 0 && fixed.size() > 1) return refuse(fixed[1], fixed[0], "second", oneLine);
    if (fixed.size() > 2) {
        return refuse(fixed[2], fixed[0], "third", "without a Vessel or Coupled point one line between two Fixed "
                                                   "points is supported");
    }
    towFixed = vessel < 0;
    if (towFixed) {
        if (fixed.empty()) {
            error = "the POINTS table has no Vessel, Coupled or Fixed point: the tow point, where the line starts";
            return false;
        }
        auto at_attach_b = [&](int q) {
            return !points[q].lines.empty() && lines[points[q].lines[0]].end[1] == q;
        };
        vessel = fixed[0];
        if (fixed.size() == 2) {
            const double z0 = points[fixed[0]].position[2], z1 = points[fixed[1]].position[2];
            if (z1 > z0 || (z1 == z0 && at_attach_b(fixed[1]) && !at_attach_b(fixed[0]))) vessel = fixed[1];
        }
        fixed.erase(std::find(fixed.begin(), fixed.end(), vessel));
    }
    const int fixedPoint = fixed.empty() ? -1 : fixed[0];
    for (const Point& p : points) {
        if (p.lines.empty()) {
            error = at_line(p.row, "point " + std::to_string(p.id) + " is not attached to any line");
            return false;
        }
        if (p.lines.size() > 2 || (p.kind != PointKind::Free && p.lines.size() > 1)) {
            error = at_line(p.row, std::string(kind_name(p.kind)) + " point " + std::to_string(p.id) + " joins " +
                                       std::to_string(p.lines.size()) + " lines: several lines or chains at a point "
                                       "are not supported (one chain of lines, the vessel and the anchor at its ends)");
            return false;
        }
    }
    std::vector<bool> used(lines.size(), false);
    int point = vessel, line = points[vessel].lines[0];
    while (true) {
        const Line& l = lines[line];
        const bool reversed = l.end[1] == point;  // the line runs from AttachB at the tow side
        chain.emplace_back(line, reversed);
        used[line] = true;
        point = l.end[reversed ? 0 : 1];
        const Point& p = points[point];
        if (p.lines.size() == 1) break;
        line = p.lines[0] == line ? p.lines[1] : p.lines[0];
        if (used[line]) break;  // a closed loop: reported below as a line off the chain
    }
    farPoint = point;
    for (size_t k = 0; k < lines.size(); ++k) {
        if (!used[k]) {
            error = at_line(lines[k].row, "line " + std::to_string(lines[k].id) + " is not on the chain of lines "
                                          "from the vessel point to its far end (one chain only)");
            return false;
        }
    }
    if (points[farPoint].lines.size() != 1) {
        error = at_line(points[farPoint].row, "the lines form a closed loop");
        return false;
    }
    if (fixedPoint >= 0 && fixedPoint != farPoint) {
        error = at_line(points[fixedPoint].row, "the Fixed point " + std::to_string(points[fixedPoint].id) +
                                                    " is not the far end of the chain");
        return false;
    }
    return true;
}

// Our elements for each line: the rule per line, or `total` shared in proportion to the lengths.
void assign_elements(std::vector<LineFileSection>& sections, int total) {
    double length = 0.0;
    for (const LineFileSection& s : sections) length += s.length;
    for (LineFileSection& s : sections) {
        s.elements = total > 0 ? std::max(1, static_cast<int>(std::lround(total * s.length / length)))
                               : elements_for_segments(s.numSegs);
    }
}


// The tables of a deck, checked row by row, and its environment (MoorDyn's defaults, its water depth
// raised to the deepest point). system: a mooring system's deck (BODIES rows and points on bodies are
// read); otherwise they are refused as outside one line.
struct Deck {
    std::vector<LineType> types;
    std::vector<Point> points;
    std::vector<Line> lines;
    std::vector<Row> bodies;  // the BODIES rows (system only)
    int bodiesHeader = 0;
    double waterDepth = 0.0, gravity = 0.0, waterDensity = 0.0;
    int waterDepthRow = 0, gravityRow = 0, waterDensityRow = 0;
    bool noInitialConditions = false;
    LineFileSeabed seabed;
    LineFileSea sea;
};

bool parse_deck(std::string_view text, bool system, const LineFileCompanions& companions, Deck& deck,
                std::vector<std::string>& notes, std::string& error) {
    std::vector<std::optional<Section>> sections;
    if (!collect_sections(text, sections, error)) return false;
    auto section = [&](Kind kind) -> const std::optional<Section>& { return sections[static_cast<size_t>(kind)]; };

    for (Kind kind : {Kind::Bodies, Kind::Rods, Kind::Failure, Kind::Control, Kind::ExternalLoads, Kind::SyropeIC}) {
        if (system && kind == Kind::Bodies) continue;
        if (section(kind) && !section(kind)->rows.empty()) {
            error = at_line(section(kind)->rows[0].number, std::string(unsupported(kind)) + " (" + title(kind) +
                                                                " section)");
            return false;
        }
    }
    if (section(Kind::Bodies)) {
        deck.bodies = section(Kind::Bodies)->rows;
        deck.bodiesHeader = section(Kind::Bodies)->header;
    }
    if (section(Kind::RodTypes) && !section(Kind::RodTypes)->rows.empty()) {
        notes.push_back(at_line(section(Kind::RodTypes)->header, "ROD TYPES ignored (there are no rods)"));
    }
    if (section(Kind::Outputs) && !section(Kind::Outputs)->rows.empty()) {
        notes.push_back(at_line(section(Kind::Outputs)->header, "OUTPUTS ignored: the FMU's outputs are its "
                                                                "variables (towForce, tension[k], shape.*, ...)"));
    }
    for (Kind kind : {Kind::LineTypes, Kind::Points, Kind::Lines}) {
        if (!section(kind)) {
            error = std::string("the deck has no ") + title(kind) + " section (a header line such as ---- " +
                    title(kind) + " ----)";
            return false;
        }
        if (section(kind)->rows.empty()) {
            error = at_line(section(kind)->header, std::string("the ") + title(kind) + " table is empty");
            return false;
        }
    }

    Options options;
    if (section(Kind::Options) && !read_options(*section(Kind::Options), options, notes, error)) return false;
    if (!read_sea(options, companions, deck.sea, notes, error)) return false;

    std::vector<LineType>& types = deck.types;
    for (const Row& row : section(Kind::LineTypes)->rows) {
        LineType t{};
        if (!read_line_type(row, t, error)) return false;
        for (const LineType& other : types) {
            if (other.name == t.name) {
                error = at_line(row.number, "line type " + quoted(t.name) + " is defined twice (also at line " +
                                                std::to_string(other.row) + ")");
                return false;
            }
        }
        types.push_back(t);
    }

    std::vector<Point>& points = deck.points;
    for (const Row& row : section(Kind::Points)->rows) {
        Point p;
        if (!read_point(row, static_cast<int>(points.size()) + 1, system, p, notes, error)) return false;
        points.push_back(p);
    }

    std::vector<Line>& lines = deck.lines;
    for (const Row& row : section(Kind::Lines)->rows) {
        Line l;
        if (!read_line(row, static_cast<int>(lines.size()) + 1, types, static_cast<int>(points.size()), l, error)) {
            return false;
        }
        for (int e : l.end) points[e].lines.push_back(static_cast<int>(lines.size()));
        lines.push_back(l);
    }

    deck.gravity = options.gravity;
    deck.waterDensity = options.waterDensity;
    deck.noInitialConditions = options.noInitialConditions;
    deck.waterDepth = options.waterDepth;
    deck.waterDepthRow = options.waterDepthRow;
    deck.gravityRow = options.gravityRow;
    deck.waterDensityRow = options.waterDensityRow;
    deck.seabed = options.seabed;
    for (const Point& p : points) {
        if (p.kind != PointKind::Body && -p.position[2] > deck.waterDepth) {
            if (options.waterDepth > 0.0) {
                notes.push_back(at_line(p.row, "point " + std::to_string(p.id) + " lies below WtrDpth: the water "
                                               "depth is set to its depth, " + number_text(-p.position[2]) +
                                               " m (as MoorDyn does)"));
            }
            deck.waterDepth = -p.position[2];
        }
    }
    return true;
}

// A Free point's mass, volume, added mass (CA rho V) and drag area.
LineFilePoint point_body(const Point& p, double waterDensity) {
    LineFilePoint q;
    q.id = p.id;
    q.mass = p.mass;
    q.volume = p.volume;
    q.addedMass = p.Ca * waterDensity * p.volume;
    q.CdA = p.CdA;
    q.row = p.row;
    return q;
}

// One MoorDyn line as a section of ours, in our conventions.
LineFileSection section_of(const Line& l, const LineType& t) {
    LineFileSection s;
    s.type = t.name;
    s.length = l.length;
    s.diameter = t.diameter;
    s.massPerLength = t.massPerLength;
    s.EA = t.EA;
    s.EI = t.EI;
    // BA/-zeta < 0: a fraction of critical damping of one MoorDyn segment, converted as MoorDyn does,
    // BA = zeta (UnstrLen / NumSegs) sqrt(EA Mass/m) (docs/lines.md).
    s.axialDamping = t.BA >= 0.0 ? t.BA : -t.BA * (l.length / l.numSegs) * std::sqrt(t.EA * t.massPerLength);
    s.Cdn = t.Cd;
    s.Cdt = t.CdAx;
    s.Can = t.Ca;
    s.Cat = t.CaAx;
    s.numSegs = l.numSegs;
    s.row = l.row;
    return s;
}

}  // namespace

int elements_for_segments(int numSegs) { return std::max(1, (numSegs + 1) / 2); }

std::vector<std::string> line_file_companions(std::string_view text) {
    std::vector<std::optional<Section>> sections;
    std::string error;
    std::vector<std::string> names, notes;
    Options options;
    if (!collect_sections(text, sections, error)) return names;
    const auto& o = sections[static_cast<size_t>(Kind::Options)];
    if (!o || !read_options(*o, options, notes, error)) return names;
    if (options.waveKin.first == 7) names.push_back(kWaveFrequenciesFile);
    if (options.currents.first == 1) names.push_back(kCurrentProfileFile);
    return names;
}

bool read_line_file(std::string_view text, int elementsTotal, LineFileLine& out, std::string& error,
                    const LineFileCompanions& companions) {
    out = LineFileLine();
    Deck deck;
    if (!parse_deck(text, false, companions, deck, out.notes, error)) return false;
    const std::vector<LineType>& types = deck.types;
    const std::vector<Point>& points = deck.points;
    const std::vector<Line>& lines = deck.lines;

    std::vector<std::pair<int, bool>> chain;
    int farPoint = -1;
    if (!walk_chain(points, lines, chain, farPoint, out.towFixed, error)) return false;

    out.gravity = deck.gravity;
    out.waterDensity = deck.waterDensity;
    out.waterDepth = deck.waterDepth;
    out.waterDepthRow = deck.waterDepthRow;
    out.gravityRow = deck.gravityRow;
    out.waterDensityRow = deck.waterDensityRow;
    out.seabed = deck.seabed;
    out.sea = deck.sea;

    for (const auto& [index, reversed] : chain) {
        const Line& l = lines[index];
        out.sections.push_back(section_of(l, types[l.type]));
        (void)reversed;  // a line is uniform: its orientation in the file does not matter
    }
    assign_elements(out.sections, elementsTotal);

    auto free_point = [&](const Point& p) { return point_body(p, out.waterDensity); };
    for (size_t k = 0; k + 1 < chain.size(); ++k) {
        const Line& l = lines[chain[k].first];
        out.joints.push_back(free_point(points[l.end[chain[k].second ? 0 : 1]]));
    }
    const Point& vessel = points[lines[chain.front().first].end[chain.front().second ? 1 : 0]];
    std::copy(vessel.position, vessel.position + 3, out.towPoint);
    if (out.towFixed) {
        out.notes.push_back(at_line(vessel.row, "no Vessel or Coupled point: the Fixed point " + std::to_string(vessel.id) +
                                                    " is the tow point, which follows the inputs tow.*: hold them at "
                                                    "its X Y Z = (" + number_text(vessel.position[0]) + ", " +
                                                    number_text(vessel.position[1]) + ", " +
                                                    number_text(vessel.position[2]) + ") m, at rest"));
    }
    const Point& far = points[farPoint];
    if (far.kind == PointKind::Fixed) {
        out.farEnd = LineFileFarEnd::Anchored;
        std::copy(far.position, far.position + 3, out.anchor);
    } else {
        out.body = free_point(far);
        out.farEnd = out.body.empty() ? LineFileFarEnd::Free : LineFileFarEnd::Body;
    }
    return true;
}

namespace {

// The properties of one MoorDyn line into the scalar line parameters or one section (the members
// have the same names).
template <class Line>
void copy_line_properties(const LineFileSection& s, Line& out) {
    out.length = s.length;
    out.diameter = s.diameter;
    out.massPerLength = s.massPerLength;
    out.EA = s.EA;
    out.EI = s.EI;
    out.axialDamping = s.axialDamping;
    out.Cdn = s.Cdn;
    out.Cdt = s.Cdt;
    out.Can = s.Can;
    out.Cat = s.Cat;
    out.nElements = s.elements;
}

}  // namespace

bool apply_line_file(const LineFileLine& line, UCParams& p, std::string& error) {
    if (line.sections.empty()) {
        error = "the line file describes no line";
        return false;
    }
    if (line.sections.size() > UC_MAX_SECTIONS) {
        error = at_line(line.sections[UC_MAX_SECTIONS].row, "a chain of " + std::to_string(line.sections.size()) +
                                                                 " lines: at most " + std::to_string(UC_MAX_SECTIONS) +
                                                                 " lines (sections) are supported");
        return false;
    }
    for (const LineFileSection& s : line.sections) {
        if (s.elements > 1000) {
            error = at_line(s.row, "NumSegs " + std::to_string(s.numSegs) + " gives " + std::to_string(s.elements) +
                                       " elements, more than 1000: set lineFileElements");
            return false;
        }
    }
    if (line.sections.size() == 1) {
        p.nSections = 1;
        copy_line_properties(line.sections[0], p);
        p.nAttachments = 0;
    } else {
        // Each MoorDyn line is a section; the points between them are pinned joints (MoorDyn's
        // points carry no moment), with their mass, volume, drag and added mass an attachment there.
        p.nSections = static_cast<int>(line.sections.size());
        p.nAttachments = 0;
        double s0 = 0.0;
        for (size_t k = 0; k < line.sections.size(); ++k) {
            const LineFileSection& s = line.sections[k];
            UCSection& out = p.section[k];
            copy_line_properties(s, out);
            out.GJ = p.GJ;
            out.joint = 1;
            s0 += s.length;
            if (k + 1 == line.sections.size() || line.joints[k].empty()) continue;
            if (p.nAttachments == UC_MAX_ATTACHMENTS) {
                error = at_line(line.joints[k].row, "more than " + std::to_string(UC_MAX_ATTACHMENTS) +
                                                        " points with mass, volume or drag between lines");
                return false;
            }
            UCAttachment& a = p.attachment[p.nAttachments++];
            a.s = s0;
            a.mass = line.joints[k].mass;
            a.volume = line.joints[k].volume;
            a.addedMass = line.joints[k].addedMass;
            a.CdA = line.joints[k].CdA;
        }
    }
    switch (line.farEnd) {
        case LineFileFarEnd::Anchored:
            p.bottomEnd = UC_BOTTOM_ANCHORED;
            std::copy(line.anchor, line.anchor + 3, p.anchor);
            break;
        case LineFileFarEnd::Body:
            p.bottomEnd = UC_BOTTOM_TOWED_BODY;
            p.bodyMass = line.body.mass;
            p.bodyVolume = line.body.volume;
            p.bodyAddedMass = line.body.addedMass;
            p.bodyCdA = line.body.CdA;
            break;
        case LineFileFarEnd::Free:
            p.bottomEnd = UC_BOTTOM_FREE;
            break;
    }
    // The environment and MoorDyn's seabed, which is always there at WtrDpth (docs/lines.md, "Seabed"),
    // except where the importer set the parameter explicitly (p.deckKeep).
    const int keep = p.deckKeep;
    const LineFileSeabed& bed = line.seabed;
    const double d = line.sections.back().diameter;  // the section on the seabed at the anchor
    if (!(keep & UC_DECK_KEEP_WATER_DEPTH)) p.waterDepth = line.waterDepth;
    if (!(keep & UC_DECK_KEEP_GRAVITY)) p.gravity = line.gravity;
    if (!(keep & UC_DECK_KEEP_WATER_DENSITY)) p.waterDensity = line.waterDensity;
    if (!(keep & UC_DECK_KEEP_ENABLE_SEABED)) p.enableSeabed = bed.kBot > 0.0 ? 1 : 0;
    if (!(keep & UC_DECK_KEEP_SEABED_STIFFNESS) && bed.kBot > 0.0) p.seabedStiffness = bed.kBot * d;
    if (!(keep & UC_DECK_KEEP_SEABED_DAMPING) && bed.kBot > 0.0) p.seabedDamping = bed.cBot * d;
    if (!(keep & UC_DECK_KEEP_SEABED_FRICTION)) p.seabedFriction = bed.friction;
    // MoorDyn's lines are tension-only: a deck's line is the same line
    if (!(keep & UC_DECK_KEEP_ENABLE_COMPRESSION)) p.enableCompression = 0;
    const LineFileSea& sea = line.sea;
    if (sea.profileRows > 0) {
        p.currentProfileRows = sea.profileRows;
        for (int k = 0; k < sea.profileRows; ++k) {
            p.currentProfileDepth[k] = sea.profileDepth[k];
            p.currentProfileX[k] = sea.profileX[k];
            p.currentProfileY[k] = sea.profileY[k];
        }
    }
    if (sea.regularWave) {
        p.wavesMode = 1;
        p.wavesHeight = sea.waveHeight;
        p.wavesPeriod = sea.wavePeriod;
        p.wavesDirection = sea.waveDirection;
        p.wavesStretching = 1;  // MoorDyn's Wheeler stretching
        p.wavesRampTime = 0.0;
    }
    return true;
}

}  // namespace uc

// ------------------------------------------------------------------------------- mooring systems
namespace uc {
namespace {

enum class BodyKind { Coupled, Fixed, Free };

struct DeckBody {
    int id = 0;
    BodyKind kind = BodyKind::Coupled;
    double pose[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};  // X0 Y0 Z0 [m], r0 p0 y0 [rad]
    double mass = 0.0, volume = 0.0, cg[3] = {0.0, 0.0, 0.0};  // a Free body's
    double inertia[3] = {0.0, 0.0, 0.0};
    double CdA[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};  // body axes: translations x, y, z, rotations about them
    double Ca[3] = {0.0, 0.0, 0.0};                  // translations in body axes
    int row = 0;
};

// The numbers of a field separated by '|' (MoorDyn's CG*, I*, CdA*, Ca*), of one of the counts allowed.
bool bar_numbers(Fields& f, const Row& row, size_t i, const char* name, std::initializer_list<size_t> counts,
                 std::vector<double>& v) {
    if (i >= row.tokens.size()) return f.fail(std::string("a Free body needs its ") + name);
    v.clear();
    std::string_view t = row.tokens[i];
    while (true) {
        const size_t bar = t.find('|');
        const auto x = to_number(t.substr(0, bar));
        if (!x) return f.fail(std::string(name) + " " + quoted(row.tokens[i]) + " is not numbers separated by '|'");
        v.push_back(*x);
        if (bar == std::string_view::npos) break;
        t = t.substr(bar + 1);
    }
    if (std::find(counts.begin(), counts.end(), v.size()) == counts.end()) {
        std::string allowed;
        for (size_t c : counts) allowed += (allowed.empty() ? "" : ", ") + std::to_string(c);
        return f.fail(std::string(name) + " " + quoted(row.tokens[i]) + ": " + allowed + " numbers");
    }
    return true;
}

// A field of one number or three (CG*, I*, Ca*); one number c is (0, 0, c) for the centre of gravity
// (oneIsZ), (c, c, c) otherwise.
bool vector_field(Fields& f, const Row& row, size_t i, const char* name, bool oneIsZ, double out[3]) {
    std::vector<double> v;
    if (!bar_numbers(f, row, i, name, {1, 3}, v)) return false;
    for (int k = 0; k < 3; ++k) out[k] = v.size() == 3 ? v[k] : (oneIsZ ? (k == 2 ? v[0] : 0.0) : v[0]);
    return true;
}

// CdA* as MoorDyn's documentation has it: one number for all six directions, two (translations,
// rotations), three (per body axis, for translation and rotation alike) or six.
bool drag_field(Fields& f, const Row& row, size_t i, double out[6]) {
    std::vector<double> v;
    if (!bar_numbers(f, row, i, "CdA", {1, 2, 3, 6}, v)) return false;
    for (int k = 0; k < 6; ++k) {
        out[k] = v.size() == 1 ? v[0] : v.size() == 2 ? v[k / 3] : v.size() == 3 ? v[k % 3] : v[k];
    }
    return true;
}

// A Free body's inertia, drag and added mass as its equations of motion need them: each moment of inertia
// positive, drag areas and added-mass coefficients not negative, and mass or volume (a body with neither
// has no inertia of translation). False (the error naming the column and the value) where not.
bool free_body_plausible(Fields& f, const Row& row, const DeckBody& b) {
    static const char* const kAxes[6] = {"x", "y", "z", "rotation about x", "rotation about y", "rotation about z"};
    const std::string id = "Free body " + std::to_string(b.id);
    for (int k = 0; k < 3; ++k) {
        if (!(b.inertia[k] > 0.0))
            return f.fail("I = " + shown(row.tokens[10]) + ": " + id + "'s moment of inertia about its " + kAxes[k] +
                          " axis is " + number_text(b.inertia[k]) + " kg m2; it must be positive");
    }
    for (int k = 0; k < 6; ++k) {
        if (b.CdA[k] < 0.0)
            return f.fail("CdA = " + shown(row.tokens[12]) + ": " + id + "'s drag area in " + kAxes[k] + " is " +
                          number_text(b.CdA[k]) + " m2; it must not be negative");
    }
    for (int k = 0; k < 3; ++k) {
        if (b.Ca[k] < 0.0)
            return f.fail("Ca = " + shown(row.tokens[13]) + ": " + id + "'s added-mass coefficient in " + kAxes[k] +
                          " is " + number_text(b.Ca[k]) + "; it must not be negative");
    }
    if (b.mass == 0.0 && b.volume == 0.0)
        return f.fail("Mass = 0 kg and Volume = 0 m3: " + id + " has neither mass nor volume, so no inertia of "
                      "translation and no weight (give its mass, or its volume for a buoy)");
    return true;
}

// MoorDyn's BODIES row: ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca* (angles in degrees).
bool read_body(const Row& row, int expectedId, DeckBody& b, std::vector<std::string>& notes, std::string& error) {
    Fields f(row, error);
    if (row.tokens.size() < 8) {
        return f.fail("a body has the fields ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*; this row has " +
                      std::to_string(row.tokens.size()));
    }
    if (!read_id(f, "body", expectedId, b.id)) return false;
    const std::string u = upper(row.tokens[1]);
    std::string head;
    for (char c : u) {
        if (!std::isalpha(static_cast<unsigned char>(c))) break;
        head += c;
    }
    if (is_one_of(head, {"COUPLED", "CPLD", "VESSEL", "VES"})) {
        b.kind = BodyKind::Coupled;
    } else if (is_one_of(head, {"FIXED", "FIX", "ANCHOR"})) {
        b.kind = BodyKind::Fixed;
    } else if (is_one_of(head, {"FREE"})) {
        b.kind = BodyKind::Free;
    } else if (is_one_of(head, {"PINNED", "CPLDPIN", "COUPLEDPINNED"})) {
        return f.fail("body " + std::to_string(b.id) + " is pinned (coupled in translation, free in rotation): not "
                      "supported (Coupled and Fixed bodies)");
    } else {
        return f.fail("unknown body attachment " + quoted(row.tokens[1]) + " (Coupled or Fixed)");
    }
    static const char* const kColumns[] = {"X0", "Y0", "Z0", "r0", "p0", "y0"};
    const double kDegree = kPi / 180.0;
    for (int k = 0; k < 6; ++k) b.pose[k] = f.number(2 + k, kColumns[k]) * (k < 3 ? 1.0 : kDegree);
    b.row = row.number;
    if (f.ok() && b.kind == BodyKind::Free) {
        if (row.tokens.size() < 14) {
            return f.fail("a Free body has the fields ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*; this "
                          "row has " + std::to_string(row.tokens.size()));
        }
        b.mass = f.non_negative(8, "Mass");
        b.volume = f.non_negative(11, "Volume");
        if (!f.ok() || !vector_field(f, row, 9, "CG", true, b.cg) || !vector_field(f, row, 10, "I", false, b.inertia) ||
            !drag_field(f, row, 12, b.CdA) || !vector_field(f, row, 13, "Ca", false, b.Ca))
            return false;
        if (!free_body_plausible(f, row, b)) return false;
    }
    if (f.ok() && b.kind == BodyKind::Coupled && row.tokens.size() > 8) {
        notes.push_back(at_line(row.number, "the mass, inertia, volume and drag of coupled body " + std::to_string(b.id) +
                                                " ignored (its motion is given by the body[k].* inputs; the lines' load "
                                                "on it is the output)"));
    }
    return f.ok();
}

// R = Rx(a0) Ry(a1) Rz(a2): MoorDyn's orientation of a body from its roll, pitch and yaw.
void rotate_xyz(const double a[3], const double r[3], double out[3]) {
    const double cx = std::cos(a[0]), sx = std::sin(a[0]), cy = std::cos(a[1]), sy = std::sin(a[1]),
                 cz = std::cos(a[2]), sz = std::sin(a[2]);
    const double z1[3] = {cz * r[0] - sz * r[1], sz * r[0] + cz * r[1], r[2]};
    const double y1[3] = {cy * z1[0] + sy * z1[2], z1[1], -sy * z1[0] + cy * z1[2]};
    out[0] = y1[0];
    out[1] = cx * y1[1] - sx * y1[2];
    out[2] = sx * y1[1] + cx * y1[2];
}

// Where the end of a line at point p is held.
bool mooring_end(const Point& p, const std::vector<DeckBody>& bodies, const std::vector<int>& bodyNode,
                 bool bodiesSection, MooringEnd& end, std::string& error) {
    switch (p.kind) {
        case PointKind::Fixed:
            end.kind = MooringEnd::Kind::Fixed;
            std::copy(p.position, p.position + 3, end.position);
            return true;
        case PointKind::Vessel:
            if (bodiesSection) {
                if (p.id > UC_MAX_POINTS) {
                    error = at_line(p.row, "coupled point " + std::to_string(p.id) + ": the coupled points' inputs "
                                           "point[k].* go up to k = " + std::to_string(UC_MAX_POINTS) +
                                           " (give it a smaller ID)");
                    return false;
                }
                end.kind = MooringEnd::Kind::Point;
                end.point = p.id;
            } else {
                end.kind = MooringEnd::Kind::Body;  // a platform's fairlead: rides body 1
                end.body = 1;
            }
            std::copy(p.position, p.position + 3, end.position);
            return true;
        case PointKind::Body: {
            if (p.body < 1 || p.body > static_cast<int>(bodies.size())) {
                error = at_line(p.row, "point " + std::to_string(p.id) + " is on body " + std::to_string(p.body) +
                                       ", which the BODIES table does not have");
                return false;
            }
            const DeckBody& b = bodies[p.body - 1];
            if (b.kind == BodyKind::Free) {  // a free node: at its position in the body's frame
                end.kind = MooringEnd::Kind::Node;
                end.node = bodyNode[p.body - 1];
                std::copy(p.position, p.position + 3, end.position);
                return true;
            }
            if (b.kind == BodyKind::Fixed) {
                end.kind = MooringEnd::Kind::Fixed;
                rotate_xyz(b.pose + 3, p.position, end.position);
                for (int k = 0; k < 3; ++k) end.position[k] += b.pose[k];
                return true;
            }
            if (p.body > UC_MAX_BODIES) {
                error = at_line(p.row, "point " + std::to_string(p.id) + " is on coupled body " + std::to_string(p.body) +
                                       ": the bodies' inputs body[k].* go up to k = " + std::to_string(UC_MAX_BODIES));
                return false;
            }
            end.kind = MooringEnd::Kind::Body;
            end.body = p.body;
            std::copy(p.position, p.position + 3, end.position);
            return true;
        }
        case PointKind::Free:
            error = at_line(p.row, "point " + std::to_string(p.id) + " is a Free point: it holds no line's end "
                                   "(its lines are joined through it)");
            return false;
    }
    return false;
}

}  // namespace

bool is_mooring_system_deck(std::string_view text) {
    std::vector<std::optional<Section>> sections;
    std::string error;
    if (!collect_sections(text, sections, error)) return false;
    const auto& lines = sections[static_cast<size_t>(Kind::Lines)];
    const auto& points = sections[static_cast<size_t>(Kind::Points)];
    const auto& bodies = sections[static_cast<size_t>(Kind::Bodies)];
    if (!lines || !points) return false;
    if (lines->rows.size() > 1 || (bodies && !bodies->rows.empty())) return true;
    for (const Row& row : points->rows) {
        if (row.tokens.size() > 1 && upper(row.tokens[1]).rfind("BODY", 0) == 0) return true;
    }
    return false;
}

bool read_mooring_deck(std::string_view text, int elementsPerLine, MooringDeck& out, std::string& error,
                       const LineFileCompanions& companions) {
    out = MooringDeck();
    Deck deck;
    if (!parse_deck(text, true, companions, deck, out.notes, error)) return false;
    std::vector<DeckBody> bodies;
    for (const Row& row : deck.bodies) {
        DeckBody b;
        if (!read_body(row, static_cast<int>(bodies.size()) + 1, b, out.notes, error)) return false;
        bodies.push_back(b);
        if (b.kind == BodyKind::Coupled) out.bodies = std::max(out.bodies, b.id);
    }
    out.bodiesSection = !bodies.empty();
    if (deck.lines.size() > UC_MAX_LINES) {
        error = at_line(deck.lines[UC_MAX_LINES].row, "line " + std::to_string(UC_MAX_LINES + 1) + ": a mooring system "
                                                      "holds at most " + std::to_string(UC_MAX_LINES) + " lines");
        return false;
    }
    for (const Point& p : deck.points) {
        if (p.lines.empty()) out.notes.push_back(at_line(p.row, "point " + std::to_string(p.id) + " ignored: no line "
                                                                "is attached to it"));
    }
    // Free points where three or more lines meet are the system's free nodes.
    std::vector<int> nodeOf(deck.points.size(), -1);
    for (size_t i = 0; i < deck.points.size(); ++i) {
        const Point& p = deck.points[i];
        if (p.kind != PointKind::Free || p.lines.size() < 3) continue;
        nodeOf[i] = static_cast<int>(out.nodes.size());
        MooringNode node;
        node.point = point_body(p, deck.waterDensity);
        std::copy(p.position, p.position + 3, node.position);
        out.nodes.push_back(node);
    }
    // Free bodies are free nodes too (six unknowns), after the points
    std::vector<int> bodyNode(bodies.size(), -1);
    for (const DeckBody& b : bodies) {
        if (b.kind != BodyKind::Free) continue;
        bodyNode[b.id - 1] = static_cast<int>(out.nodes.size());
        MooringNode node;
        node.body = true;
        node.point.id = b.id;
        node.point.mass = b.mass;
        node.point.volume = b.volume;
        std::copy(b.CdA, b.CdA + 6, node.CdA);
        std::copy(b.Ca, b.Ca + 3, node.Ca);
        std::copy(b.inertia, b.inertia + 3, node.inertia);
        node.point.row = b.row;
        std::copy(b.pose, b.pose + 3, node.position);
        std::copy(b.pose + 3, b.pose + 6, node.angles);
        std::copy(b.cg, b.cg + 3, node.cg);
        out.nodes.push_back(node);
    }
    auto on_free_body = [&](int q) {
        const Point& p = deck.points[q];
        return p.kind == PointKind::Body && p.body >= 1 && p.body <= static_cast<int>(bodies.size()) &&
               bodies[p.body - 1].kind == BodyKind::Free;
    };
    auto node_end = [&](int q, MooringEnd& end) {
        end = MooringEnd();
        end.kind = MooringEnd::Kind::Node;
        end.node = nodeOf[q];
        std::copy(deck.points[q].position, deck.points[q].position + 3, end.position);
    };
    // Each of our lines is a chain of the deck's lines from an end on a coupled object (or, for lines
    // no coupled object holds, on a free node; then, for lines neither holds, at a Fixed point) through
    // Free points that join two lines, to a Fixed point, another coupled end, a free node or a Free point
    // at its end.
    std::vector<bool> used(deck.lines.size(), false);
    auto fixed_end = [&](int q) {
        const Point& p = deck.points[q];
        return p.kind == PointKind::Fixed || (p.kind == PointKind::Body && p.body >= 1 &&
                                              p.body <= static_cast<int>(bodies.size()) &&
                                              bodies[p.body - 1].kind == BodyKind::Fixed);
    };
    // a point held by the importer: a Vessel/Coupled point or a point on a Coupled body
    auto coupled = [&](int q) {
        const PointKind kind = deck.points[q].kind;
        return kind == PointKind::Vessel || (kind == PointKind::Body && !on_free_body(q) && !fixed_end(q));
    };
    for (int pass = 0; pass < 3; ++pass)
    for (size_t first = 0; first < deck.lines.size(); ++first) {
        if (used[first]) continue;
        const Line& l0 = deck.lines[first];
        int start = -1;
        for (int e : {1, 0}) {  // AttachB first: MoorDyn's usual fairlead
            if (start < 0 && (pass == 0 ? coupled(l0.end[e])
                              : pass == 1 ? (nodeOf[l0.end[e]] >= 0 || on_free_body(l0.end[e]))
                                          : fixed_end(l0.end[e])))
                start = l0.end[e];
        }
        if (start < 0) continue;  // reached from another line's coupled end or a node, or refused below
        MooringDeckLine line;
        line.id = l0.id;
        line.row = l0.row;
        if (pass == 1 && nodeOf[start] >= 0) {
            node_end(start, line.fairlead);
        } else if (!mooring_end(deck.points[start], bodies, bodyNode, out.bodiesSection, line.fairlead, error)) {
            return false;
        }
        int point = start, index = static_cast<int>(first);
        while (true) {
            const Line& l = deck.lines[index];
            used[index] = true;
            LineFileSection section = section_of(l, deck.types[l.type]);
            section.elements = elementsPerLine > 0 ? elementsPerLine : elements_for_segments(l.numSegs);
            line.sections.push_back(section);
            line.deckLines.push_back(index);
            const int from = point;
            point = l.end[l.end[1] == point ? 0 : 1];
            // the deck line's own fairlead: its end on a coupled object (AttachB where both are; a point on
            // a Free or Fixed body is none), else the end nearer our fairlead
            const int fairlead = coupled(l.end[1]) ? l.end[1] : coupled(l.end[0]) ? l.end[0] : from;
            line.flipped.push_back(fairlead == point);
            const Point& p = deck.points[point];
            if (p.kind != PointKind::Free) {
                if (!mooring_end(p, bodies, bodyNode, out.bodiesSection, line.far, error)) return false;
                break;
            }
            if (p.lines.size() == 1) {  // a free far end: a towed body, or none
                line.farFree = true;
                line.farBody = point_body(p, deck.waterDensity);
                break;
            }
            if (p.lines.size() > 2) {  // a free node: the line ends there
                node_end(point, line.far);
                break;
            }
            index = p.lines[0] == index ? p.lines[1] : p.lines[0];
            if (used[index]) {
                error = at_line(p.row, "the lines through point " + std::to_string(p.id) + " form a closed loop");
                return false;
            }
            line.joints.push_back(point_body(p, deck.waterDensity));
        }
        if (line.sections.size() > UC_MAX_SECTIONS) {
            error = at_line(deck.lines[line.deckLines[UC_MAX_SECTIONS]].row,
                            "a chain of " + std::to_string(line.sections.size()) + " lines from point " +
                                std::to_string(deck.points[start].id) + ": at most " + std::to_string(UC_MAX_SECTIONS) +
                                " lines in a row are supported");
            return false;
        }
        if (out.bodies == 0 && line.fairlead.kind == MooringEnd::Kind::Body) out.bodies = 1;
        out.lines.push_back(line);
    }
    for (size_t k = 0; k < deck.lines.size(); ++k) {
        if (used[k]) continue;
        const Line& l = deck.lines[k];
        error = at_line(l.row, "line " + std::to_string(l.id) + " is not reached from a coupled point, a free node "
                                                                "or a Fixed point: every line of a system runs from "
                                                                "one of them through free points joining two lines "
                                                                "to its end (the lines through its points form a "
                                                                "closed loop)");
        return false;
    }
    for (const MooringNode& node : out.nodes) {
        if (!node.body) continue;
        bool held = false;
        for (const MooringDeckLine& l : out.lines)
            for (const MooringEnd* e : {&l.fairlead, &l.far})
                held = held || (e->kind == MooringEnd::Kind::Node && out.nodes[e->node].body && out.nodes[e->node].point.id == node.point.id);
        if (!held) {
            error = at_line(node.point.row, "Free body " + std::to_string(node.point.id) + " holds no line: a free body of "
                                            "a mooring system is held by the lines on its points");
            return false;
        }
    }
    out.deckLines = static_cast<int>(deck.lines.size());
    out.nodesFromDeck = deck.noInitialConditions;
    out.waterDepth = deck.waterDepth;
    out.gravity = deck.gravity;
    out.waterDensity = deck.waterDensity;
    out.waterDepthRow = deck.waterDepthRow;
    out.gravityRow = deck.gravityRow;
    out.waterDensityRow = deck.waterDensityRow;
    out.seabed = deck.seabed;
    out.sea = deck.sea;
    return true;
}

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

bool mooring_line_params(const MooringDeck& deck, int k, const UCParams& base, UCParams& p, std::string& error) {
    const MooringDeckLine& l = deck.lines[k];
    LineFileLine line;
    line.sections = l.sections;
    line.joints = l.joints;
    line.waterDepth = deck.waterDepth;
    line.gravity = deck.gravity;
    line.waterDensity = deck.waterDensity;
    line.seabed = deck.seabed;
    line.sea = deck.sea;
    if (l.farFree) {
        line.body = l.farBody;
        line.farEnd = l.farBody.empty() ? LineFileFarEnd::Free : LineFileFarEnd::Body;
    } else {
        line.farEnd = LineFileFarEnd::Anchored;
        std::copy(l.far.position, l.far.position + 3, line.anchor);
    }
    p = base;
    if (!apply_line_file(line, p, error)) return false;
    if (!l.farFree && l.far.kind != MooringEnd::Kind::Fixed) p.bottomEnd = UC_BOTTOM_EXTERNAL;
    p.mooringSystem = 0;  // each line is one line
    return true;
}

}  // namespace uc
