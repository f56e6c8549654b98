// The shared object loads like an importer loads it, exports every fmi2 function, and fmi2Instantiate
// rejects arguments that are not for this FMU (FMI 2.0 section 2.1.5).
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cstring>

#include "fmu_harness.h"

TEST(Loading, DlopenWithRtldNowResolvesEveryFmi2Function) {
    void* handle = dlopen(UC_FMU_SO, RTLD_NOW | RTLD_LOCAL);
    ASSERT_NE(handle, nullptr) << dlerror();
    const char* names[] = {
#define UC_NAME(name) "fmi2" #name,
        UC_FMI2_FUNCTIONS(UC_NAME)
#undef UC_NAME
    };
    for (const char* name : names) EXPECT_NE(dlsym(handle, name), nullptr) << name;
    EXPECT_EQ(fmi().missing.size(), 0u);
    dlclose(handle);
}

TEST(Loading, ReportsVersionAndPlatform) {
    EXPECT_STREQ(fmi().GetVersion(), "2.0");
    EXPECT_STREQ(fmi().GetTypesPlatform(), "default");
}

struct Rejection {
    const char* name;
    fmi2Type type;
    const char* guid;
    const char* expectedInLog;
};

TEST(Instantiate, RejectsArgumentsThatAreNotForThisFmu) {
    const Rejection cases[] = {
        {nullptr, fmi2CoSimulation, fmu_guid(), "instanceName"},
        {"", fmi2CoSimulation, fmu_guid(), "instanceName"},
        {"cable", fmi2ModelExchange, fmu_guid(), "fmi2CoSimulation"},
        {"cable", fmi2CoSimulation, "{00000000-0000-0000-0000-000000000000}", "fmuGUID"},
        {"cable", fmi2CoSimulation, nullptr, "fmuGUID"},
    };
    for (const Rejection& r : cases) {
        LogCapture log;
        const fmi2CallbackFunctions callbacks = {capture_logger, nullptr, nullptr, nullptr, &log};
        EXPECT_EQ(fmi().Instantiate(r.name, r.type, r.guid, nullptr, &callbacks, fmi2False, fmi2False), nullptr);
        EXPECT_TRUE(log.contains(r.expectedInLog)) << log.all();
    }
}

TEST(Instantiate, RejectsMissingCallbacks) {
    EXPECT_EQ(fmi().Instantiate("cable", fmi2CoSimulation, fmu_guid(), nullptr, nullptr, fmi2False, fmi2False),
              nullptr);
    const fmi2CallbackFunctions noLogger = {nullptr, nullptr, nullptr, nullptr, nullptr};
    EXPECT_EQ(fmi().Instantiate("cable", fmi2CoSimulation, fmu_guid(), nullptr, &noLogger, fmi2False, fmi2False),
              nullptr);
}

TEST(Instantiate, AcceptsNullResourceLocationAndNamesWithSpaces) {
    Instance inst("Test FMI 2.0 CS");
    EXPECT_NE(inst.c, nullptr);
}

TEST(Instantiate, CopiesTheCallbackStructAndInstanceName) {
    LogCapture log;
    char name[] = "first";
    fmi2Component c = nullptr;
    {
        const fmi2CallbackFunctions callbacks = {capture_logger, nullptr, nullptr, nullptr, &log};
        c = fmi().Instantiate(name, fmi2CoSimulation, fmu_guid(), nullptr, &callbacks, fmi2False, fmi2True);
    }
    std::strcpy(name, "xxxxx");
    ASSERT_NE(c, nullptr);
    const fmi2ValueReference bad = 99999;
    double value = 0;
    EXPECT_EQ(fmi().SetReal(c, &bad, 1, &value), fmi2Error);  // logs through the copied callbacks
    EXPECT_TRUE(log.contains("99999")) << log.all();
    fmi().FreeInstance(c);
}

TEST(FreeInstance, NullIsANoOp) { fmi().FreeInstance(nullptr); }
