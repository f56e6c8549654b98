/*
 * fmi2Functions.c - the exported FMI 2.0 Co-Simulation functions. Each one checks the machine state
 * against the set of states it may be called in (FMI 2.0 section 4.2.4), delegates, and applies the
 * worst-status rule (an fmi2Error puts the instance into the error state): the state machine of
 * common/fmi2_machine.h, which the partner FMUs share.
 */
#include <math.h>
#include <string.h>

#include "fmi2Functions.h"
#include "instance.h"
#include "simulation.h"
#include "state_serialization.h"
#include "uc_guid.h"
#include "value_access.h"

/* Runs `body` (an expression yielding fmi2Status) if the instance may call `function` now. */
#define GUARDED(c, mask, function, body) UC_MACHINE_GUARDED(UCInstance, c, mask, function, body)

/* As GUARDED, for a call whose refusal (fmi2Error from `body`) changes nothing in the instance: a state to
 * restore that is refused (corrupted or truncated bytes, another version, an edited deck) leaves the
 * instance, its machine state included, as it was, so it goes on as if the call had not been made. An
 * illegal call sequence still puts it into the error state; `body` sets that state itself where its failure
 * did change the instance. */
#define REFUSABLE(c, mask, function, body)                                                                  \
    do {                                                                                                     \
        UCInstance* inst = (UCInstance*)(c);                                                                 \
        if (inst == NULL) return fmi2Error;                                                                  \
        fmi2Status status = uc_machine_check(&inst->log, inst->state, (mask), (function));                   \
        if (status != fmi2OK) return uc_machine_finish(&inst->state, status);                                \
        return (body);                                                                                       \
    } while (0)

/* ---- common functions ------------------------------------------------------------------------------- */

const char* fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }

const char* fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
    GUARDED(c, UC_MASK_SET_DEBUG_LOGGING, "fmi2SetDebugLogging",
            uc_log_configure(&inst->log, loggingOn, nCategories, categories));
}

static int reject_instantiation(const fmi2CallbackFunctions* functions, fmi2String instanceName,
                                const char* reason) {
    if (functions != NULL) {
        uc_log_raw(functions->logger, functions->componentEnvironment, instanceName, fmi2Error,
                   UC_LOG_STATUS_ERROR, reason);
    }
    return 1;
}

/* Non-zero (logged) if the arguments of fmi2Instantiate are not for this FMU. */
static int instantiation_rejected(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                                  const fmi2CallbackFunctions* functions) {
    if (functions == NULL || functions->logger == NULL) return 1; /* nobody to tell */
    if (instanceName == NULL || instanceName[0] == '\0') {
        return reject_instantiation(functions, instanceName, "fmi2Instantiate: instanceName is NULL or empty");
    }
    if (fmuType != fmi2CoSimulation) {
        return reject_instantiation(functions, instanceName,
                                    "fmi2Instantiate: fmuType must be fmi2CoSimulation (this FMU has no Model "
                                    "Exchange interface)");
    }
    if (fmuGUID == NULL || strcmp(fmuGUID, UC_GUID) != 0) {
        return reject_instantiation(functions, instanceName,
                                    "fmi2Instantiate: fmuGUID does not match the guid " UC_GUID
                                    " of this binary (modelDescription.xml from another build?)");
    }
    return 0;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions* functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn) {
    (void)visible; /* no user interface */
    if (instantiation_rejected(instanceName, fmuType, fmuGUID, functions)) return NULL;
    UCInstance* inst = uc_instance_new(instanceName, fmuResourceLocation, functions->logger,
                                       functions->componentEnvironment, loggingOn);
    if (inst == NULL) {
        reject_instantiation(functions, instanceName, "fmi2Instantiate: out of memory");
        return NULL;
    }
    uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS, "fmi2Instantiate: %s, guid %s, resources %s", instanceName, UC_GUID,
           fmuResourceLocation ? fmuResourceLocation : "(none)");
    return inst;
}

void fmi2FreeInstance(fmi2Component c) { uc_instance_free((UCInstance*)c); }

static fmi2Status setup_experiment(UCInstance* inst, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                                   fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    if (!isfinite(startTime) || (stopTimeDefined && !(stopTime >= startTime && isfinite(stopTime)))) {
        uc_log_status(&inst->log, fmi2Error,
                      "fmi2SetupExperiment: startTime = %g, stopTime = %g: need finite startTime <= stopTime",
                      startTime, stopTime);
        return fmi2Error;
    }
    if (toleranceDefined) {
        uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS,
               "fmi2SetupExperiment: tolerance %g not used; the integrator uses the parameters relTol and absTol",
               tolerance);
    }
    uc_instance_drop_core(inst);
    inst->startTime = startTime;
    inst->time = startTime;
    inst->lastSuccessfulTime = startTime;
    inst->stopTimeDefined = stopTimeDefined != fmi2False;
    inst->stopTime = stopTimeDefined ? stopTime : 0.0;
    return fmi2OK;
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    GUARDED(c, UC_MASK_SETUP_EXPERIMENT, "fmi2SetupExperiment",
            setup_experiment(inst, toleranceDefined, tolerance, startTime, stopTimeDefined, stopTime));
}

static fmi2Status enter_initialization_mode(UCInstance* inst) {
    uc_machine_enter_initialization(&inst->state);
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    GUARDED(c, UC_MASK_ENTER_INIT, "fmi2EnterInitializationMode", enter_initialization_mode(inst));
}

static fmi2Status exit_initialization_mode(UCInstance* inst) {
    return uc_machine_exit_initialization(&inst->state, uc_sim_ensure_initialized(inst, "fmi2ExitInitializationMode"));
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    GUARDED(c, UC_MASK_EXIT_INIT, "fmi2ExitInitializationMode", exit_initialization_mode(inst));
}

static fmi2Status terminate(UCInstance* inst) {
    uc_input_checks_summary(inst);
    uc_machine_terminate(&inst->state); /* the core is kept: values stay readable */
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) { GUARDED(c, UC_MASK_TERMINATE, "fmi2Terminate", terminate(inst)); }

static fmi2Status reset(UCInstance* inst) {
    uc_instance_reset(inst);
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) { GUARDED(c, UC_MASK_RESET, "fmi2Reset", reset(inst)); }

/* ---- getting and setting values -------------------------------------------------------------------- */

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
    GUARDED(c, UC_MASK_GET, "fmi2GetReal", uc_get_values(inst, vr, nvr, value, UC_TYPE_REAL, "fmi2GetReal"));
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
    GUARDED(c, UC_MASK_GET, "fmi2GetInteger",
            uc_get_values(inst, vr, nvr, value, UC_TYPE_INTEGER, "fmi2GetInteger"));
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[]) {
    GUARDED(c, UC_MASK_GET, "fmi2GetBoolean",
            uc_get_values(inst, vr, nvr, value, UC_TYPE_BOOLEAN, "fmi2GetBoolean"));
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[]) {
    GUARDED(c, UC_MASK_GET, "fmi2GetString", uc_get_strings(inst, vr, nvr, value, "fmi2GetString"));
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    GUARDED(c, UC_MASK_SET, "fmi2SetReal", uc_set_values(inst, vr, nvr, value, UC_TYPE_REAL, "fmi2SetReal"));
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[]) {
    GUARDED(c, UC_MASK_SET, "fmi2SetInteger",
            uc_set_values(inst, vr, nvr, value, UC_TYPE_INTEGER, "fmi2SetInteger"));
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[]) {
    GUARDED(c, UC_MASK_SET, "fmi2SetBoolean",
            uc_set_values(inst, vr, nvr, value, UC_TYPE_BOOLEAN, "fmi2SetBoolean"));
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[]) {
    GUARDED(c, UC_MASK_SET, "fmi2SetString", uc_set_strings(inst, vr, nvr, value, "fmi2SetString"));
}

/* ---- FMU states ----------------------------------------------------------------------------------- */

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
    GUARDED(c, UC_MASK_FMU_STATE, "fmi2GetFMUstate", uc_state_get(inst, FMUstate));
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
    REFUSABLE(c, UC_MASK_FMU_STATE, "fmi2SetFMUstate", uc_state_set(inst, FMUstate));
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
    GUARDED(c, UC_MASK_FMU_STATE, "fmi2FreeFMUstate", uc_state_free(inst, FMUstate));
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t* size) {
    GUARDED(c, UC_MASK_FMU_STATE, "fmi2SerializedFMUstateSize", uc_state_serialized_size(inst, FMUstate, size));
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[],
                                 size_t size) {
    GUARDED(c, UC_MASK_FMU_STATE, "fmi2SerializeFMUstate", uc_state_serialize(inst, FMUstate, serializedState, size));
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate* FMUstate) {
    REFUSABLE(c, UC_MASK_FMU_STATE, "fmi2DeSerializeFMUstate",
              uc_state_deserialize(inst, serializedState, size, FMUstate));
}

/* ---- derivatives ---------------------------------------------------------------------------------- */

static fmi2Status not_provided(UCInstance* inst, const char* function, const char* why) {
    uc_log_status(&inst->log, fmi2Error, "%s: not provided (%s)", function, why);
    return fmi2Error;
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[], size_t nUnknown,
                                        const fmi2ValueReference vKnown_ref[], size_t nKnown,
                                        const fmi2Real dvKnown[], fmi2Real dvUnknown[]) {
    GUARDED(c, UC_MASK_DIRECTIONAL_DERIVATIVE, "fmi2GetDirectionalDerivative",
            uc_get_directional_derivative(inst, vUnknown_ref, nUnknown, vKnown_ref, nKnown, dvKnown, dvUnknown));
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    GUARDED(c, UC_MASK_INPUT_DERIVATIVES, "fmi2SetRealInputDerivatives",
            uc_set_input_derivatives(inst, vr, nvr, order, value));
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[]) {
    (void)vr, (void)nvr, (void)order, (void)value;
    GUARDED(c, UC_MASK_OUTPUT_DERIVATIVES, "fmi2GetRealOutputDerivatives",
            not_provided(inst, "fmi2GetRealOutputDerivatives", "maxOutputDerivativeOrder = 0"));
}

/* ---- stepping ------------------------------------------------------------------------------------- */

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    (void)noSetFMUStatePriorToCurrentPoint; /* states are independent copies: nothing to release */
    GUARDED(c, UC_MASK_DO_STEP, "fmi2DoStep", uc_sim_do_step(inst, currentCommunicationPoint, communicationStepSize));
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    /* fmi2DoStep is synchronous, so there is never a step in progress to cancel. */
    GUARDED(c, UC_MASK_CANCEL_STEP, "fmi2CancelStep", fmi2OK);
}

/* ---- status --------------------------------------------------------------------------------------- */

static fmi2Status status_not_available(UCInstance* inst, const char* function, fmi2StatusKind kind) {
    uc_log_status(&inst->log, fmi2Discard, "%s: status kind %d is not available", function, (int)kind);
    return fmi2Discard;
}

static fmi2Status check_status_pointer(UCInstance* inst, const void* value, const char* function) {
    if (value != NULL) return fmi2OK;
    uc_log_status(&inst->log, fmi2Error, "%s: value is NULL", function);
    return fmi2Error;
}

static fmi2Status get_real_status(UCInstance* inst, fmi2StatusKind s, fmi2Real* value) {
    if (check_status_pointer(inst, value, "fmi2GetRealStatus") != fmi2OK) return fmi2Error;
    if (s != fmi2LastSuccessfulTime) return status_not_available(inst, "fmi2GetRealStatus", s);
    *value = inst->lastSuccessfulTime;
    return fmi2OK;
}

static fmi2Status get_boolean_status(UCInstance* inst, fmi2StatusKind s, fmi2Boolean* value) {
    if (check_status_pointer(inst, value, "fmi2GetBooleanStatus") != fmi2OK) return fmi2Error;
    if (s != fmi2Terminated) return status_not_available(inst, "fmi2GetBooleanStatus", s);
    *value = inst->terminateRequested ? fmi2True : fmi2False;
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
