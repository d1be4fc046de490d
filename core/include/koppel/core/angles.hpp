// Angle units and wrap-aware comparison. Radians inside koppel; degrees at the boundary.
#pragma once

#include <cmath>

namespace koppel {

inline constexpr double kPi = 3.14159265358979323846;

inline constexpr double DegToRad(double degrees) { return degrees * (kPi / 180.0); }
inline constexpr double RadToDeg(double radians) { return radians * (180.0 / kPi); }

// The signed difference a - b folded into [-pi, pi]: the only way koppel compares angles.
inline double AngleDifference(double a, double b) { return std::remainder(a - b, 2.0 * kPi); }

// The angle folded into (-pi, pi]: a difference of angles as the tolerance and sensitivity
// reports give it (half a turn is +pi, never -pi).
inline double WrapToHalfTurn(double radians) {
  const double r = std::remainder(radians, 2 * kPi);
  return r <= -kPi ? r + 2 * kPi : r;
}

// The angle folded into [0, 2 pi): how an input angle of a revolute drive is reported (a
// rounding that would give 2 pi gives 0).
inline double WrapToFullTurn(double radians) {
  double wrapped = std::fmod(radians, 2.0 * kPi);
  if (wrapped < 0) wrapped += 2.0 * kPi;
  return wrapped < 2.0 * kPi ? wrapped : 0.0;
}

}  // namespace koppel
