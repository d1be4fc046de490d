// DesignedFourBar, FourBarJointB and FourBarBranch (solver/synthesis/src/four_bar_design.cpp):
// the mechanism the syntheses hand to the solver must be the drawn four-bar, checked against
// independent geometry (distances, the rigid motion of the coupler plane).
#include "koppel/synthesis/four_bar_design.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/plane.hpp"
#include "koppel/solver/sweep.hpp"

#include <Eigen/Geometry>
#include "hand_picked_four_bar.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace koppel::four_bar_design_test {
namespace {

// Triangle geometry in double on O(1) lengths: a few ulps of 4.
constexpr double kRoundoff = 1e-12;
// The solver's poses against independent geometry: Newton converges to 1e-13 of the size, the
// issue's bar for a re-analysed synthesis is 1e-9 of the mechanism's size (here ~4).
constexpr double kPose = 1e-9;

// The outputs P, theta, psi, mu at one input (a sweep of one point).
Eigen::VectorXd OutputsAt(const Mechanism& m, double input) {
  SweepOptions s;
  s.from = s.to = input;
  s.order = 0;
  const SweepResult r = Sweep(m, s);
  REQUIRE(r.complete());
  Eigen::VectorXd out(5);
  for (int c = 0; c < 5; ++c) out[c] = r.outputs(0, c);
  return out;
}

TEST_CASE("FourBarJointB closes the triangle on the asked branch", "[four_bar_design]") {
  // reference: |B - A| = b, |B - B0| = c, and the side of B against A -> B0 (a cross product)
  std::mt19937 rng(2401);
  std::uniform_real_distribution<double> u(-2, 2);
  int closed = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Vector2d a(u(rng), u(rng)), b0(u(rng), u(rng));
    const double b = 1 + std::abs(u(rng)), c = 1 + std::abs(u(rng)), r = (b0 - a).norm();
    for (int branch : {1, -1}) {
      const auto joint = FourBarJointB(a, b0, b, c, branch);
      const bool closes = r <= b + c && r >= std::abs(b - c);
      REQUIRE(joint.has_value() == closes);
      if (!joint) continue;
      ++closed;
      CHECK_THAT((*joint - a).norm(), Catch::Matchers::WithinAbs(b, kRoundoff));
      CHECK_THAT((*joint - b0).norm(), Catch::Matchers::WithinAbs(c, kRoundoff));
      const double side = (b0 - a).x() * (*joint - a).y() - (b0 - a).y() * (*joint - a).x();
      if (std::abs(side) > kRoundoff) {
        CHECK((side > 0 ? 1 : -1) == branch);
        CHECK(FourBarBranch(a, *joint, b0) == branch);
      }
    }
  }
  CHECK(closed > 100);  // the test did test something
}

TEST_CASE("FourBarJointB refuses what cannot close, FourBarBranch says 0 on the line", "[four_bar_design]") {
  CHECK_FALSE(FourBarJointB({0, 0}, {5, 0}, 1, 2, 1));       // 1 + 2 < 5: too short
  CHECK_FALSE(FourBarJointB({0, 0}, {0.5, 0}, 4, 1, 1));     // |4 - 1| > 0.5: too long
  CHECK_FALSE(FourBarJointB({1, 1}, {1, 1}, 1, 1, 1));       // A on B0: no direction
  // stretched: B on the line A -> B0, between them
  const auto stretched = FourBarJointB({0, 0}, {3, 0}, 1, 2, 1);
  REQUIRE(stretched);
  CHECK_THAT(stretched->x(), Catch::Matchers::WithinAbs(1, kRoundoff));
  CHECK(FourBarBranch({0, 0}, {1, 0}, {3, 0}) == 0);
}

TEST_CASE("the designed four-bar is the drawn one in its pose", "[four_bar_design]") {
  // reference: the geometry it was made from: P at the plane's origin, theta the plane's angle,
  // psi the angle of B0 -> B, mu from the angle between B -> A and B -> B0 folded to 0..90 deg
  const FourBarGeometry g = test::HandPickedFourBar(0.3);
  const Mechanism m = DesignedFourBar(g, "drawn");
  CHECK(m.name == "drawn");
  const double phi = Direction(g.a - g.a0);
  const Eigen::VectorXd out = OutputsAt(m, phi);
  CHECK_THAT(out[0], Catch::Matchers::WithinAbs(g.plane_origin.x(), kPose));
  CHECK_THAT(out[1], Catch::Matchers::WithinAbs(g.plane_origin.y(), kPose));
  CHECK_THAT(WrapToHalfTurn(out[2] - g.plane_angle), Catch::Matchers::WithinAbs(0, kPose));
  CHECK_THAT(WrapToHalfTurn(out[3] - Direction(g.b - g.b0)), Catch::Matchers::WithinAbs(0, kPose));
  const Eigen::Vector2d ba = g.a - g.b, bb0 = g.b0 - g.b;
  const double gamma = std::acos(ba.dot(bb0) / (ba.norm() * bb0.norm()));
  CHECK_THAT(out[4], Catch::Matchers::WithinAbs(std::min(gamma, kPi - gamma), kPose));
}

TEST_CASE("driven away from its pose the coupler plane moves rigidly", "[four_bar_design]") {
  // reference: A' on the crank circle, B' from the triangle A' B' B0 on the pose's branch, and
  // the plane point carried by the rotation of A -> B into A' -> B'
  FourBarGeometry g = test::HandPickedFourBar(0.3);
  g.input = 0.25;  // the input reads 0.25 rad in the drawn pose
  g.psi = -1.0;
  const Mechanism m = DesignedFourBar(g, "offset");
  const double a = (g.a - g.a0).norm(), b = (g.b - g.a).norm(), c = (g.b0 - g.b).norm();
  const int branch = FourBarBranch(g.a, g.b, g.b0);
  const double phi0 = Direction(g.a - g.a0);
  for (double turn_deg : {0.0, 30.0, 75.0, -40.0}) {
    const double turn = DegToRad(turn_deg);
    const Eigen::VectorXd out = OutputsAt(m, *g.input + turn);
    const Eigen::Vector2d a1 = g.a0 + a * Eigen::Vector2d(std::cos(phi0 + turn), std::sin(phi0 + turn));
    const auto b1 = FourBarJointB(a1, g.b0, b, c, branch);
    REQUIRE(b1);
    const double rotation = Direction(*b1 - a1) - Direction(g.b - g.a);
    const Eigen::Vector2d p1 = a1 + Eigen::Rotation2Dd(rotation) * (g.plane_origin - g.a);
    INFO("turn " << turn_deg << " deg");
    CHECK_THAT(out[0], Catch::Matchers::WithinAbs(p1.x(), kPose));
    CHECK_THAT(out[1], Catch::Matchers::WithinAbs(p1.y(), kPose));
    CHECK_THAT(WrapToHalfTurn(out[2] - (g.plane_angle + rotation)), Catch::Matchers::WithinAbs(0, kPose));
    const double psi1 = *g.psi + Direction(*b1 - g.b0) - Direction(g.b - g.b0);
    CHECK_THAT(WrapToHalfTurn(out[3] - psi1), Catch::Matchers::WithinAbs(0, kPose));
  }
}

}  // namespace
}  // namespace koppel::four_bar_design_test
