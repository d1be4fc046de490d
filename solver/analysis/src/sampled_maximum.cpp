#include "koppel/analysis/sampled_maximum.hpp"

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>

namespace koppel {
namespace {

// Brent to half the mantissa in the input: the value at a smooth maximum is then exact to
// roundoff (its error is second order in the input's).
constexpr int kBits = std::numeric_limits<double>::digits / 2;
// Iterations of one bracket: Brent needs about 40 for kBits from a bracket of one or two steps.
constexpr std::uintmax_t kMaxIterations = 100;

}  // namespace

SampledMaximum RefineSampledMaximum(const std::vector<double>& inputs, const std::vector<double>& values,
                                    const std::function<std::optional<double>(double)>& evaluate) {
  SampledMaximum best;
  const int n = static_cast<int>(std::min(inputs.size(), values.size()));
  if (n == 0) {
    best.message = "no samples";
    return best;
  }
  const int largest = static_cast<int>(std::max_element(values.begin(), values.begin() + n) - values.begin());
  best = {true, "", inputs[largest], values[largest]};
  for (int i = 0; i < n; ++i) {
    const bool left_lower = i == 0 || values[i - 1] <= values[i], right_lower = i + 1 == n || values[i + 1] <= values[i];
    if (!left_lower || !right_lower || n == 1) continue;
    const double a = inputs[std::max(i - 1, 0)], b = inputs[std::min(i + 1, n - 1)];
    bool failed = false;
    // Brent minimises: the negated function, a failed evaluation counting as no maximum there
    auto negated = [&](double x) {
      const std::optional<double> v = evaluate(x);
      if (!v) failed = true;
      return v ? -*v : std::numeric_limits<double>::infinity();
    };
    std::uintmax_t iterations = kMaxIterations;
    const std::pair<double, double> found = boost::math::tools::brent_find_minima(negated, std::min(a, b), std::max(a, b), kBits, iterations);
    if (failed) {
      best.ok = false;
      best.message = "the function cannot be evaluated between the samples at " + std::to_string(a) + " and " + std::to_string(b);
      return best;
    }
    if (-found.second > best.value) best = {true, "", found.first, -found.second};
  }
  return best;
}

}  // namespace koppel
