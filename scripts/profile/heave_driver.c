/* heave_driver.c - fixed heave run through the core C API (src/api/cable_api.h), for
 * scripts/profile_callgrind --scene heave: the heave case of python/studies/cases/heave.py (1000 m
 * umbilical, 10 t body, 0.5 m/s current, top heave 2 m at 10 s ramped in over the first period),
 * 0.1 s communication steps with the exact tow acceleration. Usage: heave_driver [t_end=30]
 * [nElements=20]. Prints the integrator statistics as "key value" lines. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/cable_api.h"
#include "driver.h"

int main(int argc, char** argv) {
    const double t_end = argc > 1 ? atof(argv[1]) : 30.0;
    const int n_el = argc > 2 ? atoi(argv[2]) : 20;
    const double h = 0.1;
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
    UCInputs in;
    memset(&in, 0, sizeof in);
    in.current[0] = 0.5;
    return run_ramped_sine(&p, &in, 2, 2.0, 10.0, t_end, h);
}
