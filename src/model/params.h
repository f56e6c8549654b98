// params.h - physical and numerical settings of a cable, validated in one place.
#pragma once

#include <string>

#include "model/parameters.h"
#include "terms/syrope.h"

namespace uc {

// The Hopland 1993 tow cable (paper section 3.1): d = 33.2 mm, rho_c = 3121 kg/m3, E = 77.5 GPa.
constexpr double kHoplandDiameter = 0.0332;
constexpr double kHoplandDensity = 3121.0;
constexpr double kHoplandModulus = 77.5e9;

// Returns an empty string when every parameter is admissible, otherwise one message in the
// format "<variable> = <value> is outside <range>: <why>" (the FMU log shows it verbatim).
std::string check_params(const UCParams& p);

// The Syrope model of a uniform line from its parameters (syrope.*, axialCurve.* its original working curve,
// EAdynamic and EAdynamicSlope its dynamic stiffness); false (s off) when the line has none or its curve
// does not build.
bool syrope_from_params(const UCParams& p, SyropeProps& s);

}  // namespace uc
