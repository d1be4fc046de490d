#include "koppel/analysis/status.hpp"

namespace koppel {

const char* ToString(AnalysisStatus status) {
  switch (status) {
    case AnalysisStatus::kNotRun: return "not run";
    case AnalysisStatus::kComplete: return "complete";
    case AnalysisStatus::kPartial: return "partial";
    case AnalysisStatus::kFailed: return "failed";
  }
  return "not run";
}

}  // namespace koppel
