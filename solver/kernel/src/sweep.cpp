#include "koppel/solver/sweep.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/assembly.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace koppel {
namespace {

std::string FormatInput(const Mechanism& m, double input) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%s = %.10g", m.drive.input_name.c_str(), m.InputIsAngle() ? RadToDeg(input) : input);
  return std::string(buffer) + (m.InputIsAngle() ? " deg" : "");
}

std::string FormatInterval(const Mechanism& m, double a, double b) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.10g", m.InputIsAngle() ? RadToDeg(b) : b);
  return FormatInput(m, a) + " .. " + buffer + (m.InputIsAngle() ? " deg" : "");
}

// The end of one outward walk.
struct WalkEnd {
  bool complete = true;
  double input = 0.0;  // where it stopped (when not complete)
  std::string message;
};

}  // namespace

const char* ToString(SweepStatus status) {
  switch (status) {
    case SweepStatus::kNotRun: return "not run";
    case SweepStatus::kComplete: return "complete";
    case SweepStatus::kPartial: return "partial";
    case SweepStatus::kNotAssemblable: return "not assemblable";
    case SweepStatus::kInvalidOptions: return "invalid options";
  }
  return "not run";
}

bool SweepOptions::IsValid(std::string* why) const {
  auto fail = [&](std::string text) {
    if (why) *why = std::move(text);
    return false;
  };
  if (!std::isfinite(from) || !std::isfinite(to)) return fail("the sweep limits must be finite numbers");
  if (!std::isfinite(step) || step == 0.0) return fail("the step must be a finite number other than 0");
  if (order < 0 || order > kMaxOrder) return fail("the order must lie between 0 and " + std::to_string(kMaxOrder));
  if (SampleCount(from, to, step) > static_cast<double>(kMaxSweepSamples))
    return fail("the range and step ask for more than " + std::to_string(kMaxSweepSamples) + " samples");
  return continuation.IsValid(why);
}

double SampleCount(double from, double to, double step) {
  if (step == 0.0) return 1.0;
  return std::floor(std::abs(to - from) / std::abs(step) + 1e-9) + 1.0;
}

std::string SweepResult::Brief() const {
  std::string brief = std::string(ToString(status)) + ": " + std::to_string(inputs.size()) + " of " +
                      std::to_string(requested_samples) + " samples";
  int limits = 0, branches = 0, flagged = 0;
  for (const SingularPoint& p : singular_points) (p.kind == SingularKind::kLimitPoint ? limits : branches)++;
  for (std::uint8_t s : singular) flagged += s;
  if (limits) brief += ", " + std::to_string(limits) + " limit point" + (limits > 1 ? "s" : "");
  if (branches) brief += ", " + std::to_string(branches) + " branch point" + (branches > 1 ? "s" : "");
  if (flagged) brief += ", " + std::to_string(flagged) + " singular row" + (flagged > 1 ? "s" : "");
  if (!gaps.empty()) brief += ", " + std::to_string(gaps.size()) + " gap" + (gaps.size() > 1 ? "s" : "");
  return brief;
}

SweepResult Sweep(const Mechanism& m, const SweepOptions& options) {
  SweepResult result;
  result.order = options.order;
  std::string why;
  if (!options.IsValid(&why)) {
    result.status = SweepStatus::kInvalidOptions;
    result.message = why;
    return result;
  }
  PositionSolver solver(m, options.newton);
  const int n = solver.NumCoordinates();
  if (solver.system().NumEquations() < n) {
    result.status = SweepStatus::kNotAssemblable;
    result.message = "the mechanism has fewer joint equations than coordinates: more freedom than its one drive "
                     "(see CheckMobility)";
    return result;
  }
  const int samples = static_cast<int>(SampleCount(options.from, options.to, options.step));
  const double step = options.to >= options.from ? std::abs(options.step) : -std::abs(options.step);
  result.requested_samples = samples;

  const Assembly assembly = AssembleRegular(m, solver, options.continuation);
  result.notes = assembly.notes;
  if (!assembly.ok()) {
    result.status = SweepStatus::kNotAssemblable;
    result.message = assembly.error;
    result.reached = {m.hint.input, m.hint.input};
    result.gaps.push_back({options.from, options.to});
    return result;
  }

  const int width = solver.OutputWidth(options.order);
  Table outputs(samples, width), poses(samples, n);
  std::vector<std::uint8_t> done(samples, 0), singular(samples, 0);
  std::vector<std::int8_t> valid(samples, static_cast<std::int8_t>(options.order));
  // Samples at or above the assembly input are reached walking up, the others walking down; each
  // walk visits its samples outward from the assembly.
  std::vector<int> up, down;
  up.reserve(samples);
  down.reserve(samples);
  for (int i = 0; i < samples; ++i) (options.from + i * step >= assembly.input ? up : down).push_back(i);
  auto by_input = [&](bool ascending) {
    return [&, ascending](int a, int b) { return ascending == (step > 0) ? a < b : a > b; };
  };
  std::sort(up.begin(), up.end(), by_input(true));
  std::sort(down.begin(), down.end(), by_input(false));

  const int derivative_order = std::max(options.order, 2);
  auto walk = [&](const std::vector<int>& indices) {
    WalkEnd end;
    Continuation path(solver, options.continuation);
    path.Start(assembly.input, assembly.q);
    for (int i : indices) {
      const WalkReport report = path.AdvanceTo(options.from + i * step, std::numeric_limits<double>::infinity());
      if (!report.ok()) {
        end = {false, report.input, report.message};
        break;
      }
      const Eigen::MatrixXd& coefficients = path.Series(derivative_order);
      solver.OutputDerivatives(coefficients, options.order, outputs.row(i).data());
      valid[i] = static_cast<std::int8_t>(std::min(path.ValidOrder(), options.order));
      if (valid[i] < options.order) {
        // transfer functions the pose cannot give are zeroed; valid_order tells the reader
        for (int column = 0; column < width; ++column) {
          if (column % (options.order + 1) > valid[i]) outputs(i, column) = 0.0;
        }
      }
      singular[i] = path.AtSingularPose() ? 1 : 0;
      poses.row(i) = path.q().transpose();
      done[i] = 1;
    }
    result.singular_points.insert(result.singular_points.end(), path.singular_points().begin(), path.singular_points().end());
    return end;
  };
  const WalkEnd up_end = walk(up);
  const WalkEnd down_end = walk(down);
  std::sort(result.singular_points.begin(), result.singular_points.end(),
            [](const SingularPoint& a, const SingularPoint& b) { return a.input < b.input; });

  // the drivable part of the range, and the gaps around it
  const double low = std::min(options.from, options.to), high = std::max(options.from, options.to);
  const double reached_low = down_end.complete ? std::min(low, assembly.input) : down_end.input;
  const double reached_high = up_end.complete ? std::max(high, assembly.input) : up_end.input;
  result.reached = {reached_low, reached_high};
  std::vector<InputInterval> gaps;  // ascending
  if (reached_low > low) gaps.push_back({low, std::min(reached_low, high)});
  if (reached_high < high) gaps.push_back({std::max(reached_high, low), high});
  if (gaps.size() == 2 && gaps[0].to >= gaps[1].from) gaps = {{low, high}};
  if (step < 0) {
    std::reverse(gaps.begin(), gaps.end());
    for (InputInterval& g : gaps) std::swap(g.from, g.to);
  }
  result.gaps = gaps;

  // the computed rows, in sweep order
  int count = 0;
  for (int i = 0; i < samples; ++i) count += done[i];
  result.outputs.resize(count, width);
  result.poses.resize(count, n);
  result.inputs.reserve(count);
  result.singular.reserve(count);
  result.valid_order.reserve(count);
  for (int i = 0, row = 0; i < samples; ++i) {
    if (!done[i]) continue;
    result.inputs.push_back(options.from + i * step);
    result.outputs.row(row) = outputs.row(i);
    result.poses.row(row) = poses.row(i);
    result.singular.push_back(singular[i]);
    result.valid_order.push_back(valid[i]);
    ++row;
  }

  if (count == samples) {
    result.status = SweepStatus::kComplete;
    return result;
  }
  result.status = SweepStatus::kPartial;
  std::string text = std::to_string(samples - count) + " of " + std::to_string(samples) + " samples lie outside the drivable part of the branch (";
  for (size_t g = 0; g < result.gaps.size(); ++g) text += (g ? "; " : "") + FormatInterval(m, result.gaps[g].from, result.gaps[g].to);
  text += ")";
  for (const WalkEnd* end : {&up_end, &down_end}) {
    if (!end->complete) text += "; " + end->message;
  }
  result.message = text;
  return result;
}

SweepEvents EventsOf(const SweepResult& sweep) {
  SweepEvents events;
  events.status = sweep.status;
  events.message = sweep.message;
  events.notes = sweep.notes;
  events.singular_points = sweep.singular_points;
  events.gaps = sweep.gaps;
  events.reached = sweep.reached;
  for (size_t i = 0; i < sweep.inputs.size(); ++i) {
    if (sweep.singular[i]) events.singular_inputs.push_back(sweep.inputs[i]);
  }
  return events;
}

InputRange DrivableRange(const Mechanism& mechanism, double span, double step) {
  InputRange range;
  PositionSolver solver(mechanism);
  ContinuationOptions options;
  if (std::abs(step) > 0) options.max_step = std::min(options.max_step, std::abs(step));
  const Assembly assembly = AssembleRegular(mechanism, solver, options);
  if (!assembly.ok()) {
    range.low = range.high = mechanism.hint.input;
    range.low_limited = range.high_limited = true;
    return range;
  }
  for (double direction : {+1.0, -1.0}) {
    Continuation path(solver, options);
    path.Start(assembly.input, assembly.q);
    const double target = assembly.input + direction * span;
    const WalkReport report = path.AdvanceTo(target, std::numeric_limits<double>::infinity());
    (direction > 0 ? range.high : range.low) = report.ok() ? target : report.input;
    (direction > 0 ? range.high_limited : range.low_limited) = !report.ok();
  }
  return range;
}

}  // namespace koppel
