// The design file of a synthesis (--design FILE.yaml): the design space
// (koppel/synthesis/design_space.hpp) as an engineer writes it, every key optional (but one at least):
//   lengths: [min, max]        every link, the frame too
//   ratio: max                 longest link / shortest link
//   pivots: {x: [a, b], y: [c, d]}   both frame pivots inside this box
//   input: crank | any         crank: the input turns fully
//   A0: [x, y]                 the crank's pivot fixed there
//   frame_angle: deg           the frame line A0 -> B0 fixed at this angle against +x
//   coupler_point: [min, max]  both coordinates of K in the coupler's frame
//   mu_min: deg                the smallest transmission angle over the worked stretch
// Numbers may be formulas. Unknown keys, a contradiction (an empty interval, a ratio below 1) and
// non-finite numbers are errors with file:line:column (InputError, as mechanism_file.hpp).
#pragma once

#include "koppel/synthesis/design_space.hpp"

#include <string>

namespace koppel {

DesignSpace ReadDesignSpace(const std::string& path);
DesignSpace ParseDesignSpaceText(const std::string& text, const std::string& path);

}  // namespace koppel
