// simulation_internal.h - what the files of CableSimulation (line/*.cpp by stage) share and nothing
// else includes.
#pragma once

#include "core/types.h"
#include "model/parameters.h"
#include "line/simulation.h"

namespace uc {

inline Vec3 vec(const double v[3]) { return Vec3(v[0], v[1], v[2]); }

// The linearization of the end load (12 inputs) is finite (simulation.cpp).
bool end_load_linearization_finite(const LineEnvironment& env);

// phi(A) = A (e^A - I)^-1 (proxy_end.cpp).
Mat3 bernoulli_phi(const Mat3& A);

}  // namespace uc
