/*
 * vessel.c - a survey vessel in the horizontal plane (3 DOF: surge, sway, yaw) with a speed and heading
 * autopilot, towing at a tow point aft: the partner FMU "Vessel" (adapter: ../common/partner_fmi.c).
 *
 * Frames: Earth x, y horizontal, z up (as the cable FMU); heading psi from +x towards +y; body axes x
 * forward, y to port. Body velocities u (surge), v (sway), r (yaw rate). Fossen's manoeuvring model
 * with diagonal added mass, no Munk moment:
 *
 *   (m + Xa) du/dt - (m + Ya) v r = -Xu u - Xuu |u| u + thrust + Fx_tow
 *   (m + Ya) dv/dt + (m + Xa) u r = -Yv v - Yvv |v| v          + Fy_tow
 *   (Iz + Na) dr/dt               = -Nr r - Nrr |r| r + N_rudder + x_t Fy_tow - y_t Fx_tow
 *
 * F_tow = the input towForce.x/y (the cable FMU's towForce: the force of the cable on the tow point) in
 * body axes; its vertical component is not felt in the horizontal plane. Over a communication step
 * [t, t + h] the force is linear in time, from the input and the input of the step before, as the
 * parameter towForceTiming says when the master took the input (docs/cosimulation.md):
 *   1 (default) at the step's start, the meaning of an input set at a communication point (a Jacobi
 *     master: libcosim's fixed-step algorithm): extrapolated with the rate of the last two inputs,
 *     F(t + s) = F_k + (F_k - F_{k-1}) s / h_{k-1} (held in the first step);
 *   2 at the step's end (a Gauss-Seidel master that steps the cable first): interpolated from the input
 *     before, F(t + s) = F_k + (F_{k+1} - F_k) s / h;
 *   0 held, whenever it was taken: first order in h (a master that steps the vessel after the cable
 *     lets it lead by h, one that steps it first lets it lag by h).
 * Held, the force is off by half a step on average: at 1 s the vessel's sway and the heading loop's
 * integral turn that into a track 0.3 m off; linear, the error is second order. The autopilot: speed PI with feed-forward of the ordered acceleration, the
 * resistance and the measured tow force; heading PID with feed-forward of the ordered turn rate; gains
 * from pole placement on the rigid vessel (speed loop: a double pole at -speedBandwidth; heading loop:
 * a double pole at -headingBandwidth and one at -headingIntegralBandwidth, whose integral action takes
 * out the steady yaw moment of the tow, so a turn ends on its ordered heading; 0 gives the plain
 * critically damped PD); each integrator is frozen while its actuator saturates in the direction of
 * its error. Orders: speed speed0 until rampStart, linear to speed1 over rampDuration; heading
 * heading0 until turnStart, then turning at turnRate until it has changed by turnAngle.
 * Integration: classical Runge-Kutta, ceil(h / maxSubstep) substeps per communication step.
 *
 * Waves (waves.mode 1 or 2; 0, the default, leaves the vessel above untouched): the wave-frequency motion of
 * the vessel is superimposed on the manoeuvring one, which it does not feed back into (no wave forces act
 * on the 3 DOF model). The sea is the cable FMU's (sea_state.c: the same components from the same waves.*
 * parameters), the motion that of its displacement RAOs (rao_table.c: the table the parameter raoFile
 * names, by default resources/rao.csv, as the VesselRAO FMU's; read only in waves). The RAO reference
 * point is the vessel's origin (x, y) on the waterline, the motions
 * are along and about the body axes of the current heading psi (z up): a component of amplitude a,
 * frequency w, wavenumber k along the direction of travel beta and phase p has at the reference point X(t)
 * the elevation a cos(theta), theta = w t - k.X(t) - p, whose phase advances at the encounter frequency
 * we = w - k.dX/dt (exact: X is the manoeuvring position). It moves degree of freedom j by a |R_j| cos(theta
 * - phi_j), R_j = |R_j| e^(i phi_j) the RAO at the encounter period 2 pi / |we| and the relative heading
 * beta - psi(t), conjugated when we < 0 (the vessel overtakes the waves: the crests pass from the stern).
 * The tow point at r = towPoint (body axes) moves by (surge, sway, heave) + (roll, pitch, yaw) x r, turned
 * into Earth axes by psi(t). Velocity and acceleration are its time derivatives, the RAO's own rates
 * included (through dpsi/dt = r, dr/dt and dwe/dt = -k.(acceleration of X)) as the interpolation's slopes
 * within the cell of the table: the velocity is exact between the table's periods and headings (it jumps
 * where the path crosses one, as the slopes of a piecewise-linear interpolation do); the acceleration
 * leaves out the term of d2we/dt2, i.e. of the vessel's jerk, which no state gives (a relative error of
 * order (r / we)^2 k U / we in a turn at rate r and speed U). Default waves.mode 0 computes none of it
 * (today's results bit for bit, and no RAO table is read).
 *
 * Defaults: a ~20 m, 50 t survey vessel; resistance 1.25 kN at 2.4 kn and 15 kN at 10 kn; surge added
 * mass 5 % and sway 80 % of the mass; yaw inertia m (L/4)^2 with 50 % added inertia; thrust 25 kN
 * ahead, 12 kN astern; rudder moment 200 kN m; tow point on the centreline 10 m aft of the centre of
 * gravity, at the surface.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include "partner.h"
#include "rao_table.h"
#include "sea_parameters.h"
#include "sea_state.h"

static const double kTwoPi = 6.28318530717958647692;
static const double kPi = 3.14159265358979323846;

enum { X, Y, PSI, U, V, R, INTEGRAL, HEADING_INTEGRAL, N_STATES };

typedef struct VesselData {
    /* parameters */
    double mass, addedMassSurge, addedMassSway, inertiaYaw, addedInertiaYaw;
    double Xu, Xuu, Yv, Yvv, Nr, Nrr;
    double towPoint[3];
    double maxThrust, maxAstern, maxRudderMoment;
    double speedBandwidth, headingBandwidth;
    double x0, y0, heading0, speed0, speed1, rampStart, rampDuration;
    double turnStart, turnRate, turnAngle;
    double maxSubstep;
    PMSeaParameters sea; /* the waves (the cable FMU's names and meaning) */
    char raoFile[PM_STRING_CAPACITY]; /* the RAO table: "" the shipped one (rao_table.h) */
    double headingIntegralBandwidth;
    double towForceTiming; /* Integer: TowForceTiming */
    /* inputs */
    double towForce[3];
    /* states */
    double state[N_STATES];
    /* outputs */
    double tow[3], towVelocity[3], towAcceleration[3];
    double x, y, heading, surge, sway, yawRate, speed, thrust, rudderMoment;
    double waveMotion[PM_RAO_DOF], waveElevation;
    /* the tow force over the current step, stepForce + stepForceRate (t - stepStart), from the input and the
       input of the step before (previousTowForce; previousStep its step, 0 before the first step) */
    double stepForce[3], stepForceRate[3], stepStart;
    double previousTowForce[3], previousStep;
} VesselData;

/* When the master took the towForce input (the parameter towForceTiming). */
enum TowForceTiming { TOW_FORCE_HELD = 0, TOW_FORCE_AT_STEP_START = 1, TOW_FORCE_AT_STEP_END = 2 };

/* The derived data of the waves: the sea's components and the RAO table (none in calm water). */
typedef struct VesselWaves {
    size_t n;
    PMWaveComponent* sea;
    PMRAOTable table;
} VesselWaves;

typedef struct Commands {
    double thrust, moment, integralRate, headingIntegralRate;
} Commands;

static double m11(const VesselData* d) { return d->mass + d->addedMassSurge; }
static double m22(const VesselData* d) { return d->mass + d->addedMassSway; }
static double m66(const VesselData* d) { return d->inertiaYaw + d->addedInertiaYaw; }
static double surge_resistance(const VesselData* d, double u) { return d->Xu * u + d->Xuu * fabs(u) * u; }
static double clamp(double x, double lo, double hi) { return x < lo ? lo : x > hi ? hi : x; }

/* Speed order and its rate at time t. */
static void speed_order(const VesselData* d, double t, double* speed, double* rate) {
    double end = d->rampStart + d->rampDuration;
    if (t < d->rampStart) {
        *speed = d->speed0, *rate = 0.0;
    } else if (t < end) {
        *rate = (d->speed1 - d->speed0) / d->rampDuration;
        *speed = d->speed0 + *rate * (t - d->rampStart);
    } else {
        *speed = d->speed1, *rate = 0.0;
    }
}

/* Heading order and its rate at time t. */
static void heading_order(const VesselData* d, double t, double* heading, double* rate) {
    if (t <= d->turnStart || d->turnRate == 0.0) {
        *heading = d->heading0, *rate = 0.0;
    } else if (t >= d->turnStart + d->turnAngle / fabs(d->turnRate)) {
        *heading = d->heading0 + copysign(d->turnAngle, d->turnRate), *rate = 0.0;
    } else {
        *heading = d->heading0 + d->turnRate * (t - d->turnStart), *rate = d->turnRate;
    }
}

static Commands autopilot(const VesselData* d, double t, const double* x, double fxBody) {
    double w = d->speedBandwidth, uRef, aRef;
    speed_order(d, t, &uRef, &aRef);
    double e = uRef - x[U];
    double raw = m11(d) * aRef + surge_resistance(d, uRef) - fxBody + 2.0 * w * m11(d) * e +
                 w * w * m11(d) * x[INTEGRAL];
    Commands c;
    c.thrust = clamp(raw, -d->maxAstern, d->maxThrust);
    c.integralRate = (c.thrust != raw && e * raw > 0.0) ? 0.0 : e; /* anti-windup */

    /* poles -wp, -wp, -wi: (s + wp)^2 (s + wi) = s^3 + (2 wp + wi) s^2 + (wp^2 + 2 wp wi) s + wp^2 wi */
    double wp = d->headingBandwidth, wi = d->headingIntegralBandwidth, psiRef, rRef;
    heading_order(d, t, &psiRef, &rRef);
    double err = remainder(psiRef - x[PSI], kTwoPi);
    double moment = d->Nr * rRef + d->Nrr * fabs(rRef) * rRef + (wp * wp + 2.0 * wp * wi) * m66(d) * err +
                    (2.0 * wp + wi) * m66(d) * (rRef - x[R]) + wp * wp * wi * m66(d) * x[HEADING_INTEGRAL];
    c.moment = clamp(moment, -d->maxRudderMoment, d->maxRudderMoment);
    c.headingIntegralRate = (c.moment != moment && err * moment > 0.0) ? 0.0 : err; /* anti-windup */
    return c;
}

/* The Earth-frame tow force at time t of the current step (at its end after it). */
static void tow_force(const VesselData* d, double t, double* f) {
    for (int i = 0; i < 3; ++i) f[i] = d->stepForce[i] + d->stepForceRate[i] * (t - d->stepStart);
}

/* The tow force's law over the step [t, t + h] from the input and the input of the step before. */
static void begin_step(VesselData* d, double t, double h) {
    const int timing = (int)d->towForceTiming;
    for (int i = 0; i < 3; ++i) {
        const double now = d->towForce[i], before = d->previousTowForce[i];
        if (timing == TOW_FORCE_AT_STEP_END) {
            d->stepForce[i] = before;
            d->stepForceRate[i] = (now - before) / h;
        } else {
            d->stepForce[i] = now;
            d->stepForceRate[i] =
                timing == TOW_FORCE_AT_STEP_START && d->previousStep > 0.0 ? (now - before) / d->previousStep : 0.0;
        }
    }
    d->stepStart = t;
}

/* dx/dt (the tow force's x, y components used). */
static void derivatives(const VesselData* d, double t, const double* x, double* dx) {
    double c = cos(x[PSI]), s = sin(x[PSI]), f[3];
    tow_force(d, t, f);
    double fxb = c * f[0] + s * f[1], fyb = -s * f[0] + c * f[1];
    Commands cmd = autopilot(d, t, x, fxb);
    double u = x[U], v = x[V], r = x[R];
    double surge = -surge_resistance(d, u) + cmd.thrust + fxb;
    double sway = -d->Yv * v - d->Yvv * fabs(v) * v + fyb;
    double yaw = -d->Nr * r - d->Nrr * fabs(r) * r + cmd.moment + d->towPoint[0] * fyb - d->towPoint[1] * fxb;
    dx[X] = c * u - s * v;
    dx[Y] = s * u + c * v;
    dx[PSI] = r;
    dx[U] = (surge + m22(d) * v * r) / m11(d);
    dx[V] = (sway - m11(d) * u * r) / m22(d);
    dx[R] = yaw / m66(d);
    dx[INTEGRAL] = cmd.integralRate;
    dx[HEADING_INTEGRAL] = cmd.headingIntegralRate;
}

/* Adds the wave-frequency motion at time t of the vessel in the manoeuvring state x (rates dx) to the tow
   point's position, velocity and acceleration (Earth axes); the six motions and the elevation at the
   reference point to the outputs. */
static void add_wave_motion(VesselData* d, const VesselWaves* w, double t, const double* x, const double* dx,
                            double* pos, double* vel, double* acc) {
    const double c = cos(x[PSI]), s = sin(x[PSI]), r = x[R], dr = dx[R];
    const double ax = c * dx[U] - s * dx[V] - r * dx[Y], ay = s * dx[U] + c * dx[V] + r * dx[X]; /* Earth */
    const double cb = cos(d->sea.direction), sb = sin(d->sea.direction);
    const double mu = (d->sea.direction - x[PSI]) * 180.0 / kPi, dmu = -r * 180.0 / kPi, ddmu = -dr * 180.0 / kPi;
    /* the motions (q), their rates (v) and accelerations (a) without the ramp, then ramped */
    double q[PM_RAO_DOF] = {0}, v[PM_RAO_DOF] = {0}, a[PM_RAO_DOF] = {0};
    for (size_t i = 0; i < w->n; ++i) {
        const PMWaveComponent* cw = &w->sea[i];
        const double kx = cw->k * cb, ky = cw->k * sb;
        const double theta = cw->omega * t - (kx * x[X] + ky * x[Y]) - cw->phase;
        const double we = cw->omega - (kx * dx[X] + ky * dx[Y]), dwe = -(kx * ax + ky * ay);
        const double sign = we < 0.0 ? -1.0 : 1.0;
        /* the encounter period and its rates (the second without the vessel's jerk: see the header) */
        const double T = we != 0.0 ? kTwoPi / fabs(we) : HUGE_VAL, rate = we != 0.0 ? dwe / we : 0.0;
        double re[PM_RAO_DOF], im[PM_RAO_DOF], dre[PM_RAO_DOF], dim[PM_RAO_DOF], ddre[PM_RAO_DOF], ddim[PM_RAO_DOF];
        pm_rao_interpolate_rates(&w->table, T, mu, -T * rate, dmu, 2.0 * T * rate * rate, ddmu, re, im, dre, dim, ddre,
                                 ddim);
        const double ct = cw->amplitude * cos(theta), st = cw->amplitude * sin(theta);
        for (int j = 0; j < PM_RAO_DOF; ++j) {
            const double m = re[j] * ct + sign * im[j] * st, dm = sign * im[j] * ct - re[j] * st; /* dm: d/dtheta */
            q[j] += m;
            v[j] += dre[j] * ct + sign * dim[j] * st + we * dm;
            a[j] += ddre[j] * ct + sign * ddim[j] * st + 2.0 * we * (sign * dim[j] * ct - dre[j] * st) + dwe * dm -
                    we * we * m;
        }
    }
    pm_sea_ramp_signals(d->sea.rampTime, t, PM_RAO_DOF, q, v, a);
    for (int j = 0; j < PM_RAO_DOF; ++j) d->waveMotion[j] = q[j];
    /* the tow point's displacement, rate and acceleration in the body axes, which turn at r about z */
    double p[3], dp[3], ddp[3];
    pm_rao_point(q, d->towPoint, p);
    pm_rao_point(v, d->towPoint, dp);
    pm_rao_point(a, d->towPoint, ddp);
    const double vb[2] = {dp[0] - r * p[1], dp[1] + r * p[0]};
    const double ab[2] = {ddp[0] - 2.0 * r * dp[1] - dr * p[1] - r * r * p[0],
                          ddp[1] + 2.0 * r * dp[0] + dr * p[0] - r * r * p[1]};
    pos[0] += c * p[0] - s * p[1], pos[1] += s * p[0] + c * p[1], pos[2] += p[2];
    vel[0] += c * vb[0] - s * vb[1], vel[1] += s * vb[0] + c * vb[1], vel[2] += dp[2];
    acc[0] += c * ab[0] - s * ab[1], acc[1] += s * ab[0] + c * ab[1], acc[2] += ddp[2];
    d->waveElevation = pm_sea_elevation(w->sea, w->n, d->sea.direction, d->sea.rampTime, x[X], x[Y], t);
}

/* Tow point position, velocity and acceleration (rigid-body kinematics of the point (xt, yt)), with the
   wave motion superimposed in waves. */
static void update_outputs(VesselData* d, const VesselWaves* w, double t) {
    const double* x = d->state;
    double dx[N_STATES], f[3];
    derivatives(d, t, x, dx);
    tow_force(d, t, f);
    double c = cos(x[PSI]), s = sin(x[PSI]);
    double xt = d->towPoint[0], yt = d->towPoint[1];
    double wx = x[U] - x[R] * yt, wy = x[V] + x[R] * xt; /* tow point velocity, body axes */
    double ax = dx[U] - dx[R] * yt - x[R] * wy, ay = dx[V] + dx[R] * xt + x[R] * wx;
    d->tow[0] = x[X] + c * xt - s * yt;
    d->tow[1] = x[Y] + s * xt + c * yt;
    d->tow[2] = d->towPoint[2];
    d->towVelocity[0] = c * wx - s * wy;
    d->towVelocity[1] = s * wx + c * wy;
    d->towVelocity[2] = 0.0;
    d->towAcceleration[0] = c * ax - s * ay;
    d->towAcceleration[1] = s * ax + c * ay;
    d->towAcceleration[2] = 0.0;
    d->x = x[X];
    d->y = x[Y];
    d->heading = x[PSI];
    d->surge = x[U];
    d->sway = x[V];
    d->yawRate = x[R];
    d->speed = hypot(x[U], x[V]);
    Commands cmd = autopilot(d, t, x, c * f[0] + s * f[1]);
    d->thrust = cmd.thrust;
    d->rudderMoment = cmd.moment;
    if (w != NULL && w->n > 0) add_wave_motion(d, w, t, x, dx, d->tow, d->towVelocity, d->towAcceleration);
}

static void release_waves(void* derived) {
    VesselWaves* w = derived;
    if (w == NULL) return;
    free(w->sea);
    pm_rao_free(&w->table);
    free(w);
}

/* The sea's components and the RAO table; in calm water neither (nor the resources, nor raoFile). */
static void* build_waves(const void* data, const char* resources, char* msg, size_t msgSize) {
    const VesselData* d = data;
    const PMWaves waves = pm_waves_of(&d->sea);
    VesselWaves* w = calloc(1, sizeof *w);
    if (w == NULL) {
        snprintf(msg, msgSize, "out of memory");
        return NULL;
    }
    w->n = pm_sea_size(&waves);
    if (w->n == 0) return w;
    w->sea = calloc(w->n, sizeof *w->sea);
    if (w->sea == NULL) {
        snprintf(msg, msgSize, "out of memory for %zu wave components", w->n);
        release_waves(w);
        return NULL;
    }
    if (pm_sea_components(&waves, w->sea, msg, msgSize) != 0 ||
        pm_rao_load(resources, d->raoFile, &w->table, msg, msgSize) != 0) {
        release_waves(w);
        return NULL;
    }
    return w;
}

static int vessel_check(const void* data, char* msg, size_t msgSize) {
    (void)data, (void)msg, (void)msgSize; /* every parameter is independent of the others */
    return 0;
}

static int vessel_initialize(void* data, const void* derived, double t0, char* msg, size_t msgSize) {
    (void)msg, (void)msgSize;
    VesselData* d = data;
    d->state[X] = d->x0;
    d->state[Y] = d->y0;
    d->state[PSI] = d->heading0;
    d->state[U] = d->speed0;
    d->state[V] = d->state[R] = d->state[INTEGRAL] = d->state[HEADING_INTEGRAL] = 0.0;
    for (int i = 0; i < 3; ++i) {
        d->previousTowForce[i] = d->stepForce[i] = d->towForce[i];
        d->stepForceRate[i] = 0.0;
    }
    d->previousStep = 0.0;
    d->stepStart = t0;
    update_outputs(d, derived, t0);
    return 0;
}

static int vessel_do_step(void* data, const void* derived, double t, double h, char* msg, size_t msgSize) {
    (void)msg, (void)msgSize;
    VesselData* d = data;
    int n = (int)ceil(h / d->maxSubstep - 1e-12);
    if (n < 1) n = 1;
    double dt = h / n, k1[N_STATES], k2[N_STATES], k3[N_STATES], k4[N_STATES], tmp[N_STATES];
    double* x = d->state;
    begin_step(d, t, h);
    for (int i = 0; i < n; ++i) {
        double ti = t + i * dt;
        derivatives(d, ti, x, k1);
        for (int j = 0; j < N_STATES; ++j) tmp[j] = x[j] + 0.5 * dt * k1[j];
        derivatives(d, ti + 0.5 * dt, tmp, k2);
        for (int j = 0; j < N_STATES; ++j) tmp[j] = x[j] + 0.5 * dt * k2[j];
        derivatives(d, ti + 0.5 * dt, tmp, k3);
        for (int j = 0; j < N_STATES; ++j) tmp[j] = x[j] + dt * k3[j];
        derivatives(d, ti + dt, tmp, k4);
        for (int j = 0; j < N_STATES; ++j) x[j] += dt / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
    }
    for (int i = 0; i < 3; ++i) d->previousTowForce[i] = d->towForce[i];
    d->previousStep = h;
    update_outputs(d, derived, t + h);
    return 0;
}

#define P(field, name, start, min, max, unit, why, description) \
    PM_PAR(VesselData, field, name, start, min, max, unit, why, description)
#define O(field, name, unit, feedthrough, description) PM_OUT(VesselData, field, name, unit, feedthrough, description)

static const PMVariable kVariables[] = {
    P(mass, "mass", 50.0e3, 1.0, 1e9, "kg", "the vessel must have a positive mass", "Mass of the vessel"),
    P(addedMassSurge, "addedMassSurge", 2.5e3, 0.0, 1e9, "kg", "added mass cannot be negative", "Surge added mass"),
    P(addedMassSway, "addedMassSway", 40.0e3, 0.0, 1e9, "kg", "added mass cannot be negative", "Sway added mass"),
    P(inertiaYaw, "inertiaYaw", 1.25e6, 1.0, 1e13, "kg.m2", "the yaw inertia must be positive",
      "Yaw moment of inertia, m (L/4)^2"),
    P(addedInertiaYaw, "addedInertiaYaw", 0.625e6, 0.0, 1e13, "kg.m2", "added inertia cannot be negative",
      "Yaw added moment of inertia"),
    P(Xu, "Xu", 400.0, 0.0, 1e9, "N.s/m", "resistance must dissipate", "Linear surge resistance coefficient"),
    P(Xuu, "Xuu", 500.0, 0.0, 1e9, "N.s2/m2", "resistance must dissipate", "Quadratic surge resistance coefficient"),
    P(Yv, "Yv", 1.0e4, 0.0, 1e9, "N.s/m", "resistance must dissipate", "Linear sway damping coefficient"),
    P(Yvv, "Yvv", 2.0e4, 0.0, 1e9, "N.s2/m2", "resistance must dissipate",
      "Quadratic sway damping coefficient, 0.5 rho A_lateral Cd"),
    P(Nr, "Nr", 2.0e6, 0.0, 1e13, "N.m.s", "damping must dissipate", "Linear yaw damping coefficient"),
    P(Nrr, "Nrr", 2.0e7, 0.0, 1e13, "N.m.s2", "damping must dissipate", "Quadratic yaw damping coefficient"),
    P(towPoint[0], "towPoint.x", -10.0, -1e3, 1e3, "m", "the tow point must be on or near the vessel",
      "Tow point in body axes, forward of the centre of gravity"),
    P(towPoint[1], "towPoint.y", 0.0, -1e3, 1e3, "m", "the tow point must be on or near the vessel",
      "Tow point in body axes, to port"),
    P(towPoint[2], "towPoint.z", 0.0, -1e3, 1e3, "m", "the tow point must be on or near the vessel",
      "Height of the tow point (Earth z, 0 = free surface)"),
    P(maxThrust, "maxThrust", 25.0e3, 0.0, 1e9, "N", "a thrust limit cannot be negative", "Thrust limit ahead"),
    P(maxAstern, "maxAstern", 12.0e3, 0.0, 1e9, "N", "a thrust limit cannot be negative",
      "Thrust limit astern (magnitude)"),
    P(maxRudderMoment, "maxRudderMoment", 2.0e5, 0.0, 1e12, "N.m", "a moment limit cannot be negative",
      "Limit of the rudder yaw moment"),
    P(speedBandwidth, "speedBandwidth", 0.2, 1e-4, 100.0, "1/s", "the speed loop needs a positive bandwidth",
      "Bandwidth of the speed loop (critically damped PI)"),
    P(headingBandwidth, "headingBandwidth", 0.3, 1e-4, 100.0, "1/s", "the heading loop needs a positive bandwidth",
      "Bandwidth of the heading loop (its double pole; see headingIntegralBandwidth)"),
    P(x0, "x0", 0.0, -1e8, 1e8, "m", "a position on Earth", "Initial x of the centre of gravity"),
    P(y0, "y0", 0.0, -1e8, 1e8, "m", "a position on Earth", "Initial y of the centre of gravity"),
    P(heading0, "heading0", 0.0, -100.0, 100.0, "rad", "a heading within +-100 rad",
      "Initial heading and heading order before the turn (from +x towards +y)"),
    P(speed0, "speed0", 1.1 * 1852.0 / 3600.0, -30.0, 30.0, "m/s", "a speed within +-30 m/s",
      "Initial surge speed and speed order before the ramp"),
    P(speed1, "speed1", 2.4 * 1852.0 / 3600.0, -30.0, 30.0, "m/s", "a speed within +-30 m/s",
      "Speed order after the ramp"),
    P(rampStart, "rampStart", 0.0, 0.0, 1e8, "s", "the ramp starts at t >= 0", "Start of the speed ramp"),
    P(rampDuration, "rampDuration", 60.0, 0.0, 1e8, "s", "a duration cannot be negative",
      "Duration of the speed ramp (0: a step)"),
    P(turnStart, "turnStart", 0.0, 0.0, 1e8, "s", "the turn starts at t >= 0", "Start of the turn"),
    P(turnRate, "turnRate", 0.0, -1.0, 1.0, "rad/s", "a turn rate within +-1 rad/s",
      "Rate of the heading order in the turn (sign: + to port)"),
    P(turnAngle, "turnAngle", 0.0, 0.0, 1e6, "rad", "a heading change cannot be negative",
      "Heading change of the turn (a large value: a circle)"),
    P(maxSubstep, "maxSubstep", 0.05, 1e-4, 10.0, "s", "a Runge-Kutta substep within [1e-4, 10] s",
      "Largest Runge-Kutta substep inside a communication step"),
    PM_IN(VesselData, towForce[0], "towForce.x", "N", "x of the force of the cable on the tow point (cable towForce.x)"),
    PM_IN(VesselData, towForce[1], "towForce.y", "N", "y of the force of the cable on the tow point (cable towForce.y)"),
    PM_IN(VesselData, towForce[2], "towForce.z", "N", "z of the force of the cable on the tow point (not used)"),
    O(tow[0], "tow.x", "m", 0, "x of the tow point (to the cable's tow.x)"),
    O(tow[1], "tow.y", "m", 0, "y of the tow point"),
    O(tow[2], "tow.z", "m", 0, "z of the tow point"),
    O(towVelocity[0], "tow.vx", "m/s", 0, "x velocity of the tow point (to the cable's tow.vx)"),
    O(towVelocity[1], "tow.vy", "m/s", 0, "y velocity of the tow point"),
    O(towVelocity[2], "tow.vz", "m/s", 0, "z velocity of the tow point"),
    O(towAcceleration[0], "tow.ax", "m/s2", 1, "x acceleration of the tow point (the cable's der(tow.vx))"),
    O(towAcceleration[1], "tow.ay", "m/s2", 1, "y acceleration of the tow point"),
    O(towAcceleration[2], "tow.az", "m/s2", 1, "z acceleration of the tow point"),
    O(x, "x", "m", 0, "x of the centre of gravity"),
    O(y, "y", "m", 0, "y of the centre of gravity"),
    O(heading, "heading", "rad", 0, "Heading from +x towards +y"),
    O(surge, "surge", "m/s", 0, "Surge velocity u"),
    O(sway, "sway", "m/s", 0, "Sway velocity v (to port)"),
    O(yawRate, "yawRate", "rad/s", 0, "Yaw rate r"),
    O(speed, "speed", "m/s", 0, "Speed through the water, hypot(u, v)"),
    O(thrust, "thrust", "N", 1, "Thrust of the autopilot"),
    O(rudderMoment, "rudderMoment", "N.m", 0, "Rudder yaw moment of the autopilot"),
    /* the superimposed wave motion (after the variables above, whose value references stay) */
    PM_SEA_VARIABLES(VesselData, sea),
    O(waveMotion[0], "waveMotion.surge", "m", 0, "Wave-frequency surge of the RAO reference point (body x)"),
    O(waveMotion[1], "waveMotion.sway", "m", 0, "Wave-frequency sway of the RAO reference point (body y, to port)"),
    O(waveMotion[2], "waveMotion.heave", "m", 0, "Wave-frequency heave of the RAO reference point (up)"),
    O(waveMotion[3], "waveMotion.roll", "rad", 0, "Wave-frequency roll about body x (positive lifts the port side)"),
    O(waveMotion[4], "waveMotion.pitch", "rad", 0, "Wave-frequency pitch about body y (positive lowers the bow)"),
    O(waveMotion[5], "waveMotion.yaw", "rad", 0, "Wave-frequency yaw about z"),
    O(waveElevation, "waveElevation", "m", 0,
      "Elevation of the sea surface at the RAO reference point (the vessel's x, y on the waterline)"),
    PM_RAO_FILE_VARIABLE(VesselData, raoFile),
    /* after the variables above, whose value references stay */
    P(headingIntegralBandwidth, "headingIntegralBandwidth", 0.05, 0.0, 100.0, "1/s",
      "the heading loop's integral pole cannot be negative",
      "Pole of the heading loop's integral action (0: a PD without it, which leaves the tow's yaw moment as a "
      "heading error)"),
    PM_INT_PAR(VesselData, towForceTiming, "towForceTiming", 1.0, 0.0, 2.0,
               "towForceTiming is 0 (held), 1 (the input is the force at the step's start) or 2 (at its end)",
               "When the master took the towForce input, which sets the force over a step: 1 at the step's start (a "
               "Jacobi master, libcosim), extrapolated with the last two inputs' rate; 2 at its end (Gauss-Seidel, "
               "the cable stepped first), interpolated from the input before; 0 held over the step"),
};

const PMModel kPartnerModel = {
    "Vessel",
    "Survey vessel, 3 DOF (surge, sway, yaw) with speed and heading autopilot, towing a cable at a tow point aft; "
    "optionally the wave-frequency motion of its displacement RAOs superimposed",
    sizeof(VesselData),
    kVariables,
    sizeof kVariables / sizeof kVariables[0],
    vessel_check,
    vessel_initialize,
    vessel_do_step,
    build_waves,
    release_waves,
};
