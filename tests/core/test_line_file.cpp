// The MoorDyn v2 input file reader (src/deck/line_file.cpp, docs/lines.md): what a supported deck becomes
// in our conventions, that every kind of unsupported or malformed deck is refused naming its line, and
// that random truncations and mutations of a valid deck never crash it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <tuple>

#include "api/cable_api.h"
#include "deck_mutation.h"
#include "deck/line_file.h"
#include "model/params.h"
#include "terms/seabed.h"

namespace {

// A chain-wire-chain mooring with a clump weight and a buoy at the joints, lines given in both
// orientations (AttachA at the anchor side for line 1, at the vessel side for lines 2 and 3).
const char* const kChainWireChain = R"(--------------------- MoorDyn Input File ------------------------------------
Chain-wire-chain test deck
---------------------- LINE TYPES ---------------------------------------------------
TypeName   Diam    Mass/m     EA        BA/-zeta   EI    Cd    Ca    CdAx   CaAx
(name)     (m)     (kg/m)     (N)       (N-s/-)    (N-m^2) (-) (-)   (-)    (-)
chain      0.138   113.0      7.5e8     -0.5       0     1.333 1.0   0.64   0.5
wire       0.09    42.0       6.0e8     1.0e6      0     1.2   1.0   0.008  0.0
---------------------- POINTS -----------------------------------------------------
ID   Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)        (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1    Fixed      -850     0     -320   0      0       0      0
2    Free       -600     0     -300   5000   0.5     1.0    1.0
3    Free       -200     0     -150   0      2.0     0.5    0.8
4    Vessel      0       0     -70    0      0       0      0
---------------------- LINES ------------------------------------------------------
ID  LineType  AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)    (#)      (#)      (m)       (-)      (-)
1    chain     1        2        300       30       -
2    wire      3        2        450       20       -
3    chain     4        3        150       10       pt
---------------------- OPTIONS -----------------------------------------------------
0.001   dtM       time step
3.0e6   kBot      bottom stiffness
320     WtrDpth   water depth
9.81    g
1025    rho
------------------------- need this line -------------------------------------
)";

// The single chain of the mooring scene (docs/mooring.md) as a deck.
const char* const kSingleChain = R"(--------------------- MoorDyn Input File ------------------------------------
single chain
---------------------- LINE TYPES --------------------------------
TypeName   Diam    Mass/m  EA      BA/-zeta  EI   Cd    Ca    CdAx  CaAx
(name)     (m)     (kg/m)  (N)     (N-s/-)   (-)  (-)   (-)   (-)   (-)
chain      0.0766  113     7.5e8   -0.8      0    2.4   1.0   0.2   0.0
---------------------- POINTS --------------------------------
ID   Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)        (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed      -850    0     -320   0      0       0      0
2     Coupled    0       0     -70    0      0       0      0
---------------------- LINES --------------------------------------
ID    LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)      (m)       (-)      (-)
1     chain      1        2        900       40       -
---------------------- OPTIONS -----------------------------------------
0.002    dtM
320      WtrDpth
---------------------- OUTPUTS -----------------------------------------
FairTen1
END
------------------------- need this line -------------------------------------
)";

struct Read {
    bool ok = false;
    uc::LineFileLine line;
    std::string error;
};

Read read(const std::string& text, int elementsTotal = 0) {
    Read r;
    r.ok = uc::read_line_file(text, elementsTotal, r.line, r.error);
    return r;
}

// The deck with the first occurrence of `from` replaced by `to` (which must exist).
std::string edit(const std::string& deck, const std::string& from, const std::string& to) {
    const size_t at = deck.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at == std::string::npos) return deck;
    std::string s = deck;
    s.replace(at, from.size(), to);
    return s;
}

// 1-based line of the deck holding `marker` (0 for an empty marker).
int line_of(const std::string& deck, const std::string& marker) {
    if (marker.empty()) return 0;
    const size_t at = deck.find(marker);
    EXPECT_NE(at, std::string::npos) << marker;
    return at == std::string::npos ? -1 : 1 + static_cast<int>(std::count(deck.begin(), deck.begin() + at, '\n'));
}

// The refusal names the line of the deck holding `marker` ("": a message about the whole deck) and says
// what is wrong.
void expect_refused(const std::string& deck, const std::string& marker, const std::string& what) {
    const int line = line_of(deck, marker);
    const Read r = read(deck);
    ASSERT_FALSE(r.ok) << "accepted; expected an error at line " << line << " about " << what;
    const std::string prefix = line > 0 ? "line " + std::to_string(line) + ": " : "";
    EXPECT_EQ(r.error.rfind(prefix, 0), 0u) << r.error;
    EXPECT_NE(r.error.find(what), std::string::npos) << r.error;
}

bool has_note(const uc::LineFileLine& line, const std::string& text) {
    for (const std::string& n : line.notes) {
        if (n.find(text) != std::string::npos) return true;
    }
    return false;
}

}  // namespace

TEST(LineFile, ChainWireChainIsOrientedFromTheVesselPointWithJointsInOrder) {
    const Read r = read(kChainWireChain);
    ASSERT_TRUE(r.ok) << r.error;
    const uc::LineFileLine& l = r.line;
    ASSERT_EQ(l.sections.size(), 3u);
    EXPECT_EQ(l.sections[0].type, "chain");
    EXPECT_EQ(l.sections[0].length, 150.0);
    EXPECT_EQ(l.sections[0].row, line_of(kChainWireChain, "3    chain     4"));
    EXPECT_EQ(l.sections[1].type, "wire");
    EXPECT_EQ(l.sections[1].length, 450.0);
    EXPECT_EQ(l.sections[2].type, "chain");
    EXPECT_EQ(l.sections[2].length, 300.0);
    ASSERT_EQ(l.joints.size(), 2u);
    EXPECT_EQ(l.joints[0].id, 3);  // the buoy between the top chain and the wire
    EXPECT_EQ(l.joints[1].id, 2);  // the clump weight between the wire and the bottom chain
    EXPECT_EQ(l.joints[1].mass, 5000.0);
    EXPECT_EQ(l.joints[1].volume, 0.5);
    EXPECT_EQ(l.joints[1].CdA, 1.0);
    EXPECT_EQ(l.joints[1].addedMass, 1.0 * 1025.0 * 0.5);  // CA rho V
    EXPECT_EQ(l.joints[0].addedMass, 0.8 * 1025.0 * 2.0);
    EXPECT_EQ(l.farEnd, uc::LineFileFarEnd::Anchored);
    EXPECT_EQ(l.anchor[0], -850.0);
    EXPECT_EQ(l.anchor[2], -320.0);
    EXPECT_EQ(l.towPoint[0], 0.0);
    EXPECT_EQ(l.towPoint[2], -70.0);
    EXPECT_EQ(l.waterDepth, 320.0);
    EXPECT_EQ(l.gravity, 9.81);
    EXPECT_EQ(l.waterDensity, 1025.0);
    EXPECT_TRUE(has_note(l, "line 22: dtM ignored")) << l.notes.size();
    EXPECT_EQ(l.seabed.kBot, 3.0e6);
    EXPECT_EQ(l.seabed.kBotRow, 23);
    EXPECT_FALSE(has_note(l, "kBot ignored"));
}

TEST(LineFile, LineTypeColumnsMapOntoOurCoefficients) {
    const Read r = read(kChainWireChain);
    ASSERT_TRUE(r.ok) << r.error;
    const uc::LineFileSection& wire = r.line.sections[1];
    EXPECT_EQ(wire.diameter, 0.09);  // MoorDyn's volume-equivalent diameter is ours
    EXPECT_EQ(wire.massPerLength, 42.0);
    EXPECT_EQ(wire.EA, 6.0e8);
    EXPECT_EQ(wire.EI, 0.0);
    EXPECT_EQ(wire.axialDamping, 1.0e6);  // BA >= 0 is N.s already
    EXPECT_EQ(wire.Cdn, 1.2);             // Cd on d
    EXPECT_EQ(wire.Cdt, 0.008);           // CdAx on pi d, as our Cdt
    EXPECT_EQ(wire.Can, 1.0);
    EXPECT_EQ(wire.Cat, 0.0);
}

TEST(LineFile, NegativeBaIsAFractionOfCriticalDampingOfOneMoorDynSegment) {
    const Read r = read(kChainWireChain);
    ASSERT_TRUE(r.ok) << r.error;
    // zeta 0.5, bottom chain: 300 m in 30 segments, BA = zeta (L / N) sqrt(EA w).
    EXPECT_DOUBLE_EQ(r.line.sections[2].axialDamping, 0.5 * (300.0 / 30.0) * std::sqrt(7.5e8 * 113.0));
    // The top chain, same type, 150 m in 10 segments: longer segments, more damping.
    EXPECT_DOUBLE_EQ(r.line.sections[0].axialDamping, 0.5 * (150.0 / 10.0) * std::sqrt(7.5e8 * 113.0));
}

TEST(LineFile, ElementsComeFromNumSegsOrAreSharedInProportionToLength) {
    Read r = read(kChainWireChain);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.line.sections[0].elements, uc::elements_for_segments(10));
    EXPECT_EQ(r.line.sections[1].elements, uc::elements_for_segments(20));
    EXPECT_EQ(r.line.sections[2].elements, uc::elements_for_segments(30));
    EXPECT_EQ(uc::elements_for_segments(1), 1);
    EXPECT_EQ(uc::elements_for_segments(40), 20);
    EXPECT_EQ(uc::elements_for_segments(41), 21);
    r = read(kChainWireChain, 18);  // 900 m: 150, 450, 300 m -> 3, 9, 6
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.line.sections[0].elements, 3);
    EXPECT_EQ(r.line.sections[1].elements, 9);
    EXPECT_EQ(r.line.sections[2].elements, 6);
    r = read(kChainWireChain, 2);  // at least one each
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.line.sections[0].elements, 1);
}

TEST(LineFile, EitherOrientationOfAttachAAndAttachBGivesTheSameLine) {
    const Read a = read(kSingleChain);
    const Read b = read(edit(kSingleChain, "chain      1        2", "chain      2        1"));
    ASSERT_TRUE(a.ok) << a.error;
    ASSERT_TRUE(b.ok) << b.error;
    ASSERT_EQ(b.line.sections.size(), 1u);
    EXPECT_EQ(a.line.sections[0].length, b.line.sections[0].length);
    EXPECT_EQ(a.line.farEnd, uc::LineFileFarEnd::Anchored);
    EXPECT_EQ(b.line.anchor[0], -850.0);
    EXPECT_EQ(b.line.towPoint[2], -70.0);
}

TEST(LineFile, MissingOptionsTakeMoorDynDefaultsAndTheDepthOfTheDeepestPoint) {
    std::string deck = edit(kSingleChain, "320      WtrDpth\n", "");
    Read r = read(deck);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.line.gravity, uc::kMoorDynGravity);
    EXPECT_EQ(r.line.waterDensity, uc::kMoorDynWaterDensity);
    EXPECT_EQ(r.line.waterDepth, 320.0);  // the anchor's depth
    r = read(edit(kSingleChain, "320      WtrDpth", "300      WtrDpth"));
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.line.waterDepth, 320.0);  // raised to the anchor, with a note
    EXPECT_TRUE(has_note(r.line, "line 10: point 1 lies below WtrDpth"));
    r = read(edit(kSingleChain, "320      WtrDpth", "500      WtrDpth\n9.7 gravity\n1000 WtrDnsty"));
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.line.waterDepth, 500.0);
    EXPECT_EQ(r.line.gravity, 9.7);
    EXPECT_EQ(r.line.waterDensity, 1000.0);
}

TEST(LineFile, OlderHeaderNamesCommentsCrLfAndTwelveColumnPointsAreRead) {
    std::string deck = edit(kSingleChain, "LINE TYPES", "LINE DICTIONARY");
    deck = edit(deck, "---- POINTS ----", "---- POINT PROPERTIES ----");
    deck = edit(deck, "---- LINES ----", "---- LINE PROPERTIES ----");
    deck = edit(deck, "1     Fixed      -850    0     -320   0      0       0      0",
                "1     Fixed      -850    0     -320   0      0   0 0 0     0      0   # anchor # more");
    deck = edit(deck, "single chain", "# a comment line\n  \n");
    std::string crlf;
    for (char c : deck) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    const Read r = read(crlf);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.line.sections.size(), 1u);
    EXPECT_EQ(r.line.anchor[0], -850.0);
}

TEST(LineFile, AFreeFarEndIsATowedBodyOrAFreeEnd) {
    Read r = read(edit(kSingleChain, "1     Fixed      -850    0     -320   0      0       0      0",
                       "1     Free       -850    0     -320   800    0.1     0.6    1.0"));
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.line.farEnd, uc::LineFileFarEnd::Body);
    EXPECT_EQ(r.line.body.mass, 800.0);
    EXPECT_EQ(r.line.body.volume, 0.1);
    EXPECT_EQ(r.line.body.CdA, 0.6);
    EXPECT_EQ(r.line.body.addedMass, 1.0 * 1025.0 * 0.1);
    r = read(edit(kSingleChain, "1     Fixed", "1     Free "));
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.line.farEnd, uc::LineFileFarEnd::Free);
}

TEST(LineFile, OutputsAndIgnoredOptionsAreNotedWithTheirLine) {
    const Read r = read(edit(kSingleChain, "0.002    dtM", "0.002    dtM\n1 writeLog\n5 frobnicate"));
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(has_note(r.line, "line 17: dtM ignored"));
    EXPECT_TRUE(has_note(r.line, "line 18: writeLog ignored"));
    EXPECT_TRUE(has_note(r.line, "line 19: unknown option 'frobnicate' ignored"));
    EXPECT_TRUE(has_note(r.line, "OUTPUTS ignored"));
}

TEST(LineFile, ApplyWritesTheLineAndKeepsTheOtherParameters) {
    UCParams p;
    uc_params_default(&p);
    p.seabedStiffness = 2.5e6;  // set explicitly by the importer: kept over the deck's
    p.deckKeep = UC_DECK_KEEP_SEABED_STIFFNESS;
    p.relTol = 1e-7;
    double tow[3] = {1, 1, 1};
    char notes[4096], msg[512];
    const std::string deck = kSingleChain;
    ASSERT_EQ(uc_line_file_apply(deck.data(), deck.size(), &p, tow, notes, sizeof notes, msg, sizeof msg), 0) << msg;
    EXPECT_EQ(p.length, 900.0);
    EXPECT_EQ(p.diameter, 0.0766);
    EXPECT_EQ(p.massPerLength, 113.0);
    EXPECT_EQ(p.EA, 7.5e8);
    EXPECT_EQ(p.EI, 0.0);
    EXPECT_EQ(p.axialDamping, 0.8 * (900.0 / 40.0) * std::sqrt(7.5e8 * 113.0));
    EXPECT_EQ(p.Cdn, 2.4);
    EXPECT_EQ(p.Cdt, 0.2);
    EXPECT_EQ(p.Can, 1.0);
    EXPECT_EQ(p.Cat, 0.0);
    EXPECT_EQ(p.nElements, 20);
    EXPECT_EQ(p.bottomEnd, UC_BOTTOM_ANCHORED);
    EXPECT_EQ(p.anchor[0], -850.0);
    EXPECT_EQ(p.anchor[1], 0.0);
    EXPECT_EQ(p.anchor[2], -320.0);
    EXPECT_EQ(p.waterDepth, 320.0);
    EXPECT_EQ(p.enableCompression, 0);  // tension-only, as MoorDyn's lines are
    EXPECT_EQ(p.gravity, uc::kMoorDynGravity);
    EXPECT_EQ(p.waterDensity, 1025.0);
    EXPECT_EQ(p.seabedStiffness, 2.5e6);
    EXPECT_EQ(p.enableSeabed, 1);  // MoorDyn's seabed, always there
    EXPECT_EQ(p.seabedDamping, 3.0e5 * 0.0766);
    EXPECT_EQ(p.relTol, 1e-7);
    EXPECT_NE(std::strstr(notes, "seabedStiffness = 2500000 set through the FMI is used, not kBot 3000000 Pa/m"),
              nullptr) << notes;
    EXPECT_EQ(tow[0], 0.0);
    EXPECT_EQ(tow[2], -70.0);
    EXPECT_NE(std::strstr(notes, "line 17: dtM ignored"), nullptr) << notes;
    EXPECT_EQ(uc_params_check(&p, msg, sizeof msg), 0) << msg;
    p.lineFileElements = 7;
    ASSERT_EQ(uc_line_file_apply(deck.data(), deck.size(), &p, nullptr, nullptr, 0, msg, sizeof msg), 0) << msg;
    EXPECT_EQ(p.nElements, 7);
}

// MoorDyn always has a seabed at WtrDpth: kBot and cBot per unit of projected area, on the line's
// diameter, its friction coefficient; MoorDyn's defaults (3e6 Pa/m, 3e5 Pa s/m, no friction) where the
// deck is silent. The parameters' own values (seabed off, 1e5 N/m2, 1000 N s/m2) do not survive the deck.
TEST(LineFileSeabed, TheDecksSeabedIsOnWithKBotAndCBotTimesTheDiameter) {
    UCParams p;
    uc_params_default(&p);
    ASSERT_EQ(p.enableSeabed, 0);
    double tow[3];
    char notes[4096], msg[512];
    const std::string silent = kSingleChain;
    ASSERT_EQ(uc_line_file_apply(silent.data(), silent.size(), &p, tow, notes, sizeof notes, msg, sizeof msg), 0) << msg;
    EXPECT_EQ(p.enableSeabed, 1);
    EXPECT_EQ(p.seabedStiffness, 3.0e6 * 0.0766);
    EXPECT_EQ(p.seabedDamping, 3.0e5 * 0.0766);
    EXPECT_EQ(p.seabedFriction, 0.0);
    EXPECT_NE(std::strstr(notes, "seabedStiffness = 229800 N/m2 from kBot 3000000 Pa/m (MoorDyn's default"), nullptr)
        << notes;

    const std::string set = edit(kSingleChain, "320      WtrDpth", "320 WtrDpth\n1.0e5 kBot\n1.0e4 cBot\n0.5 FrictionCoefficient");
    uc_params_default(&p);
    ASSERT_EQ(uc_line_file_apply(set.data(), set.size(), &p, tow, notes, sizeof notes, msg, sizeof msg), 0) << msg;
    EXPECT_EQ(p.enableSeabed, 1);
    EXPECT_EQ(p.seabedStiffness, 1.0e5 * 0.0766);
    EXPECT_EQ(p.seabedDamping, 1.0e4 * 0.0766);
    EXPECT_EQ(p.seabedFriction, 0.5);
    // MoorDyn's friction is a saturated damping of each node, the FMU's Coulomb's: a warning says so
    EXPECT_NE(std::strstr(notes, "warning: seabedFriction = FrictionCoefficient 0.5 (line "), nullptr) << notes;

    const std::string none = edit(kSingleChain, "320      WtrDpth", "320 WtrDpth\n0 kBot");
    uc_params_default(&p);
    ASSERT_EQ(uc_line_file_apply(none.data(), none.size(), &p, tow, notes, sizeof notes, msg, sizeof msg), 0) << msg;
    EXPECT_EQ(p.enableSeabed, 0);  // MoorDyn has no contact at a zero stiffness
}

// What the importer set explicitly (deckKeep) keeps its value, and the notes say which value won.
TEST(LineFileSeabed, ParametersTheImporterSetKeepTheirValueOverTheDecks) {
    UCParams p;
    uc_params_default(&p);
    p.enableSeabed = 0;
    p.waterDepth = 400.0;
    p.seabedDamping = 77.0;
    p.enableCompression = 1;
    p.deckKeep = UC_DECK_KEEP_ENABLE_SEABED | UC_DECK_KEEP_WATER_DEPTH | UC_DECK_KEEP_SEABED_DAMPING |
                 UC_DECK_KEEP_ENABLE_COMPRESSION;
    double tow[3];
    char notes[4096], msg[512];
    const std::string deck = kSingleChain;
    ASSERT_EQ(uc_line_file_apply(deck.data(), deck.size(), &p, tow, notes, sizeof notes, msg, sizeof msg), 0) << msg;
    EXPECT_EQ(p.enableSeabed, 0);
    EXPECT_EQ(p.waterDepth, 400.0);
    EXPECT_EQ(p.seabedDamping, 77.0);
    EXPECT_EQ(p.enableCompression, 1);
    EXPECT_EQ(p.seabedStiffness, 3.0e6 * 0.0766);  // not set: the deck's
    EXPECT_EQ(p.gravity, uc::kMoorDynGravity);      // the deck is silent: MoorDyn's
    for (const char* said : {"enableSeabed = false set through the FMI is used, not the deck's seabed",
                             "waterDepth = 400 set through the FMI is used, not WtrDpth 320 m (line 18)",
                             "seabedDamping = 77 set through the FMI is used, not cBot 300000 Pa s/m (MoorDyn's default",
                             "enableCompression = true set through the FMI is used"}) {
        EXPECT_NE(std::strstr(notes, said), nullptr) << said << "\n" << notes;
    }
}

// Every line of a mooring system gets the seabed from its own far-end section's diameter.
TEST(LineFileSeabed, EachLineOfASystemGetsKBotTimesItsOwnDiameter) {
    uc::MooringDeck deck;
    std::string error;
    ASSERT_TRUE(uc::read_mooring_deck(kChainWireChain, 0, deck, error)) << error;
    UCParams base, p;
    uc_params_default(&base);
    ASSERT_TRUE(uc::mooring_line_params(deck, 0, base, p, error)) << error;
    EXPECT_EQ(p.enableSeabed, 1);
    EXPECT_EQ(p.seabedStiffness, 3.0e6 * 0.138);  // the chain at the anchor
    base.deckKeep = UC_DECK_KEEP_ENABLE_SEABED;
    ASSERT_TRUE(uc::mooring_line_params(deck, 0, base, p, error)) << error;
    EXPECT_EQ(p.enableSeabed, 0);
}

TEST(LineFile, ApplyRefusesMoreElementsThanTheModelTakesNamingTheLine) {
    UCParams p;
    uc_params_default(&p);
    const std::string deck = edit(kSingleChain, "900       40", "900       2500");
    char msg[512];
    ASSERT_EQ(uc_line_file_apply(deck.data(), deck.size(), &p, nullptr, nullptr, 0, msg, sizeof msg), 1);
    EXPECT_STREQ(msg, "line 15: NumSegs 2500 gives 1250 elements, more than 1000: set lineFileElements");
}

TEST(LineFile, ApplyMakesSectionsPinnedJointsAndAttachmentsOfAChainOfLines) {
    UCParams p;
    uc_params_default(&p);
    p.nAttachments = 3;  // the deck's points replace attachments set by parameters
    const std::string deck = kChainWireChain;
    char msg[512];
    ASSERT_EQ(uc_line_file_apply(deck.data(), deck.size(), &p, nullptr, nullptr, 0, msg, sizeof msg), 0) << msg;
    ASSERT_EQ(p.nSections, 3);
    const double lengths[3] = {150.0, 450.0, 300.0};  // from the vessel: chain, wire, chain
    const int elements[3] = {5, 10, 15};              // ceil(NumSegs / 2)
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(p.section[k].length, lengths[k]) << k;
        EXPECT_EQ(p.section[k].nElements, elements[k]) << k;
        EXPECT_EQ(p.section[k].joint, 1) << k;  // MoorDyn's points carry no moment
    }
    EXPECT_EQ(p.section[1].massPerLength, 42.0);
    EXPECT_EQ(p.section[1].EA, 6.0e8);
    EXPECT_EQ(p.section[1].axialDamping, 1.0e6);
    // point 3 (the buoy) at 150 m, point 2 (the clump weight) at 600 m
    ASSERT_EQ(p.nAttachments, 2);
    EXPECT_EQ(p.attachment[0].s, 150.0);
    EXPECT_EQ(p.attachment[0].volume, 2.0);
    EXPECT_EQ(p.attachment[0].addedMass, 0.8 * 1025.0 * 2.0);
    EXPECT_EQ(p.attachment[1].s, 600.0);
    EXPECT_EQ(p.attachment[1].mass, 5000.0);
    EXPECT_EQ(p.attachment[1].CdA, 1.0);
    EXPECT_EQ(uc_params_check(&p, msg, sizeof msg), 0) << msg;
}

// Nine lines in a chain: one more than the sections a line can have; the ninth is named.
TEST(LineFile, ApplyRefusesMoreLinesThanSections) {
    std::string deck = "---------------------- LINE TYPES ----\nName Diam Mass EA BA EI Cd Ca CdAx CaAx\n"
                       "(-) (m) (kg/m) (N) (Ns) (Nm2) (-) (-) (-) (-)\n"
                       "chain 0.0766 113 7.5e8 -0.8 0 2.4 1.0 0.2 0.0\n"
                       "---------------------- POINTS ----\nID Attachment X Y Z Mass Volume CdA CA\n"
                       "(#) (-) (m) (m) (m) (kg) (m3) (m2) (-)\n"
                       "1 Fixed -900 0 -320 0 0 0 0\n";
    for (int k = 2; k <= 9; ++k) deck += std::to_string(k) + " Free " + std::to_string(-900 + 100 * (k - 1)) + " 0 -300 0 0 0 0\n";
    deck += "10 Vessel 0 0 -70 0 0 0 0\n---------------------- LINES ----\n"
            "ID LineType AttachA AttachB UnstrLen NumSegs Outputs\n(#) (-) (#) (#) (m) (-) (-)\n";
    for (int k = 1; k <= 9; ++k)
        deck += std::to_string(k) + " chain " + std::to_string(k) + " " + std::to_string(k + 1) + " 100 4 -\n";
    deck += "---------------------- OPTIONS ----\n320 WtrDpth\n------------------------- need this line ----\n";
    UCParams p;
    uc_params_default(&p);
    char msg[512];
    ASSERT_EQ(uc_line_file_apply(deck.data(), deck.size(), &p, nullptr, nullptr, 0, msg, sizeof msg), 1);
    EXPECT_NE(std::strstr(msg, "a chain of 9 lines: at most 8 lines (sections) are supported"), nullptr) << msg;
    EXPECT_EQ(std::strncmp(msg, "line ", 5), 0) << msg;
}

// ---- refusals: each names the line of the deck

TEST(LineFile, ViscoelasticLineTypesGiveTheStaticAndDynamicStiffnessAndDamping) {
    UCParams p;
    uc_params_default(&p);
    double tow[3] = {0, 0, 0};
    char notes[4096], msg[512];
    // MoorDyn's EA_s|EA_Dc|EA_D_Lm with BA_s|BA_d: EA is the static stiffness, BA_s its damping
    std::string deck = edit(kSingleChain, "7.5e8   -0.8", "1.424e8|1.586e8|0.4 4e9|11e6");
    ASSERT_EQ(uc_line_file_apply(deck.data(), deck.size(), &p, tow, notes, sizeof notes, msg, sizeof msg), 0) << msg;
    EXPECT_EQ(p.EA, 1.424e8);
    EXPECT_EQ(p.EAdynamic, 1.586e8);
    EXPECT_EQ(p.EAdynamicSlope, 0.4);
    EXPECT_EQ(p.axialDamping, 4e9);
    EXPECT_EQ(p.axialDampingDynamic, 11e6);
    EXPECT_EQ(uc::check_params(p), "");
    // EA_s|EA_d alone: a constant dynamic stiffness, no dynamic damping; -zeta converted with EA_s
    deck = edit(kSingleChain, "7.5e8   -0.8", "7e8|9e8 -0.8");
    ASSERT_EQ(uc_line_file_apply(deck.data(), deck.size(), &p, tow, notes, sizeof notes, msg, sizeof msg), 0) << msg;
    EXPECT_EQ(p.EA, 7e8);
    EXPECT_EQ(p.EAdynamic, 9e8);
    EXPECT_EQ(p.EAdynamicSlope, 0.0);
    EXPECT_EQ(p.axialDampingDynamic, 0.0);
    EXPECT_EQ(p.axialDamping, 0.8 * (900.0 / 40.0) * std::sqrt(7e8 * 113.0));
    // a constant deck loaded after it leaves no viscoelastic model behind
    deck = kSingleChain;
    ASSERT_EQ(uc_line_file_apply(deck.data(), deck.size(), &p, tow, notes, sizeof notes, msg, sizeof msg), 0) << msg;
    EXPECT_EQ(p.EAdynamic, 0.0);
}

TEST(LineFileRefuses, BodiesRodsAndOtherObjects) {
    std::string d = edit(kSingleChain, "---------------------- POINTS",
                         "---- BODIES ----\nID Attachment X0\n(#) (-) (m)\n1 coupled 0 0 0 0 0 0 0 0 0 0 0 0\n"
                         "---------------------- POINTS");
    expect_refused(d, "1 coupled", "bodies are not supported (BODIES section)");
    d = edit(kSingleChain, "---------------------- POINTS",
             "---- RODS ----\nID RodType\n(#) (-)\n1 can body1 0 0 0 0 0 1 4 p\n---------------------- POINTS");
    expect_refused(d, "1 can body1", "rod type 'can' is not among the ROD TYPES (none)");
    d = edit(kSingleChain, "chain      1        2", "chain      R1A      2");
    expect_refused(d, "R1A", "AttachA 'R1A': a rod's end, but the deck has no RODS rows");
    d = edit(kSingleChain, "1     Fixed ", "1     Body1 ");
    expect_refused(d, "Body1", "a point attached to 'Body1': bodies are not supported");
    d = edit(kSingleChain, "0.002    dtM",
             "0.002 dtM\n---- EXTERNAL LOADS ----\nID Object\n(#) (-)\n1 Point1 0|0|0 0|0|0 0|0|0 -");
    expect_refused(d, "1 Point1", "external loads");
}

TEST(LineFileRefuses, SeveralChainsAndPoints) {
    const std::string coupled = "2     Coupled    0       0     -70    0      0       0      0";
    const std::string line1 = "1     chain      1        2        900       40       -";
    expect_refused(edit(edit(kSingleChain, "2     Coupled", "2     Free   "), "1     Fixed ", "1     Free  "), "",
                   "no Vessel, Coupled or Fixed point");
    std::string d = edit(kSingleChain, "1     Fixed ", "1     Vessel");
    expect_refused(d, "2     Coupled", "a second Vessel point (the first is point 1)");
    d = edit(edit(kSingleChain, coupled,
                  coupled + "\n3     Fixed      850     0     -320   0      0       0      0\n"
                            "4     Vessel     10      0     -70    0      0       0      0"),
             line1, "1 chain 1 2 900 40 -\n2 chain 3 4 900 40 -");
    expect_refused(d, "3     Fixed", "a second Fixed point");
    d = edit(edit(kSingleChain, coupled,
                  coupled + "\n3     Free       -400    0     -200   0      0       0      0\n"
                            "4     Free       -400    0     -100   0      0       0      0\n"
                            "5     Free       -400    0     -150   0      0       0      0"),
             line1, "1 chain 1 3 400 20 -\n2 chain 3 2 500 20 -\n3 chain 3 4 100 5 -\n4 chain 4 5 10 1 -");
    expect_refused(d, "3     Free", "Free point 3 joins 3 lines");
    d = edit(edit(kSingleChain, coupled,
                  coupled + "\n3     Free       -400    0     -200   0      0       0      0\n"
                            "4     Free       -400    0     -100   0      0       0      0"),
             line1, "1 chain 1 2 900 40 -\n2 chain 3 4 100 5 -");
    expect_refused(d, "2 chain 3 4", "line 2 is not on the chain");
    d = edit(kSingleChain, coupled, coupled + "\n3     Free       -400    0     -200   0      0       0      0");
    expect_refused(d, "3     Free", "point 3 is not attached to any line");
    d = edit(kSingleChain, "chain      1        2", "chain      2        2");
    expect_refused(d, "chain      2        2", "AttachA and AttachB are the same point");
    d = edit(kSingleChain, "chain      1        2", "chain      1        7");
    expect_refused(d, "chain      1        7", "AttachB '7': there is no point 7 (the POINTS table has 2)");
}

TEST(LineFileRefuses, UnknownLineTypesAndNonNumericFields) {
    std::string d = edit(kSingleChain, "1     chain ", "1     Chain ");
    expect_refused(d, "1     Chain", "line type 'Chain' is not among the LINE TYPES ('chain')");
    d = edit(kSingleChain, "chain      0.0766", "chain      0.07x6");
    expect_refused(d, "0.07x6", "Diam '0.07x6' is not a number");
    d = edit(kSingleChain, "900       40", "nine      40");
    expect_refused(d, "nine", "UnstrLen 'nine' is not a number");
    d = edit(kSingleChain, "900       40", "900       4.5");
    expect_refused(d, "4.5", "NumSegs '4.5' is not a whole number");
    d = edit(kSingleChain, "900       40", "900       0 ");
    expect_refused(d, "900       0 ", "NumSegs = 0: must be between 1 and 100000");
    d = edit(kSingleChain, "-850    0     -320   0", "-850    0     nan    0");
    expect_refused(d, "nan", "Z 'nan' is not a number");
    d = edit(kSingleChain, "113     7.5e8", "-113    7.5e8");
    expect_refused(d, "-113", "Mass/m = -113: must be positive");
    d = edit(kSingleChain, "-0.8      0    2.4", "-0.8      0    -2.4");
    expect_refused(d, "-2.4", "Cd = -2.4: must not be negative");
    d = edit(kSingleChain, "0.002    dtM", "abc    g");
    expect_refused(d, "abc", "g 'abc' is not a number");
    d = edit(kSingleChain, "1     Fixed      -850", "3     Fixed      -850");
    expect_refused(d, "3     Fixed", "point ID 3: IDs must be 1, 2, 3, ... in order (expected 1)");
    d = edit(kSingleChain, "1     chain      1", "2     chain      1");
    expect_refused(d, "2     chain", "line ID 2: IDs must be 1, 2, 3, ... in order (expected 1)");
}

TEST(LineFileRefuses, NonLinearAndOtherUnsupportedLineProperties) {
    std::string d = edit(kSingleChain, "7.5e8   -0.8", "ea.txt  -0.8");
    expect_refused(d, "ea.txt", "EA 'ea.txt': the tension-strain file is not next to the deck, or cannot be read");
    // the viscoelastic model loads (ViscoelasticDeck below); what it cannot be is refused
    d = edit(kSingleChain, "7.5e8   -0.8", "9e8|7e8 -0.8");
    expect_refused(d, "9e8|7e8", "a dynamic stiffness above it [N] (the springs are in series)");
    d = edit(kSingleChain, "7.5e8   -0.8", "7e8|9e8|x -0.8");
    expect_refused(d, "7e8|9e8|x", "a viscoelastic EA is EA_s|EA_d or EA_s|EA_Dc|EA_D_Lm");
    d = edit(kSingleChain, "7.5e8   -0.8", "7e8|9e8 0|0");
    expect_refused(d, "0|0", "the viscoelastic model needs a damping");
    d = edit(kSingleChain, "7.5e8   -0.8", "SYROPE:wc.txt|1e8|0.4 -0.8");  // (LineFileSyrope below)
    expect_refused(d, "SYROPE", "EA 'SYROPE:wc.txt|1e8|0.4': the Syrope settings file 'wc.txt' is not next to the deck");
    d = edit(kSingleChain, "7.5e8   -0.8", "7.5e8   1e5|2e5");
    expect_refused(d, "1e5|2e5", "BA_s|BA_d belongs to a viscoelastic EA");
    d = edit(kSingleChain, "7.5e8   -0.8", "7.5e8   ba.txt");
    expect_refused(d, "ba.txt", "a non-linear damping (table) is not supported");
    d = edit(kSingleChain, "-0.8      0    2.4", "-0.8      ei.txt 2.4");
    expect_refused(d, "ei.txt", "EI 'ei.txt': a non-linear bending stiffness");
    // vortex-induced vibration: Cl alone (MoorDyn's dF 0.08 and cF 0.18), or Cl dF cF
    const Read viv = read(edit(kSingleChain, "1.0   0.2   0.0\n", "1.0   0.2   0.0   0.8\n"));
    ASSERT_TRUE(viv.ok) << viv.error;
    EXPECT_EQ(viv.line.sections[0].Cl, 0.8);
    EXPECT_EQ(viv.line.sections[0].vivFrequencyRange, 0.08);
    EXPECT_EQ(viv.line.sections[0].vivFrequency, 0.18);
    const Read vivFull = read(edit(kSingleChain, "1.0   0.2   0.0\n", "1.0   0.2   0.0   0.7 0.05 0.2\n"));
    ASSERT_TRUE(vivFull.ok) << vivFull.error;
    EXPECT_EQ(vivFull.line.sections[0].Cl, 0.7);
    EXPECT_EQ(vivFull.line.sections[0].vivFrequencyRange, 0.05);
    EXPECT_EQ(vivFull.line.sections[0].vivFrequency, 0.2);
    d = edit(kSingleChain, "1.0   0.2   0.0\n", "1.0   0.2   0.0   -0.8\n");
    expect_refused(d, "-0.8\n", "Cl");
    d = edit(kSingleChain, "1.0   0.2   0.0\n", "1.0   0.2   0.0   0.8 0.08 0\n");
    expect_refused(d, "0.8 0.08 0", "cF = 0: the centre of the VIV model's non-dimensional shedding frequencies is positive");
    const Read r = read(edit(kSingleChain, "1.0   0.2   0.0\n", "1.0   0.2   0.0   0 0.08 0.18\n"));
    EXPECT_TRUE(r.ok) << r.error;  // Cl = 0: no VIV, dF and cF unused
    EXPECT_EQ(r.line.sections[0].Cl, 0.0);
    d = edit(kSingleChain, "1.0   0.2   0.0\n", "1.0   0.2\n");
    expect_refused(d, "1.0   0.2\n", "this row has 9");
    d = edit(kSingleChain, "0.002    dtM", "2 WaveKin");
    expect_refused(d, "2 WaveKin", "WaveKin = 2: MoorDyn reads wave_frequencies.txt from the deck's directory");
    d = edit(kSingleChain, "0.002    dtM", "1 Currents");  // its file is not handed over
    expect_refused(d, "1 Currents", "Currents = 1: MoorDyn reads current_profile.txt from the deck's directory");
    d = edit(kSingleChain, "320      WtrDpth", "bathy.txt WtrDpth");
    expect_refused(d, "bathy.txt", "a bathymetry file is not supported");
    d = edit(kSingleChain, "0.002    dtM", "sea.txt SeafloorFile");  // its file is not handed over
    expect_refused(d, "sea.txt", "SeafloorFile 'sea.txt': it could not be read");
    d = edit(kSingleChain, "1     Fixed      -850    0     -320   0      0       0      0",
             "1     Free       -850    0     -320   0      0   0 0 -100  0      0");
    expect_refused(d, "1     Free", "a steady force on a Free point is not supported");
}

TEST(LineFileRefuses, MissingOrMalformedSections) {
    expect_refused("", "", "the deck has no LINE TYPES section");
    std::string d = edit(kSingleChain, "---------------------- LINES", "---------------------- LIMES");
    expect_refused(d, "", "the deck has no LINES section");
    d = edit(kSingleChain, "1     chain      1        2        900       40       -\n", "");
    expect_refused(d, "---------------------- LINES", "the LINES table is empty");
    d = edit(kSingleChain, "---------------------- OPTIONS", "---- POINT LIST ----\n---------------------- OPTIONS");
    expect_refused(d, "POINT LIST", "a second POINTS section (the first is at line 7)");
    d = edit(kSingleChain, "(#)   (name)     (#)      (#)      (m)       (-)      (-)\n"
                           "1     chain      1        2        900       40       -\n", "");
    expect_refused(d, "---------------------- LINES", "the LINES table needs a line of column names and a line of units");
    d = edit(kSingleChain, "1     Fixed      -850    0     -320   0      0       0      0",
             "1     Fixed      -850    0     -320   0      0       0");
    expect_refused(d, "1     Fixed", "a point has 9 fields");
    d = edit(kSingleChain, "1     chain      1        2        900       40       -", "1     chain      1        2        900");
    expect_refused(d, "1     chain", "this row has 5");
    d = edit(kSingleChain, "chain      0.0766  113",
             "chain      0.0766  113     7.5e8   -0.8      0    2.4   1.0   0.2   0.0\nchain      0.0800  113");
    expect_refused(d, "0.0800", "line type 'chain' is defined twice (also at line 6)");
}

TEST(LineFile, TwelveColumnPointsWithZeroForcesAreRead) {
    const Read r = read(edit(kSingleChain, "-850    0     -320   0      0       0      0",
                             "-850    0     -320   0      0   0 0 0  0      0"));
    EXPECT_TRUE(r.ok) << r.error;
}

// ---- robustness: random truncations and mutations of a valid deck (fixed seed) never crash the reader;
// a refusal always says where or what.


TEST(LineFileFuzz, TruncationsAndMutationsOfAValidDeckNeverCrash) {
    std::mt19937 rng(20240607u);
    int accepted = 0, refused = 0;
    for (int i = 0; i < 20000; ++i) {
        const std::string deck = mutate_deck(i % 2 ? kChainWireChain : kSingleChain, rng);
        UCParams p;
        uc_params_default(&p);
        p.lineFileElements = static_cast<int>(rng() % 3) * 7;
        char notes[2048], msg[512];
        msg[0] = '\0';
        const int rc = uc_line_file_apply(deck.data(), deck.size(), &p, nullptr, notes, sizeof notes, msg, sizeof msg);
        ASSERT_TRUE(rc == 0 || rc == 1) << rc;
        if (rc == 0) {
            ++accepted;
            continue;
        }
        ++refused;
        const std::string m = msg;
        ASSERT_FALSE(m.empty()) << "iteration " << i;
        bool named = false;
        const bool inDeck = names_a_line_of(m, deck, &named);
        ASSERT_TRUE(named ? inDeck : m.rfind("the ", 0) == 0) << m << ", iteration " << i;
    }
    // Both outcomes occur (the mutations are neither all harmless nor all fatal).
    EXPECT_GT(accepted, 1000);
    EXPECT_GT(refused, 1000);
}

// ------------------------------------------------------------------ no Vessel point: a Fixed tow point
TEST(LineFileFixedTowPoint, ALineHangingFromAFixedPointHasItAsTowPoint) {
    // the anchor at the top, the Vessel point made a Free end with a mass: the line hangs from point 1
    const std::string d = edit(edit(kSingleChain, "1     Fixed      -850    0     -320", "1     Fixed      0       0     -10 "),
                               "2     Coupled    0       0     -70    0", "2     Free       0       0     -70    500");
    const Read r = read(d);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(r.line.towFixed);
    EXPECT_EQ(r.line.farEnd, uc::LineFileFarEnd::Body);
    EXPECT_DOUBLE_EQ(r.line.towPoint[2], -10.0);
    EXPECT_DOUBLE_EQ(r.line.body.mass, 500.0);
    EXPECT_TRUE(has_note(r.line, "the Fixed point 1 is the tow point"));
}

TEST(LineFileFixedTowPoint, BetweenTwoFixedPointsTheHigherIsTheTowPoint) {
    const Read r = read(edit(kSingleChain, "2     Coupled", "2     Fixed  "));
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(r.line.towFixed);
    EXPECT_DOUBLE_EQ(r.line.towPoint[2], -70.0);   // point 2, above point 1
    EXPECT_DOUBLE_EQ(r.line.anchor[0], -850.0);
    // on a tie, the point at AttachB of its line (MoorDyn's fairlead end)
    const Read tie = read(edit(edit(kSingleChain, "2     Coupled    0       0     -70", "2     Fixed      0       0     -320"),
                               "chain      1        2", "chain      2        1"));
    ASSERT_TRUE(tie.ok) << tie.error;
    EXPECT_DOUBLE_EQ(tie.line.towPoint[0], -850.0);
    // a third Fixed point is refused
    const std::string coupled = "2     Coupled    0       0     -70    0      0       0      0";
    const std::string three = edit(edit(kSingleChain, coupled,
                                        "2     Fixed      0       0     -70    0      0       0      0\n"
                                        "3     Fixed      10      0     -70    0      0       0      0"),
                                   "1     chain      1        2        900       40       -",
                                   "1 chain 1 2 900 40 -\n2 chain 3 2 10 1 -");
    expect_refused(three, "3     Fixed", "a third Fixed point (the first is point 1)");
}

// ------------------------------------------------------------------ kinematics options
Read read_with(const std::string& text, const uc::LineFileCompanions& files) {
    Read r;
    r.ok = uc::read_line_file(text, 0, r.line, r.error, files);
    return r;
}

TEST(LineFileKinematics, ASteadyCurrentProfileIsTheFmusProfileWithoutItsRedundantRows) {
    const std::string d = edit(kSingleChain, "0.002    dtM", "1 Currents");
    EXPECT_EQ(uc::line_file_companions(d), std::vector<std::string>{"current_profile.txt"});
    // 7 rows, z increasing; the rows at -300 and -250 lie on the chord of their neighbours, -320 repeats -310
    const std::string profile = "--- currents\ncomment\nz ux uy uz\n-320 0.1 0 0\n-310 0.1 0 0\n-300 0.2 0.05 0\n"
                                "-250 0.7 0.3 0\n-200 1.2 0.55 0\n\n-100 1.0 0.5\n0 1.5\n";
    const Read r = read_with(d, {{"current_profile.txt", profile}});
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(r.line.sea.profileRows, 4);
    const double depth[] = {0, 100, 200, 310}, ux[] = {1.5, 1.0, 1.2, 0.1}, uy[] = {0, 0.5, 0.55, 0.1 * 0};
    for (int k = 0; k < 4; ++k) {
        EXPECT_DOUBLE_EQ(r.line.sea.profileDepth[k], depth[k]);
        EXPECT_DOUBLE_EQ(r.line.sea.profileX[k], ux[k]);
        EXPECT_DOUBLE_EQ(r.line.sea.profileY[k], uy[k]);
    }
    UCParams p;
    uc_params_default(&p);
    std::string error;
    ASSERT_TRUE(uc::apply_line_file(r.line, p, error)) << error;
    EXPECT_EQ(p.currentProfileRows, 4);
    EXPECT_DOUBLE_EQ(p.currentProfileDepth[3], 310.0);
    EXPECT_DOUBLE_EQ(p.currentProfileX[3], 0.1);
}

TEST(LineFileKinematics, CurrentsGivenAsDataAreTheCurrentsModeWithTheFileBesideTheDeck) {
    // Currents 2: a profile changing in time; Currents 5: a grid in x, y, z and t (MoorDyn's formats)
    const std::string dynamic = "--- currents\ncomment\n2\n3\n-300 0\n\n0 0.1 0.2 0 0\n10 0.3 0.4 0.1 0\n";
    const std::string grid4d = "1 1 2 2\n0\n0\n-300 0\n0 10\n0 0 -300 0 0.1 0 0\n0 0 -300 10 0.3 0 0\n"
                               "0 0 0 0 0.2 0 0\n0 0 0 10 0.4 0 0\n";
    for (const auto& [mode, name, text] : std::vector<std::tuple<int, std::string, std::string>>{
             {2, "current_profile_dynamic.txt", dynamic}, {5, "current_profile_4d.txt", grid4d}}) {
        const std::string d = edit(kSingleChain, "0.002    dtM", std::to_string(mode) + " Currents");
        EXPECT_EQ(uc::line_file_companions(d), std::vector<std::string>{name});
        const Read r = read_with(d, {{name, text}});
        ASSERT_TRUE(r.ok) << r.error;
        ASSERT_TRUE(r.line.sea.currentGrid);
        uc::Vec3 u;
        r.line.sea.currentGrid->at(uc::Vec3(-500.0, 3.0, -150.0), 5.0, u);
        EXPECT_NEAR(u.x(), 0.25, 1e-15);  // halfway in depth and in time
        bool said = false;
        for (const std::string& n : r.line.notes) said |= n.find("Currents " + std::to_string(mode) + ": " + name) != std::string::npos;
        EXPECT_TRUE(said);
        UCParams p;
        uc_params_default(&p);
        std::string error;
        ASSERT_TRUE(uc::apply_line_file(r.line, p, error)) << error;
        EXPECT_EQ(p.currentsMode, mode);
        EXPECT_EQ(std::string(p.currentsFile), name);  // the adapter puts the path it was read from in its place
        // a currents.file the importer set keeps its place and its mode
        UCParams own;
        uc_params_default(&own);
        own.currentsMode = 5;
        std::snprintf(own.currentsFile, sizeof own.currentsFile, "%s", "mine.txt");
        ASSERT_TRUE(uc::apply_line_file(r.line, own, error)) << error;
        EXPECT_EQ(own.currentsMode, 5);
        EXPECT_EQ(std::string(own.currentsFile), "mine.txt");
        // data that are not such a file are refused naming the deck's line, the file and its line
        const Read bad = read_with(d, {{name, text + "1 2 3\n"}});
        ASSERT_FALSE(bad.ok);
        EXPECT_NE(bad.error.find("Currents = " + std::to_string(mode) + ": " + name + ": line "), std::string::npos)
            << bad.error;
    }
}

// MoorDyn's SeafloorFile grid (nx ny, the x values, the y values, rows x y z) of heights a + b x + c y,
// one point moved up by `bump`.
std::string seafloor_grid(double a, double b, double c, double bump) {
    const double xs[] = {-1000.0, -400.0, 0.0, 250.0}, ys[] = {-300.0, 0.0, 500.0};
    std::string text = "4 3\n-1000 -400 0 250\n-300 0 500\n";
    for (double x : xs)
        for (double y : ys) {
            const double z = a + b * x + c * y + (x == 0.0 && y == 0.0 ? bump : 0.0);
            char row[120];
            std::snprintf(row, sizeof row, "%.17g %.17g %.17g\n", x, y, z);
            text += row;
        }
    return text;
}

TEST(LineFileSeabed, ASeafloorFileThatIsAPlaneIsTheSlopedSeabed) {
    // The plane z = -320 + 0.05 x - 0.02 y: 320 m deep under the origin, rising along x, falling along
    // y, so it descends towards (-0.05, 0.02) at atan(|(0.05, -0.02)|).
    const std::string d = edit(kSingleChain, "0.002    dtM", "Mooring/3D_seafloor/bed.txt SeafloorFile");
    EXPECT_EQ(uc::line_file_companions(d), std::vector<std::string>{"Mooring/3D_seafloor/bed.txt"});
    const Read r = read_with(d, {{"Mooring/3D_seafloor/bed.txt", seafloor_grid(-320.0, 0.05, -0.02, 0.0)}});
    ASSERT_TRUE(r.ok) << r.error;
    UCParams p;
    uc_params_default(&p);
    std::string error;
    ASSERT_TRUE(uc::apply_line_file(r.line, p, error)) << error;
    EXPECT_NEAR(p.waterDepth, 320.0, 1e-9);
    EXPECT_NEAR(p.seabedSlope, std::atan(std::hypot(0.05, 0.02)) * 180.0 / uc::kPi, 1e-9);
    EXPECT_NEAR(p.seabedSlopeHeading, std::atan2(0.02, -0.05) * 180.0 / uc::kPi, 1e-9);
    // the FMU's plane through those parameters gives back the file's heights
    uc::SeabedProps bed;
    bed.depth = p.waterDepth;
    uc::set_slope(bed, p.seabedSlope, p.seabedSlopeHeading);
    EXPECT_NEAR(uc::seabed_height(bed, -850.0, 40.0), -320.0 + 0.05 * -850.0 - 0.02 * 40.0, 1e-9);
    bool said = false;
    for (const std::string& n : r.line.notes) said |= n.find("SeafloorFile: its grid is a plane") != std::string::npos;
    EXPECT_TRUE(said);
    // a grid that is not a plane is the seabed as a grid (seabed.file, the file by its name beside the deck),
    // the water depth its mean depth as MoorDyn takes it; a file that is missing is refused naming the file
    const Read bumpy = read_with(d, {{"Mooring/3D_seafloor/bed.txt", seafloor_grid(-320.0, 0.05, -0.02, 2.0)}});
    ASSERT_TRUE(bumpy.ok) << bumpy.error;
    ASSERT_TRUE(bumpy.line.seabed.grid);
    EXPECT_NEAR(bumpy.line.seabed.grid->height(0.0, 0.0), -318.0, 1e-9);
    UCParams q;
    uc_params_default(&q);
    ASSERT_TRUE(uc::apply_line_file(bumpy.line, q, error)) << error;
    EXPECT_STREQ(q.seabedFile, "Mooring/3D_seafloor/bed.txt");
    EXPECT_EQ(q.seabedSlope, 0.0);
    double mean = 0.0;
    for (double x : {-1000.0, -400.0, 0.0, 250.0})
        for (double y : {-300.0, 0.0, 500.0}) mean += (-320.0 + 0.05 * x - 0.02 * y) / 12.0;
    EXPECT_NEAR(q.waterDepth, -(mean + 2.0 / 12.0), 1e-9);
    said = false;
    for (const std::string& n : bumpy.line.notes) said |= n.find("SeafloorFile: its grid is not a plane") != std::string::npos;
    EXPECT_TRUE(said);
    const Read broken = read_with(d, {{"Mooring/3D_seafloor/bed.txt", "4 3\n-1000 -400 250 0\n-300 0 500\n"}});
    ASSERT_FALSE(broken.ok);
    EXPECT_NE(broken.error.find("SeafloorFile 'Mooring/3D_seafloor/bed.txt': "), std::string::npos) << broken.error;
    const Read missing = read_with(d, {});
    ASSERT_FALSE(missing.ok);
    EXPECT_NE(missing.error.find("it could not be read"), std::string::npos) << missing.error;
}

TEST(LineFileKinematics, WhatTheFmusSeaCannotHoldIsRefusedNamingOptionAndValue) {
    const std::string d = edit(kSingleChain, "0.002    dtM", "1 Currents");
    auto refused = [&](const std::string& deck, const uc::LineFileCompanions& files) {
        const Read r = read_with(deck, files);
        EXPECT_FALSE(r.ok);
        return r.error;
    };
    std::string many = "a\nb\nc\n";
    for (int k = 0; k < 12; ++k) many += std::to_string(-12 + k) + " " + std::to_string(k % 2) + " 0 0\n";
    EXPECT_NE(refused(d, {{"current_profile.txt", many}}).find("a profile of 12 rows, 12 of them off the straight "
                                                                 "lines between their neighbours"), std::string::npos);
    EXPECT_NE(refused(d, {{"current_profile.txt", "a\nb\nc\n-10 1 0 0.2\n"}}).find("a vertical current"), std::string::npos);
    EXPECT_NE(refused(d, {{"current_profile.txt", "a\nb\nc\n0 1\n-10 1\n"}}).find("z must increase"), std::string::npos);
    for (const auto& [option, what] : std::vector<std::pair<std::string, std::string>>{
             {"2 Currents", "Currents = 2: MoorDyn reads current_profile_dynamic.txt from the deck's directory"},
             {"3 Currents", "Currents = 3: not implemented in MoorDyn v2 either"},
             {"5 Currents", "Currents = 5: MoorDyn reads current_profile_4d.txt from the deck's directory"},
             {"3 WaveKin", "WaveKin = 3: MoorDyn reads wave_elevation.txt from the deck's directory"},
             {"5 WaveKin", "WaveKin = 5: not implemented in MoorDyn v2 either"},
             {"9 WaveKin", "WaveKin = 9: not a MoorDyn v2 option"}}) {
        expect_refused(edit(kSingleChain, "0.002    dtM", option), option, what);
    }
    const std::string w = edit(kSingleChain, "0.002    dtM", "7 WaveKin");
    EXPECT_NE(refused(w, {{"wave_frequencies.txt", "0 0 0\n-0.4 1 0\n"}}).find("line 2: a component of frequency -0.4"), std::string::npos);
    const std::string s = edit(kSingleChain, "0.002    dtM", "2 WaveKin");
    EXPECT_NE(refused(s, {{"wave_frequencies.txt", "0.1 0 0\n0.4 1 0\n"}}).find("the first at 0 rad/s"), std::string::npos);
    EXPECT_NE(refused(s, {{"wave_frequencies.txt", "0 0 0\n0.4 1 0\n0.4 1 0\n"}}).find("line 3: omega = 0.4"),
              std::string::npos);
    const std::string e = edit(kSingleChain, "0.002    dtM", "3 WaveKin");
    EXPECT_NE(refused(e, {{"wave_elevation.txt", "0 0\n0.1 0.2\n"}}).find("shorter than two steps of dtWave = 0.25 s"),
              std::string::npos);
    EXPECT_NE(refused(e, {{"wave_elevation.txt", "0 0\n1 0.2\n0.5 0\n"}}).find("line 3: t = 0.5 s: the times must increase"),
              std::string::npos);
}

namespace {

// The deck's given components (waves.mode 3) as written into the parameters.
std::vector<std::array<double, 4>> given_components(const Read& r) {
    UCParams p;
    uc_params_default(&p);
    std::string error;
    EXPECT_TRUE(uc::apply_line_file(r.line, p, error)) << error;
    EXPECT_EQ(p.wavesMode, 3);
    EXPECT_EQ(p.wavesStretching, 1);
    std::vector<std::array<double, 4>> out;
    for (int k = 0; k < p.waveComponentCount; ++k)
        out.push_back({p.waveComponents[4 * k], p.waveComponents[4 * k + 1], p.waveComponents[4 * k + 2], p.waveComponents[4 * k + 3]});
    return out;
}

}  // namespace

TEST(LineFileKinematics, WaveKin7ComponentsAreGivenComponentsInTheFmusConvention) {
    // MoorDyn's |A| sin(w t - k x + arg A) is a cos(k x - w t + p) with a = |A|, p = pi/2 - arg A
    const std::string w = edit(kSingleChain, "0.002    dtM", "7 WaveKin");
    const Read r = read_with(w, {{"wave_frequencies.txt", "0.0 0.0 0.0\n0.35 1.0 0.0 0.0\n0.4 0.0 1.0 1.57\n0.6 0.0 0.0\n"}});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_FALSE(r.line.sea.regularWave);
    EXPECT_TRUE(has_note(r.line, "WaveKin 7: the 2 components of wave_frequencies.txt are the given components of waves.mode 3"));
    const auto c = given_components(r);
    ASSERT_EQ(c.size(), 2u);
    const double half = 2.0 * std::acos(0.0) / 2.0;
    EXPECT_EQ(c[0], (std::array<double, 4>{0.35, 1.0, half, 0.0}));
    EXPECT_EQ(c[1], (std::array<double, 4>{0.4, 1.0, 0.0, 1.57}));
    const Read zero = read_with(w, {{"wave_frequencies.txt", "0 0 0\n0.4 1 0\n"}});  // arg A = 0: one component, not the regular wave
    ASSERT_TRUE(zero.ok) << zero.error;
    EXPECT_EQ(given_components(zero), (std::vector<std::array<double, 4>>{{0.4, 1.0, half, 0.0}}));
}

TEST(LineFileKinematics, WaveKin2SpectrumIsInterpolatedToMoorDynsEqualStepsAndWaveKin3RecordIsItsFourierComponents) {
    // WaveKin 2: steps of 0.1 rad/s (the smallest spacing) from 0 to 0.4; A interpolated linearly between
    // rows; MoorDyn's elevation Re(A e^{i (w t - k x)}): p = -arg A; the last frequency (the transform's
    // Nyquist bin) enters as Re(A) / 2.
    const std::string s = edit(kSingleChain, "0.002    dtM", "2 WaveKin");
    const Read r = read_with(s, {{"wave_frequencies.txt", "0 0 0\n0.2 1 0\n0.3 0 2\n0.4 -1.5 3\n"}});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(has_note(r.line, "WaveKin 2: the spectrum of wave_frequencies.txt, interpolated to equal frequency steps"));
    const auto c = given_components(r);
    ASSERT_EQ(c.size(), 4u);
    const double pi = 2.0 * std::acos(0.0);
    EXPECT_NEAR(c[0][0], 0.1, 1e-15);
    EXPECT_NEAR(c[0][1], 0.5, 1e-15);  // halfway from 0 to 1
    EXPECT_NEAR(c[0][2], 0.0, 1e-15);
    EXPECT_NEAR(c[2][1], 2.0, 1e-14);  // interpolated at 3 x 0.1 rad/s, as MoorDyn does: round-off
    EXPECT_NEAR(c[2][2], -pi / 2, 1e-15);
    EXPECT_NEAR(c[3][0], 0.4, 1e-15);
    EXPECT_NEAR(c[3][1], 0.75, 1e-15);  // Re(A) / 2 = -0.75: amplitude 0.75, phase pi
    EXPECT_NEAR(std::abs(c[3][2]), pi, 1e-15);
    // WaveKin 3: a record of known components on the transform's frequencies (dtWave 0.5 s, 80 samples:
    // dw = 2 pi / 40 s) returns them, amplitudes and phases to 1e-12; a 0.75 m mean is left out (noted).
    const double dw = 2.0 * pi / 40.0;
    const std::vector<std::array<double, 3>> known = {{3 * dw, 0.8, 0.4}, {7 * dw, 0.3, -2.0}, {20 * dw, 0.1, 1.0}};
    std::string record;
    for (int m = 0; m <= 80; ++m) {  // 81 samples: the odd last one is dropped, as MoorDyn does
        const double t = 0.5 * m;
        double eta = 0.75;
        for (const auto& k : known) eta += k[1] * std::cos(-k[0] * t + k[2]);
        char row[64];
        std::snprintf(row, sizeof row, "%.17g %.17g\n", t, eta);
        record += row;
    }
    const std::string e = edit(kSingleChain, "0.002    dtM", "3 WaveKin\n0.5 dtWave");
    const Read rr = read_with(e, {{"wave_elevation.txt", record}});
    ASSERT_TRUE(rr.ok) << rr.error;
    EXPECT_TRUE(has_note(rr.line, "WaveKin 3: the record of wave_elevation.txt resampled at dtWave = 0.5 s (80 samples)"));
    EXPECT_TRUE(has_note(rr.line, "its mean 0.75 m is not a wave: left out"));
    std::vector<std::array<double, 4>> found;
    for (const auto& k : given_components(rr))
        if (k[1] > 1e-12) found.push_back(k);
    ASSERT_EQ(found.size(), known.size());
    for (size_t i = 0; i < known.size(); ++i) {
        EXPECT_NEAR(found[i][0], known[i][0], 1e-14);
        EXPECT_NEAR(found[i][1], known[i][1], 1e-12);
        EXPECT_NEAR(std::remainder(found[i][2] - known[i][2], 2 * pi), 0.0, 1e-12);
    }
}

TEST(LineFileKinematics, AWavesFileIsRowsOfComponentsInTheFmusConvention) {
    std::vector<std::array<double, 4>> c;
    std::string error;
    ASSERT_TRUE(uc::read_wave_file("# omega a p beta\n0.5 1.2 0.3\n\n0.7 0.4 -1 1.2\n", 0.25, c, error)) << error;
    EXPECT_EQ(c, (std::vector<std::array<double, 4>>{{0.5, 1.2, 0.3, 0.25}, {0.7, 0.4, -1.0, 1.2}}));
    EXPECT_FALSE(uc::read_wave_file("0.5 1.2\n", 0.0, c, error));
    EXPECT_EQ(error, "line 1: a row is omega [rad/s] amplitude [m] phase [rad] [direction, rad] (a comment starts with #)");
    EXPECT_FALSE(uc::read_wave_file("0.5 x 1\n", 0.0, c, error));
    EXPECT_EQ(error, "line 1: 'x' is not a number");
    UCParams p;
    uc_params_default(&p);
    EXPECT_FALSE(uc::apply_wave_components(std::vector<std::array<double, 4>>(UC_MAX_WAVE_COMPONENTS + 1), "waves.file", p, error));
    EXPECT_EQ(error, "waves.file: 1025 wave components, the FMU holds 1024 (waves.mode 3)");
}

TEST(LineFileKinematics, OneWaveComponentIsTheRegularWaveAndExternalKinematicsTheFmusSea) {
    const std::string w = edit(kSingleChain, "0.002    dtM", "7 WaveKin");
    const Read r = read_with(w, {{"wave_frequencies.txt", "0.0 0.0 0.0\n0.5 0.0 1.5 0.3\n"}});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(r.line.sea.regularWave);
    EXPECT_DOUBLE_EQ(r.line.sea.waveHeight, 3.0);
    EXPECT_DOUBLE_EQ(r.line.sea.wavePeriod, 4.0 * std::acos(0.0) / 0.5);
    EXPECT_DOUBLE_EQ(r.line.sea.waveDirection, 0.3);
    UCParams p;
    uc_params_default(&p);
    std::string error;
    ASSERT_TRUE(uc::apply_line_file(r.line, p, error)) << error;
    EXPECT_EQ(p.wavesMode, 1);
    EXPECT_EQ(p.wavesStretching, 1);
    const Read external = read(edit(kSingleChain, "0.002    dtM", "1 WaveKin"));
    ASSERT_TRUE(external.ok) << external.error;
    EXPECT_TRUE(has_note(external.line, "WaveKin 1 (water kinematics set by the program driving MoorDyn)"));
    EXPECT_EQ(external.line.sea.profileRows, 0);
    EXPECT_FALSE(external.line.sea.regularWave);
}

// ------------------------------------------------------------------ tension-strain files (EA from a file)
namespace {

const char* const kRopeCurve = "polyester working curve\nstrain tension\n(-) (N)\n0.005 2e4\n0.012  6e4\n\n"
                               "0.03 2.3e5 extra-field\n0.045 4.2e5\n---\nignored 1\n";

}  // namespace

TEST(LineFileTensionStrain, AFileAsEaIsTheLinesCurveAndItsSecantTheEa) {
    const std::string d = edit(kSingleChain, "7.5e8   -0.8", "rope.txt  -0.8");
    EXPECT_EQ(uc::line_file_companions(d), std::vector<std::string>{"rope.txt"});
    const Read r = read_with(d, {{"rope.txt", kRopeCurve}});
    ASSERT_TRUE(r.ok) << r.error;
    const uc::LineFileSection& s = r.line.sections[0];
    ASSERT_EQ(s.curveStrain, (std::vector<double>{0.005, 0.012, 0.03, 0.045}));
    ASSERT_EQ(s.curveTension, (std::vector<double>{2e4, 6e4, 2.3e5, 4.2e5}));
    EXPECT_DOUBLE_EQ(s.EA, 4.2e5 / 0.045);  // MoorDyn's EA of a curve: its last point's secant
    // -zeta is converted with that EA, as MoorDyn does
    EXPECT_DOUBLE_EQ(s.axialDamping, 0.8 * (900.0 / 40) * std::sqrt(4.2e5 / 0.045 * 113));
    UCParams p;
    uc_params_default(&p);
    std::string error;
    ASSERT_TRUE(uc::apply_line_file(r.line, p, error)) << error;
    EXPECT_EQ(p.axialCurvePoints, 4);
    EXPECT_EQ(p.axialCurveStrain[2], 0.03);
    EXPECT_EQ(p.axialCurveTension[3], 4.2e5);
    EXPECT_EQ(uc::check_params(p), "");
    // a deck of a constant EA read into the same parameters leaves no curve behind
    const Read chain = read(kSingleChain);
    ASSERT_TRUE(chain.ok) << chain.error;
    ASSERT_TRUE(uc::apply_line_file(chain.line, p, error)) << error;
    EXPECT_EQ(p.axialCurvePoints, 0);
}

TEST(LineFileTensionStrain, AFileThatMakesNoCurveIsRefusedNamingItsLine) {
    const std::string d = edit(kSingleChain, "7.5e8   -0.8", "rope.txt  -0.8");
    auto refused = [&](const std::string& curve) {
        const Read r = read_with(d, {{"rope.txt", curve}});
        EXPECT_FALSE(r.ok);
        EXPECT_EQ(r.error.rfind("line 6: EA 'rope.txt': rope.txt", 0), 0u) << r.error;
        return r.error;
    };
    EXPECT_NE(refused("a\nb\nc\n0.01 1e5\n0.02 abc\n").find("rope.txt line 5: '0.02 abc' is not a row of two numbers"),
              std::string::npos);
    EXPECT_NE(refused("a\nb\nc\n0.01 1e5\n0.02 0.9e5\n").find("the tension falls from point 1"), std::string::npos);
    EXPECT_NE(refused("a\nb\nc\n").find("a tension-strain curve has 2 to 30 points, not 0"), std::string::npos);
    std::string many = "a\nb\nc\n";
    for (int k = 1; k <= 31; ++k) many += std::to_string(0.001 * k) + " " + std::to_string(1000 * k) + "\n";
    EXPECT_NE(refused(many).find("31 points, more than the 30 a curve holds"), std::string::npos);
}

TEST(LineFileTensionStrain, ACurveOnAChainOfLinesIsRefused) {
    // two line types, the second on a curve, in a chain of two lines: the FMU's curve is a uniform line's
    std::string d = edit(kSingleChain, "chain      0.0766  113     7.5e8   -0.8      0    2.4   1.0   0.2   0.0",
                         "chain      0.0766  113     7.5e8   -0.8      0    2.4   1.0   0.2   0.0\n"
                         "rope       0.1     8       rope.txt 1e5     0    1.2   1.0   0.2   0.0");
    d = edit(d, "2     Coupled    0       0     -70    0      0       0      0",
             "2     Coupled    0       0     -70    0      0       0      0\n3     Free   -400 0 -200 0 0 0 0");
    d = edit(d, "1     chain      1        2        900       40       -",
             "1     chain      1        3        500       20       -\n2     rope       3        2        400       20       -");
    const Read r = read_with(d, {{"rope.txt", kRopeCurve}});
    ASSERT_TRUE(r.ok) << r.error;
    UCParams p;
    uc_params_default(&p);
    std::string error;
    EXPECT_FALSE(uc::apply_line_file(r.line, p, error));
    EXPECT_NE(error.find("line type 'rope' has a tension-strain curve (EA from a file) in a chain of 2 lines"),
              std::string::npos) << error;
}

// ------------------------------------------------------------------ the Syrope model (SYROPE:..., SYROPE IC)
namespace {

// MoorDyn's tests/Mooring/syrope/linear_wc/line.txt, its syrope.dat and (the first rows of) ../owc.dat.
const char* const kSyropeDeck = R"(One single segment.
------------------------- LINE TYPES --------------------------------------------------
LineType  Diam    MassDenInAir    EA                        BA/-zeta       EI     Can   Cat  Cdn   Cdt
(-)       (m)       (kg/m)        (-)                       (Pa-s/-)      (n-m^2) (-)   (-)  (-)   (-)
poly      0.203     40      SYROPE:syrope.dat|1.53e8|23.12  5.0e10|1.0e5   0.0    0.0   0.0   0.0  0.0
----------------------- POINTS ----------------------------------------------
Node      Type      X          Y         Z        M        V         CdA   CA
(-)       (-)      (m)        (m)       (m)      (kg)     (m^3)     (m^2)  (-)
1         Fixed    0.0         0       -5.0       0        0          0     0
2         Coupled  1.0148657   0       -5.0       0        0          0     0
-------------------------- LINES -------------------------------------------------
Line     LineType NodeA     NodeB  UnstrLen   NumSegs     Flags/Outputs
(-)      (-)       (-)       (-)    (m)         (-)          (-)
1        poly       2         1     1.0          1           tsc
-------------------------- SYROPE IC -------------------------------------------------------
Line(s)   Tmax0    Tmean0
(-)        (N)      (N)
1       1.3886e6  4.339e5
-------------------------- SOLVER OPTIONS---------------------------------------------------
0        g            - gravitational acceleration
1025     rho          - water density
70       WtrDpth      - water depth
--------------------------- need this line -------------------------------------------------
)";
const char* const kSyropeSettings = "../owc.dat  OWC     Original working curve lookup table path\n"
                                    "LINEAR      WCType  Working curve formula\n"
                                    "1.25e8      k1      First parameter\n"
                                    "0.0         k2      Second parameter\n";
const char* const kOwc = "Strain      Tension\n(-)         (N)\n0.00000e+00 0.00000e+00\n2.06897e-03 1.71768e+05\n"
                         "4.13793e-03 3.30952e+05\n2.06897e-02 1.29964e+06\n4.13793e-02 2.45267e+06\n6.00000e-02 4.38601e+06\n";

uc::LineFileCompanions syrope_files(const std::string& settings = kSyropeSettings) {
    return {{"syrope.dat", settings}, {"../owc.dat", kOwc}};
}

}  // namespace

TEST(LineFileSyrope, TheSyropeModelIsReadWithItsSettingsCurveAndInitialTensions) {
    EXPECT_EQ(uc::line_file_companions(kSyropeDeck), std::vector<std::string>{"syrope.dat"});
    EXPECT_EQ(uc::line_file_nested_companions(kSyropeDeck, "syrope.dat", kSyropeSettings),
              std::vector<std::string>{"../owc.dat"});
    EXPECT_TRUE(uc::line_file_nested_companions(kSyropeDeck, "other.dat", kSyropeSettings).empty());
    const Read r = read_with(kSyropeDeck, syrope_files());
    ASSERT_TRUE(r.ok) << r.error;
    const uc::LineFileSection& s = r.line.sections[0];
    EXPECT_EQ(s.syropeForm, uc::kSyropeLinear);
    EXPECT_EQ(s.syropeK1, 1.25e8);
    EXPECT_EQ(s.syropeTmax0, 1.3886e6);
    EXPECT_EQ(s.syropeTmean0, 4.339e5);
    EXPECT_EQ(s.EAd, 1.53e8);
    EXPECT_EQ(s.EAslope, 23.12);
    EXPECT_EQ(s.axialDamping, 5e10);
    EXPECT_EQ(s.BAd, 1e5);
    // MoorDyn's three header lines: the curve starts at its fourth line, as MoorDyn reads it
    ASSERT_EQ(s.curveStrain.size(), 5u);
    EXPECT_EQ(s.curveStrain[0], 2.06897e-03);
    UCParams p;
    uc_params_default(&p);
    std::string error;
    ASSERT_TRUE(uc::apply_line_file(r.line, p, error)) << error;
    EXPECT_EQ(p.syropeWorkingCurve, uc::kSyropeLinear);
    EXPECT_EQ(p.syropeTensionMax0, 1.3886e6);
    EXPECT_EQ(p.syropeTensionMean0, 4.339e5);
    EXPECT_EQ(p.EAdynamic, 1.53e8);
    EXPECT_EQ(p.axialCurvePoints, 5);
    EXPECT_EQ(uc::check_params(p), "");
}

TEST(LineFileSyrope, WhatMakesNoSyropeRopeIsRefusedNamingItsLine) {
    const std::string ea = "SYROPE:syrope.dat|1.53e8|23.12";
    auto refused = [&](const std::string& deck, const uc::LineFileCompanions& files, const std::string& marker,
                       const std::string& what) {
        const Read r = read_with(deck, files);
        ASSERT_FALSE(r.ok) << "accepted: expected " << what;
        EXPECT_EQ(r.error.rfind("line " + std::to_string(line_of(deck, marker)) + ": ", 0), 0u) << r.error;
        EXPECT_NE(r.error.find(what), std::string::npos) << r.error;
    };
    refused(kSyropeDeck, {}, ea, "the Syrope settings file 'syrope.dat' is not next to the deck");
    refused(kSyropeDeck, {{"syrope.dat", kSyropeSettings}}, ea,
            "the original working curve's file OWC '../owc.dat' (syrope.dat, relative to the deck) cannot be read");
    refused(kSyropeDeck, syrope_files(edit(kSyropeSettings, "LINEAR  ", "CUBIC   ")), ea,
            "syrope.dat line 2: WCType 'CUBIC' is not a working-curve formula (LINEAR, QUADRATIC or EXP)");
    refused(kSyropeDeck, syrope_files(edit(edit(kSyropeSettings, "LINEAR  ", "QUADRATIC"), "1.25e8", "1.5")), ea,
            "k1 = 1.5, k2 = 0: QUADRATIC needs 0 <= k1 < 1 and 0 < k2 <= 1");
    refused(kSyropeDeck, syrope_files(edit(kSyropeSettings, "0.0         k2", "0.0         k3")), ea,
            "syrope.dat: no row \"<value> k2\" gives k2");
    refused(edit(kSyropeDeck, ea, "SYROPE:syrope.dat|1.53e8"), syrope_files(), "SYROPE:syrope.dat|1.53e8",
            "a Syrope EA is SYROPE:<settings file>|EA_Dc|EA_D_Lm");
    refused(edit(kSyropeDeck, "1       1.3886e6  4.339e5", "1       1.3886e6  2e6"), syrope_files(), "1.3886e6  2e6",
            "SYROPE IC of line 1: tensionMean0 = 2e+06 N: Tmean0 lies between 0 and Tmax0");
    refused(edit(kSyropeDeck, "1       1.3886e6  4.339e5", "3       1.3886e6  4.339e5"), syrope_files(), "3       1.3886e6",
            "Line(s) '3': '3' is not a line of the deck (1 to 1)");
    refused(edit(kSyropeDeck, "1       1.3886e6  4.339e5\n", ""), syrope_files(), "1        poly",
            "line 1 has the Syrope model (type 'poly') but no SYROPE IC row: give its Tmax0 and Tmean0 [N]");
    // a SYROPE IC section in a deck without the model: refused, as MoorDyn does
    refused(edit(kSyropeDeck, ea, "1.5e8|3e8"), {}, "1       1.3886e6", "a SYROPE IC section, but no line has the Syrope model");
}
