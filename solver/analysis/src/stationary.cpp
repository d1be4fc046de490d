#include "koppel/analysis/stationary.hpp"

#include "koppel/solver/sweep.hpp"

#include <cmath>
#include <limits>
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

namespace {

// One Newton step in the input from the output's value and transfer functions up to the order
// asked for (d[0] = y, d[1] = y', ...): the step, or why there is none.
struct NewtonStep {
  double step = 0;
  const char* stop = nullptr;  // set: no isolated root from here
};

// Newton in the input along the assembly branch (continuation between the steps, each capped at
// max_step): `step_of` gives the step from the transfer functions up to `order` at the current
// pose; converged when the step is below input_tolerance (`second`: the order of the transfer
// function reported as StationaryPoint::second, 0 for none); a step to outside low..high ends
// the search.
template <class StepOf>
StationaryPoint Newton(const Mechanism& m, int output, int component, int order, int second, double input, const Eigen::VectorXd& q,
                       const StationaryOptions& options, double low, double high, StepOf step_of) {
  StationaryPoint result;
  std::string why;
  if (!options.IsValid(&why)) return Failed(result, "invalid options: " + why);
  PositionSolver solver(m);
  Continuation path(solver, options.continuation);
  if (!path.Start(input, q).ok()) return Failed(result, "the starting pose does not solve");
  const int column = OutputColumn(m, output, component, order);
  std::vector<double> derivatives(solver.OutputWidth(order));
  for (int it = 0; it < options.max_iterations; ++it) {
    path.OutputDerivatives(order, derivatives.data());
    const double* d = derivatives.data() + column;
    result.iterations = it;
    const NewtonStep next = step_of(d);
    if (next.stop) return Failed(result, next.stop);
    if (std::abs(next.step) <= options.input_tolerance) {
      result.status = AnalysisStatus::kComplete;
      result.input = path.input();
      result.value = d[0];
      result.second = second > 0 ? d[second] : 0.0;
      result.q = path.q();
      return result;
    }
    if (path.input() + next.step < low || path.input() + next.step > high) return Failed(result, "no root in the bracket");
    const double step = std::abs(next.step) > options.max_step ? std::copysign(options.max_step, next.step) : next.step;
    const WalkReport moved = path.AdvanceTo(path.input() + step, options.max_step);
    if (!moved.ok()) return Failed(result, "the branch ends before the root: " + moved.message);
  }
  return Failed(result, "Newton did not converge");
}

}  // namespace

StationaryPoint RefineStationary(const Mechanism& m, int output, int component, double input, const Eigen::VectorXd& q,
                                 const StationaryOptions& options) {
  const int k = options.order;
  const double infinity = std::numeric_limits<double>::infinity();
  // Newton on y^(k)(input) = target with y^(k+1)
  return Newton(m, output, component, k + 1, k + 1, input, q, options, -infinity, infinity, [&](const double* d) {
    if (d[k + 1] == 0.0) return NewtonStep{0, "the next derivative vanishes: no isolated root"};
    return NewtonStep{-(d[k] - options.target) / d[k + 1]};
  });
}

StationaryPoint RefineFold(const Mechanism& m, int output, double fold, double input, const Eigen::VectorXd& q, double bracket_low,
                           double bracket_high, const StationaryOptions& options) {
  // Newton on h = sign(y') (y - fold) with h' = |y'|
  return Newton(m, output, 0, 1, 0, input, q, options, bracket_low, bracket_high, [&](const double* d) {
    if (d[1] == 0.0) return NewtonStep{0, "the output is stationary here: no fold"};
    return NewtonStep{-(d[1] > 0 ? d[0] - fold : fold - d[0]) / std::abs(d[1])};
  });
}

}  // namespace koppel
