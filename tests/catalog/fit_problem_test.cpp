// The problem file of `koppel synth fit` (catalog/src/fit_problem.cpp): what it asks in internal
// units (degrees at the file, radians inside), a builder that changes only the free parameters,
// and every problem of the file at its line.
#include "koppel/catalog/fit_problem.hpp"

#include "koppel/core/angles.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

namespace koppel::fit_problem_test {
namespace {

// Degrees to radians of numbers read from text: a few ulps.
constexpr double kRoundoff = 1e-12;

// tests/data/fit-direction-fourbar.yaml: l1 1.8, l2 3.5, l3 3, l4 3; outputs dir (a direction),
// mu (a transmission angle); no point output.
const std::string kMechanism = std::string(KOPPEL_TEST_DATA_DIR) + "/fit-direction-fourbar.yaml";

std::vector<Diagnostic> Problems(const std::string& path) {
  try {
    ReadFitProblem(path);
  } catch (const InputError& e) {
    return e.diagnostics();
  }
  return {};
}

bool Has(const std::vector<Diagnostic>& d, int line, const std::string& phrase) {
  for (const Diagnostic& x : d)
    if (x.line == line && x.message.find(phrase) != std::string::npos) return true;
  return false;
}

TEST_CASE("a fit problem in the file's units becomes one in radians", "[fit_problem]") {
  test::TempDir dir;
  const std::string path = dir.Write("p.yaml", "mechanism: " + kMechanism + R"(
parameters:
  l3: {start: 4, lower: 3, upper: 6}
  l2:
starts: 3
require: {from: 10, to: 50}
tolerance: {length: 1e-4, angle: 0.01}
targets:
  - {output: dir, input: 90, value: 104.4, weight: 2, tolerance: 0.5}
  - {deadcentre: dir, input: 170, name: dc}
)");
  const FitProblem p = ReadFitProblem(path);
  CHECK(p.mechanism_path == kMechanism);
  REQUIRE(p.parameters.size() == 2);
  CHECK(p.parameters[0].name == "l3");
  CHECK(p.parameters[0].start == 4);
  CHECK(p.parameters[0].lower == 3);
  CHECK(p.parameters[0].upper == 6);
  CHECK(p.parameters[1].name == "l2");
  CHECK(p.parameters[1].start == 3.5);  // the file's value when not given
  CHECK(p.options.starts == 3);
  CHECK_THAT(p.options.require_from, Catch::Matchers::WithinAbs(DegToRad(10), kRoundoff));
  CHECK_THAT(p.options.require_to, Catch::Matchers::WithinAbs(DegToRad(50), kRoundoff));
  CHECK(p.options.length_tolerance == 1e-4);
  CHECK_THAT(p.options.angle_tolerance, Catch::Matchers::WithinAbs(DegToRad(0.01), kRoundoff));
  REQUIRE(p.targets.size() == 2);
  const FitTarget& t = p.targets[0];
  CHECK(t.output == p.base.mechanism.FindOutput("dir"));
  CHECK_THAT(t.input, Catch::Matchers::WithinAbs(DegToRad(90), kRoundoff));
  CHECK_THAT(t.value, Catch::Matchers::WithinAbs(DegToRad(104.4), kRoundoff));  // an angle output: degrees in the file
  CHECK_THAT(t.tolerance, Catch::Matchers::WithinAbs(DegToRad(0.5), kRoundoff));
  CHECK(t.weight == 2);
  CHECK(p.targets[1].deadcentre);
  CHECK(p.targets[1].name == "dc");
  // the builder changes l3 and l2 and nothing else (reference: the links' points in the file)
  const Expected<Mechanism> built = p.builder({4.5, 3.25});
  REQUIRE(built);
  const Mechanism& m = *built;
  const Link& rocker = m.links[m.FindLink("rocker")];
  const Link& coupler = m.links[m.FindLink("coupler")];
  const Link& crank = m.links[m.FindLink("crank")];
  CHECK(rocker.points[rocker.FindPoint("B")].local.x() == 4.5);
  CHECK(coupler.points[coupler.FindPoint("B")].local.x() == 3.25);
  CHECK(crank.points[crank.FindPoint("A")].local.x() == 1.8);
}

TEST_CASE("a fit problem's mistakes are all reported, each at its line", "[fit_problem]") {
  test::TempDir dir;
  const std::string path = dir.Write("p.yaml", "mechanism: " + kMechanism + R"(
parameters:
  l9: {start: 1}
  l3: {start: 7, lower: 3, upper: 6}
tolerance: -1
targets:
  - {output: psi, input: 90, value: 1}
  - {output: dir, input: 90, value: 1, weight: 0}
  - {point: mu, input: 0, at: [1, 2]}
  - {output: dir, value: 1}
)");
  const std::vector<Diagnostic> d = Problems(path);
  INFO(d.size());
  CHECK(Has(d, 3, "'l9' is not a parameter of"));
  CHECK(Has(d, 4, "needs lower <= start <= upper"));
  CHECK(Has(d, 5, "a tolerance must be positive"));
  CHECK(Has(d, 7, "names no output 'psi'"));
  CHECK(Has(d, 8, "a weight must not be 0"));
  CHECK(Has(d, 9, "'mu' is not a point output"));
  CHECK(Has(d, 10, "missing required key 'input'"));
  for (const Diagnostic& x : d) CHECK(x.file == path);
}

TEST_CASE("a broken mechanism file is reported under the problem's mechanism line", "[fit_problem]") {
  test::TempDir dir;
  dir.Write("m.yaml", "name: x\nlinks: 3\n");
  const std::string path = dir.Write("p.yaml", "targets: []\nmechanism: m.yaml\n");
  const std::vector<Diagnostic> d = Problems(path);
  REQUIRE(d.size() >= 2);
  CHECK(d[0].file == path);
  CHECK(d[0].line == 2);
  CHECK(d[0].message == "the mechanism file has problems:");
  CHECK(d[1].file == dir.Write("m.yaml", "name: x\nlinks: 3\n"));  // the mechanism's own, with its path
}

}  // namespace
}  // namespace koppel::fit_problem_test
