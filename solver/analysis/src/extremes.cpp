#include "koppel/analysis/extremes.hpp"

#include "extremes_of_search.hpp"

#include "koppel/core/angles.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

namespace koppel {
namespace {

// Extremes closer in value than this (rad, or times the length scale) are one extreme: the
// refinement leaves roundoff of ~1e-15 in the value, ties of a symmetric mechanism are exact.
constexpr double kSameValue = 1e-12;
// A sample may lie this far (rad, or times the length scale) beyond a refined extreme by roundoff:
// samples inside a branch-point window are the window's interpolant (~1e-10). A missed extreme
// lies beyond by about y'' step^2 / 8, orders of magnitude more.
constexpr double kSampleSlack = 1e-9;

std::string Where(const Mechanism& m, double input) {
  char text[96];
  std::snprintf(text, sizeof text, "%s = %.10g%s", m.drive.input_name.c_str(), m.InputIsAngle() ? RadToDeg(input) : input,
                m.InputIsAngle() ? " deg" : "");
  return text;
}

OutputExtremes Failed(OutputExtremes r, std::string message) {
  r.status = AnalysisStatus::kFailed;
  r.message = std::move(message);
  return r;
}

// Every place an extreme can be: stationary points, folds, the ends of a range that is not periodic.
std::vector<OutputExtreme> Candidates(const StationarySearch& s) {
  std::vector<OutputExtreme> all;
  for (const StationaryPoint& p : s.points) all.push_back({p.input, p.value, ExtremeKind::kStationary});
  for (const StationaryPoint& p : s.folds) all.push_back({p.input, p.value, ExtremeKind::kFold});
  for (int e : s.ends) all.push_back({s.sweep.inputs[e], s.sweep.outputs(e, s.column), ExtremeKind::kRangeEnd});
  return all;
}

// The least and the largest candidate; of equal ones (within `same`) the one at the smaller input.
void Choose(const std::vector<OutputExtreme>& all, double same, OutputExtremes& r) {
  r.minimum = r.maximum = all.front();
  for (const OutputExtreme& c : all) {
    const auto earlier = [&](const OutputExtreme& best) { return c.input < best.input; };
    if (c.value < r.minimum.value - same || (std::abs(c.value - r.minimum.value) <= same && earlier(r.minimum))) r.minimum = c;
    if (c.value > r.maximum.value + same || (std::abs(c.value - r.maximum.value) <= same && earlier(r.maximum))) r.maximum = c;
  }
}

}  // namespace

const char* ToString(ExtremeKind kind) {
  switch (kind) {
    case ExtremeKind::kStationary: return "stationary";
    case ExtremeKind::kFold: return "fold";
    case ExtremeKind::kRangeEnd: return "range end";
    case ExtremeKind::kConstant: return "constant";
  }
  return "stationary";
}

std::string OutputExtremes::Brief() const {
  std::string text = ToString(status);
  if (Usable(status)) text += ": min " + std::to_string(minimum.value) + ", max " + std::to_string(maximum.value);
  return text + (message.empty() ? "" : "; " + message);
}

OutputExtremes ExtremesOf(const Mechanism& m, int output, const StationarySearch& s) {
  OutputExtremes r;
  r.sweep = EventsOf(s.sweep);
  r.message = s.sweep.message;
  if (s.sweep.inputs.empty()) return Failed(r, s.sweep.message.empty() ? "no sample to search" : s.sweep.message);
  const double same = kSameValue * (m.OutputIsAngle(output) ? 1.0 : LengthScale(m));
  r.status = s.sweep.complete() ? AnalysisStatus::kComplete : AnalysisStatus::kPartial;
  if (s.constant) {
    r.minimum = r.maximum = {s.sweep.inputs[0], s.sweep.outputs(0, s.column), ExtremeKind::kConstant};
    return r;
  }
  if (s.period > 0 && std::abs(s.turn_gain) > same)
    return Failed(r, "the output turns with the drive: over whole turns it has no least and largest value");
  if (!s.unresolved.empty())
    return Failed(r, "y' changes sign near " + Where(m, s.unresolved.front()) + " at neither a stationary point nor a fold: " +
                         s.unresolved_message);
  const std::vector<OutputExtreme> all = Candidates(s);
  if (all.empty()) return Failed(r, "the output has no extreme over whole turns of the drive");
  Choose(all, same, r);
  // every sample lies between the extremes, or one was missed (a root of y' between two samples
  // with y' of one sign at both): then say so rather than give a wrong extreme
  const double slack = kSampleSlack * (m.OutputIsAngle(output) ? 1.0 : LengthScale(m));
  const Eigen::Index rows = s.sweep.outputs.rows();
  for (Eigen::Index i = 0; i < rows; ++i) {
    const double v = s.sweep.outputs(i, s.column);
    if (v < r.minimum.value - slack || v > r.maximum.value + slack)
      return Failed(r, "the sample at " + Where(m, s.sweep.inputs[i]) + " lies beyond the extremes found: refine the step");
  }
  return r;
}

OutputExtremes FindOutputExtremes(const Mechanism& m, int output, int component, const SweepOptions& range) {
  return ExtremesOf(m, output, SearchStationaryPoints(m, output, component, range));
}

}  // namespace koppel
