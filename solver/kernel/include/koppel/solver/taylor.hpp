// Truncated Taylor series in one variable t: x(t) = c[0] + c[1] t + ... + c[N] t^N.
// Residuals and outputs are templated on their scalar, so evaluating them on Taylor<N>
// coefficients of the coordinates q(t) gives the series of the residual, from which the
// transfer functions of any order follow exactly (no differencing). Fixed size: no heap.
#pragma once

#include "koppel/core/angles.hpp"

#include <array>
#include <cmath>

namespace koppel {

template <int N>
struct Taylor {
  static_assert(N >= 0);
  std::array<double, N + 1> c{};

  Taylor() = default;
  Taylor(double value) { c[0] = value; }  // NOLINT: a constant is a series

  Taylor& operator+=(const Taylor& o) { for (int k = 0; k <= N; ++k) c[k] += o.c[k]; return *this; }
  Taylor& operator-=(const Taylor& o) { for (int k = 0; k <= N; ++k) c[k] -= o.c[k]; return *this; }
};

template <int N> Taylor<N> operator+(Taylor<N> a, const Taylor<N>& b) { return a += b; }
template <int N> Taylor<N> operator-(Taylor<N> a, const Taylor<N>& b) { return a -= b; }
template <int N> Taylor<N> operator-(Taylor<N> a) { for (double& x : a.c) x = -x; return a; }
template <int N> Taylor<N> operator+(Taylor<N> a, double b) { a.c[0] += b; return a; }
template <int N> Taylor<N> operator-(Taylor<N> a, double b) { a.c[0] -= b; return a; }
template <int N> Taylor<N> operator*(Taylor<N> a, double b) { for (double& x : a.c) x *= b; return a; }
template <int N> Taylor<N> operator*(double b, Taylor<N> a) { return a * b; }

// Cauchy product.
template <int N>
Taylor<N> operator*(const Taylor<N>& a, const Taylor<N>& b) {
  Taylor<N> r;
  for (int k = 0; k <= N; ++k) {
    double s = 0.0;
    for (int j = 0; j <= k; ++j) s += a.c[j] * b.c[k - j];
    r.c[k] = s;
  }
  return r;
}

// r = a / b from a = r b, solved coefficient by coefficient; requires b.c[0] != 0.
template <int N>
Taylor<N> operator/(const Taylor<N>& a, const Taylor<N>& b) {
  Taylor<N> r;
  for (int k = 0; k <= N; ++k) {
    double s = a.c[k];
    for (int j = 1; j <= k; ++j) s -= b.c[j] * r.c[k - j];
    r.c[k] = s / b.c[0];
  }
  return r;
}

inline void SinCos(double u, double& s, double& c) { s = std::sin(u); c = std::cos(u); }  // one sincos call

// sin and cos of a series whose constant term's sin and cos are known (s0, c0): the
// coefficient recurrences s' = c u', c' = -s u'.
template <int N>
void SinCos(const Taylor<N>& u, double s0, double c0, Taylor<N>& s, Taylor<N>& c) {
  s.c[0] = s0;
  c.c[0] = c0;
  for (int k = 1; k <= N; ++k) {
    double ss = 0.0, cc = 0.0;
    for (int j = 1; j <= k; ++j) {
      ss += j * u.c[j] * c.c[k - j];
      cc -= j * u.c[j] * s.c[k - j];
    }
    s.c[k] = ss / k;
    c.c[k] = cc / k;
  }
}
// sin and cos together.
template <int N>
void SinCos(const Taylor<N>& u, Taylor<N>& s, Taylor<N>& c) {
  double s0, c0;
  SinCos(u.c[0], s0, c0);
  SinCos(u, s0, c0, s, c);
}
template <int N> Taylor<N> sin(const Taylor<N>& u) { Taylor<N> s, c; SinCos(u, s, c); return s; }
template <int N> Taylor<N> cos(const Taylor<N>& u) { Taylor<N> s, c; SinCos(u, s, c); return c; }

// r = sqrt(a) from r*r = a; requires a.c[0] > 0.
template <int N>
Taylor<N> sqrt(const Taylor<N>& a) {
  Taylor<N> r;
  r.c[0] = std::sqrt(a.c[0]);
  for (int k = 1; k <= N; ++k) {
    double s = a.c[k];
    for (int j = 1; j < k; ++j) s -= r.c[j] * r.c[k - j];
    r.c[k] = s / (2.0 * r.c[0]);
  }
  return r;
}

// Integral of a series with a given constant term: the tool for functions known by their
// derivative (atan2).
template <int N>
Taylor<N> IntegrateWithConstant(const Taylor<N>& derivative, double constant) {
  Taylor<N> r;
  r.c[0] = constant;
  for (int k = 1; k <= N; ++k) r.c[k] = derivative.c[k - 1] / k;
  return r;
}

// The derivative series d/dt, truncated (its top coefficient is zero).
template <int N>
Taylor<N> Derivative(const Taylor<N>& a) {
  Taylor<N> r;
  for (int k = 0; k < N; ++k) r.c[k] = (k + 1) * a.c[k + 1];
  return r;
}

// atan2(y, x): theta' = (x y' - y x') / (x^2 + y^2); requires (x, y) != 0.
template <int N>
Taylor<N> atan2(const Taylor<N>& y, const Taylor<N>& x) {
  const Taylor<N> rate = (x * Derivative(y) - y * Derivative(x)) / (x * x + y * y);
  return IntegrateWithConstant(rate, std::atan2(y.c[0], x.c[0]));
}

// Scalar access so that templated code can branch on the value (wrap, signs).
inline double Value(double x) { return x; }
template <int N> double Value(const Taylor<N>& x) { return x.c[0]; }

// Folds the value into [-pi, pi] by a whole number of turns; higher coefficients are untouched
// because a constant shift does not change derivatives.
// The shortcuts give remainder's numbers: inside [-pi, pi] it returns x itself, and for
// pi < |x| < 3 pi it returns x -+ 2 pi, which is exact there (Sterbenz: x and 2 pi lie within a
// factor of 2). One turn off is the common case (an angle row after the crank's first turn).
inline double WrapAngle(double x) {
  const double a = std::abs(x);
  if (a <= kPi) return x;
  if (a < 3.0 * kPi) return x > 0.0 ? x - 2.0 * kPi : x + 2.0 * kPi;
  return std::remainder(x, 2.0 * kPi);
}
template <int N>
Taylor<N> WrapAngle(Taylor<N> x) {
  x.c[0] = WrapAngle(x.c[0]);
  return x;
}

}  // namespace koppel
