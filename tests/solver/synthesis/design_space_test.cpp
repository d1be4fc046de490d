// DesignSpace (solver/synthesis/src/design_space.cpp): each constraint against hand-made
// four-bars whose lengths, pivots and Grashof type are known by construction.
#include "koppel/synthesis/design_space.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

namespace koppel::design_space_test {

namespace {
// crank 1, coupler 3.5, rocker 3, frame 4 (A0 at the origin, B0 at (4, 0)): Grashof, crank shortest
FourBarSizes CrankRocker() { return {{0, 0}, {4, 0}, 1, 3.5, 3, Eigen::Vector2d(1, 0.5), std::nullopt}; }  // K 1 along A -> B, 0.5 left
}  // namespace

TEST_CASE("DesignSpace: each constraint names what a four-bar breaks", "[synthesis][design-space]") {
  DesignSpace none;
  CHECK(none.Empty());
  CHECK(none.Violation(CrankRocker()).empty());

  DesignSpace lengths;
  lengths.lengths = std::make_pair(0.5, 3.6);
  CHECK_THAT(lengths.Violation(CrankRocker()), Catch::Contains("the frame is 4") && Catch::Contains("beyond 3.6"));
  lengths.lengths = std::make_pair(1.5, 10.0);
  CHECK_THAT(lengths.Violation(CrankRocker()), Catch::Contains("the crank is 1") && Catch::Contains("below 1.5"));

  DesignSpace ratio;
  ratio.ratio = 3.9;  // frame / crank = 4
  CHECK_THAT(ratio.Violation(CrankRocker()), Catch::Contains("ratio: the frame (4) is 4 times the crank (1)"));
  ratio.ratio = 4;
  CHECK(ratio.Violation(CrankRocker()).empty());

  DesignSpace pivots;
  pivots.pivots_x = std::make_pair(-1.0, 3.0);
  CHECK_THAT(pivots.Violation(CrankRocker()), Catch::Contains("B0 at x = 4"));
  pivots.pivots_x = std::make_pair(-1.0, 5.0);
  pivots.pivots_y = std::make_pair(0.5, 1.0);
  CHECK_THAT(pivots.Violation(CrankRocker()), Catch::Contains("A0 at y = 0"));

  DesignSpace crank;
  crank.input = InputTurn::kCrank;
  CHECK(crank.Violation(CrankRocker()).empty());
  // the rocker shortest: a Grashof rocker-crank, whose input at A0 only rocks
  CHECK_THAT(crank.Violation({{0, 0}, {4, 0}, 3, 3.5, 1, std::nullopt, std::nullopt}), Catch::Contains("does not turn fully"));
  // non-Grashof (3 + 5 > 4 + 2.5: the triple-rocker of the catalog)
  CHECK_THAT(crank.Violation({{0, 0}, {5, 0}, 3, 4, 2.5, std::nullopt, std::nullopt}), Catch::Contains("does not turn fully"));
  // the frame shortest: a double crank turns fully
  CHECK(crank.Violation({{0, 0}, {1, 0}, 3, 3.5, 4, std::nullopt, std::nullopt}).empty());

  // A0 and the frame angle fixed: held to kFixedTolerance of the longest link (4 here)
  DesignSpace fixed;
  fixed.a0 = Eigen::Vector2d(0, 0);
  fixed.frame_angle = 0;
  CHECK(fixed.Violation(CrankRocker()).empty());
  fixed.a0 = Eigen::Vector2d(0, 1e-8);  // 2.5e-9 of the longest link: beyond 1e-9
  CHECK_THAT(fixed.Violation(CrankRocker()), Catch::Contains("A0: at (0, 0), not at the fixed (0, 1e-08)"));
  fixed.a0.reset();
  fixed.frame_angle = DegToRad(90);
  CHECK_THAT(fixed.Violation(CrankRocker()), Catch::Contains("frame_angle: the frame line A0 -> B0 is at 0 deg, not at the fixed 90 deg"));
  // B0 at (4, 0) seen from A0: the angle 0 and 360 deg are the same line
  fixed.frame_angle = DegToRad(360);
  CHECK(fixed.Violation(CrankRocker()).empty());

  // K's coordinates in the coupler's frame (1 along, 0.5 left)
  DesignSpace k;
  k.coupler_point = std::make_pair(0.0, 0.9);
  CHECK_THAT(k.Violation(CrankRocker()), Catch::Contains("coupler_point: K lies 1 along A -> B, outside [0, 0.9]"));
  k.coupler_point = std::make_pair(0.6, 2.0);
  CHECK_THAT(k.Violation(CrankRocker()), Catch::Contains("coupler_point: K lies 0.5 left of A -> B, outside [0.6, 2]"));
  k.coupler_point = std::make_pair(0.5, 1.0);
  CHECK(k.Violation(CrankRocker()).empty());
}

TEST_CASE("DesignSpace::IsValid refuses a space no design fits", "[synthesis][design-space]") {
  std::string why;
  DesignSpace s;
  s.lengths = std::make_pair(2.0, 1.0);
  CHECK_FALSE(s.IsValid(&why));
  CHECK_THAT(why, Catch::Contains("lengths"));
  s.lengths.reset();
  s.ratio = 0.9;
  CHECK_FALSE(s.IsValid(&why));
  s.ratio = 1;
  CHECK(s.IsValid(&why));
}

TEST_CASE("DesignSpace::Unsupported names a key a synthesis cannot keep", "[synthesis][design-space]") {
  DesignSpace space;
  space.lengths = std::make_pair(0.0, 1.0);
  CHECK(space.Unsupported("synth function", false, false).empty());
  space.coupler_point = std::make_pair(-1.0, 1.0);
  CHECK(space.Unsupported("synth function", false, false) == "coupler_point: synth function designs no coupler point");
  CHECK(space.Unsupported("synth motion", true, false).empty());
  space.frame_angle = 0;
  CHECK_THAT(space.Unsupported("synth motion", true, false), Catch::Contains("frame_angle: synth motion places its frame itself"));
  space.a0 = Eigen::Vector2d(0, 0);
  CHECK_THAT(space.Unsupported("synth motion", true, false), Catch::Contains("A0: synth motion places its frame itself"));
  CHECK(space.Unsupported("synth path", true, true).empty());
}

}  // namespace koppel::design_space_test
