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
 * RAOs: the table resources/rao.csv of the FMU (docs/waves.md): rows of period [s], relative heading [deg]
 * (the waves' direction of travel relative to the bow: 0 following seas, 90 waves travelling to port,
 * 180 head seas), then amplitude and phase for surge, sway, heave (m/m), roll, pitch, yaw (deg/m), phases
 * in degrees as lags behind the wave crest at the reference point. A component of amplitude a, frequency
 * w and phase p with the elevation a cos(w t - k.X - p) at the reference point X moves degree of freedom j
 * by a |R_j| cos(w t - k.X - p - phi_j), R_j the RAO at the component's period 2 pi / w and the relative
 * heading waves.direction - heading, interpolated linearly (complex amplitudes) in period, held constant
 * beyond the table's periods, periodic in heading. The motion is linear, as the RAOs: the tow point at r
 * (towPoint, body axes) moves by (surge, sway, heave) + (roll, pitch, yaw) x r. waves.rampTime grows the
 * motion from rest as it grows the sea (the same half cosine), velocity and acceleration its exact time
 * derivatives.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "partner.h"
#include "sea_state.h"

static const double kPi = 3.14159265358979323846;
#define RAO_FILE "rao.csv"
#define N_DOF 6

typedef struct VesselRAOData {
    /* parameters: the sea (the cable FMU's names and meaning) */
    double wavesMode, wavesHeight, wavesPeriod, wavesGamma, wavesDirection, wavesSeed, wavesNComponents;
    double wavesRampTime, waterDepth, gravity;
    /* parameters: the vessel */
    double x0, y0, heading, towPoint[3];
    /* outputs */
    double tow[3], towVelocity[3], towAcceleration[3];
    double motion[N_DOF], waveElevation;
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

/* ---- the RAO table -------------------------------------------------------------------------------- */

typedef struct RAOTable {
    size_t nPeriods, nHeadings;
    double* periods;  /* ascending */
    double* headings; /* ascending in [0, 360) */
    double* re;       /* [(iPeriod * nHeadings + iHeading) * N_DOF + j]: real and imaginary RAO, rad for angles */
    double* im;
} RAOTable;

static void free_table(RAOTable* t) {
    free(t->periods);
    free(t->headings);
    free(t->re);
    free(t->im);
    memset(t, 0, sizeof *t);
}

static int compare_doubles(const void* a, const void* b) {
    double x = *(const double*)a, y = *(const double*)b;
    return x < y ? -1 : x > y;
}

/* The sorted distinct values of v[0..n) in place; their number. */
static size_t unique_sorted(double* v, size_t n) {
    qsort(v, n, sizeof *v, compare_doubles);
    size_t m = 0;
    for (size_t i = 0; i < n; ++i)
        if (m == 0 || v[i] != v[m - 1]) v[m++] = v[i];
    return m;
}

static size_t find_index(const double* v, size_t n, double x) {
    for (size_t i = 0; i < n; ++i)
        if (v[i] == x) return i;
    return n;
}

static double normalized_heading(double deg) {
    double h = fmod(deg, 360.0);
    return h < 0.0 ? h + 360.0 : h;
}

/* Reads the RAO table from path; 0 on success, else a message naming the file and line. */
static int read_table(const char* path, RAOTable* table, char* msg, size_t msgSize) {
    memset(table, 0, sizeof *table);
    FILE* f = fopen(path, "r");
    if (f == NULL) {
        snprintf(msg, msgSize, "cannot open the RAO table %s", path);
        return 1;
    }
    size_t capacity = 0, nRows = 0;
    double* rows = NULL; /* 14 numbers per row */
    char line[1024];
    int lineNo = 0, header = 0, rc = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        ++lineNo;
        char* s = line;
        while (*s == ' ' || *s == '\t') ++s;
        if (*s == '#' || *s == '\n' || *s == '\r' || *s == '\0') continue;
        double v[14];
        int k = 0;
        char* p = s;
        for (; k < 14; ++k) {
            char* end;
            v[k] = strtod(p, &end);
            if (end == p) break;
            while (*end == ' ' || *end == '\t') ++end;
            p = end;
            if (k < 13) {
                if (*p != ',') { ++k; break; }
                ++p;
            }
        }
        while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') ++p;
        if (k == 0 && !header && nRows == 0) { /* the column names */
            header = 1;
            continue;
        }
        if (k != 14 || *p != '\0') {
            snprintf(msg, msgSize, "RAO table %s, line %d: expected 14 comma-separated numbers (period, heading, "
                     "amplitude and phase of surge, sway, heave, roll, pitch, yaw)", path, lineNo);
            rc = 1;
            break;
        }
        int bad = !(v[0] > 0.0) || !isfinite(v[0]) || !isfinite(v[1]);
        for (int j = 2; j < 14; ++j) bad |= !isfinite(v[j]) || (j % 2 == 0 && v[j] < 0.0);
        if (bad) {
            snprintf(msg, msgSize, "RAO table %s, line %d: a period must be positive, amplitudes non-negative and "
                     "every number finite", path, lineNo);
            rc = 1;
            break;
        }
        if (nRows == capacity) {
            capacity = capacity ? 2 * capacity : 256;
            double* grown = realloc(rows, capacity * 14 * sizeof *rows);
            if (grown == NULL) {
                snprintf(msg, msgSize, "RAO table %s: out of memory", path);
                rc = 1;
                break;
            }
            rows = grown;
        }
        v[1] = normalized_heading(v[1]);
        memcpy(rows + nRows * 14, v, sizeof v);
        ++nRows;
    }
    fclose(f);
    if (rc == 0 && nRows == 0) {
        snprintf(msg, msgSize, "RAO table %s has no rows", path);
        rc = 1;
    }
    if (rc == 0) {
        table->periods = malloc(nRows * sizeof(double));
        table->headings = malloc(nRows * sizeof(double));
        if (table->periods == NULL || table->headings == NULL) {
            snprintf(msg, msgSize, "RAO table %s: out of memory", path);
            rc = 1;
        }
    }
    if (rc == 0) {
        for (size_t r = 0; r < nRows; ++r) {
            table->periods[r] = rows[r * 14];
            table->headings[r] = rows[r * 14 + 1];
        }
        table->nPeriods = unique_sorted(table->periods, nRows);
        table->nHeadings = unique_sorted(table->headings, nRows);
        if (table->nPeriods * table->nHeadings != nRows) {
            snprintf(msg, msgSize, "RAO table %s: %zu rows are not one per period and heading (%zu periods x %zu "
                     "headings)", path, nRows, table->nPeriods, table->nHeadings);
            rc = 1;
        }
    }
    if (rc == 0) {
        const size_t size = nRows * N_DOF;
        table->re = calloc(size, sizeof(double));
        table->im = calloc(size, sizeof(double));
        char* seen = calloc(nRows, 1);
        if (table->re == NULL || table->im == NULL || seen == NULL) {
            snprintf(msg, msgSize, "RAO table %s: out of memory", path);
            rc = 1;
        }
        for (size_t r = 0; rc == 0 && r < nRows; ++r) {
            const double* v = rows + r * 14;
            const size_t cell = find_index(table->periods, table->nPeriods, v[0]) * table->nHeadings +
                                find_index(table->headings, table->nHeadings, v[1]);
            if (seen[cell]) {
                snprintf(msg, msgSize, "RAO table %s: period %g s and heading %g deg appear twice", path, v[0], v[1]);
                rc = 1;
                break;
            }
            seen[cell] = 1;
            for (int j = 0; j < N_DOF; ++j) {
                const double amplitude = v[2 + 2 * j] * (j >= 3 ? kPi / 180.0 : 1.0);
                const double lag = v[3 + 2 * j] * kPi / 180.0;
                table->re[cell * N_DOF + j] = amplitude * cos(lag);
                table->im[cell * N_DOF + j] = amplitude * sin(lag);
            }
        }
        free(seen);
    }
    free(rows);
    if (rc != 0) free_table(table);
    return rc;
}

/* Linear interpolation weights of x in the ascending v[0..n): i0, i1 and the weight of i1 (held beyond). */
static void bracket(const double* v, size_t n, double x, size_t* i0, size_t* i1, double* w) {
    if (n == 1 || x <= v[0]) {
        *i0 = *i1 = 0, *w = 0.0;
        return;
    }
    if (x >= v[n - 1]) {
        *i0 = *i1 = n - 1, *w = 0.0;
        return;
    }
    size_t i = 0;
    while (v[i + 1] < x) ++i;
    *i0 = i, *i1 = i + 1, *w = (x - v[i]) / (v[i + 1] - v[i]);
}

/* The same, periodic over [0, 360) degrees. */
static void bracket_heading(const double* v, size_t n, double x, size_t* i0, size_t* i1, double* w) {
    if (n == 1) {
        *i0 = *i1 = 0, *w = 0.0;
        return;
    }
    if (x >= v[0] && x <= v[n - 1]) {
        bracket(v, n, x, i0, i1, w);
        return;
    }
    const double span = v[0] + 360.0 - v[n - 1]; /* from the last heading round to the first */
    const double d = x >= v[n - 1] ? x - v[n - 1] : x + 360.0 - v[n - 1];
    *i0 = n - 1, *i1 = 0, *w = d / span;
}

/* The complex RAO (re, im) of every degree of freedom at period T [s] and relative heading mu [deg]. */
static void interpolate(const RAOTable* t, double T, double mu, double* re, double* im) {
    size_t p0, p1, h0, h1;
    double wp, wh;
    bracket(t->periods, t->nPeriods, T, &p0, &p1, &wp);
    bracket_heading(t->headings, t->nHeadings, normalized_heading(mu), &h0, &h1, &wh);
    const size_t c00 = (p0 * t->nHeadings + h0) * N_DOF, c01 = (p0 * t->nHeadings + h1) * N_DOF;
    const size_t c10 = (p1 * t->nHeadings + h0) * N_DOF, c11 = (p1 * t->nHeadings + h1) * N_DOF;
    for (int j = 0; j < N_DOF; ++j) {
        re[j] = (1 - wp) * ((1 - wh) * t->re[c00 + j] + wh * t->re[c01 + j]) +
                wp * ((1 - wh) * t->re[c10 + j] + wh * t->re[c11 + j]);
        im[j] = (1 - wp) * ((1 - wh) * t->im[c00 + j] + wh * t->im[c01 + j]) +
                wp * ((1 - wh) * t->im[c10 + j] + wh * t->im[c11 + j]);
    }
}

/* ---- the model ------------------------------------------------------------------------------------ */

static PMWaves waves_of(const VesselRAOData* d) {
    PMWaves w;
    w.mode = (int)d->wavesMode;
    w.height = d->wavesHeight;
    w.period = d->wavesPeriod;
    w.gamma = d->wavesGamma;
    w.direction = d->wavesDirection;
    w.seed = (uint64_t)d->wavesSeed;
    w.nComponents = (int)d->wavesNComponents;
    w.rampTime = d->wavesRampTime;
    w.depth = d->waterDepth;
    w.gravity = d->gravity;
    return w;
}

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
    if (resources == NULL) {
        snprintf(msg, msgSize, "no resources directory was given to fmi2Instantiate: the RAO table " RAO_FILE
                 " is in the FMU's resources");
        return NULL;
    }
    char path[4096];
    if ((size_t)snprintf(path, sizeof path, "%s/%s", resources, RAO_FILE) >= sizeof path) {
        snprintf(msg, msgSize, "the resources path is too long");
        return NULL;
    }
    RAOTable table;
    if (read_table(path, &table, msg, msgSize) != 0) return NULL;
    const PMWaves w = waves_of(d);
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
        free_table(&table);
        return NULL;
    }
    if (pm_sea_components(&w, r->sea, msg, msgSize) != 0) {
        release(r);
        free_table(&table);
        return NULL;
    }
    const double cb = cos(d->wavesDirection), sb = sin(d->wavesDirection);
    const double mu = (d->wavesDirection - d->heading) * 180.0 / kPi;
    for (size_t i = 0; i < n; ++i) {
        const PMWaveComponent* c = &r->sea[i];
        double re[N_DOF], im[N_DOF];
        interpolate(&table, 2.0 * kPi / c->omega, mu, re, im);
        const double kX = c->k * cb * d->x0 + c->k * sb * d->y0;
        r->omega[i] = c->omega;
        for (int j = 0; j < N_DOF; ++j) {
            r->amplitude[j][i] = c->amplitude * hypot(re[j], im[j]);
            r->phase[j][i] = kX + c->phase + atan2(im[j], re[j]);
        }
    }
    free_table(&table);
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
    double f, df, ddf;
    pm_sea_ramp(d->wavesRampTime, t, &f, &df, &ddf);
    for (int j = 0; j < N_DOF; ++j) {
        const double s0 = s[j], v0 = v[j], a0 = a[j];
        s[j] = f * s0;
        v[j] = f * v0 + df * s0;
        a[j] = f * a0 + 2.0 * df * v0 + ddf * s0;
        d->motion[j] = s[j];
    }
    /* the tow point: translation + rotation x lever arm, body axes, then turned by the heading */
    const double* p = d->towPoint;
    double body[3][3]; /* position offset, velocity, acceleration in body axes */
    const double* q[3] = {s, v, a};
    for (int k = 0; k < 3; ++k) {
        const double* x = q[k];
        body[k][0] = x[0] + x[4] * p[2] - x[5] * p[1];
        body[k][1] = x[1] + x[5] * p[0] - x[3] * p[2];
        body[k][2] = x[2] + x[3] * p[1] - x[4] * p[0];
    }
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
    d->waveElevation = pm_sea_elevation(r->sea, r->n, d->wavesDirection, d->wavesRampTime, d->x0, d->y0, t);
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
#define I(field, name, start, min, max, why, description) \
    PM_INT_PAR(VesselRAOData, field, name, start, min, max, why, description)
#define O(field, name, unit, description) PM_OUT(VesselRAOData, field, name, unit, 0, description)

static const PMVariable kVariables[] = {
    I(wavesMode, "waves.mode", 0, 0, 2, "unknown wave model",
      "Waves: 0 calm, 1 regular Airy wave (waves.height H, waves.period T), 2 irregular JONSWAP sea (Hs, Tp)"),
    P(wavesHeight, "waves.height", 0.0, 0.0, 40.0, "m", "the wave height is a length between 0 and 40 m",
      "Wave height H (regular) or significant wave height Hs (JONSWAP)"),
    P(wavesPeriod, "waves.period", 10.0, 1e-3, 60.0, "s", "the wave period is a positive time up to 60 s",
      "Wave period T (regular) or peak period Tp (JONSWAP)"),
    P(wavesGamma, "waves.gamma", 3.3, 1.0, 10.0, NULL,
      "the JONSWAP peak enhancement factor is between 1 (Pierson-Moskowitz) and 10",
      "JONSWAP peak enhancement factor (1: Pierson-Moskowitz)"),
    P(wavesDirection, "waves.direction", 0.0, -7.0, 7.0, "rad", "the direction of travel is an angle",
      "Direction in which the waves travel, from +x toward +y"),
    I(wavesSeed, "waves.seed", 1, 0, 999999999, "the seed is a non-negative integer",
      "Seed of the random phases of the irregular sea (SplitMix64: the same sea as the cable FMU's)"),
    I(wavesNComponents, "waves.nComponents", 200, 1, 5000, "the irregular sea has 1 to 5000 components",
      "Number of wave components of the irregular sea (equal frequency bands over 0.5 to 3 times the peak "
      "frequency)"),
    P(wavesRampTime, "waves.rampTime", 0.0, 0.0, 1e6, "s", "the ramp time is a non-negative time",
      "Time over which the waves and the motion grow from calm (half a cosine); 0: full waves from the start"),
    P(waterDepth, "waterDepth", 1000.0, 1e-3, 12000.0, "m", "the seabed lies below the surface",
      "Water depth (wave dispersion)"),
    P(gravity, "gravity", 9.81, 0.0, 100.0, "m/s2", "gravity points along -z; give its magnitude",
      "Gravitational acceleration (wave dispersion)"),
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
