// Assembly from hints, Newton, the exact derivative series, and the mobility from the
// constraint Jacobian's rank (against Grübler–Kutzbach from the graph).
#include "koppel/solver/position.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/structure.hpp"
#include "koppel/solver/sweep.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::position_test {
namespace {

// a parallelogram's coupler translates: E_y = sin(phi) and its rate cos(phi) from a pose Newton
// solves to ~1e-13 of the unit lengths
constexpr double kTranslation = 1e-12;

const double kL23 = 2.5 * std::sqrt(3.0);

// A parallelogram A0 A B B0 with a third parallel link E0 E: Grübler counts 0, the rank says 1.
Mechanism OverconstrainedParallelogram() {
  Mechanism m;
  m.name = "parallelogram";
  m.links = {{"frame", true, {{"A0", {0, 0}}, {"B0", {4, 0}}, {"E0", {2, 0}}}},
             {"crank", false, {{"A0", {0, 0}}, {"A", {1, 0}}}},
             {"coupler", false, {{"A", {0, 0}}, {"B", {4, 0}}, {"E", {2, 0}}}},
             {"rocker", false, {{"B0", {0, 0}}, {"B", {1, 0}}}},
             {"extra", false, {{"E0", {0, 0}}, {"E", {1, 0}}}}};
  auto r = [&](const char* name, int a, int b) { return PinJoint(m, name, a, b); };
  m.joints = {r("A0", 0, 1), r("A", 1, 2), r("B", 2, 3), r("B0", 0, 3), r("E", 2, 4), r("E0", 0, 4)};
  m.drive.joint = 0;
  m.hint.input = DegToRad(60);
  m.hint.points = {{{2, 1}, {4.5, 0.9}}};
  Output y;
  y.name = "Ey";
  y.kind = OutputKind::kPoint;
  y.p = {2, 2};
  m.outputs = {y};
  return m;
}

}  // namespace

TEST_CASE("assembly follows the hint to the chosen branch", "[position]") {
  for (int side : {1, -1}) {
    const Mechanism m = test::FourBar(1.0, kL23, kL23, 4.0, 1.0, 0.0, side);
    PositionSolver solver(m);
    Eigen::VectorXd q(solver.NumCoordinates());
    const SolveReport report = solver.Assemble(q);
    REQUIRE(report.ok());
    CHECK(report.residual_norm <= 1e-13 * 4.0);
    // coupler B on the hinted side of A0B0
    double b[2];
    solver.system().GlobalPoint({2, 1}, q.data(), b);
    CHECK(b[1] * side > 1.0);
  }
}

TEST_CASE("LinksTheHintLeavesOpen: the links whose pose no hinted point, drive or joint carries", "[position]") {
  // the four-bar hinted at B: the crank by the drive, coupler by A and B, rocker by B0 and B
  const Mechanism hinted = test::FourBar(1.0, kL23, kL23, 4.0, 1.0, 0.0, 1);
  CHECK(LinksTheHintLeavesOpen(hinted).empty());
  // without its point the coupler's angle is the solver's choice, and with it the rocker's
  Mechanism bare = hinted;
  bare.hint.points.clear();
  const std::vector<int> open = LinksTheHintLeavesOpen(bare);
  REQUIRE(open.size() == 1);
  CHECK(bare.links[open[0]].name == "coupler");
  // a hint on the frame alone carries nothing to a moving link
  Mechanism frame_only = bare;
  frame_only.hint.points.push_back({{frame_only.FrameLink(), 1}, Eigen::Vector2d(4, 0)});
  CHECK(LinksTheHintLeavesOpen(frame_only) == open);
}

TEST_CASE("a failed Newton leaves q unchanged", "[position]") {
  const Mechanism m = test::FourBar(1.0, 2.0, 2.0, 10.0, 1.0, 0.0, 1);  // cannot be assembled
  PositionSolver solver(m);
  Eigen::VectorXd q = Eigen::VectorXd::Constant(solver.NumCoordinates(), 0.25);
  const Eigen::VectorXd before = q;
  const SolveReport report = solver.Correct(0.0, q);
  CHECK_FALSE(report.ok());
  CHECK(q == before);
  Eigen::VectorXd assembled = q;
  CHECK(solver.Assemble(assembled).status == SolveStatus::kNotAssemblable);
  CHECK(assembled == before);
}

TEST_CASE("the series of q: first order solves J q' = -dF/dinput", "[position]") {
  const Mechanism m = test::SliderCrank(1.0, 2.6, 0.8);
  PositionSolver solver(m);
  Eigen::VectorXd q(solver.NumCoordinates());
  REQUIRE(solver.Assemble(q).ok());
  Eigen::MatrixXd series;
  REQUIRE(solver.Series(3, series));
  CHECK(series.cols() == 4);
  // J q1 + dF/dinput = 0, with dF/dinput = InputColumn() in the drive row
  Eigen::MatrixXd jacobian(solver.system().NumEquations(), solver.NumCoordinates());
  solver.system().Jacobian(q.data(), jacobian);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(jacobian.rows());
  rhs(solver.system().DriveRow()) = solver.system().InputColumn();
  CHECK((jacobian * series.col(1) + rhs).lpNorm<Eigen::Infinity>() < 1e-12);
}

TEST_CASE("mobility: Grübler from the graph, the actual one from the Jacobian's rank", "[position]") {
  const Mechanism four_bar = test::FourBar(1.0, kL23, kL23, 4.0, 1.0, 0.0, 1);
  PositionSolver solver(four_bar);
  Eigen::VectorXd q(solver.NumCoordinates());
  REQUIRE(solver.Assemble(q).ok());
  CHECK(AnalyseStructure(four_bar).gruebler_mobility == 1);
  CHECK(solver.NumCoordinates() - solver.ConstraintRank(q) == 1);

  const Mechanism parallelogram = OverconstrainedParallelogram();
  CHECK(AnalyseStructure(parallelogram).gruebler_mobility == 0);
  PositionSolver redundant(parallelogram);
  Eigen::VectorXd p(redundant.NumCoordinates());
  REQUIRE(redundant.Assemble(p).ok());
  CHECK(redundant.NumCoordinates() - redundant.ConstraintRank(p) == 1);
  // the redundant system still sweeps (least squares through QR): E stays at height sin(phi)
  SweepOptions o;
  o.from = DegToRad(20);
  o.to = DegToRad(160);
  o.step = DegToRad(10);
  o.order = 1;
  const SweepResult r = Sweep(parallelogram, o);
  REQUIRE(r.complete());
  for (size_t i = 0; i < r.inputs.size(); ++i) {
    // columns: E_x, E_x_d1, E_y, E_y_d1; a parallelogram translates its coupler: E_y = sin(phi)
    CHECK(r.outputs(i, 2) == Approx(std::sin(r.inputs[i])).margin(kTranslation));
    CHECK(r.outputs(i, 3) == Approx(std::cos(r.inputs[i])).margin(kTranslation));
  }
}

}  // namespace koppel::position_test
