// The stationary-point search (solver/analysis/src/stationary_search.cpp) through its two
// consumers, FindDeadCentres and FindOutputExtremes. The property test of issue 22 item 1: 1000
// seeded random crank-rockers and slider-cranks whose dead centres and transmission-angle
// extremes are put on the boundary of the search range on purpose (by the drive's zero, or by
// --from / --to at the closed-form input), over whole turns and over part of a turn, either way.
// References: the closed forms of tests/support/closed_forms.hpp (seed 000; law of cosines).
#include "koppel/analysis/dead_centres.hpp"
#include "koppel/analysis/extremes.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/build.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace koppel::stationary_search_test {
namespace {

// [rad] mu from the fixture's geometry against an independent acos of the same triangle: rounding
constexpr double kMuRoundoff = 1e-12;
// [rad] mu at a closed-form fold (90 deg): the fold's input is itself an acos in the closed form,
// whose rounding grows towards sqrt(eps) ~ 1e-8 where its argument nears +-1; mu's slope is O(1)
constexpr double kFoldMu = 1e-7;

constexpr double kTurn = 2 * kPi;
// Refined to 1e-12 in the input (stationary.hpp); the closed forms' acos keep ~1e-13 for these
// well-conditioned mechanisms; the search keeps a root within 1e-9 beyond the range's edge.
constexpr double kInput = 1e-9;
// Values at a stationary point are second-order in the input error; at a fold or a range end
// they are the solver's output at that input, exact to roundoff.
constexpr double kValue = 1e-10;

// A mechanism with its closed forms, in crank angles (input = crank angle - drive zero).
struct Case {
  Mechanism m;
  int stroke_output = 0, mu_output = 0;
  bool output_is_angle = false;
  std::vector<double> dead_centres, dead_values;  // extended, folded
  std::function<double(double)> mu;
  std::vector<double> mu_places;  // where mu is stationary (0, 180 deg) or folds at 90 deg
  std::array<double, 4> bars{};   // crank-rocker: a, b, c, d
};

// Away from the change point and from two extremes of mu within a few search steps.
constexpr double kMargin = DegToRad(10);

bool FarFromZeroAndHalfTurn(const std::vector<double>& folds) {
  return std::all_of(folds.begin(), folds.end(), [](double f) {
    return std::abs(std::remainder(f, kPi)) > kMargin;
  });
}

bool RandomCrankRocker(std::mt19937& rng, Case& c) {
  std::uniform_real_distribution<double> length(1.4, 5.0);
  const double a = 1, b = length(rng), cc = length(rng), d = length(rng);
  const double longest = std::max({b, cc, d});
  if (a + longest > b + cc + d - longest - 0.2) return false;  // Grashof with margin, crank shortest
  const double mu0 = test::CrankRockerMu(a, b, cc, d, 0), mu180 = test::CrankRockerMu(a, b, cc, d, kPi);
  const std::vector<double> folds = test::CrankRockerMuFolds(a, b, cc, d);
  if (std::min(mu0, mu180) < kMargin || !FarFromZeroAndHalfTurn(folds)) return false;
  c.m = test::FourBar(a, b, cc, d, 1.0, 0.0, 1);  // outputs K, psi, phi, mu
  // assembled at phi = 0 with B above the frame line, the branch of the closed forms
  c.m.hint.points.clear();
  HintPoint(c.m, "coupler", "B", test::FourBarRocker(a, b, cc, d, 0.0, 1)->b);
  c.stroke_output = 1;
  c.mu_output = 3;
  c.output_is_angle = true;
  c.bars = {a, b, cc, d};
  const test::CrankRockerDeadCentre ext = test::CrankRockerExtended(a, b, cc, d), fold = test::CrankRockerFolded(a, b, cc, d);
  c.dead_centres = {ext.phi, fold.phi};
  c.dead_values = {ext.psi, fold.psi};
  c.mu = [=](double phi) { return test::CrankRockerMu(a, b, cc, d, phi); };
  c.mu_places = {0, kPi};
  c.mu_places.insert(c.mu_places.end(), folds.begin(), folds.end());
  return true;
}

bool RandomSliderCrank(std::mt19937& rng, Case& c) {
  std::uniform_real_distribution<double> coupler(1.5, 5.0), offset(-1, 1);
  const double l1 = 1, l2 = coupler(rng), e = offset(rng) * (l2 - l1 - 0.3);
  const std::vector<double> folds = test::SliderCrankMuFolds(l1, e);
  if (kPi / 2 - std::asin((l1 + std::abs(e)) / l2) < kMargin || !FarFromZeroAndHalfTurn(folds)) return false;
  c.m = test::SliderCrank(l1, l2, e);  // outputs s, mu
  c.stroke_output = 0;
  c.mu_output = 1;
  c.dead_centres = {test::SliderCrankPhiA(l1, l2, e), test::SliderCrankPhiI(l1, l2, e)};
  // s_a = sqrt((l1 + l2)^2 - e^2), s_i = sqrt((l2 - l1)^2 - e^2) (seed 000)
  c.dead_values = {std::sqrt((l1 + l2) * (l1 + l2) - e * e), std::sqrt((l2 - l1) * (l2 - l1) - e * e)};
  c.mu = [=](double phi) { return test::SliderCrank(l1, l2, e, phi).mu; };
  c.mu_places = {0, kPi};
  c.mu_places.insert(c.mu_places.end(), folds.begin(), folds.end());
  return true;
}

// The same mechanism with the drive's zero at `zero` (the hint moved with it).
void SetZero(Mechanism& m, double zero) {
  m.hint.input -= zero - m.drive.zero;
  m.drive.zero = zero;
}

struct Placement {
  double zero = 0;
  SweepOptions range;
  bool periodic = false;
  std::string Describe() const {
    return "zero " + std::to_string(RadToDeg(zero)) + " deg, range " + std::to_string(RadToDeg(range.from)) + " .. " +
           std::to_string(RadToDeg(range.to)) + " step " + std::to_string(RadToDeg(range.step));
  }
};

// Puts crank angle `target` on the start or the end of the range: whole turns (by the zero, by
// from, or at the end), or part of a turn (at its start or end), ascending or descending.
Placement Place(std::mt19937& rng, double target) {
  std::uniform_int_distribution<int> mode(0, 4), coin(0, 1), steps(0, 2);
  std::uniform_real_distribution<double> zero(-kPi, kPi), span(DegToRad(60), DegToRad(300));
  Placement p;
  p.range.step = DegToRad(std::array<double, 3>{1, 2, 4}[steps(rng)]);
  const int how = mode(rng);
  p.periodic = how <= 2;
  p.zero = how == 0 ? target : zero(rng);
  const double at = target - p.zero;  // the target as an input
  const double length = p.periodic ? kTurn : span(rng);
  const bool at_start = how == 0 || how == 1 || how == 3;
  p.range.from = at_start ? at : at - length;
  p.range.to = at_start ? at + length : at;
  if (coin(rng)) std::swap(p.range.from, p.range.to);  // descending
  return p;
}

// Every input in [low, high] equivalent to crank angle `phi` (input = phi - zero + k turns).
std::vector<double> InputsInRange(double phi, const Placement& p) {
  const double low = std::min(p.range.from, p.range.to), high = std::max(p.range.from, p.range.to);
  std::vector<double> inputs;
  double x = phi - p.zero;
  x += kTurn * std::ceil((low - kInput - x) / kTurn);  // the first at least low - kInput
  for (; x <= high + kInput; x += kTurn) inputs.push_back(x);
  if (p.periodic && inputs.size() == 2) inputs.pop_back();  // whole turns: each once
  return inputs;
}

double InputDistance(double a, double b, bool periodic) { return periodic ? std::abs(std::remainder(a - b, kTurn)) : std::abs(a - b); }

void CheckDeadCentres(const Case& c, const Placement& p) {
  const DeadCentreReport r = FindDeadCentres(c.m, c.stroke_output, 0, p.range);
  std::string found_inputs;
  for (const DeadCentre& d : r.points) found_inputs += " " + std::to_string(RadToDeg(d.input));
  INFO("found at" << found_inputs << " deg; " << r.message);
  REQUIRE(r.status == AnalysisStatus::kComplete);
  CHECK(r.unresolved.empty());
  size_t expected = 0;
  for (size_t k = 0; k < 2; ++k) {
    for (double input : InputsInRange(c.dead_centres[k], p)) {
      ++expected;
      INFO("dead centre " << (k == 0 ? "extended" : "folded") << " at input " << RadToDeg(input) << " deg");
      const auto found = std::find_if(r.points.begin(), r.points.end(),
                                      [&](const DeadCentre& d) { return InputDistance(d.input, input, p.periodic) < kInput; });
      REQUIRE(found != r.points.end());
      const double value_error = c.output_is_angle ? AngleDifference(found->value, c.dead_values[k]) : found->value - c.dead_values[k];
      CHECK(std::abs(value_error) < kValue);
      CHECK(found->kind == (k == 0 ? DeadCentreKind::kExtended : DeadCentreKind::kFolded));
    }
  }
  CHECK(r.points.size() == expected);
  // inputs are reported within the range (a root at its edge within kInput)
  for (const DeadCentre& d : r.points) {
    CHECK(d.input >= std::min(p.range.from, p.range.to) - kInput);
    CHECK(d.input <= std::max(p.range.from, p.range.to) + kInput);
  }
}

void CheckTransmissionExtremes(const Case& c, const Placement& p) {
  const OutputExtremes r = FindOutputExtremes(c.m, c.mu_output, 0, p.range);
  REQUIRE(r.status == AnalysisStatus::kComplete);
  // the closed-form extremes: at the stationary points and folds in the range, and at the ends
  // of a part of a turn
  double least = 10, largest = -10;
  auto consider = [&](double phi) {
    least = std::min(least, c.mu(phi));
    largest = std::max(largest, c.mu(phi));
  };
  for (double place : c.mu_places) {
    if (!InputsInRange(place, p).empty()) consider(place);
  }
  if (!p.periodic) {
    consider(p.range.from + p.zero);
    consider(p.range.to + p.zero);
  }
  CHECK(std::abs(r.minimum.value - least) < kValue);
  CHECK(std::abs(r.maximum.value - largest) < kValue);
  // and the inputs given are where mu has those values, in the range
  for (const OutputExtreme* e : {&r.minimum, &r.maximum}) {
    CHECK(std::abs(c.mu(e->input + p.zero) - e->value) < kValue);
    CHECK(e->input >= std::min(p.range.from, p.range.to) - kInput);
    CHECK(e->input <= std::max(p.range.from, p.range.to) + kInput);
  }
}

}  // namespace

// The references themselves against the independent circle-intersection four-bar
// (test::FourBarRocker): mu is the angle between coupler and rocker folded to 0..90 deg, the
// rocker stands still (psi' = 0) at the dead centres with the rocker angle given.
TEST_CASE("the crank-rocker closed forms agree with the circle-intersection four-bar", "[stationary]") {
  std::mt19937 rng(7);
  for (int tested = 0; tested < 50;) {
    Case c;
    if (!RandomCrankRocker(rng, c)) continue;
    ++tested;
    const auto [a, b, cc, d] = c.bars;
    for (double phi = 0; phi < kTurn; phi += 0.37) {
      const auto r = test::FourBarRocker(a, b, cc, d, phi, 1);
      REQUIRE(r);
      const Eigen::Vector2d a_point(a * std::cos(phi), a * std::sin(phi)), b0(d, 0);
      const double between = std::acos((r->b - a_point).normalized().dot((r->b - b0).normalized()));
      CHECK(c.mu(phi) == Approx(std::min(between, kPi - between)).margin(kMuRoundoff));
    }
    for (size_t k = 0; k < 2; ++k) {
      const auto r = test::FourBarRocker(a, b, cc, d, c.dead_centres[k], 1);
      REQUIRE(r);
      CHECK(std::abs(r->psi1) < 1e-7);  // psi' = 0 there (the acos of a near-tangent loses digits)
      CHECK(std::abs(AngleDifference(r->psi, c.dead_values[k])) < 1e-12);
    }
    for (double fold : test::CrankRockerMuFolds(a, b, cc, d)) CHECK(c.mu(fold) == Approx(kPi / 2).margin(kFoldMu));
  }
}

TEST_CASE("dead centres and transmission extremes on the search boundary: 1000 random crank-rockers and slider-cranks",
          "[stationary][property]") {
  std::mt19937 rng(22);
  int tested = 0, periodic = 0;
  while (tested < 1000) {
    Case c;
    const bool crank_rocker = tested % 2 == 0;
    if (!(crank_rocker ? RandomCrankRocker(rng, c) : RandomSliderCrank(rng, c))) continue;
    // the target: a dead centre, or a place of mu's extremes (stationary point or fold)
    std::vector<double> targets = c.dead_centres;
    targets.insert(targets.end(), c.mu_places.begin(), c.mu_places.end());
    const double target = targets[std::uniform_int_distribution<size_t>(0, targets.size() - 1)(rng)];
    const Placement p = Place(rng, target);
    SetZero(c.m, p.zero);
    INFO("case " << tested << ": " << (crank_rocker ? "crank-rocker" : "slider-crank") << ", target crank angle "
                 << RadToDeg(target) << " deg, " << p.Describe());
    CheckDeadCentres(c, p);
    CheckTransmissionExtremes(c, p);
    periodic += p.periodic;
    ++tested;
  }
  // both kinds of range were drawn
  CHECK(periodic > 400);
  CHECK(periodic < 800);
}

}  // namespace koppel::stationary_search_test
