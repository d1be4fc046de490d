#include "figures.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/structure.hpp"
#include "koppel/core/expression.hpp"
#include "koppel/synthesis/cognates.hpp"
#include "koppel/analysis/coupler_curve.hpp"
#include "koppel/analysis/dead_centres.hpp"
#include "koppel/analysis/proportionality.hpp"
#include "koppel/analysis/stationary.hpp"
#include "koppel/solver/sweep.hpp"

#include <cmath>
#include <optional>

namespace koppel {
namespace {

[[noreturn]] void Fail(const MechanismFile& file, const FigureCheck& f, const std::string& message) {
  throw InputError({Diagnostic{file.path, f.line, 0, "catalog.figures." + f.name, message}});
}

struct Extremum {
  double input;
  double value;
};

// The sampled extreme of a sweep column, refined where it lies inside the range by Newton on
// the first-order transfer function (stationary.hpp), so figures are exact, not sampled.
std::optional<Extremum> FindExtremum(const Mechanism& m, const SweepResult& sweep, int output, int component, int column,
                                     bool maximum, std::string* detail) {
  const int n = static_cast<int>(sweep.inputs.size());
  int best = 0;
  for (int i = 1; i < n; ++i) {
    const double v = sweep.outputs(i, column), b = sweep.outputs(best, column);
    if (maximum ? v > b : v < b) best = i;
  }
  const Eigen::VectorXd q = sweep.poses.row(best).transpose();
  const StationaryPoint p = RefineStationary(m, output, component, sweep.inputs[best], q);
  const bool interior = best > 0 && best < n - 1;
  if (!p.ok()) {
    if (interior) {
      *detail = p.message;
      return std::nullopt;
    }
    return Extremum{sweep.inputs[best], sweep.outputs(best, column)};  // an end of the range
  }
  // a stationary point outside the range (or the wrong kind) leaves the end sample as the extreme
  const double lo = std::min(sweep.inputs.front(), sweep.inputs.back()), hi = std::max(sweep.inputs.front(), sweep.inputs.back());
  const bool inside = p.input >= lo - 1e-12 && p.input <= hi + 1e-12;
  const bool better = maximum ? p.value >= sweep.outputs(best, column) : p.value <= sweep.outputs(best, column);
  if (inside && better) return Extremum{p.input, p.value};
  return Extremum{sweep.inputs[best], sweep.outputs(best, column)};
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
  const bool angle_output = m.OutputIsAngle(output);
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
    const std::optional<Extremum> lo = FindExtremum(m, sweep, output, f.component, column, false, &out.detail);
    const std::optional<Extremum> hi = FindExtremum(m, sweep, output, f.component, column, true, &out.detail);
    if (!lo || !hi) return out;
    // inputs in degrees for an R drive (the unit of the figure then says deg)
    if (q == "min") value = in_unit(lo->value);
    if (q == "max") value = in_unit(hi->value);
    if (q == "argmin") value = in_unit(lo->input);
    if (q == "argmax") value = in_unit(hi->input);
    if (q == "stroke") value = in_unit(hi->value - lo->value);
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
  } else if (q == "deadcentre_span" || q == "deadcentre_phi_a" || q == "deadcentre_phi_i" || q == "phase_ratio") {
    // dead centres of the output (dead_centres.hpp): the crank angle from the folded to the
    // extended dead centre, counter-clockwise, or either dead centre's input
    SweepOptions options;
    options.from = input_internal(card.from);
    options.to = input_internal(card.to);
    options.step = input_internal(card.step);
    const DeadCentreReport r = FindDeadCentres(m, output, f.component, options);
    if (!r.has_stroke || !r.classified) {
      out.detail = r.sweep.message.empty() ? "no extended and folded dead centre found" : r.sweep.message;
      return out;
    }
    const double turn = 2 * kPi;
    const double span = std::fmod(std::fmod(r.phi_a - r.phi_i, turn) + turn, turn);
    if (q == "phase_ratio") {
      if (!angle_input) Fail(file, f, "a phase ratio needs a rotating drive");
      value = r.phase_ratio;  // phi_H / (360 deg - phi_H), phi_H from phi_a to phi_i counter-clockwise
    } else {
      value = in_unit(q == "deadcentre_span" ? span : q == "deadcentre_phi_a" ? std::fmod(r.phi_a + turn, turn) : std::fmod(r.phi_i + turn, turn));
    }
  } else if (q == "proportionality_ds" || q == "proportionality_qp") {
    // seed 001's reading example: band about the flat-point tangent (proportionality.hpp)
    const auto from = f.args.find("from"), to = f.args.find("to");
    if (from == f.args.end() || to == f.args.end()) Fail(file, f, "quantity '" + q + "' needs 'from' and 'to'");
    const std::optional<double> a = file.parameters.Evaluate(from->second, &error), b = file.parameters.Evaluate(to->second, &error);
    if (!a || !b) Fail(file, f, error);
    const Proportionality p = ProportionalityDeviation(m, output, input_internal(*a), input_internal(*b), CrankLength(m), std::nullopt,
                                                       input_internal(card.step) / 20);
    if (!Usable(p.status)) {
      out.detail = p.message;
      return out;
    }
    value = q == "proportionality_ds" ? p.delta_s : p.qp;
  } else if (q == "straightline_phi_g" || q == "straightline_phi_a" || q == "straightline_length") {
    // seed 003's reading example: longest stretch through K_I with Q_G <= qg (coupler_curve.hpp)
    const auto qg = f.args.find("qg");
    if (qg == f.args.end()) Fail(file, f, "quantity '" + q + "' needs 'qg'");
    const std::optional<double> limit = file.parameters.Evaluate(qg->second, &error);
    if (!limit) Fail(file, f, error);
    std::optional<double> at;
    if (const auto a = f.args.find("at"); a != f.args.end()) at = input_internal(file.parameters.Evaluate(a->second, &error).value_or(0));
    const StraightStretch s = LongestStraightStretch(m, m.outputs[output].p, *limit, at, kPi, DegToRad(0.02));
    if (!s.ok()) {
      out.detail = s.message;
      return out;
    }
    value = q == "straightline_phi_g" ? in_unit(s.phi_g) : q == "straightline_phi_a" ? in_unit(s.phi_a) : s.length;
  } else if (q == "cognate_frame") {
    const Cognates c = RobertsCognates(m, m.outputs[output].p);
    if (!c.ok) {
      out.detail = c.message;
      return out;
    }
    value = c.frame_first;
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
