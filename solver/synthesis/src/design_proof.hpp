// Re-analysis of a synthesised crank mechanism by the generic solver: the proof every
// dead-centre design passes before it is returned (deadcentre_synthesis.hpp).
#pragma once

#include "koppel/analysis/status.hpp"
#include "koppel/core/mechanism.hpp"

#include <string>

namespace koppel {

struct CrankReanalysis {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // complete or failed: there is no partial proof
  std::string message;   // why not, when failed
  double phi0 = 0;       // crank angle from the folded to the extended dead centre, counter-clockwise
  double turn = 0;       // output change from the folded to the extended dead centre (angles wrapped
                         // to (-pi, pi]: > 0 counter-clockwise)
  double mu_min = 0;     // smallest transmission angle over a full turn
  double mu_min_at = 0;  // input where it occurs, in [-pi, pi]
  bool ok() const { return status == AnalysisStatus::kComplete; }
};

// Drives the crank through a full turn with the solver and finds the extended and folded dead
// centres of output `stroke_output` and the smallest value of the transmission angle output
// `mu_output`, over the turn from `quiet_input` (any input serves: over a full turn the search
// is periodic, a dead centre at its start is found like any other).
CrankReanalysis ReanalyseCrank(const Mechanism& mechanism, int stroke_output, int mu_output, double quiet_input);

}  // namespace koppel
