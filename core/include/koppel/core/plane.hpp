// Vectors in the plane of the mechanism: the quarter turn, the scalar cross product, a rotation.
// Angles count counter-clockwise from the x axis (mathematically positive), as everywhere in
// koppel; x to the right, y up.
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace koppel {

// v turned by +90 degrees (k x v): the derivative of Rotate(theta, v) with respect to theta.
inline Eigen::Vector2d Perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }

// The z component of a x b: positive when b points counter-clockwise of a.
inline double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The direction of v: its angle from the x axis [rad], in (-pi, pi].
inline double Direction(const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()); }

// v turned by theta [rad] counter-clockwise.
inline Eigen::Vector2d Rotate(double theta, const Eigen::Vector2d& v) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace koppel
