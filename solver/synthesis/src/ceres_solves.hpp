// The least-squares problems of synthesis that Ceres solves: the fit's starts (fit.cpp) and the
// closed-form pre-polish of path synthesis (path_prepolish.cpp). Ceres, with glog, SuiteSparse and
// LAPACK, lives in the module libkoppel_ceres.so (solver/synthesis/ceres), loaded on the first
// solve (koppel/core/module.hpp), so that nothing else of koppel maps them at start-up.
#pragma once

#include "koppel/core/module.hpp"
#include "path_residual.hpp"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace koppel {

// Minimise 1/2 |r(x)|^2 over x within bounds, with the fit's solver options (ceres_solves.cpp).
struct BoundedLeastSquares {
  int residuals = 0;
  int unknowns = 0;
  std::vector<double> lower, upper;  // per unknown; beyond +-1e299: unbounded on that side
  // residuals r(x) and, where `jacobian` is not null, dr/dx row-major (residuals x unknowns);
  // false where r cannot be evaluated
  std::function<bool(const double* x, double* residuals, double* jacobian)> evaluate;
  int max_iterations = 0;
};

struct LeastSquaresOutcome {
  bool usable = false;  // Ceres' IsSolutionUsable
  int iterations = 0;
  double final_cost = 0;
  std::string brief;  // Ceres' BriefReport
};

// Path synthesis with prescribed timing in closed form (path_residual.hpp's TimedPointResidual):
// the unknowns u (kTimedUnknowns) fitted to the points, each at phi_1 + its offset.
inline constexpr int kTimedUnknowns = 10;
struct TimedPathProblem {
  std::vector<Eigen::Vector2d> points;
  std::vector<double> offsets;       // per point: its crank angle minus phi_1
  // The timing free: each point's crank angle from the frame line its own unknown, in phases
  // (in: the start, out: the solution; u[9] is then held fixed). A point whose `same_phase` is
  // not -1 shares that point's angle (a closed path's last point repeating its first).
  std::vector<double>* phases = nullptr;
  std::vector<int> same_phase;
  int branch = 1;
  TimedLimits limits;
  std::vector<double> lower, upper;  // per unknown (lower == upper: fixed); beyond +-1e299: unbounded
  int max_iterations = 200;
};

struct CeresSolvesTable : ModuleTable {
  // x: the start, in; the solution, out
  LeastSquaresOutcome (*fit)(const BoundedLeastSquares& problem, double* x);
  // path_prepolish.hpp's PrePolish
  double (*prepolish)(const std::vector<Eigen::Vector2d>& points, int branch, std::vector<double>* unknowns,
                      std::vector<double>* inputs, const std::vector<std::pair<double, double>>* bounds);
  // the sum of squared distances at the end (u: the start, in; the solution, out); infinity
  // when the start cannot be evaluated or the solve fails
  double (*timed_path)(const TimedPathProblem& problem, double* u);
  // glog, which Ceres logs through, lets only fatal messages through (quiet_solver_log.hpp)
  void (*quiet_solver_log)();
};

// The module's functions, loaded on the first call; std::runtime_error when it cannot be loaded.
inline const CeresSolvesTable& CeresSolves() { return static_cast<const CeresSolvesTable&>(LoadModule("ceres")); }

}  // namespace koppel
