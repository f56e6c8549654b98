/* sea_state.c - see sea_state.h. */
#include "sea_state.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const double kPi = 3.14159265358979323846;

double pm_wave_number(double omega, double depth, double gravity) {
    double k = omega * omega / gravity; /* deep water */
    if (k * depth < 10.0) k = fmax(k, omega / sqrt(gravity * depth));
    for (int i = 0; i < 100; ++i) {
        const double th = tanh(k * depth);
        const double f = gravity * k * th - omega * omega;
        const double df = gravity * (th + k * depth * (1.0 - th * th));
        const double step = f / df;
        k -= step;
        if (fabs(step) <= 1e-15 * k) break;
    }
    return k;
}

uint64_t pm_splitmix64_next(uint64_t* state) {
    uint64_t z = (*state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

double pm_splitmix64_uniform(uint64_t* state) { return (double)(pm_splitmix64_next(state) >> 11) * 0x1.0p-53; }

/* JONSWAP spectral shape (unscaled) at omega for peak wp and peakedness gamma. */
static double jonswap_shape(double w, double wp, double gamma) {
    const double sigma = w <= wp ? 0.07 : 0.09;
    const double r = exp(-(w - wp) * (w - wp) / (2.0 * sigma * sigma * wp * wp));
    return pow(w, -5.0) * exp(-1.25 * pow(wp / w, 4.0)) * pow(gamma, r);
}

size_t pm_sea_size(const PMWaves* w) {
    if (w->mode == 0 || w->height == 0.0) return 0;
    if (w->mode == 1) return 1;
    return w->nComponents > 0 ? (size_t)w->nComponents : 1;
}

int pm_sea_components(const PMWaves* w, PMWaveComponent* out, char* msg, size_t msgSize) {
    const size_t n = pm_sea_size(w);
    if (n == 0) return 0;
    const double g = w->gravity;
    if (!(g > 0.0)) {
        snprintf(msg, msgSize, "gravity = %.17g: waves need gravity, it sets their wavelength (w^2 = g k tanh(k h))", g);
        return 1;
    }
    const double wp = 2.0 * kPi / w->period;
    const double kp = pm_wave_number(wp, w->depth, g);
    const double steepness = w->height * kp / (2.0 * kPi);
    if (steepness > 1.0 / 7.0) {
        snprintf(msg, msgSize,
                 "waves.height = %.17g is too steep for waves.period = %.17g s in %.17g m of water: H / lambda = "
                 "%.3g exceeds the breaking limit 1/7 (lambda = %.4g m)",
                 w->height, w->period, w->depth, steepness, 2.0 * kPi / kp);
        return 1;
    }
    if (w->mode == 1) {
        out[0].amplitude = 0.5 * w->height;
        out[0].omega = wp;
        out[0].k = kp;
        out[0].phase = 0.0;
        return 0;
    }
    /* JONSWAP: n components at the midpoints of equal bands over [0.5, 3] wp, amplitudes sqrt(2 S dw) with
       S scaled so that 4 sqrt(m0) = Hs; phases 2 pi u from the seed. The shape values wait in amplitude. */
    const double w0 = 0.5 * wp, w1 = 3.0 * wp, dw = (w1 - w0) / (double)n;
    double m0 = 0.0;
    for (size_t i = 0; i < n; ++i) {
        out[i].amplitude = jonswap_shape(w0 + ((double)i + 0.5) * dw, wp, w->gamma);
        m0 += out[i].amplitude * dw;
    }
    const double scale = w->height * w->height / 16.0 / m0;
    uint64_t state = w->seed;
    for (size_t i = 0; i < n; ++i) {
        const double om = w0 + ((double)i + 0.5) * dw;
        out[i].amplitude = sqrt(2.0 * scale * out[i].amplitude * dw);
        out[i].omega = om;
        out[i].k = pm_wave_number(om, w->depth, g);
        out[i].phase = 2.0 * kPi * pm_splitmix64_uniform(&state);
    }
    return 0;
}

void pm_sea_ramp(double rampTime, double t, double* f, double* df, double* ddf) {
    if (!(rampTime > 0.0) || t >= rampTime) {
        *f = 1.0, *df = 0.0, *ddf = 0.0;
    } else if (t <= 0.0) {
        *f = 0.0, *df = 0.0, *ddf = 0.0;
    } else {
        const double c = kPi / rampTime;
        *f = 0.5 * (1.0 - cos(c * t));
        *df = 0.5 * c * sin(c * t);
        *ddf = 0.5 * c * c * cos(c * t);
    }
}

void pm_sea_ramp_signals(double rampTime, double t, size_t n, double* s, double* v, double* a) {
    double f, df, ddf;
    pm_sea_ramp(rampTime, t, &f, &df, &ddf);
    for (size_t j = 0; j < n; ++j) {
        const double s0 = s[j], v0 = v[j], a0 = a[j];
        s[j] = f * s0;
        v[j] = f * v0 + df * s0;
        a[j] = f * a0 + 2.0 * df * v0 + ddf * s0;
    }
}

double pm_sea_elevation(const PMWaveComponent* c, size_t n, double direction, double rampTime, double x, double y,
                        double t) {
    if (n == 0) return 0.0;
    const double cb = cos(direction), sb = sin(direction);
    double eta = 0.0;
    for (size_t i = 0; i < n; ++i) { /* cos(k.x - (w t - p)), as the cable's sum */
        const double phi = c[i].omega * t - c[i].phase;
        const double kx = c[i].k * cb * x + c[i].k * sb * y;
        eta += c[i].amplitude * (cos(kx) * cos(phi) + sin(kx) * sin(phi));
    }
    double f, df, ddf;
    pm_sea_ramp(rampTime, t, &f, &df, &ddf);
    return f * eta;
}
