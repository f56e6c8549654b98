/*
 * partner_instance.h - one instance of a partner FMU: everything it owns (no globals) and its values. Its
 * state machine (FMI 2.0 section 4.2.4) is the cable adapter's, common/fmi2_machine.h.
 */
#ifndef UNDERWATERCABLE_PARTNER_INSTANCE_H
#define UNDERWATERCABLE_PARTNER_INSTANCE_H

#include "common/fmi2_machine.h"
#include "fmi2FunctionTypes.h"
#include "logging.h"
#include "partner.h"

#define PM_MSG_SIZE 512
#define PM_TIME_TOLERANCE 1e-5 /* relative to max(1, |t|), as the cable's adapter */

typedef struct PMInstance {
    const PMModel* model;
    char* instanceName;         /* copied in fmi2Instantiate */
    UCLogger log;
    UCMachineState state;
    double startTime;
    int stopTimeDefined;
    double stopTime;
    double time;                /* startTime, then the end of the last step */
    int ready;                  /* data holds the initialization of the current parameters and inputs (or a step) */
    void* data;                 /* model->dataSize bytes: parameters, inputs, states, outputs */
    char* resources;            /* the resources directory as a path (from fmuResourceLocation); may be NULL */
    void* derived;              /* the model's derived data of the current parameters (model->build); may be NULL */
    char msg[PM_MSG_SIZE];      /* scratch for messages of the model */
} PMInstance;

PMInstance* pm_instance_new(const PMModel* model, const char* instanceName, const char* resourceLocation,
                            fmi2CallbackLogger logger, fmi2ComponentEnvironment environment, int loggingOn);
void pm_instance_free(PMInstance* inst);

/* Back to "instantiated" with every start value. */
void pm_instance_reset(PMInstance* inst);

/* The double of variable v in the instance's data. */
double* pm_value(PMInstance* inst, const PMVariable* v);

/* The characters of the String variable v in the instance's data (PM_STRING_CAPACITY bytes). */
char* pm_string(PMInstance* inst, const PMVariable* v);

/* Range checks of every parameter, then the model's own check, its derived data, then its initialization. */
fmi2Status pm_ensure_initialized(PMInstance* inst, const char* function);

/* The model's derived data rebuilt from the parameters in the data (after a state was restored). */
fmi2Status pm_rebuild_derived(PMInstance* inst, const char* function);

#endif /* UNDERWATERCABLE_PARTNER_INSTANCE_H */
