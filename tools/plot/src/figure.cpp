#include "koppel/plot/figure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace koppel::plot {
namespace {

constexpr std::array<const char*, 8> kPalette = {"#1f5fa8", "#c0392b", "#2e8b57", "#7d3c98",
                                                 "#d68910", "#6e4b3a", "#c2185b", "#138d90"};
// Layout in px: room for tick labels on the left, the axis label below, a title line above.
constexpr double kLeft = 78, kRight = 24, kTop = 34, kPanelTitle = 22, kBottom = 44;
constexpr double kMaxEqualAspectHeight = 620, kLegendWidth = 150;

const char* kFigureStyle =
    "<style>"
    "text{font-family:DejaVu Sans,Arial,sans-serif;font-size:12px;fill:#222}"
    ".title{font-size:15px;font-weight:bold}.panel-title{font-size:13px}"
    ".plot-area{fill:#fff;stroke:#444;stroke-width:1}"
    ".grid{stroke:#e3e3e3;stroke-width:1}.tick{stroke:#444;stroke-width:1}"
    ".curve{fill:none;stroke-width:1.8;stroke-linejoin:round}"
    ".rule{stroke:#888;stroke-width:1;stroke-dasharray:4 3}"
    ".rule.singular{stroke:#c0392b}.gap{fill:#f3d6d3;fill-opacity:.6}"
    ".band{fill:#f4d03f;fill-opacity:.35;stroke:#b7950b;stroke-width:.8}"
    ".marker circle{fill:#fff;stroke:#111;stroke-width:1.4}"
    ".marker.singular circle{fill:#c0392b}.marker.minimum circle{fill:#111}"
        "</style>";

std::string StrokeOf(const Curve& curve) { return curve.stroke.empty() ? kPalette[curve.colour % kPalette.size()] : curve.stroke; }

// Decimals that show every tick exactly (0.25 -> 2, 30 -> 0).
int DecimalsFor(const Axis& axis) {
  int decimals = 0;
  for (double t : axis.ticks) {
    int d = 0;
    while (d < 6 && std::abs(t * std::pow(10.0, d) - std::round(t * std::pow(10.0, d))) > 1e-6 * std::pow(10.0, d)) ++d;
    decimals = std::max(decimals, d);
  }
  return decimals;
}

struct Mapping {
  double x0, y0, w, h;  // plot area in px
  const Axis *x, *y;
  Eigen::Vector2d operator()(const Eigen::Vector2d& p) const {
    return {x0 + (p.x() - x->min) / (x->max - x->min) * w, y0 + h - (p.y() - y->min) / (y->max - y->min) * h};
  }
};

void DrawAxes(Svg& svg, const Mapping& map) {
  svg.Rect(map.x0, map.y0, map.w, map.h, {{"class", "plot-area"}});
  const int dx = DecimalsFor(*map.x), dy = DecimalsFor(*map.y);
  svg.OpenGroup({{"class", "axis x"}, {"data-min", Num(map.x->min, 9)}, {"data-max", Num(map.x->max, 9)}});
  for (double t : map.x->ticks) {
    const double px = map({t, map.y->min}).x();
    svg.Line({px, map.y0}, {px, map.y0 + map.h}, {{"class", "grid"}});
    svg.Line({px, map.y0 + map.h}, {px, map.y0 + map.h + 5}, {{"class", "tick"}, {"data-value", Num(t, 9)}});
    svg.Text({px, map.y0 + map.h + 18}, Num(t, dx), {{"class", "tick-label"}, {"text-anchor", "middle"}});
  }
  svg.Text({map.x0 + map.w / 2, map.y0 + map.h + 36}, map.x->label, {{"class", "axis-label"}, {"text-anchor", "middle"}});
  svg.CloseGroup();
  svg.OpenGroup({{"class", "axis y"}, {"data-min", Num(map.y->min, 9)}, {"data-max", Num(map.y->max, 9)}});
  for (double t : map.y->ticks) {
    const double py = map({map.x->min, t}).y();
    svg.Line({map.x0, py}, {map.x0 + map.w, py}, {{"class", "grid"}});
    svg.Line({map.x0 - 5, py}, {map.x0, py}, {{"class", "tick"}, {"data-value", Num(t, 9)}});
    svg.Text({map.x0 - 8, py + 4}, Num(t, dy), {{"class", "tick-label"}, {"text-anchor", "end"}});
  }
  const Eigen::Vector2d label_at(map.x0 - 58, map.y0 + map.h / 2);
  svg.Text(label_at, map.y->label,
           {{"class", "axis-label"}, {"text-anchor", "middle"},
            {"transform", "rotate(-90 " + Num(label_at.x()) + " " + Num(label_at.y()) + ")"}});
  svg.CloseGroup();
}

// The legend to the right of the plot area, clear of the curves and their labels.
void DrawLegend(Svg& svg, const Mapping& map, const std::vector<Curve>& curves) {
  std::vector<const Curve*> named;
  for (const Curve& c : curves)
    if (!c.name.empty()) named.push_back(&c);
  if (named.empty()) return;
  const double x = map.x0 + map.w + 12, y = map.y0;
  svg.OpenGroup({{"class", "legend"}});
  for (size_t i = 0; i < named.size(); ++i) {
    const double row = y + 12 + 17.0 * static_cast<double>(i);
    Attrs style = {{"class", "legend-line"}, {"stroke", StrokeOf(*named[i])}, {"stroke-width", "2"}};
    if (named[i]->dashed) style.push_back({"stroke-dasharray", "6 3"});
    svg.Line({x, row - 4}, {x + 20, row - 4}, style);
    svg.Text({x + 25, row}, named[i]->name, {{"class", "legend-label"}});
  }
  svg.CloseGroup();
}

bool HasLegend(const Panel& panel) {
  return std::any_of(panel.curves.begin(), panel.curves.end(), [](const Curve& c) { return !c.name.empty(); });
}

void DrawPanel(Svg& svg, const Panel& panel, const Mapping& map, int index) {
  svg.OpenGroup({{"class", "panel"}, {"data-title", panel.title}});
  if (!panel.title.empty()) svg.Text({map.x0, map.y0 - 7}, panel.title, {{"class", "panel-title"}});
  DrawAxes(svg, map);
  const std::string clip = "clip" + std::to_string(index);
  svg.Defs("<clipPath id=\"" + clip + "\"><rect x=\"" + Num(map.x0) + "\" y=\"" + Num(map.y0) + "\" width=\"" + Num(map.w) +
           "\" height=\"" + Num(map.h) + "\"/></clipPath>");
  svg.OpenGroup({{"clip-path", "url(#" + clip + ")"}});
  for (const auto& [from, to] : panel.shaded) {
    const double a = map({std::max(from, map.x->min), 0}).x(), b = map({std::min(to, map.x->max), 0}).x();
    if (b > a) svg.Rect(a, map.y0, b - a, map.h, {{"class", "gap"}});
  }
  for (const Band& band : panel.bands) {
    std::vector<Eigen::Vector2d> corners;
    for (const auto& c : band.corners) corners.push_back(map(c));
    svg.Polygon(corners, {{"class", "band"}, {"data-label", band.label}});
  }
  for (const Rule& rule : panel.rules) {
    const double px = map({rule.x, 0}).x();
    svg.Line({px, map.y0}, {px, map.y0 + map.h}, {{"class", "rule " + rule.kind}, {"data-x", Num(rule.x, 9)}});
  }
  for (const Curve& curve : panel.curves) {
    std::vector<std::vector<Eigen::Vector2d>> runs;
    for (const auto& run : curve.runs) {
      if (run.empty()) continue;
      runs.emplace_back();
      for (const auto& p : run) runs.back().push_back(map(p));
    }
    Attrs style = {{"class", "curve"}, {"data-name", curve.name}, {"stroke", StrokeOf(curve)}};
    if (curve.dashed) style.push_back({"stroke-dasharray", "6 3"});
    svg.Path(runs, style);
  }
  svg.CloseGroup();
  for (const Rule& rule : panel.rules)
    if (!rule.label.empty())
      svg.Text({map({rule.x, 0}).x() + 3, map.y0 + 13}, rule.label, {{"class", "rule-label"}});
  for (const Marker& marker : panel.markers) {
    const Eigen::Vector2d p = map(marker.at);
    svg.OpenGroup({{"class", "marker " + marker.kind}, {"data-x", Num(marker.at.x(), 9)}, {"data-y", Num(marker.at.y(), 9)}});
    svg.Circle(p, 3.5, {});
    // above right of the marker, or below it where the panel's title line would be in the way
    const Eigen::Vector2d offset = p.y() - map.y0 < 16 ? Eigen::Vector2d(6, 15) : Eigen::Vector2d(6, -6);
    if (!marker.label.empty()) svg.Text(p + offset, marker.label, {{"class", "marker-label"}});
    svg.CloseGroup();
  }
  DrawLegend(svg, map, panel.curves);
  svg.CloseGroup();
}

}  // namespace

Axis NiceAxis(const std::string& label, double low, double high, bool degrees, int target) {
  Axis axis;
  axis.label = label;
  if (!(high > low)) {
    const double pad = std::max(1.0, std::abs(low)) * 0.05;
    low -= pad;
    high += pad;
  }
  const double raw = (high - low) / std::max(1, target);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * magnitude;
  static constexpr double kSteps[] = {1, 2, 2.5, 5, 10};
  for (double s : kSteps)
    if (s * magnitude >= raw) {
      step = s * magnitude;
      break;
    }
  if (degrees && raw >= 10) {
    static constexpr double kDegreeSteps[] = {15, 30, 45, 90, 180, 360};
    for (double s : kDegreeSteps)
      if (s >= raw) {
        step = s;
        break;
      }
  }
  // Ticks on multiples of the step; a tiny relative slack keeps 359.9999999 from adding a tick.
  const double slack = 1e-9 * (high - low);
  axis.min = std::floor((low + slack) / step) * step;
  axis.max = std::ceil((high - slack) / step) * step;
  for (double t = axis.min; t <= axis.max + slack; t += step) axis.ticks.push_back(std::abs(t) < slack ? 0.0 : t);
  return axis;
}

std::string RampColour(double t) {
  // viridis (matplotlib, van der Walt and Smith 2015) at t = 0, 0.1, ..., 0.8
  static constexpr std::array<std::array<int, 3>, 9> kViridis = {{{0x44, 0x01, 0x54}, {0x48, 0x24, 0x75}, {0x41, 0x44, 0x87},
                                                                  {0x35, 0x5f, 0x8d}, {0x2a, 0x78, 0x8e}, {0x21, 0x91, 0x8c},
                                                                  {0x22, 0xa8, 0x84}, {0x44, 0xbf, 0x70}, {0x7a, 0xd1, 0x51}}};
  const double at = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * (kViridis.size() - 1);
  const size_t i = std::min(static_cast<size_t>(at), kViridis.size() - 2);
  const double f = at - static_cast<double>(i);
  char hex[8];
  int rgb[3];
  for (int c = 0; c < 3; ++c) rgb[c] = static_cast<int>(std::lround((1 - f) * kViridis[i][c] + f * kViridis[i + 1][c]));
  std::snprintf(hex, sizeof hex, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
  return hex;
}

std::string RenderFigure(const Figure& figure) {
  // First the height of each panel, then draw.
  std::vector<Mapping> maps;
  double y = kTop;
  const bool legend = std::any_of(figure.panels.begin(), figure.panels.end(), HasLegend);
  const double plot_width = figure.width - kLeft - kRight - (legend ? kLegendWidth : 0);
  for (const Panel& panel : figure.panels) {
    Mapping map{kLeft, y + kPanelTitle, plot_width, figure.panel_height, &panel.x, &panel.y};
    if (panel.equal_aspect) {
      const double dx = panel.x.max - panel.x.min, dy = panel.y.max - panel.y.min;
      const double scale = std::min(plot_width / dx, kMaxEqualAspectHeight / dy);
      map.w = dx * scale;
      map.h = dy * scale;
    }
    maps.push_back(map);
    y = map.y0 + map.h + kBottom;
  }
  Svg svg(figure.width, y + 6);
  svg.Defs(kFigureStyle);
  svg.Rect(0, 0, figure.width, y + 6, {{"fill", "#fff"}});
  if (!figure.title.empty()) svg.Text({kLeft, 22}, figure.title, {{"class", "title"}});
  for (size_t i = 0; i < figure.panels.size(); ++i) DrawPanel(svg, figure.panels[i], maps[i], static_cast<int>(i));
  return svg.Finish();
}

}  // namespace koppel::plot
