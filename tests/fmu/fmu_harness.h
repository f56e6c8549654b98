// fmu_harness.h - a minimal FMI 2.0 importer for the adapter tests: loads UnderwaterCable.so with
// dlopen(RTLD_NOW | RTLD_LOCAL), resolves every fmi2 function, captures the log, and wraps an instance.
#ifndef UNDERWATERCABLE_TESTS_FMU_HARNESS_H
#define UNDERWATERCABLE_TESTS_FMU_HARNESS_H

#include <string>
#include <vector>

#include "fmi2FunctionTypes.h"

// Every function an FMI 2.0 Co-Simulation FMU must export (FMI 2.0 section 2.3).
#define UC_FMI2_FUNCTIONS(X)                                                                                 \
    X(GetTypesPlatform) X(GetVersion) X(SetDebugLogging) X(Instantiate) X(FreeInstance) X(SetupExperiment)   \
    X(EnterInitializationMode) X(ExitInitializationMode) X(Terminate) X(Reset) X(GetReal) X(GetInteger)      \
    X(GetBoolean) X(GetString) X(SetReal) X(SetInteger) X(SetBoolean) X(SetString) X(GetFMUstate)            \
    X(SetFMUstate) X(FreeFMUstate) X(SerializedFMUstateSize) X(SerializeFMUstate) X(DeSerializeFMUstate)     \
    X(GetDirectionalDerivative) X(SetRealInputDerivatives) X(GetRealOutputDerivatives) X(DoStep)            \
    X(CancelStep) X(GetStatus) X(GetRealStatus) X(GetIntegerStatus) X(GetBooleanStatus) X(GetStringStatus)

struct FmiApi {
#define UC_DECLARE_POINTER(name) fmi2##name##TYPE* name = nullptr;
    UC_FMI2_FUNCTIONS(UC_DECLARE_POINTER)
#undef UC_DECLARE_POINTER
    void* handle = nullptr;
    std::vector<std::string> missing;  // functions dlsym could not resolve
    std::string error;                 // dlerror() of a failed dlopen
};

// The library, loaded once per test process (dlopen of the same path returns the same handle anyway).
const FmiApi& fmi();

// Log lines "<category>: <message>" as an importer prints them (the message vsnprintf-formatted).
struct LogCapture {
    std::vector<std::string> lines;
    bool contains(const std::string& text) const;
    std::string all() const;
};

// The logger callback of the harness: componentEnvironment is the LogCapture*.
void capture_logger(fmi2ComponentEnvironment env, fmi2String instanceName, fmi2Status status, fmi2String category,
                    fmi2String message, ...);

unsigned int vr_of(const std::string& name);  // value reference by variable name (from the VR table)
std::vector<unsigned int> output_vrs();       // all Real outputs, in table order

const char* fmu_guid();

// One instance with its own log; Instance's destructor frees it.
class Instance {
public:
    // resourceLocation: the fmuResourceLocation URI given to fmi2Instantiate (none by default).
    explicit Instance(const char* name = "cable", bool loggingOn = true, const char* resourceLocation = nullptr);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    fmi2Component c = nullptr;
    LogCapture log;

    fmi2Status setReal(const std::string& name, double value);
    fmi2Status setInteger(const std::string& name, int value);
    fmi2Status setString(const std::string& name, const char* value);
    std::string getString(const std::string& name);
    double getReal(const std::string& name);
    std::vector<double> outputs();            // every Real output, for bitwise comparisons

    fmi2Status setup(double startTime = 0.0, double stopTime = 100.0);
    fmi2Status initialize(double startTime = 0.0, double stopTime = 100.0);  // setup + enter + exit
    fmi2Status steps(int n, double h, double* t);                            // n steps of h from *t
};

// A steady tow along x at about 2 kn from the origin, with a side current.
void set_tow_inputs(Instance& inst);

bool bitwise_equal(const std::vector<double>& a, const std::vector<double>& b);

#endif  // UNDERWATERCABLE_TESTS_FMU_HARNESS_H
