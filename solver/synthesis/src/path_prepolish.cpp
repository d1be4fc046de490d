#include "path_prepolish.hpp"

#include "quiet_solver_log.hpp"

#include <ceres/ceres.h>

#include <cmath>
#include <limits>

namespace koppel {
namespace {

// The coupler point at crank angle phi minus the target, in closed form (the triangle A B B0).
struct PointResidual {
  Eigen::Vector2d target;
  int branch;
  template <class T> bool operator()(const T* const v, const T* const phi, T* residual) const {
    const T ax = v[0] + v[4] * ceres::cos(phi[0]), ay = v[1] + v[4] * ceres::sin(phi[0]);
    const T dx = v[2] - ax, dy = v[3] - ay;
    const T r = ceres::sqrt(dx * dx + dy * dy);
    const T cos_gamma = (v[5] * v[5] + r * r - v[6] * v[6]) / (T(2) * v[5] * r);
    if (!(cos_gamma > T(-1) && cos_gamma < T(1))) return false;  // the loop does not close here
    const T gamma = ceres::atan2(dy, dx) + T(branch) * ceres::acos(cos_gamma);
    const T ux = ceres::cos(gamma), uy = ceres::sin(gamma);
    residual[0] = ax + v[7] * ux - v[8] * uy - T(target.x());
    residual[1] = ay + v[7] * uy + v[8] * ux - T(target.y());
    return true;
  }
};

}  // namespace

bool CouplerPointAt(const std::vector<double>& v, int branch, double phi, Eigen::Vector2d* point) {
  double r[2];
  if (!PointResidual{Eigen::Vector2d::Zero(), branch}(v.data(), &phi, r)) return false;
  *point = {r[0], r[1]};
  return true;
}

double PrePolish(const std::vector<Eigen::Vector2d>& points, int branch, std::vector<double>* v, std::vector<double>* inputs) {
  ceres::Problem problem;
  for (size_t i = 0; i < points.size(); ++i) {
    auto* cost = new ceres::AutoDiffCostFunction<PointResidual, 2, 9, 1>(new PointResidual{points[i], branch});
    double r[2];
    const double* blocks[] = {v->data(), &(*inputs)[i]};
    if (!cost->Evaluate(blocks, r, nullptr)) {
      delete cost;
      return std::numeric_limits<double>::infinity();
    }
    problem.AddResidualBlock(cost, nullptr, v->data(), &(*inputs)[i]);
  }
  ceres::Solver::Options options;
  options.max_num_iterations = 500;
  options.linear_solver_type = ceres::DENSE_SCHUR;  // the crank angles are the eliminated block
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-15;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  QuietSolverLog();
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable()) return std::numeric_limits<double>::infinity();
  return std::sqrt(2 * summary.final_cost / points.size());
}

}  // namespace koppel
