#include "stationary_search.hpp"

#include "same_pose.hpp"

#include "koppel/core/angles.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace koppel {
namespace {

// Inputs closer than this (rad; a sliding drive: times its length scale) are one input, and a
// root this far outside the range is at its edge: far above the refinement's 1e-12 and the
// roundoff of a drive zero from a formula, far below any two distinct dead centres.
constexpr double kSameInput = 1e-9;
// Neighbouring samples are one step apart; this much more is roundoff of from + i step, not a gap.
constexpr double kStepSlack = 1e-6;
// An output whose samples all lie within this of each other (rad; a length: times the length
// scale) is constant: solver roundoff is ~1e-13 of the size.
constexpr double kConstantOutput = 1e-12;
// Whole turns tried for the period of a rotating drive (as ranges.hpp's max_turns).
constexpr int kMaxTurns = 4;

// A sign change of y' between two samples; `closing`: the second is sample 0 one period on.
struct Bracket {
  int first = 0, second = 0;
  bool closing = false;
};

class Searcher {
 public:
  Searcher(const Mechanism& m, int output, int component, const SweepOptions& range, StationarySearch& s)
      : m_(m), output_(output), component_(component), range_(range), s_(s), direction_(range.to >= range.from ? 1.0 : -1.0) {
    refine_.max_step = s_.step;
    refine_.continuation = range.continuation;
  }

  void Run() {
    s_.period = Period();
    s_.window = direction_ > 0 ? range_.from : range_.from - s_.period;
    const int used = UsedSamples();
    s_.constant = Constant(used);
    if (s_.constant) return;
    for (int i = 0; i + 1 < used; ++i) {
      if (Adjacent(i, i + 1) && SlopeKnown(i) && SlopeKnown(i + 1) && SignChange(Slope(i), Slope(i + 1))) Resolve({i, i + 1, false});
    }
    if (s_.period > 0) {
      if (SlopeKnown(used - 1) && SlopeKnown(0) && SignChange(Slope(used - 1), Slope(0))) Resolve({used - 1, 0, true});
    } else {
      for (int i = 0; i < used; ++i) {
        const bool starts = i == 0 || !Adjacent(i - 1, i), stops = i + 1 == used || !Adjacent(i, i + 1);
        if (starts || stops) s_.ends.push_back(i);
      }
      for (int e : s_.ends) RefineEnd(e);
    }
    auto by_input = [](const StationaryPoint& a, const StationaryPoint& b) { return a.input < b.input; };
    std::sort(s_.points.begin(), s_.points.end(), by_input);
    std::sort(s_.folds.begin(), s_.folds.end(), by_input);
  }

 private:
  double Input(int i) const { return s_.sweep.inputs[i]; }
  double Slope(int i) const { return s_.sweep.outputs(i, s_.column + 1); }
  // a sample on a limit point has no y' (infinite there, stored as 0): no sign change with it
  bool SlopeKnown(int i) const { return s_.sweep.valid_order[i] >= 1; }
  Eigen::VectorXd Pose(int i) const { return s_.sweep.poses.row(i).transpose(); }
  bool Adjacent(int i, int j) const { return std::abs(Input(j) - Input(i)) <= s_.step * (1 + kStepSlack); }

  // The period of the pose when the range covers whole turns of a rotating drive: the pose one
  // turn (or k turns) on from the first sample is the first sample's pose. 0 otherwise. Records
  // what the output gains over the period (an output that turns with the drive gains 2 pi k).
  double Period() {
    const SweepResult& sweep = s_.sweep;
    if (!m_.InputIsAngle() || !sweep.complete() || sweep.inputs.empty()) return 0.0;
    PositionSolver solver(m_);
    for (int k = 1; k <= kMaxTurns && 2 * kPi * k <= s_.high - s_.low + s_.tolerance; ++k) {
      const double turn = 2 * kPi * k;
      int last = 0;  // the last sample at most a turn on
      while (last + 1 < static_cast<int>(sweep.inputs.size()) && direction_ * (Input(last + 1) - range_.from) <= turn + s_.tolerance) ++last;
      Continuation path(solver, range_.continuation);
      if (!path.Start(Input(last), Pose(last)).ok()) return 0.0;
      if (!path.AdvanceTo(range_.from + direction_ * turn, s_.step).ok()) return 0.0;
      if (SamePose(path.q(), Pose(0), solver.system().length_scale())) {
        std::vector<double> y(solver.OutputWidth(0));
        path.OutputDerivatives(0, y.data());
        s_.turn_gain = y[OutputColumn(m_, output_, component_, 0)] - s_.sweep.outputs(0, s_.column);
        return turn;
      }
    }
    return 0.0;
  }

  bool Constant(int used) const {
    const auto y = s_.sweep.outputs.col(s_.column).head(used);
    const double scale = m_.OutputIsAngle(output_) ? 1.0 : LengthScale(m_);
    return y.maxCoeff() - y.minCoeff() <= kConstantOutput * scale;
  }

  // The samples searched: a periodic search stops before the first sample's repeat.
  int UsedSamples() const {
    const int n = static_cast<int>(s_.sweep.inputs.size());
    if (s_.period <= 0) return n;
    int used = 0;
    while (used < n && direction_ * (Input(used) - range_.from) < s_.period - s_.tolerance) ++used;
    return used;
  }

  // The input of a bracket's end: the closing bracket's second end is sample 0 one period on.
  double EndInput(const Bracket& b, bool second) const {
    if (!second) return Input(b.first);
    return b.closing ? Input(0) + direction_ * s_.period : Input(b.second);
  }

  void Resolve(const Bracket& b) {
    const double a = EndInput(b, false), c = EndInput(b, true);
    const double low = std::min(a, c), high = std::max(a, c), middle = 0.5 * (a + c);
    const bool transmission = m_.outputs[output_].kind == OutputKind::kTransmissionAngle;
    // y' + to - with increasing input: a maximum (a transmission angle's fold at 90 deg)
    const double slope_low = a <= c ? Slope(b.first) : Slope(b.second);
    const double slope_high = a <= c ? Slope(b.second) : Slope(b.first);
    const bool maximum = slope_low > 0 || (slope_low == 0 && slope_high < 0);
    // start from the end nearer the root (smaller |y'|); no path starts on a singular pose
    int order[2] = {b.first, b.second};
    if (std::abs(Slope(b.second)) < std::abs(Slope(b.first))) std::swap(order[0], order[1]);
    for (int start : order) {
      if (s_.sweep.singular[start]) continue;
      const double input = start == b.first ? a : c;
      if (transmission) {
        const StationaryPoint fold = RefineFold(m_, output_, maximum ? kPi / 2 : 0.0, input, Pose(start), low - s_.tolerance,
                                                high + s_.tolerance, refine_);
        if (fold.ok()) return Keep(fold, s_.folds);
      }
      const StationaryPoint p = RefineStationary(m_, output_, component_, input, Pose(start), refine_);
      // a root Newton found beyond the neighbouring samples belongs to another bracket
      if (p.ok() && std::abs(p.input - middle) <= 0.5 * (high - low) + s_.step) return Keep(p, s_.points);
      if (s_.unresolved_message.empty() && !p.ok()) s_.unresolved_message = p.message;
    }
    s_.unresolved.push_back(s_.Canonical(middle));
    if (s_.unresolved_message.empty()) s_.unresolved_message = "Newton on y' leaves the samples around the sign change";
  }

  // An end of a run whose Newton prediction lands in the range: a root at (or within roundoff
  // beyond) the end, where y' need not change sign between the samples.
  void RefineEnd(int e) {
    const double y1 = Slope(e), y2 = s_.sweep.outputs(e, s_.column + 2);
    if (y2 == 0.0 || s_.sweep.singular[e]) return;
    const double predicted = Input(e) - y1 / y2;
    if (std::abs(predicted - Input(e)) > s_.step || !InRange(predicted)) return;
    const StationaryPoint p = RefineStationary(m_, output_, component_, Input(e), Pose(e), refine_);
    if (p.ok() && InRange(p.input) && std::abs(p.input - Input(e)) <= s_.step + s_.tolerance) Keep(p, s_.points);
  }

  bool InRange(double input) const { return input >= s_.low - s_.tolerance && input <= s_.high + s_.tolerance; }

  // Keeps a refined point once, its input as reported; a periodic search wraps it into its window.
  void Keep(StationaryPoint p, std::vector<StationaryPoint>& into) {
    if (s_.period <= 0 && !InRange(p.input)) return;
    p.input = s_.Canonical(p.input);
    for (const std::vector<StationaryPoint>* list : {&s_.points, &s_.folds}) {
      for (const StationaryPoint& kept : *list) {
        if (s_.Distance(kept.input, p.input) < s_.tolerance) return;
      }
    }
    into.push_back(std::move(p));
  }

  const Mechanism& m_;
  int output_, component_;
  const SweepOptions& range_;
  StationarySearch& s_;
  double direction_;
  StationaryOptions refine_;
};

}  // namespace

double SameInputTolerance(const Mechanism& m) { return kSameInput * (m.InputIsAngle() ? 1.0 : LengthScale(m)); }

void SampleRangeEnd(const Mechanism& m, const SweepOptions& options, SweepResult& sweep) {
  if (sweep.inputs.empty()) return;
  const double last = sweep.inputs.back(), rest = std::abs(options.to - last);
  if (rest <= SameInputTolerance(m) || rest > std::abs(options.step) * (1 + kStepSlack)) return;
  PositionSolver solver(m);
  Continuation path(solver, options.continuation);
  const Eigen::VectorXd q = sweep.poses.row(sweep.poses.rows() - 1).transpose();
  if (!path.Start(last, q).ok() || !path.AdvanceTo(options.to, std::abs(options.step)).ok()) return;
  const Eigen::Index n = sweep.outputs.rows();
  sweep.outputs.conservativeResize(n + 1, Eigen::NoChange);
  path.OutputDerivatives(sweep.order, sweep.outputs.row(n).data());
  sweep.poses.conservativeResize(n + 1, Eigen::NoChange);
  sweep.poses.row(n) = path.q().transpose();
  sweep.inputs.push_back(options.to);
  sweep.singular.push_back(path.AtSingularPose() ? 1 : 0);
  sweep.valid_order.push_back(static_cast<std::int8_t>(std::min(path.ValidOrder(), sweep.order)));
}

double StationarySearch::Distance(double a, double b) const {
  return period > 0 ? std::abs(std::remainder(a - b, period)) : std::abs(a - b);
}

double StationarySearch::Canonical(double input) const {
  if (period <= 0) return input;
  double c = window + std::fmod(input - window, period);
  if (c < window) c += period;
  // a root within the tolerance below the window's end is the root at its start
  if (c > window + period - tolerance) c -= period;
  return c;
}

StationarySearch SearchStationaryPoints(const Mechanism& m, int output, int component, const SweepOptions& range) {
  StationarySearch s;
  SweepOptions options = range;
  options.order = 2;
  s.sweep = Sweep(m, options);
  s.column = OutputColumn(m, output, component, 2);
  s.step = std::abs(options.step);
  s.low = std::min(range.from, range.to);
  s.high = std::max(range.from, range.to);
  s.tolerance = SameInputTolerance(m);
  SampleRangeEnd(m, options, s.sweep);
  if (s.sweep.inputs.empty()) return s;
  Searcher(m, output, component, options, s).Run();
  return s;
}

}  // namespace koppel
