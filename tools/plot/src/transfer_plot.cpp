// Transfer functions of 0th..nth order (seed 000/001 "Bild 2") and the transmission angle
// (seed 000 "Bild 4").
#include "koppel/plot/plots.hpp"

#include "plot_support.hpp"

#include "koppel/analysis/dead_centres.hpp"
#include "koppel/analysis/extremes.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/solver/position.hpp"

#include <algorithm>
#include <cmath>

namespace koppel::plot {
namespace {

// Samples in a plot: a few thousand at most, more only bloat the file.
constexpr int kMaxTransferSamples = 20001;

Axis InputAxis(const Mechanism& m, const SweepOptions& range, const std::string& length_unit) {
  const double a = ShownInput(m, range.from), b = ShownInput(m, range.to);
  Axis axis = NiceAxis(InputLabel(m, length_unit), std::min(a, b), std::max(a, b), m.InputIsAngle());
  return axis;
}

PlotResult Failed(const std::string& message) { return {PlotStatus::kFailed, message, ""}; }

// Dead-centre labels: φ_a / φ_i for the classified pair, else the kind.
std::string DeadCentreLabel(const Mechanism& m, const DeadCentre& d) {
  const std::string name = m.drive.input_name == "phi" ? "φ" : m.drive.input_name;
  switch (d.kind) {
    case DeadCentreKind::kExtended: return name + "_a";
    case DeadCentreKind::kFolded: return name + "_i";
    case DeadCentreKind::kUnclassified: return d.second < 0 ? "max" : "min";
  }
  return "";
}

}  // namespace

const char* ToString(PlotStatus status) {
  switch (status) {
    case PlotStatus::kComplete: return "complete";
    case PlotStatus::kPartial: return "partial";
    case PlotStatus::kFailed: return "failed";
  }
  return "failed";
}

std::string PlotResult::Brief() const { return std::string(ToString(status)) + (message.empty() ? "" : ": " + message); }

bool TransferPlotOptions::IsValid(const Mechanism& m, std::string* why) const {
  if (output < 0 || output >= static_cast<int>(m.outputs.size())) {
    *why = "no such output";
    return false;
  }
  if (order < 0 || order > kMaxOrder) {
    *why = "--order must be 0.." + std::to_string(kMaxOrder);
    return false;
  }
  return RangeIsValid(range, kMaxTransferSamples, why);
}

PlotResult TransferPlot(const Mechanism& m, const TransferPlotOptions& options) {
  std::string why;
  if (!options.IsValid(m, &why)) return Failed(why);
  SweepOptions sweep = options.range;
  sweep.order = options.order;
  const SampledRun run = SampleMechanism(m, sweep);
  if (run.size() == 0) return Failed(run.message);
  const Output& out = m.outputs[options.output];
  Figure figure;
  figure.title = m.name + ": transfer functions of " + out.name + " (0th to " + std::to_string(options.order) +
                 (options.order == 1 ? "st" : options.order == 2 ? "nd" : options.order == 3 ? "rd" : "th") + " order)";
  const bool scalar = out.Components() == 1;
  DeadCentreReport dead;
  if (scalar) {
    SweepOptions search = options.range;
    dead = FindDeadCentres(m, options.output, 0, search);
  }
  for (int k = 0; k <= options.order; ++k) {
    Panel panel;
    panel.x = InputAxis(m, options.range, options.length_unit);
    double low = 0, high = 0;
    for (int c = 0; c < out.Components(); ++c) {
      Curve curve;
      curve.name = scalar ? "" : out.ComponentLabel(c);
      curve.colour = c;
      curve.runs = InputRuns(m, run, run.Column(m, options.output, c, k), options.output, k);
      double a, b;
      YRange(curve.runs, &a, &b);
      low = c == 0 ? a : std::min(low, a);
      high = c == 0 ? b : std::max(high, b);
      panel.curves.push_back(std::move(curve));
    }
    panel.title = DerivativeLabel(m, options.output, scalar ? "" : " (x, y)", k, options.length_unit);
    panel.y = NiceAxis(panel.title, low, high);
    MarkGaps(m, run, panel, k == 0);
    for (const DeadCentre& d : dead.points) {
      panel.rules.push_back({ShownInput(m, d.input), k == 0 ? DeadCentreLabel(m, d) : "", "deadcentre"});
      if (k == 0) panel.markers.push_back({{ShownInput(m, d.input), ShownOutput(m, options.output, 0, d.value)}, "", "deadcentre"});
    }
    figure.panels.push_back(std::move(panel));
  }
  PlotResult result;
  result.svg = RenderFigure(figure);
  if (!run.complete) {
    result.status = PlotStatus::kPartial;
    result.message = run.message;
  } else if (dead.sweep.status != SweepStatus::kNotRun && !dead.sweep.complete()) {
    result.status = PlotStatus::kPartial;
    result.message = "dead centres: " + dead.sweep.message;
  }
  return result;
}

bool MuPlotOptions::IsValid(const Mechanism& m, std::string* why) const {
  if (output < 0 || output >= static_cast<int>(m.outputs.size()) || m.outputs[output].kind != OutputKind::kTransmissionAngle) {
    *why = "the mechanism has no transmission-angle output (add one: {transmission: {coupler: L, joint: J}})";
    return false;
  }
  return RangeIsValid(range, kMaxTransferSamples, why);
}

PlotResult MuPlot(const Mechanism& m, const MuPlotOptions& options) {
  std::string why;
  if (!options.IsValid(m, &why)) return Failed(why);
  SweepOptions sweep = options.range;
  sweep.order = 0;
  const SampledRun run = SampleMechanism(m, sweep);
  if (run.size() == 0) return Failed(run.message);
  const int column = run.Column(m, options.output, 0, 0);
  // μ_min and where: a stationary point, a fold or an end of the range (extremes.hpp)
  const OutputExtremes extremes = FindOutputExtremes(m, options.output, 0, options.range);
  Panel panel;
  panel.x = InputAxis(m, options.range, options.length_unit);
  panel.title = "transmission angle " + DerivativeLabel(m, options.output, "", 0, options.length_unit);
  Curve curve;
  curve.runs = InputRuns(m, run, column, options.output, 0);
  double low, high;
  YRange(curve.runs, &low, &high);
  panel.y = NiceAxis(DerivativeLabel(m, options.output, "", 0, options.length_unit), std::min(0.0, low), std::max(90.0, high), true);
  panel.curves.push_back(std::move(curve));
  MarkGaps(m, run, panel, true);
  if (Usable(extremes.status)) {
    const double mu_min = extremes.minimum.value, at = extremes.minimum.input;
    const std::string input = m.drive.input_name == "phi" ? "φ" : m.drive.input_name;
    char label[96];
    std::snprintf(label, sizeof label, "μ_min = %.2f° at %s = %.2f%s", RadToDeg(mu_min), input.c_str(), ShownInput(m, at),
                  m.InputIsAngle() ? "°" : "");
    panel.markers.push_back({{ShownInput(m, at), RadToDeg(mu_min)}, label, "minimum"});
  }
  Figure figure;
  figure.title = m.name + ": transmission angle " + m.outputs[options.output].name;
  figure.panels.push_back(std::move(panel));
  PlotResult result;
  result.svg = RenderFigure(figure);
  if (!run.complete) {
    result.status = PlotStatus::kPartial;
    result.message = run.message + " (μ_min over the computed part)";
  } else if (!Usable(extremes.status)) {
    result.status = PlotStatus::kPartial;
    result.message = "μ_min not found: " + extremes.message;
  }
  return result;
}

}  // namespace koppel::plot
