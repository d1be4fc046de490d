// The drive torque over the input and polar diagrams of joint reactions.
#include "koppel/plot/forces_plot.hpp"

#include "plot_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace koppel::plot {
namespace {

// As the other plots: a few thousand samples at most.
constexpr int kMaxForceSamples = 20001;

// Stretches of consecutive rows that have forces, as (x, y) by `point`.
template <class Point>
std::vector<std::vector<Eigen::Vector2d>> Runs(const ForcesResult& result, Point point) {
  std::vector<std::vector<Eigen::Vector2d>> runs;
  bool open = false;
  for (const ForcesRow& row : result.rows) {
    if (!row.computed) {
      open = false;
      continue;
    }
    if (!open) runs.emplace_back();
    open = true;
    runs.back().push_back(point(row));
  }
  return runs;
}

double Extent(const std::vector<std::vector<Eigen::Vector2d>>& runs) {
  double r = 0.0;
  for (const auto& run : runs) {
    for (const Eigen::Vector2d& p : run) r = std::max(r, p.cwiseAbs().maxCoeff());
  }
  return r > 0.0 ? r : 1.0;
}

}  // namespace

bool ForcesPlotOptions::IsValid(const Mechanism& m, std::string* why) const {
  for (int j : joints) {
    if (j < 0 || j >= static_cast<int>(m.joints.size())) {
      *why = "no such joint";
      return false;
    }
  }
  return forces.IsValid(why) && RangeIsValid(forces.sweep, kMaxForceSamples, why);
}

PlotResult ForcesPlot(const Mechanism& m, const Loads& loads, const ForcesPlotOptions& options) {
  std::string why;
  if (!options.IsValid(m, &why)) return {PlotStatus::kFailed, why, ""};
  const ForcesResult result = AnalyseForces(m, loads, options.forces);
  if (result.rows.empty() || result.status == AnalysisStatus::kFailed)
    return {PlotStatus::kFailed, result.message, ""};
  const bool angle = m.InputIsAngle();
  Figure figure;
  figure.title = m.name + (result.kinetostatic ? ": kinetostatics" : ": statics");

  Panel drive;
  const double from = ShownInput(m, options.forces.sweep.from), to = ShownInput(m, options.forces.sweep.to);
  drive.x = NiceAxis(InputLabel(m, loads.LengthUnit()), std::min(from, to), std::max(from, to), angle);
  drive.title = angle ? "drive torque [N m]" : "drive force [N]";
  Curve torque;
  torque.runs = Runs(result, [&](const ForcesRow& r) { return Eigen::Vector2d(ShownInput(m, r.input), r.drive); });
  double low = 0.0, high = 0.0;
  YRange(torque.runs, &low, &high);
  drive.y = NiceAxis(drive.title, std::min(low, 0.0), std::max(high, 0.0));
  drive.curves.push_back(std::move(torque));
  // what has no forces: shaded, as the gaps of a sweep
  for (size_t i = 0; i < result.rows.size(); ++i) {
    if (result.rows[i].computed) continue;
    const double x = ShownInput(m, result.rows[i].input);
    drive.rules.push_back({x, result.rows[i].singular ? "singular" : "", "singular"});
  }
  for (const InputInterval& gap : result.sweep.gaps) drive.shaded.push_back({ShownInput(m, gap.from), ShownInput(m, gap.to)});
  figure.panels.push_back(std::move(drive));

  for (int j : options.joints) {
    Panel polar;
    polar.title = "joint " + m.joints[j].name + ": force of " + m.links[m.joints[j].link_a].name + " on " +
                  m.links[m.joints[j].link_b].name + " [N]";
    Curve tip;
    tip.runs = Runs(result, [&](const ForcesRow& r) { return Eigen::Vector2d(r.joints[j].force); });
    const double r = Extent(tip.runs);
    polar.x = NiceAxis("F_x [N]", -r, r);
    polar.y = NiceAxis("F_y [N]", -r, r);
    polar.equal_aspect = true;
    polar.markers.push_back({Eigen::Vector2d::Zero(), "", "point"});
    // where the cycle starts, so the sense of the diagram can be read
    for (const ForcesRow& row : result.rows) {
      if (!row.computed) continue;
      char label[64];
      std::snprintf(label, sizeof label, "%s = %.4g%s", m.drive.input_name.c_str(), ShownInput(m, row.input), angle ? "°" : "");
      polar.markers.push_back({row.joints[j].force, label, "point"});
      break;
    }
    polar.curves.push_back(std::move(tip));
    figure.panels.push_back(std::move(polar));
  }
  PlotResult plot;
  plot.svg = RenderFigure(figure);
  if (!result.complete()) {
    plot.status = PlotStatus::kPartial;
    plot.message = result.message;
  }
  return plot;
}

}  // namespace koppel::plot
