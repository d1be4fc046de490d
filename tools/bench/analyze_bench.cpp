// `koppel analyze` of 360 000 steps to a CSV file, run in this process through the command
// itself (the file read, the sweep, the formatting and the atomic write; the koppel executable
// runs it for the module, bench_module.hpp's Host): seed 000's
// slider-crank from the catalog, 0 to 360 deg in steps of 0.001 deg, against its 1 s budget.
#include "bench.hpp"
#include "koppel/catalog/catalog.hpp"

#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace koppel::bench {
namespace analyze_bench {  // this file's own names, apart from the other benchmarks' in a unity build
namespace {

void TimeAnalyze(benchmark::State& state) {
  char folder[] = "/tmp/koppel-bench-XXXXXX";
  if (!mkdtemp(folder)) {
    state.SkipWithError("cannot make a temporary folder");
    return;
  }
  const std::string out = std::string(folder) + "/analyze.csv";
  const std::string file = DefaultCatalogDirectory() + "/slider-crank-offset.yaml";
  const std::vector<std::string> args = {file, "--from", "0", "--to", "360", "--step", "0.001", "-o", out};
  const Host& host = CurrentHost();
  for (auto _ : state) {
    if (const std::string why = host.analyze(args); !why.empty()) {
      state.SkipWithError(why.c_str());
      break;
    }
  }
  std::error_code ignored;
  if (std::filesystem::file_size(out, ignored) < 360000 * 10) state.SkipWithError("the CSV file is too short");
  std::filesystem::remove_all(folder, ignored);
}

}  // namespace
}  // namespace analyze_bench

std::vector<Case> AnalyzeCases() {
  using namespace analyze_bench;
  Case c;
  c.name = "analyze-360000";
  c.per = Per::kRun;
  c.budget_ns = 1e9;
  c.run = TimeAnalyze;
  return {c};
}

}  // namespace koppel::bench
