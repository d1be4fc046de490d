// Issue 23 items 10 and 12: a number that overflows is named (quantity, sample, cause) instead of
// "internal error: refusing to print a non-finite number", and every diagnostic names its place
// (file:line, or the flag). Each case is a repro of the issue; the reference is the input itself.
#include "support/run.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace koppel::diagnostic_place_test {
namespace {

std::string Loads() { return test::TestDataPath("slider-crank-loads.yaml"); }

// slider-crank-loads.yaml with `from` replaced by `to`.
std::string LoadsWith(const test::TempDir& dir, const std::string& from, const std::string& to) {
  std::string text = test::ReadText(Loads());
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  return dir.Write("loads.yaml", text);
}

int Lines(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

}  // namespace

TEST_CASE("a length unit that would overflow every force is refused at its line", "[cli][diagnostics]") {
  test::TempDir dir;
  const std::string file = LoadsWith(dir, "units: {length: mm}", "units: {length: 1e308}");
  const test::RunResult r = test::RunKoppel("forces " + file + " --step 90");
  INFO(r.err);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("loads.yaml:7:") && Catch::Contains("kMaxLengthUnit") && Catch::Contains("units.length"));
  CHECK_THAT(r.err, !Catch::Contains("internal error"));
}

TEST_CASE("a motor curve whose torque overflows ends the motion, named, not an internal error", "[cli][diagnostics]") {
  const test::RunResult r = test::RunKoppel("simulate " + Loads() + " --motor 0:-1e308,1:1e308 --t 0:0.1");
  INFO(r.err);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("is not a finite number") && Catch::Contains("at t = "));
  CHECK_THAT(r.err, !Catch::Contains("internal error"));
  CHECK(r.out.rfind("t,phi,speed", 0) == 0);
}

TEST_CASE("a --set that fails is reported once, at --set, without a cascade", "[cli][diagnostics]") {
  const test::RunResult r = test::RunKoppel("analyze " + Loads() + " --set e=1/0 --step 90");
  INFO(r.err);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("--set e") && Catch::Contains("formula '1/0' does not give a finite number"));
  // e names the frame's point A0 and the offset: neither is reported again
  CHECK(Lines(r.err) == 1);
}

TEST_CASE("a parameter that fails in the file is reported once, at its line", "[cli][diagnostics]") {
  test::TempDir dir;
  const std::string file = LoadsWith(dir, "  e: 10 ", "  e: 1/0 ");
  const test::RunResult r = test::RunKoppel("analyze " + file + " --step 90");
  INFO(r.err);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("loads.yaml:12:") && Catch::Contains("(parameters.e)"));
  CHECK(Lines(r.err) == 1);
}

TEST_CASE("outputs and points named on the command line, or missing, say where", "[cli][diagnostics]") {
  // A is on the crank and on the coupler
  const test::RunResult point = test::RunKoppel("curve " + Loads() + " --point A");
  CHECK(point.exit_code == 2);
  CHECK_THAT(point.err, Catch::Contains("--point A: ") && Catch::Contains("several links"));
  const test::RunResult output = test::RunKoppel("deadcentres " + Loads() + " --output nope");
  CHECK(output.exit_code == 2);
  CHECK_THAT(output.err, Catch::Contains("--output nope") && Catch::Contains("slider-crank-loads.yaml has no scalar output 'nope'") &&
                             Catch::Contains("its scalar outputs: s"));
  test::TempDir dir;
  const std::string no_scalar = LoadsWith(dir, "outputs:\n  s: {joint: S}", "outputs:\n  K: {point: coupler.S2}");
  const test::RunResult none = test::RunKoppel("deadcentres " + no_scalar);
  INFO(none.err);
  CHECK(none.exit_code == 2);
  CHECK_THAT(none.err, Catch::Contains("loads.yaml: the mechanism declares no scalar output"));
  const test::RunResult samples = test::RunKoppel("view " + Loads() + " --step 0.01 -o " + (dir.path() / "v.html").string());
  CHECK(samples.exit_code == 2);
  CHECK_THAT(samples.err, Catch::Contains("--step") && Catch::Contains("36001 samples, more than 3600"));
}

TEST_CASE("an empty function formula is reported at its line", "[cli][diagnostics]") {
  test::TempDir dir;
  const std::string spec = dir.Write("f.yaml", "type: four-bar\nfunction: ''\nx: [1, 2]\ninput: [0, 90]\noutput: [0, 90]\n");
  const test::RunResult r = test::RunKoppel("synth function " + spec);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("f.yaml:2:") && Catch::Contains("found an empty text"));
}

}  // namespace koppel::diagnostic_place_test
