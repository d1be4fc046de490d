// Structural analysis from the joint graph: link degrees, joint types, Grübler–Kutzbach,
// drive at the frame, output links, the crank length; and the consistency check of a model.
#include "koppel/core/structure.hpp"

#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

namespace koppel::structure_test {

TEST_CASE("seed 001's structure: 6 links (4 binary, 2 ternary), 7 joints (4 D, 3 S)", "[structure]") {
  const Mechanism m = test::ProportionalLinkage(1.0, 0.5, 1.83);
  const StructureSummary s = AnalyseStructure(m);
  CHECK(s.links == 6);
  CHECK(s.links_by_degree.at(2) == 4);
  CHECK(s.links_by_degree.at(3) == 2);
  CHECK(s.joints == 7);
  CHECK(s.revolute == 4);
  CHECK(s.prismatic == 3);
  CHECK(s.gruebler_mobility == 1);
  CHECK(s.drive_joints == 1);
  CHECK(s.drive_joints_at_frame == 1);
  CHECK_THAT(s.formula, Catch::Contains("A0: D frame-crank (drive)") && Catch::Contains("S34: S slot-block4"));
  CHECK(OutputLink(m, m.outputs[0]) == m.FindLink("slider"));
  CHECK(CrankLength(m) == 0.5);
}

TEST_CASE("a four-bar driven at the rocker still has its drive at the frame; degree names", "[structure]") {
  const Mechanism m = test::FourBar(1, 4, 4, 4, 1, 0, 1, true);
  CHECK(AnalyseStructure(m).drive_joints_at_frame == 1);
  CHECK(DegreeName(2) == "binary");
  CHECK(DegreeName(4) == "quaternary");
  CHECK(DegreeName(9) == "9-ary");
}

TEST_CASE("consistency check names each problem", "[structure]") {
  Mechanism m = test::SliderCrank(1, 2.6, 0.8);
  CHECK(CheckConsistency(m).empty());
  m.joints[3].axis = {2, 0};  // not a unit vector
  m.links[1].is_frame = true;  // a second frame
  m.outputs[0].joint = 17;
  const auto problems = CheckConsistency(m);
  CHECK(problems.size() == 3);
}

}  // namespace koppel::structure_test
