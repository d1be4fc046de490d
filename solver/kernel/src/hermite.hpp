// A branch q(input) between two poses, as the polynomial that matches the branch's Taylor
// coefficients at both ends (two-point Hermite interpolation). Where the Jacobian is singular
// between them (a branch point), this is how koppel evaluates poses and transfer functions:
// both ends are well-conditioned, so their low-order coefficients are accurate, while a solve
// through J^-1 at the singular pose itself is not.
#pragma once

#include <Eigen/Core>

namespace koppel {

class HermiteSegment {
 public:
  HermiteSegment() = default;
  // c0: n x (m0 + 1) Taylor coefficients d^k q / d input^k / k! at input0; c1 the same at input1.
  // The polynomial has degree m0 + m1 + 1.
  HermiteSegment(double input0, const Eigen::MatrixXd& c0, double input1, const Eigen::MatrixXd& c1);

  bool empty() const { return a_.cols() == 0; }
  double from() const { return std::min(input0_, input0_ + h_); }
  double to() const { return std::max(input0_, input0_ + h_); }
  bool Contains(double input) const { return !empty() && input >= from() && input <= to(); }
  // The highest order of Taylor coefficient the ends fix on both sides.
  int ValidOrder() const { return valid_order_; }

  // Taylor coefficients d^k q / d input^k / k! at `input`, k = 0..order, into out (n x order+1).
  void Coefficients(double input, int order, Eigen::MatrixXd& out) const;

 private:
  double input0_ = 0.0, h_ = 1.0;
  int valid_order_ = 0;
  Eigen::MatrixXd a_;  // n x (degree + 1): coefficients in s = (input - input0) / h
};

}  // namespace koppel
