/* instance.c - see instance.h. */
#include "instance.h"

#include <stdlib.h>
#include <string.h>

#include "variables.h"

static char* copy_string(const char* s) {
    if (s == NULL) return NULL;
    size_t n = strlen(s) + 1;
    char* copy = malloc(n);
    if (copy != NULL) memcpy(copy, s, n);
    return copy;
}

UCInstance* uc_instance_new(const char* instanceName, const char* resourceLocation, fmi2CallbackLogger logger,
                            fmi2ComponentEnvironment environment, int loggingOn) {
    UCInstance* inst = calloc(1, sizeof *inst);
    if (inst == NULL) return NULL;
    inst->instanceName = copy_string(instanceName);
    inst->resourceLocation = copy_string(resourceLocation);
    if (inst->instanceName == NULL || (resourceLocation != NULL && inst->resourceLocation == NULL)) {
        uc_instance_free(inst);
        return NULL;
    }
    size_t count = 0;
    uc_variables(&count);
    inst->setByImporter = calloc(count, 1);
    if (inst->setByImporter == NULL) {
        uc_instance_free(inst);
        return NULL;
    }
    inst->log.callback = logger;
    inst->log.environment = environment;
    inst->log.instanceName = inst->instanceName;
    uc_log_configure(&inst->log, loggingOn, 0, NULL);
    uc_instance_reset(inst);
    return inst;
}

void uc_instance_free(UCInstance* inst) {
    if (inst == NULL) return;
    uc_instance_drop_core(inst);
    free(inst->instanceName);
    free(inst->resourceLocation);
    free(inst->setByImporter);
    free(inst);
}

void uc_instance_drop_core(UCInstance* inst) {
    uc_free(inst->cable);
    inst->cable = NULL;
    inst->coreReady = 0;
    inst->outputsProvisional = 0;
}

void uc_instance_reset(UCInstance* inst) {
    uc_instance_drop_core(inst);
    inst->state = UC_STATE_INSTANTIATED;
    inst->startTime = 0.0;
    inst->stopTimeDefined = 0;
    inst->stopTime = 0.0;
    inst->time = 0.0;
    inst->lastSuccessfulTime = 0.0;
    inst->terminateRequested = 0;
    memset(&inst->params, 0, sizeof inst->params); /* deterministic padding bytes in saved states */
    uc_params_default(&inst->params);
    memcpy(&inst->coreParams, &inst->params, sizeof inst->coreParams);
    uc_inputs_default(&inst->inputs);
    memset(&inst->outputs, 0, sizeof inst->outputs);
    size_t count = 0;
    uc_variables(&count);
    memset(inst->setByImporter, 0, count);
    inst->msg[0] = '\0';
}

void uc_instance_mark_set(UCInstance* inst, const UCVariable* v) {
    size_t count = 0;
    const UCVariable* table = uc_variables(&count);
    if (v < table || v >= table + count || inst->setByImporter[v - table]) return;
    inst->setByImporter[v - table] = 1;
    /* a deck's parameter set now keeps its value over the deck's: the initialization changes */
    if (v->causality == UC_CAUSALITY_PARAMETER && inst->state != UC_STATE_STEP_COMPLETE) uc_instance_drop_core(inst);
}

int uc_instance_was_set(const UCInstance* inst, const char* name) {
    size_t count = 0;
    const UCVariable* table = uc_variables(&count);
    for (size_t k = 0; k < count; ++k)
        if (strcmp(table[k].name, name) == 0) return inst->setByImporter[k];
    return 0;
}

fmi2Status uc_instance_finish(UCInstance* inst, fmi2Status status) {
    return inst == NULL ? status : uc_machine_finish(&inst->state, status);
}
