// The fit's residual model (solver/synthesis/src/fit_model.*): its Jacobian against central
// differences of its own residuals, for point, angle (at the +-180 deg seam) and dead-centre
// targets; and a deliberately wrong sensitivity that the check must reject.
#include "../../../solver/synthesis/src/fit_model.hpp"

#include "koppel/core/angles.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace koppel::fit_model_test {
namespace {

// [rad] 202 deg - (-158 deg) is one turn: wrapped to 0 up to the rounding of two degree conversions
constexpr double kWrapRoundoff = 1e-15;

// Central differences, h = 1e-6 max(1, |x|) (the house rule): truncation ~1e-12, roundoff of
// residuals solved to 1e-13 ~ 1e-7; the IFT Jacobian itself carries a 1e-6 parameter step.
constexpr double kJacobianTolerance = 1e-5;

// seed 003's four-bar with l2, l3 free; outputs K (point), psi (rocker angle), phi, mu
MechanismBuilder Builder() {
  return [](const std::vector<double>& p) -> Expected<Mechanism> {
    return test::FourBar(1.0, p[0], p[1], 4.0, 8.0, 0.3, 1);
  };
}

// The largest difference between the model's Jacobian and central differences of its residuals;
// `skew` scales the model's last column first (a deliberately wrong Jacobian).
double JacobianError(const TargetModel& model, std::vector<double> x, int n_params, double skew = 1.0) {
  const int rows = model.Residuals(), cols = static_cast<int>(x.size());
  std::vector<double> r(rows), jacobian(rows * cols), plus(rows), minus(rows);
  REQUIRE(model.Evaluate(x.data(), n_params, r.data(), jacobian.data()));
  for (int i = 0; i < rows; ++i) jacobian[i * cols + cols - 1] *= skew;
  double worst = 0;
  for (int j = 0; j < cols; ++j) {
    const double h = 1e-6 * std::max(1.0, std::abs(x[j])), keep = x[j];
    x[j] = keep + h;
    REQUIRE(model.Evaluate(x.data(), n_params, plus.data(), nullptr));
    x[j] = keep - h;
    REQUIRE(model.Evaluate(x.data(), n_params, minus.data(), nullptr));
    x[j] = keep;
    for (int i = 0; i < rows; ++i) worst = std::max(worst, std::abs(jacobian[i * cols + j] - (plus[i] - minus[i]) / (2 * h)));
  }
  return worst;
}

}  // namespace

TEST_CASE("fit model: the Jacobian agrees with central differences (fixed seed)", "[fit]") {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> l2(3.8, 4.6), l3(3.8, 4.6), phi(0, 2 * kPi);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<FitTarget> targets(3);
    targets[0].output = 0;  // K at a free input
    targets[0].point = true;
    targets[0].input_free = true;
    targets[0].input = phi(rng);
    targets[0].position = {1, 8};
    targets[1].output = 1;  // psi: an angle, wrapped
    targets[1].input = phi(rng);
    targets[1].value = phi(rng) - kPi;
    targets[2].output = 1;  // a dead centre of psi near 0
    targets[2].deadcentre = true;
    targets[2].input = 0.2;
    const TargetModel model(Builder(), targets);
    const std::vector<double> x = {l2(rng), l3(rng), targets[0].input};
    INFO("trial " << trial << ": l2 " << x[0] << ", l3 " << x[1]);
    CHECK(JacobianError(model, x, 2) < kJacobianTolerance);
  }
}

TEST_CASE("fit model: an angle target across the +-180 deg seam has a wrapped residual and a smooth Jacobian", "[fit]") {
  // the rocker angle psi of this design at phi = 0, and a target 1e-3 rad on the far side of
  // +-180 deg from it: the residual is the short way round, not ~2 pi
  std::vector<FitTarget> targets(1);
  targets[0].output = 1;
  targets[0].input = 0;
  std::vector<double> x = {4.2, 4.3}, r(1);
  REQUIRE(TargetModel(Builder(), targets).Evaluate(x.data(), 2, r.data(), nullptr));
  const double psi = r[0];  // the residual against 0 is psi itself (wrapped)
  targets[0].value = WrappedAngle(psi + kPi + 1e-3);  // the antipode, a little further on
  const TargetModel model(Builder(), targets);
  REQUIRE(model.Evaluate(x.data(), 2, r.data(), nullptr));
  CHECK(std::abs(std::abs(r[0]) - (kPi - 1e-3)) < 1e-12);
  CHECK(JacobianError(model, x, 2) < kJacobianTolerance);
  // and the wrap itself: (-pi, pi], pi maps to pi, -pi to pi
  CHECK(WrappedAngle(kPi) == Approx(kPi));
  CHECK(WrappedAngle(-kPi) == Approx(kPi));
  CHECK(WrappedAngle(DegToRad(202) - DegToRad(-158)) == Approx(0).margin(kWrapRoundoff));
}

TEST_CASE("fit model: the check rejects a deliberately wrong sensitivity", "[fit]") {
  // the model's Jacobian with the l3 column 1 % off must fail the same check that passes it
  std::vector<FitTarget> targets(1);
  targets[0].output = 0;
  targets[0].point = true;
  targets[0].input = 0.7;
  const TargetModel model(Builder(), targets);
  CHECK(JacobianError(model, {4.2, 4.3}, 2) < kJacobianTolerance);
  CHECK(JacobianError(model, {4.2, 4.3}, 2, 1.01) > 100 * kJacobianTolerance);
}

}  // namespace koppel::fit_model_test
