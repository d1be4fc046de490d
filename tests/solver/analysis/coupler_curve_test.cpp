// Coupler curves and the straight-line analysis: arc length against a circle; seed 003's
// distances and its reading example (Q_G = 0.005 -> phi_G = 163.3 deg, phi_A = 98.3 deg, L = 3.91 l1).
#include "koppel/analysis/coupler_curve.hpp"

#include "koppel/core/angles.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace koppel::coupler_curve_test {
namespace {

// relative: Gauss on the Hermite interpolant of a circle: O(h^4) ~ 1e-7 at 5 deg steps
constexpr double kArcLength = 1e-6;
// relative: a circle's curvature from exact transfer functions: rounding only
constexpr double kCurvatureRoundoff = 1e-12;
// [length] a converged pose against seed 003's closed form on O(10) lengths: rounding only
constexpr double kPoseRoundoff = 1e-12;
// [deg] the document's figures, read off a chart to 0.1 deg: half of it
constexpr double kChartDeg = 0.05;
// L / l1 printed as 3.91: half a unit of its last digit
constexpr double kChartLength = 0.005;
// the same band computed twice from the same samples and stretch: rounding only
constexpr double kSameBand = 1e-12;
// [deg] the reference input is the one asked for, through two unit conversions
constexpr double kReferenceDeg = 1e-12;
// [deg] the sum of two chart readings, each to within kChartDeg
constexpr double kChartSumDeg = 0.1;
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
  CHECK(c.arc_length.back() == Approx(2 * kPi).epsilon(kArcLength));
  for (double k : c.curvature) CHECK(k == Approx(1.0).epsilon(kCurvatureRoundoff));  // curvature 1/l1
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
  CHECK((k_i - b0).norm() == Approx(10.0 / 3 * std::sqrt(6.0)).margin(kPoseRoundoff));
  CHECK((k_ii - b0).norm() - (k_i - b0).norm() == Approx(std::sqrt(2.0) / 3 * (5 * std::sqrt(11.0) - 9 * std::sqrt(3.0))).margin(kPoseRoundoff));
  // six-point contact: the curvature vanishes at K_I, and it is the flattest sample
  CHECK(std::abs(c.curvature[360]) < 1e-12);
  CHECK(FlattestSample(c) == 360);
}

TEST_CASE("seed 003 reading example: Q_G = 0.005", "[curve]") {
  const StraightStretch s = LongestStraightStretch(Seed003(), {2, 2}, 0.005, kPi, kPi, DegToRad(0.02));
  REQUIRE(s.ok());
  // the document's figures, read off a chart: phi_G = 163.3 deg, phi_A = 98.3 deg (0.1 deg), L/l1 = 3.91
  CHECK(RadToDeg(s.phi_g) == Approx(163.3).margin(kChartDeg));
  CHECK(RadToDeg(s.phi_a) == Approx(98.3).margin(kChartDeg));
  CHECK(s.length == Approx(3.91).margin(kChartLength));
  CHECK(s.qg <= 0.005);
  // the band of the reported stretch, measured on its own, is the same
  const StraightStretch band = StretchBand(Seed003(), {2, 2}, kPi, s.phi_a, s.phi_e, DegToRad(0.02));
  CHECK(band.band == Approx(s.band).margin(kSameBand));
  // a tighter tolerance gives a shorter stretch
  const StraightStretch tight = LongestStraightStretch(Seed003(), {2, 2}, 0.001, kPi, kPi, DegToRad(0.1));
  REQUIRE(tight.ok());
  CHECK(tight.phi_g < s.phi_g);
}

// Issue 22 item 5: the stretch is reported in seed 003's convention (phi_I = 180 deg, phi_A =
// 98.3 deg, phi_G = 163.3 deg, so phi_E = 261.6 deg), whatever reference the search starts
// from: the default (least curvature, found at -180 deg) and +-180 or 540 deg are one point of
// the crank circle, so they must give the same numbers.
TEST_CASE("a stretch is reported with phi_I and phi_A in [0, 360) and phi_E = phi_A + phi_G, whatever --at", "[curve]") {
  // the same stretch sampled from a reference a whole turn away: equal to roundoff of the sweep
  constexpr double kSameStretch = 1e-9;
  const Mechanism m = Seed003();
  const StraightStretch at_180 = LongestStraightStretch(m, {2, 2}, 0.005, kPi, kPi, DegToRad(0.02));
  REQUIRE(at_180.ok());
  CHECK(RadToDeg(at_180.reference) == Approx(180).margin(kReferenceDeg));
  CHECK(RadToDeg(at_180.phi_a) == Approx(98.3).margin(kChartDeg));
  CHECK(RadToDeg(at_180.phi_e) == Approx(98.3 + 163.3).margin(kChartSumDeg));
  for (const std::optional<double> reference : {std::optional<double>(), std::optional<double>(-kPi), std::optional<double>(3 * kPi)}) {
    const StraightStretch s = LongestStraightStretch(m, {2, 2}, 0.005, reference, kPi, DegToRad(0.02));
    INFO("reference " << (reference ? RadToDeg(*reference) : -1.0) << " deg: " << s.Brief());
    REQUIRE(s.ok());
    CHECK(s.reference == Approx(at_180.reference).margin(kSameStretch));
    CHECK(s.phi_a == Approx(at_180.phi_a).margin(kSameStretch));
    CHECK(s.phi_e == Approx(at_180.phi_e).margin(kSameStretch));
    CHECK(s.phi_g == Approx(at_180.phi_g).margin(kSameStretch));
    CHECK(s.length == Approx(at_180.length).margin(kSameStretch));
    CHECK(s.band == Approx(at_180.band).margin(kSameStretch));
  }
}

TEST_CASE("a stretch through input 0 ends beyond 360 deg; its band does not depend on how it is written", "[curve]") {
  constexpr double kSameStretch = 1e-9;  // as above: the same points, sampled a turn apart
  const Mechanism m = Seed003();
  // K_II at phi = 0 (seed 003): the stretch -20..20 deg around it, written three ways
  const StraightStretch around_0 = StretchBand(m, {2, 2}, 0, DegToRad(-20), DegToRad(20), DegToRad(0.05));
  REQUIRE(around_0.ok());
  CHECK(RadToDeg(around_0.reference) == Approx(0).margin(kReferenceDeg));
  CHECK(RadToDeg(around_0.phi_a) == Approx(340).margin(kSameStretch));
  CHECK(RadToDeg(around_0.phi_e) == Approx(380).margin(kSameStretch));
  CHECK(RadToDeg(around_0.phi_g) == Approx(40).margin(kSameStretch));
  const StraightStretch shifted = StretchBand(m, {2, 2}, 2 * kPi, DegToRad(340), DegToRad(380), DegToRad(0.05));
  const StraightStretch turned = StretchBand(m, {2, 2}, 0, DegToRad(340), DegToRad(380), DegToRad(0.05));
  for (const StraightStretch* s : {&shifted, &turned}) {
    REQUIRE(s->ok());
    CHECK(s->reference == Approx(around_0.reference).margin(kSameStretch));
    CHECK(s->phi_a == Approx(around_0.phi_a).margin(kSameStretch));
    CHECK(s->phi_e == Approx(around_0.phi_e).margin(kSameStretch));
    CHECK(s->band == Approx(around_0.band).margin(kSameStretch));
    CHECK(s->length == Approx(around_0.length).margin(kSameStretch));
  }
  // K_II is the point farthest from B0 on the symmetry axis (seed 003): the tangent there is
  // normal to B0 K_II, so the reference point's position is the document's
  CHECK((around_0.reference_point - Eigen::Vector2d(4, 0)).norm() ==
        Approx(10.0 / 3 * std::sqrt(6.0) + std::sqrt(2.0) / 3 * (5 * std::sqrt(11.0) - 9 * std::sqrt(3.0))).margin(kPoseRoundoff));
  CHECK(std::abs(around_0.tangent.dot((around_0.reference_point - Eigen::Vector2d(4, 0)).normalized())) < 1e-9);
}

TEST_CASE("a stretch must end after its start, within a turn", "[curve]") {
  std::string why;
  CHECK(StretchIsValid(DegToRad(300), DegToRad(420), &why));
  CHECK(why.empty());
  CHECK_FALSE(StretchIsValid(DegToRad(20), DegToRad(-20), &why));
  CHECK_THAT(why, Catch::Contains("end after its start"));
  CHECK_FALSE(StretchIsValid(DegToRad(0), DegToRad(361), &why));
  CHECK_THAT(why, Catch::Contains("more than one turn"));
  // reversed ends are refused, not measured over an empty range
  const StraightStretch reversed = StretchBand(Seed003(), {2, 2}, kPi, DegToRad(261.66), DegToRad(98.34), DegToRad(0.05));
  CHECK(reversed.status == AnalysisStatus::kFailed);
  CHECK_THAT(reversed.message, Catch::Contains("end after its start"));
}

}  // namespace koppel::coupler_curve_test
