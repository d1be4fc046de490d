// koppel curvature and koppel poles end to end (tools/cli/curvature_command.cpp,
// poles_command.cpp): issue 27's command on seed 003's crank-rocker at phi = 180 deg, against the
// document's geometry (K on the inflection circle: the six-point tangent; the pole where the crank
// line meets the rocker line).
#include "support/instant_geometry.hpp"
#include "support/run.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace koppel::curvature_command_test {
namespace {

// seed 003 at phi = 180 deg: A = (-1, 0); B on the perpendicular bisector of A and B0 = (4, 0)
// (AB = B0B = 5/2 sqrt(3)), above A0B0
const Eigen::Vector2d kA0(0, 0), kA(-1, 0), kB0(4, 0), kB(1.5, std::sqrt(18.75 - 6.25));

}  // namespace

// issue 27, "Done when"
TEST_CASE("curvature: seed 003's K at 180 deg lies on the inflection circle, the pole on the crank and rocker lines", "[cli][curvature]") {
  const test::RunResult r = test::RunKoppel("curvature " + test::CatalogEntryPath("mzc-crank-rocker") + " --point K --at 180 --format json");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : {"pole_x", "pole_y", "pole_direction_x", "pole_direction_y", "inflection_x", "inflection_y", "inflection_diameter",
                          "ball_x", "ball_y", "K_x", "K_y", "curvature"}) {
    INFO(key);
    CHECK(j[key].is_number());
  }
  const auto pole = test::LineIntersection(kA0, kA, kB0, kB);
  REQUIRE(pole);
  // printed with 12 digits
  CHECK(j["pole_x"].get<double>() == Approx(pole->x()).margin(1e-9));
  CHECK(j["pole_y"].get<double>() == Approx(pole->y()).margin(1e-9));
  const Eigen::Vector2d k(j["K_x"], j["K_y"]), centre(j["inflection_x"], j["inflection_y"]);
  CHECK((k - centre).norm() == Approx(j["inflection_diameter"].get<double>() / 2).margin(1e-9));
  CHECK(j["rho"].is_null());
  CHECK(j["rho_infinite"] == true);
  CHECK(j["curvature"] == 0.0);
  CHECK(std::hypot(j["ball_x"].get<double>() - k.x(), j["ball_y"].get<double>() - k.y()) < 1e-6);
  // K_I lies 10/3 sqrt(6) from B0 (seed 003)
  CHECK((k - kB0).norm() == Approx(10.0 / 3 * std::sqrt(6.0)).margin(1e-9));
}

TEST_CASE("curvature CSV: quantity,value,unit with a finite radius at another input", "[cli][curvature]") {
  const test::RunResult r = test::RunKoppel("curvature " + test::CatalogEntryPath("mzc-crank-rocker") + " --point K --at 90");
  REQUIRE(r.exit_code == 0);
  const auto v = test::ParseSummary(r.out);
  CHECK(v.count("rho") == 1);
  CHECK(std::hypot(v.at("centre_x") - v.at("K_x"), v.at("centre_y") - v.at("K_y")) == Approx(std::abs(v.at("rho"))).epsilon(1e-9));
}

TEST_CASE("curvature: a slider's pole is at infinity: the quantities that exist are printed, exit 1", "[cli][curvature]") {
  const test::RunResult r = test::RunKoppel("curvature " + test::CatalogEntryPath("slider-crank-offset") + " --point slider.B --at 60");
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("pole is at infinity"));
  CHECK_THAT(r.out, Catch::Contains("\npole_x,,length\n") && Catch::Contains("\nslider.B_x,3.11769145362,length\n"));
}

TEST_CASE("curvature refuses an unknown point with exit 2", "[cli][curvature]") {
  const test::RunResult r = test::RunKoppel("curvature " + test::CatalogEntryPath("mzc-crank-rocker") + " --point Q --at 90");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("Q"));
}

TEST_CASE("poles: every pair of a four-bar, the joints where two links meet and the coupler's pole at B0", "[cli][poles]") {
  const test::RunResult r = test::RunKoppel("poles " + test::CatalogEntryPath("mzc-crank-rocker") + " --at 180");
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::StartsWith("link_a,link_b,kind,pole_x,pole_y,direction_x,direction_y\n"));
  CHECK_THAT(r.out, Catch::Contains("\nframe,crank,finite,0,0,,\n"));
  CHECK_THAT(r.out, Catch::Contains("\nframe,rocker,finite,4,0,,\n"));
  CHECK_THAT(r.out, Catch::Contains("\ncrank,coupler,finite,-1,"));
  CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 7);
  // the coupler against the frame: the crank line (the x axis here) meets the rocker line in B0
  CHECK_THAT(r.out, Catch::Contains("\nframe,coupler,finite,4,"));
}

TEST_CASE("poles --centrode: the coupler's centrodes, the moving one carried to --at touches the fixed one at the pole", "[cli][poles]") {
  const test::RunResult r =
      test::RunKoppel("poles " + test::CatalogEntryPath("mzc-crank-rocker") + " --at 180 --centrode coupler --from 170 --to 190 --step 10 --format json");
  REQUIRE(r.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  REQUIRE(j["rows"].size() == 3);
  const nlohmann::json& at = j["rows"][1];  // phi = 180
  CHECK(at[0] == 180.0);
  CHECK(at[1].get<double>() == Approx(at[5].get<double>()).margin(1e-9));
  CHECK(at[2].get<double>() == Approx(at[6].get<double>()).margin(1e-9));
}

// Every length figure says the file's unit (mm here), the curvature its reciprocal.
TEST_CASE("curvature labels lengths with the file's unit", "[cli][curvature]") {
  const test::RunResult r = test::RunKoppel("curvature " + test::TestDataPath("slider-crank-loads.yaml") + " --at 30 --point coupler.S2");
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::Contains("\ncoupler.S2_x,77.80") && Catch::Contains(",mm\n") && Catch::Contains(",1/mm\n") && !Catch::Contains("length"));
}
}  // namespace koppel::curvature_command_test
