// koppel::Model (tools/api/src/model.cpp): loading, parameters, poses and their transfer
// functions, against seed 000's closed form of the slider-crank (tests/support/closed_forms).
#include "koppel/api/model.hpp"
#include "koppel/api/workspace.hpp"
#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

using namespace koppel;
using Catch::Matchers::WithinAbs;

namespace model_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

// [deg] the pose's input is the one asked for, through degrees -> radians -> degrees
constexpr double kInputDeg = 1e-12;
// [deg] kClosedForm (1e-9 rad) shown in degrees (x 57.3), with margin
constexpr double kAngleDeg = 1e-7;
// s''' against a central difference of the closed-form s'' (h = 1e-5): truncation ~1e-10 and
// rounding ~1e-11 (see the test), plus the solver's own 1e-9-class error of a third derivative
constexpr double kThirdOrder = 1e-8;
// the written file has every number to 17 digits: the same mechanism, the same Newton path
constexpr double kWrittenBack = 1e-12;
// the closed-form checks of the catalog entry ask 1e-9 of the solver; the API adds only a unit
// conversion
constexpr double kClosedForm = 1e-9;
constexpr double kL1 = 1, kL2 = 2.6;
}  // namespace

TEST_CASE("Model::Load reads a file with overrides; parameters() lists them after evaluation", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("slider-crank-offset"), {{"e", "0.5"}});
  CHECK(m.name() == "slider-crank-offset");
  CHECK(m.input_name() == "phi");
  CHECK(m.input_is_angle());
  CHECK(m.output_names() == std::vector<std::string>{"s", "mu"});
  CHECK_FALSE(m.output_is_angle("s"));
  CHECK(m.output_is_angle("mu"));
  bool seen = false;
  for (const auto& [name, value] : m.parameters()) {
    if (name == "e") {
      seen = true;
      CHECK(value == 0.5);
    }
  }
  CHECK(seen);
}

TEST_CASE("Model::Span: what is given, the file's sweep for what is not", "[api]") {
  const Model m = Model::Load(test::TestDataPath("triple-rocker.yaml"));
  const SweepSpan file = m.Span();
  CHECK(file.from == m.sweep_from());
  CHECK(file.to == m.sweep_to());
  CHECK(file.step == m.sweep_step());
  const SweepSpan given = m.Span(10.0, std::nullopt, 0.5);
  CHECK(given.from == 10.0);
  CHECK(given.to == m.sweep_to());
  CHECK(given.step == 0.5);
}

TEST_CASE("Model::With evaluates the file anew with the new value; the model it came from is unchanged", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("slider-crank-offset"));  // e = 0.8
  const Model flat = m.With("e", 0.0);
  const PoseResult p = Workspace(flat).MoveTo(30);
  REQUIRE(p.status == AnalysisStatus::kComplete);
  CHECK_THAT(p.Get("s"), WithinAbs(test::SliderCrank(kL1, kL2, 0.0, DegToRad(30)).s, kClosedForm));
  const Model half = flat.With("e", "l1/2");
  CHECK_THAT(Workspace(half).MoveTo(30).Get("s"), WithinAbs(test::SliderCrank(kL1, kL2, 0.5, DegToRad(30)).s, kClosedForm));
  CHECK_THAT(Workspace(m).MoveTo(30).Get("s"), WithinAbs(test::SliderCrank(kL1, kL2, 0.8, DegToRad(30)).s, kClosedForm));

  try {
    (void)half.With("no_such_parameter", 1.0);
    FAIL("an unknown parameter was accepted");
  } catch (const InputError& e) {
    REQUIRE(!e.diagnostics().empty());
    CHECK_THAT(e.what(), Catch::Contains("no_such_parameter"));
  }
  CHECK_THROWS_AS(half.With("e", "1/0"), InputError);
  CHECK_THROWS_AS(half.With("e", std::nan("")), InputError);
}

TEST_CASE("Model::Parse reports the line of a bad field with the given name; With leaves the original", "[api]") {
  const std::string text = test::ReadText(test::TestDataPath("triple-rocker.yaml"));
  const Model m = Model::Parse(text, "mine.yaml");
  CHECK(m.path() == "mine.yaml");
  const Model changed = m.With("a", 1.0);
  CHECK(m.parameters() != changed.parameters());
  CHECK(changed.path() == "mine.yaml");  // evaluated from the text it was parsed from

  std::string bad = text;
  bad.replace(bad.find("links: [coupler, rocker]"), 24, "links: [coupler, rockr]");
  try {
    Model::Parse(bad, "bad.yaml");
    FAIL("a joint naming an unknown link was accepted");
  } catch (const InputError& e) {
    REQUIRE(!e.diagnostics().empty());
    CHECK(e.diagnostics()[0].file == "bad.yaml");
    CHECK(e.diagnostics()[0].line == 13);
    CHECK_THAT(e.what(), Catch::Contains("rockr"));
  }
}

TEST_CASE("Model::ToYaml reads back to the same outputs", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("slider-crank-offset"), {{"e", "0.3"}});
  const Model back = Model::Parse(m.ToYaml(), "written.yaml");
  CHECK_THAT(Workspace(back).MoveTo(77).Get("s"), WithinAbs(Workspace(m).MoveTo(77).Get("s"), kWrittenBack));
}

TEST_CASE("Model::ToYaml is the file as written with only the set parameters' values changed", "[api]") {
  // reference: the catalog entry's own text, with e's line edited by hand
  const std::string path = test::CatalogEntryPath("slider-crank-offset");
  const std::string text = test::ReadText(path);
  CHECK(Model::Load(path).ToYaml() == text);
  const Model m = Model::Load(path).With("e", 0.25);
  const size_t e = text.find("\n  e: ");
  REQUIRE(e != std::string::npos);
  const size_t value = e + std::string("\n  e: ").size(), value_end = text.find_first_of(" \n", value);
  CHECK(m.ToYaml() == text.substr(0, value) + "0.25" + text.substr(value_end));
  const Model back = Model::Parse(m.ToYaml(), "written.yaml");
  CHECK(back.parameters() == m.parameters());
}

TEST_CASE("Model::ToYaml of every catalog entry, unchanged, is the entry's text byte for byte", "[api]") {
  int entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(KOPPEL_CATALOG_DIR)) {
    if (e.path().extension() != ".yaml") continue;
    INFO(e.path());
    CHECK(Model::Load(e.path().string()).ToYaml() == test::ReadText(e.path().string()));
    ++entries;
  }
  CHECK(entries >= 30);
}

TEST_CASE("Model::With refuses a parameter that no formula reads", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("watt-six-bar"));
  CHECK_THROWS_WITH(m.With("psi1_a", 1.0), Catch::Contains("no formula of this file reads the parameter 'psi1_a'"));
  CHECK_NOTHROW(m.With("a1", 1.01));
}

TEST_CASE("Model::FromMechanism refuses an inconsistent mechanism", "[api]") {
  Mechanism broken;
  broken.name = "broken";
  CHECK_THROWS_AS(Model::FromMechanism(broken), InputError);
}

}  // namespace model_test

namespace model_test {

TEST_CASE("ParseAtBranchPoint: the kernel's words, empty for continue, InputError naming the field otherwise", "[api]") {
  // the reference is the kernel's own spelling (ToString), so the words cannot drift apart
  for (const AtBranchPoint action : {AtBranchPoint::kContinue, AtBranchPoint::kStop, AtBranchPoint::kSwitch})
    CHECK(ParseAtBranchPoint(ToString(action)) == action);
  CHECK(ParseAtBranchPoint("") == AtBranchPoint::kContinue);
  try {
    (void)ParseAtBranchPoint("swap");
    FAIL("accepted 'swap'");
  } catch (const InputError& e) {
    REQUIRE(e.diagnostics().size() == 1);
    CHECK(e.diagnostics()[0].path == "at_branch_point");
    CHECK_THAT(e.diagnostics()[0].message, Catch::Contains("'swap'"));
  }
}

}  // namespace model_test
