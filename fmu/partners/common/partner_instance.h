/*
 * partner_instance.h - one instance of a partner FMU: everything it owns (no globals), its state
 * machine (FMI 2.0 section 4.2.4, the same bit sets as the cable's adapter) and its values.
 */
#ifndef UNDERWATERCABLE_PARTNER_INSTANCE_H
#define UNDERWATERCABLE_PARTNER_INSTANCE_H

#include "fmi2FunctionTypes.h"
#include "logging.h"
#include "partner.h"

typedef enum {
    PM_STATE_INSTANTIATED = 1 << 0,
    PM_STATE_INIT_MODE = 1 << 1,
    PM_STATE_STEP_COMPLETE = 1 << 2,
    PM_STATE_STEP_IN_PROGRESS = 1 << 3,
    PM_STATE_STEP_FAILED = 1 << 4,
    PM_STATE_STEP_CANCELED = 1 << 5,
    PM_STATE_TERMINATED = 1 << 6,
    PM_STATE_ERROR = 1 << 7,
    PM_STATE_FATAL = 1 << 8
} PMMachineState;

#define PM_MSG_SIZE 512
#define PM_TIME_TOLERANCE 1e-5 /* relative to max(1, |t|), as the cable's adapter */

typedef struct PMInstance {
    const PMModel* model;
    char* instanceName;         /* copied in fmi2Instantiate */
    UCLogger log;
    PMMachineState state;
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

/* fmi2OK if the instance is in one of allowedStates, else logs "illegal call sequence" (fmi2Error). */
fmi2Status pm_instance_check(PMInstance* inst, unsigned int allowedStates, const char* function);

/* fmi2Error puts the instance into the error state, fmi2Fatal into fatal. Returns status. */
fmi2Status pm_instance_finish(PMInstance* inst, fmi2Status status);

/* The double of variable v in the instance's data. */
double* pm_value(PMInstance* inst, const PMVariable* v);

/* The characters of the String variable v in the instance's data (PM_STRING_CAPACITY bytes). */
char* pm_string(PMInstance* inst, const PMVariable* v);

/* Range checks of every parameter, then the model's own check, its derived data, then its initialization. */
fmi2Status pm_ensure_initialized(PMInstance* inst, const char* function);

/* The model's derived data rebuilt from the parameters in the data (after a state was restored). */
fmi2Status pm_rebuild_derived(PMInstance* inst, const char* function);

const char* pm_state_name(PMMachineState state);

#endif /* UNDERWATERCABLE_PARTNER_INSTANCE_H */
