// Every file in tests/data/bad/ through `koppel analyze`, as a user would meet it: the exit code,
// a fragment of the message and, where one line of the file is at fault, that line
// (file:LINE: on stderr), as listed in tests/data/bad/expected.tsv. A crash, a hang (the test's
// timeout) or an unlisted file fails.
#include "support/run.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace koppel::bad_input_test {
namespace {

struct Expectation {
  std::string file;
  int exit_code = 0;
  std::string line;  // "-" when no one line is at fault
  std::string fragment;
};

std::vector<Expectation> ReadExpectations(const std::string& path) {
  std::vector<Expectation> all;
  std::ifstream in(path);
  for (std::string row; std::getline(in, row);) {
    if (row.empty() || row[0] == '#') continue;
    std::istringstream cells(row);
    Expectation e;
    std::string code;
    std::getline(cells, e.file, '\t');
    std::getline(cells, code, '\t');
    std::getline(cells, e.line, '\t');
    std::getline(cells, e.fragment);
    e.exit_code = std::stoi(code);
    all.push_back(e);
  }
  return all;
}

}  // namespace

TEST_CASE("every bad input exits with its code, message and line", "[cli][bad]") {
  const std::string folder = std::string(KOPPEL_TEST_DATA_DIR) + "/bad";
  const std::vector<Expectation> expected = ReadExpectations(folder + "/expected.tsv");
  REQUIRE(expected.size() >= 15);
  std::set<std::string> listed;
  for (const Expectation& e : expected) {
    listed.insert(e.file);
    const std::string path = folder + "/" + e.file;
    const test::RunResult r = test::RunKoppel("analyze '" + path + "' --step 90");
    INFO(e.file << "\n" << r.err);
    CHECK(r.exit_code == e.exit_code);
    CHECK_THAT(r.err, Catch::Contains(e.fragment));
    if (e.line != "-") {
      CHECK_THAT(r.err, Catch::Contains(e.file + ":" + e.line + ":"));
    }
    CHECK(r.out.find("internal error") == std::string::npos);
    CHECK(r.err.find("internal error") == std::string::npos);
    // the messages go to a terminal: no control character but the line ends (a name's ESC is
    // shown as \x1B, never sent)
    CHECK(std::none_of(r.err.begin(), r.err.end(), [](char c) { return (static_cast<unsigned char>(c) < 0x20 && c != '\n') || c == '\x7f'; }));
  }
  // a file added to the folder without its expectation is a test nobody runs
  for (const auto& item : std::filesystem::directory_iterator(folder)) {
    if (item.path().filename() == "expected.tsv") continue;
    INFO(item.path().filename().string());
    CHECK(listed.count(item.path().filename().string()) == 1);
  }
}

}  // namespace koppel::bad_input_test
