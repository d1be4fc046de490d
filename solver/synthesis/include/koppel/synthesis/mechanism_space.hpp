// A design space (design_space.hpp) read for any mechanism, as synth fit returns one: the four-bar's
// keys said of every link and every frame pivot.
//   lengths, ratio: the distance between every two R joints of one link: a binary link's length,
//     a ternary link's sides, the distances of the frame's pivots (two joints at one place of a
//     link have none between them).
//   pivots: every R joint of the frame inside the box.
//   input: crank: the drive turns a whole turn from its assembly.
//   mu_min: every transmission-angle output over the worked stretch.
// A0, frame_angle and coupler_point name a four-bar's parts: DesignSpace::Unsupported refuses them.
#pragma once

#include "koppel/core/mechanism.hpp"
#include "koppel/synthesis/design_space.hpp"

#include <string>
#include <utility>
#include <vector>

namespace koppel {

struct MechanismSizes {
  // "coupler A-B" and its length, in the mechanism's order of links and joints
  std::vector<std::pair<std::string, double>> lengths;
  // each R joint of the frame and where it stands (the frame's body frame is the global one)
  std::vector<std::pair<std::string, Eigen::Vector2d>> pivots;
};
MechanismSizes SizesOf(const Mechanism& mechanism);

// Empty when the space can be checked on `mechanism`; else why not, in words: a key that names a
// four-bar's part, mu_min on a mechanism without a transmission-angle output, a crank asked of a
// slide drive.
std::string UncheckableSpace(const DesignSpace& space, const Mechanism& mechanism);

// The first constraint `mechanism` breaks, in words with its figures ("lengths: coupler A-B is
// 12.5, beyond 10"); empty when it lies inside the space. mu_min is checked over from..to (the
// worked stretch); input: crank by a sweep over a whole turn from the assembly input.
// Precondition: UncheckableSpace is empty.
std::string MechanismViolation(const DesignSpace& space, const Mechanism& mechanism, double from, double to);

}  // namespace koppel
