// `koppel synth ...` end to end: a synthesised mechanism written as YAML that analyze and
// deadcentres confirm; the charts; the Meyer zur Capellen linkage; a fit problem file.
#include "support/run.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <sstream>

namespace koppel {
namespace {

}  // namespace

TEST_CASE("synth deadcentre crank-rocker writes a mechanism that deadcentres confirms", "[cli][synth]") {
  test::TempDir dir;
  const std::string yaml = (dir.path() / "cr.yaml").string();
  const test::RunResult r = test::RunKoppel("synth deadcentre crank-rocker --phi0 164 --psi0 60 --beta 30 -o " + yaml);
  REQUIRE(r.exit_code == 0);
  CHECK(test::ParseSummary(r.out).at("beta") == Approx(30).margin(1e-12));
  const test::RunResult dc = test::RunKoppel("deadcentres " + yaml + " --output psi --summary");
  REQUIRE(dc.exit_code == 0);
  const auto v = test::ParseSummary(dc.out);
  CHECK(v.at("psi_H") == Approx(60).margin(1e-9));                      // the rocker swing psi0
  CHECK(std::fmod(v.at("phi_a") - v.at("phi_i") + 720, 360) == Approx(164).margin(1e-9));  // phi0, folded -> extended
  CHECK(test::RunKoppel("analyze " + yaml + " --step 10").exit_code == 0);
  const test::RunResult best = test::RunKoppel("synth deadcentre crank-rocker --phi0 164 --psi0 60");
  CHECK(test::ParseSummary(best.out).at("mu_min") == Approx(40.56).margin(0.01));
  CHECK(test::RunKoppel("synth deadcentre crank-rocker --phi0 164").exit_code == 2);  // --psi0 missing
  CHECK(test::RunKoppel("synth deadcentre crank-rocker --phi0 164 --psi0 60 --beta 170").exit_code == 1);
}

TEST_CASE("synth deadcentre slider-crank and the charts", "[cli][synth]") {
  test::TempDir dir;
  const std::string yaml = (dir.path() / "sc.yaml").string();
  const test::RunResult r = test::RunKoppel("synth deadcentre slider-crank --phi0 120 --stroke 1 -o " + yaml);
  REQUIRE(r.exit_code == 0);
  CHECK(test::ParseSummary(r.out).at("e_s0") == Approx(0.16).margin(0.005));
  const auto v = test::ParseSummary(test::RunKoppel("deadcentres " + yaml + " --output s --summary").out);
  CHECK(v.at("s_H") == Approx(1.0).margin(1e-9));
  const test::RunResult chart = test::RunKoppel("synth chart slider-crank --phi0 110:130:10 --quiet");
  REQUIRE(chart.exit_code == 0);
  CHECK_THAT(chart.out, Catch::StartsWith("phi0,e_s0,l1_s0,l2_s0,mu_min,beta\n110,"));
  const test::RunResult cr = test::RunKoppel("synth chart crank-rocker --phi0 164:164:1 --psi0 60:60:1 --quiet");
  REQUIRE(cr.exit_code == 0);
  CHECK_THAT(cr.out, Catch::Contains("\n164,60,38.16"));
  CHECK(test::RunKoppel("synth chart crank-rocker --phi0 170:160:1").exit_code == 2);
}

TEST_CASE("synth mzc --lambda 5/6: six-point contact and the seed 003 cognate", "[cli][synth]") {
  test::TempDir dir;
  const test::RunResult r = test::RunKoppel("synth mzc --lambda 5/6 --D 1 -o " + (dir.path() / "mzc.yaml").string());
  REQUIRE(r.exit_code == 0);
  const auto v = test::ParseSummary(r.out);
  CHECK(v.at("contact_points") >= 6);
  CHECK(v.at("kappa") == Approx(15.79).margin(0.005));
  CHECK(v.at("crank_rocker_l4") / v.at("crank_rocker_l1") == Approx(4.0).epsilon(1e-9));
  CHECK(test::RunKoppel("analyze " + (dir.path() / "mzc.yaml").string()).exit_code == 0);
  CHECK(test::RunKoppel("synth mzc --lambda 2").exit_code == 2);
}

TEST_CASE("synth fit: five precision points recover seed 003's dimensions", "[cli][synth]") {
  test::TempDir dir;
  const std::string fitted = (dir.path() / "fitted.yaml").string();
  const test::RunResult r = test::RunKoppel("synth fit " + std::string(KOPPEL_TEST_DATA_DIR) + "/fit-mzc-precision-points.yaml --quiet -o " + fitted);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto v = test::ParseSummary(r.out);
  CHECK(v.at("l3") == Approx(2.5 * std::sqrt(3.0)).margin(1e-8));
  CHECK(v.at("k") == Approx(25.0 / 3).margin(1e-8));
  CHECK(v.at("full_rotation") == 1);
  CHECK(test::RunKoppel("analyze " + fitted + " --step 30").exit_code == 0);
  const std::string bad = dir.Write("bad.yaml", "mechanism: nowhere.yaml\nparameters: {}\ntargets: []\n");
  const test::RunResult b = test::RunKoppel("synth fit " + bad);
  CHECK(b.exit_code == 2);
  CHECK_THAT(b.err, Catch::Contains("bad.yaml:1:"));
}

}  // namespace koppel
