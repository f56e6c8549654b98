// Where the static profile puts the nodes (meshGrading): a three-section mooring of polyester, wire
// and chain whose chain lies on the seabed and whose wire touches down. Graded in each section (1),
// every section keeps its elements and the touchdown is a node; graded along the line (2), the
// total is kept, every section end is a node, the chain on the seabed gives up elements to the
// hanging part and the equilibrium is closer to the exact profile; 0 keeps equal elements.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "api/cable_api.h"
#include "line/simulation.h"

using namespace uc;

namespace {

void section(UCSection& s, double length, double massPerLength, double displacement, double EA, int nElements) {
    s.length = length;
    s.diameter = displacement;
    s.massPerLength = massPerLength;
    s.EA = EA;
    s.EI = 0.0;
    s.nElements = nElements;
    s.joint = 1;
}

// Polyester 34.8 m - wire 50.3 m - chain 71.5 m in 63.4 m of water, fairlead 7.2 m deep, anchor
// 120.4 m away: the chain rests on the seabed, the wire touches down 17 m above the joint.
UCParams mooring(int grading) {
    UCParams p;
    uc_params_default(&p);
    p.nSections = 3;
    section(p.section[0], 34.805, 24.82, 0.1513, 1.828e8, 2);
    section(p.section[1], 50.294, 31.15, 0.0905, 5.714e8, 3);
    section(p.section[2], 71.508, 460.7, 0.2732, 1.972e9, 5);
    p.bottomEnd = UC_BOTTOM_ANCHORED;
    p.anchor[0] = -120.447;
    p.anchor[2] = -63.382;
    p.waterDepth = 63.382;
    p.enableSeabed = 1;
    p.seabedStiffness = 1e8;
    p.seabedFriction = 0.0;
    p.enableBending = 0;
    p.enableCompression = 0;
    p.meshGrading = grading;
    return p;
}

struct Start {
    bool ok;
    std::string error;
    std::vector<double> nodes;   // arc lengths of the nodes
    std::vector<int> perSection;  // elements per section
    double towTension, endTension;
};

Start start(int grading) {
    const UCParams p = mooring(grading);
    CableSimulation sim(p);
    UCInputs in{};
    in.tow[2] = -7.244;
    Start s{};
    s.ok = sim.initialize(0.0, in, s.error);
    const CableModel& m = sim.model();
    s.perSection.assign(m.n_sections(), 0);
    for (int e = 0; e < m.n_elements(); ++e) {
        s.nodes.push_back(m.element_start(e));
        for (int k = 0; k < m.n_sections(); ++k)
            if (&m.element_section(e) == &m.section(k)) ++s.perSection[k];
    }
    s.nodes.push_back(m.line().length);
    s.towTension = sim.outputs().towTension;
    s.endTension = sim.outputs().endTension;
    return s;
}

bool has_node(const std::vector<double>& nodes, double s) {
    for (double x : nodes)
        if (std::abs(x - s) < 1e-9 * 156.607) return true;
    return false;
}

}  // namespace

TEST(MeshGrading, EachSectionKeepsItsElementsWhenGradedInIt) {
    const Start s = start(1);
    EXPECT_EQ(s.perSection, (std::vector<int>{2, 3, 5}));
    EXPECT_TRUE(has_node(s.nodes, 34.805));
    EXPECT_TRUE(has_node(s.nodes, 34.805 + 50.294));
}

TEST(MeshGrading, AlongTheLineTheRestingChainGivesItsElementsToTheHangingPart) {
    const Start one = start(1), two = start(2);
    ASSERT_TRUE(two.ok) << two.error;
    int total = 0;
    for (int n : two.perSection) {
        EXPECT_GE(n, 1);
        total += n;
    }
    EXPECT_EQ(total, 10);
    EXPECT_TRUE(has_node(two.nodes, 34.805));
    EXPECT_TRUE(has_node(two.nodes, 34.805 + 50.294));
    EXPECT_LT(two.perSection[2], one.perSection[2]);  // the chain lies straight on the seabed
    // the line's elastic catenary (MoorPy with a rigid seabed: fairlead 10532.7 N, anchor 2911.9 N)
    // within 0.5 % at both ends: the bound asked of 20 elements, here with 10
    EXPECT_NEAR(two.towTension, 10532.7, 5e-3 * 10532.7);
    EXPECT_NEAR(two.endTension, 2911.9, 5e-3 * 2911.9);
}

TEST(MeshGrading, OffKeepsEqualElements) {
    const Start s = start(0);
    ASSERT_EQ(s.perSection, (std::vector<int>{2, 3, 5}));
    for (size_t i = 0; i + 1 < s.nodes.size(); ++i) {
        const double l = s.nodes[i + 1] - s.nodes[i];
        const double expected = i < 2 ? 34.805 / 2 : i < 5 ? 50.294 / 3 : 71.508 / 5;
        EXPECT_NEAR(l, expected, 1e-9 * expected) << "element " << i;
    }
}
