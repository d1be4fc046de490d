// Transfer-function and transmission-angle plots of seed 000's slider-crank, read back from the
// SVG and compared with the seed's closed forms (tests/support/closed_forms.hpp).
#include "koppel/plot/plots.hpp"

#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"
#include "tools/plot/svg_reading.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>

namespace koppel::transfer_plot_test {
namespace {

// SVG coordinates carry two decimals: 0.005 px. On a 618 px wide 0..360 deg axis that is
// 0.003 deg; the tolerances below allow a few times that.
constexpr double kDegreesPerPxRounding = 0.02;

constexpr double l1 = 1, l2 = 2.6, e = 0.8;

plot::TransferPlotOptions FullTurn(const Mechanism& m, int order) {
  plot::TransferPlotOptions o;
  o.output = m.FindOutput("s");
  o.order = order;
  o.range.from = 0;
  o.range.to = DegToRad(360);
  o.range.step = DegToRad(1);
  return o;
}

}  // namespace

TEST_CASE("transfer plot of seed 000: panels, axes, one path per curve, values of the closed form", "[plot]") {
  const Mechanism m = test::SliderCrank(l1, l2, e);
  const plot::PlotResult r = plot::TransferPlot(m, FullTurn(m, 2));
  REQUIRE(r.status == plot::PlotStatus::kComplete);
  const auto doc = test::ParseSvg(r.svg);
  const auto panels = test::Find(doc, "g", "panel");
  REQUIRE(panels.size() == 3);  // s, s', s''
  for (int k = 0; k < 3; ++k) {
    INFO("order " << k);
    const test::AxisMap x = test::ReadAxis(panels[k], "x"), y = test::ReadAxis(panels[k], "y");
    CHECK(x.data_min == 0);
    CHECK(x.data_max == 360);
    const auto paths = test::Find(panels[k], "path", "curve");
    REQUIRE(paths.size() == 1);
    const auto runs = test::Subpaths(paths[0]);
    REQUIRE(runs.size() == 1);
    REQUIRE(runs[0].size() == 361);
    // every drawn point where seed 000's closed form puts it (px rounding: 0.005 px)
    double low = 1e300, high = -1e300;
    for (const auto& p : runs[0]) {
      const double phi = x.ToData(p.x());
      const test::SliderCrankValues v = test::SliderCrank(l1, l2, e, DegToRad(phi));
      const double expected = k == 0 ? v.s : k == 1 ? v.s1 : v.s2;
      // 0.005 px rounding in y, and in x (0.003 deg) times the slope: a few hundredths of a px
      CHECK(y.ToPx(expected) == Approx(p.y()).margin(0.03));
      low = std::min(low, expected), high = std::max(high, expected);
    }
    // the y axis holds the curve and is at most one tick step wider at either end
    const double step = y.tick_values[1] - y.tick_values[0];
    CHECK(y.data_min <= low);
    CHECK(y.data_max >= high);
    CHECK(low - y.data_min <= step);
    CHECK(y.data_max - high <= step);
  }
}

TEST_CASE("transfer plot of seed 000 marks the dead centres at phi_a and phi_i", "[plot]") {
  const Mechanism m = test::SliderCrank(l1, l2, e);
  const plot::PlotResult r = plot::TransferPlot(m, FullTurn(m, 1));
  REQUIRE(r.status == plot::PlotStatus::kComplete);
  const auto doc = test::ParseSvg(r.svg);
  const auto panel = test::Find(doc, "g", "panel").at(0);
  const test::AxisMap x = test::ReadAxis(panel, "x"), y = test::ReadAxis(panel, "y");
  const auto markers = test::Find(panel, "g", "deadcentre");
  REQUIRE(markers.size() == 2);
  // seed 000: phi_a = 90 deg + asin(eps/(1 + lambda)), phi_i = 270 deg + asin(eps/(1 - lambda))
  const double lambda = l1 / l2, eps = e / l2;
  const double phi_a = 90 + RadToDeg(std::asin(eps / (1 + lambda))), phi_i = 270 + RadToDeg(std::asin(eps / (1 - lambda)));
  const double s_a = std::sqrt((l1 + l2) * (l1 + l2) - e * e), s_i = std::sqrt((l2 - l1) * (l2 - l1) - e * e);
  const auto a = markers[0].child("circle"), i = markers[1].child("circle");
  CHECK(x.ToData(a.attribute("cx").as_double()) == Approx(phi_a).margin(kDegreesPerPxRounding));
  CHECK(x.ToData(i.attribute("cx").as_double()) == Approx(phi_i).margin(kDegreesPerPxRounding));
  CHECK(a.attribute("cy").as_double() == Approx(y.ToPx(s_a)).margin(0.01));
  CHECK(i.attribute("cy").as_double() == Approx(y.ToPx(s_i)).margin(0.01));
  // the rules through all panels, labelled on the first
  std::vector<std::string> labels;
  for (const auto& t : test::Find(panel, "text", "rule-label")) labels.push_back(t.child_value());
  CHECK(labels == std::vector<std::string>{"φ_a", "φ_i"});
  CHECK(test::Find(test::Find(doc, "g", "panel").at(1), "line", "deadcentre").size() == 2);
}

TEST_CASE("a slider-crank that cannot turn fully: the curve ends at the limit, the rest is shaded, no bridge", "[plot]") {
  // l2 - l1 = 0.5 < e = 0.8: the crank is limited where |A_y| = l2, cos(phi) = (l2 - e)/l1,
  // phi_limit = 360 deg - acos(0.7) = 314.43 deg when swept up from 90 deg.
  Mechanism m = test::SliderCrank(1, 1.5, 0.8);
  m.hint.input = kPi;
  m.hint.points[0].global = {1.5, 0};
  plot::TransferPlotOptions o = FullTurn(m, 1);
  o.range.from = DegToRad(90);
  const plot::PlotResult r = plot::TransferPlot(m, o);
  REQUIRE(r.status == plot::PlotStatus::kPartial);
  CHECK_THAT(r.message, Catch::Contains("limit point"));
  const double limit = 360 - RadToDeg(std::acos(0.7));
  const auto doc = test::ParseSvg(r.svg);
  for (const auto& panel : test::Find(doc, "g", "panel")) {
    const test::AxisMap x = test::ReadAxis(panel, "x");
    const auto runs = test::Subpaths(test::Find(panel, "path", "curve").at(0));
    REQUIRE(runs.size() == 1);
    for (const auto& p : runs[0]) CHECK(x.ToData(p.x()) <= limit + kDegreesPerPxRounding);
    CHECK(x.ToData(runs[0].back().x()) == Approx(314).margin(kDegreesPerPxRounding));  // the last whole degree
    const auto gap = test::Find(panel, "rect", "gap");
    REQUIRE(gap.size() == 1);
    CHECK(x.ToData(gap[0].attribute("x").as_double()) == Approx(limit).margin(0.05));
    CHECK(x.ToData(gap[0].attribute("x").as_double() + gap[0].attribute("width").as_double()) == Approx(360).margin(kDegreesPerPxRounding));
  }
}

TEST_CASE("mu plot of seed 000 marks mu_min = 90 deg - asin(lambda + eps) at phi = 0", "[plot]") {
  const Mechanism m = test::SliderCrank(l1, l2, e);
  plot::MuPlotOptions o;
  o.output = m.FindOutput("mu");
  o.range = FullTurn(m, 0).range;
  const plot::PlotResult r = plot::MuPlot(m, o);
  REQUIRE(r.status == plot::PlotStatus::kComplete);
  const auto doc = test::ParseSvg(r.svg);
  const auto panel = test::Find(doc, "g", "panel").at(0);
  const test::AxisMap x = test::ReadAxis(panel, "x"), y = test::ReadAxis(panel, "y");
  CHECK(y.data_min == 0);
  CHECK(y.data_max >= 90);
  const auto marker = test::Find(panel, "g", "minimum");
  REQUIRE(marker.size() == 1);
  const double mu_min = 90 - RadToDeg(std::asin(l1 / l2 + e / l2));  // seed 000, corrected location phi = 0
  const double phi = x.ToData(marker[0].child("circle").attribute("cx").as_double());
  CHECK(std::min(std::abs(phi), std::abs(phi - 360)) < kDegreesPerPxRounding);
  CHECK(y.ToData(marker[0].child("circle").attribute("cy").as_double()) == Approx(mu_min).margin(0.01));
  CHECK_THAT(std::string(marker[0].child("text").child_value()), Catch::StartsWith("μ_min = 46.19°"));
  plot::MuPlotOptions wrong = o;
  wrong.output = m.FindOutput("s");
  std::string why;
  CHECK_FALSE(wrong.IsValid(m, &why));
  CHECK(plot::MuPlot(m, wrong).status == plot::PlotStatus::kFailed);
}

}  // namespace koppel::transfer_plot_test
