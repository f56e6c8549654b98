// mesh_grading.h - where the nodes of an anchored line go: graded by its static profile
// (docs/model.md, "Initial equilibrium"). A line without bending stiffness turns sharply where it
// leaves the seabed (its curvature jumps from 0 to w / H), which elements of equal length resolve
// poorly when H / w is short against them; a node at the touchdown and nodes spread by arc length
// and by the angle the line turns through represent it as well as a freely hanging line.
#pragma once

#include <vector>

#include "cable_model.h"
#include "line_profile.h"

namespace uc {

// Arc lengths of the nodes from the tow point (0 first, the line's length last). Each section keeps
// its number of elements (one more per piece where attachments and the touchdown cut it into more
// pieces than it has elements); inside a section the nodes sit at equal steps of
//   M(s) = s / L_section + theta(s) / max(Theta_section, kGradingAngle)
//          + lambda(s) / max(Lambda_section / kGradingLogTensionWeight, kGradingLogTension),
// theta the angle the profile turns through, lambda the change of ln(tension) (counted inside the
// pieces between attachments and contacts: a point load makes it jump), with a node at each
// attachment and wherever the line reaches or leaves the seabed. Equal steps of ln(tension) space
// the nodes geometrically up from a touchdown whose H / w is short against the elements.
// `towOnTop`: the profile's top end is the tow point (else the anchor, above it). `alongLine`
// (meshGrading 2): one monitor along the whole line, whose elements (the sections' total) go where
// it turns, every section end a node and at least one element per section and piece.
std::vector<double> graded_nodes(const CableModel& model, const LineProfile& profile, bool towOnTop,
                                 bool alongLine = false);

// Below this total turning [rad] a section's nodes tend to equal spacing.
constexpr double kGradingAngle = 0.5;
// The tension term is lambda(s) / max(Lambda / kGradingLogTensionWeight, kGradingLogTension): it
// counts half the change of ln(tension) up to a total of 3 (a tension ratio of e^6 = 400 along the
// piece) and grades with the weight 3 beyond. It matters where the bottom tension H is small
// against the top's: there the line rises nearly vertically and its horizontal offset grows as
// (H / w) ln(s) above the touchdown. A line whose tension changes little keeps nearly the mesh the
// arc length and the turning give it (the work-precision benchmark's snapping chain: ratio 1.18).
constexpr double kGradingLogTension = 2.0;
constexpr double kGradingLogTensionWeight = 3.0;

}  // namespace uc
