// Lines of several sections: the compiled description (mesh, joints, attachments) against exact
// solutions: a uniform line cut into equal sections, the elastica with a joint, a pinned joint
// under an end force, a hanging line whose EA jumps, and the equilibrium of an attachment.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "api/cable_api.h"
#include "model/cable_model.h"
#include "line/simulation.h"
#include "cantilever.h"

using namespace uc;
using uc::testing::cantilever;

namespace {

using uc::kPi;

void copy_line_into_section(const UCParams& p, double length, int nElements, UCSection& s) {
    s.length = length;
    s.diameter = p.diameter;
    s.massPerLength = p.massPerLength;
    s.EA = p.EA;
    s.EI = p.EI;
    s.GJ = p.GJ;
    s.axialDamping = p.axialDamping;
    s.Cdn = p.Cdn;
    s.Cdt = p.Cdt;
    s.Can = p.Can;
    s.Cat = p.Cat;
    s.nElements = nElements;
    s.joint = 0;
}

UCInputs deep(double endLoadZ) {
    UCInputs in{};
    in.tow[2] = -50;
    in.endLoad[2] = endLoadZ;
    return in;
}

}  // namespace

TEST(Sections, MeshPlacesNodesAtSectionEndsAndAttachments) {
    UCParams p;
    uc_params_default(&p);
    p.nSections = 3;
    copy_line_into_section(p, 100.0, 4, p.section[0]);
    copy_line_into_section(p, 50.0, 5, p.section[1]);
    copy_line_into_section(p, 150.0, 3, p.section[2]);
    p.section[1].joint = 1;  // pinned between sections 2 and 3
    p.nAttachments = 2;
    p.attachment[0].s = 137.3;  // inside section 2
    p.attachment[1].s = 100.0;  // on the joint of sections 1 and 2
    const CableModel m(p);
    EXPECT_EQ(m.n_sections(), 3);
    EXPECT_EQ(m.n_elements(), 4 + 5 + 3);  // section 2 cut at 137.3 m: 3.73 and 1.27 of 5 elements -> 4 + 1
    EXPECT_EQ(m.n_slots(), m.n_elements() + 2);  // one more slot for the pinned joint
    EXPECT_DOUBLE_EQ(m.line().length, 300.0);
    bool found = false;
    for (int i = 0; i < m.n_slots(); ++i) found |= std::abs(m.slot_arc_length(i) - 137.3) < 1e-12;
    EXPECT_TRUE(found) << "no node at the attachment";
    ASSERT_EQ(m.attachments().size(), 2u);
    EXPECT_DOUBLE_EQ(m.slot_arc_length(m.attachments()[0].offset / 6), 100.0);
    EXPECT_DOUBLE_EQ(m.slot_arc_length(m.attachments()[1].offset / 6), 137.3);
    // Every element's start is where the previous one ends; the pinned joint repeats a position's
    // free unknowns in its second slot and nothing else.
    for (int e = 1; e < m.n_elements(); ++e)
        EXPECT_NEAR(m.element_start(e), m.element_start(e - 1) + m.element_length(e - 1), 1e-12);
    int e = 0;
    double xi = 0.0;
    m.locate(137.3 + 0.25 * m.element_length(8), e, xi);
    EXPECT_NEAR(m.element_start(e) + xi * m.element_length(e), 137.3 + 0.25 * m.element_length(8), 1e-12);
}

TEST(Sections, EqualSectionsReproduceTheUniformLine) {
    UCParams uniform;
    uc_params_default(&uniform);
    uniform.nElements = 20;
    UCParams cut = uniform;
    cut.nSections = 2;
    copy_line_into_section(uniform, 120.0, 8, cut.section[0]);  // the same 15 m elements
    copy_line_into_section(uniform, 180.0, 12, cut.section[1]);
    UCInputs in{};
    in.towVelocity[0] = 1.5;
    CableSimulation a(uniform), b(cut);
    std::string error;
    ASSERT_TRUE(a.initialize(0.0, in, error)) << error;
    ASSERT_TRUE(b.initialize(0.0, in, error)) << error;
    for (int k = 0; k < 10; ++k) {
        in.towVelocity[0] = 1.5 + 0.05 * k;
        in.towVelocity[1] = 0.1 * k;
        in.tow[0] = a.outputs().shapeX[0];
        in.tow[1] = a.outputs().shapeY[0];
        ASSERT_TRUE(a.step(a.time(), 1.0, in, error)) << error;
        ASSERT_TRUE(b.step(b.time(), 1.0, in, error)) << error;
    }
    // The same equations in the same order: only the arc lengths of the output stations are
    // computed from a section start (round-off), and the integrator takes the same steps.
    const UCOutputs &x = a.outputs(), &y = b.outputs();
    EXPECT_NEAR(x.towTension, y.towTension, 1e-9 * x.towTension);
    for (int k = 0; k < UC_NUM_STATIONS; ++k) {
        EXPECT_NEAR(x.shapeX[k], y.shapeX[k], 1e-9 * uniform.length) << k;
        EXPECT_NEAR(x.shapeZ[k], y.shapeZ[k], 1e-9 * uniform.length) << k;
        EXPECT_NEAR(x.tension[k], y.tension[k], 1e-9 * x.towTension) << k;
    }
}

// The elastica cut in two sections of different element lengths with a rigid joint: the same
// accuracy as the uniform mesh (1e-4 L with about ten elements).
TEST(Sections, ElasticaAcrossARigidJoint) {
    const double P = 40, xTip = 7.85696019238, zTip = -5.60624938203;  // the exact elastica (validation)
    UCParams p = cantilever(10);
    p.nSections = 2;
    copy_line_into_section(p, 4.0, 5, p.section[0]);
    copy_line_into_section(p, 6.0, 5, p.section[1]);
    CableSimulation sim(p);
    std::string error;
    ASSERT_TRUE(sim.initialize(0.0, deep(-P), error)) << error;
    const UCOutputs& out = sim.outputs();
    EXPECT_LT(std::hypot(out.endPosition[0] - xTip, out.endPosition[2] + 50 - zTip) / 10.0, 1e-4);
}

// A pinned joint carries no moment: a cantilever pinned at its middle under a downward end force.
// The outer half hangs straight down from the pin (exact to round-off: a straight line is in the
// element space); the inner half is the elastica of a 5 m cantilever with the force at its tip.
TEST(Sections, PinnedJointCarriesNoMoment) {
    UCParams p = cantilever(10);
    p.nSections = 2;
    copy_line_into_section(p, 5.0, 5, p.section[0]);
    copy_line_into_section(p, 5.0, 5, p.section[1]);
    p.section[0].joint = 1;
    CableSimulation sim(p);
    std::string error;
    ASSERT_TRUE(sim.initialize(0.0, deep(-40.0), error)) << error;
    const UCOutputs& out = sim.outputs();
    const int joint = (UC_NUM_STATIONS - 1) / 2;  // station at s = 5 m
    EXPECT_NEAR(out.endPosition[0], out.shapeX[joint], 1e-9 * p.length);
    EXPECT_NEAR(out.endPosition[1], out.shapeY[joint], 1e-9 * p.length);
    EXPECT_LT(out.endPosition[2], out.shapeZ[joint] - 4.99);
    for (int k = joint + 1; k < UC_NUM_STATIONS; ++k) EXPECT_LT(out.curvature[k], 1e-9) << k;
    EXPECT_GT(out.curvature[joint - 1], 1e-2);  // the inner half is bent
    // With a rigid joint the moment passes: the outer half is bent too and the tip swings out.
    p.section[0].joint = 0;
    CableSimulation rigid(p);
    ASSERT_TRUE(rigid.initialize(0.0, deep(-40.0), error)) << error;
    EXPECT_GT(rigid.outputs().endPosition[0] - rigid.outputs().shapeX[joint], 0.5);
}

namespace {

// A line hanging from the tow point with a free end, EA jumping 100-fold at the joint of its two
// 100 m sections, no bending stiffness. Returns the error of its elongation against the exact
// integral of T / EA, relative to that elongation.
double hanging_elongation_error(int joint, int nElements) {
    UCParams p;
    uc_params_default(&p);
    p.nSections = 2;
    p.enableBending = 0;
    const double m = 50.0, d = 0.05, EA[2] = {1e7, 1e9}, L = 100.0;
    for (int k = 0; k < 2; ++k) {
        UCSection& s = p.section[k];
        copy_line_into_section(p, L, nElements, s);
        s.massPerLength = m;
        s.diameter = d;
        s.EA = EA[k];
        s.axialDamping = 0.01 * EA[k];
    }
    p.section[0].joint = joint;
    CableSimulation sim(p);
    std::string error;
    UCInputs in{};
    if (!sim.initialize(0.0, in, error)) {
        ADD_FAILURE() << error;
        return INFINITY;
    }
    const double w = (m - p.waterDensity * kPi * d * d / 4) * p.gravity;
    // T(s) = w (2L - s): int_0^L T / EA1 + int_L^2L T / EA2
    const double exact = w * 1.5 * L * L / EA[0] + w * 0.5 * L * L / EA[1];
    const double elongation = -sim.outputs().endPosition[2] - 2 * L;
    return std::abs(elongation - exact) / exact;
}

}  // namespace

// Two tangents at a pinned joint let each side take its own stretch: the elongation is exact to
// round-off (the strain is linear in s, the mean strain of every element exact). A rigid joint
// shares one tangent vector and so one stretch at the joint: the elements next to it take up the
// difference in their softened higher strain modes, an error of the elongation that falls with the
// square of the element length (docs/lines.md has the table).
TEST(Sections, StretchAcrossAnEAJump) {
    EXPECT_LT(hanging_elongation_error(1, 5), 1e-12);
    const double coarse = hanging_elongation_error(0, 10), fine = hanging_elongation_error(0, 20);
    EXPECT_LT(fine, coarse / 3.0) << "second order expected: " << coarse << " -> " << fine;
    EXPECT_LT(coarse, 1e-3);
}

// An attachment's weight, buoyancy and the line's are carried by the tow point, to round-off.
TEST(Sections, AttachmentEquilibriumClosesToRoundOff) {
    UCParams p;
    uc_params_default(&p);
    p.nAttachments = 1;
    p.attachment[0] = UCAttachment{137.3, 500.0, 0.1, 50.0, 2.0};
    CableSimulation sim(p);
    std::string error;
    ASSERT_TRUE(sim.initialize(0.0, UCInputs{}, error)) << error;
    const double A = kPi * p.diameter * p.diameter / 4;
    const double wet = ((p.massPerLength - p.waterDensity * A) * p.length + 500.0 - p.waterDensity * 0.1) * p.gravity;
    EXPECT_NEAR(sim.outputs().towForce[2], -wet, 1e-10 * wet);
    EXPECT_NEAR(sim.outputs().towForce[0], 0.0, 1e-10 * wet);
}
