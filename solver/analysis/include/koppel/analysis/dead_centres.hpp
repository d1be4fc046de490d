// Dead centres (Totlagen) of a scalar output: the inputs where its first-order transfer
// function vanishes, found along a sweep (sign changes of y', cyclically over whole turns, and
// the range's ends; stationary_search.hpp) and refined by Newton on y' with y'' to 1e-12. Where
// the drive link (crank) and the link it drives (coupler) line up, the dead centre is classified
// extended (Strecklage, äußere Totlage) or folded (Decklage, innere).
#pragma once

#include "koppel/analysis/extremes.hpp"
#include "koppel/analysis/status.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/solver/position.hpp"
#include "koppel/solver/sweep.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace koppel {

enum class DeadCentreKind { kExtended, kFolded, kUnclassified };
const char* ToString(DeadCentreKind kind);

struct DeadCentre {
  double input = 0;   // radians (R drive) or length
  double value = 0;   // output there (radians for angle outputs)
  double second = 0;  // y'' there: < 0 a maximum, > 0 a minimum
  DeadCentreKind kind = DeadCentreKind::kUnclassified;
};

struct DeadCentreReport {
  // kComplete: searched over the whole range; kPartial: over its drivable part only (the gaps are
  // in `sweep`); kFailed: no sample to search (not assemblable, invalid range)
  AnalysisStatus status = AnalysisStatus::kNotRun;
  std::string message;
  SweepEvents sweep;  // of the sweep searched
  // in input order; over whole turns of a rotating drive each once, its input within the first
  // turn from `from` (a dead centre at the start within 1e-9 of it, possibly just below)
  std::vector<DeadCentre> points;
  // Sign changes of y' that are neither a dead centre nor a transmission angle's fold (their
  // input, and why not refined in `message`): a dead centre may be missing there.
  std::vector<double> unresolved;
  // The output's least and largest value over the range, from the same search (extremes.hpp):
  // for a transmission angle mu_min and mu_max.
  OutputExtremes extremes;
  // For an output with one extended and one folded dead centre per turn (the classic crank
  // mechanisms; otherwise the maximum and minimum stand in for them): phi_a, phi_i, s_a, s_i,
  // stroke s_H = |s_a - s_i|, the crank angle of the forward stroke phi_H from phi_a to phi_i in
  // the positive sense, and the phase ratio phi_H / (2 pi - phi_H).
  bool has_stroke = false;
  bool classified = false;  // phi_a / phi_i from the crank–coupler line-up, not from max/min
  double phi_a = 0, phi_i = 0, s_a = 0, s_i = 0, stroke = 0, phi_h = 0, phase_ratio = 0;
  // The time ratio: the slow stroke's crank angle over the fast one's, the phase ratio or its
  // reciprocal, >= 1 (1: no quick return); 0 without a stroke.
  double TimeRatio() const { return phase_ratio > 0 ? std::max(phase_ratio, 1.0 / phase_ratio) : 0.0; }
  std::string Brief() const;
};

// Sweeps `range` (its step sets the search resolution) and refines every dead centre of output
// `output` (component 0/1 for a point).
DeadCentreReport FindDeadCentres(const Mechanism& mechanism, int output, int component, const SweepOptions& range);

// The crank–coupler line-up at pose q: kExtended, kFolded, or kUnclassified when the mechanism
// has no crank (binary drive link) with a coupler joined by R joints, or they are not aligned.
DeadCentreKind ClassifyLineUp(const Mechanism& mechanism, const Eigen::VectorXd& q);

}  // namespace koppel
