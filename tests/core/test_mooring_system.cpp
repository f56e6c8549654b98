// Mooring systems (src/system/mooring_system.h, the system part of src/deck/line_file.h; docs/systems_mooring.md): what
// a deck of several lines becomes, the bodies' orientation convention, the body load as the sum of the
// lines' forces, and an exact state save/restore of the whole system.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <cstring>
#include <string>
#include <vector>

#include "api/cable_api.h"
#include "chain_system_parameters.h"
#include "deck_mutation.h"
#include "deck/line_file.h"
#include "system/mooring_system.h"

namespace {

// Three chains from a platform's fairleads (Vessel points, no BODIES section: they ride body 1) to anchors;
// line 3 is two deck lines joined by a Free point with a clump weight, its lower part given anchor first.
const char* const kPlatform = R"(--------------------- MoorDyn Input File ------------------------------------
three chains on a platform
----------------------- LINE TYPES ------------------------------------------
Name     Diam      MassDen       EA    BA/-zeta    EI    Cd      Ca     CdAx   CaAx
(-)       (m)      (kg/m)        (N)    (N-s/-)    (-)   (-)     (-)    (-)    (-)
main     0.0766    113.35     7.536E8     -1.0      0    2.0     0.8    0.4    0.25
---------------------- POINTS --------------------------------
ID     Attachment  X        Y         Z      M      V       CdA   CA
(-)    (-)        (m)      (m)       (m)    (kg)   (m^3)   (m^2)  (-)
1      Fixed    418.8    725.383  -200.0     0       0       0     0
2      Fixed   -837.6      0.0    -200.0     0       0       0     0
3      Fixed    418.8   -725.383  -200.0     0       0       0     0
4      Vessel    20.434   35.393   -14.0     0       0       0     0
5      Vessel   -40.868    0.0     -14.0     0       0       0     0
6      Vessel    20.434  -35.393   -14.0     0       0       0     0
7      Free     200.0   -346.0    -190.0   20000    1.0     0.5   1.0
---------------------- LINES --------------------------------------
ID      LineType   AttachA   AttachB  UnstrLen  NumSegs   Outputs
(-)       (-)        (-)       (-)       (m)      (-)       (-)
1         main        1         4       835.35     20        -
2         main        2         5       835.35     20        -
3         main        3         7       400.0      10        -
4         main        6         7       435.35     12        -
---------------------- OPTIONS ---------------------------------------
200      WtrDpth
------------------------- need this line --------------------------------------
)";

// `text` with its first `from` replaced by `to` (`from` must be in it).
std::string edited(std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

uc::MooringDeck read_platform(int elementsPerLine = 0) {
    uc::MooringDeck deck;
    std::string error;
    EXPECT_TRUE(uc::read_mooring_deck(kPlatform, elementsPerLine, deck, error)) << error;
    return deck;
}

UCParams system_parameters() { return chain_system_parameters(); }

UCInputs platform_inputs(double x, double pitch, double vx) {
    UCInputs in;
    uc_inputs_default(&in);
    in.coupledBody[0].position[0] = x;
    in.coupledBody[0].rotation[1] = pitch;
    in.coupledBody[0].velocity[0] = vx;
    return in;
}

TEST(MooringDeck, SeveralLinesFromVesselPointsAreASystemOnBodyOne) {
    EXPECT_TRUE(uc::is_mooring_system_deck(kPlatform));
    const uc::MooringDeck deck = read_platform();
    EXPECT_EQ(deck.bodies, 1);
    EXPECT_FALSE(deck.bodiesSection);
    EXPECT_EQ(deck.deckLines, 4);
    ASSERT_EQ(deck.lines.size(), 3u);
    const uc::MooringDeckLine& l1 = deck.lines[0];
    EXPECT_EQ(l1.fairlead.kind, uc::MooringEnd::Kind::Body);
    EXPECT_EQ(l1.fairlead.body, 1);
    EXPECT_DOUBLE_EQ(l1.fairlead.position[0], 20.434);  // in the body's frame
    EXPECT_EQ(l1.far.kind, uc::MooringEnd::Kind::Fixed);
    EXPECT_DOUBLE_EQ(l1.far.position[1], 725.383);
    ASSERT_EQ(l1.sections.size(), 1u);
    EXPECT_EQ(l1.sections[0].elements, 10);  // NumSegs 20: ceil(20 / 2)
    EXPECT_EQ(read_platform(16).lines[0].sections[0].elements, 16);
}

TEST(MooringDeck, AChainThroughAFreePointIsOneLineOfSections) {
    const uc::MooringDeck deck = read_platform();
    // deck lines 3 and 4 meet at the Free point 7: one line from the fairlead (point 6) to the anchor (point 3)
    const uc::MooringDeckLine& chain = deck.lines[2];
    ASSERT_EQ(chain.sections.size(), 2u);
    EXPECT_EQ(chain.deckLines, (std::vector<int>{3, 2}));
    EXPECT_DOUBLE_EQ(chain.sections[0].length, 435.35);
    EXPECT_EQ(chain.sections[0].elements, 6);
    ASSERT_EQ(chain.joints.size(), 1u);
    EXPECT_DOUBLE_EQ(chain.joints[0].mass, 20000.0);
    EXPECT_DOUBLE_EQ(chain.joints[0].addedMass, 1.0 * 1025.0 * 1.0);  // CA rho V
    // deck line 4 has its fairlead at point 6, where our line starts; deck line 3 (points 3 and 7, neither
    // coupled) at the end nearer our fairlead, the joint: neither is turned round
    EXPECT_EQ(chain.flipped, (std::vector<bool>{false, false}));
    EXPECT_DOUBLE_EQ(chain.far.position[0], 418.8);

    UCParams p;
    std::string error;
    ASSERT_TRUE(uc::mooring_line_params(deck, 2, system_parameters(), p, error)) << error;
    EXPECT_EQ(p.nSections, 2);
    EXPECT_EQ(p.nAttachments, 1);
    EXPECT_DOUBLE_EQ(p.attachment[0].s, 435.35);
    EXPECT_EQ(p.bottomEnd, UC_BOTTOM_ANCHORED);
}

TEST(MooringDeck, WhatASystemCannotHoldIsRefusedNamingTheLine) {
    // lines 3 and 4 between free points 7 and 8 in a closed loop: nothing holds them
    const std::string point7 = "7      Free     200.0   -346.0    -190.0   20000    1.0     0.5   1.0";
    const std::string lines = "3         main        3         7       400.0      10        -\n4         main        6         7";
    const std::string text = edited(edited(kPlatform, point7, point7 + "\n8      Free     210.0   -346.0    -190.0   0 0 0 0"),
                                    lines, "3 main 8 7 400.0 10 -\n4 main 7 8 435.35 12 -");
    uc::MooringDeck deck;
    std::string error;
    EXPECT_FALSE(uc::read_mooring_deck(text, 0, deck, error));
    EXPECT_EQ(error.rfind("line 23: line 3 is not reached from a coupled point, a free node or a Fixed point", 0), 0u)
        << error;
}

TEST(MooringDeck, ALineNoCoupledObjectHoldsRunsFromItsFixedPoint) {
    // line 4 from the anchor 2 to the clump point: lines 3 and 4 are a chain between two anchors
    const std::string text = edited(kPlatform, "4         main        6         7", "4         main        2         7");
    uc::MooringDeck deck;
    std::string error;
    ASSERT_TRUE(uc::read_mooring_deck(text, 0, deck, error)) << error;
    ASSERT_EQ(deck.lines.size(), 3u);
    const uc::MooringDeckLine& chain = deck.lines[2];
    EXPECT_EQ(chain.fairlead.kind, uc::MooringEnd::Kind::Fixed);
    EXPECT_EQ(chain.far.kind, uc::MooringEnd::Kind::Fixed);
    EXPECT_EQ(chain.sections.size(), 2u);
}

TEST(MooringDeck, AFreePointWhereThreeLinesMeetIsANodeWhereTheyEnd) {
    // line 2 to the clump point too: lines 2 (from its anchor), 3 (from its anchor) and 4 (from the
    // platform) meet at point 7
    const std::string text = edited(kPlatform, "2         main        2         5", "2         main        2         7");
    uc::MooringDeck deck;
    std::string error;
    ASSERT_TRUE(uc::read_mooring_deck(text, 0, deck, error)) << error;
    ASSERT_EQ(deck.nodes.size(), 1u);
    EXPECT_EQ(deck.nodes[0].point.id, 7);
    EXPECT_DOUBLE_EQ(deck.nodes[0].point.mass, 20000.0);
    ASSERT_EQ(deck.lines.size(), 4u);
    int atNode = 0;
    for (const uc::MooringDeckLine& l : deck.lines) {
        EXPECT_EQ(l.sections.size(), 1u);  // the node ends them: no chain runs through it
        atNode += (l.fairlead.kind == uc::MooringEnd::Kind::Node) + (l.far.kind == uc::MooringEnd::Kind::Node);
    }
    EXPECT_EQ(atNode, 3);
}

// A platform (Coupled body 1) with two chains given platform end first (AttachA): line 1 to a point on a
// Fixed body 2 (an anchor the body places, 380 m out and 166 m below the fairlead, 20 m above the seabed),
// line 2 to a point on a Free body 3 (a buoy) when `buoy`. Their fairlead is the platform's end.
std::string platform_end_first_deck(bool buoy) {
    std::string text = R"(--- MoorDyn Input File ---
chains given platform end first
----------------------- LINE TYPES ------------------------------------------
Name Diam MassDen EA BA/-zeta EI Cd Ca CdAx CaAx
(-) (m) (kg/m) (N) (N-s/-) (-) (-) (-) (-) (-)
main 0.0766 113.35 7.536E8 -1.0 0 2.0 0.8 0.4 0.25
---------------------- BODIES --------------------------------
ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*
(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)
1 Coupled 0 0 0 0 0 0 0 0 0 0 0 0
2 Fixed 400 0 -180 0 0 0 0 0 0 0 0 0
)";
    if (buoy) text += "3 Free 0 150 -80 0 0 0 10000 0 20000 60 6 1\n";
    text += R"(---------------------- POINTS --------------------------------
ID Attachment X Y Z M V CdA CA
(-) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Body1 20 0 -14 0 0 0 0
2 Body2 0 0 0 0 0 0 0
)";
    if (buoy) text += "3 Body1 0 20 -14 0 0 0 0\n4 Body3 0 0 1.5 0 0 0 0\n";
    text += "---------------------- LINES --------------------------------------\n"
            "ID LineType AttachA AttachB UnstrLen NumSegs Outputs\n(-) (-) (-) (-) (m) (-) (-)\n"
            "1 main 1 2 420.0 20 -\n";
    if (buoy) text += "2 main 3 4 140.0 20 -\n";
    return text + "---------------------- OPTIONS ---------------------------------------\n200 WtrDpth\n"
                  "------------------------- need this line --------------------------------------\n";
}

TEST(MooringDeck, ALinesFairleadIsItsEndOnTheCoupledBodyNotOnAFixedOrFreeBody) {
    uc::MooringDeck deck;
    std::string error;
    ASSERT_TRUE(uc::read_mooring_deck(platform_end_first_deck(true), 0, deck, error)) << error;
    ASSERT_EQ(deck.lines.size(), 2u);
    for (const uc::MooringDeckLine& l : deck.lines) {
        EXPECT_EQ(l.fairlead.kind, uc::MooringEnd::Kind::Body) << "line " << l.id;
        EXPECT_EQ(l.fairlead.body, 1) << "line " << l.id;
        // the walk starts at the platform, as does the deck line: not turned round
        EXPECT_EQ(l.flipped, (std::vector<bool>{false})) << "line " << l.id;
    }
}

TEST(MooringSystem, AChainToAFixedBodysPointIsTautestAtThePlatform) {
    // Hanging clear of the seabed, the chain's tension grows upwards by its weight in water per metre times
    // the height: dT/dz = w / (1 + T/EA), w = (113.35 kg/m - rho pi d^2/4) g. The fairlead, 166 m above
    // the anchor, is the tauter end; the chain's strain T/EA (under 0.2 %) bounds the difference from w 166 m.
    constexpr double kPi = 3.14159265358979323846;
    const double w = (113.35 - 1025.0 * kPi / 4.0 * 0.0766 * 0.0766) * 9.80665, rise = w * 166.0;
    uc::MooringDeck deck;
    std::string error;
    ASSERT_TRUE(uc::read_mooring_deck(platform_end_first_deck(false), 0, deck, error)) << error;
    uc::MooringSystem system(system_parameters(), deck);
    ASSERT_TRUE(system.build(error)) << error;
    UCInputs in;
    uc_inputs_default(&in);
    ASSERT_TRUE(system.initialize(0.0, in, error)) << error;
    const UCMooringLine& line = system.outputs().mooringLine[0];
    EXPECT_LT(line.fairleadTension / 7.536e8, 2e-3);
    EXPECT_NEAR(line.fairleadTension - line.anchorTension, rise, 5e-3 * rise)
        << "fairlead " << line.fairleadTension << " N, anchor " << line.anchorTension << " N";
}

// A deck's title and its LINE TYPES table of one type, `leg`, of diameter d and axial stiffness EA,
// weightless in water (its mass that of the water it displaces, 1025 kg/m3).
std::string weightless_leg_deck(const char* title, double d, double EA) {
    constexpr double kPi = 3.14159265358979323846, kRho = 1025.0;
    char row[512];
    std::snprintf(row, sizeof row, "leg %.17g %.17g %.17g -1.0 0 1.2 1.0 0.05 0.0\n", d, kRho * kPi / 4.0 * d * d, EA);
    return std::string("--- MoorDyn Input File ---\n") + title +
           "\n----------------------- LINE TYPES ------------------------------------------\n"
           "Name Diam MassDen EA BA/-zeta EI Cd Ca CdAx CaAx\n(-) (m) (kg/m) (N) (N-s/-) (-) (-) (-) (-) (-)\n" + row;
}

// Three weightless elastic legs (their mass that of the water they displace) from anchors on a circle to a
// buoy: straight legs, 30 m across and 40 m up, 50 m long. With the unstretched length L each pulls with
// T = EA (50 / L - 1), and the buoy is in equilibrium there when its net buoyancy is 3 T 40/50. As a free
// point the legs meet at it (anchors 30 m out, the point 40 m above them); as a free body (its centre of
// gravity 1 m below its reference point) they hold its rim 2 m out and 1 m down (anchors 32 m out, the
// reference point 41 m above them), and it stands upright.
struct WeightlessLegs {
    static constexpr double kPi = 3.14159265358979323846, kRho = 1025.0, kG = 9.80665, kEA = 1e7, kL = 49.9;
    double tension = kEA * (50.0 / kL - 1.0), buoyancy = 3.0 * tension * 0.8;

    std::string deck(bool body) const {
        const double d = 0.05, mass = body ? 2000.0 : 0.0, volume = (buoyancy / kG + mass) / kRho;
        const double radius = body ? 32.0 : 30.0;
        std::string text = weightless_leg_deck("three weightless legs", d, kEA);
        char row[512];
        if (body) {
            text += "---------------------- BODIES ----\nID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*\n"
                    "(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)\n";
            // the deck's guess: 3.6 m to the side, 9 m low, turned by 5, -3 and 10 degrees
            std::snprintf(row, sizeof row, "1 Free 3.0 -2.0 -50.0 5 -3 10 %.17g 0|0|-1 1000 %.17g 1.0 1.0\n", mass, volume);
            text += row;
        }
        text += "---------------------- POINTS --------------------------------\nID Attachment X Y Z M V CdA CA\n"
                "(-) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)\n";
        for (int k = 0; k < 3; ++k) {
            const double a = 2.0 * kPi * k / 3.0;
            std::snprintf(row, sizeof row, "%d Fixed %.17g %.17g -100.0 0 0 0 0\n", k + 1, radius * std::cos(a),
                          radius * std::sin(a));
            text += row;
        }
        for (int k = 0; body && k < 3; ++k) {
            const double a = 2.0 * kPi * k / 3.0;
            std::snprintf(row, sizeof row, "%d Body1 %.17g %.17g -1.0 0 0 0 0\n", k + 4, 2.0 * std::cos(a), 2.0 * std::sin(a));
            text += row;
        }
        if (!body) {  // the deck's guess: 3.6 m to the side, 10 m low
            std::snprintf(row, sizeof row, "4 Free 3.0 -2.0 -50.0 0 %.17g 1.0 1.0\n", volume);
            text += row;
        }
        text += "---------------------- LINES --------------------------------------\n"
                "ID LineType AttachA AttachB UnstrLen NumSegs Outputs\n(-) (-) (-) (-) (m) (-) (-)\n";
        for (int k = 0; k < 3; ++k) {
            std::snprintf(row, sizeof row, "%d leg %d %d %.17g 10 -\n", k + 1, k + 1, body ? k + 4 : 4, kL);
            text += row;
        }
        return text + "---------------------- OPTIONS ---------------------------------------\n100 WtrDpth\n"
                      "------------------------- need this line --------------------------------------\n";
    }

    // The system of the deck, initialized (its statics solved).
    std::unique_ptr<uc::MooringSystem> solve(bool body) const {
        uc::MooringDeck read;
        std::string error;
        EXPECT_TRUE(uc::read_mooring_deck(deck(body), 0, read, error)) << error;
        auto system = std::make_unique<uc::MooringSystem>(system_parameters(), read);
        EXPECT_TRUE(system->build(error)) << error;
        UCInputs in;
        uc_inputs_default(&in);
        EXPECT_TRUE(system->initialize(0.0, in, error)) << error;
        return system;
    }

    // The node over the middle of the anchors at height z, the lines' tensions T, the residual left small.
    void expect_solution(const uc::MooringSystem& system, double z) const {
        ASSERT_EQ(system.n_nodes(), 1);
        const uc::Vec3 x = system.node_position(0);
        EXPECT_LT((x - uc::Vec3(0.0, 0.0, z)).cwiseAbs().maxCoeff(), 1e-5) << x.transpose();
        expect_tensions(system.outputs());
        EXPECT_LE(system.node_residual_norm(), 1e-6 * buoyancy);
    }

    void expect_tensions(const UCOutputs& o) const {
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(o.mooringLine[k].fairleadTension, tension, 1e-6 * tension) << "line " << k + 1;
            EXPECT_NEAR(o.mooringLine[k].anchorTension, tension, 1e-6 * tension) << "line " << k + 1;
        }
    }
};

TEST(MooringSystem, FreePointStaticsOfASymmetricBuoyHaveTheClosedFormAnswer) {
    const WeightlessLegs legs;
    const auto system = legs.solve(false);
    legs.expect_solution(*system, -60.0);
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(system->outputs().pointLoad[3].position[c], system->node_position(0)[c]);
}

TEST(MooringSystem, FreeBodyStaticsOfASymmetricBuoyHaveTheClosedFormAnswer) {
    const WeightlessLegs legs;
    const auto system = legs.solve(true);
    legs.expect_solution(*system, -59.0);
    EXPECT_LT((system->node_rotation(0) - uc::Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-6);  // upright, unturned
    const UCBodyLoad& pose = system->outputs().bodyLoad[0];
    for (int c = 0; c < 3; ++c) {
        EXPECT_DOUBLE_EQ(pose.posePosition[c], system->node_position(0)[c]);
        EXPECT_NEAR(pose.poseAngles[c], 0.0, 1e-6);
    }
}

TEST(MooringDeck, AFreeBodysDragAreasAndAddedMassAreReadPerAxisAsMoorDynDocumentsThem) {
    // CdA*: one value for all six directions, two (translations, rotations), three (per axis, for both) or
    // six; Ca*: one value or three (translations in the body's axes)
    const WeightlessLegs legs;
    const std::string text = legs.deck(true), row = " 1.0 1.0\n";  // the body row ends with CdA* Ca*
    const size_t at = text.find(row);
    ASSERT_NE(at, std::string::npos);
    const struct {
        const char* fields;
        double CdA[6], Ca[3];
    } cases[] = {{" 2 0.5\n", {2, 2, 2, 2, 2, 2}, {0.5, 0.5, 0.5}},
                 {" 2|7 1|2|3\n", {2, 2, 2, 7, 7, 7}, {1, 2, 3}},
                 {" 1|2|3 1\n", {1, 2, 3, 1, 2, 3}, {1, 1, 1}},
                 {" 1|2|3|4|5|6 1\n", {1, 2, 3, 4, 5, 6}, {1, 1, 1}}};
    for (const auto& c : cases) {
        std::string deck = text;
        deck.replace(at, row.size(), c.fields);
        uc::MooringDeck read;
        std::string error;
        ASSERT_TRUE(uc::read_mooring_deck(deck, 0, read, error)) << c.fields << error;
        ASSERT_EQ(read.nodes.size(), 1u);
        for (int k = 0; k < 6; ++k) EXPECT_EQ(read.nodes[0].CdA[k], c.CdA[k]) << c.fields << " CdA " << k;
        for (int k = 0; k < 3; ++k) EXPECT_EQ(read.nodes[0].Ca[k], c.Ca[k]) << c.fields << " Ca " << k;
    }
    const std::pair<const char*, const char*> wrong[] = {{" 1|2|3|4 1\n", "CdA '1|2|3|4'"}, {" 1 1|2\n", "Ca '1|2'"}};
    for (const auto& [fields, named] : wrong) {
        std::string deck = text;
        deck.replace(at, row.size(), fields);
        uc::MooringDeck read;
        std::string error;
        EXPECT_FALSE(uc::read_mooring_deck(deck, 0, read, error)) << fields;
        EXPECT_NE(error.find(named), std::string::npos) << error;
    }
}

TEST(MooringDeck, AFreeBodysImplausibleInertiaDragAddedMassOrMassAndVolumeAreRefusedNamingTheRowAndValue) {
    // the body row of the deck, rewritten field by field (Mass CG* I* Volume CdA* Ca*)
    const WeightlessLegs legs;
    const std::string text = legs.deck(true), head = "1 Free 3.0 -2.0 -50.0 5 -3 10 ";
    const size_t at = text.find(head), end = text.find('\n', at);
    ASSERT_NE(at, std::string::npos);
    const size_t rowNumber = static_cast<size_t>(std::count(text.begin(), text.begin() + at, '\n')) + 1;
    auto with = [&](const std::string& fields) {
        std::string deck = text;
        deck.replace(at, end - at, head + fields);
        return deck;
    };
    uc::MooringDeck read;
    std::string error;
    ASSERT_TRUE(uc::read_mooring_deck(with("2000 0|0|-1 1000 20 1.0 1.0"), 0, read, error)) << error;
    const std::pair<const char*, const char*> refused[] = {
        {"2000 0|0|-1 -1000 20 1.0 1.0", "I = -1000: Free body 1's moment of inertia about its x axis is -1000 kg m2"},
        {"2000 0|0|-1 1000|0|1000 20 1.0 1.0",
         "I = 1000|0|1000: Free body 1's moment of inertia about its y axis is 0 kg m2"},
        {"2000 0|0|-1 1000 20 -1.0 1.0", "CdA = -1.0: Free body 1's drag area in x is -1 m2"},
        {"2000 0|0|-1 1000 20 1|1|1|1|1|-2 1.0", "drag area in rotation about z is -2 m2"},
        {"2000 0|0|-1 1000 20 1.0 1|-0.5|1", "Ca = 1|-0.5|1: Free body 1's added-mass coefficient in y is -0.5"},
        {"0 0|0|-1 1000 0 1.0 1.0", "Mass = 0 kg and Volume = 0 m3: Free body 1 has neither mass nor volume"},
        {"-5 0|0|-1 1000 20 1.0 1.0", "Mass = -5: must not be negative"},
    };
    for (const auto& [fields, named] : refused) {
        EXPECT_FALSE(uc::read_mooring_deck(with(fields), 0, read, error)) << fields;
        EXPECT_NE(error.find("line " + std::to_string(rowNumber) + ": "), std::string::npos) << fields << ": " << error;
        EXPECT_NE(error.find(named), std::string::npos) << fields << ": " << error;
    }
    // a buoy of no mass (its volume gives it inertia through the added mass and a weight) is a body
    EXPECT_TRUE(uc::read_mooring_deck(with("0 0|0|-1 1000 20 1.0 1.0"), 0, read, error)) << error;
}

TEST(MooringDeck, AFreePointsNegativeMassVolumeDragOrAddedMassAreRefusedNamingTheRowAndValue) {
    // (no mass and no volume is a plain connection point: accepted, as MoorDyn's)
    const std::string head = "7      Free     200.0   -346.0    -190.0   ", row = head + "20000    1.0     0.5   1.0";
    const std::pair<std::string, const char*> refused[] = {
        {head + "-20000    1.0     0.5   1.0", "line 16: Mass = -20000: must not be negative"},
        {head + "20000    -1.0     0.5   1.0", "line 16: Volume = -1.0: must not be negative"},
        {head + "20000    1.0     -0.5   1.0", "line 16: CdA = -0.5: must not be negative"},
        {head + "20000    1.0     0.5   -1.0", "line 16: CA = -1.0: must not be negative"},
    };
    uc::MooringDeck read;
    std::string error;
    for (const auto& [to, named] : refused) {
        EXPECT_FALSE(uc::read_mooring_deck(edited(kPlatform, row, to), 0, read, error)) << to;
        EXPECT_NE(error.find(named), std::string::npos) << error;
    }
    EXPECT_TRUE(uc::read_mooring_deck(edited(kPlatform, row, head + "0 0 0 0"), 0, read, error)) << error;
}

// A bridle of weightless straight lines (their mass that of the water they displace): a pennant from the
// platform's fairlead a = (40, 0, -20) down to a buoyant free point at (0, 0, -50), two legs from there to
// anchors at (-30, +-40, -80). The lengths make the tensions T0 = 2 kN in the pennant and T1 = 0.8 T0 l1 / 60
// in each leg (l the stretched lengths, 50 and sqrt(3400) m), which the point's net buoyancy 0.2 T0 balances.
// A straight elastic string's end stiffness is (EA / L) n n^T + (T / l) (I - n n^T) (n its direction): with
// the free point re-balanced the fairlead's is the pennant's P in series with the legs',
// K_p = P - P (P + L1 + L2)^-1 P. Body 1's 6x6 stiffness about its reference point (the origin) follows from
// the fairlead's motion x + theta x a and the moment a x f of its force f = -T0 n0:
// [[K_p, -K_p [a]x], [[a]x K_p, -[a]x K_p [a]x - [f]x [a]x]].
struct StringBridle {
    static constexpr double kRho = 1025.0, kG = 9.80665, kEA = 1e7, kD = 0.05, kT0 = 2000.0;
    const uc::Vec3 node{0.0, 0.0, -50.0};
    const std::vector<uc::Vec3> ends = {{40.0, 0.0, -20.0}, {-30.0, 40.0, -80.0}, {-30.0, -40.0, -80.0}};
    const double l1 = (ends[1] - node).norm();
    const double T[3] = {kT0, 0.8 * kT0 * l1 / 60.0, 0.8 * kT0 * l1 / 60.0};

    // The system initialized with the point where the deck puts it, at `start` (TmaxIC 0: the system's statics
    // leave it there, and the stiffness re-balances it).
    std::unique_ptr<uc::MooringSystem> start_at(const uc::Vec3& start) const {
        std::string text = weightless_leg_deck("a bridle of weightless strings", kD, kEA);
        char row[512];
        text += "---------------------- POINTS --------------------------------\nID Attachment X Y Z M V CdA CA\n"
                "(-) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)\n";
        for (int k = 0; k < 3; ++k) {
            std::snprintf(row, sizeof row, "%d %s %.17g %.17g %.17g 0 0 0 0\n", k + 1, k == 0 ? "Vessel" : "Fixed",
                          ends[k].x(), ends[k].y(), ends[k].z());
            text += row;
        }
        std::snprintf(row, sizeof row, "4 Free %.17g %.17g %.17g 0 %.17g 0 0\n", start.x(), start.y(), start.z(),
                      0.2 * kT0 / (kRho * kG));
        text += row;
        text += "---------------------- LINES --------------------------------------\n"
                "ID LineType AttachA AttachB UnstrLen NumSegs Outputs\n(-) (-) (-) (-) (m) (-) (-)\n";
        for (int k = 0; k < 3; ++k) {
            std::snprintf(row, sizeof row, "%d leg %d 4 %.17g 10 -\n", k + 1, k + 1,
                          (ends[k] - node).norm() / (1.0 + T[k] / kEA));
            text += row;
        }
        text += "---------------------- OPTIONS ---------------------------------------\n100 WtrDpth\n0 TmaxIC\n"
                "------------------------- need this line --------------------------------------\n";
        uc::MooringDeck deck;
        std::string error;
        EXPECT_TRUE(uc::read_mooring_deck(text, 0, deck, error)) << error;
        auto system = std::make_unique<uc::MooringSystem>(system_parameters(), deck);
        EXPECT_TRUE(system->build(error)) << error;
        UCInputs in;
        uc_inputs_default(&in);
        EXPECT_TRUE(system->initialize(0.0, in, error)) << error;
        EXPECT_LT((system->node_position(0) - start).norm(), 1e-12);
        return system;
    }

    Eigen::Matrix<double, 6, 6> expected() const {
        auto string = [&](int k) -> uc::Mat3 {
            const uc::Vec3 n = (ends[k] - node).normalized();
            const double l = (ends[k] - node).norm(), L = l / (1.0 + T[k] / kEA);
            return kEA / L * n * n.transpose() + T[k] / l * (uc::Mat3::Identity() - n * n.transpose());
        };
        const uc::Mat3 P = string(0), legs = string(1) + string(2);
        const uc::Mat3 Kp = P - P * (P + legs).inverse() * P;
        const uc::Vec3 a = ends[0], f = -T[0] * (ends[0] - node).normalized();
        Eigen::Matrix<double, 6, 6> K;
        K << Kp, -Kp * uc::skew(a), uc::skew(a) * Kp, -uc::skew(a) * Kp * uc::skew(a) - uc::skew(f) * uc::skew(a);
        return K;
    }
};

TEST(MooringSystem, TheStiffnessWithAFreePointRebalancedIsTheStringsInSeries) {
    const StringBridle bridle;
    // 4 mm from its balance (further off than the 1 cm the strings stretch, one would slacken)
    const auto system = bridle.start_at(bridle.node + uc::Vec3(0.003, 0.002, -0.002));
    system->update_stiffness();
    EXPECT_EQ(system->take_event(), "");
    const double* K = system->outputs().bodyLoad[0].stiffness;
    const Eigen::Matrix<double, 6, 6> expected = bridle.expected();
    // central differences of exact profiles: truncation (1 mm / 50 m)^2; the profiles' closure (1e-11 of the
    // length: 5e-10 m, 1e-4 N on the strings' axial stiffness EA / L = 2e5 N/m) over the 2 mm difference: 0.05 N/m
    const double arm = bridle.ends[0].norm();
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
            const double arms = (i < 3 ? 1.0 : arm) * (j < 3 ? 1.0 : arm);
            EXPECT_NEAR(K[6 * i + j], expected(i, j), 0.05 * arms + 1e-6 * std::abs(expected(i, j)))
                << "K[" << i + 1 << "," << j + 1 << "]";
        }
}

TEST(MooringSystem, AStiffnessThatIsNotFoundIsZeroAndTheEventSaysWhy) {
    const StringBridle bridle;
    // 2.4 m off its balance the pennant is slack: a weightless slack line has no profile
    const auto system = bridle.start_at(bridle.node + uc::Vec3(2.0, 1.0, 1.0));
    system->update_stiffness();
    const std::string event = system->take_event();
    EXPECT_NE(event.find("body[1].stiffness is 0"), std::string::npos) << event;
    EXPECT_NE(event.find("mooring line 1"), std::string::npos) << event;
    for (int i = 0; i < 36; ++i) EXPECT_EQ(system->outputs().bodyLoad[0].stiffness[i], 0.0);
    system->update_stiffness();  // reported once
    EXPECT_EQ(system->take_event(), "");
}

// The rotations about x, y and z by the angles r, p, y, written out.
struct AxisRotations {
    uc::Mat3 Rx, Ry, Rz;
    AxisRotations(double r, double p, double y) {
        Rx << 1, 0, 0, 0, std::cos(r), -std::sin(r), 0, std::sin(r), std::cos(r);
        Ry << std::cos(p), 0, std::sin(p), 0, 1, 0, -std::sin(p), 0, std::cos(p);
        Rz << std::cos(y), -std::sin(y), 0, std::sin(y), std::cos(y), 0, 0, 0, 1;
    }
};

TEST(MooringSystem, BodyOrientationIsMoorDynsRollPitchYaw) {
    const double r = 0.3, p = -0.2, y = 1.1;
    const AxisRotations a(r, p, y);
    EXPECT_LT((uc::body_rotation(r, p, y) - a.Rx * a.Ry * a.Rz).norm(), 1e-15);
}

TEST(MooringSystem, ACoupledBodysOrientationIsReadAsBodyOrientationSays) {
    const double r = 0.3, p = -0.2, y = 1.1;
    const AxisRotations a(r, p, y);
    const uc::Mat3 &Rx = a.Rx, &Ry = a.Ry, &Rz = a.Rz;
    UCCoupledBody body{};
    body.rotation[0] = r, body.rotation[1] = p, body.rotation[2] = y;
    // the quaternion of Rx Ry Rz: the product of the three half-angle quaternions, scaled by 1.004
    const Eigen::Quaterniond q = Eigen::Quaterniond(Eigen::AngleAxisd(r, uc::Vec3::UnitX())) *
                                 Eigen::Quaterniond(Eigen::AngleAxisd(p, uc::Vec3::UnitY())) *
                                 Eigen::Quaterniond(Eigen::AngleAxisd(y, uc::Vec3::UnitZ()));
    body.quaternion[0] = 1.004 * q.w(), body.quaternion[1] = 1.004 * q.x();
    body.quaternion[2] = 1.004 * q.y(), body.quaternion[3] = 1.004 * q.z();
    EXPECT_EQ(uc::coupled_body_rotation(body, UC_ORIENTATION_ANGLES_XYZ), uc::body_rotation(r, p, y));
    EXPECT_LT((uc::coupled_body_rotation(body, UC_ORIENTATION_QUATERNION) - Rx * Ry * Rz).norm(), 1e-15);
    EXPECT_LT((uc::coupled_body_rotation(body, UC_ORIENTATION_ANGLES_ZYX) - Rz * Ry * Rx).norm(), 1e-15);
    EXPECT_GT((Rz * Ry * Rx - Rx * Ry * Rz).norm(), 0.1);  // two different rotations at these angles
}

TEST(MooringSystem, TheBodyLoadIsTheLinesForcesAndTheirMomentAboutTheReference) {
    uc::MooringSystem system(system_parameters(), read_platform());
    std::string error;
    ASSERT_TRUE(system.build(error)) << error;
    const UCInputs in = platform_inputs(3.0, 0.02, 0.0);
    ASSERT_TRUE(system.initialize(0.0, in, error)) << error;
    uc::Vec3 force = uc::Vec3::Zero(), moment = uc::Vec3::Zero();
    const uc::Vec3 reference(3.0, 0.0, 0.0);
    for (int k = 0; k < system.n_lines(); ++k) {
        const UCOutputs& o = system.line(k).outputs();
        const uc::Vec3 f(o.towForce[0], o.towForce[1], o.towForce[2]);
        force += f;
        moment += (system.line(k).tow_position() - reference).cross(f);
    }
    const UCBodyLoad& load = system.outputs().bodyLoad[0];
    for (int c = 0; c < 3; ++c) {
        EXPECT_DOUBLE_EQ(load.force[c], force[c]);
        EXPECT_NEAR(load.moment[c], moment[c], 1e-9 * moment.norm());
    }
    // deck line 3's anchor tension is at the joint (the clump): above it the tension is higher by about the
    // clump's submerged weight (20 t less 1 m3 of water, 186 kN) along the line there
    const UCMooringLine* lines = system.outputs().mooringLine;
    EXPECT_GT(lines[3].anchorTension, lines[2].fairleadTension);
    EXPECT_GT(lines[2].fairleadTension, 0.0);
    EXPECT_DOUBLE_EQ(lines[3].fairleadTension, system.line(2).outputs().towTension);
    EXPECT_DOUBLE_EQ(lines[2].anchorTension, system.line(2).outputs().endTension);
}

TEST(MooringSystem, ASavedStateContinuesBitForBit) {
    uc::MooringSystem system(system_parameters(), read_platform());
    std::string error;
    ASSERT_TRUE(system.build(error)) << error;
    ASSERT_TRUE(system.initialize(0.0, platform_inputs(0.0, 0.0, 0.0), error)) << error;
    double t = 0.0;
    auto step = [&](int k) {
        const double tt = 0.2 * k;
        ASSERT_TRUE(system.step(t, 0.2, platform_inputs(std::sin(0.3 * tt), 0.01 * std::sin(0.2 * tt),
                                                        0.3 * std::cos(0.3 * tt)), error))
            << error;
        t += 0.2;
    };
    for (int k = 0; k < 5; ++k) step(k);
    std::vector<unsigned char> state(system.state_size());
    system.save_state(state.data());
    const double saved = t;
    for (int k = 5; k < 10; ++k) step(k);
    const UCOutputs first = system.outputs();
    ASSERT_TRUE(system.restore_state(state.data(), state.size(), error)) << error;
    t = saved;
    for (int k = 5; k < 10; ++k) step(k);
    EXPECT_EQ(std::memcmp(&first, &system.outputs(), sizeof first), 0);
    EXPECT_FALSE(system.restore_state(state.data(), state.size() - 8, error));
}

// The platform (a Coupled body) with its first leg through a subsurface buoy (a Free body: a pennant to its top,
// two chains from its rim to anchors) and its third leg through a clump (a Free point where three lines meet):
// both free nodes move with the platform.
const char* const kPlatformFreeNodes = R"(--------------------- MoorDyn Input File ------------------------------------
the platform with a free body and a free point
----------------------- LINE TYPES ------------------------------------------
Name     Diam      MassDen       EA    BA/-zeta    EI    Cd      Ca     CdAx   CaAx
(-)       (m)      (kg/m)        (N)    (N-s/-)    (-)   (-)     (-)    (-)    (-)
main     0.0766    113.35     7.536E8     -1.0      0    2.0     0.8    0.4    0.25
---------------------- BODIES --------------------------------
ID   Attachment  X0     Y0     Z0     r0    p0    y0    Mass   CG*        I*      Volume  CdA*  Ca*
(#)  (-)         (m)    (m)    (m)   (deg) (deg) (deg)  (kg)   (m)       (kg-m^2)  (m^3)   (m^2) (-)
1    Coupled     0.0    0.0    0.0    0     0     0     0      0          0        0       0     0
2    Free      150.0  259.8  -80.0    0     0     0    10000   0|0|0.0    20000    60.0    6.0   1.0
---------------------- POINTS --------------------------------
ID     Attachment  X        Y         Z      M      V       CdA   CA
(-)    (-)        (m)      (m)       (m)    (kg)   (m^3)   (m^2)  (-)
1      Fixed    641.6     538.4   -200.0     0       0       0     0
2      Fixed   -837.6      0.0    -200.0     0       0       0     0
3      Fixed    418.8   -725.383  -200.0     0       0       0     0
4      Body1     20.434   35.393   -14.0     0       0       0     0
5      Body1    -40.868    0.0     -14.0     0       0       0     0
6      Body1     20.434  -35.393   -14.0     0       0       0     0
7      Body2      0.0      0.0      1.5     0       0       0     0
8      Body2      1.532    1.286   -1.5     0       0       0     0
9      Body2      0.347    1.970   -1.5     0       0       0     0
10     Fixed    145.448   824.875   -200.0     0       0       0     0
11     Free     220.0   -380.0    -150.0   1000     8.0     0.5   1.0
12     Fixed    600.0   -250.0    -200.0     0       0       0     0
---------------------- LINES --------------------------------------
ID      LineType   AttachA   AttachB  UnstrLen  NumSegs   Outputs
(-)       (-)        (-)       (-)       (m)      (-)       (-)
1         main        4         7       280.0      8        -
2         main        2         5       835.35     8        -
3         main        6        11       425.0      10       -
4         main        1         8       600.0      8        -
5         main       10         9       600.0      8        -
6         main       11         3       405.0      10       -
7         main       11        12       408.0      10       -
---------------------- OPTIONS ---------------------------------------
200      WtrDpth
------------------------- need this line --------------------------------------
)";

// Everything a step changes is in a saved state: a state saved mid-run and restored into a new instance (which
// has nothing of the run but the state) continues as the run does, its outputs bit for bit and the state it saves
// byte for byte, with the free nodes moving (a member of a free node's motion left out of the state would
// start the new instance's next step elsewhere).
TEST(MooringSystem, AStateRestoredIntoANewInstanceContinuesBitForBitWithFreeNodesMoving) {
    uc::MooringDeck deck;
    std::string error;
    ASSERT_TRUE(uc::read_mooring_deck(kPlatformFreeNodes, 0, deck, error)) << error;
    ASSERT_EQ(deck.nodes.size(), 2u);
    auto fresh = [&] {
        auto system = std::make_unique<uc::MooringSystem>(system_parameters(), deck);
        EXPECT_TRUE(system->build(error)) << error;
        return system;
    };
    auto inputs = [](int k) {
        const double t = 0.5 * k;
        return platform_inputs(2.0 * std::sin(0.4 * t), 0.02 * std::sin(0.3 * t), 0.8 * std::cos(0.4 * t));
    };
    const auto a = fresh();
    ASSERT_TRUE(a->initialize(0.0, inputs(0), error)) << error;
    ASSERT_EQ(a->n_nodes(), 2);
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(a->step(0.5 * k, 0.5, inputs(k), error)) << error;
    std::vector<unsigned char> state(a->state_size());
    a->save_state(state.data());
    const auto b = fresh();
    ASSERT_TRUE(b->restore_state(state.data(), state.size(), error)) << error;
    for (int k = 3; k < 6; ++k) {
        const uc::Vec3 before = a->node_position(0);
        ASSERT_TRUE(a->step(0.5 * k, 0.5, inputs(k), error)) << error;
        ASSERT_TRUE(b->step(0.5 * k, 0.5, inputs(k), error)) << error;
        for (int n = 0; n < 2; ++n) EXPECT_GT(a->node_velocity(n).norm(), 0.0) << "node " << n << " moves";
        EXPECT_GT((a->node_position(0) - before).norm(), 0.0);
        ASSERT_EQ(std::memcmp(&a->outputs(), &b->outputs(), sizeof(UCOutputs)), 0) << "step " << k;
        for (int n = 0; n < 2; ++n)
            ASSERT_EQ(std::memcmp(&a->node_motion(n), &b->node_motion(n), sizeof(uc::FreeNodeMotion)), 0)
                << "node " << n << ", step " << k;
    }
    std::vector<unsigned char> stateA(a->state_size()), stateB(b->state_size());
    a->save_state(stateA.data());
    b->save_state(stateB.data());
    ASSERT_EQ(stateA.size(), stateB.size());
    EXPECT_TRUE(stateA == stateB);
}

TEST(MooringSystem, AStateIsRefusedByASystemOfAnEditedDeckNamingWhatDiffers) {
    // saved from the platform's deck, restored into systems of the deck edited: refused, naming the first
    // value that differs and both its values (a silent mix would step the state with the new lines)
    auto built = [](const std::string& text) {
        uc::MooringDeck deck;
        std::string error;
        EXPECT_TRUE(uc::read_mooring_deck(text, 0, deck, error)) << error;
        auto system = std::make_unique<uc::MooringSystem>(system_parameters(), deck);
        EXPECT_TRUE(system->build(error)) << error;
        return system;
    };
    std::string error;
    auto saver = built(kPlatform);
    ASSERT_TRUE(saver->initialize(0.0, platform_inputs(0.0, 0.0, 0.0), error)) << error;
    ASSERT_TRUE(saver->step(0.0, 0.2, platform_inputs(0.1, 0.0, 0.5), error)) << error;
    std::vector<unsigned char> state(saver->state_size());
    saver->save_state(state.data());
    const struct {
        const char *from, *to, *named;
    } edits[] = {
        {"1         main        1         4       835.35", "1         main        1         4       845.35",
         "line 1 (deck row 20): length = 845.35000000000002 now, 835.35000000000002 in the state"},
        {"7.536E8", "3.768E8", "line 1 (deck row 20): EA = 376800000 now, 753600000 in the state"},
        {"7      Free     200.0   -346.0    -190.0   20000", "7      Free     200.0   -346.0    -190.0   40000",
         "= 40000 now, 20000 in the state"},
        {"200      WtrDpth", "210      WtrDpth", "waterDepth = 210 now, 200 in the state"},
    };
    for (const auto& e : edits) {
        auto edited_system = built(edited(kPlatform, e.from, e.to));
        ASSERT_EQ(edited_system->state_size(), state.size()) << e.to;  // the same shape: only the values tell
        bool changed = true;
        EXPECT_FALSE(edited_system->restore_state(state.data(), state.size(), error, &changed)) << e.to;
        EXPECT_FALSE(changed) << e.to << ": a refusal comes before anything changes";
        EXPECT_NE(error.find("the deck is not the one the state was saved with: "), std::string::npos) << error;
        EXPECT_NE(error.find(e.named), std::string::npos) << e.to << ": " << error;
    }
    // another line (the deck's lines 3 and 4 are one line of the system): the shape differs, refused all the same
    auto more = built(edited(kPlatform, "4         main        6         7       435.35     12        -",
                             "4         main        6         7       435.35     12        -\n"
                             "5         main        1         5       835.35     20        -"));
    EXPECT_FALSE(more->restore_state(state.data(), state.size(), error));
    EXPECT_NE(error.find("the deck is not the one the state was saved with: it makes 4 lines"), std::string::npos)
        << error;
    // the deck it was saved with: restored
    EXPECT_TRUE(built(kPlatform)->restore_state(state.data(), state.size(), error)) << error;
}

TEST(MooringDeckFuzz, TruncationsAndMutationsOfASystemDeckNeverCrash) {
    // a refusal always names the deck's line or what is missing; an accepted deck makes its system
    std::mt19937 rng(20261126u);
    int accepted = 0, refused = 0;
    const UCParams p = system_parameters();
    for (int i = 0; i < 3000; ++i) {
        const std::string deck = mutate_deck(kPlatform, rng);
        char notes[2048], msg[512];
        msg[0] = '\0';
        UCCable* cable = uc_create_system(&p, deck.data(), deck.size(), notes, sizeof notes, msg, sizeof msg);
        if (cable != nullptr) {
            ++accepted;
            uc_free(cable);
            continue;
        }
        ++refused;
        const std::string m = msg;
        ASSERT_FALSE(m.empty()) << "iteration " << i;
        bool named = false;
        const bool inDeck = names_a_line_of(m, deck, &named);
        ASSERT_TRUE(!named || inDeck) << m << ", iteration " << i;
    }
    EXPECT_GT(accepted, 100);
    EXPECT_GT(refused, 100);
}

}  // namespace

// A single line's line[1].* outputs are filled where the line makes its outputs (initialization, each step),
// in the line's own outputs: reading them copies nothing.
TEST(OneLineSystem, LineOneOutputsAreTheLinesOwnFromItsOutputs) {
    UCParams p;
    uc_params_default(&p);
    uc::OneLineSystem line(p);
    UCInputs in;
    uc_inputs_default(&in);
    std::string error;
    ASSERT_TRUE(line.initialize(0.0, in, error)) << error;
    for (int step = 0; step < 2; ++step) {
        const UCOutputs& own = line.uc::CableSimulation::outputs();
        EXPECT_GT(own.towTension, 0.0);
        EXPECT_EQ(own.mooringLine[0].fairleadTension, own.towTension);
        EXPECT_EQ(own.mooringLine[0].anchorTension, own.endTension);
        EXPECT_EQ(own.mooringLine[0].minTension, own.minTension);
        EXPECT_EQ(&line.outputs(), &own);
        ASSERT_TRUE(line.step(line.time(), 0.1, in, error)) << error;
    }
}
