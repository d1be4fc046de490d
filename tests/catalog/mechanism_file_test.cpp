// The mechanism file reader: a good file in all its parts, and every kind of bad input with the
// line of the problem and a key phrase of its message (never a crash, never a silent default).
#include "koppel/catalog/mechanism_file.hpp"

#include "koppel/core/angles.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

#include <cmath>

namespace koppel::mechanism_file_test {
namespace {

// relative: formulas and degree conversions of the file against the same in C++: a few ulps
constexpr double kUlps = 1e-15;

using test::LineOf;
using test::Replace;

const char* kGood = R"(koppel: 1
name: four-bar
parameters:
  l1: 1
  l2: 5/2*sqrt(3)
  kappa: acos(5/9*sqrt(3))
links:
  frame:
    frame: true
    points: {A0: [0, 0], B0: [4, 0], F: [0, -1]}
  crank:
    points: {A0: [0, 0], A: [l1, 0]}
  coupler:
    points: {A: [0, 0], B: [l2, 0], K: [l2*cos(kappa), l2*sin(kappa)]}
  rocker:
    points: {B0: [0, 0], B: [l2, 0]}
  slider:
    points: {K: [0, 0]}
joints:
  A0: {type: R, links: [frame, crank]}
  A: {type: D, links: [crank, coupler]}
  B: {type: revolute, links: [coupler, rocker]}
  B0: {type: R, links: [frame, rocker]}
drive: {joint: A0, zero: 90}
outputs:
  K: {point: coupler.K}
  psi: {link: rocker, zero: 10}
  d: {distance: [frame.B0, coupler.K]}
  mu: {transmission: {coupler: coupler, joint: B}}
assembly:
  input: 30
  points: {B: [1.5, 3.5], crank.A: [1, 0]}
sweep: {from: 10, to: 20, step: 0.5}
)";

// Parses `text` expecting failure; returns the diagnostics.
std::vector<Diagnostic> Bad(const std::string& text, const Overrides& overrides = {}) {
  try {
    ParseMechanismText(text, "mech.yaml", overrides);
  } catch (const InputError& e) {
    return e.diagnostics();
  }
  FAIL("the reader accepted:\n" << text);
  return {};
}

// The first diagnostic must sit on the line of `needle` and say `phrase`.
void ExpectError(const std::string& text, const std::string& needle, const std::string& phrase) {
  const std::vector<Diagnostic> d = Bad(text);
  REQUIRE_FALSE(d.empty());
  INFO(d[0].ToString());
  CHECK(d[0].file == "mech.yaml");
  CHECK(d[0].line == LineOf(text, needle));
  CHECK_THAT(d[0].message, Catch::Contains(phrase));
}

}  // namespace

TEST_CASE("a good mechanism file is read in all its parts", "[reader]") {
  const MechanismFile f = ParseMechanismText(kGood, "mech.yaml");
  const Mechanism& m = f.mechanism;
  CHECK(f.id == "four-bar");
  REQUIRE(m.links.size() == 5);
  CHECK(m.FrameLink() == 0);
  REQUIRE(m.joints.size() == 4);
  CHECK(m.joints[1].type == JointType::kRevolute);  // "D"
  CHECK(m.joints[2].type == JointType::kRevolute);  // "revolute"
  // a formula-valued coordinate, evaluated exactly: 5/2 sqrt(3)
  CHECK(m.links[2].points[1].local.x() == Approx(2.5 * std::sqrt(3.0)).epsilon(kUlps));
  CHECK(m.drive.zero == Approx(kPi / 2).epsilon(kUlps));  // degrees in YAML, radians inside
  CHECK(m.drive.input_name == "phi");
  REQUIRE(m.outputs.size() == 4);
  CHECK(m.outputs[1].offset == Approx(DegToRad(10)).epsilon(kUlps));
  CHECK(m.outputs[3].kind == OutputKind::kTransmissionAngle);
  CHECK(m.hint.input == Approx(DegToRad(30)).epsilon(kUlps));
  // bare "B" expands to the coupler's and the rocker's B; crank.A to one point
  CHECK(m.hint.points.size() == 3);
  CHECK(f.sweep.from == 10);
  CHECK(f.sweep.step == 0.5);
  CHECK_FALSE(f.card.has_value());
}

TEST_CASE("P joints: axis normalised, angle in degrees, slide drive in lengths", "[reader]") {
  const std::string text = R"(name: slider
links:
  frame: {frame: true, points: {O: [0, 0]}}
  block: {points: {P: [0, 0]}}
joints:
  S: {type: P, links: [frame, block], points: [O, P], axis: [3, 4], angle: 90}
drive: {joint: S, zero: 2}
)";
  const MechanismFile f = ParseMechanismText(text, "mech.yaml");
  const Joint& s = f.mechanism.joints[0];
  CHECK(s.type == JointType::kPrismatic);
  CHECK(s.axis.x() == Approx(0.6));
  CHECK(s.axis.y() == Approx(0.8));
  CHECK(s.angle == Approx(kPi / 2));
  CHECK(f.mechanism.drive.zero == 2.0);  // a length: not converted
  CHECK(f.mechanism.drive.input_name == "s_in");
}

TEST_CASE("a P joint without its axis is an error at its line (issue 22, item 14)", "[reader]") {
  // it was read as [1, 0] without a word
  const std::string text = R"(name: slider
links:
  frame: {frame: true, points: {O: [0, 0]}}
  block: {points: {P: [0, 0]}}
joints:
  S: {type: P, links: [frame, block], points: [O, P]}
drive: {joint: S}
)";
  ExpectError(text, "S: {type: P", "a P joint needs its slide axis");
  CHECK(Bad(text).at(0).path == "joints.S.axis");
  CHECK_THAT(Bad(text).at(0).ToString(), Catch::StartsWith("mech.yaml:6:"));
}

TEST_CASE("--set overrides a parameter and what depends on it", "[reader]") {
  const MechanismFile f = ParseMechanismText(kGood, "mech.yaml", {{"l2", "5"}});
  CHECK(f.parameters.Value("l2") == 5.0);
  CHECK(f.mechanism.links[2].points[1].local.x() == 5.0);  // coupler B = [l2, 0]
  const std::vector<Diagnostic> d = Bad(kGood, {{"l9", "1"}});
  CHECK_THAT(d.at(0).message, Catch::Contains("'l9' is not a parameter"));
  CHECK_THROWS_AS(ParseAssignment("l2"), InputError);
  CHECK(ParseAssignment("e=0.8").second == "0.8");
}

TEST_CASE("every formula of the model part is kept with its key path (the editor page's)", "[reader]") {
  const MechanismFile f = ParseMechanismText(kGood, "mech.yaml", {{"l2", "5"}});
  const auto has = [&](const std::string& path, const std::string& formula) {
    return std::find(f.formulas.begin(), f.formulas.end(), std::make_pair(path, formula)) != f.formulas.end();
  };
  CHECK(has("parameters.l1", "1"));
  CHECK(has("parameters.l2", "5"));  // the override, as it was evaluated
  CHECK(has("links.coupler.points.K[0]", "l2*cos(kappa)"));
  CHECK(has("links.frame.points.B0[0]", "4"));
  // in reading order: the parameters first
  CHECK(f.formulas.front().first == "parameters.l1");
}

TEST_CASE("bad input: each problem with its line and a clear message", "[reader]") {
  SECTION("unknown joint type") { ExpectError(Replace(kGood, "{type: R, links: [frame, rocker]}", "{type: Q, links: [frame, rocker]}"), "type: Q", "unknown type 'Q' (expected R or P"); }
  SECTION("a joint naming a missing link") { ExpectError(Replace(kGood, "links: [coupler, rocker]", "links: [coupler, crank2]"), "crank2", "names unknown link 'crank2'"); }
  SECTION("a joint point the link does not have") {
    ExpectError(Replace(kGood, "B0: {type: R, links: [frame, rocker]}", "B0: {type: R, links: [frame, rocker], points: [B0, X]}"), "points: [B0, X]", "has no point 'X'");
  }
  SECTION("a formula that does not parse") { ExpectError(Replace(kGood, "l2: 5/2*sqrt(3)", "l2: 5/2*sqrt(3"), "l2: 5/2", "does not parse"); }
  SECTION("a formula naming an unknown parameter") { ExpectError(Replace(kGood, "A: [l1, 0]", "A: [l7, 0]"), "l7", "l7"); }
  SECTION("a point that is not [x, y]") { ExpectError(Replace(kGood, "F: [0, -1]", "F: [0, -1, 2]"), "F: [0, -1, 2]", "expected a point [x, y]"); }
  SECTION("an unknown key, with a suggestion") { ExpectError(Replace(kGood, "joints:", "jionts:"), "jionts", "did you mean 'joints'"); }
  SECTION("a nested unknown key") { ExpectError(Replace(kGood, "drive: {joint: A0, zero: 90}", "drive: {joint: A0, zeroo: 90}"), "zeroo", "unknown key 'zeroo'"); }
  SECTION("no frame link") { ExpectError(Replace(kGood, "    frame: true\n", ""), "  frame:\n", "no link has 'frame: true'"); }
  SECTION("two frame links") { ExpectError(Replace(kGood, "  crank:\n", "  crank:\n    frame: true\n"), "  crank:", "a second frame link"); }
  SECTION("a drive naming a missing joint") { ExpectError(Replace(kGood, "joint: A0, zero", "joint: A9, zero"), "A9", "unknown joint 'A9'"); }
  SECTION("an output naming a missing point") { ExpectError(Replace(kGood, "point: coupler.K", "point: coupler.Q"), "coupler.Q", "has no point 'Q'"); }
  SECTION("a duplicate key") { ExpectError(Replace(kGood, "  l1: 1\n", "  l1: 1\n  l1: 2\n"), "l1: 2", "duplicate key 'l1'"); }
  SECTION("a zero slide axis") {
    const std::string text = "name: s\nlinks:\n  f: {frame: true, points: {O: [0, 0]}}\n  b: {points: {O: [0, 0]}}\njoints:\n  S: {type: P, links: [f, b], points: [O, O], axis: [0, 0]}\ndrive: {joint: S}\n";
    ExpectError(text, "axis", "must not be zero");
  }
  SECTION("a scalar where a map is expected") { ExpectError(Replace(kGood, "  rocker:\n    points: {B0: [0, 0], B: [l2, 0]}", "  rocker: 7"), "rocker: 7", "expected a map"); }
  SECTION("a transmission angle without a binary coupler") {
    ExpectError(Replace(kGood, "transmission: {coupler: coupler, joint: B}", "transmission: {coupler: crank, joint: A}"), "transmission: {coupler: crank", "must turn about or slide on the frame");
  }
  SECTION("a YAML syntax error") {
    // yaml-cpp notices the unclosed flow sequence where the next line starts: the mark is there
    const std::string text = Replace(kGood, "  A0: {type: R, links: [frame, crank]}", "  A0: {type: R, links: [frame, crank");
    const std::vector<Diagnostic> d = Bad(text);
    CHECK(d.at(0).line == LineOf(text, "  A: {type: D"));
    CHECK_THAT(d.at(0).message, Catch::Contains("YAML syntax error"));
  }
}

TEST_CASE("every name the file gives must be printable: refused at its line and column", "[reader]") {
  // YAML's escape \e is ESC (U+001B), \a BEL; each name kind of the file, one at a time
  struct Case {
    std::string from, to, needle, what;
  };
  for (const Case& c : {Case{"  crank:\n", "  \"crank\\e\":\n", "crank\\e", "link"},
                        Case{"B: [l2, 0], K:", "B: [l2, 0], \"K\\a\":", "K\\a", "point"},
                        Case{"  B0: {type: R", "  \"B0\\e\": {type: R", "B0\\e", "joint"},
                        Case{"  psi: {link", "  \"psi\\e\": {link", "psi\\e", "output"},
                        Case{"drive: {joint: A0, zero: 90}", "drive: {joint: A0, zero: 90, name: \"phi\\e\"}", "phi\\e", "drive's input"},
                        Case{"  l1: 1\n", "  l1: 1\n  \"l9\\e\": 2\n", "l9\\e", "parameter"}}) {
    const std::string text = Replace(kGood, c.from, c.to);
    const std::vector<Diagnostic> d = Bad(text);
    REQUIRE_FALSE(d.empty());
    INFO(d[0].ToString());
    CHECK(d[0].line == LineOf(text, c.needle));
    // the column of the name's opening quote (1-based)
    const size_t line_start = text.rfind('\n', text.find(c.needle)) + 1;
    CHECK(d[0].column == static_cast<int>(text.find(c.needle) - line_start));
    CHECK_THAT(d[0].message, Catch::StartsWith("the " + c.what + " name '"));
    CHECK_THAT(d[0].message, Catch::Contains("a name must be printable UTF-8 text"));
  }
  // and at most kMaxNameBytes (128) long
  const std::string text = Replace(kGood, "  psi: {link", "  " + std::string(129, 'p') + ": {link");
  CHECK_THAT(Bad(text).at(0).message, Catch::Contains("more than the limit of 128 (kMaxNameBytes)"));
  CHECK(Bad(text).at(0).line == LineOf(text, std::string(129, 'p')));
}

TEST_CASE("all problems of a file are reported at once", "[reader]") {
  std::string text = Replace(kGood, "links: [coupler, rocker]", "links: [coupler, crank2]");
  text = Replace(text, "point: coupler.K", "point: coupler.Q");
  const std::vector<Diagnostic> d = Bad(text);
  CHECK(d.size() >= 2);
  CHECK_THAT(d.at(0).ToString(), Catch::StartsWith("mech.yaml:" + std::to_string(LineOf(text, "crank2")) + ":"));
}

TEST_CASE("a file that does not exist", "[reader]") {
  try {
    ReadMechanismFile("/nonexistent/koppel.yaml");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK_THAT(e.diagnostics().at(0).ToString(), Catch::Contains("cannot open file"));
  }
}

TEST_CASE("random garbage never crashes the reader", "[reader]") {
  // fixed inputs that exercise wrong node types everywhere
  for (const std::string text : {"", "[]", "name: x\nlinks: []\njoints: 3\ndrive: [1]\n", "name: x\nlinks: {a: {points: {P: [a, b]}}}\n",
                                 "name: {a: 1}\noutputs: {o: {joint: [1]}}\n", "\t\t:::", "name: x\nparameters: {1x: 2}\n"}) {
    INFO(text);
    CHECK_THROWS_AS(ParseMechanismText(text, "mech.yaml"), InputError);
  }
}

// A decimal comma inside a flow map ({l2: 130,5, e: 15}) makes "5" a key of its own: the error
// on that line says what was meant.
TEST_CASE("a decimal comma in a flow map of parameters gets the hint", "[reader]") {
  const std::string text = "koppel: 1\nname: slider\nparameters: {l1: 40, l2: 130,5, e: 15}\n";
  const std::vector<Diagnostic> d = Bad(text);
  REQUIRE_FALSE(d.empty());
  CHECK(d[0].line == 3);
  CHECK_THAT(d[0].message, Catch::Contains("'5' cannot be a parameter name") && Catch::Contains("a decimal comma? write 130.5"));
}
}  // namespace koppel::mechanism_file_test
