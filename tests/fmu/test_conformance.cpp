// FMI 2.0 conformance of the adapter beyond the single cases of test_call_sequence.cpp:
// - every (function, machine state) pair of the FMI 2.0 state table (section 4.2.4): illegal ones return fmi2Error
//   and log "<function>: illegal call sequence", legal ones do not log it;
// - NULL pointers, non-finite values for every Real input and parameter, unknown value references for
//   every type, every parameter set after initialization, bad communication points and step sizes;
// - 8 instances stepped in parallel threads give the bits of the serial runs.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "fmu_harness.h"
#include "variables.h"

namespace {

enum class Machine { Instantiated, InitMode, StepComplete, Terminated, Error };

const char* machine_name(Machine m) {
    switch (m) {
        case Machine::Instantiated: return "instantiated";
        case Machine::InitMode: return "initializationMode";
        case Machine::StepComplete: return "stepComplete";
        case Machine::Terminated: return "terminated";
        case Machine::Error: return "error";
    }
    return "?";
}

// Brings a fresh instance into machine state m (a straight cable at rest, cheap to initialize).
void enter(Instance& inst, Machine m) {
    ASSERT_NE(inst.c, nullptr);
    ASSERT_EQ(inst.setInteger("initMode", 1), fmi2OK);
    set_tow_inputs(inst);
    if (m == Machine::Instantiated) return;
    ASSERT_EQ(inst.setup(0.0, 100.0), fmi2OK);
    ASSERT_EQ(fmi().EnterInitializationMode(inst.c), fmi2OK);
    if (m == Machine::InitMode) return;
    ASSERT_EQ(fmi().ExitInitializationMode(inst.c), fmi2OK) << inst.log.all();
    if (m == Machine::StepComplete) return;
    if (m == Machine::Terminated) {
        ASSERT_EQ(fmi().Terminate(inst.c), fmi2OK);
        return;
    }
    ASSERT_EQ(fmi().DoStep(inst.c, 42.0, 0.5, fmi2True), fmi2Error);  // wrong communication point
}

struct Call {
    const char* function;
    std::vector<Machine> legal;  // FMI 2.0 section 4.2.4; stepInProgress/-Failed/
                                 // -Canceled cannot be reached: fmi2DoStep is synchronous.
    std::function<fmi2Status(Instance&)> call;
    // Legal states in which the call is still an fmi2Error because of its argument (a fixed parameter
    // after initialization, section 2.1.2): logged with the variable name, not as a call sequence error.
    std::vector<Machine> argumentRejected = {};
    const char* rejectedName = nullptr;
};

const Machine kAll[] = {Machine::Instantiated, Machine::InitMode, Machine::StepComplete, Machine::Terminated,
                        Machine::Error};

std::vector<Call> calls() {
    using M = Machine;
    static const fmi2ValueReference towVx = vr_of("tow.vx"), tension = vr_of("towTension"),
                                    nElements = vr_of("nElements"), bending = vr_of("enableBending");
    return {
        {"fmi2SetDebugLogging", {M::Instantiated, M::InitMode, M::StepComplete, M::Terminated, M::Error},
         [](Instance& i) { return fmi().SetDebugLogging(i.c, fmi2True, 0, nullptr); }},
        {"fmi2SetupExperiment", {M::Instantiated}, [](Instance& i) { return i.setup(); }},
        {"fmi2EnterInitializationMode", {M::Instantiated},
         [](Instance& i) { return fmi().EnterInitializationMode(i.c); }},
        {"fmi2ExitInitializationMode", {M::InitMode}, [](Instance& i) { return fmi().ExitInitializationMode(i.c); }},
        {"fmi2SetReal", {M::Instantiated, M::InitMode, M::StepComplete},
         [](Instance& i) {
             const double v = 1.1;
             return fmi().SetReal(i.c, &towVx, 1, &v);
         }},
        {"fmi2SetInteger", {M::Instantiated, M::InitMode, M::StepComplete},
         [](Instance& i) {
             const fmi2Integer v = 12;
             return fmi().SetInteger(i.c, &nElements, 1, &v);
         },
         {M::StepComplete}, "nElements"},
        {"fmi2SetBoolean", {M::Instantiated, M::InitMode, M::StepComplete},
         [](Instance& i) {
             const fmi2Boolean v = fmi2True;
             return fmi().SetBoolean(i.c, &bending, 1, &v);
         },
         {M::StepComplete}, "enableBending"},
        {"fmi2GetReal", {M::InitMode, M::StepComplete, M::Terminated, M::Error},
         [](Instance& i) {
             double v = 0.0;
             return fmi().GetReal(i.c, &tension, 1, &v);
         }},
        {"fmi2GetInteger", {M::InitMode, M::StepComplete, M::Terminated, M::Error},
         [](Instance& i) {
             fmi2Integer v = 0;
             return fmi().GetInteger(i.c, &nElements, 1, &v);
         }},
        {"fmi2GetBoolean", {M::InitMode, M::StepComplete, M::Terminated, M::Error},
         [](Instance& i) {
             fmi2Boolean v = 0;
             return fmi().GetBoolean(i.c, &bending, 1, &v);
         }},
        {"fmi2SetRealInputDerivatives", {M::Instantiated, M::InitMode, M::StepComplete},
         [](Instance& i) {
             const fmi2Integer order = 1;
             const double v = 0.01;
             return fmi().SetRealInputDerivatives(i.c, &towVx, 1, &order, &v);
         }},
        {"fmi2DoStep", {M::StepComplete}, [](Instance& i) { return fmi().DoStep(i.c, 0.0, 0.5, fmi2True); }},
        {"fmi2CancelStep", {}, [](Instance& i) { return fmi().CancelStep(i.c); }},
        {"fmi2Terminate", {M::StepComplete}, [](Instance& i) { return fmi().Terminate(i.c); }},
        {"fmi2Reset", {M::Instantiated, M::InitMode, M::StepComplete, M::Terminated, M::Error},
         [](Instance& i) { return fmi().Reset(i.c); }},
        {"fmi2GetFMUstate", {M::Instantiated, M::InitMode, M::StepComplete, M::Terminated, M::Error},
         [](Instance& i) {
             fmi2FMUstate s = nullptr;
             fmi2Status status = fmi().GetFMUstate(i.c, &s);
             if (s != nullptr) fmi().FreeFMUstate(i.c, &s);
             return status;
         }},
        {"fmi2GetRealStatus", {M::StepComplete, M::Terminated},
         [](Instance& i) {
             double v = 0.0;
             return fmi().GetRealStatus(i.c, fmi2LastSuccessfulTime, &v);
         }},
        {"fmi2GetBooleanStatus", {M::StepComplete, M::Terminated},
         [](Instance& i) {
             fmi2Boolean v = 0;
             return fmi().GetBooleanStatus(i.c, fmi2Terminated, &v);
         }},
    };
}

bool contains(const std::vector<Machine>& v, Machine m) {
    for (Machine x : v) {
        if (x == m) return true;
    }
    return false;
}

}  // namespace

TEST(Conformance, EveryFunctionInEveryReachableStateFollowsTheStateMachine) {
    int illegal = 0, legal = 0;
    for (const Call& call : calls()) {
        for (Machine m : kAll) {
            Instance inst;
            enter(inst, m);
            inst.log.lines.clear();
            const fmi2Status status = call.call(inst);
            const std::string what = std::string(call.function) + " in " + machine_name(m);
            const std::string marker = std::string(call.function) + ": illegal call sequence";
            if (contains(call.argumentRejected, m)) {
                ++legal;
                EXPECT_EQ(status, fmi2Error) << what;
                EXPECT_FALSE(inst.log.contains("illegal call sequence")) << what << "\n" << inst.log.all();
                EXPECT_TRUE(inst.log.contains(call.rejectedName)) << what << "\n" << inst.log.all();
            } else if (contains(call.legal, m)) {
                ++legal;
                EXPECT_FALSE(inst.log.contains("illegal call sequence")) << what << "\n" << inst.log.all();
                EXPECT_NE(status, fmi2Error) << what << "\n" << inst.log.all();
            } else {
                ++illegal;
                EXPECT_EQ(status, fmi2Error) << what;
                EXPECT_TRUE(inst.log.contains(marker)) << what << "\n" << inst.log.all();
            }
        }
    }
    // 18 functions x 5 states: the table must actually exercise both sides.
    EXPECT_EQ(legal + illegal, 90);
    EXPECT_GT(illegal, 40);
}

TEST(Conformance, AnIllegalCallPutsTheInstanceIntoTheErrorState) {
    Instance inst;
    enter(inst, Machine::StepComplete);
    ASSERT_EQ(fmi().EnterInitializationMode(inst.c), fmi2Error);
    EXPECT_EQ(fmi().DoStep(inst.c, 0.0, 0.5, fmi2True), fmi2Error) << "an illegal call is an fmi2Error: unusable";
    EXPECT_TRUE(inst.log.contains("fmi2DoStep: illegal call sequence (called in state error)")) << inst.log.all();
}

TEST(Conformance, NullInstanceIsAnErrorForEveryFunction) {
    const fmi2ValueReference vr = vr_of("tow.vx");
    double r = 0.0;
    fmi2Integer i = 0;
    fmi2Boolean b = 0;
    fmi2FMUstate s = nullptr;
    size_t size = 0;
    EXPECT_EQ(fmi().SetDebugLogging(nullptr, fmi2True, 0, nullptr), fmi2Error);
    EXPECT_EQ(fmi().SetupExperiment(nullptr, fmi2False, 0.0, 0.0, fmi2False, 0.0), fmi2Error);
    EXPECT_EQ(fmi().EnterInitializationMode(nullptr), fmi2Error);
    EXPECT_EQ(fmi().ExitInitializationMode(nullptr), fmi2Error);
    EXPECT_EQ(fmi().GetReal(nullptr, &vr, 1, &r), fmi2Error);
    EXPECT_EQ(fmi().SetReal(nullptr, &vr, 1, &r), fmi2Error);
    EXPECT_EQ(fmi().GetInteger(nullptr, &vr, 1, &i), fmi2Error);
    EXPECT_EQ(fmi().GetBoolean(nullptr, &vr, 1, &b), fmi2Error);
    EXPECT_EQ(fmi().DoStep(nullptr, 0.0, 0.5, fmi2True), fmi2Error);
    EXPECT_EQ(fmi().Terminate(nullptr), fmi2Error);
    EXPECT_EQ(fmi().Reset(nullptr), fmi2Error);
    EXPECT_EQ(fmi().GetFMUstate(nullptr, &s), fmi2Error);
    EXPECT_EQ(fmi().SetFMUstate(nullptr, s), fmi2Error);
    EXPECT_EQ(fmi().SerializedFMUstateSize(nullptr, s, &size), fmi2Error);
    EXPECT_EQ(fmi().GetRealStatus(nullptr, fmi2LastSuccessfulTime, &r), fmi2Error);
    fmi().FreeInstance(nullptr);  // a no-op (FMI 2.0 section 4.2.4)
}

TEST(Conformance, InstantiateRejectsBadArgumentsWithNull) {
    LogCapture log;
    const fmi2CallbackFunctions callbacks = {capture_logger, nullptr, nullptr, nullptr, &log};
    const fmi2CallbackFunctions noLogger = {nullptr, nullptr, nullptr, nullptr, &log};
    EXPECT_EQ(fmi().Instantiate(nullptr, fmi2CoSimulation, fmu_guid(), nullptr, &callbacks, fmi2False, fmi2True),
              nullptr);
    EXPECT_EQ(fmi().Instantiate("", fmi2CoSimulation, fmu_guid(), nullptr, &callbacks, fmi2False, fmi2True), nullptr);
    EXPECT_EQ(fmi().Instantiate("x", fmi2ModelExchange, fmu_guid(), nullptr, &callbacks, fmi2False, fmi2True),
              nullptr);
    EXPECT_EQ(fmi().Instantiate("x", fmi2CoSimulation, nullptr, nullptr, &callbacks, fmi2False, fmi2True), nullptr);
    EXPECT_EQ(fmi().Instantiate("x", fmi2CoSimulation, "{not-the-guid}", nullptr, &callbacks, fmi2False, fmi2True),
              nullptr);
    EXPECT_EQ(fmi().Instantiate("x", fmi2CoSimulation, fmu_guid(), nullptr, nullptr, fmi2False, fmi2True), nullptr);
    EXPECT_EQ(fmi().Instantiate("x", fmi2CoSimulation, fmu_guid(), nullptr, &noLogger, fmi2False, fmi2True), nullptr);
    EXPECT_EQ(log.lines.size(), 5u) << "every rejection with a logger is logged:\n" << log.all();
}

TEST(Conformance, NullArgumentsAreErrors) {
    const fmi2ValueReference vr = vr_of("tow.vx");
    const fmi2Integer order = 1;
    double r = 1.0;
    struct Case {
        const char* what;
        std::function<fmi2Status(Instance&)> call;
    };
    const std::vector<Case> cases = {
        {"SetReal vr", [&](Instance& i) { return fmi().SetReal(i.c, nullptr, 1, &r); }},
        {"SetReal value", [&](Instance& i) { return fmi().SetReal(i.c, &vr, 1, nullptr); }},
        {"GetReal vr", [&](Instance& i) { return fmi().GetReal(i.c, nullptr, 1, &r); }},
        {"GetReal value", [&](Instance& i) { return fmi().GetReal(i.c, &vr, 1, nullptr); }},
        {"GetInteger value", [&](Instance& i) {
             const fmi2ValueReference n = vr_of("nElements");
             return fmi().GetInteger(i.c, &n, 1, nullptr);
         }},
        {"SetInteger vr", [&](Instance& i) {
             const fmi2Integer v = 3;
             return fmi().SetInteger(i.c, nullptr, 1, &v);
         }},
        {"SetBoolean value", [&](Instance& i) {
             const fmi2ValueReference b = vr_of("enableBending");
             return fmi().SetBoolean(i.c, &b, 1, nullptr);
         }},
        {"SetRealInputDerivatives order", [&](Instance& i) { return fmi().SetRealInputDerivatives(i.c, &vr, 1, nullptr, &r); }},
        {"SetRealInputDerivatives value", [&](Instance& i) { return fmi().SetRealInputDerivatives(i.c, &vr, 1, &order, nullptr); }},
        {"GetFMUstate", [](Instance& i) { return fmi().GetFMUstate(i.c, nullptr); }},
        {"SetFMUstate", [](Instance& i) { return fmi().SetFMUstate(i.c, nullptr); }},
        {"SerializedFMUstateSize state", [](Instance& i) {
             size_t size = 0;
             return fmi().SerializedFMUstateSize(i.c, nullptr, &size);
         }},
        {"SerializedFMUstateSize size", [](Instance& i) {
             fmi2FMUstate s = nullptr;
             EXPECT_EQ(fmi().GetFMUstate(i.c, &s), fmi2OK);
             const fmi2Status status = fmi().SerializedFMUstateSize(i.c, s, nullptr);
             fmi().FreeFMUstate(i.c, &s);
             return status;
         }},
        {"SerializeFMUstate buffer", [](Instance& i) {
             fmi2FMUstate s = nullptr;
             EXPECT_EQ(fmi().GetFMUstate(i.c, &s), fmi2OK);
             const fmi2Status status = fmi().SerializeFMUstate(i.c, s, nullptr, 100000);
             fmi().FreeFMUstate(i.c, &s);
             return status;
         }},
        {"DeSerializeFMUstate bytes", [](Instance& i) {
             fmi2FMUstate s = nullptr;
             return fmi().DeSerializeFMUstate(i.c, nullptr, 100, &s);
         }},
        {"DeSerializeFMUstate state", [](Instance& i) {
             const char bytes[16] = {0};
             return fmi().DeSerializeFMUstate(i.c, bytes, sizeof bytes, nullptr);
         }},
        {"GetRealStatus value", [](Instance& i) { return fmi().GetRealStatus(i.c, fmi2LastSuccessfulTime, nullptr); }},
        {"GetBooleanStatus value", [](Instance& i) { return fmi().GetBooleanStatus(i.c, fmi2Terminated, nullptr); }},
        {"SetDebugLogging categories", [](Instance& i) { return fmi().SetDebugLogging(i.c, fmi2True, 2, nullptr); }},
    };
    for (const Case& c : cases) {
        Instance inst;
        enter(inst, Machine::StepComplete);
        inst.log.lines.clear();
        EXPECT_EQ(c.call(inst), fmi2Error) << c.what << "\n" << inst.log.all();
        EXPECT_FALSE(inst.log.lines.empty()) << c.what << ": an fmi2Error is always logged";
    }
}

TEST(Conformance, ZeroLengthArraysWithNullPointersAreAccepted) {
    Instance inst;
    enter(inst, Machine::StepComplete);
    EXPECT_EQ(fmi().SetReal(inst.c, nullptr, 0, nullptr), fmi2OK);
    EXPECT_EQ(fmi().GetReal(inst.c, nullptr, 0, nullptr), fmi2OK);
    EXPECT_EQ(fmi().GetInteger(inst.c, nullptr, 0, nullptr), fmi2OK);
    EXPECT_EQ(fmi().SetBoolean(inst.c, nullptr, 0, nullptr), fmi2OK);
}

TEST(Conformance, NonFiniteValuesAreRejectedForEveryRealInputAndParameter) {
    size_t n = 0;
    const UCVariable* table = uc_variables(&n);
    const double bad[] = {std::nan(""), std::numeric_limits<double>::infinity(),
                          -std::numeric_limits<double>::infinity()};
    int checked = 0;
    for (size_t k = 0; k < n; ++k) {
        const UCVariable& v = table[k];
        if (v.type != UC_TYPE_REAL || v.causality == UC_CAUSALITY_OUTPUT) continue;
        for (double value : bad) {
            Instance inst;
            // Parameters before initialization, inputs during a run.
            enter(inst, v.causality == UC_CAUSALITY_PARAMETER ? Machine::Instantiated : Machine::StepComplete);
            EXPECT_EQ(fmi().SetReal(inst.c, &v.vr, 1, &value), fmi2Error) << v.name << " = " << value;
            EXPECT_TRUE(inst.log.contains(std::string(v.name) + " = ")) << v.name << "\n" << inst.log.all();
            ++checked;
        }
    }
    EXPECT_GT(checked, 3 * 40);
}

TEST(Conformance, NonFiniteInputDerivativeIsRejected) {
    Instance inst;
    enter(inst, Machine::StepComplete);
    const fmi2ValueReference vr = vr_of("tow.vx");
    const fmi2Integer order = 1;
    const double value = std::nan("");
    EXPECT_EQ(fmi().SetRealInputDerivatives(inst.c, &vr, 1, &order, &value), fmi2Error);
    EXPECT_TRUE(inst.log.contains("tow.vx")) << inst.log.all();
}

TEST(Conformance, UnknownValueReferencesAreErrorsForEveryType) {
    const fmi2ValueReference unknown = 777777;
    double r = 0.0;
    fmi2Integer i = 0;
    fmi2Boolean b = 0;
    fmi2String s = nullptr;
    const fmi2String text = "x";
    const std::vector<std::pair<const char*, std::function<fmi2Status(Instance&)>>> cases = {
        {"GetReal", [&](Instance& in) { return fmi().GetReal(in.c, &unknown, 1, &r); }},
        {"SetReal", [&](Instance& in) { return fmi().SetReal(in.c, &unknown, 1, &r); }},
        {"GetInteger", [&](Instance& in) { return fmi().GetInteger(in.c, &unknown, 1, &i); }},
        {"SetInteger", [&](Instance& in) { return fmi().SetInteger(in.c, &unknown, 1, &i); }},
        {"GetBoolean", [&](Instance& in) { return fmi().GetBoolean(in.c, &unknown, 1, &b); }},
        {"SetBoolean", [&](Instance& in) { return fmi().SetBoolean(in.c, &unknown, 1, &b); }},
        {"GetString", [&](Instance& in) { return fmi().GetString(in.c, &unknown, 1, &s); }},
        {"SetString", [&](Instance& in) { return fmi().SetString(in.c, &unknown, 1, &text); }},
        {"SetRealInputDerivatives", [&](Instance& in) {
             const fmi2Integer order = 1;
             return fmi().SetRealInputDerivatives(in.c, &unknown, 1, &order, &r);
         }},
    };
    for (const auto& [what, call] : cases) {
        Instance inst;
        enter(inst, Machine::StepComplete);
        EXPECT_EQ(call(inst), fmi2Error) << what;
        EXPECT_TRUE(inst.log.contains("777777")) << what << "\n" << inst.log.all();
    }
    // An existing value reference of another type is unknown for this type, also in the middle of an array.
    Instance inst;
    enter(inst, Machine::StepComplete);
    const fmi2ValueReference mixed[] = {vr_of("towTension"), vr_of("nElements")};
    double values[2] = {0.0, 0.0};
    EXPECT_EQ(fmi().GetReal(inst.c, mixed, 2, values), fmi2Error);
}

TEST(Conformance, NoParameterCanBeSetAfterInitialization) {
    size_t n = 0;
    const UCVariable* table = uc_variables(&n);
    int checked = 0;
    for (size_t k = 0; k < n; ++k) {
        const UCVariable& v = table[k];
        if (v.causality != UC_CAUSALITY_PARAMETER) continue;  // all parameters are fixed (variables.h)
        for (Machine m : {Machine::StepComplete, Machine::Terminated}) {
            Instance inst;
            enter(inst, m);
            fmi2Status status;
            if (v.type == UC_TYPE_REAL) {
                const double value = 0.5;
                status = fmi().SetReal(inst.c, &v.vr, 1, &value);
            } else if (v.type == UC_TYPE_INTEGER) {
                const fmi2Integer value = 1;
                status = fmi().SetInteger(inst.c, &v.vr, 1, &value);
            } else if (v.type == UC_TYPE_STRING) {
                const fmi2String value = "line.dat";
                status = fmi().SetString(inst.c, &v.vr, 1, &value);
            } else {
                const fmi2Boolean value = fmi2False;
                status = fmi().SetBoolean(inst.c, &v.vr, 1, &value);
            }
            EXPECT_EQ(status, fmi2Error) << v.name << " in " << machine_name(m);
            if (m == Machine::StepComplete) {
                EXPECT_TRUE(inst.log.contains(v.name)) << inst.log.all();
            } else {
                EXPECT_TRUE(inst.log.contains("illegal call sequence")) << inst.log.all();
            }
            ++checked;
        }
    }
    EXPECT_GE(checked, 2 * 33);
}

TEST(Conformance, BadCommunicationPointsAndStepSizesAreErrors) {
    const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
    struct Case {
        double tc, h;
        const char* logged;
    };
    // The instance is at t = 1.0 after two steps of 0.5; stopTime 100.
    const Case cases[] = {
        {0.5, 0.5, "currentCommunicationPoint"},   {1.5, 0.5, "currentCommunicationPoint"},
        {1.0 + 1e-3, 0.5, "currentCommunicationPoint"}, {nan, 0.5, "currentCommunicationPoint"},
        {inf, 0.5, "currentCommunicationPoint"},   {1.0, 0.0, "communicationStepSize"},
        {1.0, -0.5, "communicationStepSize"},      {1.0, -0.0, "communicationStepSize"},
        {1.0, nan, "communicationStepSize"},       {1.0, inf, "communicationStepSize"},
        {1.0, 99.5, "stopTime"},
    };
    for (const Case& c : cases) {
        Instance inst;
        enter(inst, Machine::StepComplete);
        double t = 0.0;
        ASSERT_EQ(inst.steps(2, 0.5, &t), fmi2OK);
        EXPECT_EQ(fmi().DoStep(inst.c, c.tc, c.h, fmi2True), fmi2Error) << "tc " << c.tc << " h " << c.h;
        EXPECT_TRUE(inst.log.contains(c.logged)) << inst.log.all();
    }
}

TEST(Conformance, EightInstancesInParallelThreadsGiveTheSerialBits) {
    constexpr int kInstances = 8;
    // Different parameters and inputs per instance, so that a shared global would show.
    auto run = [](Instance& inst, int k) {
        EXPECT_EQ(inst.setReal("length", 100.0 + 25.0 * k), fmi2OK);
        EXPECT_EQ(inst.setInteger("nElements", 6 + k), fmi2OK);
        EXPECT_EQ(inst.setInteger("initMode", k % 2), fmi2OK);
        EXPECT_EQ(inst.setReal("tow.vx", 0.5 + 0.1 * k), fmi2OK);
        EXPECT_EQ(inst.setReal("current.y", 0.05 * k), fmi2OK);
        EXPECT_EQ(inst.initialize(0.0, 100.0), fmi2OK) << inst.log.all();
        double t = 0.0;
        for (int step = 0; step < 6; ++step) {
            EXPECT_EQ(inst.setReal("tow.x", (0.5 + 0.1 * k) * t), fmi2OK);
            EXPECT_EQ(inst.steps(1, 0.5, &t), fmi2OK) << inst.log.all();
        }
        return inst.outputs();
    };
    std::vector<std::vector<double>> serial(kInstances), parallel(kInstances);
    for (int k = 0; k < kInstances; ++k) {
        Instance inst(("serial" + std::to_string(k)).c_str());
        serial[k] = run(inst, k);
    }
    std::vector<std::unique_ptr<Instance>> instances;
    for (int k = 0; k < kInstances; ++k) instances.push_back(std::make_unique<Instance>(("par" + std::to_string(k)).c_str()));
    std::vector<std::thread> threads;
    for (int k = 0; k < kInstances; ++k) threads.emplace_back([&, k] { parallel[k] = run(*instances[k], k); });
    for (std::thread& th : threads) th.join();
    for (int k = 0; k < kInstances; ++k) {
        EXPECT_TRUE(bitwise_equal(parallel[k], serial[k])) << "instance " << k;
        if (k > 0) {
            EXPECT_NE(serial[k][3], serial[k - 1][3]) << "instances differ (towTension)";
        }
    }
}
