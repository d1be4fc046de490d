#include "koppel/solver/jacobian_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace koppel {

Eigen::MatrixXd FiniteDifferenceJacobian(const ConstraintSystem& system, const double* q, double input) {
  const int n = system.NumCoordinates(), m = system.NumEquations();
  Eigen::MatrixXd fd(m, n);
  std::vector<double> x(q, q + n);
  Eigen::VectorXd plus(m), minus(m);
  for (int i = 0; i < n; ++i) {
    const double h = 1e-6 * std::max(1.0, std::abs(q[i]));
    x[i] = q[i] + h;
    system.Residuals(x.data(), input, plus.data());
    x[i] = q[i] - h;
    system.Residuals(x.data(), input, minus.data());
    x[i] = q[i];
    fd.col(i) = (plus - minus) / (2.0 * h);
  }
  return fd;
}

JacobianCheckResult CheckJacobian(const ConstraintSystem& system, const double* q, double input,
                                  const Eigen::MatrixXd& jacobian, double tolerance) {
  const Eigen::MatrixXd fd = FiniteDifferenceJacobian(system, q, input);
  JacobianCheckResult result;
  for (int r = 0; r < fd.rows(); ++r) {
    for (int c = 0; c < fd.cols(); ++c) {
      const double error = std::abs(jacobian(r, c) - fd(r, c));
      const double relative = error / std::max(1.0, std::abs(fd(r, c)));
      if (relative > result.max_rel_error || result.worst_row < 0) {
        result.max_rel_error = relative;
        result.worst_row = r;
        result.worst_col = c;
      }
      result.max_abs_error = std::max(result.max_abs_error, error);
    }
  }
  result.status = result.max_rel_error <= tolerance ? JacobianCheckStatus::kAgrees : JacobianCheckStatus::kDisagrees;
  return result;
}

std::string JacobianCheckResult::Brief() const {
  if (status == JacobianCheckStatus::kNotRun) return "not run";
  char text[160];
  std::snprintf(text, sizeof text, "%s: relative error %.1e at equation %d, coordinate %d",
                ok() ? "agrees" : "disagrees", max_rel_error, worst_row, worst_col);
  return text;
}

JacobianCheckResult CheckJacobian(const ConstraintSystem& system, const double* q, double input, double tolerance) {
  Eigen::MatrixXd jacobian(system.NumEquations(), system.NumCoordinates());
  system.Jacobian(q, jacobian);
  return CheckJacobian(system, q, input, jacobian, tolerance);
}

}  // namespace koppel
