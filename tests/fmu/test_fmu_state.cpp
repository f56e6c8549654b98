// FMU state get/set/serialize/deserialize continues bit for bit (FMI 2.0 section 2.1.8), also in a fresh
// instance that was never initialized (fmusim --initial-fmu-state-file, fmpy simulate_fmu(fmu_state=...)),
// and corrupted or foreign serialized states are rejected.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#if __has_include(<valgrind/memcheck.h>)
#include <valgrind/memcheck.h>
#else  // without valgrind's header the runs are only compared
#define RUNNING_ON_VALGRIND 0
#define VALGRIND_CHECK_MEM_IS_DEFINED(address, size) 0
#endif

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

// ---- states are the same bytes for the same run ------------------------------------------------------
// Two identical runs serialize byte-identical states, every byte of them defined (no padding, no heap
// slack, no addresses): under valgrind memcheck (ctest fmu_state_bytes_memcheck) each state is also checked
// for undefined bytes, which a plain run cannot see.
namespace {

// The serialized state of inst now; under valgrind, the offset of its first undefined byte in *undefined
// (-1: none).
std::vector<char> serialized_now(Instance& inst, long* undefined) {
    fmi2FMUstate s = nullptr;
    EXPECT_EQ(fmi().GetFMUstate(inst.c, &s), fmi2OK) << inst.log.all();
    size_t size = 0;
    EXPECT_EQ(fmi().SerializedFMUstateSize(inst.c, s, &size), fmi2OK);
    std::vector<char> bytes(size);
    EXPECT_EQ(fmi().SerializeFMUstate(inst.c, s, bytes.data(), bytes.size()), fmi2OK);
    fmi().FreeFMUstate(inst.c, &s);
    *undefined = -1;
    if (RUNNING_ON_VALGRIND && !bytes.empty()) {
        const uintptr_t bad = VALGRIND_CHECK_MEM_IS_DEFINED(bytes.data(), bytes.size());
        if (bad != 0) *undefined = static_cast<long>(bad - reinterpret_cast<uintptr_t>(bytes.data()));
    }
    return bytes;
}

// Appends inst's serialized state to all; the offset of the first undefined byte in all (under valgrind) in
// *undefined, where it is the first.
void append_serialized(Instance& inst, std::vector<char>& all, long* undefined) {
    long at = -1;
    const std::vector<char> bytes = serialized_now(inst, &at);
    if (at >= 0 && *undefined < 0) *undefined = static_cast<long>(all.size()) + at;
    all.insert(all.end(), bytes.begin(), bytes.end());
}

// A winch that pays out 3 m and hauls in 1.6 m of 1 m elements (splits and merges), its state serialized
// after every step (a remesh restarts the integrator: the states just after one hold a short history).
std::vector<char> winch_run(long* undefined) {
    Instance inst("winch");
    const std::pair<const char*, double> params[] = {
        {"length", 20.0}, {"body.mass", 400.0}, {"body.volume", 0.1}, {"body.CdA", 0.3}, {"winch.minLength", 5.0},
        {"winch.maxLength", 200.0}, {"winch.maxRate", 20.0}, {"winch.maxAcceleration", 0.0}};  // the drum follows at once
    for (const auto& [name, value] : params) EXPECT_EQ(inst.setReal(name, value), fmi2OK) << name;
    EXPECT_EQ(inst.setInteger("nElements", 20), fmi2OK);
    EXPECT_EQ(inst.setInteger("bottomEnd", 2), fmi2OK);
    EXPECT_EQ(inst.setInteger("winchMode", 1), fmi2OK);
    EXPECT_EQ(inst.initialize(0.0, 100.0), fmi2OK) << inst.log.all();
    double t = 0.0;
    std::vector<char> all;
    for (int k = 0; k < 50; ++k) {  // short steps: some end a few integrator steps after a remesh
        EXPECT_EQ(inst.setReal("winch.rate", k < 30 ? 5.0 : -4.0), fmi2OK);
        EXPECT_EQ(inst.steps(1, 0.02, &t), fmi2OK) << inst.log.all();
        append_serialized(inst, all, undefined);
    }
    EXPECT_NEAR(inst.getReal("unstretchedLength"), 21.4, 1e-9);
    return all;
}

// The subsurface buoy on three legs as a Free body, released off its equilibrium: a system with a free body.
std::vector<char> free_body_run(long* undefined) {
    Instance inst("system");
    const std::string deck = std::string(UC_TEST_DATA_DIR) + "/decks/subsurface_buoy_body.dat";
    EXPECT_EQ(inst.setString("lineFile", deck.c_str()), fmi2OK);
    EXPECT_EQ(inst.initialize(0.0, 100.0), fmi2OK) << inst.log.all();
    double t = 0.0;
    std::vector<char> all;
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(inst.steps(1, 0.2, &t), fmi2OK) << inst.log.all();
        append_serialized(inst, all, undefined);
    }
    return all;
}

// Run twice (another instance initialized in between: another heap history): the same bytes, all defined.
void expect_the_same_defined_bytes(std::vector<char> (*run)(long*)) {
    long undefinedA = -1, undefinedB = -1;
    const std::vector<char> a = run(&undefinedA);
    Instance other("between");
    set_tow_inputs(other);
    ASSERT_EQ(other.initialize(0.0, 100.0), fmi2OK);
    const std::vector<char> b = run(&undefinedB);
    EXPECT_EQ(undefinedA, -1) << "first undefined byte of " << a.size();
    EXPECT_EQ(undefinedB, -1) << "first undefined byte of " << b.size();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_TRUE(a == b);
}

}  // namespace

TEST(FmuStateBytes, TwoIdenticalWinchRunsWithRemeshesSerializeTheSameDefinedBytes) {
    expect_the_same_defined_bytes(winch_run);
}

TEST(FmuStateBytes, TwoIdenticalRunsOfASystemWithAFreeBodySerializeTheSameDefinedBytes) {
    expect_the_same_defined_bytes(free_body_run);
}
