// `--format json` on the commands issue 22 (item 8) found without it: synth motion, synth path,
// atlas build and atlas merge. Each JSON output is checked against the CSV of the same run (the
// reference: the same numbers, cell for cell, at CSV's 12 digits) and carries koppel's version;
// --format outside csv|json exits 2.
#include "support/run.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace koppel::format_json_test {
namespace {

std::string Digits12(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.12g", v);
  return text;
}

// The JSON table {"columns", "rows", "version"} holds what the CSV holds: the header as columns,
// every number equal at CSV's %.12g, every word equal, an empty CSV cell as null.
void CheckSameTable(const std::string& csv, const std::string& json_text) {
  const nlohmann::json j = nlohmann::json::parse(json_text);
  CHECK(j.at("version").is_string());
  const std::vector<std::vector<std::string>> cells = test::CsvCells(csv);
  REQUIRE(!cells.empty());
  CHECK(j.at("columns").get<std::vector<std::string>>() == cells[0]);
  REQUIRE(j.at("rows").size() == cells.size() - 1);
  REQUIRE(j.at("rows").size() > 0);
  for (size_t r = 0; r < j.at("rows").size(); ++r) {
    const nlohmann::json& row = j.at("rows")[r];
    REQUIRE(row.size() == cells[r + 1].size());
    for (size_t c = 0; c < row.size(); ++c) {
      const std::string& expected = cells[r + 1][c];
      INFO("row " << r + 1 << ", column " << cells[0][c]);
      if (row[c].is_null()) {
        CHECK(expected.empty());
      } else if (row[c].is_string()) {
        CHECK(row[c].get<std::string>() == expected);
      } else {
        const double v = row[c].get<double>();
        CHECK(Digits12(v) == Digits12(std::stod(expected)));
      }
    }
  }
}

}  // namespace

TEST_CASE("synth motion --format json holds the CSV's table (issue 22, item 8)", "[cli][motion][json]") {
  const std::string five = test::TestDataPath("motion-five-poses.yaml");
  const test::RunResult csv = test::RunKoppel("synth motion " + five);
  const test::RunResult json = test::RunKoppel("synth motion " + five + " --format json");
  INFO(json.err);
  REQUIRE(csv.exit_code == 0);
  REQUIRE(json.exit_code == 0);  // was 2: "The following arguments were not expected: json --format"
  CheckSameTable(csv.out, json.out);
  CHECK(nlohmann::json::parse(json.out).at("rows")[0][8].is_string());  // grashof
  CHECK(test::RunKoppel("synth motion " + five + " --format xml").exit_code == 2);
}

TEST_CASE("atlas build, atlas merge and synth path take --format json (issue 22, item 8)", "[cli][atlas][path][json]") {
  test::TempDir dir;
  const std::string d = dir.path().string();
  const test::RunResult build = test::RunKoppel("atlas build --count 3000 --quiet --format json -o " + d + "/atlas.bin");
  INFO(build.err);
  REQUIRE(build.exit_code == 0);  // was 2
  const nlohmann::json summary = nlohmann::json::parse(build.out);
  CHECK(summary.at("version").is_string());
  CHECK(summary.at("curves").at("value") == 3000);
  CHECK(summary.at("closed").at("value").get<double>() + summary.at("rocker_arcs").at("value").get<double>() == 3000);
  CHECK(summary.at("seconds").at("unit") == "s");
  // without --format the atlas goes to its file and stdout stays empty, as before
  CHECK(test::RunKoppel("atlas build --count 10 --quiet -o " + d + "/small.bin").out.empty());
  const test::RunResult csv_build = test::RunKoppel("atlas build --count 10 --seed 2 --quiet --format csv -o " + d + "/other.bin");
  REQUIRE(csv_build.exit_code == 0);
  CHECK(test::ParseSummary(csv_build.out).at("curves") == 10);
  CHECK(test::RunKoppel("atlas build --count 10 --format yaml -o " + d + "/never.bin").exit_code == 2);
  CHECK(!std::filesystem::exists(d + "/never.bin"));

  const test::RunResult merge = test::RunKoppel("atlas merge " + d + "/atlas.bin " + d + "/other.bin --quiet --format json -o " + d + "/merged.bin");
  INFO(merge.err);
  REQUIRE(merge.exit_code == 0);
  CHECK(nlohmann::json::parse(merge.out).at("curves").at("value") == 3010);

  const std::string path = "synth path " + test::TestDataPath("path-points.csv") + " --atlas " + d + "/atlas.bin --top 3";
  const test::RunResult csv = test::RunKoppel(path);
  const test::RunResult json = test::RunKoppel(path + " --format json");
  INFO(json.err);
  REQUIRE(csv.exit_code == 0);
  REQUIRE(json.exit_code == 0);  // was 2
  CheckSameTable(csv.out, json.out);
  CHECK(test::RunKoppel(path + " --format tsv").exit_code == 2);
}

}  // namespace koppel::format_json_test
