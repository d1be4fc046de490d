// Least-squares fitting of any mechanism file to targets (koppel synth fit): the whole report the
// command prints, in the user's units (degrees for angles). The problem file
// (catalog/include/koppel/catalog/fit_problem.hpp) names the mechanism, the free parameters with
// bounds and starts, and the targets. For a Design of the fit (figures and a Model), see
// SynthesiseFit in koppel/api/synthesis.hpp.
#pragma once

#include "koppel/synthesis/design_space.hpp"

#include <optional>
#include <string>
#include <vector>

namespace koppel {

struct FitRequest {
  std::string problem;         // the fit problem file
  std::optional<int> threads;  // threads for the starts; unset: the file's, else one per core
  bool yaml = false;           // also write the fitted mechanism file (FitOutcome::yaml)
  // where the design must lie (koppel/synthesis/mechanism_space.hpp): the best start inside it
  // is the result; when every start's design lies outside, nothing is fitted and the message
  // names the constraint the best one broke
  DesignSpace space;
};

// One row of the report: quantity, value, unit: the file's length unit ("mm"; "length" when the
// file names none), "deg", "bool", "1", or "parameter" for a fitted parameter of no one measure
// (MeasureOf, koppel/catalog/parameter_use.hpp).
struct FitQuantity {
  std::string quantity;
  double value = 0;
  std::string unit;
};

struct FitOutcome {
  // bad_input: the options, parameters or targets are malformed (message says why; nothing was
  // fitted). fitted: a design was found and built (report holds its rows). ok: every target is
  // within its tolerance and the design assembles over `require`; otherwise message names what
  // was missed, or why there is no design.
  bool bad_input = false, fitted = false, ok = false;
  std::string status;  // "converged", "above tolerance", "not assembling", "no usable start", ...
  std::string message;
  std::vector<std::string> starts;  // each start's solver report, in order
  double cost = 0;                  // 1/2 sum of weighted squares (angles in radians)
  int iterations = 0;
  int best_start = 0;               // 1-based: the start that gave the design
  int starts_at_best = 0;           // usable starts within 1e-6 (relative) of the best cost
  // The fitted parameters, per target its residual, tolerance, whether met (and its input when
  // free), cost, start, starts, starts_at_best, full_rotation (the drive turns a whole turn from
  // its assembly), assembles_over_required_range (else drivable_from / drivable_to), and for each
  // transmission angle output mu_min_<name> over that turn.
  std::vector<FitQuantity> report;
  // request.yaml: the problem's mechanism file as its user wrote it, the free parameters' values
  // replaced by the fitted ones in place (EditMechanismText) and a comment line on top
  std::string yaml;
};

// Throws InputError (file, line) for a problem file that does not read.
FitOutcome FitMechanism(const FitRequest& request);

}  // namespace koppel
