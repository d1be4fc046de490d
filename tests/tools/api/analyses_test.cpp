// Model::Sweep, FindDeadCentres, DrivableRanges (tools/api/src/analyses.cpp) against closed forms:
// seed 000's slider-crank and the triple rocker's limits by the law of cosines.
#include "koppel/api/model.hpp"
#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace koppel;
using Catch::Matchers::WithinAbs;

namespace analyses_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

// [deg] the sweep's inputs are from + i step in radians, shown in degrees: rounding only
constexpr double kSampleInput = 1e-9;
// [deg] an angle within kClosedForm = 1e-9 rad of the closed form, shown in degrees (x 57.3), with margin
constexpr double kAngleDeg = 1e-7;
// [deg] the end of the requested range is the requested input itself, through two unit conversions
constexpr double kRangeEnd = 1e-12;
// [deg] the limit positions are folds of the drive, located to ~1e-9 rad; shown in degrees
constexpr double kLimitDeg = 1e-7;
// [deg] a full turn is 2 pi exactly, shown in degrees: rounding only
constexpr double kPeriodDeg = 1e-9;
constexpr double kClosedForm = 1e-9;  // the catalog entry's own tolerance against seed 000
constexpr double kDeadCentre = 1e-8;  // dead centres are refined to 1e-12 in the input
constexpr double kL1 = 1, kL2 = 2.6;
}  // namespace

TEST_CASE("Model::Sweep: the columns of koppel analyze, values equal to seed 000 row by row", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("slider-crank-offset"));
  const SweepTable t = m.Sweep(0, 360, 5, 2);
  REQUIRE(t.status == AnalysisStatus::kComplete);
  CHECK(t.columns == std::vector<std::string>{"phi", "s", "s_d1", "s_d2", "mu", "mu_d1", "mu_d2", "singular"});
  CHECK(t.units == std::vector<std::string>{"deg", "length", "length/rad", "length/rad^2", "deg", "rad/rad", "rad/rad^2", "1"});
  REQUIRE(t.rows == 73);
  const std::vector<double> phi = t.Column("phi"), s = t.Column("s"), s1 = t.Column("s_d1"), s2 = t.Column("s_d2"), mu = t.Column("mu");
  for (int i = 0; i < t.rows; ++i) {
    CHECK_THAT(phi[i], WithinAbs(5.0 * i, kSampleInput));
    const test::SliderCrankValues ref = test::SliderCrank(kL1, kL2, 0.8, DegToRad(phi[i]));
    CHECK_THAT(s[i], WithinAbs(ref.s, kClosedForm));
    CHECK_THAT(s1[i], WithinAbs(ref.s1, kClosedForm));
    CHECK_THAT(s2[i], WithinAbs(ref.s2, kClosedForm));
    CHECK_THAT(mu[i], WithinAbs(RadToDeg(ref.mu), kAngleDeg));
    CHECK(t.At(i, t.ColumnIndex("singular")) == 0.0);
  }
  CHECK(t.ColumnIndex("nope") == -1);
  CHECK_THROWS_AS(t.Column("nope"), InputError);
  CHECK_THROWS_AS(m.Sweep(0, 360, 0), InputError);
  CHECK_THROWS_AS(m.Sweep(0, 1e12, 1e-6), InputError);  // beyond kMaxSweepSamples, refused before allocating
}

TEST_CASE("Model::Sweep beyond a limit point is partial: the reachable rows, the gap, the singular point", "[api]") {
  const Model m = Model::Load(test::TestDataPath("triple-rocker.yaml"));
  const SweepTable t = m.Sweep(0, 180, 1, 1);
  CHECK(t.status == AnalysisStatus::kPartial);
  CHECK(!t.message.empty());
  REQUIRE(!t.gaps.empty());
  REQUIRE(!t.singular_points.empty());
  CHECK(t.singular_points[0].kind == "limit");
  const double limit = RadToDeg(test::FourBarLimits(2, 3, 2.5, 4)[0]);
  bool matched = false;
  for (const SingularPosition& p : t.singular_points) matched = matched || std::abs(p.input - limit) < 1e-6;
  CHECK(matched);
  for (double input : t.Column("phi")) CHECK(input <= limit + 1e-9);
}

TEST_CASE("Model::FindDeadCentres: stroke, dead-centre angles and phase ratio of seed 000", "[api]") {
  for (double e : {0.0, 0.8}) {
    const Model m = Model::Load(test::CatalogEntryPath("slider-crank-offset"), {{"e", std::to_string(e)}});
    const DeadCentres d = m.FindDeadCentres("s");
    REQUIRE(d.status == AnalysisStatus::kComplete);
    REQUIRE(d.has_stroke);
    REQUIRE(d.points.size() == 2);
    // stroke = sqrt((l1 + l2)^2 - e^2) - sqrt((l2 - l1)^2 - e^2): the slider's distance from
    // the foot point with crank and coupler stretched and folded (seed 000, s_a - s_i)
    const double stroke = std::sqrt((kL1 + kL2) * (kL1 + kL2) - e * e) - std::sqrt((kL2 - kL1) * (kL2 - kL1) - e * e);
    CHECK_THAT(d.stroke, WithinAbs(stroke, kDeadCentre));
    CHECK_THAT(d.input_a, WithinAbs(RadToDeg(test::SliderCrankPhiA(kL1, kL2, e)), kDeadCentre));
    CHECK_THAT(d.input_i, WithinAbs(RadToDeg(test::SliderCrankPhiI(kL1, kL2, e)), kDeadCentre));
    const double forward = d.input_i - d.input_a;
    CHECK_THAT(d.forward_angle, WithinAbs(forward, kDeadCentre));
    CHECK_THAT(d.phase_ratio, WithinAbs(forward / (360 - forward), kDeadCentre));
    CHECK(d.points[0].kind == "extended");
    CHECK(d.points[1].kind == "folded");
  }
  const Model m = Model::Load(test::CatalogEntryPath("slider-crank-offset"));
  CHECK_THROWS_AS(m.FindDeadCentres("no_such_output"), InputError);
}

// issue 22 item 2: a transmission angle's extremes through the API, in degrees (seed 000, e = 0.8:
// mu_min = 90 deg - arcsin(lambda + eps) at phi = 0; mu folds at 90 deg where cos phi = -e/l1)
TEST_CASE("Model::FindDeadCentres: mu_min and mu_max of seed 000 and where they are", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("slider-crank-offset"));
  const DeadCentres d = m.FindDeadCentres("mu");
  REQUIRE(d.has_extremes);
  CHECK(d.minimum.at == "stationary");
  CHECK_THAT(d.minimum.input, WithinAbs(0, kDeadCentre));
  CHECK_THAT(d.minimum.value, WithinAbs(90 - RadToDeg(std::asin(kL1 / kL2 + 0.8 / kL2)), kDeadCentre));
  CHECK(d.maximum.at == "fold");
  CHECK_THAT(d.maximum.input, WithinAbs(RadToDeg(test::SliderCrankMuFolds(kL1, 0.8)[0]), kDeadCentre));
  CHECK_THAT(d.maximum.value, WithinAbs(90, kDeadCentre));
  // over part of the turn from 30 deg the least is at that end
  const DeadCentres part = m.FindDeadCentres("mu", 30, 120);
  REQUIRE(part.has_extremes);
  CHECK(part.minimum.at == "range end");
  CHECK_THAT(part.minimum.input, WithinAbs(30, kRangeEnd));
  CHECK_THAT(part.minimum.value, WithinAbs(RadToDeg(test::SliderCrank(kL1, kL2, 0.8, DegToRad(30)).mu), kClosedForm));
  CHECK(d.unresolved.empty());
}

TEST_CASE("Model::DrivableRanges: the triple rocker swings between its two limits; the slider-crank turns fully", "[api]") {
  const Model rocker = Model::Load(test::TestDataPath("triple-rocker.yaml"));
  const Ranges r = rocker.DrivableRanges();
  REQUIRE(r.status == AnalysisStatus::kComplete);
  REQUIRE(r.branches.size() == 1);
  const BranchInterval& b = r.branches[0];
  CHECK(b.from_kind == "limit");
  CHECK(b.to_kind == "limit");
  // the law of cosines: cos(phi) = (a^2 + d^2 - (b + c)^2) / (2 a d), symmetric about the frame line
  const double limit = RadToDeg(std::acos((4.0 + 16.0 - 5.5 * 5.5) / (2 * 2 * 4)));
  CHECK_THAT(b.from, WithinAbs(-limit, kLimitDeg));
  CHECK_THAT(b.to, WithinAbs(limit, kLimitDeg));

  const Model crank = Model::Load(test::CatalogEntryPath("slider-crank-offset"));
  const Ranges full = crank.DrivableRanges();
  REQUIRE(full.status == AnalysisStatus::kComplete);
  CHECK(full.branches.at(0).to_kind == "full-turn");
  CHECK_THAT(full.branches.at(0).period, WithinAbs(360, kPeriodDeg));
  CHECK(crank.SingularPositions().empty());
}

// issue 24: koppel analyze writes its rows as the API makes them (Model::Sweep with a row sink):
// the rows handed over are the table's rows, value for value, and nothing is kept twice.
TEST_CASE("Model::Sweep with a row sink: the same rows in order, no values kept; the record of the walk", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("slider-crank-offset"));
  const SweepTable kept = m.Sweep(0, 360, 7, 3);
  std::vector<double> handed;
  int next = 0;
  const SweepTable streamed = m.Sweep(0, 360, 7, 3, AtBranchPoint::kContinue, [&](const SweepTable& t, int row, const double* values) {
    CHECK(row == next++);
    CHECK(t.rows == kept.rows);  // known before the first row: a writer can reserve
    handed.insert(handed.end(), values, values + t.columns.size());
  });
  CHECK(streamed.values.empty());
  CHECK(streamed.columns == kept.columns);
  REQUIRE(handed.size() == kept.values.size());
  for (size_t i = 0; i < handed.size(); ++i) CHECK(handed[i] == kept.values[i]);
  // the record: the walk reached the whole requested range (beyond the last sample, 357 deg)
  CHECK(kept.sweep_status == "complete");
  CHECK(kept.record.complete());
  CHECK_THAT(kept.record.reached.from, WithinAbs(0, kRangeEnd));
  CHECK_THAT(kept.record.reached.to, WithinAbs(360, kRangeEnd));
  CHECK(kept.record.singular_inputs.empty());
}

TEST_CASE("Model::Sweep's record beyond a limit point: partial, the flagged rows and the gap as the table has them", "[api]") {
  const Model m = Model::Load(test::TestDataPath("triple-rocker.yaml"));
  const SweepTable t = m.Sweep(0, 180, 1, 1);
  CHECK(t.sweep_status == "partial");
  CHECK(t.record.status == AnalysisStatus::kPartial);
  CHECK(t.record.gaps.size() == t.gaps.size());
  CHECK(t.record.singular_points.size() == t.singular_points.size());
  std::vector<double> flagged;
  for (int r = 0; r < t.rows; ++r) {
    if (t.At(r, t.ColumnIndex("singular")) == 1) flagged.push_back(t.At(r, 0));
  }
  CHECK(t.record.singular_inputs == flagged);
  // the walk reached up to the limit (law of cosines), beyond the last sample before it
  CHECK_THAT(t.record.reached.to, WithinAbs(RadToDeg(test::FourBarLimits(2, 3, 2.5, 4)[0]), kLimitDeg));
  CHECK(t.record.reached.to >= t.At(t.rows - 1, 0));
}

TEST_CASE("Model::FindDeadCentres: the output searched, its kind, the line-up classification, the sweep's record", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("slider-crank-offset"));
  const DeadCentres s = m.FindDeadCentres();  // the first scalar output: s
  CHECK(s.output == "s");
  CHECK_FALSE(s.transmission_angle);
  CHECK(s.classified);  // crank and coupler line up at both dead centres of a slider-crank
  CHECK(s.search_message.empty());
  CHECK(s.sweep.complete());
  CHECK(s.sweep.singular_points.empty());
  const DeadCentres mu = m.FindDeadCentres("mu");
  CHECK(mu.output == "mu");
  CHECK(mu.transmission_angle);
  CHECK(mu.extremes_status == AnalysisStatus::kComplete);
  // the triple rocker cannot be driven over a whole turn: partial, the gap in the record
  const Model rocker = Model::Load(test::TestDataPath("triple-rocker.yaml"));
  const DeadCentres part = rocker.FindDeadCentres("", 0, 180, 1);
  CHECK_FALSE(part.sweep.complete());
  CHECK_FALSE(part.sweep.gaps.empty());
}

TEST_CASE("Model::DrivableRanges: walked, or not when the mechanism does not assemble", "[api]") {
  CHECK(Model::Load(test::TestDataPath("triple-rocker.yaml")).DrivableRanges().walked);
  // an offset beyond l1 + l2: the slider's coupler cannot reach its guide at any input
  const Model apart = Model::Load(test::CatalogEntryPath("slider-crank-offset"), {{"e", "5"}});
  const Ranges r = apart.DrivableRanges();
  CHECK_FALSE(r.walked);
  CHECK(r.status == AnalysisStatus::kFailed);
  CHECK(!r.message.empty());
}

}  // namespace analyses_test
