// TolerancePlot (tools/plot/src/tolerance_plot.cpp) on a hand-made ToleranceBand, read back from
// the SVG with an XML parser (svg_reading.hpp). The reference is the band given, by the
// definitions in plots.hpp: panel 1 the nominal output; panel 2 the deviation from nominal, the
// worst-case band from +w up and back along -w and the Monte Carlo min/max minus nominal;
// panel 3 each name's share; an unreached row breaks every curve.
#include "koppel/plot/plots.hpp"

#include "tools/plot/svg_reading.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace koppel::tolerance_plot_test {
namespace {

// SVG coordinates carry two decimals (0.005 px); reading a value back through two ticks' px
// adds the same again: a few hundredths of a px, in data units on these axes well under 1e-3
// of the axis' span.
constexpr double kPxRounding = 0.02;

constexpr int kRows = 21;

plot::ToleranceBand Band(bool with_monte_carlo) {
  plot::ToleranceBand b;
  b.mechanism = "hand-made";
  b.output = "s";
  b.output_unit = "mm";
  b.input_label = "phi [deg]";
  for (int i = 0; i < kRows; ++i) {
    const double x = 10.0 * i;  // 0 .. 200 deg
    b.inputs.push_back(x);
    b.nominal.push_back(50 + 20 * std::sin(x * 0.0174533));
    b.worst_case.push_back(0.5 + 0.01 * i);
    if (with_monte_carlo) {
      b.mc_min.push_back(b.nominal.back() - 0.3 - 0.005 * i);
      b.mc_max.push_back(b.nominal.back() + 0.25 + 0.004 * i);
    }
    b.ok.push_back(true);
  }
  b.names = {"l1", "clearance A"};
  b.shares.resize(2);
  for (int i = 0; i < kRows; ++i) {
    b.shares[0].push_back(i / (kRows - 1.0));
    b.shares[1].push_back(1 - i / (kRows - 1.0));
  }
  return b;
}

pugi::xml_node CurveNamed(const pugi::xml_node& panel, const std::string& name, int nth = 0) {
  for (const auto& c : test::Find(panel, "path", "curve"))
    if (c.attribute("data-name").as_string() == name && nth-- == 0) return c;
  FAIL("no curve '" << name << "'");
  return {};
}

std::vector<Eigen::Vector2d> Corners(const pugi::xml_node& polygon) {
  std::vector<Eigen::Vector2d> out;
  std::istringstream in(polygon.attribute("points").as_string());
  double x, y;
  char comma;
  while (in >> x >> comma >> y) out.emplace_back(x, y);
  return out;
}

// Each point of every subpath, read back in data units, against f(input); the rows drawn are
// the reached rows, in order.
void CheckRuns(const std::vector<std::vector<Eigen::Vector2d>>& runs, const test::AxisMap& x, const test::AxisMap& y,
               const plot::ToleranceBand& b, const std::vector<double>& f, size_t expected_runs) {
  REQUIRE(runs.size() == expected_runs);
  const double x_tol = kPxRounding * std::abs((x.value1 - x.value0) / (x.px1 - x.px0));
  const double y_tol = kPxRounding * std::abs((y.value1 - y.value0) / (y.px1 - y.px0));
  size_t row = 0;
  for (const auto& run : runs)
    for (const auto& p : run) {
      while (row < b.ok.size() && !b.ok[row]) ++row;
      REQUIRE(row < b.ok.size());
      CHECK_THAT(x.ToData(p.x()), Catch::Matchers::WithinAbs(b.inputs[row], x_tol));
      CHECK_THAT(y.ToData(p.y()), Catch::Matchers::WithinAbs(f[row], y_tol));
      ++row;
    }
}

}  // namespace

TEST_CASE("TolerancePlot: the three panels hold the nominal, the band and the shares given", "[plot]") {
  const plot::ToleranceBand b = Band(true);
  const plot::PlotResult r = plot::TolerancePlot(b);
  REQUIRE(r.status == plot::PlotStatus::kComplete);
  CHECK(r.message.empty());
  const auto doc = test::ParseSvg(r.svg);
  const auto panels = test::Find(doc, "g", "panel");
  REQUIRE(panels.size() == 3);
  CHECK(std::string(panels[0].attribute("data-title").as_string()) == "s [mm]");
  CHECK(std::string(panels[1].attribute("data-title").as_string()) == "s − nominal [mm]");
  CHECK(std::string(panels[2].attribute("data-title").as_string()) == "share of the variance");
  for (const auto& panel : panels) {
    const test::AxisMap x = test::ReadAxis(panel, "x");
    CHECK(x.data_min <= 0);
    CHECK(x.data_max >= 200);
  }
  // panel 1: the nominal output
  {
    const test::AxisMap x = test::ReadAxis(panels[0], "x"), y = test::ReadAxis(panels[0], "y");
    const auto curves = test::Find(panels[0], "path", "curve");
    REQUIRE(curves.size() == 1);
    CheckRuns(test::Subpaths(curves[0]), x, y, b, b.nominal, 1);
  }
  // panel 2: +w and -w, the band between them, the Monte Carlo extremes minus nominal
  {
    const test::AxisMap x = test::ReadAxis(panels[1], "x"), y = test::ReadAxis(panels[1], "y");
    std::vector<double> up, down, mc_low, mc_high;
    for (int i = 0; i < kRows; ++i) {
      up.push_back(b.worst_case[i]);
      down.push_back(-b.worst_case[i]);
      mc_low.push_back(b.mc_min[i] - b.nominal[i]);
      mc_high.push_back(b.mc_max[i] - b.nominal[i]);
    }
    CHECK(test::Find(panels[1], "path", "curve").size() == 4);
    CheckRuns(test::Subpaths(CurveNamed(panels[1], "linear worst case")), x, y, b, up, 1);
    CheckRuns(test::Subpaths(CurveNamed(panels[1], "", 0)), x, y, b, down, 1);
    CheckRuns(test::Subpaths(CurveNamed(panels[1], "Monte Carlo min, max")), x, y, b, mc_low, 1);
    CheckRuns(test::Subpaths(CurveNamed(panels[1], "", 1)), x, y, b, mc_high, 1);
    // the y axis holds the band and the Monte Carlo extremes
    CHECK(y.data_max >= b.worst_case.back());
    CHECK(y.data_min <= -b.worst_case.back());
    const auto bands = test::Find(panels[1], "polygon", "band");
    REQUIRE(bands.size() == 1);
    CHECK(std::string(bands[0].attribute("data-label").as_string()) == "linear worst case");
    // up along +w, back along -w: the outline is the upper edge then the lower one reversed
    const std::vector<Eigen::Vector2d> corners = Corners(bands[0]);
    REQUIRE(corners.size() == 2 * kRows);
    std::vector<double> outline = up;
    outline.insert(outline.end(), down.rbegin(), down.rend());
    plot::ToleranceBand doubled = b;  // the outline's rows: the inputs forth, then back
    doubled.inputs.insert(doubled.inputs.end(), b.inputs.rbegin(), b.inputs.rend());
    doubled.ok.assign(2 * kRows, true);
    CheckRuns({corners}, x, y, doubled, outline, 1);
  }
  // panel 3: one curve per name, on a 0..1 axis
  {
    const test::AxisMap x = test::ReadAxis(panels[2], "x"), y = test::ReadAxis(panels[2], "y");
    CHECK(y.data_min == 0);
    CHECK(y.data_max == 1);
    CHECK(test::Find(panels[2], "path", "curve").size() == 2);
    CheckRuns(test::Subpaths(CurveNamed(panels[2], "l1")), x, y, b, b.shares[0], 1);
    CheckRuns(test::Subpaths(CurveNamed(panels[2], "clearance A")), x, y, b, b.shares[1], 1);
  }
}

TEST_CASE("TolerancePlot: without Monte Carlo the band panel has only the worst case", "[plot]") {
  const plot::PlotResult r = plot::TolerancePlot(Band(false));
  REQUIRE(r.status == plot::PlotStatus::kComplete);
  const auto doc = test::ParseSvg(r.svg);
  const auto panels = test::Find(doc, "g", "panel");
  REQUIRE(panels.size() == 3);
  CHECK(test::Find(panels[1], "path", "curve").size() == 2);
  CHECK(test::Find(panels[1], "polygon", "band").size() == 1);
}

TEST_CASE("TolerancePlot: an unreached row breaks every curve and the band; partial", "[plot]") {
  plot::ToleranceBand b = Band(true);
  b.ok[10] = false;
  const plot::PlotResult r = plot::TolerancePlot(b);
  REQUIRE(r.status == plot::PlotStatus::kPartial);
  CHECK_THAT(r.message, Catch::Contains("not reached"));
  const auto doc = test::ParseSvg(r.svg);
  const auto panels = test::Find(doc, "g", "panel");
  REQUIRE(panels.size() == 3);
  const test::AxisMap x0 = test::ReadAxis(panels[0], "x"), y0 = test::ReadAxis(panels[0], "y");
  CheckRuns(test::Subpaths(test::Find(panels[0], "path", "curve")[0]), x0, y0, b, b.nominal, 2);
  for (const auto& c : test::Find(panels[1], "path", "curve")) CHECK(test::Subpaths(c).size() == 2);
  for (const auto& c : test::Find(panels[2], "path", "curve")) CHECK(test::Subpaths(c).size() == 2);
  // one polygon per stretch, the legend's label on the first only
  const auto bands = test::Find(panels[1], "polygon", "band");
  REQUIRE(bands.size() == 2);
  CHECK(std::string(bands[0].attribute("data-label").as_string()) == "linear worst case");
  CHECK(std::string(bands[1].attribute("data-label").as_string()).empty());
  CHECK(Corners(bands[0]).size() == 2 * 10);
  CHECK(Corners(bands[1]).size() == 2 * 10);
}

// plots.hpp: "gaps of the computed range are shaded". An unreached row is shaded from its
// reached neighbour before to the one after (it was the interval [x, x], which the figure never
// draws: figure.cpp draws a gap only when b > a).
TEST_CASE("TolerancePlot: an unreached row is shaded on the panels", "[plot]") {
  plot::ToleranceBand b = Band(true);
  b.ok[10] = false;
  const auto doc = test::ParseSvg(plot::TolerancePlot(b).svg);
  for (const auto& panel : test::Find(doc, "g", "panel")) CHECK_FALSE(test::Find(panel, "rect", "gap").empty());
}

TEST_CASE("TolerancePlot: nothing reached is a failure with no picture", "[plot]") {
  plot::ToleranceBand none = Band(true);
  none.ok.assign(none.ok.size(), false);
  const plot::PlotResult r = plot::TolerancePlot(none);
  CHECK(r.status == plot::PlotStatus::kFailed);
  CHECK(r.svg.empty());
  CHECK_THAT(r.message, Catch::Contains("no input was reached"));
  const plot::PlotResult empty = plot::TolerancePlot(plot::ToleranceBand{});
  CHECK(empty.status == plot::PlotStatus::kFailed);
  CHECK(empty.svg.empty());
}

}  // namespace koppel::tolerance_plot_test
