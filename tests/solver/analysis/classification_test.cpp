// Grashof types of four-bars and slider-cranks with their inequalities worked by hand, the drive
// rotation, and mobility by count and by rank (a five-bar with one drive; a parallelogram with a
// redundant link).
#include "koppel/analysis/classification.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/assembly.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

namespace koppel::classification_test {
namespace {

// a link length read off the mechanism's points (a difference of O(1) coordinates): an ulp
constexpr double kLengthRoundoff = 1e-15;

Mechanism FourBar(double a, double b, double c, double d) {
  const auto pose = test::FourBarRocker(a, b, c, d, DegToRad(75), 1);
  return test::PlainFourBar(a, b, c, d, DegToRad(75), pose ? pose->b : Eigen::Vector2d(d, b));
}

double Length(const Classification& c, const std::string& name) {
  for (const auto& [n, v] : c.lengths) {
    if (n == name) return v;
  }
  return -1;
}

}  // namespace

TEST_CASE("four-bars of every Grashof type", "[classification]") {
  // crank 1, coupler 3.5, rocker 3, frame 4: s + l = 1 + 4 = 5 < p + q = 3 + 3.5 = 6.5, shortest
  // is the crank, next to the frame
  const Classification crank_rocker = Classify(FourBar(1, 3.5, 3, 4));
  CHECK(crank_rocker.grashof == GrashofType::kCrankRocker);
  CHECK(Length(crank_rocker, "s") == 1);
  CHECK(Length(crank_rocker, "l") == 4);
  CHECK_THAT(crank_rocker.rule, Catch::Contains("5 < p + q") && Catch::Contains("'crank'"));
  CHECK(crank_rocker.drive_turns_fully);
  CHECK(crank_rocker.rank_mobility == 1);
  // frame 1 shortest: 1 + 3 = 4 < 2 + 2.5 = 4.5
  CHECK(ClassifyChain(FourBar(2, 3, 2.5, 1)).grashof == GrashofType::kDoubleCrank);
  // coupler 1 shortest: 1 + 4 = 5 < 3 + 3.5 = 6.5
  const Classification double_rocker = Classify(FourBar(3, 1, 3.5, 4));
  CHECK(double_rocker.grashof == GrashofType::kDoubleRocker);
  CHECK_FALSE(double_rocker.drive_turns_fully);
  // 2 + 4 = 6 > 2.5 + 3 = 5.5
  CHECK(ClassifyChain(FourBar(2, 3, 2.5, 4)).grashof == GrashofType::kTripleRocker);
  // 1 + 3 = 1 + 3: the parallelogram
  const Classification neutral = ClassifyChain(test::PlainFourBar(1, 3, 1, 3, 1.0, {3, 1}));
  CHECK(neutral.grashof == GrashofType::kChangePoint);
  CHECK_THAT(neutral.rule, Catch::Contains("Grashof-neutral"));
}

TEST_CASE("slider-cranks: crank-slider, rocker-slider, change-point", "[classification]") {
  // crank 1, offset 0.8: a + |e| = 1.8 against the coupler
  CHECK(ClassifyChain(test::SliderCrank(1, 2.6, 0.8)).grashof == GrashofType::kCrankSlider);
  CHECK(ClassifyChain(test::SliderCrank(1, 1.5, 0.8)).grashof == GrashofType::kRockerSlider);
  const Classification neutral = ClassifyChain(test::SliderCrank(1, 1.8, 0.8));
  CHECK(neutral.grashof == GrashofType::kChangePoint);
  CHECK(std::abs(Length(neutral, "e")) == Approx(0.8).margin(kLengthRoundoff));
  CHECK(Length(neutral, "a") == 1);
  CHECK(Length(neutral, "b") == Approx(1.8).margin(kLengthRoundoff));
  // the six-link proportional linkage is neither
  CHECK(ClassifyChain(test::ProportionalLinkage(1, 0.5, 1.83)).grashof == GrashofType::kNotApplicable);
}

TEST_CASE("mobility: a five-bar with one drive is refused naming both numbers; a redundant link is accepted", "[classification]") {
  const MobilityReport five = CheckMobility(test::FiveBar());
  CHECK(five.gruebler == 2);
  CHECK(five.rank_mobility == 2);
  CHECK_FALSE(five.ok());
  CHECK_THAT(five.error, Catch::Contains("mobility 2") && Catch::Contains("1 drive"));

  const MobilityReport redundant = CheckMobility(test::RedundantParallelogram());
  CHECK(redundant.gruebler == 0);
  CHECK(redundant.rank_mobility == 1);
  CHECK(redundant.ok());
  CHECK_THAT(redundant.note, Catch::Contains("overconstrained") && Catch::Contains("E0"));

  const MobilityReport plain = CheckMobility(test::SliderCrank(1, 2.6, 0.8));
  CHECK(plain.ok());
  CHECK(plain.note.empty());
  CHECK(plain.gruebler == 1);
  CHECK(plain.rank_mobility == 1);
}

}  // namespace koppel::classification_test
