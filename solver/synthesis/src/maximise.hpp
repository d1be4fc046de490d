// One-dimensional search over a family of designs: where the family is admissible, and where
// a score (mu_min) is largest. Private to the dead-centre synthesis.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

namespace koppel {

// score(x): the score of the design at x, nullopt where there is no admissible design.
using DesignScore = std::function<std::optional<double>(double)>;

struct GridMaximum {
  double x = 0, value = 0;
  // the admissible stretch around x: its grid samples' ends, and whether it reaches the grid's ends
  double run_first = 0, run_last = 0;
  double before_run = 0, after_run = 0;  // the inadmissible samples next to it (if any)
  bool run_starts_at_lo = false, run_ends_at_hi = false;
};

// Scans `samples` + 1 points of [lo, hi], then golden section between the best sample's
// neighbours, down to `x_tolerance`. nullopt when no sample is admissible.
inline std::optional<GridMaximum> MaximiseOnGrid(const DesignScore& score, double lo, double hi, int samples, double x_tolerance) {
  GridMaximum m;
  std::vector<std::optional<double>> values(samples + 1);
  auto at = [&](int k) { return lo + (hi - lo) * k / samples; };
  int best = -1;
  for (int k = 0; k <= samples; ++k) {
    values[k] = score(at(k));
    if (values[k] && (best < 0 || *values[k] > *values[best])) best = k;
  }
  if (best < 0) return std::nullopt;
  int first = best, last = best;
  while (first > 0 && values[first - 1]) --first;
  while (last < samples && values[last + 1]) ++last;
  m.run_first = at(first);
  m.run_last = at(last);
  m.run_starts_at_lo = first == 0;
  m.run_ends_at_hi = last == samples;
  m.before_run = at(std::max(first - 1, 0));
  m.after_run = at(std::min(last + 1, samples));
  auto f = [&](double x) {
    const std::optional<double> v = score(x);
    return v ? *v : -1e300;
  };
  double a = at(std::max(best - 1, 0)), b = at(std::min(best + 1, samples));
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double c = b - g * (b - a), d = a + g * (b - a), fc = f(c), fd = f(d);
  while (b - a > x_tolerance) {
    if (fc >= fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - g * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + g * (b - a);
      fd = f(d);
    }
  }
  const double x = 0.5 * (a + b), fx = f(x);
  if (fx >= *values[best]) {
    m.x = x;
    m.value = fx;
  } else {
    m.x = at(best);
    m.value = *values[best];
  }
  return m;
}

// The edge of the admissible set between x_in (admissible) and x_out (not), by bisection.
inline double AdmissibleEdge(const DesignScore& score, double x_in, double x_out) {
  for (int i = 0; i < 200 && x_in != x_out; ++i) {
    const double mid = 0.5 * (x_in + x_out);
    if (mid == x_in || mid == x_out) break;
    (score(mid) ? x_in : x_out) = mid;
  }
  return x_in;
}

}  // namespace koppel
