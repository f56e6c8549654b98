// Calls outside the states the FMI 2.0 state machine allows them in (section 4.2.4) return fmi2Error and
// log "illegal call sequence"; rejected arguments name the variable. After an error the instance only
// accepts reset, free, state restore and debug calls (FMI 2.0 section 4.2.4).
#include <gtest/gtest.h>

#include <cmath>

#include "api/cable_api.h"
#include "fmu_harness.h"

TEST(CallSequence, DoStepBeforeInitializationIsIllegal) {
    Instance inst;
    EXPECT_EQ(fmi().DoStep(inst.c, 0.0, 0.5, fmi2True), fmi2Error);
    EXPECT_TRUE(inst.log.contains("illegal call sequence")) << inst.log.all();
}

TEST(CallSequence, ExitInitializationWithoutEnterIsIllegal) {
    Instance inst;
    ASSERT_EQ(inst.setup(), fmi2OK);
    EXPECT_EQ(fmi().ExitInitializationMode(inst.c), fmi2Error);
    EXPECT_TRUE(inst.log.contains("illegal call sequence")) << inst.log.all();
}

TEST(CallSequence, SetupExperimentAfterInitializationIsIllegal) {
    Instance inst;
    ASSERT_EQ(inst.initialize(), fmi2OK);
    EXPECT_EQ(inst.setup(), fmi2Error);
    EXPECT_TRUE(inst.log.contains("illegal call sequence")) << inst.log.all();
}

TEST(CallSequence, FixedParameterCannotBeSetAfterInitialization) {
    Instance inst;
    ASSERT_EQ(inst.initialize(), fmi2OK);
    EXPECT_EQ(inst.setReal("length", 200.0), fmi2Error);
    EXPECT_TRUE(inst.log.contains("length")) << inst.log.all();
}

TEST(CallSequence, FixedIntegerParameterCannotBeSetAfterInitialization) {
    Instance inst;
    ASSERT_EQ(inst.initialize(), fmi2OK);
    EXPECT_EQ(inst.setInteger("nElements", 10), fmi2Error);
    EXPECT_TRUE(inst.log.contains("nElements")) << inst.log.all();
}

TEST(CallSequence, InputsCanBeSetBetweenSteps) {
    Instance inst;
    ASSERT_EQ(inst.initialize(), fmi2OK);
    EXPECT_EQ(inst.setReal("tow.vx", 1.2), fmi2OK);
    double t = 0.0;
    EXPECT_EQ(inst.steps(1, 0.5, &t), fmi2OK) << inst.log.all();
}

TEST(CallSequence, DoStepAtTheWrongTimeIsAnError) {
    Instance inst;
    ASSERT_EQ(inst.initialize(), fmi2OK);
    EXPECT_EQ(fmi().DoStep(inst.c, 1.0, 0.5, fmi2True), fmi2Error);
    EXPECT_TRUE(inst.log.contains("currentCommunicationPoint")) << inst.log.all();
}

TEST(CallSequence, NonPositiveStepSizeIsAnError) {
    for (double h : {0.0, -0.5}) {
        Instance inst;
        ASSERT_EQ(inst.initialize(), fmi2OK);
        EXPECT_EQ(fmi().DoStep(inst.c, 0.0, h, fmi2True), fmi2Error);
        EXPECT_TRUE(inst.log.contains("communicationStepSize")) << inst.log.all();
    }
}

// A step too short for the driven end's quintic (its coefficients scale with h^-5) once ended
// "successfully" with NaN outputs (found by scripts/fuzz_fmi): an error naming the argument, and the
// instance's outputs stay finite.
TEST(CallSequence, StepShorterThanTheShortestStepIsAnError) {
    for (double h : {4.9406564584124654e-324, 1e-200, 0.5 * UC_MIN_STEP_SIZE}) {
        Instance inst;
        ASSERT_EQ(inst.initialize(), fmi2OK);
        ASSERT_EQ(fmi().DoStep(inst.c, 0.0, 0.2652741128105266, fmi2True), fmi2OK);
        EXPECT_EQ(fmi().DoStep(inst.c, 0.2652741128105266, h, fmi2True), fmi2Error) << h;
        EXPECT_TRUE(inst.log.contains("communicationStepSize")) << inst.log.all();
    }
    Instance inst;  // the shortest step itself is fine
    ASSERT_EQ(inst.initialize(), fmi2OK);
    ASSERT_EQ(fmi().DoStep(inst.c, 0.0, 0.2652741128105266, fmi2True), fmi2OK);
    ASSERT_EQ(fmi().DoStep(inst.c, 0.2652741128105266, UC_MIN_STEP_SIZE, fmi2True), fmi2OK);
    const fmi2ValueReference vr = 2001;  // towForce.x
    double value = 0.0;
    ASSERT_EQ(fmi().GetReal(inst.c, &vr, 1, &value), fmi2OK);
    EXPECT_TRUE(std::isfinite(value));
}

TEST(CallSequence, UnknownValueReferenceIsAnError) {
    Instance inst;
    const fmi2ValueReference vr = 424242;
    double value = 1.0;
    EXPECT_EQ(fmi().SetReal(inst.c, &vr, 1, &value), fmi2Error);
    EXPECT_TRUE(inst.log.contains("424242")) << inst.log.all();
}

TEST(CallSequence, ValueReferenceOfAnotherTypeIsAnErrorSayingWhichCallItNeeds) {
    Instance inst;
    const fmi2ValueReference vr = vr_of("nElements");
    double value = 1.0;
    EXPECT_EQ(fmi().SetReal(inst.c, &vr, 1, &value), fmi2Error);
    EXPECT_TRUE(inst.log.contains("nElements")) << inst.log.all();
    EXPECT_TRUE(inst.log.contains("is an Integer variable: use fmi2SetInteger")) << inst.log.all();
    Instance other;
    const fmi2ValueReference length = vr_of("length");
    const fmi2Integer n = 300;
    EXPECT_EQ(fmi().SetInteger(other.c, &length, 1, &n), fmi2Error);
    EXPECT_TRUE(other.log.contains("length")) << other.log.all();
    EXPECT_TRUE(other.log.contains("is a Real variable: use fmi2SetReal")) << other.log.all();
}

TEST(CallSequence, OutputsCannotBeSet) {
    Instance inst;
    EXPECT_EQ(inst.setReal("towTension", 1.0), fmi2Error);
    EXPECT_TRUE(inst.log.contains("towTension")) << inst.log.all();
}

TEST(CallSequence, TerminateIsOnlyAllowedAfterInitialization) {
    Instance inst;
    EXPECT_EQ(fmi().Terminate(inst.c), fmi2Error);
    EXPECT_TRUE(inst.log.contains("illegal call sequence")) << inst.log.all();
}

TEST(CallSequence, DoStepAfterTerminateIsIllegal) {
    Instance inst;
    ASSERT_EQ(inst.initialize(), fmi2OK);
    ASSERT_EQ(fmi().Terminate(inst.c), fmi2OK);
    EXPECT_EQ(fmi().DoStep(inst.c, 0.0, 0.5, fmi2True), fmi2Error);
    EXPECT_TRUE(inst.log.contains("illegal call sequence")) << inst.log.all();
}

TEST(CallSequence, ErrorStateAcceptsOnlyResetFreeAndStateRestore) {
    Instance inst;
    set_tow_inputs(inst);
    ASSERT_EQ(inst.initialize(), fmi2OK);
    fmi2FMUstate state = nullptr;
    ASSERT_EQ(fmi().GetFMUstate(inst.c, &state), fmi2OK);
    ASSERT_EQ(fmi().DoStep(inst.c, 7.0, 0.5, fmi2True), fmi2Error);  // into the error state
    EXPECT_EQ(fmi().DoStep(inst.c, 0.0, 0.5, fmi2True), fmi2Error);
    EXPECT_EQ(fmi().Terminate(inst.c), fmi2Error);
    EXPECT_EQ(fmi().SetDebugLogging(inst.c, fmi2True, 0, nullptr), fmi2OK);
    EXPECT_EQ(fmi().SetFMUstate(inst.c, state), fmi2OK) << inst.log.all();
    double t = 0.0;
    EXPECT_EQ(inst.steps(1, 0.5, &t), fmi2OK) << inst.log.all();
    EXPECT_EQ(fmi().FreeFMUstate(inst.c, &state), fmi2OK);
    EXPECT_EQ(state, nullptr);
    ASSERT_EQ(fmi().DoStep(inst.c, 9.0, 0.5, fmi2True), fmi2Error);
    EXPECT_EQ(fmi().Reset(inst.c), fmi2OK);
    EXPECT_EQ(inst.initialize(), fmi2OK) << inst.log.all();
}

TEST(CallSequence, UnknownLogCategoryIsAnError) {
    Instance inst;
    const fmi2String categories[] = {"logEvents", "logNonsense"};
    EXPECT_EQ(fmi().SetDebugLogging(inst.c, fmi2True, 2, categories), fmi2Error);
    EXPECT_TRUE(inst.log.contains("logNonsense")) << inst.log.all();
}

TEST(Logging, DebugCategoriesOnlyWhenEnabled) {
    Instance quiet("quiet", false);
    ASSERT_EQ(quiet.initialize(), fmi2OK);
    EXPECT_TRUE(quiet.log.lines.empty()) << quiet.log.all();
    EXPECT_EQ(fmi().DoStep(quiet.c, 5.0, 0.5, fmi2True), fmi2Error);
    EXPECT_TRUE(quiet.log.contains("logStatusError: ")) << "errors are always logged";

    Instance selective("selective", true);
    const fmi2String categories[] = {"logSolver"};
    ASSERT_EQ(fmi().SetDebugLogging(selective.c, fmi2True, 1, categories), fmi2OK);
    selective.log.lines.clear();  // fmi2Instantiate logged under logEvents while all categories were on
    ASSERT_EQ(selective.initialize(), fmi2OK);
    EXPECT_TRUE(selective.log.contains("logSolver: ")) << selective.log.all();
    EXPECT_FALSE(selective.log.contains("logEvents: ")) << selective.log.all();
}

TEST(Logging, PercentAndHashAreEscapedForTheImportersFormatting) {
    Instance inst("100% #1 cable");
    const fmi2String categories[] = {"log%s#"};
    EXPECT_EQ(fmi().SetDebugLogging(inst.c, fmi2True, 1, categories), fmi2Error);
    // After printf formatting "%%" is "%"; "##" stays for importers that expand "#<vr>#" references.
    EXPECT_TRUE(inst.log.contains("\"log%s##\"")) << inst.log.all();
}
