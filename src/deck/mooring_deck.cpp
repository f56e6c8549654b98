// mooring_deck.cpp - a mooring system from a MoorDyn v2 deck (docs/systems_mooring.md): the deck's tables
// (deck/tables.cpp) walked into lines from their fairleads on coupled bodies, coupled points or free nodes
// to their far ends, and each line's parameters.
#include "deck/line_file.h"

#include <algorithm>
#include <cmath>

#include "deck/tables.h"

namespace uc {
using namespace deck;
namespace {

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
            if (b.kind == BodyKind::Free || b.kind == BodyKind::Pinned) {  // a free node: at its position in the body's frame
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
    // a rod on a body, a rod pinned to the ground (a pinned body), or a free rod of non-zero length (a free body)
    if (const auto& rods = sections[static_cast<size_t>(Kind::Rods)]) {
        for (const Row& row : rods->rows) {
            if (row.tokens.size() < 10) continue;
            const std::string kind = upper(row.tokens[2]);
            if (kind.rfind("BODY", 0) == 0) return true;
            if (is_one_of(kind, {"FREE", "POINT", "CON"}) && row.tokens[9] != "0") return true;
            if (is_one_of(kind, {"PINNED", "PIN"})) return true;
        }
    }
    return false;
}

namespace {

// The BODIES rows of a system's deck; out.bodies (the coupled bodies' count) and out.bodiesSection set.
bool read_bodies(const Deck& deck, std::vector<DeckBody>& bodies, MooringDeck& out, std::string& error) {
    for (const Row& row : deck.bodies) {
        DeckBody b;
        if (!read_body(row, static_cast<int>(bodies.size()) + 1, b, out.notes, error)) return false;
        bodies.push_back(b);
        // a CoupledPinned body's reference point is moved by its body[k] inputs too
        if (b.kind == BodyKind::Coupled || b.kind == BodyKind::Pinned) out.bodies = std::max(out.bodies, b.id);
        if (b.kind == BodyKind::Pinned && b.id > UC_MAX_BODIES) {
            error = at_line(b.row, "CoupledPinned body " + std::to_string(b.id) + ": the bodies' inputs body[k].* go up "
                                   "to k = " + std::to_string(UC_MAX_BODIES));
            return false;
        }
    }
    out.bodiesSection = !bodies.empty();
    return true;
}

// The deck's points and bodies by the role they play in a system: which of them are free nodes (nodeOf:
// a Free point where three or more lines meet; bodyNode: a Free body), which are held by the importer
// (coupled) and which are fixed.
struct Roles {
    const Deck& deck;
    const std::vector<DeckBody>& bodies;
    std::vector<int> nodeOf, bodyNode;  // index into MooringDeck::nodes, -1 where none

    bool on_free_body(int q) const {
        const Point& p = deck.points[q];
        return p.kind == PointKind::Body && p.body >= 1 && p.body <= static_cast<int>(bodies.size()) &&
               (bodies[p.body - 1].kind == BodyKind::Free || bodies[p.body - 1].kind == BodyKind::Pinned);
    }
    void node_end(int q, MooringEnd& end) const {
        end = MooringEnd();
        end.kind = MooringEnd::Kind::Node;
        end.node = nodeOf[q];
        std::copy(deck.points[q].position, deck.points[q].position + 3, end.position);
    }
    bool fixed_end(int q) const {
        const Point& p = deck.points[q];
        return p.kind == PointKind::Fixed || (p.kind == PointKind::Body && p.body >= 1 &&
                                              p.body <= static_cast<int>(bodies.size()) &&
                                              bodies[p.body - 1].kind == BodyKind::Fixed);
    }
    // a point held by the importer: a Vessel/Coupled point or a point on a Coupled body
    bool coupled(int q) const {
        const PointKind kind = deck.points[q].kind;
        return kind == PointKind::Vessel || (kind == PointKind::Body && !on_free_body(q) && !fixed_end(q));
    }
};

// The system's free nodes: Free points where three or more lines meet, then Free bodies (six unknowns).
void add_free_nodes(Roles& roles, std::vector<MooringNode>& nodes) {
    const Deck& deck = roles.deck;
    roles.nodeOf.assign(deck.points.size(), -1);
    for (size_t i = 0; i < deck.points.size(); ++i) {
        const Point& p = deck.points[i];
        if (p.kind != PointKind::Free || p.lines.size() < 3) continue;
        roles.nodeOf[i] = static_cast<int>(nodes.size());
        MooringNode node;
        node.point = point_body(p, deck.waterDensity);
        std::copy(p.position, p.position + 3, node.position);
        nodes.push_back(node);
    }
    roles.bodyNode.assign(roles.bodies.size(), -1);
    for (const DeckBody& b : roles.bodies) {
        if (b.kind != BodyKind::Free && b.kind != BodyKind::Pinned) continue;
        roles.bodyNode[b.id - 1] = static_cast<int>(nodes.size());
        MooringNode node;
        node.body = true;
        node.pinned = b.kind == BodyKind::Pinned;
        if (node.pinned) {  // held on body pinBody at pinAt in its frame (coupled, or free: a node), or fixed at pinAt
            node.pin.kind = b.pinBody > 0 ? MooringEnd::Kind::Body : MooringEnd::Kind::Fixed;
            node.pin.body = b.pinBody;
            if (b.pinBody > 0 && roles.bodies[b.pinBody - 1].kind == BodyKind::Free) {  // (listed before it)
                node.pin.kind = MooringEnd::Kind::Node;
                node.pin.node = roles.bodyNode[b.pinBody - 1];
            }
            std::copy(b.pinAt, b.pinAt + 3, node.pin.position);
        }
        node.rods = b.rods;
        std::copy(b.cb, b.cb + 3, node.cb);
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
        node.rodLength = b.rodLength;
        nodes.push_back(node);
    }
}

// One of our lines from point `start` of deck line `first`: the chain of deck lines through Free points
// that join two lines, to a Fixed point, another coupled end, a free node or a Free point at its end.
// pass 1 starts it on a free node. The deck lines it takes are marked in `used`.
bool walk_line(const Roles& roles, size_t first, int start, int pass, int elementsPerLine, bool bodiesSection,
               std::vector<bool>& used, MooringDeckLine& line, std::string& error) {
    const Deck& deck = roles.deck;
    const Line& l0 = deck.lines[first];
    line.id = l0.id;
    line.row = l0.row;
    line.fairleadPoint = deck.points[start].id;
    if (pass == 1 && roles.nodeOf[start] >= 0) {
        roles.node_end(start, line.fairlead);
    } else if (!mooring_end(deck.points[start], roles.bodies, roles.bodyNode, bodiesSection, line.fairlead, error)) {
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
        const int fairlead = roles.coupled(l.end[1]) ? l.end[1] : roles.coupled(l.end[0]) ? l.end[0] : from;
        line.flipped.push_back(fairlead == point);
        const Point& p = deck.points[point];
        if (p.kind != PointKind::Free || p.lines.size() > 2) line.farPoint = p.id;
        if (p.kind != PointKind::Free) {
            if (!mooring_end(p, roles.bodies, roles.bodyNode, bodiesSection, line.far, error)) return false;
            break;
        }
        if (p.lines.size() == 1) {  // a free far end: a towed body, or none
            line.farFree = true;
            line.farBody = point_body(p, deck.waterDensity);
            break;
        }
        if (p.lines.size() > 2) {  // a free node: the line ends there
            roles.node_end(point, line.far);
            break;
        }
        index = p.lines[0] == index ? p.lines[1] : p.lines[0];
        if (used[index]) {
            error = at_line(p.row, "the lines through point " + std::to_string(p.id) + " form a closed loop");
            return false;
        }
        line.joints.push_back(point_body(p, deck.waterDensity));
    }
    // a line clamped to a Fixed rod at a Fixed fairlead: clamped along the rod's axis there (topEnd 1)
    const Line& l0f = deck.lines[first];
    const int e0 = l0f.end[0] == start ? 0 : 1;
    if (line.fairlead.kind == MooringEnd::Kind::Fixed && l0f.clamped[e0]) {
        line.fairleadClamped = true;
        std::copy(l0f.tangent[e0], l0f.tangent[e0] + 3, line.fairleadTangent);
    }
    if (line.sections.size() > UC_MAX_SECTIONS) {
        error = at_line(deck.lines[line.deckLines[UC_MAX_SECTIONS]].row,
                        "a chain of " + std::to_string(line.sections.size()) + " lines from point " +
                            std::to_string(deck.points[start].id) + ": at most " + std::to_string(UC_MAX_SECTIONS) +
                            " lines in a row are supported");
        return false;
    }
    return true;
}

// Every deck line is on one of our lines, and every free body holds one.
bool check_reached(const Deck& deck, const std::vector<bool>& used, const MooringDeck& out, std::string& error) {
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
        if (!node.body || node.pinned) continue;  // a pinned body is held by its pin
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
    return true;
}

}  // namespace

bool read_mooring_deck(std::string_view text, int elementsPerLine, MooringDeck& out, std::string& error,
                       const LineFileCompanions& companions) {
    out = MooringDeck();
    Deck deck;
    if (!parse_deck(text, true, companions, deck, out.notes, error)) return false;
    std::vector<DeckBody> bodies;
    if (!read_bodies(deck, bodies, out, error)) return false;
    if (!rods_into_bodies(deck, bodies, out.notes, error)) return false;
    if (deck.lines.size() > UC_MAX_LINES) {  // simulated all the same; the FMU names line[k].* up to the maximum
        out.notes.push_back(at_line(deck.lines[UC_MAX_LINES].row, "lines " + std::to_string(UC_MAX_LINES + 1) + " to " +
                                    std::to_string(deck.lines.size()) + " of the deck have no outputs line[k].* (the "
                                    "FMU's go up to k = " + std::to_string(UC_MAX_LINES) + "): they are simulated "
                                    "and load their bodies and points, their tensions are not reported"));
    }
    for (const Point& p : deck.points) {
        if (p.lines.empty()) out.notes.push_back(at_line(p.row, "point " + std::to_string(p.id) + " ignored: no line "
                                                                "is attached to it"));
    }
    Roles roles{deck, bodies, {}, {}};
    add_free_nodes(roles, out.nodes);
    // Each of our lines is a chain of the deck's lines from an end on a coupled object (or, for lines
    // no coupled object holds, on a free node; then, for lines neither holds, at a Fixed point).
    std::vector<bool> used(deck.lines.size(), false);
    for (int pass = 0; pass < 3; ++pass)
    for (size_t first = 0; first < deck.lines.size(); ++first) {
        if (used[first]) continue;
        const Line& l0 = deck.lines[first];
        int start = -1;
        for (int e : {1, 0}) {  // AttachB first: MoorDyn's usual fairlead
            if (start < 0 && (pass == 0 ? roles.coupled(l0.end[e])
                              : pass == 1 ? (roles.nodeOf[l0.end[e]] >= 0 || roles.on_free_body(l0.end[e]))
                                          : roles.fixed_end(l0.end[e])))
                start = l0.end[e];
        }
        if (start < 0) continue;  // reached from another line's coupled end or a node, or refused below
        MooringDeckLine line;
        if (!walk_line(roles, first, start, pass, elementsPerLine, out.bodiesSection, used, line, error)) return false;
        if (out.bodies == 0 && line.fairlead.kind == MooringEnd::Kind::Body) out.bodies = 1;
        out.lines.push_back(line);
    }
    if (!check_reached(deck, used, out, error)) return false;
    std::vector<std::pair<int, int>> held;
    for (const MooringDeckLine& l : out.lines) {
        if (!l.fairleadClamped) continue;
        const Line& d = deck.lines[l.deckLines[0]];
        held.emplace_back(l.deckLines[0], deck.points[d.end[0]].id == l.fairleadPoint ? 0 : 1);
    }
    note_pinned_clamps(deck, held, out.notes);
    out.deckLines = static_cast<int>(deck.lines.size());
    for (const Failure& row : deck.failures) {
        MooringFailure f;
        f.id = row.id;
        f.row = row.row;
        f.time = row.time;
        f.tension = row.tension;
        if (!resolve_failure(out, deck.points[row.point].id, row.lines, f, error)) {
            error = at_line(row.row, "failure " + std::to_string(row.id) + ": " + error);
            return false;
        }
        out.failures.push_back(f);
    }
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

bool resolve_failure(const MooringDeck& deck, int point, const std::vector<int>& deckLines, MooringFailure& f,
                     std::string& error) {
    f.ends.clear();
    for (int d : deckLines) {
        int k = -1, j = -1;
        for (size_t i = 0; i < deck.lines.size() && k < 0; ++i) {
            const auto& list = deck.lines[i].deckLines;
            const auto at = std::find(list.begin(), list.end(), d);
            if (at != list.end()) {
                k = static_cast<int>(i);
                j = static_cast<int>(at - list.begin());
            }
        }
        if (k < 0) {
            error = "there is no line " + std::to_string(d + 1) + " in the deck";
            return false;
        }
        const MooringDeckLine& l = deck.lines[k];
        const int p = point > 0 ? point : l.fairleadPoint;
        const std::string which = "line " + std::to_string(d + 1) + " at point " + std::to_string(p);
        MooringFailure::End e{k, -1, d};
        if (j == 0 && l.fairleadPoint == p) e.end = 0;
        else if (j + 1 == static_cast<int>(l.deckLines.size()) && l.farPoint == p) e.end = 1;
        if (e.end < 0) {
            error = which + ": the point joins two lines inside a chain of the system (a Free point between two "
                    "lines) or is not on the line; a failure there is not supported (docs/line_failure.md)";
            return false;
        }
        for (const MooringFailure& other : deck.failures) {
            for (const MooringFailure::End& o : other.ends) {
                if (o.line == e.line && o.end == e.end) {
                    error = which + ": that end already detaches in failure " + std::to_string(other.id);
                    return false;
                }
            }
        }
        for (const MooringFailure::End& o : f.ends) {
            if (o.line == e.line && o.end == e.end) {
                error = which + ": listed twice";
                return false;
            }
        }
        f.ends.push_back(e);
        f.point = p;
    }
    return true;
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
    line.towClamped = l.fairleadClamped;
    std::copy(l.fairleadTangent, l.fairleadTangent + 3, line.towTangent);
    p = base;
    if (!apply_line_file(line, p, error)) return false;
    // a far end on a coupled object or a free node is driven; so is an anchor a failure detaches (held at the
    // anchor until the break, then on the failure's free node)
    if (!l.farFree && (l.far.kind != MooringEnd::Kind::Fixed || l.farDetaches)) p.bottomEnd = UC_BOTTOM_EXTERNAL;
    p.mooringSystem = 0;  // each line is one line
    p.failureLine = 0;    // (the system's failures: MooringSystem)
    p.failurePoint = 0;
    p.failureTime = 0.0;
    p.failureTension = 0.0;
    p.failurePosition = 0.0;
    return true;
}

}  // namespace uc
