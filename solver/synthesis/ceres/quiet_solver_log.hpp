// Ceres logs through glog, also for outcomes koppel reports itself from the solver's summary
// ("Terminating: Residual and Jacobian evaluation failed" where a start does not assemble). The
// library never prints, so every Ceres solve in koppel calls QuietSolverLog first: once for the
// whole process (thread-safe), glog lets only fatal messages through, to stderr, no log files.
// The only place outside Ceres itself that touches glog (in the module libkoppel_ceres.so).
#pragma once

namespace koppel {

void QuietSolverLog();

}  // namespace koppel
