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
      // a tolerance or play past any part's size: the stack-up overflowed into "internal error:
      // refusing to print a non-finite number", exit 1, no rows
      {" --output s --at 10 --tol l1=1e308", "up to 1e9 (kMaxCoordinate)"},
      {" --output s --at 10 --clearance A=1e308", "up to 1e9 (kMaxCoordinate)"},
      // counts within the shared limits, whole, as formulas: --threads -1 and --seed -1 were taken,
      // --samples 5000000 over a turn ended in std::bad_alloc
      {" --output s --at 10 --tol l1=0.01 --threads -1", "--threads: expected a whole number from 0 to 256"},
      {" --output s --at 10 --tol l1=0.01 --threads 1000", "--threads: expected a whole number from 0 to 256"},
      {" --output s --at 10 --tol l1=0.01 --seed -1", "--seed: expected a whole number from 0 to 9007199254740992"},
      {" --output s --at 10 --tol l1=0.01 --samples 2.5", "--samples: expected a whole number from 0 to 1000000"},
      {" --output s --at 10 --tol l1=0.01 --samples 10000000 --threads 2", "--samples: expected a whole number from 0 to 1000000"},
      {" --output s --from 0 --to 360 --step 1 --tol l1=0.01 --samples 1000000", "kMaxToleranceValues"},
  };
  for (const auto& [arguments, phrase] : cases) {
    const test::RunResult r = test::RunKoppel("tolerance " + file + arguments);
    INFO(arguments << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains(phrase));
    CHECK(r.out.empty());
  }
}

TEST_CASE("tolerance counts are formulas like every other count", "[cli][tolerance]") {
  // --samples 1e3 was refused as "Could not convert" while --step took "360/7"
  const std::string run = "tolerance " + test::CatalogEntryPath("slider-crank-offset") + " --output s --at 60 --tol l1=0.01 --format json";
  const test::RunResult formula = test::RunKoppel(run + " --samples 1e3 --seed 2^10 --threads 1+1");
  const test::RunResult plain = test::RunKoppel(run + " --samples 1000 --seed 1024 --threads 2");
  INFO(formula.err);
  REQUIRE(formula.exit_code == 0);
  REQUIRE(plain.exit_code == 0);
  const nlohmann::json a = nlohmann::json::parse(formula.out), b = nlohmann::json::parse(plain.out);
  CHECK(a["samples"] == 1000);
  CHECK(a["seed"] == 1024);
  CHECK(a["rows"][0]["mc_std"] == b["rows"][0]["mc_std"]);
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

namespace koppel::tolerance_command_test {
namespace {

// relative: mc_std of 20000 samples against linear_std: one component of a pin uniform in its
// disc has kurtosis 2, so the sampled standard deviation's relative standard error is
// sqrt(2 - 1) / (2 sqrt(20000)) = 0.35 %; 2 % is 5.7 of them (c = 0.01 against lengths >= 1 keeps
// the linear model's own error near c^2: the crank-rocker's mu differs by 0.04 % from 200 000 samples)
constexpr double kPinMonteCarlo = 0.02;

// One row of `koppel tolerance FILE ARGUMENTS --format json`, exit 0 required.
nlohmann::json ToleranceRow(const std::string& entry, const std::string& arguments) {
  const test::RunResult r = test::RunKoppel("tolerance " + test::CatalogEntryPath(entry) + " " + arguments + " --format json");
  INFO(arguments << ": " << r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  REQUIRE(j["rows"].size() == 1);
  return j["rows"][0];
}

}  // namespace

TEST_CASE("tolerance: play at any joint of the crank-rocker moves mu alike, and the samples spread as linear_std says", "[cli][tolerance]") {
  // the repro: the crank-rocker (a, b, c, d = 1, 3.5, 3, 4) at phi = 60 deg. In one loop
  // a gap delta at any joint enters the closure as a frame vector (d, 0) + delta would: its x
  // part lengthens d, its y part turns the frame by delta_y / d (the crank angle less that), so
  // |d mu / d delta| = sqrt((d mu / d d)^2 + (d mu / d phi / d)^2) at all four joints, from the
  // catalog's closed form mu = min(gamma, 180 deg - gamma) (central differences, h = 1e-6)
  const double a = 1, b = 3.5, c = 3, d = 4, phi = M_PI / 3, h = 1e-6;
  const double dmu_dd = (test::CrankRockerMu(a, b, c, d + h, phi) - test::CrankRockerMu(a, b, c, d - h, phi)) / (2 * h);
  const double dmu_dphi = (test::CrankRockerMu(a, b, c, d, phi + h) - test::CrankRockerMu(a, b, c, d, phi - h)) / (2 * h);
  const double reference = std::hypot(dmu_dd, dmu_dphi / d) * 180 / M_PI;  // [deg per length]
  for (const char* joint : {"A0", "A", "B", "B0"}) {
    const nlohmann::json row = ToleranceRow("crank-rocker", std::string("--output mu --at 60 --tol a=1e-9 --clearance ") + joint +
                                                                "=0.01 --samples 20000 --seed 1");
    INFO("play at " << joint << ": " << row.dump());
    CHECK(row[std::string("sens_clearance_") + joint].get<double>() == Approx(reference).epsilon(1e-7));
    CHECK(row["mc_std"].get<double>() == Approx(row["linear_std"].get<double>()).epsilon(kPinMonteCarlo));
    // and linear_std is the pin's c / 2 times that gradient (a's 1e-9 adds nothing visible)
    CHECK(row["linear_std"].get<double>() == Approx(0.01 / 2 * reference).epsilon(1e-7));
  }
}

TEST_CASE("tolerance: play at any joint of the slider-crank moves mu as the offset e does", "[cli][tolerance]") {
  // seed 000: A gap's x part goes into s, its y part shifts the crank's pivot as e does:
  // |d mu / d delta| = |d mu / d e| (closed form mu = 90 deg - |psi|, central differences)
  const double phi = M_PI / 3, h = 1e-6;
  const double reference = std::abs(test::SliderCrank(1, 2.6, 0.8 + h, phi).mu - test::SliderCrank(1, 2.6, 0.8 - h, phi).mu) / (2 * h) * 180 / M_PI;
  for (const char* joint : {"A0", "A", "B"}) {
    const nlohmann::json row = ToleranceRow("slider-crank-offset", std::string("--output mu --at 60 --tol l1=1e-9 --clearance ") + joint +
                                                                       "=0.003 --samples 20000 --seed 1");
    INFO("play at " << joint << ": " << row.dump());
    CHECK(row[std::string("sens_clearance_") + joint].get<double>() == Approx(reference).epsilon(1e-7));
    CHECK(row["mc_std"].get<double>() == Approx(row["linear_std"].get<double>()).epsilon(kPinMonteCarlo));
  }
}

TEST_CASE("tolerance: the shares are each term's part of linear_std^2, for either distribution", "[cli][tolerance]") {
  // README's example. Seed 000's closed form gives the sensitivities (central differences,
  // h = 1e-6) and the pin's gain 1 / cos psi; each term's variance is (s T sigma)^2 with sigma =
  // 1 / sqrt(3) (uniform) or 1 / 3 (normal), and (gain c)^2 / 4 for the pin in its disc
  const double phi = M_PI / 3, h = 1e-6;
  const std::vector<double> nominal = {1, 2.6, 0.8}, tolerance = {0.01, 0.02, 0.005};
  std::vector<double> part;  // s_j T_j, then gain c
  for (int j = 0; j < 3; ++j) {
    std::vector<double> plus = nominal, minus = nominal;
    plus[j] += h;
    minus[j] -= h;
    part.push_back((test::SliderCrank(plus[0], plus[1], plus[2], phi).s - test::SliderCrank(minus[0], minus[1], minus[2], phi).s) / (2 * h) * tolerance[j]);
  }
  const double sin_psi = -std::cos(phi) / 2.6 - 0.8 / 2.6;
  part.push_back(0.003 / std::sqrt(1 - sin_psi * sin_psi));
  for (const auto& [distribution, sigma] : {std::pair{"uniform", 1 / std::sqrt(3.0)}, std::pair{"normal", 1.0 / 3}}) {
    const nlohmann::json row = ToleranceRow("slider-crank-offset", std::string("--output s --at 60 --tol l1=0.01 --tol l2=0.02 --tol e=0.005"
                                                                               " --clearance A=0.003 --distribution ") + distribution);
    std::vector<double> variance;
    for (int j = 0; j < 3; ++j) variance.push_back(std::pow(part[j] * sigma, 2));
    variance.push_back(std::pow(part[3], 2) / 4);
    double total = 0;
    for (double v : variance) total += v;
    INFO(distribution << ": " << row.dump());
    CHECK(row["linear_std"].get<double>() == Approx(std::sqrt(total)).epsilon(1e-8));
    const char* keys[] = {"share_l1", "share_l2", "share_e", "share_clearance_A"};
    for (int t = 0; t < 4; ++t) CHECK(row[keys[t]].get<double>() == Approx(variance[t] / total).epsilon(1e-7));
  }
}

}  // namespace koppel::tolerance_command_test
