// One cycle of the drive: its range, the frames' inputs, the traced curves. References: the
// four-bar's limit positions by the law of cosines (tests/support/closed_forms FourBarLimits),
// the circle-intersection coupler point of seed 003, seed 000's slider at its dead centres, and the definition of a cycle (a full turn
// in equal steps; a rocker's range there and back).
#include "koppel/plot/cycle.hpp"

#include "tools/plot/cycle_fixtures.hpp"

#include "koppel/api/model.hpp"
#include "koppel/core/angles.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

namespace koppel::cycle_test {
namespace {

// [rad] inputs of a cycle are from + i step on angles below 2 pi: rounding only
constexpr double kStepRoundoff = 1e-12;
// [rad] the way back mirrors the way out on inputs of 1..2: the same arithmetic, an ulp at most
constexpr double kMirrored = 1e-15;

using Catch::Matchers::WithinAbs;

// The solver converges to 1e-12 of the length scale.
constexpr double kTolerance = 1e-9;
// [length] a travel's ends are its extremes refined to 1e-12 in the input, where s' = 0
constexpr double kRefined = 1e-12;
// A limit point is located by the range analysis to about 1e-9 rad (its bisection's resolution).
constexpr double kLimitTolerance = 1e-7;

SweepOptions FileSweep(double from_deg, double to_deg) {
  SweepOptions o;
  o.from = DegToRad(from_deg);
  o.to = DegToRad(to_deg);
  return o;
}


}  // namespace

TEST_CASE("cycle range: a crank turns fully, a rocker swings between its limits", "[plot][cycle]") {
  const Expected<plot::CycleRange> turn = plot::CycleRangeOf(test::MzcCrankRocker(), FileSweep(0, 360));
  REQUIRE(turn);
  CHECK(turn->full_turn);
  CHECK(turn->from == 0);
  CHECK_THAT(turn->to, WithinAbs(2 * kPi, kStepRoundoff));
  CHECK(turn->note.empty());

  const Expected<plot::CycleRange> swing = plot::CycleRangeOf(test::DoubleRocker(), FileSweep(52, 95));
  REQUIRE(swing);
  CHECK_FALSE(swing->full_turn);
  std::vector<double> limits = test::FourBarLimits(3, 1, 3.5, 3);
  std::sort(limits.begin(), limits.end());
  // the branch assembled at 70 deg lies between the limits either side of it
  const auto above = std::upper_bound(limits.begin(), limits.end(), DegToRad(70));
  REQUIRE(above != limits.begin());
  REQUIRE(above != limits.end());
  CHECK_THAT(swing->from, WithinAbs(*(above - 1), kLimitTolerance));
  CHECK_THAT(swing->to, WithinAbs(*above, kLimitTolerance));
}

TEST_CASE("cycle inputs: a turn in equal steps, a swing there and back", "[plot][cycle]") {
  const plot::CycleRange turn{0, 2 * kPi, true, ""};
  const std::vector<double> t = plot::CycleInputs(turn, 36);
  REQUIRE(t.size() == 36);
  for (int i = 0; i < 36; ++i) CHECK_THAT(t[i], WithinAbs(DegToRad(10.0 * i), kStepRoundoff));  // never 360 again
  CHECK(plot::TracedUpTo(turn, 36, 20) == t[20]);

  const plot::CycleRange swing{1, 2, false, ""};
  const std::vector<double> s = plot::CycleInputs(swing, 12);
  REQUIRE(s.size() == 12);
  CHECK(s[0] == 1);
  CHECK(s[6] == 2);
  for (int i = 1; i < 12; ++i) CHECK_THAT(s[i], WithinAbs(s[12 - i], kMirrored));  // the same way back
  for (int i = 1; i <= 6; ++i) CHECK(s[i] > s[i - 1]);
  // the curves grow on the way there and stay whole on the way back
  CHECK(plot::TracedUpTo(swing, 12, 3) == s[3]);
  CHECK(plot::TracedUpTo(swing, 12, 9) == 2);
  CHECK(plot::CycleInputs(swing, 1) == std::vector<double>{1});
}

TEST_CASE("cycle samples: the coupler curve of a full turn, closed, on the closed form", "[plot][cycle]") {
  const Mechanism m = test::MzcCrankRocker();
  const plot::CycleRange turn{0, 2 * kPi, true, ""};
  const Expected<plot::CycleSamples> samples = plot::SampleCycle(m, turn, plot::PointOutputs(m));
  REQUIRE(samples);
  REQUIRE(samples->curves.size() == 1);
  const plot::TracedCurve& k = samples->curves[0];
  CHECK(k.name == "K");
  CHECK(k.closed);
  REQUIRE(k.runs.size() == 1);
  CHECK(k.runs[0].size() == plot::kCycleSegments);  // the repeated point at 360 deg left out
  for (size_t i = 0; i < k.runs[0].size(); ++i) {
    const double phi = k.inputs[0][i];
    CHECK((k.runs[0][i] - test::MzcK(phi)).norm() < kTolerance);
  }
  // cut at an input: the points up to it
  const auto cut = k.UpTo(DegToRad(90.5));
  REQUIRE(cut.size() == 1);
  CHECK(cut[0].size() == 91);
  CHECK(k.UpTo(-1).empty());
}

TEST_CASE("cycle samples: a rocker's curve is open", "[plot][cycle]") {
  const Mechanism m = test::DoubleRocker();
  const Expected<plot::CycleRange> range = plot::CycleRangeOf(m, FileSweep(52, 95));
  REQUIRE(range);
  PointRef b{m.FindLink("coupler"), m.links[m.FindLink("coupler")].FindPoint("B")};
  const Expected<plot::CycleSamples> samples = plot::SampleCycle(m, *range, {{b, "B"}});
  REQUIRE(samples);
  CHECK_FALSE(samples->curves[0].closed);
  CHECK(samples->curves[0].runs[0].size() == plot::kCycleSegments + 1);
}

TEST_CASE("cycle samples: a slide's travel from dead centre to dead centre, not from sample to sample", "[plot][cycle]") {
  // seed 000 (tests/support/closed_forms): s at the dead centres, 102.8 and 300.1 deg, which the
  // 1-degree samples miss by up to 1.2e-5
  const double l1 = 1, l2 = 2.6, e = 0.8;
  const Mechanism m = test::SliderCrank(l1, l2, e);
  const Expected<plot::CycleSamples> samples = plot::SampleCycle(m, plot::CycleRange{0, 2 * kPi, true, ""}, {});
  REQUIRE(samples);
  const int s = m.FindJoint("S");
  REQUIRE(samples->travel.size() == m.joints.size());
  CHECK_THAT(samples->travel[s].first, WithinAbs(test::SliderCrank(l1, l2, e, test::SliderCrankPhiI(l1, l2, e)).s, kRefined));
  CHECK_THAT(samples->travel[s].second, WithinAbs(test::SliderCrank(l1, l2, e, test::SliderCrankPhiA(l1, l2, e)).s, kRefined));
  for (size_t j = 0; j < m.joints.size(); ++j)
    if (static_cast<int>(j) != s) CHECK(samples->travel[j] == std::pair<double, double>{0.0, 0.0});
}

TEST_CASE("cycle options of a model: its point outputs, the default sizes, the file's sweep in radians", "[plot][cycle]") {
  // the file: sweep 0 .. 360 deg; one point output K
  const Model model = Model::Load(test::CatalogEntryPath("mzc-crank-rocker"));
  const plot::CycleOptions options = plot::CycleOptionsOf(model);
  CHECK_THAT(options.sweep.from, WithinAbs(DegToRad(model.sweep_from()), kStepRoundoff));
  CHECK_THAT(options.sweep.to, WithinAbs(DegToRad(model.sweep_to()), kStepRoundoff));
  CHECK_THAT(options.sweep.to - options.sweep.from, WithinAbs(2 * kPi, kStepRoundoff));
  REQUIRE(options.traced.size() == plot::PointOutputs(model.mechanism()).size());
  REQUIRE(options.traced.size() == 1);
  CHECK(options.traced[0].name == "K");
  CHECK(options.sizes.plate_width == plot::DefaultPartSizes(model.mechanism()).plate_width);
  std::string why;
  CHECK(options.IsValid(&why));
}

}  // namespace koppel::cycle_test
