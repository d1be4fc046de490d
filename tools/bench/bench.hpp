// The benchmarks of `koppel bench`: each one times a piece of work in this process and names the
// baseline it is compared with (a hand-written closed form doing the same work, another
// benchmark scaled to the same size, or a time budget from issue 16), so that the ratio printed
// next to it means something on any machine and under any load.
#pragma once

#include "bench_module.hpp"

#include <benchmark/benchmark.h>

#include <functional>
#include <string>
#include <vector>

namespace koppel::bench {

// A benchmark: what the table shows (CaseInfo, bench_module.hpp) and the code it times.
struct Case : CaseInfo {
  std::function<void(benchmark::State&)> run;
};

// The program's services to the benchmarks (analyze_bench.cpp runs `koppel analyze` through it),
// set by the module's run for its duration.
const Host& CurrentHost();


// Every case, in the order of the table. Each file adds its own (walk_bench.cpp, ...).
std::vector<Case> AllCases();
std::vector<Case> WalkCases();       // walk_bench.cpp: four-bar, slider-crank, seed 001, chains
std::vector<Case> SlvsCases();       // slvs_bench.cpp: SolveSpace's libslvs side by side
std::vector<Case> SynthesisCases();  // synthesis_bench.cpp: dead-centre synthesis, chart, fit
std::vector<Case> AnalyzeCases();    // analyze_bench.cpp: koppel analyze to a CSV file
std::vector<Case> AtlasBuildCases();  // atlas_build_bench.cpp: the atlas of path synthesis on one core
std::vector<Case> StartupCases();    // startup_bench.cpp: koppel --version and analyze as new processes

}  // namespace koppel::bench
