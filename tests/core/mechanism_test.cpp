// The mechanism model's own rules (core/src/mechanism.cpp): look-ups by name, the unit of every
// output kind, joints of binary links, the consistency check, the mirror image and the length
// scale. References: the conventions stated in mechanism.hpp, and a slider-crank and a four-bar
// built by name (tests/support/mechanisms.cpp) whose indices are known.
#include "koppel/core/mechanism.hpp"

#include "koppel/core/build.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace koppel::mechanism_test {
namespace {

// relative: the length scale is the longest distance of the points, one sqrt: a few ulps
constexpr double kUlps = 1e-15;

using Catch::Matchers::Contains;

// Every output kind once on a slider-crank: the unit of each is fixed by the convention.
Mechanism WithEveryOutput() {
  Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);  // outputs s (P joint) and mu
  JointOutput(m, "phi_joint", "A0");
  LinkAngleOutput(m, "theta", "coupler");
  PointOutput(m, "B", "coupler", "B");
  DistanceOutput(m, "AB", "crank", "A", "slider", "B");
  DirectionOutput(m, "AB_dir", "crank", "A", "slider", "B");
  return m;
}

TEST_CASE("look-ups by name give the index or -1", "[mechanism]") {
  const Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  CHECK(m.FindLink("frame") == 0);
  CHECK(m.FindLink("slider") == 3);
  CHECK(m.FindLink("Slider") == -1);  // names are case-sensitive, as in the files
  CHECK(m.FindJoint("S") == 3);
  CHECK(m.FindJoint("C") == -1);
  CHECK(m.FindOutput("mu") == 1);
  CHECK(m.FindOutput("psi") == -1);
  CHECK(m.links[2].FindPoint("B") == 1);
  CHECK(m.links[2].FindPoint("K") == -1);
  CHECK(m.FrameLink() == 0);
  Mechanism none = m;
  none.links[0].is_frame = false;
  CHECK(none.FrameLink() == -1);
}

TEST_CASE("the unit of each output: angles for R joints, link angles, directions and mu", "[mechanism]") {
  const Mechanism m = WithEveryOutput();
  auto angle = [&](const std::string& name) { return m.OutputIsAngle(m.FindOutput(name)); };
  CHECK_FALSE(angle("s"));  // a P joint's displacement is a length
  CHECK(angle("mu"));
  CHECK(angle("phi_joint"));  // an R joint's value is an angle
  CHECK(angle("theta"));
  CHECK_FALSE(angle("B"));
  CHECK_FALSE(angle("AB"));
  CHECK(angle("AB_dir"));
  // the drive's unit follows its joint the same way
  CHECK(m.InputIsAngle());
  Mechanism slider_driven = m;
  slider_driven.drive.joint = m.FindJoint("S");
  CHECK_FALSE(slider_driven.InputIsAngle());
}

TEST_CASE("joints of a link: the point a joint has on it, the other joint of a binary link", "[mechanism]") {
  const Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  const int coupler = m.FindLink("coupler"), a = m.FindJoint("A"), b = m.FindJoint("B");
  const PointRef on_coupler = JointPointOn(m.joints[a], coupler);
  CHECK(on_coupler.link == coupler);
  CHECK(m.links[coupler].points[on_coupler.point].name == "A");
  CHECK(OtherJointOfBinaryLink(m, coupler, a) == b);
  CHECK(OtherJointOfBinaryLink(m, coupler, b) == a);
  // the frame carries A0 and S: binary too; the slider carries B and S
  CHECK(OtherJointOfBinaryLink(m, m.FindLink("frame"), m.FindJoint("A0")) == m.FindJoint("S"));
  // a ternary link has no single other joint
  Mechanism ternary = m;
  ternary.links[coupler].points.push_back({"C", {1, 1}});
  AddLink(ternary, "extra", {{"C", {0, 0}}});
  Revolute(ternary, "C", "coupler", "extra");
  CHECK(OtherJointOfBinaryLink(ternary, coupler, a) == -1);
}

TEST_CASE("PinJoint pins the points of its name, -1 where a link lacks it", "[mechanism]") {
  const Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  const Joint j = PinJoint(m, "A", 1, 2);
  CHECK(j.type == JointType::kRevolute);
  CHECK(j.point_a == m.links[1].FindPoint("A"));
  CHECK(j.point_b == m.links[2].FindPoint("A"));
  CHECK(PinJoint(m, "B", 1, 2).point_a == -1);
}

TEST_CASE("the consistency check names every broken reference", "[mechanism]") {
  const Mechanism good = WithEveryOutput();
  REQUIRE(CheckConsistency(good).empty());
  auto problems_of = [](const Mechanism& m) {
    std::string all;
    for (const std::string& p : CheckConsistency(m)) all += p + "\n";
    return all;
  };
  Mechanism two_frames = good;
  two_frames.links[1].is_frame = true;
  CHECK_THAT(problems_of(two_frames), Contains("exactly one frame link, found 2"));
  Mechanism bad_link = good;
  bad_link.joints[1].link_b = 17;
  CHECK_THAT(problems_of(bad_link), Contains("joint 'A' names a link that does not exist"));
  Mechanism itself = good;
  itself.joints[1].link_b = itself.joints[1].link_a;
  CHECK_THAT(problems_of(itself), Contains("joins link 'crank' to itself"));
  Mechanism bad_point = good;
  bad_point.joints[2].point_a = 9;
  CHECK_THAT(problems_of(bad_point), Contains("joint 'B' names a point that does not exist"));
  Mechanism long_axis = good;
  long_axis.joints[3].axis = {2, 0};
  CHECK_THAT(problems_of(long_axis), Contains("joint 'S' has a slide axis that is not a unit vector"));
  Mechanism no_drive = good;
  no_drive.drive.joint = 4;
  CHECK_THAT(problems_of(no_drive), Contains("the drive names no joint"));
  Mechanism bad_outputs = good;
  bad_outputs.outputs[bad_outputs.FindOutput("s")].joint = -1;
  bad_outputs.outputs[bad_outputs.FindOutput("theta")].link = 8;
  bad_outputs.outputs[bad_outputs.FindOutput("B")].p.point = 5;
  bad_outputs.outputs[bad_outputs.FindOutput("AB")].q.link = -1;
  bad_outputs.outputs[bad_outputs.FindOutput("mu")].link = -1;
  const std::string all = problems_of(bad_outputs);
  CHECK_THAT(all, Contains("output 's' names no joint"));
  CHECK_THAT(all, Contains("output 'theta' names no link"));
  CHECK_THAT(all, Contains("output 'B' names no point"));
  CHECK_THAT(all, Contains("output 'AB' names no point"));
  CHECK_THAT(all, Contains("output 'mu' needs a coupler link and an output joint"));
  Mechanism bad_hint = good;
  bad_hint.hint.points.push_back({{3, 4}, {0, 0}});
  CHECK_THAT(problems_of(bad_hint), Contains("an assembly hint names no point"));
}

TEST_CASE("the mirror image reflects points, hints and senses; twice is the original", "[mechanism]") {
  Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  m.drive.zero = 0.3;
  m.hint.input = 0.7;
  m.joints[3].angle = 0.2;
  m.outputs[0].offset = 0.5;
  const Mechanism mirror = MirrorMechanism(m);
  for (size_t l = 0; l < m.links.size(); ++l) {
    for (size_t p = 0; p < m.links[l].points.size(); ++p) {
      CHECK(mirror.links[l].points[p].local.x() == m.links[l].points[p].local.x());
      CHECK(mirror.links[l].points[p].local.y() == -m.links[l].points[p].local.y());
    }
  }
  CHECK(mirror.drive.zero == -0.3);  // an R drive turns the other way
  CHECK(mirror.hint.input == -0.7);
  CHECK(mirror.joints[3].angle == -0.2);
  CHECK(mirror.hint.points[0].global.y() == -m.hint.points[0].global.y());
  const Mechanism twice = MirrorMechanism(mirror);
  CHECK(twice.drive.zero == m.drive.zero);
  CHECK(twice.links[2].points[1].local == m.links[2].points[1].local);
  CHECK(twice.outputs[0].offset == m.outputs[0].offset);
  // a P drive keeps its displacement's sign: zero and hint input stay
  Mechanism slider_driven = m;
  slider_driven.drive.joint = 3;
  const Mechanism slider_mirror = MirrorMechanism(slider_driven);
  CHECK(slider_mirror.drive.zero == 0.3);
  CHECK(slider_mirror.hint.input == 0.7);
}

TEST_CASE("the length scale is the largest body-frame point distance, without a floor", "[mechanism]") {
  // slider-crank: |A| = l1 on the crank, |B| = l2 on the coupler, |A0| = e on the frame
  CHECK(LengthScale(test::SliderCrank(1.0, 2.6, 0.8)) == Approx(2.6).epsilon(kUlps));
  CHECK(LengthScale(test::SliderCrank(1e-6, 2.6e-6, 0.8e-6)) == Approx(2.6e-6).epsilon(kUlps));
  CHECK(LengthScale(Mechanism()) == 1.0);  // no points at all: a unit scale
}

}  // namespace
}  // namespace koppel::mechanism_test

namespace koppel::mechanism_test {

TEST_CASE("a scalar output by name; no name is the first scalar output", "[mechanism]") {
  // the four-bar's outputs in file order: K (a point: two components), psi, phi, mu
  const Mechanism m = test::FourBar(1, 3, 2.5, 3.2, 1.5, 0.4, 1);
  const Expected<int> first = FindScalarOutput(m, "");
  REQUIRE(first);
  CHECK(m.outputs[*first].name == "psi");  // K is skipped: not scalar
  const Expected<int> mu = FindScalarOutput(m, "mu");
  REQUIRE(mu);
  CHECK(*mu == m.FindOutput("mu"));
  const Expected<int> point = FindScalarOutput(m, "K");
  REQUIRE_FALSE(point);
  CHECK(point.error() == "has no scalar output 'K' (its scalar outputs: psi, phi, mu)");
  Mechanism bare = m;
  bare.outputs.erase(bare.outputs.begin() + 1, bare.outputs.end());  // only the point K is left
  const Expected<int> none = FindScalarOutput(bare, "");
  REQUIRE_FALSE(none);
  CHECK(none.error() == "the mechanism declares no scalar output (outputs: an angle or a distance, see README)");
}

}  // namespace koppel::mechanism_test

namespace koppel::mechanism_component_test {

TEST_CASE("a point's components are named NAME_x and NAME_y, and read back", "[core][mechanism]") {
  CHECK(ComponentName("K", 0) == "K_x");
  CHECK(ComponentName("K", 1) == "K_y");
  for (const char* name : {"K", "coupler_point", "P_x"}) {
    for (int c = 0; c < 2; ++c) {
      const auto split = SplitComponentName(ComponentName(name, c));
      REQUIRE(split);
      CHECK(split->first == name);
      CHECK(split->second == c);
    }
  }
  CHECK_FALSE(SplitComponentName("_x"));
  CHECK_FALSE(SplitComponentName("psi"));
  Output point;
  point.name = "K";
  point.kind = OutputKind::kPoint;
  CHECK(point.ComponentLabel(1) == "K_y");
  Output scalar;
  scalar.name = "psi";
  scalar.kind = OutputKind::kLinkAngle;
  CHECK(scalar.ComponentLabel(0) == "psi");
}

}  // namespace koppel::mechanism_component_test
