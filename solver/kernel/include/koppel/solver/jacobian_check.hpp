// Checks a Jacobian of the position equations against central finite differences, in the
// spirit of Ceres' GradientChecker: public, so users of custom joints can prove theirs, and
// tested with a deliberately wrong Jacobian that it must reject.
#pragma once

#include "koppel/solver/constraints.hpp"

#include <Eigen/Core>

#include <string>

namespace koppel {

enum class JacobianCheckStatus {
  kNotRun,
  kAgrees,     // max_rel_error <= tolerance
  kDisagrees,  // some entry is further from the finite difference than the tolerance
};

struct JacobianCheckResult {
  JacobianCheckStatus status = JacobianCheckStatus::kNotRun;
  double max_abs_error = 0.0;  // largest |J - J_fd| entry
  double max_rel_error = 0.0;  // that error over max(1, |J_fd| entry)
  int worst_row = -1;
  int worst_col = -1;
  bool ok() const { return status == JacobianCheckStatus::kAgrees; }
  // e.g. "disagrees: relative error 3.1e-02 at equation 4, coordinate 7"
  std::string Brief() const;
};

// Central differences of ConstraintSystem::Residuals with step h = 1e-6 * max(1, |q_i|)
// (truncation error O(h^2) ~ 1e-12 against roundoff O(eps/h) ~ 1e-10), compared with `jacobian`.
JacobianCheckResult CheckJacobian(const ConstraintSystem& system, const double* q, double input,
                                  const Eigen::MatrixXd& jacobian, double tolerance);
// The same for the system's own analytic Jacobian.
JacobianCheckResult CheckJacobian(const ConstraintSystem& system, const double* q, double input, double tolerance);

// The finite-difference Jacobian itself (NumEquations x NumCoordinates).
Eigen::MatrixXd FiniteDifferenceJacobian(const ConstraintSystem& system, const double* q, double input);

}  // namespace koppel
