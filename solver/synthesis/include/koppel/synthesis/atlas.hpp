// An atlas of four-bar coupler curves for path synthesis (path_synthesis.hpp): N four-bars drawn
// from a documented space, each curve stored as a descriptor invariant under position, rotation,
// scale and starting point, with the dimensions that made it.
//
// The space (frame A0 = (0, 0), B0 = (1, 0); every draw from a counter-based generator, so entry
// i of seed S is the same whichever machine, shard or thread draws it):
//   crank a, coupler b, rocker c: log-uniform in [1/5, 5] (Grashof and non-Grashof chains alike);
//   coupler point K = A + p (B - A) + q (B - A)^perp with p uniform in [-1, 2], q in [-1.5, 1.5];
//   the assembly branch (B left or right of A -> B0) and, where the crank angles that close the
//   loop form two intervals, which one: each with probability 1/2.
// A draw whose loop never closes, or whose crank reaches less than 10 deg, is drawn again from
// the same generator. Where the crank turns fully the curve is closed (`closed`); otherwise it is
// the arc the crank drives between its two limit positions on the branch, traced there and back
// (a closed path of zero area: open targets are matched against these).
//
// Descriptor: the curve resampled at 64 points of equal arc length, its Fourier coefficients c_k
// (k = -5..5); c_0 removed (position), divided by |c_1| (scale), traversed so that |c_1| >=
// |c_-1|, and turned and shifted in time so that c_1 and c_-1 are real and positive (rotation and
// starting point). That leaves one ambiguity (turn and shift both by pi: c_k -> (-1)^(k+1) c_k),
// which the query tries both ways. The features are Re and Im of c_k for k != 0, 1.
#pragma once

#include "koppel/core/expected.hpp"

#include <Eigen/Core>

#include <array>
#include <complex>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace koppel {

inline constexpr int kAtlasHarmonics = 5;
inline constexpr int kAtlasFeatures = 2 * (2 * kAtlasHarmonics - 1);  // 18
// Curves one atlas file may hold: 10^9 entries are about 100 GB; a count beyond it is a mistake.
inline constexpr std::uint64_t kMaxAtlasCurves = 1'000'000'000;

struct AtlasEntry {
  std::uint64_t seed = 0, index = 0;       // the draw that made it
  double crank = 0, coupler = 0, rocker = 0;  // a, b, c (frame 1)
  double p = 0, q = 0;                     // coupler point, in units of the coupler AB (see above)
  std::int8_t branch = 1;                  // +1: B left of A -> B0
  std::int8_t side = 1;                    // +1: the crank-angle interval above the frame line (two intervals only)
  std::uint8_t closed = 1;                 // 1: the crank turns fully
  std::array<float, kAtlasFeatures> descriptor{};
};

// The draw of entry `index` from `seed` (deterministic).
AtlasEntry DrawAtlasEntry(std::uint64_t seed, std::uint64_t index);

// The entry's curve: `samples` points over one cycle, with the crank angle [rad] and the joint
// positions of each (frame A0 = 0, B0 = (1, 0)). False when the loop does not close.
struct AtlasCurve {
  std::vector<Eigen::Vector2d> coupler_point, a, b;
  std::vector<double> crank_angle;
};
bool TraceAtlasCurve(const AtlasEntry& entry, int samples, AtlasCurve* curve);

// The normal form of a closed path (see above); false when the path has no extent.
struct CurveDescriptor {
  std::array<double, kAtlasFeatures> features{};
  std::complex<double> centre;  // c_0
  double scale = 0;             // |c_1|
  double turn = 0;              // the rotation that made c_1, c_-1 real [rad]
};
bool DescribeCurve(const std::vector<Eigen::Vector2d>& closed_path, CurveDescriptor* descriptor);
// The same curve with the other choice of the ambiguity (turn + pi).
CurveDescriptor OtherBranchOfAmbiguity(const CurveDescriptor& d);

struct AtlasBuildOptions {
  std::uint64_t count = 0;  // curves of the whole atlas (every shard together)
  std::uint64_t seed = 1;
  int shard = 0, shards = 1;  // this call draws indices [shard count / shards, (shard + 1) count / shards)
  int threads = 0;            // 0: one per core
  bool IsValid(std::string* why) const;
};

// The bytes a build holds at its peak: the shard's entries and the file image written from them.
std::uint64_t AtlasBuildBytes(const AtlasBuildOptions& options);
// Done when AtlasBuildBytes fits in `usable_bytes` (koppel/core/memory.hpp's UsableMemory, named
// by `source`); else the error gives both figures and the way out (shards, merged afterwards).
Outcome CheckAtlasBuildMemory(const AtlasBuildOptions& options, std::uint64_t usable_bytes, const std::string& source);

// The shard's entries in index order (the same numbers on any number of threads). `progress`,
// when given, is called now and then from the calling thread with the fraction done (0..1).
std::vector<AtlasEntry> BuildAtlas(const AtlasBuildOptions& options, const std::function<void(double)>& progress = {});

// The atlas file (writing, reading, its checksums) is atlas_file.hpp.

// The union of atlases, ordered by (seed, index); an error when an entry appears twice (a shard
// merged twice).
Expected<std::vector<AtlasEntry>> MergeAtlases(std::vector<std::vector<AtlasEntry>> parts);

}  // namespace koppel
