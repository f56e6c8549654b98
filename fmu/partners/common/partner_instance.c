/* partner_instance.c - see partner_instance.h. */
#include "partner_instance.h"

#include "file_uri.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static char* copy_string(const char* s) {
    size_t n = strlen(s) + 1;
    char* copy = malloc(n);
    if (copy != NULL) memcpy(copy, s, n);
    return copy;
}

PMInstance* pm_instance_new(const PMModel* model, const char* instanceName, const char* resourceLocation,
                            fmi2CallbackLogger logger, fmi2ComponentEnvironment environment, int loggingOn) {
    PMInstance* inst = calloc(1, sizeof *inst);
    if (inst == NULL) return NULL;
    inst->model = model;
    inst->instanceName = copy_string(instanceName);
    inst->data = calloc(1, model->dataSize);
    if (resourceLocation != NULL) { /* not a local file URI: no resources (a model needing them says so) */
        const size_t size = strlen(resourceLocation) + 1;
        inst->resources = malloc(size);
        if (inst->resources != NULL && uc_file_uri_to_path(resourceLocation, inst->resources, size) != 0) {
            free(inst->resources);
            inst->resources = NULL;
        }
    }
    if (inst->instanceName == NULL || inst->data == NULL) {
        pm_instance_free(inst);
        return NULL;
    }
    inst->log.callback = logger;
    inst->log.environment = environment;
    inst->log.instanceName = inst->instanceName;
    uc_log_configure(&inst->log, loggingOn, 0, NULL);
    pm_instance_reset(inst);
    return inst;
}

void pm_instance_free(PMInstance* inst) {
    if (inst == NULL) return;
    if (inst->derived != NULL) inst->model->release(inst->derived);
    free(inst->resources);
    free(inst->data);
    free(inst->instanceName);
    free(inst);
}

double* pm_value(PMInstance* inst, const PMVariable* v) { return (double*)((char*)inst->data + v->offset); }

char* pm_string(PMInstance* inst, const PMVariable* v) { return (char*)inst->data + v->offset; }

void pm_instance_reset(PMInstance* inst) {
    const PMModel* m = inst->model;
    memset(inst->data, 0, m->dataSize);
    for (size_t i = 0; i < m->nVariables; ++i) {
        const PMVariable* v = &m->variables[i];
        if (v->causality != PM_OUTPUT && v->type != PM_STRING) *pm_value(inst, v) = v->start; /* Strings: "" */
    }
    inst->state = UC_STATE_INSTANTIATED;
    inst->startTime = inst->time = inst->stopTime = 0.0;
    inst->stopTimeDefined = 0;
    inst->ready = 0;
    inst->msg[0] = '\0';
}

static fmi2Status check_parameter_ranges(PMInstance* inst, const char* function) {
    const PMModel* m = inst->model;
    for (size_t i = 0; i < m->nVariables; ++i) {
        const PMVariable* v = &m->variables[i];
        if (v->causality != PM_PARAMETER || v->type == PM_STRING) continue;
        double value = *pm_value(inst, v);
        if (!(value >= v->min && value <= v->max)) {
            uc_log_status(&inst->log, fmi2Error, "%s: invalid parameter: %s = %.17g is outside [%g, %g]: %s", function,
                          v->name, value, v->min, v->max, v->why);
            return fmi2Error;
        }
    }
    return fmi2OK;
}

fmi2Status pm_ensure_initialized(PMInstance* inst, const char* function) {
    if (inst->ready) return fmi2OK;
    if (check_parameter_ranges(inst, function) != fmi2OK) return fmi2Error;
    inst->msg[0] = '\0';
    const PMModel* m = inst->model;
    if (m->check(inst->data, inst->msg, sizeof inst->msg) != 0) {
        uc_log_status(&inst->log, fmi2Error, "%s: invalid parameter: %s", function, inst->msg);
        return fmi2Error;
    }
    if (pm_rebuild_derived(inst, function) != fmi2OK) return fmi2Error;
    if (m->initialize(inst->data, inst->derived, inst->startTime, inst->msg, sizeof inst->msg) != 0) {
        uc_log_status(&inst->log, fmi2Error, "%s: initialization failed: %s", function, inst->msg);
        return fmi2Error;
    }
    inst->time = inst->startTime;
    inst->ready = 1;
    uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS, "%s: %s initialized at t = %.9g", function, m->identifier, inst->time);
    return fmi2OK;
}

fmi2Status pm_rebuild_derived(PMInstance* inst, const char* function) {
    const PMModel* m = inst->model;
    if (m->build == NULL) return fmi2OK;
    if (inst->derived != NULL) m->release(inst->derived);
    inst->msg[0] = '\0';
    inst->derived = m->build(inst->data, inst->resources, inst->msg, sizeof inst->msg);
    if (inst->derived == NULL) {
        uc_log_status(&inst->log, fmi2Error, "%s: %s", function, inst->msg[0] != '\0' ? inst->msg : "out of memory");
        return fmi2Error;
    }
    return fmi2OK;
}
