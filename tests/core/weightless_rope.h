// weightless_rope.h - one element of a weightless, dragless rope between an anchor at the origin and the tow point
// (the tests of the axial models: only the axial law acts; bending off, no seabed).
#pragma once

#include "api/cable_api.h"

inline UCParams weightless_rope(double length, double diameter, double massPerLength) {
    UCParams p;
    uc_params_default(&p);
    p.length = length;
    p.nElements = 1;
    p.diameter = diameter;
    p.massPerLength = massPerLength;
    p.gravity = 0.0;
    p.Cdn = p.Cdt = p.Can = p.Cat = 0.0;
    p.enableSeabed = 0;
    p.enableBending = 0;
    p.bottomEnd = UC_BOTTOM_ANCHORED;
    p.anchor[0] = p.anchor[1] = p.anchor[2] = 0.0;
    return p;
}
