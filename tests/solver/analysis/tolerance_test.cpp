// The tolerance analysis (tolerance.hpp) on seed 000's slider-crank: sensitivities against
// central differences of the closed form, the crank pin's clearance against c / cos psi, and the
// Monte Carlo run through the exact solver against the linear worst case and standard deviation.
#include "koppel/analysis/tolerance.hpp"

#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::tolerance_test {
namespace {

// [length] the nominal pose against seed 000's closed form: rounding of a converged pose
constexpr double kNominalRoundoff = 1e-12;
// a sensitivity against a central difference of the closed form (step h of the test):
// truncation O(h^2) and rounding O(eps / h) of the reference
constexpr double kSensitivityFd = 1e-8;
// relative: the worst case is the same three products summed again here: rounding only
constexpr double kSameSum = 1e-14;
// the shares of the variance add up to 1: rounding of a few quotients
constexpr double kSharesSum = 1e-12;
// relative: the clearance's worst case against c / cos(psi) from the closed-form psi
constexpr double kClearance = 1e-9;
// relative: the sampled standard deviation of 20000 samples against the linear model's: within
// ~1 % (3 standard errors, see the checks), 3 % with margin for the seed
constexpr double kMonteCarlo = 0.03;
// the sampled mean within 0.05 linear standard deviations of the nominal: about seven
// standard errors of a 20000-sample mean (1 / sqrt(20000) = 0.007)
constexpr double kMonteCarloMean = 0.05;

// parameters l1, l2, e of seed 000's slider-crank (tests/support/mechanisms.hpp)
const MechanismBuilder kBuilder = [](const std::vector<double>& p) -> Expected<Mechanism> {
  if (!(p[0] > 0 && p[1] > 0)) return Expected<Mechanism>::Error("lengths must be positive");
  return test::SliderCrank(p[0], p[1], p[2]);
};
const std::vector<double> kNominal = {1.0, 2.6, 0.8};

ToleranceOptions Options(std::vector<double> inputs_deg, std::vector<double> tolerances) {
  ToleranceOptions o;
  o.output = 0;  // s
  for (double x : inputs_deg) o.inputs.push_back(DegToRad(x));
  o.tolerances = std::move(tolerances);
  return o;
}

}  // namespace

TEST_CASE("sensitivities of s to l1, l2, e against central differences of seed 000's closed form", "[tolerance]") {
  const ToleranceReport r = AnalyseTolerances(kBuilder, kNominal, Options({0, 60, 135, 250}, {0.01, 0.02, 0.005}));
  REQUIRE(r.status == AnalysisStatus::kComplete);
  // h = 1e-5: truncation h^2 s''' ~ 1e-10, roundoff 1e-16 / h ~ 1e-11
  const double h = 1e-5;
  for (const ToleranceRow& row : r.rows) {
    REQUIRE(row.ok);
    CHECK(row.nominal == Approx(test::SliderCrank(1.0, 2.6, 0.8, row.input).s).margin(kNominalRoundoff));
    for (int j = 0; j < 3; ++j) {
      std::vector<double> plus = kNominal, minus = kNominal;
      plus[j] += h;
      minus[j] -= h;
      const double reference =
          (test::SliderCrank(plus[0], plus[1], plus[2], row.input).s - test::SliderCrank(minus[0], minus[1], minus[2], row.input).s) / (2 * h);
      INFO("phi = " << RadToDeg(row.input) << ", parameter " << j);
      CHECK(row.sensitivity[j] == Approx(reference).margin(kSensitivityFd));
    }
    const double worst = std::abs(row.sensitivity[0]) * 0.01 + std::abs(row.sensitivity[1]) * 0.02 + std::abs(row.sensitivity[2]) * 0.005;
    CHECK(row.worst_case == Approx(worst).epsilon(kSameSum));
    double shares = 0;
    for (double s : row.share) shares += s;
    CHECK(shares == Approx(1.0).epsilon(kSharesSum));
  }
}

TEST_CASE("the crank pin's clearance moves the slider by c / cos psi", "[tolerance]") {
  // slider-crank: the coupler end of the crank pin A free in a circle of radius c moves B along
  // the slide by delta . (B - A) / (B - A)_x, at most c l2 / (l2 cos psi) = c / cos psi, psi the
  // coupler's angle to the slide (seed 000: sin psi = -lambda cos phi - eps)
  const Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  ToleranceOptions o = Options({0, 45, 60, 170, 300}, {0.01, 0.02, 0.005});
  o.clearance_joints = {m.FindJoint("A")};
  o.clearances = {0.003};
  const ToleranceReport r = AnalyseTolerances(kBuilder, kNominal, o);
  REQUIRE(r.status == AnalysisStatus::kComplete);
  for (const ToleranceRow& row : r.rows) {
    const double sin_psi = -(1.0 / 2.6) * std::cos(row.input) - 0.8 / 2.6;
    const double cos_psi = std::sqrt(1 - sin_psi * sin_psi);
    INFO("phi = " << RadToDeg(row.input));
    CHECK(row.clearance_worst_case == Approx(0.003 / cos_psi).epsilon(kClearance));
  }
}

TEST_CASE("Monte Carlo through the exact solver stays inside the worst-case band; its spread is the linear one", "[tolerance]") {
  // small tolerances: the second-order terms (~ T^2 s'' ~ 1e-8) stay far below the band's width
  const Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  for (ToleranceDistribution distribution : {ToleranceDistribution::kUniform, ToleranceDistribution::kNormal}) {
    ToleranceOptions o = Options({60, 200}, {1e-4, 2e-4, 5e-5});
    o.clearance_joints = {m.FindJoint("A")};
    o.clearances = {3e-5};
    o.samples = 20000;
    o.seed = 1;
    o.distribution = distribution;
    const ToleranceReport r = AnalyseTolerances(kBuilder, kNominal, o);
    REQUIRE(r.status == AnalysisStatus::kComplete);
    for (const ToleranceRow& row : r.rows) {
      INFO(ToString(distribution) << ", phi = " << RadToDeg(row.input));
      CHECK(row.mc_samples == 20000);
      CHECK(row.mc_failed == 0);
      if (distribution == ToleranceDistribution::kUniform) {
        // every sample within the linear worst case (plus second order)
        const double band = row.worst_case + row.clearance_worst_case + 1e-7;
        CHECK(row.mc_min >= row.nominal - band);
        CHECK(row.mc_max <= row.nominal + band);
      }
      // the standard deviation of 20000 samples is within ~1 % (3 standard errors) of the
      // linear model's: T / sqrt(3) for uniform, T / 3 for normal, c / 2 for a pin in its hole
      CHECK(row.mc_std == Approx(row.linear_std).epsilon(kMonteCarlo));
      CHECK(row.mc_mean == Approx(row.nominal).margin(kMonteCarloMean * row.linear_std));
    }
  }
}

TEST_CASE("without clearance the Monte Carlo standard deviation is rss / sqrt(3) (uniform) or rss / 3 (normal)", "[tolerance]") {
  for (auto [distribution, factor] : {std::pair{ToleranceDistribution::kUniform, 1 / std::sqrt(3.0)}, std::pair{ToleranceDistribution::kNormal, 1.0 / 3}}) {
    ToleranceOptions o = Options({60}, {1e-4, 2e-4, 5e-5});
    o.samples = 20000;
    o.distribution = distribution;
    const ToleranceReport r = AnalyseTolerances(kBuilder, kNominal, o);
    REQUIRE(r.status == AnalysisStatus::kComplete);
    CHECK(r.rows[0].mc_std == Approx(r.rows[0].rss * factor).epsilon(kMonteCarlo));
  }
}

TEST_CASE("Monte Carlo results do not depend on the number of threads", "[tolerance]") {
  ToleranceOptions o = Options({60}, {0.01, 0.02, 0.005});
  o.samples = 500;
  o.seed = 7;
  o.threads = 1;
  const ToleranceReport one = AnalyseTolerances(kBuilder, kNominal, o);
  o.threads = 3;
  const ToleranceReport three = AnalyseTolerances(kBuilder, kNominal, o);
  CHECK(one.rows[0].mc_std == three.rows[0].mc_std);
  CHECK(one.rows[0].quantiles == three.rows[0].quantiles);
  o.seed = 8;
  CHECK(AnalyseTolerances(kBuilder, kNominal, o).rows[0].mc_std != one.rows[0].mc_std);
}

TEST_CASE("tolerances past the mechanism's limits: samples that do not assemble are counted, the status says so", "[tolerance]") {
  // l2 = 1.9 with l1 + e = 1.8: l2 +- 0.3 makes some samples unable to reach phi = 0 (A0A pointing away from the slide)
  ToleranceOptions o = Options({0}, {0.01, 0.3, 0.01});
  o.samples = 400;
  const ToleranceReport r = AnalyseTolerances(kBuilder, {1.0, 1.9, 0.8}, o);
  CHECK(r.status == AnalysisStatus::kPartial);
  CHECK(r.rows[0].mc_failed > 0);
  CHECK_THAT(r.message, Catch::Contains("did not assemble"));
}

TEST_CASE("clearance is refused on a slide joint", "[tolerance]") {
  const Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  ToleranceOptions o = Options({60}, {0.01, 0.02, 0.005});
  o.clearance_joints = {m.FindJoint("S")};
  o.clearances = {0.001};
  const ToleranceReport r = AnalyseTolerances(kBuilder, kNominal, o);
  CHECK(r.status == AnalysisStatus::kFailed);
  CHECK_THAT(r.message, Catch::Contains("not a revolute joint"));
}

}  // namespace koppel::tolerance_test
