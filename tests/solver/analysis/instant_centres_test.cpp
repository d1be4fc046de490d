// Instant centres of every link pair: the Aronhold–Kennedy theorem (three poles of three links on
// one line) on a Watt six-bar, the crank and rocker pivots, a rocker at its dead centre (a pole
// from the accelerations), a slider's pole at infinity, and the centrodes touching at the pole.
#include "koppel/analysis/instant_centres.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/position.hpp"
#include "support/closed_forms.hpp"
#include "support/instant_geometry.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::instant_centres_test {
namespace {

struct Solved {
  PositionSolver solver;
  Eigen::MatrixXd series;
  Solved(const Mechanism& m, double input) : solver(m) {
    Eigen::VectorXd q(solver.NumCoordinates());
    REQUIRE(solver.Assemble(q).ok());
    const double start = m.hint.input;
    for (int i = 1; i <= 200; ++i) REQUIRE(solver.Correct(start + (input - start) * i / 200, q).ok());
    REQUIRE(solver.Series(3, series));
  }
};

const InstantCentre& Find(const std::vector<InstantCentre>& all, int a, int b) {
  for (const InstantCentre& c : all) {
    if (c.link_a == std::min(a, b) && c.link_b == std::max(a, b)) return c;
  }
  FAIL("no pole " << a << ", " << b);
  return all.front();
}

}  // namespace

TEST_CASE("Aronhold–Kennedy: every three poles of three links of a Watt six-bar lie on one line", "[instant_centres]") {
  const Mechanism m = test::WattSixBar();
  const int n = static_cast<int>(m.links.size());
  for (double phi_deg : {15.0, 80.0}) {
    const Solved s(m, DegToRad(phi_deg));
    const std::vector<InstantCentre> poles = InstantCentres(s.solver.system(), s.series);
    REQUIRE(poles.size() == static_cast<size_t>(n * (n - 1) / 2));
    int triples = 0;
    for (int a = 0; a < n; ++a) {
      for (int b = a + 1; b < n; ++b) {
        for (int c = b + 1; c < n; ++c) {
          const InstantCentre &ab = Find(poles, a, b), &bc = Find(poles, b, c), &ac = Find(poles, a, c);
          if (ab.at_infinity || bc.at_infinity || ac.at_infinity) continue;
          const Eigen::Vector2d u = bc.position - ab.position, v = ac.position - ab.position;
          const double area = std::abs(u.x() * v.y() - u.y() * v.x());
          INFO(m.links[a].name << ", " << m.links[b].name << ", " << m.links[c].name);
          CHECK(area < 1e-8 * (1 + u.squaredNorm() + v.squaredNorm()));
          ++triples;
        }
      }
    }
    CHECK(triples >= 15);
  }
}

TEST_CASE("the poles at a four-bar's pivots and joints are the joints themselves", "[instant_centres]") {
  const Mechanism m = test::FourBar(1, 3.5, 3, 4, 2, 0.5, +1);
  const Solved s(m, DegToRad(70));
  const std::vector<InstantCentre> poles = InstantCentres(s.solver.system(), s.series);
  const ConstraintSystem& system = s.solver.system();
  for (const Joint& j : m.joints) {
    double xy[2];
    system.GlobalPoint({j.link_a, j.point_a}, s.series.col(0).data(), xy);
    const InstantCentre& p = Find(poles, j.link_a, j.link_b);
    INFO(j.name);
    REQUIRE_FALSE(p.at_infinity);
    CHECK((p.position - Eigen::Vector2d(xy[0], xy[1])).norm() < 1e-10);
  }
}

TEST_CASE("a rocker at its dead centre stands still: its pole is B0, from the accelerations", "[instant_centres]") {
  // crank-rocker 1, 3.5, 3, 4: the rocker's extended dead centre (tests/support closed form)
  const test::CrankRockerDeadCentre dc = test::CrankRockerExtended(1, 3.5, 3, 4);
  const Mechanism m = test::PlainFourBar(1, 3.5, 3, 4, 0, {2.5, 2.6});
  const Solved s(m, dc.phi);
  const std::vector<InstantCentre> poles = InstantCentres(s.solver.system(), s.series);
  const InstantCentre& p = Find(poles, m.FindLink("frame"), m.FindLink("rocker"));
  REQUIRE(p.defined);
  CHECK(p.from_acceleration);
  CHECK((p.position - Eigen::Vector2d(4, 0)).norm() < 1e-8);
}

TEST_CASE("a slider's pole against the frame is at infinity, perpendicular to the slide", "[instant_centres]") {
  const Mechanism m = test::SliderCrank(1, 2.6, 0.8);
  const Solved s(m, DegToRad(60));
  const std::vector<InstantCentre> centres = InstantCentres(s.solver.system(), s.series);  // kept: p refers into it
  const InstantCentre& p = Find(centres, m.FindLink("frame"), m.FindLink("slider"));
  REQUIRE(p.at_infinity);
  CHECK(std::abs(p.direction.x()) < 1e-12);
}

TEST_CASE("the fixed and moving centrodes: the coupler's pole at each input, in the frame and on the coupler", "[instant_centres]") {
  const Mechanism m = test::FourBar(1, 3.5, 3, 4, 2, 0.5, +1);
  const int coupler = m.FindLink("coupler");
  std::vector<double> inputs;
  for (int i = 0; i <= 36; ++i) inputs.push_back(DegToRad(10.0 * i));
  const Centrodes c = TraceCentrodes(m, coupler, m.FindLink("frame"), inputs);
  REQUIRE(c.status == AnalysisStatus::kComplete);
  REQUIRE(c.points.size() == inputs.size());
  // at 70 deg the fixed centrode's point is the pole found from the pose alone
  const Solved s(m, DegToRad(70));
  const std::vector<InstantCentre> centres = InstantCentres(s.solver.system(), s.series);  // kept: p refers into it
  const InstantCentre& p = Find(centres, m.FindLink("frame"), coupler);
  CHECK((c.points[7].fixed - p.position).norm() < 1e-9);
  // and the moving centrode's point, carried by the coupler's pose, is the same point
  const int i = s.solver.system().CoordinateOf(coupler);
  const double theta = s.series(i + 2, 0);
  const Eigen::Vector2d carried = Eigen::Vector2d(s.series(i, 0), s.series(i + 1, 0)) +
                                  Eigen::Vector2d(std::cos(theta) * c.points[7].moving.x() - std::sin(theta) * c.points[7].moving.y(),
                                                  std::sin(theta) * c.points[7].moving.x() + std::cos(theta) * c.points[7].moving.y());
  CHECK((carried - p.position).norm() < 1e-9);
}

}  // namespace koppel::instant_centres_test
