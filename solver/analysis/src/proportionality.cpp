#include "koppel/analysis/proportionality.hpp"

#include "koppel/solver/sweep.hpp"

#include <algorithm>
#include <cmath>

namespace koppel {

Proportionality ProportionalityDeviation(const Mechanism& m, int output, double from, double to, double reference_length,
                                         std::optional<double> reference, double resolution, const ContinuationOptions& continuation) {
  Proportionality p;
  SweepOptions options;
  options.continuation = continuation;
  options.from = from;
  options.to = to;
  options.step = resolution;
  options.order = 2;
  Mechanism single = m;
  single.outputs = {m.outputs[output]};
  const SweepResult sweep = Sweep(single, options);
  p.sweep = EventsOf(sweep);
  const int n = static_cast<int>(sweep.inputs.size());
  if (n < 2) {
    p.status = AnalysisStatus::kFailed;
    p.message = sweep.message.empty() ? "fewer than two samples in the range" : sweep.message;
    return p;
  }
  // the tangent point: given, or the flat point (least |s''| over the samples; the table step
  // is then the resolution of the answer)
  double s_ref = 0;
  if (reference) {
    SweepOptions at;
    at.continuation = continuation;
    at.from = at.to = *reference;
    at.order = 1;
    const SweepResult r = Sweep(single, at);
    if (!r.complete()) {
      p.status = AnalysisStatus::kFailed;
      p.message = r.message;
      return p;
    }
    p.reference = *reference;
    s_ref = r.outputs(0, 0);
    p.slope = r.outputs(0, 1);
  } else {
    int ref = 0;
    for (int i = 1; i < n; ++i) {
      if (std::abs(sweep.outputs(i, 2)) < std::abs(sweep.outputs(ref, 2))) ref = i;
    }
    p.reference = sweep.inputs[ref];
    s_ref = sweep.outputs(ref, 0);
    p.slope = sweep.outputs(ref, 1);
  }
  double lo = 0, hi = 0;
  for (int i = 0; i < n; ++i) {
    const double d = sweep.outputs(i, 0) - s_ref - p.slope * (sweep.inputs[i] - p.reference);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  p.delta_s = hi - lo;
  const double chord = (sweep.outputs(n - 1, 0) - sweep.outputs(0, 0)) / (sweep.inputs[n - 1] - sweep.inputs[0]);
  for (int i = 0; i < n; ++i)
    p.chord_deviation = std::max(p.chord_deviation, std::abs(sweep.outputs(i, 0) - sweep.outputs(0, 0) - chord * (sweep.inputs[i] - sweep.inputs[0])));
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
