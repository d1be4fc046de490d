// Coupler-curve plot of seed 003 with its straight-line stretch, read back from the SVG and
// compared with the independent four-bar (tests/support/closed_forms) and the seed's reading
// example (Q_G = 0.005: φ_A = 98.3°, φ_G = 163.3°, L = 3.91 l1).
#include "koppel/plot/plots.hpp"

#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"
#include "tools/plot/svg_reading.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>

namespace koppel::curve_plot_test {

TEST_CASE("curve plot of seed 003: to scale, K_A/K_I/K_E on the independent curve, band of the stretch", "[plot]") {
  const double l1 = 1, l2 = 2.5 * std::sqrt(3.0), l4 = 4, k = 25.0 / 3, kappa = std::acos(5.0 / 9 * std::sqrt(3.0));
  const Mechanism m = test::FourBar(l1, l2, l2, l4, k, kappa, +1);
  plot::CurvePlotOptions o;
  o.point = {m.FindLink("coupler"), m.links[m.FindLink("coupler")].FindPoint("K")};
  o.range.from = 0;
  o.range.to = DegToRad(360);
  o.range.step = DegToRad(1);
  o.straight = true;
  o.reference = kPi;
  const plot::PlotResult r = plot::CurvePlot(m, o);
  REQUIRE(r.status == plot::PlotStatus::kComplete);
  const auto doc = test::ParseSvg(r.svg);
  const auto panels = test::Find(doc, "g", "panel");
  REQUIRE(panels.size() == 2);
  const test::AxisMap x = test::ReadAxis(panels[0], "x"), y = test::ReadAxis(panels[0], "y");
  // to scale: a unit in x is as many px as a unit in y
  CHECK(std::abs(x.ToPx(1) - x.ToPx(0)) == Approx(std::abs(y.ToPx(1) - y.ToPx(0))).epsilon(1e-3));
  const auto curves = test::Find(panels[0], "path", "curve");
  REQUIRE(curves.size() == 3);  // the curve, the stretch, the tangent
  const auto runs = test::Subpaths(curves[0]);
  REQUIRE(runs.size() == 1);
  REQUIRE(runs[0].size() == 361);
  // every 30th drawn point on the independent four-bar's curve at its sample's input
  for (int i = 0; i <= 360; i += 30) {
    const Eigen::Vector2d K = test::FourBarCouplerPoint(l1, l2, l2, l4, k, kappa, DegToRad(i), +1);
    CHECK(x.ToPx(K.x()) == Approx(runs[0][i].x()).margin(0.01));
    CHECK(y.ToPx(K.y()) == Approx(runs[0][i].y()).margin(0.01));
  }
  // K_A, K_E at the inputs their labels give, K_I at 180 deg
  for (const auto& marker : test::Find(panels[0], "g", "marker")) {
    const std::string label = marker.child("text").child_value();
    const double input = std::strtod(label.substr(label.find('=') + 1).c_str(), nullptr);
    const Eigen::Vector2d K = test::FourBarCouplerPoint(l1, l2, l2, l4, k, kappa, DegToRad(input), +1);
    const auto c = marker.child("circle");
    INFO(label);
    CHECK(x.ToPx(K.x()) == Approx(c.attribute("cx").as_double()).margin(0.05));
    CHECK(y.ToPx(K.y()) == Approx(c.attribute("cy").as_double()).margin(0.05));
    if (label.rfind("K_A", 0) == 0) CHECK(input == Approx(98.3).margin(0.05));
    if (label.rfind("K_E", 0) == 0) CHECK(input - 98.3 == Approx(163.3).margin(0.1));
    if (label.rfind("K_I", 0) == 0) CHECK(input == Approx(180).margin(1e-9));
  }
  // the band panel: the band's height is Δy of the stretch measured independently: the
  // four-bar's points over φ_A..φ_E against the tangent at K_I (central difference, h = 1e-6)
  const auto band = test::Find(panels[1], "polygon", "band");
  REQUIRE(band.size() == 1);
  const test::AxisMap u = test::ReadAxis(panels[1], "x"), v = test::ReadAxis(panels[1], "y");
  double v_low = 1e300, v_high = -1e300, u_low = 1e300, u_high = -1e300;
  std::istringstream corners(band[0].attribute("points").as_string());
  std::string corner;
  while (corners >> corner) {
    const double px = std::strtod(corner.c_str(), nullptr), py = std::strtod(corner.substr(corner.find(',') + 1).c_str(), nullptr);
    v_low = std::min(v_low, v.ToData(py)), v_high = std::max(v_high, v.ToData(py));
    u_low = std::min(u_low, u.ToData(px)), u_high = std::max(u_high, u.ToData(px));
  }
  const double h = 1e-6;
  const Eigen::Vector2d t = (test::FourBarCouplerPoint(l1, l2, l2, l4, k, kappa, kPi + h, +1) -
                             test::FourBarCouplerPoint(l1, l2, l2, l4, k, kappa, kPi - h, +1)).normalized();
  const Eigen::Vector2d n(-t.y(), t.x()), k_i = test::FourBarCouplerPoint(l1, l2, l2, l4, k, kappa, kPi, +1);
  double low = 1e300, high = -1e300, along_low = 1e300, along_high = -1e300;
  for (double phi = 98.34; phi <= 261.66; phi += 0.01) {
    const Eigen::Vector2d p = test::FourBarCouplerPoint(l1, l2, l2, l4, k, kappa, DegToRad(phi), +1) - k_i;
    low = std::min(low, n.dot(p)), high = std::max(high, n.dot(p));
    along_low = std::min(along_low, t.dot(p)), along_high = std::max(along_high, t.dot(p));
  }
  // px rounding of the band corners: 0.005 px on a ~0.0195 per 220 px axis = 5e-7
  CHECK(v_high - v_low == Approx(high - low).margin(2e-4));
  CHECK(u_high - u_low == Approx(3.91).margin(0.005));  // seed 003's reading: L = 3.91 l1
}

}  // namespace koppel::curve_plot_test
