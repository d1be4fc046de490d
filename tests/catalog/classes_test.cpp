// Catalog classes and motion words: the structural classes follow from the joint graph (Watt's
// six-bar: the two ternary links jointed to each other; Stephenson's: not), a declared class
// the graph contradicts is reported, and motion queries match side by side.
#include "koppel/catalog/classes.hpp"

#include "koppel/catalog/mechanism_file.hpp"
#include "support/mechanisms.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

namespace koppel::classes_test {
namespace {

bool HasClass(const std::vector<std::string>& classes, const std::string& c) {
  return std::find(classes.begin(), classes.end(), c) != classes.end();
}

// A link with the named points at the origin (the chain is what matters here).
Link Named(const std::string& name, std::initializer_list<const char*> points, bool frame = false) {
  Link l;
  l.name = name;
  l.is_frame = frame;
  for (const char* p : points) l.points.push_back({p, Eigen::Vector2d::Zero()});
  return l;
}

// Stephenson's chain: a four-bar A0 A B B0 whose coupler carries a dyad C D to the frame pivot D0;
// the ternary links (frame and coupler) are not jointed to each other.
Mechanism Stephenson() {
  Mechanism m;
  m.links = {Named("frame", {"A0", "B0", "D0"}, true), Named("crank", {"A0", "A"}), Named("coupler", {"A", "B", "C"}),
             Named("rocker", {"B0", "B"}),             Named("link5", {"C", "D"}),   Named("link6", {"D0", "D"})};
  m.joints = {PinJoint(m, "A0", 0, 1), PinJoint(m, "A", 1, 2), PinJoint(m, "B", 2, 3), PinJoint(m, "B0", 0, 3),
              PinJoint(m, "C", 2, 4),  PinJoint(m, "D", 4, 5), PinJoint(m, "D0", 0, 5)};
  m.drive.joint = 0;
  return m;
}

}  // namespace

TEST_CASE("structural classes follow from the joint graph", "[catalog][classes]") {
  const std::vector<std::string> four_bar = StructuralClasses(test::FourBar(1, 3, 2.5, 3, 0, 0, 1));
  CHECK(HasClass(four_bar, "four-bar"));
  CHECK_FALSE(HasClass(four_bar, "slider-crank-chain"));
  const std::vector<std::string> slider_crank = StructuralClasses(test::SliderCrank(1, 2.6, 0.8));
  CHECK(HasClass(slider_crank, "slider-crank-chain"));
  CHECK(HasClass(slider_crank, "slider-crank"));  // the slide is on the frame
  CHECK_FALSE(HasClass(slider_crank, "moving-slider"));
  // seed 001: two ternary links (frame, slotted link) jointed at B0 -> Watt; S34 between moving links
  const std::vector<std::string> proportional = StructuralClasses(test::ProportionalLinkage(1, 0.5, 1.83));
  CHECK(HasClass(proportional, "watt-six-bar"));
  CHECK(HasClass(proportional, "moving-slider"));
  const std::vector<std::string> watt = StructuralClasses(test::WattSixBar());
  CHECK(HasClass(watt, "watt-six-bar"));
  CHECK_FALSE(HasClass(watt, "stephenson-six-bar"));
  const std::vector<std::string> stephenson = StructuralClasses(Stephenson());
  CHECK(HasClass(stephenson, "stephenson-six-bar"));
  CHECK_FALSE(HasClass(stephenson, "watt-six-bar"));
}

TEST_CASE("a declared structural class the graph contradicts is a problem", "[catalog][classes]") {
  CHECK(ClassProblems(Stephenson(), {"stephenson-six-bar", "quick-return"}).empty());
  const std::vector<std::string> p = ClassProblems(Stephenson(), {"watt-six-bar"});
  REQUIRE(p.size() == 1);
  CHECK_THAT(p[0], Catch::Contains("watt-six-bar"));
  CHECK(ClassProblems(test::SliderCrank(1, 2.6, 0.8), {"four-bar"}).size() == 1);
  CHECK(ClassProblems(test::FourBar(1, 3, 2.5, 3, 0, 0, 1), {"moving-slider"}).size() == 1);
  // behavioural classes are proved by figures, not by the graph
  CHECK(ClassProblems(test::FourBar(1, 3, 2.5, 3, 0, 0, 1), {"crank-rocker", "toggle"}).empty());
  // a Grashof type is the four-bar's lengths': s + l = 1 + 3 < p + q = 2.5 + 3, the crank shortest
  const std::vector<std::string> grashof = ClassProblems(test::FourBar(1, 3, 2.5, 3, 0, 0, 1), {"double-crank"});
  REQUIRE(grashof.size() == 1);
  CHECK_THAT(grashof[0], Catch::Contains("is a crank-rocker"));
  // the frame shortest (1 + 3.5 < 2.5 + 3): a double crank; s + l > p + q: a triple rocker
  CHECK(ClassProblems(test::FourBar(2.5, 3, 3.5, 1, 0, 0, 1), {"double-crank"}).empty());
  CHECK(ClassProblems(test::FourBar(3, 4, 2.5, 5, 0, 0, 1), {"triple-rocker"}).empty());
  CHECK(ClassProblems(test::SliderCrank(1, 2.6, 0.8), {"crank-rocker"}).size() == 1);
  for (const CatalogClass& c : CatalogClasses()) CHECK(IsCatalogClass(c.name));
  CHECK_FALSE(IsCatalogClass("crank rocker"));
}

TEST_CASE("motion words: the form is checked and queries match side by side", "[catalog][classes]") {
  CHECK(MotionProblem("full rotation -> oscillating translation").empty());
  CHECK(MotionProblem("full rotation -> straight-line guidance of a coupler point (approximate)").empty());
  CHECK_THAT(MotionProblem("full rotation to translation"), Catch::Contains("->"));
  CHECK_THAT(MotionProblem("rotation -> translation"), Catch::Contains("input motion 'rotation'"));
  CHECK_THAT(MotionProblem("full rotation -> oscillatingtranslation"), Catch::Contains("does not start with"));
  const std::string motion = "full rotation -> oscillating translation with a proportional range";
  CHECK(MotionMatches(motion, "rotation -> oscillating translation"));
  CHECK(MotionMatches(motion, "Rotation->Translation"));
  CHECK(MotionMatches(motion, "translation"));  // one word: either side
  CHECK_FALSE(MotionMatches(motion, "translation -> rotation"));
  CHECK_FALSE(MotionMatches(motion, "rotation -> oscillating rotation"));
}

}  // namespace koppel::classes_test
