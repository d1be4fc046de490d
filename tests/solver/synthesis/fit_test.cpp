// Least-squares fitting: a five-precision-point path synthesis whose answer is seed 003's
// crank-rocker (started away from it), a function-generation problem, free inputs, and a
// problem whose targets cannot all be met, reported honestly.
#include "koppel/synthesis/fit.hpp"

#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel {
namespace {

const double kL23 = 2.5 * std::sqrt(3.0);
const double kKappa = std::acos(5.0 / 9.0 * std::sqrt(3.0));

// seed 003's four-bar with l3 and AK free
MechanismBuilder FourBarBuilder() {
  return [](const std::vector<double>& p, Mechanism* m, std::string*) {
    *m = test::FourBar(1.0, kL23, p[0], 4.0, p[1], kKappa, 1);
    return true;
  };
}

std::vector<FitTarget> PrecisionPoints(const std::vector<double>& inputs_deg) {
  std::vector<FitTarget> targets;
  for (double phi : inputs_deg) {
    FitTarget t;
    t.name = "K";
    t.output = 0;
    t.point = true;
    t.input = DegToRad(phi);
    // reference: the independent circle-intersection model with the true dimensions
    t.position = test::FourBarCouplerPoint(1.0, kL23, kL23, 4.0, 25.0 / 3, kKappa, t.input, 1);
    targets.push_back(t);
  }
  return targets;
}

}  // namespace

TEST_CASE("five precision points find seed 003's crank-rocker again", "[fit]") {
  const std::vector<FitParameter> params = {{"l3", 4.0, 3.5, 5.0}, {"k", 7.5, 6.0, 9.0}};
  FitOptions options;
  options.require_from = 0;
  options.require_to = 2 * kPi;
  const FitReport r = Fit(FourBarBuilder(), params, PrecisionPoints({0, 72, 144, 216, 288}), options);
  REQUIRE(r.ok);
  CHECK(r.values[0] == Approx(kL23).margin(1e-8));
  CHECK(r.values[1] == Approx(25.0 / 3).margin(1e-8));
  for (double residual : r.target_residuals) CHECK(residual < 1e-9);
  CHECK(r.assembles_over_range);
  // exact gradients through the solver: Gauss–Newton converges in a handful of iterations
  CHECK(r.iterations < 15);
}

TEST_CASE("precision points with free inputs", "[fit]") {
  auto targets = PrecisionPoints({20, 100, 180, 260, 330});
  for (FitTarget& t : targets) {
    t.input_free = true;
    t.input += DegToRad(3);  // the start is off by 3 degrees
  }
  const std::vector<FitParameter> params = {{"l3", 4.2, 3.5, 5.0}, {"k", 8.0, 6.0, 9.0}};
  const FitReport r = Fit(FourBarBuilder(), params, targets, FitOptions{});
  REQUIRE(r.ok);
  CHECK(r.values[0] == Approx(kL23).margin(1e-7));
  CHECK(r.values[1] == Approx(25.0 / 3).margin(1e-7));
  CHECK(RadToDeg(r.fitted_inputs[2]) == Approx(180).margin(1e-6));
}

TEST_CASE("function generation: the offset of a slider-crank from its slider positions", "[fit]") {
  const MechanismBuilder builder = [](const std::vector<double>& p, Mechanism* m, std::string*) {
    *m = test::SliderCrank(1.0, 2.6, p[0]);
    return true;
  };
  std::vector<FitTarget> targets;
  for (double phi : {0.0, 60.0, 130.0, 250.0}) {
    FitTarget t;
    t.name = "s";
    t.output = 0;
    t.input = DegToRad(phi);
    t.value = test::SliderCrank(1.0, 2.6, 0.8, t.input).s;  // seed 000's closed form, e = 0.8
    targets.push_back(t);
  }
  const FitReport r = Fit(builder, {{"e", 0.2, 0.0, 1.2}}, targets, FitOptions{});
  REQUIRE(r.ok);
  CHECK(r.values[0] == Approx(0.8).margin(1e-9));
}

TEST_CASE("targets that cannot all be met: the residuals say so", "[fit]") {
  auto targets = PrecisionPoints({0, 90, 180, 270});
  targets[1].position += Eigen::Vector2d(0.3, -0.2);  // a point off the curve of any nearby design
  const std::vector<FitParameter> params = {{"l3", kL23, 3.5, 5.0}, {"k", 25.0 / 3, 6.0, 9.0}};
  const FitReport r = Fit(FourBarBuilder(), params, targets, FitOptions{});
  REQUIRE(r.ok);
  double worst = 0;
  for (double residual : r.target_residuals) worst = std::max(worst, residual);
  CHECK(worst > 0.01);
  CHECK(r.cost > 1e-5);
  // the reported cost is the sum of the reported residuals' squares (weights 1)
  double sum = 0;
  for (double residual : r.target_residuals) sum += 0.5 * residual * residual;
  CHECK(r.cost == Approx(sum).epsilon(1e-9));
}

}  // namespace koppel

namespace koppel {

TEST_CASE("dead-centre targets: a crank-rocker whose rocker has its dead centres where asked", "[fit]") {
  // reference: the dead-centre synthesis answer for phi0 = 164 deg, psi0 = 60 deg, beta = 30 deg has
  // its extended dead centre at phi = 30 deg and the folded one at 30 - 164 = -134 deg; start from
  // other rocker and coupler lengths and ask for dead centres there (plus the swing as a value)
  const MechanismBuilder builder = [](const std::vector<double>& p, Mechanism* m, std::string*) {
    *m = test::FourBar(0.33200614543343, p[0], p[1], 1.0, 0.1, 0.0, 1);
    return true;
  };
  std::vector<FitTarget> targets(2);
  targets[0].name = "extended";
  targets[0].output = 1;  // psi
  targets[0].deadcentre = true;
  targets[0].input = DegToRad(30);
  targets[1] = targets[0];
  targets[1].name = "folded";
  targets[1].input = DegToRad(-134 + 360);
  const FitReport r = Fit(builder, {{"l2", 1.0, 0.5, 2.0}, {"l3", 0.8, 0.3, 1.5}}, targets, FitOptions{});
  REQUIRE(r.ok);
  // the answer of the synthesis (re-analysed there to 1e-9): l2 = 1.05178..., l3 = 0.71977...
  CHECK(r.values[0] == Approx(1.0517844152462932).margin(1e-7));
  CHECK(r.values[1] == Approx(0.7197782698128629).margin(1e-7));
  for (double residual : r.target_residuals) CHECK(residual < 1e-9);
  CHECK(r.iterations < 25);
}

}  // namespace koppel

namespace koppel {

TEST_CASE("straight-line target: AK of seed 003 that makes K's path straightest around phi = 180", "[fit]") {
  // seed 003's K has six-point contact with its tangent at phi = 180 deg only for AK = 25/3
  // (with the other dimensions fixed): fitting AK for straightness over 150..210 deg finds it
  const MechanismBuilder builder = [](const std::vector<double>& p, Mechanism* m, std::string*) {
    *m = test::FourBar(1.0, kL23, kL23, 4.0, p[0], kKappa, 1);
    return true;
  };
  FitTarget t;
  t.name = "straight";
  t.output = 0;
  t.straight = true;
  t.input = DegToRad(150);
  t.to = DegToRad(210);
  t.samples = 31;
  const FitReport r = Fit(builder, {{"k", 7.0, 5.0, 10.0}}, {t}, FitOptions{});
  REQUIRE(r.ok);
  // the optimum over a finite stretch sits close to, not exactly at, the six-point point
  CHECK(r.values[0] == Approx(25.0 / 3).margin(0.02));
  CHECK(r.iterations < 15);  // exact sensitivities, including the line's own motion
  // and the deviation there is tiny compared with the start's (no iterations: the start itself)
  FitOptions none;
  none.max_iterations = 0;
  const FitReport start = Fit(builder, {{"k", 7.0, 5.0, 10.0}}, {t}, none);
  REQUIRE(start.ok);
  CHECK(r.target_residuals[0] < 0.01 * start.target_residuals[0]);
}

}  // namespace koppel
