// The tolerance band of an output over the input (koppel plot --tolerance): the nominal output;
// its deviation: the linear worst case of tolerances and clearances as a filled band and the
// Monte Carlo extremes; and each tolerance's share of the variance.
#include "koppel/plot/plots.hpp"

#include <algorithm>

namespace koppel::plot {
namespace {

// Stretches of consecutive reached rows: a row that was not reached breaks every curve.
std::vector<std::vector<Eigen::Vector2d>> Runs(const ToleranceBand& b, const std::vector<double>& y) {
  std::vector<std::vector<Eigen::Vector2d>> runs(1);
  for (size_t i = 0; i < b.inputs.size(); ++i) {
    if (!b.ok[i]) {
      if (!runs.back().empty()) runs.emplace_back();
      continue;
    }
    runs.back().push_back({b.inputs[i], y[i]});
  }
  if (runs.back().empty()) runs.pop_back();
  return runs;
}

void Widen(const std::vector<std::vector<Eigen::Vector2d>>& runs, double* low, double* high) {
  for (const auto& run : runs) {
    for (const Eigen::Vector2d& p : run) {
      *low = std::min(*low, p.y());
      *high = std::max(*high, p.y());
    }
  }
}

// Marks the inputs that were not reached on a panel.
void ShadeUnreachedInputs(const ToleranceBand& b, Panel* panel) {
  // a run of unreached rows is shaded from the last reached input before it to the first after
  // it (nothing is known in between), as the sweeping plots shade their gaps (MarkGaps)
  const size_t n = b.inputs.size();
  for (size_t i = 0; i < n;) {
    if (b.ok[i]) {
      ++i;
      continue;
    }
    size_t j = i;
    while (j < n && !b.ok[j]) ++j;  // rows i .. j-1 are unreached
    const double from = b.inputs[i > 0 ? i - 1 : i], to = b.inputs[j < n ? j : n - 1];
    panel->shaded.emplace_back(std::min(from, to), std::max(from, to));
    i = j;
  }
}

// The output itself over the input.
Panel NominalOutputPanel(const ToleranceBand& b, double x_low, double x_high) {
  Panel output;
  output.x = NiceAxis(b.input_label, x_low, x_high, b.input_degrees);
  Curve nominal{"", Runs(b, b.nominal), 0, false, ""};
  double low = 1e300, high = -1e300;
  Widen(nominal.runs, &low, &high);
  output.curves.push_back(std::move(nominal));
  output.title = b.output + " [" + b.output_unit + "]";
  output.y = NiceAxis(output.title, low, high);
  ShadeUnreachedInputs(b, &output);
  return output;
}

// The deviation from nominal: the linear worst case as a filled band (one polygon per stretch:
// up along the upper edge, back along the lower) with its edges, and the Monte Carlo extremes.
Panel DeviationBandPanel(const ToleranceBand& b, double x_low, double x_high) {
  const size_t n = b.inputs.size();
  Panel band;
  band.x = NiceAxis(b.input_label, x_low, x_high, b.input_degrees);
  std::vector<double> upper(n), lower(n);
  for (size_t i = 0; i < n; ++i) {
    upper[i] = b.worst_case[i];
    lower[i] = -b.worst_case[i];
  }
  const auto upper_runs = Runs(b, upper), lower_runs = Runs(b, lower);
  for (size_t r = 0; r < upper_runs.size(); ++r) {
    Band polygon;
    polygon.corners = upper_runs[r];
    polygon.corners.insert(polygon.corners.end(), lower_runs[r].rbegin(), lower_runs[r].rend());
    polygon.label = r == 0 ? "linear worst case" : "";
    band.bands.push_back(std::move(polygon));
  }
  double low = 0, high = 0;
  Widen(upper_runs, &low, &high);
  Widen(lower_runs, &low, &high);
  Curve worst_high{"linear worst case", upper_runs, 0, false, ""}, worst_low{"", lower_runs, 0, false, ""};
  band.curves.push_back(std::move(worst_high));
  band.curves.push_back(std::move(worst_low));
  if (!b.mc_min.empty()) {
    std::vector<double> mc_low(n), mc_high(n);
    for (size_t i = 0; i < n; ++i) {
      mc_low[i] = b.mc_min[i] - b.nominal[i];
      mc_high[i] = b.mc_max[i] - b.nominal[i];
    }
    Curve mc_min{"Monte Carlo min, max", Runs(b, mc_low), 1, true, ""}, mc_max{"", Runs(b, mc_high), 1, true, ""};
    Widen(mc_min.runs, &low, &high);
    Widen(mc_max.runs, &low, &high);
    band.curves.push_back(std::move(mc_min));
    band.curves.push_back(std::move(mc_max));
  }
  band.title = b.output + " − nominal [" + b.output_unit + "]";
  band.y = NiceAxis(band.title, low, high);
  ShadeUnreachedInputs(b, &band);
  return band;
}

// Each tolerance's share of the variance over the input.
Panel VarianceSharePanel(const ToleranceBand& b, double x_low, double x_high) {
  Panel shares;
  shares.x = NiceAxis(b.input_label, x_low, x_high, b.input_degrees);
  shares.y = NiceAxis("share of the variance", 0, 1);
  shares.title = "share of the variance";
  for (size_t j = 0; j < b.names.size(); ++j) shares.curves.push_back({b.names[j], Runs(b, b.shares[j]), static_cast<int>(j), false, ""});
  ShadeUnreachedInputs(b, &shares);
  return shares;
}

}  // namespace

PlotResult TolerancePlot(const ToleranceBand& b) {
  const size_t n = b.inputs.size();
  if (n == 0 || std::none_of(b.ok.begin(), b.ok.end(), [](bool ok) { return ok; }))
    return {PlotStatus::kFailed, "no input was reached: nothing to draw", ""};
  Figure figure;
  figure.title = b.mechanism + ": tolerance band of " + b.output;
  const double x_low = *std::min_element(b.inputs.begin(), b.inputs.end()), x_high = *std::max_element(b.inputs.begin(), b.inputs.end());
  // the output itself, then its deviation from nominal: the band is a few percent of the output
  figure.panels.push_back(NominalOutputPanel(b, x_low, x_high));
  figure.panels.push_back(DeviationBandPanel(b, x_low, x_high));
  figure.panels.push_back(VarianceSharePanel(b, x_low, x_high));
  PlotResult result;
  result.svg = RenderFigure(figure);
  if (std::any_of(b.ok.begin(), b.ok.end(), [](bool ok) { return !ok; })) {
    result.status = PlotStatus::kPartial;
    result.message = "some inputs were not reached: the curves break there";
  }
  return result;
}

}  // namespace koppel::plot
