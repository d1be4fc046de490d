// The branch-point window's interpolant: two-point Hermite interpolation reproduces a polynomial
// of its degree exactly (coefficients, derivatives, any point between), and takes unequal orders
// at its two ends.
#include "hermite.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::hermite_test {
namespace {

// p(x) = sum c_k x^k for two components, and its Taylor coefficients at x0 (d^k p / dx^k / k!).
Eigen::MatrixXd TaylorAt(const Eigen::MatrixXd& c, double x0, int order) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(c.rows(), order + 1);
  for (int k = 0; k <= order; ++k) {
    for (int j = k; j < c.cols(); ++j) {
      double binomial = 1;
      for (int i = 1; i <= k; ++i) binomial = binomial * (j - k + i) / i;
      out.col(k) += binomial * std::pow(x0, j - k) * c.col(j);
    }
  }
  return out;
}

}  // namespace

TEST_CASE("Hermite segment reproduces a degree-7 polynomial from its coefficients up to order 3 at both ends", "[hermite]") {
  Eigen::MatrixXd c(2, 8);
  c << 0.3, -1.2, 0.5, 2.0, -0.7, 0.1, 0.9, -0.4,
       1.0, 0.0, -2.0, 0.3, 0.8, -1.5, 0.2, 0.05;
  const double x0 = -0.02, x1 = 0.03;
  const HermiteSegment h(x0, TaylorAt(c, x0, 3), x1, TaylorAt(c, x1, 3));
  CHECK(h.ValidOrder() == 3);
  CHECK(h.Contains(0.0));
  CHECK_FALSE(h.Contains(0.031));
  Eigen::MatrixXd got;
  for (double x : {-0.02, -0.011, 0.0, 0.004, 0.03}) {
    h.Coefficients(x, 7, got);
    const Eigen::MatrixXd want = TaylorAt(c, x, 7);
    INFO("x = " << x);
    // exact up to roundoff amplified by 1/h^k for the k-th coefficient (h = 0.05)
    for (int k = 0; k <= 7; ++k) CHECK((got.col(k) - want.col(k)).cwiseAbs().maxCoeff() < 1e-13 * std::pow(20.0, k));
  }
}

TEST_CASE("Hermite segment with orders 1 and 3 at its ends (the switch to another branch)", "[hermite]") {
  Eigen::MatrixXd c(1, 6);
  c << 0.1, 1.0, -0.5, 0.25, 0.3, -0.2;  // degree 5 = 1 + 3 + 1
  const HermiteSegment h(0.0, TaylorAt(c, 0.0, 1), 0.1, TaylorAt(c, 0.1, 3));
  CHECK(h.ValidOrder() == 1);
  Eigen::MatrixXd got;
  h.Coefficients(0.05, 2, got);
  CHECK((got - TaylorAt(c, 0.05, 2)).cwiseAbs().maxCoeff() < 1e-12);
}

}  // namespace koppel::hermite_test
