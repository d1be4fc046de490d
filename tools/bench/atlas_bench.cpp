// The atlas of path synthesis: build throughput (curves per second on one core) against the bare
// closed-form tracing of the same curves (the baseline, in the same process), the nearest-neighbour
// lookup of one query (the 8 readings of synth path, 100 neighbours each) in atlases of 10^5 and
// 10^6 curves, and a whole synth path query (lookup, pre-polish, fit) in 10^5 curves.
//   build/tools/koppel_bench --benchmark_filter=Atlas
#include "koppel/core/angles.hpp"
#include "koppel/synthesis/atlas.hpp"
#include "koppel/synthesis/four_bar_design.hpp"
#include "koppel/synthesis/path_synthesis.hpp"

#include <benchmark/benchmark.h>

#include <map>
#include <memory>

namespace {

using namespace koppel;

constexpr int kBuildCurves = 5000;

// the baseline: the curves' points alone (256 samples each, as the build traces them)
void AtlasTraceOnly(benchmark::State& state) {
  std::vector<AtlasEntry> entries;
  for (int i = 0; i < kBuildCurves; ++i) entries.push_back(DrawAtlasEntry(1, i));
  AtlasCurve curve;
  for (auto _ : state) {
    for (const AtlasEntry& e : entries) {
      TraceAtlasCurve(e, 256, &curve);
      benchmark::DoNotOptimize(curve.coupler_point.data());
    }
  }
  state.counters["curves_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()) * kBuildCurves, benchmark::Counter::kIsRate);
}
BENCHMARK(AtlasTraceOnly)->Unit(benchmark::kMillisecond);

// one core: draw, trace, describe
void AtlasBuildOneCore(benchmark::State& state) {
  AtlasBuildOptions o;
  o.count = kBuildCurves;
  o.threads = 1;
  for (auto _ : state) {
    const std::vector<AtlasEntry> entries = BuildAtlas(o);
    benchmark::DoNotOptimize(entries.data());
  }
  state.counters["curves_per_s_per_core"] = benchmark::Counter(static_cast<double>(state.iterations()) * kBuildCurves, benchmark::Counter::kIsRate);
}
BENCHMARK(AtlasBuildOneCore)->Unit(benchmark::kMillisecond);

const AtlasIndex& Atlas(std::uint64_t count) {
  static std::map<std::uint64_t, std::unique_ptr<AtlasIndex>> atlases;
  auto& a = atlases[count];
  if (!a) {
    AtlasBuildOptions o;
    o.count = count;
    a = std::make_unique<AtlasIndex>(BuildAtlas(o));
  }
  return *a;
}

// the points of a crank-rocker's coupler curve (not in any atlas), every 15 deg
std::vector<Eigen::Vector2d> QueryPoints() {
  AtlasEntry e;
  for (std::uint64_t i = 0;; ++i) {
    e = DrawAtlasEntry(4242, i);
    if (e.closed) break;
  }
  AtlasCurve curve;
  TraceAtlasCurve(e, 24, &curve);
  return curve.coupler_point;
}

void AtlasLookup(benchmark::State& state) {
  const AtlasIndex& atlas = Atlas(state.range(0));
  std::vector<CurveDescriptor> readings;
  std::vector<Eigen::Vector2d> points = QueryPoints();
  CurveDescriptor d;
  DescribeCurve(points, &d);
  readings = {d, OtherBranchOfAmbiguity(d)};
  for (auto _ : state) {
    for (int repeat = 0; repeat < 4; ++repeat) {  // mirror x traversal, as synth path reads the points
      for (const CurveDescriptor& r : readings) {
        std::array<float, kAtlasFeatures> f;
        for (int i = 0; i < kAtlasFeatures; ++i) f[i] = static_cast<float>(r.features[i]);
        benchmark::DoNotOptimize(atlas.Nearest(f, true, 100).data());
      }
    }
  }
}
BENCHMARK(AtlasLookup)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

void AtlasPathQuery(benchmark::State& state) {
  const AtlasIndex& atlas = Atlas(state.range(0));
  PathRequest r;
  r.points = QueryPoints();
  r.top = 3;
  for (auto _ : state) {
    const PathResult result = SynthesisePath(atlas, r);
    benchmark::DoNotOptimize(result.linkages.data());
  }
}
BENCHMARK(AtlasPathQuery)->Arg(100'000)->Iterations(3)->Unit(benchmark::kMillisecond);

}  // namespace
