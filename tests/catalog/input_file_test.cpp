// Reading input files within the limits (catalog/src/input_file.cpp, core/limits.hpp): a
// runaway file (/dev/zero), a FIFO, a directory, a deep YAML nesting and too many parameters each
// end in one InputError that names the limit; a generated file with 20 000 parameters is read
// with work linear in them.
#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/core/limits.hpp"
#include "input_file.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <fcntl.h>
#include <functional>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace koppel::input_file_test {
namespace {

// relative: a chain of 20 000 parameters each adding 1e-5 to the last: the rounding of 20 000 sums
constexpr double kSumRoundoff = 1e-12;

// A four-bar whose crank length is the last of `count` chained parameters p0..p{count-1}.
std::string ManyParameters(int count) {
  std::string text = "name: many\nparameters:\n  p0: 0\n";
  for (int i = 1; i < count; ++i) text += "  p" + std::to_string(i) + ": p" + std::to_string(i - 1) + " + 1e-5\n";
  text += "  l1: 0.8 + p" + std::to_string(count - 1) + "*0\n";
  text += R"(links:
  frame: {frame: true, points: {A0: [0, 0], B0: [3, 0]}}
  crank: {points: {A0: [0, 0], A: [l1, 0]}}
  coupler: {points: {A: [0, 0], B: [3, 0]}}
  rocker: {points: {B0: [0, 0], B: [0, 2.5]}}
joints:
  A0: {type: R, links: [frame, crank]}
  A: {type: R, links: [crank, coupler]}
  B: {type: R, links: [coupler, rocker]}
  B0: {type: R, links: [rocker, frame]}
drive: {joint: A0}
assembly: {input: 0, points: {B: [2, 2]}}
)";
  return text;
}

std::string FirstMessage(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.diagnostics().at(0).ToString();
  }
  return "no error";
}

}  // namespace

TEST_CASE("a runaway input stops at kMaxInputBytes", "[reader][limits]") {
  const std::string message = FirstMessage([] { ReadMechanismFile("/dev/zero"); });
  CHECK_THAT(message, Catch::Contains("/dev/zero") && Catch::Contains("kMaxInputBytes"));
  test::TempDir dir;
  const std::string big = dir.Write("big.yaml", "# " + std::string(kMaxInputBytes, 'x') + "\n");
  CHECK_THAT(FirstMessage([&] { ReadMechanismFile(big); }), Catch::Contains("larger than the input limit"));
}

TEST_CASE("a directory is not read as a file", "[reader]") {
  test::TempDir dir;
  CHECK_THAT(FirstMessage([&] { ReadMechanismFile(dir.path().string()); }), Catch::Contains("is a directory"));
}

TEST_CASE("a FIFO is read from its writer, and one without a writer does not hang", "[reader]") {
  test::TempDir dir;
  const std::string fifo = (dir.path() / "mech.fifo").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // no writer: read as an empty file at once
  CHECK_THAT(FirstMessage([&] { ReadMechanismFile(fifo); }), Catch::Contains("found nothing"));
  // a writer waiting in open(2) is there when the reader opens: the whole text arrives
  const std::string text = ManyParameters(3);
  std::thread writer([&] {
    const int fd = ::open(fifo.c_str(), O_WRONLY);
    if (fd >= 0) {
      (void)!::write(fd, text.data(), text.size());
      ::close(fd);
    }
  });
  ::usleep(100'000);  // let the writer reach open(2)
  const MechanismFile file = ReadMechanismFile(fifo);
  writer.join();
  CHECK(file.mechanism.links.size() == 4);
}

TEST_CASE("YAML deeper than kMaxYamlDepth is refused at its line", "[reader][limits]") {
  const std::string deep = "name: x\nparameters:\n  a: " + std::string(200, '[') + std::string(200, ']') + "\n";
  try {
    ParseMechanismText(deep, "deep.yaml");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.diagnostics().at(0).line == 3);
    CHECK_THAT(e.diagnostics().at(0).message, Catch::Contains("kMaxYamlDepth"));
  }
  // as deep as the limit allows is fine for the parser (the reader then says what it expected)
  const std::string ok = "name: x\nparameters:\n  a: " + std::string(kMaxYamlDepth - 2, '[') + std::string(kMaxYamlDepth - 2, ']') + "\n";
  CHECK_THAT(FirstMessage([&] { ParseMechanismText(ok, "ok.yaml"); }), !Catch::Contains("kMaxYamlDepth"));
}

// The nesting depth of a parsed tree, counted on the tree (the reference for YamlNestingBound).
int TreeDepth(const YAML::Node& node) {
  if (!node.IsMap() && !node.IsSequence()) return 0;
  int deepest = 0;
  for (const auto& item : node) {
    if (node.IsMap()) {
      deepest = std::max({deepest, TreeDepth(item.first), TreeDepth(item.second)});
    } else {
      deepest = std::max(deepest, TreeDepth(item));
    }
  }
  return deepest + 1;
}

TEST_CASE("the nesting bound from the characters is never below the parsed tree's depth", "[reader][limits]") {
  const std::vector<std::string> texts = {
      "a:\n  b:\n    c: 1\n",
      "- - - - x\n",
      "a:\n- b:\n  - c: [[1], {d: [2]}]\n",
      "- &x a: 1\n- *x\n",
      "? - a\n  - b\n: - c\n",
      "a: {b: {c: {d: 1}}}\nz:\n  - - y\n",
      "x:\n  y:\n  - z:\n      w: \"[ not a list\"\n",
  };
  for (const std::string& text : texts) {
    INFO(text);
    CHECK(YamlNestingBound(text) >= TreeDepth(YAML::Load(text)));
  }
  // the catalog's crank-rocker (the start-up benchmark's file) skips the counting pass
  CHECK(YamlNestingBound(test::ReadText(test::CatalogEntryPath("crank-rocker"))) <= kMaxYamlDepth);
}

TEST_CASE("maps nested by indentation deeper than kMaxYamlDepth are refused at their line", "[reader][limits]") {
  std::string deep = "name: x\nparameters:\n";
  for (int level = 0; level < kMaxYamlDepth + 5; ++level) deep += std::string(2 * level + 2, ' ') + "k" + std::to_string(level) + ":\n";
  REQUIRE(TreeDepth(YAML::Load(deep)) > kMaxYamlDepth);
  try {
    ParseMechanismText(deep, "deep.yaml");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.diagnostics().at(0).line == kMaxYamlDepth + 2);  // the map of depth kMaxYamlDepth + 1: keys of line 2 + 64
    CHECK_THAT(e.diagnostics().at(0).message, Catch::Contains("kMaxYamlDepth"));
  }
}

TEST_CASE("20 000 parameters are read with work linear in them", "[reader][limits]") {
  constexpr int kCount = 20'000;
  const std::string text = ManyParameters(kCount);
  const long long before = ParameterSet::ParameterReads();
  const MechanismFile file = ParseMechanismText(text, "many.yaml");
  const long long reads = ParameterSet::ParameterReads() - before;
  // one read per chained formula, plus the few names the links use; quadratic would be 2e8
  CHECK(reads >= kCount);
  CHECK(reads < kCount + 100);
  CHECK(file.parameters.Value("p19999") == Approx(19'999 * 1e-5).epsilon(kSumRoundoff));
  CHECK(file.mechanism.links[1].points[1].local.x() == Approx(0.8));
}

TEST_CASE("more than kMaxParameters parameters are refused before they are evaluated", "[reader][limits]") {
  std::string text = "name: x\nparameters:\n";
  for (size_t i = 0; i <= kMaxParameters; ++i) text += "  p" + std::to_string(i) + ": 1\n";
  const long long before = ParameterSet::ParameterReads();
  const std::string message = FirstMessage([&] { ParseMechanismText(text, "many.yaml"); });
  CHECK_THAT(message, Catch::Contains("kMaxParameters") && Catch::Contains("many.yaml:3:"));
  CHECK(ParameterSet::ParameterReads() == before);
}

}  // namespace koppel::input_file_test
