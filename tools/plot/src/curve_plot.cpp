// The coupler curve to scale with the straight-line stretch of seed 003 ("Bild 1a", "Bild 2":
// K_A, K_I, K_E, the tangent g, the band Δy over the length L).
#include "koppel/plot/plots.hpp"

#include "plot_support.hpp"

#include "koppel/analysis/coupler_curve.hpp"
#include "koppel/core/angles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace koppel::plot {
namespace {

// Samples of the stretch K_A..K_E drawn in the band panel: fine enough that the band edges
// of the drawn curve match the analysis' Δy to well below a pixel.
constexpr int kStretchSamples = 800;

std::vector<std::vector<Eigen::Vector2d>> PointRuns(const SampledRun& run) {
  std::vector<std::vector<Eigen::Vector2d>> runs;
  for (const Stretch& s : run.stretches) {
    runs.emplace_back();
    for (int i = s.begin; i < s.end; ++i) runs.back().emplace_back(run.outputs(i, 0), run.outputs(i, 1));
  }
  return runs;
}

void Bounds(const std::vector<std::vector<Eigen::Vector2d>>& runs, Eigen::Vector2d* low, Eigen::Vector2d* high) {
  for (const auto& r : runs)
    for (const auto& p : r) {
      *low = low->cwiseMin(p);
      *high = high->cwiseMax(p);
    }
}

std::string PointName(const Mechanism& m, const PointRef& p) { return m.links[p.link].points[p.point].name; }

// The stretch K_A..K_E in coordinates along (u) and across (v) the tangent g at K_I, with its
// extent (which includes K_I, the origin).
struct StretchAlongTangent {
  Curve across;
  double u_low = 0, u_high = 0, v_low = 0, v_high = 0;
};

StretchAlongTangent StretchInTangentFrame(const Curve& stretch, const StraightStretch& s) {
  const Eigen::Vector2d t = s.tangent, n(-t.y(), t.x()), k_i = s.reference_point;
  StretchAlongTangent a;
  a.across.name = "";
  a.across.colour = 1;
  for (const auto& r : stretch.runs) {
    a.across.runs.emplace_back();
    for (const auto& p : r) {
      const double u = t.dot(p - k_i), v = n.dot(p - k_i);
      a.across.runs.back().emplace_back(u, v);
      a.u_low = std::min(a.u_low, u), a.u_high = std::max(a.u_high, u), a.v_low = std::min(a.v_low, v), a.v_high = std::max(a.v_high, v);
    }
  }
  return a;
}

// The markers K_A, K_E (the highlighted stretch's ends) and K_I with their input angles.
void MarkStretchPoints(const StraightStretch& s, const Curve& stretch, Panel* curve_panel) {
  const Eigen::Vector2d k_a = stretch.runs.front().front(), k_e = stretch.runs.back().back();
  char label[64];
  std::snprintf(label, sizeof label, "K_A (φ_A = %.2f°)", RadToDeg(s.phi_a));
  curve_panel->markers.push_back({k_a, label, "point"});
  std::snprintf(label, sizeof label, "K_E (φ_E = %.2f°)", RadToDeg(s.phi_e));
  curve_panel->markers.push_back({k_e, label, "point"});
  std::snprintf(label, sizeof label, "K_I (φ_I = %.2f°)", RadToDeg(s.reference));
  curve_panel->markers.push_back({s.reference_point, label, "point"});
}

// The band panel: the enlargement of seed 003 "Bild 2", the stretch along g inside its band Δy.
Panel StraightBandPanel(const StraightStretch& s, StretchAlongTangent a) {
  Panel band_panel;
  char title[200];
  std::snprintf(title, sizeof title, "stretch K_A..K_E along g: L = %.4g, Δy = %.4g, Q_G = Δy/L = %.4g, φ_G = %.2f°", s.length,
                s.band, s.qg, RadToDeg(s.phi_g));
  band_panel.title = title;
  band_panel.x = NiceAxis("along g [length]", a.u_low, a.u_high);
  band_panel.y = NiceAxis("across g [length]", std::min(a.v_low, 0.0), std::max(a.v_high, 0.0));
  band_panel.bands.push_back({{{a.u_low, a.v_low}, {a.u_high, a.v_low}, {a.u_high, a.v_high}, {a.u_low, a.v_high}}, "Δy"});
  band_panel.curves.push_back(std::move(a.across));
  band_panel.markers.push_back({{0, 0}, "K_I", "point"});
  return band_panel;
}

// Draws the straight stretch s on the curve panel (the stretch K_A..K_E sampled finely, the
// tangent g at K_I, the markers), widening the curve's bounds; returns the band panel.
Panel DrawStraightStretch(const Mechanism& traced, const StraightStretch& s, Panel* curve_panel, Eigen::Vector2d* low,
                          Eigen::Vector2d* high) {
  SweepOptions stretch_range;
  stretch_range.from = s.phi_a;
  stretch_range.to = s.phi_e;
  stretch_range.step = (s.phi_e - s.phi_a) / kStretchSamples;
  stretch_range.order = 0;
  const SampledRun stretch = SampleMechanism(traced, stretch_range);
  Curve highlighted;
  highlighted.name = "K_A..K_E";
  highlighted.colour = 1;
  highlighted.runs = PointRuns(stretch);
  Bounds(highlighted.runs, low, high);
  StretchAlongTangent along = StretchInTangentFrame(highlighted, s);
  const Eigen::Vector2d t = s.tangent, k_i = s.reference_point;
  const double margin = 0.1 * (along.u_high - along.u_low);
  Curve tangent;
  tangent.name = "tangent g at K_I";
  tangent.colour = 3;
  tangent.dashed = true;
  tangent.runs = {{k_i + (along.u_low - margin) * t, k_i + (along.u_high + margin) * t}};
  Bounds(tangent.runs, low, high);
  MarkStretchPoints(s, highlighted, curve_panel);
  curve_panel->curves.push_back(std::move(highlighted));
  curve_panel->curves.push_back(tangent);
  return StraightBandPanel(s, std::move(along));
}

}  // namespace

bool CurvePlotOptions::IsValid(const Mechanism& m, std::string* why) const {
  if (point.link < 0 || point.link >= static_cast<int>(m.links.size()) || point.point < 0 ||
      point.point >= static_cast<int>(m.links[point.link].points.size())) {
    *why = "no such point";
    return false;
  }
  if (!RangeIsValid(range, 20001, why)) return false;
  if (straight && (!(qg > 0) || !(resolution > 0) || !m.InputIsAngle())) {
    *why = "the straight-line analysis needs a rotating drive, Q_G > 0 and a positive resolution";
    return false;
  }
  return true;
}

PlotResult CurvePlot(const Mechanism& m, const CurvePlotOptions& options) {
  std::string why;
  if (!options.IsValid(m, &why)) return {PlotStatus::kFailed, why, ""};
  const Mechanism traced = WithPointOutput(m, options.point);
  SweepOptions sweep = options.range;
  sweep.order = 0;
  const SampledRun run = SampleMechanism(traced, sweep);
  if (run.size() == 0) return {PlotStatus::kFailed, run.message, ""};
  const std::string name = PointName(m, options.point);
  Figure figure;
  figure.title = m.name + ": coupler curve of " + name;
  Panel curve_panel;
  curve_panel.equal_aspect = true;
  curve_panel.title = "coupler curve k_" + name;
  Curve curve;
  curve.name = "k_" + name;
  curve.runs = PointRuns(run);
  Eigen::Vector2d low = curve.runs.front().front(), high = low;
  Bounds(curve.runs, &low, &high);
  curve_panel.curves.push_back(std::move(curve));
  PlotResult result;
  if (!run.complete) {
    result.status = PlotStatus::kPartial;
    result.message = run.message;
    // the last computed position: where the curve ends because the solver could not go on
    const Eigen::Vector2d end(run.outputs(run.size() - 1, 0), run.outputs(run.size() - 1, 1));
    curve_panel.markers.push_back({end, "stop", "singular"});
  }
  std::optional<Panel> band_panel;
  if (options.straight) {
    const StraightStretch s = LongestStraightStretch(m, options.point, options.qg, options.reference, kPi, options.resolution);
    if (!s.ok()) {
      result.status = PlotStatus::kPartial;
      result.message = (result.message.empty() ? "" : result.message + "; ") + "straight line: " + s.message;
    } else {
      band_panel = DrawStraightStretch(traced, s, &curve_panel, &low, &high);
    }
  }
  const Eigen::Vector2d pad = 0.04 * (high - low).cwiseMax(Eigen::Vector2d::Constant(1e-9));
  curve_panel.x = NiceAxis("x [length]", low.x() - pad.x(), high.x() + pad.x());
  curve_panel.y = NiceAxis("y [length]", low.y() - pad.y(), high.y() + pad.y());
  figure.panels.push_back(std::move(curve_panel));
  if (band_panel) figure.panels.push_back(std::move(*band_panel));
  result.svg = RenderFigure(figure);
  return result;
}

}  // namespace koppel::plot
