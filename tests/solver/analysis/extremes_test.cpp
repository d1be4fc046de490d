// The extremes of an output (extremes.hpp): a transmission angle's mu_min and mu_max at
// stationary points, at its fold at 90 deg, and at the ends of part of a turn, against the
// closed forms of tests/support/closed_forms.hpp (law of cosines; seed 000).
#include "koppel/analysis/extremes.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/build.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

namespace koppel::extremes_test {
namespace {

// [deg] against the document's value printed to 10 decimals: its last digit
constexpr double kDocumentDeg = 1e-9;
// [rad] an extreme at the range's end is at the requested input itself: an ulp
constexpr double kRangeEnd = 1e-15;
// [rad] mu of an assembled pose against the closed form: rounding of a converged pose
constexpr double kSweptMu = 1e-12;

// Stationary points refined to 1e-12 in the input; folds to 1e-12 by Newton on the folded angle.
constexpr double kRefined = 1e-11;

// The crank-rocker a, b, c, d (B above the frame line, assembled from the closed form); outputs
// K, psi, phi, mu (mu is output 3).
Mechanism CrankRocker(double a, double b, double c, double d) {
  Mechanism m = test::FourBar(a, b, c, d, 1.0, 0.0, 1);
  m.hint.points.clear();
  HintPoint(m, "coupler", "B", test::FourBarRocker(a, b, c, d, 0.0, 1)->b);
  return m;
}

SweepOptions Range(double from_deg, double to_deg, double step_deg) {
  SweepOptions range;
  range.from = DegToRad(from_deg);
  range.to = DegToRad(to_deg);
  range.step = DegToRad(step_deg);
  return range;
}

}  // namespace

// issue 22 item 1's repro: mu_min = 33.2061837935 deg at phi = 0 (it was reported as 78.79 at 180)
TEST_CASE("crank-rocker mu_min at phi = 0 and mu_max at 180 deg over a whole turn", "[extremes]") {
  const double a = 0.65, b = 3.2, c = 1.685, d = 2.664;
  const OutputExtremes r = FindOutputExtremes(CrankRocker(a, b, c, d), 3, 0, Range(0, 360, 1));
  REQUIRE(r.status == AnalysisStatus::kComplete);
  CHECK(std::abs(r.minimum.input) < kRefined);
  CHECK(r.minimum.value == Approx(test::CrankRockerMu(a, b, c, d, 0)).margin(kRefined));
  CHECK(RadToDeg(r.minimum.value) == Approx(33.2061837935).margin(kDocumentDeg));
  CHECK(r.minimum.kind == ExtremeKind::kStationary);
  CHECK(std::abs(r.maximum.input - kPi) < kRefined);
  CHECK(r.maximum.value == Approx(test::CrankRockerMu(a, b, c, d, kPi)).margin(kRefined));
  CHECK(r.maximum.kind == ExtremeKind::kStationary);
}

TEST_CASE("mu_max at the fold where the coupler-rocker angle passes 90 deg", "[extremes]") {
  // the catalog's crank-rocker 1 : 3.5 : 3 : 4: gamma runs from 54.3 to 100.3 deg
  const Mechanism m = CrankRocker(1, 3.5, 3, 4);
  const OutputExtremes r = FindOutputExtremes(m, 3, 0, Range(0, 360, 1));
  REQUIRE(r.status == AnalysisStatus::kComplete);
  CHECK(r.maximum.kind == ExtremeKind::kFold);
  CHECK(r.maximum.value == Approx(kPi / 2).margin(kRefined));
  // the first of the two folds (cos phi = (a^2 + d^2 - b^2 - c^2)/(2ad), phi and 360 - phi)
  CHECK(std::abs(r.maximum.input - test::CrankRockerMuFolds(1, 3.5, 3, 4)[0]) < kRefined);
  CHECK(r.minimum.kind == ExtremeKind::kStationary);
  CHECK(std::abs(r.minimum.input) < kRefined);
}

TEST_CASE("over part of a turn an extreme may be an end of the range", "[extremes]") {
  // seed 000, e = 0.8: mu rises from phi = 30 deg to its fold at 143.13 deg and falls to 200 deg
  const double l1 = 1, l2 = 2.6, e = 0.8;
  const OutputExtremes r = FindOutputExtremes(test::SliderCrank(l1, l2, e), 1, 0, Range(30, 200, 1));
  REQUIRE(r.status == AnalysisStatus::kComplete);
  CHECK(r.minimum.kind == ExtremeKind::kRangeEnd);
  CHECK(r.minimum.input == Approx(DegToRad(30)).margin(kRangeEnd));
  CHECK(r.minimum.value == Approx(test::SliderCrank(l1, l2, e, DegToRad(30)).mu).margin(kSweptMu));
  CHECK(r.maximum.kind == ExtremeKind::kFold);
  CHECK(std::abs(r.maximum.input - test::SliderCrankMuFolds(l1, e)[0]) < kRefined);
}

TEST_CASE("equal extremes: the one at the smaller input", "[extremes]") {
  // seed 000, e = 0: mu_min = arccos(l1/l2) at both 0 and 180 deg
  const OutputExtremes r = FindOutputExtremes(test::SliderCrank(1, 2.6, 0), 1, 0, Range(0, 360, 1));
  REQUIRE(r.status == AnalysisStatus::kComplete);
  CHECK(r.minimum.value == Approx(std::acos(1 / 2.6)).margin(kRefined));
  CHECK(std::abs(r.minimum.input) < kRefined);
  // the folds at 90 and 270 deg: 90
  CHECK(std::abs(r.maximum.input - kPi / 2) < kRefined);
}

TEST_CASE("an output that turns with the drive has no extremes over whole turns", "[extremes]") {
  // output 2 of the four-bar is the crank's own joint angle: y' = 1 everywhere
  const OutputExtremes r = FindOutputExtremes(CrankRocker(1, 3.5, 3, 4), 2, 0, Range(0, 360, 5));
  CHECK(r.status == AnalysisStatus::kFailed);
  CHECK_THAT(r.message, Catch::Contains("turns with the drive"));
}

}  // namespace koppel::extremes_test

namespace koppel::extremes_test {

// A parallelogram's coupler only translates: its angle is constant, with no isolated extreme.
TEST_CASE("a constant output has itself as its extremes", "[extremes]") {
  const Mechanism m = test::PlainFourBar(1, 3, 1, 3, kPi / 2, {3, 1});  // B above B0: the parallelogram
  // output 1: the coupler's angle theta, 0 throughout (A -> B parallel to A0 -> B0)
  const OutputExtremes r = FindOutputExtremes(m, 1, 0, Range(10, 170, 5));
  REQUIRE(r.status == AnalysisStatus::kComplete);
  CHECK(r.minimum.kind == ExtremeKind::kConstant);
  CHECK(r.maximum.kind == ExtremeKind::kConstant);
  CHECK(r.minimum.value == Approx(0).margin(kSweptMu));
}

}  // namespace koppel::extremes_test

#include "extremes_of_search.hpp"

namespace koppel::extremes_test {

// The rule itself on a search made by hand: a sample beyond every candidate means an extreme was
// missed between two samples (no sign change of y' showed it): no number rather than a wrong one.
TEST_CASE("extremes: a sample beyond the candidates fails the search", "[extremes]") {
  const Mechanism m = test::SliderCrank(1, 2.6, 0.8);  // output 1: mu, an angle
  StationarySearch s;
  s.column = 0;
  s.sweep.status = SweepStatus::kComplete;
  s.sweep.inputs = {0.0, 0.1, 0.2};
  s.sweep.singular = {0, 0, 0};
  s.sweep.valid_order = {2, 2, 2};
  s.sweep.outputs = Table::Zero(3, 3);
  s.sweep.outputs(0, 0) = 0.5;
  s.sweep.outputs(1, 0) = 0.9;  // above both ends, and no stationary point found
  s.sweep.outputs(2, 0) = 0.6;
  s.ends = {0, 2};
  const OutputExtremes missed = ExtremesOf(m, 1, s);
  CHECK(missed.status == AnalysisStatus::kFailed);
  CHECK_THAT(missed.message, Catch::Contains("lies beyond the extremes found"));
  // with the maximum found between them the same samples are consistent
  StationaryPoint top;
  top.status = AnalysisStatus::kComplete;
  top.input = 0.09;
  top.value = 0.95;
  top.second = -1;
  s.points = {top};
  const OutputExtremes found = ExtremesOf(m, 1, s);
  REQUIRE(found.status == AnalysisStatus::kComplete);
  CHECK(found.maximum.kind == ExtremeKind::kStationary);
  CHECK(found.maximum.value == 0.95);
  CHECK(found.minimum.kind == ExtremeKind::kRangeEnd);
  CHECK(found.minimum.input == 0.0);
}

}  // namespace koppel::extremes_test

namespace koppel::extremes_test {

// A range from limit point to limit point (a triple-rocker swung over all it can): the samples on
// the limits have no y' (infinite there, stored as 0), so no sign change may be bracketed with
// them. The extreme search used to fail there ("neither a stationary point nor a fold"), and the
// DXF slots and GIF frames of hand-pump with it. Reference: psi of the closed form, sampled 2e5
// times over the range and at its ends.
TEST_CASE("extremes over a range that ends on two limit points", "[extremes]") {
  const double a = 2, b = 3, c = 2.5, d = 4;
  const std::vector<double> limits = test::FourBarLimits(a, b, c, d);
  double limit = 0;
  for (double l : limits) limit = std::max(limit, std::abs(std::remainder(l, 2 * kPi)));
  const auto start = test::FourBarRocker(a, b, c, d, 1.0, 1);
  REQUIRE(start);
  const Mechanism m = test::PlainFourBar(a, b, c, d, 1.0, start->b);
  SweepOptions range;
  range.from = -limit;
  range.to = limit;
  range.step = DegToRad(1);
  const OutputExtremes e = FindOutputExtremes(m, 0, 0, range);
  INFO(e.Brief());
  REQUIRE(Usable(e.status));
  double low = 1e300, high = -1e300;
  for (int i = 0; i <= 200000; ++i) {
    const double phi = -limit + 2 * limit * i / 200000.0;
    const auto rocker = test::FourBarRocker(a, b, c, d, std::clamp(phi, -limit, limit), 1);
    if (!rocker) continue;  // a rounding beyond the limit
    const double psi = rocker->psi < 0 ? rocker->psi + 2 * kPi : rocker->psi;  // the branch runs through pi
    low = std::min(low, psi);
    high = std::max(high, psi);
  }
  // the sampled reference is within (2 limit / 2e5)^2 psi'' / 8 of the true extreme, and the
  // closed form loses half its digits next to the limits (sqrt of a discriminant near 0)
  CHECK(e.minimum.value == Approx(low).margin(1e-7));
  CHECK(e.maximum.value == Approx(high).margin(1e-7));
}

}  // namespace koppel::extremes_test
