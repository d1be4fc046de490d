// The compiled joint-point step against the general kernel: both walk the same mechanism in steps
// of 1 deg (the general one by predictor-corrector continuation on link poses, continuation.hpp,
// on the dense reference path, which never takes the schedule; the schedule by its dyads' 2 x 2
// Newton on joint points), and every pose, every output, and their first and second derivatives
// must agree. Both converge to 1e-13 L and differentiate exactly, so the reference is the general
// kernel itself to 1e-10 (units of L and rad).
#include "koppel/solver/point_schedule.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/build.hpp"
#include "koppel/solver/assembly.hpp"
#include "koppel/solver/continuation.hpp"
#include "koppel/solver/singular.hpp"
#include "support/mechanisms.hpp"
#include "support/seeds.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace koppel::point_schedule_test {
namespace {

// q and its series from two exact methods, each converged to 1e-13 L: far below this.
constexpr double kAgreement = 1e-10;

struct WalkResult {
  int steps = 0;
  double worst = 0.0;   // the largest difference of q, dq, d2q/2 (units of L and rad)
  double worst_output = 0.0;  // the largest difference of an output or its 1st or 2nd derivative
  int sign_products = 0;  // distinct values of (general det sign) x (schedule det sign) seen
};

// Walks `m` `steps` steps of `step` from its regular assembly with both kernels.
WalkResult WalkBoth(const Mechanism& m, int steps, double step) {
  NewtonOptions dense;
  dense.dense = true;  // the reference path: the continuation takes no compiled step on it
  PositionSolver solver(m, dense);
  const Assembly assembly = AssembleRegular(m, solver);
  REQUIRE(assembly.ok());
  Continuation path(solver);
  REQUIRE(path.Start(assembly.input, assembly.q).ok());
  PointSchedule schedule(solver.system());
  REQUIRE(schedule.compiled());
  schedule.Load(path.input(), path.q(), path.Series(2));
  const double length = solver.system().length_scale();
  WalkResult result;
  int first_product = 0;
  bool mixed = false;
  Eigen::VectorXd q;
  Eigen::MatrixXd series(solver.NumCoordinates(), 3);
  std::vector<double> outputs(solver.OutputWidth(2)), reference_outputs(solver.OutputWidth(2));
  for (int i = 1; i <= steps; ++i) {
    const double next = assembly.input + i * step;
    if (!path.AdvanceTo(next, step).ok()) break;
    REQUIRE(schedule.Step(next));
    schedule.Pose(q);
    schedule.Series(series);
    const Eigen::MatrixXd& reference = path.Series(2);
    for (int k = 0; k <= 2; ++k) {
      for (int r = 0; r < q.size(); ++r) {
        const double scale = r % 3 == 2 ? 1.0 : length;
        const double mine = k == 0 ? q(r) : series(r, k);
        result.worst = std::max(result.worst, std::abs(mine - reference(r, k)) / scale);
        if (k == 0) result.worst = std::max(result.worst, std::abs(series(r, 0) - reference(r, 0)) / scale);
      }
    }
    schedule.OutputDerivatives(2, outputs.data());
    path.OutputDerivatives(2, reference_outputs.data());
    for (size_t c = 0; c < outputs.size(); ++c) {
      // angles and lengths alike in units of L: the test mechanisms are about 1 to 10 L long
      result.worst_output = std::max(result.worst_output, std::abs(outputs[c] - reference_outputs[c]) / std::max(1.0, length));
    }
    const int product = solver.JacobianSign() * schedule.DeterminantSign();
    if (first_product == 0) first_product = product;
    mixed = mixed || product != first_product;
    ++result.steps;
  }
  result.sign_products = mixed ? 2 : 1;
  return result;
}

// `m` with an output of every kind the seeds lack: a distance and a direction between two moving
// points, the relative angle of the joint at `joint`. (The direction is chosen away from +-180
// deg, where both kernels' atan2 would jump by a turn at slightly different inputs.)
Mechanism WithEveryOutputKind(Mechanism m, const std::string& link_p, const std::string& p, const std::string& link_q,
                              const std::string& q, const std::string& joint) {
  DistanceOutput(m, "distance", link_p, p, link_q, q);
  DirectionOutput(m, "direction", link_p, p, link_q, q);
  JointOutput(m, "joint", joint);
  return m;
}

// Both kernels walked all `steps` and agreed (see kAgreement), det J's sign with the dyads'.
void CheckAgreement(const WalkResult& r, int steps) {
  CHECK(r.steps == steps);
  CHECK(r.worst <= kAgreement);
  CHECK(r.worst_output <= kAgreement);
  CHECK(r.sign_products == 1);
}

// A four-bar with a block sliding on its rocker's line, pushed by a rod from the crank pin: an RP
// dyad on a turning guide and the displacement of a slide that turns (the rod longer than A's
// farthest distance from B0, 5: the rod never stands square to the line).
Mechanism FourBarWithRockerSlider() {
  Mechanism m = test::FourBar(1, 4, 3.5, 4, 2, 0.3, 1);
  m.name = "four-bar with a slider on its rocker";
  AddLink(m, "rod", {{"A", {0, 0}}, {"C", {6, 0}}});
  AddLink(m, "block", {{"C", {0, 0}}});
  Revolute(m, "A2", "crank", "rod", "A", "A");
  Revolute(m, "C", "rod", "block");
  Prismatic(m, "S", "rocker", "B0", "block", "C", {1, 0});
  JointOutput(m, "s", "S");
  return m;
}

// `loops` four-bar loops in a row on one frame line, 4 apart: a crank-rocker (1, 3.5, 3, 4) drives
// the first rocker, and each rocker drives the next through a coupler of 4 from its point D (2.5
// along it) to the next rocker's C (2.6 along it): nearly parallelograms, each loop's swing a
// little smaller than the one before. L is the frame's length, 4 (loops + 1); the crank is 1.
Mechanism ChainOfLoops(int loops) {
  Mechanism m;
  m.name = "chain of " + std::to_string(loops) + " loops";
  PointList frame{{"A0", {0, 0}}};
  for (int i = 0; i < loops; ++i) frame.push_back({"P" + std::to_string(i), {4.0 * (i + 1), 0}});
  AddLink(m, "frame", frame, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {1, 0}}});
  AddLink(m, "coupler0", {{"A", {0, 0}}, {"B", {3.5, 0}}});
  AddLink(m, "rocker0", {{"P0", {0, 0}}, {"B", {3, 0}}, {"D", {2.5, 0}}});
  Revolute(m, "A0", "frame", "crank");
  Revolute(m, "A", "crank", "coupler0");
  Revolute(m, "B", "coupler0", "rocker0");
  Revolute(m, "P0", "frame", "rocker0");
  HintPoint(m, "coupler0", "B", {3.5, 2.9});  // B above the frame line (the crank at 0: B near (3.6, 2.97))
  for (int i = 1; i < loops; ++i) {
    const std::string k = std::to_string(i), previous = std::to_string(i - 1);
    AddLink(m, "coupler" + k, {{"D" + previous, {0, 0}}, {"C" + k, {4, 0}}});
    AddLink(m, "rocker" + k, {{"P" + k, {0, 0}}, {"C" + k, {2.6, 0}}, {"D", {2.5, 0}}});
    Revolute(m, "D" + previous, "rocker" + previous, "coupler" + k, "D", "D" + previous);
    Revolute(m, "C" + k, "coupler" + k, "rocker" + k);
    Revolute(m, "P" + k, "frame", "rocker" + k);
    HintPoint(m, "rocker" + k, "C" + k, Eigen::Vector2d(4.0 * (i + 1) - 0.3, 2.58));  // the rockers upright, leaning back
  }
  SetDrive(m, "A0");
  LinkAngleOutput(m, "psi", "rocker" + std::to_string(loops - 1));
  return m;
}

}  // namespace

TEST_CASE("a chain of small loops compiles: each dyad's gauge is its own, not the whole mechanism's size", "[point_schedule]") {
  // 40 loops: the crank is 1/164 of L, below the 1e-2 of L the schedule once required of every dyad link
  const Mechanism m = ChainOfLoops(40);
  PositionSolver solver(m);
  REQUIRE(1.0 / solver.system().length_scale() < 1e-2);
  // the reference: the general kernel on its dense path, over a turn, pose for pose
  CheckAgreement(WalkBoth(m, 360, DegToRad(1.0)), 360);
  // and the general kernel's own test of a singular position (the whole Jacobian's reciprocal
  // condition) finds none where the schedule's gauges call the poses regular
  NewtonOptions dense;
  dense.dense = true;
  PositionSolver reference(m, dense);
  const Assembly assembly = AssembleRegular(m, reference);
  REQUIRE(assembly.ok());
  Continuation path(reference);
  REQUIRE(path.Start(assembly.input, assembly.q).ok());
  double least = 1.0;
  for (int i = 10; i <= 360; i += 10) {
    REQUIRE(path.AdvanceTo(assembly.input + DegToRad(i), DegToRad(1.0)).ok());
    least = std::min(least, ReciprocalCondition(reference.system(), path.q()));
  }
  INFO("least reciprocal condition " << least);
  CHECK(least > 100 * kSingularRowRcond);
}

TEST_CASE("the schedule compiles dyad mechanisms and names what it cannot compile", "[point_schedule]") {
  // seed 001's proportional linkage: a slotted link turning about its pivot (RPR) and two blocks
  // hinged to each other on two guides (PRP)
  for (const Mechanism& m : {test::SliderCrank(1, 2.6, 0.8), test::FourBar(1, 4.33, 4.33, 4, 8.33, 0.3, 1), test::WattSixBar(),
                             test::FourBar(1, 4.33, 4.33, 4, 8.33, 0.3, 1, true), test::ProportionalLinkage(1.0, 0.5, 1.83)}) {
    PositionSolver solver(m);
    const PointSchedule schedule(solver.system());
    INFO(m.name << ": " << schedule.why_not());
    CHECK(schedule.compiled());
  }
  // a transmission angle the kernel cannot measure (its block slides on the rocker, not on the
  // frame): built here without the file reader, which refuses it
  Mechanism unmeasurable = FourBarWithRockerSlider();
  TransmissionOutput(unmeasurable, "mu2", "rod", "C");
  // a redundant crank (more joint equations than coordinates)
  for (const Mechanism& m : {test::RedundantParallelogram(), unmeasurable}) {
    PositionSolver solver(m);
    const PointSchedule schedule(solver.system());
    INFO(m.name << ": " << schedule.why_not());
    CHECK_FALSE(schedule.compiled());
    CHECK_FALSE(schedule.why_not().empty());
  }
}

TEST_CASE("seed mechanisms: the schedule's poses and transfer functions equal the general kernel's", "[point_schedule]") {
  const double step = DegToRad(1.0);
  // every output kind: point, link angle, joint (R and P), distance, direction, transmission
  // angle about a pivot and on a slide
  for (const Mechanism& m : {WithEveryOutputKind(test::SliderCrank(1, 2.6, 0.8), "crank", "A", "slider", "B", "A"),
                             WithEveryOutputKind(test::FourBar(1, 2.5 * std::sqrt(3.0), 2.5 * std::sqrt(3.0), 4, 25.0 / 3, 0.3, 1),
                                                 "coupler", "K", "rocker", "B", "B"),
                             WithEveryOutputKind(test::WattSixBar(), "crank", "A", "link6", "D", "C"),
                             WithEveryOutputKind(test::ProportionalLinkage(1.0, 0.5, 1.83), "slider", "D", "slot", "B0", "B0"),
                             FourBarWithRockerSlider()}) {
    INFO(m.name);
    // det J of the whole system and the product of the dyads' determinants change sign together
    CheckAgreement(WalkBoth(m, 720, step), 720);
  }
}

TEST_CASE("200 random crank-rockers and 100 random slider-cranks agree with the general kernel over two turns",
          "[point_schedule][property]") {
  std::mt19937 random(20261127);
  std::uniform_real_distribution<double> length(0.2, 2.0), unit(0.0, 1.0);
  int fourbars = 0, slider_cranks = 0;
  while (fourbars < test::SeedCount(200)) {
    // Grashof crank-rockers (the crank the shortest, s + l < p + q by a margin): no limit point
    std::array<double, 4> l{length(random), length(random), length(random), length(random)};
    std::sort(l.begin(), l.end());
    if (l[0] + l[3] > 0.9 * (l[1] + l[2])) continue;
    std::shuffle(l.begin() + 1, l.end(), random);
    const double a = l[0], b = l[1], c = l[2], d = l[3];
    const double phi = 2 * kPi * unit(random);
    const Eigen::Vector2d crank_pin(a * std::cos(phi), a * std::sin(phi));
    // B near the intersection on one side: the hint only picks the branch
    const Eigen::Vector2d b0(d, 0.0), across = b0 - crank_pin;
    const double side = unit(random) < 0.5 ? 1.0 : -1.0;
    const Eigen::Vector2d hint = crank_pin + 0.5 * across + side * Eigen::Vector2d(-across.y(), across.x());
    const Mechanism m = test::PlainFourBar(a, b, c, d, phi, hint);
    INFO("four-bar " << a << " " << b << " " << c << " " << d << " at " << phi);
    CheckAgreement(WalkBoth(m, 720, DegToRad(1.0)), 720);
    ++fourbars;
  }
  while (slider_cranks < test::SeedCount(100)) {
    const double crank = length(random), coupler = length(random), offset = (unit(random) - 0.5) * crank;
    if (coupler < 1.2 * (crank + std::abs(offset))) continue;  // a crank that turns round
    const Mechanism m = test::SliderCrank(crank, coupler, offset);
    INFO("slider-crank " << crank << " " << coupler << " " << offset);
    CheckAgreement(WalkBoth(m, 720, DegToRad(1.0)), 720);
    ++slider_cranks;
  }
}

TEST_CASE("100 random proportional linkages (RPR and PRP dyads) agree with the general kernel over two turns",
          "[point_schedule][property]") {
  std::mt19937 random(20261128);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < test::SeedCount(100); ++i) {
    // the crank shorter than the frame: the slot swings (never upright, so the slider's guide and
    // the slot never turn parallel) and the crank turns round
    const double frame = 0.5 + 1.5 * unit(random), crank = (0.1 + 0.75 * unit(random)) * frame, h = (0.3 + 2.0 * unit(random)) * frame;
    const Mechanism m = test::ProportionalLinkage(frame, crank, h);
    INFO("proportional linkage " << frame << " " << crank << " " << h);
    CheckAgreement(WalkBoth(m, 720, DegToRad(1.0)), 720);
  }
}

TEST_CASE("a step onto another branch or past a fold is refused and leaves the state as it was", "[point_schedule]") {
  // seed 003's four-bar is a crank-rocker; a step of 90 deg predicted from the 2nd-order series
  // lands far from the prediction: the guards refuse it, and the state still steps on from where
  // it stood
  const Mechanism m = test::FourBar(1, 2.5 * std::sqrt(3.0), 2.5 * std::sqrt(3.0), 4, 25.0 / 3, 0.3, 1);
  PositionSolver solver(m);
  const Assembly assembly = AssembleRegular(m, solver);
  REQUIRE(assembly.ok());
  Continuation path(solver);
  REQUIRE(path.Start(assembly.input, assembly.q).ok());
  PointSchedule schedule(solver.system());
  schedule.Load(path.input(), path.q(), path.Series(2));
  Eigen::VectorXd before, after;
  schedule.Pose(before);
  CHECK_FALSE(schedule.Step(assembly.input + DegToRad(90.0)));
  schedule.Pose(after);
  CHECK((after - before).norm() == 0.0);
  CHECK(schedule.Step(assembly.input + DegToRad(1.0)));
  REQUIRE(path.AdvanceTo(assembly.input + DegToRad(1.0), 0.05).ok());
  schedule.Pose(after);
  CHECK((after - path.q()).lpNorm<Eigen::Infinity>() <= kAgreement);
}

}  // namespace koppel::point_schedule_test
