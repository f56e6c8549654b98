/*
 * sea_parameters.h - the sea's parameters of a partner FMU that moves with the waves, under the cable FMU's
 * names, types and ranges (waves.mode, waves.height, waves.period, waves.gamma, waves.direction, waves.seed,
 * waves.nComponents, waves.rampTime, waterDepth, gravity): one block of doubles in the model's data, its
 * variable-table entries, and the sea (sea_state.h) they describe.
 */
#ifndef UNDERWATERCABLE_SEA_PARAMETERS_H
#define UNDERWATERCABLE_SEA_PARAMETERS_H

#include <stdint.h>

#include "partner.h"
#include "sea_state.h"

/* Doubles, as every value of a partner model's data (Integers hold integers). */
typedef struct PMSeaParameters {
    double mode, height, period, gamma, direction, seed, nComponents, rampTime, depth, gravity;
} PMSeaParameters;

static inline PMWaves pm_waves_of(const PMSeaParameters* p) {
    PMWaves w;
    w.mode = (int)p->mode;
    w.height = p->height;
    w.period = p->period;
    w.gamma = p->gamma;
    w.direction = p->direction;
    w.seed = (uint64_t)p->seed;
    w.nComponents = (int)p->nComponents;
    w.rampTime = p->rampTime;
    w.depth = p->depth;
    w.gravity = p->gravity;
    return w;
}

/* The variable-table entries of the PMSeaParameters `field` of the model data type T. */
#define PM_SEA_VARIABLES(T, field)                                                                              \
    PM_INT_PAR(T, field.mode, "waves.mode", 0, 0, 2, "unknown wave model",                                      \
               "Waves: 0 calm, 1 regular Airy wave (waves.height H, waves.period T), 2 irregular JONSWAP sea "   \
               "(Hs, Tp)"),                                                                                     \
    PM_PAR(T, field.height, "waves.height", 0.0, 0.0, 40.0, "m", "the wave height is a length between 0 and 40 m", \
           "Wave height H (regular) or significant wave height Hs (JONSWAP)"),                                  \
    PM_PAR(T, field.period, "waves.period", 10.0, 1e-3, 60.0, "s", "the wave period is a positive time up to 60 s", \
           "Wave period T (regular) or peak period Tp (JONSWAP)"),                                              \
    PM_PAR(T, field.gamma, "waves.gamma", 3.3, 1.0, 10.0, NULL,                                                 \
           "the JONSWAP peak enhancement factor is between 1 (Pierson-Moskowitz) and 10",                        \
           "JONSWAP peak enhancement factor (1: Pierson-Moskowitz)"),                                           \
    PM_PAR(T, field.direction, "waves.direction", 0.0, -7.0, 7.0, "rad", "the direction of travel is an angle",  \
           "Direction in which the waves travel, from +x toward +y"),                                           \
    PM_INT_PAR(T, field.seed, "waves.seed", 1, 0, 999999999, "the seed is a non-negative integer",              \
               "Seed of the random phases of the irregular sea (SplitMix64: the same sea as the cable FMU's)"),  \
    PM_INT_PAR(T, field.nComponents, "waves.nComponents", 200, 1, 5000, "the irregular sea has 1 to 5000 components", \
               "Number of wave components of the irregular sea (equal frequency bands over 0.5 to 3 times the "  \
               "peak frequency)"),                                                                              \
    PM_PAR(T, field.rampTime, "waves.rampTime", 0.0, 0.0, 1e6, "s", "the ramp time is a non-negative time",      \
           "Time over which the waves and the motion grow from calm (half a cosine); 0: full waves from the "    \
           "start"),                                                                                            \
    PM_PAR(T, field.depth, "waterDepth", 1000.0, 1e-3, 12000.0, "m", "the seabed lies below the surface",       \
           "Water depth (wave dispersion)"),                                                                    \
    PM_PAR(T, field.gravity, "gravity", 9.81, 0.0, 100.0, "m/s2", "gravity points along -z; give its magnitude", \
           "Gravitational acceleration (wave dispersion)")

#endif /* UNDERWATERCABLE_SEA_PARAMETERS_H */
