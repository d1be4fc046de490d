// The workshop drawing: the parts at the pose asked for and the curves over the cycle, or why
// there is no pose. References: the circle-intersection four-bar of seed 003
// (tests/support/closed_forms) and its limit positions (a double rocker cannot reach 120 deg).
#include "koppel/plot/workshop.hpp"

#include "tools/plot/cycle_fixtures.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::workshop_test {
namespace {

// The solver converges to 1e-12 of the length scale.
constexpr double kTolerance = 1e-9;

plot::WorkshopOptions Options(const Mechanism& m, double at) { return {test::CycleOptionsFor(m), at}; }

}  // namespace

TEST_CASE("workshop drawing of seed 003 at 30 deg", "[plot][workshop]") {
  const Mechanism m = test::MzcCrankRocker();
  const double phi = DegToRad(30);
  const plot::WorkshopDrawing d = plot::DrawWorkshop(m, Options(m, phi));
  REQUIRE(d.status == plot::PlotStatus::kComplete);
  CHECK(d.input == phi);
  CHECK(d.range.full_turn);
  REQUIRE(d.parts.size() == 4);
  // the crank's second hole is A = (cos phi, sin phi); the rocker's moving one is B
  bool a = false, b = false;
  for (const plot::Part& p : d.parts)
    for (const plot::Hole& h : p.holes) {
      a |= p.link == "crank" && (h.centre - Eigen::Vector2d(std::cos(phi), std::sin(phi))).norm() < kTolerance;
      b |= p.link == "rocker" && (h.centre - test::MzcB(phi)).norm() < kTolerance;
    }
  CHECK(a);
  CHECK(b);
  REQUIRE(d.curves.size() == 1);
  CHECK(d.curves[0].closed);
}

TEST_CASE("workshop drawing beyond a limit: no pose, and why", "[plot][workshop]") {
  const Mechanism m = test::DoubleRocker();  // swings 49.2 .. 97.2 deg
  const plot::WorkshopDrawing d = plot::DrawWorkshop(m, Options(m, DegToRad(120)));
  CHECK(d.status == plot::PlotStatus::kFailed);
  CHECK_THAT(d.message, Catch::Contains("cannot reach"));
  CHECK(d.parts.empty());
  const plot::WorkshopDrawing ok = plot::DrawWorkshop(m, Options(m, DegToRad(60)));
  CHECK(ok.status == plot::PlotStatus::kComplete);
}

}  // namespace koppel::workshop_test
