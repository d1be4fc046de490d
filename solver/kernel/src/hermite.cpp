#include "hermite.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace koppel {
namespace {

double Binomial(int n, int k) {
  if (k < 0 || k > n) return 0.0;
  double b = 1.0;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return b;
}

}  // namespace

HermiteSegment::HermiteSegment(double input0, const Eigen::MatrixXd& c0, double input1, const Eigen::MatrixXd& c1)
    : input0_(input0), h_(input1 - input0) {
  const int n = static_cast<int>(c0.rows());
  const int m0 = static_cast<int>(c0.cols()) - 1, m1 = static_cast<int>(c1.cols()) - 1;
  const int degree = m0 + m1 + 1;
  valid_order_ = std::min(m0, m1);
  a_.setZero(n, degree + 1);
  // in s = (input - input0) / h the k-th Taylor coefficient scales by h^k
  for (int k = 0; k <= m0; ++k) a_.col(k) = c0.col(k) * std::pow(h_, k);
  // at s = 1: sum_j C(j, k) a_j = c1_k h^k for k = 0..m1, for the unknown a_{m0+1} .. a_degree
  Eigen::MatrixXd system(m1 + 1, m1 + 1);
  Eigen::MatrixXd rhs(m1 + 1, n);
  for (int k = 0; k <= m1; ++k) {
    for (int j = 0; j <= m1; ++j) system(k, j) = Binomial(m0 + 1 + j, k);
    Eigen::VectorXd known = c1.col(k) * std::pow(h_, k);
    for (int j = 0; j <= m0; ++j) known -= Binomial(j, k) * a_.col(j);
    rhs.row(k) = known.transpose();
  }
  const Eigen::MatrixXd upper = system.fullPivLu().solve(rhs);
  for (int j = 0; j <= m1; ++j) a_.col(m0 + 1 + j) = upper.row(j).transpose();
}

void HermiteSegment::Coefficients(double input, int order, Eigen::MatrixXd& out) const {
  const int n = static_cast<int>(a_.rows()), degree = static_cast<int>(a_.cols()) - 1;
  out.setZero(n, order + 1);
  const double s = (input - input0_) / h_;
  for (int k = 0; k <= std::min(order, degree); ++k) {
    // the k-th Taylor coefficient of p at s, back in input units
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
    for (int j = k; j <= degree; ++j) b += Binomial(j, k) * std::pow(s, j - k) * a_.col(j);
    out.col(k) = b / std::pow(h_, k);
  }
}

}  // namespace koppel
