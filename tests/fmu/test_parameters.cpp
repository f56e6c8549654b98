// Bad parameters and inputs give fmi2Error with a log line naming the variable (DESIGN 4): non-finite
// values at fmi2SetReal, out-of-range values at fmi2ExitInitializationMode (uc_params_check).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "fmu_harness.h"

namespace {

// Sets the value (expecting OK), then expects fmi2ExitInitializationMode to fail naming the variable.
void expect_rejected_at_initialization(const char* name, double value) {
    Instance inst;
    ASSERT_EQ(inst.setReal(name, value), fmi2OK);
    ASSERT_EQ(inst.setup(), fmi2OK);
    ASSERT_EQ(fmi().EnterInitializationMode(inst.c), fmi2OK);
    EXPECT_EQ(fmi().ExitInitializationMode(inst.c), fmi2Error);
    EXPECT_TRUE(inst.log.contains(name)) << inst.log.all();
}

}  // namespace

TEST(Parameters, NegativeLengthIsRejectedNamingLength) { expect_rejected_at_initialization("length", -1.0); }

TEST(Parameters, ZeroDiameterIsRejectedNamingDiameter) { expect_rejected_at_initialization("diameter", 0.0); }

TEST(Parameters, ZeroElementsIsRejectedNamingNElements) {
    Instance inst;
    ASSERT_EQ(inst.setInteger("nElements", 0), fmi2OK);
    ASSERT_EQ(inst.setup(), fmi2OK);
    ASSERT_EQ(fmi().EnterInitializationMode(inst.c), fmi2OK);
    EXPECT_EQ(fmi().ExitInitializationMode(inst.c), fmi2Error);
    EXPECT_TRUE(inst.log.contains("nElements")) << inst.log.all();
}

TEST(Parameters, NaNDiameterIsRejectedBySetReal) {
    Instance inst;
    EXPECT_EQ(inst.setReal("diameter", std::nan("")), fmi2Error);
    EXPECT_TRUE(inst.log.contains("diameter")) << inst.log.all();
}

TEST(Parameters, InfiniteInputIsRejectedBySetReal) {
    Instance inst;
    ASSERT_EQ(inst.initialize(), fmi2OK);
    EXPECT_EQ(inst.setReal("tow.x", std::numeric_limits<double>::infinity()), fmi2Error);
    EXPECT_TRUE(inst.log.contains("tow.x")) << inst.log.all();
}

TEST(Parameters, BadParametersAreAlsoReportedForInitialUnknowns) {
    Instance inst;
    ASSERT_EQ(inst.setReal("length", -1.0), fmi2OK);
    ASSERT_EQ(inst.setup(), fmi2OK);
    ASSERT_EQ(fmi().EnterInitializationMode(inst.c), fmi2OK);
    const fmi2ValueReference vr = vr_of("towTension");
    double value = 0.0;
    EXPECT_EQ(fmi().GetReal(inst.c, &vr, 1, &value), fmi2Error);
    EXPECT_TRUE(inst.log.contains("length")) << inst.log.all();
}

TEST(Parameters, AnotherInstanceIsUnaffectedByAnError) {
    Instance bad("bad"), good("good");
    ASSERT_EQ(bad.setReal("length", -1.0), fmi2OK);
    EXPECT_EQ(bad.initialize(), fmi2Error);
    set_tow_inputs(good);
    ASSERT_EQ(good.initialize(), fmi2OK) << good.log.all();
    double t = 0.0;
    EXPECT_EQ(good.steps(2, 0.5, &t), fmi2OK);
    EXPECT_GT(good.getReal("towTension"), 0.0);
}

TEST(Parameters, BooleanAndIntegerParametersRoundTrip) {
    Instance inst;
    const fmi2ValueReference bending = vr_of("enableBending");
    const fmi2Boolean off = fmi2False;
    ASSERT_EQ(fmi().SetBoolean(inst.c, &bending, 1, &off), fmi2OK);
    ASSERT_EQ(inst.setInteger("nElements", 12), fmi2OK);
    ASSERT_EQ(inst.setup(), fmi2OK);
    ASSERT_EQ(fmi().EnterInitializationMode(inst.c), fmi2OK);
    fmi2Boolean b = fmi2True;
    fmi2Integer n = 0;
    const fmi2ValueReference elements = vr_of("nElements");
    EXPECT_EQ(fmi().GetBoolean(inst.c, &bending, 1, &b), fmi2OK);
    EXPECT_EQ(fmi().GetInteger(inst.c, &elements, 1, &n), fmi2OK);
    EXPECT_EQ(b, fmi2False);
    EXPECT_EQ(n, 12);
}
