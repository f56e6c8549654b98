/*
 * variables.h - the value-reference table: every FMU variable of modelDescription.xml with its
 * value reference, name, type, causality and its place in UCParams / UCInputs / UCOutputs.
 * Both this table and modelDescription.xml are generated from the variable schema
 * (schema/variables.toml); tests/fmu still checks them against each other both ways.
 * Variability follows from causality (parameter: fixed; input, output: continuous); start values of
 * parameters are those of uc_params_default, of inputs 0, outputs have none (initial="calculated").
 */
#ifndef UNDERWATERCABLE_FMU_VARIABLES_H
#define UNDERWATERCABLE_FMU_VARIABLES_H

#include <stddef.h>

#include "api/cable_api.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { UC_TYPE_REAL, UC_TYPE_INTEGER, UC_TYPE_BOOLEAN, UC_TYPE_STRING } UCVarType;

/* Causality also names the struct the variable lives in: UCParams, UCInputs or UCOutputs. */
typedef enum { UC_CAUSALITY_PARAMETER, UC_CAUSALITY_INPUT, UC_CAUSALITY_OUTPUT } UCCausality;

typedef struct UCVariable {
    unsigned int vr;
    const char* name;
    UCVarType type;        /* Real: double, Integer and Boolean: int, String: char[size], NUL-terminated */
    UCCausality causality;
    size_t offset;         /* byte offset into the struct named by causality */
    size_t size;           /* bytes of the member (a String holds at most size - 1 characters) */
} UCVariable;

/* The whole table, sorted by value reference (same order as modelDescription.xml). */
const UCVariable* uc_variables(size_t* count);

/* The variable with this value reference and type, or NULL. */
const UCVariable* uc_variable_find(unsigned int vr, UCVarType type);

/* Address of the variable's value in the given structs. */
void* uc_variable_address(const UCVariable* v, UCParams* p, UCInputs* in, UCOutputs* out);
const void* uc_variable_address_const(const UCVariable* v, const UCParams* p, const UCInputs* in,
                                      const UCOutputs* out);

const char* uc_type_name(UCVarType t);           /* "Real", "Integer", "Boolean", "String" */
const char* uc_causality_name(UCCausality c);    /* "parameter", "input", "output" */
const char* uc_variability_name(UCCausality c);  /* "fixed" or "continuous" */

#ifdef __cplusplus
}
#endif

#endif /* UNDERWATERCABLE_FMU_VARIABLES_H */
