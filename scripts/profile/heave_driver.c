/* heave_driver.c - fixed heave run through the core C API (src/cable_api.h), for
 * scripts/profile_callgrind --scene heave: the heave case of scripts/ucable/heave.py (1000 m
 * umbilical, 10 t body, 0.5 m/s current, top heave 2 m at 10 s ramped in over the first period),
 * 0.1 s communication steps with the exact tow acceleration. Usage: heave_driver [t_end=30]
 * [nElements=20]. Prints the integrator statistics as "key value" lines. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cable_api.h"

/* z, velocity and acceleration of the ramped heave A r(t) sin(w t), r = 3 tau^2 - 2 tau^3. */
static void heave(double t, double* z, double* v, double* a) {
    const double A = 2.0, T = 10.0, w = 2.0 * 3.14159265358979323846 / T;
    const double tau = t < T ? t / T : 1.0;
    const double r = 3 * tau * tau - 2 * tau * tau * tau;
    const double dr = t < T ? (6 * tau - 6 * tau * tau) / T : 0.0, ddr = t < T ? (6 - 12 * tau) / (T * T) : 0.0;
    const double s = sin(w * t), c = cos(w * t);
    *z = A * r * s;
    *v = A * (dr * s + r * w * c);
    *a = A * (ddr * s + 2 * dr * w * c - r * w * w * s);
}

int main(int argc, char** argv) {
    const double t_end = argc > 1 ? atof(argv[1]) : 30.0;
    const int n_el = argc > 2 ? atoi(argv[2]) : 20;
    const double h = 0.1;
    char msg[512];
    UCParams p;
    uc_params_default(&p);
    p.nElements = n_el;
    p.length = 1000.0;
    p.diameter = 0.1;
    p.massPerLength = 20.0;
    p.EA = 5e8;
    p.EI = 1e4;
    p.axialDamping = 0.01 * p.EA;
    p.Cdn = 1.2;
    p.Cdt = 0.008;
    p.Can = 1.0;
    p.Cat = 0.0;
    p.bottomEnd = UC_BOTTOM_TOWED_BODY;
    p.bodyMass = 10000.0;
    p.bodyVolume = 2.0;
    p.bodyAddedMass = 2000.0;
    p.bodyCdA = 3.0;
    p.initMode = UC_INIT_EQUILIBRIUM;
    p.initialDirection[0] = 0.0;
    p.initialDirection[1] = 0.0;
    p.initialDirection[2] = -1.0;
#ifdef UC_PROFILE_WAVES /* heave_waves_driver.c: the same case in a JONSWAP sea */
    p.wavesMode = 2;
    p.wavesHeight = 3.0;
    p.wavesPeriod = 10.0;
    p.wavesNComponents = UC_PROFILE_WAVES;
#endif
    UCCable* c = uc_create(&p, msg, sizeof msg);
    if (!c) { fprintf(stderr, "uc_create: %s\n", msg); return 1; }
    UCInputs in;
    memset(&in, 0, sizeof in);
    in.current[0] = 0.5;
    if (uc_initialize(c, 0.0, &in, msg, sizeof msg)) { fprintf(stderr, "init: %s\n", msg); return 1; }
    UCOutputs out;
    uc_get_outputs(c, &out);
    const double res0 = out.nResidualEvals;
    const int n = (int)(t_end / h + 0.5);
    for (int k = 0; k < n; ++k) {
        const double t = k * h;
        heave(t, &in.tow[2], &in.towVelocity[2], &in.towAcceleration[2]);
        in.towAccelerationGiven = 1;
        if (uc_do_step(c, t, h, &in, msg, sizeof msg)) { fprintf(stderr, "step: %s\n", msg); return 1; }
    }
    uc_get_outputs(c, &out);
    printf("nElements %d\nt_end %g\nnSteps %.0f\nnResidualEvals %.0f\nnResidualEvalsInit %.0f\n"
           "nJacobianEvals %.0f\nnNonlinearFailures %.0f\nnErrorTestFailures %.0f\ntowTension %.6f\n",
           n_el, t_end, out.nSteps, out.nResidualEvals, res0, out.nJacobianEvals,
           out.nNonlinearFailures, out.nErrorTestFailures, out.towTension);
    uc_free(c);
    return 0;
}
