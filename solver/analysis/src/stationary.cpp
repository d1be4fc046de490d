#include "koppel/analysis/stationary.hpp"

#include "koppel/solver/sweep.hpp"

#include <cmath>
#include <vector>

namespace koppel {

StationaryPoint RefineStationary(const Mechanism& m, int output, int component, double input, const Eigen::VectorXd& q,
                                 const StationaryOptions& options) {
  StationaryPoint result;
  PositionSolver solver(m);
  Continuation path(solver);
  if (!path.Start(input, q).ok()) {
    result.message = "the starting pose does not solve";
    return result;
  }
  const int column = OutputColumn(m, output, component, 2);
  std::vector<double> derivatives(solver.OutputWidth(2));
  for (int it = 0; it < options.max_iterations; ++it) {
    solver.OutputDerivatives(path.Series(2), 2, derivatives.data());
    const double y1 = derivatives[column + 1], y2 = derivatives[column + 2];
    result.iterations = it;
    if (y2 == 0.0) {
      result.message = "the second derivative vanishes: no isolated stationary point";
      return result;
    }
    double step = -y1 / y2;
    if (std::abs(step) <= options.input_tolerance) {
      result.found = true;
      result.input = path.input();
      result.value = derivatives[column];
      result.second = y2;
      result.q = path.q();
      return result;
    }
    if (std::abs(step) > options.max_step) step = std::copysign(options.max_step, step);
    const WalkReport moved = path.AdvanceTo(path.input() + step, options.max_step);
    if (!moved.ok()) {
      result.message = "the branch ends before the stationary point: " + moved.message;
      return result;
    }
  }
  result.message = "Newton on the first-order transfer function did not converge";
  return result;
}

}  // namespace koppel
