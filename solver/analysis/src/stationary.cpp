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
  if (order < 1 || order + 1 > kMaxOrder) return fail("order must be between 1 and kMaxOrder - 1");
  if (!std::isfinite(target)) return fail("target must be finite");
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
  const int k = options.order;
  const int column = OutputColumn(m, output, component, k + 1);
  std::vector<double> derivatives(solver.OutputWidth(k + 1));
  for (int it = 0; it < options.max_iterations; ++it) {
    solver.OutputDerivatives(path.Series(k + 1), k + 1, derivatives.data());
    const double y1 = derivatives[column + k] - options.target, y2 = derivatives[column + k + 1];
    result.iterations = it;
    if (y2 == 0.0) return Failed(result, "the next derivative vanishes: no isolated root");
    // Newton on y^(k)(input) = target, its step capped so that the search stays near its start
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

StationaryPoint RefineFold(const Mechanism& m, int output, double fold, double input, const Eigen::VectorXd& q, double bracket_low,
                           double bracket_high, const StationaryOptions& options) {
  StationaryPoint result;
  std::string why;
  if (!options.IsValid(&why)) return Failed(result, "invalid options: " + why);
  PositionSolver solver(m);
  Continuation path(solver, options.continuation);
  if (!path.Start(input, q).ok()) return Failed(result, "the starting pose does not solve");
  const int column = OutputColumn(m, output, 0, 1);
  std::vector<double> derivatives(solver.OutputWidth(1));
  for (int it = 0; it < options.max_iterations; ++it) {
    solver.OutputDerivatives(path.Series(1), 1, derivatives.data());
    const double y = derivatives[column], y1 = derivatives[column + 1];
    result.iterations = it;
    if (y1 == 0.0) return Failed(result, "the output is stationary here: no fold");
    // Newton on h = sign(y') (y - fold) with h' = |y'|
    const double step = -(y1 > 0 ? y - fold : fold - y) / std::abs(y1);
    if (std::abs(step) <= options.input_tolerance) {
      result.status = AnalysisStatus::kComplete;
      result.input = path.input();
      result.value = y;
      result.q = path.q();
      return result;
    }
    const double next = path.input() + step;
    if (next < bracket_low || next > bracket_high) return Failed(result, "no fold in the bracket");
    const WalkReport moved = path.AdvanceTo(next, options.max_step);
    if (!moved.ok()) return Failed(result, "the branch ends before the fold: " + moved.message);
  }
  return Failed(result, "Newton on the folded output did not converge");
}

}  // namespace koppel
