// The file's length unit in every table that labels lengths (issue 22, item 14): a file with
// `units: {length: mm}` was reported in "length"; now in "mm", the name the file gives. The
// reference is the file itself; a file that names no unit keeps the neutral "length".
#include "support/run.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

namespace koppel::length_unit_test {

TEST_CASE("tables label lengths with the file's unit (issue 22, item 14)", "[cli][units]") {
  test::TempDir dir;
  const std::string text = test::ReadText(test::CatalogEntryPath("slider-crank-offset"));
  const std::string mm = dir.Write("mm.yaml", text + "units: {length: mm}\n");
  const test::RunResult json = test::RunKoppel("analyze " + mm + " --step 90 --format json");
  INFO(json.err);
  REQUIRE(json.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(json.out);
  const std::vector<std::string> columns = j.at("columns"), units = j.at("units");
  REQUIRE(columns.size() == units.size());
  for (size_t c = 0; c < columns.size(); ++c) {
    INFO(columns[c]);
    if (columns[c] == "s") CHECK(units[c] == "mm");
    if (columns[c] == "s_d1") CHECK(units[c] == "mm/rad");
    CHECK(units[c].find("length") == std::string::npos);
  }
  const test::RunResult summary = test::RunKoppel("deadcentres " + mm + " --output s --summary");
  REQUIRE(summary.exit_code == 0);
  CHECK_THAT(summary.out, Catch::Contains("\ns_H,") && Catch::Contains(",mm\n"));
  CHECK(summary.out.find("length") == std::string::npos);
  // no unit named: the neutral word, as before
  const test::RunResult plain = test::RunKoppel("deadcentres " + test::CatalogEntryPath("slider-crank-offset") + " --output s --summary");
  CHECK_THAT(plain.out, Catch::Contains(",length\n"));
}

}  // namespace koppel::length_unit_test
