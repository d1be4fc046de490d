// The outcome of an analysis: every result of the analysis library carries one of these (it
// starts as kNotRun), a message, and a one-line Brief(), in the manner of Ceres' Solver::Summary.
#pragma once

namespace koppel {

enum class AnalysisStatus {
  kNotRun,
  kComplete,  // computed over the whole requested range
  kPartial,   // computed over the drivable part of the range only: the sweep events name the gaps
  kFailed,    // not computed: the message says why
};
const char* ToString(AnalysisStatus status);  // "not run", "complete", "partial", "failed"

// Complete or partial: the numbers of the result may be used (for the part the sweep covered).
inline bool Usable(AnalysisStatus status) { return status == AnalysisStatus::kComplete || status == AnalysisStatus::kPartial; }

}  // namespace koppel
