// Walking a mechanism along its drive input by predictor–corrector continuation, on one branch.
//
// Predictor: the 2nd-order Taylor series of q(input) (exact transfer functions). Corrector:
// Newton. A step is accepted only when Newton converges in a few iterations, the correction is
// small (in units of L, radians for angles) and the first-order transfer functions at the new
// pose continue the predicted ones — a step that lands on another assembly branch changes them
// by O(1) — and det J keeps its sign. det J changes sign only at singular positions; a step that
// changes it is refused, so the walk refines its step towards the position: it follows a branch
// that turns sharply without a singular position (a linkage a hair from its change point, whose
// branch passes the other one at sqrt(defect) — the step is not a guess at the branch), and it
// stalls at a limit point or at a branch point, which are then located (below).
//
// Regular steps take the compiled joint-point schedule (point_schedule.hpp) where the mechanism
// compiles into one and the solver is not asked for the dense reference path: the same guards
// (iterations, correction, tangent), and a step whose dyad determinants come near zero
// (kFastGauge) or change sign is handed to the general step. A pose reached by the schedule has
// no factorisation of its own: whatever needs one (a higher order, a singular-position test
// below the gauge, the general step) first re-solves the pose with the general kernel.
//
// Singular positions (see singular.hpp):
// - limit point: no step gets past. Where the steps stall, the point is located on the augmented
//   system (singular.hpp, LocateLimitPoint) to roundoff; a target between the walk and the point
//   is reached from the point along its quadratic branch q(s) = q* + s null (Newton at the
//   target), a target on the point itself gets the pose there (flagged singular, valid order 0:
//   the transfer functions are infinite), a target beyond it ends the walk at the point. Should
//   the augmented Newton fail, the walk ends where steps shorter than `limit_resolution` fail.
// - branch point: only where the mechanism's dimensions reach a flat, self-stressed pose to
//   roundoff (singular.hpp, LocateBranchPoint: defect at most kBranchPointDefect L); crossed along
//   the incoming branch (ContinuationOptions::at_branch_point says
//   whether to continue on the branch that continues the incoming one analytically, to stop, or
//   to switch to the other). The crossing jumps from a pose A a window's half-width before the
//   point to a pose B as far beyond it, predicting along A's Taylor series and verifying at B
//   that the transfer functions continue; the point itself is the bifurcation system's solution
//   (singular.hpp, LocateBranchPoint), the window centred on it. Inside the window, poses and the transfer functions up to 3rd order come from
//   the Hermite interpolant of A and B: both ends are well-conditioned, the point is not.
#pragma once

#include "koppel/core/mechanism.hpp"
#include "koppel/solver/point_schedule.hpp"
#include "koppel/solver/position.hpp"
#include "koppel/solver/singular.hpp"

#include <Eigen/Core>

#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace koppel {

struct ContinuationOptions {
  // Largest continuation step [rad for an R drive, units of L for a P drive]: the predictor's
  // error (~ q''' h^3) stays far below the distance between assembly branches.
  double max_step = 0.05;
  // The walk gives up stepping towards a singular position when steps this short fail [rad, or
  // units of L]; a limit point is then located to roundoff on the augmented system (see above).
  double limit_resolution = 1e-11;
  // Steps shorter than this fraction of max_step mean a singular position is near: the pose is
  // examined (an SVD) and a branch point is crossed rather than crept around.
  double stall_fraction = 1e-7;
  // Half-width of the window around a branch point [rad, or units of L]; see the file comment.
  double branch_window = 1e-2;
  // Newton iterations a corrector may use before the step counts as too long.
  int max_corrector_iterations = 8;
  // Largest Newton correction of a predicted pose [units of L; rad for angles].
  double max_correction = 0.02;
  // Largest change of the first-order transfer functions against their prediction, relative to
  // (1 + their size) in units of L and rad.
  double max_tangent_change = 0.02;
  BranchPointAction at_branch_point = BranchPointAction::kContinue;
  // Continuation steps one AdvanceTo may take: a walk to a far input is refused, never endless.
  long max_steps = 20'000'000;
  // Seconds one AdvanceTo may take: a walk that creeps (a singular stretch examined again and
  // again) ends, saying where it stood, instead of running on. 20 million steps of a four-bar take
  // about 4 s; a walk of a few samples' distance takes microseconds.
  double time_budget = 30.0;

  // Empty *why and true when every field is usable; otherwise the first problem.
  bool IsValid(std::string* why) const;
};

enum class WalkStatus {
  kNotRun,
  kReached,          // the target input was reached
  kLimitPoint,       // a limit point of the drive lies between: the branch ends there
  kBranchPointStop,  // a branch point lies between and the options say stop
  kTooFar,           // the target needs more than max_steps steps or time_budget seconds
  kFailed,           // no pose could be found (Newton failed without a singular position)
  kRunOff,           // a joint runs off to infinity ahead (two slide lines turn parallel): the branch ends there
};
const char* ToString(WalkStatus status);

struct WalkReport {
  WalkStatus status = WalkStatus::kNotRun;
  double input = 0.0;   // where the walk stands: the target when reached
  std::string message;  // why it ended short; empty when reached
  bool ok() const { return status == WalkStatus::kReached; }
};

// Walks one mechanism along its input. Holds the solver's factorisation at the current pose.
class Continuation {
 public:
  Continuation(PositionSolver& solver, ContinuationOptions options = {});
  ~Continuation();

  // Starts at (input, q); q need only be close: Newton polishes it.
  SolveReport Start(double input, const Eigen::VectorXd& q);
  // Moves to `target` in steps of at most min(max_step, options.max_step) (max_step > 0). On
  // failure the walk stands at the last input it reached and the report says why.
  WalkReport AdvanceTo(double target, double max_step);

  double input() const { return input_; }
  const Eigen::VectorXd& q() const {
    MaterializePose();
    return q_;
  }
  // Taylor coefficients d^k q / d input^k / k! at the current pose in columns 0..order (the
  // matrix may have more columns, left from a higher order asked for before: read only these,
  // e.g. with leftCols(order + 1)). Columns above ValidOrder() are zero: not computable here. Precondition 0 <= order <= kMaxOrder
  // (std::out_of_range otherwise: the caller validated its options, e.g. SweepOptions::IsValid).
  const Eigen::MatrixXd& Series(int order);
  // Every output's value and derivatives up to `order` at the current pose, as
  // PositionSolver::OutputDerivatives(Series(max(order, 2)), order, out): at a pose of the
  // compiled schedule and order <= 2 from the schedule's jets (the same outputs on the same
  // series, without the matrix; PointSchedule::OutputDerivatives).
  void OutputDerivatives(int order, double* out);
  // kMaxOrder at a regular pose; 3 at a singular pose inside a branch-point window, where
  // higher orders through J^-1 would be noise.
  int ValidOrder() const { return valid_order_; }
  // True when the current pose is singular: reciprocal condition of J S below kSingularRowRcond.
  bool AtSingularPose();
  // Every singular position the walk met, in the order met.
  const std::vector<SingularPoint>& singular_points() const { return singular_points_; }

 private:
  struct Window;
  struct StepResult {
    bool accepted = false;
  };
  // max |a - b| over the coordinates, in units of L (positions) and rad (angles)
  double ScaledPoseNorm(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;
  // the same for first-order transfer functions dq/dinput (b may be null: |a| itself)
  // (a is taken by reference: a column of a series is read in place, not copied to the heap)
  double ScaledTangentNorm(Eigen::Ref<const Eigen::VectorXd> a, const Eigen::VectorXd* b) const;
  enum class Crossing { kNotCrossed, kPassed, kFinished };
  StepResult TryStep(double next);
  // The schedule's step; accepted poses are regular (every dyad's gauge above kFastGauge).
  StepResult TryCompiledStep(double next);
  // AdvanceTo's common case: `target` within one step of a regular pose, reached by the
  // compiled step (which never crosses a sign change of det J); false: the walk's full loop.
  bool OneCompiledStepTo(double target, double max_step);
  // AdvanceTo's walk: steps, halved and doubled, across singular positions, to the target or to
  // where it ends (out of line: AdvanceTo's common case saves no registers for it)
  [[gnu::noinline]] WalkReport Walk(double target, double max_step);
  // After compiled steps: the general kernel's factorisation, sign and gauge at the current pose.
  void EnsureFactorized();
  // Keeps the current pose as the last regular one when `regular`, else forgets the last one (the
  // walk jumped: a pose set from outside, a window's end).
  void RememberIfRegular(bool regular);
  // The newest remembered regular pose at or behind `input` in `direction` (of the ring below or
  // of the schedule's history); false when there is none.
  struct RegularPose {
    double input = 0.0;
    Eigen::VectorXd q;
    long seq = 0;  // when it was remembered (seq_)
  };
  bool RegularPoseBefore(double input, double direction, RegularPose* pose) const;
  // A compiled step leaves q_ to be written from the schedule when first read: its angles cost an
  // atan2 each, which a walk whose outputs come from the schedule's jets need not pay per step.
  void MaterializePose() const;
  void Accept(double next);
  void SetRegularPose(double input, const Eigen::VectorXd& q);
  bool RestoreFactorization();
  bool RegularWalkTo(double target);
  Crossing CrossBranchPoint(double estimate, double direction, double target, WalkReport* finished);
  // One attempt at the branch point located at `estimate`: the window of half-width `delta` about
  // it (A before it on the incoming branch, B beyond on A's prediction);
  // null when A or B is not reached. *at_star: the pose and tangent at the point.
  std::unique_ptr<Window> OpenBranchWindow(double estimate, double direction, double delta, Eigen::MatrixXd* at_star);
  // Continues the window past its point on the other branch (its far end B'); false when that
  // branch does not cross the point in the input.
  bool SwitchBranchInWindow(const Eigen::MatrixXd& at_star, Window* window);
  Crossing LeaveOrEnterWindow(double target, WalkReport* finished);
  // AdvanceTo's steps stall: crosses a branch point here, or finishes at a limit point ahead;
  // kNotCrossed when neither is near (the walk goes on with shorter steps).
  Crossing ExamineStall(double direction, double target, WalkReport* finished);
  // The current pose has run off (a link's origin beyond kRunOff L): where two slide lines turn
  // parallel, their meeting point goes to infinity, and no step reaches the input there.
  bool RunsOff() const;
  std::string RunOffMessage() const;
  bool OutOfTime(std::chrono::steady_clock::time_point start) const;  // the walk's time_budget is spent
  std::string OutOfTimeMessage(long steps, double target) const;
  // AdvanceTo's steps fell below the limit resolution: the walk ends here (at a limit point, or failed).
  WalkReport EndAtStall(double direction, double target);
  // At a stall in `direction` towards `target`: locates the limit point ahead and reaches the
  // target (or ends at the point). False when no limit point was located (the caller goes on).
  bool FinishAtLimitPoint(double target, double direction, WalkReport* finished);
  void SetLimitPose(double input, const Eigen::VectorXd& q);
  std::string LimitMessage(const SingularStructure& s, double input) const;
  void EvaluateInWindow(double input);
  WalkReport Reached() const;
  WalkReport Ended(WalkStatus status, std::string message) const;
  std::string Where(double input) const;

  PositionSolver& solver_;
  ContinuationOptions options_;
  double length_scale_ = 1.0;
  double input_scale_ = 1.0;  // 1 for an R drive, L for a P drive
  bool started_ = false;
  double reach_ = 0.0;  // a link's origin beyond this |x| or |y| has run off (RunsOff)
  // the current pose
  double input_ = 0.0;
  mutable Eigen::VectorXd q_;
  mutable bool q_pending_ = false;  // q_ is the schedule's pose, not yet written
  bool factorized_here_ = false;  // the solver's factorisation belongs to the current pose
  bool from_window_ = false;      // the current pose came from a window's interpolant
  int sign_ = 0;
  double determinant_ = 0.0;
  double rcond_ = -1.0;           // < 0: not yet computed
  double pivot_ratio_ = 0.0;      // of the current pose's factorisation
  int valid_order_ = kMaxOrder;
  Eigen::MatrixXd series_;
  int series_order_ = -1;
  Eigen::MatrixXd window_series_;  // the interpolant's coefficients at a window pose
  // workspaces, allocated once: no allocation per step
  Eigen::VectorXd q_trial_, predicted_, tangent_predicted_;
  Eigen::MatrixXd trial_series_;
  std::unique_ptr<Window> window_;
  // standing on a located limit point: the regular pose the walk came from, to step back to
  bool at_limit_ = false;
  double retreat_input_ = 0.0;
  Eigen::VectorXd retreat_q_;
  std::vector<SingularPoint> singular_points_;
  // the compiled step: null when the mechanism does not compile or the dense path is asked for
  std::unique_ptr<PointSchedule> schedule_;
  PointSchedule::StepOptions schedule_options_;  // the walk's guards, as the schedule takes them
  bool schedule_loaded_ = false;  // the schedule's state is the current pose
  bool compiled_pose_ = false;    // the current pose came from the schedule (no factorisation)
  std::function<void(Eigen::VectorXd&)> fill_pose_;  // the solver's AdoptPending: the schedule's pose
  // the last accepted poses of the walk that were clearly regular (pivot gauge above
  // kRegularPivotRatio), newest last, since the walk last jumped: a branch crossing starts from
  // one behind its window. Compiled poses stay in the schedule's history (every one is regular),
  // numbered on from schedule_seq_ backwards.
  long seq_ = 0, schedule_seq_ = 0;
  static constexpr int kRememberedPoses = 8;
  std::array<RegularPose, kRememberedPoses> regular_;
  int regular_next_ = 0, regular_count_ = 0;
};

}  // namespace koppel
