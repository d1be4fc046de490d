// The proportionality deviation of a Model's scalar output over a range of its drive (koppel
// proportional; seed 001, koppel/analysis/proportionality.hpp explains the definition), in the
// model's units (koppel/api/model.hpp).
#pragma once

#include "koppel/analysis/status.hpp"
#include "koppel/api/model.hpp"

#include <optional>
#include <string>

namespace koppel {

struct ProportionalityRequest {
  std::string output;                // a scalar output; empty: the first
  double from = 0, to = 0;           // the range phi_P [deg | length]; from != to
  std::optional<double> at;          // the tangent's input [deg | length]; unset: the flat point (least |s''|)
  std::optional<double> length;      // the reference length l [length] > 0; unset: ReferenceLength(model)
  double resolution = 0.05;          // the sampling step [deg | length]
  AtBranchPoint at_branch_point = AtBranchPoint::kContinue;
};

struct ProportionalityReport {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // partial: over the drivable part (sweep names the gaps)
  std::string message;                              // why not computed, or why partial
  std::string output;
  double from = 0, to = 0;     // as requested [deg | length]
  double range = 0;            // phi_P, the range covered [deg | length]
  double reference = 0;        // the tangent's input [deg | length]
  // As the analysis gives them, the input x in radians (R drive) or length: the slope s'(x) at
  // the reference, the band width delta_s about the tangent and the chord's deviation (in the
  // output's unit; radians for an angle output), the reference length l and
  // Q_P = (delta_s / l) / phi_P [1/rad | 1/length].
  double slope = 0, delta_s = 0, chord_deviation = 0, reference_length = 0, qp = 0;
  SweepRecord sweep;
  std::string Brief() const;
};

// The default reference length l: the crank length l1 (koppel/core/structure.hpp, CrankLength);
// 0 when the drive link has none (then a length must be given).
double ReferenceLength(const Model& model);

// InputError (naming the model's file and the field) for an output that is not scalar, from ==
// to, a reference length that is not positive, a range that cannot be sampled by `resolution`.
ProportionalityReport FindProportionality(const Model& model, const ProportionalityRequest& request);

}  // namespace koppel
