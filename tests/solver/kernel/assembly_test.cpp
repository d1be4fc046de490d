// AssembleRegular and the Levenberg–Marquardt assembly under it, where no pose exists: the
// search must say so, and each LM run must give up at a non-zero minimum of |F| instead of
// spending its whole budget creeping towards it (a Peaucellier cell whose rhombus is too long
// for its arms took 0.7 s in Release, 20 s under the sanitizers, before LM had a stall test).
#include "koppel/solver/assembly.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/position.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace koppel::assembly_test {
namespace {

// The Peaucellier–Lipkin cell of catalog/entries/peaucellier-lipkin.yaml (crank O'C = k, arms
// OA = OB = L, rhombus sides s) with s = 11.5 > L + 2k: |OC| <= 2k < s - L, so A cannot reach
// both O and C at any crank angle: no pose exists anywhere.
Mechanism OverlongPeaucellier() {
  const double k = 1, L = 3, s = 11.5;
  Mechanism m;
  m.name = "peaucellier-overlong";
  m.links = {{"frame", true, {{"O", {0, 0}}, {"O1", {k, 0}}}},
             {"crank", false, {{"O1", {0, 0}}, {"C", {k, 0}}}},
             {"longA", false, {{"O", {0, 0}}, {"A", {L, 0}}}},
             {"longB", false, {{"O", {0, 0}}, {"B", {L, 0}}}},
             {"rhombusAC", false, {{"A", {0, 0}}, {"C", {s, 0}}}},
             {"rhombusBC", false, {{"B", {0, 0}}, {"C", {s, 0}}}},
             {"rhombusAP", false, {{"A", {0, 0}}, {"P", {s, 0}}}},
             {"rhombusBP", false, {{"B", {0, 0}}, {"P", {s, 0}}}}};
  auto r = [&](const char* name, int a, int b) { return PinJoint(m, name, a, b); };
  m.joints = {r("O1", 0, 1), r("O", 0, 2), r("O", 0, 3), r("A", 2, 4), r("A", 2, 6),
              r("B", 3, 5), r("B", 3, 7), r("C", 1, 4), r("C", 1, 5), r("P", 6, 7)};
  m.drive.joint = 0;
  m.hint.input = DegToRad(31);
  m.hint.points = {{{1, 1}, {1.866, 0.5}}, {{2, 1}, {2.44, 1.74}}, {{3, 1}, {2.85, -0.93}}, {{6, 1}, {3.375, 0.904}}};
  return m;
}

TEST_CASE("no pose anywhere: AssembleRegular says so after its search", "[assembly]") {
  const Mechanism m = OverlongPeaucellier();
  PositionSolver solver(m);
  const Assembly a = AssembleRegular(m, solver);
  CHECK_FALSE(a.ok());
  CHECK_THAT(a.error, Catch::Contains("nor at any input of a turn"));
}

TEST_CASE("LM stops at a non-zero minimum of |F| well inside its budget", "[assembly]") {
  // Before the stall test these runs took 260 to 400 iterations each (the budget is 400); a run
  // that gains less than 0.1 % of |F|^2 over 16 iterations now stops. Seeded random guesses, as
  // AssembleRegular's search makes them.
  const Mechanism m = OverlongPeaucellier();
  PositionSolver solver(m);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Eigen::VectorXd hint = solver.HintGuess();
  int total = 0;
  constexpr int kRuns = 40;
  for (int run = 0; run < kRuns; ++run) {
    Eigen::VectorXd q = hint;
    if (run > 0) {
      for (int i = 0; i < q.size(); ++i) q(i) = i % 3 == 2 ? kPi * unit(random) : hint(i) + 6.0 * unit(random);
    }
    const SolveReport report = solver.AssembleFrom(DegToRad(-180 + 9 * run), q);
    REQUIRE(report.status == SolveStatus::kNotAssemblable);
    total += report.iterations;
  }
  CHECK(total < kRuns * 150);
}

TEST_CASE("the stall test does not stop a run that converges slowly onto a singular pose", "[assembly]") {
  // The four-bar 1, 3, 2.5, 3 assembled exactly at its extended dead centre (crank and coupler
  // in line, the input angle from the law of cosines in the triangle A0 B B0): |F| falls only
  // linearly there, and LM must still reach the hand-over to Newton.
  const double a = 1, b = 3, c = 2.5, d = 3;
  const double phi = std::acos(((a + b) * (a + b) + d * d - c * c) / (2 * (a + b) * d));
  const Mechanism m = test::PlainFourBar(a, b, c, d, phi, {(a + b) * std::cos(phi) + 0.3, (a + b) * std::sin(phi) + 0.4});
  PositionSolver solver(m);
  Eigen::VectorXd q = solver.HintGuess();
  const SolveReport report = solver.AssembleFrom(phi, q);
  CHECK(report.status != SolveStatus::kNotAssemblable);
}

}  // namespace
}  // namespace koppel::assembly_test
