// Branches and singular positions: Grashof-neutral four-bars stay on their branch through their
// change points (checked against an independent closed form of that branch at every row), the
// change points are reported where they are, --at-branch-point stop/switch do what they say,
// limit points end a sweep where the law of cosines puts them, a loop folding flat inside a
// six-bar is crossed and reported, and a scaled mechanism gives the same dimensionless answers.
#include "koppel/solver/continuation.hpp"
#include "koppel/solver/sweep.hpp"

#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace koppel::continuation_test {
namespace {

// [rad] a sample's input is from + i step: rounding only
constexpr double kSampleInput = 1e-12;
// [length/rad] s' in a row at a branch point comes from the window's interpolant of the
// branch (exact to ~1e-11 in the pose, less in its derivative), not from the singular Jacobian
constexpr double kBranchPointRate = 1e-8;

// The solver and the closed forms agree to roundoff; a pose next to a branch point comes from
// the window's interpolant (exact to ~1e-11 there): 1e-9 rad leaves room for both.
constexpr double kPose = 1e-9;
// psi' against a central difference of the closed form (h = 1e-6: truncation ~1e-12 psi''',
// roundoff ~1e-10): 1e-7.
constexpr double kRate = 1e-7;
// Branch points are located by regula falsi on det(J S) to ~1e-13 rad.
constexpr double kLocation = 1e-9;

SweepOptions Range(double from_deg, double to_deg, double step_deg, BranchPointAction action = BranchPointAction::kContinue) {
  SweepOptions o;
  o.from = DegToRad(from_deg);
  o.to = DegToRad(to_deg);
  o.step = DegToRad(step_deg);
  o.order = 2;
  o.continuation.at_branch_point = action;
  return o;
}

// Compares every row's psi and psi' with a closed form psi(phi) of the expected branch (psi' from
// `rate` when given, else a central difference of psi).
void CheckBranch(const Mechanism& m, const SweepResult& r, const std::function<double(double)>& psi,
                 const std::function<double(double)>& rate = nullptr) {
  const int column = OutputColumn(m, 0, 0, r.order);
  for (size_t i = 0; i < r.inputs.size(); ++i) {
    const double phi = r.inputs[i], h = 1e-6;
    INFO("phi = " << RadToDeg(phi) << " deg");
    CHECK(std::abs(AngleDifference(r.outputs(i, column), psi(phi))) < kPose);
    const double expected_rate = rate ? rate(phi) : AngleDifference(psi(phi + h), psi(phi - h)) / (2 * h);
    CHECK(std::abs(r.outputs(i, column + 1) - expected_rate) < kRate);
    CHECK(r.valid_order[i] >= 2);
    CHECK(std::isfinite(r.outputs(i, column + 2)));
  }
}

void CheckBranchPointsAt(const SweepResult& r, const std::vector<double>& expected_deg) {
  std::vector<double> found;
  for (const SingularPoint& p : r.singular_points) {
    CHECK(p.kind == SingularKind::kBranchPoint);
    found.push_back(p.input);
  }
  REQUIRE(found.size() == expected_deg.size());
  for (size_t k = 0; k < found.size(); ++k) CHECK(std::abs(found[k] - DegToRad(expected_deg[k])) < kLocation);
}

// Antiparallelogram (crank = rocker = a, coupler = frame = d): the loop closure
// d (cos psi - cos phi) + a (1 - cos(psi - phi)) = 0 factors into sin((psi - phi)/2) = 0 (the
// parallelogram) and a sin((psi - phi)/2) = d sin((psi + phi)/2), i.e.
// tan(psi/2) = k tan(phi/2), k = (a + d)/(a - d), psi' = k / (cos^2(phi/2) + k^2 sin^2(phi/2)).
// Well-conditioned at the change points, where the circle intersection is not.
double AntiParallelogram(double a, double d, double phi) {
  const double k = (a + d) / (a - d);
  return 2 * std::atan2(k * std::sin(phi / 2), std::cos(phi / 2));
}
double AntiParallelogramRate(double a, double d, double phi) {
  const double k = (a + d) / (a - d);
  return k / (std::pow(std::cos(phi / 2), 2) + k * k * std::pow(std::sin(phi / 2), 2));
}

}  // namespace

TEST_CASE("parallelogram over 0..720 deg stays a parallelogram through its change points", "[continuation]") {
  // crank = rocker = 1, coupler = frame = 3: Grashof-neutral; all links line up at 0, 180, 360 ...
  const Mechanism m = test::PlainFourBar(1, 3, 1, 3, DegToRad(90), {3, 1});
  const SweepResult r = Sweep(m, Range(0, 720, 7.5));
  REQUIRE(r.complete());
  REQUIRE(r.inputs.size() == 97);
  CheckBranch(m, r, [](double phi) { return phi; });  // psi = phi on the parallelogram branch
  CheckBranchPointsAt(r, {0, 180, 360, 540, 720});
  for (size_t i = 0; i < r.inputs.size(); ++i) {
    const bool at_change_point = std::abs(std::remainder(r.inputs[i], kPi)) < 1e-12;
    CHECK(r.singular[i] == (at_change_point ? 1 : 0));
  }
}

TEST_CASE("antiparallelogram over 0..720 deg stays an antiparallelogram", "[continuation]") {
  const Mechanism m = test::PlainFourBar(1, 3, 1, 3, DegToRad(90), {2.5, -0.6});
  const SweepResult r = Sweep(m, Range(0, 720, 7.5));
  REQUIRE(r.complete());
  CheckBranch(m, r, [](double phi) { return AntiParallelogram(1, 3, phi); }, [](double phi) { return AntiParallelogramRate(1, 3, phi); });
  CheckBranchPointsAt(r, {0, 180, 360, 540, 720});
}

TEST_CASE("deltoid (kite) turns its crank twice for one turn of the rocker, through its branch points", "[continuation]") {
  // crank = frame = a, coupler = rocker = b: A meets B0 at phi = 0, 360, 720 (a branch point
  // where the coupler and rocker could turn together); the kite branch has B on the bisector of
  // A A0 B0: B = r (cos phi/2, sin phi/2), r = a cos(phi/2) + sqrt(b^2 - a^2 sin^2(phi/2)).
  const double a = 1, b = 2.5;
  const Mechanism m = test::PlainFourBar(a, b, b, a, DegToRad(90), {2, 2});
  auto psi = [&](double phi) {
    const double r = a * std::cos(phi / 2) + std::sqrt(b * b - a * a * std::pow(std::sin(phi / 2), 2));
    return std::atan2(r * std::sin(phi / 2), r * std::cos(phi / 2) - a);
  };
  const SweepResult r = Sweep(m, Range(0, 720, 7.5));
  REQUIRE(r.complete());
  CheckBranch(m, r, psi);
  CheckBranchPointsAt(r, {0, 360, 720});
  // the rocker turns once while the crank turns twice
  const int column = OutputColumn(m, 0, 0, 2);
  CHECK(r.outputs(r.inputs.size() - 1, column) - r.outputs(0, column) == Approx(2 * kPi).margin(kPose));
  // switching is impossible there: the other branch (coupler and rocker turning together) runs
  // at constant input; the sweep stops at the point and says why
  const SweepResult s = Sweep(m, Range(0, 720, 7.5, BranchPointAction::kSwitch));
  CHECK(s.status == SweepStatus::kPartial);
  CHECK_THAT(s.message, Catch::Contains("cannot switch"));
  CHECK(std::abs(s.reached.to - DegToRad(360)) < kLocation);
}

TEST_CASE("--at-branch-point switch takes the other branch, stop ends the sweep there", "[continuation]") {
  const Mechanism m = test::PlainFourBar(1, 3, 1, 3, DegToRad(90), {3, 1});
  const SweepResult s = Sweep(m, Range(90, 350, 5, BranchPointAction::kSwitch));
  REQUIRE(s.complete());
  const int column = OutputColumn(m, 0, 0, 2);
  for (size_t i = 0; i < s.inputs.size(); ++i) {
    const double phi = s.inputs[i];
    INFO("phi = " << RadToDeg(phi));
    const double expected = phi <= kPi + 1e-12 ? phi : AntiParallelogram(1, 3, phi);  // antiparallelogram after 180
    CHECK(std::abs(AngleDifference(s.outputs(i, column), expected)) < kPose);
  }
  REQUIRE(s.singular_points.size() == 1);
  CHECK(s.singular_points[0].action == BranchPointAction::kSwitch);

  const SweepResult t = Sweep(m, Range(90, 350, 5, BranchPointAction::kStop));
  CHECK(t.status == SweepStatus::kPartial);
  CHECK(std::abs(t.reached.to - kPi) < kLocation);
  REQUIRE(t.gaps.size() == 1);
  CHECK(t.inputs.back() == Approx(kPi).margin(kSampleInput));  // the sample on the point itself is kept, flagged
  CHECK(t.singular.back() == 1);
}

TEST_CASE("a slider-crank with l2 = l1 + e: the rows at its branch points carry the branch's s', not 1e12", "[continuation]") {
  // l2 = l1 + e makes phi = 0 a branch point (A, B on the normal to the slide). The branch that
  // continues analytically has s = l1 sin phi + 2 sin(phi/2) sqrt(l1^2 cos^2(phi/2) + e l1)
  // (from s = A_x + sqrt(l2^2 - A_y^2) with l2^2 - A_y^2 = 4 sin^2(phi/2)(l1^2 cos^2(phi/2) + e l1)),
  // so s'(0) = l1 + sqrt(l1^2 + e l1) and s'(360 deg) = l1 - sqrt(l1^2 + e l1).
  const double l1 = 1, e = 0.8;
  const Mechanism m = test::SliderCrank(l1, l1 + e, e);
  const SweepResult r = Sweep(m, Range(0, 360, 10));
  REQUIRE(r.complete());
  CHECK(!r.notes.empty());  // the hint's input 0 is the branch point: said so
  const int s = OutputColumn(m, 0, 0, 2);
  auto closed = [&](double phi) { return l1 * std::sin(phi) + 2 * std::sin(phi / 2) * std::sqrt(l1 * l1 * std::pow(std::cos(phi / 2), 2) + e * l1); };
  for (size_t i = 0; i < r.inputs.size(); ++i) {
    const double phi = r.inputs[i], h = 1e-6;
    INFO("phi = " << RadToDeg(phi));
    CHECK(std::abs(r.outputs(i, s) - closed(phi)) < kPose);
    CHECK(std::abs(r.outputs(i, s + 1) - (closed(phi + h) - closed(phi - h)) / (2 * h)) < kRate);
    CHECK(std::abs(r.outputs(i, s + 2)) < 10.0);  // finite and of the size of the geometry
  }
  CHECK(r.outputs(0, s + 1) == Approx(l1 + std::sqrt(l1 * l1 + e * l1)).margin(kBranchPointRate));
  CHECK(r.outputs(r.inputs.size() - 1, s + 1) == Approx(l1 - std::sqrt(l1 * l1 + e * l1)).margin(kBranchPointRate));
  CHECK(r.singular.front() == 1);
  CHECK(r.singular.back() == 1);
}

TEST_CASE("a double-rocker driven across its limits: rows up to the limits, gaps beyond, limits by the law of cosines", "[continuation]") {
  // Grashof double-rocker: the coupler (1) is shortest; the input link a = 3 can only swing
  // while 2.5 <= |A B0| <= 4.5
  const double a = 3, b = 1, c = 3.5, d = 4;
  const auto limits = test::FourBarLimits(a, b, c, d);  // 38.62, 78.58 deg and their mirrors
  const double low = *std::min_element(limits.begin(), limits.end()), high = limits[0];
  const Eigen::Vector2d hint = test::FourBarRocker(a, b, c, d, DegToRad(60), +1)->b;
  const Mechanism m = test::PlainFourBar(a, b, c, d, DegToRad(60), hint);
  const SweepResult r = Sweep(m, Range(0, 120, 1));
  CHECK(r.status == SweepStatus::kPartial);
  CHECK(std::abs(r.reached.from - low) < 1e-9);
  CHECK(std::abs(r.reached.to - high) < 1e-9);
  REQUIRE(r.gaps.size() == 2);
  CHECK(r.gaps[0].from == 0.0);
  CHECK(r.gaps[0].to == r.reached.from);
  CHECK(r.gaps[1].to == DegToRad(120));
  CHECK(r.inputs.size() == 40);  // 39 .. 78 deg
  CheckBranch(m, r, [&](double phi) { return test::FourBarRocker(a, b, c, d, phi, +1)->psi; });
  REQUIRE(r.singular_points.size() == 2);
  for (const SingularPoint& p : r.singular_points) CHECK(p.kind == SingularKind::kLimitPoint);
}

TEST_CASE("a six-bar whose second loop folds flat: rows follow the branch, the fold is a branch point of that loop", "[continuation]") {
  // the fold direction is the direction of B0 -> C at phi = 110 deg (from the first loop's closed
  // form), so the parallelogram loop B0 C D D0 lines up there and again where the rocker swings back
  const double r_c = 1.5, gamma = 0.7, e = 2.0;
  const double psi110 = test::FourBarRocker(1, 3.5, 3, 4, DegToRad(110), +1)->psi;
  const Mechanism m = test::FoldingSixBar(r_c, gamma, e, psi110 + gamma);
  const SweepResult r = Sweep(m, Range(0, 360, 2));
  REQUIRE(r.complete());
  const int psi = OutputColumn(m, 0, 0, 2), chi = OutputColumn(m, 1, 0, 2);
  for (size_t i = 0; i < r.inputs.size(); ++i) {
    INFO("phi = " << RadToDeg(r.inputs[i]));
    const double rocker = test::FourBarRocker(1, 3.5, 3, 4, r.inputs[i], +1)->psi;
    CHECK(std::abs(AngleDifference(r.outputs(i, psi), rocker)) < kPose);
    // parallelogram branch: D0 D stays parallel to B0 C
    CHECK(std::abs(AngleDifference(r.outputs(i, chi), rocker + gamma)) < kPose);
  }
  // the folds: where the rocker passes psi(110 deg) again on its way back
  int folds = 0;
  for (const SingularPoint& p : r.singular_points) {
    CHECK(p.kind == SingularKind::kBranchPoint);
    const double rocker = test::FourBarRocker(1, 3.5, 3, 4, p.input, +1)->psi;
    CHECK(std::abs(std::remainder(rocker - psi110, kPi)) < 1e-8);
    // the self-stress lives in the second loop only
    std::vector<std::string> names;
    for (int j : p.joints) names.push_back(m.joints[j].name);
    std::sort(names.begin(), names.end());
    CHECK(names == std::vector<std::string>{"B0", "C", "D", "D0"});
    ++folds;
  }
  CHECK(folds == 2);
  CHECK(std::any_of(r.singular_points.begin(), r.singular_points.end(),
                    [](const SingularPoint& p) { return std::abs(p.input - DegToRad(110)) < kLocation; }));
}

TEST_CASE("scaled by 1e-6 and 1e6 the same mechanism gives the same dimensionless results and singular points", "[continuation]") {
  const Mechanism base = test::PlainFourBar(1, 3, 1, 3, DegToRad(90), {3, 1});
  const SweepResult reference = Sweep(base, Range(0, 360, 15));
  REQUIRE(reference.complete());
  for (double factor : {1e-6, 1e6}) {
    INFO("factor " << factor);
    const SweepResult r = Sweep(test::Scaled(base, factor), Range(0, 360, 15));
    REQUIRE(r.complete());
    REQUIRE(r.inputs.size() == reference.inputs.size());
    // angles and first-order transfer functions to 1e-9; the second order at the branch points
    // comes from the window's interpolant, good to ~1e-8 there
    const int psi = OutputColumn(base, 0, 0, 2);
    CHECK((r.outputs.middleCols(psi, 2) - reference.outputs.middleCols(psi, 2)).cwiseAbs().maxCoeff() < 1e-9);
    CHECK((r.outputs.col(psi + 2) - reference.outputs.col(psi + 2)).cwiseAbs().maxCoeff() < 1e-7);
    REQUIRE(r.singular_points.size() == reference.singular_points.size());
    for (size_t k = 0; k < r.singular_points.size(); ++k) CHECK(std::abs(r.singular_points[k].input - reference.singular_points[k].input) < kLocation);
    CHECK(r.singular == reference.singular);
  }
  // a slider drive: lengths scale, the slide input too
  const Mechanism slider = test::SliderCrank(1, 2.6, 0.8);
  const SweepResult s0 = Sweep(slider, Range(0, 360, 10));
  for (double factor : {1e-6, 1e6}) {
    const SweepResult s = Sweep(test::Scaled(slider, factor), Range(0, 360, 10));
    REQUIRE(s.complete());
    // s, s', s'' are lengths: divided by the factor they equal the unscaled ones
    CHECK((s.outputs.leftCols(3) / factor - s0.outputs.leftCols(3)).cwiseAbs().maxCoeff() < 1e-9);
  }
}

TEST_CASE("continuation options validate themselves", "[continuation]") {
  ContinuationOptions o;
  std::string why;
  CHECK(o.IsValid(&why));
  CHECK(why.empty());
  o.max_step = 0;
  CHECK_FALSE(o.IsValid(&why));
  CHECK_THAT(why, Catch::Contains("max_step"));
  o = ContinuationOptions{};
  o.branch_window = 2;
  CHECK_FALSE(o.IsValid(&why));
  SweepOptions s;
  s.step = 0;
  CHECK_FALSE(s.IsValid(&why));
  s.step = 1e-12;
  CHECK_FALSE(s.IsValid(&why));
  CHECK_THAT(why, Catch::Contains("samples"));
  s.step = 0.01;
  s.order = 9;
  CHECK_FALSE(s.IsValid(&why));
  const SweepResult r = Sweep(test::SliderCrank(1, 2.6, 0.8), s);
  CHECK(r.status == SweepStatus::kInvalidOptions);
  CHECK(r.inputs.empty());
}

}  // namespace koppel::continuation_test

namespace koppel::continuation_test {

// The walk budget: a walk that has spent its time ends, saying where it stood, and the walk
// stands on the branch there (a later walk goes on from it). The reference: a crank-rocker's
// rocker angle at the input the walk stopped at, from the same mechanism walked there directly.
TEST_CASE("a walk past its time budget stops where it stands and says so", "[continuation]") {
  const Mechanism m = test::PlainFourBar(1, 3.5, 3, 4, 0.0, Eigen::Vector2d(2.5, 2.6));
  PositionSolver solver(m);
  Eigen::VectorXd q(solver.NumCoordinates());
  REQUIRE(solver.Assemble(q).ok());
  ContinuationOptions options;
  options.time_budget = 1e-9;  // spent at the first look at the clock (the 1024th step)
  Continuation walk(solver, options);
  REQUIRE(walk.Start(0.0, q).ok());
  const WalkReport r = walk.AdvanceTo(1e4, 0.01);  // a million steps of 0.01 rad
  REQUIRE(r.status == WalkStatus::kTooFar);
  CHECK_THAT(r.message, Catch::Contains("time budget") && Catch::Contains("1024 continuation steps"));
  CHECK(r.input == Approx(1023 * 0.01).margin(1e-9));
  const Eigen::VectorXd stood = walk.q();
  PositionSolver fresh_solver(m);
  Continuation fresh(fresh_solver);
  REQUIRE(fresh.Start(0.0, q).ok());
  REQUIRE(fresh.AdvanceTo(r.input, 0.01).ok());
  CHECK((fresh.q() - stood).cwiseAbs().maxCoeff() < 1e-9);
  ContinuationOptions none;
  none.time_budget = 0;
  std::string why;
  CHECK_FALSE(none.IsValid(&why));
  CHECK_THAT(why, Catch::Contains("time_budget"));
}

}  // namespace koppel::continuation_test
