// MechanismViolation (solver/synthesis/src/mechanism_space.cpp): the design space read on any
// mechanism. References: on seeded random four-bars it must agree with the four-bar's own rule
// (DesignSpace::Violation, whose crank test is Grashof's inequality and whose mu is the closed
// form cos mu = (b^2 + c^2 - (d -+ a)^2) / (2 b c) at the crank's two dead-centre-free extremes);
// on a six-bar, the ternary links' sides by hand.
#include "koppel/synthesis/mechanism_space.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/build.hpp"

#include "../../support/mechanisms.hpp"
#include "../../support/seeds.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <random>

namespace koppel::mechanism_space_test {
namespace {

// The four-bar's smallest transmission angle over a whole crank turn in closed form, folded to
// 0..90 deg as the solver's output: extreme where the crank lies along the frame (f = d -+ a).
double ClosedFormMuMin(double a, double b, double c, double d) {
  double smallest = kPi / 2;
  for (const double f : {d - a, d + a}) {
    const double gamma = std::acos(std::clamp((b * b + c * c - f * f) / (2 * b * c), -1.0, 1.0));
    smallest = std::min(smallest, std::min(gamma, kPi - gamma));
  }
  return smallest;
}

}  // namespace

TEST_CASE("MechanismViolation agrees with the four-bar rule on random four-bars", "[synthesis][design-space][property]") {
  std::mt19937 rng(20261129);
  std::uniform_real_distribution<double> length(0.5, 6), place(-1, 1);
  int cranks = 0, compared = 0, inside = 0;
  for (int seed = 0; seed < test::SeedCount(200); ++seed) {
    const double a = length(rng), b = length(rng), c = length(rng), d = length(rng);
    // assembled at the crank angle pi/2 where the loop closes; a loop that closes nowhere there is skipped
    const Eigen::Vector2d A(0, a), B0(d, 0);
    const double diagonal = (B0 - A).norm();
    if (diagonal > b + c || diagonal < std::abs(b - c)) continue;
    const double along = (b * b - c * c + diagonal * diagonal) / (2 * diagonal);
    const Eigen::Vector2d u = (B0 - A) / diagonal;
    const Eigen::Vector2d B = A + along * u + std::sqrt(b * b - along * along) * Eigen::Vector2d(-u.y(), u.x());
    Mechanism m = test::PlainFourBar(a, b, c, d, kPi / 2, B);
    TransmissionOutput(m, "mu", "coupler", "B");
    DesignSpace space;
    space.lengths = std::make_pair(0.3 + length(rng) / 8, 4 + length(rng));
    space.ratio = 3 + 5 * (place(rng) + 1) / 2;
    space.pivots_x = std::make_pair(-0.5, 0.5 + 6 * (place(rng) + 1) / 2);
    if (seed % 2 == 0) space.input = InputTurn::kCrank;  // half the spaces ask for a crank
    const FourBarSizes sizes{{0, 0}, {d, 0}, a, b, c, std::nullopt, std::nullopt};
    const std::string four_bar = space.Violation(sizes), any = MechanismViolation(space, m, kPi / 2, kPi / 2 + 2 * kPi);
    INFO("a " << a << " b " << b << " c " << c << " d " << d << ": four-bar '" << four_bar << "', any '" << any << "'");
    CHECK(four_bar.empty() == any.empty());
    if (!four_bar.empty() && !any.empty()) CHECK(four_bar.substr(0, 6) == any.substr(0, 6));  // the same key first
    ++compared;
    inside += four_bar.empty() ? 1 : 0;
    // mu_min over the whole turn of every crank against the closed form, 0.01 deg either side of the bound
    DesignSpace crank;
    crank.input = InputTurn::kCrank;
    if (!crank.Violation(sizes).empty()) continue;
    ++cranks;
    const double mu = ClosedFormMuMin(a, b, c, d);
    crank.mu_min = mu - DegToRad(0.01);
    CHECK(MechanismViolation(crank, m, kPi / 2, kPi / 2 + 2 * kPi).empty());
    crank.mu_min = mu + DegToRad(0.01);
    CHECK_THAT(MechanismViolation(crank, m, kPi / 2, kPi / 2 + 2 * kPi), Catch::Contains("mu_min: the smallest transmission angle is"));
  }
  CHECK(compared >= test::SeedCount(200) / 2);
  CHECK(inside >= 5);                // designs on both sides of the space
  CHECK(compared - inside >= 5);
  CHECK(cranks >= 5);  // the mu comparison was reached
}

TEST_CASE("MechanismViolation reads a six-bar's ternary links and frame pivots", "[synthesis][design-space]") {
  // FoldingSixBar: frame A0 (0, 0), B0 (4, 0), D0 = B0 + e (cos f, sin f); the rocker B0 B C is
  // ternary (B0B 3, B0C r, BC by the law of cosines with the angle gamma between them)
  const double r = 2, gamma = DegToRad(60), e = 5;
  const Mechanism m = test::FoldingSixBar(r, gamma, e, DegToRad(90));
  const MechanismSizes sizes = SizesOf(m);
  std::map<std::string, double> by_name(sizes.lengths.begin(), sizes.lengths.end());
  CHECK(by_name.at("frame A0-B0") == Approx(4));
  CHECK(by_name.at("frame B0-D0") == Approx(e));
  CHECK(by_name.at("frame A0-D0") == Approx(std::sqrt(16 + 25.0)));
  CHECK(by_name.at("rocker B-B0") == Approx(3).epsilon(1e-12));
  CHECK(by_name.at("rocker B-C") == Approx(std::sqrt(9 + 4 - 12 * std::cos(gamma))));
  CHECK(sizes.pivots.size() == 3);
  DesignSpace space;
  space.lengths = std::make_pair(0.5, 6.0);
  CHECK_THAT(MechanismViolation(space, m, 0, 2 * kPi), Catch::Contains("lengths: frame A0-D0 is 6.40312, beyond 6"));
  space.lengths.reset();
  space.pivots_y = std::make_pair(-1.0, 4.0);
  CHECK_THAT(MechanismViolation(space, m, 0, 2 * kPi), Catch::Contains("pivots: D0 at y = 5, outside [-1, 4]"));
}

TEST_CASE("UncheckableSpace names what a mechanism cannot be held to", "[synthesis][design-space]") {
  const Mechanism plain = test::PlainFourBar(1, 3.5, 3, 4, kPi / 2, {2, 3});  // no transmission-angle output
  DesignSpace space;
  CHECK(UncheckableSpace(space, plain).empty());
  space.mu_min = DegToRad(30);
  CHECK_THAT(UncheckableSpace(space, plain), Catch::Contains("no transmission-angle output"));
  space.mu_min.reset();
  space.a0 = Eigen::Vector2d(0, 0);
  CHECK_THAT(UncheckableSpace(space, plain), Catch::StartsWith("A0: synth fit places its frame itself"));
  space.a0.reset();
  space.input = InputTurn::kCrank;
  Mechanism slide_driven = test::SliderCrank(1, 3, 0.5);
  SetDrive(slide_driven, "S");
  CHECK_THAT(UncheckableSpace(space, slide_driven), Catch::Contains("the drive is a slide"));
}

}  // namespace koppel::mechanism_space_test
