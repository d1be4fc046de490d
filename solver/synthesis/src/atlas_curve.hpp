// An atlas entry's curve (atlas.cpp): the four-bar's coupler curve traced, and a closed path
// described. Private to synthesis. Compiled on its own with -fno-math-errno (CMakeLists.txt), so
// that its loops vectorise: std::sqrt need not call the C library to set errno for a negative
// argument, which none of these can be (the numbers are those of IEEE sqrt either way).
#pragma once

#include "koppel/synthesis/atlas.hpp"

namespace koppel {

// The crank angles at which the loop closes: [lo, hi] (hi - lo < 2 pi) or the full turn.
struct AtlasCrankRange {
  bool any = false, full = false;
  double lo = 0, hi = 0;
};
// Crank a, coupler b, rocker c (frame 1); side: which of two intervals (atlas.hpp).
AtlasCrankRange AtlasCrankAngles(double a, double b, double c, int side);

// Samples [first, first + count) of a curve of n samples, count <= kAtlasTraceBlock, in arrays.
inline constexpr int kAtlasTraceBlock = 256;
struct AtlasTraceBlock {
  alignas(64) double phi[kAtlasTraceBlock], ax[kAtlasTraceBlock], ay[kAtlasTraceBlock], bx[kAtlasTraceBlock], by[kAtlasTraceBlock],
      kx[kAtlasTraceBlock], ky[kAtlasTraceBlock];
};

// The crank angles phi, joints A and B and coupler points K of the samples: a full turn,
// phi = t; an interval, there and back, phi = mid - half cos t (smooth at the limits);
// t = 2 pi i / n. B - A is the unit vector from A to B0 turned by the triangle's angle gamma at A
// (cos gamma from the cosine rule, sin gamma >= 0 from it, the sign from the branch), clamped at
// the limit positions, where rounding may leave |cos gamma| a few ulps above 1. In plain
// arithmetic (no libm call): the same numbers on every machine and C library. False when the
// loop does not close at a sample.
bool TraceAtlasSamples(const AtlasEntry& e, const AtlasCrankRange& range, int first, int count, int n, AtlasTraceBlock* t);

// DescribeCurve (atlas.hpp) of the closed path path[0..n).
bool DescribeAtlasPath(const Eigen::Vector2d* path, int n, CurveDescriptor* descriptor);

// sin and cos of |x| <= 8 to within an ulp or two (TraceAtlasSamples' own, tested against libm).
void AtlasSinCos(double x, double& sine, double& cosine);

}  // namespace koppel
