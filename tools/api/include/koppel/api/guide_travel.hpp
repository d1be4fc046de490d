// The travel of each slider along its guide over a range of the drive: how long the slot of a
// workshop drawing (koppel export --dxf, koppel animate) must be cut. For a prismatic joint its
// displacement s, the joint's own value (an output {joint: S}): the block's point from the
// guide's point along the guide's axis, in the guide link's frame [length unit]. Its least and
// greatest value over the range are extremes of s (analysis FindOutputExtremes): a stationary
// point refined by Newton on s' to 1e-12 in the input, or an end of the range; never the
// nearest sample, which falls short of a dead centre by about s'' step^2 / 8.
//
// Inputs in the solver's units, as the pictures hold them: radians for an R drive, length for a
// P drive (unlike Model's degrees).
#pragma once

#include "koppel/analysis/status.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/solver/branch_point_action.hpp"  // BranchPointAction: the words, without the solver

#include <string>
#include <vector>

namespace koppel {

struct GuideTravel {
  int joint = -1;     // index of the prismatic joint in mechanism.joints
  std::string name;   // its name
  // kComplete: over the whole range; kPartial: over the part the drive reaches (the message
  // says why not all); kFailed: no travel (low = high = 0), the message says why.
  AnalysisStatus status = AnalysisStatus::kNotRun;
  std::string message;
  double low = 0, high = 0;  // least and greatest s [length unit], low <= high
};

// One entry per prismatic joint, in joint order, over from..to searched at `step` (the search
// resolution: every extreme is refined) on the branch of the assembly hint. Precondition:
// CheckConsistency(mechanism) is empty; throws std::invalid_argument for a range that cannot be
// swept (ends not finite, step 0; the sign of step is ignored).
std::vector<GuideTravel> FindGuideTravels(const Mechanism& mechanism, double from, double to, double step,
                                          BranchPointAction at_branch_point = BranchPointAction::kContinue);

}  // namespace koppel
