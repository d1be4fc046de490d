// Design charts from `koppel synth chart` CSVs: curve families with their parameter, gaps of
// the grid not bridged, tables that are not charts refused with the line.
#include "koppel/plot/plots.hpp"

#include "tools/plot/svg_reading.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

namespace koppel::chart_plot_test {
namespace {

// CIE L*a*b* (D65) of an sRGB colour "#rrggbb": IEC 61966-2-1's transfer function, then CIE 1976.
std::array<double, 3> Lab(const std::string& hex) {
  REQUIRE(hex.size() == 7);
  double rgb[3];
  for (int c = 0; c < 3; ++c) {
    const double v = std::strtol(hex.substr(1 + 2 * c, 2).c_str(), nullptr, 16) / 255.0;
    rgb[c] = v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  }
  const double x = (0.4124 * rgb[0] + 0.3576 * rgb[1] + 0.1805 * rgb[2]) / 0.95047,
               y = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2],
               z = (0.0193 * rgb[0] + 0.1192 * rgb[1] + 0.9505 * rgb[2]) / 1.08883;
  auto f = [](double t) { return t > 216.0 / 24389 ? std::cbrt(t) : (24389.0 / 27 * t + 16) / 116; };
  return {116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))};
}

}  // namespace

TEST_CASE("crank-rocker chart: one curve per psi0, labelled, a missing design breaks its curve", "[plot]") {
  std::string csv = "phi0,psi0,beta,mu_min,l1,l2,l3,l4\n";
  for (int psi : {40, 60})
    for (int phi = 160; phi <= 180; phi += 5)
      if (!(psi == 60 && phi == 170)) csv += std::to_string(phi) + "," + std::to_string(psi) + ",30," + std::to_string(phi - psi) + ",1,2,3,4\n";
  const plot::PlotResult r = plot::ChartPlot(csv, "chart.csv");
  REQUIRE(r.status == plot::PlotStatus::kComplete);
  const auto doc = test::ParseSvg(r.svg);
  const auto panels = test::Find(doc, "g", "panel");
  REQUIRE(panels.size() == 2);  // max mu_min and beta over phi0
  const auto curves = test::Find(panels[0], "path", "curve");
  REQUIRE(curves.size() == 2);
  CHECK(std::string(curves[0].attribute("data-name").as_string()) == "ψ0 = 40°");
  CHECK(std::string(curves[1].attribute("data-name").as_string()) == "ψ0 = 60°");
  CHECK(test::Subpaths(curves[0]).size() == 1);
  CHECK(test::Subpaths(curves[1]).size() == 2);  // 170 is missing: 160..165 and 175..180
  const test::AxisMap x = test::ReadAxis(panels[0], "x"), y = test::ReadAxis(panels[0], "y");
  const auto last = test::Subpaths(curves[1]).back().back();
  CHECK(x.ToData(last.x()) == Approx(180).margin(0.01));
  CHECK(y.ToData(last.y()) == Approx(120).margin(0.01));
}

TEST_CASE("slider-crank chart: e/s0, l1/s0, l2/s0 and mu_min over phi0", "[plot]") {
  const std::string csv = "phi0,e_s0,l1_s0,l2_s0,mu_min,beta\n120,0.16,0.5,1.1,11.2,10\n130,0.2,0.55,1.2,15,12\n";
  const plot::PlotResult r = plot::ChartPlot(csv, "s.csv");
  REQUIRE(r.status == plot::PlotStatus::kComplete);
  const auto doc = test::ParseSvg(r.svg);
  const auto panels = test::Find(doc, "g", "panel");
  REQUIRE(panels.size() == 2);
  CHECK(test::Find(panels[0], "path", "curve").size() == 3);
  CHECK(test::Find(panels[1], "path", "curve").size() == 1);
}

TEST_CASE("synth chart's rows without a design are gaps; one rocker sense per plot", "[plot]") {
  const std::string header = "phi0,psi0,rocker_sense,status,beta,mu_min,l1,l2,l3,l4,beta_L,beta_E\n";
  std::string csv = header;
  for (int phi = 160; phi <= 180; phi += 5)
    csv += phi == 170 ? "170,40,same,none,,,,,,,,\n" : std::to_string(phi) + ",40,same,ok,30,20,1,2,3,4,50,10\n";
  const plot::PlotResult r = plot::ChartPlot(csv, "chart.csv");
  REQUIRE(r.status == plot::PlotStatus::kComplete);
  const auto doc = test::ParseSvg(r.svg);  // the nodes below point into it: keep it alive
  const auto curves = test::Find(test::Find(doc, "g", "panel")[0], "path", "curve");
  REQUIRE(curves.size() == 1);
  CHECK(test::Subpaths(curves[0]).size() == 2);  // 170 has no design: 160..165 and 175..180
  const plot::PlotResult both = plot::ChartPlot(csv + "160,40,opposite,ok,30,20,1,2,3,4,50,10\n", "chart.csv");
  CHECK(both.status == plot::PlotStatus::kFailed);
  CHECK_THAT(both.message, Catch::Contains("--rocker-sense"));
}

TEST_CASE("tables that are not charts are refused, naming the file and line", "[plot]") {
  CHECK_THAT(plot::ChartPlot("phi0,psi0,beta,mu_min\n1,2,3,4\n1,2,x,4\n", "c.csv").message, Catch::StartsWith("c.csv:3:"));
  CHECK_THAT(plot::ChartPlot("phi0,psi0,beta,mu_min\n1,2,3\n", "c.csv").message, Catch::StartsWith("c.csv:2:"));
  CHECK(plot::ChartPlot("a,b\n1,2\n", "c.csv").status == plot::PlotStatus::kFailed);
  CHECK(plot::ChartPlot("", "c.csv").status == plot::PlotStatus::kFailed);
}

// Issue 22 item 15: with `synth chart`'s default psi0 = 20:100:2 the chart draws nine curves
// (20, 30, ..., 100 deg) and gave 20 and 100 deg the same colour (an eight-colour palette again).
TEST_CASE("crank-rocker chart: every psi0 its own colour, lightness rising with psi0", "[plot]") {
  // a difference of 10 CIE76 units is plain at a glance (2.3 is the just noticeable difference)
  constexpr double kDistinct = 10;
  std::string csv = "phi0,psi0,beta,mu_min,l1,l2,l3,l4\n";
  for (int psi = 20; psi <= 100; psi += 2)
    for (int phi = 160; phi <= 200; phi += 10) csv += std::to_string(phi) + "," + std::to_string(psi) + ",30,40,1,2,3,4\n";
  const plot::PlotResult r = plot::ChartPlot(csv, "chart.csv");
  REQUIRE(r.status == plot::PlotStatus::kComplete);
  const auto doc = test::ParseSvg(r.svg);
  for (const auto& panel : test::Find(doc, "g", "panel")) {
    std::map<double, std::string> colour;  // by psi0
    for (const auto& c : test::Find(panel, "path", "curve")) {
      const std::string name = c.attribute("data-name").as_string();  // "ψ0 = 20°"
      colour[std::stod(name.substr(name.find('=') + 1))] = c.attribute("stroke").as_string();
    }
    REQUIRE(colour.size() == 9);
    CHECK(colour.begin()->first == 20);
    CHECK(colour.rbegin()->first == 100);
    for (auto a = colour.begin(); a != colour.end(); ++a) {
      for (auto b = std::next(a); b != colour.end(); ++b) {
        const auto la = Lab(a->second), lb = Lab(b->second);
        INFO("psi0 " << a->first << " (" << a->second << ") and " << b->first << " (" << b->second << ")");
        CHECK(std::hypot(la[0] - lb[0], la[1] - lb[1], la[2] - lb[2]) >= kDistinct);
        CHECK(lb[0] > la[0]);  // ordered: a larger psi0 is lighter
      }
    }
    // the legend shows the curves' colours
    std::map<std::string, std::string> legend;
    const auto lines = test::Find(panel, "line", "legend-line");
    const auto labels = test::Find(panel, "text", "legend-label");
    REQUIRE(lines.size() == labels.size());
    for (size_t i = 0; i < lines.size(); ++i) legend[labels[i].child_value()] = lines[i].attribute("stroke").as_string();
    for (const auto& c : test::Find(panel, "path", "curve")) CHECK(legend[c.attribute("data-name").as_string()] == c.attribute("stroke").as_string());
  }
}

}  // namespace koppel::chart_plot_test
