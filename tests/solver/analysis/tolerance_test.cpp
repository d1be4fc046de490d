// The tolerance analysis (tolerance.hpp) on seed 000's slider-crank: sensitivities against
// central differences of the closed form, the crank pin's clearance against c / cos psi, and the
// Monte Carlo run through the exact solver against the linear worst case and standard deviation;
// play at every joint of the crank-rocker and the slider-crank against their loop closure's
// closed form, the samples' spread against linear_std at every joint of a four-bar, a
// slider-crank and a six-bar, and the shares against the variance sampled term by term.
#include "koppel/analysis/tolerance.hpp"

#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"
#include "support/seeds.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

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

// ---- play at every joint (issue: mu's clearance at B and the samples at A and B0 disagreed) ----

namespace koppel::tolerance_test {
namespace {

// [rad/length] a clearance gradient against central differences of a closed form, step kGapStep:
// truncation h^2 y''' ~ 1e-12, rounding eps / h ~ 1e-10
constexpr double kGapStep = 1e-6;
constexpr double kGapDifference = 1e-8;
// relative: a Monte Carlo standard deviation of kPlaySamples samples against linear_std. One
// component of a pin uniform in its disc has kurtosis 2, so the sampled standard deviation's
// relative standard error is sqrt(kurtosis - 1) / (2 sqrt(n)) = 0.35 %; 2 % is 5.7 of them (the
// linear model's own error at c = 1e-3 of lengths 1 .. 4 is ~ c / length < 0.1 %)
constexpr long kPlaySamples = 20000;
constexpr double kPlayMonteCarlo = 0.02;
// relative: a share against the part of the variance sampled term by term (kPlaySamples each): a
// sampled variance's relative standard error is sqrt((kurtosis - 1) / n) <= sqrt(2 / 20000) = 1 %
// (normal), so the quotient of one and their sum is within ~1.5 %; 5 % is over three of them
constexpr double kShareMonteCarlo = 0.05;

// The acute angle between two lines of directions alpha and beta: the transmission angle's
// definition (the catalog's mu = min(gamma, 180 deg - gamma)), independent of the kernel's formula.
double AcuteBetween(double alpha, double beta) {
  const double g = std::abs(WrapToHalfTurn(alpha - beta));
  return std::min(g, kPi - g);
}

// The crank-rocker's rocker and coupler directions with a gap in its loop: by the closure
// A0A + AB = A0B0 + B0B, a gap at any of the four joints adds to it as a frame vector
// (d, 0) + gap would. Circle intersection (tests/support FourBarRocker) in the frame turned onto
// that vector, B on side +1 (above the frame line, the catalog's branch).
struct LoopDirections {
  double psi, theta_coupler;
};
LoopDirections CrankRockerWithGap(double a, double b, double c, double d, double phi, const Eigen::Vector2d& gap) {
  const Eigen::Vector2d frame = Eigen::Vector2d(d, 0) + gap;
  const double beta = std::atan2(frame.y(), frame.x());
  const std::optional<test::RockerValues> r = test::FourBarRocker(a, b, c, frame.norm(), phi - beta, +1);
  REQUIRE(r);
  const Eigen::Vector2d ab = r->b - a * Eigen::Vector2d(std::cos(phi - beta), std::sin(phi - beta));
  return {r->psi + beta, std::atan2(ab.y(), ab.x()) + beta};
}

// |d y / d gap| of an angle y(gap) by central differences, step kGapStep in x and y.
double GapGradientNorm(const std::function<double(const Eigen::Vector2d&)>& y) {
  const double h = kGapStep;
  const double dx = WrapToHalfTurn(y({h, 0}) - y({-h, 0})) / (2 * h), dy = WrapToHalfTurn(y({0, h}) - y({0, -h})) / (2 * h);
  return std::hypot(dx, dy);
}

// A mechanism with no toleranced parameters: only play.
MechanismBuilder Fixed(const Mechanism& m) {
  return [m](const std::vector<double>&) -> Expected<Mechanism> { return m; };
}

ToleranceOptions PlayAt(const Mechanism& m, const std::string& output, std::vector<std::string> joints, double c, double input_deg) {
  ToleranceOptions o;
  o.output = m.FindOutput(output);
  REQUIRE(o.output >= 0);
  o.inputs = {DegToRad(input_deg)};
  for (const std::string& joint : joints) {
    o.clearance_joints.push_back(m.FindJoint(joint));
    REQUIRE(o.clearance_joints.back() >= 0);
    o.clearances.push_back(c);
  }
  return o;
}

}  // namespace

TEST_CASE("play at any joint of the crank-rocker moves psi and mu alike: the loop closure's closed form", "[tolerance]") {
  // the catalog's crank-rocker 1 : 3.5 : 3 : 4; mu 58 .. 86 deg here, off its fold at 90 deg (phi = 122, 238 deg)
  const double a = 1, b = 3.5, c = 3, d = 4;
  const Mechanism m = test::FourBar(a, b, c, d, 0, 0, +1);
  for (double degrees : {30.0, 60.0, 135.0, 250.0}) {
    const double phi = DegToRad(degrees);
    const ToleranceReport psi = AnalyseTolerances(Fixed(m), {}, PlayAt(m, "psi", {"A0", "A", "B", "B0"}, 0.01, degrees));
    const ToleranceReport mu = AnalyseTolerances(Fixed(m), {}, PlayAt(m, "mu", {"A0", "A", "B", "B0"}, 0.01, degrees));
    REQUIRE(psi.status == AnalysisStatus::kComplete);
    REQUIRE(mu.status == AnalysisStatus::kComplete);
    const LoopDirections nominal = CrankRockerWithGap(a, b, c, d, phi, {0, 0});
    REQUIRE(psi.rows[0].nominal == Approx(nominal.psi).margin(kNominalRoundoff));  // the branch of the reference
    REQUIRE(mu.rows[0].nominal == Approx(AcuteBetween(nominal.psi, nominal.theta_coupler)).margin(kNominalRoundoff));
    const double psi_reference = GapGradientNorm([&](const Eigen::Vector2d& gap) { return CrankRockerWithGap(a, b, c, d, phi, gap).psi; });
    const double mu_reference = GapGradientNorm([&](const Eigen::Vector2d& gap) {
      const LoopDirections l = CrankRockerWithGap(a, b, c, d, phi, gap);
      return AcuteBetween(l.psi, l.theta_coupler);
    });
    for (int joint = 0; joint < 4; ++joint) {
      const char* const names[] = {"A0", "A", "B", "B0"};
      INFO("phi = " << degrees << ", play at " << names[joint]);
      CHECK(psi.rows[0].clearance_gain[joint] == Approx(psi_reference).margin(kGapDifference));
      CHECK(mu.rows[0].clearance_gain[joint] == Approx(mu_reference).margin(kGapDifference));
    }
  }
}

TEST_CASE("play at any joint of the slider-crank moves mu as its offset e does: seed 000's closed form", "[tolerance]") {
  // the closure A0A + AB = A0F + FB: a gap's x part goes into s, its y part shifts A0 like e, so
  // |d mu / d gap| = |d mu / d e| (seed 000: mu = 90 deg - |psi|, sin psi = -lambda cos phi - eps)
  const Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  for (double degrees : {0.0, 60.0, 170.0, 300.0}) {
    const ToleranceReport r = AnalyseTolerances(Fixed(m), {}, PlayAt(m, "mu", {"A0", "A", "B"}, 0.003, degrees));
    REQUIRE(r.status == AnalysisStatus::kComplete);
    const double phi = DegToRad(degrees), h = kGapStep;
    const double reference = std::abs(test::SliderCrank(1.0, 2.6, 0.8 + h, phi).mu - test::SliderCrank(1.0, 2.6, 0.8 - h, phi).mu) / (2 * h);
    for (int joint = 0; joint < 3; ++joint) {
      const char* const names[] = {"A0", "A", "B"};
      INFO("phi = " << degrees << ", play at " << names[joint]);
      CHECK(r.rows[0].clearance_gain[joint] == Approx(reference).margin(kGapDifference));
    }
  }
}

TEST_CASE("play alone: the Monte Carlo's spread is linear_std at every joint and for every kind of output", "[tolerance]") {
  // the four-bar with a coupler point K and the distance A0K, the slider-crank, and a Watt six-bar
  // with a transmission angle on its second loop: one joint's play at a time, c = 1e-3
  Mechanism four_bar = test::FourBar(1, 3.5, 3, 4, 2, 0.5, +1);
  const int frame = four_bar.FindLink("frame"), coupler = four_bar.FindLink("coupler");
  const Output distance{.name = "A0K",
                        .kind = OutputKind::kDistance,
                        .p = {frame, four_bar.links[frame].FindPoint("A0")},
                        .q = {coupler, four_bar.links[coupler].FindPoint("K")}};
  four_bar.outputs.push_back(distance);
  Mechanism six_bar = test::WattSixBar();
  six_bar.outputs.push_back(
      Output{.name = "mu2", .kind = OutputKind::kTransmissionAngle, .joint = six_bar.FindJoint("D"), .link = six_bar.FindLink("link5"), .p = {}, .q = {}});
  const Mechanism slider_crank = test::SliderCrank(1.0, 2.6, 0.8);
  struct Case {
    const Mechanism* m;
    std::vector<std::pair<std::string, int>> outputs;  // name, component
  };
  int combination = 0;
  for (const Case& k : {Case{&four_bar, {{"K", 0}, {"K", 1}, {"psi", 0}, {"mu", 0}, {"A0K", 0}}}, Case{&slider_crank, {{"s", 0}, {"mu", 0}}},
                        Case{&six_bar, {{"chi", 0}, {"mu2", 0}}}}) {
    for (const Joint& joint : k.m->joints) {
      if (joint.type != JointType::kRevolute) continue;
      for (const auto& [output, component] : k.outputs) {
        if (!test::InCheckedShare(combination++)) continue;
        ToleranceOptions o = PlayAt(*k.m, output, {joint.name}, 1e-3, 60);
        o.component = component;
        o.samples = kPlaySamples;
        const ToleranceReport r = AnalyseTolerances(Fixed(*k.m), {}, o);
        REQUIRE(r.status == AnalysisStatus::kComplete);
        const ToleranceRow& row = r.rows[0];
        INFO(k.m->name << ", play at " << joint.name << ", output " << output << " " << component << ": linear_std " << row.linear_std
                       << ", mc_std " << row.mc_std);
        REQUIRE(row.linear_std > 0);
        CHECK(row.mc_std == Approx(row.linear_std).epsilon(kPlayMonteCarlo));
        CHECK(row.mc_mean == Approx(row.nominal).margin(kMonteCarloMean * row.linear_std));
      }
    }
  }
}

TEST_CASE("the shares are each term's part of linear_std^2: against the variance sampled term by term", "[tolerance]") {
  // README's example: l1, l2, e and the crank pin's play; each term alone in its own Monte Carlo
  // run gives its variance, their sum the whole (independent terms of a linear model); a share is
  // one of them over the sum, for either distribution (T / sqrt(3) or T / 3 per tolerance, c / 2
  // per pin: not T against c alike)
  const Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  const std::vector<double> tolerances = {0.01, 0.02, 0.005};
  for (ToleranceDistribution distribution : {ToleranceDistribution::kUniform, ToleranceDistribution::kNormal}) {
    if (!test::InCheckedShare(static_cast<int>(distribution))) continue;  // the checked build: uniform (0) alone
    ToleranceOptions all = Options({60}, tolerances);
    all.clearance_joints = {m.FindJoint("A")};
    all.clearances = {0.003};
    all.distribution = distribution;
    const ToleranceReport whole = AnalyseTolerances(kBuilder, kNominal, all);
    REQUIRE(whole.status == AnalysisStatus::kComplete);
    std::vector<double> variances;
    for (size_t j = 0; j < tolerances.size(); ++j) {
      // parameter j alone: the others held at their nominal values
      const MechanismBuilder only_j = [j](const std::vector<double>& p) {
        std::vector<double> full = kNominal;
        full[j] = p[0];
        return kBuilder(full);
      };
      ToleranceOptions o = Options({60}, {tolerances[j]});
      o.samples = kPlaySamples;
      o.distribution = distribution;
      variances.push_back(std::pow(AnalyseTolerances(only_j, {kNominal[j]}, o).rows[0].mc_std, 2));
    }
    ToleranceOptions pin = PlayAt(m, "s", {"A"}, 0.003, 60);
    pin.samples = kPlaySamples;
    variances.push_back(std::pow(AnalyseTolerances(Fixed(m), {}, pin).rows[0].mc_std, 2));
    double sum = 0;
    for (double v : variances) sum += v;
    for (size_t t = 0; t < variances.size(); ++t) {
      INFO(ToString(distribution) << ", term " << t);
      CHECK(whole.rows[0].share[t] == Approx(variances[t] / sum).epsilon(kShareMonteCarlo));
    }
  }
}

}  // namespace koppel::tolerance_test
