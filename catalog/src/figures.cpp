#include "figures.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/expression.hpp"
#include "koppel/solver/sweep.hpp"

#include <cmath>
#include <optional>

namespace koppel {
namespace {

[[noreturn]] void Fail(const MechanismFile& file, const FigureCheck& f, const std::string& message) {
  throw InputError({Diagnostic{file.path, f.line, 0, "catalog.figures." + f.name, message}});
}

// Vertex of the parabola through three equally spaced samples: refines a sampled extremum to
// O(h^3) without another solve. Returns (abscissa offset in steps, value).
std::pair<double, double> ParabolaVertex(double y0, double y1, double y2) {
  const double curvature = y0 - 2 * y1 + y2;
  if (curvature == 0.0) return {0.0, y1};
  const double t = 0.5 * (y0 - y2) / curvature;
  return {t, y1 - 0.25 * (y0 - y2) * t};
}

struct Extremum {
  double input;
  double value;
};

Extremum FindExtremum(const SweepResult& sweep, int column, bool maximum) {
  const int n = static_cast<int>(sweep.inputs.size());
  int best = 0;
  for (int i = 1; i < n; ++i) {
    const double v = sweep.outputs(i, column), b = sweep.outputs(best, column);
    if (maximum ? v > b : v < b) best = i;
  }
  if (best == 0 || best == n - 1) return {sweep.inputs[best], sweep.outputs(best, column)};
  const auto [t, v] = ParabolaVertex(sweep.outputs(best - 1, column), sweep.outputs(best, column), sweep.outputs(best + 1, column));
  const double h = sweep.inputs[best + 1] - sweep.inputs[best];
  return {sweep.inputs[best] + t * h, v};
}

}  // namespace

int OutputColumn(const Mechanism& m, const std::string& name, int component, int k, int order) {
  int column = 0;
  for (const Output& o : m.outputs) {
    if (o.name == name) return column + component * (order + 1) + k;
    column += o.Components() * (order + 1);
  }
  return -1;
}

bool FigureApplies(const FigureCheck& figure, const std::string& variant) {
  return figure.variant.empty() || figure.variant == variant;
}

CheckOutcome EvaluateFigure(const MechanismFile& file, const CatalogCard& card, const FigureCheck& f,
                            const std::string& variant) {
  CheckOutcome out{variant, f.name, "figure", 0.0, f.tolerance, 0.0, 0.0, false, false, f.note};
  std::string error;
  const std::optional<double> expected = file.parameters.Evaluate(f.expected, &error);
  if (!expected) Fail(file, f, "expected value: " + error);
  if (f.pending) {
    out.pending = true;
    out.detail = "pending: " + (f.note.empty() ? "needs an analysis koppel does not have yet" : f.note);
    return out;
  }
  const Mechanism& m = file.mechanism;
  const bool angle_input = m.InputIsAngle();
  const int output = m.FindOutput(f.output);
  if (output < 0) Fail(file, f, "names no output '" + f.output + "'");
  const bool angle_output = m.outputs[output].IsAngle();
  auto input_internal = [&](double v) { return angle_input ? DegToRad(v) : v; };
  // koppel's value in the figure's unit: degrees when the figure is an angle given in degrees
  auto in_unit = [&](double v) { return f.unit == "deg" ? RadToDeg(v) : v; };

  std::optional<double> value;
  const std::string& q = f.quantity;
  if (q == "min" || q == "max" || q == "argmin" || q == "argmax" || q == "stroke") {
    SweepOptions options;
    options.from = input_internal(card.from);
    options.to = input_internal(card.to);
    options.step = input_internal(card.step);
    options.order = 0;
    const SweepResult sweep = Sweep(m, options);
    if (!sweep.complete()) {
      out.detail = sweep.message;
      return out;
    }
    const int column = OutputColumn(m, f.output, f.component, 0, 0);
    const Extremum lo = FindExtremum(sweep, column, false), hi = FindExtremum(sweep, column, true);
    if (q == "min") value = in_unit(lo.value);
    if (q == "max") value = in_unit(hi.value);
    if (q == "argmin") value = in_unit(lo.input);
    if (q == "argmax") value = in_unit(hi.input);
    if (q == "stroke") value = in_unit(hi.value - lo.value);
  } else if (q == "value" || q == "derivative") {
    const auto at_text = f.args.find("at");
    if (at_text == f.args.end()) Fail(file, f, "quantity '" + q + "' needs 'at'");
    const std::optional<double> at = file.parameters.Evaluate(at_text->second, &error);
    if (!at) Fail(file, f, "at: " + error);
    SweepOptions options;
    options.from = options.to = input_internal(*at);
    options.step = 1.0;
    options.order = q == "value" ? 0 : f.order;
    const SweepResult sweep = Sweep(m, options);
    if (!sweep.complete()) {
      out.detail = sweep.message;
      return out;
    }
    const double v = sweep.outputs(0, OutputColumn(m, f.output, f.component, options.order, options.order));
    value = (q == "value" && angle_output) ? in_unit(v) : v;
  } else {
    out.pending = true;
    out.detail = "pending: quantity '" + q + "' needs an analysis koppel does not have yet";
    return out;
  }
  out.value = *value;
  out.worst = std::abs(*value - *expected);
  out.passed = out.worst <= f.tolerance;
  if (!out.passed && out.detail.empty()) out.detail = "document: " + std::to_string(*expected);
  return out;
}

}  // namespace koppel
