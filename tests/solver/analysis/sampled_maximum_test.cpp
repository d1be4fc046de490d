// RefineSampledMaximum (sampled_maximum.hpp) on functions whose maximum is known in closed form.
#include "koppel/analysis/sampled_maximum.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::sampled_maximum_test {
namespace {

// Brent's last point lies within its own input tolerance of the range end; the value there, of
// slope O(1), within 1e-7
constexpr double kBrentEnd = 1e-7;

// Brent to half the mantissa in the input: the value at a smooth maximum exact to roundoff.
constexpr double kValue = 1e-15;
constexpr double kInput = 1e-7;

struct Samples {
  std::vector<double> inputs, values;
};

template <class F>
Samples Sample(F f, double from, double to, int n) {
  Samples s;
  for (int i = 0; i < n; ++i) {
    s.inputs.push_back(from + (to - from) * i / (n - 1));
    s.values.push_back(f(s.inputs.back()));
  }
  return s;
}

}  // namespace

TEST_CASE("the maximum between samples: sin x has 1 at pi/2", "[sampled]") {
  auto f = [](double x) { return std::sin(x); };
  for (const auto& [from, to] : {std::pair{0.1, 3.0}, std::pair{3.0, 0.1}}) {  // either order
    const Samples s = Sample(f, from, to, 8);  // no sample at pi/2
    const SampledMaximum m = RefineSampledMaximum(s.inputs, s.values, [&](double x) -> std::optional<double> { return f(x); });
    REQUIRE(m.ok);
    CHECK(std::abs(m.value - 1) < kValue);
    CHECK(std::abs(m.input - kPi / 2) < kInput);
  }
}

TEST_CASE("a maximum at the end of the samples stays there; two local maxima: the larger", "[sampled]") {
  auto rising = [](double x) { return x * x; };
  const Samples s = Sample(rising, 0, 1, 5);
  const SampledMaximum m = RefineSampledMaximum(s.inputs, s.values, [&](double x) -> std::optional<double> { return rising(x); });
  REQUIRE(m.ok);
  CHECK(m.value == Approx(1).margin(kBrentEnd));  // Brent's last point within its tolerance of the end
  CHECK(m.value <= 1);
  // |sin 3x| e^(-x/10) over 0..3: the first hump is the highest, at x = (atan(30) / 3)
  auto humps = [](double x) { return std::abs(std::sin(3 * x)) * std::exp(-x / 10); };
  const Samples h = Sample(humps, 0, 3, 31);
  const SampledMaximum top = RefineSampledMaximum(h.inputs, h.values, [&](double x) -> std::optional<double> { return humps(x); });
  REQUIRE(top.ok);
  CHECK(std::abs(top.input - std::atan(30.0) / 3) < kInput);
  CHECK(std::abs(top.value - humps(std::atan(30.0) / 3)) < kValue);
}

TEST_CASE("a function that cannot be evaluated in a bracket gives no maximum", "[sampled]") {
  const Samples s = Sample([](double x) { return std::sin(x); }, 0.1, 3.0, 8);
  const SampledMaximum m = RefineSampledMaximum(s.inputs, s.values, [](double) -> std::optional<double> { return std::nullopt; });
  CHECK_FALSE(m.ok);
  CHECK_THAT(m.message, Catch::Contains("cannot be evaluated"));
  CHECK_FALSE(RefineSampledMaximum({}, {}, [](double) -> std::optional<double> { return 0.0; }).ok);
}

}  // namespace koppel::sampled_maximum_test
