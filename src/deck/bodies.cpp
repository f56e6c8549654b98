// bodies.cpp - the BODIES section of a MoorDyn v2 deck (docs/systems_mooring.md): Coupled, Fixed and Free
// bodies of a mooring system.
#include "deck/tables.h"

#include <algorithm>
#include <cctype>
#include <initializer_list>

namespace uc {
namespace deck {

namespace {

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

}  // namespace

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
    } else if (is_one_of(head, {"VESSELPINNED", "VESPIN", "CPLDPIN", "COUPLEDPINNED"})) {
        b.kind = BodyKind::Pinned;  // its reference point held by the body[k] inputs, free to turn about it
        b.pinBody = b.id;
    } else {
        return f.fail("unknown body attachment " + quoted(row.tokens[1]) + " (Coupled, Fixed, Free or CoupledPinned)");
    }
    static const char* const kColumns[] = {"X0", "Y0", "Z0", "r0", "p0", "y0"};
    const double kDegree = kPi / 180.0;
    for (int k = 0; k < 6; ++k) b.pose[k] = f.number(2 + k, kColumns[k]) * (k < 3 ? 1.0 : kDegree);
    b.row = row.number;
    if (f.ok() && (b.kind == BodyKind::Free || b.kind == BodyKind::Pinned)) {
        const char* what = b.kind == BodyKind::Free ? "a Free body" : "a CoupledPinned body";
        if (row.tokens.size() < 14) {
            return f.fail(std::string(what) + " has the fields ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* "
                          "Ca*; this row has " + std::to_string(row.tokens.size()));
        }
        b.mass = f.non_negative(8, "Mass");
        b.volume = f.non_negative(11, "Volume");
        if (!f.ok() || !vector_field(f, row, 9, "CG", true, b.cg) || !vector_field(f, row, 10, "I", false, b.inertia) ||
            !drag_field(f, row, 12, b.CdA) || !vector_field(f, row, 13, "Ca", false, b.Ca))
            return false;
        std::copy(b.cg, b.cg + 3, b.cb);  // MoorDyn's body: its buoyancy at its centre of gravity
        // a pinned body's rods may give it the inertia it lacks: checked once they are added (rods_into_bodies)
        if (b.kind == BodyKind::Free && !free_body_plausible(f, row, b)) return false;
    }
    if (f.ok() && b.kind == BodyKind::Coupled && row.tokens.size() > 8) {
        notes.push_back(at_line(row.number, "the mass, inertia, volume and drag of coupled body " + std::to_string(b.id) +
                                                " ignored (its motion is given by the body[k].* inputs; the lines' load "
                                                "on it is the output)"));
    }
    return f.ok();
}

}  // namespace deck
}  // namespace uc
