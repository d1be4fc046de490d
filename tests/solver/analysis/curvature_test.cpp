// The pole, inflection circle, Ball point and path curvature of curvature.hpp against independent
// references: the Euler–Savary equation, the curvature of the point's own transfer functions, the
// pivots of a four-bar's crank and rocker (the centres of curvature of A and B), and seed 003's
// coupler point K at phi = 180 deg, the point of a six-point tangent (on the inflection circle).
#include "koppel/analysis/curvature.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/position.hpp"
#include "support/instant_geometry.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::curvature_test {
namespace {

// relative: a path point's radius of curvature from second-order transfer functions (Taylor
// series of the pose, ~1e-13) against the link's length
constexpr double kRadius = 1e-10;
// relative: the curvature against the closed form: second derivatives of the pose, the 1e-9
constexpr double kCurvature = 1e-9;
// relative: a point on a unit crank circles it: rounding of one Taylor step
constexpr double kUnitRadius = 1e-12;

// Seed 003's crank-rocker (catalog/entries/mzc-crank-rocker.yaml): l1 = 1, l2 = l3 = 5/2 sqrt(3),
// l4 = 4, AK = 25/3, angle BAK = acos(5/9 sqrt(3)), B above A0B0.
Mechanism Seed003() {
  return test::FourBar(1, 2.5 * std::sqrt(3.0), 2.5 * std::sqrt(3.0), 4, 25.0 / 3, std::acos(5.0 / 9 * std::sqrt(3.0)), +1);
}

// Positions agree to 1e-9 L (L ~ 8 here): the quantities come from Taylor coefficients good to
// ~1e-13, divided by rates of order 1.
constexpr double kPositionTolerance = 1e-9;

struct Pose {
  PositionSolver solver;
  Eigen::MatrixXd series;
  Pose(const Mechanism& m, double input) : solver(m) {
    Eigen::VectorXd q(solver.NumCoordinates());
    REQUIRE(solver.Assemble(q).ok());
    // from the hint's input to `input` in small Newton steps (the crank-rocker turns fully)
    const double start = m.hint.input;
    for (int i = 1; i <= 360; ++i) REQUIRE(solver.Correct(start + (input - start) * i / 360, q).ok());
    REQUIRE(solver.Series(3, series));
  }
  Eigen::Vector2d Point(const std::string& link, const std::string& point) const {
    const Mechanism& m = solver.system().mechanism();
    const int l = m.FindLink(link);
    double xy[2];
    solver.system().GlobalPoint({l, m.links[l].FindPoint(point)}, series.col(0).data(), xy);
    return {xy[0], xy[1]};
  }
};

PointRef Ref(const Mechanism& m, const std::string& link, const std::string& point) {
  const int l = m.FindLink(link);
  return {l, m.links[l].FindPoint(point)};
}

}  // namespace

TEST_CASE("the coupler's pole is where the crank line A0A meets the rocker line B0B", "[curvature]") {
  const Mechanism m = Seed003();
  for (double phi_deg : {10.0, 75.0, 140.0, 200.0, 290.0}) {
    const Pose pose(m, DegToRad(phi_deg));
    const auto expected = test::LineIntersection(pose.Point("frame", "A0"), pose.Point("crank", "A"), pose.Point("frame", "B0"),
                                                 pose.Point("rocker", "B"));
    REQUIRE(expected);
    const CurvatureResult r = CurvatureAt(pose.solver.system(), pose.series, DegToRad(phi_deg), Ref(m, "coupler", "K"));
    INFO("phi = " << phi_deg << ": " << r.message);
    REQUIRE(r.has_pole);
    CHECK((r.pole - *expected).norm() < kPositionTolerance * (1 + expected->norm()));
  }
}

TEST_CASE("A and B of a four-bar's coupler have their centres of curvature at A0 and B0", "[curvature]") {
  // A turns about A0 on the crank, B about B0 on the rocker: radii l1 and l3, exactly
  const Mechanism m = Seed003();
  const Pose pose(m, DegToRad(50));
  for (const auto& [point, pivot, radius] : {std::tuple{"A", "A0", 1.0}, std::tuple{"B", "B0", 2.5 * std::sqrt(3.0)}}) {
    const CurvatureResult r = CurvatureAt(pose.solver.system(), pose.series, DegToRad(50), Ref(m, "coupler", point));
    INFO(point << ": " << r.message);
    REQUIRE(r.rho_finite);
    CHECK((r.centre - pose.Point("frame", pivot)).norm() < kPositionTolerance);
    CHECK(std::abs(r.rho) == Approx(radius).epsilon(kRadius));
  }
}

TEST_CASE("Euler–Savary: the centre of curvature from the pole and the inflection circle equals the one from K's transfer functions",
          "[curvature]") {
  const Mechanism m = Seed003();
  const int k_output = m.FindOutput("K");
  for (double phi_deg : {20.0, 95.0, 160.0, 230.0, 315.0}) {
    Pose pose(m, DegToRad(phi_deg));
    // the reference: K_x', K_y', K_x'', K_y'' as `koppel analyze` prints them
    std::vector<double> d(pose.solver.OutputWidth(2));
    pose.solver.OutputDerivatives(pose.series, 2, d.data());
    const int cx = OutputColumn(m, k_output, 0, 2), cy = OutputColumn(m, k_output, 1, 2);
    const double kappa = test::PathCurvature(d[cx + 1], d[cy + 1], d[cx + 2], d[cy + 2]);
    const CurvatureResult r = CurvatureAt(pose.solver.system(), pose.series, DegToRad(phi_deg), Ref(m, "coupler", "K"));
    INFO("phi = " << phi_deg << ": " << r.message);
    REQUIRE(r.has_pole);
    REQUIRE(r.rho_finite);
    CHECK(r.curvature == Approx(kappa).epsilon(kCurvature));
    const auto centre = test::EulerSavaryCentre(r.pole, r.inflection_pole, r.point);
    REQUIRE(centre);
    CHECK((*centre - r.centre).norm() < 1e-8 * (1 + std::abs(r.rho)));
    CHECK(std::abs((*centre - r.point).norm() - std::abs(1 / kappa)) < 1e-8 * (1 + std::abs(1 / kappa)));
  }
}

TEST_CASE("the pole moves along the pole tangent, the inflection pole lies on the pole normal", "[curvature]") {
  // the acceleration of the body point at the pole is perpendicular to the pole's velocity
  // (Bottema and Roth, Theoretical Kinematics, ch. IV: a_P = w x u_P)
  const Mechanism m = Seed003();
  for (double phi_deg : {30.0, 120.0, 250.0}) {
    const Pose pose(m, DegToRad(phi_deg));
    const CurvatureResult r = CurvatureAt(pose.solver.system(), pose.series, DegToRad(phi_deg), Ref(m, "coupler", "K"));
    REQUIRE(r.has_pole_tangent);
    CHECK(std::abs(r.pole_velocity.normalized().dot((r.inflection_pole - r.pole).normalized())) < 1e-9);
  }
}

TEST_CASE("seed 003: K at phi = 180 deg lies on the inflection circle and is its Ball point", "[curvature]") {
  // seed 003: the straight line g touches the coupler curve six-fold in K_I (phi = 180 deg): K's
  // path has an inflection there (K on the inflection circle) with stationary curvature (the Ball
  // point, where the curve's contact with its tangent is at least four-fold)
  const Mechanism m = Seed003();
  const Pose pose(m, kPi);
  const CurvatureResult r = CurvatureAt(pose.solver.system(), pose.series, kPi, Ref(m, "coupler", "K"));
  INFO(r.message);
  REQUIRE(r.has_pole);
  CHECK(std::abs((r.point - r.inflection_centre).norm() - r.inflection_diameter / 2) < kPositionTolerance);
  CHECK_FALSE(r.rho_finite);
  CHECK(r.curvature == 0.0);
  REQUIRE(r.has_ball_point);
  CHECK((r.ball_point - r.point).norm() < 1e-7);
  // and a point off the circle at the same pose has a finite radius
  const CurvatureResult b = CurvatureAt(pose.solver.system(), pose.series, kPi, Ref(m, "coupler", "B"));
  CHECK(b.rho_finite);
}

TEST_CASE("the crank turns about A0: its pole is A0 and its inflection circle shrinks to it", "[curvature]") {
  const Mechanism m = Seed003();
  const Pose pose(m, DegToRad(40));
  const CurvatureResult r = CurvatureAt(pose.solver.system(), pose.series, DegToRad(40), Ref(m, "crank", "A"));
  REQUIRE(r.has_pole);
  CHECK(r.pole.norm() < kPositionTolerance);
  CHECK(r.inflection_diameter == 0.0);
  CHECK_FALSE(r.has_ball_point);
  CHECK(std::abs(r.rho) == Approx(1.0).epsilon(kUnitRadius));
}

TEST_CASE("a slider translates: no pole, and its point's path is straight", "[curvature]") {
  const Mechanism m = test::SliderCrank(1, 2.6, 0.8);
  const Pose pose(m, DegToRad(60));
  const CurvatureResult r = CurvatureAt(pose.solver.system(), pose.series, DegToRad(60), Ref(m, "slider", "B"));
  CHECK_FALSE(r.has_pole);
  CHECK(r.status == AnalysisStatus::kPartial);
  CHECK_THAT(r.message, Catch::Contains("pole is at infinity"));
  REQUIRE(r.has_curvature);
  CHECK_FALSE(r.rho_finite);
}

TEST_CASE("CurvatureAtInput walks to the input; an input beyond a limit point fails with the reason", "[curvature]") {
  const Mechanism m = Seed003();
  const CurvatureResult r = CurvatureAtInput(m, Ref(m, "coupler", "K"), kPi);
  REQUIRE(r.status == AnalysisStatus::kComplete);
  CHECK_FALSE(r.rho_finite);
  // the same mechanism driven at its rocker cannot pass the rocker's limits
  const Mechanism rocker_driven = test::FourBar(1, 2.5 * std::sqrt(3.0), 2.5 * std::sqrt(3.0), 4, 25.0 / 3, 0.3, +1, true);
  const CurvatureResult beyond = CurvatureAtInput(rocker_driven, Ref(rocker_driven, "coupler", "K"), DegToRad(170));
  CHECK(beyond.status == AnalysisStatus::kFailed);
  CHECK_FALSE(beyond.message.empty());
}

}  // namespace koppel::curvature_test
