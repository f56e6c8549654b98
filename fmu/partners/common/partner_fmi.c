/*
 * partner_fmi.c - the exported FMI 2.0 Co-Simulation functions of a partner FMU (the model is
 * kPartnerModel, linked in). Each function checks the machine state against the set of states it may
 * be called in (FMI 2.0 section 4.2.4), delegates, and applies the worst-status rule in one place: the
 * state machine of the cable's adapter, common/fmi2_machine.h. Values: the value reference of a variable is its position in the model's table
 * (1-based); Real, Integer and Boolean variables are stored as doubles in the model's data, String
 * parameters as char arrays in it (copied in, so that a saved state holds them).
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "partner_guid.h"
#include "partner_instance.h"
#include "string_value.h"

/* Runs `body` (an expression yielding fmi2Status) if the instance may call `function` now. */
#define GUARDED(c, mask, function, body) UC_MACHINE_GUARDED(PMInstance, c, mask, function, body)

/* ---- common functions ------------------------------------------------------------------------------- */

const char* fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }

const char* fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
    GUARDED(c, UC_MASK_SET_DEBUG_LOGGING, "fmi2SetDebugLogging",
            uc_log_configure(&inst->log, loggingOn, nCategories, categories));
}

static int rejected(const fmi2CallbackFunctions* functions, fmi2String instanceName, const char* reason) {
    if (functions != NULL) {
        uc_log_raw(functions->logger, functions->componentEnvironment, instanceName, fmi2Error,
                   UC_LOG_STATUS_ERROR, reason);
    }
    return 1;
}

static int instantiation_rejected(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                                  const fmi2CallbackFunctions* functions) {
    if (functions == NULL || functions->logger == NULL) return 1;
    if (instanceName == NULL || instanceName[0] == '\0') {
        return rejected(functions, instanceName, "fmi2Instantiate: instanceName is NULL or empty");
    }
    if (fmuType != fmi2CoSimulation) {
        return rejected(functions, instanceName, "fmi2Instantiate: fmuType must be fmi2CoSimulation");
    }
    if (fmuGUID == NULL || strcmp(fmuGUID, PM_GUID) != 0) {
        return rejected(functions, instanceName,
                        "fmi2Instantiate: fmuGUID does not match the guid " PM_GUID " of this binary");
    }
    return 0;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions* functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn) {
    (void)visible; /* no user interface */
    if (instantiation_rejected(instanceName, fmuType, fmuGUID, functions)) return NULL;
    PMInstance* inst = pm_instance_new(&kPartnerModel, instanceName, fmuResourceLocation, functions->logger,
                                       functions->componentEnvironment, loggingOn);
    if (inst == NULL) {
        rejected(functions, instanceName, "fmi2Instantiate: out of memory");
        return NULL;
    }
    uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS, "fmi2Instantiate: %s (%s), guid %s", instanceName,
           kPartnerModel.identifier, PM_GUID);
    return inst;
}

void fmi2FreeInstance(fmi2Component c) { pm_instance_free((PMInstance*)c); }

static fmi2Status setup_experiment(PMInstance* inst, fmi2Real startTime, fmi2Boolean stopTimeDefined,
                                   fmi2Real stopTime) {
    if (!isfinite(startTime) || (stopTimeDefined && !(stopTime >= startTime && isfinite(stopTime)))) {
        uc_log_status(&inst->log, fmi2Error,
                      "fmi2SetupExperiment: startTime = %g, stopTime = %g: need finite startTime <= stopTime",
                      startTime, stopTime);
        return fmi2Error;
    }
    inst->startTime = inst->time = startTime;
    inst->stopTimeDefined = stopTimeDefined != fmi2False;
    inst->stopTime = stopTimeDefined ? stopTime : 0.0;
    inst->ready = 0;
    return fmi2OK;
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    (void)toleranceDefined, (void)tolerance; /* fixed-step Runge-Kutta: no tolerance */
    GUARDED(c, UC_MASK_SETUP_EXPERIMENT, "fmi2SetupExperiment",
            setup_experiment(inst, startTime, stopTimeDefined, stopTime));
}

static fmi2Status enter_initialization_mode(PMInstance* inst) {
    uc_machine_enter_initialization(&inst->state);
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    GUARDED(c, UC_MASK_ENTER_INIT, "fmi2EnterInitializationMode", enter_initialization_mode(inst));
}

static fmi2Status exit_initialization_mode(PMInstance* inst) {
    return uc_machine_exit_initialization(&inst->state, pm_ensure_initialized(inst, "fmi2ExitInitializationMode"));
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    GUARDED(c, UC_MASK_EXIT_INIT, "fmi2ExitInitializationMode", exit_initialization_mode(inst));
}

static fmi2Status terminate(PMInstance* inst) {
    uc_machine_terminate(&inst->state);
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) {
    GUARDED(c, UC_MASK_TERMINATE, "fmi2Terminate", terminate(inst));
}

static fmi2Status reset(PMInstance* inst) {
    pm_instance_reset(inst);
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) {
    GUARDED(c, UC_MASK_RESET, "fmi2Reset", reset(inst));
}

/* ---- values ----------------------------------------------------------------------------------------- */

static const PMVariable* find_variable(PMInstance* inst, fmi2ValueReference vr, PMType type, const char* function) {
    const PMModel* m = inst->model;
    if (vr >= 1 && vr <= m->nVariables && m->variables[vr - 1].type == type) return &m->variables[vr - 1];
    static const char* const kTypeNames[] = {"Real", "Boolean", "Integer", "String"};
    uc_log_status(&inst->log, fmi2Error, "%s: unknown value reference %u for type %s", function, vr, kTypeNames[type]);
    return NULL;
}

static fmi2Status check_arrays(PMInstance* inst, const void* vr, size_t nvr, const void* values,
                               const char* function) {
    if (nvr > 0 && (vr == NULL || values == NULL)) {
        uc_log_status(&inst->log, fmi2Error, "%s: vr or value is NULL with nvr = %zu", function, nvr);
        return fmi2Error;
    }
    return fmi2OK;
}

/* Reads nvr values into reals (Real) or ints (Boolean, Integer: both int in FMI 2.0); outputs read in
 * initialization mode are computed from the current parameters and inputs. */
static fmi2Status get_values(PMInstance* inst, const fmi2ValueReference vr[], size_t nvr, PMType type,
                             fmi2Real* reals, int* ints, const char* function) {
    if (check_arrays(inst, vr, nvr, type == PM_REAL ? (const void*)reals : (const void*)ints, function) != fmi2OK) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; ++i) {
        const PMVariable* v = find_variable(inst, vr[i], type, function);
        if (v == NULL) return fmi2Error;
        if (v->causality == PM_OUTPUT && inst->state == UC_STATE_INIT_MODE &&
            pm_ensure_initialized(inst, function) != fmi2OK) {
            return fmi2Error;
        }
        double value = *pm_value(inst, v);
        if (type == PM_REAL) {
            reals[i] = value;
        } else if (type == PM_INTEGER) {
            ints[i] = (int)value;
        } else {
            ints[i] = value != 0.0 ? fmi2True : fmi2False;
        }
    }
    return fmi2OK;
}

static fmi2Status check_settable(PMInstance* inst, const PMVariable* v, const char* function) {
    if (v->causality == PM_OUTPUT) {
        uc_log_status(&inst->log, fmi2Error, "%s: %s is an output and cannot be set", function, v->name);
        return fmi2Error;
    }
    if (v->causality == PM_PARAMETER && inst->state == UC_STATE_STEP_COMPLETE) {
        uc_log_status(&inst->log, fmi2Error, "%s: %s is a fixed parameter and cannot be changed after initialization",
                      function, v->name);
        return fmi2Error;
    }
    return fmi2OK;
}

static fmi2Status check_number(PMInstance* inst, const PMVariable* v, double value, const char* function) {
    if (check_settable(inst, v, function) != fmi2OK) return fmi2Error;
    if (!isfinite(value)) {
        uc_log_status(&inst->log, fmi2Error, "%s: %s = %g is outside (-inf, inf): it must be a finite number",
                      function, v->name, value);
        return fmi2Error;
    }
    return fmi2OK;
}

static fmi2Status set_values(PMInstance* inst, const fmi2ValueReference vr[], size_t nvr, PMType type,
                             const fmi2Real* reals, const int* ints, const char* function) {
    if (check_arrays(inst, vr, nvr, type == PM_REAL ? (const void*)reals : (const void*)ints, function) != fmi2OK) {
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; ++i) {
        const PMVariable* v = find_variable(inst, vr[i], type, function);
        double value = type == PM_REAL ? reals[i] : type == PM_INTEGER ? (double)ints[i] : (ints[i] != fmi2False ? 1.0 : 0.0);
        if (v == NULL || check_number(inst, v, value, function) != fmi2OK) return fmi2Error;
        double* target = pm_value(inst, v);
        if (*target == value) continue;
        *target = value;
        if (inst->state != UC_STATE_STEP_COMPLETE) inst->ready = 0; /* the initialization depends on it */
    }
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
    GUARDED(c, UC_MASK_GET, "fmi2GetReal", get_values(inst, vr, nvr, PM_REAL, value, NULL, "fmi2GetReal"));
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[]) {
    GUARDED(c, UC_MASK_GET, "fmi2GetBoolean", get_values(inst, vr, nvr, PM_BOOLEAN, NULL, value, "fmi2GetBoolean"));
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    GUARDED(c, UC_MASK_SET, "fmi2SetReal", set_values(inst, vr, nvr, PM_REAL, value, NULL, "fmi2SetReal"));
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[]) {
    GUARDED(c, UC_MASK_SET, "fmi2SetBoolean", set_values(inst, vr, nvr, PM_BOOLEAN, NULL, value, "fmi2SetBoolean"));
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
    GUARDED(c, UC_MASK_GET, "fmi2GetInteger", get_values(inst, vr, nvr, PM_INTEGER, NULL, value, "fmi2GetInteger"));
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[]) {
    GUARDED(c, UC_MASK_SET, "fmi2SetInteger", set_values(inst, vr, nvr, PM_INTEGER, NULL, value, "fmi2SetInteger"));
}

static fmi2Status get_strings(PMInstance* inst, const fmi2ValueReference vr[], size_t nvr, fmi2String values[],
                              const char* function) {
    if (check_arrays(inst, vr, nvr, values, function) != fmi2OK) return fmi2Error;
    for (size_t i = 0; i < nvr; ++i) {
        const PMVariable* v = find_variable(inst, vr[i], PM_STRING, function);
        if (v == NULL) return fmi2Error;
        values[i] = pm_string(inst, v); /* the instance's copy: valid until the variable is set again */
    }
    return fmi2OK;
}

/* The instance's copy of one string (string_value.h): in the data, so that a saved state holds it. */
static fmi2Status store_string(PMInstance* inst, const PMVariable* v, const char* value, const char* function) {
    const int changed = uc_store_string(&inst->log, function, v->name, pm_string(inst, v), PM_STRING_CAPACITY, value);
    if (changed < 0) return fmi2Error;
    if (changed && inst->state != UC_STATE_STEP_COMPLETE) inst->ready = 0; /* the initialization depends on it */
    return fmi2OK;
}

static fmi2Status set_strings(PMInstance* inst, const fmi2ValueReference vr[], size_t nvr, const fmi2String values[],
                              const char* function) {
    if (check_arrays(inst, vr, nvr, values, function) != fmi2OK) return fmi2Error;
    for (size_t i = 0; i < nvr; ++i) {
        const PMVariable* v = find_variable(inst, vr[i], PM_STRING, function);
        if (v == NULL || check_settable(inst, v, function) != fmi2OK) return fmi2Error;
        if (store_string(inst, v, values[i], function) != fmi2OK) return fmi2Error;
    }
    return fmi2OK;
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[]) {
    GUARDED(c, UC_MASK_GET, "fmi2GetString", get_strings(inst, vr, nvr, value, "fmi2GetString"));
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[]) {
    GUARDED(c, UC_MASK_SET, "fmi2SetString", set_strings(inst, vr, nvr, value, "fmi2SetString"));
}

/* ---- FMU states: a byte copy of the adapter's time and machine state and of the model's data -------- */

#define PM_STATE_MAGIC "PMFMUST" /* 8 bytes with the NUL */
#define PM_GUID_FIELD_SIZE 64

typedef struct PMSavedState {
    char magic[8];
    int32_t machineState;
    int32_t ready;
    int32_t stopTimeDefined;
    double startTime, stopTime, time;
    unsigned char data[]; /* model->dataSize bytes */
} PMSavedState;

static PMSavedState* as_saved_state(PMInstance* inst, fmi2FMUstate state, const char* function) {
    PMSavedState* s = (PMSavedState*)state;
    if (s == NULL || memcmp(s->magic, PM_STATE_MAGIC, sizeof s->magic) != 0) {
        uc_log_status(&inst->log, fmi2Error, "%s: FMUstate is NULL or not a state of this FMU", function);
        return NULL;
    }
    return s;
}

static fmi2Status get_state(PMInstance* inst, fmi2FMUstate* state) {
    if (state == NULL) {
        uc_log_status(&inst->log, fmi2Error, "fmi2GetFMUstate: FMUstate is NULL");
        return fmi2Error;
    }
    PMSavedState* s = *state != NULL ? as_saved_state(inst, *state, "fmi2GetFMUstate")
                                     : calloc(1, sizeof(PMSavedState) + inst->model->dataSize);
    if (s == NULL) {
        if (*state == NULL) uc_log_status(&inst->log, fmi2Error, "fmi2GetFMUstate: out of memory");
        return fmi2Error;
    }
    memcpy(s->magic, PM_STATE_MAGIC, sizeof s->magic);
    s->machineState = (int32_t)inst->state;
    s->ready = inst->ready;
    s->stopTimeDefined = inst->stopTimeDefined;
    s->startTime = inst->startTime;
    s->stopTime = inst->stopTime;
    s->time = inst->time;
    memcpy(s->data, inst->data, inst->model->dataSize);
    *state = s;
    return fmi2OK;
}

static fmi2Status set_state(PMInstance* inst, fmi2FMUstate state) {
    const PMSavedState* s = as_saved_state(inst, state, "fmi2SetFMUstate");
    if (s == NULL) return fmi2Error;
    inst->state = (UCMachineState)s->machineState;
    inst->ready = s->ready;
    inst->stopTimeDefined = s->stopTimeDefined;
    inst->startTime = s->startTime;
    inst->stopTime = s->stopTime;
    inst->time = s->time;
    memcpy(inst->data, s->data, inst->model->dataSize);
    /* the derived data of the restored parameters (a state of another instance may have other ones) */
    if (inst->ready && pm_rebuild_derived(inst, "fmi2SetFMUstate") != fmi2OK) return fmi2Error;
    uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS, "fmi2SetFMUstate: restored state %s at t = %.17g",
           uc_state_name(inst->state), inst->time);
    return fmi2OK;
}

static fmi2Status free_state(PMInstance* inst, fmi2FMUstate* state) {
    if (state == NULL || *state == NULL) return fmi2OK;
    PMSavedState* s = as_saved_state(inst, *state, "fmi2FreeFMUstate");
    if (s == NULL) return fmi2Error;
    memset(s->magic, 0, sizeof s->magic);
    free(s);
    *state = NULL;
    return fmi2OK;
}

/* Serialized: magic, guid, data size, then the saved state as laid out in memory. */
static size_t serialized_size(const PMInstance* inst) {
    return 8 + PM_GUID_FIELD_SIZE + sizeof(uint64_t) + sizeof(PMSavedState) + inst->model->dataSize;
}

static fmi2Status serialized_state_size(PMInstance* inst, fmi2FMUstate state, size_t* size) {
    if (as_saved_state(inst, state, "fmi2SerializedFMUstateSize") == NULL) return fmi2Error;
    if (size == NULL) {
        uc_log_status(&inst->log, fmi2Error, "fmi2SerializedFMUstateSize: size is NULL");
        return fmi2Error;
    }
    *size = serialized_size(inst);
    return fmi2OK;
}

static fmi2Status serialize_state(PMInstance* inst, fmi2FMUstate state, fmi2Byte buffer[], size_t size) {
    const PMSavedState* s = as_saved_state(inst, state, "fmi2SerializeFMUstate");
    if (s == NULL) return fmi2Error;
    if (buffer == NULL || size < serialized_size(inst)) {
        uc_log_status(&inst->log, fmi2Error, "fmi2SerializeFMUstate: buffer of %zu bytes, %zu needed", size,
                      serialized_size(inst));
        return fmi2Error;
    }
    char guid[PM_GUID_FIELD_SIZE] = {0};
    strncpy(guid, PM_GUID, sizeof guid - 1);
    uint64_t dataSize = inst->model->dataSize;
    char* out = buffer;
    memcpy(out, PM_STATE_MAGIC, 8);
    memcpy(out += 8, guid, sizeof guid);
    memcpy(out += sizeof guid, &dataSize, sizeof dataSize);
    memcpy(out += sizeof dataSize, s, sizeof(PMSavedState) + inst->model->dataSize);
    return fmi2OK;
}

static fmi2Status deserialize_state(PMInstance* inst, const fmi2Byte buffer[], size_t size, fmi2FMUstate* state) {
    const char* function = "fmi2DeSerializeFMUstate";
    uint64_t dataSize = 0;
    char guid[PM_GUID_FIELD_SIZE];
    if (state == NULL || buffer == NULL || size != serialized_size(inst) || memcmp(buffer, PM_STATE_MAGIC, 8) != 0) {
        uc_log_status(&inst->log, fmi2Error, "%s: not a serialized state of this FMU (%zu bytes, %zu expected)",
                      function, size, serialized_size(inst));
        return fmi2Error;
    }
    memcpy(guid, buffer + 8, sizeof guid);
    guid[sizeof guid - 1] = '\0';
    memcpy(&dataSize, buffer + 8 + sizeof guid, sizeof dataSize);
    if (strcmp(guid, PM_GUID) != 0 || dataSize != inst->model->dataSize) {
        uc_log_status(&inst->log, fmi2Error, "%s: state of guid %s, this FMU is %s", function, guid, PM_GUID);
        return fmi2Error;
    }
    PMSavedState* s = malloc(sizeof(PMSavedState) + inst->model->dataSize);
    if (s == NULL) {
        uc_log_status(&inst->log, fmi2Error, "%s: out of memory", function);
        return fmi2Error;
    }
    memcpy(s, buffer + 8 + sizeof guid + sizeof dataSize, sizeof(PMSavedState) + inst->model->dataSize);
    if (memcmp(s->magic, PM_STATE_MAGIC, sizeof s->magic) != 0 || s->machineState < UC_STATE_INSTANTIATED ||
        s->machineState > UC_STATE_FATAL || (s->machineState & (s->machineState - 1)) != 0) {
        free(s);
        uc_log_status(&inst->log, fmi2Error, "%s: corrupt state", function);
        return fmi2Error;
    }
    *state = s;
    return fmi2OK;
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
    GUARDED(c, UC_MASK_FMU_STATE, "fmi2GetFMUstate", get_state(inst, FMUstate));
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
    GUARDED(c, UC_MASK_FMU_STATE, "fmi2SetFMUstate", set_state(inst, FMUstate));
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
    GUARDED(c, UC_MASK_FMU_STATE, "fmi2FreeFMUstate", free_state(inst, FMUstate));
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t* size) {
    GUARDED(c, UC_MASK_FMU_STATE, "fmi2SerializedFMUstateSize", serialized_state_size(inst, FMUstate, size));
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[], size_t size) {
    GUARDED(c, UC_MASK_FMU_STATE, "fmi2SerializeFMUstate", serialize_state(inst, FMUstate, serializedState, size));
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate* FMUstate) {
    GUARDED(c, UC_MASK_FMU_STATE, "fmi2DeSerializeFMUstate", deserialize_state(inst, serializedState, size, FMUstate));
}

/* ---- derivatives: not provided ------------------------------------------------------------------- */

static fmi2Status not_provided(PMInstance* inst, const char* function, const char* why) {
    uc_log_status(&inst->log, fmi2Error, "%s: not provided (%s)", function, why);
    return fmi2Error;
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[], size_t nUnknown,
                                        const fmi2ValueReference vKnown_ref[], size_t nKnown,
                                        const fmi2Real dvKnown[], fmi2Real dvUnknown[]) {
    (void)vUnknown_ref, (void)nUnknown, (void)vKnown_ref, (void)nKnown, (void)dvKnown, (void)dvUnknown;
    GUARDED(c, UC_MASK_DIRECTIONAL_DERIVATIVE, "fmi2GetDirectionalDerivative",
            not_provided(inst, "fmi2GetDirectionalDerivative", "providesDirectionalDerivative = false"));
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    (void)vr, (void)nvr, (void)order, (void)value;
    GUARDED(c, UC_MASK_INPUT_DERIVATIVES, "fmi2SetRealInputDerivatives",
            not_provided(inst, "fmi2SetRealInputDerivatives", "canInterpolateInputs = false"));
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[]) {
    (void)vr, (void)nvr, (void)order, (void)value;
    /* refused as not provided also in initialization mode, where the cable refuses it as a call sequence */
    GUARDED(c, UC_MASK_GET, "fmi2GetRealOutputDerivatives",
            not_provided(inst, "fmi2GetRealOutputDerivatives", "maxOutputDerivativeOrder = 0"));
}

/* ---- stepping ------------------------------------------------------------------------------------- */

static double time_tolerance(double t) { return PM_TIME_TOLERANCE * fmax(1.0, fabs(t)); }

static fmi2Status do_step(PMInstance* inst, double tc, double h) {
    if (!(fabs(tc - inst->time) <= time_tolerance(inst->time))) {
        uc_log_status(&inst->log, fmi2Error,
                      "fmi2DoStep: currentCommunicationPoint = %.17g but the FMU is at t = %.17g (tolerance %g)", tc,
                      inst->time, time_tolerance(inst->time));
        return fmi2Error;
    }
    if (!(h > 0.0) || !isfinite(h)) {
        uc_log_status(&inst->log, fmi2Error, "fmi2DoStep: communicationStepSize = %g must be positive and finite", h);
        return fmi2Error;
    }
    if (inst->stopTimeDefined && tc + h > inst->stopTime + time_tolerance(inst->stopTime)) {
        uc_log_status(&inst->log, fmi2Error, "fmi2DoStep: step to t = %.17g goes past stopTime = %.17g", tc + h,
                      inst->stopTime);
        return fmi2Error;
    }
    inst->msg[0] = '\0';
    /* The FMU's own time, not tc: the master's tc carries its round-off. */
    if (inst->model->do_step(inst->data, inst->derived, inst->time, h, inst->msg, sizeof inst->msg) != 0) {
        uc_log_status(&inst->log, fmi2Error, "fmi2DoStep: step from t = %.17g to %.17g failed: %s", inst->time,
                      inst->time + h, inst->msg);
        return fmi2Error;
    }
    inst->time += h;
    return fmi2OK;
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    (void)noSetFMUStatePriorToCurrentPoint;
    GUARDED(c, UC_MASK_DO_STEP, "fmi2DoStep", do_step(inst, currentCommunicationPoint, communicationStepSize));
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    /* fmi2DoStep is synchronous: there is never a step in progress to cancel. */
    GUARDED(c, UC_MASK_CANCEL_STEP, "fmi2CancelStep", fmi2OK);
}

/* ---- status --------------------------------------------------------------------------------------- */

static fmi2Status status_not_available(PMInstance* inst, const char* function, fmi2StatusKind kind) {
    uc_log_status(&inst->log, fmi2Discard, "%s: status kind %d is not available", function, (int)kind);
    return fmi2Discard;
}

static fmi2Status get_real_status(PMInstance* inst, fmi2StatusKind s, fmi2Real* value) {
    if (value == NULL) {
        uc_log_status(&inst->log, fmi2Error, "fmi2GetRealStatus: value is NULL");
        return fmi2Error;
    }
    if (s != fmi2LastSuccessfulTime) return status_not_available(inst, "fmi2GetRealStatus", s);
    *value = inst->time;
    return fmi2OK;
}

static fmi2Status get_boolean_status(PMInstance* inst, fmi2StatusKind s, fmi2Boolean* value) {
    if (value == NULL) {
        uc_log_status(&inst->log, fmi2Error, "fmi2GetBooleanStatus: value is NULL");
        return fmi2Error;
    }
    if (s != fmi2Terminated) return status_not_available(inst, "fmi2GetBooleanStatus", s);
    *value = fmi2False;
    return fmi2OK;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status* value) {
    (void)value;
    GUARDED(c, UC_MASK_GET_STATUS, "fmi2GetStatus", status_not_available(inst, "fmi2GetStatus", s));
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real* value) {
    GUARDED(c, UC_MASK_GET_STATUS, "fmi2GetRealStatus", get_real_status(inst, s, value));
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer* value) {
    (void)value;
    GUARDED(c, UC_MASK_GET_STATUS, "fmi2GetIntegerStatus", status_not_available(inst, "fmi2GetIntegerStatus", s));
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean* value) {
    GUARDED(c, UC_MASK_GET_STATUS, "fmi2GetBooleanStatus", get_boolean_status(inst, s, value));
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String* value) {
    (void)value;
    GUARDED(c, UC_MASK_GET_STATUS, "fmi2GetStringStatus", status_not_available(inst, "fmi2GetStringStatus", s));
}
