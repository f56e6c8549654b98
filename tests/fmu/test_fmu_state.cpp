// FMU state get/set/serialize/deserialize continues bit for bit (FMI 2.0 section 2.1.8), also in a fresh
// instance that was never initialized (fmusim --initial-fmu-state-file, fmpy simulate_fmu(fmu_state=...)),
// and corrupted or foreign serialized states are rejected.
#include <gtest/gtest.h>

#include <cstring>

#include "fmu_harness.h"

namespace {

class FmuState : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_NE(inst.c, nullptr);
        set_tow_inputs(inst);
        ASSERT_EQ(inst.initialize(0.0, 100.0), fmi2OK) << inst.log.all();
        ASSERT_EQ(inst.steps(3, 0.5, &t), fmi2OK);
    }
    void TearDown() override { fmi().FreeFMUstate(inst.c, &state); }

    // Five steps from the current time with a changing input, then all outputs.
    std::vector<double> continue_run(Instance& i, double t0) {
        double time = t0;
        for (int k = 0; k < 5; ++k) {
            EXPECT_EQ(i.setReal("tow.vx", 1.0 + 0.05 * k), fmi2OK);
            EXPECT_EQ(i.steps(1, 0.5, &time), fmi2OK) << i.log.all();
        }
        return i.outputs();
    }
    std::vector<char> serialize(fmi2FMUstate s) {
        size_t size = 0;
        EXPECT_EQ(fmi().SerializedFMUstateSize(inst.c, s, &size), fmi2OK);
        std::vector<char> bytes(size);
        EXPECT_EQ(fmi().SerializeFMUstate(inst.c, s, bytes.data(), bytes.size()), fmi2OK);
        return bytes;
    }

    Instance inst;
    double t = 0.0;
    fmi2FMUstate state = nullptr;
};

}  // namespace

TEST_F(FmuState, GetSetRoundTripIsBitIdentical) {
    ASSERT_EQ(fmi().GetFMUstate(inst.c, &state), fmi2OK);
    const std::vector<double> a = continue_run(inst, t);
    ASSERT_EQ(fmi().SetFMUstate(inst.c, state), fmi2OK) << inst.log.all();
    const std::vector<double> b = continue_run(inst, t);
    EXPECT_TRUE(bitwise_equal(a, b));
}

TEST_F(FmuState, GetFMUstateReusesAnExistingState) {
    ASSERT_EQ(fmi().GetFMUstate(inst.c, &state), fmi2OK);
    fmi2FMUstate first = state;
    ASSERT_EQ(inst.steps(1, 0.5, &t), fmi2OK);
    ASSERT_EQ(fmi().GetFMUstate(inst.c, &state), fmi2OK);
    EXPECT_EQ(state, first);
    const std::vector<double> a = continue_run(inst, t);
    ASSERT_EQ(fmi().SetFMUstate(inst.c, state), fmi2OK);
    EXPECT_TRUE(bitwise_equal(continue_run(inst, t), a));
}

TEST_F(FmuState, SerializeDeserializeRoundTripIsBitIdentical) {
    ASSERT_EQ(fmi().GetFMUstate(inst.c, &state), fmi2OK);
    const std::vector<char> bytes = serialize(state);
    const std::vector<double> a = continue_run(inst, t);
    fmi2FMUstate restored = nullptr;
    ASSERT_EQ(fmi().DeSerializeFMUstate(inst.c, bytes.data(), bytes.size(), &restored), fmi2OK) << inst.log.all();
    ASSERT_EQ(fmi().SetFMUstate(inst.c, restored), fmi2OK) << inst.log.all();
    EXPECT_TRUE(bitwise_equal(continue_run(inst, t), a));
    EXPECT_EQ(serialize(restored), bytes) << "serialize(deserialize(x)) == x";
    EXPECT_EQ(fmi().FreeFMUstate(inst.c, &restored), fmi2OK);
}

TEST_F(FmuState, DeserializeIntoAFreshNeverInitializedInstanceContinuesBitIdentically) {
    ASSERT_EQ(fmi().GetFMUstate(inst.c, &state), fmi2OK);
    const std::vector<char> bytes = serialize(state);
    const std::vector<double> a = continue_run(inst, t);

    Instance fresh("fresh");
    fmi2FMUstate restored = nullptr;
    ASSERT_EQ(fmi().DeSerializeFMUstate(fresh.c, bytes.data(), bytes.size(), &restored), fmi2OK);
    ASSERT_EQ(fmi().SetFMUstate(fresh.c, restored), fmi2OK) << fresh.log.all();
    EXPECT_EQ(fmi().FreeFMUstate(fresh.c, &restored), fmi2OK);
    EXPECT_TRUE(bitwise_equal(continue_run(fresh, t), a));
}

TEST_F(FmuState, StateOfAnInstanceWithOtherParametersCanBeRestored) {
    ASSERT_EQ(fmi().GetFMUstate(inst.c, &state), fmi2OK);
    const std::vector<double> a = continue_run(inst, t);
    Instance other("other");
    ASSERT_EQ(other.setReal("length", 80.0), fmi2OK);
    ASSERT_EQ(other.setInteger("nElements", 7), fmi2OK);
    ASSERT_EQ(other.initialize(), fmi2OK);
    ASSERT_EQ(fmi().SetFMUstate(other.c, state), fmi2OK) << other.log.all();
    EXPECT_TRUE(bitwise_equal(continue_run(other, t), a));
}

TEST_F(FmuState, StateSavedBeforeInitializationRestoresTheStartValues) {
    Instance fresh("fresh");
    fmi2FMUstate startState = nullptr;
    ASSERT_EQ(fmi().GetFMUstate(fresh.c, &startState), fmi2OK);
    ASSERT_EQ(fresh.setReal("length", 50.0), fmi2OK);
    ASSERT_EQ(fmi().SetFMUstate(fresh.c, startState), fmi2OK);
    ASSERT_EQ(fresh.setup(), fmi2OK);
    ASSERT_EQ(fmi().EnterInitializationMode(fresh.c), fmi2OK);
    EXPECT_EQ(fresh.getReal("length"), 300.0);
    EXPECT_EQ(fmi().FreeFMUstate(fresh.c, &startState), fmi2OK);
}

TEST_F(FmuState, CorruptedOrForeignSerializedStatesAreRejected) {
    ASSERT_EQ(fmi().GetFMUstate(inst.c, &state), fmi2OK);
    const std::vector<char> bytes = serialize(state);
    struct Case {
        const char* what;
        std::vector<char> bytes;
    };
    std::vector<Case> cases;
    cases.push_back({"magic", bytes});
    cases.back().bytes[0] ^= 0x55;
    cases.push_back({"guid", bytes});
    cases.back().bytes[8 + 4 + 1] ^= 0x01;  // first characters of the guid after magic and version
    cases.push_back({"truncated", std::vector<char>(bytes.begin(), bytes.end() - 3)});
    cases.push_back({"trailing", bytes});
    cases.back().bytes.push_back(0);
    cases.push_back({"version", bytes});
    cases.back().bytes[8] ^= 0x7f;
    for (const Case& c : cases) {
        Instance fresh("fresh");
        fmi2FMUstate restored = nullptr;
        EXPECT_EQ(fmi().DeSerializeFMUstate(fresh.c, c.bytes.data(), c.bytes.size(), &restored), fmi2Error) << c.what;
        EXPECT_EQ(restored, nullptr) << c.what;
        EXPECT_TRUE(fresh.log.contains("fmi2DeSerializeFMUstate")) << c.what << "\n" << fresh.log.all();
    }
}

TEST_F(FmuState, SerializeIntoATooSmallBufferIsAnError) {
    ASSERT_EQ(fmi().GetFMUstate(inst.c, &state), fmi2OK);
    size_t size = 0;
    ASSERT_EQ(fmi().SerializedFMUstateSize(inst.c, state, &size), fmi2OK);
    std::vector<char> bytes(size - 1);
    EXPECT_EQ(fmi().SerializeFMUstate(inst.c, state, bytes.data(), bytes.size()), fmi2Error);
}

TEST_F(FmuState, FreeingANullStateIsANoOp) {
    fmi2FMUstate none = nullptr;
    EXPECT_EQ(fmi().FreeFMUstate(inst.c, &none), fmi2OK);
    EXPECT_EQ(fmi().FreeFMUstate(inst.c, nullptr), fmi2OK);
}
