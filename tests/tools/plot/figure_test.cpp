// Plot layout: round ticks that cover the data, and figures whose parts an XML parser finds.
#include "koppel/plot/figure.hpp"

#include "tools/plot/svg_reading.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace koppel::figure_test {

TEST_CASE("NiceAxis covers the data with evenly spaced round ticks (random ranges)", "[plot]") {
  std::mt19937 random(14);
  std::uniform_real_distribution<double> centre(-1e3, 1e3), exponent(-4, 4);
  for (int trial = 0; trial < 500; ++trial) {
    const double width = std::pow(10.0, exponent(random)), low = centre(random), high = low + width;
    const plot::Axis a = plot::NiceAxis("v", low, high, trial % 2 == 0);
    INFO("range " << low << " .. " << high);
    REQUIRE(a.ticks.size() >= 2);
    CHECK(a.min <= low);
    CHECK(a.max >= high);
    CHECK(a.ticks.front() == Approx(a.min));
    CHECK(a.ticks.back() == Approx(a.max).margin(1e-9 * width));
    const double step = a.ticks[1] - a.ticks[0];
    // not wider than one step beyond the data at either end, and not too many ticks
    CHECK(low - a.min < step * (1 + 1e-9));
    CHECK(a.max - high < step * (1 + 1e-9));
    CHECK(a.ticks.size() <= 14);
    for (size_t i = 1; i < a.ticks.size(); ++i) CHECK(a.ticks[i] - a.ticks[i - 1] == Approx(step).epsilon(1e-6));
  }
}

TEST_CASE("NiceAxis in degrees ticks a full turn at multiples of 30, 45 or 90", "[plot]") {
  const plot::Axis a = plot::NiceAxis("φ [deg]", 0, 360, true);
  CHECK(a.min == 0);
  CHECK(a.max == 360);
  const double step = a.ticks[1] - a.ticks[0];
  CHECK((step == 30 || step == 45 || step == 90));
}

TEST_CASE("RenderFigure: one path per curve, gaps as separate subpaths, markers where the data says", "[plot]") {
  plot::Figure f;
  plot::Panel p;
  p.x = plot::NiceAxis("x", 0, 10);
  p.y = plot::NiceAxis("y", -1, 1);
  p.curves.push_back({"first", {{{0, 0}, {1, 0.5}, {2, 1}}, {{5, -1}, {10, 0}}}, 0, false, ""});
  p.curves.push_back({"second", {{{0, 1}, {10, -1}}}, 1, true, ""});
  p.markers.push_back({{7, 0.25}, "m", "deadcentre"});
  p.shaded.push_back({2, 5});
  f.panels = {p, p};
  const auto doc = test::ParseSvg(plot::RenderFigure(f));
  const auto panels = test::Find(doc, "g", "panel");
  REQUIRE(panels.size() == 2);
  for (const auto& panel : panels) {
    const auto curves = test::Find(panel, "path", "curve");
    REQUIRE(curves.size() == 2);
    CHECK(test::Subpaths(curves[0]).size() == 2);
    CHECK(test::Subpaths(curves[1]).size() == 1);
    const test::AxisMap x = test::ReadAxis(panel, "x"), y = test::ReadAxis(panel, "y");
    CHECK(x.data_min == 0);
    CHECK(x.data_max == 10);
    const auto last = test::Subpaths(curves[0])[1].back();
    CHECK(x.ToData(last.x()) == Approx(10).margin(0.02));
    CHECK(y.ToData(last.y()) == Approx(0).margin(0.01));
    const auto markers = test::Find(panel, "g", "marker");
    REQUIRE(markers.size() == 1);
    const auto circle = markers[0].child("circle");
    CHECK(x.ToData(circle.attribute("cx").as_double()) == Approx(7).margin(0.02));
    CHECK(y.ToData(circle.attribute("cy").as_double()) == Approx(0.25).margin(0.01));
    const auto gap = test::Find(panel, "rect", "gap");
    REQUIRE(gap.size() == 1);
    CHECK(x.ToData(gap[0].attribute("x").as_double()) == Approx(2).margin(0.02));
    CHECK(test::Find(panel, "text", "legend-label").size() == 2);
  }
}

}  // namespace koppel::figure_test
