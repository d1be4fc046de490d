// The benchmarks of `koppel bench` live in the module libkoppel_bench.so (bench_module.cpp, with
// Google Benchmark), loaded by that command alone (koppel/core/module.hpp): every other start of
// koppel maps one library less, and libbenchmark's static initialisers do not run (issue 25).
// This header is what the command and the module share; it does not include benchmark.h (whose
// header runs an initialiser in every file that includes it).
#pragma once

#include "koppel/core/module.hpp"

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace koppel::bench {

// the time is reported per walk step (ns), per run (ms) or per atlas curve (us)
enum class Per { kStep, kRun, kCurve };

// A benchmark as the table shows it (bench.hpp's Case without the code that is timed).
struct CaseInfo {
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
  std::string note;       // printed with the table (e.g. why a case is skipped)
  bool skipped = false;
};

struct Measured {
  double cpu_ns = 0.0, wall_ns = 0.0;  // per benchmark iteration
  std::string error;
  bool ran = false;
};

// What the benchmarks need from the program that runs them (the koppel executable).
struct Host {
  // `koppel analyze ARGS...` run in this process (ARGS without "analyze"): empty when it
  // succeeded, else what went wrong
  std::function<std::string(const std::vector<std::string>& args)> analyze;
  // called with a case's name when it has run
  std::function<void(const std::string& name)> done;
};

struct BenchModuleTable : ModuleTable {
  std::vector<CaseInfo> (*cases)();  // every case, in the order of the table
  // runs the cases named in `wanted` (skipped ones excepted), each at least min_time seconds
  std::map<std::string, Measured> (*run)(const std::set<std::string>& wanted, double min_time, const Host& host);
};

// Loaded on the first call; std::runtime_error when it cannot be loaded.
inline const BenchModuleTable& BenchModule() { return static_cast<const BenchModuleTable&>(LoadModule("bench")); }

}  // namespace koppel::bench
