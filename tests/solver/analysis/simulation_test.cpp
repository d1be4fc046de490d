// The equation of motion (Simulate) against closed forms: a physical pendulum (small-amplitude
// period and the exact elliptic-integral period), a spring-loaded parallelogram four-bar (the
// period of its linearisation), a mass-spring-damper on a slide (the damped oscillation), a
// flywheel under a constant torque and under a motor curve; energy conserved to the integrator's
// tolerance for conservative systems.
#include "koppel/analysis/simulation.hpp"

#include "koppel/core/angles.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::simulation_test {
namespace {

// relative: the ratio of two anharmonic period errors (O(amplitude^2)) is 1/4 up to their own
// higher-order terms and the crossing times' error (kPeriodMeasurement), a few percent of 3e-6
constexpr double kQuarterRatio = 0.02;

// [rad, rad/s] constant torque on a constant inertia: phi and its speed are polynomials the
// integrator follows to its step tolerances (1e-10 per step, the defaults) accumulated over the rows
constexpr double kIntegrated = 1e-8;
// the motor's exponential approach to ws, relative to ws: the same accumulated step errors
// on a solution that is not a polynomial
constexpr double kIntegratedRelative = 1e-7;

constexpr double kGravity = 9.81;
// Crossing times come from the cubic Hermite interpolant of the rows (values and speeds), whose
// error is O((omega dt)^4) ~ 1e-8 of the period for 200 rows per period.
constexpr double kPeriodMeasurement = 1e-7;
// Energy of a conservative system over a few periods with relative and absolute error 1e-10
// per step (the defaults): the integrator's local errors add up to about 1e-9 of the energy.
constexpr double kEnergyDrift = 1e-8;

// A link pinned to the frame at A0, driven (measured) there: the input is the link's angle.
Mechanism Pendulum() {
  Mechanism m;
  m.name = "pendulum";
  m.links = {{"frame", true, {{"A0", {0, 0}}}}, {"rod", false, {{"A0", {0, 0}}, {"S", {0.5, 0}}}}};
  m.joints = {PinJoint(m, "A0", 0, 1)};
  m.drive.joint = 0;
  Output theta;
  theta.name = "theta";
  theta.kind = OutputKind::kLinkAngle;
  theta.link = 1;
  m.outputs = {theta};
  return m;
}

// Times where input - centre changes sign upwards, from the Hermite interpolant of the rows.
std::vector<double> UpwardCrossings(const SimulationResult& r, double centre) {
  std::vector<double> times;
  for (size_t i = 0; i + 1 < r.rows.size(); ++i) {
    const SimulationRow &a = r.rows[i], &b = r.rows[i + 1];
    const double y0 = a.input - centre, y1 = b.input - centre, h = b.time - a.time;
    if (!(y0 < 0.0 && y1 >= 0.0)) continue;
    auto hermite = [&](double s) {  // s in [0, 1]
      const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s, h01 = -2 * s * s * s + 3 * s * s,
                   h11 = s * s * s - s * s;
      return h00 * y0 + h10 * h * a.speed + h01 * y1 + h11 * h * b.speed;
    };
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (hermite(mid) < 0.0 ? lo : hi) = mid;
    }
    times.push_back(a.time + 0.5 * (lo + hi) * h);
  }
  return times;
}

double MeanPeriod(const std::vector<double>& crossings) {
  REQUIRE(crossings.size() >= 2);
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

double WorstEnergyDrift(const SimulationResult& r) {
  const double e0 = r.rows.front().kinetic_energy + r.rows.front().potential_energy;
  double worst = 0.0;
  for (const SimulationRow& row : r.rows) worst = std::max(worst, std::abs(row.kinetic_energy + row.potential_energy - e0));
  return worst;
}

}  // namespace

TEST_CASE("physical pendulum: period against the closed forms, energy conserved", "[simulate]") {
  const Mechanism m = Pendulum();
  const double mass = 2.0, a = 0.5, inertia = 0.05;
  Loads loads;
  loads.gravity = {0, -kGravity};
  loads.masses.push_back({1, mass, {a, 0}, inertia});
  const double j_a = inertia + mass * a * a;  // about the pivot (Steiner)
  const double t0 = 2 * kPi * std::sqrt(j_a / (mass * kGravity * a));
  const double hanging = -kPi / 2;

  SECTION("small amplitude: T = 2 pi sqrt(J_A / (m g a)) (1 + theta0^2 / 16)") {
    const double amplitude = DegToRad(1.0);
    SimulationOptions options;
    options.initial_input = hanging + amplitude;
    options.t_end = 3.2 * t0;
    options.output_step = t0 / 200;
    const SimulationResult r = Simulate(m, loads, DriveLaw{}, options);
    REQUIRE(r.status == AnalysisStatus::kComplete);
    const double period = MeanPeriod(UpwardCrossings(r, hanging));
    // the next term of the series, 11/3072 theta0^4, is 3e-10 here
    const double expected = t0 * (1 + amplitude * amplitude / 16);
    INFO("period " << period << " s, small-amplitude closed form " << expected << " s (relative difference " << period / expected - 1
                   << "), 2 pi sqrt(J/mga) " << t0 << " s; energy drift " << WorstEnergyDrift(r) << " J");
    CHECK(std::abs(period / expected - 1) < kPeriodMeasurement);
    CHECK(std::abs(period / t0 - 1) > 0.5 * amplitude * amplitude / 16);  // the measurement sees the amplitude's effect
    CHECK(WorstEnergyDrift(r) < kEnergyDrift * mass * kGravity * a * (1 - std::cos(amplitude)));
  }
  SECTION("large amplitude: T = 4 sqrt(J_A / (m g a)) K(sin(theta0 / 2))") {
    for (double degrees : {60.0, 150.0}) {
      const double amplitude = DegToRad(degrees);
      SimulationOptions options;
      options.initial_input = hanging + amplitude;
      const double expected = 4 * std::sqrt(j_a / (mass * kGravity * a)) * std::comp_ellint_1(std::sin(amplitude / 2));
      options.t_end = 3.2 * expected;
      options.output_step = expected / 200;
      const SimulationResult r = Simulate(m, loads, DriveLaw{}, options);
      REQUIRE(r.status == AnalysisStatus::kComplete);
      const double period = MeanPeriod(UpwardCrossings(r, hanging));
      const double drift = WorstEnergyDrift(r) / (mass * kGravity * a * (1 - std::cos(amplitude)));
      INFO(degrees << " deg: period " << period << " s, elliptic closed form " << expected << " s (relative difference "
                   << period / expected - 1 << "); energy drift " << drift
                   << " of the swing's energy, " << r.steps << " steps");
      CHECK(std::abs(period / expected - 1) < kPeriodMeasurement);
      CHECK(drift < kEnergyDrift);
    }
  }
}

TEST_CASE("spring-loaded parallelogram four-bar: period of the linearisation", "[simulate]") {
  // A0 B0 = A B = 0.6, A0 A = B0 B = 0.2: the coupler translates with the crank tip. A spring of
  // free length l0 from the frame point P0 = (0.3, D) to the coupler's middle M: with
  // r^2 = l1^2 + D^2 - 2 l1 D sin(phi) its energy k (r - l0)^2 / 2 is least at phi = 90 deg, where
  // r' = 0 and r'' = l1 D / (D - l1), so V'' = k l1 D (D - l1 - l0) / (D - l1).
  const double l1 = 0.2, l2 = 0.6, depth = 0.5, free = 0.1, k = 500.0;
  Mechanism m = test::FourBar(l1, l2, l1, l2, 0.3, 0.0, +1);
  m.hint.input = kPi / 2;
  m.hint.points = {{{2, 1}, {l2, l1}}};
  m.links[0].points.push_back({"P0", {l2 / 2, depth}});
  Loads loads;
  loads.masses = {{1, 0.5, {l1 / 2, 0}, 0.002}, {2, 1.0, {l2 / 2, 0}, 0.01}, {3, 0.5, {l1 / 2, 0}, 0.002}};
  SpringDamper spring;
  spring.name = "k";
  spring.from = {0, 2};
  spring.to = {2, 2};  // the coupler's K at 0.3 along A B: its middle
  spring.stiffness = k;
  spring.free_length = free;
  loads.springs = {spring};
  // the coupler does not turn: J_red = J_1 + m_1 (l1/2)^2 + J_3 + m_3 (l1/2)^2 + m_2 l1^2
  const double j_red = 2 * (0.002 + 0.5 * l1 * l1 / 4) + 1.0 * l1 * l1;
  const double stiffness = k * l1 * depth * (depth - l1 - free) / (depth - l1);
  const double t0 = 2 * kPi * std::sqrt(j_red / stiffness);
  std::vector<double> errors;
  for (double degrees : {0.2, 0.1}) {
    SimulationOptions options;
    options.initial_input = kPi / 2 + DegToRad(degrees);
    options.t_end = 3.2 * t0;
    options.output_step = t0 / 200;
    const SimulationResult r = Simulate(m, loads, DriveLaw{}, options);
    REQUIRE(r.status == AnalysisStatus::kComplete);
    const double period = MeanPeriod(UpwardCrossings(r, kPi / 2));
    errors.push_back(period / t0 - 1);
    INFO(degrees << " deg: period " << period << " s, linearisation " << t0 << " s");
    // the anharmonic correction is O(amplitude^2) = 1.2e-5 at 0.2 deg, 3e-6 at 0.1 deg
    CHECK(std::abs(errors.back()) < 1e-5);
    CHECK(WorstEnergyDrift(r) < kEnergyDrift * 0.5 * stiffness * std::pow(DegToRad(degrees), 2));
  }
  // and it shrinks with the amplitude's square: halving the amplitude quarters it
  INFO("relative period errors " << errors[0] << " at 0.2 deg, " << errors[1] << " at 0.1 deg");
  CHECK(errors[1] / errors[0] == Approx(0.25).epsilon(kQuarterRatio));
}

TEST_CASE("a crank-rocker with masses, gravity and a spring runs through full turns with its energy kept", "[simulate]") {
  Mechanism m = test::FourBar(0.1, 0.35, 0.25, 0.3, 0.2, 0.4, +1);
  m.links[0].points.push_back({"P0", {-0.1, 0.3}});
  Loads loads;
  loads.gravity = {0, -kGravity};
  loads.masses = {{1, 1.2, {0.04, 0.005}, 0.0005}, {2, 2.0, {0.16, 0.05}, 0.009}, {3, 1.5, {0.11, -0.01}, 0.004}};
  SpringDamper spring;
  spring.name = "k";
  spring.from = {0, 2};
  spring.to = {2, 2};  // coupler K
  spring.stiffness = 300.0;
  spring.free_length = 0.2;
  loads.springs = {spring};
  SimulationOptions options;
  options.initial_input = 0.0;
  options.initial_speed = 30.0;  // rad/s: several turns
  options.t_end = 2.0;
  options.output_step = 0.002;
  const SimulationResult r = Simulate(m, loads, DriveLaw{}, options);
  REQUIRE(r.status == AnalysisStatus::kComplete);
  const double e0 = r.rows.front().kinetic_energy + r.rows.front().potential_energy;
  const double drift = WorstEnergyDrift(r) / std::abs(e0);
  INFO("energy " << e0 << " J, worst drift " << drift << " of it over " << r.rows.back().input / (2 * kPi) << " turns, "
                 << r.steps << " steps, " << r.evaluations << " solved poses");
  CHECK(r.rows.back().input > 4 * 2 * kPi);
  CHECK(drift < kEnergyDrift);
}

TEST_CASE("mass-spring-damper on a slide in mm: the damped oscillation", "[simulate]") {
  // a block of mass m on a P-driven slide, a spring (k, free length 100 mm) and damper (c) to the
  // frame point G 100 mm behind the slide's origin: m x'' + c x' + k x = 0 for x = s in metres
  Mechanism m;
  m.name = "oscillator";
  m.links = {{"frame", true, {{"F", {0, 0}}, {"G", {-100, 0}}}}, {"block", false, {{"B", {0, 0}}}}};
  Joint slide;
  slide.name = "S";
  slide.type = JointType::kPrismatic;
  slide.link_a = 0;
  slide.link_b = 1;
  slide.point_a = 0;
  slide.point_b = 0;
  m.joints = {slide};
  m.drive.joint = 0;
  m.drive.input_name = "s";
  m.hint.input = 20;
  m.hint.points = {{{1, 0}, {20, 0}}};
  const double mass = 0.4, k = 900.0, c = 3.0;
  Loads loads;
  loads.metres_per_unit = 0.001;
  loads.masses = {{1, mass, {0, 0}, 0.0}};
  SpringDamper spring;
  spring.name = "kc";
  spring.from = {0, 1};
  spring.to = {1, 0};
  spring.stiffness = k;
  spring.free_length = 100;  // mm
  spring.damping = c;
  loads.springs = {spring};
  SimulationOptions options;
  options.initial_input = 20;  // mm
  options.t_end = 0.5;
  options.output_step = 0.005;
  const SimulationResult r = Simulate(m, loads, DriveLaw{}, options);
  REQUIRE(r.status == AnalysisStatus::kComplete);
  const double wn = std::sqrt(k / mass), zeta = c / (2 * std::sqrt(k * mass)), wd = wn * std::sqrt(1 - zeta * zeta);
  const double x0 = 0.020;
  double worst = 0.0;
  for (const SimulationRow& row : r.rows) {
    const double t = row.time;
    const double x = x0 * std::exp(-zeta * wn * t) * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t));
    worst = std::max(worst, std::abs(row.input * 0.001 - x));
  }
  INFO("worst |s - closed form| " << worst << " m of x0 = " << x0 << " m");
  // the integrator's error per step 1e-10 (in mm and mm/s) adds up to about 1e-9 of x0
  CHECK(worst < 1e-8 * x0);
  // the damper takes energy: it never grows
  for (size_t i = 1; i < r.rows.size(); ++i) {
    CHECK(r.rows[i].kinetic_energy + r.rows[i].potential_energy <= r.rows[i - 1].kinetic_energy + r.rows[i - 1].potential_energy + 1e-12);
  }
}

TEST_CASE("a flywheel under a torque formula and under a motor curve", "[simulate]") {
  Mechanism m = Pendulum();
  Loads loads;
  loads.masses.push_back({1, 1.0, {0, 0}, 0.5});  // balanced: J = 0.5 kg m^2
  SimulationOptions options;
  options.t_end = 2.0;
  options.output_step = 0.1;
  DriveLaw law;
  law.kind = DriveLaw::Kind::kFormula;
  law.formula = "2 + 0*phi_dot";  // N m
  SimulationResult r = Simulate(m, loads, law, options);
  REQUIRE(r.status == AnalysisStatus::kComplete);
  for (const SimulationRow& row : r.rows) {
    CHECK_THAT(row.input, Catch::Matchers::WithinAbs(0.5 * 4.0 * row.time * row.time, kIntegrated));  // phi = M t^2 / (2 J)
    CHECK_THAT(row.speed, Catch::Matchers::WithinAbs(4.0 * row.time, kIntegrated));
    CHECK(row.drive == 2.0);
  }
  // a motor whose torque falls linearly from M0 at rest to 0 at ws: w = ws (1 - exp(-M0 t / (J ws)))
  const double m0 = 10.0, ws = 100.0;
  law.kind = DriveLaw::Kind::kMotor;
  law.speeds = {0.0, ws, 2 * ws};
  law.torques = {m0, 0.0, -m0};
  r = Simulate(m, loads, law, options);
  REQUIRE(r.status == AnalysisStatus::kComplete);
  for (const SimulationRow& row : r.rows) {
    const double expected = ws * (1 - std::exp(-m0 * row.time / (0.5 * ws)));
    CHECK_THAT(row.speed, Catch::Matchers::WithinAbs(expected, kIntegratedRelative * ws));
  }
  // a curve that ends below the speed the motion needs: the run stops there and says so
  law.speeds = {-1.0, 5.0};
  law.torques = {m0, 5.0};
  r = Simulate(m, loads, law, options);
  CHECK(r.status == AnalysisStatus::kPartial);
  CHECK_THAT(r.message, Catch::Contains("motor curve"));
  REQUIRE(!r.rows.empty());
  CHECK(r.rows.back().speed <= 5.0);
}

TEST_CASE("the run stops at a dead centre of the drive and refuses a mechanism without mass", "[simulate]") {
  // a crank-rocker driven at its rocker swings into the rocker's limit position (126.87 deg,
  // where A0 B = l2 - l1)
  Mechanism m = test::FourBar(1.0, 3.5, 2.5, 3.0, 2.0, 0.4, +1, true);
  m.hint.input = DegToRad(100);
  m.hint.points = {{{2, 1}, Eigen::Vector2d(3, 0) + 2.5 * Eigen::Vector2d(std::cos(m.hint.input), std::sin(m.hint.input))}};
  Loads loads;
  loads.masses = {{3, 1.0, {1.0, 0}, 0.2}};
  DriveLaw law;
  law.kind = DriveLaw::Kind::kFormula;
  law.formula = "50";
  SimulationOptions options;
  options.initial_input = m.hint.input;
  options.t_end = 5.0;
  options.output_step = 0.01;
  SimulationResult r = Simulate(m, loads, law, options);
  CHECK(r.status == AnalysisStatus::kPartial);
  CHECK_THAT(r.message, Catch::Contains("cannot move on"));
  CHECK(r.rows.size() >= 1);
  CHECK(r.rows.back().time < options.t_end);
  CHECK(r.rows.back().input < DegToRad(126.87));

  loads.masses.clear();
  r = Simulate(m, loads, law, options);
  CHECK(r.status == AnalysisStatus::kFailed);
  CHECK(r.bad_input);
  CHECK_THAT(r.message, Catch::Contains("no link has a mass"));

  options.t_end = -1;
  r = Simulate(m, loads, law, options);
  CHECK(r.status == AnalysisStatus::kFailed);
  CHECK(r.bad_input);
}

}  // namespace koppel::simulation_test
