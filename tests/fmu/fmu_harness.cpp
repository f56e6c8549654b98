// fmu_harness.cpp - see fmu_harness.h.
#include "fmu_harness.h"

#include <dlfcn.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "uc_guid.h"
#include "variables.h"

static FmiApi load() {
    FmiApi api;
    api.handle = dlopen(UC_FMU_SO, RTLD_NOW | RTLD_LOCAL);
    if (api.handle == nullptr) {
        api.error = dlerror();
        return api;
    }
#define UC_RESOLVE(name)                                                                      \
    api.name = reinterpret_cast<fmi2##name##TYPE*>(dlsym(api.handle, "fmi2" #name));         \
    if (api.name == nullptr) api.missing.push_back("fmi2" #name);
    UC_FMI2_FUNCTIONS(UC_RESOLVE)
#undef UC_RESOLVE
    return api;
}

const FmiApi& fmi() {
    static const FmiApi api = load();
    if (api.handle == nullptr || !api.missing.empty()) throw std::runtime_error("cannot load " UC_FMU_SO);
    return api;
}

bool LogCapture::contains(const std::string& text) const {
    for (const std::string& line : lines) {
        if (line.find(text) != std::string::npos) return true;
    }
    return false;
}

std::string LogCapture::all() const {
    std::string s;
    for (const std::string& line : lines) s += line + "\n";
    return s;
}

// Formats like fmpy's and fmusim's logger proxies: the message is a printf format.
void capture_logger(fmi2ComponentEnvironment env, fmi2String instanceName, fmi2Status status,
                           fmi2String category, fmi2String message, ...) {
    (void)instanceName;
    (void)status;
    char text[4096];
    va_list args;
    va_start(args, message);
    std::vsnprintf(text, sizeof text, message, args);
    va_end(args);
    static_cast<LogCapture*>(env)->lines.push_back(std::string(category ? category : "(null)") + ": " + text);
}

unsigned int vr_of(const std::string& name) {
    size_t n = 0;
    const UCVariable* table = uc_variables(&n);
    for (size_t i = 0; i < n; ++i) {
        if (name == table[i].name) return table[i].vr;
    }
    throw std::invalid_argument("no variable " + name);
}

std::vector<unsigned int> output_vrs() {
    size_t n = 0;
    const UCVariable* table = uc_variables(&n);
    std::vector<unsigned int> vrs;
    for (size_t i = 0; i < n; ++i) {
        if (table[i].causality == UC_CAUSALITY_OUTPUT) vrs.push_back(table[i].vr);
    }
    return vrs;
}

const char* fmu_guid() { return UC_GUID; }

Instance::Instance(const char* name, bool loggingOn, const char* resourceLocation) {
    const fmi2CallbackFunctions callbacks = {capture_logger, nullptr, nullptr, nullptr, &log};
    c = fmi().Instantiate(name, fmi2CoSimulation, UC_GUID, resourceLocation, &callbacks, fmi2False, loggingOn);
}

Instance::~Instance() { fmi().FreeInstance(c); }

fmi2Status Instance::setString(const std::string& name, const char* value) {
    const fmi2ValueReference vr = vr_of(name);
    return fmi().SetString(c, &vr, 1, &value);
}

std::string Instance::getString(const std::string& name) {
    const fmi2ValueReference vr = vr_of(name);
    fmi2String value = nullptr;
    if (fmi().GetString(c, &vr, 1, &value) != fmi2OK || value == nullptr) return "<error>";
    return value;
}

fmi2Status Instance::setReal(const std::string& name, double value) {
    const fmi2ValueReference vr = vr_of(name);
    return fmi().SetReal(c, &vr, 1, &value);
}

fmi2Status Instance::setInteger(const std::string& name, int value) {
    const fmi2ValueReference vr = vr_of(name);
    return fmi().SetInteger(c, &vr, 1, &value);
}

double Instance::getReal(const std::string& name) {
    const fmi2ValueReference vr = vr_of(name);
    double value = std::nan("");
    if (fmi().GetReal(c, &vr, 1, &value) != fmi2OK) throw std::runtime_error("fmi2GetReal(" + name + ") failed");
    return value;
}

std::vector<double> Instance::outputs() {
    const std::vector<unsigned int> vrs = output_vrs();
    std::vector<double> values(vrs.size(), std::nan(""));
    if (fmi().GetReal(c, vrs.data(), vrs.size(), values.data()) != fmi2OK) {
        throw std::runtime_error("fmi2GetReal(outputs) failed:\n" + log.all());
    }
    return values;
}

fmi2Status Instance::setup(double startTime, double stopTime) {
    return fmi().SetupExperiment(c, fmi2False, 0.0, startTime, fmi2True, stopTime);
}

fmi2Status Instance::initialize(double startTime, double stopTime) {
    fmi2Status s = setup(startTime, stopTime);
    if (s == fmi2OK) s = fmi().EnterInitializationMode(c);
    if (s == fmi2OK) s = fmi().ExitInitializationMode(c);
    return s;
}

fmi2Status Instance::steps(int n, double h, double* t) {
    for (int i = 0; i < n; ++i) {
        const fmi2Status s = fmi().DoStep(c, *t, h, fmi2True);
        if (s != fmi2OK) return s;
        *t += h;
    }
    return fmi2OK;
}

void set_tow_inputs(Instance& inst) {
    inst.setReal("tow.vx", 1.0);
    inst.setReal("current.y", 0.1);
}

bool bitwise_equal(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}
