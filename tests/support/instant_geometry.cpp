#include "support/instant_geometry.hpp"

#include <cmath>

namespace koppel::test {

std::optional<Eigen::Vector2d> LineIntersection(const Eigen::Vector2d& p1, const Eigen::Vector2d& p2, const Eigen::Vector2d& q1,
                                                const Eigen::Vector2d& q2) {
  const Eigen::Vector2d r = p2 - p1, s = q2 - q1;
  const double denominator = r.x() * s.y() - r.y() * s.x();
  if (std::abs(denominator) < 1e-14 * r.norm() * s.norm()) return std::nullopt;
  const Eigen::Vector2d d = q1 - p1;
  const double t = (d.x() * s.y() - d.y() * s.x()) / denominator;
  return p1 + t * r;
}

std::optional<Eigen::Vector2d> EulerSavaryCentre(const Eigen::Vector2d& pole, const Eigen::Vector2d& inflection_pole, const Eigen::Vector2d& k) {
  const double pk = (k - pole).norm();
  const Eigen::Vector2d e = (k - pole) / pk;
  const double pw = e.dot(inflection_pole - pole);  // the circle |X - P|^2 = (X - P).(W - P) on the ray
  const double inverse = 1.0 / pk - 1.0 / pw;
  if (std::abs(inverse) < 1e-13 / pk) return std::nullopt;
  return pole + e / inverse;
}

double PathCurvature(double x1, double y1, double x2, double y2) { return (x1 * y2 - y1 * x2) / std::pow(x1 * x1 + y1 * y1, 1.5); }

}  // namespace koppel::test
