// FindProportionality (tools/api/src/proportionality.cpp) against an independent reading of the
// same definition from the API's own sweep: the band about the tangent at the reference input,
// measured on a fine table of s (Model::Sweep), and seed 001's reading example.
#include "koppel/api/proportionality.hpp"
#include "koppel/core/angles.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace koppel;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace proportionality_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

// [length] the band of a table sampled every 0.005 deg misses the true extremes between samples by
// at most s'' h^2 / 8 ~ 1e-9 (|s''| < 1 here, h = 8.7e-5 rad), far inside this
constexpr double kBand = 1e-7;

// The width of the band parallel to the tangent (slope [length/rad] at `reference` [deg]) that
// holds s over the sampled table.
double BandWidth(const SweepTable& t, double reference, double slope) {
  const std::vector<double> phi = t.Column("phi"), s = t.Column("s");
  double low = INFINITY, high = -INFINITY;
  for (size_t i = 0; i < phi.size(); ++i) {
    const double off = s[i] - slope * DegToRad(phi[i] - reference);
    low = std::min(low, off);
    high = std::max(high, off);
  }
  return high - low;
}

}  // namespace

TEST_CASE("FindProportionality: seed 001's reading example, delta_s and Q_P from the band about the flat point's tangent", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("proportional-linkage"));
  ProportionalityRequest request;
  request.output = "s";
  request.from = 112.5;
  request.to = 247.5;
  const ProportionalityReport p = FindProportionality(m, request);
  REQUIRE(p.status == AnalysisStatus::kComplete);
  CHECK(p.sweep.complete());
  CHECK(p.output == "s");
  CHECK(p.from == 112.5);
  CHECK(p.to == 247.5);
  CHECK_THAT(p.range, WithinAbs(135, 1e-9));
  // l1 = 0.5 puts the flat point at 180 deg (the catalog entry's note); the reference length is l1
  CHECK_THAT(p.reference, WithinAbs(180, 1e-6));
  CHECK(p.reference_length == 0.5);
  CHECK(ReferenceLength(m) == 0.5);
  // the band, measured independently on a fine table, with the slope the API reports
  const SweepTable fine = m.Sweep(112.5, 247.5, 0.005, 1);
  CHECK_THAT(p.delta_s, WithinAbs(BandWidth(fine, p.reference, p.slope), kBand));
  // and the slope is s' at the reference (the fine table's row there)
  const int at = static_cast<int>(std::lround((p.reference - 112.5) / 0.005));
  CHECK_THAT(p.slope, WithinAbs(fine.At(at, fine.ColumnIndex("s_d1")), 1e-6));
  CHECK_THAT(p.qp, WithinRel(p.delta_s / p.reference_length / DegToRad(135), 1e-12));
  // the document's reading: delta_s = 0.018, Q_P = 1.5e-2 (two digits)
  CHECK_THAT(p.delta_s, WithinAbs(0.018, 0.0005));
  CHECK_THAT(p.qp, WithinAbs(1.5e-2, 0.05e-2));
}

TEST_CASE("FindProportionality: a given reference and length; bad requests are InputError", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("proportional-linkage"));
  ProportionalityRequest request;
  request.from = 112.5;
  request.to = 247.5;
  request.at = 150;
  request.length = 2;
  const ProportionalityReport p = FindProportionality(m, request);
  REQUIRE(p.status == AnalysisStatus::kComplete);
  CHECK_THAT(p.reference, WithinAbs(150, 1e-9));
  CHECK(p.reference_length == 2);
  const SweepTable fine = m.Sweep(112.5, 247.5, 0.005, 1);
  const int at = static_cast<int>(std::lround((150 - 112.5) / 0.005));
  CHECK_THAT(p.slope, WithinAbs(fine.At(at, fine.ColumnIndex("s_d1")), 1e-9));
  CHECK_THAT(p.delta_s, WithinAbs(BandWidth(fine, 150, p.slope), kBand));

  ProportionalityRequest same = request;
  same.to = same.from;
  CHECK_THROWS_AS(FindProportionality(m, same), InputError);
  ProportionalityRequest no_length = request;
  no_length.length = 0.0;
  CHECK_THROWS_AS(FindProportionality(m, no_length), InputError);
  ProportionalityRequest unknown = request;
  unknown.output = "nope";
  CHECK_THROWS_AS(FindProportionality(m, unknown), InputError);
  ProportionalityRequest dense = request;
  dense.resolution = 1e-6;  // beyond kMaxSweepSamples: refused before sampling
  CHECK_THROWS_AS(FindProportionality(m, dense), InputError);
}

TEST_CASE("FindProportionality beyond a limit point: partial, over the drivable part, the gap named", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("triple-rocker"));
  ProportionalityRequest request;
  request.from = 250;
  request.to = 360;
  const ProportionalityReport p = FindProportionality(m, request);
  CHECK(p.status == AnalysisStatus::kPartial);
  CHECK_FALSE(p.sweep.complete());
  CHECK_FALSE(p.sweep.gaps.empty());
  CHECK(p.range < 110);
}

}  // namespace proportionality_test
