// Issue 22, items 4, 6, 7 and 12 end to end, as a new user met them: a sample 1e-9 deg inside a
// crossed four-bar's limit is served; a triple-rocker's input is an angle modulo 360 (260 deg is
// -100 deg); a file whose assembly hint does not assemble is started where a search over a turn
// finds a pose, and says so; a distance output through zero prints its rows, leaves the cells it
// cannot give empty, names the output and the input, and exits 1.
#include "support/closed_forms.hpp"
#include "support/run.hpp"
#include "support/text.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace koppel::drive_input_test {
namespace {

constexpr double kDeg = M_PI / 180;

}  // namespace

TEST_CASE("issue 22 item 6: analyze triple-rocker --from 260 --to 360 takes 260 deg as -100 deg", "[cli][periodic]") {
  // catalog/entries/triple-rocker.yaml: a, b, c, d = 3, 4, 2.5, 5, B above the frame line; it
  // swings between -+phi_G, cos phi_G = (a^2 + d^2 - (b + c)^2) / (2 a d) = 105.96 deg
  const test::RunResult r = test::RunKoppel("analyze " + test::CatalogEntryPath("triple-rocker") + " --from 260 --to 360 --step 10");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto rows = test::CsvCells(r.out);
  REQUIRE(rows.size() == 12);  // header and 260, 270, ..., 360
  const double a = 3, b = 4, c = 2.5, d = 5;
  for (size_t i = 1; i < rows.size(); ++i) {
    const double phi_shown = std::stod(rows[i][0]);
    CHECK(phi_shown == Approx(250 + 10.0 * i).margin(1e-9));  // the input as asked, not -100
    // psi by the circle intersection at phi, B left of A -> B0 (above the frame line at phi = 0)
    const double psi = test::FourBarRocker(a, b, c, d, phi_shown * kDeg, +1)->psi / kDeg;
    INFO("phi = " << phi_shown);
    CHECK(std::remainder(std::stod(rows[i][1]) - psi, 360.0) == Approx(0).margin(1e-8));
  }
  // 250 deg = -110 deg lies beyond the limit: one row missing, the gap named, exit 1
  const test::RunResult s = test::RunKoppel("analyze " + test::CatalogEntryPath("triple-rocker") + " --from 250 --to 360 --step 10");
  CHECK(s.exit_code == 1);
  CHECK(test::CsvCells(s.out).size() == 12);
  CHECK_THAT(s.err, Catch::Contains("1 of 12 samples") && Catch::Contains("phi = 250 deg .. 254.0379858 deg"));
}

TEST_CASE("issue 22 item 4: a sample 1e-9 deg inside the crossed triple-rocker's limit is served", "[cli][limit]") {
  // tests/data/crossed-triple-rocker.yaml: the catalog's triple-rocker assembled crossed (B below
  // the frame line); limits at -+phi_G = 105.962014163 deg by the law of cosines
  const double phi_g = std::acos((9.0 + 25 - 6.5 * 6.5) / 30) / kDeg;
  char inside[64], beyond[64];
  std::snprintf(inside, sizeof inside, "%.17g", phi_g - 1e-9);
  std::snprintf(beyond, sizeof beyond, "%.17g", phi_g + 1e-9);
  const test::RunResult r = test::RunKoppel("analyze " + test::TestDataPath("crossed-triple-rocker.yaml") + " --from " + inside +
                                            " --to " + inside + " --step 1");
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(test::CsvCells(r.out).size() == 2);
  const test::RunResult s = test::RunKoppel("analyze " + test::TestDataPath("crossed-triple-rocker.yaml") + " --from " + beyond +
                                            " --to " + beyond + " --step 1");
  CHECK(s.exit_code == 1);
  CHECK(test::CsvCells(s.out).size() == 1);
  // range reports the limits to the printed digits of the closed form
  const test::RunResult range = test::RunKoppel("range " + test::TestDataPath("crossed-triple-rocker.yaml"));
  REQUIRE(range.exit_code == 0);
  const auto rows = test::CsvCells(range.out);
  REQUIRE(rows.size() == 2);
  CHECK(std::stod(rows[1][1]) == Approx(-phi_g).margin(1e-9));
  CHECK(std::stod(rows[1][2]) == Approx(phi_g).margin(1e-9));
}

TEST_CASE("issue 22 item 7: range starts where a search finds a pose when the hint does not assemble", "[cli][assembly]") {
  // tests/data/short-rod-slider-crank.yaml: r, l, e = 30, 10, 15 mm, drivable while
  // 1/6 <= sin phi <= 5/6; the hint at phi = 0 is outside
  const test::RunResult r = test::RunKoppel("range " + test::TestDataPath("short-rod-slider-crank.yaml"));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto rows = test::CsvCells(r.out);
  REQUIRE(rows.size() == 2);
  CHECK(std::stod(rows[1][1]) == Approx(std::asin(1.0 / 6) / kDeg).margin(1e-9));
  CHECK(std::stod(rows[1][2]) == Approx(std::asin(5.0 / 6) / kDeg).margin(1e-9));
  CHECK(rows[1][3] == "limit");
  CHECK(rows[1][4] == "limit");
  CHECK_THAT(r.err, Catch::Contains("does not assemble at phi = 0 deg") && Catch::Contains("assembled at phi = 10 deg"));
  // every branch: both intervals on both sides of A
  const test::RunResult all = test::RunKoppel("range " + test::TestDataPath("short-rod-slider-crank.yaml") + " --all-branches");
  REQUIRE(all.exit_code == 0);
  const auto branches = test::CsvCells(all.out);
  REQUIRE(branches.size() == 5);
  int low = 0, high = 0;
  for (size_t i = 1; i < branches.size(); ++i) {
    const double from = std::stod(branches[i][1]), to = std::stod(branches[i][2]);
    if (std::abs(from - std::asin(1.0 / 6) / kDeg) < 1e-9 && std::abs(to - std::asin(5.0 / 6) / kDeg) < 1e-9) ++low;
    if (std::abs(from - (180 - std::asin(5.0 / 6) / kDeg)) < 1e-9 && std::abs(to - (180 - std::asin(1.0 / 6) / kDeg)) < 1e-9) ++high;
  }
  CHECK(low == 2);
  CHECK(high == 2);
  // analyze starts there too
  const test::RunResult a = test::RunKoppel("analyze " + test::TestDataPath("short-rod-slider-crank.yaml") + " --from 20 --to 40 --step 10");
  CHECK(a.exit_code == 0);
  CHECK(test::CsvCells(a.out).size() == 4);
  CHECK_THAT(a.err, Catch::Contains("assembled at phi = 10 deg"));
}

TEST_CASE("issue 22 item 12: a distance through zero prints its rows, leaves d' and d'' empty there, names both, exits 1", "[cli][outputs]") {
  // tests/data/distance-through-zero.yaml: d = |A X| = 2 a |sin(phi / 2)|, a = 1: d(0) = 0, d'
  // jumps from -1 to +1 there; elsewhere d' = a cos(phi / 2) sign(sin(phi / 2))
  const test::RunResult r = test::RunKoppel("analyze " + test::TestDataPath("distance-through-zero.yaml") + " --from -20 --to 20 --step 10");
  INFO(r.err);
  CHECK(r.exit_code == 1);
  const auto rows = test::CsvCells(r.out);
  REQUIRE(rows.size() == 6);
  REQUIRE(rows[0][0] == "phi");
  REQUIRE(rows[0][1] == "d");
  for (size_t i = 1; i < rows.size(); ++i) {
    const double phi = std::stod(rows[i][0]) * kDeg;
    INFO("phi = " << rows[i][0]);
    CHECK(std::stod(rows[i][1]) == Approx(2 * std::abs(std::sin(phi / 2))).margin(1e-12));
    if (phi == 0) {
      CHECK(rows[i][2].empty());
      CHECK(rows[i][3].empty());
    } else {
      CHECK(std::stod(rows[i][2]) == Approx(std::cos(phi / 2) * (phi > 0 ? 1 : -1)).margin(1e-9));
    }
    CHECK(!rows[i][4].empty());  // psi is defined everywhere
  }
  CHECK_THAT(r.err, Catch::Contains("'d'") && Catch::Contains("phi = 0 deg") && Catch::Contains("not differentiable"));
  CHECK_THAT(r.err, !Catch::Contains("internal error"));
}

}  // namespace koppel::drive_input_test
