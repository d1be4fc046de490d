// Where a transmission angle is measured: which points of the mechanism form the coupler line and
// the output's path. Topology alone (no pose, no solver), so the file reader checks a
// transmission output while it reads, and the kernel evaluates it at every pose.
#pragma once

#include "koppel/core/expected.hpp"
#include "koppel/core/mechanism.hpp"

namespace koppel {

// How the transmission angle of an output is measured: the coupler line runs from `coupler_from`
// to `coupler_to` (the output joint's point on the coupler); the output joint point moves either
// on a circle about `pivot` (a point of the output link pinned to the frame) or along the global
// direction of `slide_joint`'s axis.
struct TransmissionGeometry {
  PointRef coupler_from;
  PointRef coupler_to;
  PointRef pivot;        // valid when the output link turns about a frame pivot
  int slide_joint = -1;  // valid when the output link slides on the frame
};

// Resolves a kTransmissionAngle output; an error when the coupler is not binary or the output
// link is not jointed directly to the frame.
Expected<TransmissionGeometry> ResolveTransmission(const Mechanism& m, const Output& o);

}  // namespace koppel
