// The benchmarks of `koppel bench`: each one times a piece of work in this process and names the
// baseline it is compared with (a hand-written closed form doing the same work, another
// benchmark scaled to the same size, or a time budget from issue 16), so that the ratio printed
// next to it means something on any machine and under any load.
#pragma once

#include <benchmark/benchmark.h>

#include <functional>
#include <string>
#include <vector>

namespace koppel::bench {

// the time is reported per walk step (ns), per run (ms) or per atlas curve (us)
enum class Per { kStep, kRun, kCurve };

struct Case {
  std::string name;
  Per per = Per::kStep;
  long steps_per_iteration = 1;  // kStep, kCurve: the walk steps (curves) one benchmark iteration takes
  // The baseline: another case's name (its time per step times baseline_factor), or empty with
  // budget_ns > 0 (a time budget), or neither (no ratio).
  std::string baseline;
  double baseline_factor = 1.0;
  double budget_ns = 0.0;
  // Threads of its own (the chart, the fit's starts) or another process's work (the start-up of
  // koppel): timed by the wall clock. Every other case by the CPU time of this process, which
  // other programs on a loaded machine do not inflate.
  bool threaded = false;
  std::string note;  // printed with the table (e.g. why a case is skipped)
  bool skipped = false;
  std::function<void(benchmark::State&)> run;
};

// Every case, in the order of the table. Each file adds its own (walk_bench.cpp, ...).
std::vector<Case> AllCases();
std::vector<Case> WalkCases();       // walk_bench.cpp: four-bar, slider-crank, seed 001, chains
std::vector<Case> SlvsCases();       // slvs_bench.cpp: SolveSpace's libslvs side by side
std::vector<Case> SynthesisCases();  // synthesis_bench.cpp: dead-centre synthesis, chart, fit
std::vector<Case> AnalyzeCases();    // analyze_bench.cpp: koppel analyze to a CSV file
std::vector<Case> AtlasBuildCases();  // atlas_build_bench.cpp: the atlas of path synthesis on one core
std::vector<Case> StartupCases();    // startup_bench.cpp: koppel --version and analyze as new processes

}  // namespace koppel::bench
