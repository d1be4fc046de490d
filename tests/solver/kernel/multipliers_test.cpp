// Joint reactions from the multipliers, against the statics of one link worked out by hand:
// a pendulum (R joint and R drive) and a block on a slide (P joint and P drive, in mm).
#include "koppel/solver/multipliers.hpp"

#include "koppel/core/angles.hpp"
#include "tolerances.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::multipliers_test {
namespace {

// Statics of one link: sums of three terms of size ~10, exact up to roundoff.
constexpr double kStatics = 1e-12;

Eigen::Vector2d Rotate(double theta, const Eigen::Vector2d& v) {
  return {std::cos(theta) * v.x() - std::sin(theta) * v.y(), std::sin(theta) * v.x() + std::cos(theta) * v.y()};
}
double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Q of a force f at point r (global, relative to the link's body origin at `origin`), SI.
Eigen::Vector3d ForceOnLink(const Eigen::Vector2d& origin, const Eigen::Vector2d& at, const Eigen::Vector2d& f, double metres) {
  return {f.x(), f.y(), Cross((at - origin) * metres, f)};
}

}  // namespace

TEST_CASE("pendulum: the pivot takes -F, the drive holds -r x F", "[multipliers]") {
  Mechanism m;
  m.name = "pendulum";
  m.links = {{"frame", true, {{"A0", {1, 2}}}}, {"rod", false, {{"A0", {0.5, 0}}, {"T", {2.5, 0.5}}}}};
  m.joints = {PinJoint(m, "A0", 0, 1)};
  m.drive.joint = 0;
  PositionSolver solver(m);
  Eigen::VectorXd q(3);
  const Eigen::Vector2d force(3.0, -7.0);
  for (double degrees : {0.0, 35.0, 160.0, -100.0}) {
    const double phi = DegToRad(degrees);
    q << 1 - std::cos(phi) * 0.5, 2 - std::sin(phi) * 0.5, phi;  // rod point A0 on the frame's A0
    REQUIRE(solver.Correct(phi, q).ok());
    const Eigen::Vector2d origin(q(0), q(1)), tip = origin + Rotate(q(2), {2.5, 0.5});
    Reactions r;
    REQUIRE(JointReactions(solver, q, ForceOnLink(origin, tip, force, 1.0), 1.0, &r));
    REQUIRE(r.joints.size() == 1);
    CHECK((r.joints[0].force + force).norm() < kStatics);
    CHECK_THAT(r.drive, Catch::Matchers::WithinAbs(-Cross(tip - Eigen::Vector2d(1, 2), force), kStatics));
  }
}

TEST_CASE("block on a slide in mm: drive force, normal force and the moment across the slide", "[multipliers]") {
  // guide along (cos 30, sin 30) through F; the block is driven along it; a force f acts 1000 mm
  // from the block's point, across the slide
  Mechanism m;
  m.name = "slide";
  m.links = {{"frame", true, {{"F", {0, 0}}}}, {"block", false, {{"B", {0, 0}}, {"T", {0, 1000}}}}};
  Joint slide;
  slide.name = "S";
  slide.type = JointType::kPrismatic;
  slide.link_a = 0;
  slide.link_b = 1;
  slide.point_a = 0;
  slide.point_b = 0;
  slide.axis = {std::cos(DegToRad(30)), std::sin(DegToRad(30))};
  slide.angle = DegToRad(30);
  m.joints = {slide};
  m.drive.joint = 0;
  PositionSolver solver(m);
  const double s = 250.0, metres = 0.001;
  Eigen::VectorXd q(3);
  q << s * slide.axis.x(), s * slide.axis.y(), DegToRad(30);
  REQUIRE(solver.Correct(s, q).ok());
  const Eigen::Vector2d force(4.0, 9.0), origin(q(0), q(1)), tip = origin + Rotate(q(2), {0, 1000});
  Reactions r;
  REQUIRE(JointReactions(solver, q, ForceOnLink(origin, tip, force, metres), metres, &r));
  const Eigen::Vector2d axis = slide.axis, normal(-axis.y(), axis.x());
  // the block in balance: drive along the axis, normal force across it, moment about B
  CHECK_THAT(r.drive, Catch::Matchers::WithinAbs(-force.dot(axis), kStatics));
  CHECK_THAT(r.joints[0].normal, Catch::Matchers::WithinAbs(-force.dot(normal), kStatics));
  CHECK((r.joints[0].force + force.dot(normal) * normal).norm() < kStatics);
  CHECK_THAT(r.joints[0].moment, Catch::Matchers::WithinAbs(-Cross((tip - origin) * metres, force), kStatics));
}

TEST_CASE("no multipliers without a factorised pose", "[multipliers]") {
  Mechanism m;
  m.name = "pendulum";
  m.links = {{"frame", true, {{"A0", {0, 0}}}}, {"rod", false, {{"A0", {0, 0}}}}};
  m.joints = {PinJoint(m, "A0", 0, 1)};
  m.drive.joint = 0;
  const PositionSolver solver(m);
  Reactions r;
  CHECK_FALSE(JointReactions(solver, Eigen::VectorXd::Zero(3), Eigen::VectorXd::Zero(3), 1.0, &r));
}

}  // namespace koppel::multipliers_test
