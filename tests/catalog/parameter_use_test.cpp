// Which parameters a file reads, and the refusal of --set for one that no formula reads.
// Reference: the files below, read by eye.
#include "koppel/catalog/parameter_use.hpp"

#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

namespace koppel::parameter_use_test {
namespace {

const char* kFile =
    "koppel: 1\n"
    "name: rule\n"
    "parameters: {a: 1, b: 2*a, c: 3, unused: 4, by_unused: unused + 1}\n"
    "links:\n"
    "  frame: {frame: true, points: {A0: [0, 0], B0: [c, 0]}}\n"
    "  crank: {points: {A0: [0, 0], A: [b, 0]}}\n"
    "joints:\n"
    "  A0: {type: R, links: [frame, crank]}\n"
    "drive: {joint: A0}\n";

}  // namespace

TEST_CASE("ParametersRead follows the formulas through other parameters", "[catalog][parameter_use]") {
  const MechanismFile f = ParseMechanismText(kFile, "rule.yaml");
  CHECK(ParametersRead(f) == std::vector<std::string>{"a", "b", "c"});
}

TEST_CASE("a load's magnitude reads a parameter", "[catalog][parameter_use]") {
  const MechanismFile f = ReadMechanismFile(test::TestDataPath("slider-crank-loads.yaml"));
  CHECK(ParametersRead(f) == std::vector<std::string>{"l1", "l2", "e", "p"});
  CHECK_NOTHROW(ReadMechanismFile(test::TestDataPath("slider-crank-loads.yaml"), {{"p", "250"}}));
}

TEST_CASE("setting a parameter that no formula reads is refused, naming it and the ones read", "[catalog][parameter_use]") {
  CHECK_NOTHROW(ParseMechanismText(kFile, "rule.yaml", {{"a", "1.5"}}));
  try {
    ParseMechanismText(kFile, "rule.yaml", {{"unused", "5"}});
    FAIL("no error");
  } catch (const InputError& e) {
    REQUIRE(e.diagnostics().size() == 1);
    CHECK(e.diagnostics()[0].path == "--set unused");
    CHECK_THAT(e.diagnostics()[0].message, Catch::Contains("no formula of this file reads the parameter 'unused'") &&
                                               Catch::Contains("(the parameters read: a b c)"));
  }
  // read only by a parameter that nothing reads: not read either
  CHECK_THROWS_WITH(ParseMechanismText(kFile, "rule.yaml", {{"by_unused", "5"}}), Catch::Contains("'by_unused'"));
}

}  // namespace koppel::parameter_use_test

namespace koppel::parameter_use_test {

TEST_CASE("MeasureOf: a length, an angle, or neither, from where the value goes", "[catalog][parameter_use]") {
  const MechanismFile loads = ReadMechanismFile(test::TestDataPath("slider-crank-loads.yaml"));
  CHECK(MeasureOf(loads, "l1") == ParameterMeasure::kLength);  // A: [0, -l1]
  CHECK(MeasureOf(loads, "l2") == ParameterMeasure::kLength);  // B: [l2, 0], S2: [0.35*l2, 0]
  CHECK(MeasureOf(loads, "p") == ParameterMeasure::kUnknown);  // a force [N]
  const MechanismFile f = ParseMechanismText(
      "koppel: 1\nname: m\nparameters: {c: 2, gamma: 60, r: 2, w: 1/r, s: 30}\n"
      "links:\n  frame: {frame: true, points: {A0: [0, 0], B0: [c*cos(gamma*deg), c*sin(gamma*deg)], F: [0, w]}}\n"
      "  crank: {points: {A0: [0, 0], A: [c, 0]}}\n"
      "joints:\n  A0: {type: R, links: [frame, crank]}\n"
      "drive: {joint: A0}\noutputs: {phi1: {joint: A0, zero: s + 0}}\n",
      "m.yaml");
  CHECK(MeasureOf(f, "c") == ParameterMeasure::kLength);
  CHECK(MeasureOf(f, "gamma") == ParameterMeasure::kUnknown);  // inside cos( )
  CHECK(MeasureOf(f, "r") == ParameterMeasure::kUnknown);      // a divisor
  CHECK(MeasureOf(f, "s") == ParameterMeasure::kAngle);        // an output's zero [deg]
}

}  // namespace koppel::parameter_use_test
