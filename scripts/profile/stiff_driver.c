/* stiff_driver.c - the stiff power cable of scripts/bench_work_precision through the core C API
 * (src/api/cable_api.h), for scripts/profile_callgrind --scenes stiff: 250 m, 60 kg/m, d 0.2 m, EA 7e8 N,
 * EI 2e4 N m2, anchored on a 100 m deep seabed at (-210, 0, -100) m with the benchmark's contact
 * (3e6 Pa/m and 3e5 Pa s/m times d), fairlead at (0, 0, -10) m surging 3 m at 8 s along x (amplitude
 * ramped in over the first period), 0.05 s communication steps with the exact acceleration.
 * Usage: stiff_driver [t_end=30] [nElements=20] [tensionTolerance=1e-3] [projectedErrorControl=0]
 *                    [positionTolerance=1e-3] [seabedContactSpacing=0] [solver.maxOrder=5].
 * Prints the integrator statistics as "key value" lines. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/cable_api.h"
#include "driver.h"

int main(int argc, char** argv) {
    const double t_end = argc > 1 ? atof(argv[1]) : 30.0;
    const int n_el = argc > 2 ? atoi(argv[2]) : 20;
    const double h = 0.05;
    UCParams p;
    uc_params_default(&p);
    p.nElements = n_el;
    if (argc > 3) p.tensionTolerance = atof(argv[3]);
    if (argc > 4) p.projectedErrorControl = atoi(argv[4]);
    if (argc > 5) p.positionTolerance = atof(argv[5]);
    if (argc > 6) p.seabedContactSpacing = atof(argv[6]);
    if (argc > 7) p.solverMaxOrder = atoi(argv[7]);
    p.length = 250.0;
    p.diameter = 0.2;
    p.massPerLength = 60.0;
    p.EA = 7e8;
    p.EI = 2e4;
    p.Cdn = 1.2;
    p.Cdt = 0.008;
    p.Can = 1.0;
    p.Cat = 0.0;
    anchor_on_seabed(&p, -210.0, -100.0, 100.0);
    UCInputs in;
    memset(&in, 0, sizeof in);
    in.tow[2] = -10.0;
    return run_ramped_sine(&p, &in, 0, 3.0, 8.0, t_end, h);
}
