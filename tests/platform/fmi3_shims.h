/*
 * fmi3_shims.h - for uc_fmu_driver_fmi3: the FMI 2.0 calls of fmu_driver.c carried out with the FMI 3.0
 * variant's functions, so both libraries run the same scenes. The outputs are read by FMI 3.0 variable: an
 * array's elements are FMI 2.0 scalars at the stride uc_fmi3_arrays.h gives.
 */
#include <stdbool.h>

#include "fmi3Types.h"
#include "uc_fmi3_arrays.h"

static struct {
    void* (*Instantiate)(fmi3String, fmi3String, fmi3String, fmi3Boolean, fmi3Boolean, fmi3Boolean, fmi3Boolean,
                         const fmi3ValueReference*, size_t, fmi3InstanceEnvironment, fmi3LogMessageCallback,
                         fmi3IntermediateUpdateCallback);
    void (*FreeInstance)(fmi3Instance);
    fmi3Status (*EnterInitializationMode)(fmi3Instance, fmi3Boolean, fmi3Float64, fmi3Float64, fmi3Boolean, fmi3Float64);
    fmi3Status (*ExitInitializationMode)(fmi3Instance);
    fmi3Status (*SetFloat64)(fmi3Instance, const fmi3ValueReference*, size_t, const fmi3Float64*, size_t);
    fmi3Status (*GetFloat64)(fmi3Instance, const fmi3ValueReference*, size_t, fmi3Float64*, size_t);
    fmi3Status (*SetInt32)(fmi3Instance, const fmi3ValueReference*, size_t, const fmi3Int32*, size_t);
    fmi3Status (*SetBoolean)(fmi3Instance, const fmi3ValueReference*, size_t, const fmi3Boolean*, size_t);
    fmi3Status (*SetString)(fmi3Instance, const fmi3ValueReference*, size_t, const fmi3String*, size_t);
    fmi3Status (*DoStep)(fmi3Instance, fmi3Float64, fmi3Float64, fmi3Boolean, fmi3Boolean*, fmi3Boolean*, fmi3Boolean*,
                         fmi3Float64*);
    fmi3Status (*GetFMUState)(fmi3Instance, fmi3FMUState*);
    fmi3Status (*SetFMUState)(fmi3Instance, fmi3FMUState);
    fmi3Status (*FreeFMUState)(fmi3Instance, fmi3FMUState*);
    fmi3Status (*SerializedFMUStateSize)(fmi3Instance, fmi3FMUState, size_t*);
    fmi3Status (*SerializeFMUState)(fmi3Instance, fmi3FMUState, fmi3Byte*, size_t);
    fmi3Status (*DeserializeFMUState)(fmi3Instance, const fmi3Byte*, size_t, fmi3FMUState*);
    double startTime, stopTime;
    int stopTimeDefined;
} fmi3;

static void log3(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message) {
    (void)env;
    if (status != fmi3OK) fprintf(stderr, "[cable %s %d] %s\n", category, (int)status, message);
}

static fmi2Component shim_instantiate(fmi2String name, fmi2Type type, fmi2String token, fmi2String uri,
                                      const fmi2CallbackFunctions* callbacks, fmi2Boolean visible, fmi2Boolean loggingOn) {
    (void)type, (void)uri, (void)callbacks;
    return fmi3.Instantiate(name, token, NULL, visible, loggingOn, false, false, NULL, 0, NULL, log3, NULL);
}
static void shim_free_instance(fmi2Component c) { fmi3.FreeInstance(c); }
static fmi2Status shim_setup_experiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                                        fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    (void)c, (void)toleranceDefined, (void)tolerance;
    fmi3.startTime = startTime;
    fmi3.stopTimeDefined = stopTimeDefined;
    fmi3.stopTime = stopTime;
    return fmi2OK;
}
static fmi2Status shim_enter_initialization_mode(fmi2Component c) {
    return (fmi2Status)fmi3.EnterInitializationMode(c, false, 0.0, fmi3.startTime, fmi3.stopTimeDefined, fmi3.stopTime);
}
static fmi2Status shim_exit_initialization_mode(fmi2Component c) { return (fmi2Status)fmi3.ExitInitializationMode(c); }
static fmi2Status shim_set_integer(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer v[]) {
    return (fmi2Status)fmi3.SetInt32(c, vr, n, v, n);
}
static fmi2Status shim_set_boolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Boolean v[]) {
    fmi3Boolean b[16];
    if (n > 16) return fmi2Error;
    for (size_t k = 0; k < n; ++k) b[k] = v[k] != fmi2False;
    return (fmi2Status)fmi3.SetBoolean(c, vr, n, b, n);
}
static fmi2Status shim_set_string(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2String v[]) {
    return (fmi2Status)fmi3.SetString(c, vr, n, v, n);
}
/* Whether vr is one of the count scalars from `from` at `stride`, and then its element's index (offset + its
 * position there). */
static int shim_part(fmi2ValueReference vr, fmi2ValueReference from, size_t count, fmi2ValueReference stride,
                     size_t offset, size_t* index) {
    if (count == 0 || vr < from || vr >= from + count * stride || (vr - from) % stride != 0) return 0;
    *index = offset + (vr - from) / stride;
    return 1;
}
/* The FMI 3.0 array (its first value reference and length) that holds the FMI 2.0 scalar vr as element
 * *index (its first `kept` elements from its value reference, the others from the extension); 0 for a
 * scalar. */
static int array_element(fmi2ValueReference vr, fmi3ValueReference* first, size_t* count, size_t* index) {
#define UC_SHIM_ELEMENT(f, n, stride, name, kept, ext, sizedBy, perIndex)                                   \
    if (shim_part(vr, (f), (kept), (stride), 0, index) ||                                                  \
        shim_part(vr, (ext), (size_t)(n) - (size_t)(kept), (stride), (kept), index)) {                     \
        *first = (f);                                                                                      \
        *count = (n);                                                                                      \
        return 1;                                                                                          \
    }
    UC_FMI3_ARRAYS(UC_SHIM_ELEMENT)
#undef UC_SHIM_ELEMENT
    return 0;
}
/* The FMI 2.0 scalars read through the FMI 3.0 variables that hold them: a scalar as it is, an element from
 * its array (read once while the next scalars are elements of the same array). */
static fmi2Status shim_get_real(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real v[]) {
    fmi3Float64 array[UC_FMI3_MAX_ELEMENTS];
    fmi3ValueReference cached = 0, first;
    size_t count, index;
    fmi3Status worst = fmi3OK;
    for (size_t k = 0; k < n; ++k) {
        fmi3Status status = fmi3OK;
        if (!array_element(vr[k], &first, &count, &index)) {
            status = fmi3.GetFloat64(c, &vr[k], 1, &v[k], 1);
        } else {
            if (first != cached) {
                status = fmi3.GetFloat64(c, &first, 1, array, count);
                cached = status <= fmi3Warning ? first : 0;
            }
            v[k] = array[index];
        }
        if (status > worst) worst = status;
        if (worst > fmi3Warning) break;
    }
    return (fmi2Status)worst;
}
/* An element of an array is set with the array's other elements as they are. */
static fmi2Status shim_set_real(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real v[]) {
    fmi3Float64 array[UC_FMI3_MAX_ELEMENTS];
    fmi3ValueReference first;
    size_t count, index;
    for (size_t k = 0; k < n; ++k) {
        fmi3Status status;
        if (!array_element(vr[k], &first, &count, &index)) {
            status = fmi3.SetFloat64(c, &vr[k], 1, &v[k], 1);
        } else {
            status = fmi3.GetFloat64(c, &first, 1, array, count);
            array[index] = v[k];
            if (status <= fmi3Warning) status = fmi3.SetFloat64(c, &first, 1, array, count);
        }
        if (status > fmi3Warning) return (fmi2Status)status;
    }
    return fmi2OK;
}
static fmi2Status shim_set_input_derivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                             const fmi2Integer order[], const fmi2Real v[]) {
    (void)c, (void)vr, (void)n, (void)order, (void)v; /* FMI 3.0 co-simulation has none */
    return fmi2OK;
}
static fmi2Status shim_do_step(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean noSetPrior) {
    fmi3Boolean event = false, terminate = false, early = false;
    fmi3Float64 last = 0.0;
    return (fmi2Status)fmi3.DoStep(c, t, h, noSetPrior, &event, &terminate, &early, &last);
}
static fmi2Status shim_get_state(fmi2Component c, fmi2FMUstate* s) { return (fmi2Status)fmi3.GetFMUState(c, s); }
static fmi2Status shim_set_state(fmi2Component c, fmi2FMUstate s) { return (fmi2Status)fmi3.SetFMUState(c, s); }
static fmi2Status shim_free_state(fmi2Component c, fmi2FMUstate* s) { return (fmi2Status)fmi3.FreeFMUState(c, s); }
static fmi2Status shim_state_size(fmi2Component c, fmi2FMUstate s, size_t* size) {
    return (fmi2Status)fmi3.SerializedFMUStateSize(c, s, size);
}
static fmi2Status shim_serialize(fmi2Component c, fmi2FMUstate s, fmi2Byte bytes[], size_t size) {
    return (fmi2Status)fmi3.SerializeFMUState(c, s, (fmi3Byte*)bytes, size);
}
static fmi2Status shim_deserialize(fmi2Component c, const fmi2Byte bytes[], size_t size, fmi2FMUstate* s) {
    return (fmi2Status)fmi3.DeserializeFMUState(c, (const fmi3Byte*)bytes, size, s);
}

static void load_api(Library lib, Api* api) {
#define UC_LOAD3(f) *(void**)&fmi3.f = require(lib, "fmi3" #f);
    *(void**)&fmi3.Instantiate = require(lib, "fmi3InstantiateCoSimulation");
    UC_LOAD3(FreeInstance) UC_LOAD3(EnterInitializationMode) UC_LOAD3(ExitInitializationMode)
    UC_LOAD3(SetFloat64) UC_LOAD3(GetFloat64) UC_LOAD3(SetInt32) UC_LOAD3(SetBoolean) UC_LOAD3(SetString)
    UC_LOAD3(DoStep) UC_LOAD3(GetFMUState) UC_LOAD3(SetFMUState) UC_LOAD3(FreeFMUState)
    UC_LOAD3(SerializedFMUStateSize) UC_LOAD3(SerializeFMUState) UC_LOAD3(DeserializeFMUState)
#undef UC_LOAD3
    api->Instantiate = shim_instantiate;
    api->FreeInstance = shim_free_instance;
    api->SetupExperiment = shim_setup_experiment;
    api->EnterInitializationMode = shim_enter_initialization_mode;
    api->ExitInitializationMode = shim_exit_initialization_mode;
    api->SetReal = shim_set_real;
    api->SetInteger = shim_set_integer;
    api->SetBoolean = shim_set_boolean;
    api->SetString = shim_set_string;
    api->GetReal = shim_get_real;
    api->SetRealInputDerivatives = shim_set_input_derivatives;
    api->DoStep = shim_do_step;
    api->GetFMUstate = shim_get_state;
    api->SetFMUstate = shim_set_state;
    api->FreeFMUstate = shim_free_state;
    api->SerializedFMUstateSize = shim_state_size;
    api->SerializeFMUstate = shim_serialize;
    api->DeSerializeFMUstate = shim_deserialize;
}
