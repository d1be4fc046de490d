#include "koppel/synthesis/atlas.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/core/memory.hpp"
#include "koppel/synthesis/atlas_file.hpp"
#include "atlas_curve.hpp"
#include "koppel/core/worker_threads.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <thread>

namespace koppel {
namespace {

constexpr int kTraceSamples = 256;  // points of a curve for its descriptor
constexpr double kLogLength = 1.6094379124341003;  // log 5: lengths in [1/5, 5]
constexpr double kShortestArc = kPi / 18;  // 10 deg of crank travel at least


// SplitMix64 (Steele, Lea, Flood 2014): a counter-based seed for entry `index`, so that any
// shard or thread draws the same entry.
std::uint64_t Mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Uniform in [0, 1) from the top 53 bits (the same on every standard library).
struct Draw {
  std::uint64_t state;
  double Next() {
    state = Mix(state);
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  }
};

// The coupler points of n <= kAtlasTraceBlock samples (TraceAtlasCurve without the joints, into `k`).
bool TraceCouplerPoints(const AtlasEntry& e, const AtlasCrankRange& f, int n, Eigen::Vector2d* k) {
  AtlasTraceBlock t;
  if (!TraceAtlasSamples(e, f, 0, n, n, &t)) return false;
  for (int i = 0; i < n; ++i) k[i] = Eigen::Vector2d(t.kx[i], t.ky[i]);
  return true;
}

}  // namespace

AtlasEntry DrawAtlasEntry(std::uint64_t seed, std::uint64_t index) {
  Draw draw{Mix(seed) ^ Mix(index + 0x632be59bd9b4e019ULL)};
  std::array<Eigen::Vector2d, kTraceSamples> curve;  // on the stack: a build allocates nothing per curve
  for (;;) {
    AtlasEntry e;
    e.seed = seed;
    e.index = index;
    e.crank = std::exp(kLogLength * (2 * draw.Next() - 1));
    e.coupler = std::exp(kLogLength * (2 * draw.Next() - 1));
    e.rocker = std::exp(kLogLength * (2 * draw.Next() - 1));
    e.p = -1 + 3 * draw.Next();
    e.q = -1.5 + 3 * draw.Next();
    e.branch = draw.Next() < 0.5 ? 1 : -1;
    e.side = draw.Next() < 0.5 ? 1 : -1;
    const AtlasCrankRange f = AtlasCrankAngles(e.crank, e.coupler, e.rocker, e.side);
    if (!f.any || f.hi - f.lo < kShortestArc) continue;
    e.closed = f.full ? 1 : 0;
    CurveDescriptor d;
    if (!TraceCouplerPoints(e, f, kTraceSamples, curve.data()) || !DescribeAtlasPath(curve.data(), kTraceSamples, &d)) continue;
    for (int k = 0; k < kAtlasFeatures; ++k) e.descriptor[k] = static_cast<float>(d.features[k]);
    return e;
  }
}

bool TraceAtlasCurve(const AtlasEntry& e, int samples, AtlasCurve* curve) {
  const AtlasCrankRange f = AtlasCrankAngles(e.crank, e.coupler, e.rocker, e.side);
  if (!f.any || samples < 3) return false;
  curve->coupler_point.resize(samples);
  curve->a.resize(samples);
  curve->b.resize(samples);
  curve->crank_angle.resize(samples);
  AtlasTraceBlock t;  // the same points as the build's TraceCouplerPoints, a block at a time
  for (int first = 0; first < samples; first += kAtlasTraceBlock) {
    const int count = std::min(kAtlasTraceBlock, samples - first);
    if (!TraceAtlasSamples(e, f, first, count, samples, &t)) return false;
    for (int i = 0; i < count; ++i) {
      curve->crank_angle[first + i] = t.phi[i];
      curve->a[first + i] = Eigen::Vector2d(t.ax[i], t.ay[i]);
      curve->b[first + i] = Eigen::Vector2d(t.bx[i], t.by[i]);
      curve->coupler_point[first + i] = Eigen::Vector2d(t.kx[i], t.ky[i]);
    }
  }
  return true;
}

bool DescribeCurve(const std::vector<Eigen::Vector2d>& path, CurveDescriptor* d) {
  return DescribeAtlasPath(path.data(), static_cast<int>(path.size()), d);
}

CurveDescriptor OtherBranchOfAmbiguity(const CurveDescriptor& d) {
  CurveDescriptor o = d;
  o.turn = d.turn + kPi;
  int f = 0;
  for (int k = -kAtlasHarmonics; k <= kAtlasHarmonics; ++k) {
    if (k == 0 || k == 1) continue;
    const double sign = (k + 1) % 2 == 0 ? 1.0 : -1.0;  // e^{i pi (k + 1)}
    o.features[f] *= sign;
    o.features[f + 1] *= sign;
    f += 2;
  }
  return o;
}

bool AtlasBuildOptions::IsValid(std::string* why) const {
  std::string problem;
  if (count < 1 || count > kMaxAtlasCurves) problem = fmt::format("count must be between 1 and {}", kMaxAtlasCurves);
  else if (shards < 1 || shard < 0 || shard >= shards) problem = "the shard k/n needs 0 <= k < n";
  else if (static_cast<std::uint64_t>(shards) > count) problem = "more shards than curves";
  else if (threads < 0 || threads > kMaxThreads)
    problem = "threads must be 0 (one per core) to " + std::to_string(kMaxThreads) + " (kMaxThreads)";
  if (why) *why = problem;
  return problem.empty();
}

namespace {

// Indices [first, last) of the options' shard: every index in exactly one shard.
std::pair<std::uint64_t, std::uint64_t> ShardRange(const AtlasBuildOptions& o) {
  const auto bound = [&](int k) { return static_cast<std::uint64_t>((static_cast<unsigned __int128>(o.count) * k) / o.shards); };
  return {bound(o.shard), bound(o.shard + 1)};
}

}  // namespace

std::uint64_t AtlasBuildBytes(const AtlasBuildOptions& o) {
  const auto [first, last] = ShardRange(o);
  return (last - first) * sizeof(AtlasEntry) + AtlasFileSize(last - first);
}

Outcome CheckAtlasBuildMemory(const AtlasBuildOptions& o, std::uint64_t usable_bytes, const std::string& source) {
  const std::uint64_t needed = AtlasBuildBytes(o);
  if (needed <= usable_bytes) return Done();
  const std::uint64_t shards = (needed + usable_bytes / 2 - 1) / (usable_bytes / 2);  // each shard at most half of it
  return Outcome::Error(fmt::format("{} curves need about {} of memory (the curves and the file written from them), more than the {} "
                                    "this process may have ({}); build them in shards, e.g. --shard k/{}, and merge them with "
                                    "koppel atlas merge",
                                    ShardRange(o).second - ShardRange(o).first, FormatBytes(static_cast<double>(needed)),
                                    FormatBytes(static_cast<double>(usable_bytes)), source, std::max<std::uint64_t>(2, shards)));
}

std::vector<AtlasEntry> BuildAtlas(const AtlasBuildOptions& o, const std::function<void(double)>& progress) {
  if (!o.IsValid(nullptr)) return {};
  const std::pair<std::uint64_t, std::uint64_t> range = ShardRange(o);
  const std::uint64_t first = range.first;
  std::vector<AtlasEntry> entries(range.second - range.first);
  constexpr std::uint64_t kChunk = 1024;
  std::atomic<std::uint64_t> next{0};
  const std::thread::id caller = std::this_thread::get_id();
  auto work = [&] {
    for (std::uint64_t start = next.fetch_add(kChunk); start < entries.size(); start = next.fetch_add(kChunk)) {
      const std::uint64_t end = std::min<std::uint64_t>(start + kChunk, entries.size());
      for (std::uint64_t i = start; i < end; ++i) entries[i] = DrawAtlasEntry(o.seed, first + i);
      // the callback runs on the caller's thread only: it need not be thread-safe
      if (progress && std::this_thread::get_id() == caller)
        progress(std::min(1.0, static_cast<double>(next.load()) / static_cast<double>(entries.size())));
    }
  };
  RunOnThreads(o.threads, work);
  if (progress) progress(1.0);
  return entries;
}

Expected<std::vector<AtlasEntry>> MergeAtlases(std::vector<std::vector<AtlasEntry>> parts) {
  using Result = Expected<std::vector<AtlasEntry>>;
  std::uint64_t total = 0;
  for (const auto& part : parts) total += part.size();
  if (total > kMaxAtlasCurves) return Result::Error(fmt::format("{} curves together: more than {}", total, kMaxAtlasCurves));
  std::vector<AtlasEntry> merged;
  merged.reserve(total);
  for (auto& part : parts) merged.insert(merged.end(), part.begin(), part.end());
  std::sort(merged.begin(), merged.end(), [](const AtlasEntry& a, const AtlasEntry& b) { return a.seed != b.seed ? a.seed < b.seed : a.index < b.index; });
  for (size_t i = 1; i < merged.size(); ++i) {
    if (merged[i].seed == merged[i - 1].seed && merged[i].index == merged[i - 1].index)
      return Result::Error(fmt::format("curve {} of seed {} appears twice (a shard given twice?)", merged[i].index, merged[i].seed));
  }
  return merged;
}

}  // namespace koppel
