#include "koppel/solver/continuation.hpp"

#include "hermite.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/solver/singular.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace koppel {
namespace {

// The compiled step hands over to the general one where a dyad's normalised determinant (the sine
// of the angle between its two rows) falls below this: far above any singular position's
// (kSingularRowRcond), so a compiled pose is never one, and far below a regular walk's.
constexpr double kFastGauge = 1e-2;
// A pose examined at a stall is near a singular position below this reciprocal condition.
constexpr double kNearSingularRcond = 1e-3;
// Taylor order at the two ends of a branch-point window: orders up to 3 are accurate at both
// (their errors grow like eps / rcond^k, and rcond ~ 1e-2 there).
constexpr int kWindowOrder = 3;
// Attempts at crossing a branch point, each with a window a quarter as wide as the one before.
constexpr int kCrossingAttempts = 3;
// A branch point is located to about this [rad, or units of L]: the bifurcation system's Newton
// stops at roundoff (LocateBranchPoint); a sample on the point must not fall off by a rounding.
constexpr double kBranchPointLocation = 1e-10;
// A stall is examined again only after the steps have grown back to this many times the stall's.
constexpr double kReexamineStall = 1024.0;
// A pose with a link's origin farther than this (times L, beyond where the walk started) has run off: a
// joint at the meeting point of two slide lines that turn parallel goes to infinity as the input
// approaches the input where they are parallel, and the walk's steps shrink with the distance left.
// A mechanism reaching a million times its own size has no pose a user builds there.
constexpr double kRunOff = 1e6;
// Steps a walk between two nearby regular poses may take (it never passes a singular position).
constexpr long kRegularWalkSteps = 100000;
// A target within this of a located limit point (relative to max(1, |input|), times L for a P
// drive) is the point: a few ulps, below the location's roundoff (about 1e-15).
constexpr double kAtLimitPoint = 1e-14;

// The stored size of a pose difference in units of L: theta times L, (x, y) as they are.
Eigen::VectorXd Unscaled(const Eigen::VectorXd& d, double length) {
  Eigen::VectorXd out = d;
  for (int i = 2; i < out.size(); i += 3) out(i) *= length;
  return out;
}

std::string JointNames(const Mechanism& m, const std::vector<int>& joints) {
  std::string names;
  for (int j : joints) names += (names.empty() ? "" : ", ") + m.joints[j].name;
  return names;
}

}  // namespace

struct Continuation::Window {
  HermiteSegment incoming;  // A .. B on the incoming branch (continue, stop; switch: up to the point)
  HermiteSegment outgoing;  // switch only: the point .. B' on the other branch
  double star = 0.0;        // the branch point
  double near_end = 0.0;    // A
  double far_end = 0.0;     // B (B'), or the point itself when the walk stops there
  Eigen::VectorXd near_q, far_q;
  double direction = 1.0;   // +1: entered with increasing input
  bool stop = false;
  std::string stop_message;  // why the walk ends at the point
  // `slack`: how far beyond the far end still counts as at it (a branch point is located to
  // about 1e-12; a sample on it must not fall off by a rounding)
  bool Contains(double input, double slack) const {
    return direction * (input - near_end) >= 0.0 && direction * (far_end - input) >= -slack;
  }
};

const char* ToString(WalkStatus status) {
  switch (status) {
    case WalkStatus::kNotRun: return "not run";
    case WalkStatus::kReached: return "reached";
    case WalkStatus::kLimitPoint: return "limit point";
    case WalkStatus::kBranchPointStop: return "stopped at a branch point";
    case WalkStatus::kTooFar: return "too far";
    case WalkStatus::kFailed: return "failed";
    case WalkStatus::kRunOff: return "runs off";
  }
  return "failed";
}

bool ContinuationOptions::IsValid(std::string* why) const {
  auto fail = [&](const char* text) {
    if (why) *why = text;
    return false;
  };
  auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!positive(max_step)) return fail("max_step must be positive and finite");
  if (!positive(limit_resolution) || limit_resolution >= max_step) return fail("limit_resolution must be positive and below max_step");
  if (!positive(stall_fraction) || stall_fraction >= 1.0) return fail("stall_fraction must lie in (0, 1)");
  if (!positive(branch_window) || branch_window > 0.5) return fail("branch_window must lie in (0, 0.5]");
  if (max_corrector_iterations < 1) return fail("max_corrector_iterations must be at least 1");
  if (!positive(max_correction)) return fail("max_correction must be positive");
  if (!positive(max_tangent_change)) return fail("max_tangent_change must be positive");
  if (max_steps < 1) return fail("max_steps must be at least 1");
  if (!positive(time_budget)) return fail("time_budget must be positive");
  if (why) why->clear();
  return true;
}

Continuation::Continuation(PositionSolver& solver, ContinuationOptions options)
    : solver_(solver), options_(options), length_scale_(solver.system().length_scale()) {
  const int n = solver.NumCoordinates();
  input_scale_ = solver.system().mechanism().InputIsAngle() ? 1.0 : length_scale_;
  q_.setZero(n);
  for (RegularPose& p : regular_) p.q.setZero(n);
  q_trial_.setZero(n);
  predicted_.setZero(n);
  tangent_predicted_.setZero(n);
  series_.setZero(n, kWindowOrder + 1);
  trial_series_.setZero(n, kWindowOrder + 1);
  if (!solver.options().dense) {
    schedule_ = std::make_unique<PointSchedule>(solver.system());
    if (!schedule_->compiled()) schedule_.reset();
    schedule_options_.tolerance = solver.options().tolerance;
    schedule_options_.max_iterations = options_.max_corrector_iterations;
    schedule_options_.max_correction = options_.max_correction;
    schedule_options_.max_tangent_change = options_.max_tangent_change;
    schedule_options_.min_gauge = kFastGauge;
  }
  fill_pose_ = [this](Eigen::VectorXd& q) { q = this->q(); };
}

Continuation::~Continuation() {
  // the solver outlives the walk: it gets the pose itself, not a way to ask this walk for it
  if (solver_.IsPending(&fill_pose_)) {
    MaterializePose();
    solver_.AdoptPose(input_, q_);
  }
}

// Both norms go link by link: (x, y) in units of L, theta in rad.
double Continuation::ScaledPoseNorm(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
  const double per_length = 1.0 / length_scale_;
  double norm = 0.0;
  for (int i = 0; i + 2 < a.size(); i += 3) {
    norm = std::max(norm, std::abs(a(i) - b(i)) * per_length);
    norm = std::max(norm, std::abs(a(i + 1) - b(i + 1)) * per_length);
    norm = std::max(norm, std::abs(a(i + 2) - b(i + 2)));
  }
  return norm;
}

double Continuation::ScaledTangentNorm(Eigen::Ref<const Eigen::VectorXd> a, const Eigen::VectorXd* b) const {
  const double per_length = 1.0 / length_scale_;
  double norm = 0.0;
  for (int i = 0; i < a.size(); ++i) {
    const double d = b ? a(i) - (*b)(i) : a(i);
    norm = std::max(norm, std::abs(d) * (i % 3 == 2 ? 1.0 : per_length) * input_scale_);
  }
  return norm;
}

std::string Continuation::Where(double input) const {
  const Mechanism& m = solver_.system().mechanism();
  char buffer[96];
  if (m.InputIsAngle()) {
    std::snprintf(buffer, sizeof buffer, "%s = %.10g deg", m.drive.input_name.c_str(), RadToDeg(input));
  } else {
    std::snprintf(buffer, sizeof buffer, "%s = %.10g", m.drive.input_name.c_str(), input);
  }
  return buffer;
}

WalkReport Continuation::Reached() const { return {WalkStatus::kReached, input_, {}}; }

WalkReport Continuation::Ended(WalkStatus status, std::string message) const {
  return {status, input_, std::move(message)};
}

void Continuation::SetRegularPose(double input, const Eigen::VectorXd& q) {
  at_limit_ = false;
  input_ = input;
  q_ = q;
  q_pending_ = false;
  from_window_ = false;
  RestoreFactorization();
}

bool Continuation::RestoreFactorization() {
  MaterializePose();
  compiled_pose_ = false;
  schedule_loaded_ = false;
  q_trial_ = q_;
  if (!solver_.Correct(input_, q_trial_).ok()) return false;
  q_ = q_trial_;
  q_pending_ = false;
  factorized_here_ = true;
  from_window_ = false;
  sign_ = solver_.JacobianSign();
  determinant_ = solver_.ScaledDeterminant();
  pivot_ratio_ = solver_.PivotRatio();
  RememberIfRegular(pivot_ratio_ > kRegularPivotRatio);
  rcond_ = -1.0;
  valid_order_ = kMaxOrder;
  series_order_ = -1;
  return true;
}

SolveReport Continuation::Start(double input, const Eigen::VectorXd& q) {
  q_trial_ = q;
  SolveReport report = solver_.Correct(input, q_trial_);
  if (report.ok()) {
    started_ = true;
    at_limit_ = false;
    double extent = 0.0;
    for (int i = 0; i + 2 < q_trial_.size(); i += 3) extent = std::max({extent, std::abs(q_trial_(i)), std::abs(q_trial_(i + 1))});
    reach_ = extent + kRunOff * length_scale_;
    compiled_pose_ = false;
    schedule_loaded_ = false;
    input_ = input;
    q_ = q_trial_;
    q_pending_ = false;
    factorized_here_ = true;
    from_window_ = false;
    sign_ = solver_.JacobianSign();
    determinant_ = solver_.ScaledDeterminant();
    pivot_ratio_ = solver_.PivotRatio();
    RememberIfRegular(pivot_ratio_ > kRegularPivotRatio);
    rcond_ = -1.0;
    valid_order_ = kMaxOrder;
    series_order_ = -1;
    window_.reset();
  }
  return report;
}

const Eigen::MatrixXd& Continuation::Series(int order) {
  if (order < 0 || order > kMaxOrder)
    throw std::out_of_range("Continuation::Series: order " + std::to_string(order) + " outside 0.." + std::to_string(kMaxOrder));
  if (from_window_) {
    // orders up to 3 from the interpolant; higher ones through J^-1 where the pose is regular
    if (order <= kWindowOrder || series_order_ >= order) return series_;
    if (AtSingularPose()) {
      series_.conservativeResize(Eigen::NoChange, order + 1);
      series_.rightCols(order - kWindowOrder).setZero();
      series_order_ = order;
      return series_;
    }
    const double input = input_;
    if (!RestoreFactorization()) return series_;
    solver_.Series(order, series_);
    series_.leftCols(kWindowOrder + 1) = window_series_;  // the interpolant is the better one there
    series_order_ = order;
    from_window_ = true;
    input_ = input;
    return series_;
  }
  if (series_order_ >= order) return series_;
  if (compiled_pose_ && order <= 2) {
    // the schedule's jets, taken only when asked for (a sweep's outputs come from the jets)
    schedule_->Series(series_);
    series_order_ = 2;
    return series_;
  }
  if (!factorized_here_) RestoreFactorization();
  solver_.Series(order, series_);
  series_order_ = order;
  return series_;
}

void Continuation::OutputDerivatives(int order, double* out) {
  if (compiled_pose_ && order <= 2) {
    schedule_->OutputDerivatives(order, out);
    return;
  }
  solver_.OutputDerivatives(Series(std::max(order, 2)), order, out);
}

bool Continuation::AtSingularPose() {
  if (compiled_pose_) return false;  // every dyad's gauge above kFastGauge: regular
  if (rcond_ < 0.0) {
    rcond_ = (!from_window_ && pivot_ratio_ > kRegularPivotRatio) ? pivot_ratio_
                                                                   : ReciprocalCondition(solver_.system(), q_);
  }
  return rcond_ < kSingularRowRcond;
}

void Continuation::Accept(double next) {
  schedule_loaded_ = false;
  at_limit_ = false;
  input_ = next;
  q_ = q_trial_;
  q_pending_ = false;
  factorized_here_ = true;
  from_window_ = false;
  sign_ = solver_.JacobianSign();
  determinant_ = solver_.ScaledDeterminant();
  pivot_ratio_ = solver_.PivotRatio();
  rcond_ = -1.0;
  valid_order_ = kMaxOrder;
  // The trial's series (order 2) is the new pose's. Copied into series_'s first columns rather
  // than swapped: a swap would hand the higher-order storage a sweep asks for to the trial, and
  // both matrices would change shape (a malloc each) at every step.
  if (series_.rows() != trial_series_.rows() || series_.cols() < trial_series_.cols()) series_.resize(trial_series_.rows(), trial_series_.cols());
  series_.leftCols(trial_series_.cols()) = trial_series_;
  series_order_ = 2;
  // a step that is not clearly regular keeps the last regular pose (the walk is continuous)
  if (pivot_ratio_ > kRegularPivotRatio) RememberIfRegular(true);
}

void Continuation::RememberIfRegular(bool regular) {
  if (!regular) {
    regular_count_ = 0;
    if (schedule_) schedule_->ForgetHistory();
    return;
  }
  MaterializePose();
  RegularPose& p = regular_[regular_next_];
  p.input = input_;
  p.q = q_;
  p.seq = ++seq_;
  regular_next_ = (regular_next_ + 1) % kRememberedPoses;
  regular_count_ = std::min(regular_count_ + 1, kRememberedPoses);
}

bool Continuation::RegularPoseBefore(double input, double direction, RegularPose* pose) const {
  const RegularPose* found = nullptr;
  for (int k = 1; k <= regular_count_ && !found; ++k) {
    const int slot = (regular_next_ - k + kRememberedPoses) % kRememberedPoses;
    if (direction * (input - regular_[slot].input) >= 0.0) found = &regular_[slot];
  }
  const int history = schedule_ ? schedule_->History() : 0;
  for (int back = 0; back < history; ++back) {
    if (found && found->seq > schedule_seq_ - back) break;  // the ring's is newer
    if (direction * (input - schedule_->HistoryInput(back)) < 0.0) continue;
    pose->input = schedule_->HistoryInput(back);
    schedule_->HistoryPose(back, pose->q);
    pose->seq = schedule_seq_ - back;
    return true;
  }
  if (found) *pose = *found;
  return found != nullptr;
}

void Continuation::MaterializePose() const {
  if (!q_pending_) return;
  schedule_->Pose(q_);
  q_pending_ = false;
}

void Continuation::EnsureFactorized() {
  if (compiled_pose_) RestoreFactorization();
}

Continuation::StepResult Continuation::TryCompiledStep(double next) {
  StepResult out;
  if (!schedule_ || from_window_ || at_limit_) return out;
  if (!compiled_pose_ && !(pivot_ratio_ > kRegularPivotRatio)) return out;  // near a singular position
  if (!schedule_loaded_) {
    schedule_->Load(input_, q_, Series(2));
    schedule_loaded_ = true;
  }
  if (!schedule_->Step(next, schedule_options_)) return out;
  input_ = next;
  q_pending_ = true;  // written when read (MaterializePose)
  solver_.AdoptPending(next, &fill_pose_);
  series_order_ = -1;  // Series() takes the schedule's when asked
  factorized_here_ = false;
  from_window_ = false;
  at_limit_ = false;
  compiled_pose_ = true;
  schedule_seq_ = ++seq_;  // remembered in the schedule's history: every dyad's gauge above kFastGauge
  rcond_ = -1.0;
  valid_order_ = kMaxOrder;
  out.accepted = true;
  return out;
}

Continuation::StepResult Continuation::TryStep(double next) {
  EnsureFactorized();
  StepResult out;
  const double h = next - input_;
  const Eigen::MatrixXd& c = Series(2);
  // the 2nd-order Taylor prediction of the pose and of its first derivative, in one pass
  const double hh = h * h, h2 = 2.0 * h;
  for (int i = 0; i < q_trial_.size(); ++i) {
    predicted_(i) = c(i, 0) + h * c(i, 1) + hh * c(i, 2);
    tangent_predicted_(i) = c(i, 1) + h2 * c(i, 2);
    q_trial_(i) = predicted_(i);
  }
  const SolveReport report = solver_.Correct(next, q_trial_);
  factorized_here_ = false;
  if (!report.ok() || report.iterations > options_.max_corrector_iterations) return out;
  if (ScaledPoseNorm(q_trial_, predicted_) > options_.max_correction) return out;
  // the first-order transfer functions must continue the predicted ones: on another branch they
  // differ by O(1), on this one by O(h^2)
  solver_.Series(2, trial_series_);
  const double change = ScaledTangentNorm(trial_series_.col(1), &tangent_predicted_);
  if (change > options_.max_tangent_change * (1.0 + ScaledTangentNorm(tangent_predicted_, nullptr))) return out;
  // det J keeps its sign along a branch between singular positions: a step that changes it got
  // onto another branch (past a limit point's gap, or across the sharp turn a linkage near its
  // change point takes) or straight across a branch point, and is refused like one too long.
  // The walk refines its step: it follows a sharp turn, and stalls at a limit point or a branch
  // point, which ExamineStall then locates.
  const int sign = solver_.JacobianSign();
  if (sign_ != 0 && sign != 0 && sign != sign_) return out;
  out.accepted = true;
  Accept(next);
  return out;
}

bool Continuation::RegularWalkTo(double target) {
  const double cap = options_.max_step * input_scale_;
  double h = std::min(cap, std::abs(target - input_));
  long steps = 0;
  while (input_ != target) {
    if (++steps > kRegularWalkSteps) return false;
    const double remaining = target - input_;
    const double next = std::abs(remaining) <= h ? target : input_ + std::copysign(h, remaining);
    if (TryStep(next).accepted) {
      h = std::min(cap, 2.0 * h);
      continue;
    }
    h *= 0.5;
    if (h < options_.limit_resolution * input_scale_) return false;
  }
  return true;
}

std::unique_ptr<Continuation::Window> Continuation::OpenBranchWindow(double estimate, double direction, double delta,
                                                                     Eigen::MatrixXd* at_star) {
  MaterializePose();
  // A: a regular pose of the incoming branch, a window's half-width before the point
  const double a_input = estimate - direction * delta;
  if (!RegularWalkTo(a_input)) return nullptr;
  const Eigen::MatrixXd a_series = Series(kWindowOrder).leftCols(kWindowOrder + 1);
  const Eigen::VectorXd a_q = q_;
  // B: as far beyond, predicted along A's Taylor series, the transfer functions verified
  const double b_input = estimate + direction * delta;
  const double span = b_input - a_input;
  Eigen::VectorXd predicted = Eigen::VectorXd::Zero(a_q.size()), tangent = Eigen::VectorXd::Zero(a_q.size());
  for (int k = kWindowOrder; k >= 0; --k) predicted = predicted * span + a_series.col(k);
  for (int k = kWindowOrder; k >= 1; --k) tangent = tangent * span + k * a_series.col(k);
  Eigen::VectorXd b_q = predicted;
  const SolveReport at_b = solver_.Correct(b_input, b_q);
  factorized_here_ = false;
  if (!at_b.ok() || ScaledPoseNorm(b_q, predicted) > options_.max_correction) return nullptr;
  Eigen::MatrixXd b_series;
  solver_.Series(kWindowOrder, b_series);
  if (ScaledTangentNorm(b_series.col(1), &tangent) > options_.max_tangent_change * (1.0 + ScaledTangentNorm(tangent, nullptr)))
    return nullptr;
  // the point: located on the bifurcation system (ExamineStall), to roundoff
  const double star = estimate;
  const HermiteSegment incoming(a_input, a_series, b_input, b_series);
  incoming.Coefficients(star, 1, *at_star);

  auto window = std::make_unique<Window>();
  window->direction = direction;
  window->star = star;
  window->near_end = a_input;
  window->near_q = a_q;
  window->incoming = incoming;
  window->far_end = b_input;
  window->far_q = b_q;
  return window;
}

bool Continuation::SwitchBranchInWindow(const Eigen::MatrixXd& at_star, Window* window) {
  const ConstraintSystem& system = solver_.system();
  const double star = window->star, b_input = window->far_end;
  const std::optional<Eigen::VectorXd> other = OtherBranchTangent(system, at_star.col(0), star, at_star.col(1));
  if (!other) return false;
  // B': the other branch's pose at B's input, predicted along its tangent from the point; it must
  // land apart from B and near its prediction, with a tangent that agrees
  Eigen::VectorXd other_q = at_star.col(0) + (b_input - star) * *other;
  Eigen::MatrixXd other_series;
  bool switched = false;
  const Eigen::VectorXd other_predicted = other_q;
  const Eigen::VectorXd incoming_tangent = at_star.col(1);
  const double separation = ScaledTangentNorm(*other, &incoming_tangent) * std::abs(b_input - star) / input_scale_;
  if (solver_.Correct(b_input, other_q).ok() && ScaledPoseNorm(other_q, window->far_q) > 0.25 * separation &&
      ScaledPoseNorm(other_q, other_predicted) < 0.25 * separation) {
    solver_.Series(kWindowOrder, other_series);
    switched = ScaledTangentNorm(other_series.col(1), &*other) <=
               5.0 * options_.max_tangent_change * (1.0 + ScaledTangentNorm(*other, nullptr));
  }
  factorized_here_ = false;
  if (!switched) return false;
  Eigen::MatrixXd star_data(at_star.rows(), 2);
  star_data.col(0) = at_star.col(0);
  star_data.col(1) = *other;
  window->outgoing = HermiteSegment(star, star_data, b_input, other_series);
  window->far_q = other_q;
  return true;
}

Continuation::Crossing Continuation::CrossBranchPoint(double estimate, double direction, double target,
                                                      WalkReport* finished) {
  MaterializePose();
  const ConstraintSystem& system = solver_.system();
  const double start_input = input_;
  const Eigen::VectorXd start_q = q_;
  double delta = options_.branch_window * input_scale_;
  // The window's near end is walked to from a regular pose behind it when the walk has one: the
  // walk that stalled here may stand so close to the point that its tangent is noise, and a step
  // back from there can land on the other branch.
  RegularPose behind;
  const bool has_behind = RegularPoseBefore(estimate - direction * delta, direction, &behind);
  for (int attempt = 0; attempt < kCrossingAttempts; ++attempt, delta *= 0.25) {
    if (attempt == 0 && has_behind) SetRegularPose(behind.input, behind.q);
    if (attempt > 0) SetRegularPose(start_input, start_q);
    Eigen::MatrixXd at_star;
    std::unique_ptr<Window> window = OpenBranchWindow(estimate, direction, delta, &at_star);
    if (!window) continue;
    const double star = window->star;
    const SingularStructure structure = AnalyseSingularity(system, at_star.col(0));
    SingularPoint point{SingularKind::kBranchPoint, star, structure.rcond, structure.joints, options_.at_branch_point};
    const std::string joints = JointNames(system.mechanism(), structure.joints);
    if (options_.at_branch_point == BranchPointAction::kStop) {
      window->far_end = star;
      window->stop = true;
      window->stop_message = "a branch point at " + Where(star) + " (joints " + joints + "); stopped there as asked";
    } else if (options_.at_branch_point == BranchPointAction::kSwitch && !SwitchBranchInWindow(at_star, window.get())) {
      // the walk ends at the point: it may not continue on a branch it was told to leave
      point.action = BranchPointAction::kStop;
      window->far_end = star;
      window->stop = true;
      window->stop_message = "cannot switch to the other branch at the branch point " + Where(star) + " (joints " + joints +
                             "): the other branch does not cross there in the input (it runs at constant input, or "
                             "the crossing is not simple); stopped there";
    }
    singular_points_.push_back(point);
    window_ = std::move(window);
    return LeaveOrEnterWindow(target, finished);
  }
  // No crossing was found: not a branch point after all. Back to where the caller stood.
  SetRegularPose(start_input, start_q);
  return Crossing::kNotCrossed;
}

Continuation::Crossing Continuation::LeaveOrEnterWindow(double target, WalkReport* finished) {
  const Window& w = *window_;
  if (w.Contains(target, w.stop ? kBranchPointLocation * input_scale_ : 0.0)) {
    EvaluateInWindow(target);
    *finished = Reached();
    return Crossing::kFinished;
  }
  if (w.direction * (target - w.far_end) > 0.0) {
    if (w.stop) {
      const std::string message = w.stop_message;
      EvaluateInWindow(w.star);
      *finished = Ended(WalkStatus::kBranchPointStop, message);
      return Crossing::kFinished;
    }
    const double far_end = w.far_end;
    const Eigen::VectorXd far_q = w.far_q;
    window_.reset();
    SetRegularPose(far_end, far_q);
    return Crossing::kPassed;
  }
  const double near_end = w.near_end;
  const Eigen::VectorXd near_q = w.near_q;
  window_.reset();
  SetRegularPose(near_end, near_q);
  return Crossing::kPassed;
}

void Continuation::EvaluateInWindow(double input) {
  regular_count_ = 0;
  compiled_pose_ = false;
  schedule_loaded_ = false;
  const Window& w = *window_;
  const bool outgoing = !w.outgoing.empty() && w.direction * (input - w.star) > 0.0;
  const HermiteSegment& segment = outgoing ? w.outgoing : w.incoming;
  segment.Coefficients(input, kWindowOrder, window_series_);
  series_ = window_series_;
  series_order_ = kWindowOrder;
  input_ = input;
  at_limit_ = false;
  q_ = window_series_.col(0);
  q_pending_ = false;
  from_window_ = true;
  factorized_here_ = false;
  rcond_ = ReciprocalCondition(solver_.system(), q_);
  valid_order_ = rcond_ < kSingularRowRcond ? segment.ValidOrder() : kMaxOrder;
}

std::string Continuation::LimitMessage(const SingularStructure& s, double input) const {
  const std::string what = s.kind == SingularKind::kLimitPoint
                               ? "a limit point of the drive (a singular position: dead centre with respect to the input; joints "
                               : "a limit point of the drive where loops also fold flat (a singular position no branch passes; joints ";
  return what + JointNames(solver_.system().mechanism(), s.joints) + ") at " + Where(input) + ": the input cannot pass it on this branch";
}

void Continuation::SetLimitPose(double input, const Eigen::VectorXd& q) {
  regular_count_ = 0;
  compiled_pose_ = false;
  schedule_loaded_ = false;
  retreat_input_ = input_;
  retreat_q_ = q_;
  at_limit_ = true;
  input_ = input;
  q_ = q;
  q_pending_ = false;
  from_window_ = false;
  factorized_here_ = false;
  rcond_ = ReciprocalCondition(solver_.system(), q_);
  // the pose is known, its transfer functions are infinite: none is computable here
  valid_order_ = 0;
  series_.setZero(q_.size(), kMaxOrder + 1);
  series_.col(0) = q_;
  series_order_ = kMaxOrder;
}

bool Continuation::FinishAtLimitPoint(double target, double direction, WalkReport* finished) {
  MaterializePose();
  const ConstraintSystem& system = solver_.system();
  const std::optional<LimitPoint> limit = LocateLimitPoint(system, input_, q_);
  if (!limit) return false;
  const double tolerance = kAtLimitPoint * std::max(input_scale_, std::abs(limit->input));
  // the point must lie ahead of the walk and on its branch (not a fold of another one)
  if (direction * (limit->input - input_) < -tolerance || ScaledPoseNorm(limit->q, q_) > options_.max_correction) return false;
  const double beyond = direction * (target - limit->input);
  if (beyond > tolerance) {
    const SingularStructure s = AnalyseSingularity(system, limit->q);
    singular_points_.push_back({SingularKind::kLimitPoint, limit->input, s.rcond, s.joints, options_.at_branch_point});
    SetLimitPose(limit->input, limit->q);
    *finished = Ended(WalkStatus::kLimitPoint, LimitMessage(s, limit->input));
    return true;
  }
  if (beyond >= -tolerance) {  // the target is the point, within roundoff
    SetLimitPose(target, limit->q);
    *finished = Reached();
    return true;
  }
  // between the walk and the point: from the point along its quadratic branch
  // q(s) = q* + s null, input(s) = input* + curvature s^2, on the side the walk came from
  const double delta = target - limit->input;
  if (limit->curvature == 0.0 || (delta > 0.0) != (limit->curvature > 0.0)) return false;
  const Eigen::VectorXd null = Unscaled(limit->null, length_scale_);
  const double side = Unscaled(q_ - limit->q, length_scale_).dot(null) >= 0.0 ? 1.0 : -1.0;
  Eigen::VectorXd q = limit->q + side * std::sqrt(delta / limit->curvature) * limit->null;
  if (!solver_.Correct(target, q).ok()) return false;
  if (Unscaled(q - limit->q, length_scale_).dot(null) * side <= 0.0) return false;  // landed on the other half
  SetRegularPose(target, q);
  *finished = Reached();
  return true;
}

bool Continuation::OneCompiledStepTo(double target, double max_step) {
  return schedule_ && started_ && !at_limit_ && !window_ && target != input_ &&
         std::abs(target - input_) <= std::min(max_step, options_.max_step * input_scale_) && TryCompiledStep(target).accepted;
}

WalkReport Continuation::AdvanceTo(double target, double max_step) {
  if (OneCompiledStepTo(target, max_step)) return Reached();  // the common case, without the walk's setup
  return Walk(target, max_step);
}

WalkReport Continuation::Walk(double target, double max_step) {
  if (!started_) return Ended(WalkStatus::kFailed, "the walk was not started");
  if (!std::isfinite(target) || !(max_step > 0.0)) return Ended(WalkStatus::kFailed, "invalid target or step");
  if (at_limit_) {
    if (target == input_) return Reached();
    SetRegularPose(retreat_input_, retreat_q_);  // back onto the branch, then on as usual
  }
  const double cap = std::min(max_step, options_.max_step * input_scale_);
  if (std::abs(target - input_) > static_cast<double>(options_.max_steps) * cap) {
    return Ended(WalkStatus::kTooFar, Where(target) + " lies more than " + std::to_string(options_.max_steps) +
                                          " continuation steps from " + Where(input_));
  }
  WalkReport finished;
  if (window_ && LeaveOrEnterWindow(target, &finished) == Crossing::kFinished) return finished;
  double h = cap;
  bool examined = false;
  long steps = 0;
  const auto start = std::chrono::steady_clock::now();
  while (input_ != target) {
    if (++steps > options_.max_steps) {
      return Ended(WalkStatus::kTooFar, "more than " + std::to_string(options_.max_steps) + " continuation steps");
    }
    // the clock is read every 1024 steps: a step is a microsecond, a clock read a few dozen ns
    if (steps % 1024 == 0 && OutOfTime(start)) return Ended(WalkStatus::kTooFar, OutOfTimeMessage(steps, target));
    const double remaining = target - input_;
    const double direction = remaining > 0.0 ? 1.0 : -1.0;
    const double next = std::abs(remaining) <= h ? target : input_ + direction * h;
    StepResult step = TryCompiledStep(next);
    if (!step.accepted) step = TryStep(next);
    if (step.accepted) {
      // a stall is examined again once the steps have grown back: a walk creeping on in steps
      // this short (towards a joint that runs off) must not pay an SVD a step
      if (h >= kReexamineStall * options_.stall_fraction * cap) examined = false;
      h = std::min(cap, 2.0 * h);
      if (h < cap && RunsOff()) return Ended(WalkStatus::kRunOff, RunOffMessage());
      continue;
    }
    h *= 0.5;
    if (!examined && h < options_.stall_fraction * cap) {
      if (OutOfTime(start)) return Ended(WalkStatus::kTooFar, OutOfTimeMessage(steps, target));
      examined = true;
      const Crossing crossing = ExamineStall(direction, target, &finished);
      if (crossing == Crossing::kFinished) return finished;
      if (crossing == Crossing::kPassed) {
        h = cap;
        examined = false;
        continue;
      }
    }
    if (h < options_.limit_resolution * input_scale_) return EndAtStall(direction, target);
  }
  return Reached();
}

bool Continuation::OutOfTime(std::chrono::steady_clock::time_point start) const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > options_.time_budget;
}

std::string Continuation::OutOfTimeMessage(long steps, double target) const {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%g", options_.time_budget);
  return "the walk stopped at " + Where(input_) + " short of " + Where(target) + " after " + seconds + " s and " +
         std::to_string(steps) + " continuation steps (its time budget): the branch creeps through a singular stretch there";
}

bool Continuation::RunsOff() const {
  MaterializePose();
  for (int i = 0; i + 2 < q_.size(); i += 3) {
    if (std::abs(q_(i)) > reach_ || std::abs(q_(i + 1)) > reach_) return true;
  }
  return false;
}

std::string Continuation::RunOffMessage() const {
  const Mechanism& m = solver_.system().mechanism();
  std::string links;
  for (size_t k = 0, i = 0; k < m.links.size(); ++k) {
    const int c = solver_.system().CoordinateOf(static_cast<int>(k));
    if (c < 0) continue;
    if (std::abs(q_(c)) > reach_ || std::abs(q_(c + 1)) > reach_)
      links += (i++ ? ", " : "") + m.links[k].name;
  }
  return "the mechanism runs off to infinity near " + Where(input_) + " (link " + links +
         " beyond a million times the mechanism's size: two slide lines turn parallel there, or a link's line passes "
         "through infinity): the input cannot pass it on this branch";
}

Continuation::Crossing Continuation::ExamineStall(double direction, double target, WalkReport* finished) {
  MaterializePose();
  // Steps this short mean a singular position is near. A branch point is crossed here rather than
  // crept around (creeping would follow a roundoff-sized detour onto the other branch), but only
  // where the mechanism's dimensions reach a flat, self-stressed pose: near one they miss, the
  // branch turns sharply, and the walk follows it with shorter steps (or it ends at a limit point).
  const ConstraintSystem& system = solver_.system();
  const SingularStructure s = AnalyseSingularity(system, q_);
  if (!(s.rcond < kNearSingularRcond)) return Crossing::kNotCrossed;
  if (s.constraint_rcond < kNearSingularRcond) {
    const std::optional<BranchPoint> point = LocateBranchPoint(system, input_, q_);
    if (point && point->defect <= kBranchPointDefect && ScaledPoseNorm(point->q, q_) <= options_.max_correction)
      return CrossBranchPoint(point->input, direction, target, finished);
  }
  if (FinishAtLimitPoint(target, direction, finished)) return Crossing::kFinished;
  return Crossing::kNotCrossed;
}

WalkReport Continuation::EndAtStall(double direction, double target) {
  MaterializePose();
  const SingularStructure s = AnalyseSingularity(solver_.system(), q_);
  if (s.rcond < kNearSingularRcond) {
    // A singular position no step passes ends the branch for the drive: a limit point, or a
    // flat, self-stressed pose whose branches all turn back there (a double fold, such as the
    // Peaucellier cell stretched out) — for the drive that too is a limit.
    WalkReport finished;
    if (s.kind == SingularKind::kLimitPoint && FinishAtLimitPoint(target, direction, &finished)) return finished;
    singular_points_.push_back({SingularKind::kLimitPoint, input_, s.rcond, s.joints, options_.at_branch_point});
    return Ended(WalkStatus::kLimitPoint, LimitMessage(s, input_));
  }
  return Ended(WalkStatus::kFailed, "no pose could be found beyond " + Where(input_) +
                                        " (Newton did not converge, and the pose there is not singular)");
}

}  // namespace koppel
