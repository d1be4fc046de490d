// The atlas of path synthesis built on one core, as `koppel atlas build --threads 1` builds it
// (draw, trace 256 samples, describe; without the file): the time per curve against issue 25's
// budget of 100 000 curves per second per core, 10 us a curve. (koppel_bench's AtlasBuildOneCore
// and AtlasTraceOnly time the same build and its tracing alone.)
#include "bench.hpp"

#include "koppel/synthesis/atlas.hpp"

namespace koppel::bench {
namespace atlas_build_bench {  // this file's own names, apart from the other benchmarks' in a unity build
namespace {

constexpr int kCurves = 5000;  // one iteration: entries 0 .. 4999 of seed 1

void TimeAtlasBuild(benchmark::State& state) {
  AtlasBuildOptions o;
  o.count = kCurves;
  o.seed = 1;
  o.threads = 1;
  for (auto _ : state) {
    const std::vector<AtlasEntry> entries = BuildAtlas(o);
    if (entries.size() != kCurves) {
      state.SkipWithError("the build did not return every curve");
      return;
    }
    benchmark::DoNotOptimize(entries.data());
  }
}

}  // namespace
}  // namespace atlas_build_bench

std::vector<Case> AtlasBuildCases() {
  using namespace atlas_build_bench;
  Case c;
  c.name = "atlas-build";
  c.per = Per::kCurve;
  c.steps_per_iteration = kCurves;
  c.budget_ns = 1e9 / 100'000;  // 100 000 curves per second on one core
  c.note = "one core; curves/s = 1e9 / time";
  c.run = TimeAtlasBuild;
  return {c};
}

}  // namespace koppel::bench
