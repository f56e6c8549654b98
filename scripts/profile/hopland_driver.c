/* hopland_driver.c - fixed short Hopland run through the core C API (src/api/cable_api.h), for
 * scripts/profile_callgrind: steady tow at 1.1 kn, then the 2.4 kn ramp, 0.5 s steps, with the
 * exact tow acceleration. Usage: hopland_driver [t_end=60] [nElements=20]. Prints the integrator
 * statistics as "key value" lines. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/cable_api.h"
#include "driver.h"

int main(int argc, char** argv) {
    const double t_end = argc > 1 ? atof(argv[1]) : 60.0;
    const int n_el = argc > 2 ? atoi(argv[2]) : 20;
    const double knot = 1852.0 / 3600.0, v0 = 1.1 * knot, v1 = 2.4 * knot, ramp = 60.0, h = 0.5;
    char msg[512];
    UCParams p;
    uc_params_default(&p);
    p.nElements = n_el;
    UCCable* c = uc_create(&p, msg, sizeof msg);
    if (!c) { fprintf(stderr, "uc_create: %s\n", msg); return 1; }
    UCInputs in;
    memset(&in, 0, sizeof in);
    in.towVelocity[0] = v0;
    if (uc_initialize(c, 0.0, &in, msg, sizeof msg)) { fprintf(stderr, "init: %s\n", msg); return 1; }
    UCOutputs out;
    uc_get_outputs(c, &out);
    const double res0 = out.nResidualEvals; /* statics is not part of the time stepping */
    const double a = (v1 - v0) / ramp;
    for (double t = 0.0; t < t_end - 1e-9; t += h) {
        const double tc = t < ramp ? t : ramp;
        in.tow[0] = v0 * tc + 0.5 * a * tc * tc + (t > ramp ? v1 * (t - ramp) : 0.0);
        in.towVelocity[0] = t < ramp ? v0 + a * t : v1;
        in.towAcceleration[0] = t < ramp ? a : 0.0;
        in.towAccelerationGiven = 1;
        if (uc_do_step(c, t, h, &in, msg, sizeof msg)) { fprintf(stderr, "step: %s\n", msg); return 1; }
    }
    return print_statistics(c, n_el, t_end, res0);
}
