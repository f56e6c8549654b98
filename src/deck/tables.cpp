// tables.cpp - the tables of a MoorDyn v2 deck read section by section into one Deck, with its environment
// (MoorDyn's defaults, its water depth raised to the deepest point).
#include "deck/tables.h"

#include <algorithm>

namespace uc {
namespace deck {

bool parse_deck(std::string_view text, bool system, const LineFileCompanions& companions, Deck& deck,
                std::vector<std::string>& notes, std::string& error) {
    std::vector<std::optional<Section>> sections;
    if (!collect_sections(text, sections, error)) return false;
    auto section = [&](Kind kind) -> const std::optional<Section>& { return sections[static_cast<size_t>(kind)]; };

    for (Kind kind : {Kind::Bodies, Kind::Failure, Kind::Control, Kind::ExternalLoads}) {
        if (system && (kind == Kind::Bodies || kind == Kind::Failure)) continue;
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
    const bool anyRods = section(Kind::Rods) && !section(Kind::Rods)->rows.empty();
    if (section(Kind::RodTypes) && !section(Kind::RodTypes)->rows.empty()) {
        if (!anyRods) {
            notes.push_back(at_line(section(Kind::RodTypes)->header, "ROD TYPES ignored (there are no rods)"));
        } else {
            for (const Row& row : section(Kind::RodTypes)->rows) {
                RodType t;
                if (!read_rod_type(row, t, error)) return false;
                for (const RodType& other : deck.rodTypes) {
                    if (other.name == t.name) {
                        error = at_line(row.number, "rod type " + quoted(t.name) + " is defined twice (also at line " +
                                                        std::to_string(other.row) + ")");
                        return false;
                    }
                }
                deck.rodTypes.push_back(t);
            }
        }
    }
    if (anyRods) {
        for (const Row& row : section(Kind::Rods)->rows) {
            Rod r;
            if (!read_rod(row, static_cast<int>(deck.rods.size()) + 1, deck.rodTypes, r, error)) return false;
            deck.rods.push_back(r);
        }
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
    if (!read_seafloor(companions, options.seabed, notes, error)) return false;

    std::vector<LineType>& types = deck.types;
    for (const Row& row : section(Kind::LineTypes)->rows) {
        LineType t{};
        if (!read_line_type(row, section(Kind::LineTypes)->columns, companions, t, error)) return false;
        for (const LineType& other : types) {
            if (other.name == t.name) {
                error = at_line(row.number, "line type " + quoted(t.name) + " is defined twice (also at line " +
                                                std::to_string(other.row) + ")");
                return false;
            }
        }
        if (t.MBL == 0.0) {
            std::string note;
            t.MBL = default_breaking_load(t, note);
            notes.push_back(at_line(t.row, note));
        }
        types.push_back(t);
    }

    std::vector<Point>& points = deck.points;
    for (const Row& row : section(Kind::Points)->rows) {
        Point p;
        if (!read_point(row, static_cast<int>(points.size()) + 1, system, p, notes, error)) return false;
        points.push_back(p);
    }

    deck.deckPoints = static_cast<int>(points.size());
    if (!deck.rods.empty()) {
        // the free bodies that free rods of non-zero length become are numbered after the deck's bodies (and
        // after body 1, the platform the Vessel points ride, in a deck without a BODIES section)
        const bool vessel = std::any_of(points.begin(), points.end(), [](const Point& p) { return p.kind == PointKind::Vessel; });
        const int firstBody = static_cast<int>(deck.bodies.size()) + (deck.bodies.empty() && vessel ? 1 : 0) + 1;
        if (!rods_as_points(deck.rods, firstBody, system, points, error)) return false;
    }

    std::vector<Line>& lines = deck.lines;
    for (const Row& row : section(Kind::Lines)->rows) {
        Line l;
        if (!read_line(row, static_cast<int>(lines.size()) + 1, types, deck.deckPoints, l, error,
                       deck.rods.empty() ? nullptr : &deck.rods)) {
            return false;
        }
        for (int e : l.end) points[e].lines.push_back(static_cast<int>(lines.size()));
        lines.push_back(l);
    }
    if (!deck.rods.empty()) clamp_lines_to_rods(deck.rods, deck.rodTypes, types, points, lines, notes);
    if (!read_syrope_ic(section(Kind::SyropeIC) ? section(Kind::SyropeIC)->rows : std::vector<Row>(), types, lines, notes,
                        error))
        return false;

    if (section(Kind::Failure)) {
        for (const Row& row : section(Kind::Failure)->rows) {
            Failure f;
            if (!read_failure(row, static_cast<int>(deck.failures.size()) + 1, points, lines, f, error)) return false;
            deck.failures.push_back(f);
        }
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
            // (with a SeafloorFile the seabed is the file's, its depth under the origin the water depth: no note)
            if (options.waterDepth > 0.0 && options.seabed.seafloorFile.empty()) {
                notes.push_back(at_line(p.row, "point " + std::to_string(p.id) + " lies below WtrDpth: the water "
                                               "depth is set to its depth, " + number_text(-p.position[2]) +
                                               " m (as MoorDyn does)"));
            }
            deck.waterDepth = -p.position[2];
        }
    }
    return true;
}

}  // namespace deck
}  // namespace uc
