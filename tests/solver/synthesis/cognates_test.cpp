// Roberts cognates of seed 003's crank-rocker: the first one has the dimensions the document
// lists (with A0*B0* = 40/9 sqrt 3), the second the original's; both trace the same coupler
// curve to 1e-9 at 360 points.
#include "koppel/synthesis/cognates.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>

namespace koppel::cognates_test {
namespace {

// Roberts' cognates are closed forms (similar triangles) of O(10) lengths: rounding only
constexpr double kCognateRoundoff = 1e-12;
const double kL23 = 2.5 * std::sqrt(3.0);
const double kKappa = std::acos(5.0 / 9.0 * std::sqrt(3.0));
constexpr double kSame = 1e-9;  // "the same curve": the 1e-9 at 360 points
}  // namespace

TEST_CASE("seed 003 cognate dimensions", "[cognates]") {
  const Cognates c = RobertsCognates(test::FourBar(1.0, kL23, kL23, 4.0, 25.0 / 3, kKappa, 1), {2, 2});
  REQUIRE(c.ok());
  // first cognate as listed: l1* = 25/3, l2* = 10/9 sqrt 3, l3* = 25/3, k* = l* = 1, and the
  // frame A0*B0* = 40/9 sqrt 3 (the printed 40/3 sqrt 3 is an OCR error)
  CHECK(c.crank_first == Approx(25.0 / 3).margin(kCognateRoundoff));
  CHECK(c.coupler_first == Approx(10.0 / 9 * std::sqrt(3.0)).margin(kCognateRoundoff));
  CHECK(c.rocker_first == Approx(25.0 / 3).margin(kCognateRoundoff));
  CHECK(c.k_first == Approx(1.0).margin(kCognateRoundoff));
  CHECK(c.l_first == Approx(1.0).margin(kCognateRoundoff));
  CHECK(c.frame_first == Approx(40.0 / 9 * std::sqrt(3.0)).margin(kCognateRoundoff));
  CHECK(std::abs(c.frame_first - 40.0 / 3 * std::sqrt(3.0)) > 10);
  // second cognate: "the same kinematic dimensions as the original"
  CHECK(c.frame_second == Approx(4.0).margin(kCognateRoundoff));
  CHECK(c.crank_second == Approx(1.0).margin(kCognateRoundoff));
  CHECK(c.coupler_second == Approx(kL23).margin(kCognateRoundoff));
  CHECK(c.rocker_second == Approx(kL23).margin(kCognateRoundoff));
}

TEST_CASE("cognates trace the same coupler curve at 360 points", "[cognates]") {
  const Mechanism original = test::FourBar(1.0, kL23, kL23, 4.0, 25.0 / 3, kKappa, 1);
  const Cognates c = RobertsCognates(original, {2, 2});
  REQUIRE(c.ok());
  SweepOptions turn;
  turn.from = 0;
  turn.to = DegToRad(359);
  turn.step = DegToRad(1);
  const SweepResult a = Sweep(original, turn);
  REQUIRE(a.complete());
  REQUIRE(a.inputs.size() == 360);

  // cognate 2 has the original's input: sweep it and compare K sample by sample
  const SweepResult second = Sweep(c.second, turn);
  REQUIRE(second.complete());
  double worst2 = 0;
  for (int i = 0; i < 360; ++i)
    worst2 = std::max({worst2, std::abs(second.outputs(i, 0) - a.outputs(i, 0)), std::abs(second.outputs(i, 3) - a.outputs(i, 3))});
  INFO("cognate 2 worst " << worst2);
  CHECK(worst2 <= kSame);

  // cognate 1 follows the original coupler, whose direction oscillates (a double rocker driven
  // by a rocker cannot be swept through its turning points). Instead: at each sample build the
  // pose Roberts' relations give (A1 = A0 + r (B - A), C1 = A1 + r (A - A0)), let cognate 1's own
  // Newton polish it at its input, and demand that it needs nothing (its joints close) and that
  // its K is the original's K.
  const ConstraintSystem original_system(original);
  PositionSolver solver(c.first);
  const std::complex<double> r = std::polar(25.0 / 3 / kL23, kKappa);  // K = A + r (B - A)
  double worst1 = 0, worst_residual = 0;
  for (int i = 0; i < 360; ++i) {
    const Eigen::VectorXd qo = a.poses.row(i).transpose();
    auto at = [&](PointRef p) {
      double xy[2];
      original_system.GlobalPoint(p, qo.data(), xy);
      return std::complex<double>(xy[0], xy[1]);
    };
    const std::complex<double> a0 = at({0, 0}), pa = at({2, 0}), pb = at({2, 1}), b0 = at({0, 1});
    const std::complex<double> a1 = a0 + r * (pb - pa), c1 = a1 + r * (pa - a0), c0 = a0 + r * (b0 - a0);
    Eigen::VectorXd start(9);
    start << a0.real(), a0.imag(), std::arg(a1 - a0), a1.real(), a1.imag(), std::arg(c1 - a1), c0.real(), c0.imag(), std::arg(c1 - c0);
    const double input = std::arg(a1 - a0) - c.first.drive.zero;
    Eigen::VectorXd residual(solver.system().NumEquations());
    solver.system().Residuals(start.data(), input, residual.data());
    worst_residual = std::max(worst_residual, residual.lpNorm<Eigen::Infinity>());
    REQUIRE(solver.Correct(input, start).ok());
    double k[2];
    solver.system().GlobalPoint({2, 2}, start.data(), k);
    worst1 = std::max({worst1, std::abs(k[0] - a.outputs(i, 0)), std::abs(k[1] - a.outputs(i, 3))});
  }
  INFO("cognate 1: joints close to " << worst_residual);
  CHECK(worst_residual <= kSame);
  INFO("cognate 1 worst " << worst1);
  CHECK(worst1 <= kSame);
}

TEST_CASE("cognates need a four-bar of R joints and a coupler point", "[cognates]") {
  CHECK_FALSE(RobertsCognates(test::SliderCrank(1, 2.6, 0), {2, 1}).ok());
  CHECK_FALSE(RobertsCognates(test::FourBar(1.0, kL23, kL23, 4.0, 1.0, 0.0, 1), {1, 1}).ok());  // a crank point
}

}  // namespace koppel::cognates_test
