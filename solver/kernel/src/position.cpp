#include "koppel/solver/position.hpp"

#include "koppel/core/plane.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <limits>
#include <cmath>

namespace koppel {
namespace {

// Guesses tried for links whose angle the hint leaves open.
constexpr int kAssemblyAttempts = 12;
// Levenberg–Marquardt budget for assembly from a rough guess: generous, it runs once.
constexpr int kAssemblyIterations = 400;
// Assembly hands over to Newton once the residual is this small relative to L: Newton then
// converges quadratically on the branch LM found.
constexpr double kAssemblyHandover = 1e-8;
// LM gives up when a window of this many iterations lowered |F|^2 by less than this fraction: a
// local minimum of |F| that is not zero (no pose there), or a crawl that would take millions of
// steps. Ceres' function_tolerance stops on 1e-6 in a single step; a window is more patient with
// a step that overshoots, and a converging run (linear even at a singular pose) gains far more.
constexpr int kAssemblyStallWindow = 16;
constexpr double kAssemblyStallGain = 1e-3;
// A pivot ratio below this counts as a singular Jacobian (about 100 ulps).
constexpr double kSingularPivotRatio = 1e-14;
// Below this pivot ratio a converged pose is polished by one more Newton update (Correct): J is
// ill-conditioned enough that the tolerance's residual moves the pose by more than roundoff.
constexpr double kPolishPivotRatio = 1e-3;
// ... when its residual is above this (times its extent): 16 ulps, above evaluation roundoff.
constexpr double kPolishResidual = 16.0 * std::numeric_limits<double>::epsilon();

// The link poses the assembly hint determines: hinted points give estimates of link points, joints
// carry them (and the drive and prismatic joints carry angles) from posed links to their
// neighbours, and a link with an angle and an estimated point is posed.
class LinkPoseGuess {
 public:
  explicit LinkPoseGuess(const Mechanism& m)
      : m_(m), n_links_(static_cast<int>(m.links.size())), posed_(n_links_, false), angle_known_(n_links_, false),
        theta_(n_links_, 0.0), origin_(n_links_, Eigen::Vector2d::Zero()), estimates_(n_links_) {
    const int frame = m.FrameLink();
    posed_[frame] = angle_known_[frame] = true;
    for (const AssemblyHint::Entry& e : m.hint.points) AddEstimate(e.point.link, e.point.point, e.global);
  }

  // Propagates what is determined; where nothing is, poses a link with the angle it has (or a
  // free one) at its first estimated point (or the origin) and propagates again.
  void PoseAll(int attempt) {
    for (;;) {
      Propagate();
      int pick = -1;
      for (int l = 0; l < n_links_ && pick < 0; ++l) {
        if (!posed_[l] && !estimates_[l].empty()) pick = l;
      }
      for (int l = 0; l < n_links_ && pick < 0; ++l) {
        if (!posed_[l]) pick = l;
      }
      if (pick < 0) break;
      open_.push_back(pick);
      angle_known_[pick] = true;
      // a free angle: 0 first, then angles spread by the golden ratio (no two attempts alike)
      if (attempt > 0) theta_[pick] = WrapAngle(2 * kPi * std::fmod(0.6180339887498949 * (attempt + 7 * pick), 1.0));
      if (!estimates_[pick].empty())
        origin_[pick] = estimates_[pick][0].second - Rotate(theta_[pick], m_.links[pick].points[estimates_[pick][0].first].local);
      posed_[pick] = true;
    }
  }

  double theta(int link) const { return theta_[link]; }
  // the links PoseAll had to pose with a free angle or place, in the order it did
  const std::vector<int>& open() const { return open_; }
  const Eigen::Vector2d& origin(int link) const { return origin_[link]; }

 private:
  // An estimate of a link point's global position; the first one wins (false: one was known).
  bool AddEstimate(int link, int point, const Eigen::Vector2d& g) {
    for (const auto& [p, unused] : estimates_[link]) {
      if (p == point) return false;
    }
    estimates_[link].emplace_back(point, g);
    return true;
  }
  Eigen::Vector2d Global(int link, int point) const {
    return Eigen::Vector2d(origin_[link] + Rotate(theta_[link], m_.links[link].points[point].local));
  }
  bool SetAngle(int link, double value) {
    if (angle_known_[link]) return false;
    angle_known_[link] = true;
    theta_[link] = value;
    return true;
  }

  // One pass over the joints: what a posed link (or one of known angle) says of its neighbour.
  bool CarryAcrossJoints() {
    const double input = m_.hint.input;
    bool changed = false;
    for (int k = 0; k < static_cast<int>(m_.joints.size()); ++k) {
      const Joint& j = m_.joints[k];
      const bool is_drive = (k == m_.drive.joint);
      if (j.type == JointType::kRevolute) {
        if (posed_[j.link_a] && !posed_[j.link_b]) changed |= AddEstimate(j.link_b, j.point_b, Global(j.link_a, j.point_a));
        if (posed_[j.link_b] && !posed_[j.link_a]) changed |= AddEstimate(j.link_a, j.point_a, Global(j.link_b, j.point_b));
        if (is_drive && angle_known_[j.link_a]) changed |= SetAngle(j.link_b, theta_[j.link_a] + m_.drive.zero + input);
        if (is_drive && angle_known_[j.link_b]) changed |= SetAngle(j.link_a, theta_[j.link_b] - m_.drive.zero - input);
      } else {
        if (angle_known_[j.link_a]) changed |= SetAngle(j.link_b, theta_[j.link_a] + j.angle);
        if (angle_known_[j.link_b]) changed |= SetAngle(j.link_a, theta_[j.link_b] - j.angle);
        const double s = is_drive ? m_.drive.zero + input : 0.0;
        if (posed_[j.link_a] && !posed_[j.link_b])
          changed |= AddEstimate(j.link_b, j.point_b, Global(j.link_a, j.point_a) + s * Rotate(theta_[j.link_a], j.axis));
      }
    }
    return changed;
  }

  // Poses each link with an angle (known, or from two estimated points) and an estimated point.
  bool PoseEstimatedLinks() {
    bool changed = false;
    for (int l = 0; l < n_links_; ++l) {
      if (posed_[l] || estimates_[l].empty()) continue;
      const auto& est = estimates_[l];
      const Eigen::Vector2d& p0 = m_.links[l].points[est[0].first].local;
      if (!angle_known_[l] && est.size() >= 2) {
        const Eigen::Vector2d& p1 = m_.links[l].points[est[1].first].local;
        const Eigen::Vector2d dl = p1 - p0, dg = est[1].second - est[0].second;
        if (dl.norm() > 0 && dg.norm() > 0) SetAngle(l, std::atan2(dg.y(), dg.x()) - std::atan2(dl.y(), dl.x()));
      }
      if (!angle_known_[l]) continue;
      origin_[l] = est[0].second - Rotate(theta_[l], p0);
      posed_[l] = changed = true;
    }
    return changed;
  }

  void Propagate() {
    bool changed = true;
    while (changed) {
      changed = CarryAcrossJoints();
      changed = PoseEstimatedLinks() || changed;
    }
  }

  const Mechanism& m_;
  const int n_links_;
  std::vector<bool> posed_, angle_known_;
  std::vector<int> open_;
  std::vector<double> theta_;
  std::vector<Eigen::Vector2d> origin_;
  // global estimates of link points, (point index, position) per link
  std::vector<std::vector<std::pair<int, Eigen::Vector2d>>> estimates_;
};

}  // namespace

std::vector<int> LinksTheHintLeavesOpen(const Mechanism& mechanism) {
  LinkPoseGuess guess(mechanism);
  guess.PoseAll(0);
  return guess.open();
}

const char* ToString(SolveStatus status) {
  switch (status) {
    case SolveStatus::kConverged: return "converged";
    case SolveStatus::kNotAssemblable: return "not assemblable";
    case SolveStatus::kSingular: return "singular";
    case SolveStatus::kDidNotConverge: return "did not converge";
  }
  return "unknown";
}

PositionSolver::PositionSolver(const Mechanism& mechanism, NewtonOptions options)
    : mechanism_(mechanism), system_(mechanism), options_(options) {
  const int n = system_.NumCoordinates(), m = system_.NumEquations();
  square_ = (n == m);
  residual_.resize(m);
  rhs_.resize(m);
  step_.resize(n);
  q_try_.resize(n);
  pending_q_.resize(n);
  q_solved_.setZero(n);
  jacobian_.resize(m, n);
  use_blocks_ = square_ && !options_.dense && n > 0 && blocks_.Analyse(n, system_.pattern_rows(), system_.pattern_cols());
  if (use_blocks_) {
    jacobian_values_.resize(system_.pattern_rows().size());
    trig_.resize(system_.TrigSize());
    trig_solved_.resize(system_.TrigSize());
    for (size_t l = 0; l < trig_solved_.size(); l += 2) trig_solved_[l] = 1.0;  // cos and sin at q_solved_ = 0
    trig_series_.resize(system_.TrigSize() * (kMaxOrder + 1));
  } else if (square_) {
    lu_ = Eigen::PartialPivLU<Eigen::MatrixXd>(n);
  }
  column_scale_.setOnes(n);
  for (int i = 2; i < n; i += 3) column_scale_(i) = 1.0 / system_.length_scale();
  q2_.resize(n);
  q8_.resize(n);
  r2_.resize(m);
  r8_.resize(m);
  trig2_.resize(system_.TrigSize());
  trig8_.resize(system_.TrigSize());
}

void PositionSolver::Evaluate(const Eigen::VectorXd& q, double input) {
  if (use_blocks_) {
    system_.Evaluate(q.data(), input, residual_.data(), jacobian_values_.data(), trig_.data());
    return;
  }
  system_.Residuals(q.data(), input, residual_.data());
  system_.Jacobian(q.data(), jacobian_);
}

void PositionSolver::FillDenseJacobian() {
  if (!use_blocks_) return;
  jacobian_.setZero();
  const std::vector<int>& rows = system_.pattern_rows();
  const std::vector<int>& cols = system_.pattern_cols();
  for (size_t e = 0; e < jacobian_values_.size(); ++e) jacobian_(rows[e], cols[e]) = jacobian_values_[e];
}

bool PositionSolver::Factorize() {
  double max_pivot = 0.0, min_pivot = 0.0;
  scaled_determinant_ = 0.0;
  // The gauge, det(J S) and its sign from an LU of J whose pivot j belongs to coordinate j
  // (`sign`: that of the LU's permutations): the pivots of J S are pivot_j S_jj.
  auto take_pivots = [&](int sign, auto pivot_of) {
    double determinant = sign;
    min_pivot = std::abs(pivot_of(0) * column_scale_(0));
    for (int j = 0; j < NumCoordinates(); ++j) {
      const double d = pivot_of(j) * column_scale_(j);
      max_pivot = std::max(max_pivot, std::abs(d));
      min_pivot = std::min(min_pivot, std::abs(d));
      determinant *= d;
      if (d < 0) sign = -sign;
    }
    pivot_ratio_ = max_pivot > 0 ? min_pivot / max_pivot : 0.0;
    scaled_determinant_ = determinant;
    jacobian_sign_ = pivot_ratio_ > kSingularPivotRatio ? sign : 0;
  };
  if (use_blocks_) {
    // the blocks' LUs are one LU of the permuted J (pivoting within the blocks)
    blocks_.Factorize(jacobian_values_.data());
    take_pivots(blocks_.DeterminantSign(), [&](int j) { return blocks_.Pivot(j); });
  } else if (square_ && jacobian_.rows() > 0) {
    lu_.compute(jacobian_);
    // Partial pivoting permutes rows only, so column j of U still belongs to coordinate j.
    const auto& lu = lu_.matrixLU();
    take_pivots(static_cast<int>(lu_.permutationP().determinant()), [&](int j) { return lu(j, j); });
  } else {
    // Redundant constraints (more rows than coordinates): least squares through QR, no sign.
    // Column pivoting ranks the columns by size, so scale them first to compare like with like.
    qr_.compute(jacobian_ * column_scale_.asDiagonal());
    const auto& r = qr_.matrixR();
    const int k = std::min(r.rows(), r.cols());
    // full rank min(rows, cols): overconstrained and consistent (more rows), or a mechanism with
    // more freedom than drives (more columns; Newton then takes a basic solution, and the
    // mobility check refuses such a mechanism before anything is computed from it)
    max_pivot = k > 0 ? std::abs(r(0, 0)) : 0.0;
    min_pivot = k > 0 ? std::abs(r(k - 1, k - 1)) : 0.0;
    pivot_ratio_ = max_pivot > 0 ? min_pivot / max_pivot : 0.0;
    jacobian_sign_ = 0;
  }
  return pivot_ratio_ > kSingularPivotRatio;
}

void PositionSolver::SolveFactorized(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) const {
  if (use_blocks_) {
    x = rhs;
    blocks_.Solve(x.data());
  } else if (square_) {
    x.noalias() = lu_.solve(rhs);
  } else {
    x.noalias() = qr_.solve(rhs);   // of J S: undo the column scaling
    x.array() *= column_scale_.array();
  }
}

SolveReport PositionSolver::Report(SolveStatus status, int iterations, std::string message) const {
  SolveReport report;
  report.status = status;
  report.iterations = iterations;
  report.residual_norm = residual_.size() ? residual_.lpNorm<Eigen::Infinity>() : 0.0;
  double worst = -1.0;
  for (int row = 0; row < residual_.size(); ++row) {
    if (std::abs(residual_(row)) > worst) {
      worst = std::abs(residual_(row));
      report.worst_joint = row == system_.DriveRow() ? -1 : row / 2;
    }
  }
  report.message = std::move(message);
  return report;
}

void PositionSolver::AdoptPending(double input, const std::function<void(Eigen::VectorXd& q)>* fill) {
  pending_ = true;
  pending_input_ = input;
  pending_fill_ = fill;
}

void PositionSolver::AdoptPose(double input, const Eigen::VectorXd& q, const double* trig) {
  pending_ = true;
  pending_fill_ = nullptr;
  pending_input_ = input;
  pending_q_ = q;
  if (use_blocks_ && trig) {
    // what OutputDerivatives reads at the pose; the factorisation's users call Resolve first,
    // which solves anew
    q_solved_ = q;
    std::copy(trig, trig + trig_solved_.size(), trig_solved_.begin());
  }
}

void PositionSolver::Resolve() const {
  if (!pending_) return;
  // the adopted pose is converged (to roundoff): Newton takes at most one step and factorises
  auto* self = const_cast<PositionSolver*>(this);
  self->pending_ = false;
  if (pending_fill_) (*pending_fill_)(self->pending_q_);
  self->pending_fill_ = nullptr;
  self->Correct(pending_input_, self->pending_q_);
}

SolveReport PositionSolver::Correct(double input, Eigen::VectorXd& q) {
  pending_ = false;
  pending_fill_ = nullptr;
  q_try_ = q;
  // a few hundred ulps of the coordinates: of L, or of the pose's own extent where a link lies
  // farther out (a slider far along its guide: its rows cannot be evaluated closer than that)
  double extent = system_.length_scale();
  for (int i = 0; i + 2 < q_try_.size(); i += 3) extent = std::max({extent, std::abs(q_try_(i)), std::abs(q_try_(i + 1))});
  const double tolerance = options_.tolerance * extent;
  double first_norm = -1.0;
  bool polished = false;
  for (int it = 0; it <= options_.max_iterations; ++it) {
    Evaluate(q_try_, input);
    const double norm = residual_.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(norm)) return Report(SolveStatus::kDidNotConverge, it, "the residual is not finite");
    if (first_norm < 0) first_norm = norm;
    const bool regular = Factorize();
    if (norm <= tolerance) {
      if (!regular) {
        factorized_ = false;
        return Report(SolveStatus::kSingular, it, "the pose is singular: the Jacobian has lost rank");
      }
      // Near a singular position a residual within the tolerance still moves the pose by about
      // residual / sigma_min (1e-13 L / 3e-6 at a linkage 1e-11 from its change point): one more
      // update brings it to roundoff there. Elsewhere the tolerance is the accuracy already, and
      // a residual at roundoff is left alone (an update from it is roundoff / sigma_min, which
      // next to a branch point can land on the other branch).
      if (!polished && norm > kPolishResidual * extent && pivot_ratio_ < kPolishPivotRatio) {
        polished = true;
        SolveStep();
        continue;
      }
      q = q_try_;
      q_solved_ = q_try_;
      input_solved_ = input;
      factorized_ = true;
      if (use_blocks_) trig_solved_ = trig_;
      return Report(SolveStatus::kConverged, it, "");
    }
    if (!regular) return Report(SolveStatus::kSingular, it, "the Jacobian is singular before convergence");
    // Divergence guard: Newton from a good predictor never grows the residual this much.
    if (it > 0 && norm > 1e3 * first_norm && norm > system_.length_scale())
      return Report(SolveStatus::kDidNotConverge, it, "Newton diverged");
    SolveStep();
  }
  return Report(SolveStatus::kDidNotConverge, options_.max_iterations,
                "Newton did not converge in " + std::to_string(options_.max_iterations) + " iterations");
}

void PositionSolver::SolveStep() {
  if (use_blocks_) {
    step_ = -residual_;
    blocks_.Solve(step_.data());
  } else {
    rhs_ = -residual_;
    SolveFactorized(rhs_, step_);
  }
  q_try_ += step_;
}

Eigen::VectorXd PositionSolver::InitialGuess(int attempt) const {
  LinkPoseGuess guess(mechanism_);
  guess.PoseAll(attempt);
  Eigen::VectorXd q(system_.NumCoordinates());
  for (int l = 0; l < static_cast<int>(mechanism_.links.size()); ++l) {
    const int i = system_.CoordinateOf(l);
    if (i < 0) continue;
    q(i) = guess.origin(l).x();
    q(i + 1) = guess.origin(l).y();
    q(i + 2) = guess.theta(l);
  }
  return q;
}

SolveReport PositionSolver::Assemble(Eigen::VectorXd& q) { return AssembleAt(mechanism_.hint.input, q); }

SolveReport PositionSolver::AssembleAt(double input, Eigen::VectorXd& q) {
  // The guess honours the drive at the hint's input; at another input the drive row pulls the
  // driven link there during the least-squares phase. A link whose angle the hint leaves open
  // starts at 0; should least squares stall there (a link lying across the line it must reach is
  // a stationary point of the cost), other angles are tried.
  SolveReport report;
  for (int attempt = 0; attempt < kAssemblyAttempts; ++attempt) {
    Eigen::VectorXd x = InitialGuess(attempt);
    report = AssembleFromGuess(input, x);
    if (report.ok() || report.status == SolveStatus::kSingular) {
      if (report.ok()) q = x;
      return report;
    }
  }
  return report;
}

SolveReport PositionSolver::AssembleFrom(double input, Eigen::VectorXd& q) {
  Eigen::VectorXd x = q;
  SolveReport report = AssembleFromGuess(input, x);
  if (report.ok()) q = x;
  return report;
}

SolveReport PositionSolver::AssembleFromGuess(double input, Eigen::VectorXd& x) {
  const double scale = system_.length_scale();
  // Levenberg–Marquardt in dimensionless variables: residuals over L and the scaled Jacobian
  // J S (theta columns over L), so that a mechanism drawn in micrometres and one in kilometres
  // take the same steps. A step dz of the scaled problem moves the coordinates by L S dz.
  auto scaled_jacobian = [&] {
    FillDenseJacobian();
    return Eigen::MatrixXd(jacobian_ * column_scale_.asDiagonal());
  };
  Evaluate(x, input);
  double cost = residual_.squaredNorm();
  Eigen::MatrixXd j_hat = scaled_jacobian();
  Eigen::MatrixXd normal = j_hat.transpose() * j_hat;
  Eigen::VectorXd gradient = j_hat.transpose() * residual_ / scale;
  double lambda = 1e-3 * std::max(normal.diagonal().maxCoeff(), 1e-12);
  int it = 0;
  double window_cost = cost;
  for (; it < kAssemblyIterations && residual_.lpNorm<Eigen::Infinity>() > kAssemblyHandover * scale; ++it) {
    if (it > 0 && it % kAssemblyStallWindow == 0) {
      if (cost > (1.0 - kAssemblyStallGain) * window_cost) break;
      window_cost = cost;
    }
    Eigen::MatrixXd damped = normal;
    damped.diagonal() += lambda * (normal.diagonal().array() + 1e-9).matrix();
    const Eigen::VectorXd dz = -damped.ldlt().solve(gradient);
    const Eigen::VectorXd trial = x + scale * column_scale_.cwiseProduct(dz);
    Evaluate(trial, input);
    const double trial_cost = residual_.squaredNorm();
    if (std::isfinite(trial_cost) && trial_cost < cost) {
      x = trial;
      cost = trial_cost;
      j_hat = scaled_jacobian();
      normal = j_hat.transpose() * j_hat;
      gradient = j_hat.transpose() * residual_ / scale;
      lambda = std::max(lambda / 3.0, 1e-15);
    } else {
      Evaluate(x, input);  // restore residual_ for the stall test and the report
      lambda *= 4.0;
      if (lambda > 1e16) break;  // no descent left: a local minimum of |F| that is not zero
    }
  }
  if (residual_.lpNorm<Eigen::Infinity>() > kAssemblyHandover * scale) {
    std::string what = "no pose satisfies all joints";
    const SolveReport partial = Report(SolveStatus::kNotAssemblable, it, "");
    if (partial.worst_joint >= 0) {
      what += " (joint '" + mechanism_.joints[partial.worst_joint].name + "' stays open by " +
              std::to_string(partial.residual_norm) + ")";
    } else {
      what += " (the drive cannot reach its input)";
    }
    return Report(SolveStatus::kNotAssemblable, it, what);
  }
  // Angles into (-pi, pi] so that outputs start on the principal value.
  for (int l = 0; l < static_cast<int>(mechanism_.links.size()); ++l) {
    if (const int i = system_.CoordinateOf(l); i >= 0) x(i + 2) = WrapAngle(x(i + 2));
  }
  SolveReport report = Correct(input, x);
  report.iterations += it;
  return report;
}

template <int N>
bool PositionSolver::SeriesImpl(int order, Eigen::MatrixXd& coefficients) {
  std::vector<Taylor<N>>& qs = CoordinateSeries<N>();
  std::vector<Taylor<N>>& rs = ResidualSeries<N>();
  const int n = system_.NumCoordinates();
  coefficients.col(0) = q_solved_;
  Taylor<N> input(input_solved_);
  input.c[1] = 1.0;
  for (int k = 1; k <= order; ++k) {
    // Coefficient k of F(q(t), input + t) with q's own coefficient k still zero is the
    // right-hand side: J q_k = -[F]_k.
    for (int i = 0; i < n; ++i) {
      qs[i] = Taylor<N>();
      for (int j = 0; j < k; ++j) qs[i].c[j] = coefficients(i, j);
    }
    system_.Residuals(qs.data(), input, rs.data());
    for (int i = 0; i < rhs_.size(); ++i) rhs_(i) = -rs[i].c[k];
    SolveFactorized(rhs_, step_);
    coefficients.col(k) = step_;
  }
  return true;
}

void PositionSolver::BlockSeries(int order, Eigen::MatrixXd& coefficients) {
  const int n = NumCoordinates();
  coefficients.col(0) = q_solved_;
  std::copy(trig_solved_.begin(), trig_solved_.end(), trig_series_.begin());
  for (int k = 1; k <= order; ++k) {
    double* q_k = coefficients.data() + static_cast<std::ptrdiff_t>(n) * k;
    if (k == 1) {
      // with q's coefficient 1 taken as zero nothing in F moves but the input: the right-hand
      // side is dF/dinput, the drive row's alone (the recurrences give exact zeros elsewhere)
      std::fill(trig_series_.begin() + system_.TrigSize(), trig_series_.begin() + 2 * system_.TrigSize(), 0.0);
      std::fill(q_k, q_k + n, 0.0);
      q_k[system_.DriveRow()] = -system_.InputColumn();
    } else {
      system_.TrigSeriesPartial(k, coefficients.data(), trig_series_.data());
      system_.SeriesResidual(k, coefficients.data(), trig_series_.data(), rhs_.data());
      for (int i = 0; i < n; ++i) q_k[i] = -rhs_(i);
    }
    blocks_.Solve(q_k);
    system_.TrigSeriesComplete(k, coefficients.data(), trig_series_.data());
  }
}

bool PositionSolver::Series(int order, Eigen::MatrixXd& coefficients) {
  Resolve();
  if (!factorized_ || order < 0 || order > kMaxOrder) return false;
  if (coefficients.rows() != NumCoordinates() || coefficients.cols() != order + 1)
    coefficients.resize(NumCoordinates(), order + 1);
  if (use_blocks_) {
    BlockSeries(order, coefficients);
    return true;
  }
  return order <= 2 ? SeriesImpl<2>(order, coefficients) : SeriesImpl<kMaxOrder>(order, coefficients);
}

int OutputColumn(const Mechanism& m, int output, int component, int order) {
  int column = 0;
  for (int o = 0; o < output; ++o) column += m.outputs[o].Components() * (order + 1);
  return column + component * (order + 1);
}

int PositionSolver::OutputWidth(int order) const {
  int width = 0;
  for (const Output& o : mechanism_.outputs) width += o.Components() * (order + 1);
  return width;
}

template <int N>
void PositionSolver::OutputDerivativesImpl(const Eigen::MatrixXd& coefficients, int order, double* out, const double* trig_at_pose) const {
  std::vector<Taylor<N>>& qs = CoordinateSeries<N>();
  std::vector<Taylor<N>>& trig = TrigSeries<N>();
  for (int i = 0; i < NumCoordinates(); ++i) {
    qs[i] = Taylor<N>();
    for (int j = 0; j <= order; ++j) qs[i].c[j] = coefficients(i, j);
  }
  // cos and sin of each link angle once, not once per point an output looks at; at the pose
  // Newton converged to (the common case: a walk's outputs) the last evaluation's values, the
  // same numbers as a new sincos
  if (!trig_at_pose && use_blocks_ && coefficients.col(0) == q_solved_) trig_at_pose = trig_solved_.data();
  for (int l = 0; l < static_cast<int>(mechanism_.links.size()); ++l) {
    const int i = system_.CoordinateOf(l);
    if (i < 0) {
      trig[2 * l] = Taylor<N>(1.0);
      trig[2 * l + 1] = Taylor<N>(0.0);
    } else if (trig_at_pose) {
      SinCos(qs[i + 2], trig_at_pose[2 * l + 1], trig_at_pose[2 * l], trig[2 * l + 1], trig[2 * l]);
    } else {
      SinCos(qs[i + 2], trig[2 * l + 1], trig[2 * l]);
    }
  }
  int column = 0;
  auto write = [&](const Taylor<N>& y) {
    double factorial = 1.0;
    for (int k = 0; k <= order; ++k) {
      if (k > 1) factorial *= k;
      out[column++] = y.c[k] * factorial;
    }
  };
  for (int o = 0; o < static_cast<int>(mechanism_.outputs.size()); ++o) {
    const Output& output = mechanism_.outputs[o];
    if (output.kind == OutputKind::kPoint) {
      // both coordinates from one evaluation of the point (Output gives one of them)
      Taylor<N> xy[2];
      system_.GlobalPoint(output.p, qs.data(), xy, trig.data());
      write(xy[0]);
      write(xy[1]);
    } else {
      write(system_.Output(o, 0, qs.data(), trig.data()));
    }
  }
}

void PositionSolver::OutputDerivatives(const Eigen::MatrixXd& coefficients, int order, double* out) const {
  OutputDerivatives(coefficients, order, out, nullptr);
}

void PositionSolver::OutputDerivatives(const Eigen::MatrixXd& coefficients, int order, double* out, const double* trig) const {
  if (order <= 2) {
    OutputDerivativesImpl<2>(coefficients, order, out, trig);
  } else {
    OutputDerivativesImpl<kMaxOrder>(coefficients, order, out, trig);
  }
}

Eigen::VectorXd PositionSolver::SolveWithJacobian(const Eigen::VectorXd& rhs) const {
  Resolve();
  Eigen::VectorXd x(NumCoordinates());
  SolveFactorized(rhs, x);
  return x;
}

int PositionSolver::ConstraintRank(const Eigen::VectorXd& q) const {
  Eigen::MatrixXd jac(system_.NumEquations(), system_.NumCoordinates());
  system_.Jacobian(q.data(), jac);
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(jac.topRows(system_.NumEquations() - 1));
  // Rank threshold relative to the largest pivot, scaled like the Newton tolerance.
  qr.setThreshold(1e-10);
  return static_cast<int>(qr.rank());
}

}  // namespace koppel
