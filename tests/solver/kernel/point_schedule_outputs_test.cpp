// The compiled step's outputs (solver/kernel/src/point_schedule_outputs.cpp): every output kind's
// value, 1st and 2nd derivative, from the schedule alone (loaded once at the assembly, then
// stepped by itself), against closed forms rather than against the general kernel
// (point_schedule_test.cpp holds the two kernels to each other). References: seed 000's
// slider-crank (s, s', s'', mu; mu' and mu'' differentiated by hand from sin psi = -lambda cos phi
// - eps); the four-bar by circle intersection (tests/support/closed_forms: the rocker angle and
// psi', the coupler point, the transmission angle) and a rocker-slider by the same geometry, with
// the derivatives the closed forms lack by five-point central differences; a drive joint's angle
// (phi - offset, 1, 0) by hand; orders 0 and 1 against the leading columns of order 2.
#include "koppel/solver/point_schedule.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/build.hpp"
#include "koppel/solver/assembly.hpp"
#include "koppel/solver/continuation.hpp"
#include "koppel/solver/position.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace koppel::point_schedule_outputs_test {
namespace {

// [L | rad] the schedule (converged to 1e-13 L, derivatives exact) against a closed form
constexpr double kExact = 1e-10;
// against five-point differences with h = 1e-3 of closed forms of size ~5: 1st derivative
// truncation h^4 f^(5) / 30 ~ 1e-13 f^(5), rounding 1.5 eps |f| / h ~ 2e-12; 2nd derivative
// truncation h^4 f^(6) / 90, rounding 5.3 eps |f| / h^2 ~ 6e-9
constexpr double kD1 = 1e-9, kD2 = 1e-7, kH = 1e-3;

using Scalar = std::function<double(double)>;
double D1(const Scalar& f, double x) { return (f(x - 2 * kH) - 8 * f(x - kH) + 8 * f(x + kH) - f(x + 2 * kH)) / (12 * kH); }
double D2(const Scalar& f, double x) {
  return (-f(x - 2 * kH) + 16 * f(x - kH) - 30 * f(x) + 16 * f(x + kH) - f(x + 2 * kH)) / (12 * kH * kH);
}

// A schedule loaded at the mechanism's assembly (the mechanism must outlive it).
struct Loaded {
  explicit Loaded(const Mechanism& m) : solver(m), assembly(AssembleRegular(m, solver)), schedule(solver.system()) {
    REQUIRE(assembly.ok());
    REQUIRE(schedule.compiled());
    Continuation path(solver);
    REQUIRE(path.Start(assembly.input, assembly.q).ok());
    schedule.Load(path.input(), path.q(), path.Series(2));
  }
  PositionSolver solver;
  Assembly assembly;
  PointSchedule schedule;
};

// Steps the schedule of `m` alone 360 times by 1 deg from its assembly and calls `check` with the
// input and the (output, component) -> {y, y', y''} reader.
using Reader = std::function<std::array<double, 3>(int output, int component)>;
void Walk(const Mechanism& m, const std::function<void(double input, const Reader& y)>& check) {
  Loaded loaded(m);
  std::vector<double> out(loaded.solver.OutputWidth(2));
  const Reader y = [&](int o, int c) {
    const int at = OutputColumn(m, o, c, 2);
    return std::array<double, 3>{out[at], out[at + 1], out[at + 2]};
  };
  for (int i = 1; i <= 360; ++i) {
    const double input = loaded.assembly.input + DegToRad(i);
    REQUIRE(loaded.schedule.Step(input));
    loaded.schedule.OutputDerivatives(2, out.data());
    check(input, y);
  }
}

double Wrapped(double angle) { return std::remainder(angle, 2 * kPi); }

}  // namespace

TEST_CASE("a slide on the frame and its transmission angle: seed 000's closed form", "[kernel][point-schedule-outputs]") {
  const double l1 = 1, l2 = 2.6, e = 0.8, lambda = l1 / l2;
  Walk(test::SliderCrank(l1, l2, e), [&](double phi, const Reader& y) {
    INFO("phi = " << RadToDeg(phi));
    const test::SliderCrankValues v = test::SliderCrank(l1, l2, e, phi);
    const std::array<double, 3> s = y(0, 0), mu = y(1, 0);
    CHECK_THAT(s[0], Catch::Matchers::WithinAbs(v.s, kExact));
    CHECK_THAT(s[1], Catch::Matchers::WithinAbs(v.s1, kExact));
    CHECK_THAT(s[2], Catch::Matchers::WithinAbs(v.s2, kExact));
    CHECK_THAT(mu[0], Catch::Matchers::WithinAbs(v.mu, kExact));
    // psi' cos psi = lambda sin phi; psi'' = (lambda cos phi + sin psi psi'^2) / cos psi; mu = 90 deg - |psi|
    const double sin_psi = -lambda * std::cos(phi) - e / l2, cos_psi = std::sqrt(1 - sin_psi * sin_psi);
    const double psi1 = lambda * std::sin(phi) / cos_psi, psi2 = (lambda * std::cos(phi) + sin_psi * psi1 * psi1) / cos_psi;
    if (std::abs(sin_psi) < 1e-3) return;  // mu folds at 90 deg (psi = 0): no derivative
    const double sign = sin_psi > 0 ? -1.0 : 1.0;
    CHECK_THAT(mu[1], Catch::Matchers::WithinAbs(sign * psi1, kExact));
    CHECK_THAT(mu[2], Catch::Matchers::WithinAbs(sign * psi2, kExact));
  });
}

TEST_CASE("four-bar: point, link angle, drive joint, distance, direction, transmission angle", "[kernel][point-schedule-outputs]") {
  const double a = 1, b = 3, c = 2.5, d = 3.2, k = 1.5, kappa = 0.4;  // a Grashof crank-rocker (1 + 3.2 < 3 + 2.5)
  Mechanism m = test::FourBar(a, b, c, d, k, kappa, 1);  // outputs K, psi, phi, mu
  m.outputs[1].offset = 0.5;  // offsets: subtracted from the value only
  m.outputs[2].offset = 0.1;
  DistanceOutput(m, "KB", "coupler", "K", "rocker", "B");
  DirectionOutput(m, "dKB", "coupler", "K", "rocker", "B").offset = 0.25;
  const auto rocker = [=](double phi) { return *test::FourBarRocker(a, b, c, d, phi, 1); };
  const auto coupler_point = [=](double phi) { return test::FourBarCouplerPoint(a, b, c, d, k, kappa, phi, 1); };
  const std::vector<double> folds = test::CrankRockerMuFolds(a, b, c, d);
  Walk(m, [&](double phi, const Reader& y) {
    INFO("phi = " << RadToDeg(phi));
    const Eigen::Vector2d kk = coupler_point(phi);
    for (int axis : {0, 1}) {
      const Scalar f = [&](double x) { return coupler_point(x)[axis]; };
      CHECK_THAT(y(0, axis)[0], Catch::Matchers::WithinAbs(kk[axis], kExact));
      CHECK_THAT(y(0, axis)[1], Catch::Matchers::WithinAbs(D1(f, phi), kD1));
      CHECK_THAT(y(0, axis)[2], Catch::Matchers::WithinAbs(D2(f, phi), kD2));
    }
    const std::array<double, 3> psi = y(1, 0), drive = y(2, 0), mu = y(3, 0), distance = y(4, 0), direction = y(5, 0);
    CHECK_THAT(Wrapped(psi[0] + 0.5 - rocker(phi).psi), Catch::Matchers::WithinAbs(0.0, kExact));
    CHECK_THAT(psi[1], Catch::Matchers::WithinAbs(rocker(phi).psi1, kExact));
    CHECK_THAT(psi[2], Catch::Matchers::WithinAbs(D1([&](double x) { return rocker(x).psi1; }, phi), kD1));
    CHECK_THAT(Wrapped(drive[0] + 0.1 - phi), Catch::Matchers::WithinAbs(0.0, kExact));
    CHECK(drive[1] == Approx(1.0).margin(kExact));
    CHECK_THAT(drive[2], Catch::Matchers::WithinAbs(0.0, kExact));
    const Scalar length = [&](double x) { return (rocker(x).b - coupler_point(x)).norm(); };
    CHECK_THAT(distance[0], Catch::Matchers::WithinAbs(length(phi), kExact));
    CHECK_THAT(distance[1], Catch::Matchers::WithinAbs(D1(length, phi), kD1));
    CHECK_THAT(distance[2], Catch::Matchers::WithinAbs(D2(length, phi), kD2));
    // the direction K -> B, unwrapped about phi for the differences
    const auto angle = [&](double x) { const Eigen::Vector2d u = rocker(x).b - coupler_point(x); return std::atan2(u.y(), u.x()); };
    const Scalar near = [&](double x) { return Wrapped(angle(x) - angle(phi)); };
    CHECK_THAT(Wrapped(direction[0] + 0.25 - angle(phi)), Catch::Matchers::WithinAbs(0.0, kExact));
    CHECK_THAT(direction[1], Catch::Matchers::WithinAbs(D1(near, phi), kD1));
    CHECK_THAT(direction[2], Catch::Matchers::WithinAbs(D2(near, phi), kD2));
    const Scalar transmission = [&](double x) { return test::CrankRockerMu(a, b, c, d, x); };
    CHECK_THAT(mu[0], Catch::Matchers::WithinAbs(transmission(phi), kExact));
    for (double fold : folds)
      if (std::abs(Wrapped(phi - fold)) < DegToRad(0.5)) return;  // mu = min(gamma, 180 deg - gamma) folds there
    CHECK_THAT(mu[1], Catch::Matchers::WithinAbs(D1(transmission, phi), kD1));
    CHECK_THAT(mu[2], Catch::Matchers::WithinAbs(D2(transmission, phi), kD2));
  });
}

TEST_CASE("a slide on a turning guide: a block on the rocker's line pushed by a rod", "[kernel][point-schedule-outputs]") {
  // the four-bar (1, 4, 3.5, 4) with a rod of 6 from the crank pin A to a block C on the rocker's
  // line through B0: C = B0 + s u, u the rocker's direction, |C - A| = 6, so
  // s = u.w + sigma sqrt(36 - (u x w)^2), w = A - B0 (sigma the branch the assembly takes)
  Mechanism m = test::FourBar(1, 4, 3.5, 4, 2, 0.3, 1);
  m.outputs.clear();
  AddLink(m, "rod", {{"A", {0, 0}}, {"C", {6, 0}}});
  AddLink(m, "block", {{"C", {0, 0}}});
  Revolute(m, "A2", "crank", "rod", "A", "A");
  Revolute(m, "C", "rod", "block");
  Prismatic(m, "S", "rocker", "B0", "block", "C", {1, 0});
  JointOutput(m, "s", "S");
  const auto travel = [](double phi, double sigma) {
    const Eigen::Vector2d w = Eigen::Vector2d(std::cos(phi), std::sin(phi)) - Eigen::Vector2d(4, 0);
    const double psi = test::FourBarRocker(1, 4, 3.5, 4, phi, 1)->psi;
    const Eigen::Vector2d u(std::cos(psi), std::sin(psi));
    const double cross = u.x() * w.y() - u.y() * w.x();
    return u.dot(w) + sigma * std::sqrt(36 - cross * cross);
  };
  double sigma = 0;
  Walk(m, [&](double phi, const Reader& y) {
    INFO("phi = " << RadToDeg(phi));
    const std::array<double, 3> s = y(0, 0);
    if (sigma == 0) sigma = std::abs(s[0] - travel(phi, 1)) < std::abs(s[0] - travel(phi, -1)) ? 1 : -1;  // the branch, once
    const Scalar f = [&](double x) { return travel(x, sigma); };
    CHECK_THAT(s[0], Catch::Matchers::WithinAbs(f(phi), kExact));
    CHECK_THAT(s[1], Catch::Matchers::WithinAbs(D1(f, phi), kD1));
    CHECK_THAT(s[2], Catch::Matchers::WithinAbs(D2(f, phi), kD2));
  });
}

TEST_CASE("orders 0 and 1 write the leading columns of order 2's values", "[kernel][point-schedule-outputs]") {
  const Mechanism m = test::FourBar(1, 3, 2.5, 3.2, 1.5, 0.4, 1);
  Loaded loaded(m);
  PointSchedule& schedule = loaded.schedule;
  const PositionSolver& solver = loaded.solver;
  REQUIRE(schedule.Step(loaded.assembly.input + DegToRad(1.0)));
  std::vector<double> two(solver.OutputWidth(2)), one(solver.OutputWidth(1)), zero(solver.OutputWidth(0));
  schedule.OutputDerivatives(2, two.data());
  schedule.OutputDerivatives(1, one.data());
  schedule.OutputDerivatives(0, zero.data());
  for (int o = 0; o < static_cast<int>(m.outputs.size()); ++o)
    for (int c = 0; c < m.outputs[o].Components(); ++c) {
      for (int k = 0; k <= 1; ++k) CHECK(one[OutputColumn(m, o, c, 1) + k] == two[OutputColumn(m, o, c, 2) + k]);
      CHECK(zero[OutputColumn(m, o, c, 0)] == two[OutputColumn(m, o, c, 2)]);
    }
}

}  // namespace koppel::point_schedule_outputs_test
