// koppel proportional's analysis in the model's units.
#include "koppel/api/proportionality.hpp"

#include "display.hpp"
#include "scalar_output.hpp"

#include "koppel/analysis/proportionality.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/core/structure.hpp"

#include <cmath>

namespace koppel {

using namespace api_detail;

std::string ProportionalityReport::Brief() const {
  return std::string(ToString(status)) + (Usable(status) ? ": delta_s " + std::to_string(delta_s) + ", Q_P " + std::to_string(qp) : "") +
         (message.empty() ? "" : "; " + message);
}

double ReferenceLength(const Model& model) { return CrankLength(model.mechanism()); }

ProportionalityReport FindProportionality(const Model& model, const ProportionalityRequest& request) {
  const Mechanism& m = model.mechanism();
  const int output = ScalarOutput(model, request.output);
  const double length = request.length.value_or(ReferenceLength(model));
  if (!(length > 0)) BadInput(model.path(), "length", "no reference length: give one (the drive link has no crank length)");
  const double from = request.from, to = request.to, step = request.resolution;
  if (!std::isfinite(from) || !std::isfinite(to) || !std::isfinite(step) || step == 0 || from == to)
    BadInput(model.path(), "from/to/resolution", "the range needs finite, different from and to and a resolution that is not 0");
  if (SampleCount(from, to, step) > static_cast<double>(kMaxSweepSamples))
    BadInput(model.path(), "from/to/resolution", "more than kMaxSweepSamples (" + std::to_string(kMaxSweepSamples) + ") samples");
  std::optional<double> at;
  if (request.at) at = InputInternal(m, *request.at);
  ContinuationOptions continuation;
  continuation.at_branch_point = request.at_branch_point;
  const Proportionality p = ProportionalityDeviation(m, output, InputInternal(m, from), InputInternal(m, to), length, at,
                                                     InputInternal(m, step), continuation);
  ProportionalityReport r;
  r.status = p.status;
  r.message = p.message;
  r.output = m.outputs[output].name;
  r.from = from;
  r.to = to;
  r.range = InputShown(m, p.phi_p);
  r.reference = InputShown(m, p.reference);
  r.slope = p.slope;
  r.delta_s = p.delta_s;
  r.chord_deviation = p.chord_deviation;
  r.reference_length = length;
  r.qp = p.qp;
  r.sweep = Shown(m, p.sweep);
  return r;
}

}  // namespace koppel
