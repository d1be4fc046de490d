#include "koppel/analysis/stationary.hpp"

#include "koppel/solver/sweep.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace koppel {
namespace {

StationaryPoint Failed(StationaryPoint result, std::string message) {
  result.status = AnalysisStatus::kFailed;
  result.message = std::move(message);
  return result;
}

}  // namespace

bool StationaryOptions::IsValid(std::string* why) const {
  auto fail = [&](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (!(input_tolerance > 0) || !std::isfinite(input_tolerance)) return fail("input_tolerance must be positive and finite");
  if (max_iterations < 1) return fail("max_iterations must be at least 1");
  if (!(max_step > 0) || !std::isfinite(max_step)) return fail("max_step must be positive and finite");
  return continuation.IsValid(why);
}

std::string StationaryPoint::Brief() const {
  return std::string(ToString(status)) + (ok() ? " at input " + std::to_string(input) : ": " + message) + " (" +
         std::to_string(iterations) + " iterations)";
}

StationaryPoint RefineStationary(const Mechanism& m, int output, int component, double input, const Eigen::VectorXd& q,
                                 const StationaryOptions& options) {
  StationaryPoint result;
  std::string why;
  if (!options.IsValid(&why)) return Failed(result, "invalid options: " + why);
  PositionSolver solver(m);
  Continuation path(solver, options.continuation);
  if (!path.Start(input, q).ok()) return Failed(result, "the starting pose does not solve");
  const int column = OutputColumn(m, output, component, 2);
  std::vector<double> derivatives(solver.OutputWidth(2));
  for (int it = 0; it < options.max_iterations; ++it) {
    solver.OutputDerivatives(path.Series(2), 2, derivatives.data());
    const double y1 = derivatives[column + 1], y2 = derivatives[column + 2];
    result.iterations = it;
    if (y2 == 0.0) return Failed(result, "the second derivative vanishes: no isolated stationary point");
    // Newton on y'(input) = 0, its step capped so that the search stays near its start
    double step = -y1 / y2;
    if (std::abs(step) <= options.input_tolerance) {
      result.status = AnalysisStatus::kComplete;
      result.input = path.input();
      result.value = derivatives[column];
      result.second = y2;
      result.q = path.q();
      return result;
    }
    if (std::abs(step) > options.max_step) step = std::copysign(options.max_step, step);
    const WalkReport moved = path.AdvanceTo(path.input() + step, options.max_step);
    if (!moved.ok()) return Failed(result, "the branch ends before the stationary point: " + moved.message);
  }
  return Failed(result, "Newton on the first-order transfer function did not converge");
}

}  // namespace koppel
