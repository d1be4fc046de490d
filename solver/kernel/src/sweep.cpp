#include "koppel/solver/sweep.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/assembly.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace koppel {
namespace {

std::string FormatInterval(const Mechanism& m, double a, double b) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.10g", m.InputIsAngle() ? RadToDeg(b) : b);
  return FormatInput(m, a) + " .. " + buffer + (m.InputIsAngle() ? " deg" : "");
}

// Two singular points of one kind closer than this (rad, or times L) are one point, met by two
// walks: far above their location's roundoff, far below two distinct singular positions.
constexpr double kSameSingularPoint = 1e-9;

// The end of one outward walk.
struct WalkEnd {
  bool complete = true;
  WalkStatus status = WalkStatus::kReached;
  double input = 0.0;  // where it stopped (when not complete)
  std::string message;
};

// The outputs with undefined cells, each with the inputs (up to four) and the orders concerned.
std::string UndefinedMessage(const Mechanism& m, const SweepResult& r, int order) {
  std::string text;
  const int per_component = order + 1;
  const int outputs = static_cast<int>(m.outputs.size());
  for (int o = 0; o < outputs; ++o) {
    const int column0 = OutputColumn(m, o, 0, order);
    const int end = o + 1 < outputs ? OutputColumn(m, o + 1, 0, order) : static_cast<int>(r.outputs.cols());
    std::vector<int> rows;
    int lowest = order + 1, highest = -1;
    for (const SweepResult::Cell& c : r.undefined) {
      if (c.column < column0 || c.column >= end) continue;
      if (rows.empty() || rows.back() != c.row) rows.push_back(c.row);
      lowest = std::min(lowest, c.column % per_component);
      highest = std::max(highest, c.column % per_component);
    }
    if (rows.empty()) continue;
    std::string inputs;
    for (size_t k = 0; k < rows.size() && k < 4; ++k) {
      char buffer[48];
      std::snprintf(buffer, sizeof buffer, "%.10g", m.InputIsAngle() ? RadToDeg(r.inputs[rows[k]]) : r.inputs[rows[k]]);
      inputs += (k ? ", " : "") + std::string(buffer);
    }
    if (rows.size() > 4) inputs += ", ... (" + std::to_string(rows.size()) + " rows)";
    const std::string orders = lowest == 0 ? (highest == 0 ? "its value" : "its value and derivatives up to order " + std::to_string(highest))
                                           : "its derivatives of order " + std::to_string(lowest) +
                                                 (highest > lowest ? " to " + std::to_string(highest) : "");
    text += (text.empty() ? "" : "; ") + std::string("output '") + m.outputs[o].name + "' is not differentiable at " +
            m.drive.input_name + " = " + inputs + (m.InputIsAngle() ? " deg" : "") + ": " + orders +
            " there are not finite numbers (e.g. a distance through zero) and are left empty";
  }
  return text;
}

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

  const double input_scale = m.InputIsAngle() ? 1.0 : solver.system().length_scale();
  const int width = solver.OutputWidth(options.order);
  Table outputs(samples, width), poses(samples, n);
  std::vector<std::uint8_t> done(samples, 0), singular(samples, 0);
  std::vector<std::int8_t> valid(samples, static_cast<std::int8_t>(options.order));
  // Each sample is walked to at its target: its own input, or for an R drive the same angle a
  // whole number of turns away (the drive row is periodic: the pose at input + 2 pi k is the pose
  // at input) when the branch reaches it only there. Targets at or above the assembly input are
  // reached walking up, the others walking down; each walk visits its samples outward.
  std::vector<SweepResult::Cell> undefined_cells;  // by sample index, then by row
  std::vector<double> target(samples);
  for (int i = 0; i < samples; ++i) target[i] = options.from + i * step;
  const int derivative_order = std::max(options.order, 2);
  // the singular points a walk met, each once (two walks may meet one)
  auto absorb = [&](const Continuation& path, bool only_in_range) {
    for (const SingularPoint& p : path.singular_points()) {
      // an exploring walk's point counts where it bounds part of the range (a turn away, maybe)
      if (only_in_range && std::ceil((std::min(options.from, options.to) - p.input) / (2 * kPi)) * 2 * kPi + p.input >
                               std::max(options.from, options.to))
        continue;
      const bool known = std::any_of(result.singular_points.begin(), result.singular_points.end(), [&](const SingularPoint& k) {
        return k.kind == p.kind && std::abs(k.input - p.input) <= kSameSingularPoint * input_scale;
      });
      if (!known) result.singular_points.push_back(p);
    }
  };
  auto walk = [&](const std::vector<int>& indices) {
    WalkEnd end;
    Continuation path(solver, options.continuation);
    path.Start(assembly.input, assembly.q);
    for (int i : indices) {
      const WalkReport report = path.AdvanceTo(target[i], std::numeric_limits<double>::infinity());
      if (!report.ok()) {
        end = {false, report.status, report.input, report.message};
        break;
      }
      const Eigen::MatrixXd& coefficients = path.Series(derivative_order);
      solver.OutputDerivatives(coefficients, options.order, outputs.row(i).data());
      for (int column = 0; column < width; ++column) {
        if (std::isfinite(outputs(i, column))) continue;
        outputs(i, column) = 0.0;  // never a non-finite number in a result
        undefined_cells.push_back({i, column});
      }
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
    absorb(path, false);
    return end;
  };
  // walks up and down over `indices` (by target, outward from the assembly)
  auto walk_both = [&](const std::vector<int>& indices, WalkEnd* up_end, WalkEnd* down_end) {
    std::vector<int> up, down;
    up.reserve(indices.size());
    down.reserve(indices.size());
    for (int i : indices) (target[i] >= assembly.input ? up : down).push_back(i);
    std::sort(up.begin(), up.end(), [&](int a, int b) { return target[a] < target[b]; });
    std::sort(down.begin(), down.end(), [&](int a, int b) { return target[a] > target[b]; });
    *up_end = walk(up);
    *down_end = walk(down);
  };
  std::vector<int> all(samples);
  for (int i = 0; i < samples; ++i) all[i] = i;
  WalkEnd up_end, down_end;
  walk_both(all, &up_end, &down_end);

  // the part of the branch the walks cover, [reached_low, reached_high] in the branch's inputs
  const double low = std::min(options.from, options.to), high = std::max(options.from, options.to);
  double reached_low = down_end.complete ? std::min(low, assembly.input) : down_end.input;
  double reached_high = up_end.complete ? std::max(high, assembly.input) : up_end.input;
  bool periodic = false;  // the covered part repeats every turn (samples were mapped into it)
  const double turn = 2 * kPi;
  // Only a branch that ends at limit points (the drive swings) or covers a turn is one closed
  // interval of the angle: where a walk stopped at a branch point or failed, what lies beyond is
  // another sheet (a kite's second turn), not this one a turn away.
  auto ends_in_limit = [](const WalkEnd& e) { return e.complete || e.status == WalkStatus::kLimitPoint; };
  if (m.InputIsAngle() && ends_in_limit(up_end) && ends_in_limit(down_end) && std::count(done.begin(), done.end(), 1) < samples) {
    // Samples beyond the branch's ends as numbered from the assembly may lie on it a turn away:
    // follow the branch to its ends (or over a whole turn), then map each such sample into it.
    bool closed = true;
    auto explore = [&](double to) {
      Continuation path(solver, options.continuation);
      path.Start(assembly.input, assembly.q);
      const WalkReport report = path.AdvanceTo(to, std::numeric_limits<double>::infinity());
      if (!report.ok() && report.status != WalkStatus::kLimitPoint) closed = false;
      if (closed) absorb(path, true);
      return report.ok() ? to : report.input;
    };
    const double high_end = up_end.complete ? explore(std::max(reached_high, reached_low + turn)) : reached_high;
    const double low_end = down_end.complete && closed ? explore(std::min(reached_low, high_end - turn)) : reached_low;
    if (closed) {
      reached_low = low_end;
      reached_high = high_end;
      periodic = true;
    }
    std::vector<int> mapped;
    for (int i = 0; i < samples && periodic; ++i) {
      if (done[i]) continue;
      const double x = options.from + i * step;
      const double k_low = std::ceil((reached_low - x) / turn), k_high = std::floor((reached_high - x) / turn);
      if (k_low > k_high) continue;
      const double k = k_low > 0 ? k_low : (k_high < 0 ? k_high : 0.0);  // the fewest turns away
      target[i] = x + k * turn;
      mapped.push_back(i);
    }
    WalkEnd mapped_up, mapped_down;
    if (!mapped.empty()) walk_both(mapped, &mapped_up, &mapped_down);
  }
  std::sort(result.singular_points.begin(), result.singular_points.end(),
            [](const SingularPoint& a, const SingularPoint& b) { return a.input < b.input; });

  // the gaps: what of [low, high] the covered part and its copies a turn apart (R drive) leave
  result.reached = {reached_low, reached_high};
  std::vector<InputInterval> gaps;  // ascending
  if (!periodic || reached_high - reached_low < turn) {
    double covered_to = low;  // [low, covered_to] is covered
    bool any = false;
    const double k_first = periodic ? std::floor((low - reached_high) / turn) : 0.0;
    const double k_last = periodic ? std::ceil((high - reached_low) / turn) : 0.0;
    for (double k = k_first; k <= k_last; ++k) {
      const double a = reached_low + k * turn, b = reached_high + k * turn;  // exact for k = 0
      if (b < low || a > high) continue;
      if (a > covered_to) gaps.push_back({covered_to, a});
      covered_to = std::max(covered_to, b);
      any = true;
    }
    if (!any) {
      gaps.push_back({low, high});
    } else if (covered_to < high) {
      gaps.push_back({covered_to, high});
    }
  }
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
  std::vector<int> row_of(samples, -1);
  for (int i = 0, row = 0; i < samples; ++i) {
    if (!done[i]) continue;
    row_of[i] = row;
    result.inputs.push_back(options.from + i * step);
    result.outputs.row(row) = outputs.row(i);
    result.poses.row(row) = poses.row(i);
    result.singular.push_back(singular[i]);
    result.valid_order.push_back(valid[i]);
    ++row;
  }

  // cells above a row's valid order are not computable anyway (valid_order says so)
  for (const SweepResult::Cell& c : undefined_cells) {
    if (done[c.row] && c.column % (options.order + 1) <= valid[c.row]) result.undefined.push_back({row_of[c.row], c.column});
  }
  std::sort(result.undefined.begin(), result.undefined.end());
  const std::string undefined_text = UndefinedMessage(m, result, options.order);
  if (count == samples) {
    result.status = SweepStatus::kComplete;
    result.message = undefined_text;
    return result;
  }
  result.status = SweepStatus::kPartial;
  std::string text = std::to_string(samples - count) + " of " + std::to_string(samples) + " samples lie outside the drivable part of the branch (";
  for (size_t g = 0; g < result.gaps.size(); ++g) text += (g ? "; " : "") + FormatInterval(m, result.gaps[g].from, result.gaps[g].to);
  text += ")";
  for (const WalkEnd* end : {&up_end, &down_end}) {
    if (!end->complete) text += "; " + end->message;
  }
  result.message = text + (undefined_text.empty() ? "" : "; " + undefined_text);
  return result;
}

bool SweepResult::Defined(int row, int column) const {
  return !std::binary_search(undefined.begin(), undefined.end(), Cell{row, column});
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
