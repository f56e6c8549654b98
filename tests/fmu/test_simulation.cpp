// A master's ordinary run: instantiate, set up, initialize, step, read, terminate, free; reset-and-rerun
// and several instances in one process (FMI 2.0 sections 4.2.4 and 2.1.2).
#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "fmu_harness.h"

namespace {

// The outputs after `n` steps of 0.5 s of a steady tow, from a freshly initialized instance.
// Starts straight at rest (initMode 1): these tests are about the adapter, not the statics.
std::vector<double> tow_run(Instance& inst, int n, double length = 300.0) {
    EXPECT_EQ(inst.setReal("length", length), fmi2OK);
    EXPECT_EQ(inst.setInteger("initMode", 1), fmi2OK);
    set_tow_inputs(inst);
    EXPECT_EQ(inst.initialize(0.0, 100.0), fmi2OK) << inst.log.all();
    double t = 0.0;
    EXPECT_EQ(inst.steps(n, 0.5, &t), fmi2OK) << inst.log.all();
    return inst.outputs();
}

}  // namespace

TEST(Simulation, SteadyTowGivesFinitePositiveTowTension) {
    Instance inst;
    ASSERT_NE(inst.c, nullptr);
    set_tow_inputs(inst);
    ASSERT_EQ(inst.initialize(0.0, 10.0), fmi2OK) << inst.log.all();
    double t = 0.0;
    ASSERT_EQ(inst.steps(4, 0.5, &t), fmi2OK) << inst.log.all();
    const double tension = inst.getReal("towTension");
    EXPECT_TRUE(std::isfinite(tension));
    EXPECT_GT(tension, 0.0);
    for (double value : inst.outputs()) EXPECT_TRUE(std::isfinite(value));
    EXPECT_EQ(fmi().Terminate(inst.c), fmi2OK);
    EXPECT_EQ(inst.getReal("towTension"), tension) << "values stay readable after fmi2Terminate";
}

TEST(Simulation, InitialUnknownsAreComputedInInitializationMode) {
    Instance inst;
    set_tow_inputs(inst);
    ASSERT_EQ(inst.setup(), fmi2OK);
    ASSERT_EQ(fmi().EnterInitializationMode(inst.c), fmi2OK);
    const double tension300 = inst.getReal("towTension");
    EXPECT_GT(tension300, 0.0);
    ASSERT_EQ(inst.setReal("length", 150.0), fmi2OK);  // invalidates the cached initialization
    const double tension150 = inst.getReal("towTension");
    EXPECT_GT(tension150, 0.0);
    EXPECT_NE(tension150, tension300);
    ASSERT_EQ(fmi().ExitInitializationMode(inst.c), fmi2OK);
    EXPECT_EQ(inst.getReal("towTension"), tension150);
}

TEST(Simulation, AcceptsCommunicationPointsWithMasterRoundOff) {
    Instance inst;
    set_tow_inputs(inst);
    ASSERT_EQ(inst.initialize(0.0, 2.0), fmi2OK);
    double t = 0.0;
    ASSERT_EQ(inst.steps(2, 0.5, &t), fmi2OK);
    EXPECT_EQ(fmi().DoStep(inst.c, 0.9999999999999999, 0.5, fmi2True), fmi2OK) << inst.log.all();
    // The last step ends at stopTime up to round-off: allowed.
    EXPECT_EQ(fmi().DoStep(inst.c, 1.5, 0.5000000000000001, fmi2True), fmi2OK) << inst.log.all();
}

TEST(Simulation, StepPastStopTimeIsAnError) {
    Instance inst;
    ASSERT_EQ(inst.initialize(0.0, 1.0), fmi2OK);
    EXPECT_EQ(fmi().DoStep(inst.c, 0.0, 1.5, fmi2True), fmi2Error);
    EXPECT_TRUE(inst.log.contains("stopTime")) << inst.log.all();
}

TEST(Simulation, StatusQueries) {
    Instance inst;
    ASSERT_EQ(inst.initialize(0.0, 10.0), fmi2OK);
    double t = 0.0;
    ASSERT_EQ(inst.steps(3, 0.5, &t), fmi2OK);
    double last = -1.0;
    EXPECT_EQ(fmi().GetRealStatus(inst.c, fmi2LastSuccessfulTime, &last), fmi2OK);
    EXPECT_EQ(last, 1.5);
    fmi2Boolean terminated = fmi2True;
    EXPECT_EQ(fmi().GetBooleanStatus(inst.c, fmi2Terminated, &terminated), fmi2OK);
    EXPECT_EQ(terminated, fmi2False);
    fmi2Status status = fmi2OK;
    EXPECT_EQ(fmi().GetStatus(inst.c, fmi2DoStepStatus, &status), fmi2Discard);
    fmi2Integer integer = 0;
    EXPECT_EQ(fmi().GetIntegerStatus(inst.c, fmi2LastSuccessfulTime, &integer), fmi2Discard);
    fmi2String string = nullptr;
    EXPECT_EQ(fmi().GetStringStatus(inst.c, fmi2PendingStatus, &string), fmi2Discard);
    EXPECT_EQ(inst.steps(1, 0.5, &t), fmi2OK) << "Discard of a status query does not stop the instance";
}

TEST(Simulation, TowAccelerationFromInputDerivatives) {
    Instance inst;
    set_tow_inputs(inst);
    ASSERT_EQ(inst.initialize(0.0, 10.0), fmi2OK);
    const fmi2ValueReference vx = vr_of("tow.vx"), x = vr_of("tow.x"), load = vr_of("endLoad.z");
    const fmi2Integer one = 1, two = 2;
    const double a = 0.05;
    EXPECT_EQ(fmi().SetRealInputDerivatives(inst.c, &vx, 1, &one, &a), fmi2OK);
    EXPECT_EQ(fmi().SetRealInputDerivatives(inst.c, &x, 1, &two, &a), fmi2OK);
    EXPECT_EQ(fmi().SetRealInputDerivatives(inst.c, &x, 1, &one, &a), fmi2OK) << "accepted, ignored";
    EXPECT_EQ(fmi().SetRealInputDerivatives(inst.c, &load, 1, &one, &a), fmi2OK) << "accepted, ignored";
    double t = 0.0;
    EXPECT_EQ(inst.steps(2, 0.5, &t), fmi2OK) << inst.log.all();
    double derivative = 0.0;
    EXPECT_EQ(fmi().GetRealOutputDerivatives(inst.c, &vx, 1, &one, &derivative), fmi2Error);
}

TEST(Simulation, UnsupportedInputDerivativesAreErrors) {
    const fmi2Integer two = 2, three = 3;
    const double a = 0.05;
    {
        Instance inst;
        ASSERT_EQ(inst.initialize(), fmi2OK);
        const fmi2ValueReference vx = vr_of("tow.vx");
        EXPECT_EQ(fmi().SetRealInputDerivatives(inst.c, &vx, 1, &two, &a), fmi2Error);
        EXPECT_TRUE(inst.log.contains("tow.vx")) << inst.log.all();
    }
    {
        Instance inst;
        ASSERT_EQ(inst.initialize(), fmi2OK);
        const fmi2ValueReference x = vr_of("tow.x");
        EXPECT_EQ(fmi().SetRealInputDerivatives(inst.c, &x, 1, &three, &a), fmi2Error);
    }
    {
        Instance inst;
        ASSERT_EQ(inst.initialize(), fmi2OK);
        const fmi2ValueReference out = vr_of("towTension");
        const fmi2Integer one = 1;
        EXPECT_EQ(fmi().SetRealInputDerivatives(inst.c, &out, 1, &one, &a), fmi2Error);
        EXPECT_TRUE(inst.log.contains("towTension")) << inst.log.all();
    }
}

TEST(Simulation, ResetThenRerunIsBitIdenticalToAFreshInstance) {
    Instance fresh;
    const std::vector<double> expected = tow_run(fresh, 6);
    Instance reused;
    tow_run(reused, 3, 120.0);  // different parameters and a shorter run before the reset
    ASSERT_EQ(fmi().Reset(reused.c), fmi2OK);
    EXPECT_TRUE(bitwise_equal(tow_run(reused, 6), expected));
}

TEST(Simulation, ResetRestoresStartValues) {
    Instance inst;
    ASSERT_EQ(inst.setReal("length", 42.0), fmi2OK);
    ASSERT_EQ(inst.setReal("tow.vx", 3.0), fmi2OK);
    ASSERT_EQ(inst.setInteger("initMode", 1), fmi2OK);
    ASSERT_EQ(inst.initialize(), fmi2OK);
    ASSERT_EQ(fmi().Reset(inst.c), fmi2OK);
    ASSERT_EQ(inst.setup(), fmi2OK);
    ASSERT_EQ(fmi().EnterInitializationMode(inst.c), fmi2OK);
    EXPECT_EQ(inst.getReal("length"), 300.0);
    EXPECT_EQ(inst.getReal("tow.vx"), 0.0);
    const fmi2ValueReference initMode = vr_of("initMode");
    fmi2Integer mode = -1;
    EXPECT_EQ(fmi().GetInteger(inst.c, &initMode, 1, &mode), fmi2OK);
    EXPECT_EQ(mode, 0);
}

TEST(Simulation, TwoInstancesWithDifferentParametersAreIndependent) {
    Instance aloneLong("long"), aloneShort("short");
    const std::vector<double> expectedLong = tow_run(aloneLong, 4, 300.0);
    const std::vector<double> expectedShort = tow_run(aloneShort, 4, 100.0);

    Instance a("a"), b("b");
    ASSERT_EQ(a.setReal("length", 300.0), fmi2OK);
    ASSERT_EQ(b.setReal("length", 100.0), fmi2OK);
    ASSERT_EQ(a.setInteger("initMode", 1), fmi2OK);
    ASSERT_EQ(b.setInteger("initMode", 1), fmi2OK);
    set_tow_inputs(a);
    set_tow_inputs(b);
    ASSERT_EQ(a.initialize(), fmi2OK);
    ASSERT_EQ(b.initialize(), fmi2OK);
    double ta = 0.0, tb = 0.0;
    for (int i = 0; i < 4; ++i) {  // interleaved
        ASSERT_EQ(a.steps(1, 0.5, &ta), fmi2OK);
        ASSERT_EQ(b.steps(1, 0.5, &tb), fmi2OK);
    }
    EXPECT_TRUE(bitwise_equal(a.outputs(), expectedLong));
    EXPECT_TRUE(bitwise_equal(b.outputs(), expectedShort));
    EXPECT_NE(a.getReal("towTension"), b.getReal("towTension"));
}

TEST(Simulation, InstancesInSeparateThreadsGiveTheSequentialResults) {
    Instance sequentialLong("long"), sequentialShort("short");
    const std::vector<double> expectedLong = tow_run(sequentialLong, 3, 300.0);
    const std::vector<double> expectedShort = tow_run(sequentialShort, 3, 100.0);

    Instance a("a"), b("b");
    std::vector<double> resultLong, resultShort;
    std::thread first([&] { resultLong = tow_run(a, 3, 300.0); });
    std::thread second([&] { resultShort = tow_run(b, 3, 100.0); });
    first.join();
    second.join();
    EXPECT_TRUE(bitwise_equal(resultLong, expectedLong));
    EXPECT_TRUE(bitwise_equal(resultShort, expectedShort));
}
