// The one SVG writer: numbers, escaping, balanced groups, paths whose runs stay separate.
#include "koppel/plot/svg.hpp"

#include "tools/plot/svg_reading.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace koppel::svg_test {

TEST_CASE("Num prints short numbers and refuses non-finite ones", "[plot]") {
  CHECK(plot::Num(1.0) == "1");
  CHECK(plot::Num(-0.0001) == "0");
  CHECK(plot::Num(2.345678) == "2.35");
  CHECK(plot::Num(2.75, 0) == "3");
  CHECK(plot::Num(1234.5, 3) == "1234.5");
  CHECK_THROWS_AS(plot::Num(std::numeric_limits<double>::quiet_NaN()), std::logic_error);
  CHECK_THROWS_AS(plot::Num(INFINITY), std::logic_error);
}

TEST_CASE("Svg writes a document an XML parser reads back, text escaped", "[plot]") {
  plot::Svg svg(200, 100);
  svg.OpenGroup({{"class", "panel"}, {"data-title", "s < 1 & \"q\""}});
  svg.Text({10, 20}, "φ_a <i> & 'x'", {{"class", "label"}});
  svg.Path({{{0, 0}, {10, 10}}, {{20, 20}, {30, 30}, {40, 35}}}, {{"class", "curve"}});
  svg.CloseGroup();
  const auto doc = test::ParseSvg(svg.Finish());
  const auto panel = test::Find(doc, "g", "panel");
  REQUIRE(panel.size() == 1);
  CHECK(std::string(panel[0].attribute("data-title").as_string()) == "s < 1 & \"q\"");
  CHECK(std::string(test::Find(doc, "text", "label")[0].child_value()) == "φ_a <i> & 'x'");
  const auto runs = test::Subpaths(test::Find(doc, "path", "curve")[0]);
  REQUIRE(runs.size() == 2);  // the gap between the runs is not bridged
  CHECK(runs[0].size() == 2);
  CHECK(runs[1].size() == 3);
  CHECK(runs[1].back().isApprox(Eigen::Vector2d(40, 35)));
}

TEST_CASE("Svg refuses unbalanced groups", "[plot]") {
  plot::Svg svg(10, 10);
  CHECK_THROWS_AS(svg.CloseGroup(), std::logic_error);
  svg.OpenGroup({});
  CHECK_THROWS_AS(svg.Finish(), std::logic_error);
}

}  // namespace koppel::svg_test
