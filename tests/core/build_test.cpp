// The builders by name (core/src/build.cpp): what they write into the Mechanism is what the
// index-based model says, and a name that does not exist is an error naming it.
#include "koppel/core/build.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

namespace koppel::build_test {
namespace {

// relative: a normalised axis (3, 4) / 5: a few ulps
constexpr double kUlps = 1e-15;

using Catch::Matchers::Contains;

Mechanism Crank() {
  Mechanism m;
  m.name = "test";
  AddLink(m, "frame", {{"A0", {0, 0}}, {"F", {0, 1}}}, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {1, 0}}});
  AddLink(m, "block", {{"A", {0, 0}}});
  return m;
}

TEST_CASE("links, joints, drive, outputs and hints land at the indices the names say", "[build]") {
  Mechanism m = Crank();
  CHECK(AddLink(m, "spare", {}) == 3);
  CHECK(m.links[0].is_frame);
  CHECK_FALSE(m.links[1].is_frame);
  const Joint& r = Revolute(m, "A0", "frame", "crank");
  CHECK(r.type == JointType::kRevolute);
  CHECK((r.link_a == 0 && r.point_a == 0 && r.link_b == 1 && r.point_b == 0));
  // different point names on the two links
  const Joint& r2 = Revolute(m, "pin", "crank", "block", "A", "A");
  CHECK((r2.link_a == 1 && r2.point_a == 1 && r2.link_b == 2 && r2.point_b == 0));
  const Joint& p = Prismatic(m, "S", "frame", "F", "block", "A", {3, 4}, 0.25);
  CHECK(p.type == JointType::kPrismatic);
  CHECK((p.link_a == 0 && p.point_a == 1 && p.link_b == 2 && p.point_b == 0));
  CHECK(p.axis.x() == Approx(0.6).epsilon(kUlps));  // normalised
  CHECK(p.axis.y() == Approx(0.8).epsilon(kUlps));
  CHECK(p.angle == 0.25);
  SetDrive(m, "A0", 0.5, "alpha");
  CHECK((m.drive.joint == 0 && m.drive.zero == 0.5 && m.drive.input_name == "alpha"));
  CHECK(JointOutput(m, "s", "S").joint == 2);
  CHECK(LinkAngleOutput(m, "theta", "crank").link == 1);
  const Output& point = PointOutput(m, "A", "crank", "A");
  CHECK((point.kind == OutputKind::kPoint && point.p.link == 1 && point.p.point == 1));
  const Output& distance = DistanceOutput(m, "d", "frame", "F", "crank", "A");
  CHECK((distance.kind == OutputKind::kDistance && distance.p.point == 1 && distance.q.link == 1));
  CHECK(DirectionOutput(m, "u", "frame", "F", "crank", "A").kind == OutputKind::kDirection);
  const Output& mu = TransmissionOutput(m, "mu", "crank", "pin");
  CHECK((mu.link == 1 && mu.joint == 1));
  CHECK(m.outputs.size() == 6);
  HintInput(m, 1.25);
  HintPoint(m, "crank", "A", {0.3, 0.9});
  CHECK(m.hint.input == 1.25);
  CHECK((m.hint.points.back().point.link == 1 && m.hint.points.back().point.point == 1));
  CHECK(CheckConsistency(m).empty());
}

TEST_CASE("a name that does not exist is an error naming it", "[build]") {
  Mechanism m = Crank();
  CHECK_THROWS_WITH(Revolute(m, "A0", "frame", "rotor"), Contains("no link 'rotor'"));
  CHECK_THROWS_WITH(Revolute(m, "B", "frame", "crank"), Contains("link 'frame' has no point 'B'"));
  CHECK_THROWS_WITH(SetDrive(m, "A9"), Contains("no joint 'A9'"));
  CHECK_THROWS_WITH(JointOutput(m, "s", "S"), Contains("no joint 'S'"));
  CHECK_THROWS_WITH(HintPoint(m, "crank", "K", {0, 0}), Contains("no point 'K'"));
  CHECK_THROWS_AS(Prismatic(m, "S", "frame", "F", "block", "A", {0, 0}), std::invalid_argument);  // no direction
  CHECK(m.joints.empty());  // nothing half-added
  CHECK(m.outputs.empty());
}

}  // namespace
}  // namespace koppel::build_test
