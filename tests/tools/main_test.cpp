// The program around the commands (tools/cli/main.cpp): --version, and Ceres' glog messages kept
// off stderr by the synthesis library itself (solver/synthesis/src/quiet_solver_log.cpp, so the
// Python module gets the same), so that --quiet means a clean stderr and a failure is told once.
#include "support/run.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

namespace koppel::main_test {

TEST_CASE("koppel --version prints the project's version and exits 0", "[cli]") {
  const test::RunResult r = test::RunKoppel("--version");
  CHECK(r.exit_code == 0);
  CHECK(r.out == std::string("koppel ") + KOPPEL_VERSION_TEXT + "\n");
  CHECK(r.err.empty());
}

TEST_CASE("synth fit --quiet leaves stderr clean: no glog lines from starts that fail", "[cli][synth]") {
  const std::string data = KOPPEL_TEST_DATA_DIR;
  const test::RunResult ok = test::RunKoppel("synth fit " + data + "/fit-mzc-precision-points.yaml --quiet");
  CHECK(ok.exit_code == 0);
  CHECK(ok.err.empty());

  // starts that do not assemble make Ceres log through glog; koppel reports outcomes itself
  const test::RunResult hard = test::RunKoppel("synth fit " + data + "/fit-unassemblable-start.yaml --quiet");
  CHECK((hard.exit_code == 0 || hard.exit_code == 1));
  CHECK(hard.err.find("InitGoogleLogging") == std::string::npos);
  CHECK(hard.err.find("Terminating") == std::string::npos);
  CHECK(hard.err.find(".cc:") == std::string::npos);  // no glog line ("E... trust_region_minimizer.cc:71]")
  if (hard.exit_code == 0) CHECK(hard.err.empty());
  if (hard.exit_code == 1) CHECK(std::count(hard.err.begin(), hard.err.end(), '\n') == 1);
}

}  // namespace koppel::main_test
