// deadcentres, curve --straight, proportional and cognates end to end on the catalog files,
// against the seed documents' figures (the library is tested against closed forms in
// tests/solver; here: that the commands print those numbers under the documented names).
#include "support/run.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <sstream>

namespace koppel::analysis_commands_test {
namespace {

}  // namespace

TEST_CASE("deadcentres: slider-crank e = 0.8 summary (seed 000, corrected phi_i)", "[cli]") {
  const test::RunResult r = test::RunKoppel("deadcentres " + test::CatalogEntryPath("slider-crank-offset") + " --output s --summary");
  REQUIRE(r.exit_code == 0);
  const auto v = test::ParseSummary(r.out);
  CHECK(v.at("phi_a") == Approx(90 + std::asin((0.8 / 2.6) / (1 + 1 / 2.6)) * 180 / M_PI).margin(1e-8));
  CHECK(v.at("phi_i") == Approx(300).margin(1e-8));
  CHECK(v.at("s_H") == Approx(std::sqrt(3.6 * 3.6 - 0.64) - std::sqrt(1.6 * 1.6 - 0.64)).margin(1e-9));
  const test::RunResult table = test::RunKoppel("deadcentres " + test::CatalogEntryPath("slider-crank-offset"));
  CHECK_THAT(table.out, Catch::StartsWith("kind,phi,s,s_d2\nextended,") && Catch::Contains("\nfolded,300,"));
}

TEST_CASE("curve --straight reproduces seed 003's reading example", "[cli]") {
  const test::RunResult r =
      test::RunKoppel("curve " + test::CatalogEntryPath("mzc-crank-rocker") + " --point K --straight --qg 0.005 --at 180");
  REQUIRE(r.exit_code == 0);
  const auto v = test::ParseSummary(r.out);
  CHECK(v.at("phi_G") == Approx(163.3).margin(0.05));
  CHECK(v.at("phi_A") == Approx(98.3).margin(0.05));
  CHECK(v.at("L") == Approx(3.91).margin(0.005));
  const test::RunResult table = test::RunKoppel("curve " + test::CatalogEntryPath("mzc-crank-rocker") + " --point coupler.K --step 90");
  CHECK_THAT(table.out, Catch::StartsWith("phi,x,y,dx,dy,arc,curvature,singular\n0,"));
  CHECK(test::RunKoppel("curve " + test::CatalogEntryPath("mzc-crank-rocker") + " --point Q").exit_code == 2);
  CHECK(test::RunKoppel("curve " + test::CatalogEntryPath("mzc-crank-rocker") + " --point B").exit_code == 2);  // on two links
}

// Issue 22 item 5: without --at the stretch was printed as phi_I = -180, phi_A = -261.66,
// phi_E = -98.34; seed 003 writes phi_I = 180, phi_A = 98.3, phi_G = 163.3 deg.
TEST_CASE("curve --straight prints seed 003's convention with and without --at", "[cli]") {
  const std::string command = "curve " + test::CatalogEntryPath("mzc-crank-rocker") + " --point K --straight";
  const test::RunResult plain = test::RunKoppel(command), at = test::RunKoppel(command + " --at 180"),
                        turned = test::RunKoppel(command + " --at -180");
  REQUIRE(plain.exit_code == 0);
  REQUIRE(at.exit_code == 0);
  REQUIRE(turned.exit_code == 0);
  const auto v = test::ParseSummary(plain.out);
  CHECK(v.at("phi_I") == Approx(180).margin(1e-9));
  CHECK(v.at("phi_A") == Approx(98.3).margin(0.05));
  CHECK(v.at("phi_E") == Approx(98.3 + 163.3).margin(0.1));
  CHECK(v.at("phi_E") - v.at("phi_A") == Approx(v.at("phi_G")).margin(1e-9));
  CHECK(at.out == plain.out);
  CHECK(turned.out == plain.out);
  // a stretch through 0 is written with its end beyond 360; a reversed one is bad input
  const test::RunResult through_0 = test::RunKoppel(command + " --at 0 --stretch 340:380 --resolution 0.05");
  REQUIRE(through_0.exit_code == 0);
  CHECK(test::ParseSummary(through_0.out).at("phi_A") == Approx(340).margin(1e-9));
  CHECK(test::ParseSummary(through_0.out).at("phi_E") == Approx(380).margin(1e-9));
  const test::RunResult reversed = test::RunKoppel(command + " --at 180 --stretch 261.66:98.34");
  CHECK(reversed.exit_code == 2);
  CHECK_THAT(reversed.err, Catch::Contains("--stretch") && Catch::Contains("end after its start"));
}

TEST_CASE("proportional reproduces seed 001's reading example", "[cli]") {
  const test::RunResult r = test::RunKoppel("proportional " + test::CatalogEntryPath("proportional-linkage") +
                                            " --output s --from 112.5 --to 247.5");
  REQUIRE(r.exit_code == 0);
  const auto v = test::ParseSummary(r.out);
  CHECK(v.at("delta_s") == Approx(0.018).margin(0.0005));
  CHECK(v.at("Q_P") == Approx(0.015).margin(0.0005));
  CHECK(v.at("reference") == Approx(180).margin(1e-9));
}

// A parallelogram's coupler only translates: cognate 1's crank, which turns with that coupler,
// stands still while K moves (its input range over a turn of the original is one value). Said on
// stderr, and the file's sweep is that one pose rather than a reversed range.
TEST_CASE("cognates of a parallelogram: cognate 1 cannot be driven, and says so", "[cli]") {
  test::TempDir dir;
  const test::RunResult r = test::RunKoppel("cognates " + test::CatalogEntryPath("parallel-crank") + " --point K -o " + dir.path().string());
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("cognate 1 cannot be driven"));
  const auto v = test::ParseSummary(r.out);
  CHECK(v.at("cognate1_input_min") == v.at("cognate1_input_max"));
  const std::string first = test::ReadText((dir.path() / "parallel-crank-cognate-1.yaml").string());
  CHECK_THAT(first, Catch::Contains("sweep:"));
  // cognate 2 runs with the original's input and is checked sample by sample inside RobertsCognates
  CHECK(test::RunKoppel("analyze " + (dir.path() / "parallel-crank-cognate-2.yaml").string() + " --step 30").exit_code == 0);
}

TEST_CASE("cognates of a file in millimetres write their files in millimetres", "[cli]") {
  test::TempDir dir;
  const std::string text = test::ReadText(test::CatalogEntryPath("mzc-crank-rocker"));
  const std::string mm = dir.Write("mm.yaml", test::Replace(text, "\nparameters:", "\nunits: {length: mm}\nparameters:"));
  const test::RunResult r = test::RunKoppel("cognates " + mm + " --point K -o " + dir.path().string());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  // the files are named by the mechanism, not by the file
  for (const char* name : {"mzc-crank-rocker-cognate-1.yaml", "mzc-crank-rocker-cognate-2.yaml"}) {
    INFO(name);
    CHECK_THAT(test::ReadText((dir.path() / name).string()), Catch::Contains("\nunits: {length: mm}\n"));
  }
}

TEST_CASE("cognates writes two mechanism files that koppel analyses", "[cli]") {
  test::TempDir dir;
  const test::RunResult r = test::RunKoppel("cognates " + test::CatalogEntryPath("mzc-crank-rocker") + " --point K -o " + dir.path().string());
  REQUIRE(r.exit_code == 0);
  const auto v = test::ParseSummary(r.out);
  CHECK(v.at("cognate1_A0C0") == Approx(40.0 / 9 * std::sqrt(3.0)).margin(1e-9));
  for (const char* name : {"mzc-crank-rocker-cognate-1.yaml", "mzc-crank-rocker-cognate-2.yaml"}) {
    const test::RunResult a = test::RunKoppel("analyze " + (dir.path() / name).string());
    INFO(name << ": " << a.err);
    CHECK(a.exit_code == 0);
  }
  // cognate 2 runs with the original's input: its table equals the original's K columns
  const test::RunResult original = test::RunKoppel("analyze " + test::CatalogEntryPath("mzc-crank-rocker") + " --step 30 --order 0");
  const test::RunResult second = test::RunKoppel("analyze " + (dir.path() / "mzc-crank-rocker-cognate-2.yaml").string() + " --step 30 --order 0");
  std::istringstream a(original.out), b(second.out);
  std::string la, lb;
  std::getline(a, la);
  std::getline(b, lb);
  int rows = 0;
  while (std::getline(a, la) && std::getline(b, lb)) {
    std::istringstream ca(la), cb(lb);
    std::string phi_a, x_a, y_a, phi_b, x_b, y_b;
    std::getline(ca, phi_a, ',');
    std::getline(ca, x_a, ',');
    std::getline(ca, y_a, ',');
    std::getline(cb, phi_b, ',');
    std::getline(cb, x_b, ',');
    std::getline(cb, y_b, ',');
    CHECK(std::stod(x_a) == Approx(std::stod(x_b)).margin(1e-9));
    CHECK(std::stod(y_a) == Approx(std::stod(y_b)).margin(1e-9));
    ++rows;
  }
  CHECK(rows == 13);
}

}  // namespace koppel::analysis_commands_test
