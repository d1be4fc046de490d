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

namespace {

// What the walks along the branch write, by sample index, while the sweep runs: the samples'
// targets and, for each sample a walk reached, its outputs, pose, valid order and singular flag.
struct SweepWalks {
  SweepWalks(const Mechanism& m_, const SweepOptions& options_, PositionSolver& solver_, const Assembly& assembly_,
             int samples_, double step_)
      : m(m_), options(options_), solver(solver_), assembly(assembly_), samples(samples_), step(step_),
        input_scale(m_.InputIsAngle() ? 1.0 : solver_.system().length_scale()),
        width(solver_.OutputWidth(options_.order)), outputs(samples_, width), poses(samples_, options_.poses ? solver_.NumCoordinates() : 0),
        done(samples_, 0), singular(samples_, 0), valid(samples_, static_cast<std::int8_t>(options_.order)),
        target(samples_) {
    for (int i = 0; i < samples; ++i) target[i] = options.from + i * step;
  }
  int Reached() const { return static_cast<int>(std::count(done.begin(), done.end(), 1)); }

  const Mechanism& m;
  const SweepOptions& options;
  PositionSolver& solver;
  const Assembly& assembly;
  const int samples;
  const double step;  // signed: from + i * step is sample i's input
  const double input_scale;
  const int width;
  Table outputs, poses;
  std::vector<std::uint8_t> done, singular;
  std::vector<std::int8_t> valid;
  // Each sample is walked to at its target: its own input, or for an R drive the same angle a
  // whole number of turns away (the drive row is periodic: the pose at input + 2 pi k is the pose
  // at input) when the branch reaches it only there.
  std::vector<double> target;
  std::vector<SweepResult::Cell> undefined_cells;  // by sample index, then by row
  std::vector<SingularPoint> singular_points;      // the ones the walks met, each once
};

// Adds the singular points a walk met, each once (two walks may meet one).
void AbsorbSingularPoints(SweepWalks& w, const Continuation& path, bool only_in_range) {
  for (const SingularPoint& p : path.singular_points()) {
    // an exploring walk's point counts where it bounds part of the range (a turn away, maybe)
    if (only_in_range && std::ceil((std::min(w.options.from, w.options.to) - p.input) / (2 * kPi)) * 2 * kPi + p.input >
                             std::max(w.options.from, w.options.to))
      continue;
    const bool known = std::any_of(w.singular_points.begin(), w.singular_points.end(), [&](const SingularPoint& k) {
      return k.kind == p.kind && std::abs(k.input - p.input) <= kSameSingularPoint * w.input_scale;
    });
    if (!known) w.singular_points.push_back(p);
  }
}

// Writes sample i from the walk standing at its target: outputs and their derivatives, pose,
// valid order, singular flag.
void RecordSample(SweepWalks& w, int i, Continuation& path) {
  const int order = w.options.order;
  path.OutputDerivatives(order, w.outputs.row(i).data());
  for (int column = 0; column < w.width; ++column) {
    if (std::isfinite(w.outputs(i, column))) continue;
    w.outputs(i, column) = 0.0;  // never a non-finite number in a result
    w.undefined_cells.push_back({i, column});
  }
  w.valid[i] = static_cast<std::int8_t>(std::min(path.ValidOrder(), order));
  if (w.valid[i] < order) {
    // transfer functions the pose cannot give are zeroed; valid_order tells the reader
    for (int column = 0; column < w.width; ++column) {
      if (column % (order + 1) > w.valid[i]) w.outputs(i, column) = 0.0;
    }
  }
  w.singular[i] = path.AtSingularPose() ? 1 : 0;
  if (w.options.poses) w.poses.row(i) = path.q().transpose();
  w.done[i] = 1;
}

// One walk from the assembly through the samples `indices` (in walking order) to their targets;
// it stops at the first target it cannot reach.
WalkEnd WalkThroughSamples(SweepWalks& w, const std::vector<int>& indices) {
  WalkEnd end;
  Continuation path(w.solver, w.options.continuation);
  path.Start(w.assembly.input, w.assembly.q);
  for (int i : indices) {
    const WalkReport report = path.AdvanceTo(w.target[i], std::numeric_limits<double>::infinity());
    if (!report.ok()) {
      end = {false, report.status, report.input, report.message};
      break;
    }
    RecordSample(w, i, path);
  }
  AbsorbSingularPoints(w, path, false);
  return end;
}

// Walks up and down over `indices`: targets at or above the assembly input are reached walking
// up, the others walking down; each walk visits its samples outward.
void WalkUpAndDown(SweepWalks& w, const std::vector<int>& indices, WalkEnd* up_end, WalkEnd* down_end) {
  std::vector<int> up, down;
  up.reserve(indices.size());
  down.reserve(indices.size());
  for (int i : indices) (w.target[i] >= w.assembly.input ? up : down).push_back(i);
  std::sort(up.begin(), up.end(), [&](int a, int b) { return w.target[a] < w.target[b]; });
  std::sort(down.begin(), down.end(), [&](int a, int b) { return w.target[a] > w.target[b]; });
  *up_end = WalkThroughSamples(w, up);
  *down_end = WalkThroughSamples(w, down);
}

// The part of the branch the walks cover, [low, high] in the branch's inputs; `periodic` when it
// repeats every turn (samples were mapped into it).
struct CoveredPart {
  double low = 0.0, high = 0.0;
  bool periodic = false;
};

// Follows the branch from the assembly to `to` (or to the limit point before it), adding the
// singular points it meets within the range while the branch still looks closed; returns where it
// stopped and clears `closed` when it stopped other than at a limit point.
double ExploreBranchEnd(SweepWalks& w, double to, bool* closed) {
  Continuation path(w.solver, w.options.continuation);
  path.Start(w.assembly.input, w.assembly.q);
  const WalkReport report = path.AdvanceTo(to, std::numeric_limits<double>::infinity());
  if (!report.ok() && report.status != WalkStatus::kLimitPoint && report.status != WalkStatus::kRunOff) *closed = false;
  if (*closed) AbsorbSingularPoints(w, path, true);
  return report.ok() ? to : report.input;
}

// The part of the branch the first walks covered, and for an R drive whose branch ends at limit
// points (or covers a turn) with samples left over, the whole branch: each left-over sample is
// mapped into it (the fewest turns away) and walked to there.
CoveredPart CoverBranchOverTurns(SweepWalks& w, const WalkEnd& up_end, const WalkEnd& down_end) {
  const SweepOptions& options = w.options;
  const double low = std::min(options.from, options.to), high = std::max(options.from, options.to);
  CoveredPart part;
  part.low = down_end.complete ? std::min(low, w.assembly.input) : down_end.input;
  part.high = up_end.complete ? std::max(high, w.assembly.input) : up_end.input;
  const double turn = 2 * kPi;
  // Only a branch that ends at limit points (the drive swings) or covers a turn is one closed
  // interval of the angle: where a walk stopped at a branch point or failed, what lies beyond is
  // another sheet (a kite's second turn), not this one a turn away.
  // (a joint running off to infinity ends the branch's finite poses as a limit point does)
  auto ends_in_limit = [](const WalkEnd& e) {
    return e.complete || e.status == WalkStatus::kLimitPoint || e.status == WalkStatus::kRunOff;
  };
  if (!w.m.InputIsAngle() || !ends_in_limit(up_end) || !ends_in_limit(down_end) || w.Reached() >= w.samples) return part;
  // Samples beyond the branch's ends as numbered from the assembly may lie on it a turn away:
  // follow the branch to its ends (or over a whole turn), then map each such sample into it.
  bool closed = true;
  const double high_end = up_end.complete ? ExploreBranchEnd(w, std::max(part.high, part.low + turn), &closed) : part.high;
  const double low_end =
      down_end.complete && closed ? ExploreBranchEnd(w, std::min(part.low, high_end - turn), &closed) : part.low;
  if (!closed) return part;
  part = {low_end, high_end, true};
  std::vector<int> mapped;
  for (int i = 0; i < w.samples; ++i) {
    if (w.done[i]) continue;
    const double x = options.from + i * w.step;
    const double k_low = std::ceil((part.low - x) / turn), k_high = std::floor((part.high - x) / turn);
    if (k_low > k_high) continue;
    const double k = k_low > 0 ? k_low : (k_high < 0 ? k_high : 0.0);  // the fewest turns away
    w.target[i] = x + k * turn;
    mapped.push_back(i);
  }
  WalkEnd mapped_up, mapped_down;
  if (!mapped.empty()) WalkUpAndDown(w, mapped, &mapped_up, &mapped_down);
  return part;
}

// The gaps, in sweep order: what of the range the covered part and its copies a turn apart (R
// drive, periodic) leave.
std::vector<InputInterval> GapsInRange(const SweepOptions& options, double step, const CoveredPart& part) {
  const double low = std::min(options.from, options.to), high = std::max(options.from, options.to);
  const double turn = 2 * kPi;
  std::vector<InputInterval> gaps;  // ascending
  if (!part.periodic || part.high - part.low < turn) {
    double covered_to = low;  // [low, covered_to] is covered
    bool any = false;
    const double k_first = part.periodic ? std::floor((low - part.high) / turn) : 0.0;
    const double k_last = part.periodic ? std::ceil((high - part.low) / turn) : 0.0;
    for (double k = k_first; k <= k_last; ++k) {
      const double a = part.low + k * turn, b = part.high + k * turn;  // exact for k = 0
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
  return gaps;
}

// Moves the computed samples into the result's rows, in sweep order, with their undefined cells.
void CollectComputedRows(const SweepWalks& w, SweepResult* result) {
  const int count = w.Reached();
  result->outputs.resize(count, w.width);
  result->poses.resize(count, w.poses.cols());
  result->inputs.reserve(count);
  result->singular.reserve(count);
  result->valid_order.reserve(count);
  std::vector<int> row_of(w.samples, -1);
  for (int i = 0, row = 0; i < w.samples; ++i) {
    if (!w.done[i]) continue;
    row_of[i] = row;
    result->inputs.push_back(w.options.from + i * w.step);
    result->outputs.row(row) = w.outputs.row(i);
    result->poses.row(row) = w.poses.row(i);
    result->singular.push_back(w.singular[i]);
    result->valid_order.push_back(w.valid[i]);
    ++row;
  }
  // cells above a row's valid order are not computable anyway (valid_order says so)
  for (const SweepResult::Cell& c : w.undefined_cells) {
    if (w.done[c.row] && c.column % (w.options.order + 1) <= w.valid[c.row])
      result->undefined.push_back({row_of[c.row], c.column});
  }
  std::sort(result->undefined.begin(), result->undefined.end());
}

// Why a partial sweep lacks samples: the gaps, and how each incomplete walk ended.
std::string PartialSweepMessage(const Mechanism& m, const SweepResult& result, int samples, const WalkEnd& up_end,
                                const WalkEnd& down_end) {
  const int count = static_cast<int>(result.inputs.size());
  // a gap narrower than the step holds no sample, but the range is not drivable all the same
  std::string text = count == samples ? "every sample was computed, but the range holds inputs the branch cannot be driven through ("
                                      : std::to_string(samples - count) + " of " + std::to_string(samples) +
                                            " samples lie outside the drivable part of the branch (";
  for (size_t g = 0; g < result.gaps.size(); ++g) text += (g ? "; " : "") + FormatInterval(m, result.gaps[g].from, result.gaps[g].to);
  text += ")";
  for (const WalkEnd* end : {&up_end, &down_end}) {
    if (!end->complete) text += "; " + end->message;
  }
  return text;
}

}  // namespace

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
  if (solver.system().NumEquations() < solver.NumCoordinates()) {
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

  // walk the branch outward from the assembly to every sample, then a turn away where it closes
  SweepWalks walks(m, options, solver, assembly, samples, step);
  std::vector<int> all(samples);
  for (int i = 0; i < samples; ++i) all[i] = i;
  WalkEnd up_end, down_end;
  WalkUpAndDown(walks, all, &up_end, &down_end);
  const CoveredPart covered = CoverBranchOverTurns(walks, up_end, down_end);
  result.singular_points = walks.singular_points;
  std::sort(result.singular_points.begin(), result.singular_points.end(),
            [](const SingularPoint& a, const SingularPoint& b) { return a.input < b.input; });

  result.reached = {covered.low, covered.high};
  result.gaps = GapsInRange(options, step, covered);
  CollectComputedRows(walks, &result);
  const std::string undefined_text = UndefinedMessage(m, result, options.order);
  if (walks.Reached() == samples && result.gaps.empty()) {
    result.status = SweepStatus::kComplete;
    result.message = undefined_text;
    return result;
  }
  result.status = SweepStatus::kPartial;
  const std::string text = PartialSweepMessage(m, result, samples, up_end, down_end);
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
