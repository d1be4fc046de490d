// The reduced moment of inertia against seed 000's closed form (slider-crank: J_red = J_1 + m s'^2),
// its derivative against central differences, and the inertia loads against Lagrange's identity.
#include "koppel/analysis/inertia.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"
#include "support/closed_forms.hpp"
#include "series_at.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::inertia_test {
namespace {

// relative: dJ/dphi with lengths in mm and in m: the same computation scaled by 1e3 (lengths) and
// 1e-6 (J): rounding of the scaling through a derivative
constexpr double kUnitChange = 1e-10;

using test::SeriesAt;

// Closed form and solver are both exact: roundoff of O(10) operations.
constexpr double kExact = 1e-12;
// Central difference with h = 1e-5 rad of an O(1) function: truncation h^2/6 |f'''| ~ 1e-10,
// roundoff eps/h ~ 1e-11.
constexpr double kDifference = 1e-8;

ReducedInertia At(const Mechanism& m, const std::vector<LinkMass>& masses, double input, double metres_per_unit = 1.0) {
  const Eigen::MatrixXd series = SeriesAt(m, input);
  const ConstraintSystem system(m);
  return ReduceInertia(PoseMotion(system, series, metres_per_unit), masses);
}

}  // namespace

TEST_CASE("slider-crank: J_red = J_crank + m_slider s'^2 and its derivative 2 m s' s'' (seed 000)", "[inertia]") {
  const double l1 = 1.0, l2 = 2.6, e = 0.8, crank = 0.3, slider = 2.0;
  const Mechanism m = test::SliderCrank(l1, l2, e);
  const std::vector<LinkMass> masses = {{1, 0.0, {0, 0}, crank}, {3, slider, {0, 0}, 0.0}};
  for (double degrees = 0; degrees < 360; degrees += 15) {
    INFO("phi = " << degrees);
    const double phi = DegToRad(degrees);
    const test::SliderCrankValues v = test::SliderCrank(l1, l2, e, phi);
    const ReducedInertia j = At(m, masses, phi);
    CHECK_THAT(j.value, Catch::Matchers::WithinAbs(crank + slider * v.s1 * v.s1, kExact * (crank + slider * l1 * l1)));
    CHECK_THAT(j.derivative, Catch::Matchers::WithinAbs(2 * slider * v.s1 * v.s2, 10 * kExact * slider * l1 * l1));
  }
  // in mm with the unit declared, the same kg m^2
  Mechanism mm = m;
  for (Link& l : mm.links) {
    for (NamedPoint& p : l.points) p.local *= 1000;
  }
  for (AssemblyHint::Entry& h : mm.hint.points) h.global *= 1000;
  const ReducedInertia in_m = At(m, masses, 1.0), in_mm = At(mm, masses, 1.0, 0.001);
  CHECK(in_mm.value == Approx(in_m.value).epsilon(kExact));
  CHECK(in_mm.derivative == Approx(in_m.derivative).epsilon(kUnitChange));
}

TEST_CASE("four-bar: dJ_red/dphi against central differences of J_red", "[inertia]") {
  const Mechanism m = test::FourBar(1.0, 3.5, 2.5, 3.0, 2.0, 0.4, +1);
  const std::vector<LinkMass> masses = {{1, 1.2, {0.4, 0.05}, 0.05}, {2, 2.0, {1.6, 0.5}, 0.9}, {3, 1.5, {1.1, -0.1}, 0.4}};
  const double h = 1e-5;
  for (double degrees = 0; degrees < 360; degrees += 30) {
    INFO("phi = " << degrees);
    const double phi = DegToRad(degrees);
    const ReducedInertia j = At(m, masses, phi);
    const double difference = (At(m, masses, phi + h).value - At(m, masses, phi - h).value) / (2 * h);
    CHECK_THAT(j.derivative, Catch::Matchers::WithinAbs(difference, kDifference * (1 + j.value)));
    CHECK(j.value > 0.0);
  }
}

TEST_CASE("inertia loads do the virtual work -(J_red phi'' + J_red' phi'^2 / 2); kinetic energy J_red phi'^2 / 2", "[inertia]") {
  const Mechanism m = test::FourBar(1.0, 3.5, 2.5, 3.0, 2.0, 0.4, +1);
  const std::vector<LinkMass> masses = {{1, 1.2, {0.4, 0.05}, 0.05}, {2, 2.0, {1.6, 0.5}, 0.9}, {3, 1.5, {1.1, -0.1}, 0.4}};
  const ConstraintSystem system(m);
  for (double degrees : {10.0, 100.0, 250.0}) {
    const Eigen::MatrixXd series = SeriesAt(m, DegToRad(degrees));
    const PoseMotion pose(system, series, 1.0);
    MotionState state;
    state.speed = 12.0;
    state.acceleration = -30.0;
    const ReducedInertia j = ReduceInertia(pose, masses);
    // the drive torque that moves the inertia loads: Lagrange's equation for the drive
    const double expected = j.value * state.acceleration + 0.5 * j.derivative * state.speed * state.speed;
    CHECK_THAT(VirtualWorkDrive(InertiaLoads(pose, masses, state)), Catch::Matchers::WithinAbs(expected, kExact * 1e3));
    CHECK(KineticEnergy(pose, masses, state.speed) == Approx(0.5 * j.value * 144.0).epsilon(kExact));
  }
}

}  // namespace koppel::inertia_test
