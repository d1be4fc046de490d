// The outcome of a synthesis: every design result of the synthesis library carries one of these
// (it starts as kNotRun), a message and a one-line Brief().
#pragma once

namespace koppel {

enum class DesignStatus {
  kNotRun,
  kOk,                // a design, proved by re-analysis
  kInvalidRequest,    // the request failed IsValid, or the mechanism given is not of the kind needed
  kNoDesign,          // no mechanism of the kind asked for satisfies the request
  kBoundaryOptimum,   // mu_min grows towards a boundary where a link vanishes: no best design
  kReanalysisFailed,  // the generic solver does not confirm the closed form: nothing reported
};
const char* ToString(DesignStatus status);  // "ok", "no design", ...

}  // namespace koppel
