// Property test of the continuation: 2000 random four-bars and 1000 random slider-cranks (fixed
// seed), each assembled on a random branch at a random input and swept over a random range with
// a random step. Every row must match the closed-form circle intersection of the branch it was
// assembled on — a single row on the other branch fails — and every limit point must sit where
// the law of cosines puts the dead centre of the drive, to 1e-9 rad.
#include "koppel/solver/sweep.hpp"

#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"
#include "support/seeds.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <algorithm>
#include <array>
#include <random>

namespace koppel::continuation_property_test {
namespace {

// Rows vs closed form: both exact to roundoff; generic mechanisms keep J well away from
// singular except next to a limit point, where the closed form itself loses digits.
constexpr double kRow = 1e-8;
// Limit points are located to 1e-11 rad; the law of cosines is exact to roundoff.
constexpr double kLimit = 1e-9;
// Mechanisms this close (relative) to Grashof-neutral have branch points or near-crossings;
// they are tested on purpose elsewhere (continuation_test.cpp), not drawn at random here.
constexpr double kNeutralMargin = 0.02;

double NearestLimit(const std::vector<double>& limits, double input) {
  double best = 1e300;
  for (double l : limits) best = std::min(best, std::abs(std::remainder(input - l, 2 * kPi)));
  return best;
}

struct Stats {
  int mechanisms = 0, rows = 0, limits = 0;
};

}  // namespace

TEST_CASE("2000 random four-bars: every row on the assembly branch, every limit point where the law of cosines puts it",
          "[continuation][property]") {
  std::mt19937 random(20261122);
  std::uniform_real_distribution<double> length(0.2, 2.0), angle(0.0, 2 * kPi), unit(0.0, 1.0);
  Stats stats;
  while (stats.mechanisms < test::SeedCount(2000)) {
    const double a = length(random), b = length(random), c = length(random), d = length(random);
    std::array<double, 4> sorted{a, b, c, d};
    std::sort(sorted.begin(), sorted.end());
    if (std::abs(sorted[0] + sorted[3] - sorted[1] - sorted[2]) < kNeutralMargin * sorted[3]) continue;
    const double phi0 = angle(random);
    const int side = unit(random) < 0.5 ? 1 : -1;
    const auto at_start = test::FourBarRocker(a, b, c, d, phi0, side);
    if (!at_start) continue;  // no assembly at this input
    // a start too close to a limit point would make the hint ambiguous: keep 1e-3 rad away
    if (NearestLimit(test::FourBarLimits(a, b, c, d), phi0) < 1e-3) continue;
    const Mechanism m = test::PlainFourBar(a, b, c, d, phi0, at_start->b);
    SweepOptions o;
    o.from = phi0 + (unit(random) - 0.5) * 4 * kPi;
    o.to = o.from + (unit(random) - 0.5) * 4 * kPi;
    o.step = DegToRad(0.5 + 44.5 * unit(random));
    o.order = 1;
    const SweepResult r = Sweep(m, o);
    INFO("four-bar a=" << a << " b=" << b << " c=" << c << " d=" << d << " phi0=" << phi0 << " side=" << side << " step="
                       << RadToDeg(o.step) << " from " << RadToDeg(o.from) << " to " << RadToDeg(o.to));
    REQUIRE(r.status != SweepStatus::kNotAssemblable);
    const int psi = OutputColumn(m, 0, 0, 1);
    for (size_t i = 0; i < r.inputs.size(); ++i) {
      const auto expected = test::FourBarRocker(a, b, c, d, r.inputs[i], side);
      REQUIRE(expected);
      INFO("row phi = " << RadToDeg(r.inputs[i]));
      REQUIRE(std::abs(AngleDifference(r.outputs(i, psi), expected->psi)) < kRow);
      ++stats.rows;
    }
    const std::vector<double> limits = test::FourBarLimits(a, b, c, d);
    for (const SingularPoint& p : r.singular_points) {
      REQUIRE(p.kind == SingularKind::kLimitPoint);
      REQUIRE(NearestLimit(limits, p.input) < kLimit);
      ++stats.limits;
    }
    // a partial sweep ends at limit points only
    if (!r.complete()) REQUIRE(!r.singular_points.empty());
    ++stats.mechanisms;
  }
  INFO(stats.rows << " rows, " << stats.limits << " limit points");
  CHECK(stats.rows > 10 * test::SeedCount(2000));
  CHECK(stats.limits > test::SeedCount(2000) / 4);
}

TEST_CASE("1000 random slider-cranks: every row on the assembly branch, every limit point where |A_y| = l2",
          "[continuation][property]") {
  std::mt19937 random(11222026);
  std::uniform_real_distribution<double> length(0.2, 2.0), angle(0.0, 2 * kPi), unit(0.0, 1.0);
  Stats stats;
  while (stats.mechanisms < test::SeedCount(1000)) {
    const double l1 = length(random), l2 = length(random), e = (unit(random) - 0.5) * 2.0;
    if (std::abs(l1 + std::abs(e) - l2) < kNeutralMargin * std::max(l1, l2)) continue;
    const double phi0 = angle(random);
    const int side = unit(random) < 0.5 ? 1 : -1;
    const auto at_start = test::SliderCrankBranch(l1, l2, e, phi0, side);
    if (!at_start) continue;
    if (NearestLimit(test::SliderCrankLimits(l1, l2, e), phi0) < 1e-3) continue;
    Mechanism m = test::SliderCrank(l1, l2, e);
    m.hint.input = phi0;
    m.hint.points[0].global = {at_start->s, 0.0};
    SweepOptions o;
    o.from = phi0 + (unit(random) - 0.5) * 4 * kPi;
    o.to = o.from + (unit(random) - 0.5) * 4 * kPi;
    o.step = DegToRad(0.5 + 44.5 * unit(random));
    o.order = 1;
    const SweepResult r = Sweep(m, o);
    INFO("slider-crank l1=" << l1 << " l2=" << l2 << " e=" << e << " phi0=" << phi0 << " side=" << side);
    REQUIRE(r.status != SweepStatus::kNotAssemblable);
    const int s = OutputColumn(m, 0, 0, 1);
    for (size_t i = 0; i < r.inputs.size(); ++i) {
      const auto expected = test::SliderCrankBranch(l1, l2, e, r.inputs[i], side);
      REQUIRE(expected);
      INFO("row phi = " << RadToDeg(r.inputs[i]));
      REQUIRE(std::abs(r.outputs(i, s) - expected->s) < kRow);
      REQUIRE(std::abs(r.outputs(i, s + 1) - expected->s1) < 1e-6 * (1 + std::abs(expected->s1)));
      ++stats.rows;
    }
    const std::vector<double> limits = test::SliderCrankLimits(l1, l2, e);
    for (const SingularPoint& p : r.singular_points) {
      REQUIRE(p.kind == SingularKind::kLimitPoint);
      REQUIRE(NearestLimit(limits, p.input) < kLimit);
      ++stats.limits;
    }
    if (!r.complete()) REQUIRE(!r.singular_points.empty());
    ++stats.mechanisms;
  }
  CHECK(stats.rows > 10 * test::SeedCount(1000));
  CHECK(stats.limits > test::SeedCount(1000) / 5);
}

}  // namespace koppel::continuation_property_test
