/* value_access.c - see value_access.h. */
#include "value_access.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "generated/uc_schema_derivatives.h"
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
 * "Mooring stiffness": a fifth of a step's cost): the schema's computedWhenRead outputs. */
static int is_stiffness(const UCVariable* v) {
    static const unsigned int computed[] = {
#define UC_COMPUTED_ROW(vr) vr,
        UC_SCHEMA_COMPUTED_WHEN_READ(UC_COMPUTED_ROW)
#undef UC_COMPUTED_ROW
    };
    if (v->causality != UC_CAUSALITY_OUTPUT) return 0;
    size_t lo = 0, hi = sizeof computed / sizeof computed[0]; /* ascending: a binary search, every read asks */
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (computed[mid] == v->vr) return 1;
        if (computed[mid] < v->vr) lo = mid + 1; else hi = mid;
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
    uc_sim_log_events(inst, function);
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

/* ---- the inputs' time derivatives, from the schema (derivativeOf, derivativeField, givenFlag) ---- */

typedef struct {
    unsigned int vr, of; /* the input vr is the time derivative of the input of */
} DerivativeOf;

typedef struct {
    unsigned int vr; /* an input */
    size_t offset;   /* a member of UCInputs: where der(vr) is kept, or the flag that it was given */
} InputMember;

typedef struct {
    unsigned int vr; /* an input that is another input's derivative (tow.a*) */
    size_t offset;   /* the int flag of UCInputs that it was given for the coming step */
    int component;   /* its component (UC_ACCELERATION_AS_INPUT) */
} InputFlag;

#define UC_DERIVATIVE_OF_ROW(vr, of) {vr, of},
#define UC_MEMBER_ROW(vr, member) {vr, offsetof(UCInputs, member)},
#define UC_INPUT_FLAG_ROW(vr, flag, component) {vr, offsetof(UCInputs, flag), component},
static const DerivativeOf kDerivativeOf[] = {UC_SCHEMA_DERIVATIVE_OF(UC_DERIVATIVE_OF_ROW)};
static const InputMember kDerivativeMembers[] = {UC_SCHEMA_DERIVATIVE_MEMBERS(UC_MEMBER_ROW)};
static const InputMember kMemberFlags[] = {UC_SCHEMA_DERIVATIVE_MEMBER_FLAGS(UC_MEMBER_ROW)};
static const InputFlag kInputFlags[] = {UC_SCHEMA_DERIVATIVE_INPUT_FLAGS(UC_INPUT_FLAG_ROW)};
#define UC_COUNT(table) (sizeof(table) / sizeof((table)[0]))

/* The input that is the time derivative of the input vr, or 0. */
static unsigned int derivative_input(unsigned int vr) {
    for (size_t i = 0; i < UC_COUNT(kDerivativeOf); ++i)
        if (kDerivativeOf[i].of == vr) return kDerivativeOf[i].vr;
    return 0;
}

static const InputMember* input_member(const InputMember* table, size_t count, unsigned int vr) {
    for (size_t i = 0; i < count; ++i)
        if (table[i].vr == vr) return &table[i];
    return NULL;
}

static const InputFlag* input_flag(unsigned int vr) {
    for (size_t i = 0; i < UC_COUNT(kInputFlags); ++i)
        if (kInputFlags[i].vr == vr) return &kInputFlags[i];
    return NULL;
}

static void* inputs_at(UCInstance* inst, size_t offset) { return (char*)&inst->inputs + offset; }

/* Component c of an input that is another's derivative (an acceleration of a driven end) is given for the coming
 * step, by fmi2SetRealInputDerivatives (asInput 0) or by setting the input itself (asInput 1:
 * UC_ACCELERATION_AS_INPUT); before initialization that changes the initialization (the first step's end). */
static void mark_given(UCInstance* inst, const InputFlag* f, int asInput) {
    int* given = (int*)inputs_at(inst, f->offset);
    const int before = *given, c = f->component;
    *given = asInput ? (before | 1 | UC_ACCELERATION_AS_INPUT(c)) : ((before | 1) & ~UC_ACCELERATION_AS_INPUT(c));
    if (before == 0 && inst->state != UC_STATE_STEP_COMPLETE) uc_instance_drop_core(inst);
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
            const InputFlag* given = v->causality == UC_CAUSALITY_INPUT ? input_flag(v->vr) : NULL;
            if (given != NULL) mark_given(inst, given, 1);
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

/* Where fmi2SetRealInputDerivatives keeps a derivative: target NULL if it is accepted and ignored (the input held
 * over the step); inputFlag (an input that is a derivative) or flag (of a member), or neither. */
typedef struct {
    double* target;
    const InputFlag* inputFlag;
    int* flag;
} DerivativeTarget;

/* Where the derivative of `order` of the input v is kept. Along v's chain of derivatives (derivativeOf), it lands
 * in the last input of the chain when that is `order` links away, or in the member that keeps the last input's
 * derivative when that is; a derivative of order 1 elsewhere is accepted and ignored (der(tow.x) is the input
 * tow.vx), any other is refused. fmi2Error (logged) if it is refused. */
static fmi2Status derivative_target(UCInstance* inst, const UCVariable* v, int order, double value,
                                    DerivativeTarget* kept) {
    const char* function = "fmi2SetRealInputDerivatives";
    kept->target = NULL;
    kept->inputFlag = NULL;
    kept->flag = NULL;
    if (v->causality != UC_CAUSALITY_INPUT) {
        uc_log_status(&inst->log, fmi2Error, "%s: %s is not an input", function, v->name);
        return fmi2Error;
    }
    if (check_real_value(inst, v, value, function) != fmi2OK) return fmi2Error;
    unsigned int last = v->vr; /* the last input of v's chain, and how many links it is from v */
    int links = 0;
    for (unsigned int next; (next = derivative_input(last)) != 0; ++links) last = next;
    const InputMember* member = input_member(kDerivativeMembers, UC_COUNT(kDerivativeMembers), last);
    if (order >= 1 && links == order && member == NULL) {
        kept->target = (double*)uc_variable_address(uc_variable_find(last, UC_TYPE_REAL), &inst->params,
                                                    &inst->inputs, &inst->outputs);
        kept->inputFlag = input_flag(last);
    } else if (order >= 1 && links == order - 1 && member != NULL) {
        kept->target = (double*)inputs_at(inst, member->offset);
        const InputMember* flag = input_member(kMemberFlags, UC_COUNT(kMemberFlags), last);
        if (flag != NULL) kept->flag = (int*)inputs_at(inst, flag->offset);
    } else if (order != 1) {
        const int supported = links + (member != NULL);
        if (supported > 1) {
            uc_log_status(&inst->log, fmi2Error, "%s: derivative of order %d of %s is not supported (orders 1 and %d)",
                          function, order, v->name, supported);
        } else {
            uc_log_status(&inst->log, fmi2Error, "%s: derivative of order %d of %s is not supported (order 1)",
                          function, order, v->name);
        }
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
    DerivativeTarget kept;
    for (size_t i = 0; i < nvr; ++i) { /* every derivative is checked before any is kept */
        const UCVariable* v = find_or_log(inst, vr[i], UC_TYPE_REAL, function);
        if (v == NULL || derivative_target(inst, v, order[i], values[i], &kept) != fmi2OK) return fmi2Error;
    }
    for (size_t i = 0; i < nvr; ++i) {
        const UCVariable* v = uc_variable_find(vr[i], UC_TYPE_REAL);
        derivative_target(inst, v, order[i], values[i], &kept);
        if (kept.target == NULL) {
            const UCVariable* rate = uc_variable_find(derivative_input(v->vr), UC_TYPE_REAL);
            uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS, "%s: derivative of %s ignored (held constant over a step%s%s)",
                   function, v->name, rate != NULL ? "; its derivative is the input " : "", rate != NULL ? rate->name : "");
            continue;
        }
        *kept.target = values[i];
        if (kept.inputFlag != NULL) {
            mark_given(inst, kept.inputFlag, 0);
        } else if (kept.flag != NULL) {
            *kept.flag = 1;
        }
    }
    return fmi2OK;
}

/* ---- directional derivatives, from the schema (directionalDerivative) ------------------------------ */

typedef enum { UC_MATRIX_INTERFACE, UC_MATRIX_BODY } UCMatrix;

typedef struct {
    unsigned int vr;
    UCMatrix matrix;
    int index; /* the row (an output) or column (an input) */
    int body;  /* 1-based body of a BODY matrix, 0 for INTERFACE */
} DerivativeCell;

#define UC_CELL_ROW(vr, matrix, index, body) {vr, UC_MATRIX_##matrix, index, body},
static const DerivativeCell kDerivativeColumns[] = {UC_SCHEMA_DERIVATIVE_COLUMNS(UC_CELL_ROW)};
static const DerivativeCell kDerivativeRows[] = {UC_SCHEMA_DERIVATIVE_ROWS(UC_CELL_ROW)};

_Static_assert(UC_SCHEMA_INTERFACE_DERIVATIVE_COLUMNS == 18 && UC_SCHEMA_INTERFACE_DERIVATIVE_ROWS == 6,
               "uc_interface_derivative: a seed of 18 inputs, 6 outputs");
_Static_assert(UC_SCHEMA_BODY_DERIVATIVE_COLUMNS == UC_BODY_DERIVATIVE_INPUTS && UC_SCHEMA_BODY_DERIVATIVE_ROWS == 6,
               "uc_body_derivatives: UC_BODY_DERIVATIVE_INPUTS inputs, 6 outputs");

/* The row or column of the variable vr in `matrix` (table: kDerivativeRows or kDerivativeColumns) and in *body
 * its body (the first of a call sets it, the others must agree); -1 (logged by the caller) if it has none. */
static int cell_index(const DerivativeCell* table, size_t count, UCMatrix matrix, unsigned int vr, int* body) {
    for (size_t i = 0; i < count; ++i) {
        if (table[i].vr != vr || table[i].matrix != matrix) continue;
        if (*body != 0 && *body != table[i].body) return -1;
        *body = table[i].body;
        return table[i].index;
    }
    return -1;
}

/* The row or column of the variable vr, or -1 with a message: "no derivative <relation> <name> (<which>)". */
static int derivative_index(UCInstance* inst, fmi2ValueReference vr, const DerivativeCell* table, size_t count,
                            UCMatrix matrix, int* body, const char* relation, const char* which) {
    const char* function = "fmi2GetDirectionalDerivative";
    const UCVariable* v = find_or_log(inst, vr, UC_TYPE_REAL, function);
    if (v == NULL) return -1;
    const int index = cell_index(table, count, matrix, vr, body);
    if (index < 0) uc_log_status(&inst->log, fmi2Error, "%s: no derivative %s %s (%s)", function, relation, v->name, which);
    return index;
}

/* A seed must be a finite number (logged naming its input). */
static fmi2Status check_seed(UCInstance* inst, fmi2ValueReference vr, double seed) {
    if (isfinite(seed)) return fmi2OK;
    uc_log_status(&inst->log, fmi2Error, "fmi2GetDirectionalDerivative: the seed of %s is not a finite number",
                  uc_variable_find(vr, UC_TYPE_REAL)->name);
    return fmi2Error;
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

/* A mooring system: d body[k].force/moment (t + h) / d body[k].* inputs (t) (uc_body_derivatives). */
static fmi2Status body_directional_derivative(UCInstance* inst, const fmi2ValueReference unknown[], size_t nUnknown,
                                              const fmi2ValueReference known[], size_t nKnown,
                                              const fmi2Real dvKnown[], fmi2Real dvUnknown[]) {
    const char* which = "a mooring system provides " UC_SCHEMA_BODY_DERIVATIVE_ROWS_TEXT " with respect to "
                        UC_SCHEMA_BODY_DERIVATIVE_COLUMNS_TEXT ", of one body per call";
    const char* function = "fmi2GetDirectionalDerivative";
    int rows[UC_SCHEMA_BODY_DERIVATIVE_ROWS], cols[UC_SCHEMA_BODY_DERIVATIVE_COLUMNS], body = 0;
    if (nUnknown > UC_SCHEMA_BODY_DERIVATIVE_ROWS || nKnown > UC_SCHEMA_BODY_DERIVATIVE_COLUMNS) {
        uc_log_status(&inst->log, fmi2Error, "%s: at most %d unknowns and %d knowns per call (%s)", function,
                      UC_SCHEMA_BODY_DERIVATIVE_ROWS, UC_SCHEMA_BODY_DERIVATIVE_COLUMNS, which);
        return fmi2Error;
    }
    for (size_t i = 0; i < nUnknown; ++i) {
        rows[i] = derivative_index(inst, unknown[i], kDerivativeRows, UC_COUNT(kDerivativeRows), UC_MATRIX_BODY,
                                   &body, "involving", which);
        if (rows[i] < 0) return fmi2Error;
    }
    for (size_t j = 0; j < nKnown; ++j) {
        cols[j] = derivative_index(inst, known[j], kDerivativeColumns, UC_COUNT(kDerivativeColumns), UC_MATRIX_BODY,
                                   &body, "involving", which);
        if (cols[j] < 0 || check_seed(inst, known[j], dvKnown[j]) != fmi2OK) return fmi2Error;
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
    const char* function = "fmi2GetDirectionalDerivative";
    if ((nUnknown > 0 && (unknown == NULL || dvUnknown == NULL)) ||
        (nKnown > 0 && (known == NULL || dvKnown == NULL))) {
        uc_log_status(&inst->log, fmi2Error, "%s: NULL array", function);
        return fmi2Error;
    }
    if (inst->coreParams.mooringSystem && inst->cable != NULL && inst->coreReady)
        return body_directional_derivative(inst, unknown, nUnknown, known, nKnown, dvKnown, dvUnknown);
    int rows[UC_SCHEMA_INTERFACE_DERIVATIVE_ROWS], body = 0;
    double seed[UC_SCHEMA_INTERFACE_DERIVATIVE_COLUMNS] = {0.0};
    if (nUnknown > UC_SCHEMA_INTERFACE_DERIVATIVE_ROWS || nKnown > UC_SCHEMA_INTERFACE_DERIVATIVE_COLUMNS) {
        uc_log_status(&inst->log, fmi2Error, "%s: at most %d unknowns (%s) and %d knowns (%s) per call", function,
                      UC_SCHEMA_INTERFACE_DERIVATIVE_ROWS, UC_SCHEMA_INTERFACE_DERIVATIVE_ROWS_TEXT,
                      UC_SCHEMA_INTERFACE_DERIVATIVE_COLUMNS, UC_SCHEMA_INTERFACE_DERIVATIVE_COLUMNS_TEXT);
        return fmi2Error;
    }
    for (size_t i = 0; i < nUnknown; ++i) {
        rows[i] = derivative_index(inst, unknown[i], kDerivativeRows, UC_COUNT(kDerivativeRows), UC_MATRIX_INTERFACE,
                                   &body, "of", "derivatives are provided of " UC_SCHEMA_INTERFACE_DERIVATIVE_ROWS_TEXT);
        if (rows[i] < 0) return fmi2Error;
    }
    for (size_t j = 0; j < nKnown; ++j) {
        const int col = derivative_index(inst, known[j], kDerivativeColumns, UC_COUNT(kDerivativeColumns),
                                         UC_MATRIX_INTERFACE, &body, "with respect to",
                                         "derivatives are provided with respect to "
                                         UC_SCHEMA_INTERFACE_DERIVATIVE_COLUMNS_TEXT);
        if (col < 0 || check_seed(inst, known[j], dvKnown[j]) != fmi2OK) return fmi2Error;
        seed[col] += dvKnown[j];
    }
    if (inst->cable == NULL || !inst->coreReady) {
        uc_log_status(&inst->log, fmi2Error,
                      "%s: the derivatives are over the next communication step: available after the first "
                      "fmi2DoStep", function);
        return fmi2Error;
    }
    double d[UC_SCHEMA_INTERFACE_DERIVATIVE_ROWS];
    if (uc_interface_derivative(inst->cable, seed, d, inst->msg, sizeof inst->msg) != 0) {
        uc_log_status(&inst->log, fmi2Error, "%s: %s", function, inst->msg);
        return fmi2Error;
    }
    for (size_t i = 0; i < nUnknown; ++i) dvUnknown[i] = d[rows[i]];
    return fmi2OK;
}
