// Sweeps of the drive input by predictor–corrector continuation: the Taylor series of q
// (1st and 2nd order transfer functions) predicts, Newton corrects. A step is accepted only
// when Newton converges quickly, the correction stays small and det J keeps its sign, so the
// sweep stays on the assembly branch it started on; otherwise the step is halved. Where no
// step gets through, the sweep stops and says where and why.
#pragma once

#include "koppel/core/mechanism.hpp"
#include "koppel/solver/position.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel {

struct ContinuationOptions {
  // Smallest sub-step, relative to the requested step: the resolution with which a
  // singular position is located (1e-9 of a 1 degree step is about 2e-11 rad).
  double min_step_fraction = 1e-9;
  // Newton iterations a corrector may use before the step counts as too long.
  int max_corrector_iterations = 8;
  // Largest Newton correction, relative to the length scale, before the step counts as a
  // possible branch jump.
  double max_correction = 0.05;
};

// Walks one mechanism along its input. Holds the solver's factorisation at the current pose.
class Continuation {
 public:
  Continuation(PositionSolver& solver, ContinuationOptions options = {});

  // Starts at (input, q); q need only be close: Newton polishes it.
  SolveReport Start(double input, const Eigen::VectorXd& q);
  // Moves to `target`, in sub-steps of at most `max_step` (> 0). On failure the state stays
  // at the last input reached and the report says why (kSingular: the Jacobian went singular
  // or changed sign on the way; kDidNotConverge: no sub-step could be corrected).
  SolveReport AdvanceTo(double target, double max_step);

  double input() const { return input_; }
  const Eigen::VectorXd& q() const { return q_; }
  // Taylor coefficients of q at the current pose (columns 0..order), see PositionSolver::Series.
  const Eigen::MatrixXd& Series(int order);

 private:
  PositionSolver& solver_;
  ContinuationOptions options_;
  double input_ = 0.0;
  Eigen::VectorXd q_, q_trial_, predicted_;
  Eigen::MatrixXd series_;
  int series_order_ = -1;
};

struct SweepOptions {
  double from = 0.0;          // drive input: radians for an R drive, length for a P drive
  double to = 2.0 * 3.14159265358979323846;
  double step = 3.14159265358979323846 / 180.0;
  int order = 2;              // highest transfer function order in the table (0..kMaxOrder)
  ContinuationOptions continuation;
};

// Row-major so that one sample's outputs are contiguous (written in place by the solver).
using Table = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct SweepResult {
  SolveStatus status = SolveStatus::kConverged;  // kConverged: every requested sample computed
  std::string message;                           // why the sweep stopped, empty when complete
  double stopped_at = 0.0;                       // last input reached when it stopped
  int order = 2;
  int requested_samples = 0;
  std::vector<double> inputs;  // computed samples only
  Table outputs;               // inputs.size() x OutputWidth(order), see OutputDerivatives
  Table poses;         // inputs.size() x NumCoordinates()
  bool complete() const { return status == SolveStatus::kConverged; }
};

// Assembles at the mechanism's hint, follows the branch to `from`, then samples from..to.
// Precondition: CheckConsistency(mechanism) is empty and options.step != 0.
SweepResult Sweep(const Mechanism& mechanism, const SweepOptions& options);

// The input interval the drive can reach from the assembly hint, following the branch up to
// `span` either way (radians or length): for a double rocker, its two limit positions.
struct InputRange {
  double low = 0, high = 0;
  bool low_limited = false, high_limited = false;  // stopped before `span`
};
InputRange DrivableRange(const Mechanism& mechanism, double span, double step);

// Number of samples of from..to in steps of |step| (the last one at most `to`).
int SampleCount(double from, double to, double step);

}  // namespace koppel
