// `koppel catalog list | find | show | check` end to end.
#include "support/run.hpp"

#include <catch2/catch.hpp>

namespace koppel {

TEST_CASE("catalog check passes for every entry and says so per check", "[cli][catalog]") {
  const test::RunResult r = test::RunKoppel("catalog check");
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::StartsWith("id,variant,kind,check,status,worst,tolerance,value,at,detail"));
  CHECK(r.out.find(",FAIL,") == std::string::npos);
  CHECK_THAT(r.err, Catch::Contains("0 failed"));
}

TEST_CASE("catalog find by the issue's example, by ranges, by kind; list; show", "[cli][catalog]") {
  const test::RunResult f = test::RunKoppel("catalog find --links 6 --ternary 2 --revolute 4 --prismatic 3 --drives-at-frame 1");
  REQUIRE(f.exit_code == 0);
  CHECK_THAT(f.out, Catch::Contains("\nproportional-linkage,"));
  CHECK(std::count(f.out.begin(), f.out.end(), '\n') == 2);  // header + one entry
  const test::RunResult range = test::RunKoppel("catalog find --links 3..4 --prismatic 0 --format json");
  REQUIRE(range.exit_code == 0);
  CHECK_THAT(range.out, Catch::Contains("\"mzc-crank-rocker\""));
  CHECK(range.out.find("proportional-linkage") == std::string::npos);
  CHECK(test::RunKoppel("catalog find --links six").exit_code == 2);
  CHECK(test::RunKoppel("catalog find --kind other").exit_code == 2);
  const test::RunResult list = test::RunKoppel("catalog list");
  CHECK_THAT(list.out, Catch::Contains("slider-crank-offset") && Catch::Contains("mzc-crank-rocker"));
  const test::RunResult show = test::RunKoppel("catalog show proportional-linkage");
  REQUIRE(show.exit_code == 0);
  CHECK_THAT(show.out, Catch::Contains("S34: S slot-block4") && Catch::Contains("4 binary, 2 ternary") &&
                           Catch::Contains("Waagrechtstoßmaschine"));
  const test::RunResult missing = test::RunKoppel("catalog show nothing-like-this");
  CHECK(missing.exit_code == 2);
  CHECK_THAT(missing.err, Catch::Contains("no catalog entry"));
}

}  // namespace koppel
