// Stationary points of an output (where its first-order transfer function vanishes): the
// dead centres (Totlagen) of an output, and the extremes of any output over the input.
// Newton on y'(input) = 0 with y'' from the exact Taylor series, moving along the assembly
// branch by continuation.
#pragma once

#include "koppel/analysis/status.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/solver/continuation.hpp"

#include <Eigen/Core>

#include <string>

namespace koppel {

struct StationaryPoint {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // kComplete: found
  std::string message;       // why not found
  double input = 0.0;        // radians (R drive) or length (P drive)
  double value = 0.0;        // the output there
  double second = 0.0;       // y'' there: < 0 a maximum, > 0 a minimum (order 2: y''')
  int iterations = 0;
  Eigen::VectorXd q;         // the pose there
  bool ok() const { return status == AnalysisStatus::kComplete; }
  std::string Brief() const;
};

struct StationaryOptions {
  // The transfer function refined to `target`: order 1, target 0 a stationary point; order 1,
  // target k an extreme of y - k input (the deviation from a line of slope k); order 2, target 0
  // a flat point (y'' = 0, an inflection of y).
  int order = 1;
  double target = 0.0;
  // |y'| small enough relative to |y''| that the input is within this of the root [rad or length]
  double input_tolerance = 1e-12;
  int max_iterations = 40;
  // Largest Newton step in the input: keeps the search near the sample it started from.
  double max_step = 0.1;
  ContinuationOptions continuation;  // how to walk between Newton steps
  bool IsValid(std::string* why) const;
};

// Refines a stationary point of output `output` (component 0/1 for points) starting from a
// converged pose q at `input` (e.g. a sweep sample next to a sign change of y'): Newton on
// y^(order) - target with y^(order + 1).
StationaryPoint RefineStationary(const Mechanism& mechanism, int output, int component, double input,
                                 const Eigen::VectorXd& q, const StationaryOptions& options = {});

// Refines a fold of an output that is folded onto a bound: a transmission angle, folded to
// 0..90 deg, has a kink where the angle it folds passes 90 deg (a maximum, y' jumps from + to -)
// or 0 (a minimum, at a singular position). There y = `fold` and y' changes sign without
// vanishing: Newton on h = sign(y') (y - fold), whose slope |y'| is regular on both sides,
// starting from a converged pose q at `input`. Found only within `bracket_low` .. `bracket_high`
// (a step of Newton leaving that interval ends the search); `second` is 0 in the result.
StationaryPoint RefineFold(const Mechanism& mechanism, int output, double fold, double input, const Eigen::VectorXd& q,
                           double bracket_low, double bracket_high, const StationaryOptions& options = {});

}  // namespace koppel
