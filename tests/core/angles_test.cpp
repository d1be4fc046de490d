// Angle folding: WrapToFullTurn and WrapToHalfTurn against their definitions (the representative
// in [0, 2 pi), resp. (-pi, pi], of the angle's class mod 2 pi), and AngleDifference's range.
#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::angles_test {

TEST_CASE("WrapToFullTurn folds any angle into [0, 2 pi)", "[angles]") {
  // fmod is exact; adding 2 pi rounds once: a few ulps of 2 pi
  constexpr double kRounding = 1e-15 * 2 * kPi * 4;
  CHECK(WrapToFullTurn(0) == 0);
  CHECK(WrapToFullTurn(DegToRad(-180)) == Approx(kPi).margin(kRounding));
  CHECK(WrapToFullTurn(DegToRad(-261.66)) == Approx(DegToRad(98.34)).margin(kRounding));
  CHECK(WrapToFullTurn(DegToRad(540)) == Approx(kPi).margin(kRounding));
  CHECK(WrapToFullTurn(2 * kPi) == 0);
  // a tiny negative angle would round up to 2 pi: it is 0
  CHECK(WrapToFullTurn(-1e-300) == 0);
  for (int k = -2000; k <= 2000; ++k) {
    const double a = 0.0137 * k * k - 3.1 * k;
    const double w = WrapToFullTurn(a);
    INFO("a = " << a);
    CHECK(w >= 0);
    CHECK(w < 2 * kPi);
    CHECK(std::abs(AngleDifference(w, a)) <= 1e-12 * std::max(1.0, std::abs(a)));
  }
}

TEST_CASE("WrapToHalfTurn folds any angle into (-pi, pi], half a turn to +pi", "[angles]") {
  constexpr double kRounding = 1e-15 * 2 * kPi * 4;  // remainder is exact; one rounding of 2 pi
  CHECK(WrapToHalfTurn(kPi) == kPi);
  CHECK(WrapToHalfTurn(-kPi) == kPi);
  CHECK(WrapToHalfTurn(3 * kPi) == Approx(kPi).margin(kRounding));
  CHECK(WrapToHalfTurn(DegToRad(-190)) == Approx(DegToRad(170)).margin(kRounding));
  for (int k = -2000; k <= 2000; ++k) {
    const double a = 0.0137 * k * k - 3.1 * k;
    const double w = WrapToHalfTurn(a);
    INFO("a = " << a);
    CHECK(w > -kPi);
    CHECK(w <= kPi);
    CHECK(std::abs(AngleDifference(w, a)) <= 1e-12 * std::max(1.0, std::abs(a)));
  }
}

}  // namespace koppel::angles_test
