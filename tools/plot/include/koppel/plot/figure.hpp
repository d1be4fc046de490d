// Plot layout: a figure is a column of panels; each panel has its own x and y axis (with ticks
// at round values, units and a label), curves drawn as one <path> each (a curve's stretches are
// subpaths, so a gap stays a gap), markers with labels, vertical rules across the panel, filled
// bands, and a legend. RenderFigure turns the description into SVG through the one SVG writer.
#pragma once

#include "koppel/plot/svg.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel::plot {

struct Axis {
  std::string label;        // e.g. "φ [deg]"
  double min = 0, max = 1;  // the drawn range
  std::vector<double> ticks;
};

// Ticks at round values (1, 2, 5 × 10^k; for degrees also 15, 30, 45, 90) covering [low, high],
// about `target` of them; the axis range is widened to the outer ticks. A zero-width range is
// widened around its value.
Axis NiceAxis(const std::string& label, double low, double high, bool degrees = false, int target = 6);

struct Curve {
  std::string name;                                // legend entry; empty: no legend entry
  std::vector<std::vector<Eigen::Vector2d>> runs;  // data coordinates; one subpath each
  int colour = 0;                                  // index into the palette (8 colours, then again)
  bool dashed = false;
  std::string stroke;                              // "#rrggbb" instead of the palette (a ramp)
};

struct Marker {
  Eigen::Vector2d at = Eigen::Vector2d::Zero();  // data coordinates
  std::string label;
  std::string kind;  // CSS class suffix: "deadcentre", "minimum", "singular", "point"
};

struct Rule {
  double x = 0;  // a vertical line at this abscissa across the panel
  std::string label;
  std::string kind;  // "deadcentre", "gap", "singular"
};

struct Band {
  std::vector<Eigen::Vector2d> corners;  // data coordinates of a filled polygon
  std::string label;
};

struct Panel {
  Axis x, y;
  std::string title;
  std::vector<Curve> curves;
  std::vector<Marker> markers;
  std::vector<Rule> rules;
  std::vector<Band> bands;
  std::vector<std::pair<double, double>> shaded;  // x intervals shaded (not computed / gaps)
  bool equal_aspect = false;                       // one unit in x is one unit in y (curves)
};

struct Figure {
  std::string title;
  std::vector<Panel> panels;
  double width = 720;         // px
  double panel_height = 220;  // px, for panels without equal aspect
};

std::string RenderFigure(const Figure& figure);

// The colour at t in [0, 1] (clamped) of an ordered family of curves: viridis, perceptually
// uniform with lightness rising with t, its lightest tenths (yellow on white) left out. For a
// family parameter, unlike the palette, whose ninth colour is its first again.
std::string RampColour(double t);

}  // namespace koppel::plot
