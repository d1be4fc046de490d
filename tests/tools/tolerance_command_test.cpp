// koppel tolerance end to end (tools/cli/tolerance_command.cpp): issue 27's command on seed 000's
// slider-crank, its numbers against the closed form (tests/support/closed_forms.hpp: s, and the
// crank pin's clearance c / cos psi), and the bad inputs it refuses.
#include "support/closed_forms.hpp"
#include "support/run.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace koppel::tolerance_command_test {

// issue 27, "Done when"
TEST_CASE("tolerance: issue 27's slider-crank at 60 deg prints every named quantity, proved by the closed form", "[cli][tolerance]") {
  const test::RunResult r = test::RunKoppel("tolerance " + test::CatalogEntryPath("slider-crank-offset") +
                                            " --output s --at 60 --tol l1=0.01 --tol l2=0.02 --tol e=0.005 --clearance A=0.003"
                                            " --samples 20000 --seed 1 --format json");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  REQUIRE(j["rows"].size() == 1);
  const nlohmann::json& row = j["rows"][0];
  for (const char* key : {"phi", "nominal", "sens_l1", "sens_l2", "sens_e", "sens_clearance_A", "worst_case", "rss", "clearance_worst_case",
                          "linear_std", "share_l1", "share_l2", "share_e", "share_clearance_A", "mc_samples", "mc_failed", "mc_min", "mc_max",
                          "mc_mean", "mc_std", "mc_q0.001", "mc_q0.01", "mc_q0.5", "mc_q0.99", "mc_q0.999"}) {
    INFO(key);
    CHECK(row.contains(key));
    CHECK(row[key].is_number());
  }
  const double phi = M_PI / 3;
  CHECK(row["nominal"].get<double>() == Approx(test::SliderCrank(1, 2.6, 0.8, phi).s).margin(1e-11));
  // central differences of the closed form, h = 1e-5 (error ~1e-10)
  const double h = 1e-5;
  CHECK(row["sens_l1"].get<double>() ==
        Approx((test::SliderCrank(1 + h, 2.6, 0.8, phi).s - test::SliderCrank(1 - h, 2.6, 0.8, phi).s) / (2 * h)).margin(1e-8));
  CHECK(row["sens_e"].get<double>() ==
        Approx((test::SliderCrank(1, 2.6, 0.8 + h, phi).s - test::SliderCrank(1, 2.6, 0.8 - h, phi).s) / (2 * h)).margin(1e-8));
  // the crank pin: c / cos psi, sin psi = -lambda cos phi - eps (seed 000)
  const double sin_psi = -std::cos(phi) / 2.6 - 0.8 / 2.6;
  CHECK(row["clearance_worst_case"].get<double>() == Approx(0.003 / std::sqrt(1 - sin_psi * sin_psi)).epsilon(1e-9));
  // the samples stay inside the linear band but for second-order terms (T^2 s'' ~ 1e-3 here)
  const double nominal = row["nominal"], band = row["worst_case"].get<double>() + row["clearance_worst_case"].get<double>();
  CHECK(row["mc_min"].get<double>() >= nominal - band - 1e-3);
  CHECK(row["mc_max"].get<double>() <= nominal + band + 1e-3);
  CHECK(row["mc_std"].get<double>() == Approx(row["linear_std"].get<double>()).epsilon(0.05));
  CHECK(row["mc_failed"].get<double>() == 0);
  double shares = 0;
  for (const char* key : {"share_l1", "share_l2", "share_e", "share_clearance_A"}) shares += row[key].get<double>();
  CHECK(shares == Approx(1).epsilon(1e-12));
  // the same seed gives the same numbers (on any number of threads)
  const test::RunResult again = test::RunKoppel("tolerance " + test::CatalogEntryPath("slider-crank-offset") +
                                                " --output s --at 60 --tol l1=0.01 --tol l2=0.02 --tol e=0.005 --clearance A=0.003"
                                                " --samples 20000 --seed 1 --format json --threads 1");
  REQUIRE(again.exit_code == 0);
  CHECK(nlohmann::json::parse(again.out)["rows"][0]["mc_std"] == row["mc_std"]);
}

TEST_CASE("tolerance over a range: one CSV row per input", "[cli][tolerance]") {
  const test::RunResult r = test::RunKoppel("tolerance " + test::CatalogEntryPath("slider-crank-offset") +
                                            " --output s --from 0 --to 90 --step 30 --tol l2=0.02");
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::StartsWith("phi,nominal,sens_l2,worst_case,rss,clearance_worst_case,linear_std,share_l2\n0,"));
  CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 5);
}

TEST_CASE("tolerance refuses bad input with exit 2 and names it", "[cli][tolerance]") {
  const std::string file = test::CatalogEntryPath("slider-crank-offset");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {" --output s --at 60 --tol l9=0.01", "no parameter 'l9'"},
      {" --output s --at 60 --tol l1=0.01 --clearance S=0.001", "joint 'S' is a slide"},
      {" --output s --at 60 --tol l1=-0.01", "must be a positive number"},
      {" --output s --tol l1=0.01", "either --at"},
      {" --output s --at 60 --tol l1", "expected NAME=VALUE"},
      {" --output s --at 60 --tol l1=0.01 --distribution triangular", "uniform or normal"},
      {" --output nope --at 60 --tol l1=0.01", "no output 'nope'"},
  };
  for (const auto& [arguments, phrase] : cases) {
    const test::RunResult r = test::RunKoppel("tolerance " + file + arguments);
    INFO(arguments << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains(phrase));
    CHECK(r.out.empty());
  }
}

TEST_CASE("tolerance past the mechanism's limits: the samples that do not assemble are counted, exit 1", "[cli][tolerance]") {
  // e = 1.55: at phi = 0 (A0A away from the slide) B needs l2 >= l1 + e = 2.55: a quarter of l2 = 2.6 +- 0.1 misses
  const test::RunResult r = test::RunKoppel("tolerance " + test::CatalogEntryPath("slider-crank-offset") +
                                            " --set e=1.55 --output s --at 0 --tol l2=0.1 --samples 400 --format json");
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("did not assemble"));
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["rows"][0]["mc_failed"].get<double>() > 0);
  CHECK(j["status"] == "partial");
}

}  // namespace koppel::tolerance_command_test

namespace koppel::tolerance_command_test {

TEST_CASE("plot --tolerance draws the nominal output in its worst-case band, the Monte Carlo extremes and the shares", "[cli][tolerance]") {
  const std::string file = test::CatalogEntryPath("slider-crank-offset");
  const test::RunResult r = test::RunKoppel("plot " + file + " --tolerance s --tol l1=0.01 --tol l2=0.02 --clearance A=0.003 --from 0 --to 360 --step 10 --samples 200");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::StartsWith("<svg") || Catch::StartsWith("<?xml"));
  for (const char* label : {"linear worst case", "nominal", "Monte Carlo min, max", "share of the variance", "clearance A", "l2"}) {
    INFO(label);
    CHECK_THAT(r.out, Catch::Contains(label));
  }
  const test::RunResult none = test::RunKoppel("plot " + file + " --tolerance s");
  CHECK(none.exit_code == 2);
  CHECK_THAT(none.err, Catch::Contains("at least one tolerance"));
}

}  // namespace koppel::tolerance_command_test
