/*
 * vessel_rao.c - the wave-frequency motion of a vessel holding station in waves, from its displacement
 * RAOs: the partner FMU "VesselRAO" (adapter: ../common/partner_fmi.c). It generates the sea from the same
 * waves.* parameters as the cable FMU (sea_state.c: the same components, frequencies, wavenumbers and
 * phases), so that the vessel and the cable see one sea, and gives the 6-DOF motion of a tow point at a
 * lever arm: position, velocity and acceleration for the cable's tow.* inputs and der(tow.v*).
 *
 * Frames: Earth x, y horizontal, z up (as the cable FMU); the vessel's mean position (x0, y0) at the
 * waterline is the RAO reference point, its heading psi from +x toward +y; body axes x forward, y to port,
 * z up. Motions of the reference point: surge, sway, heave [m] along the body axes, roll, pitch, yaw [rad]
 * about them (right-handed: positive roll lifts the port side, positive pitch lowers the bow).
 *
 * RAOs: the table the parameter raoFile names, by default resources/rao.csv of the FMU (docs/waves.md; read
 * and interpolated by ../sea/rao_table.c, as for the Vessel FMU's superimposed wave motion): rows of period
 * [s], relative heading [deg] (the waves' direction of travel relative to the bow: 0 following seas, 90 waves
 * travelling to port, 180 head seas), then amplitude and phase for surge, sway, heave (m/m), roll, pitch, yaw
 * (deg/m), phases in degrees as lags behind the wave crest at the reference point. A component of amplitude
 * a, frequency w and phase p with the elevation a cos(w t - k.X - p) at the reference point X moves degree of
 * freedom j by a |R_j| cos(w t - k.X - p - phi_j), R_j the RAO at the component's period 2 pi / w and the
 * relative heading waves.direction - heading, interpolated linearly (complex amplitudes) in period, held
 * constant beyond the table's periods, periodic in heading. The motion is linear, as the RAOs: the tow point
 * at r (towPoint, body axes) moves by (surge, sway, heave) + (roll, pitch, yaw) x r; the outputs platform.*
 * give the reference point's pose and rates in the Earth frame for a mooring FMU's coupled body (the
 * small angles about the Earth's axes, the yaw on top of the heading). waves.rampTime grows the
 * motion from rest as it grows the sea (the same half cosine), velocity and acceleration its exact time
 * derivatives.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "partner.h"
#include "rao_table.h"
#include "sea_parameters.h"
#include "sea_state.h"

static const double kPi = 3.14159265358979323846;
#define N_DOF PM_RAO_DOF

typedef struct VesselRAOData {
    PMSeaParameters sea; /* parameters: the sea (the cable FMU's names and meaning) */
    /* parameters: the vessel */
    double x0, y0, heading, towPoint[3];
    char raoFile[PM_STRING_CAPACITY]; /* the RAO table: "" the shipped one (rao_table.h) */
    /* outputs */
    double tow[3], towVelocity[3], towAcceleration[3];
    double motion[N_DOF], waveElevation;
    /* the reference point's pose in the Earth frame and its rates, for a mooring FMU's body[k].* inputs */
    double platform[N_DOF], platformRate[N_DOF], platformAcceleration[N_DOF];
} VesselRAOData;

/* The derived data: per wave component its frequency and, per degree of freedom, the motion amplitude
   a |R_j| and phase k.X + p + phi_j; the components themselves for the elevation. */
typedef struct VesselRAODerived {
    size_t n;
    PMWaveComponent* sea;
    double* omega;
    double* amplitude[N_DOF];
    double* phase[N_DOF];
} VesselRAODerived;

/* ---- the model ------------------------------------------------------------------------------------ */

static void release(void* derived) {
    VesselRAODerived* r = derived;
    if (r == NULL) return;
    free(r->sea);
    free(r->omega);
    for (int j = 0; j < N_DOF; ++j) {
        free(r->amplitude[j]);
        free(r->phase[j]);
    }
    free(r);
}

static void* build(const void* data, const char* resources, char* msg, size_t msgSize) {
    const VesselRAOData* d = data;
    PMRAOTable table;
    if (pm_rao_load(resources, d->raoFile, &table, msg, msgSize) != 0) return NULL;
    const PMWaves w = pm_waves_of(&d->sea);
    const size_t n = pm_sea_size(&w);
    VesselRAODerived* r = calloc(1, sizeof *r);
    int ok = r != NULL;
    if (ok) {
        r->n = n;
        const size_t m = n > 0 ? n : 1;
        r->sea = calloc(m, sizeof *r->sea);
        r->omega = calloc(m, sizeof(double));
        ok = r->sea != NULL && r->omega != NULL;
        for (int j = 0; j < N_DOF; ++j) {
            r->amplitude[j] = calloc(m, sizeof(double));
            r->phase[j] = calloc(m, sizeof(double));
            ok = ok && r->amplitude[j] != NULL && r->phase[j] != NULL;
        }
    }
    if (!ok) {
        snprintf(msg, msgSize, "out of memory for %zu wave components", n);
        release(r);
        pm_rao_free(&table);
        return NULL;
    }
    if (pm_sea_components(&w, r->sea, msg, msgSize) != 0) {
        release(r);
        pm_rao_free(&table);
        return NULL;
    }
    const double cb = cos(d->sea.direction), sb = sin(d->sea.direction);
    const double mu = (d->sea.direction - d->heading) * 180.0 / kPi;
    for (size_t i = 0; i < n; ++i) {
        const PMWaveComponent* c = &r->sea[i];
        double re[N_DOF], im[N_DOF];
        pm_rao_interpolate(&table, 2.0 * kPi / c->omega, mu, re, im);
        const double kX = c->k * cb * d->x0 + c->k * sb * d->y0;
        r->omega[i] = c->omega;
        for (int j = 0; j < N_DOF; ++j) {
            r->amplitude[j][i] = c->amplitude * hypot(re[j], im[j]);
            r->phase[j][i] = kX + c->phase + atan2(im[j], re[j]);
        }
    }
    pm_rao_free(&table);
    return r;
}

static void update_outputs(VesselRAOData* d, const VesselRAODerived* r, double t) {
    /* the motions (s), their rates (v) and accelerations (a) without the ramp, then ramped */
    double s[N_DOF] = {0}, v[N_DOF] = {0}, a[N_DOF] = {0};
    for (size_t i = 0; i < r->n; ++i) {
        const double w = r->omega[i];
        for (int j = 0; j < N_DOF; ++j) {
            const double A = r->amplitude[j][i], th = w * t - r->phase[j][i];
            const double c = cos(th), sn = sin(th);
            s[j] += A * c;
            v[j] -= A * w * sn;
            a[j] -= A * w * w * c;
        }
    }
    pm_sea_ramp_signals(d->sea.rampTime, t, N_DOF, s, v, a);
    for (int j = 0; j < N_DOF; ++j) d->motion[j] = s[j];
    /* the tow point: translation + rotation x lever arm, body axes, then turned by the heading */
    const double* p = d->towPoint;
    double body[3][3]; /* position offset, velocity, acceleration in body axes */
    const double* q[3] = {s, v, a};
    for (int k = 0; k < 3; ++k) pm_rao_point(q[k], p, body[k]);
    body[0][0] += p[0], body[0][1] += p[1], body[0][2] += p[2];
    const double ch = cos(d->heading), sh = sin(d->heading);
    double* out[3] = {d->tow, d->towVelocity, d->towAcceleration};
    for (int k = 0; k < 3; ++k) {
        out[k][0] = ch * body[k][0] - sh * body[k][1];
        out[k][1] = sh * body[k][0] + ch * body[k][1];
        out[k][2] = body[k][2];
    }
    d->tow[0] += d->x0;
    d->tow[1] += d->y0;
    /* the reference point: translations and roll/pitch turned by the heading (small rotations about the
       Earth's axes, to first order as the RAOs are), yaw on top of the heading */
    const double* motion[3] = {s, v, a};
    double* pose[3] = {d->platform, d->platformRate, d->platformAcceleration};
    for (int k = 0; k < 3; ++k) {
        for (int j = 0; j < N_DOF; j += 3) {
            pose[k][j] = ch * motion[k][j] - sh * motion[k][j + 1];
            pose[k][j + 1] = sh * motion[k][j] + ch * motion[k][j + 1];
            pose[k][j + 2] = motion[k][j + 2];
        }
    }
    d->platform[0] += d->x0;
    d->platform[1] += d->y0;
    d->platform[5] += d->heading;
    d->waveElevation = pm_sea_elevation(r->sea, r->n, d->sea.direction, d->sea.rampTime, d->x0, d->y0, t);
}

static int vessel_rao_check(const void* data, char* msg, size_t msgSize) {
    (void)data, (void)msg, (void)msgSize; /* the parameters are independent; the sea's steepness is checked in build */
    return 0;
}

static int vessel_rao_initialize(void* data, const void* derived, double t0, char* msg, size_t msgSize) {
    (void)msg, (void)msgSize;
    update_outputs(data, derived, t0);
    return 0;
}

static int vessel_rao_do_step(void* data, const void* derived, double t, double h, char* msg, size_t msgSize) {
    (void)msg, (void)msgSize;
    update_outputs(data, derived, t + h);
    return 0;
}

#define P(field, name, start, min, max, unit, why, description) \
    PM_PAR(VesselRAOData, field, name, start, min, max, unit, why, description)
#define O(field, name, unit, description) PM_OUT(VesselRAOData, field, name, unit, 0, description)

static const PMVariable kVariables[] = {
    PM_SEA_VARIABLES(VesselRAOData, sea),
    P(x0, "x0", 0.0, -1e8, 1e8, "m", "a position on Earth", "x of the vessel's mean position (the RAO reference point)"),
    P(y0, "y0", 0.0, -1e8, 1e8, "m", "a position on Earth", "y of the vessel's mean position (the RAO reference point)"),
    P(heading, "heading", 0.0, -100.0, 100.0, "rad", "a heading within +-100 rad",
      "Heading of the vessel, from +x towards +y (relative wave heading: waves.direction - heading)"),
    P(towPoint[0], "towPoint.x", -30.0, -1e3, 1e3, "m", "the tow point must be on or near the vessel",
      "Tow point in body axes from the RAO reference point, forward"),
    P(towPoint[1], "towPoint.y", 0.0, -1e3, 1e3, "m", "the tow point must be on or near the vessel",
      "Tow point in body axes from the RAO reference point, to port"),
    P(towPoint[2], "towPoint.z", 0.0, -1e3, 1e3, "m", "the tow point must be on or near the vessel",
      "Tow point in body axes from the RAO reference point (at the waterline), up"),
    O(tow[0], "tow.x", "m", "x of the tow point (to the cable's tow.x)"),
    O(tow[1], "tow.y", "m", "y of the tow point"),
    O(tow[2], "tow.z", "m", "z of the tow point"),
    O(towVelocity[0], "tow.vx", "m/s", "x velocity of the tow point (to the cable's tow.vx)"),
    O(towVelocity[1], "tow.vy", "m/s", "y velocity of the tow point"),
    O(towVelocity[2], "tow.vz", "m/s", "z velocity of the tow point"),
    O(towAcceleration[0], "tow.ax", "m/s2", "x acceleration of the tow point (the cable's der(tow.vx))"),
    O(towAcceleration[1], "tow.ay", "m/s2", "y acceleration of the tow point"),
    O(towAcceleration[2], "tow.az", "m/s2", "z acceleration of the tow point"),
    O(motion[0], "surge", "m", "Surge of the RAO reference point (body x)"),
    O(motion[1], "sway", "m", "Sway of the RAO reference point (body y, to port)"),
    O(motion[2], "heave", "m", "Heave of the RAO reference point (up)"),
    O(motion[3], "roll", "rad", "Roll about body x (positive lifts the port side)"),
    O(motion[4], "pitch", "rad", "Pitch about body y (positive lowers the bow)"),
    O(motion[5], "yaw", "rad", "Wave-frequency yaw about z"),
    O(waveElevation, "waveElevation", "m", "Elevation of the sea surface at the RAO reference point (x0, y0)"),
    PM_RAO_FILE_VARIABLE(VesselRAOData, raoFile),
    O(platform[0], "platform.x", "m", "x of the RAO reference point, Earth frame (to a mooring FMU's body[k].x)"),
    O(platform[1], "platform.y", "m", "y of the RAO reference point, Earth frame"),
    O(platform[2], "platform.z", "m", "z of the RAO reference point (its heave)"),
    O(platform[3], "platform.roll", "rad", "Roll and pitch turned to the Earth's x axis (to body[k].roll)"),
    O(platform[4], "platform.pitch", "rad", "Roll and pitch turned to the Earth's y axis (to body[k].pitch)"),
    O(platform[5], "platform.yaw", "rad", "Heading plus yaw (to body[k].yaw)"),
    O(platformRate[0], "platform.vx", "m/s", "x velocity of the RAO reference point (to body[k].vx)"),
    O(platformRate[1], "platform.vy", "m/s", "y velocity of the RAO reference point"),
    O(platformRate[2], "platform.vz", "m/s", "z velocity of the RAO reference point"),
    O(platformRate[3], "platform.wx", "rad/s", "Angular velocity about the Earth's x axis (to body[k].wx)"),
    O(platformRate[4], "platform.wy", "rad/s", "Angular velocity about the Earth's y axis"),
    O(platformRate[5], "platform.wz", "rad/s", "Angular velocity about z"),
    O(platformAcceleration[0], "platform.ax", "m/s2", "x acceleration of the RAO reference point (der(body[k].vx))"),
    O(platformAcceleration[1], "platform.ay", "m/s2", "y acceleration of the RAO reference point"),
    O(platformAcceleration[2], "platform.az", "m/s2", "z acceleration of the RAO reference point"),
    O(platformAcceleration[3], "platform.alphax", "rad/s2", "Angular acceleration about the Earth's x axis (der(body[k].wx))"),
    O(platformAcceleration[4], "platform.alphay", "rad/s2", "Angular acceleration about the Earth's y axis"),
    O(platformAcceleration[5], "platform.alphaz", "rad/s2", "Angular acceleration about z"),
};

const PMModel kPartnerModel = {
    "VesselRAO",
    "Vessel holding station in waves: 6-DOF wave-frequency motion of a tow point from displacement RAOs and the "
    "cable FMU's sea state",
    sizeof(VesselRAOData),
    kVariables,
    sizeof kVariables / sizeof kVariables[0],
    vessel_rao_check,
    vessel_rao_initialize,
    vessel_rao_do_step,
    build,
    release,
};
