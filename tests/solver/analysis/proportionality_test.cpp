// Seed 001's reading example: 112.5..247.5 deg -> Q_P = 1.5e-2, Δs = 0.018 (printed rounding).
#include "koppel/analysis/proportionality.hpp"

#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::proportionality_test {

// the tangent's slope against seed 001's closed-form s' at the flat point: rounding of a converged pose
constexpr double kSlopeRoundoff = 1e-12;
// the document's Δs = 0.018: half a unit of its last digit
constexpr double kDocumentDs = 0.0005;
// the document's Q_P = 1.5 %: half a unit of its last digit
constexpr double kDocumentQp = 0.05e-2;
// the closed form's band from samples 0.001 deg apart: at an extreme a sample misses by
// ~(h / 2)^2 |d''| / 2 ~ 1e-10
constexpr double kBandSamples = 1e-9;
// [deg] phi_P on a whole degree reached through unit conversions: rounding only
constexpr double kSampleDeg = 1e-12;
// [deg] the flat point is a triple root of s'': located to where its sign is rounding (~1e-5 rad)
constexpr double kTripleRootDeg = 1e-3;

TEST_CASE("proportional linkage reading example", "[proportionality]") {
  const Mechanism m = test::ProportionalLinkage(1.0, 0.5, 1.83);
  const Proportionality p = ProportionalityDeviation(m, 0, DegToRad(112.5), DegToRad(247.5), 0.5, std::nullopt, DegToRad(0.05));
  REQUIRE(p.status == AnalysisStatus::kComplete);
  CHECK(RadToDeg(p.reference) == Approx(180).margin(1e-9));  // the flat point
  CHECK(p.slope == Approx(test::Proportional(1.0, 0.5, 1.83, kPi).s1).margin(kSlopeRoundoff));
  CHECK(p.delta_s == Approx(0.018).margin(kDocumentDs));
  CHECK(p.qp == Approx(1.5e-2).margin(kDocumentQp));
  // independent check of Δs: band of the closed form about its tangent at 180 deg, 0.001 deg samples
  double lo = 0, hi = 0;
  for (int i = 0; i <= 135000; ++i) {
    const double phi = DegToRad(112.5 + i * 0.001);
    const double d = test::ProportionalS(1.0, 0.5, 1.83, phi) - p.slope * (phi - kPi);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  CHECK(p.delta_s == Approx(hi - lo).margin(kBandSamples));
  // the chord deviation is a different, smaller measure that does not reproduce the document
  CHECK(p.chord_deviation < 0.006);
}

// A resolution that does not divide the range: the band still covers it up to `to`, the flat
// point and the band's extremes are refined between samples (they were the samples': phi_P 133
// deg instead of 135, delta_s 0.01678 instead of 0.01812).
TEST_CASE("proportionality over the whole range whatever the resolution", "[proportionality]") {
  const Mechanism m = test::ProportionalLinkage(1.0, 0.5, 1.83);
  const Proportionality p = ProportionalityDeviation(m, 0, DegToRad(112.5), DegToRad(247.5), 0.5, std::nullopt, DegToRad(7));
  REQUIRE(p.status == AnalysisStatus::kComplete);
  CHECK(RadToDeg(p.phi_p) == Approx(135).margin(kSampleDeg));
  // s'' = -c sin phi (1 - 2 lambda^2 + lambda cos phi)/(1 - lambda cos phi)^3 vanishes at 180 deg
  // (seed 001), a triple root here: located to where the sign of s'' is roundoff (~1e-5 rad),
  // where the tangent's slope differs from s'(180 deg) by ~(1e-5)^3 s''''
  CHECK(RadToDeg(p.reference) == Approx(180).margin(kTripleRootDeg));
  CHECK(p.slope == Approx(test::Proportional(1.0, 0.5, 1.83, kPi).s1).margin(kSlopeRoundoff));
  // the closed form's band about its tangent at 180 deg, 0.001 deg samples
  double lo = 0, hi = 0;
  for (int i = 0; i <= 135000; ++i) {
    const double phi = DegToRad(112.5 + i * 0.001);
    const double d = test::ProportionalS(1.0, 0.5, 1.83, phi) - test::ProportionalS(1.0, 0.5, 1.83, kPi) - p.slope * (phi - kPi);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  CHECK(p.delta_s == Approx(hi - lo).margin(kBandSamples));
}

}  // namespace koppel::proportionality_test
