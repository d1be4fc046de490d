// Issue 22, items 6, 7 and 12 in the kernel: an R drive's input is an angle modulo a turn (a
// triple-rocker swept over 260..360 deg gets its rows at -100..0 deg, printed as asked); a
// mechanism whose assembly hint does not assemble is started where a seeded search over a turn
// finds a regular pose, the same every run; a distance output through zero gives its rows with
// the cells it has no number for listed, never a non-finite number.
#include "koppel/solver/assembly.hpp"
#include "koppel/solver/sweep.hpp"

#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::drive_input_test {
namespace {

// [rad] a sample's input is the one asked for (from + i step): rounding only
constexpr double kSampleInput = 1e-12;
// [rad] limit points are located by regula falsi on det(J S) to ~1e-13 rad (continuation.hpp)
constexpr double kLimitInput = 1e-12;
// a distance output against 2 a |sin(phi / 2)| of O(1) lengths: rounding of the assembled pose
constexpr double kDistanceRoundoff = 1e-12;

// psi against the circle intersection: roundoff of both (1e-12), far below a wrong branch (O(1)).
constexpr double kPose = 1e-9;

SweepOptions Range(double from_deg, double to_deg, double step_deg) {
  SweepOptions o;
  o.from = DegToRad(from_deg);
  o.to = DegToRad(to_deg);
  o.step = DegToRad(step_deg);
  return o;
}

// catalog/entries/triple-rocker.yaml's four-bar (3, 4, 2.5, 5), B above the frame line: it swings
// between -+phi_G, cos phi_G = (a^2 + d^2 - (b + c)^2) / (2 a d) (105.962 deg)
struct TripleRocker {
  double a = 3, b = 4, c = 2.5, d = 5;
  double phi_g = std::acos((a * a + d * d - (b + c) * (b + c)) / (2 * a * d));
  Mechanism m = test::PlainFourBar(a, b, c, d, 0.0, test::FourBarRocker(a, b, c, d, 0.0, +1)->b);
};

}  // namespace

TEST_CASE("an R drive's input is an angle: 260 .. 360 deg of a triple-rocker are -100 .. 0 deg", "[sweep][periodic]") {
  const TripleRocker f;
  const SweepResult r = Sweep(f.m, Range(260, 360, 10));
  INFO(r.message);
  REQUIRE(r.complete());
  REQUIRE(r.inputs.size() == 11);
  const int psi = OutputColumn(f.m, 0, 0, 2);
  for (size_t i = 0; i < r.inputs.size(); ++i) {
    CHECK(r.inputs[i] == Approx(DegToRad(260 + 10.0 * i)).margin(kSampleInput));  // as asked
    INFO("phi = " << RadToDeg(r.inputs[i]));
    CHECK(std::abs(AngleDifference(r.outputs(i, psi), test::FourBarRocker(f.a, f.b, f.c, f.d, r.inputs[i], +1)->psi)) < kPose);
  }
  // over a whole turn: the rows on both sides, one gap between the limits (phi_G .. 360 - phi_G)
  const SweepResult t = Sweep(f.m, Range(0, 360, 1));
  CHECK(t.status == SweepStatus::kPartial);
  REQUIRE(t.gaps.size() == 1);
  CHECK(t.gaps[0].from == Approx(f.phi_g).margin(kLimitInput));
  CHECK(t.gaps[0].to == Approx(2 * kPi - f.phi_g).margin(kLimitInput));
  CHECK(t.inputs.size() == 106 + 106);  // 0 .. 105 and 255 .. 360
  for (size_t i = 0; i < t.inputs.size(); ++i) {
    INFO("phi = " << RadToDeg(t.inputs[i]));
    CHECK(std::abs(AngleDifference(t.outputs(i, psi), test::FourBarRocker(f.a, f.b, f.c, f.d, t.inputs[i], +1)->psi)) < kPose);
  }
  // both limits are reported, each once
  REQUIRE(t.singular_points.size() == 2);
  CHECK(t.singular_points[0].input == Approx(-f.phi_g).margin(kLimitInput));
  CHECK(t.singular_points[1].input == Approx(f.phi_g).margin(kLimitInput));
}

TEST_CASE("a branch point stop is no limit: the kite's second turn is not its first one again", "[sweep][periodic]") {
  // the kite (deltoid) a = 1, b = 2.5 turns its crank twice for one rocker turn; stopped at its
  // branch point at 360 deg, the rows beyond are a gap, not the first turn mapped
  const double a = 1, b = 2.5;
  const Mechanism m = test::PlainFourBar(a, b, b, a, DegToRad(90), {2, 2});
  SweepOptions o = Range(0, 720, 7.5);
  o.continuation.at_branch_point = BranchPointAction::kStop;
  const SweepResult r = Sweep(m, o);
  CHECK(r.status == SweepStatus::kPartial);
  CHECK(r.inputs.back() <= DegToRad(360) + 1e-9);
}

TEST_CASE("an assembly hint that does not assemble: a seeded search over a turn finds the start", "[assembly]") {
  // seed 000's slider-crank with a rod too short to reach the slide at the hint's phi = 0:
  // |A_y| = |e + l1 cos phi| <= l2 only for cos phi <= (l2 - e) / l1, phi in 66.4 .. 293.6 deg
  const double l1 = 1, l2 = 0.9, e = 0.5;
  const Mechanism m = test::SliderCrank(l1, l2, e);
  PositionSolver solver(m);
  Eigen::VectorXd q(solver.NumCoordinates());
  REQUIRE(!solver.Assemble(q).ok());
  const Assembly a = AssembleRegular(m, solver);
  REQUIRE(a.ok());
  CHECK(a.start == AssemblyStart::kSearched);
  CHECK(std::cos(a.input) <= (l2 - e) / l1);
  REQUIRE(a.notes.size() == 1);
  CHECK_THAT(a.notes[0], Catch::Contains("does not assemble at phi = 0 deg") && Catch::Contains("assembled at"));
  // the pose closes the joints there: s from seed 000's closed form on one of its two branches
  const std::optional<test::SlideValues> right = test::SliderCrankBranch(l1, l2, e, a.input, +1);
  const std::optional<test::SlideValues> left = test::SliderCrankBranch(l1, l2, e, a.input, -1);
  REQUIRE(right);
  REQUIRE(left);
  const double s = a.q(6);  // the slider's x: its body origin is B
  CHECK(std::min(std::abs(s - right->s), std::abs(s - left->s)) < 1e-12);
  // reproducible
  PositionSolver again(m);
  const Assembly b = AssembleRegular(m, again);
  CHECK(b.input == a.input);
  CHECK((b.q - a.q).cwiseAbs().maxCoeff() == 0.0);
  // and the sweep starts there: the drivable range ends at the closed form's limits
  const SweepResult sweep = Sweep(m, Range(0, 360, 5));
  CHECK(sweep.inputs.size() == static_cast<size_t>(std::floor(293.6 / 5) - std::ceil(66.4 / 5) + 1));
  REQUIRE(!sweep.notes.empty());
  // a mechanism that assembles nowhere still says so
  const Mechanism never = test::SliderCrank(1, 0.2, 2);
  PositionSolver third(never);
  const Assembly c = AssembleRegular(never, third);
  CHECK(!c.ok());
  CHECK_THAT(c.error, Catch::Contains("nor at any input of a turn"));
}

TEST_CASE("a distance output through zero: its rows, the cells without a number listed, no NaN", "[sweep][outputs]") {
  // crank-rocker 1, 3, 2.5, 3 with a frame point X = (a, 0): d = |A X| = 2 a |sin(phi / 2)| is 0
  // at phi = 0, where d' jumps from -a to a: d' and d'' have no value there
  const double a = 1;
  Mechanism m = test::PlainFourBar(a, 3, 2.5, 3, DegToRad(60), {3.2, 2.5});
  const int frame = m.FindLink("frame"), crank = m.FindLink("crank");
  m.links[frame].points.push_back({"X", {a, 0}});
  Output d;
  d.name = "d";
  d.kind = OutputKind::kDistance;
  d.p = {crank, m.links[crank].FindPoint("A")};
  d.q = {frame, m.links[frame].FindPoint("X")};
  m.outputs.insert(m.outputs.begin(), d);
  const SweepResult r = Sweep(m, Range(-20, 20, 10));
  INFO(r.message);
  CHECK(r.complete());  // every sample is there
  CHECK(r.undefined.size() == 2);
  REQUIRE(r.inputs.size() == 5);
  CHECK(r.outputs.allFinite());
  const int column = OutputColumn(m, 0, 0, 2);
  for (int i = 0; i < 5; ++i) {
    const double phi = r.inputs[i];
    CHECK(r.outputs(i, column) == Approx(2 * a * std::abs(std::sin(phi / 2))).margin(kDistanceRoundoff));
    const bool zero = i == 2;
    CHECK(r.Defined(i, column));
    CHECK(r.Defined(i, column + 1) == !zero);
    CHECK(r.Defined(i, column + 2) == !zero);
    if (!zero) CHECK(r.outputs(i, column + 1) == Approx(a * std::cos(phi / 2) * (phi > 0 ? 1 : -1)).margin(kPose));
    CHECK(r.Defined(i, OutputColumn(m, 1, 0, 2) + 1));  // psi is differentiable everywhere
  }
  CHECK_THAT(r.message, Catch::Contains("output 'd' is not differentiable at phi = 0 deg"));
}

}  // namespace koppel::drive_input_test
