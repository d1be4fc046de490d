// Sweeps against closed forms of the seed documents and an independent circle-intersection
// model; a sweep that must stop at a dead centre of the drive; a mechanism that cannot be
// assembled; branches that never flip.
#include "koppel/solver/sweep.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/singular.hpp"
#include "solver/kernel/tolerances.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

namespace koppel::sweep_test {
namespace {

// y' against a central difference of the swept y with h = 1e-5: truncation h^2 y''' / 6 ~ 1e-11,
// rounding eps |y| / h ~ 1e-11; 1e-7 with margin
constexpr double kFirstDifference = 1e-7;
// y'' against (y(+h) - 2 y + y(-h)) / h^2 with h = 1e-5: the rounding of the poses (~1e-13)
// over h^2 = 1e-10 is ~1e-3
constexpr double kSecondDifference = 1e-3;

// [rad] singular points are located to about 1e-10 (continuation.hpp) by either path, the block
// and the dense one
constexpr double kSingularLocation = 1e-9;

const double kL23 = 2.5 * std::sqrt(3.0);              // seed 003: l2 = l3 = 5/2 sqrt(3)
const double kKappa = std::acos(5.0 / 9.0 * std::sqrt(3.0));  // seed 003: cos kappa = 5/9 sqrt(3)

SweepOptions FullTurn(int order = 2) {
  SweepOptions o;
  o.from = 0;
  o.to = 2 * kPi;
  o.step = DegToRad(1);
  o.order = order;
  return o;
}

bool AllFinite(const SweepResult& r) { return r.outputs.allFinite() && r.poses.allFinite(); }

}  // namespace

TEST_CASE("seed 000: slider-crank s, s', s'', mu over a full turn match the document", "[sweep]") {
  for (double e : {0.0, 0.8}) {
    const double l1 = 1.0, l2 = 2.6;
    const SweepResult r = Sweep(test::SliderCrank(l1, l2, e), FullTurn());
    REQUIRE(r.complete());
    REQUIRE(r.inputs.size() == 361);
    double worst = 0;
    for (size_t i = 0; i < r.inputs.size(); ++i) {
      const test::SliderCrankValues v = test::SliderCrank(l1, l2, e, r.inputs[i]);
      // columns: s, s_d1, s_d2, mu, mu_d1, mu_d2
      worst = std::max({worst, std::abs(r.outputs(i, 0) - v.s), std::abs(r.outputs(i, 1) - v.s1),
                        std::abs(r.outputs(i, 2) - v.s2), std::abs(r.outputs(i, 3) - v.mu)});
    }
    INFO("e = " << e << ": worst deviation " << worst);
    CHECK(worst <= test::kClosedForm * l1);
  }
}

TEST_CASE("seed 001: proportional linkage s, s', s'' over a full turn match the document", "[sweep]") {
  const double l6 = 1.0, l1 = 0.5, h = 1.83;
  const SweepResult r = Sweep(test::ProportionalLinkage(l6, l1, h), FullTurn());
  REQUIRE(r.complete());
  double worst = 0;
  for (size_t i = 0; i < r.inputs.size(); ++i) {
    const test::ProportionalValues v = test::Proportional(l6, l1, h, r.inputs[i]);
    worst = std::max({worst, std::abs(r.outputs(i, 0) - v.s), std::abs(r.outputs(i, 1) - v.s1), std::abs(r.outputs(i, 2) - v.s2)});
  }
  INFO("worst deviation " << worst);
  CHECK(worst <= test::kClosedForm * l1);
}

TEST_CASE("seed 001: 3rd and 4th order against finite differences of the closed form s''", "[sweep]") {
  const double l6 = 1.0, l1 = 0.5, h = 1.83;
  const SweepResult r = Sweep(test::ProportionalLinkage(l6, l1, h), FullTurn(4));
  REQUIRE(r.complete());
  // five-point stencils on the closed-form s'' with step 1e-3: truncation O(h^4 s^(7)) ~ 1e-10,
  // roundoff O(eps |s''| / h^2) ~ 1e-10 for the 4th order
  const double step = 1e-3;
  double worst3 = 0, worst4 = 0;
  for (size_t i = 0; i < r.inputs.size(); i += 5) {
    const double phi = r.inputs[i];
    auto s2 = [&](double x) { return test::Proportional(l6, l1, h, x).s2; };
    const double d3 = (-s2(phi + 2 * step) + 8 * s2(phi + step) - 8 * s2(phi - step) + s2(phi - 2 * step)) / (12 * step);
    const double d4 = (-s2(phi + 2 * step) + 16 * s2(phi + step) - 30 * s2(phi) + 16 * s2(phi - step) - s2(phi - 2 * step)) /
                      (12 * step * step);
    worst3 = std::max(worst3, std::abs(r.outputs(i, 3) - d3));
    worst4 = std::max(worst4, std::abs(r.outputs(i, 4) - d4));
  }
  INFO("worst s''' deviation " << worst3 << ", s'''' " << worst4);
  CHECK(worst3 <= 1e-8);
  CHECK(worst4 <= 1e-6);
}

TEST_CASE("seed 001: the flat point s''(180) = s'''(180) = s''''(180) = 0 for lambda = 0.5", "[sweep]") {
  SweepOptions at180;
  at180.from = at180.to = kPi;
  at180.order = 6;
  const SweepResult r = Sweep(test::ProportionalLinkage(1.0, 0.5, 1.83), at180);
  REQUIRE(r.complete());
  CHECK(std::abs(r.outputs(0, 2)) < 1e-9);
  CHECK(std::abs(r.outputs(0, 3)) < 1e-9);
  CHECK(std::abs(r.outputs(0, 4)) < 1e-9);
  // the 5th derivative does not vanish: the flat point is of order four, not a constant s'
  CHECK(std::abs(r.outputs(0, 5)) > 0.1);
  // for lambda = 0.4 s''' does not vanish: differentiating the document's s'' at 180 deg gives
  // s'''(180) = c (1 - 2 lambda^2 - lambda)/(1 + lambda)^3, c = l1 h/l6, zero only for lambda = 0.5
  const double lambda = 0.4, c = 0.4 * 1.83;
  const SweepResult other = Sweep(test::ProportionalLinkage(1.0, 0.4, 1.83), at180);
  CHECK(other.outputs(0, 3) == Approx(c * (1 - 2 * lambda * lambda - lambda) / std::pow(1 + lambda, 3)).margin(test::kClosedForm));
  CHECK(std::abs(other.outputs(0, 3)) > 0.07);
}

TEST_CASE("seed 003: coupler point K over a full turn matches a circle-intersection model", "[sweep]") {
  for (int side : {1, -1}) {
    const SweepResult r = Sweep(test::FourBar(1.0, kL23, kL23, 4.0, 25.0 / 3, kKappa, side), FullTurn());
    REQUIRE(r.complete());
    double worst = 0;
    for (size_t i = 0; i < r.inputs.size(); ++i) {
      const Eigen::Vector2d k = test::FourBarCouplerPoint(1.0, kL23, kL23, 4.0, 25.0 / 3, kKappa, r.inputs[i], side);
      // columns: K_x, K_x_d1, K_x_d2, K_y, ...
      worst = std::max({worst, std::abs(r.outputs(i, 0) - k.x()), std::abs(r.outputs(i, 3) - k.y())});
    }
    INFO("branch side " << side << ": worst deviation " << worst);
    CHECK(worst <= test::kClosedForm);  // also proves the branch never flipped over 361 samples
  }
}

TEST_CASE("a crank-rocker driven at the rocker stops at the dead centre and says so", "[sweep]") {
  const Mechanism m = test::FourBar(1.0, kL23, kL23, 4.0, 25.0 / 3, kKappa, 1, true);
  // the rocker's extreme angles: A0B = l2 + l1 (extended) and l2 - l1 (folded), law of cosines
  auto rocker_limit = [&](double a0b) {
    const double at_b0 = std::acos((4.0 * 4.0 + kL23 * kL23 - a0b * a0b) / (2 * 4.0 * kL23));
    return kPi - at_b0;  // angle of B0 -> B against +x
  };
  const double upper = rocker_limit(kL23 + 1.0), lower = rocker_limit(kL23 - 1.0);
  Mechanism driven = m;
  driven.hint.input = DegToRad(110);
  driven.hint.points = {{{2, 1}, {1.8, 3.9}}};  // coupler B, above A0B0
  SweepOptions o;
  o.from = DegToRad(110);
  o.to = DegToRad(180);
  o.step = DegToRad(1);
  const SweepResult up = Sweep(driven, o);
  CHECK(up.status == SweepStatus::kPartial);
  CHECK_THAT(up.message, Catch::Contains("limit point") && Catch::Contains("phi = 133.0795"));
  // limit points are located to 1e-11 rad; the law of cosines is the reference
  CHECK(std::abs(up.reached.to - std::max(upper, lower)) < 1e-9);
  REQUIRE(up.singular_points.size() == 1);
  CHECK(up.singular_points[0].kind == SingularKind::kLimitPoint);
  CHECK(std::abs(up.singular_points[0].input - std::max(upper, lower)) < 1e-9);
  REQUIRE(up.gaps.size() == 1);
  CHECK(up.gaps[0].from == up.reached.to);
  CHECK(up.gaps[0].to == o.to);
  CHECK(AllFinite(up));
  CHECK(up.inputs.size() == 24);  // 110 .. 133 deg
  o.to = DegToRad(90);
  const SweepResult down = Sweep(driven, o);
  CHECK(down.status == SweepStatus::kPartial);
  CHECK(std::abs(down.reached.from - std::min(upper, lower)) < 1e-9);
  CHECK(AllFinite(down));
}

TEST_CASE("a mechanism that cannot be assembled is reported, naming a joint", "[sweep]") {
  const Mechanism m = test::FourBar(1.0, 2.0, 2.0, 10.0, 1.0, 0.0, 1);  // 1 + 2 + 2 < 10
  const SweepResult r = Sweep(m, FullTurn());
  CHECK(r.status == SweepStatus::kNotAssemblable);
  CHECK_THAT(r.message, Catch::Contains("joint '"));
  CHECK(r.inputs.empty());
}

TEST_CASE("two independent loops: velocities agree with differences of solved positions", "[sweep]") {
  const Mechanism m = test::WattSixBar();
  const SweepResult r = Sweep(m, FullTurn());
  REQUIRE(r.complete());
  REQUIRE(AllFinite(r));
  // reference: central differences of the solver's own positions, step 1e-5 rad
  // (truncation ~1e-10 chi''', Newton tolerance 1e-13 / 1e-5 = 1e-8)
  const double h = 1e-5;
  for (double phi : {0.3, 1.7, 4.0}) {
    SweepOptions o;
    o.from = phi - h;
    o.to = phi + h;
    o.step = h;
    o.order = 2;
    const SweepResult local = Sweep(m, o);
    REQUIRE(local.complete());
    REQUIRE(local.inputs.size() == 3);
    const double fd1 = (local.outputs(2, 0) - local.outputs(0, 0)) / (2 * h);
    const double fd2 = (local.outputs(2, 0) - 2 * local.outputs(1, 0) + local.outputs(0, 0)) / (h * h);
    CHECK(local.outputs(1, 1) == Approx(fd1).margin(kFirstDifference));
    CHECK(local.outputs(1, 2) == Approx(fd2).margin(kSecondDifference));
  }
}

namespace {

// The block path (default) against the dense reference path: the same rows, flags, singular
// points and gaps; poses, outputs and transfer functions within kSamePath, except the k-th
// orders near singular positions, which either path knows only to eps / rcond^k.
double CheckSamePaths(const Mechanism& m, SweepOptions o) {
  SweepOptions dense = o;
  dense.newton.dense = true;
  const SweepResult fast = Sweep(m, o), reference = Sweep(m, dense);
  REQUIRE(fast.status == reference.status);
  REQUIRE(fast.inputs == reference.inputs);
  REQUIRE(fast.singular == reference.singular);
  REQUIRE(fast.valid_order == reference.valid_order);
  REQUIRE(fast.singular_points.size() == reference.singular_points.size());
  for (size_t i = 0; i < fast.singular_points.size(); ++i) {
    CHECK(fast.singular_points[i].kind == reference.singular_points[i].kind);
    CHECK(fast.singular_points[i].joints == reference.singular_points[i].joints);
    // located to about 1e-10 (continuation.hpp) by either path
    CHECK_THAT(fast.singular_points[i].input, Catch::Matchers::WithinAbs(reference.singular_points[i].input, kSingularLocation));
  }
  REQUIRE(fast.gaps.size() == reference.gaps.size());
  double worst = 0.0;
  const double scale = LengthScale(m);
  for (Eigen::Index i = 0; i < fast.poses.size(); ++i) {
    worst = std::max(worst, std::abs(fast.poses.data()[i] - reference.poses.data()[i]) / scale);
  }
  const ConstraintSystem system(m);
  for (Eigen::Index r = 0; r < fast.outputs.rows(); ++r) {
    double rcond = -1.0;  // computed where needed
    for (Eigen::Index c = 0; c < fast.outputs.cols(); ++c) {
      const double a = fast.outputs(r, c), b = reference.outputs(r, c);
      const double deviation = std::abs(a - b) / (1.0 + std::abs(b));
      if (deviation <= test::kSamePath) {
        worst = std::max(worst, deviation);
        continue;
      }
      // Near a singular position the k-th order carries roundoff of order eps / rcond^k by either
      // path (singular.hpp): there they can only agree that well (100: the roundoff of the some
      // tens of operations behind each entry).
      if (rcond < 0.0) rcond = ReciprocalCondition(system, reference.poses.row(r).transpose());
      const int k = static_cast<int>(c % (o.order + 1));
      INFO("row " << r << ", column " << c << " (order " << k << "): rcond " << rcond);
      CHECK(deviation <= 100.0 * std::numeric_limits<double>::epsilon() / std::pow(rcond, k));
    }
  }
  return worst;  // of the entries within kSamePath, for the report
}

}  // namespace

TEST_CASE("the block path gives the dense path's sweeps: seeds 000, 001, 003, two-loop and folding six-bars", "[sweep][blocks]") {
  SweepOptions o = FullTurn(4);
  double worst = 0.0;
  for (double e : {0.0, 0.8}) worst = std::max(worst, CheckSamePaths(test::SliderCrank(1.0, 2.6, e), o));
  worst = std::max(worst, CheckSamePaths(test::ProportionalLinkage(1.0, 0.5, 1.83), o));
  worst = std::max(worst, CheckSamePaths(test::FourBar(1.0, kL23, kL23, 4.0, 25.0 / 3.0, kKappa, +1), o));
  worst = std::max(worst, CheckSamePaths(test::WattSixBar(), o));
  // a second loop folding flat mid-sweep (the fold direction that of B0 -> C at phi = 110 deg, as
  // continuation_test): branch points crossed by both paths alike
  const double psi110 = test::FourBarRocker(1, 3.5, 3, 4, DegToRad(110), +1)->psi;
  worst = std::max(worst, CheckSamePaths(test::FoldingSixBar(1.5, 0.7, 2.0, psi110 + 0.7), o));
  INFO("worst deviation " << worst);
  SUCCEED();
}

TEST_CASE("the block path gives the dense path's sweeps: random four-bars and slider-cranks", "[sweep][blocks]") {
  std::mt19937 random(20261123);
  std::uniform_real_distribution<double> length(0.5, 4.0), offset(-1.0, 1.0), side(-1.0, 1.0);
  SweepOptions o = FullTurn(2);
  o.step = DegToRad(3);
  double worst = 0.0;
  for (int trial = 0; trial < 12; ++trial) {
    // crank-rockers, double rockers (limit points) and non-Grashof linkages alike
    const double a = length(random), b = length(random), c = length(random), d = length(random);
    const Eigen::Vector2d pa(a, 0), b0(d, 0);
    const double dist = (b0 - pa).norm();
    if (dist > b + c || dist < std::abs(b - c)) continue;  // no pose at input 0
    const double along = (b * b - c * c + dist * dist) / (2 * dist);
    const Eigen::Vector2d u = (b0 - pa) / dist, n(-u.y(), u.x());
    const Eigen::Vector2d hint = pa + along * u + (side(random) > 0 ? 1.0 : -1.0) * std::sqrt(b * b - along * along) * n;
    INFO("four-bar " << a << ", " << b << ", " << c << ", " << d);
    worst = std::max(worst, CheckSamePaths(test::PlainFourBar(a, b, c, d, 0.0, hint), o));
  }
  for (int trial = 0; trial < 12; ++trial) {
    const double l1 = length(random), l2 = length(random), e = offset(random);
    if (l2 <= std::abs(e + l1) + 0.05) continue;  // no pose at input 0 (crank pointing away from the slide line)
    INFO("slider-crank " << l1 << ", " << l2 << ", " << e);
    worst = std::max(worst, CheckSamePaths(test::SliderCrank(l1, l2, e), o));
  }
  INFO("worst deviation " << worst);
  SUCCEED();
}

TEST_CASE("sample counts", "[sweep]") {
  CHECK(SampleCount(0, 360, 1) == 361);
  CHECK(SampleCount(0, 1, 0.3) == 4);
  CHECK(SampleCount(360, 0, 1) == 361);
  CHECK(SampleCount(5, 5, 1) == 1);
}

TEST_CASE("a sweep without poses has the same rows, flags and events as one with them", "[sweep]") {
  // reference: the same sweep keeping its poses; only SweepResult::poses may differ (no columns)
  for (const Mechanism& m : {test::SliderCrank(1.0, 2.6, 0.8), test::FourBar(1.0, 3.5, 3.0, 4.0, 2.0, 0.5, 1)}) {
    SweepOptions with = FullTurn(3), without = FullTurn(3);
    without.poses = false;
    const SweepResult a = Sweep(m, with), b = Sweep(m, without);
    REQUIRE(a.complete());
    REQUIRE(b.complete());
    CHECK(a.poses.rows() == static_cast<Eigen::Index>(a.inputs.size()));
    CHECK(a.poses.cols() > 0);
    CHECK(b.poses.cols() == 0);
    CHECK(b.inputs == a.inputs);
    CHECK(b.outputs == a.outputs);  // bit for bit: the same walk, the angles only not read
    CHECK(b.singular == a.singular);
    CHECK(b.valid_order == a.valid_order);
    CHECK(b.singular_points.size() == a.singular_points.size());
  }
}

}  // namespace koppel::sweep_test
