/*
 * value_access.h - fmi2Get/Set{Real,Integer,Boolean,String} and the input derivatives by value reference, with
 * the FMI rules on which variable may be set when (FMI 2.0 section 4.2.4): parameters in instantiated and
 * initialization mode only (all are fixed), inputs until terminated, outputs never; Real values must be
 * finite. Every rejection is logged with the variable name and returns fmi2Error.
 */
#ifndef UNDERWATERCABLE_FMU_VALUE_ACCESS_H
#define UNDERWATERCABLE_FMU_VALUE_ACCESS_H

#include "instance.h"
#include "variables.h"

/* values points to fmi2Real[] for UC_TYPE_REAL, fmi2Integer[] / fmi2Boolean[] otherwise. */
fmi2Status uc_get_values(UCInstance* inst, const fmi2ValueReference vr[], size_t nvr, void* values, UCVarType type,
                         const char* function);
fmi2Status uc_set_values(UCInstance* inst, const fmi2ValueReference vr[], size_t nvr, const void* values,
                         UCVarType type, const char* function);

/* fmi2GetString hands out pointers to the instance's own characters (valid until the variable is set
 * again or the instance is freed); fmi2SetString copies each string. A NULL string, or one longer than
 * the variable holds, is fmi2Error naming the variable. */
fmi2Status uc_get_strings(UCInstance* inst, const fmi2ValueReference vr[], size_t nvr, fmi2String values[],
                          const char* function);
fmi2Status uc_set_strings(UCInstance* inst, const fmi2ValueReference vr[], size_t nvr, const fmi2String values[],
                          const char* function);

/* Order 1 of tow.vx/vy/vz or order 2 of tow.x/y/z: the tow acceleration of the next step.
 * Order 1 of current.x/y: the current changes linearly over the next step.
 * Order 1 of any other input (including tow.x/y/z, whose velocity is the input tow.v*) is accepted and
 * ignored: inputs are held constant over a step. Other orders and non-inputs: fmi2Error. */
fmi2Status uc_set_input_derivatives(UCInstance* inst, const fmi2ValueReference vr[], size_t nvr,
                                    const fmi2Integer order[], const fmi2Real values[]);

/* dvUnknown = J dvKnown with J the interface derivatives of the core (uc_interface_derivatives):
 * unknowns towForce.* and endForce.*, knowns tow.*, tow.v*, end.*, end.v*; anything else, NULL
 * arrays, non-finite seeds or a call before the first step: fmi2Error naming it. */
fmi2Status uc_get_directional_derivative(UCInstance* inst, const fmi2ValueReference unknown[], size_t nUnknown,
                                         const fmi2ValueReference known[], size_t nKnown, const fmi2Real dvKnown[],
                                         fmi2Real dvUnknown[]);

#endif /* UNDERWATERCABLE_FMU_VALUE_ACCESS_H */
