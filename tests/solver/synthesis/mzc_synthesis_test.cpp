// Meyer zur Capellen linkages (seed 003): the lambda = 5/6 example's dimensions, kappa, and the
// six-point contact verified by exact higher-order transfer functions.
#include "koppel/synthesis/mzc_synthesis.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/synthesis/cognates.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::mzc_synthesis_test {

// [deg] against seed 003's phi0 printed to 4 decimals: its last digit
constexpr double kSeedDeg = 1e-4;
// relative: MzC's dimensions are closed forms (seed 003) of O(10) lengths: rounding only
constexpr double kMzcRoundoff = 1e-12;
// relative: the cognate's ratios through the re-analysed design: the 1e-9
constexpr double kCognateRatio = 1e-9;

TEST_CASE("lambda = 5/6: the document's dimensions and kappa", "[mzc]") {
  const double D = 2.0, f = 0.25 * std::sqrt(2.0) * std::sqrt(3.0) * D;  // the document's factor 1/4 sqrt2 sqrt3 D
  const MzcDesign d = MzcFromLambda(5.0 / 6, D);
  REQUIRE(d.ok());
  CHECK(RadToDeg(d.phi0) == Approx(54.7356).margin(kSeedDeg));
  CHECK(d.l1 == Approx(25.0 / 3 * f).epsilon(kMzcRoundoff));
  CHECK(d.l2 == Approx(10.0 / 9 * std::sqrt(3.0) * f).epsilon(kMzcRoundoff));
  CHECK(d.l4 == Approx(40.0 / 9 * std::sqrt(3.0) * f).epsilon(kMzcRoundoff));
  CHECK(d.k == Approx(f).epsilon(kMzcRoundoff));
  CHECK(std::tan(d.kappa) == Approx(std::sqrt(2.0) / 5).epsilon(kMzcRoundoff));
  // K, placed at the inflection pole, is at k' from A' and B' as the formula says
  const Mechanism m = MzcMechanism(d);
  const Eigen::Vector2d k = m.links[2].points[2].local;
  CHECK(k.norm() == Approx(d.k).epsilon(kMzcRoundoff));
  CHECK((k - m.links[2].points[1].local).norm() == Approx(d.k).epsilon(kMzcRoundoff));
  const Expected<double> lambda = LambdaFromKappa(d.kappa);
  REQUIRE(lambda);
  CHECK(*lambda == Approx(5.0 / 6).epsilon(kMzcRoundoff));
}

TEST_CASE("six-point contact of the coupler curve with its tangent", "[mzc]") {
  for (double lambda : {0.6, 5.0 / 6, 1.0, 1.3}) {
    INFO("lambda " << lambda);
    const MzcDesign d = MzcFromLambda(lambda, 1.0);
    REQUIRE(d.ok());
    const Mechanism m = MzcMechanism(d);
    // the across-tangent Taylor coefficients of K vanish up to order 5: six-point contact
    CHECK(TangentContactOrder(m, {2, 2}, m.hint.input, 1e-9) >= 6);
  }
  // a point next to the inflection pole is no straight-line point: contact order 2 (curvature)
  const MzcDesign d = MzcFromLambda(5.0 / 6, 1.0);
  Mechanism off = MzcMechanism(d);
  off.links[2].points[2].local.y() += 0.05;
  CHECK(TangentContactOrder(off, {2, 2}, off.hint.input, 1e-9) == 2);
}

TEST_CASE("the crank-rocker cognate of the lambda = 5/6 linkage is seed 003's, scaled", "[mzc]") {
  const MzcDesign d = MzcFromLambda(5.0 / 6, 1.0);
  const Cognates c = RobertsCognates(MzcMechanism(d), {2, 2});
  REQUIRE(c.ok());
  // seed 003: l1 = 1, l2 = l3 = 5/2 sqrt 3, l4 = 4, AK = 25/3: all lengths in the same ratio
  const double scale = c.crank_first;  // the crank-rocker's crank
  CHECK(c.coupler_first / scale == Approx(2.5 * std::sqrt(3.0)).epsilon(kCognateRatio));
  CHECK(c.rocker_first / scale == Approx(2.5 * std::sqrt(3.0)).epsilon(kCognateRatio));
  CHECK(c.frame_first / scale == Approx(4.0).epsilon(kCognateRatio));
  CHECK(c.k_first / scale == Approx(25.0 / 3).epsilon(kCognateRatio));
}

}  // namespace koppel::mzc_synthesis_test
