// Proportionality deviation (seed 001, "Antriebsbezogene Proportionalitätsabweichung"): over an
// input range phi_P, how far an output s departs from proportionality to the input.
//
// Reference line: the tangent of s at the reference input (by default the flattest point of s',
// i.e. the least |s''| in the range: the Flachpunkt, refined to the root of s'' where s'' changes
// sign there). Δs is the width of the band parallel to that line that holds s over the range
// (max - min of s - tangent; the extremes between samples refined by Newton on s' = slope, the
// range sampled up to `to` whatever the resolution). This is the definition that
// reproduces the document's reading example (112.5..247.5 deg: Δs = 0.018, Q_P = 1.5e-2); the
// deviation from the chord (0.0050) or from the best minimax line (0.0030) do not.
// Q_P = (Δs / l) / phi_P with phi_P in radians and l the reference length.
#pragma once

#include "koppel/analysis/status.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/solver/position.hpp"
#include "koppel/solver/sweep.hpp"

#include <optional>
#include <string>

namespace koppel {

struct Proportionality {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // partial: over the drivable part of the range (see sweep)
  std::string message;    // why not computed, or why partial
  SweepEvents sweep;      // singular points and gaps of the range
  double reference = 0;   // input of the tangent point
  double slope = 0;       // s' there
  double delta_s = 0;     // band width about the tangent
  double chord_deviation = 0;    // max |s - chord through the end points|, for comparison
  double phi_p = 0;       // range in radians (or length)
  double qp = 0;          // (delta_s / reference_length) / phi_p
  std::string Brief() const;
};

// Over the drivable part of from..to when the branch cannot be driven through all of it (the
// gaps are in `sweep`); not computed with fewer than two samples.
Proportionality ProportionalityDeviation(const Mechanism& mechanism, int output, double from, double to, double reference_length,
                                         std::optional<double> reference, double resolution,
                                         const ContinuationOptions& continuation = {});

}  // namespace koppel
