// Sweeps of the drive input: every output and its transfer functions at the samples
// from, from + step, ... up to `to`, on the assembly branch the mechanism's hint chooses.
//
// The sweep assembles at the hint's input and walks outward from there (continuation.hpp), up
// to the larger end of the range and down to the smaller, so every sample it can reach on that
// branch is computed — including those on the way from the assembly to `from` — and the parts
// of the range the branch cannot be driven through (beyond a limit point, or a branch point with
// BranchPointAction::kStop) are listed as gaps. A sample at a singular pose is flagged; inside a
// branch-point window its transfer functions up to 3rd order are the branch's (the interpolant
// of the window), higher orders are marked not computable.
#pragma once

#include "koppel/core/angles.hpp"
#include "koppel/core/limits.hpp"  // kMaxSweepSamples
#include "koppel/core/mechanism.hpp"
#include "koppel/solver/continuation.hpp"
#include "koppel/solver/position.hpp"
#include "koppel/solver/singular.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace koppel {

struct SweepOptions {
  double from = 0.0;  // drive input: radians for an R drive, length for a P drive
  double to = 2.0 * kPi;
  double step = kPi / 180.0;  // != 0; its sign is ignored (from -> to)
  int order = 2;  // highest transfer function order in the table (0..kMaxOrder)
  ContinuationOptions continuation;
  NewtonOptions newton;  // the corrector; newton.dense: the reference path (see NewtonOptions)
  // Keep every sample's pose (SweepResult::poses). false: poses has no columns, and a compiled
  // walk step never writes its link angles (an atan2 a link a row) for a caller that shows only
  // the outputs (the API's tables).
  bool poses = true;

  // Empty *why and true when usable: finite from/to/step, step != 0, order in 0..kMaxOrder, at
  // most kMaxSweepSamples samples, valid continuation options.
  bool IsValid(std::string* why) const;
};

// Row-major so that one sample's outputs are contiguous (written in place by the solver).
using Table = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct InputInterval {
  double from = 0.0, to = 0.0;  // in sweep order (from may be above to)
};

enum class SweepStatus {
  kNotRun,
  kComplete,        // every requested sample computed, and the whole range drivable
  kPartial,         // part of the range (some samples, or a gap between two) is not drivable: see gaps
  kNotAssemblable,  // no pose at the assembly input
  kInvalidOptions,  // see SweepOptions::IsValid
};
const char* ToString(SweepStatus status);

struct SweepResult {
  SweepStatus status = SweepStatus::kNotRun;
  std::string message;             // why samples are missing; empty when complete
  std::vector<std::string> notes;  // what the user should know although every sample was computed
  int order = 2;
  int requested_samples = 0;
  std::vector<double> inputs;  // the computed samples, in sweep order
  Table outputs;               // inputs.size() x OutputWidth(order), see OutputDerivatives
  Table poses;                 // inputs.size() x NumCoordinates() (x 0 without SweepOptions::poses)
  std::vector<std::uint8_t> singular;   // per row: 1 when its pose is singular (rcond < kSingularRowRcond)
  std::vector<std::int8_t> valid_order;  // per row: transfer functions above this order are not computable there (stored as 0)
  std::vector<SingularPoint> singular_points;  // met by the walks, in input order
  std::vector<InputInterval> gaps;             // parts of from..to that are not drivable, in sweep order
  InputInterval reached;  // the input interval the walks covered, around the assembly input (low, high)
  // Cells of `outputs` that are not finite numbers (an output not differentiable there: a distance
  // through zero has no derivative where it vanishes), stored as 0 and listed here by (row,
  // column), ascending; `message` names the outputs and inputs (also when complete: the samples
  // are all there, the status says nothing about cells). Never printed as numbers.
  struct Cell {
    int row = 0, column = 0;
    bool operator<(const Cell& o) const { return row != o.row ? row < o.row : column < o.column; }
  };
  std::vector<Cell> undefined;
  bool Defined(int row, int column) const;

  bool complete() const { return status == SweepStatus::kComplete; }
  // One line: status, rows, singular points and gaps.
  std::string Brief() const;
};

// What a sweep met on its way, without its rows: the part every analysis built on a sweep
// passes on, so that the reader learns of the singular points and gaps behind its numbers.
struct SweepEvents {
  SweepStatus status = SweepStatus::kNotRun;
  std::string message;
  std::vector<std::string> notes;
  std::vector<SingularPoint> singular_points;
  std::vector<InputInterval> gaps;
  InputInterval reached;
  std::vector<double> singular_inputs;  // inputs of the rows flagged singular
  bool complete() const { return status == SweepStatus::kComplete; }
};
SweepEvents EventsOf(const SweepResult& sweep);

// Assembles at the mechanism's hint and samples from..to on that branch.
// Precondition: CheckConsistency(mechanism) is empty.
SweepResult Sweep(const Mechanism& mechanism, const SweepOptions& options);

// The input interval the drive can reach from the assembly hint, following the branch up to
// `span` either way (radians or length): for a double rocker, its two limit positions.
struct InputRange {
  double low = 0, high = 0;
  bool low_limited = false, high_limited = false;  // stopped before `span`
};
InputRange DrivableRange(const Mechanism& mechanism, double span, double step);

// Number of samples of from..to in steps of |step| (the last one at most `to`), as a double so
// that absurd requests can be refused before anything is allocated; 1 for a zero step.
double SampleCount(double from, double to, double step);

}  // namespace koppel
