#include "koppel/solver/singular.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>

namespace koppel {
namespace {

// The augmented Newton of LocateLimitPoint: at most this many iterations (it converges
// quadratically in about five from a stalled walk); it stops when a step changes no unknown by
// more than kLimitStep (in units of L, rad and the scaled null vector's unit), or when two
// steps in a row no longer shrink (roundoff reached).
constexpr int kLimitIterations = 30;
constexpr double kLimitStep = 1e-15;
// A located limit point must close the joints to this (times L) and its null vector to this:
// a few hundred ulps, as NewtonOptions::tolerance.
constexpr double kLimitResidual = 1e-12;

// A joint's share of a left singular vector below this fraction of the largest counts as zero:
// the vector is exact to about 1e-10 at a located singular point.
constexpr double kSingularJointShare = 1e-4;

Eigen::VectorXd ColumnScale(const ConstraintSystem& system) {
  Eigen::VectorXd scale = Eigen::VectorXd::Ones(system.NumCoordinates());
  for (int i = 2; i < scale.size(); i += 3) scale(i) = 1.0 / system.length_scale();
  return scale;
}

double Ratio(double small, double large) { return large > 0.0 ? small / large : 0.0; }

// Joints whose constraint rows (and the drive joint, for the drive row) carry a share of `rows`.
std::vector<int> JointsOf(const ConstraintSystem& system, const Eigen::VectorXd& rows) {
  const int n_joints = static_cast<int>(system.mechanism().joints.size());
  std::vector<double> share(n_joints, 0.0);
  for (int k = 0; k < n_joints; ++k) share[k] = rows.segment(system.FirstRowOf(k), 2).norm();
  if (rows.size() > system.DriveRow()) {
    double& drive = share[system.mechanism().drive.joint];
    drive = std::max(drive, std::abs(rows(system.DriveRow())));
  }
  const double largest = *std::max_element(share.begin(), share.end());
  std::vector<int> joints;
  for (int k = 0; k < n_joints; ++k) {
    if (share[k] > kSingularJointShare * largest) joints.push_back(k);
  }
  return joints;
}

// Coefficient of t^2 of F(q + t v, input): half the second derivative F''[v, v].
Eigen::VectorXd HalfSecondDerivative(const ConstraintSystem& system, const Eigen::VectorXd& q, double input,
                                     const Eigen::VectorXd& v) {
  const int n = system.NumCoordinates(), m = system.NumEquations();
  std::vector<Taylor<2>> qs(n), rs(m);
  for (int i = 0; i < n; ++i) {
    qs[i].c[0] = q(i);
    qs[i].c[1] = v(i);
  }
  system.Residuals(qs.data(), Taylor<2>(input), rs.data());
  Eigen::VectorXd out(m);
  for (int i = 0; i < m; ++i) out(i) = rs[i].c[2];
  return out;
}

// The augmented Newton system of a limit point (Moore-Spence): F(q, input) = 0, (J S) u = 0 and
// c.u = 1 in the unknowns (S^-1 q, input, u); its residual *g and Jacobian *a at (q, lambda, u).
// False when F is not finite there.
bool LimitPointNewtonSystem(const ConstraintSystem& system, const Eigen::VectorXd& q, double lambda, const Eigen::VectorXd& u,
                            const Eigen::VectorXd& c, const Eigen::VectorXd& scale, Eigen::MatrixXd* a, Eigen::VectorXd* g) {
  const int n = system.NumCoordinates();
  Eigen::MatrixXd jacobian(n, n);
  Eigen::VectorXd residual(n), e = Eigen::VectorXd::Zero(n);
  system.Jacobian(q.data(), jacobian);
  const Eigen::MatrixXd scaled = jacobian * scale.asDiagonal();
  system.Residuals(q.data(), lambda, residual.data());
  if (!residual.allFinite()) return false;
  const Eigen::VectorXd v = scale.cwiseProduct(u);
  g->head(n) = residual;
  g->segment(n, n) = scaled * u;
  (*g)(2 * n) = c.dot(u) - 1.0;
  a->setZero();
  a->topLeftCorner(n, n) = scaled;
  (*a)(system.DriveRow(), n) = system.InputColumn();
  // d(J S u)/dx_i = F''[v, S e_i] = (H(v + S e_i) - H(v - S e_i)) / 2, H the half second
  // derivative: exact, both directions of the size of one unit of L
  for (int i = 0; i < n; ++i) {
    e(i) = scale(i);
    a->block(n, i, n, 1) = 0.5 * (HalfSecondDerivative(system, q, lambda, v + e) - HalfSecondDerivative(system, q, lambda, v - e));
    e(i) = 0.0;
  }
  a->block(n, n + 1, n, n) = scaled;
  a->block(2 * n, n + 1, 1, n) = c.transpose();
  return true;
}

// The curvature input'' of the branch through a limit point (q, lambda) with null vector `null`
// and scaled Jacobian `scaled`: differentiate F(q(s), input(s)) = 0 twice at s = 0 (q' = null,
// input' = 0) and project on the left null vector psi: psi.F''[null, null] + psi.F_input input'' = 0.
// 0 when the drive row has no share in psi.
double LimitPointCurvature(const ConstraintSystem& system, const Eigen::MatrixXd& scaled, const Eigen::VectorXd& q, double lambda,
                           const Eigen::VectorXd& null) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeFullU);
  const Eigen::VectorXd psi = svd.matrixU().col(system.NumCoordinates() - 1);
  const double along = psi(system.DriveRow()) * system.InputColumn();
  return along != 0.0 ? -psi.dot(HalfSecondDerivative(system, q, lambda, null)) / along : 0.0;
}

// The Hessian of psi . G in the scaled coordinates, H(i, k) = psi^T G''[S e_i, S e_k], by
// polarisation of half second derivatives: n (n + 1) / 2 residual evaluations in Taylor<2>
// (`psi` has a zero for the drive row).
Eigen::MatrixXd SelfStressHessian(const ConstraintSystem& system, const Eigen::VectorXd& q, double input, const Eigen::VectorXd& psi,
                                  const Eigen::VectorXd& scale) {
  const int n = system.NumCoordinates();
  Eigen::MatrixXd h(n, n);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(n), diagonal(n);
  auto half = [&] { return psi.dot(HalfSecondDerivative(system, q, input, e)); };
  for (int i = 0; i < n; ++i) {
    e(i) = scale(i);
    diagonal(i) = half();
    h(i, i) = 2.0 * diagonal(i);
    e(i) = 0.0;
  }
  for (int i = 0; i < n; ++i) {
    for (int k = i + 1; k < n; ++k) {
      e(i) = scale(i);
      e(k) = scale(k);
      h(i, k) = h(k, i) = half() - diagonal(i) - diagonal(k);
      e(i) = e(k) = 0.0;
    }
  }
  return h;
}

// The bifurcation system of LocateBranchPoint at (q, psi, sigma): its residual *g and Jacobian *a
// in the unknowns (S^-1 q, psi, sigma), rows G - sigma psi, (J_c S)^T psi, psi . psi - 1. False
// when the residuals are not finite there.
bool BranchPointNewtonSystem(const ConstraintSystem& system, const Eigen::VectorXd& q, double input, const Eigen::VectorXd& psi,
                             double sigma, const Eigen::VectorXd& scale, Eigen::MatrixXd* a, Eigen::VectorXd* g) {
  const int n = system.NumCoordinates(), m = n - 1;
  Eigen::VectorXd residual(n);
  system.Residuals(q.data(), input, residual.data());
  if (!residual.allFinite()) return false;
  const Eigen::MatrixXd jc = ScaledJacobian(system, q, false);
  Eigen::VectorXd psi_rows = Eigen::VectorXd::Zero(n);
  psi_rows.head(m) = psi;
  g->head(m) = residual.head(m) - sigma * psi;
  g->segment(m, n) = jc.transpose() * psi;
  (*g)(2 * n - 1) = psi.squaredNorm() - 1.0;
  a->setZero();
  a->block(0, 0, m, n) = jc;
  a->block(0, n, m, m) = -sigma * Eigen::MatrixXd::Identity(m, m);
  a->block(0, n + m, m, 1) = -psi;
  a->block(m, 0, n, n) = SelfStressHessian(system, q, input, psi_rows, scale);
  a->block(m, n, n, m) = jc.transpose();
  a->block(2 * n - 1, n, 1, m) = 2.0 * psi.transpose();
  return true;
}

}  // namespace

const char* ToString(SingularKind kind) {
  switch (kind) {
    case SingularKind::kLimitPoint: return "limit";
    case SingularKind::kBranchPoint: return "branch-point";
  }
  return "limit";
}

const char* ToString(BranchPointAction action) {
  switch (action) {
    case BranchPointAction::kContinue: return "continue";
    case BranchPointAction::kStop: return "stop";
    case BranchPointAction::kSwitch: return "switch";
  }
  return "continue";
}

std::optional<BranchPointAction> ParseBranchPointAction(const std::string& text) {
  for (BranchPointAction a : {BranchPointAction::kContinue, BranchPointAction::kStop, BranchPointAction::kSwitch}) {
    if (text == ToString(a)) return a;
  }
  return std::nullopt;
}

Eigen::MatrixXd ScaledJacobian(const ConstraintSystem& system, const Eigen::VectorXd& q, bool with_drive_row) {
  Eigen::MatrixXd jacobian(system.NumEquations(), system.NumCoordinates());
  system.Jacobian(q.data(), jacobian);
  const Eigen::MatrixXd scaled = jacobian * ColumnScale(system).asDiagonal();
  return with_drive_row ? scaled : Eigen::MatrixXd(scaled.topRows(system.NumEquations() - 1));
}

double ReciprocalCondition(const ConstraintSystem& system, const Eigen::VectorXd& q) {
  const Eigen::MatrixXd j = ScaledJacobian(system, q, true);
  if (j.cols() == 0) return 1.0;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(j);
  const Eigen::VectorXd& s = svd.singularValues();
  return Ratio(s(s.size() - 1), s(0));
}

SingularStructure AnalyseSingularity(const ConstraintSystem& system, const Eigen::VectorXd& q) {
  SingularStructure out;
  const int n = system.NumCoordinates();
  if (n == 0) return out;
  const Eigen::MatrixXd full = ScaledJacobian(system, q, true);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd_full(full, Eigen::ComputeFullU);
  const Eigen::VectorXd& s_full = svd_full.singularValues();
  out.rcond = Ratio(s_full(s_full.size() - 1), s_full(0));
  // The constraint rows of a one-DOF mechanism have rank n - 1 everywhere but at branch points.
  const Eigen::MatrixXd constraints = full.topRows(full.rows() - 1);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd_c(constraints, Eigen::ComputeFullU);
  const Eigen::VectorXd& s_c = svd_c.singularValues();
  const int r = std::min<int>(n - 1, static_cast<int>(s_c.size()));
  out.constraint_rcond = r >= 1 ? Ratio(s_c(r - 1), s_c(0)) : 1.0;
  if (out.constraint_rcond < kBranchPointRcond) {
    out.kind = SingularKind::kBranchPoint;
    // the self-stress: the constraint rows' left singular vector of sigma_{n-1}
    Eigen::VectorXd rows = Eigen::VectorXd::Zero(full.rows());
    rows.head(constraints.rows()) = svd_c.matrixU().col(r - 1);
    out.joints = JointsOf(system, rows);
  } else {
    out.kind = SingularKind::kLimitPoint;
    out.joints = JointsOf(system, svd_full.matrixU().col(std::min<int>(n, full.rows()) - 1));
  }
  return out;
}

std::optional<Eigen::VectorXd> OtherBranchTangent(const ConstraintSystem& system, const Eigen::VectorXd& q, double input,
                                                  const Eigen::VectorXd& tangent) {
  const int n = system.NumCoordinates();
  if (n == 0 || system.NumEquations() != n) return std::nullopt;
  const Eigen::MatrixXd full = ScaledJacobian(system, q, true);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(full, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd psi = svd.matrixU().col(n - 1);
  // J (S v) = (J S) v: the null direction in coordinates, the drive held (drive row of J S v = 0)
  const Eigen::VectorXd w = ColumnScale(system).cwiseProduct(svd.matrixV().col(n - 1));
  auto second = [&](const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
    // psi^T F''[u, v] by polarisation of the half second derivatives
    return psi.dot(HalfSecondDerivative(system, q, input, u + v) - HalfSecondDerivative(system, q, input, u) -
                   HalfSecondDerivative(system, q, input, v));
  };
  const double a = 2.0 * psi.dot(HalfSecondDerivative(system, q, input, tangent));
  const double b = second(tangent, w);
  const double c = 2.0 * psi.dot(HalfSecondDerivative(system, q, input, w));
  // c a^2 + 2 b a + a0 = 0 for the coefficient along w; a0 = psi^T F''[t, t] is ~0 on a branch
  const double scale = std::max({std::abs(a), std::abs(b), std::abs(c), 1e-300});
  if (std::abs(c) <= 1e-9 * scale) return std::nullopt;  // the other branch runs at constant input
  const double discriminant = b * b - a * c;
  if (discriminant < 0.0) return std::nullopt;  // an isolated point, not a crossing
  const double root = std::sqrt(discriminant);
  const double alpha1 = (-b + root) / c, alpha2 = (-b - root) / c;
  const double other = std::abs(alpha1) > std::abs(alpha2) ? alpha1 : alpha2;
  if (other == 0.0) return std::nullopt;
  return Eigen::VectorXd(tangent + other * w);
}

std::optional<LimitPoint> LocateLimitPoint(const ConstraintSystem& system, double input, const Eigen::VectorXd& q0) {
  const int n = system.NumCoordinates();
  if (n == 0 || system.NumEquations() != n) return std::nullopt;
  const double length = system.length_scale();
  const double input_scale = system.mechanism().InputIsAngle() ? 1.0 : length;
  const Eigen::VectorXd scale = ColumnScale(system);
  Eigen::VectorXd q = q0;
  double lambda = input;
  // the null vector's first estimate: the right singular vector of sigma_min of J S
  Eigen::VectorXd u;
  {
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(ScaledJacobian(system, q, true), Eigen::ComputeFullV);
    u = svd.matrixV().col(n - 1);
  }
  const Eigen::VectorXd c = u;
  Eigen::MatrixXd jacobian(n, n), a(2 * n + 1, 2 * n + 1);
  Eigen::VectorXd g(2 * n + 1), residual(n);
  double previous_step = std::numeric_limits<double>::infinity();
  int growing = 0, it = 0;
  bool converged = false;
  for (; it < kLimitIterations; ++it) {
    if (!LimitPointNewtonSystem(system, q, lambda, u, c, scale, &a, &g)) return std::nullopt;
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(a);
    const Eigen::VectorXd d = lu.solve(-g);
    if (!d.allFinite()) return std::nullopt;
    const double step = std::max({(d.head(n).cwiseAbs().maxCoeff()) / length, std::abs(d(n)) / input_scale,
                                  d.tail(n).cwiseAbs().maxCoeff()});
    q += scale.cwiseProduct(d.head(n));
    lambda += d(n);
    u += d.tail(n);
    if (step <= kLimitStep * std::max(1.0, std::abs(lambda) / input_scale)) {
      converged = true;
      ++it;
      break;
    }
    growing = step >= previous_step ? growing + 1 : 0;
    if (growing >= 2) {
      converged = step < 1e-10;  // stalled at roundoff, not diverging
      ++it;
      break;
    }
    previous_step = step;
  }
  if (!converged) return std::nullopt;
  system.Jacobian(q.data(), jacobian);
  system.Residuals(q.data(), lambda, residual.data());
  const Eigen::MatrixXd scaled = jacobian * scale.asDiagonal();
  if (!(residual.cwiseAbs().maxCoeff() <= kLimitResidual * length) || !((scaled * u).cwiseAbs().maxCoeff() <= kLimitResidual * u.norm()))
    return std::nullopt;
  LimitPoint out;
  out.input = lambda;
  out.q = q;
  out.null = scale.cwiseProduct(u / u.norm());
  out.iterations = it;
  out.curvature = LimitPointCurvature(system, scaled, q, lambda, out.null);
  return out;
}

}  // namespace koppel

namespace koppel {

std::optional<BranchPoint> LocateBranchPoint(const ConstraintSystem& system, double input, const Eigen::VectorXd& q0) {
  const int n = system.NumCoordinates(), m = n - 1;
  if (n < 2 || system.NumEquations() != n) return std::nullopt;
  const double length = system.length_scale();
  const Eigen::VectorXd scale = ColumnScale(system);
  Eigen::VectorXd q = q0, residual(n);
  // the self-stress's first estimate: the constraint rows' left singular vector of sigma_min
  Eigen::VectorXd psi = Eigen::JacobiSVD<Eigen::MatrixXd>(ScaledJacobian(system, q, false), Eigen::ComputeFullU).matrixU().col(m - 1);
  system.Residuals(q.data(), input, residual.data());
  double sigma = psi.dot(residual.head(m));
  Eigen::MatrixXd a(2 * n, 2 * n);
  Eigen::VectorXd g(2 * n);
  double previous_step = std::numeric_limits<double>::infinity();
  int growing = 0, it = 0;
  bool converged = false;
  for (; it < kLimitIterations && !converged; ++it) {
    if (!BranchPointNewtonSystem(system, q, input, psi, sigma, scale, &a, &g)) return std::nullopt;
    const Eigen::VectorXd d = Eigen::PartialPivLU<Eigen::MatrixXd>(a).solve(-g);
    if (!d.allFinite()) return std::nullopt;
    const double step = std::max({d.head(n).cwiseAbs().maxCoeff() / length, d.segment(n, m).cwiseAbs().maxCoeff(),
                                  std::abs(d(2 * n - 1)) / length});
    q += scale.cwiseProduct(d.head(n));
    psi += d.segment(n, m);
    sigma += d(2 * n - 1);
    growing = step >= previous_step ? growing + 1 : 0;
    // quadratic convergence: the step after one of 1e-13 is at roundoff
    converged = step <= 1e-13 || (growing >= 2 && step < 1e-10);
    if (growing >= 2 && !converged) return std::nullopt;  // diverging
    previous_step = step;
  }
  if (!converged) return std::nullopt;
  system.Residuals(q.data(), input, residual.data());
  const Eigen::MatrixXd jc = ScaledJacobian(system, q, false);
  if (!((residual.head(m) - sigma * psi).cwiseAbs().maxCoeff() <= kLimitResidual * length) ||
      !((jc.transpose() * psi).cwiseAbs().maxCoeff() <= kLimitResidual))
    return std::nullopt;
  BranchPoint out;
  out.input = input - residual(system.DriveRow()) / system.InputColumn();
  out.q = q;
  out.defect = std::abs(sigma) / length;
  out.iterations = it;
  return out;
}

}  // namespace koppel
