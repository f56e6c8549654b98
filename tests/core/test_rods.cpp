// Rods of a MoorDyn v2 deck (src/deck/rods.cpp, docs/lines.md "Rods"): what each kind of rod becomes (a
// Fixed rod's end a clamped tow point, a free zero-length rod a rigid joint, a free rod of non-zero length a
// free body with the rod's integrated loads, a rod on a free body added to it), and the rods refused with
// their row and why.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "api/cable_api.h"
#include "deck/line_file.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

// A cantilever: 10 m of beam leaving a Fixed rod's end B along the rod (+x), its far end a free point.
const char* const kCantilever = R"(--------------------- MoorDyn Input File ------------------------------------
a beam clamped to a fixed rod
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
beam      0.05     100.0      1.5e9      -1.0        1e7        0.0    0.0    0.1     0.0
---------------------- ROD TYPES ------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
stub          0.25     100.0     0.0    0.0     0.0      0.0
---------------------- RODS ----------------------------------------
ID   RodType   Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs  RodOutputs
(#)  (name)     (#/key)    (m)   (m)   (m)   (m)   (m)   (m)  (-)       (-)
1    stub       Fixed      -1.0  0     10.0  0.0   0     10.0 1         -
---------------------- POINTS --------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Free      10      0.0     9.9     0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     beam       R1B      1         10        19      -
---------------------- OPTIONS -----------------------------------------
10            WtrDpth
------------------------- need this line --------------------------------------
)";

// Two cables from a coupled point to an anchor joined by a free zero-length rod (MoorDyn's bend-stiffener
// joint), the lower cable given anchor first.
const char* const kJoined = R"(--------------------- MoorDyn Input File ------------------------------------
two cables joined by a zero-length rod
----------------------- LINE TYPES ------------------------------------------
TypeName  Diam   Mass/m  EA      BA/-zeta  EI     Cd   Ca   CdAx  CaAx
(name)    (m)    (kg/m)  (N)     (N-s/-)   (N-m^2) (-) (-)  (-)   (-)
cable     0.116  25      362e6   -1.0      1e2    1.1  1.0  0.008 0.0
stiff     0.19   25      362e6   -1.0      38e3   1.1  1.0  0.008 0.0
---------------------- ROD TYPES ------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
conn          0.116    25        1.1    1.0     1.1      1.0
---------------------- RODS ----------------------------------------
ID   RodType  Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs  RodOutputs
(#)  (name)    (#/key)    (m)   (m)   (m)   (m)   (m)   (m)  (-)       (-)
1    conn        Free     100.0 0  -150.0  -1.0  0  1.0  0         -
---------------------- POINTS --------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     200     0      -200     0      0       0      0
2     Coupled   0       0      -20      0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     cable      1        R1A       120       12      -
2     stiff      R1B      2         180       18      -
---------------------- OPTIONS -----------------------------------------
200           WtrDpth
------------------------- need this line --------------------------------------
)";

// A submerged free rod of 20 m hanging on two ropes from two Fixed points (MoorDyn's RodHanging, moved).
const char* const kHanging = R"(--------------------- MoorDyn Input File ------------------------------------
a rod hanging from two ropes
----------------------- LINE TYPES ------------------------------------------
TypeName Diam  Mass/m   EA         BA/-zeta EI      Cd  Ca  CdAx CaAx
(name)   (m)   (kg/m)   (N)        (N-s/-)  (N-m^2) (-) (-) (-)  (-)
rope     0.09  77.7066  384.243E6  -0.3     0       1.6 1.0 0.1  0.0
---------------------- ROD TYPES -----------------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
rod           0.25     77.7066   1.6    1.0     1.6      1.0
---------------------- RODS ----------------------------------------------------
ID   RodType   Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs RodOutputs
(#)  (name)     (#/key)    (m)   (m)   (m)   (m)   (m)   (m)  (-)     (-)
1    rod       Free        -10   0     -75   10    0     -75  1       -
---------------------- POINTS --------------------------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (mˆ3)   (m^2)  (-)
1     Fixed     -450    0       0       0      0       0      0
2     Fixed      450    0       0       0      0       0      0
---------------------- LINES ---------------------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     rope       1        R1A       450       45      -
2     rope       2        R1B       450       45      -
---------------------- OPTIONS -------------------------------------------------
150           WtrDpth
1000          WtrDnsty
------------------------- need this line --------------------------------------
)";

std::string edited(std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

int line_of(const std::string& deck, const std::string& marker) {
    const size_t at = deck.find(marker);
    EXPECT_NE(at, std::string::npos) << marker;
    return 1 + static_cast<int>(std::count(deck.begin(), deck.begin() + static_cast<long>(at), '\n'));
}

bool has(const std::vector<std::string>& notes, const std::string& text) {
    return std::any_of(notes.begin(), notes.end(), [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

}  // namespace

TEST(Rods, ALineOnAFixedRodIsClampedAtTheTowPointAlongTheRod) {
    uc::LineFileLine line;
    std::string error;
    ASSERT_TRUE(uc::read_line_file(kCantilever, 0, line, error)) << error;
    EXPECT_TRUE(line.towFixed);
    EXPECT_TRUE(line.towClamped);
    EXPECT_EQ(line.towTangent[0], 1.0);  // out of the rod's end B along A -> B
    EXPECT_EQ(line.towTangent[2], 0.0);
    EXPECT_EQ(line.towPoint[0], 0.0);
    EXPECT_EQ(line.towPoint[2], 10.0);
    EXPECT_EQ(line.farEnd, uc::LineFileFarEnd::Free);
    const int row = line_of(kCantilever, "1    stub");
    EXPECT_TRUE(has(line.notes, "line " + std::to_string(row) + ": rod 1 (Fixed, 1 m) read as Fixed point 2 (end B)"));
    UCParams p;
    uc_params_default(&p);
    ASSERT_TRUE(uc::apply_line_file(line, p, error)) << error;
    EXPECT_EQ(p.topEnd, 1);
    EXPECT_EQ(p.topTangent[0], 1.0);
    EXPECT_EQ(p.initialDirection[0], 1.0);  // the statics start along the clamp

    // at end A the line leaves against the rod's direction A -> B
    ASSERT_TRUE(uc::read_line_file(edited(kCantilever, "R1B      1", "R1A      1"), 0, line, error)) << error;
    EXPECT_EQ(line.towTangent[0], -1.0);
    EXPECT_EQ(line.towPoint[0], -1.0);
    // a line without bending stiffness is pinned to the rod (MoorDyn's), the tow point hinged
    ASSERT_TRUE(uc::read_line_file(edited(kCantilever, "1e7        0.0    0.0", "0          0.0    0.0"), 0, line, error))
        << error;
    EXPECT_FALSE(line.towClamped);
}

TEST(Rods, AFreeZeroLengthRodBetweenTwoStiffLinesIsARigidJoint) {
    uc::LineFileLine line;
    std::string error;
    ASSERT_TRUE(uc::read_line_file(kJoined, 0, line, error)) << error;
    ASSERT_EQ(line.sections.size(), 2u);
    ASSERT_EQ(line.joints.size(), 1u);
    EXPECT_TRUE(line.joints[0].rigid);
    EXPECT_TRUE(line.joints[0].empty());  // no mass, no volume: MoorDyn's zero-length rod
    const int row = line_of(kJoined, "1    conn");
    EXPECT_TRUE(has(line.notes, "line " + std::to_string(row) + ": rod 1 (Free, zero length): a rigid joint between lines 1, 2"));
    EXPECT_TRUE(has(line.notes, "2 CdEnd A = " ));
    EXPECT_FALSE(has(line.notes, "warning: "));
    UCParams p;
    uc_params_default(&p);
    ASSERT_TRUE(uc::apply_line_file(line, p, error)) << error;
    EXPECT_EQ(p.section[0].joint, 0);  // rigid splice
    EXPECT_EQ(p.nAttachments, 0);

    // one line without bending stiffness: the rod follows the other line's end, a pinned joint (as in MoorDyn)
    ASSERT_TRUE(uc::read_line_file(edited(kJoined, "1e2    1.1", "0      1.1"), 0, line, error)) << error;
    EXPECT_FALSE(line.joints[0].rigid);
    EXPECT_FALSE(has(line.notes, "warning: "));
    ASSERT_TRUE(uc::apply_line_file(line, p, error)) << error;
    EXPECT_EQ(p.section[0].joint, 1);
    // both lines on end A: no joint that passes the moment; the clamps are pinned with a warning each
    ASSERT_TRUE(uc::read_line_file(edited(kJoined, "R1B      2", "R1A      2"), 0, line, error)) << error;
    EXPECT_FALSE(line.joints[0].rigid);
    EXPECT_TRUE(has(line.notes, "warning: line " + std::to_string(line_of(kJoined, "2     stiff")) +
                                    ": line 2 (EI 38000 N m2): its end A is clamped to rod 1's axis in MoorDyn, pinned"));
}

TEST(Rods, RodsTheFMUHasNoCounterpartForAreRefusedNamingTheRodAndItsRow) {
    uc::LineFileLine line;
    std::string error;
    const int row = line_of(kJoined, "1    conn");
    // a rod coupled and pinned has no input for its pin; a rod pinned to the ground or a body is a pinned body,
    // which makes the deck a mooring system (docs/systems_mooring.md, "Pinned bodies")
    for (const char* kind : {"CoupledPinned", "VesPin"}) {
        EXPECT_FALSE(uc::read_line_file(edited(kJoined, "conn        Free", std::string("conn ") + kind), 0, line, error));
        EXPECT_EQ(error.rfind("line " + std::to_string(row) + ": rod 1 is coupled and pinned", 0), 0u) << error;
    }
    for (const char* kind : {"Pinned", "Body1Pinned"}) {
        EXPECT_FALSE(uc::read_line_file(edited(kJoined, "conn        Free", std::string("conn ") + kind), 0, line, error));
        EXPECT_NE(error.find("a pinned rod or a free rod of non-zero length makes the deck a mooring system"),
                  std::string::npos) << error;
    }
    EXPECT_FALSE(uc::read_line_file(edited(kJoined, "R1A       120", "R2A       120"), 0, line, error));
    EXPECT_NE(error.find("AttachB 'R2A': there is no rod 2 (the RODS table has 1)"), std::string::npos) << error;
    EXPECT_FALSE(uc::read_line_file(edited(kJoined, "R1A       120", "R1C       120"), 0, line, error));
    EXPECT_NE(error.find("AttachB 'R1C' is not a rod's end (R<ID>A or R<ID>B)"), std::string::npos) << error;
    EXPECT_FALSE(uc::read_line_file(edited(kJoined, "-1.0  0  1.0  0 ", "0.0  0  0.0  0 "), 0, line, error));
    EXPECT_EQ(error, "line " + std::to_string(row) + ": rod 1: Xb Yb Zb, the direction of a zero-length rod, is (0, 0, 0)");
    EXPECT_FALSE(uc::read_line_file(edited(kJoined, "conn        Free", "pipe        Free"), 0, line, error));
    EXPECT_NE(error.find("rod type 'pipe' is not among the ROD TYPES ('conn')"), std::string::npos) << error;
}

TEST(Rods, AFreeRodOfNonZeroLengthIsAFreeBodyWithTheRodsIntegratedLoads) {
    EXPECT_TRUE(uc::is_mooring_system_deck(kHanging));
    uc::MooringDeck deck;
    std::string error;
    ASSERT_TRUE(uc::read_mooring_deck(kHanging, 0, deck, error)) << error;
    ASSERT_EQ(deck.nodes.size(), 1u);
    const uc::MooringNode& n = deck.nodes[0];
    EXPECT_TRUE(n.body);
    EXPECT_EQ(n.point.id, 1);
    const double d = 0.25, L = 20.0, A = kPi * d * d / 4, m = 77.7066 * L, rho = 1000.0;
    EXPECT_DOUBLE_EQ(n.point.mass, m);
    EXPECT_DOUBLE_EQ(n.point.volume, A * L);
    EXPECT_DOUBLE_EQ(n.position[0], 0.0);
    EXPECT_DOUBLE_EQ(n.position[2], -75.0);
    EXPECT_DOUBLE_EQ(n.angles[1], 0.0);  // along x: no turn
    EXPECT_DOUBLE_EQ(n.inertia[0], m * d * d / 8);
    EXPECT_DOUBLE_EQ(n.inertia[1], m * (L * L / 12 + d * d / 16) + 1.0 * rho * A * L * L * L / 12);
    EXPECT_DOUBLE_EQ(n.CdA[0], 2 * 1.6 * A);       // the two ends' CdEnd
    EXPECT_DOUBLE_EQ(n.CdA[1], 1.6 * d * L);       // transverse Cd d L
    EXPECT_DOUBLE_EQ(n.CdA[3], 0.0);               // no drag turning about its axis
    EXPECT_DOUBLE_EQ(n.CdA[4], 1.6 * d * std::pow(L, 4) / 32);
    EXPECT_DOUBLE_EQ(n.Ca[1], 1.0);
    EXPECT_DOUBLE_EQ(n.Ca[0], 2 * 1.0 * kPi * d * d * d / 12 / (A * L));
    ASSERT_EQ(deck.lines.size(), 2u);
    for (const uc::MooringDeckLine& l : deck.lines) {
        const uc::MooringEnd& e = l.far.kind == uc::MooringEnd::Kind::Node ? l.far : l.fairlead;
        ASSERT_EQ(e.kind, uc::MooringEnd::Kind::Node);
        EXPECT_DOUBLE_EQ(std::abs(e.position[0]), 10.0);  // the rod's ends on its x axis
    }

    // tilted: the body's x axis turned onto the rod's (R = Rx Ry Rz: (cos p cos y, sin y, -sin p cos y))
    ASSERT_TRUE(uc::read_mooring_deck(edited(kHanging, "-10   0     -75   10    0     -75", "-8   -6    -75   8     6     -70"),
                                      0, deck, error)) << error;
    const double* a = deck.nodes[0].angles;
    const double q[3] = {16, 12, 5};
    const double nq = std::sqrt(16 * 16 + 12 * 12 + 25.0);
    EXPECT_NEAR(std::cos(a[1]) * std::cos(a[2]), q[0] / nq, 1e-15);
    EXPECT_NEAR(std::sin(a[2]), q[1] / nq, 1e-15);
    EXPECT_NEAR(-std::sin(a[1]) * std::cos(a[2]), q[2] / nq, 1e-15);

    EXPECT_DOUBLE_EQ(deck.nodes[0].rodLength, std::sqrt(16 * 16 + 12 * 12 + 25.0));  // its buoyancy follows its draft
}

TEST(Rods, ARodOnAFreeBodyAddsItsMassVolumeAndLoadsToTheBody) {
    // the hanging rod made a clamp of 0.2 m on a free body of 29.5 kg (MoorDyn's riser), the ropes on its ends
    const std::string body = edited(
        edited(kHanging, "---------------------- RODS", "---------------------------- BODIES ----\n"
                                                         "ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca\n"
                                                         "(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)\n"
                                                         "1 Free 0 0 -75 0 0 0 29.5 0 0.098 0.014 0.5|0.5 1.0\n"
                                                         "---------------------- RODS"),
        "1    rod       Free        -10   0     -75   10    0     -75  1", "1    rod       Body1       0.1   0     0.0   -0.1  0     0.0  1");
    uc::MooringDeck deck;
    std::string error;
    ASSERT_TRUE(uc::read_mooring_deck(body, 0, deck, error)) << error;
    ASSERT_EQ(deck.nodes.size(), 1u);
    const uc::MooringNode& n = deck.nodes[0];
    const double d = 0.25, L = 0.2, A = kPi * d * d / 4, m = 77.7066 * L, V = A * L;
    // its mass and inertia are the body's; its volume, drag and added mass its own, from its part under water
    // as the body moves (src/system/body_rods.h)
    EXPECT_DOUBLE_EQ(n.point.mass, 29.5 + m);
    EXPECT_DOUBLE_EQ(n.point.volume, 0.014);
    EXPECT_DOUBLE_EQ(n.inertia[0], 0.098 + m * d * d / 8);
    EXPECT_DOUBLE_EQ(n.CdA[1], 0.5);
    EXPECT_DOUBLE_EQ(n.Ca[1], 1.0);
    ASSERT_EQ(n.rods.size(), 1u);
    EXPECT_DOUBLE_EQ(n.rods[0].a[0], 0.1);
    EXPECT_DOUBLE_EQ(n.rods[0].diameter, d);
    EXPECT_DOUBLE_EQ(n.rods[0].Cd, 1.6);
    EXPECT_TRUE(has(deck.notes, "rod 1 (Body1, 0.2 m): added to Free body 1"));
    (void)V;

    // off the body's reference point: the centre of gravity moves to the pair's
    ASSERT_TRUE(uc::read_mooring_deck(edited(body, "0.1   0     0.0   -0.1  0     0.0", "0.3   0     0.0   0.1   0     0.0"), 0,
                                      deck, error)) << error;
    EXPECT_NEAR(deck.nodes[0].cg[0], m * 0.2 / (29.5 + m), 1e-15);
    // across the body's axes: its inertia would not be diagonal in them
    EXPECT_FALSE(uc::read_mooring_deck(edited(body, "0.1   0     0.0   -0.1  0     0.0", "0.1   0.1   0.0   -0.1  -0.1  0.0"), 0,
                                       deck, error));
    EXPECT_NE(error.find("rod 1 (Body1, 0.282843 m): added to Free body 1 it makes an inertia that is not diagonal"),
              std::string::npos) << error;
    // through the waterline: read (its buoyancy follows its draft)
    EXPECT_TRUE(uc::read_mooring_deck(edited(body, "1 Free 0 0 -75", "1 Free 0 0 0"), 0, deck, error)) << error;
}

TEST(Rods, ZeroLengthFreeRodsInASystemAreRigidJointsOfItsLines) {
    // the joined cables with their coupled point on a platform: a system line of two sections, rigid between
    const std::string text = edited(kJoined, "2     Coupled   0       0      -20      0      0       0      0",
                                    "2     Coupled   0       0      -20      0      0       0      0\n"
                                    "3     Fixed     -200    0      -200     0      0       0      0\n"
                                    "4     Coupled   -10     0      -20      0      0       0      0");
    const std::string deckText = edited(text, "2     stiff      R1B      2         180       18      -",
                                        "2     stiff      R1B      2         180       18      -\n"
                                        "3     cable      3        4         260       12      -");
    uc::MooringDeck deck;
    std::string error;
    ASSERT_TRUE(uc::read_mooring_deck(deckText, 0, deck, error)) << error;
    const uc::MooringDeckLine& l = deck.lines[0];
    ASSERT_EQ(l.sections.size(), 2u);
    EXPECT_TRUE(l.joints[0].rigid);
    UCParams base, p;
    uc_params_default(&base);
    ASSERT_TRUE(uc::mooring_line_params(deck, 0, base, p, error)) << error;
    EXPECT_EQ(p.section[0].joint, 0);
}

namespace {

// MoorDyn's pinned-body deck in water: a CoupledPinned body of no mass with a rod hanging 5-15 m below its
// pin, a dummy line between two Fixed points; a second rod pinned to coupled body 2 at (2, 0, 0) in its frame.
const char* const kPinned = R"(--------------------- MoorDyn Input File ------------------------------------
pinned bodies and rods
------------------------- LINE TYPES --------------------------------------------------
LineType  Diam    MassDenInAir    EA       BA/-zeta    EI      Can   Cat  Cdn   Cdt
(-)       (m)       (kg/m)        (N)      (Pa-s/-)  (n-m^2)   (-)   (-)  (-)   (-)
nylon      0.124      35.0    5515288.0     -0.8      0.0     1.0   0.0  1.6   0.05
---------------------- ROD TYPES ------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
Can          2       5e3     0.6    1.0     1.2      1.0
----------------------- BODIES ------------------------------------------------------
ID   Attachment         X0      Y0     Z0     r0      p0     y0     Mass          CG*          I*      Volume   CdA*   Ca*
(#)     (-)             (m)     (m)    (m)   (deg)   (deg)  (deg)   (kg)          (m)         (kg-m^2)  (m^3)   (m^2)  (-)
1     CoupledPinned    0.00    0.00  -5.00   0.00   0.00   0.00   0.00        0.00        0.000e+00  0.00     0.00  0.00
2     Coupled          0.00    0.00  -30.00   0.00   0.00   0.00   0.00        0.00        0.000e+00  0.00     0.00  0.00
---------------------- RODS ----------------------------------------
ID   RodType  Attachment     Xa    Ya    Za    Xb    Yb     Zb    NumSegs  RodOutputs
(#)  (name)    (#/key)      (m)   (m)   (m)   (m)   (m)    (m)   (-)       (-)
1      Can     Body1         0     0     -5     0     0     -15     3         p
2      Can     Body2Pinned   2     0      0     2     0     -10     3         p
----------------------- POINTS ----------------------------------------------
Node      Type      X        Y         Z        M        V         CdA   CA
(-)       (-)      (m)      (m)       (m)      (kg)     (m^3)     (m^2)  (-)
1         Fixed    30    0      -5       0        0          0     0
2         Fixed    30    0      -10       0        0          0     0
-------------------------- LINES -------------------------------------------------
Line     LineType NodeA     NodeB  UnstrLen  NumSegs     Flags/Outputs
(-)      (-)       (-)       (-)   (m)         (-)          (-)
1        nylon      1         2    5        1           p
-------------------------- SOLVER OPTIONS---------------------------------------------------
1025.0     WtrDnsty     - Water Density
50       WtrDpth      - water depth
0.0    TmaxIC       - threshold for IC convergence
--------------------------- need this line -------------------------------------------------
)";

}  // namespace

TEST(Rods, APinnedBodyAndAPinnedRodTurnAboutTheirPinsWithTheirRodsLoadsAboutIt) {
    EXPECT_TRUE(uc::is_mooring_system_deck(kPinned));
    uc::MooringDeck deck;
    std::string error;
    ASSERT_TRUE(uc::read_mooring_deck(kPinned, 0, deck, error)) << error;
    EXPECT_EQ(deck.bodies, 2);  // the CoupledPinned body's pin takes the body[1] inputs
    ASSERT_EQ(deck.nodes.size(), 2u);
    const double rho = 1025.0, d = 2.0, A = kPi, m = 5e4;
    // body 1: the rod 5-15 m below its pin along its z axis: mass and buoyancy 10 m below it, inertia about
    // its centre of gravity, the added inertia Ca rho A (15^3 - 5^3) / 3 about the pin, the turning drag
    // Cd d (15^4 - 5^4) / 4
    const uc::MooringNode& b = deck.nodes[0];
    EXPECT_TRUE(b.body && b.pinned);
    EXPECT_EQ(b.point.id, 1);
    EXPECT_EQ(b.pin.kind, uc::MooringEnd::Kind::Body);
    EXPECT_EQ(b.pin.body, 1);
    EXPECT_DOUBLE_EQ(b.point.mass, m);
    EXPECT_NEAR(b.point.volume, A * 10.0, 1e-12);
    EXPECT_NEAR(b.cg[2], -10.0, 1e-12);
    EXPECT_NEAR(b.cb[2], -10.0, 1e-12);
    const double transverse = m * (100.0 / 12.0 + d * d / 16.0) + rho * A * (15.0 * 15.0 * 15.0 - 125.0) / 3.0;
    EXPECT_NEAR(b.inertia[0], transverse, 1e-9 * transverse);
    EXPECT_NEAR(b.inertia[1], transverse, 1e-9 * transverse);
    EXPECT_NEAR(b.inertia[2], m * d * d / 8.0, 1e-9);
    EXPECT_NEAR(b.CdA[3], 0.6 * d * (std::pow(15.0, 4) - std::pow(5.0, 4)) / 4.0, 1e-9);
    EXPECT_NEAR(b.CdA[5], 0.0, 1e-12);
    EXPECT_NEAR(b.Ca[0], 1.0, 1e-12);
    EXPECT_NEAR(b.Ca[2], 2.0 * 1.0 * kPi * 8.0 / 12.0 / (A * 10.0), 1e-12);  // its two ends' CaEnd
    // rod 2: a pinned body after the deck's (ID 3) at its end A, held by body 2 at (2, 0, 0) in its frame,
    // its x axis along the rod (pointing down: pitch 90 deg), its mass 5 m out along it
    const uc::MooringNode& r = deck.nodes[1];
    EXPECT_TRUE(r.body && r.pinned);
    EXPECT_EQ(r.point.id, 3);
    EXPECT_EQ(r.pin.kind, uc::MooringEnd::Kind::Body);
    EXPECT_EQ(r.pin.body, 2);
    EXPECT_DOUBLE_EQ(r.pin.position[0], 2.0);
    EXPECT_NEAR(r.position[2], -30.0, 1e-12);
    EXPECT_NEAR(r.angles[1], kPi / 2, 1e-12);
    EXPECT_NEAR(r.cg[0], 5.0, 1e-12);
    EXPECT_TRUE(has(deck.notes, "rod 2 (Body2Pinned, 10 m) read as pinned body 3 (its end A held by body 2, free to "
                                "turn about it)"));
    // refused: a rod pinned to a pinned body, a coupled pinned rod (a rod pinned to a free body is read:
    // test_body_rods.cpp)
    EXPECT_FALSE(uc::read_mooring_deck(edited(kPinned, "Body2Pinned", "Body1Pinned"), 0, deck, error));
    EXPECT_NE(error.find("rod 2 (Body1Pinned, 10 m): it is pinned to CoupledPinned body 1"), std::string::npos) << error;
    EXPECT_FALSE(uc::read_mooring_deck(edited(kPinned, "Body2Pinned", "CoupledPinned"), 0, deck, error));
    EXPECT_NE(error.find("rod 2 is coupled and pinned ('CoupledPinned'"), std::string::npos) << error;
    // a pin on a coupled body beyond the body[k] inputs
    std::string bodies;
    for (int k = 3; k <= UC_MAX_BODIES + 1; ++k) bodies += std::to_string(k) + " Coupled 0 0 -30 0 0 0\n";
    const std::string beyond = edited(edited(kPinned, "0.000e+00  0.00     0.00  0.00\n---------------------- RODS",
                                             "0.000e+00  0.00     0.00  0.00\n" + bodies + "---------------------- RODS"),
                                      "Body2Pinned", "Body" + std::to_string(UC_MAX_BODIES + 1) + "Pinned");
    EXPECT_FALSE(uc::read_mooring_deck(beyond, 0, deck, error));
    EXPECT_NE(error.find("it is pinned to coupled body " + std::to_string(UC_MAX_BODIES + 1) +
                         ": the bodies' inputs body[k].* go up to k = " + std::to_string(UC_MAX_BODIES)),
              std::string::npos) << error;
}
