// QuietSolverLog (solver/synthesis/ceres/quiet_solver_log.cpp), called through the module
// libkoppel_ceres.so as the fits call it (ceres_solves.hpp): after it, glog (Ceres' logger, the
// same shared library here and in the module) lets only fatal messages through, to stderr, and
// writes no log files; racing threads are safe. The test includes glog itself: it is the one test
// of the one place that touches glog.
#include "ceres_solves.hpp"

#include <catch2/catch.hpp>
#include <glog/logging.h>

#include <cstdio>
#include <thread>
#include <unistd.h>
#include <vector>

namespace koppel::quiet_solver_log_test {
namespace {

// What a LOG(ERROR) writes to stderr meanwhile (stderr redirected to a temporary file).
std::string StderrOf(void (*log)()) {
  std::fflush(stderr);
  const int saved = dup(STDERR_FILENO);
  std::FILE* capture = std::tmpfile();
  REQUIRE(capture != nullptr);
  dup2(fileno(capture), STDERR_FILENO);
  log();
  std::fflush(stderr);
  dup2(saved, STDERR_FILENO);
  close(saved);
  std::rewind(capture);
  std::string text;
  for (int c; (c = std::fgetc(capture)) != EOF;) text.push_back(static_cast<char>(c));
  std::fclose(capture);
  return text;
}

TEST_CASE("after QuietSolverLog only fatal messages pass, to stderr, no log files", "[quiet_solver_log]") {
  // eight threads race to the first call (the function-local static makes one of them set the flags)
  std::vector<std::thread> threads;
  for (int i = 0; i < 8; ++i) threads.emplace_back([] { CeresSolves().quiet_solver_log(); });
  for (std::thread& t : threads) t.join();
  CHECK(FLAGS_logtostderr);
  CHECK(FLAGS_minloglevel == google::GLOG_FATAL);
  CHECK(FLAGS_stderrthreshold == google::GLOG_FATAL);
  // reference: what reaches stderr, read back
  CHECK(StderrOf([] { LOG(ERROR) << "Terminating: Residual and Jacobian evaluation failed."; }).empty());
  CHECK(StderrOf([] { LOG(WARNING) << "a warning"; }).empty());
  CeresSolves().quiet_solver_log();  // again: nothing changes
  CHECK(FLAGS_minloglevel == google::GLOG_FATAL);
}

}  // namespace
}  // namespace koppel::quiet_solver_log_test
