/*
 * sea_state.h - the wave components of the sea, in C: the regular wave or the JONSWAP discretization,
 * the finite-depth dispersion and the SplitMix64 phases, the one implementation of both the cable's sea
 * state (its kinematics in waves.cpp) and the partner FMUs' (fmu/partners/sea), so that a partner given
 * the same waves.* parameters sees the same sea as the cable (tests/core/test_partner_sea_state.cpp).
 * The ramp here is the cable's too; its elevation (waves.cpp, with the phases cached per time) is the same sum.
 *
 * Convention: a component of amplitude a, frequency w, wavenumber k, direction of travel beta (from +x
 * toward +y) and phase p has the elevation a cos(k (x cos beta + y sin beta) - w t + p); the regular wave
 * has p = 0 (a crest at the origin at t = 0).
 */
#ifndef UNDERWATERCABLE_SEA_STATE_H
#define UNDERWATERCABLE_SEA_STATE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct PMWaves {
    int mode;             /* 0 calm, 1 regular Airy, 2 JONSWAP */
    double height;        /* H or Hs [m] */
    double period;        /* T or Tp [s] */
    double gamma;         /* JONSWAP peak enhancement */
    double direction;     /* direction of travel [rad] */
    uint64_t seed;        /* SplitMix64 seed of the irregular phases */
    int nComponents;      /* components of the irregular sea */
    double rampTime;      /* [s], half a cosine from calm; 0: none */
    double depth;         /* water depth [m] */
    double gravity;       /* [m/s2] */
} PMWaves;

typedef struct PMWaveComponent {
    double amplitude, omega, k, phase;
} PMWaveComponent;

/* The wavenumber of frequency omega in water of the given depth: omega^2 = g k tanh(k h), Newton. */
double pm_wave_number(double omega, double depth, double gravity);

/* SplitMix64: the next 64-bit output, and a uniform double in [0, 1) from its top 53 bits. */
uint64_t pm_splitmix64_next(uint64_t* state);
double pm_splitmix64_uniform(uint64_t* state);

/* The number of components of the sea (0: calm; the largest is max(1, nComponents)). */
size_t pm_sea_size(const PMWaves* w);

/* Fills out[0 .. pm_sea_size(w)) with the components; 0 on success, non-zero with a message naming the
   parameter when the sea cannot be built (a breaking regular or peak wave, H / wavelength > 1/7). */
int pm_sea_components(const PMWaves* w, PMWaveComponent* out, char* msg, size_t msgSize);

/* The ramp factor of time t and its first two time derivatives (rampTime <= 0: 1, 0, 0). */
void pm_sea_ramp(double rampTime, double t, double* f, double* df, double* ddf);

/* Ramps n signals s (in place) with their first and second time derivatives v, a: f s, (f s)', (f s)''. */
void pm_sea_ramp_signals(double rampTime, double t, size_t n, double* s, double* v, double* a);

/* The elevation at (x, y) and time t of n components travelling along direction (ramp included). */
double pm_sea_elevation(const PMWaveComponent* c, size_t n, double direction, double rampTime, double x, double y,
                        double t);

#ifdef __cplusplus
}
#endif

#endif /* UNDERWATERCABLE_SEA_STATE_H */
