// The plane's vector helpers against their definitions: Rotate is the rotation matrix
// [cos -sin; sin cos], Perp the quarter turn, Cross |a||b| sin of the angle from a to b, and
// Direction the angle Rotate(theta, x axis) was turned by.
#include "koppel/core/plane.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::plane_test {

// O(1) operations on O(1) numbers: a few ulps.
constexpr double kRoundoff = 1e-14;

TEST_CASE("Rotate turns counter-clockwise, Perp is a quarter turn", "[plane]") {
  const Eigen::Vector2d x(1, 0), v(2.5, -0.75);
  CHECK((Rotate(kPi / 2, x) - Eigen::Vector2d(0, 1)).norm() < kRoundoff);
  for (double theta : {-3.0, -1.0, 0.0, 0.4, 2.0, 6.0}) {
    Eigen::Matrix2d r;
    r << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
    CHECK((Rotate(theta, v) - r * v).norm() < kRoundoff);
    // d/dtheta R(theta) v = Perp(R(theta) v)
    constexpr double h = 1e-6;
    const Eigen::Vector2d derivative = (Rotate(theta + h, v) - Rotate(theta - h, v)) / (2 * h);
    CHECK((derivative - Perp(Rotate(theta, v))).norm() < 1e-9);
  }
  CHECK((Perp(v) - Rotate(kPi / 2, v)).norm() < kRoundoff);
}

TEST_CASE("Cross is |a| |b| sin(angle from a to b); Direction is the angle from the x axis", "[plane]") {
  const Eigen::Vector2d a(1.5, 0.5);
  for (double turn : {-2.5, -0.3, 0.0, 0.7, 1.9, 3.1}) {
    const Eigen::Vector2d b = 0.8 * Rotate(turn, a);
    CHECK(Cross(a, b) == Approx(a.norm() * b.norm() * std::sin(turn)).margin(kRoundoff));
    CHECK(Direction(Rotate(turn, Eigen::Vector2d(2, 0))) == Approx(turn).margin(kRoundoff));
  }
  CHECK(Direction(Eigen::Vector2d(-1, 0)) == Approx(kPi));  // half a turn is +pi
}

}  // namespace koppel::plane_test
