#include "koppel/synthesis/atlas.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/core/memory.hpp"
#include "koppel/synthesis/atlas_file.hpp"
#include "worker_threads.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

namespace koppel {
namespace {

constexpr int kResample = 64;       // points of equal arc length the descriptor is taken from
constexpr int kTraceSamples = 256;  // points of a curve for its descriptor
constexpr double kLogLength = 1.6094379124341003;  // log 5: lengths in [1/5, 5]
constexpr double kShortestArc = kPi / 18;  // 10 deg of crank travel at least

using Complex = std::complex<double>;

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

// The crank angles at which the loop closes: [lo, hi] (hi - lo < 2 pi) or the full turn.
struct Feasible {
  bool any = false, full = false;
  double lo = 0, hi = 0;
};

// |A - B0|^2 = a^2 + 1 - 2 a cos(phi) must lie in [(b - c)^2, (b + c)^2].
Feasible CrankAngles(double a, double b, double c, int side) {
  Feasible f;
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

// B for crank angle phi on `branch`; the triangle's angle clamped at the limit positions, where
// rounding may leave |cos| a few ulps above 1.
bool JointB(double a, double b, double c, double phi, int branch, Eigen::Vector2d* pa, Eigen::Vector2d* pb) {
  *pa = a * Eigen::Vector2d(std::cos(phi), std::sin(phi));
  const Eigen::Vector2d d = Eigen::Vector2d(1, 0) - *pa;
  const double r = d.norm();
  double cos_gamma = (b * b + r * r - c * c) / (2 * b * r);
  if (!(std::abs(cos_gamma) <= 1 + 1e-9)) return false;
  cos_gamma = std::clamp(cos_gamma, -1.0, 1.0);
  const double gamma = std::atan2(d.y(), d.x()) + branch * std::acos(cos_gamma);
  *pb = *pa + b * Eigen::Vector2d(std::cos(gamma), std::sin(gamma));
  return true;
}

}  // namespace

AtlasEntry DrawAtlasEntry(std::uint64_t seed, std::uint64_t index) {
  Draw draw{Mix(seed) ^ Mix(index + 0x632be59bd9b4e019ULL)};
  AtlasCurve curve;
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
    const Feasible f = CrankAngles(e.crank, e.coupler, e.rocker, e.side);
    if (!f.any || f.hi - f.lo < kShortestArc) continue;
    e.closed = f.full ? 1 : 0;
    CurveDescriptor d;
    if (!TraceAtlasCurve(e, kTraceSamples, &curve) || !DescribeCurve(curve.coupler_point, &d)) continue;
    for (int k = 0; k < kAtlasFeatures; ++k) e.descriptor[k] = static_cast<float>(d.features[k]);
    return e;
  }
}

bool TraceAtlasCurve(const AtlasEntry& e, int samples, AtlasCurve* curve) {
  const Feasible f = CrankAngles(e.crank, e.coupler, e.rocker, e.side);
  if (!f.any || samples < 3) return false;
  curve->coupler_point.resize(samples);
  curve->a.resize(samples);
  curve->b.resize(samples);
  curve->crank_angle.resize(samples);
  const double mid = 0.5 * (f.lo + f.hi), half = 0.5 * (f.hi - f.lo);
  for (int i = 0; i < samples; ++i) {
    const double t = 2 * kPi * i / samples;
    // a full turn: phi = t; an interval: there and back, phi = mid - half cos t (smooth at the limits)
    const double phi = f.full ? t : mid - half * std::cos(t);
    Eigen::Vector2d a, b;
    if (!JointB(e.crank, e.coupler, e.rocker, phi, e.branch, &a, &b)) return false;
    const Eigen::Vector2d ab = b - a, normal(-ab.y(), ab.x());
    curve->a[i] = a;
    curve->b[i] = b;
    curve->crank_angle[i] = phi;
    curve->coupler_point[i] = a + e.p * ab + e.q * normal;
  }
  return true;
}

bool DescribeCurve(const std::vector<Eigen::Vector2d>& path, CurveDescriptor* d) {
  const int n = static_cast<int>(path.size());
  if (n < 3) return false;
  // resample at equal arc length along the closed polygon
  std::vector<double> s(n + 1, 0.0);
  for (int i = 0; i < n; ++i) s[i + 1] = s[i] + (path[(i + 1) % n] - path[i]).norm();
  const double total = s[n];
  double extent = 0;
  for (const Eigen::Vector2d& p : path) extent = std::max(extent, (p - path[0]).norm());
  if (!(total > 0) || !(extent > 1e-12 * total) || !std::isfinite(total)) return false;
  std::vector<Complex> z(kResample);
  int seg = 0;
  for (int j = 0; j < kResample; ++j) {
    const double at = total * j / kResample;
    while (seg < n - 1 && s[seg + 1] <= at) ++seg;
    const double w = s[seg + 1] > s[seg] ? (at - s[seg]) / (s[seg + 1] - s[seg]) : 0.0;
    const Eigen::Vector2d p = (1 - w) * path[seg] + w * path[(seg + 1) % n];
    z[j] = {p.x(), p.y()};
  }
  std::array<Complex, 2 * kAtlasHarmonics + 1> c{};  // c[k + K] = c_k
  for (int k = -kAtlasHarmonics; k <= kAtlasHarmonics; ++k) {
    Complex sum = 0;
    for (int j = 0; j < kResample; ++j) sum += z[j] * std::polar(1.0, -2 * kPi * k * j / kResample);
    c[k + kAtlasHarmonics] = sum / static_cast<double>(kResample);
  }
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
