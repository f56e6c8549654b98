// A line type's minimum breaking load (docs/design_checks.md): the deck's MBL column, MoorPy's default formula
// for a type named for its material (the hand values below are MoorProps_default.yaml's coefficients at the
// nominal diameter d = sqrt(Mass/m / mass_d2)), the refusals, and the parameters the deck writes.
#include <gtest/gtest.h>

#include <string>

#include "api/cable_api.h"
#include "deck/line_file.h"

namespace {

const char* const kDeck = R"(--------------------- MoorDyn Input File ------------------------------------
chain and wire
---------------------- LINE TYPES --------------------------------
TypeName   Diam    Mass/m  EA      BA/-zeta  EI   Cd    Ca    CdAx  CaAx
(name)     (m)     (kg/m)  (N)     (N-s/-)   (-)  (-)   (-)   (-)   (-)
chain      0.135   113     7.5e8   -0.8      0    1.3   1.0   0.1   0.0
wire       0.09    42.0    6.0e8   1.0e6     0    1.2   1.0   0.008 0.0
---------------------- POINTS --------------------------------
ID   Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)        (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed      -850    0     -320   0      0       0      0
2     Free       -400    0     -250   0      0       0      0
3     Coupled    0       0     -70    0      0       0      0
---------------------- LINES --------------------------------------
ID    LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)      (m)       (-)      (-)
1     chain      1        2        500       20       -
2     wire       2        3        420       20       -
---------------------- OPTIONS -----------------------------------------
320      WtrDpth
------------------------- need this line -------------------------------------
)";

std::string edit(std::string deck, const std::string& from, const std::string& to) {
    const size_t at = deck.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) deck.replace(at, from.size(), to);
    return deck;
}

bool has_note(const uc::LineFileLine& line, const std::string& text) {
    for (const std::string& n : line.notes) {
        if (n.find(text) != std::string::npos) return true;
    }
    return false;
}

// The deck's line from the vessel: section 0 the wire, section 1 the chain.
uc::LineFileLine read(const std::string& deck) {
    uc::LineFileLine line;
    std::string error;
    EXPECT_TRUE(uc::read_line_file(deck, 0, line, error)) << error;
    return line;
}

}  // namespace

TEST(BreakingLoad, ChainAndWireTypesGetMoorPysMblAtTheNominalDiameterOfTheirMass) {
    const uc::LineFileLine line = read(kDeck);
    ASSERT_EQ(line.sections.size(), 2u);
    // chain: d = sqrt(113 / 20.0e3) = 0.0751665 m; 9.11e2 d + 1.21e9 d^2 - 2.19e9 d^3 = 5906496.0 N
    EXPECT_NEAR(line.sections[1].MBL, 5906496.0, 1.0);
    // wire: d = sqrt(42 / 5293) = 0.0890787 m; 1022e6 d^2 = 8109578.7 N
    EXPECT_NEAR(line.sections[0].MBL, 8109578.7, 1.0);
    EXPECT_TRUE(has_note(line, "line type 'chain': no MBL column: MoorPy's R4 studless chain, MBL = 911 d + "
                               "1.21e+09 d^2 - 2.19e+09 d^3 N at the nominal diameter d = sqrt(Mass/m / 2e+04 "
                               "kg/m3) = 0.07517 m: MBL = 5.906e+06 N"));
    EXPECT_TRUE(has_note(line, "line type 'wire': no MBL column: MoorPy's wire rope"));
}

TEST(BreakingLoad, StudlinkPolyesterAndNylonNamesTakeTheirOwnFormula) {
    // studlink: d = sqrt(113 / 21.9e3) = 0.0718319 m, the chain formula: 5431744.3 N
    std::string d = edit(edit(kDeck, "chain      0.135", "studlink   0.135"), "1     chain ", "1     studlink ");
    d = edit(edit(d, "wire       0.09", "polyester  0.09"), "2     wire ", "2     polyester ");
    uc::LineFileLine line = read(d);
    EXPECT_NEAR(line.sections[1].MBL, 5431744.3, 1.0);
    // polyester of 42 kg/m: d = sqrt(42 / 679) = 0.248708 m, 308e6 d^2 = 19051546.4 N
    EXPECT_NEAR(line.sections[0].MBL, 308e6 * 42.0 / 679.0, 1.0);
    EXPECT_NEAR(line.sections[0].MBL, 19051546.4, 1.0);
    line = read(edit(edit(kDeck, "wire       0.09    42.0", "nylon      0.12    8.0 "), "2     wire ", "2     nylon "));
    // nylon of 8 kg/m: d = sqrt(8 / 585) = 0.116941 m, 207e6 d^2 + 230e6 d^3 = 3198583.9 N
    EXPECT_NEAR(line.sections[0].MBL, 3198583.9, 1.0);
}

TEST(BreakingLoad, AnMblColumnNamedInTheHeaderIsReadAndWinsOverTheDefault) {
    std::string d = edit(kDeck, "CdAx  CaAx\n(name)", "CdAx  CaAx  MBL\n(name)");
    d = edit(d, "0.1   0.0\n", "0.1   0.0   6.5e6\n");
    d = edit(d, "0.008 0.0\n", "0.008 0.0   9.0e6\n");
    const uc::LineFileLine line = read(d);
    EXPECT_EQ(line.sections[1].MBL, 6.5e6);
    EXPECT_EQ(line.sections[0].MBL, 9.0e6);
    EXPECT_FALSE(has_note(line, "no MBL column"));

    // after Cl dF cF as well; MoorDyn's columns keep their meaning
    d = edit(kDeck, "CdAx  CaAx\n(name)", "CdAx  CaAx  Cl  dF  cF  MBL\n(name)");
    d = edit(d, "0.1   0.0\n", "0.1   0.0   0   0   0   7e6\n");
    d = edit(d, "0.008 0.0\n", "0.008 0.0   0   0   0   8e6\n");
    const uc::LineFileLine after = read(d);
    EXPECT_EQ(after.sections[1].MBL, 7e6);
    EXPECT_EQ(after.sections[0].Cdt, 0.008);
}

TEST(BreakingLoad, NonsenseMblIsRefusedNamingTheLineAndTheType) {
    std::string d = edit(kDeck, "CdAx  CaAx\n(name)", "CdAx  CaAx  MBL\n(name)");
    d = edit(d, "0.008 0.0\n", "0.008 0.0   9.0e6\n");
    for (const char* bad : {"0", "-5e6", "x"}) {
        const std::string deck = edit(d, "0.1   0.0\n", std::string("0.1   0.0   ") + bad + "\n");
        uc::LineFileLine line;
        std::string error;
        ASSERT_FALSE(uc::read_line_file(deck, 0, line, error)) << bad;
        EXPECT_EQ(error.rfind("line 6: MBL ", 0), 0u) << error;
        EXPECT_NE(error.find("(the minimum breaking load [N] of line type 'chain')"), std::string::npos) << error;
    }
    // a row without the column the header names
    const std::string deck = edit(edit(kDeck, "CdAx  CaAx\n(name)", "CdAx  CaAx  MBL\n(name)"), "0.008 0.0\n",
                                  "0.008 0.0   9.0e6\n");
    uc::LineFileLine line;
    std::string error;
    ASSERT_FALSE(uc::read_line_file(deck, 0, line, error));
    EXPECT_EQ(error, "line 6: the column names (line 4) have MBL as column 11, this row has 10 fields: give every "
                     "line type its MBL [N]");
}

TEST(BreakingLoad, ATypeNamedForNoMaterialHasNoMblAndTheParameterStands) {
    const uc::LineFileLine line = read(edit(edit(kDeck, "wire       0.09", "main       0.09"), "2     wire ",
                                            "2     main "));
    EXPECT_EQ(line.sections[0].MBL, 0.0);
    EXPECT_TRUE(has_note(line, "line type 'main': no MBL column and its name names no material of MoorPy's"));
    UCParams p;
    uc_params_default(&p);
    p.MBL = 3.0e6;  // the importer's
    std::string error;
    ASSERT_TRUE(uc::apply_line_file(line, p, error)) << error;
    ASSERT_EQ(p.nSections, 2);
    EXPECT_EQ(p.section[0].MBL, 0.0);  // 0: the line's MBL, 3e6
    EXPECT_NEAR(p.section[1].MBL, 5906496.0, 1.0);
    EXPECT_EQ(p.MBL, 3.0e6);
}
