#include "path_prepolish.hpp"

#include "ceres_solves.hpp"
#include "path_residual.hpp"

#include <algorithm>

namespace koppel {

double PointsScale(const std::vector<Eigen::Vector2d>& points) {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const auto& p : points) centre += p / static_cast<double>(points.size());
  double s = 0;
  for (const auto& p : points) s = std::max(s, (p - centre).norm());
  return s;
}

bool CouplerPointAt(const std::vector<double>& v, int branch, double phi, Eigen::Vector2d* point) {
  double r[2];
  if (!PointResidual{Eigen::Vector2d::Zero(), branch}(v.data(), &phi, r)) return false;
  *point = {r[0], r[1]};
  return true;
}

double PrePolish(const std::vector<Eigen::Vector2d>& points, int branch, std::vector<double>* v, std::vector<double>* inputs,
                 const std::vector<std::pair<double, double>>* bounds) {
  return CeresSolves().prepolish(points, branch, v, inputs, bounds);
}

}  // namespace koppel
