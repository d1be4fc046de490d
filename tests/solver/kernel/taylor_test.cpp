// Taylor series arithmetic against known series (the reference for each is the textbook
// expansion named in the check).
#include "koppel/solver/taylor.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace koppel::taylor_test {
namespace {
// series coefficients are sums of a few products of O(1) numbers: roundoff level
constexpr double kSeries = 1e-14;

Taylor<6> T() {  // the series of t itself
  Taylor<6> t;
  t.c[1] = 1.0;
  return t;
}

double Factorial(int k) { return k <= 1 ? 1.0 : k * Factorial(k - 1); }
}  // namespace

TEST_CASE("sin and cos of a + t are the Taylor series of sin and cos at a", "[taylor]") {
  const double a = 0.7;
  Taylor<6> s, c;
  SinCos(T() + a, s, c);
  for (int k = 0; k <= 6; ++k) {
    // d^k/dt^k sin(a + t) = sin(a + k pi/2)
    CHECK(s.c[k] == Approx(std::sin(a + k * M_PI / 2) / Factorial(k)).margin(kSeries));
    CHECK(c.c[k] == Approx(std::cos(a + k * M_PI / 2) / Factorial(k)).margin(kSeries));
  }
}

TEST_CASE("division, square root and atan2", "[taylor]") {
  // 1/(1 - t) = sum t^k
  const Taylor<6> geometric = Taylor<6>(1.0) / (Taylor<6>(1.0) - T());
  for (int k = 0; k <= 6; ++k) CHECK(geometric.c[k] == Approx(1.0).margin(kSeries));
  // sqrt(1 + t) = sum binom(1/2, k) t^k
  const Taylor<6> root = sqrt(Taylor<6>(1.0) + T());
  double binom = 1.0;
  for (int k = 0; k <= 6; ++k) {
    CHECK(root.c[k] == Approx(binom).margin(kSeries));
    binom *= (0.5 - k) / (k + 1);
  }
  // atan2(t, 1) = atan(t) = t - t^3/3 + t^5/5
  const Taylor<6> angle = atan2(T(), Taylor<6>(1.0));
  const double expected[] = {0, 1, 0, -1.0 / 3, 0, 1.0 / 5, 0};
  for (int k = 0; k <= 6; ++k) CHECK(angle.c[k] == Approx(expected[k]).margin(kSeries));
  // atan2 keeps the quadrant of its value: atan2(1 + t, -1) starts at 3 pi / 4
  CHECK(atan2(Taylor<6>(1.0) + T(), Taylor<6>(-1.0)).c[0] == Approx(3 * M_PI / 4));
}

TEST_CASE("wrapping an angle series shifts only its value", "[taylor]") {
  Taylor<3> x(7.0);
  x.c[1] = 2.0;
  const Taylor<3> w = WrapAngle(x);
  CHECK(w.c[0] == Approx(7.0 - 2 * M_PI));
  CHECK(w.c[1] == 2.0);
}

}  // namespace koppel::taylor_test

namespace koppel::taylor_test {

// The wrap's shortcuts against the IEEE remainder they stand for (exact, so equal bit for bit):
// seeded random angles over several turns, and the edges of each shortcut.
TEST_CASE("WrapAngle gives std::remainder(x, 2 pi) exactly", "[taylor]") {
  std::mt19937 random(16);
  std::uniform_real_distribution<double> turns(-5.0, 5.0);
  std::vector<double> xs;
  for (int i = 0; i < 20000; ++i) xs.push_back(turns(random) * 2.0 * kPi);
  for (double edge : {kPi, 2.0 * kPi, 3.0 * kPi, 5.0 * kPi}) {
    for (double x : {edge, std::nextafter(edge, 0.0), std::nextafter(edge, 10.0 * kPi)}) {
      xs.push_back(x);
      xs.push_back(-x);
    }
  }
  xs.push_back(0.0);
  xs.push_back(1e300);
  for (double x : xs) {
    INFO("x = " << x);
    CHECK(WrapAngle(x) == std::remainder(x, 2.0 * kPi));
  }
}

}  // namespace koppel::taylor_test
