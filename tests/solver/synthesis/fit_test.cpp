// Least-squares fitting: a five-precision-point path synthesis whose answer is seed 003's
// crank-rocker (started away from it), a function-generation problem, free inputs, and a
// problem whose targets cannot all be met, reported honestly.
#include "koppel/synthesis/fit.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/build.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::fit_test {
namespace {

const double kL23 = 2.5 * std::sqrt(3.0);
const double kKappa = std::acos(5.0 / 9.0 * std::sqrt(3.0));

// seed 003's four-bar with l3 and AK free
MechanismBuilder FourBarBuilder() {
  return [](const std::vector<double>& p) -> Expected<Mechanism> {
    return test::FourBar(1.0, kL23, p[0], 4.0, p[1], kKappa, 1);
  };
}

std::vector<FitTarget> PrecisionPoints(const std::vector<double>& inputs_deg) {
  std::vector<FitTarget> targets;
  for (double phi : inputs_deg) {
    FitTarget t;
    t.name = "K";
    t.output = 0;
    t.point = true;
    t.input = DegToRad(phi);
    // reference: the independent circle-intersection model with the true dimensions
    t.position = test::FourBarCouplerPoint(1.0, kL23, kL23, 4.0, 25.0 / 3, kKappa, t.input, 1);
    targets.push_back(t);
  }
  return targets;
}

}  // namespace

TEST_CASE("five precision points find seed 003's crank-rocker again", "[fit]") {
  const std::vector<FitParameter> params = {{"l3", 4.0, 3.5, 5.0}, {"k", 7.5, 6.0, 9.0}};
  FitOptions options;
  options.require_from = 0;
  options.require_to = 2 * kPi;
  options.starts = 1;
  const FitReport r = Fit(FourBarBuilder(), params, PrecisionPoints({0, 72, 144, 216, 288}), options);
  INFO(r.Brief());
  REQUIRE(r.ok());
  CHECK(r.values[0] == Approx(kL23).margin(1e-8));
  CHECK(r.values[1] == Approx(25.0 / 3).margin(1e-8));
  for (const FitTargetResult& t : r.targets) {
    CHECK(t.residual < 1e-9);
    CHECK(t.unit == FitUnit::kLength);
  }
  CHECK(r.assembles_over_range);
  // exact gradients through the solver: Gauss–Newton converges in a handful of iterations
  CHECK(r.iterations < 15);
}

TEST_CASE("precision points with free inputs", "[fit]") {
  auto targets = PrecisionPoints({20, 100, 180, 260, 330});
  for (FitTarget& t : targets) {
    t.input_free = true;
    t.input += DegToRad(3);  // the start is off by 3 degrees
  }
  const std::vector<FitParameter> params = {{"l3", 4.2, 3.5, 5.0}, {"k", 8.0, 6.0, 9.0}};
  FitOptions one;
  one.starts = 1;
  const FitReport r = Fit(FourBarBuilder(), params, targets, one);
  INFO(r.Brief());
  REQUIRE(r.ok());
  CHECK(r.values[0] == Approx(kL23).margin(1e-7));
  CHECK(r.values[1] == Approx(25.0 / 3).margin(1e-7));
  CHECK(RadToDeg(r.targets[2].input) == Approx(180).margin(1e-6));
}

TEST_CASE("function generation: the offset of a slider-crank from its slider positions", "[fit]") {
  const MechanismBuilder builder = [](const std::vector<double>& p) -> Expected<Mechanism> {
    return test::SliderCrank(1.0, 2.6, p[0]);
  };
  std::vector<FitTarget> targets;
  for (double phi : {0.0, 60.0, 130.0, 250.0}) {
    FitTarget t;
    t.name = "s";
    t.output = 0;
    t.input = DegToRad(phi);
    t.value = test::SliderCrank(1.0, 2.6, 0.8, t.input).s;  // seed 000's closed form, e = 0.8
    targets.push_back(t);
  }
  const FitReport r = Fit(builder, {{"e", 0.2, 0.0, 1.2}}, targets, FitOptions{});
  INFO(r.Brief());
  REQUIRE(r.ok());
  CHECK(r.values[0] == Approx(0.8).margin(1e-9));
  CHECK(r.targets[0].unit == FitUnit::kLength);
}

TEST_CASE("targets that cannot all be met: the fit says which and by how much", "[fit]") {
  auto targets = PrecisionPoints({0, 90, 180, 270});
  targets[1].position += Eigen::Vector2d(0.3, -0.2);  // a point off the curve of any nearby design
  const std::vector<FitParameter> params = {{"l3", kL23, 3.5, 5.0}, {"k", 25.0 / 3, 6.0, 9.0}};
  FitOptions options;
  options.starts = 4;
  const FitReport r = Fit(FourBarBuilder(), params, targets, options);
  REQUIRE(!r.values.empty());
  CHECK(r.status == FitStatus::kAboveTolerance);
  CHECK_FALSE(r.ok());
  double worst = 0;
  for (const FitTargetResult& t : r.targets) worst = std::max(worst, t.residual);
  CHECK(worst > 0.01);
  CHECK(r.cost > 1e-5);
  // the message names every missed target with its residual; met ones are not named
  for (size_t i = 0; i < r.targets.size(); ++i) {
    const std::string name = "target " + std::to_string(i + 1) + " 'K' misses by";
    if (r.targets[i].met) CHECK_THAT(r.message, !Catch::Contains(name));
    else CHECK_THAT(r.message, Catch::Contains(name));
  }
  // the reported cost is the sum of the reported residuals' squares (weights 1)
  double sum = 0;
  for (const FitTargetResult& t : r.targets) sum += 0.5 * t.residual * t.residual;
  CHECK(r.cost == Approx(sum).epsilon(1e-9));
  // a tolerance that the best design meets turns the verdict
  for (FitTarget& t : targets) t.tolerance = 1.1 * worst;
  CHECK(Fit(FourBarBuilder(), params, targets, options).ok());
}

}  // namespace koppel::fit_test

namespace koppel::fit_test {

TEST_CASE("dead-centre targets: a crank-rocker whose rocker has its dead centres where asked", "[fit]") {
  // reference: the dead-centre synthesis answer for phi0 = 164 deg, psi0 = 60 deg, beta = 30 deg has
  // its extended dead centre at phi = 30 deg and the folded one at 30 - 164 = -134 deg; start from
  // other rocker and coupler lengths and ask for dead centres there (plus the swing as a value)
  const MechanismBuilder builder = [](const std::vector<double>& p) -> Expected<Mechanism> {
    return test::FourBar(0.33200614543343, p[0], p[1], 1.0, 0.1, 0.0, 1);
  };
  std::vector<FitTarget> targets(2);
  targets[0].name = "extended";
  targets[0].output = 1;  // psi
  targets[0].deadcentre = true;
  targets[0].input = DegToRad(30);
  targets[1] = targets[0];
  targets[1].name = "folded";
  targets[1].input = DegToRad(-134 + 360);
  FitOptions one;
  one.starts = 1;
  const FitReport r = Fit(builder, {{"l2", 1.0, 0.5, 2.0}, {"l3", 0.8, 0.3, 1.5}}, targets, one);
  INFO(r.Brief());
  REQUIRE(r.ok());
  // the answer of the synthesis (re-analysed there to 1e-9): l2 = 1.05178..., l3 = 0.71977...
  CHECK(r.values[0] == Approx(1.0517844152462932).margin(1e-7));
  CHECK(r.values[1] == Approx(0.7197782698128629).margin(1e-7));
  for (const FitTargetResult& t : r.targets) {
    CHECK(t.residual < 1e-9);
    CHECK(t.unit == FitUnit::kAngle);  // a dead centre of an R drive is an input angle
  }
  CHECK(r.iterations < 25);
}

}  // namespace koppel::fit_test

namespace koppel::fit_test {

TEST_CASE("straight-line target: AK of seed 003 that makes K's path straightest around phi = 180", "[fit]") {
  // seed 003's K has six-point contact with its tangent at phi = 180 deg only for AK = 25/3
  // (with the other dimensions fixed): fitting AK for straightness over 150..210 deg finds it
  const MechanismBuilder builder = [](const std::vector<double>& p) -> Expected<Mechanism> {
    return test::FourBar(1.0, kL23, kL23, 4.0, p[0], kKappa, 1);
  };
  FitTarget t;
  t.name = "straight";
  t.output = 0;
  t.straight = true;
  t.input = DegToRad(150);
  t.to = DegToRad(210);
  t.samples = 31;
  // a straight line over a finite stretch is never exact: its tolerance says what is good enough
  t.tolerance = 1e-3;
  FitOptions one;
  one.starts = 1;
  const FitReport r = Fit(builder, {{"k", 7.0, 5.0, 10.0}}, {t}, one);
  INFO(r.Brief());
  REQUIRE(r.ok());
  // the optimum over a finite stretch sits close to, not exactly at, the six-point point
  CHECK(r.values[0] == Approx(25.0 / 3).margin(0.02));
  CHECK(r.iterations < 15);  // exact sensitivities, including the line's own motion
  // and the deviation there is tiny compared with the start's (no iterations: the start itself)
  FitOptions none = one;
  none.max_iterations = 0;
  const FitReport start = Fit(builder, {{"k", 7.0, 5.0, 10.0}}, {t}, none);
  REQUIRE(!start.values.empty());
  CHECK(start.status == FitStatus::kAboveTolerance);
  CHECK(r.targets[0].residual < 0.01 * start.targets[0].residual);
}

}  // namespace koppel::fit_test

namespace koppel::fit_test {
namespace {

// A crank-rocker with a vertical frame line A0 = 0, B0 = (0, l4): its rocker swings on the left
// through the direction 180 deg. Output "dir": the direction B0 -> B (atan2, in (-180, 180]).
Mechanism VerticalFourBar(double l1, double l2, double l3, double l4) {
  Mechanism m;
  m.name = "vertical-four-bar";
  m.links = {{"frame", true, {{"A0", {0, 0}}, {"B0", {0, l4}}}},
             {"crank", false, {{"A0", {0, 0}}, {"A", {l1, 0}}}},
             {"coupler", false, {{"A", {0, 0}}, {"B", {l2, 0}}}},
             {"rocker", false, {{"B0", {0, 0}}, {"B", {l3, 0}}}}};
  m.joints = {PinJoint(m, "A0", 0, 1), PinJoint(m, "A", 1, 2), PinJoint(m, "B", 2, 3), PinJoint(m, "B0", 0, 3)};
  m.drive.joint = 0;
  Output dir;
  dir.name = "dir";
  dir.kind = OutputKind::kDirection;
  dir.p = {3, 0};
  dir.q = {3, 1};
  m.outputs = {dir};
  m.hint.input = 0;
  m.hint.points = {{{2, 1}, {-1.7, 0.5}}, {{3, 1}, {-1.7, 0.5}}};
  return m;
}

// Reference: the same four-bar by circle intersection (B left of A -> B0), the direction B0 -> B.
double VerticalFourBarDirection(double l1, double l2, double l3, double l4, double phi) {
  const Eigen::Vector2d a(l1 * std::cos(phi), l1 * std::sin(phi)), b0(0, l4), ab0 = b0 - a;
  const double r = ab0.norm(), along = (l2 * l2 - l3 * l3 + r * r) / (2 * r);
  const Eigen::Vector2d n = ab0 / r, b = a + along * n + std::sqrt(l2 * l2 - along * along) * Eigen::Vector2d(-n.y(), n.x());
  return std::atan2(b.y() - b0.y(), b.x() - b0.x());
}

MechanismBuilder VerticalBuilder() {
  return [](const std::vector<double>& p) -> Expected<Mechanism> {
    return VerticalFourBar(p[0], p[1], p[2], 3.0);
  };
}

// Three function-generation targets of the true design (l1, l2, l3) = kTrue at crank angles 100,
// 225 and 270 deg: directions about 153, 202 (reported -158) and 223 (reported -137) deg.
const double kTrue[3] = {1.674809355059234, 3.4392161246035777, 2.8153010600173283};

std::vector<FitTarget> DirectionTargets(bool as_reported) {
  std::vector<FitTarget> targets;
  for (double phi : {100.0, 225.0, 270.0}) {
    FitTarget t;
    t.name = "dir";
    t.output = 0;
    t.input = DegToRad(phi);
    t.value = VerticalFourBarDirection(kTrue[0], kTrue[1], kTrue[2], 3.0, t.input);
    if (!as_reported && t.value < 0) t.value += 2 * kPi;  // 202 deg, not -158 deg
    targets.push_back(t);
  }
  return targets;
}

// starts at the corner (2.5, 2, 1) of the bounds, where the linkage does not even assemble
// (|AB0| = 3.9 > l2 + l3 at the assembly input)
const std::vector<FitParameter> kLengths = {{"l1", 2.5, 0.5, 2.5}, {"l2", 2.0, 2.0, 6.0}, {"l3", 1.0, 1.0, 5.0}};

}  // namespace

TEST_CASE("function generation with angle targets across +-180 deg: residuals wrapped", "[fit]") {
  // the targets as a user writes them (153, 202, 223 deg) and as the output reports them
  // (153, -158, -137 deg) are the same problem with the same answer
  for (bool as_reported : {false, true}) {
    INFO("targets as reported: " << as_reported);
    const std::vector<FitTarget> targets = DirectionTargets(as_reported);
    CHECK(RadToDeg(targets[1].value) == Approx(as_reported ? -158 : 202).margin(0.5));
    std::vector<FitParameter> start = kLengths;
    start[0].start = 1.0;  // a start from which a single run converges (this one assembles)
    start[1].start = 3.0;
    start[2].start = 2.5;
    FitOptions one;
    one.starts = 1;
    const FitReport r = Fit(VerticalBuilder(), start, targets, one);
    INFO(r.Brief());
    REQUIRE(r.ok());
    for (int j = 0; j < 3; ++j) CHECK(r.values[j] == Approx(kTrue[j]).margin(1e-9));
    for (const FitTargetResult& t : r.targets) {
      CHECK(t.unit == FitUnit::kAngle);
      CHECK(t.residual < 1e-10);
    }
  }
}

TEST_CASE("an exactly solvable three-point problem is solved to 1e-10 with the default starts", "[fit]") {
  // the given start does not even assemble: a single start finds nothing, the default starts
  // find the exact design from several of them
  FitOptions single;
  single.starts = 1;
  const FitReport alone = Fit(VerticalBuilder(), kLengths, DirectionTargets(false), single);
  CHECK(alone.status == FitStatus::kNoUsableStart);
  CHECK_FALSE(alone.starts[0].usable);
  const FitReport r = Fit(VerticalBuilder(), kLengths, DirectionTargets(false), FitOptions{});
  INFO(r.Brief());
  REQUIRE(r.ok());
  CHECK(static_cast<int>(r.starts.size()) == kDefaultFitStarts);
  for (int j = 0; j < 3; ++j) CHECK(r.values[j] == Approx(kTrue[j]).margin(1e-9));
  for (const FitTargetResult& t : r.targets) CHECK(t.residual < 1e-10);
  CHECK(r.starts_at_best >= 2);
  CHECK(r.starts_at_best <= kDefaultFitStarts);
  // every start carries Ceres' report (or why it did not run)
  for (const FitStart& s : r.starts) CHECK_FALSE(s.brief.empty());
}

TEST_CASE("the result does not depend on the number of threads", "[fit]") {
  FitOptions one, two;
  one.starts = two.starts = 6;
  one.threads = 1;
  two.threads = 2;
  const FitReport a = Fit(VerticalBuilder(), kLengths, DirectionTargets(false), one);
  const FitReport b = Fit(VerticalBuilder(), kLengths, DirectionTargets(false), two);
  REQUIRE(a.values.size() == b.values.size());
  CHECK(a.best_start == b.best_start);
  CHECK(a.starts_at_best == b.starts_at_best);
  for (size_t j = 0; j < a.values.size(); ++j) CHECK(a.values[j] == b.values[j]);
  for (size_t k = 0; k < a.starts.size(); ++k) CHECK(a.starts[k].cost == b.starts[k].cost);
}

TEST_CASE("a design that does not assemble over the required range: the drivable range, not a bare 0", "[fit]") {
  // a non-Grashof four-bar (l1 + l4 = 6 > l2 + l3 = 5): its crank reaches only the inputs where
  // |AB0| <= l2 + l3, i.e. cos phi >= (l1^2 + l4^2 - (l2 + l3)^2) / (2 l1 l4) = -5/16
  const MechanismBuilder builder = [](const std::vector<double>& p) -> Expected<Mechanism> {
    return test::FourBar(2.0, 2.5, p[0], 4.0, 1.0, 0.0, 1);
  };
  FitTarget t;
  t.name = "psi";
  t.output = 1;
  t.input = DegToRad(30);
  // the target value: the generic solver's psi of the true design (l3 = 2.5) at 30 deg, read
  // as the residual against 0 of a fit that does not iterate
  {
    FitOptions zero;
    zero.starts = 1;
    zero.max_iterations = 0;
    FitTarget probe = t;
    probe.value = 0;
    const FitReport at_truth = Fit(builder, {{"l3", 2.5, 2.0, 3.0}}, {probe}, zero);
    REQUIRE(!at_truth.values.empty());
    t.value = at_truth.targets[0].residual;  // |psi - 0|: psi lies in (0, pi) on this branch
  }
  FitOptions options;
  options.starts = 1;
  options.require_from = 0;
  options.require_to = 2 * kPi;
  const FitReport r = Fit(builder, {{"l3", 2.3, 2.0, 3.0}}, {t}, options);
  INFO(r.Brief());
  REQUIRE(!r.values.empty());
  CHECK(r.values[0] == Approx(2.5).margin(1e-8));
  CHECK(r.targets[0].met);
  CHECK(r.status == FitStatus::kNotAssembling);
  CHECK_FALSE(r.assembles_over_range);
  const double limit = std::acos(-5.0 / 16);  // 108.2 deg
  CHECK(r.drivable_to == Approx(limit).margin(1e-6));
  CHECK(r.drivable_from == Approx(-limit).margin(1e-6));
  CHECK_THAT(r.message, Catch::Contains("its drive reaches -108.2"));
}

TEST_CASE("fit options validate themselves", "[fit]") {
  std::string why;
  FitOptions o;
  CHECK(o.IsValid(&why));
  o.starts = 0;
  CHECK_FALSE(o.IsValid(&why));
  CHECK_THAT(why, Catch::Contains("starts"));
  o = FitOptions{};
  o.length_tolerance = 0;
  CHECK_FALSE(o.IsValid(&why));
  const FitReport r = Fit(VerticalBuilder(), kLengths, DirectionTargets(false), o);
  CHECK(r.status == FitStatus::kInvalidOptions);
  CHECK(FitReport{}.status == FitStatus::kNotRun);
}

namespace {

// The four-bar 1, 3.5, 3 with its frame pivot B0 at (d, 0), d free, and one target: the frame's
// length |A0B0| = 4. Two exact designs, d = 4 and its mirror d = -4 (B0 left of A0), which only
// the design space's pivot box tells apart.
MechanismBuilder FramePivotBuilder() {
  return [](const std::vector<double>& p) -> Expected<Mechanism> {
    const double d = p[0];
    const Eigen::Vector2d a(0, 1), b0(d, 0);  // assembled at the crank angle 90 deg
    const double diagonal = (b0 - a).norm();
    if (diagonal > 6.5 || diagonal < 0.5) return Expected<Mechanism>::Error("the loop does not close at 90 deg");
    const double along = (3.5 * 3.5 - 9 + diagonal * diagonal) / (2 * diagonal);
    const Eigen::Vector2d u = (b0 - a) / diagonal;
    Mechanism m = test::PlainFourBar(1, 3.5, 3, d, kPi / 2, a + along * u + std::sqrt(3.5 * 3.5 - along * along) * Eigen::Vector2d(-u.y(), u.x()));
    DistanceOutput(m, "frame", "frame", "A0", "frame", "B0");
    return m;
  };
}

}  // namespace

TEST_CASE("the design space picks the start whose design lies inside it", "[fit][design-space]") {
  FitTarget frame;
  frame.name = "frame";
  frame.output = 2;  // after psi and theta
  frame.value = 4;
  const std::vector<FitParameter> params = {{"d", 0.5, -6, 6}};
  FitOptions options;
  options.threads = 2;
  options.space.pivots_x = std::make_pair(0.0, 10.0);
  const FitReport right = Fit(FramePivotBuilder(), params, {frame}, options);
  INFO(right.Brief());
  REQUIRE(right.ok());
  CHECK(right.values[0] == Approx(4).margin(1e-8));
  options.space.pivots_x = std::make_pair(-10.0, 0.0);
  const FitReport left = Fit(FramePivotBuilder(), params, {frame}, options);
  INFO(left.Brief());
  REQUIRE(left.ok());
  CHECK(left.values[0] == Approx(-4).margin(1e-8));
  // no start inside: nothing fitted, the constraint the best design broke named with its figure
  options.space.pivots_x = std::make_pair(5.0, 10.0);
  const FitReport none = Fit(FramePivotBuilder(), params, {frame}, options);
  CHECK(none.status == FitStatus::kOutsideSpace);
  CHECK(none.values.empty());
  CHECK_THAT(none.message, Catch::Contains("pivots: A0 at x = 0, outside [5, 10]"));
  // a space the mechanism cannot be held to is refused before any start
  options.space = DesignSpace();
  options.space.mu_min = DegToRad(30);  // the builder's four-bar has no transmission-angle output
  const FitReport uncheckable = Fit(FramePivotBuilder(), params, {frame}, options);
  CHECK(uncheckable.status == FitStatus::kInvalidOptions);
  CHECK_THAT(uncheckable.message, Catch::Contains("no transmission-angle output"));
}

}  // namespace koppel::fit_test
