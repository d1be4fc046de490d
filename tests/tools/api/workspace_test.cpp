// koppel::Workspace (tools/api/src/workspace.cpp): a model's pose and the walk that moves it,
// against seed 000's closed form of the slider-crank (tests/support/closed_forms) and the
// triple rocker's limit positions by the law of cosines.
#include "koppel/api/workspace.hpp"
#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace koppel;
using Catch::Matchers::WithinAbs;

namespace workspace_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

// [deg] the pose's input is the one asked for, through degrees -> radians -> degrees
constexpr double kInputDeg = 1e-12;
// [deg] kClosedForm (1e-9 rad) shown in degrees (x 57.3), with margin
constexpr double kAngleDeg = 1e-7;
// s''' against a central difference of the closed-form s'' (h = 1e-5): truncation ~1e-10 and
// rounding ~1e-11 (see the test), plus the solver's own 1e-9-class error of a third derivative
constexpr double kThirdOrder = 1e-8;
// the closed-form checks of the catalog entry ask 1e-9 of the solver; the API adds only a unit
// conversion
constexpr double kClosedForm = 1e-9;
constexpr double kL1 = 1, kL2 = 2.6;
}  // namespace

TEST_CASE("Workspace: a pose's outputs and transfer functions equal seed 000's closed form, in degrees at the boundary", "[api]") {
  Workspace m(Model::Load(test::CatalogEntryPath("slider-crank-offset")));
  const PoseResult assembled = m.Assemble(2);
  REQUIRE(assembled.status == AnalysisStatus::kComplete);
  CHECK(m.assembled());
  for (double phi_deg : {37.0, 145.0, 290.0, -60.0}) {
    const PoseResult p = m.MoveTo(phi_deg, 3);
    REQUIRE(p.status == AnalysisStatus::kComplete);
    CHECK_THAT(p.input, WithinAbs(phi_deg, kInputDeg));
    const test::SliderCrankValues ref = test::SliderCrank(kL1, kL2, 0.8, DegToRad(phi_deg));
    CHECK_THAT(p.Get("s"), WithinAbs(ref.s, kClosedForm));
    CHECK_THAT(p.Get("s_d1"), WithinAbs(ref.s1, kClosedForm));
    CHECK_THAT(p.Get("s_d2"), WithinAbs(ref.s2, kClosedForm));
    CHECK_THAT(p.Get("mu"), WithinAbs(RadToDeg(ref.mu), kAngleDeg));  // degrees: 1e-9 rad
    CHECK(p.valid_order == 3);
    CHECK_FALSE(p.singular);
  }
  CHECK_THROWS_AS(m.MoveTo(10, 9), InputError);  // orders 0..8
}

TEST_CASE("Workspace::MoveTo: the 3rd-order transfer function equals a central difference of the 2nd", "[api]") {
  // reference: (s''(phi + h) - s''(phi - h)) / 2h with s'' from the closed form, h = 1e-5 rad:
  // truncation ~ h^2 s^(5) / 6 ~ 1e-10, rounding ~ 1e-16 / h ~ 1e-11
  Workspace m(Model::Load(test::CatalogEntryPath("slider-crank-offset")));
  const double phi = DegToRad(100), h = 1e-5;
  const double reference = (test::SliderCrank(kL1, kL2, 0.8, phi + h).s2 - test::SliderCrank(kL1, kL2, 0.8, phi - h).s2) / (2 * h);
  const PoseResult p = m.MoveTo(100, 8);
  REQUIRE(p.status == AnalysisStatus::kComplete);
  CHECK_THAT(p.Get("s_d3"), WithinAbs(reference, kThirdOrder));
  CHECK(p.valid_order == 8);
  CHECK(std::isfinite(p.Get("s_d8")));
}

TEST_CASE("Workspace::MoveTo past a limit point fails and stays at the limit", "[api]") {
  // triple rocker a=2, b=3, c=2.5, d=4: limits where |A B0| = b + c (law of cosines)
  Workspace m(Model::Load(test::TestDataPath("triple-rocker.yaml")));
  const std::vector<double> limits = test::FourBarLimits(2, 3, 2.5, 4);
  REQUIRE(!limits.empty());
  const PoseResult p = m.MoveTo(170);
  CHECK(p.status == AnalysisStatus::kFailed);
  CHECK(!p.message.empty());
  double nearest = 1e9;
  for (double limit : limits) nearest = std::min(nearest, std::abs(AngleDifference(DegToRad(p.input), limit)));
  CHECK(nearest < 1e-8);
}

TEST_CASE("a copy of a workspace starts without a pose; its model is shared, not changed", "[api]") {
  Workspace w(Model::Load(test::CatalogEntryPath("slider-crank-offset")));
  REQUIRE(w.MoveTo(40).status == AnalysisStatus::kComplete);
  const Workspace copy = w;
  CHECK(w.assembled());
  CHECK_FALSE(copy.assembled());
  CHECK(copy.model().parameters() == w.model().parameters());
}

}  // namespace workspace_test
