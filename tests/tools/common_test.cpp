// The limits every command shares (tools/cli/common.cpp, CheckSampleCount): the hostile command
// lines of issue 11 each end at once with exit 2 and a message naming the limit and the options
// that change it, before anything is allocated (each used to run out of memory, overflow an int
// or run for hours). The JSON outputs carry koppel's version.
#include "support/run.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>

namespace koppel::common_test {
namespace {

struct Hostile {
  std::string arguments;
  std::string limit;    // the constant named in the message
  std::string options;  // the flags named in the message
};

}  // namespace

TEST_CASE("hostile command lines end with exit 2 naming the limit and the option", "[cli][limits]") {
  const std::string sc = test::CatalogEntryPath("slider-crank-offset"), mzc = test::CatalogEntryPath("mzc-crank-rocker"),
                    prop = test::CatalogEntryPath("proportional-linkage");
  const std::vector<Hostile> cases = {
      {"analyze " + sc + " --step 1e-12", "kMaxSweepSamples", "--step"},
      {"analyze " + sc + " --from 0 --to 1e9", "kMaxSweepSamples", "--to"},
      {"deadcentres " + sc + " --step 1e-6", "kMaxSweepSamples", "--step"},
      {"curve " + mzc + " --point K --straight --resolution 1e-6", "kMaxStraightSearchSamples", "--resolution"},
      {"curve " + mzc + " --point K --straight --resolution 0.001", "kMaxStraightSearchSamples", "--resolution"},
      {"curve " + mzc + " --point K --step 1e-5", "kMaxSweepSamples", "--step"},
      {"synth chart crank-rocker --phi0 100:260:1e-3 --psi0 10:100:1e-3", "kMaxChartCells", "--phi0"},
      {"synth chart crank-rocker --phi0 0:1e12:1e-12 --psi0 10:100:1", "kMaxChartCells", "--phi0"},
      {"synth chart slider-crank --phi0 90:180:1e-9", "kMaxChartCells", "--phi0"},
      {"proportional " + prop + " --output s --from 0 --to 1e6", "kMaxSweepSamples", "--to"},
  };
  for (const Hostile& h : cases) {
    const auto start = std::chrono::steady_clock::now();
    const test::RunResult r = test::RunKoppel(h.arguments);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    INFO(h.arguments << "\n" << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains(h.limit) && Catch::Contains(h.options) && Catch::Contains("more than the limit"));
    CHECK(r.out.empty());
    CHECK(seconds < 5);  // refused before the work: the sanitizer build starts in well under that
  }
}

TEST_CASE("a step lost in the rounding of huge inputs is refused, not walked", "[cli][limits]") {
  const std::string sc = test::CatalogEntryPath("slider-crank-offset");
  const test::RunResult r = test::RunKoppel("analyze " + sc + " --from 1e18 --to 1e18+3600");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("lost in the rounding"));
  const test::RunResult nan = test::RunKoppel("analyze " + sc + " --step 'sqrt(-1)'");
  CHECK(nan.exit_code == 2);
}

TEST_CASE("the limits leave the ordinary command lines alone", "[cli][limits]") {
  const std::string sc = test::CatalogEntryPath("slider-crank-offset");
  // 360 / 0.01 + 1 samples, a fine table: far under the limit of a million
  const test::RunResult fine = test::RunKoppel("analyze " + sc + " --step 0.01 --order 0");
  CHECK(fine.exit_code == 0);
  CHECK(std::count(fine.out.begin(), fine.out.end(), '\n') == 36001 + 1);
  CHECK(test::RunKoppel("synth chart crank-rocker --quiet").exit_code == 0);
}

TEST_CASE("JSON outputs carry koppel's version", "[cli]") {
  const std::string sc = test::CatalogEntryPath("slider-crank-offset");
  const test::RunResult version = test::RunKoppel("--version");
  REQUIRE(version.exit_code == 0);
  REQUIRE(version.out.rfind("koppel ", 0) == 0);
  const std::string number = version.out.substr(7, version.out.size() - 8);
  CHECK(number == KOPPEL_VERSION_TEXT);  // the one version, from CMake's project()
  for (const std::string& command : {"analyze " + sc + " --step 90 --format json", "deadcentres " + sc + " --output s --format json",
                                     "proportional " + sc + " --output s --from 0 --to 90 --format json"}) {
    const test::RunResult r = test::RunKoppel(command);
    INFO(command);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("\"version\": \"" + number + "\""));
  }
}

}  // namespace koppel::common_test
