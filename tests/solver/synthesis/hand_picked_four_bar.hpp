// The synthesis tests' hand-picked crank-rocker: crank 1.02 (the shortest, Grashof), coupler 3.04,
// rocker 2.28, frame 4.01 (1.02 + 4.01 < 3.04 + 2.28), its coupler plane's origin off the coupler line.
#pragma once

#include "koppel/synthesis/four_bar_design.hpp"

namespace koppel::test {

inline FourBarGeometry HandPickedFourBar(double plane_angle) {
  FourBarGeometry g;
  g.a0 = {0, 0};
  g.a = {1, 0.2};
  g.b = {3.1, 2.4};
  g.b0 = {4, 0.3};
  g.plane_origin = {2.2, 3.3};
  g.plane_angle = plane_angle;
  return g;
}

}  // namespace koppel::test
