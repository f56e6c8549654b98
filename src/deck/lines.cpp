// lines.cpp - the LINES section of a MoorDyn v2 deck (docs/lines.md), and one of its lines as a section of ours.
#include "deck/tables.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace uc {
namespace deck {

// AttachA/AttachB: a point ID ("3", "P3", "Point3", "C3", "Con3") or a rod's end ("R1A", "Rod2B").
bool read_attachment(Fields& f, std::string_view word, const char* column, int nPoints, int& index,
                     const std::vector<Rod>* rods, int* rodEnd) {
    const std::string u = upper(word);
    size_t letters = 0;
    while (letters < u.size() && std::isalpha(static_cast<unsigned char>(u[letters]))) ++letters;
    const std::string head = u.substr(0, letters), digits = u.substr(letters);
    if (is_one_of(head, {"R", "ROD"})) {
        if (rodEnd == nullptr) return f.fail(std::string(column) + " " + quoted(word) + ": a rod's end is not supported here");
        if (rods == nullptr) {
            return f.fail(std::string(column) + " " + quoted(word) + ": a rod's end, but the deck has no RODS rows");
        }
        const std::string number = digits.empty() ? digits : digits.substr(0, digits.size() - 1);
        const char side = digits.empty() ? '\0' : digits.back();
        if ((side != 'A' && side != 'B') || number.empty() || number.size() > 8 ||
            !std::all_of(number.begin(), number.end(), [](char c) { return c >= '0' && c <= '9'; })) {
            return f.fail(std::string(column) + " " + quoted(word) + " is not a rod's end (R<ID>A or R<ID>B)");
        }
        const int id = std::stoi(number);
        if (id < 1 || id > static_cast<int>(rods->size())) {
            return f.fail(std::string(column) + " " + quoted(word) + ": there is no rod " + std::to_string(id) +
                          " (the RODS table has " + std::to_string(rods->size()) + ")");
        }
        *rodEnd = 2 * (id - 1) + (side == 'B' ? 1 : 0);
        index = (*rods)[id - 1].point[side == 'B' ? 1 : 0];
        return true;
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
               std::string& error, const std::vector<Rod>* rods) {
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
    int rodEnd[2] = {-1, -1};
    if (!read_attachment(f, row.tokens[2], "AttachA", nPoints, l.end[0], rods, &rodEnd[0]) ||
        !read_attachment(f, row.tokens[3], "AttachB", nPoints, l.end[1], rods, &rodEnd[1])) {
        return false;
    }
    for (int e = 0; e < 2; ++e) l.rod[e] = rodEnd[e] + 1;  // 2 (ID - 1) + side + 1 until clamp_lines_to_rods
    if (l.end[0] == l.end[1]) return f.fail("AttachA and AttachB are the same point");
    l.length = f.positive(4, "UnstrLen");
    l.numSegs = f.integer(5, "NumSegs", 1, 100000, "must be between 1 and 100000");
    l.row = row.number;
    return f.ok();
}

// One MoorDyn line as a section of ours, in our conventions.
LineFileSection section_of(const Line& l, const LineType& t) {
    LineFileSection s;
    s.type = t.name;
    s.length = l.length;
    s.diameter = t.diameter;
    s.massPerLength = t.massPerLength;
    s.EA = t.EA;
    s.curveStrain = t.curveStrain;
    s.curveTension = t.curveTension;
    s.EAd = t.EAd;
    s.EAslope = t.EAslope;
    s.BAd = t.BAd;
    s.syropeForm = t.syropeForm;
    s.syropeK1 = t.syropeK1;
    s.syropeK2 = t.syropeK2;
    if (t.syropeForm != 0) {  // (its SYROPE IC row is there: read_syrope_ic)
        s.syropeTmax0 = l.syropeTmax0;
        s.syropeTmean0 = l.syropeTmean0;
    }
    // MoorDyn's lift acts on a line's internal nodes only: a line of one segment has none.
    s.Cl = l.numSegs >= 2 ? t.Cl : 0.0;
    s.vivFrequency = t.cF;
    s.vivFrequencyRange = t.dF;
    s.EI = t.EI;
    // BA/-zeta < 0: a fraction of critical damping of one MoorDyn segment, converted as MoorDyn does,
    // BA = zeta (UnstrLen / NumSegs) sqrt(EA Mass/m) (docs/lines.md).
    s.axialDamping = t.BA >= 0.0 ? t.BA : -t.BA * (l.length / l.numSegs) * std::sqrt(t.EA * t.massPerLength);
    s.Cdn = t.Cd;
    s.Cdt = t.CdAx;
    s.Can = t.Ca;
    s.Cat = t.CaAx;
    s.MBL = t.MBL;
    s.numSegs = l.numSegs;
    s.row = l.row;
    return s;
}

}  // namespace deck
}  // namespace uc
