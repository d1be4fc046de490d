// DesignSpace (solver/synthesis/src/design_space.cpp): each constraint against hand-made
// four-bars whose lengths, pivots and Grashof type are known by construction.
#include "koppel/synthesis/design_space.hpp"

#include <catch2/catch.hpp>

namespace koppel::design_space_test {

namespace {
// crank 1, coupler 3.5, rocker 3, frame 4 (A0 at the origin, B0 at (4, 0)): Grashof, crank shortest
FourBarSizes CrankRocker() { return {{0, 0}, {4, 0}, 1, 3.5, 3}; }
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
  CHECK_THAT(crank.Violation({{0, 0}, {4, 0}, 3, 3.5, 1}), Catch::Contains("does not turn fully"));
  // non-Grashof (3 + 5 > 4 + 2.5: the triple-rocker of the catalog)
  CHECK_THAT(crank.Violation({{0, 0}, {5, 0}, 3, 4, 2.5}), Catch::Contains("does not turn fully"));
  // the frame shortest: a double crank turns fully
  CHECK(crank.Violation({{0, 0}, {1, 0}, 3, 3.5, 4}).empty());
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

}  // namespace koppel::design_space_test
