// The compiled step's dyads with two slides (solver/kernel/src/point_schedule_slides.cpp): PRP
// (two blocks on posed guides hinged to each other) and RPR (a slotted link turning about its
// pivot, its line at an offset from it), stepped by the schedule alone from one load, and their
// hand-over where a dyad's normalised determinant falls below the step's gauge. References:
// seed 001's closed form of the proportional linkage (s, s', s''; tests/support/closed_forms) and
// its slot's direction theta = atan2(l1 sin phi, l1 cos phi - l6), differentiated by hand; the
// offset slot's geometry, n . (A - B0) = f: theta = alpha - asin(f / r), the block's travel
// s = sqrt(r^2 - f^2), r = |A - B0|, with five-point differences for theta's derivatives; the
// dyads' gauges from the same geometry (PRP: the sine between the slot and the guide; RPR:
// sqrt(1 - f^2 / r^2)).
#include "koppel/solver/point_schedule.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/build.hpp"
#include "koppel/solver/assembly.hpp"
#include "koppel/solver/continuation.hpp"
#include "koppel/solver/position.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace koppel::point_schedule_slides_test {
namespace {

// [L | rad] the schedule (converged to 1e-13 L, derivatives exact) against a closed form
constexpr double kExact = 1e-10;
// five-point differences, h = 1e-3, of a closed form of size ~3 (see point_schedule_outputs_test)
constexpr double kD1 = 1e-9, kD2 = 1e-7, kH = 1e-3;

double D1(const std::function<double(double)>& f, double x) {
  return (f(x - 2 * kH) - 8 * f(x - kH) + 8 * f(x + kH) - f(x + 2 * kH)) / (12 * kH);
}
double D2(const std::function<double(double)>& f, double x) {
  return (-f(x - 2 * kH) + 16 * f(x - kH) - 30 * f(x) + 16 * f(x + kH) - f(x + 2 * kH)) / (12 * kH * kH);
}

// A schedule loaded at the mechanism's assembly (the mechanism must outlive it).
struct Loaded {
  explicit Loaded(const Mechanism& m) : solver(m), assembly(AssembleRegular(m, solver)), schedule(solver.system()) {
    REQUIRE(assembly.ok());
    REQUIRE(schedule.compiled());
    Continuation path(solver);
    REQUIRE(path.Start(assembly.input, assembly.q).ok());
    schedule.Load(path.input(), path.q(), path.Series(2));
  }
  PositionSolver solver;
  Assembly assembly;
  PointSchedule schedule;
};

// A crank A0A = l1 about A0 = 0 and a slotted link about B0 = (l6, 0) whose line runs along its x
// axis at the distance f from B0; a block hinged at A slides on it. Assembled at phi0 on the
// branch theta = alpha - asin(f / r) (A ahead of the line's foot point). Outputs theta, s.
double OffsetSlotAngle(double l6, double l1, double f, double phi) {
  const double ax = l1 * std::cos(phi) - l6, ay = l1 * std::sin(phi);
  return std::atan2(ay, ax) - std::asin(f / std::hypot(ax, ay));
}
Mechanism OffsetSlot(double l6, double l1, double f, double phi0) {
  Mechanism m;
  m.name = "offset slot";
  AddLink(m, "frame", {{"A0", {0, 0}}, {"B0", {l6, 0}}}, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {l1, 0}}});
  AddLink(m, "slot", {{"B0", {0, 0}}, {"L", {0, f}}, {"T", {3, f}}});
  AddLink(m, "block", {{"A", {0, 0}}});
  Revolute(m, "A0", "frame", "crank");
  Revolute(m, "A", "crank", "block");
  Revolute(m, "B0", "frame", "slot");
  Prismatic(m, "S", "slot", "L", "block", "A", {1, 0});
  SetDrive(m, "A0");
  LinkAngleOutput(m, "theta", "slot");
  JointOutput(m, "s", "S");
  const double theta = OffsetSlotAngle(l6, l1, f, phi0);
  HintInput(m, phi0);
  const double c = std::cos(theta), s = std::sin(theta);  // T = B0 + R(theta) (3, f)
  HintPoint(m, "slot", "T", Eigen::Vector2d(l6 + 3 * c - f * s, 3 * s + f * c));
  return m;
}

}  // namespace

TEST_CASE("proportional linkages (RPR and PRP): s of seed 001, the slot's angle, the PRP's gauge", "[kernel][point-schedule-slides]") {
  const std::vector<std::array<double, 3>> dimensions = {{1, 0.5, 1.83}, {2, 0.6, 0.9}, {1.5, 1.1, 2.5}};  // l6, l1, h
  for (const auto& [l6, l1, h] : dimensions) {
    const Mechanism m = test::ProportionalLinkage(l6, l1, h);
    Loaded loaded(m);
    const int slot = loaded.solver.system().CoordinateOf(m.FindLink("slot")) + 2;  // its theta in q
    Eigen::VectorXd q;
    Eigen::MatrixXd series(loaded.solver.NumCoordinates(), 3);
    std::vector<double> out(loaded.solver.OutputWidth(2));
    for (int i = 1; i <= 360; ++i) {
      const double phi = loaded.assembly.input + DegToRad(i);
      INFO(l6 << " " << l1 << " " << h << " at phi = " << RadToDeg(phi));
      REQUIRE(loaded.schedule.Step(phi));
      loaded.schedule.OutputDerivatives(2, out.data());
      const test::ProportionalValues v = test::Proportional(l6, l1, h, phi);
      CHECK_THAT(out[0], Catch::Matchers::WithinAbs(v.s, kExact));
      CHECK_THAT(out[1], Catch::Matchers::WithinAbs(v.s1, kExact));
      CHECK_THAT(out[2], Catch::Matchers::WithinAbs(v.s2, kExact));
      // the slot along A - B0 (either way: mod 180 deg); theta' = (l1^2 - l1 l6 cos phi) / D,
      // theta'' = l1 l6 sin phi (l6^2 - l1^2) / D^2, D = l1^2 + l6^2 - 2 l1 l6 cos phi = |A - B0|^2
      loaded.schedule.Pose(q);
      loaded.schedule.Series(series);
      const double dd = l1 * l1 + l6 * l6 - 2 * l1 * l6 * std::cos(phi);
      const double direction = std::atan2(l1 * std::sin(phi), l1 * std::cos(phi) - l6);
      CHECK_THAT(std::remainder(q(slot) - direction, kPi), Catch::Matchers::WithinAbs(0.0, kExact));
      CHECK_THAT(series(slot, 1), Catch::Matchers::WithinAbs((l1 * l1 - l1 * l6 * std::cos(phi)) / dd, kExact));
      CHECK_THAT(2 * series(slot, 2), Catch::Matchers::WithinAbs(l1 * l6 * std::sin(phi) * (l6 * l6 - l1 * l1) / (dd * dd), kExact));
      // the guide is vertical: the sine between it and the slot is |cos(direction)|; the RPR
      // (offset 0) stands at 1
      CHECK_THAT(loaded.schedule.Gauge(), Catch::Matchers::WithinAbs(std::abs(l1 * std::cos(phi) - l6) / std::sqrt(dd), kExact));
    }
  }
}

TEST_CASE("a slot at an offset from its pivot (RPR): angle, block travel and gauge over two turns", "[kernel][point-schedule-slides]") {
  const double l6 = 2, l1 = 0.8, f = 0.5;  // |A - B0| from 1.2 to 2.8, always beyond f: the crank turns round
  const Mechanism m = OffsetSlot(l6, l1, f, 0);
  Loaded loaded(m);
  std::vector<double> out(loaded.solver.OutputWidth(2));
  for (int i = 1; i <= 720; ++i) {
    const double phi = loaded.assembly.input + DegToRad(i);
    INFO("phi = " << RadToDeg(phi));
    REQUIRE(loaded.schedule.Step(phi));
    loaded.schedule.OutputDerivatives(2, out.data());
    const auto near = [&](double x) { return std::remainder(OffsetSlotAngle(l6, l1, f, x) - OffsetSlotAngle(l6, l1, f, phi), 2 * kPi); };
    CHECK_THAT(std::remainder(out[0] - OffsetSlotAngle(l6, l1, f, phi), 2 * kPi), Catch::Matchers::WithinAbs(0.0, kExact));
    CHECK_THAT(out[1], Catch::Matchers::WithinAbs(D1(near, phi), kD1));
    CHECK_THAT(out[2], Catch::Matchers::WithinAbs(D2(near, phi), kD2));
    // s^2 = r^2 - f^2: s' = l1 l6 sin phi / s, s'' = l1 l6 cos phi / s - (l1 l6 sin phi)^2 / s^3
    const double r2 = l1 * l1 + l6 * l6 - 2 * l1 * l6 * std::cos(phi), s = std::sqrt(r2 - f * f), k = l1 * l6;
    CHECK_THAT(out[3], Catch::Matchers::WithinAbs(s, kExact));
    CHECK_THAT(out[4], Catch::Matchers::WithinAbs(k * std::sin(phi) / s, kExact));
    CHECK_THAT(out[5], Catch::Matchers::WithinAbs(k * std::cos(phi) / s - std::pow(k * std::sin(phi), 2) / (s * s * s), kExact));
    CHECK_THAT(loaded.schedule.Gauge(), Catch::Matchers::WithinAbs(std::sqrt(1 - f * f / r2), kExact));
  }
}

TEST_CASE("a step onto a pose below the step's gauge is refused, the state kept; the default gauge takes it",
          "[kernel][point-schedule-slides]") {
  // each case: the mechanism, its dyad's gauge by geometry, the walk's direction, min_gauge
  struct Case {
    const char* what;
    Mechanism m;
    std::function<double(double)> gauge;
    double step, min_gauge;
  };
  const std::vector<Case> cases = {
      {"RPR near its dead centre", OffsetSlot(2, 0.8, 1.1, DegToRad(90)),
       [](double phi) { return std::sqrt(1 - 1.21 / (4.64 - 3.2 * std::cos(phi))); }, DegToRad(-1), 0.5},
      {"PRP with the slot swinging towards the guide", test::ProportionalLinkage(1, 0.5, 1.83),
       [](double phi) { return std::abs(0.5 * std::cos(phi) - 1) / std::sqrt(1.25 - std::cos(phi)); }, DegToRad(1), 0.9}};
  for (const Case& c : cases) {
    INFO(c.what);
    Loaded loaded(c.m);
    PointSchedule::StepOptions options;
    options.min_gauge = c.min_gauge;
    double phi = loaded.assembly.input;
    REQUIRE(c.gauge(phi) > c.min_gauge);
    for (int i = 0; c.gauge(phi + c.step) > c.min_gauge; ++i) {  // every step above the gauge is taken
      REQUIRE(i < 180);
      phi += c.step;
      REQUIRE(loaded.schedule.Step(phi, options));
    }
    Eigen::VectorXd before, after;
    loaded.schedule.Pose(before);
    CHECK_FALSE(loaded.schedule.Step(phi + c.step, options));  // the first below it is not
    loaded.schedule.Pose(after);
    CHECK((after - before).norm() == 0.0);
    CHECK(loaded.schedule.Step(phi + c.step));  // the default gauge (1e-12) takes it
    CHECK_THAT(loaded.schedule.Gauge(), Catch::Matchers::WithinAbs(c.gauge(phi + c.step), kExact));
  }
}

}  // namespace koppel::point_schedule_slides_test
