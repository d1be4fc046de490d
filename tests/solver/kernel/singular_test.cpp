// Classification of singular positions from the Jacobian alone, at poses built by hand from the
// geometry: the parallelogram's change point is a branch point carried by its whole loop; a
// rocker-driven crank-rocker at its dead centre is a limit point; the other branch's tangent at
// a change point is the antiparallelogram's, from its closed form tan(psi/2) = k tan(phi/2).
#include "koppel/solver/singular.hpp"

#include "koppel/solver/position.hpp"

#include "koppel/core/angles.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

namespace koppel::singular_test {
namespace {

// the other branch's tangent from an SVD of an exact O(1) Jacobian at the branch point: rounding only
constexpr double kTangent = 1e-12;

// The parallelogram 1, 3, 1, 3 with every link lined up along x at phi = pi: crank (0, 0, pi),
// coupler from A = (-1, 0) at angle 0, rocker from B0 = (3, 0) at angle pi.
Eigen::VectorXd FlatParallelogram() {
  Eigen::VectorXd q(9);
  q << 0, 0, kPi, -1, 0, 0, 3, 0, kPi;
  return q;
}

}  // namespace

TEST_CASE("the parallelogram's change point is a branch point of the whole loop", "[singular]") {
  const Mechanism m = test::PlainFourBar(1, 3, 1, 3, kPi, {2, 0});
  const ConstraintSystem system(m);
  const Eigen::VectorXd q = FlatParallelogram();
  Eigen::VectorXd r(system.NumEquations());
  system.Residuals(q.data(), kPi, r.data());
  REQUIRE(r.cwiseAbs().maxCoeff() < 1e-15);  // the hand-built pose closes every joint
  const SingularStructure s = AnalyseSingularity(system, q);
  CHECK(s.kind == SingularKind::kBranchPoint);
  CHECK(s.rcond < 1e-15);
  CHECK(s.constraint_rcond < 1e-15);
  CHECK(s.joints == std::vector<int>{0, 1, 2, 3});
  // the other branch: the antiparallelogram, psi' = k / (cos^2(phi/2) + k^2 sin^2(phi/2)) = 1/k at
  // phi = pi with k = (a + d)/(a - d) = -2 (continuation_test.cpp derives it)
  Eigen::VectorXd tangent(9);  // the parallelogram's: crank and rocker turn alike, the coupler translates
  tangent << 0, 0, 1, 0, -1, 0, 0, 0, 1;
  const std::optional<Eigen::VectorXd> other = OtherBranchTangent(system, q, kPi, tangent);
  REQUIRE(other);
  CHECK((*other)(2) == Approx(1.0).margin(kTangent));   // the drive keeps its rate
  CHECK((*other)(8) == Approx(-0.5).margin(kTangent));  // psi' of the antiparallelogram
  // and it is a tangent of the position equations: J t = -dF/dinput
  Eigen::MatrixXd jacobian(9, 9);
  system.Jacobian(q.data(), jacobian);
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(9);
  expected(system.DriveRow()) = -system.InputColumn();
  CHECK((jacobian * *other - expected).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("a rocker-driven crank-rocker at its dead centre is a limit point; a regular pose is neither", "[singular]") {
  // crank 1, coupler 3, rocker 2.5, frame 3.5, driven at the rocker: it stops where crank and
  // coupler line up (A0 B = 4), B above the frame line
  const double b0b = 2.5, d = 3.5;
  const double cos_at_b0 = (d * d + b0b * b0b - 16.0) / (2 * d * b0b);
  const double psi = kPi - std::acos(cos_at_b0);
  const Eigen::Vector2d b(d + b0b * std::cos(psi), b0b * std::sin(psi));
  const double theta = std::atan2(b.y(), b.x());  // crank and coupler both along A0 -> B
  const Mechanism m = test::PlainFourBar(1, 3, b0b, d, psi, b, true);
  const ConstraintSystem system(m);
  Eigen::VectorXd q(9);
  q << 0, 0, theta, std::cos(theta), std::sin(theta), theta, d, 0, psi;
  Eigen::VectorXd r(system.NumEquations());
  system.Residuals(q.data(), psi, r.data());
  REQUIRE(r.cwiseAbs().maxCoeff() < 1e-14);
  const SingularStructure s = AnalyseSingularity(system, q);
  CHECK(s.kind == SingularKind::kLimitPoint);
  CHECK(s.rcond < 1e-14);
  CHECK(s.constraint_rcond > 1e-3);  // the mechanism without its drive moves freely there
  CHECK(std::find(s.joints.begin(), s.joints.end(), 3) != s.joints.end());  // the drive joint B0 holds the load

  // a regular pose of the same mechanism, assembled away from the dead centre
  Mechanism away = m;
  away.hint.input = psi + 0.3;  // the rocker swings from 98.2 deg (A0B = 4) to 146 deg (A0B = 2)
  PositionSolver solver(away);
  Eigen::VectorXd regular(9);
  REQUIRE(solver.Assemble(regular).ok());
  CHECK(ReciprocalCondition(solver.system(), regular) > 1e-3);
}

TEST_CASE("branch-point actions read and print", "[singular]") {
  for (BranchPointAction a : {BranchPointAction::kContinue, BranchPointAction::kStop, BranchPointAction::kSwitch})
    CHECK(ParseBranchPointAction(ToString(a)) == a);
  CHECK_FALSE(ParseBranchPointAction("jump"));
  CHECK(std::string(ToString(SingularKind::kBranchPoint)) == "branch-point");
  CHECK(std::string(ToString(SingularKind::kLimitPoint)) == "limit");
}

}  // namespace koppel::singular_test

namespace koppel::singular_test {

// The bifurcation system's defect: a four-bar's flat pose carries the self-stress of an axial force
// through all four pins (psi's x rows +-1/2), so closing the joints up to sigma psi leaves each
// pin open by sigma / 2 along the line, and the loop's misfit b + c - (a + d) = 4 sigma / 2.
TEST_CASE("a branch point is located where the dimensions reach a flat pose, and its defect measures how far they miss",
          "[singular]") {
  {
    const Mechanism m = test::PlainFourBar(1, 3, 1, 3, kPi, {2, 0});
    const ConstraintSystem system(m);
    Eigen::VectorXd q = FlatParallelogram();
    q(2) += 1e-4;  // a pose near the point: Newton finds it
    const std::optional<BranchPoint> point = LocateBranchPoint(system, kPi + 1e-4, q);
    REQUIRE(point);
    CHECK(point->defect < 1e-15);
    CHECK(std::abs(point->input - kPi) < 1e-12);
    CHECK(point->iterations <= 10);
  }
  for (double misfit : {1e-3, 1e-6, -1e-6, 1e-9}) {
    // b + c = a + d + misfit, flat (extended) at phi = pi: start from the walk's pose there
    const double a = 1, c = 3, d = 4, b = a + d - c + misfit;
    const auto rocker = test::FourBarRocker(a, b, c, d, kPi - 0.01, 1);
    REQUIRE(rocker);
    const Mechanism m = test::PlainFourBar(a, b, c, d, kPi - 0.01, rocker->b);
    PositionSolver solver(m);
    Eigen::VectorXd q(solver.NumCoordinates());
    REQUIRE(solver.Assemble(q).ok());
    const std::optional<BranchPoint> point = LocateBranchPoint(solver.system(), kPi - 0.01, q);
    INFO("misfit " << misfit);
    REQUIRE(point);
    CHECK(point->defect * solver.system().length_scale() == Approx(std::abs(misfit) / 2).epsilon(1e-6));
    CHECK(std::abs(point->input - kPi) < 1e-6);
  }
  {
    // a crank-rocker far from its change point has no flat pose near: none, or a large defect
    const Mechanism m = test::PlainFourBar(1, 3, 3, 3.5, 2.0, {3, 2.5});
    PositionSolver solver(m);
    Eigen::VectorXd q(solver.NumCoordinates());
    REQUIRE(solver.Assemble(q).ok());
    const std::optional<BranchPoint> point = LocateBranchPoint(solver.system(), 2.0, q);
    CHECK((!point || point->defect > 1e-3));
  }
}

}  // namespace koppel::singular_test
