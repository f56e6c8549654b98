/*
 * towfish.c - a towed body as a third party would ship it: an FMI 2.0 co-simulation FMU "Towfish",
 * written without any of the project's code and built outside its CMake (build.sh next to this file
 * calls the C compiler directly and zips the FMU). It is what the cable must couple to when the body
 * integrates itself: cable force in, position and velocity out, nothing else.
 *
 * Model (Earth frame, z up; u = current - v the relative water velocity):
 *   (m + ma_i) dv_i/dt = F_cable,i + 1/2 rho CdA_i |u| u_i - lift_i + (rho V - m) g delta_iz
 *   lift = 1/2 rho CLA |u_h|^2 e_z (a depressor of fixed attitude in the horizontal flow u_h, pulling down)
 * with the added mass ma_i = addedMass + addedMass.{x,y,z} and the drag area CdA_i = CdA + CdA.{x,y,z}
 * (isotropic values plus extras per axis). The cable force is held over a communication step; the
 * translation is integrated by classical Runge-Kutta (4th order) in substeps of at most maxSubstep.
 * FMU state: get/set/free and serialization (the whole instance data is the state).
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"

#define GUID "{6a3c1f0e-7d2b-4f5a-9c1e-0b7e2d4a8f31}"

/* Value references (modelDescription.xml lists the same). */
enum {
    VR_MASS, VR_ADDED_MASS, VR_ADDED_MASS_X, VR_ADDED_MASS_Y, VR_ADDED_MASS_Z, VR_VOLUME, VR_CDA, VR_CDA_X,
    VR_CDA_Y, VR_CDA_Z, VR_CLA, VR_RHO, VR_G, VR_POS0_X, VR_POS0_Y, VR_POS0_Z, VR_VEL0_X, VR_VEL0_Y, VR_VEL0_Z,
    VR_MAX_SUBSTEP,
    VR_FORCE_X, VR_FORCE_Y, VR_FORCE_Z, VR_CURRENT_X, VR_CURRENT_Y,
    VR_POS_X, VR_POS_Y, VR_POS_Z, VR_VEL_X, VR_VEL_Y, VR_VEL_Z,
    N_REALS
};

enum Phase { INSTANTIATED, INITIALIZING, STEPPING, TERMINATED };

typedef struct {
    double r[N_REALS];
    double x[6]; /* position, velocity */
    double time;
    int phase;
} Data;

typedef struct {
    Data d;
    fmi2CallbackFunctions cb;
    char name[128];
} Towfish;

static void say(Towfish* f, fmi2Status s, const char* fmt, ...) {
    if (f->cb.logger == NULL) return;
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    f->cb.logger(f->cb.componentEnvironment, f->name, s, s == fmi2OK ? "info" : "error", "%s", msg);
}

static void forces_and_acceleration(const Data* d, const double* v, double* a) {
    const double* r = d->r;
    double u[3] = {r[VR_CURRENT_X] - v[0], r[VR_CURRENT_Y] - v[1], -v[2]};
    double speed = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    double half_rho = 0.5 * r[VR_RHO];
    for (int i = 0; i < 3; ++i) {
        double cda = r[VR_CDA] + r[VR_CDA_X + i];
        double inertia = r[VR_MASS] + r[VR_ADDED_MASS] + r[VR_ADDED_MASS_X + i];
        double f = r[VR_FORCE_X + i] + half_rho * cda * speed * u[i];
        if (i == 2) {
            f -= half_rho * r[VR_CLA] * (u[0] * u[0] + u[1] * u[1]);
            f += (r[VR_RHO] * r[VR_VOLUME] - r[VR_MASS]) * r[VR_G];
        }
        a[i] = f / inertia;
    }
}

static void rhs(const Data* d, const double* x, double* dx) {
    for (int i = 0; i < 3; ++i) dx[i] = x[3 + i];
    forces_and_acceleration(d, x + 3, dx + 3);
}

static void publish(Data* d) {
    for (int i = 0; i < 3; ++i) {
        d->r[VR_POS_X + i] = d->x[i];
        d->r[VR_VEL_X + i] = d->x[3 + i];
    }
}

static void start(Data* d) {
    for (int i = 0; i < 3; ++i) {
        d->x[i] = d->r[VR_POS0_X + i];
        d->x[3 + i] = d->r[VR_VEL0_X + i];
    }
    publish(d);
}

static void set_defaults(Data* d) {
    memset(d, 0, sizeof *d);
    d->r[VR_MASS] = 400.0;
    d->r[VR_ADDED_MASS] = 100.0;
    d->r[VR_VOLUME] = 0.1;
    d->r[VR_CDA] = 0.3;
    d->r[VR_RHO] = 1025.0;
    d->r[VR_G] = 9.81;
    d->r[VR_MAX_SUBSTEP] = 0.01;
    start(d);
}

/* ---- FMI 2.0 ---- */
const char* fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char* fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String cats[]) {
    (void)c, (void)on, (void)n, (void)cats;
    return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String location,
                              const fmi2CallbackFunctions* cb, fmi2Boolean visible, fmi2Boolean logging) {
    (void)location, (void)visible, (void)logging;
    if (cb == NULL || type != fmi2CoSimulation || guid == NULL || strcmp(guid, GUID) != 0) return NULL;
    Towfish* f = calloc(1, sizeof *f);
    if (f == NULL) return NULL;
    memcpy((void*)&f->cb, cb, sizeof *cb);
    snprintf(f->name, sizeof f->name, "%s", name ? name : "towfish");
    set_defaults(&f->d);
    return f;
}

void fmi2FreeInstance(fmi2Component c) { free(c); }

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean tolDefined, fmi2Real tol, fmi2Real t0,
                               fmi2Boolean stopDefined, fmi2Real tStop) {
    (void)tolDefined, (void)tol, (void)stopDefined, (void)tStop;
    ((Towfish*)c)->d.time = t0;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    Towfish* f = c;
    f->d.phase = INITIALIZING;
    start(&f->d);
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    Towfish* f = c;
    start(&f->d);
    f->d.phase = STEPPING;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) {
    ((Towfish*)c)->d.phase = TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) {
    set_defaults(&((Towfish*)c)->d);
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real value[]) {
    Towfish* f = c;
    for (size_t i = 0; i < n; ++i) {
        if (vr[i] >= N_REALS) {
            say(f, fmi2Error, "fmi2GetReal: no Real with value reference %u", vr[i]);
            return fmi2Error;
        }
        value[i] = f->d.r[vr[i]];
    }
    return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real value[]) {
    Towfish* f = c;
    for (size_t i = 0; i < n; ++i) {
        if (vr[i] >= VR_POS_X) {
            say(f, fmi2Error, "fmi2SetReal: value reference %u is not a parameter or an input", vr[i]);
            return fmi2Error;
        }
        if (vr[i] < VR_FORCE_X && f->d.phase == STEPPING) {
            say(f, fmi2Error, "fmi2SetReal: value reference %u is a fixed parameter", vr[i]);
            return fmi2Error;
        }
        f->d.r[vr[i]] = value[i];
    }
    if (f->d.phase == INITIALIZING || f->d.phase == INSTANTIATED) start(&f->d);
    return fmi2OK;
}

static fmi2Status no_such(fmi2Component c, const char* what) {
    say(c, fmi2Error, "%s: the Towfish has only Real variables", what);
    return fmi2Error;
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Integer v[]) {
    (void)vr, (void)v;
    return n ? no_such(c, "fmi2GetInteger") : fmi2OK;
}
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Boolean v[]) {
    (void)vr, (void)v;
    return n ? no_such(c, "fmi2GetBoolean") : fmi2OK;
}
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2String v[]) {
    (void)vr, (void)v;
    return n ? no_such(c, "fmi2GetString") : fmi2OK;
}
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer v[]) {
    (void)vr, (void)v;
    return n ? no_such(c, "fmi2SetInteger") : fmi2OK;
}
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Boolean v[]) {
    (void)vr, (void)v;
    return n ? no_such(c, "fmi2SetBoolean") : fmi2OK;
}
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2String v[]) {
    (void)vr, (void)v;
    return n ? no_such(c, "fmi2SetString") : fmi2OK;
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean noSetPrior) {
    (void)noSetPrior;
    Towfish* f = c;
    Data* d = &f->d;
    if (d->phase != STEPPING || !(h > 0.0)) {
        say(f, fmi2Error, "fmi2DoStep: not in step mode or a step of %g s", h);
        return fmi2Error;
    }
    int n = (int)ceil(h / d->r[VR_MAX_SUBSTEP] - 1e-9);
    if (n < 1) n = 1;
    double dt = h / n, k1[6], k2[6], k3[6], k4[6], y[6];
    for (int s = 0; s < n; ++s) {
        rhs(d, d->x, k1);
        for (int j = 0; j < 6; ++j) y[j] = d->x[j] + 0.5 * dt * k1[j];
        rhs(d, y, k2);
        for (int j = 0; j < 6; ++j) y[j] = d->x[j] + 0.5 * dt * k2[j];
        rhs(d, y, k3);
        for (int j = 0; j < 6; ++j) y[j] = d->x[j] + dt * k3[j];
        rhs(d, y, k4);
        for (int j = 0; j < 6; ++j) d->x[j] += dt / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
    }
    for (int j = 0; j < 6; ++j) {
        if (!isfinite(d->x[j])) {
            say(f, fmi2Error, "fmi2DoStep: the state is not finite at t = %g s", t + h);
            return fmi2Error;
        }
    }
    d->time = t + h;
    publish(d);
    return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component c) { return no_such(c, "fmi2CancelStep (no asynchronous steps)"); }

/* ---- FMU state: a copy of the instance data ---- */
fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* state) {
    Towfish* f = c;
    if (*state == NULL) *state = malloc(sizeof(Data));
    if (*state == NULL) return fmi2Error;
    memcpy(*state, &f->d, sizeof(Data));
    return fmi2OK;
}
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state) {
    if (state == NULL) return fmi2Error;
    memcpy(&((Towfish*)c)->d, state, sizeof(Data));
    return fmi2OK;
}
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* state) {
    (void)c;
    free(*state);
    *state = NULL;
    return fmi2OK;
}
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate state, size_t* size) {
    (void)c, (void)state;
    *size = sizeof(Data);
    return fmi2OK;
}
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte bytes[], size_t size) {
    (void)c;
    if (size != sizeof(Data)) return fmi2Error;
    memcpy(bytes, state, sizeof(Data));
    return fmi2OK;
}
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte bytes[], size_t size, fmi2FMUstate* state) {
    (void)c;
    if (size != sizeof(Data)) return fmi2Error;
    *state = malloc(sizeof(Data));
    if (*state == NULL) return fmi2Error;
    memcpy(*state, bytes, sizeof(Data));
    return fmi2OK;
}

/* ---- not provided ---- */
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu,
                                        const fmi2ValueReference k[], size_t nk, const fmi2Real dk[], fmi2Real du[]) {
    (void)u, (void)nu, (void)k, (void)nk, (void)dk, (void)du;
    return no_such(c, "fmi2GetDirectionalDerivative (not provided)");
}
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                       const fmi2Integer order[], const fmi2Real v[]) {
    (void)vr, (void)n, (void)order, (void)v;
    return no_such(c, "fmi2SetRealInputDerivatives (canInterpolateInputs is false)");
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                        const fmi2Integer order[], fmi2Real v[]) {
    (void)vr, (void)n, (void)order, (void)v;
    return no_such(c, "fmi2GetRealOutputDerivatives (maxOutputDerivativeOrder is 0)");
}
fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status* v) {
    (void)s, (void)v;
    return no_such(c, "fmi2GetStatus");
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real* v) {
    (void)s, (void)v;
    return no_such(c, "fmi2GetRealStatus");
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer* v) {
    (void)s, (void)v;
    return no_such(c, "fmi2GetIntegerStatus");
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean* v) {
    (void)s, (void)v;
    return no_such(c, "fmi2GetBooleanStatus");
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String* v) {
    (void)s, (void)v;
    return no_such(c, "fmi2GetStringStatus");
}
