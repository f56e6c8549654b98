/* fmi2_machine.c - see fmi2_machine.h. */
#include "fmi2_machine.h"

const char* uc_state_name(UCMachineState state) {
    switch (state) {
        case UC_STATE_INSTANTIATED: return "instantiated";
        case UC_STATE_INIT_MODE: return "initializationMode";
        case UC_STATE_STEP_COMPLETE: return "stepComplete";
        case UC_STATE_STEP_IN_PROGRESS: return "stepInProgress";
        case UC_STATE_STEP_FAILED: return "stepFailed";
        case UC_STATE_STEP_CANCELED: return "stepCanceled";
        case UC_STATE_TERMINATED: return "terminated";
        case UC_STATE_ERROR: return "error";
        default: return "fatal";
    }
}

fmi2Status uc_machine_check(UCLogger* log, UCMachineState state, unsigned int allowedStates, const char* function) {
    if ((state & allowedStates) != 0) return fmi2OK;
    uc_log_status(log, fmi2Error, "%s: illegal call sequence (called in state %s)", function, uc_state_name(state));
    return fmi2Error;
}

fmi2Status uc_machine_finish(UCMachineState* state, fmi2Status status) {
    if (status == fmi2Fatal) {
        *state = UC_STATE_FATAL;
    } else if (status == fmi2Error && *state != UC_STATE_FATAL) {
        *state = UC_STATE_ERROR;
    }
    return status;
}

void uc_machine_enter_initialization(UCMachineState* state) { *state = UC_STATE_INIT_MODE; }

fmi2Status uc_machine_exit_initialization(UCMachineState* state, fmi2Status status) {
    if (status == fmi2OK) *state = UC_STATE_STEP_COMPLETE;
    return status;
}

void uc_machine_terminate(UCMachineState* state) { *state = UC_STATE_TERMINATED; }
