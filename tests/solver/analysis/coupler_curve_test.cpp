// Coupler curves and the straight-line analysis: arc length against a circle; seed 003's
// distances and its reading example (Q_G = 0.005 -> phi_G = 163.3 deg, phi_A = 98.3 deg, L = 3.91 l1).
#include "koppel/analysis/coupler_curve.hpp"

#include "koppel/core/angles.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel {
namespace {
const double kL23 = 2.5 * std::sqrt(3.0);
const double kKappa = std::acos(5.0 / 9.0 * std::sqrt(3.0));
Mechanism Seed003() { return test::FourBar(1.0, kL23, kL23, 4.0, 25.0 / 3, kKappa, 1); }
}  // namespace

TEST_CASE("arc length of the crank pin is l1 times the crank angle", "[curve]") {
  const Mechanism m = Seed003();
  SweepOptions range;
  range.from = 0;
  range.to = 2 * kPi;
  range.step = DegToRad(5);
  const CouplerCurve c = TraceCurve(m, {1, 1}, range);  // crank.A on a circle of radius l1 = 1
  REQUIRE(c.sweep.complete());
  // Gauss on the Hermite interpolant of a circle: O(h^4) ~ 1e-7 relative at 5 deg steps
  CHECK(c.arc_length.back() == Approx(2 * kPi).epsilon(1e-6));
  for (double k : c.curvature) CHECK(k == Approx(1.0).epsilon(1e-12));  // curvature 1/l1
}

TEST_CASE("seed 003: B0K_I = 10/3 sqrt 6, stroke h = 0.469, K_I flattest", "[curve]") {
  const Mechanism m = Seed003();
  SweepOptions range;
  range.from = 0;
  range.to = 2 * kPi;
  range.step = DegToRad(0.5);
  const CouplerCurve c = TraceCurve(m, {2, 2}, range);
  REQUIRE(c.sweep.complete());
  const Eigen::Vector2d b0(4, 0);
  const Eigen::Vector2d k_i = c.points[360], k_ii = c.points[0];  // phi = 180 deg and 0
  CHECK((k_i - b0).norm() == Approx(10.0 / 3 * std::sqrt(6.0)).margin(1e-12));
  CHECK((k_ii - b0).norm() - (k_i - b0).norm() == Approx(std::sqrt(2.0) / 3 * (5 * std::sqrt(11.0) - 9 * std::sqrt(3.0))).margin(1e-12));
  // six-point contact: the curvature vanishes at K_I, and it is the flattest sample
  CHECK(std::abs(c.curvature[360]) < 1e-12);
  CHECK(FlattestSample(c) == 360);
}

TEST_CASE("seed 003 reading example: Q_G = 0.005", "[curve]") {
  const StraightStretch s = LongestStraightStretch(Seed003(), {2, 2}, 0.005, kPi, kPi, DegToRad(0.02));
  REQUIRE(s.ok());
  // the document's figures, read off a chart: phi_G = 163.3 deg, phi_A = 98.3 deg (0.1 deg), L/l1 = 3.91
  CHECK(RadToDeg(s.phi_g) == Approx(163.3).margin(0.05));
  CHECK(RadToDeg(s.phi_a) == Approx(98.3).margin(0.05));
  CHECK(s.length == Approx(3.91).margin(0.005));
  CHECK(s.qg <= 0.005);
  // the band of the reported stretch, measured on its own, is the same
  const StraightStretch band = StretchBand(Seed003(), {2, 2}, kPi, s.phi_a, s.phi_e, DegToRad(0.02));
  CHECK(band.band == Approx(s.band).margin(1e-12));
  // a tighter tolerance gives a shorter stretch
  const StraightStretch tight = LongestStraightStretch(Seed003(), {2, 2}, 0.001, kPi, kPi, DegToRad(0.1));
  REQUIRE(tight.ok());
  CHECK(tight.phi_g < s.phi_g);
}

}  // namespace koppel
