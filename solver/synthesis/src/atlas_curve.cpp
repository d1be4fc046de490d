#include "atlas_curve.hpp"

#include "koppel/core/angles.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <complex>
#include <cstdint>
#include <vector>

namespace koppel {

// |A - B0|^2 = a^2 + 1 - 2 a cos(phi) must lie in [(b - c)^2, (b + c)^2].
AtlasCrankRange AtlasCrankAngles(double a, double b, double c, int side) {
  AtlasCrankRange f;
  const double cmin = (a * a + 1 - (b + c) * (b + c)) / (2 * a), cmax = (a * a + 1 - (b - c) * (b - c)) / (2 * a);
  if (cmin > cmax || cmin > 1 || cmax < -1) return f;
  f.any = true;
  if (cmin <= -1 && cmax >= 1) {
    f.full = true;
    f.lo = 0;
    f.hi = 2 * kPi;
  } else if (cmin > -1 && cmax < 1) {  // two intervals, mirror images in the frame line
    f.lo = std::acos(cmax);
    f.hi = std::acos(cmin);
    if (side < 0) {
      f.lo = -std::acos(cmin);
      f.hi = -std::acos(cmax);
    }
  } else if (cmin <= -1) {  // one interval through pi
    f.lo = std::acos(cmax);
    f.hi = 2 * kPi - f.lo;
  } else {  // one interval through 0
    f.hi = std::acos(cmin);
    f.lo = -f.hi;
  }
  return f;
}

namespace {

// sin and cos of |x| <= 8 (a crank angle in [-2 pi, 2 pi]) to within an ulp or two, in plain
// arithmetic without branches, so that the compiler vectorises the loops below: the reduction
// by pi/2 in two parts (Cody and Waite; n pi/2 exact in the first; n rounded by the 1.5 2^52
// shifter, whose low bits are then n mod 4) and fdlibm's kernels __kernel_sin and __kernel_cos
// (Sun Microsystems 1993, minimax on |r| <= pi/4, error below 2^-58). The same numbers on every
// machine and C library, and several times faster than libm's sincos, which the atlas called 512
// times a curve.
constexpr double kPio2Hi = 1.57079632673412561417e+00;  // the first 33 bits of pi/2
constexpr double kPio2Lo = 6.07710050650619224932e-11;  // pi/2 - kPio2Hi
constexpr double kShifter = 0x1.8p52;
inline void SinCosOfCrank(double x, double& sine, double& cosine) {
  const double shifted = x * (2 / kPi) + kShifter, n = shifted - kShifter;
  const std::uint64_t quadrant = std::bit_cast<std::uint64_t>(shifted);  // n mod 4 in the low bits
  const double r = (x - n * kPio2Hi) - n * kPio2Lo, z = r * r;
  const double sr = 8.33333333332248946124e-03 +
                    z * (-1.98412698298579493134e-04 + z * (2.75573137070700676789e-06 + z * (-2.50507602534068634195e-08 + z * 1.58969099521155010221e-10)));
  const double s = r + z * r * (-1.66666666666666324348e-01 + z * sr);
  const double cr = z * (4.16666666666666019037e-02 +
                         z * (-1.38888888888741095749e-03 +
                              z * (2.48015872894767294178e-05 + z * (-2.75573143513906633035e-07 + z * (2.08757232129817482790e-09 + z * -1.13596475577881948265e-11)))));
  const double hz = 0.5 * z, w = 1.0 - hz;
  const double c = w + (((1.0 - w) - hz) + z * cr);
  // quadrant 0: (s, c); 1: (c, -s); 2: (-s, -c); 3: (-c, s)
  // in bits, without a branch: swap where the quadrant is odd, then flip the signs
  const std::uint64_t swap = 0 - (quadrant & 1), s_bits = std::bit_cast<std::uint64_t>(s), c_bits = std::bit_cast<std::uint64_t>(c);
  const std::uint64_t sv = (s_bits & ~swap) | (c_bits & swap), cv = (c_bits & ~swap) | (s_bits & swap);
  sine = std::bit_cast<double>(sv ^ ((quadrant & 2) << 62));
  cosine = std::bit_cast<double>(cv ^ (((quadrant + 1) & 2) << 62));
}

}  // namespace

void AtlasSinCos(double x, double& sine, double& cosine) { SinCosOfCrank(x, sine, cosine); }

bool TraceAtlasSamples(const AtlasEntry& e, const AtlasCrankRange& f, int first, int count, int n, AtlasTraceBlock* t) {
  if (f.full) {
    for (int i = 0; i < count; ++i) t->phi[i] = 2 * kPi * (first + i) / n;
  } else {
    const double mid = 0.5 * (f.lo + f.hi), half = 0.5 * (f.hi - f.lo);
    for (int i = 0; i < count; ++i) {
      double sine, cosine;
      SinCosOfCrank(2 * kPi * (first + i) / n, sine, cosine);
      t->phi[i] = mid - half * cosine;
    }
  }
  const double a = e.crank, b = e.coupler, p = e.p, q = e.q, branch = e.branch;
  const double bb_cc = b * b - e.rocker * e.rocker, inv_2b = 1 / (2 * b);
  double open = 0;  // samples where the loop does not close (NaN among them), counted in doubles: it vectorises
  for (int i = 0; i < count; ++i) {
    double sine, cosine;
    SinCosOfCrank(t->phi[i], sine, cosine);
    const double ax = a * cosine, ay = a * sine;
    const double dx = 1 - ax, dy = -ay;  // A -> B0
    const double r2 = dx * dx + dy * dy, inv_r = 1 / std::sqrt(r2);
    double cos_gamma = (bb_cc + r2) * inv_r * inv_2b;
    open += std::abs(cos_gamma) <= 1 + 1e-9 ? 0.0 : 1.0;
    // clamped to [-1, 1] without a branch (the loop vectorises): |cos gamma| at most 1, its sign kept
    const double size = std::abs(cos_gamma);
    cos_gamma = std::copysign(size < 1.0 ? size : 1.0, cos_gamma);
    const double sin_gamma = branch * std::sqrt((1 - cos_gamma) * (1 + cos_gamma));
    const double ux = dx * inv_r, uy = dy * inv_r;
    const double abx = b * (ux * cos_gamma - uy * sin_gamma), aby = b * (uy * cos_gamma + ux * sin_gamma);
    t->ax[i] = ax;
    t->ay[i] = ay;
    t->bx[i] = ax + abx;
    t->by[i] = ay + aby;
    t->kx[i] = ax + p * abx - q * aby;  // A + p AB + q AB^perp
    t->ky[i] = ay + p * aby + q * abx;
  }
  return open == 0;
}

namespace {

using Complex = std::complex<double>;
constexpr int kResample = 64;  // points of equal arc length the descriptor is taken from
constexpr int kHarmonicCount = 2 * kAtlasHarmonics + 1;

// e^{-2 pi i k j / kResample} at [j][k + K] for j = 0..kResample-1, k = -K..K: the very numbers
// std::polar gave in the sum (made once, the same expression), 704 sines and cosines a curve fewer.
using Twiddles = std::array<std::array<Complex, kHarmonicCount>, kResample>;
const Twiddles& FourierTwiddles() {
  static const Twiddles table = [] {
    Twiddles t;
    for (int k = -kAtlasHarmonics; k <= kAtlasHarmonics; ++k) {
      for (int j = 0; j < kResample; ++j) t[j][k + kAtlasHarmonics] = std::polar(1.0, -2 * kPi * k * j / kResample);
    }
    return t;
  }();
  return table;
}

// The closed polygon path[0..n) resampled at kResample points of equal arc length, starting at
// path[0]; false when it has no length or no extent. *total_length: its length.
bool ResampleClosed(const Eigen::Vector2d* path, int n, std::array<Complex, kResample>* z, double* total_length) {
  std::array<double, kAtlasTraceBlock + 1> s_small;  // the build's curves need no allocation
  std::vector<double> s_large;
  double* s = s_small.data();
  if (n > kAtlasTraceBlock) {
    s_large.resize(n + 1);
    s = s_large.data();
  }
  // the sides' lengths first (a loop that vectorises), then their running sum
  for (int i = 0; i + 1 < n; ++i) s[i + 1] = (path[i + 1] - path[i]).norm();
  s[n] = (path[0] - path[n - 1]).norm();
  s[0] = 0.0;
  for (int i = 0; i < n; ++i) s[i + 1] += s[i];
  const double total = s[n];
  // the largest distance from the first point: sqrt is monotonic and correctly rounded, so the
  // root of the largest square is the largest root
  double extent2 = 0;
  for (int i = 0; i < n; ++i) {
    const double e2 = (path[i] - path[0]).squaredNorm();
    extent2 = e2 > extent2 ? e2 : extent2;
  }
  const double extent = std::sqrt(extent2);
  if (!(total > 0) || !(extent > 1e-12 * total) || !std::isfinite(total)) return false;
  int seg = 0;
  for (int j = 0; j < kResample; ++j) {
    const double at = total * j / kResample;
    while (seg < n - 1 && s[seg + 1] <= at) ++seg;
    const double w = s[seg + 1] > s[seg] ? (at - s[seg]) / (s[seg + 1] - s[seg]) : 0.0;
    const Eigen::Vector2d p = (1 - w) * path[seg] + w * path[seg + 1 < n ? seg + 1 : 0];
    (*z)[j] = {p.x(), p.y()};
  }
  *total_length = total;
  return true;
}

}  // namespace

bool DescribeAtlasPath(const Eigen::Vector2d* path, int n, CurveDescriptor* d) {
  if (n < 3) return false;
  std::array<Complex, kResample> z;
  double total = 0;
  if (!ResampleClosed(path, n, &z, &total)) return false;
  // c_k = sum_j z_j w_kj / kResample, each sum in the order of j as before, but the 11 sums side
  // by side (independent chains the processor overlaps); the products written out as
  // std::complex forms them for finite numbers, (ac - bd) + (ad + bc) i
  const Twiddles& twiddles = FourierTwiddles();
  std::array<double, kHarmonicCount> re{}, im{};
  for (int j = 0; j < kResample; ++j) {
    const double zr = z[j].real(), zi = z[j].imag();
    for (int k = 0; k < kHarmonicCount; ++k) {
      const double wr = twiddles[j][k].real(), wi = twiddles[j][k].imag();
      re[k] += zr * wr - zi * wi;
      im[k] += zr * wi + zi * wr;
    }
  }
  std::array<Complex, kHarmonicCount> c{};  // c[k + K] = c_k
  for (int k = 0; k < kHarmonicCount; ++k) c[k] = Complex(re[k], im[k]) / static_cast<double>(kResample);
  auto at = [&](int k) -> Complex& { return c[k + kAtlasHarmonics]; };
  // traverse so that |c_1| >= |c_-1| (reversing time swaps c_k and c_-k)
  if (std::abs(at(-1)) > std::abs(at(1))) std::reverse(c.begin(), c.end());
  d->centre = at(0);
  d->scale = std::abs(at(1));
  if (!(d->scale > 1e-12 * total)) return false;
  // turn by alpha and shift time by tau: c_k -> c_k e^{i(alpha + k tau)}; c_1 and c_-1 real
  const double alpha = -0.5 * (std::arg(at(1)) + std::arg(at(-1))), tau = -0.5 * (std::arg(at(1)) - std::arg(at(-1)));
  d->turn = alpha;
  int f = 0;
  for (int k = -kAtlasHarmonics; k <= kAtlasHarmonics; ++k) {
    if (k == 0 || k == 1) continue;
    const Complex v = at(k) * std::polar(1.0, alpha + k * tau) / d->scale;
    d->features[f++] = v.real();
    d->features[f++] = v.imag();
  }
  return true;
}

}  // namespace koppel
