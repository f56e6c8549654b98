// points.cpp - the POINTS section of a MoorDyn v2 deck (docs/lines.md): Fixed, Vessel/Coupled, Free
// points, and points on bodies in a mooring system.
#include "deck/tables.h"

#include <algorithm>
#include <cctype>

namespace uc {
namespace deck {

namespace {

// The attachment word of a point: letters (case-insensitive), maybe followed by a number (Body2).
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

}  // namespace

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

const char* kind_name(PointKind kind) {
    switch (kind) {
        case PointKind::Fixed: return "Fixed";
        case PointKind::Vessel: return "Vessel";
        case PointKind::Body: return "Body";
        default: return "Free";
    }
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
    q.rigid = p.rigid;
    return q;
}

}  // namespace deck
}  // namespace uc
