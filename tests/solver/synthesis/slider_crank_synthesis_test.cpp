// Slider-crank dead-centre synthesis (seed 002): designs re-analysed by the generic solver, the
// best offset against a brute-force scan with seed 000's closed form, the offset and beta
// ranges that give a crank, and the refusals (phi0 outside (90, 270) deg, the centric case).
#include "koppel/synthesis/deadcentre_synthesis.hpp"

#include "koppel/analysis/dead_centres.hpp"
#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <optional>

namespace koppel::slider_crank_synthesis_test {
namespace {

// the design's closed forms (cot, the dead-centre triangles) on O(1) lengths: rounding only
constexpr double kClosedFormRoundoff = 1e-12;
// the document's chart, read by eye to about half a unit of its 0.01 grid (koppel: 0.1621)
constexpr double kChartE = 0.005;
// [deg] the document's "~12 deg" read off its chart (koppel: 11.21 deg)
constexpr double kChartMuDeg = 1.0;

constexpr double kReanalysed = 1e-9;

double Wrap2Pi(double a) { return std::fmod(std::fmod(a, 2 * kPi) + 2 * kPi, 2 * kPi); }

SliderCrankRequest Request(double phi0_deg, double stroke) {
  SliderCrankRequest r;
  r.phi0 = DegToRad(phi0_deg);
  r.stroke = stroke;
  return r;
}

void CheckReanalysed(const SliderCrankDesign& d) {
  REQUIRE(d.ok());
  SweepOptions turn;
  turn.from = 0.3;
  turn.to = turn.from + 2 * kPi;
  turn.step = DegToRad(1);
  const DeadCentreReport r = FindDeadCentres(SliderCrankMechanism(d), 0, 0, turn);
  REQUIRE(r.classified);
  CHECK(std::abs(AngleDifference(Wrap2Pi(r.phi_a - r.phi_i), d.request.phi0)) < kReanalysed);
  CHECK(std::abs((r.s_a - r.s_i) - d.request.stroke) < kReanalysed * d.request.stroke);
  // seed 000's closed form: the dead centres at phi_a, phi_i and mu_min = 90 deg - asin((l1 + |e|)/l2)
  CHECK(std::abs(AngleDifference(r.phi_a, test::SliderCrankPhiA(d.l1, d.l2, d.e))) < kReanalysed);
  CHECK(std::abs(AngleDifference(r.phi_i, test::SliderCrankPhiI(d.l1, d.l2, d.e))) < kReanalysed);
  CHECK(d.mu_min == Approx(kPi / 2 - std::asin((d.l1 + std::abs(d.e)) / d.l2)).margin(kReanalysed));
}

// Brute force: a fine scan of the offset; each candidate's l1, l2 from the dead centres
// B_i = (x, e), B_a = (x + s0, e) with x found by bisection on the angle the rays enclose,
// its phi0 and stroke checked with seed 000's closed forms, mu_min from seed 000's mu.
struct BruteForce {
  bool found = false;
  double e = 0, mu_min = 0, step_change = 0;
};

BruteForce ScanOffset(double phi0, double s0, double step) {
  const double theta = std::abs(phi0 - kPi);
  BruteForce best;
  std::optional<double> previous;
  for (double e = step; e < 100 * s0; e += step) {
    // the angle between the rays falls from 90 deg - atan(e/s0) at x = 0 to 0 as x grows
    auto gap = [&](double x) { return std::atan2(e, x) - std::atan2(e, x + s0) - theta; };
    std::optional<double> mu;
    if (gap(0) > 0) {
      double lo = 0, hi = 1e6 * s0;
      for (int it = 0; it < 200; ++it) (gap(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
      const double x = 0.5 * (lo + hi), rho_i = std::hypot(x, e), rho_a = std::hypot(x + s0, e);
      const double l1 = 0.5 * (rho_a - rho_i), l2 = 0.5 * (rho_a + rho_i), signed_e = phi0 < kPi ? e : -e;
      const double span = Wrap2Pi(test::SliderCrankPhiA(l1, l2, signed_e) - test::SliderCrankPhiI(l1, l2, signed_e));
      if (l2 > l1 + e && std::abs(AngleDifference(span, phi0)) < 1e-9) mu = kPi / 2 - std::asin((l1 + e) / l2);
    }
    if (mu && previous) best.step_change = std::max(best.step_change, std::abs(*mu - *previous));
    previous = mu;
    if (mu && (!best.found || *mu > best.mu_min)) {
      best = {true, e, *mu, best.step_change};
    }
  }
  return best;
}

}  // namespace

TEST_CASE("best slider-cranks for phi0 on both sides of 180 deg agree with a brute-force scan of the offset", "[synthesis]") {
  for (double phi0 : {100.0, 120.0, 150.0, 170.0, 190.0, 240.0, 265.0}) {
    INFO("phi0 " << phi0);
    const SliderCrankDesign d = BestSliderCrank(Request(phi0, 2.0));
    INFO(d.Brief());
    CheckReanalysed(d);
    const BruteForce brute = ScanOffset(DegToRad(phi0), 2.0, 1e-3);
    REQUIRE(brute.found);
    CHECK(d.mu_min >= brute.mu_min - kReanalysed);
    CHECK(d.mu_min <= brute.mu_min + brute.step_change + kReanalysed);
    // phi0 < 180 deg puts A0 below the slide line, phi0 > 180 deg above it (seed 000's sign of e)
    CHECK((d.e > 0) == (phi0 < 180));
  }
}

TEST_CASE("slider-crank from the offset or from beta, inside and outside their ranges", "[synthesis]") {
  const SliderCrankRequest r = Request(120, 1.0);
  const SliderCrankDesign by_e = SliderCrankFromOffset(r, 0.16);
  CheckReanalysed(by_e);
  // the ranges: |e| < s0 cot(theta) and beta < 90 deg - theta, theta = |phi0 - 180 deg| = 60 deg
  CHECK(by_e.offset_max == Approx(1 / std::tan(DegToRad(60))).margin(kClosedFormRoundoff));
  CHECK(by_e.beta_max == Approx(DegToRad(30)).margin(kClosedFormRoundoff));
  const SliderCrankDesign by_beta = SliderCrankFromBeta(r, by_e.beta);
  CheckReanalysed(by_beta);
  CHECK(by_beta.e == Approx(0.16).margin(kClosedFormRoundoff));
  CHECK(by_beta.l1 == Approx(by_e.l1).margin(kClosedFormRoundoff));
  CHECK(by_beta.l2 == Approx(by_e.l2).margin(kClosedFormRoundoff));
  // just inside both ends of the offset range there are (poor) cranks, outside none
  CheckReanalysed(SliderCrankFromOffset(r, 0.01));
  CheckReanalysed(SliderCrankFromOffset(r, 0.99 * by_e.offset_max));
  CHECK(SliderCrankFromOffset(r, 1.01 * by_e.offset_max).status == DesignStatus::kNoDesign);
  CHECK(SliderCrankFromOffset(r, 0.0).status == DesignStatus::kNoDesign);
  CHECK(SliderCrankFromBeta(r, DegToRad(40)).status == DesignStatus::kNoDesign);  // beta + 60 >= 90 deg
  CHECK_THAT(SliderCrankFromBeta(r, DegToRad(40)).message, Catch::Contains("0 < |e| < 0.57735"));
}

TEST_CASE("seed 002's example phi0 = 120 deg: the best offset against the printed e/s0 = 0.16, mu_min ~ 12 deg", "[synthesis]") {
  const SliderCrankDesign best = BestSliderCrank(Request(120, 1.0));
  CheckReanalysed(best);
  CHECK(best.e == Approx(0.16).margin(kChartE));               // koppel: 0.1621
  CHECK(RadToDeg(best.mu_min) == Approx(12.0).margin(kChartMuDeg));  // koppel: 11.21 deg ("~12" read off the chart)
  // a true maximum: both neighbours are worse
  CHECK(SliderCrankFromOffset(best.request, best.e - 0.01).mu_min < best.mu_min);
  CHECK(SliderCrankFromOffset(best.request, best.e + 0.01).mu_min < best.mu_min);
}

TEST_CASE("slider-crank requests without a design are refused, with the reason", "[synthesis]") {
  const SliderCrankDesign centric = BestSliderCrank(Request(180, 1.0));
  CHECK(centric.status == DesignStatus::kBoundaryOptimum);
  CHECK_THAT(centric.message, Catch::Contains("centric"));
  CHECK(BestSliderCrank(Request(60, 1.0)).status == DesignStatus::kNoDesign);
  CHECK(BestSliderCrank(Request(290, 1.0)).status == DesignStatus::kNoDesign);
  CHECK(BestSliderCrank(Request(120, -1.0)).status == DesignStatus::kInvalidRequest);
  CHECK(BestSliderCrank(Request(0, 1.0)).status == DesignStatus::kInvalidRequest);
  CHECK(SliderCrankDesign{}.status == DesignStatus::kNotRun);
}

}  // namespace koppel::slider_crank_synthesis_test
