#include "quiet_solver_log.hpp"

#include <glog/logging.h>

namespace koppel {

void QuietSolverLog() {
  // a function-local static is initialised exactly once, also when threads race to it
  static const bool quiet = [] {
    FLAGS_logtostderr = true;  // no log files in the working directory or /tmp
    FLAGS_minloglevel = google::GLOG_FATAL;
    FLAGS_stderrthreshold = google::GLOG_FATAL;
    return true;
  }();
  (void)quiet;
}

}  // namespace koppel
