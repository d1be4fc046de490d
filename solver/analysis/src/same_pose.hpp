// Whether two poses of one mechanism are the same: the test by which a rotating drive's pose
// repeats after a turn (ranges.cpp: the period; stationary_search.cpp: a periodic search).
#pragma once

#include "koppel/core/angles.hpp"

#include <Eigen/Core>

#include <cmath>

namespace koppel {

// Poses closer than this (units of L for positions, rad for angles, angles modulo 2 pi) are the
// same pose: far above Newton's 1e-13, far below the distance between two assemblies.
inline constexpr double kSamePose = 1e-7;

// The coordinates are (x, y, theta) per moving link (constraints.hpp); `scale` is L.
inline bool SamePose(const Eigen::VectorXd& a, const Eigen::VectorXd& b, double scale) {
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    const double d = i % 3 == 2 ? std::abs(AngleDifference(a(i), b(i))) : std::abs(a(i) - b(i)) / scale;
    if (d > kSamePose) return false;
  }
  return true;
}

}  // namespace koppel
