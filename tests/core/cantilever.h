// cantilever.h - the parameters of the elastica cantilever, shared by the core tests.
#pragma once

#include <cmath>

#include "api/cable_api.h"

namespace uc::testing {

// The paper's cantilever (its section 3.2), the elastica of the validation: L = 10 m, d = 20 mm,
// E = 2e11 Pa, neutrally buoyant, clamped horizontally along +x (the tests put it 50 m deep so the
// rod is fully submerged).
inline UCParams cantilever(int nElements) {
    UCParams p;
    uc_params_default(&p);
    p.length = 10;
    p.diameter = 0.02;
    const double A = 3.14159265358979323846 * p.diameter * p.diameter / 4;
    p.waterDensity = 1000;
    p.massPerLength = 1000 * A;  // neutrally buoyant
    p.EA = 2e11 * A;
    p.EI = 2e11 * 3.14159265358979323846 * std::pow(p.diameter, 4) / 64;
    p.nElements = nElements;
    p.topEnd = UC_TOP_CLAMPED;
    p.topTangent[0] = 1;
    p.topTangent[2] = 0;
    p.initialDirection[0] = 1;
    p.initialDirection[2] = 0;
    return p;
}

}  // namespace uc::testing
