/* value_access.c - see value_access.h. */
#include "value_access.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "simulation.h"
#include "string_value.h"

static const UCVariable* find_or_log(UCInstance* inst, fmi2ValueReference vr, UCVarType type,
                                     const char* function) {
    const UCVariable* v = uc_variable_find(vr, type);
    if (v != NULL) return v;
    /* A value reference of another type: say which variable it is and which call it needs. */
    static const UCVarType types[4] = {UC_TYPE_REAL, UC_TYPE_INTEGER, UC_TYPE_BOOLEAN, UC_TYPE_STRING};
    for (int k = 0; k < 4; ++k) {
        const UCVariable* other = types[k] == type ? NULL : uc_variable_find(vr, types[k]);
        if (other != NULL) {
            const int getter = strncmp(function, "fmi2Get", 7) == 0;
            uc_log_status(&inst->log, fmi2Error, "%s: %s (value reference %u) is a%s %s variable: use fmi2%s%s",
                          function, other->name, vr, types[k] == UC_TYPE_INTEGER ? "n" : "", uc_type_name(types[k]),
                          getter ? "Get" : "Set", uc_type_name(types[k]));
            return NULL;
        }
    }
    uc_log_status(&inst->log, fmi2Error, "%s: unknown value reference %u (no %s variable and no variable of another "
                  "type has it)", function, vr, uc_type_name(type));
    return NULL;
}

static fmi2Status check_arrays(UCInstance* inst, const void* vr, size_t nvr, const void* values,
                               const char* function) {
    if (nvr > 0 && (vr == NULL || values == NULL)) {
        uc_log_status(&inst->log, fmi2Error, "%s: vr or value is NULL with nvr = %zu", function, nvr);
        return fmi2Error;
    }
    return fmi2OK;
}

static size_t value_size(UCVarType type) { return type == UC_TYPE_REAL ? sizeof(fmi2Real) : sizeof(fmi2Integer); }

/* Outputs during initialization mode are the InitialUnknowns: compute the initialization on demand, once per
 * call (provisional outputs and fmi2Warning while the values set so far give none: uc_sim_initial_outputs). */
static fmi2Status ensure_readable(UCInstance* inst, const UCVariable* v, const char* function, int* checked) {
    if (v->causality != UC_CAUSALITY_OUTPUT || inst->state != UC_STATE_INIT_MODE) return fmi2OK;
    if (*checked) return fmi2OK;
    *checked = 1;
    return uc_sim_initial_outputs(inst, function);
}

/* body[k].stiffness is computed when it is read, at the first read after a step (docs/systems_mooring.md,
 * "Mooring stiffness": a fifth of a step's cost). */
static int is_stiffness(const UCVariable* v) {
    if (v->causality != UC_CAUSALITY_OUTPUT) return 0;
    for (size_t b = 0; b < UC_MAX_BODIES; ++b) {
        const size_t first = offsetof(UCOutputs, bodyLoad) + b * sizeof(UCBodyLoad) + offsetof(UCBodyLoad, stiffness);
        if (v->offset >= first && v->offset < first + sizeof(((UCBodyLoad*)0)->stiffness)) return 1;
    }
    return 0;
}

static fmi2Status ensure_stiffness(UCInstance* inst, const UCVariable* v, const char* function, int* done) {
    if (*done || !is_stiffness(v) || !inst->coreReady || inst->cable == NULL) return fmi2OK;
    *done = 1;
    if (uc_update_stiffness(inst->cable, &inst->outputs, inst->msg, sizeof inst->msg) != 0) {
        uc_log_status(&inst->log, fmi2Error, "%s: body stiffness: %s", function, inst->msg);
        return fmi2Error;
    }
    if (uc_take_event(inst->cable, inst->msg, sizeof inst->msg)) {
        uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS, "%s: %s", function, inst->msg);
    }
    return fmi2OK;
}

fmi2Status uc_get_values(UCInstance* inst, const fmi2ValueReference vr[], size_t nvr, void* values, UCVarType type,
                         const char* function) {
    if (check_arrays(inst, vr, nvr, values, function) != fmi2OK) return fmi2Error;
    fmi2Status status = fmi2OK;
    int checked = 0, stiffness = 0;
    for (size_t i = 0; i < nvr; ++i) {
        const UCVariable* v = find_or_log(inst, vr[i], type, function);
        if (v == NULL) return fmi2Error;
        const fmi2Status readable = ensure_readable(inst, v, function, &checked);
        if (readable != fmi2OK && readable != fmi2Warning) return readable;
        if (readable == fmi2Warning) status = fmi2Warning;
        if (ensure_stiffness(inst, v, function, &stiffness) != fmi2OK) return fmi2Error;
        memcpy((char*)values + i * value_size(type),
               uc_variable_address_const(v, &inst->params, &inst->inputs, &inst->outputs), value_size(type));
    }
    return status;
}

static fmi2Status check_settable(UCInstance* inst, const UCVariable* v, const char* function) {
    if (v->causality == UC_CAUSALITY_OUTPUT) {
        uc_log_status(&inst->log, fmi2Error, "%s: %s is an output and cannot be set", function, v->name);
        return fmi2Error;
    }
    if (v->causality == UC_CAUSALITY_PARAMETER && inst->state == UC_STATE_STEP_COMPLETE) {
        uc_log_status(&inst->log, fmi2Error,
                      "%s: %s is a fixed parameter and cannot be changed after initialization", function, v->name);
        return fmi2Error;
    }
    return fmi2OK;
}

static fmi2Status check_real_value(UCInstance* inst, const UCVariable* v, double value, const char* function) {
    if (isfinite(value)) return fmi2OK;
    uc_log_status(&inst->log, fmi2Error, "%s: %s = %g is outside (-inf, inf): it must be a finite number", function,
                  v->name, value);
    return fmi2Error;
}

/* Component 0..2 if offset lies in the double[3] at base, else -1. */
static int component_of(size_t offset, size_t base) {
    if (offset < base || offset >= base + 3 * sizeof(double)) return -1;
    return (int)((offset - base) / sizeof(double));
}

/* Component c of an acceleration of a driven end is given for the coming step, by fmi2SetRealInputDerivatives
 * (asInput 0) or by setting the input tow.a* / end.a* (asInput 1: UC_ACCELERATION_AS_INPUT); before
 * initialization that changes the initialization (the first step's end). */
static void mark_acceleration_given(UCInstance* inst, int* given, int c, int asInput) {
    const int before = *given;
    *given = asInput ? (before | 1 | UC_ACCELERATION_AS_INPUT(c)) : ((before | 1) & ~UC_ACCELERATION_AS_INPUT(c));
    if (before == 0 && inst->state != UC_STATE_STEP_COMPLETE) uc_instance_drop_core(inst);
}

/* The flag of the acceleration input v stores into and its component *c, or NULL for any other variable. */
static int* acceleration_flag(UCInstance* inst, const UCVariable* v, int* c) {
    if (v->causality != UC_CAUSALITY_INPUT) return NULL;
    if ((*c = component_of(v->offset, offsetof(UCInputs, towAcceleration))) >= 0) return &inst->inputs.towAccelerationGiven;
    if ((*c = component_of(v->offset, offsetof(UCInputs, endAcceleration))) >= 0) return &inst->inputs.endAccelerationGiven;
    return NULL;
}

/* Stores one value; a changed parameter or input before initialization invalidates the cached one. */
static void store_value(UCInstance* inst, const UCVariable* v, const void* value) {
    void* target = uc_variable_address(v, &inst->params, &inst->inputs, &inst->outputs);
    if (memcmp(target, value, value_size(v->type)) == 0) return;
    memcpy(target, value, value_size(v->type));
    if (inst->state != UC_STATE_STEP_COMPLETE) uc_instance_drop_core(inst);
}

/* A setter validates every value before it writes any (a refusal changes nothing, FMI 2.0 section 2.1.3):
 * the variable, whether it may be set now, and the value. NULL (logged) if value i may not be stored. */
static const UCVariable* validated(UCInstance* inst, fmi2ValueReference vr, UCVarType type, const void* value,
                                   const char* function) {
    const UCVariable* v = find_or_log(inst, vr, type, function);
    if (v == NULL || check_settable(inst, v, function) != fmi2OK) return NULL;
    if (type == UC_TYPE_REAL && check_real_value(inst, v, *(const fmi2Real*)value, function) != fmi2OK) return NULL;
    if (type == UC_TYPE_STRING && uc_string_fits(&inst->log, function, v->name, v->size, value) != 0) return NULL;
    return v;
}

fmi2Status uc_set_values(UCInstance* inst, const fmi2ValueReference vr[], size_t nvr, const void* values,
                         UCVarType type, const char* function) {
    if (check_arrays(inst, vr, nvr, values, function) != fmi2OK) return fmi2Error;
    for (size_t i = 0; i < nvr; ++i) {
        if (validated(inst, vr[i], type, (const char*)values + i * value_size(type), function) == NULL)
            return fmi2Error;
    }
    for (size_t i = 0; i < nvr; ++i) {
        const void* value = (const char*)values + i * value_size(type);
        const UCVariable* v = uc_variable_find(vr[i], type);
        uc_instance_mark_set(inst, v);
        if (type == UC_TYPE_REAL) {
            store_value(inst, v, value);
            int c;
            int* given = acceleration_flag(inst, v, &c);
            if (given != NULL) mark_acceleration_given(inst, given, c, 1);
        } else if (type == UC_TYPE_BOOLEAN) {
            fmi2Integer normalized = *(const fmi2Boolean*)value != fmi2False; /* any non-zero is true */
            store_value(inst, v, &normalized);
        } else {
            store_value(inst, v, value);
        }
    }
    return fmi2OK;
}

fmi2Status uc_get_strings(UCInstance* inst, const fmi2ValueReference vr[], size_t nvr, fmi2String values[],
                          const char* function) {
    if (check_arrays(inst, vr, nvr, values, function) != fmi2OK) return fmi2Error;
    for (size_t i = 0; i < nvr; ++i) {
        const UCVariable* v = find_or_log(inst, vr[i], UC_TYPE_STRING, function);
        if (v == NULL) return fmi2Error;
        /* The instance owns the characters; they stay valid until the variable is set again. */
        values[i] = (const char*)uc_variable_address_const(v, &inst->params, &inst->inputs, &inst->outputs);
    }
    return fmi2OK;
}

/* The instance's copy of one string (string_value.h); a changed parameter drops the core built from it. */
static void store_string(UCInstance* inst, const UCVariable* v, const char* value, const char* function) {
    char* target = (char*)uc_variable_address(v, &inst->params, &inst->inputs, &inst->outputs);
    const int changed = uc_store_string(&inst->log, function, v->name, target, v->size, value);
    if (changed > 0 && inst->state != UC_STATE_STEP_COMPLETE) uc_instance_drop_core(inst);
}

fmi2Status uc_set_strings(UCInstance* inst, const fmi2ValueReference vr[], size_t nvr, const fmi2String values[],
                          const char* function) {
    if (check_arrays(inst, vr, nvr, values, function) != fmi2OK) return fmi2Error;
    for (size_t i = 0; i < nvr; ++i)
        if (validated(inst, vr[i], UC_TYPE_STRING, values[i], function) == NULL) return fmi2Error;
    for (size_t i = 0; i < nvr; ++i) {
        const UCVariable* v = uc_variable_find(vr[i], UC_TYPE_STRING);
        uc_instance_mark_set(inst, v);
        store_string(inst, v, values[i], function);
    }
    return fmi2OK;
}

/* A mooring system's body or point input: der(body[k].v*) (order 1) or der(body[k].x/y/z, 2) is the
 * reference point's acceleration, der(body[k].w*) the angular acceleration; der(point[k].v*) or of its
 * position (order 2) the point's acceleration. Where the value goes (NULL if v is none of them); `given`
 * the flag it sets. */
static double* body_derivative_target(UCInstance* inst, const UCVariable* v, int order, int** given) {
    const size_t bodies = offsetof(UCInputs, coupledBody), points = offsetof(UCInputs, coupledPoint);
    if (v->offset >= bodies && v->offset < bodies + sizeof inst->inputs.coupledBody) {
        const size_t k = (v->offset - bodies) / sizeof(UCCoupledBody), in = (v->offset - bodies) % sizeof(UCCoupledBody);
        const int c = (int)((in % (3 * sizeof(double))) / sizeof(double));
        const int linear = (order == 1 && in / (3 * sizeof(double)) == offsetof(UCCoupledBody, velocity) / (3 * sizeof(double))) ||
                           (order == 2 && in < 3 * sizeof(double));
        const int angular = order == 1 && in >= offsetof(UCCoupledBody, angularVelocity) &&
                            in < offsetof(UCCoupledBody, angularVelocity) + sizeof(double[3]);
        if (!linear && !angular) return NULL;
        *given = &inst->inputs.bodyAccelerationGiven[k];
        return &inst->inputs.bodyAcceleration[6 * k + (angular ? 3 : 0) + c];
    }
    if (v->offset >= points && v->offset < points + sizeof inst->inputs.coupledPoint) {
        const size_t k = (v->offset - points) / sizeof(UCCoupledPoint), in = (v->offset - points) % sizeof(UCCoupledPoint);
        const int velocity = in >= offsetof(UCCoupledPoint, velocity);
        if (!((velocity && order == 1) || (!velocity && order == 2))) return NULL;
        *given = &inst->inputs.pointAccelerationGiven[k];
        return &inst->inputs.pointAcceleration[3 * k + (int)((in % (3 * sizeof(double))) / sizeof(double))];
    }
    return NULL;
}

/* Where a derivative of `order` of the input v is kept: *target and the flag *given it sets (*given NULL: no
 * flag; *target NULL: accepted and ignored, the input held over the step). fmi2Error (logged) if it is refused. */
static fmi2Status derivative_target(UCInstance* inst, const UCVariable* v, int order, double value, double** target,
                                    int** given) {
    const char* function = "fmi2SetRealInputDerivatives";
    const int velocity = component_of(v->offset, offsetof(UCInputs, towVelocity));
    const int position = component_of(v->offset, offsetof(UCInputs, tow));
    const int endVelocity = component_of(v->offset, offsetof(UCInputs, endVelocity));
    const int endPosition = component_of(v->offset, offsetof(UCInputs, end));
    *target = NULL;
    *given = NULL;
    if (v->causality != UC_CAUSALITY_INPUT) {
        uc_log_status(&inst->log, fmi2Error, "%s: %s is not an input", function, v->name);
        return fmi2Error;
    }
    if (check_real_value(inst, v, value, function) != fmi2OK) return fmi2Error;
    if ((velocity >= 0 && order == 1) || (position >= 0 && order == 2)) {
        *target = &inst->inputs.towAcceleration[velocity >= 0 ? velocity : position];
        *given = &inst->inputs.towAccelerationGiven;
    } else if (order == 1 && v->offset >= offsetof(UCInputs, current) &&
               v->offset < offsetof(UCInputs, current) + sizeof inst->inputs.current) {
        *target = &inst->inputs.currentRate[(v->offset - offsetof(UCInputs, current)) / sizeof(double)];
    } else if (order == 1 && v->offset == offsetof(UCInputs, currentScale)) {
        *target = &inst->inputs.currentScaleRate;
    } else if (order == 1 && v->offset == offsetof(UCInputs, winchRate)) {
        *target = &inst->inputs.winchRateRate;
    } else if ((endVelocity >= 0 && order == 1) || (endPosition >= 0 && order == 2)) {
        *target = &inst->inputs.endAcceleration[endVelocity >= 0 ? endVelocity : endPosition];
        *given = &inst->inputs.endAccelerationGiven;
    } else if ((*target = body_derivative_target(inst, v, order, given)) == NULL && order != 1) {
        uc_log_status(&inst->log, fmi2Error,
                      "%s: derivative of order %d of %s is not supported (order 1 of tow.vx/vy/vz, order 2 of "
                      "tow.x/y/z, order 1 of other inputs)",
                      function, order, v->name);
        return fmi2Error;
    }
    return fmi2OK;
}

fmi2Status uc_set_input_derivatives(UCInstance* inst, const fmi2ValueReference vr[], size_t nvr,
                                    const fmi2Integer order[], const fmi2Real values[]) {
    const char* function = "fmi2SetRealInputDerivatives";
    if (check_arrays(inst, vr, nvr, values, function) != fmi2OK ||
        check_arrays(inst, vr, nvr, order, function) != fmi2OK) {
        return fmi2Error;
    }
    double* target;
    int* given;
    for (size_t i = 0; i < nvr; ++i) { /* every derivative is checked before any is kept */
        const UCVariable* v = find_or_log(inst, vr[i], UC_TYPE_REAL, function);
        if (v == NULL || derivative_target(inst, v, order[i], values[i], &target, &given) != fmi2OK) return fmi2Error;
    }
    for (size_t i = 0; i < nvr; ++i) {
        const UCVariable* v = uc_variable_find(vr[i], UC_TYPE_REAL);
        derivative_target(inst, v, order[i], values[i], &target, &given);
        if (target == NULL) {
            uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS, "%s: derivative of %s ignored (held constant over a step%s)",
                   function, v->name,
                   component_of(v->offset, offsetof(UCInputs, tow)) >= 0 ? "; the tow velocity is the input tow.v*" : "");
            continue;
        }
        *target = values[i];
        if (given == &inst->inputs.towAccelerationGiven) {
            mark_acceleration_given(inst, given, (int)(target - inst->inputs.towAcceleration), 0);
        } else if (given == &inst->inputs.endAccelerationGiven) {
            mark_acceleration_given(inst, given, (int)(target - inst->inputs.endAcceleration), 0);
        } else if (given != NULL) {
            *given = 1;
        }
    }
    return fmi2OK;
}

/* Index of name in names[count], or -1. */
static int name_index(const char* name, const char* const names[], int count) {
    for (int i = 0; i < count; ++i)
        if (strcmp(name, names[i]) == 0) return i;
    return -1;
}

/* The position of the variable vr among names[count] (the interface variables of the derivatives),
 * or -1 with a message naming it: "no derivative <relation> <name> (derivatives are provided <which>)". */
static int interface_index(UCInstance* inst, fmi2ValueReference vr, const char* const names[], int count,
                           const char* relation, const char* which) {
    const char* function = "fmi2GetDirectionalDerivative";
    const UCVariable* v = find_or_log(inst, vr, UC_TYPE_REAL, function);
    if (v == NULL) return -1;
    const int index = name_index(v->name, names, count);
    if (index < 0) {
        uc_log_status(&inst->log, fmi2Error, "%s: no derivative %s %s (derivatives are provided %s)", function,
                      relation, v->name, which);
    }
    return index;
}

/* dvUnknown = d[rows, cols] dvKnown for the 6 x UC_BODY_DERIVATIVE_INPUTS matrix d (row-major). */
static void seeded_product(const double d[6 * UC_BODY_DERIVATIVE_INPUTS], const int rows[], size_t nUnknown,
                           const int cols[], size_t nKnown, const fmi2Real dvKnown[], fmi2Real dvUnknown[]) {
    for (size_t i = 0; i < nUnknown; ++i) {
        double sum = 0.0;
        for (size_t j = 0; j < nKnown; ++j) sum += d[UC_BODY_DERIVATIVE_INPUTS * rows[i] + cols[j]] * dvKnown[j];
        dvUnknown[i] = sum;
    }
}

/* The index of the variable vr among body[k].<names[i]> and its body k (0 and a logged error if it is none). */
static int body_index(UCInstance* inst, fmi2ValueReference vr, const char* const names[], int count, int* body,
                      const char* which) {
    const char* function = "fmi2GetDirectionalDerivative";
    const UCVariable* v = find_or_log(inst, vr, UC_TYPE_REAL, function);
    if (v == NULL) return -1;
    int k = 0, consumed = 0;
    if (sscanf(v->name, "body[%d].%n", &k, &consumed) == 1 && consumed > 0) {
        const int index = name_index(v->name + consumed, names, count);
        if (index >= 0 && (*body == 0 || *body == k)) {
            *body = k;
            return index;
        }
    }
    uc_log_status(&inst->log, fmi2Error, "%s: no derivative involving %s (a mooring system provides %s, of one body "
                  "per call)", function, v->name, which);
    return -1;
}

/* A mooring system: d body[k].force/moment (t + h) / d body[k].* inputs (t) (uc_body_derivatives). */
static fmi2Status body_directional_derivative(UCInstance* inst, const fmi2ValueReference unknown[], size_t nUnknown,
                                              const fmi2ValueReference known[], size_t nKnown,
                                              const fmi2Real dvKnown[], fmi2Real dvUnknown[]) {
    static const char* const outputs[6] = {"force.x", "force.y", "force.z", "moment.x", "moment.y", "moment.z"};
    static const char* const inputs[UC_BODY_DERIVATIVE_INPUTS] = {"x",  "y",  "z",  "roll", "pitch", "yaw",
                                                                  "vx", "vy", "vz", "wx",   "wy",    "wz",
                                                                  "q0", "q1", "q2", "q3"};
    const char* which = "body[k].force.x/y/z and body[k].moment.x/y/z with respect to body[k].x/y/z, "
                        "roll/pitch/yaw, vx/vy/vz, wx/wy/wz and q0/q1/q2/q3";
    const char* function = "fmi2GetDirectionalDerivative";
    int rows[6], cols[UC_BODY_DERIVATIVE_INPUTS], body = 0;
    if (nUnknown > 6 || nKnown > UC_BODY_DERIVATIVE_INPUTS) {
        uc_log_status(&inst->log, fmi2Error, "%s: at most 6 unknowns and %d knowns per call (%s)", function,
                      UC_BODY_DERIVATIVE_INPUTS, which);
        return fmi2Error;
    }
    for (size_t i = 0; i < nUnknown; ++i) {
        rows[i] = body_index(inst, unknown[i], outputs, 6, &body, which);
        if (rows[i] < 0) return fmi2Error;
    }
    for (size_t j = 0; j < nKnown; ++j) {
        cols[j] = body_index(inst, known[j], inputs, UC_BODY_DERIVATIVE_INPUTS, &body, which);
        if (cols[j] < 0) return fmi2Error;
        if (!isfinite(dvKnown[j])) {
            uc_log_status(&inst->log, fmi2Error, "%s: the seed of body[%d].%s is not a finite number", function, body,
                          inputs[cols[j]]);
            return fmi2Error;
        }
    }
    double d[6 * UC_BODY_DERIVATIVE_INPUTS];
    if (body > 0 && uc_body_derivatives(inst->cable, body, d, inst->msg, sizeof inst->msg) != 0) {
        uc_log_status(&inst->log, fmi2Error, "%s: %s", function, inst->msg);
        return fmi2Error;
    }
    seeded_product(d, rows, nUnknown, cols, nKnown, dvKnown, dvUnknown);
    return fmi2OK;
}

fmi2Status uc_get_directional_derivative(UCInstance* inst, const fmi2ValueReference unknown[], size_t nUnknown,
                                         const fmi2ValueReference known[], size_t nKnown, const fmi2Real dvKnown[],
                                         fmi2Real dvUnknown[]) {
    static const char* const outputs[6] = {"towForce.x", "towForce.y", "towForce.z",
                                           "endForce.x", "endForce.y", "endForce.z"};
    static const char* const inputs[18] = {"tow.x",  "tow.y",  "tow.z",  "tow.vx", "tow.vy", "tow.vz",
                                           "end.x",  "end.y",  "end.z",  "end.vx", "end.vy", "end.vz",
                                           "tow.ax", "tow.ay", "tow.az", "end.ax", "end.ay", "end.az"};
    const char* function = "fmi2GetDirectionalDerivative";
    if ((nUnknown > 0 && (unknown == NULL || dvUnknown == NULL)) ||
        (nKnown > 0 && (known == NULL || dvKnown == NULL))) {
        uc_log_status(&inst->log, fmi2Error, "%s: NULL array", function);
        return fmi2Error;
    }
    if (inst->coreParams.mooringSystem && inst->cable != NULL && inst->coreReady)
        return body_directional_derivative(inst, unknown, nUnknown, known, nKnown, dvKnown, dvUnknown);
    int rows[6];
    double seed[18] = {0.0};
    if (nUnknown > 6 || nKnown > 18) {
        uc_log_status(&inst->log, fmi2Error,
                      "%s: at most 6 unknowns (towForce.*, endForce.*) and 18 knowns (tow.*, end.*) per call",
                      function);
        return fmi2Error;
    }
    for (size_t i = 0; i < nUnknown; ++i) {
        rows[i] = interface_index(inst, unknown[i], outputs, 6, "of", "of towForce.x/y/z and endForce.x/y/z");
        if (rows[i] < 0) return fmi2Error;
    }
    for (size_t j = 0; j < nKnown; ++j) {
        const int col = interface_index(inst, known[j], inputs, 18, "with respect to",
                                        "with respect to tow.x/y/z, tow.vx/vy/vz, tow.ax/ay/az, end.x/y/z, "
                                        "end.vx/vy/vz and end.ax/ay/az");
        if (col < 0) return fmi2Error;
        if (!isfinite(dvKnown[j])) {
            uc_log_status(&inst->log, fmi2Error, "%s: the seed of %s is not a finite number", function, inputs[col]);
            return fmi2Error;
        }
        seed[col] += dvKnown[j];
    }
    if (inst->cable == NULL || !inst->coreReady) {
        uc_log_status(&inst->log, fmi2Error,
                      "%s: the derivatives are over the next communication step: available after the first "
                      "fmi2DoStep", function);
        return fmi2Error;
    }
    double d[6];
    if (uc_interface_derivative(inst->cable, seed, d, inst->msg, sizeof inst->msg) != 0) {
        uc_log_status(&inst->log, fmi2Error, "%s: %s", function, inst->msg);
        return fmi2Error;
    }
    for (size_t i = 0; i < nUnknown; ++i) dvUnknown[i] = d[rows[i]];
    return fmi2OK;
}
