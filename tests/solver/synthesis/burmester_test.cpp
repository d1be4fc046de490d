// Burmester dyads from poses of known four-bars' couplers (a hand-picked crank-rocker and seeded
// random ones): the poses are read off the solver's sweep of the known four-bar, so the known
// pivots are an exact answer. References: the conditions |A_j - A0| = |A_1 - A0| evaluated
// directly here (not through the library's normal form), and the known four-bar itself.
#include "koppel/synthesis/burmester.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"
#include "koppel/synthesis/four_bar_design.hpp"
#include "koppel/synthesis/motion_synthesis.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace koppel::burmester_test {
namespace {

// [rad] the turn about a centre point built in closed form, read back with atan2 of O(1)
// vectors: a few ulps
constexpr double kTurnRoundoff = 1e-12;

constexpr double kRecovered = 1e-9;  // the issue's: the known four-bar among the answers to 1e-9

struct Known {
  FourBarGeometry g;
  Mechanism m;
};

// A crank-rocker A0 (0,0), A (1,0) ... with the plane's reference point off the coupler line.
Known HandPicked() {
  Known k;
  k.g.a0 = {0, 0};
  k.g.a = {1, 0.2};
  k.g.b = {3.1, 2.4};
  k.g.b0 = {4, 0.3};
  k.g.plane_origin = {2.2, 3.3};
  k.g.plane_angle = 0.3;
  k.m = DesignedFourBar(k.g, "known");
  return k;
}

// A seeded random crank-rocker: crank the shortest link, Grashof with margin.
Known RandomCrankRocker(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  for (;;) {
    const double a = 0.5 + 0.5 * u(rng), b = 2 + 2 * u(rng), c = 2 + 2 * u(rng), d = 2 + 2 * u(rng);
    if (a + std::max({b, c, d}) > 0.9 * (a + b + c + d - a - std::max({b, c, d}))) continue;
    Known k;
    const double phi = 2 * kPi * u(rng), frame = 2 * kPi * u(rng);
    k.g.a0 = {u(rng), u(rng)};
    k.g.b0 = k.g.a0 + d * Eigen::Vector2d(std::cos(frame), std::sin(frame));
    k.g.a = k.g.a0 + a * Eigen::Vector2d(std::cos(phi), std::sin(phi));
    const auto b_point = FourBarJointB(k.g.a, k.g.b0, b, c, u(rng) < 0.5 ? 1 : -1);
    if (!b_point) continue;
    k.g.b = *b_point;
    k.g.plane_origin = k.g.a + Eigen::Vector2d(2 * u(rng) - 1, 2 * u(rng) - 1) * b;
    k.g.plane_angle = 2 * kPi * u(rng) - kPi;
    k.m = DesignedFourBar(k.g, "random");
    return k;
  }
}

// The coupler's poses at crank inputs start + offsets (the solver's sweep of the known four-bar).
std::vector<Pose> PosesOf(const Known& k, const std::vector<double>& offsets_deg) {
  std::vector<Pose> poses;
  for (double offset : offsets_deg) {
    SweepOptions s;
    s.from = s.to = k.m.hint.input + DegToRad(offset);
    s.order = 0;
    const SweepResult r = Sweep(k.m, s);
    REQUIRE(r.complete());
    poses.push_back({{r.outputs(0, 0), r.outputs(0, 1)}, r.outputs(0, 2)});
  }
  return poses;
}

// The condition itself: the circle point's distances from the centre point in every pose.
double Spread(const std::vector<Pose>& poses, const Dyad& d) {
  double lo = 1e300, hi = 0;
  for (const Pose& p : poses) {
    const Eigen::Matrix2d r = Eigen::Rotation2Dd(p.angle - poses[0].angle).toRotationMatrix();
    const double dist = (p.point + r * (d.circle - poses[0].point) - d.centre).norm();
    lo = std::min(lo, dist);
    hi = std::max(hi, dist);
  }
  return hi - lo;
}

bool Contains(const std::vector<Dyad>& dyads, const Dyad& d, double tol) {
  for (const Dyad& x : dyads)
    if ((x.centre - d.centre).norm() <= tol && (x.circle - d.circle).norm() <= tol) return true;
  return false;
}

}  // namespace

TEST_CASE("three poses: the centre points of the known circle points are the known pivots", "[burmester]") {
  std::mt19937 rng(1301);
  for (int trial = 0; trial < 20; ++trial) {
    const Known k = trial == 0 ? HandPicked() : RandomCrankRocker(rng);
    const std::vector<Pose> poses = PosesOf(k, {0, 40, 95});
    const CentrePointResult ca = CentrePoint(poses, k.g.a), cb = CentrePoint(poses, k.g.b);
    REQUIRE(ca.ok());
    REQUIRE(cb.ok());
    CHECK((ca.dyad.centre - k.g.a0).norm() <= kRecovered);
    CHECK((cb.dyad.centre - k.g.b0).norm() <= kRecovered);
    const MotionFourBar f = AnalyseMotionFourBar(poses, ca.dyad, cb.dyad);
    INFO(f.message);
    CHECK(f.passes);
    CHECK_FALSE(f.branch_defect);
    CHECK_FALSE(f.order_defect);
  }
}

TEST_CASE("a circle point whose positions are collinear has no centre point", "[burmester]") {
  // pure translation along x: every point moves on a line
  const std::vector<Pose> poses = {{{0, 0}, 0}, {{1, 0}, 0}, {{2, 0}, 0}};
  const CentrePointResult r = CentrePoint(poses, {0.5, 0.5});
  CHECK_FALSE(r.ok());
  CHECK_THAT(r.message, Catch::Contains("collinear"));
}

TEST_CASE("four poses: the Burmester curves' samples meet the 4-pose condition and pass the known pivots", "[burmester]") {
  std::mt19937 rng(1302);
  for (int trial = 0; trial < 10; ++trial) {
    const Known k = trial == 0 ? HandPicked() : RandomCrankRocker(rng);
    const std::vector<Pose> poses = PosesOf(k, {0, 30, 70, 120});
    const double scale = PoseScale(poses);
    const BurmesterCurves curves = CentrePointCurve(poses, 720);
    REQUIRE(curves.ok());
    REQUIRE(curves.samples.size() > 100);
    double worst = 0, near_a0 = 1e300, near_b0 = 1e300;
    for (const BurmesterCurveSample& s : curves.samples) {
      worst = std::max(worst, Spread(poses, s.dyad));
      near_a0 = std::min(near_a0, (s.dyad.centre - k.g.a0).norm());
      near_b0 = std::min(near_b0, (s.dyad.centre - k.g.b0).norm());
    }
    CHECK(worst <= 1e-9 * scale);
    // 720 lines through the pole: the curve is sampled every quarter degree, so a point of it
    // (the known pivot) lies within a small fraction of the poses' size of a sample
    INFO("pole " << curves.base_pole.transpose() << " a0 " << k.g.a0.transpose() << " b0 " << k.g.b0.transpose() << " scale " << scale);
    CHECK(near_a0 <= 0.05 * scale);
    CHECK(near_b0 <= 0.05 * scale);
    // the known circle points have the known centre points with all four poses
    const CentrePointResult ca = CentrePoint(poses, k.g.a);
    REQUIRE(ca.ok());
    CHECK((ca.dyad.centre - k.g.a0).norm() <= kRecovered);
    // and a point off the circle-point curve has none
    CHECK_FALSE(CentrePoint(poses, k.g.a + Eigen::Vector2d(0.1, 0.05) * scale).ok());
  }
}

TEST_CASE("five poses: the known pivots are among the Ball-Burmester points, the known four-bar among the answers", "[burmester]") {
  std::mt19937 rng(1303);
  int recovered = 0;
  const int trials = 12;
  for (int trial = 0; trial < trials; ++trial) {
    const Known k = trial == 0 ? HandPicked() : RandomCrankRocker(rng);
    const std::vector<Pose> poses = PosesOf(k, {0, 25, 60, 110, 170});
    const BallBurmester bb = BallBurmesterPoints(poses);
    REQUIRE(bb.ok());
    INFO("trial " << trial << ": " << bb.dyads.size() << " points");
    CHECK(bb.dyads.size() <= 4);
    CHECK(bb.dyads.size() % 2 == 0);
    for (const Dyad& d : bb.dyads) CHECK(Spread(poses, d) <= 1e-9 * PoseScale(poses));
    const bool a_found = Contains(bb.dyads, {k.g.a0, k.g.a}, kRecovered), b_found = Contains(bb.dyads, {k.g.b0, k.g.b}, kRecovered);
    CHECK(a_found);
    CHECK(b_found);
    const MotionResult r = FourBarsFromDyads(poses, bb.dyads, {});
    CHECK(r.failed == 0);
    bool known = false;
    for (const MotionFourBar& f : r.four_bars) {
      CHECK(f.passes);
      known = known || ((f.crank.centre - k.g.a0).norm() <= kRecovered && (f.rocker.centre - k.g.b0).norm() <= kRecovered &&
                        (f.crank.circle - k.g.a).norm() <= kRecovered && (f.rocker.circle - k.g.b).norm() <= kRecovered);
    }
    CHECK(known);
    // the known crank-rocker meets its own poses in order on one branch
    for (const MotionFourBar& f : r.four_bars) {
      if ((f.crank.centre - k.g.a0).norm() > kRecovered || (f.rocker.centre - k.g.b0).norm() > kRecovered) continue;
      CHECK(f.crank_turns_fully);
      CHECK_FALSE(f.branch_defect);
      CHECK_FALSE(f.order_defect);
      CHECK(f.grashof == GrashofType::kCrankRocker);
    }
    recovered += a_found && b_found;
  }
  CHECK(recovered == trials);
}

}  // namespace koppel::burmester_test

namespace koppel::burmester_test {

TEST_CASE("two poses: the centre point on the bisector turns the crank by the given angle", "[burmester]") {
  const std::vector<Pose> poses = {{{0, 0}, 0}, {{1, 0.5}, 0.4}};
  for (double turn_deg : {30.0, 90.0, -120.0}) {
    const CentrePointResult r = CentrePointTwoPoses(poses, {0.3, 0.8}, DegToRad(turn_deg));
    REQUIRE(r.ok());
    CHECK(r.residual <= 1e-12);
    const Eigen::Vector2d a2 = MovePoint(poses[0], poses[1], {0.3, 0.8});
    const Eigen::Vector2d u = r.dyad.circle - r.dyad.centre, v = a2 - r.dyad.centre;
    CHECK_THAT(std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v)), Catch::Matchers::WithinAbs(DegToRad(turn_deg), kTurnRoundoff));
  }
}

}  // namespace koppel::burmester_test
