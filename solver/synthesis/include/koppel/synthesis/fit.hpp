// Least-squares fitting of any mechanism (synth fit) with Ceres: free parameters with bounds,
// targets on point positions (precision points, with the inputs prescribed or free), on output
// values (function generation), on dead centres and on straight-line stretches.
//
// The mechanism is a function of the parameters through a builder (the catalog rebuilds it from
// the YAML text with the parameter values as overrides). Gradients go through the solver by the
// implicit-function theorem: at a solved pose, dq/dp = -J^-1 dF/dp with the Jacobian J already
// factorised; dF/dp is one central difference of the residual function at the fixed pose (no
// Newton inside a difference), and the output's total derivative is one directional difference
// along (dq/dp, e_p). A free input adds dy/dinput, the exact first-order transfer function.
// A dead-centre target differentiates y' = 0 implicitly: dy'/dp at the fixed input comes from
// the poses q +- h dq/dp (first-order IFT predictions, polished by the factorisation's Newton
// step) of the perturbed mechanisms.
//
// Angles: every angle-valued residual (an output that is an angle: link angle, direction,
// transmission angle, R-joint angle; a dead-centre input of an R drive) is the wrapped difference
// in (-pi, pi], whatever range the output is reported in, so a target at 202 deg meets an output
// reported as -158 deg. Each target is met when its residual is within its tolerance; a fit whose
// best design misses a target, or does not assemble over the required range, says so in its
// status. Several starts (the given one, then random ones within the bounds from a fixed seed)
// run in parallel; the result does not depend on the number of threads.
#pragma once

#include "koppel/analysis/sensitivity.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/expected.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/synthesis/design_space.hpp"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace koppel {

// MechanismBuilder: koppel/analysis/sensitivity.hpp (shared with the tolerance analysis).

struct FitParameter {
  std::string name;
  double start = 0, lower = -1e300, upper = 1e300;
};

struct FitTarget {
  std::string name;      // for the report
  int output = -1;       // output index in the built mechanism
  int component = 0;     // 0 or 1 (point x, y); a point target uses both
  bool point = false;    // true: both components against `position`
  // true: the output's dead centre nearest `input` must lie at `input` (Totlage at a prescribed
  // crank angle); its sensitivity is d(input_dc)/dp = -(d y'/dp) / y'' at the dead centre
  bool deadcentre = false;
  // true: the point output over [input, to] (`samples` samples) must lie on a straight line: the
  // residuals are the samples' distances from their total-least-squares line (differentiated with
  // the line's first-order motion: centroid and direction follow the samples)
  bool straight = false;
  double to = 0;
  int samples = 0;
  double input = 0;      // radians (R drive) or length; the start value when free
  bool input_free = false;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // point targets
  double value = 0;      // output targets (radians for angles)
  double weight = 1;
  double tolerance = 0;  // met when the residual is within this (its unit); 0: FitOptions' default
};

// What a target's residual measures.
enum class FitUnit { kLength, kAngle };
const char* ToString(FitUnit unit);  // "length", "angle"
// What target t measures in mechanism m: an angle for an angle output (link angle, direction,
// transmission angle, R-joint angle) and for a dead centre of an R drive; else a length.
FitUnit TargetUnit(const Mechanism& m, const FitTarget& t);

// Enough for small exactly solvable problems (three precision points of a four-bar find their
// global minimum from several of them, see fit_test.cpp); two cores run them in parallel.
inline constexpr int kDefaultFitStarts = 16;

struct FitOptions {
  int starts = kDefaultFitStarts;  // the given start, then random starts within the bounds
  unsigned seed = 20261122;
  int max_iterations = 200;
  int threads = 0;  // starts run on this many threads; 0: one per core
  double require_from = 0, require_to = 0;  // inputs over which a design must assemble (none if equal)
  // Defaults of FitTarget::tolerance: a length target is met within length_tolerance (the
  // mechanism's length unit), an angle target within angle_tolerance [rad] (1e-6 deg).
  double length_tolerance = 1e-6;
  double angle_tolerance = DegToRad(1e-6);
  // Where the design must lie (mechanism_space.hpp says what each key means for any mechanism):
  // the best start inside it is the result; a start outside it never is. mu_min is checked over
  // the required range, or over a whole turn of an R drive from its assembly when none is given.
  DesignSpace space;
  bool IsValid(std::string* why) const;
};

enum class FitStatus {
  kNotRun,
  kConverged,       // every target within its tolerance, assembled over the required range
  kAboveTolerance,  // the best design misses some target
  kNotAssembling,   // targets met, but the design does not assemble over the required range
  kNoUsableStart,   // no start gave a design that assembles at every target
  kOutsideSpace,    // every usable start's design lies outside FitOptions::space
  kInvalidOptions,  // FitOptions::IsValid failed, or parameters / targets are malformed
};
const char* ToString(FitStatus status);

struct FitTargetResult {
  std::string name;
  FitUnit unit = FitUnit::kLength;
  double residual = 0;   // |error| in length or radians, unweighted (point: distance; straight: largest deviation)
  double tolerance = 0;  // the one it was held to
  bool met = false;
  double input = 0;      // the target's input (moved when free)
};

struct FitStart {
  int index = 0;                // 0: the given start
  std::string brief;            // Ceres' BriefReport
  bool usable = false;          // Ceres returned a usable solution that assembles at every target
  double cost = 0;              // at its solution (usable only)
  bool assembles_over_range = false;
  std::string outside;          // the design-space constraint its solution breaks; empty inside
};

struct FitReport {
  FitStatus status = FitStatus::kNotRun;
  std::string message;  // the targets missed and by how much, or why no design
  bool ok() const { return status == FitStatus::kConverged; }
  std::string Brief() const;

  std::vector<double> values;            // fitted parameters (empty without a usable start)
  std::vector<FitTargetResult> targets;  // per target
  double cost = 0;                       // Ceres cost: 1/2 sum of weighted squares (angles in rad)
  int iterations = 0;
  int best_start = -1;                   // which start gave the result
  int starts_at_best = 0;                // usable starts whose cost is within 1e-6 (relative) or 1e-24 of the best
  std::vector<FitStart> starts;          // every start, in order
  bool assembles_over_range = false;     // over FitOptions' required range; preferred among starts
  // when it does not: the inputs the drive reaches from the assembly hint (radians or length)
  double drivable_from = 0, drivable_to = 0;
};

FitReport Fit(const MechanismBuilder& builder, const std::vector<FitParameter>& parameters, const std::vector<FitTarget>& targets,
              const FitOptions& options);

}  // namespace koppel
