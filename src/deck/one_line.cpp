// one_line.cpp - one line from a MoorDyn v2 deck (docs/lines.md): the deck's tables (deck/tables.cpp)
// walked as one chain of lines from the vessel point to the far end, converted into our conventions and
// written into the parameters.
#include "deck/line_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "deck/tables.h"

namespace uc {
using namespace deck;
namespace {

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
    out.Cl = s.Cl;
    out.vivFrequency = s.vivFrequency;
    out.vivFrequencyRange = s.vivFrequencyRange;
    out.nElements = s.elements;
    if (s.MBL > 0.0) out.MBL = s.MBL;  // else the parameter's (a section's 0: the line's MBL)
}

}  // namespace

int elements_for_segments(int numSegs) { return std::max(1, (numSegs + 1) / 2); }

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
    // a line clamped to a Fixed rod at the tow point: the tow point is clamped along the rod's axis
    std::vector<std::pair<int, int>> held;
    const int towEnd = chain.front().second ? 1 : 0;
    const Line& first = lines[chain.front().first];
    if (first.clamped[towEnd] && vessel.kind == PointKind::Fixed) {
        out.towClamped = true;
        std::copy(first.tangent[towEnd], first.tangent[towEnd] + 3, out.towTangent);
        held.emplace_back(chain.front().first, towEnd);
        out.notes.push_back(at_line(vessel.row, "line " + std::to_string(first.id) + " is clamped to rod " +
                                                    std::to_string(first.rod[towEnd]) + " at the tow point: topEnd 1, "
                                                    "topTangent (" + number_text(out.towTangent[0]) + ", " +
                                                    number_text(out.towTangent[1]) + ", " +
                                                    number_text(out.towTangent[2]) + ")"));
    }
    note_pinned_clamps(deck, held, out.notes);
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
    for (const LineFileSection& s : line.sections) {
        if (s.syropeForm != 0 && line.sections.size() > 1) {
            error = at_line(s.row, "line type " + quoted(s.type) + " has the Syrope model in a chain of " +
                                   std::to_string(line.sections.size()) +
                                   " lines: the FMU's Syrope model (syrope.*) describes a line of one type");
            return false;
        }
        if (!s.curveStrain.empty() && line.sections.size() > 1) {
            error = at_line(s.row, "line type " + quoted(s.type) + " has a tension-strain curve (EA from a file) in a "
                                   "chain of " + std::to_string(line.sections.size()) +
                                   " lines: the FMU's curve (axialCurve.*) describes a line of one type");
            return false;
        }
    }
    p.axialCurvePoints = 0;
    p.EAdynamic = p.EAdynamicSlope = p.axialDampingDynamic = 0.0;
    p.syropeWorkingCurve = 0;
    if (line.sections.size() == 1) {
        p.nSections = 1;
        copy_line_properties(line.sections[0], p);
        const LineFileSection& s = line.sections[0];
        p.EAdynamic = s.EAd;
        p.EAdynamicSlope = s.EAslope;
        p.axialDampingDynamic = s.BAd;
        p.syropeWorkingCurve = s.syropeForm;
        p.syropeK1 = s.syropeK1;
        p.syropeK2 = s.syropeK2;
        p.syropeTensionMax0 = s.syropeTmax0;
        p.syropeTensionMean0 = s.syropeTmean0;
        p.axialCurvePoints = static_cast<int>(s.curveStrain.size());
        for (size_t k = 0; k < s.curveStrain.size(); ++k) {
            p.axialCurveStrain[k] = s.curveStrain[k];
            p.axialCurveTension[k] = s.curveTension[k];
        }
        p.nAttachments = 0;
    } else {
        // Each MoorDyn line is a section; the points between them are pinned joints (MoorDyn's
        // points carry no moment), with their mass, volume, drag and added mass an attachment there; a free
        // zero-length rod both lines are clamped to is a rigid joint.
        p.nSections = static_cast<int>(line.sections.size());
        p.nAttachments = 0;
        double s0 = 0.0;
        for (size_t k = 0; k < line.sections.size(); ++k) {
            const LineFileSection& s = line.sections[k];
            UCSection& out = p.section[k];
            copy_line_properties(s, out);
            out.EAdynamic = s.EAd;
            out.EAdynamicSlope = s.EAslope;
            out.axialDampingDynamic = s.BAd;
            out.GJ = p.GJ;
            out.joint = k + 1 < line.sections.size() && line.joints[k].rigid ? 0 : 1;
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
    if (line.towClamped) {  // on a Fixed rod (docs/lines.md, "Rods"); otherwise the parameter's topEnd
        p.topEnd = 1;
        std::copy(line.towTangent, line.towTangent + 3, p.topTangent);
        // a cantilever (its far end free): the statics start from the line straight along the clamp
        if (line.farEnd != LineFileFarEnd::Anchored) std::copy(line.towTangent, line.towTangent + 3, p.initialDirection);
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
    if (!(keep & UC_DECK_KEEP_WATER_DEPTH))
        p.waterDepth = bed.plane ? bed.planeDepth : bed.grid ? bed.meanDepth : line.waterDepth;
    // a grid: the file by its name beside the deck (the FMU's adapter puts the path it read it from in its
    // place), unless the importer set seabed.file
    if (bed.grid && p.seabedFile[0] == '\0') std::snprintf(p.seabedFile, sizeof p.seabedFile, "%s", bed.seafloorFile.c_str());
    if (bed.plane) {  // the SeafloorFile's plane (read_seafloor)
        p.seabedSlope = bed.slope;
        p.seabedSlopeHeading = bed.heading;
    }
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
    // Currents 2 or 5: the data's file by its name beside the deck (the FMU's adapter puts the path it read it
    // from in its place); a currents.file the importer set keeps its place and its currents.mode.
    if (sea.currentsMode != 0 && p.currentsFile[0] == '\0') {
        p.currentsMode = sea.currentsMode;
        std::snprintf(p.currentsFile, sizeof p.currentsFile, "%s", sea.currentsFile.c_str());
    }
    if (!sea.waveComponents.empty() && !apply_wave_components(sea.waveComponents, "the deck", p, error)) return false;
    if (!sea.waveComponents.empty()) {
        p.wavesMode = 3;
        p.wavesStretching = 1;  // MoorDyn's Wheeler stretching
        p.wavesRampTime = 0.0;
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
