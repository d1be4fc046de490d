// Dead centres and transmission angle of seed 000's slider-crank against the document's
// formulas (phi_i with the corrected 3/2 pi), for both offsets and the negative one.
#include "koppel/analysis/dead_centres.hpp"

#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel {
namespace {
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
    CHECK(r.phase_ratio == Approx(phi_h / (2 * kPi - phi_h)).margin(1e-10));
    // the document: phase ratio 1 for e = 0, > 1 for a positive offset, < 1 for a negative one
    if (e == 0) CHECK(r.phase_ratio == Approx(1.0).margin(1e-10));
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
      CHECK(sweep.outputs(i, 3) == Approx(test::SliderCrank(1.0, 2.6, e, sweep.inputs[i]).mu).margin(1e-12));
      if (sweep.outputs(i, 3) < mu_min - 1e-12) {
        mu_min = sweep.outputs(i, 3);
        at = sweep.inputs[i];
      }
    }
    // mu_min = 90 deg - arcsin(lambda + eps), at phi = 0 (e = 0: also at 180 deg, arccos(l1/l2))
    CHECK(mu_min == Approx(kPi / 2 - std::asin(1 / 2.6 + e / 2.6)).margin(1e-12));
    CHECK(at == 0.0);
    if (e == 0) CHECK(mu_min == Approx(std::acos(1 / 2.6)).margin(1e-12));
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
  CHECK(r.stroke == Approx(std::abs(psi(l23 + 1) - psi(l23 - 1))).margin(1e-11));
}

}  // namespace koppel
