#include "koppel/plot/cycle.hpp"

#include "koppel/analysis/ranges.hpp"
#include "koppel/api/guide_travel.hpp"
#include "koppel/api/model.hpp"
#include "koppel/core/angles.hpp"

#include <algorithm>
#include <cmath>

namespace koppel::plot {
namespace {

// The mechanism with the traced points as its only outputs, so that one sweep gives the poses
// and every curve.
Mechanism WithTracedOutputs(const Mechanism& m, const std::vector<TracedPoint>& traced) {
  Mechanism copy = m;
  copy.outputs.clear();
  for (const TracedPoint& t : traced) {
    Output o;
    o.name = t.name;
    o.kind = OutputKind::kPoint;
    o.p = t.point;
    copy.outputs.push_back(o);
  }
  return copy;
}

TracedCurve CurveOf(const Mechanism& traced, const SampledRun& run, int output, bool full_turn) {
  TracedCurve curve;
  curve.name = traced.outputs[output].name;
  const int x = run.Column(traced, output, 0, 0), y = run.Column(traced, output, 1, 0);
  for (const Stretch& s : run.stretches) {
    curve.inputs.emplace_back();
    curve.runs.emplace_back();
    for (int i = s.begin; i < s.end; ++i) {
      curve.inputs.back().push_back(run.inputs[i]);
      curve.runs.back().emplace_back(run.outputs(i, x), run.outputs(i, y));
    }
  }
  // a whole turn comes back to its first point: a closed curve, without the repeated point
  curve.closed = full_turn && run.complete && curve.runs.size() == 1 && curve.runs[0].size() > 2;
  if (curve.closed) {
    curve.inputs[0].pop_back();
    curve.runs[0].pop_back();
  }
  return curve;
}

}  // namespace

Expected<CycleRange> CycleRangeOf(const Mechanism& m, const SweepOptions& sweep) {
  const RangeReport report = DrivableRanges(m);
  if (report.status != RangeStatus::kDone || report.branches.empty())
    return Expected<CycleRange>::Error(report.message.empty() ? "no drivable range found" : report.message);
  const BranchRange& branch = report.branches[0];
  CycleRange range;
  range.full_turn = branch.from_kind == RangeEnd::kFullTurn;
  range.from = branch.from;
  range.to = branch.to;
  if (!range.full_turn) {
    const double low = std::min(sweep.from, sweep.to), high = std::max(sweep.from, sweep.to);
    if (branch.from_kind == RangeEnd::kBound) range.from = low;
    if (branch.to_kind == RangeEnd::kBound) range.to = high;
    if (branch.from_kind == RangeEnd::kBound || branch.to_kind == RangeEnd::kBound)
      range.note = "the drive meets no limit on this branch: the cycle runs over the file's sweep";
    if (branch.from_kind == RangeEnd::kFailed || branch.to_kind == RangeEnd::kFailed)
      range.note = "the branch could not be followed to its end (" + branch.message + "): the cycle ends where it stopped";
  }
  if (!(range.from < range.to))
    return Expected<CycleRange>::Error("the file's sweep lies outside the drivable range of the assembly branch");
  return range;
}

std::vector<double> CycleInputs(const CycleRange& range, int frames) {
  std::vector<double> inputs;
  const double span = range.to - range.from;
  for (int i = 0; i < frames; ++i) {
    const double t = static_cast<double>(i) / frames;
    // there and back: a triangle wave from 0 up to 1 at half the frames and down again
    inputs.push_back(range.from + span * (range.full_turn ? t : 1 - std::abs(1 - 2 * t)));
  }
  return inputs;
}

double TracedUpTo(const CycleRange& range, int frames, int frame) {
  if (range.full_turn || 2 * frame <= frames) return CycleInputs(range, frames)[frame];
  return range.to;
}

std::vector<std::vector<Eigen::Vector2d>> TracedCurve::UpTo(double input) const {
  std::vector<std::vector<Eigen::Vector2d>> cut;
  for (size_t r = 0; r < runs.size(); ++r) {
    const size_t n = std::upper_bound(inputs[r].begin(), inputs[r].end(), input) - inputs[r].begin();
    if (n > 0) cut.emplace_back(runs[r].begin(), runs[r].begin() + n);
  }
  return cut;
}

Expected<CycleSamples> SampleCycle(const Mechanism& m, const CycleRange& range, const std::vector<TracedPoint>& traced,
                                   const ContinuationOptions& continuation) {
  CycleSamples samples;
  samples.range = range;
  SweepOptions options;
  options.from = range.from;
  options.to = range.to;
  options.step = (range.to - range.from) / kCycleSegments;
  options.order = 0;
  options.continuation = continuation;
  const Mechanism with_traced = WithTracedOutputs(m, traced);
  samples.run = SampleMechanism(with_traced, options);
  if (samples.run.size() == 0) return Expected<CycleSamples>::Error(samples.run.message);
  for (size_t t = 0; t < traced.size(); ++t)
    samples.curves.push_back(CurveOf(with_traced, samples.run, static_cast<int>(t), range.full_turn));
  samples.travel.assign(m.joints.size(), {0.0, 0.0});
  for (const GuideTravel& t : FindGuideTravels(m, range.from, range.to, options.step, continuation.at_branch_point)) {
    if (!Usable(t.status)) return Expected<CycleSamples>::Error("the travel of slide " + t.name + " was not found: " + t.message);
    samples.travel[t.joint] = {t.low, t.high};
  }
  return samples;
}

Expected<CycleSamples> SampleCycle(const Mechanism& m, const CycleOptions& options) {
  const Expected<CycleRange> range = CycleRangeOf(m, options.sweep);
  if (!range) return Expected<CycleSamples>::Error(range.error());
  return SampleCycle(m, *range, options.traced, options.sweep.continuation);
}

Expected<Eigen::VectorXd> PoseOnCycle(const Mechanism& m, const CycleSamples& samples, double input) {
  const SampledRun& run = samples.run;
  // a sample at the input: the same input up to the rounding of from + i step
  const double same = 1e-12 * std::max(1.0, std::abs(input));
  for (int i = 0; i < run.size(); ++i)
    if (std::abs(run.inputs[i] - input) <= same) return Eigen::VectorXd(run.poses.row(i).transpose());
  return PoseAt(m, run, input);
}

bool CycleOptions::IsValid(std::string* why) const {
  if (!sizes.IsValid(why)) return false;
  if (!std::isfinite(sweep.from) || !std::isfinite(sweep.to)) *why = "the sweep's ends must be finite";
  return why->empty();
}

CycleOptions CycleOptionsOf(const Model& model) {
  const Mechanism& m = model.mechanism();
  CycleOptions options;
  options.traced = PointOutputs(m);
  options.sizes = DefaultPartSizes(m);
  const double unit = m.InputIsAngle() ? DegToRad(1.0) : 1.0;
  options.sweep.from = model.sweep_from() * unit;
  options.sweep.to = model.sweep_to() * unit;
  return options;
}

std::vector<TracedPoint> PointOutputs(const Mechanism& m) {
  std::vector<TracedPoint> points;
  for (const Output& o : m.outputs)
    if (o.kind == OutputKind::kPoint) points.push_back({o.p, o.name});
  return points;
}

}  // namespace koppel::plot
