// FitMechanism (tools/api/src/fit.cpp) on five precision points of seed 003's coupler point: the
// report's rows against the targets' tolerances, and what the fitted mechanism does checked
// independently on the fitted mechanism file read back through the API (a whole turn swept by
// Model::Sweep, mu_min as the least of its mu column).
#include "koppel/api/fit.hpp"
#include "koppel/api/model.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>

using namespace koppel;
using Catch::Matchers::WithinAbs;

namespace fit_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

// the fit stops at Ceres' tolerances on the targets (1e-6 of the residual): the parameters it
// recovers are that close to the answer the targets were made from
constexpr double kRecovered = 1e-6;
// the fitted file holds every value to 17 digits: read back, it is the same number
constexpr double kWrittenBack = 1e-9;

std::map<std::string, FitQuantity> ByName(const FitOutcome& outcome) {
  std::map<std::string, FitQuantity> rows;
  for (const FitQuantity& q : outcome.report) rows[q.quantity] = q;
  return rows;
}

}  // namespace

TEST_CASE("FitMechanism: seed 003's precision points met; the fitted file turns fully and its mu_min is the report's", "[api]") {
  FitRequest request;
  request.problem = test::TestDataPath("fit-mzc-precision-points.yaml");
  request.threads = 2;
  request.yaml = true;
  const FitOutcome outcome = FitMechanism(request);
  INFO(outcome.message);
  REQUIRE(outcome.fitted);
  CHECK(outcome.ok);
  CHECK(outcome.status == "converged");
  CHECK(outcome.starts.size() == 16);  // the default number of starts
  std::map<std::string, FitQuantity> rows = ByName(outcome);
  // the answer the targets were made from: l3 = 5/2 sqrt 3, k = AK = 25/3 (the problem file's note)
  CHECK_THAT(rows["l3"].value, WithinAbs(2.5 * std::sqrt(3.0), kRecovered));
  CHECK_THAT(rows["k"].value, WithinAbs(25.0 / 3.0, kRecovered));
  for (int i = 1; i <= 5; ++i) {
    const std::string key = "target" + std::to_string(i) + "_K";
    CHECK(rows[key + "_residual"].unit == "length");
    CHECK(rows[key + "_residual"].value <= rows[key + "_tolerance"].value);
    CHECK(rows[key + "_met"].value == 1);
  }
  CHECK(rows["starts"].value == 16);
  CHECK(rows["start"].value == outcome.best_start);
  // the fitted mechanism file, read back: it turns through a whole turn from its assembly
  const test::TempDir dir;
  const Model fitted = Model::Load(dir.Write("fitted.yaml", outcome.yaml));
  for (const auto& [name, value] : fitted.parameters()) {
    if (name == "l3" || name == "k") CHECK_THAT(value, WithinAbs(rows[name].value, kWrittenBack));
  }
  const SweepTable turn = fitted.Sweep(0, 360, 1, 0);
  REQUIRE(turn.status == AnalysisStatus::kComplete);
  CHECK(rows["full_rotation"].value == 1);
  CHECK(rows["assembles_over_required_range"].value == 1);
  const std::vector<double> mu = turn.Column("mu");
  CHECK_THAT(rows["mu_min_mu"].value, WithinAbs(*std::min_element(mu.begin(), mu.end()), 1e-9));
  CHECK(rows["mu_min_mu"].unit == "deg");
}

TEST_CASE("FitMechanism: bad options are bad input, nothing fitted; a problem file that does not read is InputError", "[api]") {
  FitRequest request;
  request.problem = test::TestDataPath("fit-mzc-precision-points.yaml");
  request.threads = -3;
  const FitOutcome outcome = FitMechanism(request);
  CHECK(outcome.bad_input);
  CHECK_FALSE(outcome.fitted);
  CHECK(outcome.starts.empty());
  CHECK(!outcome.message.empty());
  request.problem = test::TestDataPath("slider-crank-loads.yaml");  // a mechanism file, not a fit problem
  request.threads.reset();
  CHECK_THROWS_AS(FitMechanism(request), InputError);
}

}  // namespace fit_test
