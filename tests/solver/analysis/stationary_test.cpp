// Stationary points of an output: the dead centres of seed 000's slider-crank against the
// document's phi_a and the corrected phi_i, refined to 1e-12.
#include "koppel/analysis/stationary.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

namespace koppel::stationary_test {

// [length] the slider's extreme positions sqrt((l2 +- l1)^2 - e^2) against the refined stationary
// point, where s is flat: its input error enters squared
constexpr double kStroke = 1e-12;

TEST_CASE("slider-crank dead centres: phi_a and phi_i to 1e-12 from nearby samples", "[stationary]") {
  for (double e : {0.0, 0.8, -0.8}) {
    const Mechanism m = test::SliderCrank(1.0, 2.6, e);
    SweepOptions o;
    o.from = 0;
    o.to = 2 * kPi;
    o.step = DegToRad(5);
    const SweepResult r = Sweep(m, o);
    REQUIRE(r.complete());
    // start from the samples nearest to the closed-form answers (about 2 deg away at most)
    for (const auto& [expected, maximum] : {std::pair{test::SliderCrankPhiA(1.0, 2.6, e), true},
                                            std::pair{test::SliderCrankPhiI(1.0, 2.6, e), false}}) {
      const int i = static_cast<int>(std::lround(expected / o.step));
      const StationaryPoint p = RefineStationary(m, 0, 0, r.inputs[i], r.poses.row(i).transpose());
      INFO("e = " << e << ", expected " << RadToDeg(expected) << " deg: " << p.message);
      REQUIRE(p.ok());
      CHECK(std::abs(p.input - expected) < 1e-12);
      CHECK((maximum ? p.second < 0 : p.second > 0));
      // the value: s_a = sqrt((l1 + l2)^2 - e^2), s_i = sqrt((l2 - l1)^2 - e^2) (seed 000)
      const double s = maximum ? std::sqrt(3.6 * 3.6 - e * e) : std::sqrt(1.6 * 1.6 - e * e);
      CHECK(p.value == Approx(s).margin(kStroke));
    }
  }
}

TEST_CASE("no stationary point where the output is monotonic", "[stationary]") {
  // the crank angle itself, as an output of the crank-driven four-bar, has y' = 1 everywhere
  const Mechanism m = test::FourBar(1.0, 4.0, 4.0, 4.0, 1.0, 0.0, 1);
  SweepOptions o;
  o.from = o.to = 0.5;
  const SweepResult r = Sweep(m, o);
  REQUIRE(r.complete());
  const StationaryPoint p = RefineStationary(m, 2, 0, r.inputs[0], r.poses.row(0).transpose());
  CHECK_FALSE(p.ok());
  CHECK(p.status == AnalysisStatus::kFailed);
  CHECK_FALSE(p.message.empty());
}

}  // namespace koppel::stationary_test
