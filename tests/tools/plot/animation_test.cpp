// The frames of an animation: one per input of the cycle, each with the parts at that pose, the
// curves drawn up to the frame. References: the circle-intersection four-bar of seed 003
// (tests/support/closed_forms) at each frame's crank angle.
#include "koppel/plot/animation.hpp"

#include "tools/plot/cycle_fixtures.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/limits.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::animation_test {
namespace {

// [rad] a frame's input is from + i step, computed once: rounding only
constexpr double kFrameInput = 1e-12;

// The solver converges to 1e-12 of the length scale.
constexpr double kTolerance = 1e-9;

plot::AnimationOptions Options(const Mechanism& m, int frames) {
  return {test::CycleOptionsFor(m), frames};
}

}  // namespace

TEST_CASE("animation of seed 003: 36 frames, 10 deg apart, the crank at its angle", "[plot][animation]") {
  const Mechanism m = test::MzcCrankRocker();
  const plot::AnimationScene scene = plot::AnimateCycle(m, Options(m, 36));
  REQUIRE(scene.status == plot::PlotStatus::kComplete);
  REQUIRE(scene.frames.size() == 36);
  for (int i = 0; i < 36; ++i) {
    const plot::AnimationFrame& f = scene.frames[i];
    const double phi = DegToRad(10.0 * i);
    CHECK_THAT(f.input, Catch::Matchers::WithinAbs(phi, kFrameInput));
    CHECK(f.traced_up_to == f.input);
    bool b = false;
    for (const plot::Part& p : f.parts)
      for (const plot::Hole& h : p.holes) b |= p.link == "rocker" && (h.centre - test::MzcB(phi)).norm() < kTolerance;
    CHECK(b);
  }
  CHECK_THAT(scene.frames[3].caption, Catch::Contains("φ = 30°"));
}

TEST_CASE("animation options: frames within the limit", "[plot][animation]") {
  const Mechanism m = test::MzcCrankRocker();
  std::string why;
  CHECK_FALSE(Options(m, 0).IsValid(&why));
  CHECK_THAT(why, Catch::Contains("kMaxAnimationFrames"));
  CHECK_FALSE(Options(m, kMaxAnimationFrames + 1).IsValid(&why));
  CHECK(Options(m, kMaxAnimationFrames).IsValid(&why));
  CHECK_THROWS_AS(plot::AnimateCycle(m, Options(m, 0)), std::invalid_argument);
}

}  // namespace koppel::animation_test

namespace koppel::animation_test {

TEST_CASE("animation of a parallelogram: frames at its branch points have their poses", "[plot][animation]") {
  // the crank lines up with the frame at 0 and 180 deg: branch points the sweep passes through,
  // where a walk cannot stop; those frames take the sweep's own pose (A at (cos phi, sin phi))
  const Mechanism m = test::PlainFourBar(1, 3, 1, 3, kPi / 2, {3, 1});
  const plot::AnimationScene scene = plot::AnimateCycle(m, {test::CycleOptionsFor(m), 24});
  CHECK(scene.status == plot::PlotStatus::kComplete);
  INFO(scene.message);
  REQUIRE(scene.frames.size() == 24);
  for (const plot::AnimationFrame& f : {scene.frames[0], scene.frames[12]})
    for (const plot::Part& p : f.parts)
      if (p.link == "crank") {
        bool a = false;
        for (const plot::Hole& h : p.holes) a |= (h.centre - Eigen::Vector2d(std::cos(f.input), std::sin(f.input))).norm() < kTolerance;
        CHECK(a);
      }
}

}  // namespace koppel::animation_test
