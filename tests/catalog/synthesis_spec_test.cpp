// The motion and function specification files (catalog/src/synthesis_spec.cpp): what they say,
// in radians inside, and every problem of a file at its line.
#include "koppel/catalog/synthesis_spec.hpp"

#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::synthesis_spec_test {
namespace {

// Degrees to radians and a formula through muparser: a few ulps.
constexpr double kRoundoff = 1e-12;

std::vector<Diagnostic> Problems(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.diagnostics();
  }
  return {};
}

TEST_CASE("poses are read in order, angles in radians", "[synthesis_spec]") {
  const MotionSpecFile s = ParseMotionSpecText("poses: [[0, 0, 0], [1.2, 0.4, 15], [2.1, 1.3, -40]]\n", "p.yaml");
  CHECK(s.path == "p.yaml");
  REQUIRE(s.poses.size() == 3);
  CHECK(s.poses[1].point == Eigen::Vector2d(1.2, 0.4));
  CHECK_THAT(s.poses[1].angle, Catch::Matchers::WithinAbs(15 * kPi / 180, kRoundoff));  // reference: 15 pi / 180
  CHECK_THAT(s.poses[2].angle, Catch::Matchers::WithinAbs(-40 * kPi / 180, kRoundoff));
}

TEST_CASE("a motion file's problems are all reported, each at its line", "[synthesis_spec]") {
  // line 2: not a triple; line 4: repeats pose 2 (360 deg is 0 deg) -- regression: the malformed
  // entry before it made the duplicate be reported at line 3, as poses[1], repeating "pose 1"
  const std::vector<Diagnostic> d = Problems([] {
    ParseMotionSpecText("poses:\n  - [0, 0]\n  - [0, 0, 0]\n  - [0, 0, 360]\n  - [1, 1, 1]\n", "p.yaml");
  });
  REQUIRE(d.size() == 2);
  CHECK(d[0].line == 2);
  CHECK_THAT(d[0].message, Catch::Contains("expected [x, y, angle_deg]"));
  CHECK(d[1].line == 4);
  CHECK_THAT(d[1].message, Catch::Contains("repeats pose 2"));
  CHECK(d[1].path == "poses[2]");
  // six poses and an unknown key
  const std::vector<Diagnostic> e = Problems([] {
    ParseMotionSpecText("poses: [[0,0,0],[1,0,0],[2,0,0],[3,0,0],[4,0,0],[5,0,0]]\npose: 1\n", "p.yaml");
  });
  REQUIRE(e.size() == 2);
  bool count = false, key = false;
  for (const Diagnostic& x : e) {
    count = count || x.message.find("expected 2 to 5 poses, found 6") != std::string::npos;
    key = key || (x.line == 2 && x.message.find("pose") != std::string::npos);
  }
  CHECK(count);
  CHECK(key);
}

TEST_CASE("a function file maps degrees to radians and evaluates its formula", "[synthesis_spec]") {
  const FunctionSpecFile s = ParseFunctionSpecText(
      "type: four-bar\nfunction: log10(x)\nx: [1, 10]\ninput: [15, 75]\noutput: [105, 195]\nat: [1.5, 5, 9]\nframe: 2\n", "f.yaml");
  const FunctionRequest& q = s.request;
  CHECK(q.type == FunctionGenerator::kFourBar);
  CHECK(q.x_from == 1);
  CHECK(q.x_to == 10);
  CHECK_THAT(q.input_from, Catch::Matchers::WithinAbs(DegToRad(15), kRoundoff));
  CHECK_THAT(q.output_to, Catch::Matchers::WithinAbs(DegToRad(195), kRoundoff));
  CHECK(q.at == std::vector<double>{1.5, 5, 9});
  CHECK(q.frame == 2);
  double y = 0;
  REQUIRE(q.function(5.0, &y));
  CHECK_THAT(y, Catch::Matchers::WithinAbs(std::log10(5.0), kRoundoff));  // reference: std::log10
  CHECK_FALSE(q.function(-1.0, &y));  // log10 of a negative: undefined, said so
}

TEST_CASE("a slider-crank's output is a length, not degrees", "[synthesis_spec]") {
  const FunctionSpecFile s = ParseFunctionSpecText(
      "type: slider-crank\nfunction: x^2\nx: [0, 1]\ninput: [0, 90]\noutput: [1, 3]\npoints: 4\n", "f.yaml");
  CHECK(s.request.type == FunctionGenerator::kSliderCrank);
  CHECK(s.request.output_from == 1);
  CHECK(s.request.output_to == 3);
  CHECK(s.request.points == 4);
}

TEST_CASE("a function file's problems are all reported, each at its line", "[synthesis_spec]") {
  const std::vector<Diagnostic> d = Problems([] {
    ParseFunctionSpecText("type: three-bar\nfunction: sqrt(x)\nx: [-1, 1]\ninput: [0]\noutput: [0, 1]\nat: [0, 5, 0.5]\n", "f.yaml");
  });
  // line 1 the type; line 4 the range; line 6 the point 5 outside x (the x range is read)
  auto at_line = [&d](int line, const char* phrase) {
    for (const Diagnostic& x : d)
      if (x.line == line && x.message.find(phrase) != std::string::npos) return true;
    return false;
  };
  CHECK(at_line(1, "expected four-bar or slider-crank, found 'three-bar'"));
  CHECK(at_line(4, "expected [from, to]"));
  CHECK_FALSE(d.empty());
  const std::vector<Diagnostic> e = Problems([] {
    ParseFunctionSpecText("function: sqrt(x)\nx: [-1, 1]\ninput: [0, 90]\noutput: [0, 90]\npoints: 3\nat: [0, 0.5, 1]\n", "f.yaml");
  });
  auto in_e = [&e](int line, const char* phrase) {
    for (const Diagnostic& x : e)
      if (x.line == line && x.message.find(phrase) != std::string::npos) return true;
    return false;
  };
  CHECK(in_e(6, "give points or at, not both"));
  CHECK(in_e(1, "cannot evaluate at x = -1"));  // sqrt(-1) at the range's end
}

TEST_CASE("an empty formula is reported once, at its line", "[synthesis_spec]") {
  // regression: a formula of blanks was reported twice, the second time as "cannot evaluate at x = 1"
  const std::vector<Diagnostic> d = Problems([] {
    ParseFunctionSpecText("x: [1, 2]\nfunction: '  '\ninput: [0, 90]\noutput: [0, 90]\n", "f.yaml");
  });
  std::string all;
  for (const Diagnostic& x : d) all += x.ToString() + "\n";
  INFO(all);
  REQUIRE(d.size() == 1);
  CHECK(d[0].line == 2);
  CHECK_THAT(d[0].message, Catch::Contains("found an empty text"));
}

}  // namespace
}  // namespace koppel::synthesis_spec_test
