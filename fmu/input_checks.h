/*
 * input_checks.h - what the adapter checks in the inputs at each communication point, before the step, with
 * warnings (never refusals: the inputs are the master's): accelerations that contradict the change of the
 * velocity inputs over the last step, a driven position (the tow point, end.*, body[k].*, point[k].*) far from
 * where the previous inputs put it
 * (a step too long for the motion, or positions that contradict the velocities), and inputs beyond a
 * physical bound. Each is reported once per variable per run (docs/interface.md, "How the FMU reads a driven
 * end"). The checks compare with the inputs of the previous communication point, which the adapter keeps; a
 * restored state (another time) starts the comparison afresh. They cost a few dozen comparisons per step.
 */
#ifndef UNDERWATERCABLE_FMU_INPUT_CHECKS_H
#define UNDERWATERCABLE_FMU_INPUT_CHECKS_H

#include "api/cable_api.h"

/* Bounds beyond which an input is not a physical motion (a unit or frame mistake, a diverged partner). */
#define UC_INPUT_MAX_POSITION 1e6       /* m: the anchor's range */
#define UC_INPUT_MAX_SPEED 50.0         /* m/s: about 100 kn, beyond any vessel, towed body or current */
#define UC_INPUT_MAX_ACCELERATION 981.0 /* m/s2: 100 g */
#define UC_INPUT_MAX_ANGULAR_SPEED 10.0 /* rad/s: a body turning about 1.6 times a second */
#define UC_INPUT_MAX_ANGULAR_ACCELERATION 100.0 /* rad/s2 */

/* Integrator steps a communication step may take while an input is beyond its bound: the step then ends
 * with an error naming the input rather than after minutes of ever shorter steps. */
#define UC_IMPLAUSIBLE_STEP_BUDGET 5000

/* What the checks keep between communication points (a member of UCInstance). */
typedef struct UCInputChecks {
    UCInputs previous;    /* the inputs of the last step */
    double previousStep;  /* its size */
    double previousEnd;   /* the time it ended at: the comparison holds while the FMU is there (NaN: none) */
    unsigned char warned[UC_MAX_BODIES * 6 + UC_MAX_POINTS * 3 + 6]; /* acceleration disagreement reported */
    unsigned char bound[7 + 5 * UC_MAX_BODIES + 3 * UC_MAX_POINTS]; /* which groups were reported beyond a bound */
    unsigned char jumped[1 + UC_MAX_BODIES + UC_MAX_POINTS]; /* a jump of end.*, body[k].*, point[k].* reported */
    int disagreements;    /* further disagreements after the first report of each variable */
    int implausible;      /* an input of the coming step is beyond its bound (the step's integrator budget) */
    char implausibleName[96]; /* ... which one, and its value */
    double implausibleValue;
    const char* implausibleUnit;
    double implausibleBound;
} UCInputChecks;

struct UCInstance;

/* A new run (initialization): nothing to compare with, nothing reported. */
void uc_input_checks_reset(UCInputChecks* checks);

/* Before the step of size h at the FMU's time: the checks, each reported once (logged with fmi2Warning) per
 * run. Returns 1 if it logged one, else 0. */
int uc_input_checks_before_step(struct UCInstance* inst, double h);

/* After a successful step: the inputs it used become the previous ones. */
void uc_input_checks_after_step(struct UCInstance* inst, double h);

/* fmi2Terminate: how many more disagreements there were after each variable's first report (logged). */
void uc_input_checks_summary(struct UCInstance* inst);

#endif /* UNDERWATERCABLE_FMU_INPUT_CHECKS_H */
