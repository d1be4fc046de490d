// Least-squares fitting of any mechanism (synth fit) with Ceres: free parameters with bounds,
// targets on point positions (precision points, with the inputs prescribed or free) and on
// output values (function generation).
//
// The mechanism is a function of the parameters through a builder (the catalog rebuilds it from
// the YAML file with the parameter values as overrides). Gradients go through the solver by the
// implicit-function theorem: at a solved pose, dq/dp = -J^-1 dF/dp with the Jacobian J already
// factorised; dF/dp is one central difference of the residual function at the fixed pose (no
// Newton inside a difference), and the output's total derivative is one directional difference
// along (dq/dp, e_p). A free input adds dy/dinput, the exact first-order transfer function.
// A dead-centre target differentiates y' = 0 implicitly: dy'/dp at the fixed input comes from
// the poses q +- h dq/dp (first-order IFT predictions, polished by the factorisation's Newton
// step) of the perturbed mechanisms.
#pragma once

#include "koppel/core/mechanism.hpp"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace koppel {

// Builds the mechanism for parameter values; false and *error when the values make no mechanism.
using MechanismBuilder = std::function<bool(const std::vector<double>& values, Mechanism* mechanism, std::string* error)>;

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
};

struct FitOptions {
  int starts = 1;           // 1: from the given start; more: also random starts in the bounds (fixed seed)
  unsigned seed = 20261122;
  int max_iterations = 200;
  double require_from = 0, require_to = 0;  // inputs over which a design must assemble (empty if equal)
  bool quiet = true;
};

struct FitReport {
  bool ok = false;
  std::string message;
  std::vector<double> values;            // fitted parameters
  std::vector<double> target_residuals;  // per target: |error| (point: distance; straight: the largest deviation), unweighted
  std::vector<double> fitted_inputs;     // per target (free ones moved)
  double cost = 0;                       // Ceres cost: 1/2 sum of weighted squares
  int iterations = 0;
  int start_index = 0;                   // which start gave the result
  bool assembles_over_range = false;     // over FitOptions' required range; preferred among starts
};

FitReport Fit(const MechanismBuilder& builder, const std::vector<FitParameter>& parameters, const std::vector<FitTarget>& targets,
              const FitOptions& options);

}  // namespace koppel
