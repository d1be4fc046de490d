// Function generation on the classic exercises of Freudenstein's method (y = log10 x over
// 1 <= x <= 10 and y = x^2 over 0 <= x <= 1, three Chebyshev points; e.g. Shigley & Uicker,
// Theory of Machines and Mechanisms, ch. 10, and Hartenberg & Denavit, Kinematic Synthesis of
// Linkages, ch. 11), crank over 60 deg and rocker over 90 deg. References: the structural error is re-evaluated here in closed form (the
// triangle A B B0 of the designed lengths, the branch followed by continuity), independent of
// the solver that the library's error curve comes from.
#include "koppel/synthesis/function_synthesis.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace koppel::function_synthesis_test {
namespace {

// [deg] against the value printed to 10 decimals: its last digit
constexpr double kDocumentDeg = 1e-9;
// x of the largest error against the value printed to 5 decimals: its last digit
constexpr double kDocumentX = 1e-5;

// the Chebyshev points from one cosine each, on x ~ 10: a few ulps
constexpr double kChebyshevRoundoff = 1e-12;

constexpr double kExact = 1e-9;       // exact through the precision points: solver precision, far below 1e-9
constexpr double kSameCurve = 1e-9;   // closed form and solver agree on every sample

FunctionRequest Request(std::function<bool(double, double*)> f, double x0, double x1, double in0, double in1, double out0, double out1) {
  FunctionRequest r;
  r.function = std::move(f);
  r.x_from = x0;
  r.x_to = x1;
  r.input_from = DegToRad(in0);
  r.input_to = DegToRad(in1);
  r.output_from = DegToRad(out0);
  r.output_to = DegToRad(out1);
  return r;
}

bool Log10(double x, double* y) {
  if (!(x > 0)) return false;
  *y = std::log10(x);
  return true;
}
bool Square(double x, double* y) {
  *y = x * x;
  return true;
}

// The rocker angle of the designed four-bar at crank angle phi in closed form: the signed local
// x of A on the crank and of B on the rocker, B on the side nearest `previous_b`.
double ClosedFormPsi(const Mechanism& m, double phi, Eigen::Vector2d* previous_b) {
  const double a = m.links[1].points[1].local.x(), b = m.links[2].points[1].local.x(), c = m.links[3].points[1].local.x();
  const Eigen::Vector2d b0 = m.links[0].points[1].local, pa = a * Eigen::Vector2d(std::cos(phi), std::sin(phi));
  const Eigen::Vector2d d = b0 - pa;
  const double r = d.norm(), cos_gamma = (b * b + r * r - c * c) / (2 * b * r);
  REQUIRE(std::abs(cos_gamma) <= 1);
  Eigen::Vector2d best;
  double nearest = 1e300;
  for (int side : {-1, 1}) {
    const double g = std::atan2(d.y(), d.x()) + side * std::acos(cos_gamma);
    const Eigen::Vector2d pb = pa + b * Eigen::Vector2d(std::cos(g), std::sin(g));
    if ((pb - *previous_b).norm() < nearest) {
      nearest = (pb - *previous_b).norm();
      best = pb;
    }
  }
  *previous_b = best;
  const Eigen::Vector2d rocker = (best - b0) / c;  // signed c: the rocker's body x axis
  return std::atan2(rocker.y(), rocker.x());
}

// Golden-section search for the maximum of f over [a, b] (unimodal there), to `tolerance`.
template <class F>
std::pair<double, double> GoldenMaximum(F f, double a, double b, double tolerance) {
  const double g = (std::sqrt(5.0) - 1) / 2;
  double c = b - g * (b - a), d = a + g * (b - a), fc = f(c), fd = f(d);
  while (std::abs(b - a) > tolerance) {
    if (fc > fd) {
      b = d, d = c, fd = fc, c = b - g * (b - a), fc = f(c);
    } else {
      a = c, c = d, fc = fd, d = a + g * (b - a), fd = f(d);
    }
  }
  const double x = (a + b) / 2;
  return {x, f(x)};
}

// The design's error curve and its maximum against the closed form: the rocker angle of the
// designed lengths (triangle A B B0, the branch followed by continuity), the largest |error| of
// the samples refined by golden-section search between the neighbours of each local maximum.
void CheckAgainstClosedForm(const FunctionRequest& r, const FunctionDesign& d) {
  const Mechanism& m = d.mechanism;
  Eigen::Vector2d b = m.hint.points[2].global;
  double y0 = 0, y1 = 0;
  r.function(r.x_from, &y0);
  r.function(r.x_to, &y1);
  auto wanted = [&](double x) {
    double y = 0;
    REQUIRE(r.function(x, &y));
    return r.output_from + (y - y0) / (y1 - y0) * (r.output_to - r.output_from);
  };
  double worst = 0;
  std::vector<double> inputs, xs, errors;
  std::vector<Eigen::Vector2d> bs;
  for (const StructuralErrorSample& e : d.error_curve) {  // in x order = input order here
    const double psi = ClosedFormPsi(m, e.input, &b);
    worst = std::max(worst, std::abs(AngleDifference(psi, e.generated)));
    inputs.push_back(e.input);
    xs.push_back(e.x);
    errors.push_back(std::abs(AngleDifference(psi, wanted(e.x))));
    bs.push_back(b);
  }
  CHECK(worst <= kSameCurve);
  double largest = *std::max_element(errors.begin(), errors.end()), at_x = 0;
  const int n = static_cast<int>(errors.size());
  for (int i = 1; i + 1 < n; ++i) {
    if (errors[i] < errors[i - 1] || errors[i] < errors[i + 1]) continue;
    auto error_at = [&](double input) {
      Eigen::Vector2d near_b = bs[i];
      const double x = r.x_from + (input - r.input_from) / (r.input_to - r.input_from) * (r.x_to - r.x_from);
      return std::abs(AngleDifference(ClosedFormPsi(m, input, &near_b), wanted(x)));
    };
    const auto [input, value] = GoldenMaximum(error_at, std::min(inputs[i - 1], inputs[i + 1]), std::max(inputs[i - 1], inputs[i + 1]), 1e-10);
    if (value > largest) {
      largest = value;
      at_x = r.x_from + (input - r.input_from) / (r.input_to - r.input_from) * (r.x_to - r.x_from);
    }
  }
  // the maximum, not the largest sample (issue 22 item 3)
  CHECK(std::abs(largest - d.error_max) <= kSameCurve);
  CHECK(d.error_max >= *std::max_element(errors.begin(), errors.end()) - kSameCurve);
  if (at_x != 0) CHECK(std::abs(at_x - d.error_max_x) <= 1e-6 * std::abs(r.x_to - r.x_from));
}

bool Sine(double x, double* y) {
  *y = std::sin(x);
  return true;
}

}  // namespace

TEST_CASE("log10 x over 1..10, three Chebyshev points: exact at the points, the error maximum re-evaluated", "[function]") {
  const FunctionRequest r = Request(Log10, 1, 10, 15, 75, 105, 195);
  const FunctionDesign d = SynthesiseFunction(r);
  INFO(d.Brief());
  REQUIRE(d.ok());
  REQUIRE(d.precision_x.size() == 3);
  CHECK(d.error_at_precision <= kExact);
  CHECK(d.error_max > 1e-4);  // three points cannot make log10 exact everywhere
  CHECK(d.error_curve.size() == 361);
  CheckAgainstClosedForm(r, d);
  // the Chebyshev points themselves: x_i = 5.5 - 4.5 cos((2i - 1) pi / 6)
  CHECK_THAT(d.precision_x[0], Catch::Matchers::WithinAbs(5.5 - 4.5 * std::cos(kPi / 6), kChebyshevRoundoff));
  CHECK_THAT(d.precision_x[1], Catch::Matchers::WithinAbs(5.5, kChebyshevRoundoff));
}

TEST_CASE("x^2 over 0..1, three Chebyshev points and points given by `at`", "[function]") {
  FunctionRequest r = Request(Square, 0, 1, 165, 225, 240, 330);
  const FunctionDesign d = SynthesiseFunction(r);
  INFO(d.Brief());
  REQUIRE(d.ok());
  CHECK(d.error_at_precision <= kExact);
  CheckAgainstClosedForm(r, d);
  r.at = {0.1, 0.5, 0.9};
  const FunctionDesign at = SynthesiseFunction(r);
  REQUIRE(at.ok());
  CHECK(at.error_at_precision <= kExact);
  CheckAgainstClosedForm(r, at);
}

TEST_CASE("an exact design whose mechanism runs on another branch is refused, never printed as ok", "[function]") {
  // x^2, crank 30..120 deg, rocker 60..120 deg: Freudenstein's solution needs B on the branch the
  // assembly at the first point does not give; the solver's mechanism misses a point by ~36 deg
  const FunctionDesign d = SynthesiseFunction(Request(Square, 0, 1, 30, 120, 60, 120));
  INFO(d.Brief());
  CHECK(d.status == FunctionStatus::kMissesPoints);
  CHECK(RadToDeg(d.error_at_precision) > 1.0);
  CHECK_THAT(d.message, Catch::Matchers::Contains("different assembly branches"));
}

TEST_CASE("property: every 3-point design called ok passes through its precision points", "[function]") {
  // the proof is the solver's own mechanism at the precision points; a design that is not exact
  // there must carry another status (seeded random ranges, x^2 and log10)
  std::mt19937 rng(20261123);
  std::uniform_real_distribution<double> angle(0, 360), span(30, 120);
  int ok = 0;
  for (int i = 0; i < 200; ++i) {
    const double in0 = angle(rng), out0 = angle(rng);
    const FunctionRequest r = i % 2 ? Request(Square, 0, 1, in0, in0 + span(rng), out0, out0 + span(rng))
                                    : Request(Log10, 1, 10, in0, in0 + span(rng), out0, out0 + span(rng));
    const FunctionDesign d = SynthesiseFunction(r);
    if (!d.ok()) continue;
    ++ok;
    INFO("request " << i << ": " << d.Brief());
    CHECK(d.error_at_precision <= 1e-6 * std::abs(r.output_to - r.output_from));
  }
  CHECK(ok > 0);
}

TEST_CASE("more points: least squares polished through the mechanism does not get worse", "[function]") {
  FunctionRequest r = Request(Log10, 1, 10, 15, 75, 105, 195);
  r.points = 6;
  const FunctionDesign d = SynthesiseFunction(r);
  INFO(d.Brief() << " " << d.polish_report);
  REQUIRE(d.ok());
  CHECK(d.polished);
  CheckAgainstClosedForm(r, d);
  r.points = 3;
  const FunctionDesign three = SynthesiseFunction(r);
  // six points in the least-squares sense spread the error: the maximum stays of the same order
  CHECK(d.error_max < 3 * three.error_max);
}

TEST_CASE("slider-crank: s = x^2 exact at three points", "[function]") {
  FunctionRequest r = Request(Square, 0, 1, 40, 130, 0, 0);
  r.type = FunctionGenerator::kSliderCrank;
  r.output_from = 1.0;
  r.output_to = 2.0;
  const FunctionDesign d = SynthesiseFunction(r);
  INFO(d.Brief());
  REQUIRE(d.ok());
  CHECK(d.error_at_precision <= kExact * 2);
  CHECK(d.error_max > 1e-6);
  // independent: the slider position in closed form, s = a cos phi + sqrt(b^2 - (e - a sin phi)^2) on the branch of the first point
  const Mechanism& m = d.mechanism;
  const double a = m.links[1].points[1].local.x(), b = m.links[2].points[1].local.x(), e = m.links[0].points[1].local.y();
  const double side = m.hint.points[2].global.x() >= a * std::cos(m.hint.input) ? 1 : -1;
  double worst = 0;
  for (const StructuralErrorSample& s : d.error_curve) {
    const double closed = a * std::cos(s.input) + side * std::sqrt(b * b - std::pow(e - a * std::sin(s.input), 2));
    worst = std::max(worst, std::abs(closed - s.generated));
  }
  CHECK(worst <= kSameCurve);
}

// issue 22 item 3: error_max was the largest of the 361 samples (3.04448547268 deg); the maximum
// is 3.0445747805 deg at x = 1.05191 (the closed-form evaluation; here CheckAgainstClosedForm)
TEST_CASE("sin x over 0..1.5, five points: error_max is the maximum between the samples", "[function]") {
  FunctionRequest r = Request(Sine, 0, 1.5, 30, 120, 60, 150);
  r.points = 5;
  const FunctionDesign d = SynthesiseFunction(r);
  INFO(d.Brief());
  REQUIRE(d.ok());
  CheckAgainstClosedForm(r, d);
  CHECK(RadToDeg(d.error_max) == Approx(3.0445747805).margin(kDocumentDeg));
  CHECK(d.error_max_x == Approx(1.05191).margin(kDocumentX));
  double largest_sample = 0;
  for (const StructuralErrorSample& e : d.error_curve) largest_sample = std::max(largest_sample, std::abs(e.error));
  CHECK(RadToDeg(d.error_max - largest_sample) > 1e-5);  // the samples miss the maximum by ~9e-5 deg
}

TEST_CASE("function requests that make no mechanism are refused with a reason", "[function]") {
  FunctionRequest r = Request(Log10, 1, 10, 15, 75, 105, 195);
  r.points = 2;
  CHECK(SynthesiseFunction(r).status == FunctionStatus::kInvalidRequest);
  r.points = 3;
  r.x_from = 0;  // log10 0 undefined
  const FunctionDesign d = SynthesiseFunction(r);
  CHECK(d.status == FunctionStatus::kInvalidRequest);
  CHECK_THAT(d.message, Catch::Contains("defined"));
}

}  // namespace koppel::function_synthesis_test
