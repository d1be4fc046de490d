// `koppel range` and `koppel classify` end to end, and the three commands issue 9 reported
// (tried as a new user would), kept as regression tests: a parallelogram that changed branch at
// its change point, dead centres found where there are none, 1e12 at a slider-crank's branch point.
#include "support/run.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <vector>

namespace koppel::range_command_test {
namespace {

}  // namespace

TEST_CASE("issue 9: analyze parallelogram.yaml --step 10 stays on the parallelogram, psi'' is not 3e13", "[cli][branches]") {
  const test::RunResult r = test::RunKoppel("analyze " + test::TestDataPath("parallelogram.yaml") + " --step 10");
  REQUIRE(r.exit_code == 0);
  const auto rows = test::CsvCells(r.out);
  REQUIRE(rows[0] == std::vector<std::string>{"phi", "psi", "psi_d1", "psi_d2", "singular"});
  REQUIRE(rows.size() == 38);
  for (size_t i = 1; i < rows.size(); ++i) {
    const double phi = std::stod(rows[i][0]);
    INFO("phi = " << phi);
    CHECK(std::stod(rows[i][1]) == Approx(phi).margin(1e-9));  // psi = phi
    CHECK(std::stod(rows[i][2]) == Approx(1.0).margin(1e-9));
    CHECK(std::abs(std::stod(rows[i][3])) < 1e-8);
    CHECK(rows[i][4] == (std::fmod(phi, 180.0) == 0.0 ? "1" : "0"));  // the change points are flagged
  }
  CHECK_THAT(r.err, Catch::Contains("branch point") && Catch::Contains("phi = 180 deg"));
}

TEST_CASE("issue 9: deadcentres parallelogram.yaml --output psi finds none (psi = phi has none)", "[cli][branches]") {
  const test::RunResult r = test::RunKoppel("deadcentres " + test::TestDataPath("parallelogram.yaml") + " --output psi");
  CHECK(r.exit_code == 0);
  CHECK(r.out == "kind,phi,psi,psi_d2\n");
}

TEST_CASE("issue 9: slider-crank with l2 = l1 + e: rows at 0 and 360 carry the branch's s', flagged", "[cli][branches]") {
  const test::RunResult r = test::RunKoppel("analyze " + test::CatalogEntryPath("slider-crank-offset") + " --set l2=1.8 --step 10");
  REQUIRE(r.exit_code == 0);
  const auto rows = test::CsvCells(r.out);
  // the branch that continues analytically: s'(0) = l1 + sqrt(l1^2 + e l1), s'(360) = l1 - sqrt(...)
  // (derivation in tests/solver/kernel/continuation_test.cpp)
  CHECK(std::stod(rows[1][2]) == Approx(1 + std::sqrt(1.8)).margin(1e-8));
  CHECK(std::stod(rows.back()[2]) == Approx(1 - std::sqrt(1.8)).margin(1e-8));
  CHECK(std::abs(std::stod(rows[1][3])) < 10);
  CHECK(rows[1].back() == "1");
  CHECK(rows.back().back() == "1");
  CHECK_THAT(r.err, Catch::Contains("assembly input phi = 0 deg is a singular position"));
}

TEST_CASE("--at-branch-point switch and stop; a bad value is bad input", "[cli][branches]") {
  const test::RunResult s =
      test::RunKoppel("analyze " + test::TestDataPath("parallelogram.yaml") + " --from 90 --to 270 --step 90 --at-branch-point switch");
  REQUIRE(s.exit_code == 0);
  const auto rows = test::CsvCells(s.out);
  // after 180 deg on the antiparallelogram: tan(psi/2) = -2 tan(phi/2) -> psi(270) = 126.87 deg
  const double expected = 2 * std::atan2(-2 * std::sin(3 * M_PI / 4), std::cos(3 * M_PI / 4)) * 180 / M_PI;
  CHECK(std::abs(std::remainder(std::stod(rows.back()[1]) - expected, 360.0)) < 1e-8);
  const test::RunResult t =
      test::RunKoppel("analyze " + test::TestDataPath("parallelogram.yaml") + " --from 90 --to 270 --step 90 --at-branch-point stop");
  CHECK(t.exit_code == 1);
  CHECK(test::CsvCells(t.out).size() == 3);  // header, 90, 180
  CHECK_THAT(t.err, Catch::Contains("stopped there"));
  CHECK(test::RunKoppel("analyze " + test::TestDataPath("parallelogram.yaml") + " --at-branch-point jump").exit_code == 2);
}

TEST_CASE("a sweep whose --from lies outside the drivable range prints the rows it can reach and names the gaps", "[cli][branches]") {
  test::TempDir dir;
  const std::string json = (dir.path() / "t.json").string();
  const test::RunResult r =
      test::RunKoppel("analyze " + test::TestDataPath("triple-rocker.yaml") + " --from -180 --to 180 --step 10 --format json -o " + json);
  CHECK(r.exit_code == 1);
  const std::string text = test::ReadText(json);
  CHECK_THAT(text, Catch::Contains("\"gaps\"") && Catch::Contains("\"kind\": \"limit\"") && Catch::Contains("\"complete\": false"));
  const test::RunResult csv = test::RunKoppel("analyze " + test::TestDataPath("triple-rocker.yaml") + " --from -180 --to 180 --step 10");
  const auto rows = test::CsvCells(csv.out);
  CHECK(rows.size() == 1 + 25);  // -120 .. 120 deg: |phi| < 129.84
  CHECK(std::stod(rows[1][0]) == -120);
  CHECK_THAT(csv.err, Catch::Contains("phi = -180 deg .. -129.83844") && Catch::Contains("phi = 129.83844"));
}

TEST_CASE("koppel range: full turns, limits, periods, all branches", "[cli][range]") {
  const test::RunResult crank = test::RunKoppel("range " + test::CatalogEntryPath("mzc-crank-rocker") + " --all-branches");
  REQUIRE(crank.exit_code == 0);
  CHECK(crank.out == "branch,from,to,from_kind,to_kind\n0,0,360,full-turn,full-turn\n1,0,360,full-turn,full-turn\n");
  const test::RunResult kite = test::RunKoppel("range " + test::TestDataPath("kite.yaml"));
  CHECK(kite.out == "branch,from,to,from_kind,to_kind\n0,0,720,full-turn,full-turn\n");
  const test::RunResult triple = test::RunKoppel("range " + test::TestDataPath("triple-rocker.yaml") + " --format json");
  REQUIRE(triple.exit_code == 0);
  // law of cosines: cos phi = (2^2 + 4^2 - (3 + 2.5)^2) / (2 2 4)
  const double limit = std::acos((4.0 + 16.0 - 30.25) / 16.0) * 180 / M_PI;
  CHECK_THAT(triple.out, Catch::Contains("\"from_kind\": \"limit\"") && Catch::Contains("\"to_kind\": \"limit\""));
  const test::RunResult csv = test::RunKoppel("range " + test::TestDataPath("triple-rocker.yaml"));
  const auto rows = test::CsvCells(csv.out);
  CHECK(std::stod(rows[1][1]) == Approx(-limit).margin(1e-7));
  CHECK(std::stod(rows[1][2]) == Approx(limit).margin(1e-7));
  const test::RunResult stop = test::RunKoppel("range " + test::TestDataPath("parallelogram.yaml") + " --at-branch-point stop");
  CHECK_THAT(stop.out, Catch::Contains(",branch-point,branch-point"));
}

TEST_CASE("koppel classify: Grashof types with their inequality; mobility errors are bad input", "[cli][classify]") {
  const test::RunResult seed = test::RunKoppel("classify " + test::CatalogEntryPath("mzc-crank-rocker"));
  REQUIRE(seed.exit_code == 0);
  const auto v = test::CsvCells(seed.out);
  CHECK(v[0] == std::vector<std::string>{"quantity", "value", "unit"});
  CHECK_THAT(seed.out, Catch::Contains("mobility,1,1\nrank_mobility,1,1\ndrive_rotation,full,\ngrashof,crank-rocker,"));
  const test::RunResult parallelogram = test::RunKoppel("classify " + test::TestDataPath("parallelogram.yaml"));
  CHECK_THAT(parallelogram.out, Catch::Contains("grashof,change-point,") && Catch::Contains("s + l = 1 + 3 = 4 = p + q"));
  const test::RunResult triple = test::RunKoppel("classify " + test::TestDataPath("triple-rocker.yaml"));
  CHECK_THAT(triple.out, Catch::Contains("drive_rotation,limited,") && Catch::Contains("grashof,triple-rocker,"));
  const test::RunResult slider = test::RunKoppel("classify " + test::CatalogEntryPath("slider-crank-offset") + " --set l2=1.5");
  CHECK_THAT(slider.out, Catch::Contains("grashof,rocker-slider,"));
  // a five-bar with one drive: exit 2 naming both numbers, for every command
  const test::RunResult five = test::RunKoppel("classify " + test::TestDataPath("five-bar.yaml"));
  CHECK(five.exit_code == 2);
  CHECK_THAT(five.err, Catch::Contains("five-bar.yaml") && Catch::Contains("mobility 2") && Catch::Contains("1 drive"));
  CHECK(test::RunKoppel("analyze " + test::TestDataPath("five-bar.yaml")).exit_code == 2);
  // overconstrained but consistent: accepted with a note
  const test::RunResult redundant = test::RunKoppel("classify " + test::TestDataPath("redundant-parallelogram.yaml"));
  CHECK(redundant.exit_code == 0);
  CHECK_THAT(redundant.out, Catch::Contains("mobility,0,1\nrank_mobility,1,1"));
  CHECK_THAT(redundant.err, Catch::Contains("overconstrained but consistent"));
}

}  // namespace koppel::range_command_test
