// The design file of a synthesis (catalog/src/design_space_file.cpp): every key read, formulas
// evaluated, degrees to radians; a file read from disk equals its text parsed; every problem of a
// file reported at once, each at its line. References: the numbers written in the files below,
// worked by hand (sqrt(16) = 4, 2 * 2.5 = 5, 30 deg = pi/6, 45 deg = pi/4, pi/6 from M_PI); the
// line numbers of the lines this test writes (test::LineOf).
#include "koppel/catalog/design_space_file.hpp"

#include "koppel/catalog/mechanism_file.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace koppel::design_space_file_test {
namespace {

// degrees to radians (x pi / 180) against pi/6 and pi/4 computed here: a few ulps
constexpr double kRoundoff = 1e-15;

std::vector<Diagnostic> Problems(const std::string& text) {
  try {
    ParseDesignSpaceText(text, "design.yaml");
  } catch (const InputError& e) {
    return e.diagnostics();
  }
  return {};
}

const char* kEveryKey = R"(# every key, some as formulas
lengths: [0.5, 2*2.5]
ratio: sqrt(16)
pivots: {x: [-1, 5], y: [-1, 1]}
input: crank
A0: [0.5, -0.25]
frame_angle: 30
coupler_point: [-2, 2]
mu_min: 90/2
)";

}  // namespace

TEST_CASE("a design file with every key: intervals, formulas, degrees to radians", "[catalog][design-space-file]") {
  const DesignSpace s = ParseDesignSpaceText(kEveryKey, "design.yaml");
  REQUIRE(s.lengths);
  CHECK(*s.lengths == std::make_pair(0.5, 5.0));
  REQUIRE(s.ratio);
  CHECK(*s.ratio == 4.0);
  REQUIRE(s.pivots_x);
  CHECK(*s.pivots_x == std::make_pair(-1.0, 5.0));
  REQUIRE(s.pivots_y);
  CHECK(*s.pivots_y == std::make_pair(-1.0, 1.0));
  CHECK(s.input == InputTurn::kCrank);
  REQUIRE(s.a0);
  CHECK(*s.a0 == Eigen::Vector2d(0.5, -0.25));
  REQUIRE(s.frame_angle);
  CHECK_THAT(*s.frame_angle, Catch::Matchers::WithinAbs(M_PI / 6, kRoundoff));
  REQUIRE(s.coupler_point);
  CHECK(*s.coupler_point == std::make_pair(-2.0, 2.0));
  REQUIRE(s.mu_min);
  CHECK_THAT(*s.mu_min, Catch::Matchers::WithinAbs(M_PI / 4, kRoundoff));
  std::string why;
  CHECK(s.IsValid(&why));
  CHECK_FALSE(s.Empty());
}

TEST_CASE("keys left out stay open; input any is the default", "[catalog][design-space-file]") {
  const DesignSpace none = ParseDesignSpaceText("{}\n", "design.yaml");
  CHECK(none.Empty());
  const DesignSpace some = ParseDesignSpaceText("ratio: 2.5\ninput: any\n", "design.yaml");
  CHECK(some.ratio == 2.5);
  CHECK(some.input == InputTurn::kAny);
  CHECK_FALSE(some.lengths);
  CHECK_FALSE(some.pivots_x);
  CHECK_FALSE(some.a0);
  CHECK_FALSE(some.frame_angle);
  CHECK_FALSE(some.mu_min);
  // a degenerate interval is not empty: min = max holds one value
  CHECK(ParseDesignSpaceText("coupler_point: [1, 1]\n", "design.yaml").coupler_point == std::make_pair(1.0, 1.0));
}

TEST_CASE("a design file on disk reads as its text parses; tests/data's design files", "[catalog][design-space-file]") {
  const test::TempDir dir;
  const std::string path = dir.Write("every.yaml", kEveryKey);
  const DesignSpace disk = ReadDesignSpace(path), text = ParseDesignSpaceText(kEveryKey, path);
  CHECK(disk.lengths == text.lengths);
  CHECK(disk.ratio == text.ratio);
  CHECK(disk.a0 == text.a0);
  CHECK(disk.frame_angle == text.frame_angle);
  CHECK(disk.mu_min == text.mu_min);
  // fit-design.yaml, as its text says: lengths [0.5, 5], ratio 5, pivots x [-1, 5], y [-1, 1], crank, mu_min 40 deg
  const DesignSpace fit = ReadDesignSpace(test::TestDataPath("fit-design.yaml"));
  CHECK(fit.lengths == std::make_pair(0.5, 5.0));
  CHECK(fit.ratio == 5.0);
  CHECK(fit.pivots_x == std::make_pair(-1.0, 5.0));
  CHECK(fit.pivots_y == std::make_pair(-1.0, 1.0));
  CHECK(fit.input == InputTurn::kCrank);
  REQUIRE(fit.mu_min);
  CHECK_THAT(*fit.mu_min, Catch::Matchers::WithinAbs(40 * M_PI / 180, kRoundoff));
  CHECK_THROWS_AS(ReadDesignSpace((dir.path() / "missing.yaml").string()), InputError);
}

TEST_CASE("every problem of a design file is reported at once, each at its line", "[catalog][design-space-file]") {
  const std::string bad = "lenghts: [1, 2]\n"          // unknown key, near 'lengths'
                          "ratio: 0.5\n"               // below 1
                          "pivots: {x: [3, 1]}\n"      // empty interval
                          "input: half\n"              // neither crank nor any
                          "A0: [1]\n"                  // not [x, y]
                          "frame_angle: 1/0\n"         // not finite
                          "coupler_point: [0, k_unknown]\n"  // an unknown name in a formula
                          "mu_min: 90\n";              // not below 90 deg
  const std::vector<Diagnostic> d = Problems(bad);
  REQUIRE(d.size() == 8);
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"lenghts", "lengths"},          {"ratio", "at least 1"},         {"pivots", "min is above max"},
      {"input", "expected crank or any, found 'half'"}, {"A0", "expected [x, y]"}, {"frame_angle", "finite"},
      {"coupler_point", "k_unknown"},          {"mu_min", "below 90 deg"}};
  for (const auto& [key, phrase] : expected) {
    INFO(key << ": " << phrase);
    bool found = false;
    for (const Diagnostic& x : d) found = found || (x.line == test::LineOf(bad, key + ":") && x.message.find(phrase) != std::string::npos);
    CHECK(found);
  }
  for (const Diagnostic& x : d) CHECK(x.file == "design.yaml");
  // the largest length must be positive
  const std::vector<Diagnostic> negative = Problems("ratio: 2\nlengths: [-3, -1]\n");
  REQUIRE(negative.size() == 1);
  CHECK(negative[0].line == 2);
  CHECK_THAT(negative[0].message, Catch::Contains("largest length must be positive"));
  // a fixed A0 outside the pivots' box: a contradiction between keys, reported at the file
  const std::vector<Diagnostic> outside = Problems("pivots: {x: [0, 1]}\nA0: [2, 0]\n");
  REQUIRE(outside.size() == 1);
  CHECK_THAT(outside[0].message, Catch::Contains("A0 lies outside pivots.x"));
  CHECK_FALSE(Problems("[1, 2]\n").empty());  // a design file is a map
  // a negative smallest length: no link is negative, so the bound is a slip, not a constraint
  const std::vector<Diagnostic> below = Problems("lengths: [-5, 3]\n");
  REQUIRE(below.size() == 1);
  CHECK(below[0].line == 1);
  CHECK_THAT(below[0].message, Catch::Contains("smallest length cannot be negative"));
  // comments alone state no constraint: a --design that would change nothing is refused
  const std::vector<Diagnostic> empty = Problems("# nothing yet\n");
  REQUIRE(empty.size() == 1);
  CHECK_THAT(empty[0].message, Catch::Contains("states no constraint"));
}

}  // namespace koppel::design_space_file_test
