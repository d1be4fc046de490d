// Limit points located to roundoff on the augmented system (issue 22, item 4): the triple-rocker's
// limits on its crossed branch, and a slider-crank's, against the triangle inequality (law of
// cosines); a sample 1e-9 deg inside a limit is served, one 1e-9 deg beyond it is not, and one on
// the point itself gets the pose there, flagged singular, with no transfer function.
#include "koppel/solver/continuation.hpp"
#include "koppel/solver/singular.hpp"
#include "koppel/solver/sweep.hpp"

#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::limit_point_test {
namespace {

// The limit's input against the closed form: roundoff, 1e-13 relative (the figure; the
// closed form's own acos is good to a few 1e-16).
constexpr double kLimitLocation = 1e-13;
// psi next to a fold against the closed form: the closed form's square root of a discriminant
// near 0 loses half the digits (sqrt(1e-16) = 1e-8).
constexpr double kPoseNearFold = 1e-7;

SweepOptions At(double input) {
  SweepOptions o;
  o.from = o.to = input;
  o.step = DegToRad(1);
  o.order = 2;
  return o;
}

// The non-Grashof four-bar of catalog/entries/triple-rocker.yaml (3, 4, 2.5, 5), assembled on
// its crossed branch (B below the frame line at phi = 0): it swings between -phi_G and phi_G,
// cos phi_G = (a^2 + d^2 - (b + c)^2) / (2 a d) (coupler and rocker extended).
struct CrossedTripleRocker {
  double a = 3, b = 4, c = 2.5, d = 5;
  double phi_g = std::acos((a * a + d * d - (b + c) * (b + c)) / (2 * a * d));
  Mechanism m = test::PlainFourBar(a, b, c, d, 0.0, test::FourBarRocker(a, b, c, d, 0.0, -1)->b);
};

}  // namespace

TEST_CASE("a limit point is located on the augmented system to roundoff", "[continuation][limit]") {
  const CrossedTripleRocker f;
  PositionSolver solver(f.m);
  Eigen::VectorXd q(solver.NumCoordinates());
  // a converged pose 1e-6 rad short of the limit, as a walk stalls there
  const double start = f.phi_g - 1e-6;
  REQUIRE(solver.Assemble(q).ok());
  Continuation path(solver);
  REQUIRE(path.Start(0.0, q).ok());
  REQUIRE(path.AdvanceTo(start, 0.05).ok());
  const std::optional<LimitPoint> limit = LocateLimitPoint(solver.system(), start, path.q());
  REQUIRE(limit);
  CHECK(std::abs(limit->input - f.phi_g) <= kLimitLocation * f.phi_g);
  CHECK(limit->iterations <= 10);
  // the branch lies below the limit: input(s) = phi_G + curvature s^2 with curvature < 0
  CHECK(limit->curvature < 0);
  // J null = 0: the pose is singular, and the mechanism moves there with the drive held
  CHECK(ReciprocalCondition(solver.system(), limit->q) < 1e-12);
}

TEST_CASE("the crossed triple-rocker is served 1e-9 deg inside its limits, not 1e-9 deg beyond", "[continuation][limit]") {
  const CrossedTripleRocker f;
  const double inside = DegToRad(1e-9);
  const int psi = OutputColumn(f.m, 0, 0, 2);
  for (double limit : {f.phi_g, -f.phi_g}) {
    const double toward = limit > 0 ? -1.0 : 1.0;
    INFO("limit " << RadToDeg(limit) << " deg");
    const SweepResult served = Sweep(f.m, At(limit + toward * inside));
    REQUIRE(served.complete());
    REQUIRE(served.inputs.size() == 1);
    CHECK(std::abs(AngleDifference(served.outputs(0, psi), test::FourBarRocker(f.a, f.b, f.c, f.d, served.inputs[0], -1)->psi)) <
          kPoseNearFold);
    const SweepResult refused = Sweep(f.m, At(limit - toward * inside));
    CHECK(refused.status == SweepStatus::kPartial);
    CHECK(refused.inputs.empty());
    REQUIRE(refused.singular_points.size() == 1);
    CHECK(refused.singular_points[0].kind == SingularKind::kLimitPoint);
    CHECK(std::abs(refused.singular_points[0].input - limit) <= kLimitLocation * f.phi_g);
    // the walk ends on the point: the drivable part reaches it to roundoff
    CHECK(std::abs((limit > 0 ? refused.reached.to : refused.reached.from) - limit) <= kLimitLocation * f.phi_g);
  }
}

TEST_CASE("a sample on a limit point gets the pose there, flagged singular, without transfer functions", "[continuation][limit]") {
  const CrossedTripleRocker f;
  PositionSolver solver(f.m);
  Eigen::VectorXd q(solver.NumCoordinates());
  REQUIRE(solver.Assemble(q).ok());
  Continuation path(solver);
  REQUIRE(path.Start(0.0, q).ok());
  const WalkReport beyond = path.AdvanceTo(2.0, 0.05);
  REQUIRE(beyond.status == WalkStatus::kLimitPoint);
  const double located = beyond.input;
  CHECK(std::abs(located - f.phi_g) <= kLimitLocation * f.phi_g);
  // standing on the point, the walk is at its own input; the pose closes every joint
  REQUIRE(path.AdvanceTo(located, 0.05).ok());
  CHECK(path.AtSingularPose());
  CHECK(path.ValidOrder() == 0);
  CHECK(std::abs(AngleDifference(path.q()(8), test::FourBarRocker(f.a, f.b, f.c, f.d, f.phi_g - 1e-15, -1)->psi)) < kPoseNearFold);
  // and it walks back from there
  REQUIRE(path.AdvanceTo(0.0, 0.05).ok());
  CHECK(!path.AtSingularPose());
  // a sweep with a sample on the point: the row is there, flagged, its derivatives not computable
  const SweepResult r = Sweep(f.m, At(located));
  REQUIRE(r.complete());
  CHECK(r.singular[0] == 1);
  CHECK(r.valid_order[0] == 0);
}

TEST_CASE("a slider-crank's limits (rod shorter than crank plus offset) to roundoff", "[continuation][limit]") {
  // seed 000 conventions, l2 < l1 + e: the rod reaches the slide line only while |A_y| <= l2;
  // its limits from |e + l1 cos phi| = l2 (test::SliderCrankLimits)
  const double l1 = 1, l2 = 0.9, e = 0.5;
  Mechanism m = test::SliderCrank(l1, l2, e);
  m.hint.input = kPi / 2;  // A = (l1, -e): the rod reaches the slide line
  m.hint.points[0].global = {l1 + std::sqrt(l2 * l2 - e * e), 0};
  const std::vector<double> limits = test::SliderCrankLimits(l1, l2, e);
  SweepOptions o;
  o.from = 0;
  o.to = 2 * kPi;
  o.step = DegToRad(1);
  const SweepResult r = Sweep(m, o);
  REQUIRE(!r.singular_points.empty());
  for (const SingularPoint& p : r.singular_points) {
    INFO("limit at " << RadToDeg(p.input) << " deg");
    CHECK(p.kind == SingularKind::kLimitPoint);
    double nearest = 1e9;
    for (double l : limits) nearest = std::min(nearest, std::abs(AngleDifference(p.input, l)));
    CHECK(nearest <= kLimitLocation * std::max(1.0, std::abs(p.input)));
  }
}

}  // namespace koppel::limit_point_test

namespace koppel::limit_point_test {
namespace {

// A value with its first and second derivative in long double: the reference psi'' below, by
// the chain rule through the closed form (no differencing).
struct Jet {
  long double v = 0, d1 = 0, d2 = 0;
};
Jet operator+(Jet x, Jet y) { return {x.v + y.v, x.d1 + y.d1, x.d2 + y.d2}; }
Jet operator-(Jet x, Jet y) { return {x.v - y.v, x.d1 - y.d1, x.d2 - y.d2}; }
Jet operator*(Jet x, Jet y) { return {x.v * y.v, x.d1 * y.v + x.v * y.d1, x.d2 * y.v + 2 * x.d1 * y.d1 + x.v * y.d2}; }
Jet Constant(long double c) { return {c, 0, 0}; }
Jet Inverse(Jet x) {
  const long double i = 1 / x.v;
  return {i, -x.d1 * i * i, (2 * x.d1 * x.d1 * i - x.d2) * i * i};
}
Jet Sqrt(Jet x) {
  const long double r = std::sqrt(x.v);
  return {r, x.d1 / (2 * r), (x.d2 - x.d1 * x.d1 / (2 * x.v)) / (2 * r)};
}
// atan2(y, x): its derivative (x y' - y x') / (x^2 + y^2), differentiated once more
Jet Atan2(Jet y, Jet x) {
  const long double r2 = x.v * x.v + y.v * y.v;
  const long double n1 = x.v * y.d1 - y.v * x.d1, n1d = x.v * y.d2 - y.v * x.d2;  // (x y' - y x')'
  const long double r2d = 2 * (x.v * x.d1 + y.v * y.d1);
  return {std::atan2(y.v, x.v), n1 / r2, (n1d * r2 - n1 * r2d) / (r2 * r2)};
}

// The rocker angle of the four-bar A0 = 0, B0 = (d, 0) with its derivatives in the crank angle:
// B = A + (x r + side h r_perp) / rho, r = B0 - A, x = (b^2 - c^2 + rho^2) / (2 rho), h^2 = b^2 - x^2.
Jet RockerAngle(long double a, long double b, long double c, long double d, long double phi, int side) {
  const Jet ax{a * std::cos(phi), -a * std::sin(phi), -a * std::cos(phi)}, ay{a * std::sin(phi), a * std::cos(phi), -a * std::sin(phi)};
  const Jet rx = Constant(d) - ax, ry = Constant(0) - ay;
  const Jet rho2 = rx * rx + ry * ry, per_rho = Inverse(Sqrt(rho2));
  const Jet x = (Constant(b * b - c * c) + rho2) * per_rho * Constant(0.5L);
  const Jet h = Constant(side) * Sqrt((Constant(b) - x) * (Constant(b) + x));
  const Jet bx = ax + (x * rx - h * ry) * per_rho, by = ay + (x * ry + h * rx) * per_rho;
  return Atan2(by, bx - Constant(d));
}

}  // namespace

// A row of a sweep next to a limit point was once less exact than the same row alone (psi'' 1e-8
// relative off where one solve gives 1e-14): both against psi'' by the chain rule in long double.
// psi'' grows like 1/g^3 towards the fold (g ~ sqrt of the distance), and a row carries roundoff
// over g^2 relative: 1e-10 at 0.001 deg.
TEST_CASE("rows next to a limit point are as exact in a sweep as alone", "[continuation][limit]") {
  const CrossedTripleRocker t;
  const Mechanism& m = t.m;
  const int psi = OutputColumn(m, 0, 0, 2);
  for (double inside_deg : {0.1, 0.0101, 0.001}) {
    const double x = t.phi_g - DegToRad(inside_deg);
    const Jet reference = RockerAngle(t.a, t.b, t.c, t.d, x, -1);
    SweepOptions sweep = At(x);
    sweep.from = x - DegToRad(60);
    const SweepResult walked = Sweep(m, sweep), alone = Sweep(m, At(x));
    REQUIRE(walked.complete());
    REQUIRE(alone.complete());
    INFO(inside_deg << " deg inside the limit: psi'' = " << static_cast<double>(reference.d2));
    const int last = static_cast<int>(walked.inputs.size()) - 1;
    REQUIRE(walked.inputs[last] == x);
    for (const SweepResult* r : {&walked, &alone}) {
      const int row = r == &walked ? last : 0;
      CHECK(std::abs(r->outputs(row, psi + 1) - static_cast<double>(reference.d1)) <= 1e-11 * std::abs(static_cast<double>(reference.d1)));
      CHECK(std::abs(r->outputs(row, psi + 2) - static_cast<double>(reference.d2)) <= 1e-10 * std::abs(static_cast<double>(reference.d2)));
    }
  }
}

}  // namespace koppel::limit_point_test
