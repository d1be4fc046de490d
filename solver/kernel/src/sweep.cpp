#include "koppel/solver/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace koppel {
namespace {

std::string FormatInput(const Mechanism& m, double input) {
  char buffer[64];
  if (m.InputIsAngle()) {
    std::snprintf(buffer, sizeof buffer, "%s = %.9g deg", m.drive.input_name.c_str(), input * 180.0 / 3.14159265358979323846);
  } else {
    std::snprintf(buffer, sizeof buffer, "%s = %.9g", m.drive.input_name.c_str(), input);
  }
  return buffer;
}

}  // namespace

Continuation::Continuation(PositionSolver& solver, ContinuationOptions options)
    : solver_(solver), options_(options) {
  q_.resize(solver.NumCoordinates());
  q_trial_.resize(solver.NumCoordinates());
  predicted_.resize(solver.NumCoordinates());
}

SolveReport Continuation::Start(double input, const Eigen::VectorXd& q) {
  q_trial_ = q;
  SolveReport report = solver_.Correct(input, q_trial_);
  if (report.ok()) {
    q_ = q_trial_;
    input_ = input;
    series_order_ = -1;
  }
  return report;
}

const Eigen::MatrixXd& Continuation::Series(int order) {
  if (series_order_ != order) {
    solver_.Series(order, series_);
    series_order_ = order;
  }
  return series_;
}

SolveReport Continuation::AdvanceTo(double target, double max_step) {
  const double scale = solver_.system().length_scale();
  const double min_step = options_.min_step_fraction * max_step;
  double step = std::min(max_step, std::abs(target - input_));
  SolveReport last;
  last.status = SolveStatus::kConverged;
  bool sign_flipped = false;
  while (input_ != target) {
    const double remaining = target - input_;
    const double h = std::copysign(std::min(step, std::abs(remaining)), remaining);
    const double next = (std::abs(remaining) <= step) ? target : input_ + h;
    // predictor: second-order Taylor step along the branch
    const Eigen::MatrixXd& c = Series(std::max(series_order_, 2));
    q_trial_ = c.col(0) + h * c.col(1) + (h * h) * c.col(2);
    const int sign_before = solver_.JacobianSign();
    predicted_ = q_trial_;  // a member: no allocation inside a sweep
    SolveReport report = solver_.Correct(next, q_trial_);
    const bool flipped = report.ok() && sign_before != 0 && solver_.JacobianSign() != sign_before;
    const bool accepted = report.ok() && !flipped && report.iterations <= options_.max_corrector_iterations &&
                          (q_trial_ - predicted_).lpNorm<Eigen::Infinity>() <= options_.max_correction * scale;
    if (accepted) {
      q_ = q_trial_;
      input_ = next;
      series_order_ = -1;
      step = std::min(max_step, 2.0 * step);
      continue;
    }
    sign_flipped |= flipped;
    last = report;
    // restore the factorisation at the current pose, then try a shorter step
    q_trial_ = q_;
    solver_.Correct(input_, q_trial_);
    series_order_ = -1;
    step *= 0.5;
    if (step < min_step) {
      SolveReport failure;
      const bool singular = sign_flipped || last.status == SolveStatus::kSingular || solver_.PivotRatio() < 1e-4;
      failure.status = singular ? SolveStatus::kSingular : SolveStatus::kDidNotConverge;
      failure.residual_norm = last.residual_norm;
      failure.iterations = last.iterations;
      failure.message = singular ? "the mechanism reaches a singular position (the Jacobian loses rank: a dead centre "
                                   "with respect to the drive, or a branch point); it cannot be driven past it"
                                 : "no pose could be found beyond this input (" + last.message + ")";
      return failure;
    }
  }
  return last.ok() ? last : SolveReport{SolveStatus::kConverged, 0.0, 0, -1, ""};
}

InputRange DrivableRange(const Mechanism& mechanism, double span, double step) {
  InputRange range;
  SweepOptions options;
  options.order = 0;
  options.step = step;
  options.from = mechanism.hint.input;
  options.to = mechanism.hint.input + span;
  const SweepResult up = Sweep(mechanism, options);
  range.high = up.complete() ? options.to : up.stopped_at;
  range.high_limited = !up.complete();
  options.to = mechanism.hint.input - span;
  const SweepResult down = Sweep(mechanism, options);
  range.low = down.complete() ? options.to : down.stopped_at;
  range.low_limited = !down.complete();
  return range;
}

int SampleCount(double from, double to, double step) {
  if (step == 0.0) return 1;
  const double n = std::floor(std::abs(to - from) / std::abs(step) + 1e-9);
  return static_cast<int>(n) + 1;
}

SweepResult Sweep(const Mechanism& mechanism, const SweepOptions& options) {
  SweepResult result;
  result.order = std::clamp(options.order, 0, kMaxOrder);
  PositionSolver solver(mechanism);
  const int samples = SampleCount(options.from, options.to, options.step);
  const double step = std::copysign(std::abs(options.step), options.to - options.from);
  result.requested_samples = samples;
  result.outputs.resize(samples, solver.OutputWidth(result.order));
  result.poses.resize(samples, solver.NumCoordinates());
  result.inputs.reserve(samples);

  Eigen::VectorXd q(solver.NumCoordinates());
  const SolveReport assembled = solver.Assemble(q);
  if (!assembled.ok()) {
    result.status = SolveStatus::kNotAssemblable;
    result.stopped_at = mechanism.hint.input;
    result.message = "cannot assemble at " + FormatInput(mechanism, mechanism.hint.input) + ": " + assembled.message;
    result.outputs.resize(0, result.outputs.cols());
    result.poses.resize(0, result.poses.cols());
    return result;
  }
  Continuation path(solver, options.continuation);
  path.Start(mechanism.hint.input, q);
  const double max_step = std::abs(options.step) > 0 ? std::abs(options.step) : 3.14159265358979323846 / 180.0;
  for (int i = 0; i < samples; ++i) {
    const double target = options.from + i * step;
    const SolveReport report = path.AdvanceTo(target, max_step);
    if (!report.ok()) {
      result.status = report.status;
      result.stopped_at = path.input();
      result.message = "sweep stopped at " + FormatInput(mechanism, path.input()) + ": " + report.message + "; " +
                       std::to_string(samples - i) + " of " + std::to_string(samples) + " samples not computed";
      break;
    }
    const Eigen::MatrixXd& coefficients = path.Series(std::max(result.order, 2));
    result.inputs.push_back(target);
    solver.OutputDerivatives(coefficients, result.order, result.outputs.row(i).data());
    result.poses.row(i) = path.q().transpose();
  }
  const int done = static_cast<int>(result.inputs.size());
  result.outputs.conservativeResize(done, Eigen::NoChange);
  result.poses.conservativeResize(done, Eigen::NoChange);
  return result;
}

}  // namespace koppel
