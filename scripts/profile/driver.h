/* driver.h - what the profile drivers share: the ramped sinusoidal motion of a tow point and the
 * statistics they print (read by scripts/profile/summary.py). */
#pragma once

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "api/cable_api.h"

/* Position, velocity and acceleration of A r(t) sin(w t), w = 2 pi / T, with the amplitude ramped in over
 * the first period, r = 3 tau^2 - 2 tau^3, tau = t / T. */
static inline void ramped_sine(double A, double T, double t, double* x, double* v, double* a) {
    const double w = 2.0 * 3.14159265358979323846 / T;
    const double tau = t < T ? t / T : 1.0;
    const double r = 3 * tau * tau - 2 * tau * tau * tau;
    const double dr = t < T ? (6 * tau - 6 * tau * tau) / T : 0.0, ddr = t < T ? (6 - 12 * tau) / (T * T) : 0.0;
    const double s = sin(w * t), c = cos(w * t);
    *x = A * r * s;
    *v = A * (dr * s + r * w * c);
    *a = A * (ddr * s + 2 * dr * w * c - r * w * w * s);
}

/* The far end anchored at (x, 0, z) on a seabed `depth` deep with the benchmark's contact (MoorDyn's
 * defaults 3e6 Pa/m and 3e5 Pa s/m times the diameter, no friction; python/studies/benchmarks/work_precision.py). */
static inline void anchor_on_seabed(UCParams* p, double x, double z, double depth) {
    p->bottomEnd = UC_BOTTOM_ANCHORED;
    p->anchor[0] = x;
    p->anchor[1] = 0.0;
    p->anchor[2] = z;
    p->enableSeabed = 1;
    p->waterDepth = depth;
    p->seabedStiffness = 3e6 * p->diameter;
    p->seabedDamping = 3e5 * p->diameter;
    p->seabedFriction = 0.0;
}

/* The integrator's statistics as "key value" lines (res0: residual evaluations of the initialization);
 * frees the cable. */
static inline int print_statistics(UCCable* c, int n_el, double t_end, double res0) {
    UCOutputs out;
    uc_get_outputs(c, &out);
    printf("nElements %d\nt_end %g\nnSteps %.0f\nnResidualEvals %.0f\nnResidualEvalsInit %.0f\n"
           "nJacobianEvals %.0f\nnNonlinearFailures %.0f\nnErrorTestFailures %.0f\ntowTension %.6f\n",
           n_el, t_end, out.nSteps, out.nResidualEvals, res0, out.nJacobianEvals,
           out.nNonlinearFailures, out.nErrorTestFailures, out.towTension);
    uc_free(c);
    return 0;
}

/* Creates the cable from p, initializes it with inputs `in` and steps it to t_end in steps of h with
 * the tow point's coordinate `axis` moving as ramped_sine(A, T) about its start (exact acceleration
 * passed); prints the statistics. Returns the process status. */
static inline int run_ramped_sine(const UCParams* p, UCInputs* in, int axis, double A, double T, double t_end,
                                  double h) {
    char msg[512];
    UCCable* c = uc_create(p, msg, sizeof msg);
    if (!c) { fprintf(stderr, "uc_create: %s\n", msg); return 1; }
    if (uc_initialize(c, 0.0, in, msg, sizeof msg)) { fprintf(stderr, "init: %s\n", msg); return 1; }
    UCOutputs out;
    uc_get_outputs(c, &out);
    const double res0 = out.nResidualEvals, x0 = in->tow[axis];
    const int n = (int)(t_end / h + 0.5);
    for (int k = 0; k < n; ++k) {
        const double t = k * h;
        ramped_sine(A, T, t, &in->tow[axis], &in->towVelocity[axis], &in->towAcceleration[axis]);
        in->tow[axis] += x0;
        in->towAccelerationGiven = 1;
        if (uc_do_step(c, t, h, in, msg, sizeof msg)) { fprintf(stderr, "step: %s\n", msg); return 1; }
    }
    printf("nCommunicationSteps %d\n", n);
    return print_statistics(c, p->nElements, t_end, res0);
}
