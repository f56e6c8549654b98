/* input_checks.c - see input_checks.h. */
#include "input_checks.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "instance.h"

enum { UC_CHECK_TEXT = 640 }; /* of a log message of at most 1023 characters */

void uc_input_checks_reset(UCInputChecks* checks) {
    memset(checks, 0, sizeof *checks);
    checks->previousEnd = NAN;
}

/* ---- accelerations against the velocity inputs ---------------------------------------------------- */

/* A message built from parts (one warning per step, however many variables it names). */
typedef struct {
    char text[UC_CHECK_TEXT];
    size_t used;
    int parts;
} Report;

static void report_add(Report* r, const char* format, ...) __attribute__((format(printf, 2, 3)));
static void report_add(Report* r, const char* format, ...) {
    if (r->used + 1 >= sizeof r->text) return;
    if (r->parts++ > 0) r->used += (size_t)snprintf(r->text + r->used, sizeof r->text - r->used, "; ");
    if (r->used + 1 >= sizeof r->text) return;
    va_list args;
    va_start(args, format);
    const int n = vsnprintf(r->text + r->used, sizeof r->text - r->used, format, args);
    va_end(args);
    if (n > 0) r->used = r->used + (size_t)n < sizeof r->text ? r->used + (size_t)n : sizeof r->text - 1;
}

/* Components c of one driven quantity: accelerations a (a0 at the previous point) against the velocities v
 * (v0); the names of the acceleration and of the velocity (`%s` of each component's letter). */
typedef struct {
    const double *a, *a0, *v, *v0;
    char names[3][48], velocities[3][40]; /* e.g. tow.ax and tow.vx, der(body[1].vx) and body[1].vx */
    const char* unit;         /* m/s2 or rad/s2 */
    const char* velocityUnit; /* m/s or rad/s */
    unsigned char* warned;    /* 3 flags */
    int flags;                /* UC_ACCELERATION_AS_INPUT(k): component k is an input value, not a derivative */
} Quantity;

static void check_quantity(UCInputChecks* c, const Quantity* q, double h, Report* r) {
    for (int k = 0; k < 3; ++k) {
        const double dv = q->v[k] - q->v0[k];
        const double miss = uc_acceleration_disagreement(q->a0[k], q->a[k], dv, h);
        if (!(miss > 0.0)) continue;
        if (q->warned[k]) {
            ++c->disagreements;
            continue;
        }
        q->warned[k] = 1;
        report_add(r, "%s = %.4g %s (%.4g before) while %s changed by %.4g %s (mean %.4g %s, %.3g %s apart): %s",
                   q->names[k], q->a[k], q->unit, q->a0[k], q->velocities[k], dv, q->velocityUnit, dv / h, q->unit,
                   miss, q->unit,
                   (q->flags & UC_ACCELERATION_AS_INPUT(k)) && q->a[k] == 0.0 && q->a0[k] == 0.0 ? "taken as not set"
                                                                                                : "used as given");
    }
}

static void name_components(Quantity* q, const char* accelerationFormat, const char* velocityFormat, int index) {
    static const char letters[3] = {'x', 'y', 'z'};
    for (int k = 0; k < 3; ++k) {
        if (index > 0) {
            snprintf(q->names[k], sizeof q->names[k], accelerationFormat, index, letters[k]);
            snprintf(q->velocities[k], sizeof q->velocities[k], velocityFormat, index, letters[k]);
        } else {
            snprintf(q->names[k], sizeof q->names[k], accelerationFormat, letters[k]);
            snprintf(q->velocities[k], sizeof q->velocities[k], velocityFormat, letters[k]);
        }
    }
}

static void check_accelerations(UCInstance* inst, Report* r) {
    UCInputChecks* c = &inst->inputChecks;
    const UCInputs *in = &inst->inputs, *old = &c->previous;
    const double h = c->previousStep;
    unsigned char* warned = c->warned;
    Quantity q;
    if (!inst->coreParams.mooringSystem && in->towAccelerationGiven && old->towAccelerationGiven) {
        q = (Quantity){in->towAcceleration, old->towAcceleration, in->towVelocity, old->towVelocity, {{0}}, {{0}},
                       "m/s2", "m/s", warned, in->towAccelerationGiven};
        name_components(&q, "tow.a%c", "tow.v%c", 0);
        check_quantity(c, &q, h, r);
    }
    /* the far end's kind as the model compiled it (the core exists when a step is checked) */
    if ((uc_end_inputs(inst->cable) & UC_END_INPUTS_DRIVEN) && in->endAccelerationGiven && old->endAccelerationGiven) {
        q = (Quantity){in->endAcceleration, old->endAcceleration, in->endVelocity, old->endVelocity, {{0}}, {{0}},
                       "m/s2", "m/s", warned + 3, in->endAccelerationGiven};
        name_components(&q, "end.a%c", "end.v%c", 0);
        check_quantity(c, &q, h, r);
    }
    if (!inst->coreParams.mooringSystem) return;
    for (int b = 0; b < UC_MAX_BODIES; ++b) {
        if (!in->bodyAccelerationGiven[b] || !old->bodyAccelerationGiven[b]) continue;
        const UCCoupledBody *body = &in->coupledBody[b], *before = &old->coupledBody[b];
        q = (Quantity){in->bodyAcceleration + 6 * b, old->bodyAcceleration + 6 * b, body->velocity, before->velocity,
                       {{0}}, {{0}}, "m/s2", "m/s", warned + 6 + 6 * b, 0};
        name_components(&q, "der(body[%d].v%c)", "body[%d].v%c", b + 1);
        check_quantity(c, &q, h, r);
        q = (Quantity){in->bodyAcceleration + 6 * b + 3, old->bodyAcceleration + 6 * b + 3, body->angularVelocity,
                       before->angularVelocity, {{0}}, {{0}}, "rad/s2", "rad/s", warned + 9 + 6 * b, 0};
        name_components(&q, "der(body[%d].w%c)", "body[%d].w%c", b + 1);
        check_quantity(c, &q, h, r);
    }
    for (int p = 0; p < UC_MAX_POINTS; ++p) {
        if (!in->pointAccelerationGiven[p] || !old->pointAccelerationGiven[p]) continue;
        q = (Quantity){in->pointAcceleration + 3 * p, old->pointAcceleration + 3 * p, in->coupledPoint[p].velocity,
                       old->coupledPoint[p].velocity, {{0}}, {{0}}, "m/s2", "m/s",
                       warned + 6 + 6 * UC_MAX_BODIES + 3 * p, 0};
        name_components(&q, "der(point[%d].v%c)", "point[%d].v%c", p + 1);
        check_quantity(c, &q, h, r);
    }
}

/* ---- inputs beyond a physical bound ------------------------------------------------------------------ */

/* The largest |component| of v[0..n) beyond bound: reported once per group (flag), and remembered as the step's
 * implausible input (the integrator's budget names it). The name is format with the index k (1-based; 0: none),
 * written only when an input is beyond its bound (the checks cost comparisons, not formatting, per step). */
static void check_bound(UCInputChecks* c, Report* r, unsigned char* flag, const char* format, int k, const double* v,
                        int n, double bound, const char* unit) {
    int worst = -1;
    for (int i = 0; i < n; ++i)
        if (fabs(v[i]) > bound && (worst < 0 || fabs(v[i]) > fabs(v[worst]))) worst = i;
    if (worst < 0) return;
    char name[sizeof c->implausibleName];
    if (k > 0) {
        snprintf(name, sizeof name, format, k);
    } else {
        snprintf(name, sizeof name, "%s", format);
    }
    if (!c->implausible || fabs(v[worst]) / bound > fabs(c->implausibleValue) / c->implausibleBound) {
        c->implausible = 1;
        memcpy(c->implausibleName, name, sizeof name);
        c->implausibleValue = v[worst];
        c->implausibleUnit = unit;
        c->implausibleBound = bound;
    }
    if (*flag) return;
    *flag = 1;
    report_add(r, "%s = %.6g %s is beyond %g %s, more than a physical motion reaches (a unit or frame mistake, or a "
               "diverged partner?)", name, v[worst], unit, bound, unit);
}

static void check_bounds(UCInstance* inst, Report* r) {
    UCInputChecks* c = &inst->inputChecks;
    const UCInputs* in = &inst->inputs;
    unsigned char* f = c->bound;
    c->implausible = 0;
    c->implausibleValue = 0.0;
    c->implausibleBound = 1.0;
    if (!inst->coreParams.mooringSystem) {
        check_bound(c, r, f + 0, "tow.x/y/z", 0, in->tow, 3, UC_INPUT_MAX_POSITION, "m");
        check_bound(c, r, f + 1, "tow.vx/vy/vz", 0, in->towVelocity, 3, UC_INPUT_MAX_SPEED, "m/s");
        check_bound(c, r, f + 2, in->towAccelerationGiven ? "tow.ax/ay/az (or der(tow.v*))" : "tow.ax/ay/az", 0,
                    in->towAcceleration, 3, UC_INPUT_MAX_ACCELERATION, "m/s2");
        if (uc_end_inputs(inst->cable) & UC_END_INPUTS_EXTERNAL) { /* as the model compiled the far end */
            check_bound(c, r, f + 3, "end.x/y/z", 0, in->end, 3, UC_INPUT_MAX_POSITION, "m");
            check_bound(c, r, f + 4, "end.vx/vy/vz", 0, in->endVelocity, 3, UC_INPUT_MAX_SPEED, "m/s");
            check_bound(c, r, f + 5, "end.ax/ay/az", 0, in->endAcceleration, 3, UC_INPUT_MAX_ACCELERATION, "m/s2");
        }
    }
    check_bound(c, r, f + 6, "current.x/y", 0, in->current, 2, UC_INPUT_MAX_SPEED, "m/s");
    if (!inst->coreParams.mooringSystem) return;
    for (int b = 0; b < UC_MAX_BODIES; ++b) {
        const UCCoupledBody* body = &in->coupledBody[b];
        unsigned char* g = f + 7 + 5 * b;
        check_bound(c, r, g, "body[%d].x/y/z", b + 1, body->position, 3, UC_INPUT_MAX_POSITION, "m");
        check_bound(c, r, g + 1, "body[%d].vx/vy/vz", b + 1, body->velocity, 3, UC_INPUT_MAX_SPEED, "m/s");
        check_bound(c, r, g + 2, "body[%d].wx/wy/wz", b + 1, body->angularVelocity, 3, UC_INPUT_MAX_ANGULAR_SPEED,
                    "rad/s");
        check_bound(c, r, g + 3, "der(body[%d].vx/vy/vz)", b + 1, in->bodyAcceleration + 6 * b, 3,
                    UC_INPUT_MAX_ACCELERATION, "m/s2");
        check_bound(c, r, g + 4, "der(body[%d].wx/wy/wz)", b + 1, in->bodyAcceleration + 6 * b + 3, 3,
                    UC_INPUT_MAX_ANGULAR_ACCELERATION, "rad/s2");
    }
    for (int p = 0; p < UC_MAX_POINTS; ++p) {
        unsigned char* g = f + 7 + 5 * UC_MAX_BODIES + 3 * p;
        check_bound(c, r, g, "point[%d].x/y/z", p + 1, in->coupledPoint[p].position, 3, UC_INPUT_MAX_POSITION, "m");
        check_bound(c, r, g + 1, "point[%d].vx/vy/vz", p + 1, in->coupledPoint[p].velocity, 3, UC_INPUT_MAX_SPEED,
                    "m/s");
        check_bound(c, r, g + 2, "der(point[%d].vx/vy/vz)", p + 1, in->pointAcceleration + 3 * p, 3,
                    UC_INPUT_MAX_ACCELERATION, "m/s2");
    }
}

/* ---- driven positions against the trajectory the previous inputs extrapolated ----------------------- */

/* One driven input group: its position and velocity inputs now and at the previous communication point, where
 * the model has it now (the previous inputs extrapolated over their step), its names, and its flag. */
typedef struct {
    const double *position, *velocity, *previousPosition, *previousVelocity;
    double at[3];
    const char* name;          /* of the inputs: "tow", "end", "body[2]" ... */
    const char* what;          /* what they move: "tow point", "far end", "reference point of body[2]" ... */
    const char* inputs;        /* "tow.x/y/z", "end.x/y/z", "body[2].x/y/z" ... */
    const char* accelerations; /* "tow.a*", "end.a*", "der(body[2].v*)" ... */
} DrivenGroup;

static int check_jump(UCInstance* inst, const DrivenGroup* g, int history, double h) {
    const double dx = g->position[0] - g->at[0], dy = g->position[1] - g->at[1], dz = g->position[2] - g->at[2];
    const double distance = sqrt(dx * dx + dy * dy + dz * dz);
    if (!(distance > UC_TOW_MISMATCH_TOLERANCE)) return 0;
    /* Whether the positions agree with the velocities: the position change over the last step against the
     * velocities' trapezoid (the mean velocity of a motion whose acceleration changes little within a step). */
    char why[600] = "";
    if (history) {
        const double s = inst->inputChecks.previousStep;
        double miss2 = 0.0, change2 = 0.0;
        for (int k = 0; k < 3; ++k) {
            const double m = g->position[k] - g->previousPosition[k] - 0.5 * s * (g->velocity[k] + g->previousVelocity[k]);
            const double dv = g->velocity[k] - g->previousVelocity[k];
            miss2 += m * m;
            change2 += dv * dv;
        }
        const double miss = sqrt(miss2);
        /* The trapezoid of a smooth motion misses by about h^2 |dv| / 12 per unit of curvature; a miss larger than
         * the step's velocity change times the step is no sampling error. */
        if (miss > UC_TOW_MISMATCH_TOLERANCE && miss > 0.5 * s * sqrt(change2)) {
            snprintf(why, sizeof why, "over the last %.6g s step the position moved %.3g m away from the velocities' "
                     "trapezoid: either the positions disagree with the velocity inputs (give positions that agree with "
                     "their integral) or the step is too long for the motion (use a shorter communication step, a "
                     "tenth of the motion's shortest period or less)", s, miss);
        } else {
            snprintf(why, sizeof why, "the positions agree with the velocity inputs (within %.3g m over the last "
                     "step), so the motion changes more within a %.6g s communication step than the extrapolation "
                     "follows: use a shorter communication step (a tenth of the motion's shortest period or less) or "
                     "give the accelerations (%s)", miss, s, g->accelerations);
        }
    } else {
        snprintf(why, sizeof why, "either the communication step (%.6g s) is too long for the motion (use a tenth of "
                 "its shortest period or less) or the positions disagree with the integral of the velocity inputs", h);
    }
    uc_log_status(&inst->log, fmi2Warning,
                  "fmi2DoStep at t = %.9g: the %s position input %s = (%.6g, %.6g, %.6g) is %.3g m from where the %s "
                  "stands (%.6g, %.6g, %.6g), the previous inputs extrapolated over their step: the %s jumps there "
                  "within this step, a displacement that shows as a tension spike; %s (tolerance %g m; reported once "
                  "per run)",
                  inst->time, g->name, g->inputs, g->position[0], g->position[1], g->position[2], distance, g->what,
                  g->at[0], g->at[1], g->at[2], g->what, why, UC_TOW_MISMATCH_TOLERANCE);
    return 1;
}

/* A mooring system's numbered group (body[k] or point[k]): check_jump with its names made from the number. */
static int check_numbered_jump(UCInstance* inst, int kind, int k, const char* label, const char* whatPrefix,
                               const double* position, const double* velocity, const double* previousPosition,
                               const double* previousVelocity, int history, double h) {
    double at[3];
    if (!uc_driven_position(inst->cable, kind, k, at)) return 0;
    char name[40], what[64], inputs[48], accelerations[48];
    snprintf(name, sizeof name, "%s[%d]", label, k);
    snprintf(what, sizeof what, "%s%s[%d]", whatPrefix, label, k);
    snprintf(inputs, sizeof inputs, "%s[%d].x/y/z", label, k);
    snprintf(accelerations, sizeof accelerations, "der(%s[%d].v*)", label, k);
    const DrivenGroup g = {position, velocity, previousPosition, previousVelocity, {at[0], at[1], at[2]},
                           name, what, inputs, accelerations};
    return check_jump(inst, &g, history, h);
}

/* Every driven position the model follows, each group reported once per run: the tow point, the far end of
 * bottomEnd 3 (end.*), a mooring system's coupled bodies' reference points and coupled points. */
static int check_jumps(UCInstance* inst, int history, double h) {
    UCInputChecks* c = &inst->inputChecks;
    const UCInputs *in = &inst->inputs, *old = &c->previous;
    int warned = 0;
    double at[3];
    DrivenGroup g;
    if (!inst->coreParams.mooringSystem && !inst->towMismatchWarned) {
        g = (DrivenGroup){in->tow, in->towVelocity, old->tow, old->towVelocity, {0}, "tow", "tow point",
                          "tow.x/y/z", "tow.a*"};
        uc_tow_position(inst->cable, g.at);
        if (check_jump(inst, &g, history, h)) inst->towMismatchWarned = warned = 1;
    }
    if (!c->jumped[0] && uc_driven_position(inst->cable, UC_DRIVEN_END, 0, at)) {
        g = (DrivenGroup){in->end, in->endVelocity, old->end, old->endVelocity, {at[0], at[1], at[2]},
                          "end", "far end", "end.x/y/z", "end.a*"};
        if (check_jump(inst, &g, history, h)) c->jumped[0] = warned = 1;
    }
    if (!inst->coreParams.mooringSystem) return warned;
    for (int b = 0; b < UC_MAX_BODIES; ++b) {
        if (!c->jumped[1 + b] && check_numbered_jump(inst, UC_DRIVEN_BODY, b + 1, "body", "reference point of ",
                                                     in->coupledBody[b].position, in->coupledBody[b].velocity,
                                                     old->coupledBody[b].position, old->coupledBody[b].velocity,
                                                     history, h))
            c->jumped[1 + b] = warned = 1;
    }
    for (int p = 0; p < UC_MAX_POINTS; ++p) {
        if (!c->jumped[1 + UC_MAX_BODIES + p] &&
            check_numbered_jump(inst, UC_DRIVEN_POINT, p + 1, "point", "coupled point ", in->coupledPoint[p].position,
                                in->coupledPoint[p].velocity, old->coupledPoint[p].position,
                                old->coupledPoint[p].velocity, history, h))
            c->jumped[1 + UC_MAX_BODIES + p] = warned = 1;
    }
    return warned;
}

int uc_input_checks_before_step(UCInstance* inst, double h) {
    UCInputChecks* c = &inst->inputChecks;
    const int history = c->previousEnd == inst->time && c->previousStep > 0.0;
    Report bounds = {{0}, 0, 0}, accelerations = {{0}, 0, 0};
    check_bounds(inst, &bounds);
    if (history) check_accelerations(inst, &accelerations);
    int warned = check_jumps(inst, history, h);
    if (bounds.parts > 0) {
        uc_log_status(&inst->log, fmi2Warning, "fmi2DoStep at t = %.9g: %s (reported once per variable)", inst->time,
                      bounds.text);
        warned = 1;
    }
    if (accelerations.parts > 0) {
        uc_log_status(&inst->log, fmi2Warning,
                      "fmi2DoStep at t = %.9g: acceleration inputs disagree with the change of the velocity inputs "
                      "over the last step: %s. An input tow.a*/end.a* held at 0 while the velocity changes is taken as "
                      "not set (the FMU estimates it from the velocity inputs); any other is used as given: check its "
                      "unit, frame and sign, or leave it unset (reported once per variable; fmi2Terminate counts the later ones)",
                      inst->time, accelerations.text);
        warned = 1;
    }
    return warned;
}

void uc_input_checks_after_step(UCInstance* inst, double h) {
    UCInputChecks* c = &inst->inputChecks;
    memcpy(&c->previous, &inst->inputs, sizeof c->previous);
    c->previousStep = h;
    c->previousEnd = inst->time;
}

void uc_input_checks_summary(UCInstance* inst) {
    const UCInputChecks* c = &inst->inputChecks;
    if (c->disagreements > 0) {
        uc_log_status(&inst->log, fmi2Warning, "fmi2Terminate: acceleration inputs disagreed with the velocity inputs "
                      "at %d more communication points after they were first reported", c->disagreements);
    }
}
