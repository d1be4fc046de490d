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
