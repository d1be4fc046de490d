// The smallest and largest value of a scalar output over an input range, and where they are:
// for a transmission angle, mu_min and mu_max (seed 000 "Übertragungswinkel", seed 002).
//
// An extreme is a stationary point of the output (Newton on y' with y'', to 1e-12 in the input),
// a fold of a transmission angle (90 deg where the angle it folds passes a right angle, 0 at a
// singular position), or an end of the range when the range is not whole turns of a rotating
// drive (over whole turns there is no end: the search is periodic). Over a sweep that cannot
// drive the whole range, the ends of the drivable runs of samples count as ends. Extremes equal
// to within kSameValue are one: the one at the smaller input (as reported) is given.
#pragma once

#include "koppel/analysis/status.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/solver/sweep.hpp"

#include <string>

namespace koppel {

// kConstant: the output does not change over the range (within 1e-12 rad or of the length
// scale); minimum and maximum are then its value at the first sample.
enum class ExtremeKind { kStationary, kFold, kRangeEnd, kConstant };
const char* ToString(ExtremeKind kind);  // "stationary", "fold", "range end", "constant"

struct OutputExtreme {
  double input = 0;  // radians (R drive) or length; over whole turns within the range's first turn
  double value = 0;  // the output there (radians for angle outputs)
  ExtremeKind kind = ExtremeKind::kStationary;
};

struct OutputExtremes {
  // kComplete: over the whole range; kPartial: over the drivable part (the gaps are in `sweep`);
  // kFailed: no sample, an output that turns with the drive over whole turns (it has no least
  // and largest value there), a sign change of y' that is neither a stationary point nor a fold,
  // or a sample beyond the extremes found (then minimum and maximum are not to be used).
  AnalysisStatus status = AnalysisStatus::kNotRun;
  std::string message;
  SweepEvents sweep;
  OutputExtreme minimum, maximum;
  std::string Brief() const;
};

// Sweeps `range` (its step is the search resolution; every extreme is refined) for the extremes
// of output `output` (component 0/1 for a point).
OutputExtremes FindOutputExtremes(const Mechanism& mechanism, int output, int component, const SweepOptions& range);

}  // namespace koppel
