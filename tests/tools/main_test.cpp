// The program around the commands (tools/cli/main.cpp): --version, the commands it adds for a
// command line (only the one named: each still parses and helps as with all of them), and Ceres'
// glog messages kept off stderr by the synthesis library itself (solver/synthesis/ceres/
// quiet_solver_log.cpp, so the Python module gets the same), so that --quiet means a clean stderr
// and a failure is told once.
#include "support/run.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

namespace koppel::main_test {

TEST_CASE("koppel --version prints the project's version and exits 0", "[cli]") {
  const test::RunResult r = test::RunKoppel("--version");
  CHECK(r.exit_code == 0);
  CHECK(r.out == std::string("koppel ") + KOPPEL_VERSION_TEXT + "\n");
  CHECK(r.err.empty());
  // `--version` alone is answered before CLI11 is built (main.cpp); with more on the line, CLI11's
  // version flag answers: the reference, the same text
  const test::RunResult through_cli11 = test::RunKoppel("--version analyze");
  CHECK(through_cli11.exit_code == 0);
  CHECK(through_cli11.out == r.out);
}

TEST_CASE("koppel NAME adds only NAME: every command of --help answers its own --help, others are still named", "[cli]") {
  // the reference: the command list of `koppel --help`, which adds every command
  const test::RunResult help = test::RunKoppel("--help");
  REQUIRE(help.exit_code == 0);
  const std::string list = help.out.substr(help.out.find("Subcommands:"));
  int commands = 0;
  // a command's line: two spaces, its name; its description's further lines are indented further
  for (size_t at = list.find('\n'); at != std::string::npos && at + 3 < list.size(); at = list.find('\n', at + 1)) {
    if (list.compare(at + 1, 2, "  ") != 0 || list[at + 3] == ' ') continue;
    const std::string name = list.substr(at + 3, list.find(' ', at + 3) - (at + 3));
    INFO(name);
    const test::RunResult own = test::RunKoppel(name + " --help");
    CHECK(own.exit_code == 0);
    CHECK_THAT(own.out, Catch::Contains("Usage: ") && Catch::Contains("koppel " + name));
    ++commands;
  }
  CHECK(commands >= 21);
  // a command line that names no command (a misspelt one) adds them all: bad input, as before
  const test::RunResult typo = test::RunKoppel("analyse x.yaml");
  CHECK(typo.exit_code == 2);
  CHECK_THAT(typo.err, Catch::Contains("subcommand is required"));
  const test::RunResult none = test::RunKoppel("");
  CHECK(none.exit_code == 2);
  CHECK_THAT(none.err, Catch::Contains("subcommand"));
}

// --help speaks to users: it points into the documentation (docs/...), not at README sections
// that are no longer there, and names the source documents by title, not by a seed number.
TEST_CASE("--help-all cites the documentation, never README sections or seed numbers", "[cli]") {
  const test::RunResult r = test::RunKoppel("--help-all");
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, !Catch::Contains("README") && !Catch::Contains("seed 0") && !Catch::Contains("issue "));
  CHECK_THAT(r.out, Catch::Contains("docs/mechanism-file.md"));
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
