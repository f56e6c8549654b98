/* variables.c - the value-reference table (see variables.h), expanded from the variable schema
 * (schema/variables.toml, generated into src/generated/uc_schema.h): sorted by value reference. */
#include "variables.h"

#include <stdlib.h>

#define UC_STRUCT_PARAMETER UCParams
#define UC_STRUCT_INPUT UCInputs
#define UC_STRUCT_OUTPUT UCOutputs
#define UC_VARIABLE_ROW(vr, name, TYPE, CAUSALITY, member) \
    {vr, name, UC_TYPE_##TYPE, UC_CAUSALITY_##CAUSALITY, offsetof(UC_STRUCT_##CAUSALITY, member), \
     sizeof(((UC_STRUCT_##CAUSALITY*)0)->member)},

static const UCVariable kVariables[] = {UC_SCHEMA_VARIABLES(UC_VARIABLE_ROW)};

#define N_VARIABLES (sizeof(kVariables) / sizeof(kVariables[0]))

const UCVariable* uc_variables(size_t* count) {
    *count = N_VARIABLES;
    return kVariables;
}

static int compare_vr(const void* key, const void* element) {
    unsigned int vr = *(const unsigned int*)key;
    unsigned int other = ((const UCVariable*)element)->vr;
    return (vr > other) - (vr < other);
}

/* Value references are unique over all types (a stricter rule than FMI's per-type uniqueness). */
const UCVariable* uc_variable_find(unsigned int vr, UCVarType type) {
    const UCVariable* v = bsearch(&vr, kVariables, N_VARIABLES, sizeof(kVariables[0]), compare_vr);
    return (v != NULL && v->type == type) ? v : NULL;
}

void* uc_variable_address(const UCVariable* v, UCParams* p, UCInputs* in, UCOutputs* out) {
    return (void*)uc_variable_address_const(v, p, in, out);
}

const void* uc_variable_address_const(const UCVariable* v, const UCParams* p, const UCInputs* in,
                                      const UCOutputs* out) {
    switch (v->causality) {
        case UC_CAUSALITY_PARAMETER: return (const char*)p + v->offset;
        case UC_CAUSALITY_INPUT: return (const char*)in + v->offset;
        default: return (const char*)out + v->offset;
    }
}

const char* uc_type_name(UCVarType t) {
    switch (t) {
        case UC_TYPE_REAL: return "Real";
        case UC_TYPE_INTEGER: return "Integer";
        case UC_TYPE_BOOLEAN: return "Boolean";
        default: return "String";
    }
}

const char* uc_causality_name(UCCausality c) {
    switch (c) {
        case UC_CAUSALITY_PARAMETER: return "parameter";
        case UC_CAUSALITY_INPUT: return "input";
        default: return "output";
    }
}

const char* uc_variability_name(UCCausality c) { return c == UC_CAUSALITY_PARAMETER ? "fixed" : "continuous"; }
