// The atlas's tracing in plain arithmetic (solver/synthesis/src/atlas_curve.cpp), against
// independent references: its sine and cosine against the C library's std::sin and std::cos, its
// joints against the trigonometric construction it replaced (B at the angle atan2(A -> B0) +-
// acos of the cosine rule, evaluated here with libm), and the build's stored descriptor against
// the descriptor of the public TraceAtlasCurve's points (path synthesis places an entry by
// tracing it again: both must see the same curve), and DescribeCurve against the plain
// descriptor it was written as (std::polar in every term, one harmonic after the other): the
// table of twiddles and the side-by-side sums must give the very same bits.
#include "atlas_curve.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/synthesis/atlas.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <random>

namespace koppel::atlas_curve_test {
namespace {

// fdlibm's kernels are within 1 ulp of sin and cos, libm within 1 ulp too: 2 ulp of 1 apart.
constexpr double kSinCosAgreement = 4.5e-16;
// Away from the limit positions the two constructions of B agree to rounding, amplified by the
// cosine rule's 1 / sin(gamma) (gamma the angle at A, at least 0.01 here).
constexpr double kJointAgreement = 1e-11;

// B by the construction the atlas used before (commit 2545f8b): libm's atan2, acos, cos, sin.
Eigen::Vector2d TrigonometricB(double a, double b, double c, double phi, int branch, double* sin_gamma) {
  const Eigen::Vector2d pa = a * Eigen::Vector2d(std::cos(phi), std::sin(phi)), d = Eigen::Vector2d(1, 0) - pa;
  const double r = d.norm(), cos_gamma = std::clamp((b * b + r * r - c * c) / (2 * b * r), -1.0, 1.0);
  *sin_gamma = std::sqrt(1 - cos_gamma * cos_gamma);
  const double gamma = std::atan2(d.y(), d.x()) + branch * std::acos(cos_gamma);
  return pa + b * Eigen::Vector2d(std::cos(gamma), std::sin(gamma));
}

// DescribeCurve as first written (commit 2545f8b): resampled at 64 points of equal arc length,
// each Fourier coefficient summed on its own with std::polar's twiddles.
bool PlainDescriptor(const std::vector<Eigen::Vector2d>& path, CurveDescriptor* d) {
  using Complex = std::complex<double>;
  constexpr int kPoints = 64;
  const int n = static_cast<int>(path.size());
  if (n < 3) return false;
  std::vector<double> s(n + 1, 0.0);
  for (int i = 0; i < n; ++i) s[i + 1] = s[i] + (path[(i + 1) % n] - path[i]).norm();
  const double total = s[n];
  double extent = 0;
  for (const Eigen::Vector2d& p : path) extent = std::max(extent, (p - path[0]).norm());
  if (!(total > 0) || !(extent > 1e-12 * total) || !std::isfinite(total)) return false;
  std::vector<Complex> z(kPoints);
  int seg = 0;
  for (int j = 0; j < kPoints; ++j) {
    const double at = total * j / kPoints;
    while (seg < n - 1 && s[seg + 1] <= at) ++seg;
    const double w = s[seg + 1] > s[seg] ? (at - s[seg]) / (s[seg + 1] - s[seg]) : 0.0;
    const Eigen::Vector2d p = (1 - w) * path[seg] + w * path[(seg + 1) % n];
    z[j] = {p.x(), p.y()};
  }
  std::array<Complex, 2 * kAtlasHarmonics + 1> c{};
  for (int k = -kAtlasHarmonics; k <= kAtlasHarmonics; ++k) {
    Complex sum = 0;
    for (int j = 0; j < kPoints; ++j) sum += z[j] * std::polar(1.0, -2 * kPi * k * j / kPoints);
    c[k + kAtlasHarmonics] = sum / static_cast<double>(kPoints);
  }
  auto at = [&](int k) -> Complex& { return c[k + kAtlasHarmonics]; };
  if (std::abs(at(-1)) > std::abs(at(1))) std::reverse(c.begin(), c.end());
  d->centre = at(0);
  d->scale = std::abs(at(1));
  if (!(d->scale > 1e-12 * total)) return false;
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

bool SameBits(const CurveDescriptor& a, const CurveDescriptor& b) {
  return std::memcmp(a.features.data(), b.features.data(), sizeof a.features) == 0 && a.centre == b.centre && a.scale == b.scale &&
         a.turn == b.turn;
}

}  // namespace

TEST_CASE("DescribeCurve gives the plain descriptor's bits, on random polygons and on atlas curves", "[atlas]") {
  std::mt19937_64 random(5);
  std::normal_distribution<double> normal;
  int differ = 0, described = 0;
  auto compare = [&](const std::vector<Eigen::Vector2d>& path) {
    CurveDescriptor fast, plain;
    const bool ok = DescribeCurve(path, &fast);
    CHECK(ok == PlainDescriptor(path, &plain));
    if (ok) ++described;
    if (ok && !SameBits(fast, plain)) ++differ;
  };
  for (int t = 0; t < 2000; ++t) {
    std::vector<Eigen::Vector2d> path(3 + random() % 600);  // longer than a build's 256 too
    for (Eigen::Vector2d& p : path) p = {normal(random), normal(random)};
    compare(path);
  }
  for (std::uint64_t i = 0; i < 500; ++i) {
    AtlasCurve curve;
    for (int n : {16, 256, 1000}) {
      REQUIRE(TraceAtlasCurve(DrawAtlasEntry(2, i), n, &curve));
      compare(curve.coupler_point);
    }
  }
  compare({{0, 0}, {0, 0}, {0, 0}});  // no extent: refused by both
  CHECK(described > 3000);
  CHECK(differ == 0);
}

TEST_CASE("the atlas's sine and cosine agree with libm's over two turns either way", "[atlas]") {
  double worst = 0;
  for (int i = -400000; i <= 400000; ++i) {
    const double x = 8.0 * i / 400000 + 1e-7 * std::sin(i);  // every quadrant, its boundaries among them
    double s, c;
    AtlasSinCos(x, s, c);
    worst = std::max({worst, std::abs(s - std::sin(x)), std::abs(c - std::cos(x))});
  }
  for (int k = -5; k <= 5; ++k) {  // exactly at the multiples of pi / 2
    double s, c;
    AtlasSinCos(k * kPi / 2, s, c);
    worst = std::max({worst, std::abs(s - std::sin(k * kPi / 2)), std::abs(c - std::cos(k * kPi / 2))});
  }
  CHECK(worst <= kSinCosAgreement);
}

TEST_CASE("the atlas traces the joints the trigonometric construction gives, on both branches", "[atlas]") {
  int compared = 0;
  double worst = 0;
  for (std::uint64_t i = 0; i < 500; ++i) {
    const AtlasEntry e = DrawAtlasEntry(3, i);
    AtlasCurve curve;
    REQUIRE(TraceAtlasCurve(e, 256, &curve));
    for (int k = 0; k < 256; ++k) {
      const double phi = curve.crank_angle[k];
      double sin_gamma;
      const Eigen::Vector2d b = TrigonometricB(e.crank, e.coupler, e.rocker, phi, e.branch, &sin_gamma);
      CHECK((curve.a[k] - e.crank * Eigen::Vector2d(std::cos(phi), std::sin(phi))).norm() <= kJointAgreement);
      if (sin_gamma < 0.01) continue;  // near a limit position: both are rounding amplified (see kJointAgreement)
      worst = std::max(worst, (curve.b[k] - b).norm());
      ++compared;
    }
  }
  CHECK(compared > 100000);
  CHECK(worst <= kJointAgreement);
}

TEST_CASE("an atlas entry's descriptor is the descriptor of TraceAtlasCurve's points, bit for bit", "[atlas]") {
  for (std::uint64_t i = 0; i < 300; ++i) {
    const AtlasEntry e = DrawAtlasEntry(9, i);
    AtlasCurve curve;
    CurveDescriptor d;
    REQUIRE(TraceAtlasCurve(e, 256, &curve));
    REQUIRE(DescribeCurve(curve.coupler_point, &d));
    std::array<float, kAtlasFeatures> features;
    for (int k = 0; k < kAtlasFeatures; ++k) features[k] = static_cast<float>(d.features[k]);
    INFO("entry " << i);
    CHECK(std::memcmp(features.data(), e.descriptor.data(), sizeof features) == 0);
  }
}

}  // namespace koppel::atlas_curve_test
