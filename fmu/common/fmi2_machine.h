/*
 * fmi2_machine.h - the FMI 2.0 Co-Simulation state machine (FMI 2.0 section 4.2.4), shared by the
 * cable's adapter (fmu/instance.h) and the partner FMUs' (fmu/partners/common/partner_instance.h):
 * the states, the set of states each call may be made in, the check that logs a wrong call sequence,
 * and what a call's status and the life-cycle calls do to the state. An instance keeps its state in a
 * member `state` and its logger in a member `log`; UC_MACHINE_GUARDED runs a call on such an instance.
 */
#ifndef UNDERWATERCABLE_FMI2_MACHINE_H
#define UNDERWATERCABLE_FMI2_MACHINE_H

#include "fmi2FunctionTypes.h"
#include "logging.h"

/* Machine states as bits, so that each call declares the set of states it may be called in. */
typedef enum {
    UC_STATE_INSTANTIATED = 1 << 0,
    UC_STATE_INIT_MODE = 1 << 1,
    UC_STATE_STEP_COMPLETE = 1 << 2,
    UC_STATE_STEP_IN_PROGRESS = 1 << 3,
    UC_STATE_STEP_FAILED = 1 << 4,
    UC_STATE_STEP_CANCELED = 1 << 5,
    UC_STATE_TERMINATED = 1 << 6,
    UC_STATE_ERROR = 1 << 7,
    UC_STATE_FATAL = 1 << 8
} UCMachineState;

/* Sets of states in which each call may be made (FMI 2.0 section 4.2.4, Co-Simulation). */
#define UC_MASK_ANY_AFTER_INSTANTIATE                                                                        \
    (UC_STATE_INSTANTIATED | UC_STATE_INIT_MODE | UC_STATE_STEP_COMPLETE | UC_STATE_STEP_IN_PROGRESS |      \
     UC_STATE_STEP_FAILED | UC_STATE_STEP_CANCELED | UC_STATE_TERMINATED | UC_STATE_ERROR)
#define UC_MASK_SET_DEBUG_LOGGING UC_MASK_ANY_AFTER_INSTANTIATE
#define UC_MASK_SETUP_EXPERIMENT UC_STATE_INSTANTIATED
#define UC_MASK_ENTER_INIT UC_STATE_INSTANTIATED
#define UC_MASK_EXIT_INIT UC_STATE_INIT_MODE
#define UC_MASK_TERMINATE (UC_STATE_STEP_COMPLETE | UC_STATE_STEP_FAILED)
#define UC_MASK_RESET (UC_MASK_ANY_AFTER_INSTANTIATE & ~UC_STATE_STEP_IN_PROGRESS)
#define UC_MASK_GET                                                                                          \
    (UC_STATE_INIT_MODE | UC_STATE_STEP_COMPLETE | UC_STATE_STEP_FAILED | UC_STATE_STEP_CANCELED |          \
     UC_STATE_TERMINATED | UC_STATE_ERROR)
#define UC_MASK_SET (UC_STATE_INSTANTIATED | UC_STATE_INIT_MODE | UC_STATE_STEP_COMPLETE)
#define UC_MASK_FMU_STATE (UC_MASK_ANY_AFTER_INSTANTIATE & ~UC_STATE_STEP_IN_PROGRESS)
#define UC_MASK_DIRECTIONAL_DERIVATIVE UC_MASK_GET
#define UC_MASK_INPUT_DERIVATIVES UC_MASK_SET
#define UC_MASK_OUTPUT_DERIVATIVES                                                                           \
    (UC_STATE_STEP_COMPLETE | UC_STATE_STEP_FAILED | UC_STATE_STEP_CANCELED | UC_STATE_TERMINATED |         \
     UC_STATE_ERROR)
#define UC_MASK_DO_STEP UC_STATE_STEP_COMPLETE
#define UC_MASK_CANCEL_STEP UC_STATE_STEP_IN_PROGRESS
#define UC_MASK_GET_STATUS                                                                                   \
    (UC_STATE_STEP_COMPLETE | UC_STATE_STEP_IN_PROGRESS | UC_STATE_STEP_FAILED | UC_STATE_TERMINATED)

/* The state's name as the standard writes it ("initializationMode", "stepComplete", ...). */
const char* uc_state_name(UCMachineState state);

/* fmi2OK if state is in allowedStates; otherwise logs "<function>: illegal call sequence (called in state
 * <name>)" to log and returns fmi2Error. */
fmi2Status uc_machine_check(UCLogger* log, UCMachineState state, unsigned int allowedStates, const char* function);

/* Applies a call's status to the state: fmi2Error -> error (unless fatal), fmi2Fatal -> fatal. Returns status. */
fmi2Status uc_machine_finish(UCMachineState* state, fmi2Status status);

/* The life-cycle transitions: fmi2EnterInitializationMode, fmi2ExitInitializationMode (to stepComplete when its
 * work returned fmi2OK; returns that status), fmi2Terminate. */
void uc_machine_enter_initialization(UCMachineState* state);
fmi2Status uc_machine_exit_initialization(UCMachineState* state, fmi2Status status);
void uc_machine_terminate(UCMachineState* state);

/* In an exported function of component c (an Instance* with members state and log): runs `body` (an expression
 * of the variable inst yielding fmi2Status) if the call may be made now, applies its status and returns it. A NULL
 * instance gives fmi2Error (nothing to log to). */
#define UC_MACHINE_GUARDED(Instance, c, mask, function, body)                                               \
    do {                                                                                                     \
        Instance* inst = (Instance*)(c);                                                                     \
        if (inst == NULL) return fmi2Error;                                                                  \
        fmi2Status status = uc_machine_check(&inst->log, inst->state, (mask), (function));                   \
        if (status == fmi2OK) status = (body);                                                               \
        return uc_machine_finish(&inst->state, status);                                                      \
    } while (0)

#endif /* UNDERWATERCABLE_FMI2_MACHINE_H */
