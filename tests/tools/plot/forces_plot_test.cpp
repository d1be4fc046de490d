// The forces plot of seed 000's slider-crank with a force on the slider, read back from the SVG:
// the drive torque where F s'(phi) puts it, the frame bearing's polar diagram where the reaction
// F_A0 = (F, ...) puts it; singular rows break the curve and make the picture partial.
#include "koppel/plot/forces_plot.hpp"

#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"
#include "tools/plot/svg_reading.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::forces_plot_test {
namespace {

constexpr double l1 = 1, l2 = 2.6, e = 0.8, force = 100;

Loads SliderForce(const Mechanism& m) {
  Loads loads;
  loads.forces.push_back({"F", {m.FindLink("slider"), 0}, Eigen::Vector2d(-1, 0), m.FrameLink(), "100"});
  return loads;
}

}  // namespace

TEST_CASE("forces plot of seed 000: drive torque F s'(phi) and the bearing A0's polar diagram", "[plot]") {
  const Mechanism m = test::SliderCrank(l1, l2, e);
  plot::ForcesPlotOptions options;
  options.forces.sweep.from = 0;
  options.forces.sweep.to = DegToRad(360);
  options.forces.sweep.step = DegToRad(2);
  options.joints = {m.FindJoint("A0")};
  const plot::PlotResult r = plot::ForcesPlot(m, SliderForce(m), options);
  REQUIRE(r.status == plot::PlotStatus::kComplete);
  const auto doc = test::ParseSvg(r.svg);
  const auto panels = test::Find(doc, "g", "panel");
  REQUIRE(panels.size() == 2);
  const test::AxisMap x = test::ReadAxis(panels[0], "x"), y = test::ReadAxis(panels[0], "y");
  const auto runs = test::Subpaths(test::Find(panels[0], "path", "curve").at(0));
  REQUIRE(runs.size() == 1);
  REQUIRE(runs[0].size() == 181);
  for (const auto& p : runs[0]) {
    const double phi = DegToRad(x.ToData(p.x()));
    // 0.005 px rounding in y, and in x (0.003 deg) times the slope: a few hundredths of a px
    CHECK(y.ToPx(force * test::SliderCrank(l1, l2, e, phi).s1) == Approx(p.y()).margin(0.05));
  }
  // the frame takes the slider force: the x component of its force on the crank is +F throughout
  const test::AxisMap fx = test::ReadAxis(panels[1], "x");
  const auto polar = test::Subpaths(test::Find(panels[1], "path", "curve").at(0));
  REQUIRE(polar.size() == 1);
  for (const auto& p : polar[0]) CHECK(fx.ToData(p.x()) == Approx(force).margin(0.05));
}

TEST_CASE("forces plot: a branch point breaks the torque curve and the picture is partial", "[plot]") {
  Mechanism m = test::FourBar(1.0, 3.0, 1.0, 3.0, 1.0, 0.0, +1);  // a parallelogram: flat at phi = 0
  m.hint.input = DegToRad(-20);
  m.hint.points = {{{2, 1}, Eigen::Vector2d(3 + std::cos(DegToRad(-20)), std::sin(DegToRad(-20)))}};
  Loads loads;
  loads.torques.push_back({"M", 3, "1"});
  plot::ForcesPlotOptions options;
  options.forces.sweep.from = DegToRad(-30);
  options.forces.sweep.to = DegToRad(30);
  options.forces.sweep.step = DegToRad(5);
  const plot::PlotResult r = plot::ForcesPlot(m, loads, options);
  CHECK(r.status == plot::PlotStatus::kPartial);
  const auto doc = test::ParseSvg(r.svg);
  const auto runs = test::Subpaths(test::Find(test::Find(doc, "g", "panel").at(0), "path", "curve").at(0));
  CHECK(runs.size() == 2);  // -30..-5 and 5..30: nothing drawn across the branch point
  options.joints = {99};
  CHECK(plot::ForcesPlot(m, loads, options).status == plot::PlotStatus::kFailed);
}

}  // namespace koppel::forces_plot_test
