/*
 * instance.h - one FMU instance: everything it owns (no globals). Its state machine (FMI 2.0 section
 * 4.2.4) and what a returned status does to it are common/fmi2_machine.h's. Every function stops at its
 * first error, so the status it returns is the worst of what happened; uc_instance_finish applies it.
 */
#ifndef UNDERWATERCABLE_FMU_INSTANCE_H
#define UNDERWATERCABLE_FMU_INSTANCE_H

#include "api/cable_api.h"
#include "common/fmi2_machine.h"
#include "fmi2FunctionTypes.h"
#include "input_checks.h"
#include "logging.h"

#define UC_MSG_SIZE 512

typedef struct UCInstance {
    char* instanceName;          /* copied in fmi2Instantiate */
    char* resourceLocation;      /* copied; may be NULL */
    UCLogger log;                /* the callback pointers copied from fmi2CallbackFunctions */
    UCMachineState state;

    double startTime;            /* from fmi2SetupExperiment */
    int stopTimeDefined;
    double stopTime;
    double time;                 /* the FMU's own time: startTime, then the end of the last step */
    double lastSuccessfulTime;
    int terminateRequested;      /* fmi2GetBooleanStatus(fmi2Terminated) */
    int earlyReturnAllowed;      /* FMI 3.0's earlyReturnAllowed: a step ends at a line failure's break within it
                                    (0 in FMI 2.0: every step reaches its communication point) */

    UCParams params;             /* as set through the FMI (lineFile is a path) */
    UCParams coreParams;         /* what the core was created with: params with lineFile's line applied */
    UCInputs inputs;
    UCOutputs outputs;           /* valid when coreReady */

    UCCable* cable;              /* NULL until initialization is computed */
    int coreReady;               /* cable is initialized from the current params/inputs (or stepped since) */
    int outputsProvisional;      /* initialization mode: the initialization from the current params/inputs
                                    failed, outputs hold the provisional values (simulation.h) */
    int towMismatchWarned;       /* the tow position / velocity mismatch was reported in this run */
    UCInputChecks inputChecks;   /* the inputs of the last step and what was reported (input_checks.h) */

    /* The water pushed by the importer (water.source 1): the FMI 3.0 adapter's arrays waterVelocity.x/y/z and
       waterAcceleration.x/y/z (its own memory, waterCapacity = nWaterPoints values each), given to the core
       before its initialization and every step; NULL in FMI 2.0, which has no such arrays. */
    const double* water[6];
    size_t waterCapacity;

    unsigned char* setByImporter; /* one flag per row of the variable table (variables.h): the importer set it
                                     since instantiation or fmi2Reset (uc_instance_mark_set) */

    char msg[UC_MSG_SIZE];       /* scratch for messages of the core */
} UCInstance;

UCInstance* uc_instance_new(const char* instanceName, const char* resourceLocation, fmi2CallbackLogger logger,
                            fmi2ComponentEnvironment environment, int loggingOn);
void uc_instance_free(UCInstance* inst);

/* Back to "instantiated" with all start values (frees the core); logging settings are kept. */
void uc_instance_reset(UCInstance* inst);

/* Frees the core and marks the initialization as not computed (a value it depends on has changed). */
void uc_instance_drop_core(UCInstance* inst);

/* Applies the status to the machine (uc_machine_finish); a NULL instance only returns status. */
fmi2Status uc_instance_finish(UCInstance* inst, fmi2Status status);

/* Records that the importer set variable v (a row of uc_variables); uc_instance_was_set asks by name
 * (0 for a name not in the table). A lineFile deck leaves such parameters as the importer set them. */
struct UCVariable;
void uc_instance_mark_set(UCInstance* inst, const struct UCVariable* v);
int uc_instance_was_set(const UCInstance* inst, const char* name);

#endif /* UNDERWATERCABLE_FMU_INSTANCE_H */
