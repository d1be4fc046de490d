// The stationary points of a scalar output over a sweep, the one search behind the dead centres
// (dead_centres.hpp) and the extremes of an output (extremes.hpp).
//
// A root of y' is bracketed by a sign change of y' between neighbouring samples and refined by
// Newton (stationary.hpp). Where the range covers whole turns of a rotating drive whose pose
// repeats after them (the period), the samples are treated cyclically: the interval from the last
// sample before the period's end to the first sample plus the period is searched like any other,
// so that a root at the first sample, where y' may have either sign by roundoff, is found once,
// whichever side it falls on. Otherwise an end of the range (or of a drivable run of samples, at
// a gap) whose Newton prediction lands in the range within kSameInput is refined too, so that a
// root exactly at the start or end of the range is kept. A transmission angle, folded onto
// 0..90 deg, changes the sign of y' also at its folds (90 deg, or 0 at a singular position):
// those are located as folds, not stationary points.
#pragma once

#include "koppel/analysis/stationary.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/solver/sweep.hpp"

#include <vector>

namespace koppel {

// y' changes sign between two neighbouring samples d0, d1 (or is zero at the first): a root of y'
// lies between them.
inline bool SignChange(double d0, double d1) { return d0 == 0.0 || (d0 > 0) != (d1 > 0); }

struct StationarySearch {
  SweepResult sweep;  // of order 2, over the range asked for
  int column = -1;    // the output's column in sweep.outputs; y' and y'' follow it
  double step = 0;    // |step|: the search resolution
  double low = 0, high = 0;  // the range asked for, low <= high
  // Inputs closer than this are one input, and a root this far outside the range is in it
  // (kSameInput, in rad or scaled by the mechanism's length for a sliding drive).
  double tolerance = 0;
  // > 0: the range covers whole turns of a pose that repeats after `period`; every input below
  // is then reported in [window, window + period) (modulo the period).
  double period = 0, window = 0;
  double turn_gain = 0;  // periodic: y one period on minus y at the start (2 pi k for an output that turns)
  // The output does not change over the range (within 1e-12 rad, or of the length scale): it
  // has no isolated stationary point, and none is searched for.
  bool constant = false;
  std::vector<StationaryPoint> points;  // the stationary points in the range, each once, by input
  std::vector<StationaryPoint> folds;   // a transmission angle's folds in the range, by input
  std::vector<int> ends;                // not periodic: the samples that end a run of samples
  std::vector<double> unresolved;       // sign changes of y' that are neither (their bracket's middle)
  std::string unresolved_message;       // why the first of them was not refined

  // Wrap-aware distance of two inputs (modulo the period, when there is one).
  double Distance(double a, double b) const;
  // The input as reported: in [window, window + period) for a periodic search, else unchanged.
  double Canonical(double input) const;
};

// Inputs closer than this are one input: kSameInput, 1e-9 rad (a sliding drive: times the length
// scale), far above the refinement's 1e-12, far below two distinct stationary points.
double SameInputTolerance(const Mechanism& mechanism);

// A sweep's samples stop at the last from + k step not beyond `to`: the rest of the range (less
// than a step) is walked to from the last sample and added as a row of the sweep's order, so that
// a search or a band over the range covers all of it. Nothing is added when the branch cannot be
// driven there, or when the last sample is `to` (within SameInputTolerance).
void SampleRangeEnd(const Mechanism& mechanism, const SweepOptions& options, SweepResult& sweep);

// Sweeps `range` (its step is the search resolution) and finds every stationary point (and fold)
// of output `output` (component 0/1 for a point) in it. An empty sweep finds nothing.
StationarySearch SearchStationaryPoints(const Mechanism& mechanism, int output, int component, const SweepOptions& range);

}  // namespace koppel
