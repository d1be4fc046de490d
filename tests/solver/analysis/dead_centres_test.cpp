// Dead centres and transmission angle of seed 000's slider-crank against the document's
// formulas (phi_i with the corrected 3/2 pi), for both offsets and the negative one.
#include "koppel/analysis/dead_centres.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/build.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::dead_centres_test {
namespace {

// phi_H / (2 pi - phi_H) of dead centres refined to kRefined (1e-11): the ratio of O(1) numbers
// amplifies it a few times
constexpr double kPhaseRatio = 1e-10;
// [rad] mu of an assembled pose against seed 000's closed form: rounding of a converged pose
constexpr double kSweptMu = 1e-12;
// [deg] against the seed document's value printed to 10 decimals: its last digit
constexpr double kDocumentDeg = 1e-9;
// [deg] against the seed document's value printed to 7 decimals: its last digit
constexpr double kDocumentStrokeDeg = 1e-6;
// refined by Newton on s' to 1e-12 in the input; values then follow to roundoff
constexpr double kRefined = 1e-11;
}

TEST_CASE("slider-crank dead centres, stroke and phase ratio match seed 000", "[deadcentres]") {
  const double l1 = 1.0, l2 = 2.6;
  for (double e : {0.0, 0.8, -0.8}) {
    INFO("e = " << e);
    const Mechanism m = test::SliderCrank(l1, l2, e);
    SweepOptions range;
    range.from = 0;
    range.to = 2 * kPi;
    range.step = DegToRad(1);
    const DeadCentreReport r = FindDeadCentres(m, 0, 0, range);
    REQUIRE(r.sweep.complete());
    REQUIRE(r.points.size() == 2);
    REQUIRE(r.classified);
    const double lambda = l1 / l2, eps = e / l2;
    const double phi_a = test::SliderCrankPhiA(l1, l2, e), phi_i = test::SliderCrankPhiI(l1, l2, e);
    CHECK(std::abs(r.phi_a - phi_a) < kRefined);
    CHECK(std::abs(r.phi_i - phi_i) < kRefined);
    // s_a/l1 = sqrt((1 + 1/lambda)^2 - (eps/lambda)^2), s_i/l1 = sqrt((1 - 1/lambda)^2 - (eps/lambda)^2)
    const double s_a = l1 * std::sqrt(std::pow(1 + 1 / lambda, 2) - std::pow(eps / lambda, 2));
    const double s_i = l1 * std::sqrt(std::pow(1 - 1 / lambda, 2) - std::pow(eps / lambda, 2));
    CHECK(r.s_a == Approx(s_a).margin(kRefined));
    CHECK(r.s_i == Approx(s_i).margin(kRefined));
    CHECK(r.stroke == Approx(s_a - s_i).margin(kRefined));
    const double phi_h = phi_i - phi_a;  // phi_H = phi_i - phi_a (positive sense)
    CHECK(r.phi_h == Approx(phi_h).margin(kRefined));
    CHECK(r.phase_ratio == Approx(phi_h / (2 * kPi - phi_h)).margin(kPhaseRatio));
    // the document: phase ratio 1 for e = 0, > 1 for a positive offset, < 1 for a negative one
    if (e == 0) CHECK(r.phase_ratio == Approx(1.0).margin(kPhaseRatio));
    if (e > 0) CHECK(r.phase_ratio > 1.0);
    if (e < 0) CHECK(r.phase_ratio < 1.0);
    for (const DeadCentre& d : r.points) {
      CHECK((d.kind == DeadCentreKind::kExtended) == (std::abs(d.input - phi_a) < 1e-9));
      CHECK((d.kind == DeadCentreKind::kFolded) == (std::abs(d.input - phi_i) < 1e-9));
    }
  }
}

TEST_CASE("transmission angle: mu = 90 deg - |psi| and its minimum (seed 000)", "[deadcentres]") {
  for (double e : {0.0, 0.8}) {
    const Mechanism m = test::SliderCrank(1.0, 2.6, e);
    SweepOptions range;
    range.from = 0;
    range.to = 2 * kPi;
    range.step = DegToRad(2);
    const SweepResult sweep = Sweep(m, range);
    REQUIRE(sweep.complete());
    double mu_min = 10, at = -1;
    for (size_t i = 0; i < sweep.inputs.size(); ++i) {
      CHECK(sweep.outputs(i, 3) == Approx(test::SliderCrank(1.0, 2.6, e, sweep.inputs[i]).mu).margin(kSweptMu));
      if (sweep.outputs(i, 3) < mu_min - 1e-12) {
        mu_min = sweep.outputs(i, 3);
        at = sweep.inputs[i];
      }
    }
    // mu_min = 90 deg - arcsin(lambda + eps), at phi = 0 (e = 0: also at 180 deg, arccos(l1/l2))
    CHECK(mu_min == Approx(kPi / 2 - std::asin(1 / 2.6 + e / 2.6)).margin(kSweptMu));
    CHECK(at == 0.0);
    if (e == 0) CHECK(mu_min == Approx(std::acos(1 / 2.6)).margin(kSweptMu));
  }
}

TEST_CASE("a crank-rocker's rocker dead centres are classified", "[deadcentres]") {
  const double l23 = 2.5 * std::sqrt(3.0);
  const Mechanism m = test::FourBar(1.0, l23, l23, 4.0, 1.0, 0.0, 1);
  SweepOptions range;
  range.from = 0;
  range.to = 2 * kPi;
  range.step = DegToRad(3);
  const DeadCentreReport r = FindDeadCentres(m, 1, 0, range);  // psi, the rocker angle
  REQUIRE(r.points.size() == 2);
  CHECK(r.classified);
  // swing angle psi_0 from the law of cosines at A0B = l2 + l1 and l2 - l1
  auto psi = [&](double a0b) { return kPi - std::acos((16 + l23 * l23 - a0b * a0b) / (8 * l23)); };
  CHECK(r.stroke == Approx(std::abs(psi(l23 + 1) - psi(l23 - 1))).margin(kRefined));
}

}  // namespace koppel::dead_centres_test

namespace koppel::dead_centres_test {

// issue 22 item 1: the extended dead centre of a crank-rocker at input 0, put there by the drive's
// zero (zero = phi_a from the law of cosines, the repro-psi file): it was dropped.
TEST_CASE("a dead centre exactly at the start of a whole turn is kept, once", "[deadcentres]") {
  const double a = 1, b = 3, c = 2.5, d = 3;
  const test::CrankRockerDeadCentre extended = test::CrankRockerExtended(a, b, c, d), folded = test::CrankRockerFolded(a, b, c, d);
  Mechanism m = test::FourBar(a, b, c, d, 1.0, 0.0, 1);  // output 1: psi
  m.hint.points.clear();
  HintPoint(m, "coupler", "B", test::FourBarRocker(a, b, c, d, 0.0, 1)->b);
  m.drive.zero = extended.phi;
  m.hint.input = -extended.phi;  // the hint's pose is at crank angle 0
  for (const auto& [from, to] : {std::pair{0.0, 2 * kPi}, std::pair{2 * kPi, 0.0}, std::pair{-2 * kPi, 0.0}}) {
    INFO("from " << from << " to " << to);
    SweepOptions range;
    range.from = from;
    range.to = to;
    range.step = DegToRad(1);
    const DeadCentreReport r = FindDeadCentres(m, 1, 0, range);
    REQUIRE(r.status == AnalysisStatus::kComplete);
    REQUIRE(r.points.size() == 2);
    REQUIRE(r.classified);
    // reported in the range's first turn: the extended one at its start (within 1e-9 below it)
    const double start = std::min(from, to);
    CHECK(std::abs(r.phi_a - start) < 1e-9);
    CHECK(std::abs(r.phi_i - (start + folded.phi - extended.phi)) < kRefined);
    // psi_a = 87.1340160174 deg, stroke 51.4563618 deg (the truth, by the law of cosines)
    CHECK(std::abs(r.s_a - extended.psi) < kRefined);
    CHECK(std::abs(r.stroke - std::abs(folded.psi - extended.psi)) < kRefined);
    CHECK(RadToDeg(r.s_a) == Approx(87.1340160174).margin(kDocumentDeg));
    CHECK(RadToDeg(r.stroke) == Approx(51.4563618).margin(kDocumentStrokeDeg));
  }
}

// The same dead centre at the start and at the end of a part of the turn.
TEST_CASE("a dead centre exactly at either end of part of a turn is kept", "[deadcentres]") {
  const double l1 = 1, l2 = 2.6, e = 0.8;
  const Mechanism m = test::SliderCrank(l1, l2, e);
  const double phi_a = test::SliderCrankPhiA(l1, l2, e);
  for (const auto& [from, to] : {std::pair{phi_a, phi_a + 2.0}, std::pair{phi_a - 2.0, phi_a}, std::pair{phi_a, phi_a - 1.0}}) {
    INFO("from " << from << " to " << to);
    SweepOptions range;
    range.from = from;
    range.to = to;
    range.step = DegToRad(3);  // 2 rad is not a whole number of steps: the end is searched too
    const DeadCentreReport r = FindDeadCentres(m, 0, 0, range);
    REQUIRE(r.status == AnalysisStatus::kComplete);
    REQUIRE(r.points.size() == 1);
    CHECK(std::abs(r.points[0].input - phi_a) < 1e-9);
    CHECK(r.points[0].kind == DeadCentreKind::kExtended);
  }
}

// A sign change of y' that is no dead centre: the distance |A X| from a frame point X on the
// crank circle has a kink (|A X| = 2 a |sin(phi/2)|) at phi = 0, where y' jumps from -a to +a.
TEST_CASE("a sign change of y' that does not refine is reported, not dropped", "[deadcentres]") {
  Mechanism m = test::PlainFourBar(1, 3.5, 3, 4, 0.5, test::FourBarRocker(1, 3.5, 3, 4, 0.5, 1)->b);
  m.links[0].points.push_back({"X", {1, 0}});  // on the frame, where the crank's A passes at phi = 0
  DistanceOutput(m, "AX", "crank", "A", "frame", "X");  // output 2
  SweepOptions range;
  range.from = DegToRad(0.5);  // no sample on the kink itself
  range.to = range.from + 2 * kPi;
  range.step = DegToRad(1);
  const DeadCentreReport r = FindDeadCentres(m, 2, 0, range);
  // the maximum 2a at phi = 180 deg is a dead centre; the kink is not, and is named
  REQUIRE(r.points.size() == 1);
  CHECK(std::abs(AngleDifference(r.points[0].input, kPi)) < kRefined);
  REQUIRE(r.unresolved.size() == 1);
  CHECK(std::abs(AngleDifference(r.unresolved[0], 0.0)) < DegToRad(1));
  CHECK_THAT(r.message, Catch::Contains("not refined"));
  CHECK(r.extremes.status == AnalysisStatus::kFailed);
}

}  // namespace koppel::dead_centres_test
