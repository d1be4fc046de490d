// The atlas's tracing in plain arithmetic (solver/synthesis/src/atlas_trace.cpp), against
// independent references: its sine and cosine against the C library's std::sin and std::cos, its
// joints against the trigonometric construction it replaced (B at the angle atan2(A -> B0) +-
// acos of the cosine rule, evaluated here with libm), and the build's stored descriptor against
// the descriptor of the public TraceAtlasCurve's points (path synthesis places an entry by
// tracing it again: both must see the same curve).
#include "atlas_trace.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/synthesis/atlas.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace koppel::atlas_trace_test {
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

}  // namespace

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

}  // namespace koppel::atlas_trace_test
