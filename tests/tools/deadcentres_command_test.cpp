// koppel deadcentres end to end (tools/cli/deadcentres_command.cpp): the repros of issue 22 items
// 1 and 2 against closed forms (the law of cosines for a crank-rocker's transmission angle and
// dead centres, tests/support/closed_forms.hpp; seed 000's mu_min; seed 002's construction).
#include "support/closed_forms.hpp"
#include "support/run.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

namespace koppel::deadcentres_command_test {
namespace {

constexpr double kDeg = 180 / M_PI;
// Printed with 12 significant digits (%.12g): 1e-9 deg for angles below 1000 deg.
constexpr double kPrinted = 1e-9;

}  // namespace

// issue 22 item 1: mu is stationary at phi = 0 (its minimum) and 180 deg; the one at 0 was dropped
TEST_CASE("deadcentres --output mu keeps the stationary point at the start of the turn", "[cli][deadcentres]") {
  const double a = 0.65, b = 3.2, c = 1.685, d = 2.664;
  const std::string command = "deadcentres " + test::CatalogEntryPath("crank-rocker") +
                              " --output mu --set a=0.65 --set b=3.2 --set c=1.685 --set d=2.664";
  const test::RunResult table = test::RunKoppel(command);
  REQUIRE(table.exit_code == 0);
  CHECK_THAT(table.out, Catch::StartsWith("kind,phi,mu,mu_d2\nunclassified,0,33.2061837935,") &&
                            Catch::Contains("\nunclassified,180,78.7891362453,"));
  const test::RunResult summary = test::RunKoppel(command + " --summary");
  REQUIRE(summary.exit_code == 0);
  const auto v = test::ParseSummary(summary.out);
  CHECK(v.at("mu_min") == Approx(test::CrankRockerMu(a, b, c, d, 0) * kDeg).margin(kPrinted));
  CHECK(v.at("mu_min") == Approx(33.2061837935).margin(kPrinted));  // the truth
  CHECK(std::abs(v.at("phi_mu_min")) < kPrinted);
  CHECK(v.at("mu_max") == Approx(test::CrankRockerMu(a, b, c, d, M_PI) * kDeg).margin(kPrinted));
  CHECK(v.at("phi_mu_max") == Approx(180).margin(kPrinted));
}

// issue 22 item 1: the extended dead centre at input 0 by the drive's zero
TEST_CASE("deadcentres lists the dead centre at input 0 and its summary", "[cli][deadcentres]") {
  const std::string file = test::TestDataPath("deadcentre-at-start.yaml");
  const double a = 1, b = 3, c = 2.5, d = 3;
  const test::CrankRockerDeadCentre extended = test::CrankRockerExtended(a, b, c, d), folded = test::CrankRockerFolded(a, b, c, d);
  const test::RunResult table = test::RunKoppel("deadcentres " + file + " --output psi");
  REQUIRE(table.exit_code == 0);
  CHECK_THAT(table.out, Catch::StartsWith("kind,phi,psi,psi_d2\nextended,0,87.1340160174,") && Catch::Contains("\nfolded,197.146300799,"));
  const test::RunResult summary = test::RunKoppel("deadcentres " + file + " --output psi --summary");
  REQUIRE(summary.exit_code == 0);
  const auto v = test::ParseSummary(summary.out);
  CHECK(std::abs(v.at("phi_a")) < kPrinted);
  CHECK(v.at("phi_i") == Approx((folded.phi - extended.phi) * kDeg).margin(kPrinted));
  CHECK(v.at("psi_a") == Approx(extended.psi * kDeg).margin(kPrinted));
  CHECK(v.at("psi_a") == Approx(87.1340160174).margin(kPrinted));  // the truth
  CHECK(v.at("psi_H") == Approx((folded.psi - extended.psi) * kDeg).margin(kPrinted));
  CHECK(v.at("psi_H") == Approx(51.4563618).margin(1e-7));
  // the time ratio, slow stroke over fast at a constant crank speed: the crank's turns between the
  // dead centres from the closed form, the larger over the smaller
  const double forward = (folded.phi - extended.phi) * kDeg, slow = std::max(forward, 360 - forward), fast = std::min(forward, 360 - forward);
  CHECK(v.at("time_ratio") == Approx(slow / fast).margin(1e-9));
  CHECK(v.at("time_ratio") >= 1);
}

// issue 22 item 2: a transmission angle's summary is mu_min, mu_max and where (seed 000: mu_min =
// 90 deg - arcsin(lambda + eps) at phi = 0; the fold mu = 90 deg where lambda cos phi + eps = 0)
TEST_CASE("deadcentres --output mu --summary prints mu_min, phi_mu_min, mu_max, phi_mu_max", "[cli][deadcentres]") {
  const test::RunResult r = test::RunKoppel("deadcentres " + test::CatalogEntryPath("slider-crank-offset") + " --output mu --summary");
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::StartsWith("quantity,value,unit\nmu_min,") && !Catch::Contains("stroke") && !Catch::Contains("mu_H") &&
                        !Catch::Contains("phase_ratio"));
  const auto v = test::ParseSummary(r.out);
  CHECK(v.size() == 4);
  CHECK(v.at("mu_min") == Approx(90 - std::asin(1 / 2.6 + 0.8 / 2.6) * kDeg).margin(kPrinted));
  CHECK(std::abs(v.at("phi_mu_min")) < kPrinted);
  CHECK(v.at("mu_max") == Approx(90).margin(kPrinted));
  CHECK(v.at("phi_mu_max") == Approx(test::SliderCrankMuFolds(1, 0.8)[0] * kDeg).margin(kPrinted));
  // JSON names where each is
  const test::RunResult json = test::RunKoppel("deadcentres " + test::CatalogEntryPath("slider-crank-offset") + " --output mu --format json");
  REQUIRE(json.exit_code == 0);
  CHECK_THAT(json.out, Catch::Contains("\"extremes\"") && Catch::Contains("\"at\": \"fold\"") && Catch::Contains("\"at\": \"stationary\""));
}

// Seed 002's crank-rocker (phi0 = 164, psi0 = 60 deg, beta = 40.37 deg in the document's sense):
// the lengths by the entry's algebra of the construction, mu_min by the law of cosines at phi = 0
// or 180 deg (whichever branch: mu depends on cos phi only).
TEST_CASE("deadcentres --output mu --summary on seed 002's crank-rocker", "[cli][deadcentres]") {
  const double phi0 = 164 / kDeg, psi0 = 60 / kDeg, beta = 40.3724612576 / kDeg, l4 = 1, phi_a = -beta;
  const double g = phi_a - phi0 + psi0, det = std::sin(psi0 - phi0);
  const double rho_a = (l4 * (1 - std::cos(psi0)) * std::sin(g) + l4 * std::sin(psi0) * std::cos(g)) / det;
  const double rho_i = (-std::cos(phi_a) * l4 * std::sin(psi0) - std::sin(phi_a) * l4 * (1 - std::cos(psi0))) / det;
  const double l1 = (rho_a - rho_i) / 2, l2 = (rho_a + rho_i) / 2;
  const double l3 = std::hypot(rho_a * std::cos(phi_a) - l4, rho_a * std::sin(phi_a));
  const double mu0 = test::CrankRockerMu(l1, l2, l3, l4, 0), mu180 = test::CrankRockerMu(l1, l2, l3, l4, M_PI);
  const test::RunResult r = test::RunKoppel("deadcentres " + test::CatalogEntryPath("deadcentre-crank-rocker") + " --output mu --summary");
  REQUIRE(r.exit_code == 0);
  const auto v = test::ParseSummary(r.out);
  CHECK(v.at("mu_min") == Approx(std::min(mu0, mu180) * kDeg).margin(kPrinted));
  CHECK(v.at("phi_mu_min") == Approx(mu0 < mu180 ? 0 : 180).margin(kPrinted));
}

// A summary that cannot be had says so and exits 1 (it printed an empty table with exit 0).
TEST_CASE("deadcentres --summary without two dead centres exits 1", "[cli][deadcentres]") {
  const test::RunResult r = test::RunKoppel("deadcentres " + test::CatalogEntryPath("slider-crank-offset") +
                                            " --output s --from 60 --to 200 --summary");
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("no summary") && Catch::Contains("1 dead centre found"));
}

}  // namespace koppel::deadcentres_command_test
