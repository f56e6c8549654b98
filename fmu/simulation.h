/*
 * simulation.h - the adapter's calls into the physics core (cable_api.h): computing the initialization
 * from the current parameters and inputs, and one communication step with the FMI time checks.
 */
#ifndef UNDERWATERCABLE_FMU_SIMULATION_H
#define UNDERWATERCABLE_FMU_SIMULATION_H

#include "instance.h"

/* Relative/absolute tolerance on communication points, as in the Reference FMUs (masters accumulate
 * round-off in tc; FMI 2.0 section 4.2.4). */
#define UC_TIME_TOLERANCE 1e-5

/* Computes the initialization (uc_params_check, uc_create, uc_initialize at startTime, outputs) unless it
 * is already cached for the current parameters and inputs. Errors are logged naming `function`. */
fmi2Status uc_sim_ensure_initialized(UCInstance* inst, const char* function);

/* The outputs read in initialization mode: the initialization from the parameters and inputs set so far
 * (uc_sim_ensure_initialized; invalid parameters are errors). When the initialization itself fails (a master
 * reads outputs before it has set the inputs: a driven far end still on the tow point) it is fmi2Warning, not
 * fmi2Error, and the outputs are provisional: all 0, except that a driven far end (bottomEnd 3) is at its
 * inputs end.* / end.v*. The failure is logged once (later reads log that the outputs are still provisional);
 * the initialization is tried again when a value is set and at fmi2ExitInitializationMode (where a failure
 * is an error). */
fmi2Status uc_sim_initial_outputs(UCInstance* inst, const char* function);

/* Creates *cable for the parameters p: one line (uc_create), or the mooring system of p->lineFile
 * (p->mooringSystem); the instance itself is not changed (inst->cable neither: a restore builds into a
 * temporary). Errors are logged naming `function`. */
fmi2Status uc_sim_create_core(UCInstance* inst, const UCParams* p, UCCable** cable, const char* function);

/* Logs the core's events since the last call, each after "function: ": its warnings (a line the core starts
 * "warning: ") with status fmi2Warning, category logStatusWarning; the others as events (logEvents). */
void uc_sim_log_events(UCInstance* inst, const char* function);

/* fmi2DoStep after the state check: time checks, uc_do_step from the FMU's own time, outputs. */
fmi2Status uc_sim_do_step(UCInstance* inst, double currentCommunicationPoint, double communicationStepSize);

#endif /* UNDERWATERCABLE_FMU_SIMULATION_H */
