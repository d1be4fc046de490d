// Where the transmission angle is measured, read off the topology alone: the reference is the
// mechanisms' own drawing (tests/support/mechanisms.hpp): the four-bar's coupler line A -> B and
// rocker pivot B0; the slider-crank's coupler A -> B and the frame's slide.
#include "koppel/core/transmission.hpp"

#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

namespace koppel::transmission_test {

namespace {
PointRef On(const Mechanism& m, const std::string& link, const std::string& point) {
  const int l = m.FindLink(link);
  return {l, m.links[l].FindPoint(point)};
}
bool Same(PointRef a, PointRef b) { return a.link == b.link && a.point == b.point; }
}  // namespace

TEST_CASE("A four-bar's transmission angle is measured on A -> B against the rocker's pivot", "[transmission]") {
  const Mechanism m = test::FourBar(1, 3, 3, 4, 1, 0.3, +1);
  const Expected<TransmissionGeometry> g = ResolveTransmission(m, m.outputs[m.FindOutput("mu")]);
  REQUIRE(g);
  CHECK(Same(g->coupler_from, On(m, "coupler", "A")));
  CHECK(Same(g->coupler_to, On(m, "coupler", "B")));
  CHECK(Same(g->pivot, On(m, "rocker", "B0")));
  CHECK(g->slide_joint == -1);
}

TEST_CASE("A slider-crank's transmission angle is measured against the frame's slide", "[transmission]") {
  const Mechanism m = test::SliderCrank(1, 3, 0.5);
  const Expected<TransmissionGeometry> g = ResolveTransmission(m, m.outputs[m.FindOutput("mu")]);
  REQUIRE(g);
  REQUIRE(g->slide_joint >= 0);
  CHECK(m.joints[g->slide_joint].type == JointType::kPrismatic);
  CHECK(g->pivot.link == -1);
}

TEST_CASE("A transmission angle needs a binary coupler that holds the output joint", "[transmission]") {
  const Mechanism m = test::FourBar(1, 3, 3, 4, 1, 0.3, +1);
  Output o = m.outputs[m.FindOutput("mu")];
  o.joint = m.FindJoint("A0");  // a joint of the crank and the frame, not of the coupler
  const Expected<TransmissionGeometry> wrong_joint = ResolveTransmission(m, o);
  REQUIRE_FALSE(wrong_joint);
  CHECK(wrong_joint.error() == "joint 'A0' does not belong to coupler 'coupler'");
  // the Watt six-bar's rocker carries three joints (B0, B, C): not a coupler line
  const Mechanism watt = test::WattSixBar();
  Output t;
  t.kind = OutputKind::kTransmissionAngle;
  t.link = watt.FindLink("rocker");
  t.joint = watt.FindJoint("C");
  const Expected<TransmissionGeometry> ternary = ResolveTransmission(watt, t);
  REQUIRE_FALSE(ternary);
  CHECK(ternary.error() == "coupler 'rocker' must be a binary link (exactly two joints)");
}

}  // namespace koppel::transmission_test
