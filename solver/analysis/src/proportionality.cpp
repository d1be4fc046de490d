#include "koppel/analysis/proportionality.hpp"

#include "stationary_search.hpp"

#include "koppel/analysis/stationary.hpp"
#include "koppel/solver/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace koppel {
namespace {

// Columns of the order-3 sweep of the single output: s, s', s'', s'''.
constexpr int kS = 0, kS1 = 1, kS2 = 2;

// Bisections of a sign change of s'': the bracket shrinks to 1e-15 of a step; near a multiple
// root the sign is roundoff sooner, and any input there is as flat as the function can tell.
constexpr int kBisections = 50;
// s'' this small relative to its largest value over the range is roundoff: that sample is flat.
constexpr double kFlatToRoundoff = 1e-12;

// The flat point: the input of least |s''| among the samples and the bisections of the sign
// change of s'' next to the least sample (the root may be multiple, where Newton stalls: seed
// 001's is triple, as 1 - 2 lambda^2 + lambda cos phi vanishes there too for lambda = 1/2); that
// sample where s'' keeps its sign (the flattest end of the range).
double FlatPoint(const Mechanism& m, const SweepResult& sweep, const ContinuationOptions& continuation) {
  const int n = static_cast<int>(sweep.inputs.size());
  int flat = 0;
  for (int i = 1; i < n; ++i) {
    if (std::abs(sweep.outputs(i, kS2)) < std::abs(sweep.outputs(flat, kS2))) flat = i;
  }
  // a sample flat to roundoff (s'' below kFlatToRoundoff of its largest) is the flat point
  const double largest = sweep.outputs.col(kS2).cwiseAbs().maxCoeff();
  if (std::abs(sweep.outputs(flat, kS2)) <= kFlatToRoundoff * largest) return sweep.inputs[flat];
  int other = -1;
  if (flat > 0 && SignChange(sweep.outputs(flat - 1, kS2), sweep.outputs(flat, kS2))) other = flat - 1;
  if (other < 0 && flat + 1 < n && SignChange(sweep.outputs(flat, kS2), sweep.outputs(flat + 1, kS2))) other = flat + 1;
  if (other < 0 || sweep.outputs(flat, kS2) == 0.0) return sweep.inputs[flat];
  PositionSolver solver(m);
  std::vector<double> derivatives(solver.OutputWidth(2));
  double a = sweep.inputs[flat], b = sweep.inputs[other];
  const double step = std::abs(b - a);
  const bool positive_at_a = sweep.outputs(flat, kS2) > 0;
  double flattest = a, least = std::abs(sweep.outputs(flat, kS2));  // of the inputs tried
  for (int k = 0; k < kBisections; ++k) {
    const double middle = 0.5 * (a + b);
    Continuation path(solver, continuation);
    if (!path.Start(sweep.inputs[flat], sweep.poses.row(flat).transpose()).ok() ||
        !path.AdvanceTo(middle, step).ok())
      break;  // the bracket so far
    path.OutputDerivatives(2, derivatives.data());
    if (std::abs(derivatives[kS2]) < least) {
      least = std::abs(derivatives[kS2]);
      flattest = middle;
    }
    if ((derivatives[kS2] > 0) == positive_at_a) {
      a = middle;
    } else {
      b = middle;
    }
  }
  return flattest;
}

// The band about the line s_ref + slope (phi - reference): the least and largest deviation over
// the samples, each local extreme between two samples refined (Newton on s' = slope with s'').
void Band(const Mechanism& m, const SweepResult& sweep, double reference, double s_ref, double slope, const StationaryOptions& base,
          double* lo, double* hi) {
  auto deviation = [&](double input, double s) { return s - s_ref - slope * (input - reference); };
  *lo = *hi = 0;  // the tangent point itself
  const int n = static_cast<int>(sweep.inputs.size());
  for (int i = 0; i < n; ++i) {
    const double d = deviation(sweep.inputs[i], sweep.outputs(i, kS));
    *lo = std::min(*lo, d);
    *hi = std::max(*hi, d);
  }
  StationaryOptions options = base;
  options.target = slope;
  for (int i = 0; i + 1 < n; ++i) {
    const double d0 = sweep.outputs(i, kS1) - slope, d1 = sweep.outputs(i + 1, kS1) - slope;
    if (!SignChange(d0, d1)) continue;
    const int start = std::abs(d0) <= std::abs(d1) && !sweep.singular[i] ? i : i + 1;
    const StationaryPoint p = RefineStationary(m, 0, 0, sweep.inputs[start], sweep.poses.row(start).transpose(), options);
    const double low = std::min(sweep.inputs[i], sweep.inputs[i + 1]), high = std::max(sweep.inputs[i], sweep.inputs[i + 1]);
    if (!p.ok() || p.input < low || p.input > high) continue;  // a tangency of s' (a double root): the samples stand
    const double d = deviation(p.input, p.value);
    *lo = std::min(*lo, d);
    *hi = std::max(*hi, d);
  }
}

}  // namespace

Proportionality ProportionalityDeviation(const Mechanism& m, int output, double from, double to, double reference_length,
                                         std::optional<double> reference, double resolution, const ContinuationOptions& continuation) {
  Proportionality p;
  SweepOptions options;
  options.continuation = continuation;
  options.from = from;
  options.to = to;
  options.step = resolution;
  options.order = 3;
  Mechanism single = m;
  single.outputs = {m.outputs[output]};
  SweepResult sweep = Sweep(single, options);
  SampleRangeEnd(single, options, sweep);  // the band and phi_P cover the range up to `to`
  p.sweep = EventsOf(sweep);
  const int n = static_cast<int>(sweep.inputs.size());
  if (n < 2) {
    p.status = AnalysisStatus::kFailed;
    p.message = sweep.message.empty() ? "fewer than two samples in the range" : sweep.message;
    return p;
  }
  StationaryOptions refine;
  refine.max_step = std::abs(resolution);
  refine.continuation = continuation;
  // the tangent point: given, or the flat point
  p.reference = reference ? *reference : FlatPoint(single, sweep, continuation);
  SweepOptions at;
  at.continuation = continuation;
  at.from = at.to = p.reference;
  at.order = 1;
  const SweepResult r = Sweep(single, at);
  if (!r.complete()) {
    p.status = AnalysisStatus::kFailed;
    p.message = r.message;
    return p;
  }
  const double s_ref = r.outputs(0, 0);
  p.slope = r.outputs(0, 1);
  double lo = 0, hi = 0;
  Band(single, sweep, p.reference, s_ref, p.slope, refine, &lo, &hi);
  p.delta_s = hi - lo;
  const double chord = (sweep.outputs(n - 1, kS) - sweep.outputs(0, kS)) / (sweep.inputs[n - 1] - sweep.inputs[0]);
  for (int i = 0; i < n; ++i)
    p.chord_deviation = std::max(p.chord_deviation, std::abs(sweep.outputs(i, kS) - sweep.outputs(0, kS) - chord * (sweep.inputs[i] - sweep.inputs[0])));
  p.phi_p = std::abs(sweep.inputs[n - 1] - sweep.inputs[0]);
  p.qp = (p.delta_s / reference_length) / p.phi_p;
  p.status = sweep.complete() ? AnalysisStatus::kComplete : AnalysisStatus::kPartial;
  p.message = sweep.message;
  return p;
}

std::string Proportionality::Brief() const {
  return std::string(ToString(status)) + (Usable(status) ? ": Q_P = " + std::to_string(qp) + ", delta_s = " + std::to_string(delta_s) : "") +
         (message.empty() ? "" : "; " + message);
}

}  // namespace koppel
