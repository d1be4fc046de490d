// FindGuideTravels (tools/api/src/guide_travel.cpp): each slide's travel refined to its extremes,
// not the samples'. References: seed 000's slider-crank (tests/support/closed_forms: s at the
// dead centres SliderCrankPhiA / SliderCrankPhiI, and s = sqrt((l2 -+ l1)^2 - e^2) there by
// Pythagoras), seed 001's proportional linkage (ProportionalS; its slot through B0 and A, block 4
// at D on x = l6 - h: |B0 A| = sqrt(l1^2 + l6^2 - 2 l1 l6 cos phi), |B0 D| = sqrt(h^2 + s^2)).
#include "koppel/api/guide_travel.hpp"

#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

using namespace koppel;
using Catch::Matchers::WithinAbs;

namespace guide_travel_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

// [length, L ~ 1] the extreme's input is refined to 1e-12 rad, where s' = 0: its value is then
// exact to s'' (1e-12)^2; what is left is the pose's own convergence and roundoff
constexpr double kRefined = 1e-12;
// [length] the best 1-degree sample falls short of a dead centre by s'' dphi^2 / 2, dphi up to
// half a degree: more than this unless a sample happens to lie on it (checked, so that the
// tests below can tell a refined travel from a sampled one)
constexpr double kSampledShortfall = 1e-7;

const GuideTravel& Of(const std::vector<GuideTravel>& travels, const std::string& joint) {
  for (const GuideTravel& t : travels)
    if (t.name == joint) return t;
  FAIL("no travel of " << joint);
  throw;
}

// The greatest closed-form value over the 1-degree samples of a turn.
template <class F>
double SampledMaximum(F s) {
  double best = -1e300;
  for (int deg = 0; deg < 360; ++deg) best = std::max(best, s(DegToRad(deg)));
  return best;
}

}  // namespace

TEST_CASE("guide travel: the slider-crank's slot from dead centre to dead centre, closed form", "[api][guide_travel]") {
  const double l1 = 1, l2 = 2.6, e = 0.8;
  const std::vector<GuideTravel> travels = FindGuideTravels(test::SliderCrank(l1, l2, e), 0, 2 * kPi, DegToRad(1));
  REQUIRE(travels.size() == 1);
  const GuideTravel& s = travels[0];
  CHECK(s.name == "S");
  REQUIRE(s.status == AnalysisStatus::kComplete);
  const double s_a = test::SliderCrank(l1, l2, e, test::SliderCrankPhiA(l1, l2, e)).s;
  const double s_i = test::SliderCrank(l1, l2, e, test::SliderCrankPhiI(l1, l2, e)).s;
  // the same numbers by Pythagoras: at a dead centre A0, A, B line up, |A0 B| = l2 +- l1, A0 at height e
  CHECK_THAT(s_a, WithinAbs(std::sqrt((l2 + l1) * (l2 + l1) - e * e), kRefined));
  CHECK_THAT(s_i, WithinAbs(std::sqrt((l2 - l1) * (l2 - l1) - e * e), kRefined));
  CHECK_THAT(s.low, WithinAbs(s_i, kRefined));
  CHECK_THAT(s.high, WithinAbs(s_a, kRefined));
  CHECK_THAT(s.high - s.low, WithinAbs(s_a - s_i, kRefined));
  // the samples alone would fall short: the check above tells the two apart
  const double sampled = SampledMaximum([&](double phi) { return test::SliderCrank(l1, l2, e, phi).s; });
  CHECK(s_a - sampled > kSampledShortfall);
}

TEST_CASE("guide travel: a range that is no whole turn ends at its ends", "[api][guide_travel]") {
  // s rises from phi = 0 to the extended dead centre (103 deg): over 0 .. 60.5 deg its extremes
  // are the range's ends, the last one not on a sample
  const double l1 = 1, l2 = 2.6, e = 0.8;
  const std::vector<GuideTravel> travels = FindGuideTravels(test::SliderCrank(l1, l2, e), 0, DegToRad(60.5), DegToRad(1));
  REQUIRE(travels.size() == 1);
  REQUIRE(travels[0].status == AnalysisStatus::kComplete);
  CHECK_THAT(travels[0].low, WithinAbs(test::SliderCrank(l1, l2, e, 0).s, kRefined));
  CHECK_THAT(travels[0].high, WithinAbs(test::SliderCrank(l1, l2, e, DegToRad(60.5)).s, kRefined));
}

TEST_CASE("guide travel: blocks sliding on a turning slot, and on the frame, seed 001", "[api][guide_travel]") {
  // lambda = 0.4: the slot's steepest at cos phi = lambda (66.4 deg), off the 1-degree samples
  const double l6 = 1, l1 = 0.4, h = 1.83;
  const std::vector<GuideTravel> travels = FindGuideTravels(test::ProportionalLinkage(l6, l1, h), 0, 2 * kPi, DegToRad(1));
  REQUIRE(travels.size() == 3);
  for (const GuideTravel& t : travels) REQUIRE(t.status == AnalysisStatus::kComplete);
  // slider 5 on the frame: s = c sin phi / (1 - lambda cos phi) is extreme where cos phi = lambda
  const double phi_star = std::acos(l1 / l6);
  const double s_max = test::ProportionalS(l6, l1, h, phi_star);
  CHECK_THAT(Of(travels, "S50").high, WithinAbs(s_max, kRefined));
  CHECK_THAT(Of(travels, "S50").low, WithinAbs(test::ProportionalS(l6, l1, h, -phi_star), kRefined));
  CHECK(s_max - SampledMaximum([&](double phi) { return test::ProportionalS(l6, l1, h, phi); }) > kSampledShortfall);
  // block 4 in the turning slot, from B0 (the slot's direction, and so the sign, is the
  // assembly's): |B0 D| from h (slot level) to sqrt(h^2 + s_max^2) (slot steepest)
  const GuideTravel& s34 = Of(travels, "S34");
  CHECK(s34.low * s34.high > 0);
  CHECK_THAT(std::min(std::abs(s34.low), std::abs(s34.high)), WithinAbs(h, kRefined));
  CHECK_THAT(std::max(std::abs(s34.low), std::abs(s34.high)), WithinAbs(std::hypot(h, s_max), kRefined));
  // block 2 at A in the same slot: |B0 A| from l6 - l1 to l6 + l1
  const GuideTravel& s23 = Of(travels, "S23");
  CHECK(s23.low * s23.high > 0);
  CHECK_THAT(std::min(std::abs(s23.low), std::abs(s23.high)), WithinAbs(l6 - l1, kRefined));
  CHECK_THAT(std::max(std::abs(s23.low), std::abs(s23.high)), WithinAbs(l6 + l1, kRefined));
}

TEST_CASE("guide travel: none without a slide, an unsweepable range refused", "[api][guide_travel]") {
  CHECK(FindGuideTravels(test::PlainFourBar(1, 3.5, 3, 4, 0, {2, 3}), 0, 2 * kPi, DegToRad(1)).empty());
  CHECK_THROWS_AS(FindGuideTravels(test::SliderCrank(1, 2.6, 0.8), 0, 1, 0), std::invalid_argument);
  CHECK_THROWS_AS(FindGuideTravels(test::SliderCrank(1, 2.6, 0.8), 0, std::nan(""), 0.1), std::invalid_argument);
}

}  // namespace guide_travel_test
