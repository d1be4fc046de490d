// The analytic Jacobian of every residual type (R, P, R drive, P drive, P between moving links)
// against central finite differences, at random poses from a fixed seed and at degenerate ones;
// and a deliberately wrong Jacobian that the checker must reject.
#include "koppel/solver/constraints.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/jacobian_check.hpp"
#include "solver/kernel/tolerances.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <random>
#include <string>

namespace koppel {
namespace {

// A slide-driven mechanism: the P drive row.
Mechanism SlideDriven() {
  Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  m.drive.joint = m.FindJoint("S");
  return m;
}

void CheckAt(const ConstraintSystem& system, const Eigen::VectorXd& q, double input) {
  const JacobianCheckResult r = CheckJacobian(system, q.data(), input, test::kJacobianFd);
  INFO("worst entry (" << r.worst_row << ", " << r.worst_col << "): relative error " << r.max_rel_error);
  CHECK(r.ok());
}

}  // namespace

TEST_CASE("analytic Jacobian matches central differences at random and degenerate poses", "[constraints]") {
  const std::vector<Mechanism> mechanisms = {test::SliderCrank(1.0, 2.6, 0.8), test::ProportionalLinkage(1.0, 0.5, 1.83),
                                             test::FourBar(1.0, 2.5 * std::sqrt(3.0), 2.5 * std::sqrt(3.0), 4.0, 25.0 / 3, 0.2756, 1),
                                             test::WattSixBar(), SlideDriven()};
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0), angle(-kPi, kPi);
  for (const Mechanism& m : mechanisms) {
    INFO(m.name << (m.InputIsAngle() ? "" : " (slide drive)"));
    const ConstraintSystem system(m);
    Eigen::VectorXd q(system.NumCoordinates());
    for (int trial = 0; trial < 25; ++trial) {
      for (int i = 0; i < q.size(); ++i) q(i) = (i % 3 == 2) ? angle(rng) : coordinate(rng);
      CheckAt(system, q, angle(rng));
    }
    // degenerate poses: every link at the origin with the same angle (links aligned, joint points
    // coincident, zero residuals). Not exactly +-pi: there the wrap-safe rotation residual has its
    // branch cut and no finite difference is valid; 1e-3 short of it the derivative must hold.
    for (double theta : {0.0, kPi / 2, -kPi / 2, kPi - 1e-3, -kPi + 1e-3}) {
      for (int i = 0; i < q.size(); ++i) q(i) = (i % 3 == 2) ? theta : 0.0;
      CheckAt(system, q, theta);
    }
  }
}

TEST_CASE("the Jacobian checker rejects a wrong Jacobian", "[constraints]") {
  const Mechanism m = test::ProportionalLinkage(1.0, 0.5, 1.83);
  const ConstraintSystem system(m);
  Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(system.NumCoordinates(), -1.0, 2.0);
  Eigen::MatrixXd jacobian(system.NumEquations(), system.NumCoordinates());
  system.Jacobian(q.data(), jacobian);
  REQUIRE(CheckJacobian(system, q.data(), 0.3, jacobian, test::kJacobianFd).ok());
  // one entry off by 1e-4 (far above the FD error, far below the entry's size): caught
  const int row = system.FirstRowOf(m.FindJoint("S34")), col = system.CoordinateOf(m.FindLink("slot")) + 2;
  REQUIRE(jacobian(row, col) != 0.0);
  jacobian(row, col) += 1e-4;
  const JacobianCheckResult r = CheckJacobian(system, q.data(), 0.3, jacobian, test::kJacobianFd);
  CHECK_FALSE(r.ok());
  CHECK(r.worst_row == row);
  CHECK(r.worst_col == col);
  char error[32];
  std::snprintf(error, sizeof error, "%.1e", r.max_rel_error);
  CHECK(r.Brief() == "disagrees: relative error " + std::string(error) + " at equation " + std::to_string(row) +
                         ", coordinate " + std::to_string(col));
  CHECK(JacobianCheckResult().Brief() == "not run");
  // a sign error in a whole column: caught too
  system.Jacobian(q.data(), jacobian);
  jacobian.col(0) = -jacobian.col(0);
  CHECK_FALSE(CheckJacobian(system, q.data(), 0.3, jacobian, test::kJacobianFd).ok());
}

TEST_CASE("rotation residuals are wrap-safe: a full turn is no residual", "[constraints]") {
  const Mechanism m = test::SliderCrank(1.0, 2.6, 0.0);
  const ConstraintSystem system(m);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(system.NumCoordinates());
  Eigen::VectorXd r0(system.NumEquations()), r1(system.NumEquations());
  q(2) = 0.4;  // crank angle
  system.Residuals(q.data(), 0.4, r0.data());
  q(2) = 0.4 + 2 * kPi;
  system.Residuals(q.data(), 0.4, r1.data());
  CHECK(std::abs(r0(system.DriveRow())) < 1e-15);
  CHECK(std::abs(r1(system.DriveRow())) < 1e-12);
}

}  // namespace koppel
