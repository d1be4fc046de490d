// `koppel bench`: the table and its JSON, each ratio the time over its baseline measured in the
// same run (or a budget), the baselines run even when the filter leaves them out, bad flags
// refused with exit 2. Short runs (--min-time 0.02): the numbers are checked for consistency,
// not for speed (that is what the command is for).
#include "support/run.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <map>

namespace koppel::bench_command_test {
namespace {

std::map<std::string, nlohmann::json> ByName(const std::string& out) {
  const nlohmann::json j = nlohmann::json::parse(out);
  std::map<std::string, nlohmann::json> rows;
  for (const nlohmann::json& b : j.at("benchmarks")) rows[b.at("name").get<std::string>()] = b;
  return rows;
}

}  // namespace

TEST_CASE("bench: a walk step against its closed form, the baseline run although the filter leaves it out", "[cli][bench]") {
  const test::RunResult r = test::RunKoppel("bench --filter '^slider-crank$' --format json --min-time 0.02");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto rows = ByName(r.out);
  REQUIRE(rows.size() == 2);
  const nlohmann::json& walk = rows.at("slider-crank");
  const nlohmann::json& closed = rows.at("slider-crank-closed-form");
  CHECK(walk.at("per") == "step");
  const double ns = walk.at("ns_per_step").get<double>(), baseline = closed.at("ns_per_step").get<double>();
  CHECK(ns > 0.0);
  CHECK(baseline > 0.0);
  CHECK(walk.at("baseline").get<double>() == Approx(baseline).epsilon(1e-12));
  CHECK(walk.at("ratio").get<double>() == Approx(ns / baseline).epsilon(1e-12));
  CHECK(walk.at("baseline_name") == "slider-crank-closed-form");
  CHECK(closed.at("ratio").is_null());
}

TEST_CASE("bench: chain16 per loop against chain4 per loop", "[cli][bench]") {
  const test::RunResult r = test::RunKoppel("bench --filter 'chain16' --format json --min-time 0.02");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto rows = ByName(r.out);
  REQUIRE(rows.count("chain4") == 1);
  const double chain4 = rows.at("chain4").at("ns_per_step").get<double>();
  const nlohmann::json& chain16 = rows.at("chain16");
  CHECK(chain16.at("baseline").get<double>() == Approx(4.0 * chain4).epsilon(1e-12));
  CHECK(chain16.at("ratio").get<double>() == Approx(chain16.at("ns_per_step").get<double>() / (4.0 * chain4)).epsilon(1e-12));
}

TEST_CASE("bench: a synthesis against its time budget, as a table by default", "[cli][bench]") {
  const test::RunResult json = test::RunKoppel("bench --filter deadcentre --format json --min-time 0.02");
  INFO(json.err);
  REQUIRE(json.exit_code == 0);
  const auto rows = ByName(json.out);
  const nlohmann::json& row = rows.at("deadcentre-synthesis");
  CHECK(row.at("per") == "run");
  CHECK(row.at("baseline_name") == "budget");
  CHECK(row.at("baseline").get<double>() == 5e6);  // 5 ms
  CHECK(row.at("ratio").get<double>() == Approx(row.at("ns_per_step").get<double>() / 5e6).epsilon(1e-12));

  const test::RunResult table = test::RunKoppel("bench --filter deadcentre --min-time 0.02");
  REQUIRE(table.exit_code == 0);
  CHECK_THAT(table.out, Catch::StartsWith("name"));
  CHECK_THAT(table.out, Catch::Contains("deadcentre-synthesis") && Catch::Contains("/run") && Catch::Contains("load average"));
}

TEST_CASE("bench: the start-up of koppel itself, --version against 10 ms and analyze against twice that", "[cli][bench]") {
  const test::RunResult r = test::RunKoppel("bench --filter '^startup-analyze$' --format json --min-time 0.05");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto rows = ByName(r.out);
  REQUIRE(rows.size() == 2);  // the version's run is the analyze's baseline
  const nlohmann::json& version = rows.at("startup-version");
  const nlohmann::json& analyze = rows.at("startup-analyze");
  for (const nlohmann::json* row : {&version, &analyze}) {
    CHECK(row->at("per") == "run");
    CHECK(row->at("clock") == "wall");  // the work is another process's
    // a process that starts, loads and exits takes more than 0.1 ms
    CHECK(row->at("ns_per_step").get<double>() > 1e5);
  }
  CHECK(version.at("baseline_name") == "budget");
  CHECK(version.at("baseline").get<double>() == 1e7);  // 10 ms
  const double version_ns = version.at("ns_per_step").get<double>();
  CHECK(version.at("ratio").get<double>() == Approx(version_ns / 1e7).epsilon(1e-12));
  CHECK(analyze.at("baseline").get<double>() == Approx(2.0 * version_ns).epsilon(1e-12));
  CHECK(analyze.at("baseline_name") == "startup-version x 2");
  CHECK(analyze.at("ratio").get<double>() == Approx(analyze.at("ns_per_step").get<double>() / (2.0 * version_ns)).epsilon(1e-12));
}

TEST_CASE("bench: a filter that matches nothing, a broken expression and an unknown format are bad input", "[cli][bench]") {
  const test::RunResult none = test::RunKoppel("bench --filter no-such-benchmark");
  CHECK(none.exit_code == 2);
  CHECK_THAT(none.err, Catch::Contains("matches no benchmark") && Catch::Contains("chain128"));
  const test::RunResult broken = test::RunKoppel("bench --filter '('");
  CHECK(broken.exit_code == 2);
  CHECK_THAT(broken.err, Catch::Contains("--filter"));
  const test::RunResult format = test::RunKoppel("bench --format xml");
  CHECK(format.exit_code == 2);
  CHECK_THAT(format.err, Catch::Contains("--format"));
}

}  // namespace koppel::bench_command_test

namespace koppel::bench_command_test {

TEST_CASE("bench: the atlas build per curve against 10 us (100 000 curves per second on one core)", "[cli][bench]") {
  const test::RunResult r = test::RunKoppel("bench --filter atlas-build --format json --min-time 0.02");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto rows = ByName(r.out);
  REQUIRE(rows.size() == 1);
  const nlohmann::json& row = rows.at("atlas-build");
  CHECK(row.at("per") == "curve");
  CHECK(row.at("baseline_name") == "budget");
  CHECK(row.at("baseline").get<double>() == 10000.0);
  const double ns = row.at("ns_per_step").get<double>();
  CHECK(ns > 0.0);
  CHECK(row.at("ratio").get<double>() == Approx(ns / 10000.0).epsilon(1e-12));
  const test::RunResult table = test::RunKoppel("bench --filter atlas-build --min-time 0.02");
  CHECK_THAT(table.out, Catch::Contains("atlas-build") && Catch::Contains("/curve"));
}

}  // namespace koppel::bench_command_test
