// The program around the commands (tools/cli/main.cpp): --version, and Ceres' glog messages
// kept off stderr, so that --quiet means a clean stderr and a failure is told once, by koppel.
#include "support/run.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

namespace koppel {

TEST_CASE("koppel --version prints the project's version and exits 0", "[cli]") {
  const test::RunResult r = test::RunKoppel("--version");
  CHECK(r.exit_code == 0);
  CHECK(r.out == std::string("koppel ") + KOPPEL_VERSION_TEXT + "\n");
  CHECK(r.err.empty());
}

TEST_CASE("synth fit --quiet leaves stderr clean; a failed start is told once, without glog", "[cli][synth]") {
  const std::string data = KOPPEL_TEST_DATA_DIR;
  const test::RunResult ok = test::RunKoppel("synth fit " + data + "/fit-mzc-precision-points.yaml --quiet");
  CHECK(ok.exit_code == 0);
  CHECK(ok.err.empty());

  const test::RunResult failed = test::RunKoppel("synth fit " + data + "/fit-unassemblable-start.yaml --quiet");
  CHECK(failed.exit_code == 1);
  CHECK_THAT(failed.err, Catch::Contains("no start gave a design that assembles"));
  CHECK(failed.err.find("InitGoogleLogging") == std::string::npos);
  CHECK(failed.err.find("Terminating") == std::string::npos);
  CHECK(std::count(failed.err.begin(), failed.err.end(), '\n') == 1);
}

}  // namespace koppel
