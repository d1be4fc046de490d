// CheckJacobian and FiniteDifferenceJacobian (solver/kernel/src/jacobian_check.cpp): the checker
// must accept the analytic Jacobian, reject one wrong entry and name where it is, and its
// finite differences must equal a hand-written central difference.
#include "koppel/solver/jacobian_check.hpp"

#include "koppel/solver/constraints.hpp"
#include "koppel/solver/position.hpp"
#include "support/mechanisms.hpp"
#include "tolerances.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace koppel::jacobian_check_test {
namespace {

// A crank-rocker (a 1, coupler 3, rocker 2.5, frame 3.2) with a coupler point: three moving links.
Mechanism CrankRocker() { return test::FourBar(1.0, 3.0, 2.5, 3.2, 1.5, 0.4, 1); }

// A configuration away from any pose: the check is of dF/dq, which exists everywhere.
Eigen::VectorXd RandomConfiguration(int n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  Eigen::VectorXd q(n);
  for (int i = 0; i < n; ++i) q[i] = u(random);
  return q;
}

// Central differences with h = 1e-6 max(1, |x|): the header's promise is error O(h^2) + O(eps/h),
// so 1e-7 relative to max(1, |J|) (tolerances.hpp, kJacobianFd).
constexpr double kCheck = test::kJacobianFd;
// A deliberately wrong entry: 1e-3 is 1e4 times the check's tolerance, so it must be found.
constexpr double kWrongBy = 1e-3;

TEST_CASE("the analytic Jacobian agrees at random configurations", "[jacobian_check]") {
  const Mechanism m = CrankRocker();
  const ConstraintSystem system(m);
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const Eigen::VectorXd q = RandomConfiguration(system.NumCoordinates(), seed);
    const JacobianCheckResult r = CheckJacobian(system, q.data(), 0.3 * seed, kCheck);
    CHECK(r.ok());
    CHECK(r.max_rel_error <= kCheck);
    CHECK(r.max_abs_error <= r.max_rel_error * 1e3);  // |J| entries are O(lengths) <= O(10)
    CHECK_THAT(r.Brief(), Catch::StartsWith("agrees: relative error"));
  }
}

TEST_CASE("one wrong entry is rejected and located", "[jacobian_check]") {
  const Mechanism m = CrankRocker();
  const ConstraintSystem system(m);
  const Eigen::VectorXd q = RandomConfiguration(system.NumCoordinates(), 11);
  Eigen::MatrixXd jacobian(system.NumEquations(), system.NumCoordinates());
  system.Jacobian(q.data(), jacobian);
  const int row = 2, col = system.NumCoordinates() - 1;
  jacobian(row, col) += kWrongBy;
  const JacobianCheckResult r = CheckJacobian(system, q.data(), 0.0, jacobian, kCheck);
  CHECK_FALSE(r.ok());
  CHECK(r.status == JacobianCheckStatus::kDisagrees);
  CHECK(r.worst_row == row);
  CHECK(r.worst_col == col);
  // the reported error is the injected one, up to the finite differences' own error
  CHECK_THAT(r.max_abs_error, Catch::Matchers::WithinAbs(kWrongBy, kCheck));
  CHECK_THAT(r.Brief(), Catch::Contains("disagrees") && Catch::Contains("equation 2") &&
                            Catch::Contains("coordinate " + std::to_string(col)));
}

TEST_CASE("the finite differences are the central differences of the residuals", "[jacobian_check]") {
  // reference: the same central difference written out by hand for each column, step
  // h = 1e-6 max(1, |q_i|) as the header documents; the two must agree to roundoff of the division.
  const Mechanism m = CrankRocker();
  const ConstraintSystem system(m);
  const int n = system.NumCoordinates(), rows = system.NumEquations();
  Eigen::VectorXd q = RandomConfiguration(n, 3);
  q[0] = 250.0;  // a large coordinate: its step is scaled with |q|
  const double input = 0.7;
  const Eigen::MatrixXd fd = FiniteDifferenceJacobian(system, q.data(), input);
  REQUIRE(fd.rows() == rows);
  REQUIRE(fd.cols() == n);
  for (int i = 0; i < n; ++i) {
    const double h = 1e-6 * std::max(1.0, std::abs(q[i]));
    Eigen::VectorXd plus = q, minus = q, r_plus(rows), r_minus(rows);
    plus[i] += h;
    minus[i] -= h;
    system.Residuals(plus.data(), input, r_plus.data());
    system.Residuals(minus.data(), input, r_minus.data());
    const Eigen::VectorXd column = (r_plus - r_minus) / (2 * h);
    for (int r = 0; r < rows; ++r) CHECK(fd(r, i) == column[r]);  // the same arithmetic: identical
  }
}

TEST_CASE("a check not run says so", "[jacobian_check]") {
  const JacobianCheckResult r;
  CHECK_FALSE(r.ok());
  CHECK(r.Brief() == "not run");
}

}  // namespace
}  // namespace koppel::jacobian_check_test
