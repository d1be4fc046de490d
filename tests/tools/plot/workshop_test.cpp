// The workshop drawing: the parts at the pose asked for and the curves over the cycle, or why
// there is no pose. References: the circle-intersection four-bar of seed 003
// (tests/support/closed_forms) and its limit positions (a double rocker cannot reach 120 deg).
#include "koppel/plot/workshop.hpp"

#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel {
namespace {

// The solver converges to 1e-12 of the length scale.
constexpr double kTolerance = 1e-9;

const double kL2 = 2.5 * std::sqrt(3.0), kK = 25.0 / 3, kKappa = std::acos(5.0 / 9 * std::sqrt(3.0));

plot::WorkshopOptions Options(const Mechanism& m, double at) {
  plot::WorkshopOptions o;
  o.cycle.traced = plot::PointOutputs(m);
  o.cycle.sizes = plot::DefaultPartSizes(m);
  o.cycle.sweep.from = 0;
  o.cycle.sweep.to = 2 * kPi;
  o.at = at;
  return o;
}

}  // namespace

TEST_CASE("workshop drawing of seed 003 at 30 deg", "[plot][workshop]") {
  const Mechanism m = test::FourBar(1, kL2, kL2, 4, kK, kKappa, +1);
  const double phi = DegToRad(30);
  const plot::WorkshopDrawing d = plot::DrawWorkshop(m, Options(m, phi));
  REQUIRE(d.status == plot::PlotStatus::kComplete);
  CHECK(d.input == phi);
  CHECK(d.range.full_turn);
  REQUIRE(d.parts.size() == 4);
  // the crank's second hole is A = (cos phi, sin phi); the rocker's moving one is B
  const auto rocker = test::FourBarRocker(1, kL2, kL2, 4, phi, +1);
  REQUIRE(rocker);
  bool a = false, b = false;
  for (const plot::Part& p : d.parts)
    for (const plot::Hole& h : p.holes) {
      a |= p.link == "crank" && (h.centre - Eigen::Vector2d(std::cos(phi), std::sin(phi))).norm() < kTolerance;
      b |= p.link == "rocker" && (h.centre - rocker->b).norm() < kTolerance;
    }
  CHECK(a);
  CHECK(b);
  REQUIRE(d.curves.size() == 1);
  CHECK(d.curves[0].closed);
}

TEST_CASE("workshop drawing beyond a limit: no pose, and why", "[plot][workshop]") {
  const Mechanism m = test::PlainFourBar(3, 1, 3.5, 3, DegToRad(70), {2, 3.4});  // swings 49.2 .. 97.2 deg
  const plot::WorkshopDrawing d = plot::DrawWorkshop(m, Options(m, DegToRad(120)));
  CHECK(d.status == plot::PlotStatus::kFailed);
  CHECK_THAT(d.message, Catch::Contains("cannot reach"));
  CHECK(d.parts.empty());
  const plot::WorkshopDrawing ok = plot::DrawWorkshop(m, Options(m, DegToRad(60)));
  CHECK(ok.status == plot::PlotStatus::kComplete);
}

}  // namespace koppel
