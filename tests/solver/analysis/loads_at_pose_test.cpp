// Loads at a pose: point motions against central differences of solved positions, the
// generalised forces against virtual work, the potential energy's slope against the drive that
// holds gravity and springs, directions that turn with a link, formulas of the outputs.
#include "koppel/analysis/loads_at_pose.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"
#include "support/closed_forms.hpp"
#include "series_at.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::loads_at_pose_test {
namespace {

using test::SeriesAt;

// Central differences of positions of size ~4: with h = 1e-5 for the first derivative,
// truncation h^2 |p'''| / 6 ~ 1e-10 and roundoff eps |p| / h ~ 1e-10; with h2 = 1e-3 for the
// second, truncation h2^2 |p''''| / 12 ~ 1e-6 and roundoff (plus Newton's 1e-13 L) / h2^2 ~ 1e-6.
constexpr double kFirstDifference = 1e-8;
constexpr double kSecondDifference = 1e-5;
constexpr double kSecondStep = 1e-3;
constexpr double kExact = 1e-12;

Loads SomeLoads(Mechanism& m) {
  Loads loads;
  loads.gravity = {0.5, -9.81};
  loads.masses = {{1, 1.2, {0.4, 0.05}, 0.05}, {2, 2.0, {1.6, 0.5}, 0.9}, {3, 1.5, {1.1, -0.1}, 0.4}};
  m.links[0].points.push_back({"P0", {-1.0, 2.0}});
  SpringDamper spring;
  spring.name = "k";
  spring.from = {0, 2};
  spring.to = {2, 2};  // coupler K
  spring.stiffness = 40.0;
  spring.free_length = 1.5;
  loads.springs = {spring};
  return loads;
}

}  // namespace

TEST_CASE("point and angle motions are the derivatives of solved positions", "[loads]") {
  const Mechanism m = test::FourBar(1.0, 3.5, 2.5, 3.0, 2.0, 0.4, +1);
  const ConstraintSystem system(m);
  const double h = 1e-5;
  const Eigen::Vector2d local(1.3, -0.4);
  for (double degrees : {0.0, 75.0, 200.0, 310.0}) {
    INFO("phi = " << degrees);
    const double phi = DegToRad(degrees);
    const double h2 = kSecondStep;
    const Eigen::MatrixXd s0 = SeriesAt(m, phi), sm = SeriesAt(m, phi - h), sp = SeriesAt(m, phi + h);
    const Eigen::MatrixXd sm2 = SeriesAt(m, phi - h2), sp2 = SeriesAt(m, phi + h2);
    const PoseMotion p0(system, s0, 1.0), pm(system, sm, 1.0), pp(system, sp, 1.0), pm2(system, sm2, 1.0), pp2(system, sp2, 1.0);
    for (int link : {1, 2, 3}) {
      const PointMotion a = p0.Point(link, local), am = pm.Point(link, local), ap = pp.Point(link, local);
      CHECK((a.d1 - (ap.p - am.p) / (2 * h)).norm() < kFirstDifference);
      CHECK((a.d2 - (pp2.Point(link, local).p - 2 * a.p + pm2.Point(link, local).p) / (h2 * h2)).norm() < kSecondDifference);
      const AngleMotion w = p0.Angle(link), wm = pm.Angle(link), wp = pp.Angle(link);
      CHECK_THAT(w.d1, Catch::Matchers::WithinAbs((wp.theta - wm.theta) / (2 * h), kFirstDifference));
      CHECK_THAT(w.d2, Catch::Matchers::WithinAbs((pp2.Angle(link).theta - 2 * w.theta + pm2.Angle(link).theta) / (h2 * h2), kSecondDifference));
    }
  }
}

TEST_CASE("Q . dq/dphi is the loads' virtual work; the drive holding gravity and springs is dV/dphi", "[loads]") {
  Mechanism m = test::FourBar(1.0, 3.5, 2.5, 3.0, 2.0, 0.4, +1);
  Loads loads = SomeLoads(m);
  loads.torques = {{"M", 3, "2*cos(phi)"}};
  loads.forces = {{"F", {2, 1}, Eigen::Vector2d(0.6, 0.8), 2, "5 + psi"}};  // turns with the coupler
  const ConstraintSystem system(m);
  LoadModel model;
  REQUIRE(model.Prepare(m, loads));
  const double h = 1e-5;
  for (double degrees : {20.0, 140.0, 260.0}) {
    INFO("phi = " << degrees);
    const double phi = DegToRad(degrees);
    const Eigen::MatrixXd series = SeriesAt(m, phi);
    const PoseMotion pose(system, series, 1.0);
    AppliedLoads applied;
    MotionState state;
    state.input = phi;
    REQUIRE(model.Evaluate(pose, state, &applied));
    const Eigen::VectorXd q_force = GeneralizedForces(pose, applied);
    CHECK_THAT(q_force.dot(series.col(1)), Catch::Matchers::WithinAbs(-VirtualWorkDrive(applied), kExact * 1e3));
    // the force turns with the coupler and its magnitude reads the rocker angle psi
    const double coupler = series(system.CoordinateOf(2) + 2, 0), psi = series(system.CoordinateOf(3) + 2, 0);
    const AppliedLoads::Force& f = applied.forces[loads.masses.size()];  // after the weights, before the spring
    CHECK((f.force - (5 + psi) * Eigen::Vector2d(0.6 * std::cos(coupler) - 0.8 * std::sin(coupler),
                                                 0.6 * std::sin(coupler) + 0.8 * std::cos(coupler))).norm() < kExact * 10);
    // gravity and the spring alone: the drive that holds them is the slope of their energy
    Loads conservative = SomeLoads(m);
    conservative.masses = loads.masses;
    LoadModel potential;
    REQUIRE(potential.Prepare(m, conservative));
    AppliedLoads held;
    REQUIRE(potential.Evaluate(pose, state, &held));
    const Eigen::MatrixXd sm = SeriesAt(m, phi - h), sp = SeriesAt(m, phi + h);
    const double slope = (potential.PotentialEnergy(PoseMotion(system, sp, 1.0)) - potential.PotentialEnergy(PoseMotion(system, sm, 1.0))) / (2 * h);
    CHECK_THAT(VirtualWorkDrive(held), Catch::Matchers::WithinAbs(slope, kFirstDifference * 1e3));
  }
}

TEST_CASE("a damper's force follows the speed; a formula without a value is an error", "[loads]") {
  // slider-crank, damper from the foot point F to the slider: its length is s, so its force is c s' speed
  Mechanism m = test::SliderCrank(1.0, 2.6, 0.0);
  Loads loads;
  SpringDamper damper;
  damper.name = "c";
  damper.from = {0, 1};
  damper.to = {3, 0};
  damper.damping = 7.0;
  loads.springs = {damper};
  loads.forces = {{"F", {3, 0}, Eigen::Vector2d(1, 0), 0, "sqrt(s - 3)"}};  // s < 3 in places
  const ConstraintSystem system(m);
  LoadModel model;
  REQUIRE(model.Prepare(m, loads));
  const double phi = DegToRad(30);
  const Eigen::MatrixXd series = SeriesAt(m, phi);
  const PoseMotion pose(system, series, 1.0);
  MotionState state;
  state.input = phi;
  state.speed = 4.0;
  AppliedLoads applied;
  const double s = test::SliderCrank(1.0, 2.6, 0.0, phi).s, s1 = test::SliderCrank(1.0, 2.6, 0.0, phi).s1;
  if (s < 3) {
    const Outcome evaluated = model.Evaluate(pose, state, &applied);
    CHECK_FALSE(evaluated);
    CHECK_THAT(evaluated.error(), Catch::Contains("force 'F'") && Catch::Contains("no finite value"));
  }
  loads.forces.clear();
  REQUIRE(model.Prepare(m, loads));
  REQUIRE(model.Evaluate(pose, state, &applied));
  REQUIRE(applied.forces.size() == 2);
  // the tension c ds/dt pulls the slider back towards F
  CHECK_THAT(applied.forces[1].force.x(), Catch::Matchers::WithinAbs(-7.0 * s1 * 4.0, kExact * 100));
  CHECK_THAT(applied.forces[1].force.y(), Catch::Matchers::WithinAbs(0.0, kExact * 100));
}

}  // namespace koppel::loads_at_pose_test
