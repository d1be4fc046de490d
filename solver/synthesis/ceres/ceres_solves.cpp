// The module libkoppel_ceres.so: the one place of koppel that includes Ceres, loaded by the
// synthesis library on its first least-squares solve (ceres_solves.hpp). Knows nothing of
// mechanisms: the fit's residuals come back through BoundedLeastSquares::evaluate.
#include "ceres_solves.hpp"
#include "path_residual.hpp"
#include "quiet_solver_log.hpp"

#include <ceres/ceres.h>

#include <cmath>
#include <limits>

namespace koppel {
namespace {

bool Finite(double v) { return v > -1e299 && v < 1e299; }

class FitCost : public ceres::CostFunction {
 public:
  explicit FitCost(const BoundedLeastSquares& problem) : problem_(problem) {
    set_num_residuals(problem.residuals);
    mutable_parameter_block_sizes()->push_back(problem.unknowns);
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    return problem_.evaluate(parameters[0], residuals, jacobians ? jacobians[0] : nullptr);
  }

 private:
  const BoundedLeastSquares& problem_;
};

LeastSquaresOutcome SolveFit(const BoundedLeastSquares& p, double* x) {
  ceres::Problem problem;
  problem.AddResidualBlock(new FitCost(p), nullptr, x);
  for (int j = 0; j < p.unknowns; ++j) {
    if (Finite(p.lower[j])) problem.SetParameterLowerBound(x, j, p.lower[j]);
    if (Finite(p.upper[j])) problem.SetParameterUpperBound(x, j, p.upper[j]);
  }
  ceres::Solver::Options options;
  options.max_num_iterations = p.max_iterations;
  options.linear_solver_type = ceres::DENSE_QR;
  // A relative change of the cost below 1e-10 is the roundoff of the residuals' sensitivities
  // (central differences, relative error about 1e-10): at that floor the fit is done. Smaller
  // values leave the end to chance (an exact zero gradient, or rejected steps until the trust
  // region collapses), and the iterations then depend on the last bits of every pose.
  options.function_tolerance = 1e-10;
  options.gradient_tolerance = 1e-15;
  options.parameter_tolerance = 1e-14;
  options.num_threads = 1;  // one residual block: the fit's starts are the parallel work
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  ceres::Solver::Summary summary;
  QuietSolverLog();
  ceres::Solve(options, &problem, &summary);
  return {summary.IsSolutionUsable(), static_cast<int>(summary.iterations.size()), summary.final_cost, summary.BriefReport()};
}

// path_prepolish.hpp: the coupler point in closed form fitted to the points with automatic
// derivatives, each point's crank angle an unknown of its own.
double SolvePrePolish(const std::vector<Eigen::Vector2d>& points, int branch, std::vector<double>* v, std::vector<double>* inputs,
                      const std::vector<std::pair<double, double>>* bounds) {
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
  // a design space's bounds on the pivots and lengths (the start lies inside them)
  for (size_t j = 0; bounds && j < bounds->size() && j < v->size(); ++j) {
    if (Finite((*bounds)[j].first)) problem.SetParameterLowerBound(v->data(), static_cast<int>(j), (*bounds)[j].first);
    if (Finite((*bounds)[j].second)) problem.SetParameterUpperBound(v->data(), static_cast<int>(j), (*bounds)[j].second);
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

// ceres_solves.hpp's timed_path: every point's coupler point at its prescribed crank angle,
// automatic derivatives, fixed unknowns (lower == upper) held constant.
// Adds one residual block after evaluating it at the start; false (and nothing added) where the
// start cannot be evaluated.
bool AddEvaluable(ceres::Problem* problem, ceres::CostFunction* cost, std::vector<double*> blocks) {
  double r[2];
  if (!cost->Evaluate(blocks.data(), r, nullptr)) {
    delete cost;
    return false;
  }
  problem->AddResidualBlock(cost, nullptr, blocks);
  return true;
}

double SolveTimedPath(const TimedPathProblem& p, double* u) {
  ceres::Problem problem;
  const bool free = p.phases != nullptr;
  for (size_t i = 0; i < p.points.size(); ++i) {
    const bool added =
        free ? AddEvaluable(&problem,
                            new ceres::AutoDiffCostFunction<FreePointResidual, 2, kTimedUnknowns, 1>(new FreePointResidual{p.points[i], p.branch, &p.limits}),
                            {u, &(*p.phases)[p.same_phase[i] >= 0 ? p.same_phase[i] : i]})
             : AddEvaluable(&problem,
                            new ceres::AutoDiffCostFunction<TimedPointResidual, 2, kTimedUnknowns>(
                                new TimedPointResidual{p.points[i], p.offsets[i], p.branch, &p.limits}),
                            {u});
    if (!added) return std::numeric_limits<double>::infinity();
  }
  std::vector<int> fixed;
  for (int j = 0; j < kTimedUnknowns; ++j) {
    if (p.lower[j] == p.upper[j] || (free && j == 9)) {
      fixed.push_back(j);
      continue;
    }
    if (Finite(p.lower[j])) problem.SetParameterLowerBound(u, j, p.lower[j]);
    if (Finite(p.upper[j])) problem.SetParameterUpperBound(u, j, p.upper[j]);
  }
  if (!fixed.empty()) problem.SetManifold(u, new ceres::SubsetManifold(kTimedUnknowns, fixed));
  ceres::Solver::Options options;
  options.max_num_iterations = p.max_iterations;
  // the timing free: the crank angles are the eliminated block
  options.linear_solver_type = free ? ceres::DENSE_SCHUR : ceres::DENSE_QR;
  options.function_tolerance = 1e-14;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-14;
  options.num_threads = 1;  // the starts are the parallel work
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  QuietSolverLog();
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable()) return std::numeric_limits<double>::infinity();
  return 2 * summary.final_cost;
}

const CeresSolvesTable kTable{{KOPPEL_MODULE_VERSION}, &SolveFit, &SolvePrePolish, &SolveTimedPath, &QuietSolverLog};

}  // namespace
}  // namespace koppel

extern "C" __attribute__((visibility("default"))) const koppel::ModuleTable* koppel_ceres_module() { return &koppel::kTable; }
