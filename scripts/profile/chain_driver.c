/* chain_driver.c - the chain mooring of scripts/bench_work_precision (case "mooring") through the core
 * C API (src/api/cable_api.h), for scripts/profile_callgrind --scenes chain (and chain_still): 835 m,
 * 117 kg/m, volume-equivalent d 0.137 m, EA 7.5e8 N, no bending stiffness, tension only, anchored on a
 * 200 m deep seabed at (-800, 0, -200) m with the benchmark's contact (3e6 Pa/m and 3e5 Pa s/m times
 * d, no friction), fairlead at (0, 0, -20) m surging `amplitude` at 12 s along x (amplitude ramped in
 * over the first period; 0 holds it still), 0.05 s communication steps with the exact acceleration.
 * Usage: chain_driver [t_end=30] [nElements=10] [amplitude=5] [tensionTolerance=0.1].
 * Prints the integrator statistics as "key value" lines. */
#include <stdlib.h>
#include <string.h>

#include "api/cable_api.h"
#include "driver.h"

int main(int argc, char** argv) {
    const double t_end = argc > 1 ? atof(argv[1]) : 30.0;
    const int n_el = argc > 2 ? atoi(argv[2]) : 10;
    const double amplitude = argc > 3 ? atof(argv[3]) : 5.0;
    UCParams p;
    uc_params_default(&p);
    p.nElements = n_el;
    p.tensionTolerance = argc > 4 ? atof(argv[4]) : 0.1;
    p.length = 835.0;
    p.diameter = 0.137;
    p.massPerLength = 117.0;
    p.EA = 7.5e8;
    p.EI = 0.0;
    p.enableBending = 0;
    p.enableCompression = 0;
    p.Cdn = 2.4;
    p.Cdt = 0.2;
    p.Can = 1.0;
    p.Cat = 0.0;
    anchor_on_seabed(&p, -800.0, -200.0, 200.0);
    UCInputs in;
    uc_inputs_default(&in);
    in.tow[2] = -20.0;
    return run_ramped_sine(&p, &in, 0, amplitude, 12.0, t_end, 0.05);
}
