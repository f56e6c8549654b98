/*
 * fmi3Functions.c - the FMI 3.0 co-simulation interface of the cable FMU (docs/fmi3.md), over the FMI 2.0
 * adapter: one instance of it inside each FMI 3.0 instance, the same state machine, logging, states and
 * checks. What FMI 3.0 adds or names differently is translated here: arrays (the stations' outputs, a
 * mooring system's lines, bodies and points: one value reference each, expanded to its FMI 2.0 scalars at
 * the stride uc_fmi3_arrays.h gives), the independent variable time,
 * fmi3EnterInitializationMode with the experiment's times, fmi3DoStep's extra results, the log callback
 * without printf formatting and the resource directory as a path. The FMI 3.0 functions that a
 * co-simulation FMU without event mode, clocks or the other integer types does not provide are present
 * (FMI 3.0 requires it) and return fmi3Error with a logged message.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fmi3Types.h"
#include "instance.h"
#include "logging.h"
#include "simulation.h"
#include "uc_fmi3_arrays.h"

#if defined(_WIN32)
#define FMI3_EXPORT __declspec(dllexport)
#else
#define FMI3_EXPORT __attribute__((visibility("default")))
#endif

_Static_assert(sizeof(fmi3Int32) == sizeof(fmi2Integer), "Int32 values pass to the FMI 2.0 adapter as they are");
_Static_assert(sizeof(fmi3ValueReference) == sizeof(fmi2ValueReference), "value references pass as they are");
_Static_assert((int)fmi3Error == (int)fmi2Error && (int)fmi3Discard == (int)fmi2Discard &&
                   (int)fmi3Fatal == (int)fmi2Fatal, "the statuses have the same values");

/* The structural parameters (uc_fmi3_arrays.h), in their table's order. */
enum {
#define UC_FMI3_COUNT_STRUCTURAL(name, vr, most) +1
    UC_FMI3_STRUCTURAL = 0 UC_FMI3_STRUCTURAL_PARAMETERS(UC_FMI3_COUNT_STRUCTURAL)
#undef UC_FMI3_COUNT_STRUCTURAL
};

/* An FMI 3.0 instance: the FMI 2.0 instance, the FMI 3.0 importer's log callback, the structural parameters'
 * values (the arrays' lengths) and whether it is in configuration mode. */
typedef struct {
    UCInstance* inner;
    fmi3LogMessageCallback logMessage;
    fmi3InstanceEnvironment environment;
    fmi3UInt64 sizes[UC_FMI3_STRUCTURAL];
    int configuring;
    /* The arrays the adapter holds itself (uc_fmi3_arrays.h, UC_FMI3_ADAPTER_ARRAYS: the water pushed by the
     * importer): the 6 inputs waterVelocity.x/y/z, waterAcceleration.x/y/z, then 3 scratch arrays for the
     * positions waterPoint.x/y/z, waterCapacity (nWaterPoints) values each; NULL until first needed. */
    double* water;
    size_t waterCapacity;
} UC3Instance;

static UCInstance* inner(fmi3Instance instance) { return instance ? ((UC3Instance*)instance)->inner : NULL; }

/* The FMI 2.0 adapter's messages are printf formats with '%' and '#' doubled; FMI 3.0's are plain text. */
static void forward_log(fmi2ComponentEnvironment environment, fmi2String instanceName, fmi2Status status,
                        fmi2String category, fmi2String message, ...) {
    (void)instanceName;
    const UC3Instance* self = (const UC3Instance*)environment;
    if (self == NULL || self->logMessage == NULL) return;
    char text[2048];
    va_list args;
    va_start(args, message);
    vsnprintf(text, sizeof text, message, args);
    va_end(args);
    char* out = text;
    for (const char* in = text; *in != '\0'; ++in) {
        *out++ = *in;
        if (*in == '#' && in[1] == '#') ++in;
    }
    *out = '\0';
    self->logMessage(self->environment, (fmi3Status)status, category, text);
}

static fmi3Status unsupported(fmi3Instance instance, const char* function) {
    UCInstance* inst = inner(instance);
    if (inst != NULL) {
        uc_log_status(&inst->log, fmi2Error, "%s: not provided by this co-simulation FMU (no event mode, clocks, "
                      "model exchange or scheduled execution; Float64, Int32, Boolean and String variables and the UInt64 "
                      "structural parameters only)",
                      function);
    }
    return fmi3Error;
}

/* file:// URI of a resource directory given as a path (FMI 3.0 passes paths, the adapter reads URIs). */
static char* resource_uri(fmi3String path) {
    if (path == NULL) return NULL;
    const size_t n = strlen(path);
    char* uri = malloc(3 * n + 16);
    if (uri == NULL) return NULL;
    char* out = uri + sprintf(uri, "file://%s", path[0] == '/' ? "" : "/");
    for (const char* p = path; *p != '\0'; ++p) {
        const unsigned char c = (unsigned char)*p;
        if (c == '\\') {
            *out++ = '/';
        } else if (c == '%' || c == ' ' || c == '#' || c == '?' || c < 0x20) {
            out += sprintf(out, "%%%02X", c);
        } else {
            *out++ = (char)c;
        }
    }
    *out = '\0';
    return uri;
}

/* ---- life cycle ------------------------------------------------------------------------------------ */

FMI3_EXPORT const char* fmi3GetVersion(void) { return "3.0"; }

FMI3_EXPORT fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn, size_t nCategories,
                                           const fmi3String categories[]) {
    return (fmi3Status)fmi2SetDebugLogging(inner(instance), loggingOn, nCategories, categories);
}

FMI3_EXPORT fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath, fmi3Boolean visible,
    fmi3Boolean loggingOn, fmi3Boolean eventModeUsed, fmi3Boolean earlyReturnAllowed,
    const fmi3ValueReference requiredIntermediateVariables[], size_t nRequiredIntermediateVariables,
    fmi3InstanceEnvironment instanceEnvironment, fmi3LogMessageCallback logMessage,
    fmi3IntermediateUpdateCallback intermediateUpdate) {
    (void)requiredIntermediateVariables, (void)nRequiredIntermediateVariables;
    (void)intermediateUpdate; /* no intermediate variables: an early return (at a line failure's break) only */
    UC3Instance* self = calloc(1, sizeof *self);
    if (self == NULL) return NULL;
    self->logMessage = logMessage;
    self->environment = instanceEnvironment;
    if (eventModeUsed) {
        forward_log(self, instanceName, fmi2Error, "logStatusError",
                    "fmi3InstantiateCoSimulation: eventModeUsed = true, but the FMU has no event mode "
                    "(hasEventMode = false)");
        free(self);
        return NULL;
    }
    char* uri = resource_uri(resourcePath);
    const fmi2CallbackFunctions callbacks = {forward_log, NULL, NULL, NULL, self};
    self->inner = (UCInstance*)fmi2Instantiate(instanceName, fmi2CoSimulation, instantiationToken, uri, &callbacks,
                                               visible, loggingOn);
    free(uri);
    if (self->inner == NULL) {
        free(self);
        return NULL;
    }
    self->inner->earlyReturnAllowed = earlyReturnAllowed ? 1 : 0;
    size_t k = 0;
#define UC_FMI3_SIZE_START(name, vr, most) self->sizes[k++] = (most);
    UC_FMI3_STRUCTURAL_PARAMETERS(UC_FMI3_SIZE_START)
#undef UC_FMI3_SIZE_START
    return self;
}

FMI3_EXPORT fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName, fmi3String instantiationToken,
                                                      fmi3String resourcePath, fmi3Boolean visible,
                                                      fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
                                                      fmi3LogMessageCallback logMessage) {
    (void)instantiationToken, (void)resourcePath, (void)visible, (void)loggingOn;
    UC3Instance self = {NULL, logMessage, instanceEnvironment, {0}, 0, NULL, 0};
    forward_log(&self, instanceName, fmi2Error, "logStatusError",
                "fmi3InstantiateModelExchange: UnderwaterCable is a co-simulation FMU only");
    return NULL;
}

FMI3_EXPORT fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath, fmi3Boolean visible,
    fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment, fmi3LogMessageCallback logMessage,
    fmi3ClockUpdateCallback clockUpdate, fmi3LockPreemptionCallback lockPreemption,
    fmi3UnlockPreemptionCallback unlockPreemption) {
    (void)instantiationToken, (void)resourcePath, (void)visible, (void)loggingOn, (void)clockUpdate;
    (void)lockPreemption, (void)unlockPreemption;
    UC3Instance self = {NULL, logMessage, instanceEnvironment, {0}, 0, NULL, 0};
    forward_log(&self, instanceName, fmi2Error, "logStatusError",
                "fmi3InstantiateScheduledExecution: UnderwaterCable is a co-simulation FMU only");
    return NULL;
}

FMI3_EXPORT void fmi3FreeInstance(fmi3Instance instance) {
    if (instance == NULL) return;
    fmi2FreeInstance(inner(instance));
    free(((UC3Instance*)instance)->water);
    free(instance);
}

/* ---- the water pushed by the importer (water.source 1, docs/waves.md) ------------------------------ */

/* The structural parameter sizedBy's value (0 if it names none). */
static size_t structural_value(const UC3Instance* self, fmi3ValueReference sizedBy);

/* The slots below: the positions are the first vector (group 0), the velocity and the acceleration the next two. */
#define UC_FMI3_ADAPTER_SLOTS(avr, name, out, component, group, sizedBy) \
    _Static_assert((out) ? (group) == 0 : ((group) == 1 || (group) == 2), name " has its slot");
UC_FMI3_ADAPTER_ARRAYS(UC_FMI3_ADAPTER_SLOTS)
#undef UC_FMI3_ADAPTER_SLOTS

/* Whether vr is one of the arrays the adapter holds itself; *output, *slot (0..5 the inputs, 6..8 the
 * positions) and *length (the structural parameter's value) when it is. */
static int adapter_array(const UC3Instance* self, fmi3ValueReference vr, int* output, int* slot, size_t* length) {
#define UC_FMI3_ADAPTER_MATCH(avr, name, out, component, group, sizedBy) \
    if (vr == (avr)) {                                                  \
        *output = (out);                                                \
        *slot = (out) ? 6 + (component) : 3 * ((group) - 1) + (component); \
        *length = structural_value(self, (sizedBy));                     \
        return 1;                                                       \
    }
    UC_FMI3_ADAPTER_ARRAYS(UC_FMI3_ADAPTER_MATCH)
#undef UC_FMI3_ADAPTER_MATCH
    return 0;
}

/* The water arrays at the present nWaterPoints (zeros when new or resized), given to the FMI 2.0 adapter;
 * 0 when out of memory. */
static int ensure_water(UC3Instance* self) {
    size_t n = 0; /* every water array has the same length: the first one's */
#define UC_FMI3_ADAPTER_LENGTH(avr, name, out, component, group, sizedBy) \
    if (n == 0) n = structural_value(self, (sizedBy));
    UC_FMI3_ADAPTER_ARRAYS(UC_FMI3_ADAPTER_LENGTH)
#undef UC_FMI3_ADAPTER_LENGTH
    if (self->water != NULL && self->waterCapacity == n) return 1;
    double* water = calloc(9 * n + 1, sizeof *water);
    if (water == NULL) return 0;
    free(self->water);
    self->water = water;
    self->waterCapacity = n;
    for (int c = 0; c < 6; ++c) self->inner->water[c] = water + (size_t)c * n;
    self->inner->waterCapacity = n;
    return 1;
}

FMI3_EXPORT fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean toleranceDefined,
                                                   fmi3Float64 tolerance, fmi3Float64 startTime,
                                                   fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
    UCInstance* inst = inner(instance);
    if (inst != NULL && ((UC3Instance*)instance)->configuring) {
        uc_log_status(&inst->log, fmi2Error, "fmi3EnterInitializationMode: in configuration mode (call "
                      "fmi3ExitConfigurationMode first)");
        return fmi3Error;
    }
    if (inst != NULL && !ensure_water((UC3Instance*)instance)) {
        uc_log_status(&inst->log, fmi2Error, "fmi3EnterInitializationMode: out of memory for the water arrays");
        return fmi3Error;
    }
    const fmi2Status status = fmi2SetupExperiment(inst, toleranceDefined, tolerance, startTime, stopTimeDefined, stopTime);
    if (status > fmi2Warning) return (fmi3Status)status;
    return (fmi3Status)fmi2EnterInitializationMode(inst);
}

FMI3_EXPORT fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
    return (fmi3Status)fmi2ExitInitializationMode(inner(instance));  /* into step mode: no event mode */
}

FMI3_EXPORT fmi3Status fmi3Terminate(fmi3Instance instance) { return (fmi3Status)fmi2Terminate(inner(instance)); }

FMI3_EXPORT fmi3Status fmi3Reset(fmi3Instance instance) {
    const fmi2Status status = fmi2Reset(inner(instance));
    if (status <= fmi2Warning) { /* the structural parameters back at their start values */
        UC3Instance* self = (UC3Instance*)instance;
        size_t k = 0;
        self->configuring = 0;
#define UC_FMI3_SIZE_RESET(name, vr, most) self->sizes[k++] = (most);
        UC_FMI3_STRUCTURAL_PARAMETERS(UC_FMI3_SIZE_RESET)
#undef UC_FMI3_SIZE_RESET
        if (self->water != NULL) memset(self->water, 0, 9 * self->waterCapacity * sizeof *self->water);
    }
    return (fmi3Status)status;
}

FMI3_EXPORT fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint,
                                  fmi3Float64 communicationStepSize, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                  fmi3Boolean* eventHandlingNeeded, fmi3Boolean* terminateSimulation,
                                  fmi3Boolean* earlyReturn, fmi3Float64* lastSuccessfulTime) {
    UCInstance* inst = inner(instance);
    if (inst == NULL || eventHandlingNeeded == NULL || terminateSimulation == NULL || earlyReturn == NULL ||
        lastSuccessfulTime == NULL) {
        if (inst != NULL) uc_log_status(&inst->log, fmi2Error, "fmi3DoStep: a result pointer is NULL");
        return fmi3Error;
    }
    if (!ensure_water((UC3Instance*)instance)) { /* a state set into a fresh instance: no water arrays yet */
        uc_log_status(&inst->log, fmi2Error, "fmi3DoStep: out of memory for the water arrays");
        return fmi3Error;
    }
    const fmi2Status status = fmi2DoStep(inst, currentCommunicationPoint, communicationStepSize,
                                         noSetFMUStatePriorToCurrentPoint);
    *eventHandlingNeeded = false;
    *terminateSimulation = status == fmi2Discard && inst->terminateRequested;
    *lastSuccessfulTime = status <= fmi2Warning ? inst->time : inst->lastSuccessfulTime;
    /* with earlyReturnAllowed a step ends at a line failure's break within it: the FMU's time is then the break's,
     * short of the communication point (docs/fmi3.md) */
    *earlyReturn = status <= fmi2Warning && inst->earlyReturnAllowed &&
                   inst->time < currentCommunicationPoint + communicationStepSize -
                                    1e-12 * fmax(1.0, fabs(currentCommunicationPoint + communicationStepSize));
    return (fmi3Status)status;
}

/* ---- values ---------------------------------------------------------------------------------------- */

/* Elements of the variable vr (the array's length, or 1 for a scalar) and where its FMI 2.0 scalars are:
 * element i is the scalar vr + i * stride for i < kept, extension + (i - kept) * stride beyond (uc_fmi3_arrays.h). */
typedef struct ArrayLayout {
    fmi2ValueReference stride, kept, extension;
} ArrayLayout;

/* The value of the structural parameter vr (its index in the table; -1: none). */
static int structural_index(fmi3ValueReference vr) {
    int k = 0;
#define UC_FMI3_STRUCTURAL_INDEX(name, svr, most) \
    if (vr == (svr)) return k;                    \
    ++k;
    UC_FMI3_STRUCTURAL_PARAMETERS(UC_FMI3_STRUCTURAL_INDEX)
#undef UC_FMI3_STRUCTURAL_INDEX
    return -1;
}

/* An array sized by a structural parameter holds its value's worth of its first dimension (the first
 * elements of the maximum's); the others hold the maximum. */
static size_t array_layout(fmi3Instance instance, fmi3ValueReference vr, ArrayLayout* layout) {
    const UC3Instance* self = (const UC3Instance*)instance;
    layout->stride = 1;
    layout->kept = 1;
    layout->extension = 0;
    int output, slot;
    size_t length;
    if (self != NULL && adapter_array(self, vr, &output, &slot, &length)) return length;
#define UC_FMI3_ARRAY_LENGTH(first, count, step, name, keep, ext, sizedBy, perIndex)                  \
    if (vr == (first)) {                                                                            \
        layout->stride = (step);                                                                    \
        layout->kept = (keep);                                                                      \
        layout->extension = (ext);                                                                  \
        const int s = structural_index(sizedBy);                                                    \
        return s >= 0 && self != NULL ? (size_t)self->sizes[s] * (size_t)(perIndex) : (size_t)(count); \
    }
    UC_FMI3_ARRAYS(UC_FMI3_ARRAY_LENGTH)
#undef UC_FMI3_ARRAY_LENGTH
    return 1;
}

static size_t structural_value(const UC3Instance* self, fmi3ValueReference sizedBy) {
    const int s = structural_index(sizedBy);
    return s >= 0 ? (size_t)self->sizes[s] : 0;
}

/* The FMI 2.0 scalar of element i of the variable vr of that layout. */
static fmi2ValueReference element_vr(fmi3ValueReference vr, const ArrayLayout* layout, size_t i) {
    if (i < layout->kept) return vr + (fmi2ValueReference)i * layout->stride;
    return layout->extension + (fmi2ValueReference)(i - layout->kept) * layout->stride;
}

static size_t elements(fmi3Instance instance, fmi3ValueReference vr) {
    ArrayLayout layout;
    return array_layout(instance, vr, &layout);
}

/* `expected`: the elements of the value references, all together. */
static fmi3Status count_mismatch(UCInstance* inst, const char* function, size_t nValueReferences, size_t expected,
                                 size_t nValues) {
    uc_log_status(&inst->log, fmi2Error, "%s: %zu values for %zu value references of %zu elements in all", function,
                  nValues, nValueReferences, expected);
    return fmi3Error;
}

/* A setter's refusal before it reaches the FMI 2.0 adapter: as the adapter's own, the instance goes to the
 * error state (it does not step on with or without the values). */
static fmi3Status refuse_set(UCInstance* inst, const char* function, size_t nValueReferences, size_t expected,
                             size_t nValues) {
    count_mismatch(inst, function, nValueReferences, expected, nValues);
    return (fmi3Status)uc_instance_finish(inst, fmi2Error);
}

static size_t total_elements(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr) {
    size_t total = 0;
    for (size_t k = 0; k < nvr; ++k) total += elements(instance, vr[k]);
    return total;
}

/* Float64 get and set, variable by variable: an array is its elements' FMI 2.0 scalars (the stations'
 * outputs, a mooring system's lines, bodies and points), at most UC_FMI3_MAX_ELEMENTS of them. */
#define UC_FMI3_ARRAY_FITS(first, count, step, name, keep, ext, sizedBy, perIndex) \
    _Static_assert((count) <= UC_FMI3_MAX_ELEMENTS && (step) >= 1 && (keep) <= (count), name " fits");
UC_FMI3_ARRAYS(UC_FMI3_ARRAY_FITS)
#undef UC_FMI3_ARRAY_FITS

/* fmi3SetFloat64: the count is checked and every value goes to the FMI 2.0 adapter in one fmi2SetReal, which
 * checks them all before it writes any: a refusal leaves every variable as it was. */
static fmi3Status set_float64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                              const fmi3Float64* values, size_t nValues) {
    const char* function = "fmi3SetFloat64";
    UCInstance* inst = inner(instance);
    if (inst == NULL) return fmi3Error;
    if (nvr > 0 && (vr == NULL || values == NULL)) {
        uc_log_status(&inst->log, fmi2Error, "%s: vr or values is NULL with nvr = %zu", function, nvr);
        return (fmi3Status)uc_instance_finish(inst, fmi2Error);
    }
    const size_t expected = total_elements(instance, vr, nvr);
    if (expected != nValues) return refuse_set(inst, function, nvr, expected, nValues);
    for (size_t k = 0; k < nvr; ++k) {
        if (vr[k] == UC_FMI3_TIME_VR) {
            uc_log_status(&inst->log, fmi2Error, "%s: time (value reference %u) is the independent variable and "
                          "cannot be set", function, (unsigned)vr[k]);
            return (fmi3Status)uc_instance_finish(inst, fmi2Error);
        }
    }
    /* the water arrays (the adapter's own): inputs only, in the states where inputs may be set */
    UC3Instance* self = (UC3Instance*)instance;
    size_t own = 0;
    for (size_t k = 0; k < nvr; ++k) {
        int output, slot;
        size_t length;
        if (!adapter_array(self, vr[k], &output, &slot, &length)) continue;
        if (output || !(inst->state & UC_MASK_SET)) {
            uc_log_status(&inst->log, fmi2Error, "%s: value reference %u is %s", function, (unsigned)vr[k],
                          output ? "the output waterPoint.*, which cannot be set"
                                 : "a water input, which can be set after instantiation, in initialization mode and "
                                   "between steps only");
            return (fmi3Status)uc_instance_finish(inst, fmi2Error);
        }
        own += length;
    }
    if (own > 0 && !ensure_water(self)) {
        uc_log_status(&inst->log, fmi2Error, "%s: out of memory for the water arrays", function);
        return (fmi3Status)uc_instance_finish(inst, fmi2Error);
    }
    fmi2ValueReference* scalars = malloc((nValues + 1) * sizeof *scalars);
    fmi2Real* rest = malloc((nValues + 1) * sizeof *rest);
    if (scalars == NULL || rest == NULL) {
        free(scalars);
        free(rest);
        uc_log_status(&inst->log, fmi2Error, "%s: out of memory for %zu values", function, nValues);
        return (fmi3Status)uc_instance_finish(inst, fmi2Error);
    }
    /* the FMI 2.0 scalars of the others, set first (checked all before any is written); then the water */
    size_t at = 0, nRest = 0;
    for (size_t k = 0; k < nvr; ++k) {
        ArrayLayout layout;
        const size_t n = array_layout(instance, vr[k], &layout);
        int output, slot;
        size_t length;
        if (!adapter_array(self, vr[k], &output, &slot, &length)) {
            for (size_t i = 0; i < n; ++i) {
                scalars[nRest] = element_vr(vr[k], &layout, i);
                rest[nRest++] = values[at + i];
            }
        }
        at += n;
    }
    fmi2Status status = fmi2OK;
    if (nRest > 0 || own == 0) status = fmi2SetReal(inst, scalars, nRest, rest);
    free(scalars);
    free(rest);
    if (status > fmi2Warning || own == 0) return (fmi3Status)status;
    at = 0;
    for (size_t k = 0; k < nvr; ++k) {
        int output, slot;
        size_t length;
        if (adapter_array(self, vr[k], &output, &slot, &length)) {
            memcpy(self->water + (size_t)slot * self->waterCapacity, values + at, length * sizeof *values);
            at += length;
        } else {
            at += elements(instance, vr[k]);
        }
    }
    /* before the first step the initialization is computed again from the new water, as for any input */
    if (inst->state != UC_STATE_STEP_COMPLETE) uc_instance_drop_core(inst);
    return (fmi3Status)status;
}

/* waterPoint.x/y/z (slot 6, 7, 8) into values (length of them): the load points where the state has them, 0
 * beyond the lines' load points and before the initialization is computed. */
static fmi2Status water_positions(fmi3Instance instance, int slot, size_t length, fmi3Float64* values) {
    UC3Instance* self = (UC3Instance*)instance;
    UCInstance* inst = self->inner;
    if (inst->state & UC_STATE_INIT_MODE) {
        const fmi2Status status = uc_sim_initial_outputs(inst, "fmi3GetFloat64");
        if (status > fmi2Warning) return status;
    }
    memset(values, 0, length * sizeof *values);
    if (!inst->coreReady || inst->cable == NULL) return fmi2OK;
    const size_t n = uc_water_points(inst->cable);
    if (n == 0) return fmi2OK;
    if (!ensure_water(self)) {
        uc_log_status(&inst->log, fmi2Error, "fmi3GetFloat64: out of memory for the water arrays");
        return fmi2Error;
    }
    if (n > self->waterCapacity) return fmi2OK; /* refused at the initialization: nWaterPoints too short */
    double* p = self->water + 6 * self->waterCapacity;
    uc_water_positions(inst->cable, p, p + self->waterCapacity, p + 2 * self->waterCapacity);
    memcpy(values, p + (size_t)(slot - 6) * self->waterCapacity, (n < length ? n : length) * sizeof *values);
    return fmi2OK;
}

static fmi3Status get_float64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Float64* values,
                              size_t nValues) {
    const char* function = "fmi3GetFloat64";
    UCInstance* inst = inner(instance);
    if (inst == NULL) return fmi3Error;
    if (nvr > 0 && (vr == NULL || values == NULL)) {
        uc_log_status(&inst->log, fmi2Error, "%s: vr or values is NULL with nvr = %zu", function, nvr);
        return fmi3Error;
    }
    const size_t expected = total_elements(instance, vr, nvr);
    if (expected != nValues) return count_mismatch(inst, function, nvr, expected, nValues);
    size_t at = 0;
    fmi2Status worst = fmi2OK;
    for (size_t k = 0; k < nvr; ++k) {
        ArrayLayout layout;
        const size_t n = array_layout(instance, vr[k], &layout);
        fmi2Status status;
        int output, slot;
        size_t length;
        if (vr[k] == UC_FMI3_TIME_VR) {
            values[at] = inst->time;
            status = fmi2OK;
        } else if (adapter_array((UC3Instance*)instance, vr[k], &output, &slot, &length)) {
            if (!(inst->state & UC_MASK_GET)) {
                uc_log_status(&inst->log, fmi2Error, "fmi3GetFloat64: the water arrays cannot be read in this state");
                return fmi3Error;
            }
            UC3Instance* self = (UC3Instance*)instance;
            if (output) {
                status = water_positions(instance, slot, n, values + at);
            } else if (self->water != NULL && self->waterCapacity == n) {
                memcpy(values + at, self->water + (size_t)slot * n, n * sizeof *values);
                status = fmi2OK;
            } else {
                memset(values + at, 0, n * sizeof *values); /* the start values */
                status = fmi2OK;
            }
        } else {
            fmi2ValueReference scalars[UC_FMI3_MAX_ELEMENTS];
            for (size_t i = 0; i < n; ++i) scalars[i] = element_vr(vr[k], &layout, i);
            status = fmi2GetReal(inst, scalars, n, values + at);
        }
        if (status > worst) worst = status;
        if (worst > fmi2Warning) return (fmi3Status)worst;
        at += n;
    }
    return (fmi3Status)worst;
}

FMI3_EXPORT fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                      size_t nValueReferences, fmi3Float64 values[], size_t nValues) {
    return get_float64(instance, valueReferences, nValueReferences, values, nValues);
}

FMI3_EXPORT fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                      size_t nValueReferences, const fmi3Float64 values[], size_t nValues) {
    return set_float64(instance, valueReferences, nValueReferences, values, nValues);
}

/* Scalar-only types: one value per value reference (a setter's mismatch is a refusal: refuse_set). */
static int scalar_counts(fmi3Instance instance, size_t nvr, size_t nValues, const char* function) {
    if (inner(instance) != NULL && nvr != nValues) {
        if (strncmp(function, "fmi3Set", 7) == 0) {
            refuse_set(inner(instance), function, nvr, nvr, nValues);
        } else {
            count_mismatch(inner(instance), function, nvr, nvr, nValues);
        }
        return 0;
    }
    return inner(instance) != NULL;
}

FMI3_EXPORT fmi3Status fmi3GetInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                    size_t nValueReferences, fmi3Int32 values[], size_t nValues) {
    if (!scalar_counts(instance, nValueReferences, nValues, "fmi3GetInt32")) return fmi3Error;
    return (fmi3Status)fmi2GetInteger(inner(instance), valueReferences, nValueReferences, (fmi2Integer*)values);
}

FMI3_EXPORT fmi3Status fmi3SetInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                    size_t nValueReferences, const fmi3Int32 values[], size_t nValues) {
    if (!scalar_counts(instance, nValueReferences, nValues, "fmi3SetInt32")) return fmi3Error;
    return (fmi3Status)fmi2SetInteger(inner(instance), valueReferences, nValueReferences, (const fmi2Integer*)values);
}

FMI3_EXPORT fmi3Status fmi3GetBoolean(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                      size_t nValueReferences, fmi3Boolean values[], size_t nValues) {
    if (!scalar_counts(instance, nValueReferences, nValues, "fmi3GetBoolean")) return fmi3Error;
    if (nValueReferences > 0 && values == NULL) { /* the FMI 2.0 getter below writes into b, not values */
        uc_log_status(&inner(instance)->log, fmi2Error, "fmi3GetBoolean: values is NULL with nvr = %zu",
                      nValueReferences);
        return fmi3Error;
    }
    fmi2Boolean* b = calloc(nValues + 1, sizeof *b);
    if (b == NULL) return fmi3Error;
    const fmi2Status status = fmi2GetBoolean(inner(instance), valueReferences, nValueReferences, b);
    for (size_t k = 0; status <= fmi2Warning && k < nValues; ++k) values[k] = b[k] != fmi2False;
    free(b);
    return (fmi3Status)status;
}

FMI3_EXPORT fmi3Status fmi3SetBoolean(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                      size_t nValueReferences, const fmi3Boolean values[], size_t nValues) {
    if (!scalar_counts(instance, nValueReferences, nValues, "fmi3SetBoolean")) return fmi3Error;
    fmi2Boolean* b = calloc(nValues + 1, sizeof *b);
    if (b == NULL) return fmi3Error;
    for (size_t k = 0; k < nValues && values != NULL; ++k) b[k] = values[k] ? fmi2True : fmi2False;
    const fmi2Status status = fmi2SetBoolean(inner(instance), valueReferences, nValueReferences,
                                             values != NULL ? b : NULL);
    free(b);
    return (fmi3Status)status;
}

FMI3_EXPORT fmi3Status fmi3GetString(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                     size_t nValueReferences, fmi3String values[], size_t nValues) {
    if (!scalar_counts(instance, nValueReferences, nValues, "fmi3GetString")) return fmi3Error;
    return (fmi3Status)fmi2GetString(inner(instance), valueReferences, nValueReferences, values);
}

FMI3_EXPORT fmi3Status fmi3SetString(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                     size_t nValueReferences, const fmi3String values[], size_t nValues) {
    if (!scalar_counts(instance, nValueReferences, nValues, "fmi3SetString")) return fmi3Error;
    return (fmi3Status)fmi2SetString(inner(instance), valueReferences, nValueReferences, values);
}

/* ---- states and derivatives ----------------------------------------------------------------------- */

FMI3_EXPORT fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState* FMUState) {
    return (fmi3Status)fmi2GetFMUstate(inner(instance), (fmi2FMUstate*)FMUState);
}

FMI3_EXPORT fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState) {
    return (fmi3Status)fmi2SetFMUstate(inner(instance), FMUState);
}

FMI3_EXPORT fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState* FMUState) {
    return (fmi3Status)fmi2FreeFMUstate(inner(instance), (fmi2FMUstate*)FMUState);
}

FMI3_EXPORT fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState FMUState, size_t* size) {
    return (fmi3Status)fmi2SerializedFMUstateSize(inner(instance), FMUState, size);
}

FMI3_EXPORT fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState, fmi3Byte serializedState[],
                                             size_t size) {
    return (fmi3Status)fmi2SerializeFMUstate(inner(instance), FMUState, (fmi2Byte*)serializedState, size);
}

FMI3_EXPORT fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte serializedState[], size_t size,
                                               fmi3FMUState* FMUState) {
    return (fmi3Status)fmi2DeSerializeFMUstate(inner(instance), (const fmi2Byte*)serializedState, size,
                                               (fmi2FMUstate*)FMUState);
}

/* The derivatives of arrays with respect to arrays of as many elements (a mooring system's body.force.* and
 * body.moment.* against body.x ... body.wz): FMI 2.0 gives them body by body, the load on body k against
 * body k's inputs, so element k of the unknowns is taken against element k of the knowns; the entries
 * between different elements (bodies) are 0, as FMI 2.0 has none. An element whose seeds are all 0 has
 * sensitivities 0 (no FMI 2.0 call: a deck's bodies beyond its own have neither inputs nor loads). */
enum { UC_FMI3_MAX_DERIVATIVE_VARIABLES = 32 };

static fmi3Status array_directional_derivative(fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
                                               const fmi3ValueReference knowns[], size_t nKnowns,
                                               const fmi3Float64 seed[], size_t nSeed, fmi3Float64 sensitivity[],
                                               size_t nSensitivity) {
    const char* function = "fmi3GetDirectionalDerivative";
    UCInstance* inst = inner(instance);
    fmi2ValueReference u[UC_FMI3_MAX_DERIVATIVE_VARIABLES], k[UC_FMI3_MAX_DERIVATIVE_VARIABLES];
    ArrayLayout uLayout[UC_FMI3_MAX_DERIVATIVE_VARIABLES], kLayout[UC_FMI3_MAX_DERIVATIVE_VARIABLES];
    fmi2Real s[UC_FMI3_MAX_DERIVATIVE_VARIABLES], ds[UC_FMI3_MAX_DERIVATIVE_VARIABLES];
    const size_t n = elements(instance, unknowns[0]);
    int same = nUnknowns <= UC_FMI3_MAX_DERIVATIVE_VARIABLES && nKnowns <= UC_FMI3_MAX_DERIVATIVE_VARIABLES;
    for (size_t i = 0; same && i < nUnknowns; ++i) same = array_layout(instance, unknowns[i], &uLayout[i]) == n;
    for (size_t j = 0; same && j < nKnowns; ++j) same = array_layout(instance, knowns[j], &kLayout[j]) == n;
    if (!same || nSeed != nKnowns * n || nSensitivity != nUnknowns * n) {
        uc_log_status(&inst->log, fmi2Error, "%s: with arrays, every unknown and known is an array of the same length "
                      "(a mooring system's body.force.*, body.moment.* against body.x ... body.wz, at most %d of "
                      "each), one seed per known element and one sensitivity per unknown element (%zu knowns, %zu "
                      "seeds, %zu unknowns, %zu sensitivities)", function, (int)UC_FMI3_MAX_DERIVATIVE_VARIABLES,
                      nKnowns, nSeed, nUnknowns, nSensitivity);
        return fmi3Error;
    }
    for (size_t e = 0; e < n; ++e) {
        int seeded = 0;
        for (size_t j = 0; j < nKnowns; ++j) {
            k[j] = element_vr(knowns[j], &kLayout[j], e);
            s[j] = seed[j * n + e];
            seeded |= s[j] != 0.0;
        }
        for (size_t i = 0; i < nUnknowns; ++i) {
            u[i] = element_vr(unknowns[i], &uLayout[i], e);
            ds[i] = 0.0;
        }
        if (seeded) {
            const fmi2Status status = fmi2GetDirectionalDerivative(inst, u, nUnknowns, k, nKnowns, s, ds);
            if (status > fmi2Warning) return (fmi3Status)status;
        }
        for (size_t i = 0; i < nUnknowns; ++i) sensitivity[i * n + e] = ds[i];
    }
    return fmi3OK;
}

FMI3_EXPORT fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[],
                                                    size_t nUnknowns, const fmi3ValueReference knowns[], size_t nKnowns,
                                                    const fmi3Float64 seed[], size_t nSeed, fmi3Float64 sensitivity[],
                                                    size_t nSensitivity) {
    UCInstance* inst = inner(instance);
    if (inst == NULL) return fmi3Error;
    if ((nUnknowns > 0 && (unknowns == NULL || sensitivity == NULL)) || (nKnowns > 0 && (knowns == NULL || seed == NULL))) {
        uc_log_status(&inst->log, fmi2Error, "fmi3GetDirectionalDerivative: NULL array");
        return fmi3Error;
    }
    for (size_t k = 0; k < nUnknowns + nKnowns; ++k) {
        int output, slot;
        size_t length;
        const fmi3ValueReference vr = k < nUnknowns ? unknowns[k] : knowns[k - nUnknowns];
        if (adapter_array((UC3Instance*)instance, vr, &output, &slot, &length)) {
            uc_log_status(&inst->log, fmi2Error, "fmi3GetDirectionalDerivative: value reference %u is a water array "
                          "(waterPoint.*, waterVelocity.*, waterAcceleration.*), which has no derivatives", (unsigned)vr);
            return fmi3Error;
        }
    }
    int arrays = 0;
    for (size_t k = 0; k < nUnknowns; ++k) arrays |= elements(instance, unknowns[k]) > 1;
    for (size_t k = 0; k < nKnowns; ++k) arrays |= elements(instance, knowns[k]) > 1;
    if (arrays && nUnknowns > 0) {
        return array_directional_derivative(instance, unknowns, nUnknowns, knowns, nKnowns, seed, nSeed, sensitivity,
                                            nSensitivity);
    }
    if (nSeed != nKnowns || nSensitivity != nUnknowns) {
        uc_log_status(&inst->log, fmi2Error, "fmi3GetDirectionalDerivative: the derivatives are of scalar outputs "
                      "(towForce.*, endForce.*) with respect to scalar inputs, or of a mooring system's body arrays "
                      "with respect to its body input arrays: one seed per known and one sensitivity per unknown "
                      "(%zu knowns, %zu seeds, %zu unknowns, %zu sensitivities)",
                      nKnowns, nSeed, nUnknowns, nSensitivity);
        return fmi3Error;
    }
    return (fmi3Status)fmi2GetDirectionalDerivative(inst, unknowns, nUnknowns, knowns, nKnowns, seed, sensitivity);
}

/* ---- configuration mode: the structural parameters ------------------------------------------------- */

/* Configuration mode, after instantiation and before initialization: the structural parameters (the arrays'
 * lengths) may be set there only (docs/fmi3.md). */
FMI3_EXPORT fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance) {
    UC3Instance* self = (UC3Instance*)instance;
    UCInstance* inst = inner(instance);
    if (inst == NULL) return fmi3Error;
    if (inst->state != UC_STATE_INSTANTIATED || self->configuring) {
        uc_log_status(&inst->log, fmi2Error, "fmi3EnterConfigurationMode: only after fmi3InstantiateCoSimulation "
                      "or fmi3ExitConfigurationMode, before fmi3EnterInitializationMode");
        return fmi3Error;
    }
    self->configuring = 1;
    return fmi3OK;
}

FMI3_EXPORT fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance) {
    UC3Instance* self = (UC3Instance*)instance;
    UCInstance* inst = inner(instance);
    if (inst == NULL) return fmi3Error;
    if (!self->configuring) {
        uc_log_status(&inst->log, fmi2Error, "fmi3ExitConfigurationMode: not in configuration mode");
        return fmi3Error;
    }
    self->configuring = 0;
    return fmi3OK;
}

/* UInt64: the structural parameters only. */
static int structural_references(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const void* values,
                                 size_t nValues, const char* function) {
    UCInstance* inst = inner(instance);
    if (inst == NULL) return 0;
    if (nvr != nValues || (nvr > 0 && (vr == NULL || values == NULL))) {
        uc_log_status(&inst->log, fmi2Error, "%s: %zu values for %zu value references (one each), or a NULL array",
                      function, nValues, nvr);
        return 0;
    }
    for (size_t k = 0; k < nvr; ++k) {
        if (structural_index(vr[k]) < 0) {
            uc_log_status(&inst->log, fmi2Error, "%s: value reference %u is no UInt64 variable (the UInt64 "
                          "variables are the structural parameters nLines, nBodies and nPoints)", function,
                          (unsigned)vr[k]);
            return 0;
        }
    }
    return 1;
}

FMI3_EXPORT fmi3Status fmi3GetUInt64(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                     size_t nValueReferences, fmi3UInt64 values[], size_t nValues) {
    if (!structural_references(instance, valueReferences, nValueReferences, values, nValues, "fmi3GetUInt64"))
        return fmi3Error;
    const UC3Instance* self = (const UC3Instance*)instance;
    for (size_t k = 0; k < nValueReferences; ++k) values[k] = self->sizes[structural_index(valueReferences[k])];
    return fmi3OK;
}

/* Checks every value before it sets any: a refusal leaves every structural parameter as it was. */
FMI3_EXPORT fmi3Status fmi3SetUInt64(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                     size_t nValueReferences, const fmi3UInt64 values[], size_t nValues) {
    const char* function = "fmi3SetUInt64";
    if (!structural_references(instance, valueReferences, nValueReferences, values, nValues, function))
        return fmi3Error;
    UC3Instance* self = (UC3Instance*)instance;
    UCInstance* inst = self->inner;
    static const char* const names[] = {
#define UC_FMI3_STRUCTURAL_NAME(name, vr, most) name,
        UC_FMI3_STRUCTURAL_PARAMETERS(UC_FMI3_STRUCTURAL_NAME)
#undef UC_FMI3_STRUCTURAL_NAME
    };
    static const fmi3UInt64 most[] = {
#define UC_FMI3_STRUCTURAL_MOST(name, vr, largest) (largest),
        UC_FMI3_STRUCTURAL_PARAMETERS(UC_FMI3_STRUCTURAL_MOST)
#undef UC_FMI3_STRUCTURAL_MOST
    };
    for (size_t k = 0; k < nValueReferences; ++k) {
        const int s = structural_index(valueReferences[k]);
        if (!self->configuring) {
            uc_log_status(&inst->log, fmi2Error, "%s: %s is a structural parameter: set it in configuration mode "
                          "(fmi3EnterConfigurationMode after instantiation)", function, names[s]);
            return fmi3Error;
        }
        if (values[k] < 1 || values[k] > most[s]) {
            uc_log_status(&inst->log, fmi2Error, "%s: %s = %llu is outside [1, %llu]: the arrays it sizes hold at "
                          "most the FMU's %llu (a deck's further lines run without outputs; bodies and points beyond "
                          "it are refused)", function, names[s], (unsigned long long)values[k],
                          (unsigned long long)most[s], (unsigned long long)most[s]);
            return fmi3Error;
        }
    }
    for (size_t k = 0; k < nValueReferences; ++k) self->sizes[structural_index(valueReferences[k])] = values[k];
    return fmi3OK;
}

/* ---- what this FMU does not provide ------------------------------------------------------------------- */

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define UC_UNSUPPORTED(name, ...) \
    FMI3_EXPORT fmi3Status name(fmi3Instance instance, __VA_ARGS__) { return unsupported(instance, #name); }
#define UC_UNSUPPORTED0(name) \
    FMI3_EXPORT fmi3Status name(fmi3Instance instance) { return unsupported(instance, #name); }
#define UC_UNSUPPORTED_TYPE(T) \
    UC_UNSUPPORTED(fmi3Get##T, const fmi3ValueReference vr[], size_t nvr, fmi3##T values[], size_t nValues) \
    UC_UNSUPPORTED(fmi3Set##T, const fmi3ValueReference vr[], size_t nvr, const fmi3##T values[], size_t nValues)

UC_UNSUPPORTED0(fmi3EnterEventMode)
UC_UNSUPPORTED0(fmi3EnterStepMode)
UC_UNSUPPORTED0(fmi3EvaluateDiscreteStates)
UC_UNSUPPORTED0(fmi3EnterContinuousTimeMode)
UC_UNSUPPORTED_TYPE(Float32)
UC_UNSUPPORTED_TYPE(Int8)
UC_UNSUPPORTED_TYPE(UInt8)
UC_UNSUPPORTED_TYPE(Int16)
UC_UNSUPPORTED_TYPE(UInt16)
UC_UNSUPPORTED_TYPE(UInt32)
UC_UNSUPPORTED_TYPE(Int64)
UC_UNSUPPORTED(fmi3GetBinary, const fmi3ValueReference vr[], size_t nvr, size_t valueSizes[], fmi3Binary values[],
               size_t nValues)
UC_UNSUPPORTED(fmi3SetBinary, const fmi3ValueReference vr[], size_t nvr, const size_t valueSizes[],
               const fmi3Binary values[], size_t nValues)
UC_UNSUPPORTED(fmi3GetClock, const fmi3ValueReference vr[], size_t nvr, fmi3Clock values[])
UC_UNSUPPORTED(fmi3SetClock, const fmi3ValueReference vr[], size_t nvr, const fmi3Clock values[])
UC_UNSUPPORTED(fmi3GetNumberOfVariableDependencies, fmi3ValueReference vr, size_t* nDependencies)
UC_UNSUPPORTED(fmi3GetVariableDependencies, fmi3ValueReference dependent, size_t elementIndicesOfDependent[],
               fmi3ValueReference independents[], size_t elementIndicesOfIndependents[],
               fmi3DependencyKind dependencyKinds[], size_t nDependencies)
UC_UNSUPPORTED(fmi3GetAdjointDerivative, const fmi3ValueReference unknowns[], size_t nUnknowns,
               const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
               fmi3Float64 sensitivity[], size_t nSensitivity)
UC_UNSUPPORTED(fmi3GetOutputDerivatives, const fmi3ValueReference vr[], size_t nvr, const fmi3Int32 orders[],
               fmi3Float64 values[], size_t nValues)
UC_UNSUPPORTED(fmi3GetIntervalDecimal, const fmi3ValueReference vr[], size_t nvr, fmi3Float64 intervals[],
               fmi3IntervalQualifier qualifiers[])
UC_UNSUPPORTED(fmi3GetIntervalFraction, const fmi3ValueReference vr[], size_t nvr, fmi3UInt64 counters[],
               fmi3UInt64 resolutions[], fmi3IntervalQualifier qualifiers[])
UC_UNSUPPORTED(fmi3GetShiftDecimal, const fmi3ValueReference vr[], size_t nvr, fmi3Float64 shifts[])
UC_UNSUPPORTED(fmi3GetShiftFraction, const fmi3ValueReference vr[], size_t nvr, fmi3UInt64 counters[],
               fmi3UInt64 resolutions[])
UC_UNSUPPORTED(fmi3SetIntervalDecimal, const fmi3ValueReference vr[], size_t nvr, const fmi3Float64 intervals[])
UC_UNSUPPORTED(fmi3SetIntervalFraction, const fmi3ValueReference vr[], size_t nvr, const fmi3UInt64 counters[],
               const fmi3UInt64 resolutions[])
UC_UNSUPPORTED(fmi3SetShiftDecimal, const fmi3ValueReference vr[], size_t nvr, const fmi3Float64 shifts[])
UC_UNSUPPORTED(fmi3SetShiftFraction, const fmi3ValueReference vr[], size_t nvr, const fmi3UInt64 counters[],
               const fmi3UInt64 resolutions[])
UC_UNSUPPORTED(fmi3UpdateDiscreteStates, fmi3Boolean* discreteStatesNeedUpdate, fmi3Boolean* terminateSimulation,
               fmi3Boolean* nominalsOfContinuousStatesChanged, fmi3Boolean* valuesOfContinuousStatesChanged,
               fmi3Boolean* nextEventTimeDefined, fmi3Float64* nextEventTime)
UC_UNSUPPORTED(fmi3CompletedIntegratorStep, fmi3Boolean noSetFMUStatePriorToCurrentPoint, fmi3Boolean* enterEventMode,
               fmi3Boolean* terminateSimulation)
UC_UNSUPPORTED(fmi3SetTime, fmi3Float64 time)
UC_UNSUPPORTED(fmi3SetContinuousStates, const fmi3Float64 continuousStates[], size_t nContinuousStates)
UC_UNSUPPORTED(fmi3GetContinuousStateDerivatives, fmi3Float64 derivatives[], size_t nContinuousStates)
UC_UNSUPPORTED(fmi3GetEventIndicators, fmi3Float64 eventIndicators[], size_t nEventIndicators)
UC_UNSUPPORTED(fmi3GetContinuousStates, fmi3Float64 continuousStates[], size_t nContinuousStates)
UC_UNSUPPORTED(fmi3GetNominalsOfContinuousStates, fmi3Float64 nominals[], size_t nContinuousStates)
UC_UNSUPPORTED(fmi3GetNumberOfEventIndicators, size_t* nEventIndicators)
UC_UNSUPPORTED(fmi3GetNumberOfContinuousStates, size_t* nContinuousStates)
UC_UNSUPPORTED(fmi3ActivateModelPartition, fmi3ValueReference clockReference, fmi3Float64 activationTime)
#pragma GCC diagnostic pop
