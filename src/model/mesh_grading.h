// mesh_grading.h - where the nodes of an anchored line go: graded by its static profile
// (docs/model.md, "Initial equilibrium"). A line without bending stiffness turns sharply where it
// leaves the seabed (its curvature jumps from 0 to w / H), which elements of equal length resolve
// poorly when H / w is short against them; a node at the touchdown and nodes spread by arc length
// and by the angle the line turns through represent it as well as a freely hanging line.
#pragma once

#include <vector>

#include "model/cable_model.h"
#include "model/line_profile.h"

namespace uc {

// How the monitor weighs the line's turning and its tension against its arc length (below).
struct GradingWeights {
    double angle;             // the turning's weight
    double logTensionWeight;  // ln(tension)'s whole weight where it changes by more than
    double logTension;        // logTensionWeight times this; below, it counts lambda / logTension
};

// The gradings an initialization tries, in order, with the line's element count: the first whose
// static equilibrium passes the check against the exact profile is kept (docs/model.md, "Initial
// equilibrium"). The first suits nearly every line. Where ten or so elements share a line whose
// tension rises from a small bottom tension H by a factor of hundreds, the second spaces them
// geometrically up from the touchdown (the line rises nearly vertically there, and its offset grows
// as (H / w) ln(s)). Where short arches over a buoy, a clump or a joint turn sharply, the third gives
// the turning three times the arc length's weight.
constexpr GradingWeights kGradings[] = {{1.0, 3.0, 2.0}, {1.0, 6.0, 1.0}, {3.0, 3.0, 2.0}};
constexpr int kGradingCount = static_cast<int>(sizeof kGradings / sizeof kGradings[0]);

// Arc lengths of the nodes from the tow point (0 first, the line's length last). Each section keeps
// its number of elements (one more per piece where attachments and the touchdown cut it into more
// pieces than it has elements); inside a section the nodes sit at equal steps of
//   M(s) = s / L_section + angle theta(s) / max(Theta_section, kGradingAngle)
//          + lambda(s) / max(Lambda_section / logTensionWeight, logTension),
// theta the angle the profile turns through, lambda the change of ln(tension) (counted inside the
// pieces between attachments and contacts: a point load makes it jump), with a node at each
// attachment and wherever the line reaches or leaves the seabed. Equal steps of ln(tension) space
// the nodes geometrically up from a touchdown whose H / w is short against the elements.
// `towOnTop`: the profile's top end is the tow point (else the anchor, above it). `alongLine`
// (meshGrading 2): one monitor along the whole line, whose elements (the sections' total) go where
// it turns, every section end a node and at least one element per section and piece.
// `weights`: angle, logTensionWeight and logTension of the monitor.
std::vector<double> graded_nodes(const CableModel& model, const LineProfile& profile, bool towOnTop,
                                 bool alongLine = false, const GradingWeights& weights = kGradings[0]);

// Below this total turning [rad] a section's nodes tend to equal spacing.
constexpr double kGradingAngle = 0.5;
// The first grading's tension term, lambda(s) / max(Lambda / 3, 2), counts half the change of
// ln(tension) up to a total of 3 (a tension ratio of e^6 = 400 along the piece) and grades with the
// weight 3 beyond. It matters where the bottom tension H is small against the top's: there the line
// rises nearly vertically and its horizontal offset grows as (H / w) ln(s) above the touchdown. A
// line whose tension changes little keeps nearly the mesh the arc length and the turning give it
// (the work-precision benchmark's snapping chain: ratio 1.18).

}  // namespace uc
