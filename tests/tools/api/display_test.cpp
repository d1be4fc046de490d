// The API's units from the solver's (tools/api/src/display.cpp, private to the API): degrees for
// angles and R-drive inputs, NaN beyond the valid order, the solver's singular points and gaps
// in those units, the branch-point words mapped one to one.
#include "display.hpp"

#include "koppel/core/angles.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::display_test {
namespace {

// x * 180 / pi against RadToDeg: a few ulps of numbers up to 400.
constexpr double kRoundoff = 1e-12;

double Degrees(double radians) { return radians * 180.0 / 3.14159265358979323846; }  // the reference conversion

TEST_CASE("a row: the input and angles in degrees, lengths as they are, NaN beyond the valid order", "[display]") {
  const Mechanism m = test::FourBar(1, 3, 2.5, 3.2, 1.5, 0.4, 1);  // outputs K (point), psi, phi, mu
  const SweepColumns layout = SweepLayout(m, 2);
  const size_t width = layout.names.size();
  std::vector<double> outputs(width - 2);
  for (size_t i = 0; i < outputs.size(); ++i) outputs[i] = 0.1 * (i + 1);
  std::vector<double> row(width);
  api_detail::DisplayRow(m, layout, 1.0, outputs.data(), 1, true, row.data());
  CHECK_THAT(row[0], Catch::Matchers::WithinAbs(Degrees(1.0), kRoundoff));
  CHECK(row[width - 1] == 1.0);
  for (size_t c = 1; c + 1 < width; ++c) {
    INFO(layout.names[c]);
    const double v = outputs[c - 1];
    if (layout.order_of_column[c] == 2) CHECK(std::isnan(row[c]));
    else if (layout.names[c] == "psi" || layout.names[c] == "phi" || layout.names[c] == "mu")
      CHECK_THAT(row[c], Catch::Matchers::WithinAbs(Degrees(v), kRoundoff));
    else
      CHECK(row[c] == v);  // lengths and transfer functions per radian: unchanged
  }
  api_detail::DisplayRow(m, layout, 1.0, outputs.data(), 2, false, row.data());
  CHECK(row[width - 1] == 0.0);
  for (size_t c = 1; c + 1 < width; ++c) CHECK_FALSE(std::isnan(row[c]));
}

TEST_CASE("an R drive's input is shown in degrees and read back in radians", "[display]") {
  const Mechanism m = test::FourBar(1, 3, 2.5, 3.2, 1.5, 0.4, 1);
  CHECK_THAT(api_detail::InputShown(m, kPi / 3), Catch::Matchers::WithinAbs(60.0, kRoundoff));
  CHECK_THAT(api_detail::InputInternal(m, 60.0), Catch::Matchers::WithinAbs(kPi / 3, kRoundoff));
  const std::vector<InputGap> gaps = api_detail::Shown(m, std::vector<InputInterval>{{kPi / 2, kPi}});
  REQUIRE(gaps.size() == 1);
  CHECK_THAT(gaps[0].from, Catch::Matchers::WithinAbs(90.0, kRoundoff));
  CHECK_THAT(gaps[0].to, Catch::Matchers::WithinAbs(180.0, kRoundoff));
}

TEST_CASE("singular points in the API's words and units", "[display]") {
  const Mechanism m = test::FourBar(1, 3, 2.5, 3.2, 1.5, 0.4, 1);
  SingularPoint p;
  p.kind = SingularKind::kBranchPoint;
  p.input = kPi;
  p.rcond = 1e-9;
  p.joints = {1, 3};
  p.action = BranchPointAction::kSwitch;
  const std::vector<SingularPosition> s = api_detail::Shown(m, std::vector<SingularPoint>{p});
  REQUIRE(s.size() == 1);
  CHECK(s[0].kind == "branch-point");
  CHECK_THAT(s[0].input, Catch::Matchers::WithinAbs(180.0, kRoundoff));
  CHECK(s[0].rcond == 1e-9);
  CHECK(s[0].joints == std::vector<std::string>{m.joints[1].name, m.joints[3].name});
  CHECK(s[0].action == "switch");
}

TEST_CASE("what a sweep met, in the API's units and statuses", "[display]") {
  const Mechanism m = test::FourBar(1, 3, 2.5, 3.2, 1.5, 0.4, 1);
  SweepEvents e;
  e.status = SweepStatus::kPartial;
  e.message = "beyond the branch";
  e.notes = {"a note"};
  e.gaps = {{kPi / 2, kPi}};
  e.reached = {0, kPi / 2};
  e.singular_inputs = {kPi / 4};
  const SweepRecord r = api_detail::Shown(m, e);
  CHECK(r.status == AnalysisStatus::kPartial);
  CHECK_FALSE(r.complete());
  CHECK(r.message == e.message);
  CHECK(r.notes == e.notes);
  REQUIRE(r.gaps.size() == 1);
  CHECK_THAT(r.gaps[0].from, Catch::Matchers::WithinAbs(90.0, kRoundoff));
  CHECK_THAT(r.gaps[0].to, Catch::Matchers::WithinAbs(180.0, kRoundoff));
  CHECK_THAT(r.reached.to, Catch::Matchers::WithinAbs(90.0, kRoundoff));
  REQUIRE(r.singular_inputs.size() == 1);
  CHECK_THAT(r.singular_inputs[0], Catch::Matchers::WithinAbs(45.0, kRoundoff));
  // a sweep that could not start is a failed analysis; a complete one is complete
  CHECK(api_detail::FromSweep(SweepStatus::kNotAssemblable) == AnalysisStatus::kFailed);
  CHECK(api_detail::FromSweep(SweepStatus::kInvalidOptions) == AnalysisStatus::kFailed);
  CHECK(api_detail::FromSweep(SweepStatus::kComplete) == AnalysisStatus::kComplete);
}

TEST_CASE("bad input names the file and the field", "[display]") {
  try {
    api_detail::BadInput("m.yaml", "from", "must be finite");
    FAIL("no throw");
  } catch (const InputError& e) {
    REQUIRE(e.diagnostics().size() == 1);
    CHECK(e.diagnostics()[0].file == "m.yaml");
    CHECK(e.diagnostics()[0].path == "from");
    CHECK(e.diagnostics()[0].message == "must be finite");
  }
}

}  // namespace
}  // namespace koppel::display_test
