// PrePolish and CouplerPointAt (solver/synthesis/src/path_prepolish.cpp, private to path
// synthesis): the closed-form coupler point must be the four-bar's, and the polish must bring a
// perturbed start back onto points that a known four-bar traces.
#include "path_prepolish.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/synthesis/four_bar_design.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

namespace koppel::path_prepolish_test {
namespace {

// Closed forms in double on lengths ~4: a few ulps.
constexpr double kRoundoff = 1e-12;
// Ceres stops at function/gradient tolerance 1e-16 (path_prepolish.cpp): points that a four-bar
// traces exactly are met to far below 1e-8 of its size (~5).
constexpr double kPolished = 1e-8;

// A0 (0, 0), B0 (4, 0.3), crank 1.1, coupler 3.2, rocker 2.6, K 1.5 along A -> B and 0.8 left of it.
const std::vector<double> kKnown = {0, 0, 4, 0.3, 1.1, 3.2, 2.6, 1.5, 0.8};

// Reference: A on the crank circle, B from FourBarJointB (tested in four_bar_design_test), K in
// the frame of A -> B.
Eigen::Vector2d Reference(const std::vector<double>& v, int branch, double phi) {
  const Eigen::Vector2d a0(v[0], v[1]), b0(v[2], v[3]);
  const Eigen::Vector2d a = a0 + v[4] * Eigen::Vector2d(std::cos(phi), std::sin(phi));
  const auto b = FourBarJointB(a, b0, v[5], v[6], branch);
  REQUIRE(b);
  const Eigen::Vector2d u = (*b - a).normalized(), left(-u.y(), u.x());
  return a + v[7] * u + v[8] * left;
}

TEST_CASE("the closed-form coupler point is the four-bar's", "[path_prepolish]") {
  for (int branch : {1, -1}) {
    for (int k = 0; k < 36; ++k) {
      const double phi = DegToRad(10.0 * k);
      Eigen::Vector2d p;
      REQUIRE(CouplerPointAt(kKnown, branch, phi, &p));
      const Eigen::Vector2d ref = Reference(kKnown, branch, phi);
      CHECK_THAT(p.x(), Catch::Matchers::WithinAbs(ref.x(), kRoundoff));
      CHECK_THAT(p.y(), Catch::Matchers::WithinAbs(ref.y(), kRoundoff));
    }
  }
  // a rocker too short to reach: the loop does not close
  std::vector<double> open = kKnown;
  open[6] = 0.1;
  Eigen::Vector2d p;
  CHECK_FALSE(CouplerPointAt(open, 1, 0.0, &p));
}

TEST_CASE("a perturbed start is polished onto the points of the known four-bar", "[path_prepolish]") {
  const int branch = 1;
  std::vector<Eigen::Vector2d> points;
  std::vector<double> truth_inputs;
  for (int k = 0; k < 12; ++k) {
    truth_inputs.push_back(DegToRad(30.0 * k));
    points.push_back(Reference(kKnown, branch, truth_inputs.back()));
  }
  std::mt19937 rng(2402);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> v = kKnown, inputs = truth_inputs;
  for (double& x : v) x += 0.02 * u(rng);
  for (double& x : inputs) x += 0.02 * u(rng);
  const double rms = PrePolish(points, branch, &v, &inputs);
  CHECK(rms <= kPolished);
  // the returned RMS is that of the returned unknowns and inputs (recomputed here)
  double sum = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    Eigen::Vector2d p;
    REQUIRE(CouplerPointAt(v, branch, inputs[i], &p));
    sum += (p - points[i]).squaredNorm();
  }
  CHECK(std::sqrt(sum / points.size()) <= kPolished);
}

TEST_CASE("a start that does not close at every point is refused with infinity", "[path_prepolish]") {
  std::vector<double> v = kKnown, inputs = {0.0, 1.0};
  v[6] = 0.1;  // rocker 0.1: never closes
  const std::vector<Eigen::Vector2d> points = {{1, 1}, {2, 1}};
  const std::vector<double> before = v;
  CHECK(PrePolish(points, 1, &v, &inputs) == std::numeric_limits<double>::infinity());
  CHECK(v == before);  // nothing was solved
}

}  // namespace
}  // namespace koppel::path_prepolish_test
