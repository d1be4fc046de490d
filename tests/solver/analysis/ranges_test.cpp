// Drivable ranges against closed forms: full turns with their period (a crank-rocker 360 deg,
// the kite 720 deg), limits by the law of cosines (triple-rocker, rocker drive), a slide drive
// between the slider's dead centres, branch points ending a range only when asked, and every
// assembly branch found from random guesses.
#include "koppel/analysis/ranges.hpp"

#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::ranges_test {
namespace {

// [rad] a branch's period is a whole number of turns, summed from the sweep's steps: rounding only
constexpr double kPeriod = 1e-12;

// limits are located to 1e-11 rad (continuation.hpp); the law of cosines is exact to roundoff
constexpr double kLimit = 1e-9;

}  // namespace

TEST_CASE("a crank-rocker turns fully on both of its assembly branches", "[ranges]") {
  const Mechanism m = test::PlainFourBar(1, 3.5, 3, 4, DegToRad(90), test::FourBarRocker(1, 3.5, 3, 4, DegToRad(90), 1)->b);
  RangeOptions o;
  o.all_branches = true;
  const RangeReport r = DrivableRanges(m, o);
  REQUIRE(r.status == RangeStatus::kDone);
  REQUIRE(r.branches.size() == 2);  // B above and below A B0: two circuits
  for (const BranchRange& b : r.branches) {
    CHECK(b.from_kind == RangeEnd::kFullTurn);
    CHECK(b.to_kind == RangeEnd::kFullTurn);
    CHECK(b.period == Approx(2 * kPi).margin(kPeriod));
    CHECK(b.singular_points.empty());
  }
  CHECK(r.branches[0].branch == 0);
}

TEST_CASE("a triple-rocker swings between the limits the law of cosines gives, on both branches", "[ranges]") {
  // 2, 3, 2.5, 4: s + l = 6 > p + q = 5.5; the crank stops where |A B0| = b + c = 5.5 (|A B0|
  // never reaches |b - c| = 0.5): cos phi = (a^2 + d^2 - 5.5^2) / (2 a d)
  const double limit = std::acos((4.0 + 16.0 - 30.25) / 16.0);
  const Mechanism m = test::PlainFourBar(2, 3, 2.5, 4, DegToRad(60), {3.5, 2.4});
  RangeOptions o;
  o.all_branches = true;
  const RangeReport r = DrivableRanges(m, o);
  REQUIRE(r.branches.size() == 2);
  for (const BranchRange& b : r.branches) {
    CHECK(b.from_kind == RangeEnd::kLimit);
    CHECK(b.to_kind == RangeEnd::kLimit);
    CHECK(std::abs(b.from + limit) < kLimit);
    CHECK(std::abs(b.to - limit) < kLimit);
    CHECK(b.singular_points.size() == 2);
  }
}

TEST_CASE("a crank-rocker driven at its rocker swings between its dead centres", "[ranges]") {
  // crank 1, coupler 3.5, rocker 3, frame 4, driven at B0: the rocker stops where A0 B = 4.5
  // (crank and coupler stretched) and A0 B = 2.5 (folded); rocker angle from the law of cosines
  auto rocker = [](double a0b) { return kPi - std::acos((16.0 + 9.0 - a0b * a0b) / 24.0); };
  const double psi = DegToRad(120);  // inside 101.4 .. 141.4 deg
  const Eigen::Vector2d b(4 + 3 * std::cos(psi), 3 * std::sin(psi));
  const Mechanism m = test::PlainFourBar(1, 3.5, 3, 4, psi, b, true);
  const RangeReport r = DrivableRanges(m);
  REQUIRE(r.status == RangeStatus::kDone);
  REQUIRE(r.branches.size() == 1);
  CHECK(std::abs(r.branches[0].from - rocker(4.5)) < kLimit);
  CHECK(std::abs(r.branches[0].to - rocker(2.5)) < kLimit);
}

TEST_CASE("the kite comes round after 720 deg; the parallelogram stops at its change points when asked", "[ranges]") {
  const RangeReport kite = DrivableRanges(test::PlainFourBar(1, 2.5, 2.5, 1, DegToRad(90), {2, 2}));
  REQUIRE(kite.branches.size() == 1);
  CHECK(kite.branches[0].to_kind == RangeEnd::kFullTurn);
  CHECK(kite.branches[0].period == Approx(4 * kPi).margin(kPeriod));

  const Mechanism parallelogram = test::PlainFourBar(1, 3, 1, 3, DegToRad(90), {3, 1});
  const RangeReport turning = DrivableRanges(parallelogram);
  CHECK(turning.branches[0].period == Approx(2 * kPi).margin(kPeriod));
  RangeOptions stop;
  stop.continuation.at_branch_point = BranchPointAction::kStop;
  const RangeReport stopped = DrivableRanges(parallelogram, stop);
  REQUIRE(stopped.branches.size() == 1);
  const BranchRange& b = stopped.branches[0];
  CHECK(b.from_kind == RangeEnd::kBranchPoint);
  CHECK(b.to_kind == RangeEnd::kBranchPoint);
  CHECK(std::abs(b.from) < 1e-9);
  CHECK(std::abs(b.to - kPi) < 1e-9);
}

TEST_CASE("a slide drive moves between the slider's dead centres", "[ranges]") {
  // seed 000 slider-crank driven at its slider S: s runs from the folded dead centre
  // sqrt((l2 - l1)^2 - e^2) to the extended one sqrt((l1 + l2)^2 - e^2) (B right of A0)
  const double l1 = 1, l2 = 2.6, e = 0.8;
  Mechanism m = test::SliderCrank(l1, l2, e);
  m.drive.joint = 3;
  m.hint.input = 2.5;
  m.hint.points[0].global = {2.5, 0};
  m.hint.points.push_back({{1, 1}, {0, -e - l1}});  // crank.A below A0
  const RangeReport r = DrivableRanges(m);
  REQUIRE(r.status == RangeStatus::kDone);
  REQUIRE(r.branches.size() == 1);
  CHECK(r.branches[0].from_kind == RangeEnd::kLimit);
  CHECK(r.branches[0].to_kind == RangeEnd::kLimit);
  CHECK(std::abs(r.branches[0].from - std::sqrt(std::pow(l2 - l1, 2) - e * e)) < 1e-9);
  CHECK(std::abs(r.branches[0].to - std::sqrt(std::pow(l1 + l2, 2) - e * e)) < 1e-9);
}

TEST_CASE("range options validate themselves", "[ranges]") {
  RangeOptions o;
  std::string why;
  CHECK(o.IsValid(&why));
  o.max_turns = 0;
  CHECK_FALSE(o.IsValid(&why));
  const RangeReport r = DrivableRanges(test::PlainFourBar(1, 3, 1, 3, 1.0, {3, 1}), o);
  CHECK(r.status == RangeStatus::kInvalidOptions);
}

}  // namespace koppel::ranges_test
