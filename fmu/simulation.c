/* simulation.c - see simulation.h. */
#include "simulation.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "line_file.h"

static double time_tolerance(double t) { return UC_TIME_TOLERANCE * fmax(1.0, fabs(t)); }

static void log_solver_statistics(const UCInstance* inst, const char* when) {
    const UCOutputs* o = &inst->outputs;
    uc_log(&inst->log, fmi2OK, UC_LOG_SOLVER,
           "%s t = %.9g: steps %.0f, residual evaluations %.0f, Jacobian evaluations %.0f, "
           "nonlinear failures %.0f, error test failures %.0f",
           when, inst->time, o->nSteps, o->nResidualEvals, o->nJacobianEvals, o->nNonlinearFailures,
           o->nErrorTestFailures);
}

void uc_sim_log_events(UCInstance* inst, const char* function) {
    char prefix[128];
    if (!uc_take_event(inst->cable, inst->msg, sizeof inst->msg)) return;
    snprintf(prefix, sizeof prefix, "%s: ", function);
    uc_log_lines(&inst->log, prefix, inst->msg);
}

static fmi2Status fail_with_core_message(UCInstance* inst, const char* function, const char* what,
                                        fmi2Status status) {
    uc_log_status(&inst->log, status, "%s: %s: %s", function, what,
                  inst->msg[0] != '\0' ? inst->msg : "(no reason given)");
    uc_instance_drop_core(inst);
    return status;
}

/* The water the importer pushed (water.source 1) to the core, for its time t: refused (fmi2Error, logged) in FMI
 * 2.0, with arrays shorter than the lines' load points, or with a value that is not a number. */
static fmi2Status push_water(UCInstance* inst, const char* function, double t) {
    const size_t n = uc_water_points(inst->cable);
    if (n == 0) return fmi2OK;
    if (inst->water[0] == NULL) {
        uc_log_status(&inst->log, fmi2Error, "%s: water.source = 1 (water pushed by the importer) needs the FMI 3.0 "
                      "arrays waterVelocity.* and waterAcceleration.*, which this FMI 2.0 interface does not have: use "
                      "the FMI 3.0 FMU, or water.source = 0 (the FMU's own current and waves)", function);
        return fmi2Error;
    }
    if (n > inst->waterCapacity) {
        uc_log_status(&inst->log, fmi2Error, "%s: water.source = 1: the lines have %zu load points (3 per element), "
                      "more than nWaterPoints = %zu, the length of the water arrays: set nWaterPoints to %zu in "
                      "configuration mode (at most %d)", function, n, inst->waterCapacity, n, UC_MAX_WATER_POINTS);
        return fmi2Error;
    }
    static const char* const names[6] = {"waterVelocity.x", "waterVelocity.y", "waterVelocity.z",
                                         "waterAcceleration.x", "waterAcceleration.y", "waterAcceleration.z"};
    for (int c = 0; c < 6; ++c)
        for (size_t i = 0; i < n; ++i)
            if (!isfinite(inst->water[c][i])) {
                uc_log_status(&inst->log, fmi2Error, "%s: %s[%zu] = %g %s is not a number: the importer's water at "
                              "waterPoint[%zu] (water.source = 1) must be finite", function, names[c], i + 1,
                              inst->water[c][i], c < 3 ? "m/s" : "m/s2", i + 1);
                return fmi2Error;
            }
    uc_set_water(inst->cable, t, inst->water, inst->water + 3);
    return fmi2OK;
}

/* The initialization from the present parameters and inputs. Invalid parameters are errors; a failure of the
 * initialization itself (which the inputs may still change) is logged and returned with status `failure`. */
static fmi2Status initialize_core(UCInstance* inst, const char* function, fmi2Status failure) {
    if (inst->coreReady) return fmi2OK;
    uc_instance_drop_core(inst);
    inst->msg[0] = '\0';
    memcpy(&inst->coreParams, &inst->params, sizeof inst->coreParams);
    const int fromFile = inst->params.lineFile[0] != '\0';
    if (fromFile && uc_line_file_load(inst, &inst->coreParams, function) != fmi2OK) {
        uc_instance_drop_core(inst);
        return fmi2Error;
    }
    /* waves.mode 3: the components of waves.file, over a deck's */
    if (inst->coreParams.wavesMode == 3 && inst->coreParams.wavesFile[0] != '\0' &&
        uc_wave_file_load(inst, &inst->coreParams, function) != fmi2OK) {
        uc_instance_drop_core(inst);
        return fmi2Error;
    }
    if (uc_params_check(&inst->coreParams, inst->msg, sizeof inst->msg) != 0) {
        return fail_with_core_message(inst, function,
                                      fromFile ? "invalid parameter (with the line of lineFile)" : "invalid parameter",
                                      fmi2Error);
    }
    if (inst->coreParams.mooringSystem) {
        if (uc_sim_create_core(inst, &inst->coreParams, &inst->cable, function) != fmi2OK) {
            uc_instance_drop_core(inst);
            return fmi2Error;
        }
    } else {
        inst->cable = uc_create(&inst->coreParams, inst->msg, sizeof inst->msg);
        if (inst->cable == NULL) return fail_with_core_message(inst, function, "cannot create the cable model", fmi2Error);
        if (uc_current_file_load(inst, &inst->coreParams, inst->cable, function) != fmi2OK ||
            uc_seabed_file_load(inst, &inst->coreParams, inst->cable, function) != fmi2OK) {
            uc_instance_drop_core(inst);
            return fmi2Error;
        }
    }
    if (push_water(inst, function, inst->startTime) != fmi2OK) {
        uc_instance_drop_core(inst);
        return fmi2Error;
    }
    if (uc_initialize(inst->cable, inst->startTime, &inst->inputs, inst->msg, sizeof inst->msg) != 0) {
        return fail_with_core_message(inst, function, "initialization failed", failure);
    }
    uc_get_outputs(inst->cable, &inst->outputs);
    inst->time = inst->startTime;
    inst->lastSuccessfulTime = inst->startTime;
    inst->coreReady = 1;
    inst->towMismatchWarned = 0;
    uc_input_checks_reset(&inst->inputChecks);
    uc_log(&inst->log, fmi2OK, UC_LOG_EVENTS, "%s: initialized at t = %.9g, towTension = %.6g N", function,
           inst->time, inst->outputs.towTension);
    /* what the initialization found worth a word (a static strain beyond steel's: a warning) */
    uc_sim_log_events(inst, function);
    log_solver_statistics(inst, "initialization");
    return fmi2OK;
}

fmi2Status uc_sim_ensure_initialized(UCInstance* inst, const char* function) {
    return initialize_core(inst, function, fmi2Error);
}

fmi2Status uc_sim_initial_outputs(UCInstance* inst, const char* function) {
    if (inst->coreReady) return fmi2OK;
    if (inst->outputsProvisional) { /* nothing has been set since it failed: not tried again */
        uc_log_status(&inst->log, fmi2Warning, "%s: the outputs are still provisional (nothing set since)", function);
        return fmi2Warning;
    }
    const fmi2Status status = initialize_core(inst, function, fmi2Warning);
    if (status != fmi2Warning) return status;
    memset(&inst->outputs, 0, sizeof inst->outputs);
    /* The parameter, not the model's far end: the failed initialization dropped the core (no model to ask),
     * and the adapter, in C, sees only the parameters until a model is built from them. */
    if (inst->params.bottomEnd == UC_BOTTOM_EXTERNAL) {
        memcpy(inst->outputs.endPosition, inst->inputs.end, sizeof inst->outputs.endPosition);
        memcpy(inst->outputs.endVelocity, inst->inputs.endVelocity, sizeof inst->outputs.endVelocity);
    }
    inst->outputsProvisional = 1;
    uc_log_status(&inst->log, fmi2Warning,
                  "%s: the outputs are provisional until the parameters and inputs set so far give an "
                  "initialization (all 0, a driven far end at its inputs); it is computed again when a value is "
                  "set and at fmi2ExitInitializationMode",
                  function);
    return fmi2Warning;
}

fmi2Status uc_sim_create_core(UCInstance* inst, const UCParams* p, UCCable** cable, const char* function) {
    inst->msg[0] = '\0';
    if (p->mooringSystem) {
        if (uc_line_file_create_system(inst, p, cable, function) != fmi2OK) return fmi2Error;
    } else {
        *cable = uc_create(p, inst->msg, sizeof inst->msg);
        if (*cable == NULL) {
            uc_log_status(&inst->log, fmi2Error, "%s: cannot create the cable model: %s", function, inst->msg);
            return fmi2Error;
        }
    }
    /* the current's data are parameters outside the saved state: read again for a new core */
    if (uc_current_file_load(inst, p, *cable, function) != fmi2OK || uc_seabed_file_load(inst, p, *cable, function) != fmi2OK) {
        uc_free(*cable);
        *cable = NULL;
        return fmi2Error;
    }
    return fmi2OK;
}

static fmi2Status check_step_arguments(UCInstance* inst, double tc, double h) {
    if (!(fabs(tc - inst->time) <= time_tolerance(inst->time))) {
        uc_log_status(&inst->log, fmi2Error,
                      "fmi2DoStep: currentCommunicationPoint = %.17g but the FMU is at t = %.17g "
                      "(tolerance %g)",
                      tc, inst->time, time_tolerance(inst->time));
        return fmi2Error;
    }
    if (!(h > 0.0) || !isfinite(h)) {
        uc_log_status(&inst->log, fmi2Error, "fmi2DoStep: communicationStepSize = %g must be positive and finite",
                      h);
        return fmi2Error;
    }
    if (!(h >= UC_MIN_STEP_SIZE) || !(tc + h > tc)) {
        uc_log_status(&inst->log, fmi2Error,
                      "fmi2DoStep: communicationStepSize = %g is shorter than the shortest step the FMU takes "
                      "(%g s, or one that does not advance currentCommunicationPoint = %.17g)",
                      h, UC_MIN_STEP_SIZE, tc);
        return fmi2Error;
    }
    if (inst->stopTimeDefined && tc + h > inst->stopTime + time_tolerance(inst->stopTime)) {
        uc_log_status(&inst->log, fmi2Error, "fmi2DoStep: step to t = %.17g goes past stopTime = %.17g", tc + h,
                      inst->stopTime);
        return fmi2Error;
    }
    return fmi2OK;
}

fmi2Status uc_sim_do_step(UCInstance* inst, double tc, double h) {
    fmi2Status status = check_step_arguments(inst, tc, h);
    if (status != fmi2OK) return status;
    inst->msg[0] = '\0';
    /* accelerations against velocities, the tow point against its extrapolation, bounds: logged warnings (the
     * step itself is fine: fmi2DoStep returns what it did) */
    uc_input_checks_before_step(inst, h);
    /* The FMU's own time, not tc: the master's tc carries its round-off (FMI 2.0 section 4.2.4). */
    const UCInputChecks* checks = &inst->inputChecks;
    inst->inputs.stepBudget = checks->implausible ? UC_IMPLAUSIBLE_STEP_BUDGET : 0;
    uc_set_stop_at_breaks(inst->cable, inst->earlyReturnAllowed);
    if (push_water(inst, "fmi2DoStep", inst->time) != fmi2OK) return fmi2Error;
    if (uc_do_step(inst->cable, inst->time, h, &inst->inputs, inst->msg, sizeof inst->msg) != 0) {
        if (checks->implausible) {
            uc_log_status(&inst->log, fmi2Error, "fmi2DoStep: step from t = %.17g to %.17g failed with %s = %.6g %s "
                          "beyond %g %s (a physical bound; at most %d integrator steps while an input is beyond "
                          "one): check that input's unit and frame: %s", inst->time, inst->time + h,
                          checks->implausibleName, checks->implausibleValue, checks->implausibleUnit,
                          checks->implausibleBound, checks->implausibleUnit, UC_IMPLAUSIBLE_STEP_BUDGET,
                          inst->msg[0] != '\0' ? inst->msg : "(no reason given)");
            return fmi2Error;
        }
        uc_log_status(&inst->log, fmi2Error, "fmi2DoStep: step from t = %.17g to %.17g failed: %s", inst->time,
                      inst->time + h, inst->msg[0] != '\0' ? inst->msg : "(no reason given)");
        return fmi2Error;
    }
    inst->time = uc_time(inst->cable);
    inst->lastSuccessfulTime = inst->time;
    uc_input_checks_after_step(inst, h);
    uc_get_outputs(inst->cable, &inst->outputs);
    /* the step's events; its warnings with status fmi2Warning, while fmi2DoStep returns fmi2OK: the step was
     * taken (as for the input checks' warnings) */
    uc_sim_log_events(inst, "fmi2DoStep");
    /* Input derivatives apply to one step only (fmi2SetRealInputDerivatives before each fmi2DoStep). */
    memset(inst->inputs.towAcceleration, 0, sizeof inst->inputs.towAcceleration);
    inst->inputs.towAccelerationGiven = 0;
    memset(inst->inputs.endAcceleration, 0, sizeof inst->inputs.endAcceleration);
    inst->inputs.endAccelerationGiven = 0;
    memset(inst->inputs.currentRate, 0, sizeof inst->inputs.currentRate);
    inst->inputs.currentScaleRate = 0.0;
    inst->inputs.winchRateRate = 0.0;
    memset(inst->inputs.bodyAcceleration, 0, sizeof inst->inputs.bodyAcceleration);
    memset(inst->inputs.bodyAccelerationGiven, 0, sizeof inst->inputs.bodyAccelerationGiven);
    memset(inst->inputs.pointAcceleration, 0, sizeof inst->inputs.pointAcceleration);
    memset(inst->inputs.pointAccelerationGiven, 0, sizeof inst->inputs.pointAccelerationGiven);
    log_solver_statistics(inst, "fmi2DoStep");
    return fmi2OK;
}
