// chain_system_parameters.h - the parameters a mooring system of the OC4 chains (Diam 0.0766 m) takes beside
// its deck, as MoorDyn has them (docs/lines.md): the seabed from kBot and cBot times the diameter, tension-only
// lines; the others the defaults.
#pragma once

#include "api/cable_api.h"

inline UCParams chain_system_parameters() {
    UCParams p;
    uc_params_default(&p);
    p.enableSeabed = 1;
    p.seabedStiffness = 3e6 * 0.0766;
    p.seabedDamping = 3e5 * 0.0766;
    p.enableCompression = 0;
    return p;
}
